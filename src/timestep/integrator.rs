//! Explicit integration of one normal contact as a DEM host does it.
//!
//! A body of effective mass m approaches with speed v0 along the contact normal; the overlap δ
//! obeys `m δ'' = −F(δ, δ')` with F the pair's force kernel (zero for δ ≤ 0, clamped to ≥ 0 for
//! pairs built with [`crate::EndCriterion::Force`]). Schemes, with a = −F/m:
//!
//! * velocity-Verlet, LAMMPS/LIGGGHTS order: `δ += v dt + ½ a dt²`; `v½ = v + ½ a dt`;
//!   `a = −F(δ, v½)/m` (the dashpot sees the half-step velocity, as in `fix nve/sphere` + pair
//!   styles that read `v` after `initial_integrate`); `v = v½ + ½ a dt`.
//! * symplectic (semi-implicit) Euler: `v += a(δ, v) dt`; `δ += v dt`.
//!
//! The first contact happens at a fraction `phase ∈ [0, 1)` of a step: the run starts at
//! δ = −phase·v0·dt in free flight, so contact begins at t = phase·dt. The realised restitution is
//! −v/v0 once δ ≤ 0 again (from then on no force acts), or, for clamped pairs, at the step where
//! the clamped force becomes zero while unloading: the raw force stays negative while δ shrinks at
//! constant speed, so no force acts from there either and that velocity is the exit velocity (the
//! run stops there instead of flying the bodies apart, which takes about δ/(e v0)).
//! The contact duration is taken from the crossing the criterion defines, interpolated linearly
//! between steps (δ = 0 for `Overlap`; the raw, unclamped force for `Force`); δ_max is the
//! largest overlap seen at a step, as a host sees it. No allocation; the step count is bounded.

use crate::force::PairModel;
use crate::force::registry::{normal_force_raw, unclamped};
use crate::{EndCriterion, Error};

/// The time integrator of the host code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// Velocity-Verlet with the force evaluated at the new position and the half-step velocity.
    VelocityVerlet,
    /// Symplectic Euler: velocity first with the old force, then position with the new velocity.
    SymplecticEuler,
}

/// What one simulated collision realises.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collision {
    /// Realised restitution −v_end/v0.
    pub e: f64,
    /// Largest overlap at a step [m].
    pub delta_max: f64,
    /// Contact duration [s] to the end event of the pair's criterion (interpolated).
    pub duration: f64,
    /// Steps taken (from the start of the run to separation, or for a clamped pair to the step
    /// its force ends, after which the bodies fly apart without force).
    pub steps: u32,
}

/// Integrates one collision of `pair` (effective mass `m`, effective radius `r` for the kernels
/// that read it) at impact speed `v0` > 0 with step `dt` > 0, contact starting at `phase` ∈ [0, 1)
/// of a step. `Err(NoConvergence)` if the collision has not ended (separated, or for a clamped
/// pair reached the force's end) after `max_steps` steps.
#[allow(clippy::too_many_arguments)] // the contact's parameters, each used once
pub fn collide(
    pair: &PairModel,
    m: f64,
    r: f64,
    v0: f64,
    dt: f64,
    phase: f64,
    scheme: Scheme,
    max_steps: u32,
) -> Result<Collision, Error> {
    if !(m.is_finite() && r.is_finite() && v0.is_finite() && dt.is_finite() && phase.is_finite()) {
        return Err(Error::NotFinite);
    }
    if !(m > 0.0 && r > 0.0 && v0 > 0.0 && dt > 0.0) {
        return Err(Error::NotPositive);
    }
    if !(0.0..1.0).contains(&phase) {
        return Err(Error::ResultRange);
    }
    let (kernel, consts) = (pair.kernel, pair.consts);
    let raw_kernel = unclamped(kernel);
    let force = |d: f64, v: f64| normal_force_raw(kernel, consts, d, v, r, m);
    let raw = |d: f64, v: f64| normal_force_raw(raw_kernel, consts, d, v, r, m);
    let t0 = phase * dt;
    let (mut d, mut v) = (-phase * v0 * dt, v0);
    let mut a = -force(d, v) / m;
    let mut d_max: f64 = 0.0;
    let mut in_contact = false;
    let mut unloading = false;
    let mut f_prev = 0.0;
    let mut t_force_end = f64::NAN;
    for n in 0..max_steps {
        let t = f64::from(n) * dt;
        // One step; `v_f` is the velocity the force of the new step was evaluated with.
        let (d_new, v_f, v_new, a_new) = match scheme {
            Scheme::VelocityVerlet => {
                let d_new = d + v * dt + 0.5 * a * dt * dt;
                let vh = v + 0.5 * a * dt;
                let a_new = -force(d_new, vh) / m;
                (d_new, vh, vh + 0.5 * a_new * dt, a_new)
            }
            Scheme::SymplecticEuler => {
                let v_new = v + a * dt;
                let d_new = d + v_new * dt;
                (d_new, v_new, v_new, -force(d_new, v_new) / m)
            }
        };
        if !(d_new.is_finite() && v_new.is_finite()) {
            return Err(Error::NoConvergence);
        }
        if d_new > 0.0 {
            in_contact = true;
            d_max = d_max.max(d_new);
            if d_new < d {
                unloading = true;
            }
            if unloading && t_force_end.is_nan() {
                let f = raw(d_new, v_f);
                if !(f > 0.0) {
                    let frac = if f_prev > 0.0 {
                        f_prev / (f_prev - f)
                    } else {
                        1.0
                    };
                    t_force_end = t + frac * dt;
                    if pair.criterion == EndCriterion::Force && f < 0.0 && a_new == 0.0 {
                        // Clamped from here to separation: the law's elastic term over its
                        // dashpot term (δ^p over δ^((p-1)/2) |v|; the viscoelastic law's
                        // δ^(3/2) over δ^(1/2) |v|) only falls as δ shrinks at the constant
                        // outward speed, so the force stays 0 and every later step keeps this
                        // velocity bit for bit (v + 0·dt): it is the exit velocity. Stepping on
                        // would only fly the bodies apart, about δ/(e v0): very long for a
                        // strongly damped contact.
                        return Ok(Collision {
                            e: -v_new / v0,
                            delta_max: d_max,
                            duration: t_force_end - t0,
                            steps: n + 1,
                        });
                    }
                }
                f_prev = f;
            } else {
                f_prev = raw(d_new, v_f);
            }
        } else if in_contact {
            let t_overlap_end = t + dt * d / (d - d_new);
            let t_end = match pair.criterion {
                EndCriterion::Overlap => t_overlap_end,
                EndCriterion::Force if t_force_end.is_nan() => t_overlap_end,
                EndCriterion::Force => t_force_end,
            };
            // From here on no force acts: the velocity of this step is the exit velocity.
            return Ok(Collision {
                e: -v_new / v0,
                delta_max: d_max,
                duration: t_end - t0,
                steps: n + 1,
            });
        }
        d = d_new;
        v = v_new;
        a = a_new;
    }
    Err(Error::NoConvergence)
}

/// A resting contact under a constant load: the body is pressed with acceleration `g` > 0 (load
/// per effective mass) and starts at rest at `start` × `delta_eq`, the overlap where F = m g
/// (found by the caller; a value slightly off 1 perturbs it). Returns `true` when the integration
/// is stable at this `dt`: over the second half of `steps` steps the deviation |δ − δ_eq| never
/// exceeds 10 × the initial one (a growing mode would; a clamped pair can otherwise hide the
/// instability in a bounded but large limit cycle), and δ stays positive throughout.
#[allow(clippy::too_many_arguments)] // the contact's parameters, each used once
pub fn resting_contact_stable(
    pair: &PairModel,
    m: f64,
    r: f64,
    g: f64,
    delta_eq: f64,
    start: f64,
    dt: f64,
    scheme: Scheme,
    steps: u32,
) -> bool {
    let force = |d: f64, v: f64| normal_force_raw(pair.kernel, pair.consts, d, v, r, m);
    let (mut d, mut v) = (start * delta_eq, 0.0);
    let mut a = g - force(d, v) / m;
    let bound = 10.0 * ((start - 1.0) * delta_eq).abs();
    for n in 0..steps {
        match scheme {
            Scheme::VelocityVerlet => {
                d += v * dt + 0.5 * a * dt * dt;
                let vh = v + 0.5 * a * dt;
                a = g - force(d, vh) / m;
                v = vh + 0.5 * a * dt;
            }
            Scheme::SymplecticEuler => {
                v += a * dt;
                d += v * dt;
                a = g - force(d, v) / m;
            }
        }
        if !(d > 0.0) || (n >= steps / 2 && !((d - delta_eq).abs() <= bound)) {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::force::powerlaw::powerlaw;

    #[test]
    fn elastic_linear_spring_small_step() {
        // p = 1, e = 1: half a period π/ω0 and e = 1 up to the O(dt²) of Verlet.
        let pair =
            powerlaw(1.0, 4.0, 1.0, EndCriterion::Overlap).unwrap_or_else(|_| unreachable!());
        let c = collide(
            &pair,
            1.0,
            1.0,
            0.3,
            1e-4,
            0.37,
            Scheme::VelocityVerlet,
            1_000_000,
        );
        let c = c.unwrap_or_else(|_| unreachable!());
        assert!(
            (c.duration - core::f64::consts::FRAC_PI_2).abs() < 1e-4,
            "{}",
            c.duration
        );
        assert!((c.e - 1.0).abs() < 1e-6, "{}", c.e);
        assert!((c.delta_max - 0.15).abs() < 1e-6, "{}", c.delta_max);
    }

    #[test]
    fn resting_contact_limit_matches_linear_theory() {
        // Independent: the linear analysis of velocity-Verlet with half-step damping
        // (powerlaw::timestep::dt_static). Load g = 1, k = 1: δ_eq = 1.
        for &(p, e) in &[(1.0, 0.3), (1.5, 0.1), (1.5, 0.8), (3.0, 0.5)] {
            let pair = powerlaw(p, 1.0, e, EndCriterion::Force).unwrap_or_else(|_| unreachable!());
            let lim =
                crate::powerlaw::timestep::dt_static(p, pair.alpha, 1.0, 1.0).unwrap_or(f64::NAN);
            let stable = |dt: f64| {
                resting_contact_stable(
                    &pair,
                    1.0,
                    1.0,
                    1.0,
                    1.0,
                    1.001,
                    dt,
                    Scheme::VelocityVerlet,
                    20_000,
                )
            };
            assert!(stable(0.99 * lim), "p={p} e={e}: unstable below the limit");
            assert!(!stable(1.01 * lim), "p={p} e={e}: stable above the limit");
        }
    }
}
