//! Product quadrature ∫_0^1 y^ν f(y) dy, ν > −1, for f analytic on [0, 1] (Clenshaw–Curtis with
//! modified moments; Piessens & Branders 1973).
//!
//! f is interpolated at the N+1 Chebyshev–Lobatto points y_j = (1 + cos(jπ/N))/2, whose
//! coefficients a_k (a cosine transform) are integrated exactly against the weight through the
//! modified moments I_k = ∫_{−1}^{1} (1+x)^ν T_k(x) dx. Those obey, by integrating
//! (1+x)^{ν+1}(1−x) T_k' by parts and (1−x²)T_k' = k(T_{k−1} − T_{k+1})/2,
//!
//! ```text
//! (ν + k + 2) I_{k+1} = 2ν I_k + (k − ν − 2) I_{k−1},  I_0 = 2^{ν+1}/(ν+1),  I_1 = ν I_0/(ν+2)
//! ```
//!
//! so the weight singularity costs nothing: the nodes do not depend on ν, and the error is that
//! of Chebyshev interpolation of f alone, ρ^{−N} for f analytic inside the Bernstein ellipse ρ.
//! No allocation: N ≤ 48, cosines from a table of cos(mπ/48).

/// Supported node counts N (N + 1 evaluations of f), one per accuracy level.
pub(crate) const LEVEL_N: [usize; 5] = [6, 8, 12, 16, 24];

/// Highest accuracy level.
pub(crate) const MAX_LEVEL: u32 = 4;

const BASE: usize = 48;
/// Largest N in LEVEL_N (sizes the stack arrays).
const MAX_N: usize = 24;

/// cos(mπ/48), m = 0..=96.
const COS48: [f64; 2 * BASE + 1] = [
    1.0,
    0.9978589232386035,
    0.9914448613738104,
    0.9807852804032304,
    0.9659258262890683,
    0.9469301294951057,
    0.9238795325112867,
    0.8968727415326884,
    0.8660254037844387,
    0.8314696123025452,
    0.7933533402912352,
    0.7518398074789774,
    core::f64::consts::FRAC_1_SQRT_2,
    0.6593458151000688,
    0.6087614290087207,
    0.5555702330196024,
    0.5000000000000001,
    0.44228869021900125,
    0.38268343236508984,
    0.3214394653031617,
    0.25881904510252074,
    0.19509032201612833,
    0.1305261922200517,
    0.06540312923014327,
    0.0,
    -0.06540312923014327,
    -0.1305261922200517,
    -0.19509032201612833,
    -0.25881904510252074,
    -0.3214394653031617,
    -0.38268343236508984,
    -0.44228869021900125,
    -0.5000000000000001,
    -0.5555702330196024,
    -0.6087614290087207,
    -0.6593458151000688,
    -core::f64::consts::FRAC_1_SQRT_2,
    -0.7518398074789774,
    -0.7933533402912352,
    -0.8314696123025452,
    -0.8660254037844387,
    -0.8968727415326884,
    -0.9238795325112867,
    -0.9469301294951057,
    -0.9659258262890683,
    -0.9807852804032304,
    -0.9914448613738104,
    -0.9978589232386035,
    -1.0,
    -0.9978589232386035,
    -0.9914448613738104,
    -0.9807852804032304,
    -0.9659258262890683,
    -0.9469301294951057,
    -0.9238795325112867,
    -0.8968727415326884,
    -0.8660254037844387,
    -0.8314696123025452,
    -0.7933533402912352,
    -0.7518398074789774,
    -core::f64::consts::FRAC_1_SQRT_2,
    -0.6593458151000688,
    -0.6087614290087207,
    -0.5555702330196024,
    -0.5000000000000001,
    -0.44228869021900125,
    -0.38268343236508984,
    -0.3214394653031617,
    -0.25881904510252074,
    -0.19509032201612833,
    -0.1305261922200517,
    -0.06540312923014327,
    0.0,
    0.06540312923014327,
    0.1305261922200517,
    0.19509032201612833,
    0.25881904510252074,
    0.3214394653031617,
    0.38268343236508984,
    0.44228869021900125,
    0.5000000000000001,
    0.5555702330196024,
    0.6087614290087207,
    0.6593458151000688,
    core::f64::consts::FRAC_1_SQRT_2,
    0.7518398074789774,
    0.7933533402912352,
    0.8314696123025452,
    0.8660254037844387,
    0.8968727415326884,
    0.9238795325112867,
    0.9469301294951057,
    0.9659258262890683,
    0.9807852804032304,
    0.9914448613738104,
    0.9978589232386035,
    1.0,
];

/// Cosine matrices C[k][j] = cos(jkπ/N) for each level's N, built at compile time from COS48 so
/// that the transform is a contiguous dot product per k.
// Indexing here runs at compile time, where an out-of-range index is a build error, not a panic.
#[allow(clippy::indexing_slicing)]
const fn cos_matrix(n: usize) -> [[f64; MAX_N + 1]; MAX_N + 1] {
    let mut m = [[0.0; MAX_N + 1]; MAX_N + 1];
    let step = BASE / n;
    let mut k = 0;
    while k <= n {
        let mut j = 0;
        while j <= n {
            m[k][j] = COS48[(j * k * step) % (2 * BASE)];
            j += 1;
        }
        k += 1;
    }
    m
}

#[allow(clippy::indexing_slicing)]
static COS_MATRICES: [[[f64; MAX_N + 1]; MAX_N + 1]; 5] = [
    cos_matrix(LEVEL_N[0]),
    cos_matrix(LEVEL_N[1]),
    cos_matrix(LEVEL_N[2]),
    cos_matrix(LEVEL_N[3]),
    cos_matrix(LEVEL_N[4]),
];

/// Number of f evaluations at `level` (clamped to 0..=MAX_LEVEL).
pub fn evaluations(level: u32) -> usize {
    n_of(level) + 1
}

fn n_of(level: u32) -> usize {
    let i = level.min(MAX_LEVEL) as usize;
    LEVEL_N.get(i).copied().unwrap_or(24)
}

/// cos(jkπ/N) from the table (N divides 48).
#[inline]
fn cos_jk(j: usize, k: usize, n: usize) -> f64 {
    let m = (j * k * (BASE / n)) % (2 * BASE);
    COS48.get(m).copied().unwrap_or(f64::NAN)
}

/// ∫_0^1 y^ν f(y) dy at `level` (N = 6, 8, 12, 16, 24), for f analytic on [0, 1], given
/// `nu1` = ν + 1 > 0 rather than ν: the leading moment is 1/(ν+1), and for a weight close to
/// y^{−1} (the contact time of p → ∞, ν + 1 = 2/(p+1)) ν + 1 recomputed from ν would lose its
/// digits (and be 0 once ν + 1 < ε/2).
pub fn integrate_weighted_nu1<F: FnMut(f64) -> f64>(mut f: F, nu1: f64, level: u32) -> f64 {
    let nu = nu1 - 1.0;
    let n = n_of(level);
    // Function values at the Lobatto points, j = 0 is y = 1, j = n is y = 0.
    let mut fv = [0.0f64; MAX_N + 1];
    for (j, slot) in fv.iter_mut().enumerate().take(n + 1) {
        *slot = f(0.5 * (1.0 + cos_jk(j, 1, n)));
    }
    // Modified moments of (1+x)^ν, scaled by 2^{−(ν+1)} for the map y = (1+x)/2.
    let mut mom = [0.0f64; MAX_N + 1];
    let i0 = 1.0 / nu1;
    let mut prev = i0;
    let mut cur = nu * i0 / (nu + 2.0);
    if let Some(m) = mom.get_mut(0) {
        *m = prev;
    }
    if let Some(m) = mom.get_mut(1) {
        *m = cur;
    }
    for k in 1..n {
        let kf = k as f64;
        let next = (2.0 * nu * cur + (kf - nu - 2.0) * prev) / (nu + kf + 2.0);
        prev = cur;
        cur = next;
        if let Some(m) = mom.get_mut(k + 1) {
            *m = next;
        }
    }
    // Σ''_k a_k M_k with a_k = (2/N) Σ''_j f_j cos(jkπ/N): halve the end values once, then one
    // contiguous dot product per k against the level's cosine matrix.
    if let Some(f0) = fv.first_mut() {
        *f0 *= 0.5;
    }
    if let Some(fnn) = fv.get_mut(n) {
        *fnn *= 0.5;
    }
    let Some(mat) = COS_MATRICES.get(level.min(MAX_LEVEL) as usize) else {
        return f64::NAN;
    };
    let mut total = 0.0;
    for (k, (&mk, row)) in mom.iter().zip(mat.iter()).enumerate().take(n + 1) {
        let a: f64 = row
            .iter()
            .zip(fv.iter())
            .take(n + 1)
            .map(|(c, f)| c * f)
            .sum();
        let term = a * mk;
        total += if k == 0 || k == n { 0.5 * term } else { term };
    }
    total * 2.0 / n as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cosine_table() {
        for (m, &c) in COS48.iter().enumerate() {
            assert!(
                (c - (m as f64 * core::f64::consts::PI / 48.0).cos()).abs() < 1e-15,
                "m={m}"
            ); // the reference's argument mπ/48 is rounded: ≤ 7e-16
        }
    }

    #[test]
    fn monomials_exact() {
        // ∫ y^ν y^m dy = 1/(ν+m+1), exact for m ≤ N.
        for &nu in &[-0.9, -0.5, -1.0 / 3.0, -0.2, 0.0, 0.5] {
            for level in 0..=MAX_LEVEL {
                for m in 0..=LEVEL_N[level as usize] {
                    let got = integrate_weighted_nu1(|y| y.powi(m as i32), nu + 1.0, level);
                    let want = 1.0 / (nu + m as f64 + 1.0);
                    assert!(
                        (got - want).abs() < 5e-15 * want.max(1.0),
                        "ν={nu} level={level} m={m}: {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn weight_near_one_over_y() {
        // ν + 1 = q tiny (p → ∞): ∫_0^1 y^{q−1} e^y dy = 1/q + Σ_{k≥1} 1/(k!(q+k)), finite for
        // every q > 0 even where q − 1 rounds to −1.
        for &q in &[1e-3, 1e-8, 1e-15, 1e-17, 2.6e-196] {
            let mut want = 1.0 / q;
            let mut fact = 1.0;
            for k in 1..40 {
                fact *= k as f64;
                want += 1.0 / (fact * (q + k as f64));
            }
            let got = integrate_weighted_nu1(|y| y.exp(), q, MAX_LEVEL);
            assert!(
                ((got - want) / want).abs() < 1e-15,
                "q={q}: {got} vs {want}"
            );
        }
    }

    #[test]
    fn analytic_against_series() {
        // ∫_0^1 y^ν e^y dy = Σ_k 1/(k!(ν+k+1)): an independent series.
        for &nu in &[-0.8, -0.5, -0.2, 0.0] {
            let mut want = 0.0;
            let mut fact = 1.0;
            for k in 0..40 {
                if k > 0 {
                    fact *= k as f64;
                }
                want += 1.0 / (fact * (nu + k as f64 + 1.0));
            }
            let got = integrate_weighted_nu1(|y| y.exp(), nu + 1.0, MAX_LEVEL);
            assert!(
                ((got - want) / want).abs() < 1e-15,
                "ν={nu}: {got} vs {want}"
            );
        }
    }
}
