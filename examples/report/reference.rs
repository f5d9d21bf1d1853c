//! The report's truth for δ_max and τ: the library's adaptive Dormand–Prince reference
//! integrating the physical equation of motion (same construction as tests/common `collide()`),
//! m = 1, k = ω0², with events at v = 0 (maximum overlap) and at the criterion's end.

use demcontact::numerics::ode::{integrate_to_event, Tolerance};
use demcontact::EndCriterion;

#[derive(Clone, Copy, Debug)]
pub struct RefCollision {
    pub e: f64,
    pub delta_max: f64,
    pub tau: f64,
}

/// One collision at relative tolerance `rtol`; `observe(t, δ, v)` sees accepted points.
pub fn collide_observed(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: EndCriterion,
    rtol: f64,
    mut observe: impl FnMut(f64, f64, f64),
) -> Option<RefCollision> {
    let h = 0.5 * (p - 1.0);
    let rhs = move |y: [f64; 2]| {
        let d = y[0].abs();
        let spring = omega0 * omega0 * d.powf(p) * y[0].signum();
        let dash = alpha * omega0 * d.powf(h) * y[1];
        [y[1], -spring - dash]
    };
    let d_scale = (v0 / omega0).powf(2.0 / (p + 1.0));
    let t_scale = d_scale / v0;
    let tol = Tolerance { rtol, atol: [rtol * 1e-3 * d_scale, rtol * 1e-3 * v0] };
    let load = integrate_to_event(rhs, 0.0, [0.0, v0], |y| y[1], |t, y| observe(t, y[0], y[1]), &tol, 1e-8 * t_scale, 10_000_000).ok()?;
    let end = move |y: [f64; 2]| match criterion {
        EndCriterion::Overlap => y[0],
        EndCriterion::Force => {
            let d = y[0].abs();
            omega0 * omega0 * d.powf(p) * y[0].signum() + alpha * omega0 * d.powf(h) * y[1]
        }
    };
    let unload =
        integrate_to_event(rhs, load.t, load.y, end, |t, y| observe(t, y[0], y[1]), &tol, 1e-3 * load.t, 10_000_000).ok()?;
    observe(unload.t, unload.y[0], unload.y[1]);
    Some(RefCollision {
        e: -unload.y[1] / v0,
        delta_max: load.y[0],
        tau: unload.t,
    })
}

pub fn collide(p: f64, alpha: f64, v0: f64, omega0: f64, criterion: EndCriterion, rtol: f64) -> Option<RefCollision> {
    collide_observed(p, alpha, v0, omega0, criterion, rtol, |_, _, _| {})
}
