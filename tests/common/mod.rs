//! Shared test support: an independent high-accuracy integration of the power-law contact's
//! equation of motion in physical time, with event detection at δ = 0 and at F = 0.
//!
//! Independent of the library's closed forms: it integrates
//! `δ'' = -α ω0 |δ|^((p-1)/2) δ' - ω0² sgn(δ)|δ|^p` (m = 1, k = ω0²) with adaptive
//! Dormand–Prince at rtol 1e-13, in two phases (impact → maximum overlap, maximum → end) so that
//! the start, where δ = 0 and F = 0, cannot trigger the end events.
#![allow(
    dead_code,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing
)]

use demcontact::EndCriterion;
use demcontact::numerics::ode::{Tolerance, integrate_to_event};

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

/// The equation of motion as a first-order system in y = (δ, δ'), m = 1, k = ω0².
pub fn rhs(p: f64, alpha: f64, omega0: f64) -> impl Fn([f64; 2]) -> [f64; 2] + Copy {
    let damp_expo = 0.5 * (p - 1.0);
    move |y: [f64; 2]| {
        let d = y[0].abs();
        let spring = omega0 * omega0 * d.powf(p) * y[0].signum();
        let dash = alpha * omega0 * d.powf(damp_expo) * y[1];
        [y[1], -spring - dash]
    }
}

/// The end event of `criterion`: the overlap δ, or the total force per mass F/m = −δ''.
pub fn end_event(
    p: f64,
    alpha: f64,
    omega0: f64,
    criterion: EndCriterion,
) -> impl Fn([f64; 2]) -> f64 + Copy {
    let f = rhs(p, alpha, omega0);
    move |y: [f64; 2]| match criterion {
        EndCriterion::Overlap => y[0],
        EndCriterion::Force => -f(y)[1],
    }
}

/// Integrates one power-law collision to the end event of `criterion`.
pub fn collide(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: EndCriterion,
    rtol: f64,
) -> Collision {
    try_collide(p, alpha, v0, omega0, criterion, rtol).expect("reference collision converges")
}

/// [`collide`], `None` where the integration does not converge.
pub fn try_collide(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: EndCriterion,
    rtol: f64,
) -> Option<Collision> {
    try_collide_observed(p, alpha, v0, omega0, criterion, rtol, |_, _, _| {})
}

/// [`try_collide`], with `observe(t, δ, v)` called at every accepted step and at the end event.
pub fn try_collide_observed(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: EndCriterion,
    rtol: f64,
    mut observe: impl FnMut(f64, f64, f64),
) -> Option<Collision> {
    let rhs = rhs(p, alpha, omega0);
    // Natural scales: δ* = (v0/ω0)^(2/(p+1)), t* = δ*/v0.
    let d_scale = (v0 / omega0).powf(2.0 / (p + 1.0));
    let t_scale = d_scale / v0;
    let tol = Tolerance {
        rtol,
        atol: [rtol * 1e-3 * d_scale, rtol * 1e-3 * v0],
    };
    let h0 = 1e-8 * t_scale;
    let max_steps = 10_000_000;
    // Phase 1 starts at δ = 0, where the event function v is positive; fine.
    let load = integrate_to_event(
        rhs,
        0.0,
        [0.0, v0],
        |y| y[1],
        |t, y| observe(t, y[0], y[1]),
        &tol,
        h0,
        max_steps,
    )
    .ok()?;
    let end = end_event(p, alpha, omega0, criterion);
    let unload = integrate_to_event(
        rhs,
        load.t,
        load.y,
        end,
        |t, y| observe(t, y[0], y[1]),
        &tol,
        1e-3 * load.t,
        max_steps,
    )
    .ok()?;
    observe(unload.t, unload.y[0], unload.y[1]);
    Some(Collision {
        e: -unload.y[1] / v0,
        delta_max: load.y[0],
        t_max: load.t,
        tau: unload.t,
        evals: load.stats.evals + unload.stats.evals,
        delta_end: unload.y[0],
        v_end: unload.y[1],
    })
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
    let rhs = rhs(p, alpha, omega0);
    let ds = (v0 / omega0).powf(2.0 / (p + 1.0));
    let tol = Tolerance {
        rtol,
        atol: [rtol * 1e-3 * ds, rtol * 1e-3 * v0],
    };
    let (mut t, mut y, mut h) = (0.0, [0.0, v0], 1e-8 * ds / v0);
    let mut turned = false;
    for ((&target, &up), out) in targets.iter().zip(loading).zip(t_out.iter_mut()) {
        if !up && !turned {
            let hit = integrate_to_event(rhs, t, y, |y| y[1], |_, _| {}, &tol, h, 10_000_000)
                .expect("turn");
            h = (hit.t - t).max(1e-3 * hit.t);
            (t, y, turned) = (hit.t, hit.y, true);
        }
        let hit = if up {
            integrate_to_event(
                rhs,
                t,
                y,
                |y| (target - y[0]).min(y[1]),
                |_, _| {},
                &tol,
                h,
                10_000_000,
            )
        } else {
            integrate_to_event(rhs, t, y, |y| y[0] - target, |_, _| {}, &tol, h, 10_000_000)
        }
        .expect("sample");
        h = (hit.t - t).max(1e-6 * hit.t);
        (t, y) = (hit.t, hit.y);
        *out = t;
    }
    integrate_to_event(
        rhs,
        t,
        y,
        end_event(p, alpha, omega0, criterion),
        |_, _| {},
        &tol,
        h,
        10_000_000,
    )
    .expect("end")
    .t
}
