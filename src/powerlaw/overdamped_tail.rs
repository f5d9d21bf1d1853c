//! The time integral of an overdamped contact far from δ = 0, in closed form.
//!
//! Overdamped (ζ > 1, ω₂ = √(ζ²−1)) the phase integrand of [`super::duration`] is
//! e^{κw} S(w)^ν with κ = −νζ, ν = q − 1 ∈ (−1, 0] and S(w) = sinh(ω₂w)/ω₂. Writing
//! sinh(ω₂w) = e^{ω₂w}(1 − r)/2 with r = e^{−2ω₂w} and expanding (1 − r)^ν binomially,
//!
//! ```text
//! e^{κw} S(w)^ν = (2ω₂)^{−ν} Σ_k b_k e^{c_k w},   b_k = (−1)^k C(ν, k) = Π_{j<k} (j − ν)/(j + 1),
//! c_k = κ + νω₂ − 2kω₂ = −ν/(ζ + ω₂) − 2kω₂,
//! ```
//!
//! and each exponential integrates exactly: ∫_a^b e^{cw} dw = e^{ca}·L·exprel(cL), L = b − a,
//! exprel(x) = (e^x − 1)/x. Every b_k lies in [0, 1] (ν ≤ 0) and every term is positive: the sum
//! has no cancellation. From a = π/(2ω₂) on, r ≤ e^{−π} ≈ 0.043, so the terms fall at least by
//! that factor: 13 terms leave < 1e−17. Where the quadrature needed one panel per doubling of w
//! and a sinh, a ln and an exp per node, this costs five exps and a ln (plus an expm1 for a term
//! whose exponent over the interval is below 0.5 in magnitude).
//!
//! Why c_0 is written −ν/(ζ+ω₂): κ + νω₂ = −ν(ζ − ω₂) cancels for large ζ.

/// Most terms summed; r ≤ e^{−π} makes the 13th below 1e−17 of the first.
const MAX_TERMS: usize = 14;

/// |x| below which exprel takes expm1 (e^x − 1 would lose digits).
const EXPREL_DIRECT: f64 = 0.5;

/// (e^x − 1)/x given e^x, with expm1 where that difference cancels.
#[inline]
fn exprel(x: f64, ex: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else if x.abs() < EXPREL_DIRECT {
        x.exp_m1() / x
    } else {
        (ex - 1.0) / x
    }
}

/// ∫_a^b e^{−νζw} (sinh(ω₂w)/ω₂)^ν dw for π/(2ω₂) ≤ a ≤ b (ζ > 1, ν ∈ (−1, 0]).
pub(crate) fn overdamped_tail(nu: f64, zeta: f64, w2: f64, a: f64, b: f64) -> f64 {
    let len = b - a;
    if !(len > 0.0) {
        return 0.0;
    }
    let c0 = -nu / (zeta + w2);
    let two_w2 = 2.0 * w2;
    let r_a = (-two_w2 * a).exp();
    let r_len = (-two_w2 * len).exp();
    // e^{c_k a} and e^{c_k L} by recurrence from k = 0 (k ulps at most, k ≤ 13).
    let mut ea = (c0 * a).exp();
    let mut el = (c0 * len).exp();
    let mut bk = 1.0;
    let mut sum = 0.0;
    for k in 0..MAX_TERMS {
        let c = c0 - k as f64 * two_w2;
        let term = bk * ea * exprel(c * len, el);
        sum += term;
        if term <= 1e-17 * sum {
            break;
        }
        bk *= (k as f64 - nu) / (k as f64 + 1.0);
        ea *= r_a;
        el *= r_len;
    }
    (-nu * two_w2.ln()).exp() * len * sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same integral by composite Gauss–Legendre on many panels, with the integrand evaluated
    /// directly (sinh, powf): an independent route.
    fn brute(nu: f64, zeta: f64, w2: f64, a: f64, b: f64) -> f64 {
        // 8-point Gauss–Legendre on [−1, 1].
        const X: [f64; 4] = [
            0.183_434_642_495_649_8,
            0.525_532_409_916_329,
            0.796_666_477_413_626_7,
            0.960_289_856_497_536_3,
        ];
        const W: [f64; 4] = [
            0.362_683_783_378_362,
            0.313_706_645_877_887_3,
            0.222_381_034_453_374_5,
            0.101_228_536_290_376_3,
        ];
        let f = |w: f64| (-nu * zeta * w).exp() * ((w2 * w).sinh() / w2).powf(nu);
        let panels = 400;
        let h = (b - a) / panels as f64;
        let mut s = 0.0;
        for i in 0..panels {
            let m = a + (i as f64 + 0.5) * h;
            for (x, wt) in X.iter().zip(W.iter()) {
                s += wt * 0.5 * h * (f(m - 0.5 * h * x) + f(m + 0.5 * h * x));
            }
        }
        s
    }

    #[test]
    fn matches_composite_gauss() {
        let mut worst: f64 = 0.0;
        for &q in &[1.0, 0.8, 2.0 / 2.5, 2.0 / 3.0, 0.5, 1.0 / 3.0, 0.1] {
            let nu = q - 1.0;
            for &zeta in &[1.33, 1.5, 2.0, 4.0, 30.0, 1e3] {
                let w2 = ((zeta - 1.0) * (zeta + 1.0)) as f64;
                let w2 = w2.sqrt();
                let a = core::f64::consts::FRAC_PI_2 / w2;
                for &span in &[1e-9, 1e-3, 0.3, 1.0, 3.0, 10.0] {
                    let b = a * (1.0 + span);
                    let got = overdamped_tail(nu, zeta, w2, a, b);
                    let want = brute(nu, zeta, w2, a, b);
                    let err = ((got - want) / want).abs();
                    assert!(
                        err < 1e-13,
                        "q={q} ζ={zeta} span={span}: {got} vs {want} ({err:.1e})"
                    );
                    worst = worst.max(err);
                }
            }
        }
        println!("overdamped tail vs composite Gauss–Legendre: worst {worst:.1e}");
    }

    #[test]
    fn empty_interval_is_zero() {
        assert_eq!(overdamped_tail(-0.2, 2.0, 3f64.sqrt(), 1.0, 1.0), 0.0);
    }
}
