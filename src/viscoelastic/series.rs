//! Series tier: the published expansions of Schwager & Pöschel, Phys. Rev. E 78, 051304 (2008),
//! with the coefficients as printed (transcribed from the seed's tables; reproduced independently
//! by `tests/viscoelastic_tables.rs`, differences in docs/viscoelastic.md).
//!
//! * force end (their eq. 42, Table V): e = Σ_{k=0}^{20} h_k b^{k/2};
//! * overlap end (their eq. 36, Table III): e = 1 + Σ_{k=1}^{10} c_k b^k.
//!
//! Cheap, but only for small b: within 1e-6 of the reference for b ≤ 0.48 (force) and b ≤ 0.41
//! (overlap), within 1e-3 for b ≤ 0.76 and b ≤ 0.78; the sums diverge beyond b ≈ 1 (error 2.6 and
//! 0.98 at b = 1.5). At small b the error is set by the printed coefficients' 8-digit accuracy
//! (4e-11 at b = 0.01)
//! (measured: `cargo test --release --test viscoelastic_series -- --nocapture`).

use crate::{EndCriterion, Error};

/// Table V, h_0 … h_20 (force end, powers of b^{1/2}).
pub(crate) const H: [f64; 21] = [
    1.0,
    0.0,
    -1.153448856,
    0.0,
    0.7982665581,
    0.2666666667,
    -0.5228825657,
    -0.4613795424,
    0.3487426737,
    0.4523510496,
    -0.1464314644,
    -0.3677282992,
    -0.0432489833,
    0.2818042325,
    0.1478525872,
    -0.1794420590,
    -0.1784660326,
    0.06593358882,
    0.1713586178,
    0.0252498223,
    -0.1379234986,
];

/// Table III, c_1 … c_10 (overlap end, powers of b).
pub(crate) const C: [f64; 10] = [
    -1.153448854,
    0.7982665553,
    -0.5228825609,
    0.3487426678,
    -0.2330981260,
    0.1566821477,
    -0.1058187828,
    0.07176528242,
    -0.04885717237,
    0.03337347194,
];

/// Table III, a_1 … a_10: time of maximum compression T_max = T⁰_max + Σ a_i b^i.
pub(crate) const A: [f64; 10] = [
    -0.2867471220,
    0.1048589922,
    -0.04868406400,
    0.02543116890,
    -0.01423658282,
    0.008337660013,
    -0.005039737366,
    0.003118137108,
    -0.001964027745,
    0.001254701962,
];

/// Table III, b_0 … b_10: maximum compression X_max = Σ b_i b^i (natural units).
pub(crate) const B: [f64; 11] = [
    1.093362074,
    -0.5044548926,
    0.2840430192,
    -0.1702207776,
    0.1055007088,
    -0.06684871371,
    0.04303949229,
    -0.02805108430,
    0.01846085121,
    -0.01224618562,
    0.008177589114,
];

fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |s, &ck| s.mul_add(x, ck))
}

/// Restitution from the paper's series, b ≥ 0 finite. Any such b is evaluated; the result is
/// meaningful only for small b (see the module documentation).
pub fn e_series(b: f64, criterion: EndCriterion) -> Result<f64, Error> {
    if !b.is_finite() {
        return Err(Error::NotFinite);
    }
    if b < 0.0 {
        return Err(Error::Negative);
    }
    let e = match criterion {
        EndCriterion::Force => horner(&H, b.sqrt()),
        EndCriterion::Overlap => 1.0 + b * horner(&C, b),
    };
    // b^10 overflows beyond b ~ 1e30: report it instead of handing out ±inf
    // (tests/proptest_ffi.rs).
    if !e.is_finite() {
        return Err(Error::ResultRange);
    }
    Ok(e)
}

/// The paper's coefficient tables as printed: (h_0..h_20, c_1..c_10, a_1..a_10, b_0..b_10).
pub fn paper_tables() -> (
    &'static [f64; 21],
    &'static [f64; 10],
    &'static [f64; 10],
    &'static [f64; 11],
) {
    (&H, &C, &A, &B)
}
