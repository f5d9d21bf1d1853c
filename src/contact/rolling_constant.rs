//! Constant directional rolling torque (model "A" of Ai et al. 2011): a torque of magnitude
//! μ_r R* |Fn| opposing the rolling part of the relative angular velocity,
//!   ω_r = (ω1 − ω2) − ((ω1 − ω2)·n) n,   M1 = −μ_r R* |Fn| ω_r/|ω_r|,   M2 = −M1,
//! and zero when ω_r = 0 (|Fn|: the normal law's critical load, see [`super::tangential`]). No
//! history. (Known property of this model: near ω_r = 0 the torque
//! flips sign every step, so a resting sphere jitters; use the EPSD model for static packings.)

use super::kinematics::Kin;
use super::model::ContactModel;
use super::vec3::{V3, norm2, scale};

/// The torque on body 1 and whether it acts (ω_r ≠ 0).
#[inline(always)]
pub(crate) fn torque(m: &ContactModel, k: &Kin, f_crit: f64) -> (V3, bool) {
    let wr = k.w_roll;
    let w2 = norm2(wr);
    if w2 > 0.0 {
        let mag = m.mu_r * k.r_eff * f_crit;
        (scale(-mag / w2.sqrt(), wr), true)
    } else {
        ([0.0; 3], false)
    }
}
