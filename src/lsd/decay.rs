//! g(ζ): the logarithmic decay of the LSD from impact to the turning point.
//!
//! For the dimensionless LSD the maximum compression is `x_max = exp(-g(ζ))` with
//!
//! ```text
//! g(ζ) = ζ·arccos(ζ)/√(1-ζ²)     (ζ < 1, underdamped)
//! g(1) = 1                        (critical damping)
//! g(ζ) = ζ·arccosh(ζ)/√(ζ²-1)    (ζ > 1, overdamped)
//! ```
//!
//! which is one analytic function of ζ (with θ = arccos ζ it is θ·cot θ, and θ is imaginary when
//! overdamped). The same g gives the force-zero restitution, `e_F = exp(-2 g)`: the force of the
//! LSD vanishes at the phase mirror-image of the turning point (see `restitution.rs`).
//!
//! Both closed forms are 0/0 at ζ = 1, so around critical damping g is summed from its series in
//! w = 1 - ζ²: `arccos(ζ)/√(1-ζ²) = arcsin(√w)/√w = Σ c_n wⁿ`, `c_n = C(2n,n)/(4ⁿ(2n+1))`.

/// |w| below which the series is used; 0.125²⁰ ≈ 9e-19 bounds the truncation.
const SERIES_W: f64 = 0.125;
const N_SERIES: usize = 21;

/// c_n = C(2n, n)/(4ⁿ (2n+1)), from c_{n+1} = c_n (2n+1)²/((2n+2)(2n+3)).
// Indexing here runs at compile time, where an out-of-range index is a build error, not a panic.
#[allow(clippy::indexing_slicing)]
const SERIES: [f64; N_SERIES] = {
    let mut c = [0.0; N_SERIES];
    c[0] = 1.0;
    let mut n = 0;
    while n + 1 < N_SERIES {
        let k = n as f64;
        c[n + 1] = c[n] * (2.0 * k + 1.0) * (2.0 * k + 1.0) / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
        n += 1;
    }
    c
};

/// Above this ζ the closed form is evaluated with 1/ζ to avoid overflowing ζ².
const LARGE_ZETA: f64 = 1e8;

/// g(ζ), the log decay from impact to maximum compression (see the module docs). ζ ≥ 0, finite.
#[inline]
pub fn decay_to_turning_point(zeta: f64) -> f64 {
    decay_to_turning_point_with_slope(zeta).0
}

/// `(g(ζ), dg/dζ)`. g increases from g(0) = 0 (slope π/2) through g(1) = 1 (slope 2/3) and grows
/// like ln(2ζ) for large ζ; it is concave, which makes Newton's method on it monotone.
pub fn decay_to_turning_point_with_slope(zeta: f64) -> (f64, f64) {
    if zeta > LARGE_ZETA {
        // ζ² - 1 = ζ²(1 - r²) with r = 1/ζ; the arccosh itself is exact for large arguments.
        let r = 1.0 / zeta;
        let one_minus_r2 = (1.0 - r) * (1.0 + r);
        let g = zeta.acosh() / one_minus_r2.sqrt();
        let h = g * r;
        let slope = (1.0 - h * r) / (zeta * one_minus_r2);
        return (g, slope);
    }
    // w = 1 - ζ², exact to rounding of the product because 1 - ζ is exact near ζ = 1.
    let w = (1.0 - zeta) * (1.0 + zeta);
    if w.abs() <= SERIES_W {
        let (h, dh_dw) = series(w);
        // g = ζ h(w(ζ)), dw/dζ = -2ζ
        return (zeta * h, h - 2.0 * zeta * zeta * dh_dw);
    }
    let h = if w > 0.0 {
        zeta.acos() / w.sqrt()
    } else {
        zeta.acosh() / (-w).sqrt()
    };
    (zeta * h, (h - zeta) / w)
}

/// h(w) = Σ c_n wⁿ and dh/dw by Horner.
#[inline]
fn series(w: f64) -> (f64, f64) {
    let mut h = 0.0;
    let mut dh = 0.0;
    for &c in SERIES.iter().rev() {
        dh = dh * w + h;
        h = h * w + c;
    }
    (h, dh)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn closed_form(zeta: f64) -> f64 {
        if zeta < 1.0 {
            zeta * zeta.acos() / (1.0 - zeta * zeta).sqrt()
        } else {
            zeta * zeta.acosh() / (zeta * zeta - 1.0).sqrt()
        }
    }

    #[test]
    fn known_values() {
        assert_eq!(decay_to_turning_point(0.0), 0.0);
        assert!((decay_to_turning_point(1.0) - 1.0).abs() < 1e-16);
        // ζ = 1/2: arccos = π/3, √(3/4): g = (π/6)/(√3/2) = π/(3√3)
        let g = decay_to_turning_point(0.5);
        assert!((g - core::f64::consts::PI / (3.0 * 3f64.sqrt())).abs() < 2e-16);
        // ζ = 5/4: arccosh = ln 2, √(ζ²-1) = 3/4: g = (5/4) ln 2/(3/4) = (5/3) ln 2
        let g = decay_to_turning_point(1.25);
        assert!((g - 5.0 / 3.0 * core::f64::consts::LN_2).abs() < 4e-16);
    }

    #[test]
    fn series_matches_closed_form_at_the_switch() {
        // Where w = ±SERIES_W both forms are well conditioned: they must agree to rounding.
        for &w in &[SERIES_W, -SERIES_W, 0.9 * SERIES_W, -0.9 * SERIES_W] {
            let zeta = (1.0 - w).sqrt();
            let (h, _) = series(w);
            let rel = (zeta * h - closed_form(zeta)).abs() / closed_form(zeta);
            assert!(rel < 8e-16, "w={w}: rel {rel:e}");
        }
    }

    #[test]
    fn slope_matches_central_difference() {
        for &z in &[
            1e-6, 0.1, 0.5, 0.9, 0.97, 0.999, 1.0, 1.001, 1.05, 1.2, 3.0, 1e3, 1e7, 1e9, 1e200,
        ] {
            let (_, s) = decay_to_turning_point_with_slope(z);
            let h = 1e-5 * z;
            let fd = (decay_to_turning_point(z + h) - decay_to_turning_point(z - h)) / (2.0 * h);
            assert!(
                (s - fd).abs() <= 1e-8 * s.abs().max(1e-300),
                "ζ={z}: {s} vs {fd}"
            );
        }
    }

    #[test]
    fn increasing_and_continuous() {
        let mut prev = -1.0;
        let mut z = 0.0;
        while z < 4.0 {
            let g = decay_to_turning_point(z);
            assert!(g > prev, "not increasing at {z}");
            prev = g;
            z += 1e-4;
        }
    }

    #[test]
    fn large_zeta_asymptote() {
        // g = ln 2ζ + O(ln ζ/ζ²)
        for &z in &[1e9, 1e50, 1e300] {
            let g = decay_to_turning_point(z);
            assert!((g - (2.0 * z).ln()).abs() < 1e-15 * g, "{z}");
        }
    }
}
