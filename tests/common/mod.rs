//! Shared test support: an independent high-accuracy integration of the power-law contact's
//! equation of motion in physical time, with event detection at δ = 0 and at F = 0.
//!
//! Independent of the library's closed forms: it integrates
//! `δ'' = -α ω0 |δ|^((p-1)/2) δ' - ω0² sgn(δ)|δ|^p` (m = 1, k = ω0²) with adaptive
//! Dormand–Prince at rtol 1e-13, in two phases (impact → maximum overlap, maximum → end) so that
//! the start, where δ = 0 and F = 0, cannot trigger the end events.
#![allow(dead_code, clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

use demcontact::numerics::ode::{integrate_to_event, Tolerance};
use demcontact::EndCriterion;

/// What one reference collision gives.
#[derive(Clone, Copy, Debug)]
pub struct Collision {
    /// Realised restitution |v_end|/v0.
    pub e: f64,
    /// Maximum overlap.
    pub delta_max: f64,
    /// Time of maximum overlap.
    pub t_max: f64,
    /// Contact duration (to the end event).
    pub tau: f64,
    /// Right-hand-side evaluations used.
    pub evals: u32,
    /// Overlap at the end event (0 for the overlap end, > 0 for the force end).
    pub delta_end: f64,
    /// Overlap rate at the end event.
    pub v_end: f64,
}

/// Integrates one power-law collision to the end event of `criterion`.
pub fn collide(p: f64, alpha: f64, v0: f64, omega0: f64, criterion: EndCriterion, rtol: f64) -> Collision {
    let damp_expo = 0.5 * (p - 1.0);
    let rhs = move |y: [f64; 2]| {
        let d = y[0].abs();
        let spring = omega0 * omega0 * d.powf(p) * y[0].signum();
        let dash = alpha * omega0 * d.powf(damp_expo) * y[1];
        [y[1], -spring - dash]
    };
    // Natural scales: δ* = (v0/ω0)^(2/(p+1)), t* = δ*/v0.
    let d_scale = (v0 / omega0).powf(2.0 / (p + 1.0));
    let t_scale = d_scale / v0;
    let tol = Tolerance { rtol, atol: [rtol * 1e-3 * d_scale, rtol * 1e-3 * v0] };
    let h0 = 1e-8 * t_scale;
    let max_steps = 10_000_000;
    let load = integrate_to_event(rhs, 0.0, [0.0, v0], |y| y[1], |_, _| {}, &tol, h0, max_steps)
        .expect("loading phase converges");
    // Phase 1 starts at δ = 0, where the event function v is positive; fine.
    let end_event = move |y: [f64; 2]| match criterion {
        EndCriterion::Overlap => y[0],
        EndCriterion::Force => {
            let d = y[0].abs();
            omega0 * omega0 * d.powf(p) * y[0].signum() + alpha * omega0 * d.powf(damp_expo) * y[1]
        }
    };
    let unload = integrate_to_event(rhs, load.t, load.y, end_event, |_, _| {}, &tol, 1e-3 * load.t, max_steps)
        .expect("unloading phase converges");
    Collision {
        e: -unload.y[1] / v0,
        delta_max: load.y[0],
        t_max: load.t,
        tau: unload.t,
        evals: load.stats.evals + unload.stats.evals,
        delta_end: unload.y[0],
        v_end: unload.y[1],
    }
}

/// The adaptive reference producing a sampled trajectory: one integration chained through events
/// at prescribed overlaps (`targets[j]`, reached while loading when `loading[j]`, else while
/// unloading), continuing from each event state, then to the end event. Writes the event times
/// to `t_out` (same length as `targets`) and returns the end time. Used by the trajectory
/// benchmark as the cost of "the same trajectory by ODE".
#[allow(clippy::too_many_arguments)]
pub fn chained_reference(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: EndCriterion,
    targets: &[f64],
    loading: &[bool],
    rtol: f64,
    t_out: &mut [f64],
) -> f64 {
    let de = 0.5 * (p - 1.0);
    let rhs = move |y: [f64; 2]| {
        let d = y[0].abs();
        [y[1], -omega0 * omega0 * d.powf(p) * y[0].signum() - alpha * omega0 * d.powf(de) * y[1]]
    };
    let ds = (v0 / omega0).powf(2.0 / (p + 1.0));
    let tol = Tolerance { rtol, atol: [rtol * 1e-3 * ds, rtol * 1e-3 * v0] };
    let (mut t, mut y, mut h) = (0.0, [0.0, v0], 1e-8 * ds / v0);
    let mut turned = false;
    for ((&target, &up), out) in targets.iter().zip(loading).zip(t_out.iter_mut()) {
        if !up && !turned {
            let hit = integrate_to_event(rhs, t, y, |y| y[1], |_, _| {}, &tol, h, 10_000_000).expect("turn");
            h = (hit.t - t).max(1e-3 * hit.t);
            (t, y, turned) = (hit.t, hit.y, true);
        }
        let hit = if up {
            integrate_to_event(rhs, t, y, |y| (target - y[0]).min(y[1]), |_, _| {}, &tol, h, 10_000_000)
        } else {
            integrate_to_event(rhs, t, y, |y| y[0] - target, |_, _| {}, &tol, h, 10_000_000)
        }
        .expect("sample");
        h = (hit.t - t).max(1e-6 * hit.t);
        (t, y) = (hit.t, hit.y);
        *out = t;
    }
    let end = move |y: [f64; 2]| match criterion {
        EndCriterion::Overlap => y[0],
        EndCriterion::Force => {
            let d = y[0].abs();
            omega0 * omega0 * d.powf(p) * y[0].signum() + alpha * omega0 * d.powf(de) * y[1]
        }
    };
    integrate_to_event(rhs, t, y, end, |_, _| {}, &tol, h, 10_000_000).expect("end").t
}
