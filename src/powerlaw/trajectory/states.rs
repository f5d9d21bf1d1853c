//! The LSD state along the contact: X(u) = e^{−ζu}S(u) and the overlap rate v(u) at every sample,
//! by recurrences (no transcendental per sample) reseeded exactly every `RESEED` samples.

use super::super::contact::{Contact, Regime};

/// Samples between exact reseeds of the rotation recurrences.
const RESEED: usize = 16;

/// (S, S') one phase step h further on, as a matrix acting on (S, S'): the rotation by ωh
/// (hyperbolic by ω₂h above critical damping, a shear at ζ = 1).
fn step_matrix(c: &Contact, h: f64) -> [f64; 4] {
    match c.regime {
        Regime::Under(w) => {
            let (s, co) = (w * h).sin_cos();
            [co, s / w, -w * s, co]
        }
        Regime::Critical => [1.0, h, 0.0, 1.0],
        Regime::Over(w2) => {
            let (s, co) = ((w2 * h).sinh(), (w2 * h).cosh());
            [co, s / w2, w2 * s, co]
        }
    }
}

/// X(u_j) = e^{−ζu}S(u) into `x` and v(u_j) into `v`, u_j = j·h (the last at u_end exactly). The
/// state advances by [`step_matrix`] and e^{−ζu} by a factor, reseeded exactly every `RESEED`
/// samples (a recurrence's rounding grows with its number of steps): no transcendental per sample.
pub(super) fn fill_states(c: &Contact, h: f64, u_end: f64, x: &mut [f64], v: &mut [f64]) {
    let zeta = c.zeta;
    let [m11, m12, m21, m22] = step_matrix(c, h);
    let decay_step = (-zeta * h).exp();
    // LANES chunks advance side by side: four independent recurrence chains instead of one,
    // so the loop runs at the CPU's throughput rather than at one chain's latency.
    const LANES: usize = 4;
    // Only the group's first chunk is seeded exactly (a sin/cos and an exp); the other lanes
    // start from it by one exact step of l·RESEED phases each (computed once per call), so a
    // sample is at most 1 + 15 recurrence steps from an exact value instead of 15.
    let chunks = x.len().div_ceil(RESEED);
    let big: [([f64; 4], f64); LANES] = core::array::from_fn(|l| {
        let hl = (l * RESEED) as f64 * h;
        (step_matrix(c, hl), (-zeta * hl).exp())
    });
    for group in (0..chunks).step_by(LANES) {
        let mut st = [(0.0f64, 0.0f64, 0.0f64); LANES];
        let u0 = (group * RESEED) as f64 * h;
        let (s0, ds0) = c.s_and_slope(u0);
        let d0 = (-zeta * u0).exp();
        for (st, &([b11, b12, b21, b22], dl)) in st.iter_mut().zip(big.iter()) {
            *st = (b11 * s0 + b12 * ds0, b21 * s0 + b22 * ds0, d0 * dl);
        }
        for i in 0..RESEED {
            for (l, (s, ds, decay)) in st.iter_mut().enumerate() {
                let j = (group + l) * RESEED + i;
                if let (Some(xj), Some(vj)) = (x.get_mut(j), v.get_mut(j)) {
                    *xj = *decay * *s;
                    *vj = c.v0 * *decay * (*ds - zeta * *s);
                }
                (*s, *ds) = (m11 * *s + m12 * *ds, m21 * *s + m22 * *ds);
                *decay *= decay_step;
            }
        }
    }
    let last = x.len().saturating_sub(1);
    let at = |j: usize| if j == last { u_end } else { j as f64 * h };
    if let (Some(xl), Some(vl)) = (x.last_mut(), v.last_mut()) {
        let (s, ds) = c.s_and_slope(u_end);
        let decay = (-zeta * u_end).exp();
        *xl = decay * s;
        *vl = c.v0 * decay * (ds - zeta * s);
    }
    // Strongly overdamped: e^{−ζu}(cosh ω₂u − ζ sinh(ω₂u)/ω₂) as two decaying exponentials,
    // λ₂ = ζ + ω₂ and λ₁ = 1/λ₂ = ζ − ω₂. The cosh/sinh form cancels to ~4ζ²ε at the force end
    // (1.2e-10 relative exit speed at ζ = 400, tests/proptest_ffi.rs); this one only near critical
    // damping, hence the switch at ζ = 2 (both ≤ 16ε there).
    // X likewise: e^{−u/λ₂}(1 − e^{−2ω₂u})/(2ω₂), by expm1 (no cancellation at small u), which
    // also never forms sinh(ω₂u) (it overflows for ω₂u > 710 while e^{−ζu} underflows: NaN).
    if let Regime::Over(w2) = c.regime
        && zeta >= 2.0
    {
        let l2 = zeta + w2;
        for (j, (xj, vj)) in x.iter_mut().zip(v.iter_mut()).enumerate().skip(1) {
            let u = at(j);
            *xj = -(-u / l2).exp() * (-2.0 * w2 * u).exp_m1() / (2.0 * w2);
            *vj = c.v0 * 0.5 * ((1.0 + zeta / w2) * (-l2 * u).exp() - (-u / l2).exp() / (w2 * l2));
        }
    }
}
