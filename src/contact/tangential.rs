//! The tangential stage shared by every tangential law: carry the spring into the current
//! frame, integrate it with the contact point's tangential velocity, add the calibrated dashpot,
//! and truncate at the Coulomb limit.
//!
//! Per step (LAMMPS/LIGGGHTS order: the spring is incremented before the force is formed):
//!   ξ ← R ξ + v_t dt                       (R: the frame rotation of the step, [`super::frame`])
//!   F_t* = −k_t ξ − c_t v_t
//!   |F_t*| ≤ μ |Fn|: F_t = F_t*                       (sticking)
//!   else:           F_t = μ |Fn| F_t*/|F_t*|,  ξ ← −(F_t + c_t v_t)/k_t   (sliding; LAMMPS's
//!                   reset, so the spring alone plus the dashpot equals the applied force)
//! |Fn| is the normal law's critical load `f_crit` (`force::registry::critical_load`): the
//! magnitude of the normal force actually applied (after clamping), or for an adhesive law the
//! adhesion-corrected |Fn + 2 F_po| (docs/force.md, "Friction with adhesion"). A law only supplies k_t for the
//! contact ([`TangentialLaw`]); the "total" form F = −k_t(δ) ξ is used for Mindlin's varying k_t
//! (LAMMPS `mindlin`, LIGGGHTS `tangential history` with Hertz): see docs/force.md.
//!
//! Damping calibrated from a target tangential restitution e_t (derivation in docs/force.md):
//! while sticking, the contact point's tangential motion is the damped oscillator
//! m_t ξ'' + c_t ξ' + k_t ξ = 0 with m_t = m*/(1 + m* a1²/I1 + m* a2²/I2) = κ/(1 + κ) m* for
//! bodies with I = κ m r² (a ≈ r; 2/7 m* for solid spheres), and
//!   c_t = 2 ζ_t √(m_t k_t),  ζ_t = L/√(π² + L²),  L = −ln e_t,
//! makes one half period of that oscillator reverse the tangential velocity with factor e_t.

use super::frame::FrameStep;
use super::kinematics::Kin;
use super::model::ContactModel;
use super::spec::ContactSpec;
use super::vec3::{V3, add, norm2, scale, sub};
use crate::Error;

/// A tangential law: its spring stiffness for one contact.
pub(crate) trait TangentialLaw {
    /// k_t [N/m] of this contact (δ > 0).
    fn stiffness(m: &ContactModel, k: &Kin) -> f64;
    /// The model's stiffness constant `ContactModel::kt` from the specification, checked.
    fn stiffness_constant(s: &ContactSpec) -> Result<f64, Error>;
    /// The stiffness a stored spring had, for the energy ledger of a contact that ended (the
    /// overlap it was stored at is gone): `m.kt` for a constant k_t, 0 when unknown.
    fn stored_stiffness(m: &ContactModel) -> f64;
}

/// The tangential record as a force S and its stiffness, for the energy ledger
/// ([`super::energy`]): `(k_before, S_old, k, S_c, S_new)`, S_c the old force carried into the
/// current frame (before any rescaling: the force the bodies felt at the start of the step).
pub(crate) type LedgerForces = (f64, V3, f64, V3, V3);

/// The first three doubles of a record (zeros past its end).
#[inline(always)]
pub(crate) fn rec3(h: &[f64], at: usize) -> V3 {
    match h.get(at..at + 3) {
        Some(&[a, b, c]) => [a, b, c],
        _ => [0.0; 3],
    }
}

/// The damping ratio ζ_t = L/√(π² + L²), L = −ln e_t, for a target tangential restitution
/// e_t ∈ (0, 1] in the sticking regime.
pub fn zeta_from_e_t(e_t: f64) -> Result<f64, Error> {
    if !e_t.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(e_t > 0.0 && e_t <= 1.0) {
        return Err(Error::RestitutionRange);
    }
    // 0 − ln e, not −ln e: an undamped spring (e_t = 1) gets ζ = +0, not −0, in the model a host
    // prints.
    let l = 0.0 - e_t.ln();
    Ok(l / (core::f64::consts::PI * core::f64::consts::PI + l * l).sqrt())
}

/// Effective tangential mass factor m_t/m* = κ/(1 + κ) for bodies with I = κ m r².
#[inline(always)]
pub(crate) fn mass_factor(kappa: f64) -> f64 {
    kappa / (1.0 + kappa)
}

/// Result of the tangential stage.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TangentialOut {
    pub ft: V3,
    pub sliding: bool,
}

/// A tangential stage on its history record (the history from the stage's layout offset on; it
/// reads and writes its own first `select::tangential::history` doubles, its registry line's). Every
/// [`TangentialLaw`] is one (the displacement spring ξ of [`step`]);
/// [`super::tangential_mindlin_rescale`] stores a force and a radius instead.
pub(crate) trait TangentialStage {
    /// One step: the tangential force on body 1; `h` updated in place.
    fn run(
        m: &ContactModel,
        k: &Kin,
        f_crit: f64,
        dt: f64,
        frame: &FrameStep,
        h: &mut [f64],
    ) -> TangentialOut;

    /// The model's stiffness constant `ContactModel::kt` from the specification, checked
    /// (`μ` and `e_t`, common to every tangential law, are checked by the specification).
    fn stiffness_constant(s: &ContactSpec) -> Result<f64, Error>;

    /// The ledger's view of a step of a touching contact, from the records before (`old`) and
    /// after (`new`) it: see [`LedgerForces`].
    fn ledger_forces(
        m: &ContactModel,
        k: &Kin,
        frame: &FrameStep,
        old: &[f64],
        new: &[f64],
    ) -> LedgerForces;

    /// The ledger's view of the record of a contact that ended: (its stiffness as stored, its
    /// force S_old).
    fn ledger_ended(m: &ContactModel, old: &[f64]) -> (f64, V3);
}

impl<T: TangentialLaw> TangentialStage for T {
    #[inline(always)]
    fn run(
        m: &ContactModel,
        k: &Kin,
        f_crit: f64,
        dt: f64,
        frame: &FrameStep,
        h: &mut [f64],
    ) -> TangentialOut {
        let Some([x, y, z]) = h.get_mut(0..3) else {
            return TangentialOut {
                ft: [0.0; 3],
                sliding: false,
            };
        };
        let mut xi = [*x, *y, *z];
        let r = step::<T>(m, k, f_crit, dt, frame, &mut xi);
        [*x, *y, *z] = xi;
        r
    }

    fn stiffness_constant(s: &ContactSpec) -> Result<f64, Error> {
        T::stiffness_constant(s)
    }

    /// The spring ξ as the force −k_t ξ at this contact's k_t.
    fn ledger_forces(
        m: &ContactModel,
        k: &Kin,
        frame: &FrameStep,
        old: &[f64],
        new: &[f64],
    ) -> LedgerForces {
        let kt = T::stiffness(m, k);
        let xi_old = rec3(old, 0);
        let f = |xi: V3| scale(-kt, xi);
        (kt, f(xi_old), kt, f(frame.carry(xi_old)), f(rec3(new, 0)))
    }

    fn ledger_ended(m: &ContactModel, old: &[f64]) -> (f64, V3) {
        let k0 = T::stored_stiffness(m);
        (k0, scale(-k0, rec3(old, 0)))
    }
}

/// One tangential step of law `T`; `xi` is the stored spring, updated in place.
#[inline(always)]
pub(crate) fn step<T: TangentialLaw>(
    m: &ContactModel,
    k: &Kin,
    f_crit: f64,
    dt: f64,
    frame: &FrameStep,
    xi: &mut V3,
) -> TangentialOut {
    let kt = T::stiffness(m, k);
    let ct = if m.zeta_t > 0.0 {
        2.0 * m.zeta_t * (mass_factor(m.kappa) * k.m_eff * kt).sqrt()
    } else {
        0.0
    };
    let spring = add(frame.carry(*xi), scale(dt, k.vt));
    let trial = sub(scale(-kt, spring), scale(ct, k.vt));
    let limit = m.mu * f_crit;
    let t2 = norm2(trial);
    if t2 > limit * limit {
        let ft = scale(limit / t2.sqrt(), trial);
        *xi = if kt > 0.0 {
            scale(-1.0 / kt, add(ft, scale(ct, k.vt)))
        } else {
            spring
        };
        TangentialOut { ft, sliding: true }
    } else {
        *xi = spring;
        TangentialOut {
            ft: trial,
            sliding: false,
        }
    }
}
