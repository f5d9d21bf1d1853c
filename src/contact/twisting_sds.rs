//! Twisting spring–dashpot–slider about the normal (LAMMPS `twisting sds` form): the spring
//! torque M_k (1 double of history, a component along n, so frame rotation leaves it as is)
//!   M_k ← M_k − k_tw ω_tw dt,  ω_tw = (ω1 − ω2)·n,  |M_k| ≤ μ_tw |Fn| (μ_tw in metres),
//!   M_d = −C_tw ω_tw while below the limit (0 at the limit),
//!   M1 = (M_k + M_d) n,  M2 = −M1,
//! (|Fn|: the normal law's critical load, see [`super::tangential`]),
//! with C_tw = 2 η_tw √(I_tw k_tw), I_tw = 1/(1/(κ m1 r1²) + 1/(κ m2 r2²)).

use super::kinematics::Kin;
use super::model::ContactModel;
use super::vec3::dot;

/// The law's name in the registry (`select::TWISTING_SDS`; its stage is [`step`]): a name the
/// dispatch binds, never a value (the only twisting law needs no type to pick its code).
#[allow(dead_code)]
pub(crate) enum Sds {}

/// One twisting step: `mk` is the stored spring torque; returns the torque about n on body 1
/// and whether the spring is at its limit.
#[inline(always)]
pub(crate) fn step(m: &ContactModel, k: &Kin, f_crit: f64, dt: f64, mk: &mut f64) -> (f64, bool) {
    let wt = dot(k.w_rel, k.n);
    let spring = *mk - m.k_tw * wt * dt;
    let limit = m.mu_tw * f_crit;
    if spring.abs() > limit {
        let at = limit.copysign(spring);
        *mk = at;
        (at, true)
    } else {
        *mk = spring;
        let i1 = m.kappa * k.m1 * k.r1 * k.r1;
        let i2 = m.kappa * k.m2 * k.r2 * k.r2;
        let it = 1.0 / (1.0 / i1 + 1.0 / i2);
        let c = 2.0 * m.eta_tw * (it * m.k_tw).sqrt();
        (spring - c * wt, false)
    }
}
