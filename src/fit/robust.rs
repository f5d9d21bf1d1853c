//! Order statistics without allocation, and Huber's weight, for the robust (IRLS) fits.
//!
//! Lab restitution data sets hold tens to hundreds of points, so the median is found by rank
//! counting, O(n²) comparisons and no scratch buffer: the library core never allocates.

/// Huber's tuning constant: 95 % efficiency at the normal distribution.
const HUBER_C: f64 = 1.345;

/// 1/Φ⁻¹(3/4): scales the median absolute deviation to σ for normal data.
pub(crate) const MAD_TO_SIGMA: f64 = 1.482_602_218_505_602;

/// The k-th smallest (0-based) of x(0..n), k < n, by rank counting; NaN if n = 0.
fn kth_smallest(n: usize, k: usize, x: &impl Fn(usize) -> f64) -> f64 {
    for i in 0..n {
        let xi = x(i);
        let mut less = 0usize;
        let mut less_eq = 0usize;
        for j in 0..n {
            let xj = x(j);
            if xj < xi {
                less += 1;
            }
            if xj <= xi {
                less_eq += 1;
            }
        }
        if less <= k && k < less_eq {
            return xi;
        }
    }
    f64::NAN
}

/// The median of x(0..n) (mean of the two middle values for even n); NaN for n = 0.
pub fn median(n: usize, x: impl Fn(usize) -> f64) -> f64 {
    if n == 0 {
        return f64::NAN;
    }
    let hi = kth_smallest(n, n / 2, &x);
    if n % 2 == 1 {
        hi
    } else {
        0.5 * (kth_smallest(n, n / 2 - 1, &x) + hi)
    }
}

/// Huber's IRLS weight for a standardised residual u.
#[inline]
pub fn huber_weight(u: f64) -> f64 {
    let a = u.abs();
    if a <= HUBER_C { 1.0 } else { HUBER_C / a }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn medians() {
        let a = [3.0, 1.0, 2.0];
        assert_eq!(median(3, |i| a.get(i).copied().unwrap_or(f64::NAN)), 2.0);
        let b = [4.0, 1.0, 3.0, 2.0];
        assert_eq!(median(4, |i| b.get(i).copied().unwrap_or(f64::NAN)), 2.5);
        let c = [1.0, 1.0, 1.0, 5.0];
        assert_eq!(median(4, |i| c.get(i).copied().unwrap_or(f64::NAN)), 1.0);
        assert!(median(0, |_| 0.0).is_nan());
        assert_eq!(huber_weight(0.5), 1.0);
        assert!((huber_weight(-2.69) - 0.5).abs() < 1e-15);
    }
}
