//! Elastic–plastic spring–dashpot rolling resistance (model "C" of Ai, Chen, Rotter & Ooi 2011,
//! Powder Technol. 206:269). The spring torque M_k is history (3 doubles, carried into the
//! current frame each step like the tangential spring):
//!   M_k ← R M_k − k_r ω_r dt,   |M_k| ≤ M_max = μ_r R* |Fn|   (truncated when exceeded),
//!   M_d = −C_r ω_r while |M_k| < M_max, 0 when fully mobilised (Ai's f = 0),
//!   M1 = M_k + M_d,  M2 = −M1,
//! (|Fn|: the normal law's critical load, see [`super::tangential`]),
//! with ω_r the rolling part of ω1 − ω2 (see [`super::rolling_constant`]),
//! k_r given, or by Ai's rule k_r = 2.25 k_n μ_r² R*² with k_n = dF_el/dδ = p F_el/δ the normal
//! law's elastic tangent stiffness (taken as 0 where it is not positive: an adhesive law's
//! p F/δ is negative where the neck pulls, and a negative spring would feed the rolling motion),
//! and C_r = 2 η_r √(I_r k_r),
//! I_r = 1/(1/((1 + κ) m1 r1²) + 1/((1 + κ) m2 r2²)) (Ai's eq. 15 for I = κ m r²).

use super::frame::FrameStep;
use super::kinematics::Kin;
use super::model::ContactModel;
use super::vec3::{V3, add, norm2, scale};

/// The rolling stiffness k_r: the model's, or Ai's rule 2.25 k_n μ_r² R*² with k_n clamped at 0
/// from below (NaN too: the force's own check reports it).
#[inline(always)]
pub(crate) fn stiffness(m: &ContactModel, kn: f64, r_eff: f64) -> f64 {
    if m.k_r > 0.0 {
        m.k_r
    } else {
        let kn = if kn > 0.0 { kn } else { 0.0 };
        2.25 * kn * m.mu_r * m.mu_r * r_eff * r_eff
    }
}

/// One EPSD step: `mk` is the stored spring torque. `kn` is the normal law's elastic tangent
/// stiffness (only read with Ai's rule, k_r = 0). Returns the torque on body 1 and whether the
/// spring is at its limit.
#[inline(always)]
pub(crate) fn step(
    m: &ContactModel,
    k: &Kin,
    f_crit: f64,
    kn: f64,
    dt: f64,
    frame: &FrameStep,
    mk: &mut V3,
) -> (V3, bool) {
    let wr = k.w_roll;
    let kr = stiffness(m, kn, k.r_eff);
    let spring = add(frame.carry(*mk), scale(-kr * dt, wr));
    let limit = m.mu_r * k.r_eff * f_crit;
    let s2 = norm2(spring);
    if s2 > limit * limit {
        let at = scale(limit / s2.sqrt(), spring);
        *mk = at;
        (at, true)
    } else {
        *mk = spring;
        let i1 = (1.0 + m.kappa) * k.m1 * k.r1 * k.r1;
        let i2 = (1.0 + m.kappa) * k.m2 * k.r2 * k.r2;
        let ir = 1.0 / (1.0 / i1 + 1.0 / i2);
        let cr = 2.0 * m.eta_r * (ir * kr).sqrt();
        (add(spring, scale(-cr, wr)), false)
    }
}
