//! Gauss–Jacobi rules for ∫_0^1 y^ν f(y) dy, ν > −1: n nodes integrate f exactly up to degree
//! 2n − 1 (Clenshaw–Curtis with modified moments, [`super::jacobi_cc`], needs about 2n nodes for
//! the same degree). Built once (for a plan, see `dc_duration_plan_init`) and reused.
//!
//! Construction: the monic Jacobi polynomials for the weight (1+x)^ν on [−1, 1] obey
//! p_{k+1} = (x − a_k) p_k − b_k p_{k−1} with (α = 0, β = ν, s = 2k + ν)
//!
//! ```text
//! a_k = ν²/(s (s + 2))   (a_0 = ν/(ν + 2)),   b_k = 4 k² (k + ν)²/(s² (s + 1)(s − 1)),
//! ```
//!
//! the nodes are the zeros of p_n, found by Newton's method with the zeros already found divided
//! out (x ← x − p/(p' − p Σ 1/(x − x_i))), and the weights are the Christoffel numbers
//! λ_i = 1/Σ_k p_k(x_i)²/‖p_k‖², ‖p_k‖² = μ_0 b_1 ⋯ b_k, μ_0 = 2^{ν+1}/(ν+1). The map
//! y = (1+x)/2 scales the weights by 2^{−(ν+1)}. No allocation: callers pass the output slices.

use crate::Error;

/// Largest supported rule.
pub(crate) const MAX_NODES: usize = 16;

fn a_coef(k: usize, nu: f64) -> f64 {
    if k == 0 {
        return nu / (nu + 2.0);
    }
    let s = 2.0 * k as f64 + nu;
    nu * nu / (s * (s + 2.0))
}

fn b_coef(k: usize, nu: f64) -> f64 {
    let kf = k as f64;
    let s = 2.0 * kf + nu;
    4.0 * kf * kf * (kf + nu) * (kf + nu) / (s * s * (s + 1.0) * (s - 1.0))
}

/// (p_n(x), p_n'(x)) of the monic recurrence.
fn eval(n: usize, nu: f64, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (0.0, 1.0);
    let (mut d0, mut d1) = (0.0, 0.0);
    for k in 0..n {
        let (a, b) = (a_coef(k, nu), if k == 0 { 0.0 } else { b_coef(k, nu) });
        let p2 = (x - a) * p1 - b * p0;
        let d2 = p1 + (x - a) * d1 - b * d0;
        (p0, p1, d0, d1) = (p1, p2, d1, d2);
    }
    (p1, d1)
}

/// Fills `nodes` (ascending in y ∈ (0, 1)) and `weights` with the n-point rule for y^ν, where
/// n = `nodes.len()` = `weights.len()` ≤ [`MAX_NODES`]. Errors: bad sizes, ν ≤ −1 or not finite,
/// or no convergence (not expected for n ≤ 16 and ν ∈ (−1, 0]).
pub(crate) fn gauss_jacobi(nu: f64, nodes: &mut [f64], weights: &mut [f64]) -> Result<(), Error> {
    let n = nodes.len();
    if n == 0 || n > MAX_NODES || weights.len() != n {
        return Err(Error::BufferTooShort);
    }
    if !(nu.is_finite() && nu > -1.0) {
        return Err(Error::ExponentRange);
    }
    let mut xs = [0.0f64; MAX_NODES];
    for i in 0..n {
        // Chebyshev-like guess, largest zero first.
        let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut converged = false;
        for _ in 0..100 {
            let (p, dp) = eval(n, nu, x);
            let defl: f64 = xs.iter().take(i).map(|&xi| 1.0 / (x - xi)).sum();
            let step = p / (dp - p * defl);
            x -= step;
            if !x.is_finite() {
                return Err(Error::NoConvergence);
            }
            if step.abs() <= 1e-15 * (1.0 + x.abs()) {
                // One more step at the converged point polishes the last bit.
                let (p, dp) = eval(n, nu, x);
                let defl: f64 = xs.iter().take(i).map(|&xi| 1.0 / (x - xi)).sum();
                x -= p / (dp - p * defl);
                converged = true;
                break;
            }
        }
        if !converged {
            return Err(Error::NoConvergence);
        }
        if let Some(slot) = xs.get_mut(i) {
            *slot = x;
        }
    }
    let mu0 = (nu + 1.0).recip() * 2f64.powf(nu + 1.0);
    let scale = 2f64.powf(-(nu + 1.0));
    // Ascending y: the zeros were found largest first.
    for ((y, w), &x) in nodes
        .iter_mut()
        .zip(weights.iter_mut())
        .zip(xs.iter().take(n).rev())
    {
        let (mut p0, mut p1) = (0.0, 1.0);
        let mut norm = mu0;
        let mut sum = 1.0 / norm;
        for k in 0..n - 1 {
            let (a, b) = (a_coef(k, nu), if k == 0 { 0.0 } else { b_coef(k, nu) });
            let p2 = (x - a) * p1 - b * p0;
            (p0, p1) = (p1, p2);
            norm *= b_coef(k + 1, nu);
            sum += p1 * p1 / norm;
        }
        *y = 0.5 * (1.0 + x);
        *w = scale / sum;
    }
    if nodes.iter().chain(weights.iter()).any(|v| !v.is_finite()) {
        return Err(Error::NoConvergence);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn monomials_exact_to_degree_2n_minus_1() {
        // ∫_0^1 y^ν y^m dy = 1/(ν + m + 1): independent of the construction.
        for &nu in &[-0.9, -2.0 / 3.0, -0.5, -0.2, 0.0, 0.5] {
            for n in 1..=MAX_NODES {
                let (mut x, mut w) = ([0.0; MAX_NODES], [0.0; MAX_NODES]);
                gauss_jacobi(nu, &mut x[..n], &mut w[..n])
                    .unwrap_or_else(|e| panic!("ν={nu} n={n}: {e:?}"));
                assert!(x[..n].windows(2).all(|p| p[0] < p[1]) && x[0] > 0.0 && x[n - 1] < 1.0);
                for m in 0..2 * n {
                    let got: f64 = x[..n]
                        .iter()
                        .zip(&w[..n])
                        .map(|(&y, &wt)| wt * y.powi(m as i32))
                        .sum();
                    let want = 1.0 / (nu + m as f64 + 1.0);
                    assert!(
                        ((got - want) / want).abs() < 2e-14,
                        "ν={nu} n={n} m={m}: {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn rejects_bad_input() {
        let (mut x, mut w) = ([0.0; 4], [0.0; 3]);
        assert!(gauss_jacobi(-0.5, &mut x, &mut w).is_err());
        assert!(gauss_jacobi(-1.0, &mut x[..3], &mut w).is_err());
        assert!(gauss_jacobi(f64::NAN, &mut x[..3], &mut w).is_err());
    }
}
