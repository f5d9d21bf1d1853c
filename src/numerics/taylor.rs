//! Building blocks of Taylor-series (automatic-differentiation) integrators, without allocation.
//!
//! A Taylor method expands the solution of a polynomial ODE to order N around the current point by
//! a coefficient recursion (Cauchy products), then steps by evaluating the polynomial. For smooth
//! right-hand sides it reaches double precision in few, large steps, and the local polynomial is a
//! dense output on which events are located exactly. The same code runs on real and complex
//! numbers ([`Scalar`]), which lets the series coefficients of a restitution law be obtained by
//! Cauchy integrals over complex parameters.

use core::ops::{Add, Div, Mul, Neg, Sub};
use num_complex::Complex64;

/// The arithmetic a Taylor integrator needs: f64 and `Complex64` implement it.
pub trait Scalar:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The real number x as a scalar.
    fn from_f64(x: f64) -> Self;
    /// Modulus |x|.
    fn norm(self) -> f64;
    /// Real part.
    fn re(self) -> f64;
    /// Principal square root.
    fn sqrt_principal(self) -> Self;
}

impl Scalar for f64 {
    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline]
    fn norm(self) -> f64 {
        self.abs()
    }
    #[inline]
    fn re(self) -> f64 {
        self
    }
    #[inline]
    fn sqrt_principal(self) -> Self {
        self.sqrt()
    }
}

impl Scalar for Complex64 {
    #[inline]
    fn from_f64(x: f64) -> Self {
        Complex64::new(x, 0.0)
    }
    #[inline]
    fn norm(self) -> f64 {
        self.norm()
    }
    #[inline]
    fn re(self) -> f64 {
        self.re
    }
    #[inline]
    fn sqrt_principal(self) -> Self {
        self.sqrt()
    }
}

/// Coefficient k of the product of two series: Σ_{i=0..k} a_i b_{k−i}.
#[inline]
pub fn cauchy_term<T: Scalar, const M: usize>(a: &[T; M], b: &[T; M], k: usize) -> T {
    a.iter()
        .take(k + 1)
        .zip(b.iter().take(k + 1).rev())
        .fold(T::from_f64(0.0), |s, (&x, &y)| s + x * y)
}

/// Value and first derivative of Σ c_k δ^k at δ (Horner).
#[inline]
pub fn horner<T: Scalar, const M: usize>(c: &[T; M], d: T) -> (T, T) {
    let zero = T::from_f64(0.0);
    let (mut p, mut dp) = (zero, zero);
    for &ck in c.iter().rev() {
        dp = dp * d + p;
        p = p * d + ck;
    }
    (p, dp)
}

/// Step size for a Taylor polynomial of order M−1: the largest h for which the last two terms are
/// below `tol · scale` (Jorba & Zou 2005), so the truncation error is about tol relative.
#[inline]
pub fn step_size<T: Scalar, const M: usize>(c: &[T; M], tol: f64, scale: f64) -> f64 {
    let n = M - 1;
    let mut h = f64::INFINITY;
    for (k, ck) in c.iter().enumerate().skip(n.saturating_sub(1)) {
        let a = ck.norm();
        if a > 0.0 && k > 0 {
            h = h.min((tol * scale / a).powf(1.0 / k as f64));
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horner_value_and_slope() {
        // 1 + 2δ + 3δ²  at δ = 0.5: 2.75, slope 2 + 6·0.5 = 5
        let (p, dp) = horner(&[1.0, 2.0, 3.0], 0.5);
        assert!((p - 2.75).abs() < 1e-15 && (dp - 5.0).abs() < 1e-15);
    }

    #[test]
    fn cauchy_of_geometric_series() {
        // (Σ δ^k)² = Σ (k+1) δ^k
        let a = [1.0; 6];
        for k in 0..6 {
            assert_eq!(cauchy_term(&a, &a, k), (k + 1) as f64);
        }
    }
}
