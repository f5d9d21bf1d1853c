//! Quantiles for the fit's confidence intervals: Student's t (σ estimated from the residuals) and
//! the normal distribution (σ known).
//!
//! With σᵢ given, (β̂ − β)/SE is (to the linearisation) standard normal; with σ estimated from
//! the residual scatter, s² = RSS/(n − 1) has n − 1 degrees of freedom (one parameter fitted) and
//! (β̂ − β)/SE follows Student's t with ν = n − 1. A two-sided interval at level L uses the
//! (1 + L)/2 quantile of that distribution; ±2·SE is only right for known σ (95.4 %), and with
//! ν = 5 it covers 89.8 % instead.
//!
//! The t tail P(|T| > t) = I_x(ν/2, 1/2), x = ν/(ν + t²), is the regularized incomplete beta
//! function, evaluated by its continued fraction (modified Lentz) with ln B from `libm::lgamma`;
//! the quantile is found by bisection in θ = arctan t ∈ (0, π/2), which brackets every t > 0 and
//! ends when the bracket stops shrinking (full double precision). Above ν = 1000 the lgamma
//! differences lose digits (1.6e-13 at ν = 2000) while the Cornish–Fisher expansion in 1/ν around
//! the normal quantile (Abramowitz & Stegun 26.7.5, four terms; error ∝ ν⁻⁵, 1.1e-12 at ν = 201)
//! is exact to rounding, so it takes over there. The tests compare both with 30-digit references
//! and with each other where they overlap.

/// P(|T| > t) for Student's t with ν > 0 degrees of freedom, t ≥ 0.
fn t_two_sided_tail(t: f64, nu: f64) -> f64 {
    if !(t > 0.0) {
        return 1.0;
    }
    // x = ν/(ν + t²) and 1 − x = t²/(ν + t²), each computed directly (no cancellation).
    let t2 = t * t;
    let x = nu / (nu + t2);
    let one_minus_x = t2 / (nu + t2);
    incomplete_beta(0.5 * nu, 0.5, x, one_minus_x)
}

/// P(|Z| > z) for the standard normal, z ≥ 0.
fn normal_two_sided_tail(z: f64) -> f64 {
    libm::erfc(z * core::f64::consts::FRAC_1_SQRT_2)
}

/// The regularized incomplete beta function I_x(a, b), a, b > 0, 0 ≤ x ≤ 1 (y = 1 − x passed
/// separately for precision).
fn incomplete_beta(a: f64, b: f64, x: f64, y: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if y <= 0.0 {
        return 1.0;
    }
    let ln_front =
        libm::lgamma(a + b) - libm::lgamma(a) - libm::lgamma(b) + a * x.ln() + b * y.ln();
    let front = ln_front.exp();
    // The continued fraction converges fast for x < (a + 1)/(a + b + 2); use the symmetry
    // I_x(a, b) = 1 − I_{1−x}(b, a) above it.
    if x < (a + 1.0) / (a + b + 2.0) {
        front * beta_fraction(a, b, x) / a
    } else {
        1.0 - front * beta_fraction(b, a, y) / b
    }
}

/// The continued fraction of I_x(a, b) (without its front factor), modified Lentz.
fn beta_fraction(a: f64, b: f64, x: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let mut c = 1.0;
    let mut d = 1.0 - (a + b) * x / (a + 1.0);
    if d.abs() < TINY {
        d = TINY;
    }
    d = 1.0 / d;
    let mut h = d;
    for m in 1..=10_000u32 {
        let m = f64::from(m);
        let m2 = 2.0 * m;
        // even step: m (b − m) x / ((a + 2m − 1)(a + 2m))
        let num = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
        d = 1.0 + num * d;
        if d.abs() < TINY {
            d = TINY;
        }
        c = 1.0 + num / c;
        if c.abs() < TINY {
            c = TINY;
        }
        d = 1.0 / d;
        h *= d * c;
        // odd step: −(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1))
        let num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
        d = 1.0 + num * d;
        if d.abs() < TINY {
            d = TINY;
        }
        c = 1.0 + num / c;
        if c.abs() < TINY {
            c = TINY;
        }
        d = 1.0 / d;
        let del = d * c;
        h *= del;
        if (del - 1.0).abs() <= 1e-16 {
            break;
        }
    }
    h
}

/// The smallest q ≥ 0 with tail(q) ≤ p for a decreasing tail function of θ = arctan q, by
/// bisection on θ ∈ [0, π/2] until the bracket stops shrinking.
fn invert_tail(p: f64, tail: impl Fn(f64) -> f64) -> f64 {
    let (mut lo, mut hi) = (0.0f64, core::f64::consts::FRAC_PI_2);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if tail(mid.tan()) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi)).tan()
}

/// Degrees of freedom above which the Cornish–Fisher expansion replaces the exact tail.
const CORNISH_FISHER_FROM: u64 = 1000;

/// The two-sided quantile q with P(|X| ≤ q) = `level`: Student's t with `dof` ≥ 1 degrees of
/// freedom, or the standard normal for `dof` = 0 (σ known). `None` unless 0 < level < 1.
/// Relative precision (tests): 1e-13 against 30-digit references, both paths (incomplete beta for
/// ν ≤ 1000, expansion above).
pub fn two_sided_quantile(level: f64, dof: u64) -> Option<f64> {
    if !(level > 0.0 && level < 1.0) {
        return None;
    }
    let p = 1.0 - level; // two-sided tail probability
    let z = invert_tail(p, normal_two_sided_tail);
    if dof == 0 {
        return Some(z);
    }
    if dof > CORNISH_FISHER_FROM {
        return Some(cornish_fisher(z, dof as f64));
    }
    let nu = dof as f64;
    Some(invert_tail(p, |t| t_two_sided_tail(t, nu)))
}

/// Student's t quantile from the normal one, A&S 26.7.5 (four terms).
fn cornish_fisher(x: f64, nu: f64) -> f64 {
    let x2 = x * x;
    let g1 = (x2 + 1.0) * x / 4.0;
    let g2 = ((5.0 * x2 + 16.0) * x2 + 3.0) * x / 96.0;
    let g3 = (((3.0 * x2 + 19.0) * x2 + 17.0) * x2 - 15.0) * x / 384.0;
    let g4 = ((((79.0 * x2 + 776.0) * x2 + 1482.0) * x2 - 1920.0) * x2 - 945.0) * x / 92160.0;
    x + (g1 + (g2 + (g3 + g4 / nu) / nu) / nu) / nu
}

/// The multiplier of a fit's standard errors for its two-sided 95 % interval: t_{0.975, n−1}
/// when σ comes from the scatter of n points, z_{0.975} = 1.959964 when σ is given.
pub fn quantile95(n: usize, se_from_scatter: bool) -> f64 {
    let dof = if se_from_scatter {
        (n as u64).saturating_sub(1).max(1)
    } else {
        0
    };
    two_sided_quantile(0.95, dof).unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn published_values() {
        // Reference: mpmath 1.3 at 30 digits (root of betainc(ν/2, 1/2, 0, ν/(ν + t²)) = 1 − L;
        // √2 erfinv(L) for the normal), agreeing with the NIST/SEMATECH e-Handbook table
        // (1.3.6.7.2) to its three decimals.
        for (level, dof, want) in [
            (0.95, 1, 12.706204736174693),
            (0.95, 2, 4.302652729749462),
            (0.95, 3, 3.182446305283708),
            (0.95, 5, 2.570581835636315),
            (0.95, 10, 2.228138851986274),
            (0.95, 11, 2.200985160091639),
            (0.95, 30, 2.042272456301238),
            (0.95, 100, 1.983971518523552),
            (0.95, 200, 1.971896223633909),
            (0.95, 300, 1.967903011261087),
            (0.95, 1000, 1.962339080826409),
            (0.95, 2000, 1.961150826099438),
            (0.99, 10, 3.169272672616951),
            (0.95, 0, 1.959963984540054),
            (0.99, 0, 2.575829303548900),
        ] {
            let q = two_sided_quantile(level, dof).unwrap_or(f64::NAN);
            assert!(
                ((q - want) / want).abs() < 1e-13,
                "level {level} dof {dof}: {q} vs {want}"
            );
        }
    }

    #[test]
    fn closed_forms() {
        // ν = 1 (Cauchy): q = tan(π L/2); ν = 2: q = √(2/(1 − L²) − 2)·... exactly
        // P(|T| ≤ t) = t/√(2 + t²) ⇒ t = L √(2/(1 − L²)).
        for level in [0.5, 0.9, 0.95, 0.999] {
            let c = (core::f64::consts::FRAC_PI_2 * level).tan();
            let q = two_sided_quantile(level, 1).unwrap_or(f64::NAN);
            assert!(((q - c) / c).abs() < 1e-13, "{level}: {q} vs {c}");
            let c2 = level * (2.0 / (1.0 - level * level)).sqrt();
            let q2 = two_sided_quantile(level, 2).unwrap_or(f64::NAN);
            assert!(((q2 - c2) / c2).abs() < 1e-13, "{level}: {q2} vs {c2}");
        }
    }

    #[test]
    fn expansion_meets_the_exact_tail() {
        for dof in [800u64, 1000, 1500] {
            let exact = invert_tail(0.05, |t| t_two_sided_tail(t, dof as f64));
            let z = two_sided_quantile(0.95, 0).unwrap_or(f64::NAN);
            let cf = cornish_fisher(z, dof as f64);
            assert!(((exact - cf) / exact).abs() < 1e-12, "{dof}: {exact} {cf}");
        }
        // monotone in ν, tending to the normal quantile
        let mut prev = f64::INFINITY;
        for dof in [1u64, 2, 5, 50, 1000, 1001, 2000, 1_000_000, u64::MAX] {
            let q = two_sided_quantile(0.95, dof).unwrap_or(f64::NAN);
            assert!(q < prev && q > 1.959963984, "{dof}: {q}");
            prev = q;
        }
    }

    #[test]
    fn rejects_levels_outside_0_1() {
        for l in [0.0, 1.0, -0.5, 2.0, f64::NAN, f64::INFINITY] {
            assert_eq!(two_sided_quantile(l, 5), None);
        }
        assert!((quantile95(12, true) - 2.200985160).abs() < 1e-8);
        assert!((quantile95(12, false) - 1.959963985).abs() < 1e-8);
    }
}
