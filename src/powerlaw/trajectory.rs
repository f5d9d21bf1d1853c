//! The parametric time solution sampled over one contact, into caller buffers.
//!
//! Samples are uniform in the LSD phase u = ω0 s over [0, u_end] (u_end = π/ω for the overlap end,
//! 2u_m for the force end): δ, v, F come in closed form from the LSD image, and t from the time
//! integral of [`super::duration`]. Uniform phase puts samples densely where the contact is slow
//! (near δ = 0 for p > 1, where physical time runs fastest per unit phase).
//!
//! Times: samples within `EDGE` phase steps of a singular end of dt/du (u = 0, and u = π/ω when
//! underdamped) take the singularity-free quadrature from that end; all others accumulate
//! Gauss–Legendre over each phase step (3 points from n = 200 samples, 5 below). A step
//! [(j−1)h, jh] with j > EDGE = 8 has its centre at least 17 half-lengths from the singularity,
//! so the 3-point rule's error is about ρ^{−6} ≈ 6e−10 of that step's share (Bernstein ellipse
//! ρ = 17 + √288 ≈ 34), i.e. ≲ 1e−11 of the total for n ≥ 200; coarser grids take 5 points
//! (ρ^{−10} ≈ 5e−16).

use super::contact::{Contact, Regime};
use super::duration::{contact_duration, time_at_phase};
use crate::criterion::EndCriterion;
use crate::Error;
use core::f64::consts::{FRAC_PI_2, PI};

/// Phase steps next to a singular end that are integrated from that end.
const EDGE: f64 = 8.0;

/// 3-point Gauss–Legendre on [−1, 1]: ±√(3/5) with weight 5/9, 0 with weight 8/9.
const GL3_X: [f64; 3] = [-0.774_596_669_241_483_4, 0.0, 0.774_596_669_241_483_4];
const GL3_W: [f64; 3] = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];
/// 5-point Gauss–Legendre, for coarse sampling (n < `FINE`), where steps are long.
const GL5_X: [f64; 5] = [-0.906_179_845_938_664, -0.538_469_310_105_683_1, 0.0, 0.538_469_310_105_683_1, 0.906_179_845_938_664];
const GL5_W: [f64; 5] = [
    0.236_926_885_056_189_1,
    0.478_628_670_499_366_5,
    0.568_888_888_888_888_9,
    0.478_628_670_499_366_5,
    0.236_926_885_056_189_1,
];
/// Sample count from which the 3-point rule is used.
const FINE: usize = 200;

/// Output buffers of [`sample_trajectory`]; all four must have the same length n ≥ 2.
pub struct TrajectoryOut<'a> {
    /// Time since impact [s].
    pub t: &'a mut [f64],
    /// Overlap δ [m].
    pub delta: &'a mut [f64],
    /// Overlap rate v = dδ/dt [m/s] (positive while compressing).
    pub v: &'a mut [f64],
    /// Total normal force F = k δ^p + α √(m k) δ^((p−1)/2) v [N].
    pub force: &'a mut [f64],
}

/// Fills `out` with n samples over the contact ending by `criterion`; `mass` > 0 scales the force.
/// Errors are all detected before anything is written.
pub fn sample_trajectory(
    c: &Contact,
    criterion: EndCriterion,
    mass: f64,
    level: u32,
    out: TrajectoryOut<'_>,
) -> Result<(), Error> {
    if !mass.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(mass > 0.0) {
        return Err(Error::NotPositive);
    }
    let n = out.t.len();
    if n < 2 || out.delta.len() != n || out.v.len() != n || out.force.len() != n {
        return Err(Error::BufferTooShort);
    }
    let tau = contact_duration(c, criterion, level)?;
    let u_end = match criterion {
        EndCriterion::Overlap => c.u_overlap()?,
        EndCriterion::Force => c.u_force(),
    };
    let k = mass * c.omega0 * c.omega0;
    let damp = c.alpha * mass * c.omega0;
    if !(k.is_finite() && damp.is_finite()) {
        return Err(Error::ResultRange);
    }
    let h = u_end / (n - 1) as f64;
    let scale = c.ln_time_scale().exp();
    let nu = c.q - 1.0;
    let kappa = (1.0 - c.q) * c.zeta;
    let right_singular = match c.regime {
        Regime::Under(w) => Some(PI / w),
        _ => None,
    };
    let integrand = |u: f64| (kappa * u + nu * c.ln_s(u)).exp();
    let mut t_prev = 0.0;
    let iter = out.t.iter_mut().zip(out.delta.iter_mut()).zip(out.v.iter_mut()).zip(out.force.iter_mut());
    for (j, (((t, d), v), f)) in iter.enumerate() {
        let jf = j as f64;
        let last = j + 1 == n;
        let u = if last { u_end } else { jf * h };
        // Time.
        let near_right = right_singular.is_some_and(|ue| (ue - u) <= EDGE * h && u * (PI / ue) > FRAC_PI_2);
        let tj = if j == 0 {
            0.0
        } else if last {
            tau
        } else if c.q == 1.0 || jf <= EDGE || near_right {
            time_at_phase(c, u, level)
        } else {
            let (a, half) = (u - 0.5 * h, 0.5 * h);
            let (xs, ws): (&[f64], &[f64]) = if n >= FINE { (&GL3_X, &GL3_W) } else { (&GL5_X, &GL5_W) };
            let mut s = 0.0;
            for (&x, &w) in xs.iter().zip(ws.iter()) {
                s += w * integrand(a + half * x);
            }
            t_prev + scale * half * s
        };
        t_prev = tj;
        // State: X = e^{−ζu} S, X' = e^{−ζu}(S' − ζS).
        let (s, ds) = c.s_and_slope(u);
        let decay = (-c.zeta * u).exp();
        let vj = match c.regime {
            // Strongly overdamped: e^{−ζu}(cosh ω₂u − ζ sinh(ω₂u)/ω₂) as two decaying
            // exponentials, λ₂ = ζ + ω₂ and λ₁ = 1/λ₂ = ζ − ω₂. The cosh/sinh form cancels to
            // ~4ζ²ε at the force end (1.2e-10 relative exit speed at ζ = 400, tests/proptest_ffi.rs);
            // this one only near critical damping, hence the switch at ζ = 2 (both ≤ 16ε there).
            Regime::Over(w2) if c.zeta >= 2.0 && u > 0.0 => {
                let l2 = c.zeta + w2;
                c.v0 * 0.5 * ((1.0 + c.zeta / w2) * (-l2 * u).exp() - (-u / l2).exp() / (w2 * l2))
            }
            _ => c.v0 * decay * (ds - c.zeta * s),
        };
        *t = tj;
        *v = vj;
        if (last && criterion == EndCriterion::Overlap) || j == 0 {
            *d = 0.0;
            // At δ = 0 only the linear dashpot (p = 1) still acts.
            *f = if c.p == 1.0 { damp * vj } else { 0.0 };
        } else {
            // ln δ once: δ^((p−1)/2) from it, δ^p = δ·(δ^((p−1)/2))².
            let ln_d = c.amp.ln() + c.q * (c.ln_x0 + c.ln_s(u) - c.zeta * u);
            let dj = ln_d.exp();
            let dh = (0.5 * (c.p - 1.0) * ln_d).exp();
            *d = dj;
            *f = k * dj * dh * dh + damp * dh * vj;
        }
    }
    Ok(())
}
