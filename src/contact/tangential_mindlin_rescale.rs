//! Mindlin's tangential spring in incremental force form with the force history rescaled when
//! the contact shrinks (Thornton, Cummins & Cleary 2013, Powder Technol. 233:30, eq. 18; LAMMPS
//! `mindlin_rescale/force`). The history is the spring force F_s [N] (3 doubles) and the
//! contact radius of the last step a_old [m] (1 double). Per step, with a = √(R* δ) and
//! k_t = 8 G* a as [`super::tangential_mindlin`]:
//!   F_c = R F_s                      (carried into the current frame, [`super::frame`])
//!   a < a_old: F_c ← (a/a_old) F_c   (unloading: eq. 18b; loading keeps the force)
//!   F_s ← F_c − k_t v_t dt           (the increment at the current stiffness: eq. 18a)
//!   F_t* = F_s − c_t v_t,  |F_t*| ≤ μ |Fn|: F_t = F_t*
//!   else F_t = μ |Fn| F_t*/|F_t*|,  F_s ← F_t + c_t v_t   (LAMMPS's reset, as [`super::tangential`])
//!   a_old ← a
//! with the damping c_t of [`super::tangential`].
//!
//! Why it creates no energy: the spring's stored energy is E = |F_s|²/(2 k_t). The increment at
//! the current k_t stores exactly the work the bodies do on it (the trapezoid −F̄·v_t dt); a
//! growing k_t (loading) leaves F_s as it is, so E = |F_s|²/(2 k_t) falls; a shrinking one
//! scales F_s by a/a_old = k_t/k_t,old, so E falls by the factor a/a_old. Both losses are the
//! micro-slip of the annulus that Mindlin–Deresiewicz ascribe to a varying contact; the total
//! form F = −k_t(δ) ξ of `TANGENTIAL_MINDLIN` instead gains ½ |ξ|² Δk_t when k_t grows (and
//! returns it when k_t falls at another |ξ|): up to +0.27 % of the kinetic energy in an
//! oblique sticking impact (tests/passivity.rs, docs/force.md).

use super::frame::FrameStep;
use super::kinematics::Kin;
use super::model::ContactModel;
use super::spec::ContactSpec;
use super::tangential::{
    LedgerForces, TangentialLaw, TangentialOut, TangentialStage, mass_factor, rec3,
};
use super::tangential_mindlin::Mindlin;
use super::vec3::{V3, add, norm2, scale, sub};
use crate::Error;

/// The rescaled incremental Mindlin stage.
pub(crate) struct MindlinRescale;

/// The contact radius a = √(R* δ) of Hertz's theory (as [`super::tangential_mindlin`] forms it:
/// 8 G* · a is its k_t, bit for bit).
#[inline(always)]
pub(crate) fn contact_radius(k: &Kin) -> f64 {
    (k.r_eff * k.d).sqrt()
}

impl TangentialStage for MindlinRescale {
    #[inline(always)]
    fn run(
        m: &ContactModel,
        k: &Kin,
        f_crit: f64,
        dt: f64,
        frame: &FrameStep,
        h: &mut [f64],
    ) -> TangentialOut {
        let Some([x, y, z, a_old]) = h.get_mut(0..4) else {
            return TangentialOut {
                ft: [0.0; 3],
                sliding: false,
            };
        };
        let a = contact_radius(k);
        let kt = m.kt * a;
        let ct = if m.zeta_t > 0.0 {
            2.0 * m.zeta_t * (mass_factor(m.kappa) * k.m_eff * kt).sqrt()
        } else {
            0.0
        };
        let carried = frame.carry([*x, *y, *z]);
        // Unloading: the history shrinks with the contact (a < a_old > 0; a new contact has
        // a_old = 0 and keeps its zero force).
        let carried = if a < *a_old {
            scale(a / *a_old, carried)
        } else {
            carried
        };
        let spring = sub(carried, scale(kt * dt, k.vt));
        let trial = sub(spring, scale(ct, k.vt));
        let limit = m.mu * f_crit;
        let t2 = norm2(trial);
        *a_old = a;
        if t2 > limit * limit {
            let ft = scale(limit / t2.sqrt(), trial);
            [*x, *y, *z] = add(ft, scale(ct, k.vt));
            TangentialOut { ft, sliding: true }
        } else {
            [*x, *y, *z] = spring;
            TangentialOut {
                ft: trial,
                sliding: false,
            }
        }
    }

    /// 8 G*, as [`Mindlin`].
    fn stiffness_constant(s: &ContactSpec) -> Result<f64, Error> {
        <Mindlin as TangentialLaw>::stiffness_constant(s)
    }

    /// The record is the force; its stiffness before the step is 8 G* a_old.
    fn ledger_forces(
        m: &ContactModel,
        k: &Kin,
        frame: &FrameStep,
        old: &[f64],
        new: &[f64],
    ) -> LedgerForces {
        let a = contact_radius(k);
        let a_old = old.get(3).copied().unwrap_or(0.0);
        let f_old = rec3(old, 0);
        (
            m.kt * a_old,
            f_old,
            m.kt * a,
            frame.carry(f_old),
            rec3(new, 0),
        )
    }

    fn ledger_ended(m: &ContactModel, old: &[f64]) -> (f64, V3) {
        (m.kt * old.get(3).copied().unwrap_or(0.0), rec3(old, 0))
    }
}
