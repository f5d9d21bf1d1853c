//! The energy ledger of one contact step (after LIGGGHTS' `computeDissipatedEnergy`): the work
//! the dashpots and the slips removed during the step, and the elastic energy left in the
//! history springs, so that a host can check that a contact creates no energy:
//!   ΔKE + Δ(elastic energy of the springs) + Δ(the normal law's potential) = −dissipated,
//! to the integrator's error, step by step; over a whole contact (the springs empty and the
//! overlap zero at both ends) simply KE_out − KE_in = −Σ dissipated.
//!
//! Each history spring is a force S (the tangential force, or the rolling or twisting torque) of
//! stiffness k incremented by −k Δ over a step, Δ = rate·dt (v_t dt, ω_r dt, ω_tw dt); its
//! stored energy is E = |S|²/(2k) (a displacement spring ξ is S = −k ξ). Per step:
//!   E_before: the record as stored (at its last stiffness: known for the rescaled Mindlin law,
//!             which stores a_old; the current k for the others),
//!   S_c:      the record carried into the current frame (before the rescaling of that law: the
//!             force the bodies felt at the start of the step),
//!   W_in = −½ (S_c + S_new)·Δ: the work the bodies did on the spring (the trapezoid, exact for
//!             an elastic increment S_new = S_c − k Δ),
//!   slip = E_before − E_new + W_in   (0 to rounding while a constant-stiffness spring sticks;
//!             the Coulomb slip, the loss of the rescaled law and any loss of the frame carry
//!             otherwise),
//!   damping = c |rate|² dt           (while the dashpot acts),
//!   elastic = E_new.
//! The constant rolling torque M has no spring: slip = −M·ω_r dt. The normal dashpot:
//! (F_n − F_el) vn dt, F_el the normal law's force at vn = 0. A normal law with state
//! ([`crate::force::stateful`], e.g. elastic–plastic) reports its own loss of the step (the
//! plastic work, exact from the state before and after) plus the same dashpot term, F_el its
//! force at vn = 0 in the state after the step (0 for a law without a dashpot); its potential
//! in the balance is then the elastic energy of its unloading curve
//! ([`crate::force::elastic_plastic::stored_energy`]).
//!
//! Not counted, on purpose: the energy a law creates. `TANGENTIAL_MINDLIN` changes k_t under a
//! stored ξ (E_before is taken at the current k_t, because the previous one is not stored), so
//! its gain shows as ΔKE + Σ dissipated > 0, which is what the ledger is for; likewise EPSD
//! rolling with Ai's stiffness rule (k_r = 0) when the overlap changes. The step on which the
//! contact ends (overlap ≤ 0) resets the history: it is a step to S_new = 0, so the energy
//! dropped with the springs is counted as slip where their stiffness is known (linear and
//! rescaled Mindlin springs, EPSD with k_r > 0, twisting).
//!
//! The trapezoid is what a velocity-Verlet host integrates to O(dt²) per step; what it leaves
//! (the lever arms a_i = r_i − δ/2 and the frame turning within a step) is the scheme's own
//! first-order error, measured in tests/passivity.rs.

use super::evaluate::ContactForce;
use super::kinematics::{ContactState, Kin};
use super::model::{ContactModel, HISTORY_MAX, select};
use super::tangential::{TangentialStage, mass_factor};
use super::vec3::{V3, add, dot, norm2, scale};
use super::{rolling_constant, rolling_epsd};
use crate::force::registry::{critical_load, normal_force_raw};
use crate::force::stateful;

/// The ledger of one contact step [J] (the Rust form of `dc_contact_energy`).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ContactEnergy {
    /// Everything removed this step: the sum of the damping and slip terms below.
    pub dissipated: f64,
    /// Work of the normal dashpot this step.
    pub normal_damping: f64,
    /// Work of the tangential dashpot this step.
    pub tangential_damping: f64,
    /// Work of the tangential slip this step (Coulomb slip; for the rescaled Mindlin law also the
    /// loss of its force history when the contact radius changes).
    pub tangential_slip: f64,
    /// Elastic energy left in the tangential spring after the step.
    pub tangential_elastic: f64,
    /// Work of the EPSD rolling dashpot this step.
    pub rolling_damping: f64,
    /// Work of the rolling slip this step (EPSD at its limit; the constant rolling torque).
    pub rolling_slip: f64,
    /// Elastic energy left in the EPSD rolling spring after the step.
    pub rolling_elastic: f64,
    /// Work of the twisting dashpot this step.
    pub twisting_damping: f64,
    /// Work of the twisting slip this step.
    pub twisting_slip: f64,
    /// Elastic energy left in the twisting spring after the step.
    pub twisting_elastic: f64,
}

impl ContactEnergy {
    /// Every value (the C boundary refuses a non-finite ledger as it refuses a force).
    pub fn values(&self) -> [f64; 11] {
        [
            self.dissipated,
            self.normal_damping,
            self.tangential_damping,
            self.tangential_slip,
            self.tangential_elastic,
            self.rolling_damping,
            self.rolling_slip,
            self.rolling_elastic,
            self.twisting_damping,
            self.twisting_slip,
            self.twisting_elastic,
        ]
    }
}

fn get3(h: &[f64; HISTORY_MAX], at: usize) -> V3 {
    match h.get(at..at + 3) {
        Some(&[a, b, c]) => [a, b, c],
        _ => [0.0; 3],
    }
}

fn get1(h: &[f64; HISTORY_MAX], at: usize) -> f64 {
    h.get(at).copied().unwrap_or(0.0)
}

/// |S|²/(2k), 0 for k = 0 (an empty spring of a vanishing contact).
#[inline(always)]
fn stored(k: f64, s: V3) -> f64 {
    if k > 0.0 { norm2(s) / (2.0 * k) } else { 0.0 }
}

/// (slip, elastic) of one spring step: see the module documentation.
#[inline(always)]
fn spring(e_before: f64, k: f64, s_c: V3, s_new: V3, delta: V3) -> (f64, f64) {
    let e_new = stored(k, s_new);
    let w_in = -0.5 * dot(add(s_c, s_new), delta);
    (e_before - e_new + w_in, e_new)
}

/// The ledger of the step that took the history from `old` to `new` and gave `out`.
pub(crate) fn ledger(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    old: &[f64; HISTORY_MAX],
    new: &[f64; HISTORY_MAX],
    out: &ContactForce,
) -> ContactEnergy {
    let mut e = ContactEnergy::default();
    let k = Kin::of(s);
    let pair = &m.normal;
    let f = out.fn_;
    let touching = s.overlap > 0.0;
    let fe = if touching && m.layout.normal_state.is_none() {
        normal_force_raw(pair.kernel, pair.consts, k.d, 0.0, k.r_eff, k.m_eff)
    } else {
        f
    };
    e.normal_damping = match m.layout.normal_state {
        // A law with state: its own loss of the step (exact, from the state before and after)
        // plus the work of its dashpot, (F − F_el) vn dt with F_el its force at vn = 0 in the
        // state after the step (0 for a law whose force does not read vn).
        Some(at) => {
            let (s_old, s_new) = (get1(old, at), get1(new, at));
            let mut st = s_new;
            let f_el = stateful::force(
                pair.kernel,
                &pair.consts,
                k.d,
                0.0,
                k.r_eff,
                k.m_eff,
                &mut st,
            );
            stateful::dissipated(pair.kernel, &pair.consts, k.r_eff, s_old, s_new)
                + (f - f_el) * k.vn * dt
        }
        None => (f - fe) * k.vn * dt,
    };
    let frame = Kin::frame(s, get3(old, 0), dt, m.carry);
    if let Some(at) = m.layout.tangential {
        let (old_rec, new_rec) = (old.get(at..).unwrap_or(&[]), new.get(at..).unwrap_or(&[]));
        // Each law's view of its record (`TangentialStage::ledger_*`); a contact that ended: the
        // reset spring, its stiffness as it was stored (the current one of a linear spring,
        // 8 G* a_old of the rescaled law, unknown: 0, of the total-form Mindlin spring).
        let (k0, s_old, kt, s_c, s_new) = select::tangential::dispatch!(
            m.tangential,
            |T| if touching {
                T::ledger_forces(m, &k, &frame, old_rec, new_rec)
            } else {
                let (k0, s_old) = T::ledger_ended(m, old_rec);
                (k0, s_old, k0, frame.carry(s_old), [0.0; 3])
            },
            (0.0, [0.0; 3], 0.0, [0.0; 3], [0.0; 3]),
        );
        let (slip, el) = spring(stored(k0, s_old), kt, s_c, s_new, scale(dt, k.vt));
        let ct = if m.zeta_t > 0.0 {
            2.0 * m.zeta_t * (mass_factor(m.kappa) * k.m_eff * kt).sqrt()
        } else {
            0.0
        };
        e.tangential_slip = slip;
        e.tangential_elastic = el;
        e.tangential_damping = ct * norm2(k.vt) * dt;
    }
    // The rolling law's registry flag (EPSD or the constant torque), None for none.
    let epsd = select::rolling::dispatch!(m.rolling, |EPSD| Some(EPSD), None);
    match (epsd, m.layout.rolling) {
        (Some(false), _) if touching => {
            let fc = critical_load(pair.kernel, &pair.consts, k.r_eff, f);
            let (t, _) = rolling_constant::torque(m, &k, fc);
            e.rolling_slip = -dot(t, k.w_roll) * dt;
        }
        (Some(true), Some(at)) => {
            let kr = if m.k_r > 0.0 {
                m.k_r
            } else if !touching {
                0.0
            } else {
                rolling_epsd::stiffness(m, pair.p * fe / k.d, k.r_eff)
            };
            let m_old = get3(old, at);
            let m_c = frame.carry(m_old);
            let m_new = get3(new, at);
            let (slip, el) = spring(stored(kr, m_old), kr, m_c, m_new, scale(dt, k.w_roll));
            e.rolling_slip = slip;
            e.rolling_elastic = el;
            // The dashpot acts only below the limit (the increment was kept as it is).
            if touching && m_new == add(m_c, scale(-kr * dt, k.w_roll)) {
                let i1 = (1.0 + m.kappa) * k.m1 * k.r1 * k.r1;
                let i2 = (1.0 + m.kappa) * k.m2 * k.r2 * k.r2;
                let ir = 1.0 / (1.0 / i1 + 1.0 / i2);
                let cr = 2.0 * m.eta_r * (ir * kr).sqrt();
                e.rolling_damping = cr * norm2(k.w_roll) * dt;
            }
        }
        _ => {}
    }
    if let Some(at) = m.layout.twisting {
        let wt = dot(k.w_rel, k.n);
        let (m_old, m_new) = (get1(old, at), get1(new, at));
        let kt = m.k_tw;
        let (slip, el) = spring(
            stored(kt, [m_old, 0.0, 0.0]),
            kt,
            [m_old, 0.0, 0.0],
            [m_new, 0.0, 0.0],
            [wt * dt, 0.0, 0.0],
        );
        e.twisting_slip = slip;
        e.twisting_elastic = el;
        if touching && m_new == m_old - m.k_tw * wt * dt {
            let i1 = m.kappa * k.m1 * k.r1 * k.r1;
            let i2 = m.kappa * k.m2 * k.r2 * k.r2;
            let it = 1.0 / (1.0 / i1 + 1.0 / i2);
            let c = 2.0 * m.eta_tw * (it * m.k_tw).sqrt();
            e.twisting_damping = c * wt * wt * dt;
        }
    }
    e.dissipated = e.normal_damping
        + e.tangential_damping
        + e.tangential_slip
        + e.rolling_damping
        + e.rolling_slip
        + e.twisting_damping
        + e.twisting_slip;
    e
}
