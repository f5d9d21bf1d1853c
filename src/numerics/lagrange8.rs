//! Cumulative integration of equally spaced samples by 8-point Lagrange stencils (local error
//! O(h^9)): the integral over one interval [x_j, x_{j+1}] from the eight samples around it.

/// ∫_0^1 of the Lagrange interpolant through nodes i − s (i = 0..8) over [0, 1], for s = 0..=6:
/// ∫_{x_j}^{x_{j+1}} f = h Σ_i STENCIL[s][i] f(x_{j−s+i}). Exact rationals (rounded), each row sums
/// to 1; row 3 is the centred one (nodes j−3..j+4) and symmetric.
pub(crate) const STENCIL: [[f64; 8]; 7] = [
    [
        0.30422453703703706,
        1.1561590608465608,
        -1.0069196428571427,
        1.0179646164021163,
        -0.7320353835978836,
        0.3430803571428571,
        -0.09384093915343915,
        0.01136739417989418,
    ],
    [
        -0.01136739417989418,
        0.3951636904761905,
        0.8378720238095239,
        -0.3703455687830688,
        0.2222470238095238,
        -0.09546130952380952,
        0.024793320105820107,
        -0.0029017857142857144,
    ],
    [
        0.0029017857142857144,
        -0.034581679894179894,
        0.4764136904761905,
        0.6753720238095238,
        -0.1672205687830688,
        0.05974702380952381,
        -0.014211309523809524,
        0.0015790343915343915,
    ],
    [
        -0.0015790343915343915,
        0.015534060846560846,
        -0.07879464285714285,
        0.5648396164021164,
        0.5648396164021164,
        -0.07879464285714285,
        0.015534060846560846,
        -0.0015790343915343915,
    ],
    [
        0.0015790343915343915,
        -0.014211309523809524,
        0.05974702380952381,
        -0.1672205687830688,
        0.6753720238095238,
        0.4764136904761905,
        -0.034581679894179894,
        0.0029017857142857144,
    ],
    [
        -0.0029017857142857144,
        0.024793320105820107,
        -0.09546130952380952,
        0.2222470238095238,
        -0.3703455687830688,
        0.8378720238095239,
        0.3951636904761905,
        -0.01136739417989418,
    ],
    [
        0.01136739417989418,
        -0.09384093915343915,
        0.3430803571428571,
        -0.7320353835978836,
        1.0179646164021163,
        -1.0069196428571427,
        1.1561590608465608,
        0.30422453703703706,
    ],
];

/// The centred-row integrals (per unit h) of `inc.len()` consecutive intervals at once:
/// `inc[i]` from the nodes `w[i..i + 8]` (`w` holds at least `inc.len() + 7` samples). Written as
/// eight shifted slices zipped, which vectorises (a window per element does not); the symmetric
/// row pairs the nodes.
#[inline(always)]
pub(crate) fn centred_increments(w: &[f64], inc: &mut [f64]) {
    let [c0, c1, c2, c3, ..] = STENCIL[3];
    let len = inc.len();
    let shifted = |k: usize| w.get(k..k + len).unwrap_or(&[]);
    inc.iter_mut()
        .zip(shifted(0).iter().zip(shifted(7)))
        .zip(shifted(1).iter().zip(shifted(6)))
        .zip(shifted(2).iter().zip(shifted(5)))
        .zip(shifted(3).iter().zip(shifted(4)))
        .for_each(|((((x, (a0, a7)), (a1, a6)), (a2, a5)), (a3, a4))| {
            *x = c0 * (a0 + a7) + c1 * (a1 + a6) + c2 * (a2 + a5) + c3 * (a3 + a4);
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every row integrates polynomials of degree ≤ 7 exactly (∫_j^{j+1} x^d over nodes j−s+i),
    /// and the centred increments equal row 3 applied node by node.
    #[test]
    fn rows_are_exact_to_degree_seven() {
        for (s, row) in STENCIL.iter().enumerate() {
            for d in 0..8i32 {
                let j = s as f64; // interval [s, s+1] on nodes 0..8
                let want = ((j + 1.0).powi(d + 1) - j.powi(d + 1)) / f64::from(d + 1);
                let got: f64 = row
                    .iter()
                    .enumerate()
                    .map(|(i, &c)| c * (i as f64).powi(d))
                    .sum();
                assert!(
                    (got - want).abs() <= 1e-11 * want.abs().max(1.0),
                    "s={s} d={d}"
                );
            }
        }
        let w: Vec<f64> = (0..20).map(|i| (0.3 * f64::from(i)).sin()).collect();
        let mut inc = [0.0; 13];
        centred_increments(&w, &mut inc);
        for (i, &x) in inc.iter().enumerate() {
            let direct: f64 = STENCIL[3]
                .iter()
                .zip(&w[i..i + 8])
                .map(|(c, v)| c * v)
                .sum();
            assert!((x - direct).abs() < 1e-15);
        }
    }
}
