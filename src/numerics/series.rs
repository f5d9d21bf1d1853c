//! Power series: the exponential of a series by the J. C. P. Miller recurrence, and Horner
//! evaluation.

/// Taylor coefficients h_k (k < `kk` ≤ N, the rest 0) of h = exp(φ) for φ = Σ_{i≥1} φ_i w^i
/// (φ_0 = 0, so h_0 = 1), by k h_k = Σ_{i=1..k} i φ_i h_{k−i}: O(kk²) operations.
pub(crate) fn exp_series<const N: usize>(phi: &[f64; N], kk: usize) -> [f64; N] {
    let mut h = [0.0f64; N];
    if let Some(x) = h.get_mut(0) {
        *x = 1.0;
    }
    for k in 1..kk.min(N) {
        let s: f64 = phi
            .iter()
            .enumerate()
            .skip(1)
            .take(k)
            .zip(h.iter().take(k).rev())
            .map(|((i, &f), &hh)| i as f64 * f * hh)
            .sum();
        if let Some(x) = h.get_mut(k) {
            *x = s / k as f64;
        }
    }
    h
}

/// Σ c_k x^k by Horner's rule (plain multiply and add, no fused multiply–add).
#[inline]
pub(crate) fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ck| acc * x + ck)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// exp(w) and exp(w + w²) (coefficients by hand: 1, 1, 3/2, 7/6, 25/24) from their exponents.
    #[test]
    fn exponential_of_known_series() {
        let mut phi = [0.0f64; 8];
        phi[1] = 1.0;
        let h = exp_series(&phi, 8);
        let mut fact = 1.0;
        for (k, &hk) in h.iter().enumerate() {
            if k > 0 {
                fact *= k as f64;
            }
            assert!((hk - 1.0 / fact).abs() < 1e-16, "k={k}: {hk}");
        }
        phi[2] = 1.0;
        let h = exp_series(&phi, 5);
        for (hk, want) in h.iter().zip([1.0, 1.0, 1.5, 7.0 / 6.0, 25.0 / 24.0, 0.0]) {
            assert!((hk - want).abs() < 1e-15, "{hk} vs {want}");
        }
        assert_eq!(horner(&[1.0, 2.0, 3.0], 2.0), 17.0);
        assert_eq!(horner(&[], 2.0), 0.0);
    }
}
