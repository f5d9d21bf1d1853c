//! Polynomials by Estrin's scheme: Σ c_k x^k as pairs c_{2i} + c_{2i+1}x, then pairs of those
//! with x², x⁴, … — a dependency depth of about 2 log₂ N operations instead of Horner's 2N. Loops
//! over many independent polynomials (SIMD lanes, quadrature nodes) are bound by that depth, not
//! by the arithmetic, so this is several times faster there. Accuracy is Horner's for the series
//! used here (terms falling geometrically; the result is added to its leading term by the caller).

/// Σ_{k<N} c_k x^k (N ≤ 64).
#[inline(always)]
pub(crate) fn estrin<const N: usize>(x: f64, c: &[f64; N]) -> f64 {
    let mut buf = *c;
    let mut len = N;
    let mut xp = x;
    while len > 1 {
        let half = len.div_ceil(2);
        for i in 0..half {
            let lo = buf.get(2 * i).copied().unwrap_or(0.0);
            let hi = buf
                .get(2 * i + 1)
                .copied()
                .filter(|_| 2 * i + 1 < len)
                .unwrap_or(0.0);
            if let Some(b) = buf.get_mut(i) {
                *b = lo + hi * xp;
            }
        }
        len = half;
        xp *= xp;
    }
    buf.first().copied().unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn horner(x: f64, c: &[f64]) -> f64 {
        c.iter().rev().fold(0.0, |a, &k| a * x + k)
    }

    #[test]
    fn matches_horner() {
        // Coefficients 1/k! (exp) and alternating 1/(k+1): the two kinds of series in this crate.
        let mut fact = [0.0f64; 14];
        let mut f = 1.0;
        for (k, c) in fact.iter_mut().enumerate() {
            if k > 0 {
                f *= k as f64;
            }
            *c = 1.0 / f;
        }
        let alt: [f64; 31] =
            core::array::from_fn(|k| if k % 2 == 0 { 1.0 } else { -1.0 } / (k as f64 + 1.0));
        let mut worst: f64 = 0.0;
        for i in 0..=200 {
            let x = -0.5 + i as f64 / 200.0;
            let (a, b) = (estrin(x, &fact), horner(x, &fact));
            worst = worst.max(((a - b) / b).abs());
            let (a, b) = (estrin(x, &alt), horner(x, &alt));
            worst = worst.max(((a - b) / b).abs());
        }
        assert!(worst < 4.0 * f64::EPSILON, "{worst:e}");
        // Exact on small integer polynomials (every length, odd and even).
        assert_eq!(estrin(2.0, &[1.0]), 1.0);
        assert_eq!(estrin(2.0, &[1.0, 1.0, 1.0]), 7.0);
        assert_eq!(
            estrin(3.0, &[1.0, 2.0, 0.0, 1.0, 5.0]),
            1.0 + 6.0 + 27.0 + 405.0
        );
    }
}
