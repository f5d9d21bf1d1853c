//! One contact through every stage of a model: normal kernel → tangential → rolling →
//! twisting. Each stage picks its monomorphised law once per call (a jump), so a contact pays
//! only for the stages its model switches on.

use super::energy::{ContactEnergy, ledger};
use super::kinematics::{ContactState, Kin};
use super::model::{ContactModel, HISTORY_MAX, select};
use super::tangential::{TangentialOut, TangentialStage};
use super::vec3::{V3, add, all_finite, cross, none_negative, normal_vector, scale, sub};
use super::{rolling_constant, rolling_epsd, step_exact, twisting_sds};
use crate::Error;
use crate::force::registry::{critical_load, needs, normal_force_raw};
use crate::force::stateful;

/// Forces and torques of one contact.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ContactForce {
    /// Total force on body 1 [N] (body 2 receives the opposite).
    pub force: V3,
    /// Torque on body 1 [N m].
    pub torque1: V3,
    /// Torque on body 2 [N m] (zero for a wall).
    pub torque2: V3,
    /// Normal force, positive repulsive [N].
    pub fn_: f64,
    /// Tangential force on body 1 [N].
    pub ft: V3,
    /// The Coulomb limit was reached this step.
    pub sliding: bool,
    /// The rolling (or twisting) limit was reached this step / the constant torque acts.
    pub rolling_sliding: bool,
}

/// Checks a model built elsewhere (e.g. a `dc_contact_model` the caller may have edited).
pub(crate) fn check_model(m: &ContactModel) -> Result<(), Error> {
    // Every field by name (no `..`): a field added to the model is checked here or named as
    // not, or this does not compile (the C model's checks: `model_fields!` in src/ffi/contact.rs).
    let ContactModel {
        normal,
        tangential,
        rolling,
        twisting,
        carry,
        mu,
        kt,
        zeta_t,
        kappa,
        mu_r,
        k_r,
        eta_r,
        mu_tw,
        k_tw,
        eta_tw,
        layout,
        step,
    } = *m;
    let c = normal.consts;
    check_model_parts(
        normal.kernel,
        [tangential, rolling, twisting, carry],
        &[
            c.k, c.c, c.h, mu, kt, zeta_t, kappa, mu_r, k_r, eta_r, mu_tw, k_tw, eta_tw,
        ],
        layout,
        step.on(),
    )
}

/// The checks of [`check_model`] on the model's parts, so that the C boundary can run them on
/// the caller's struct as it reads it (without first building and re-reading a copy):
/// `sel` = tangential, rolling, twisting, carry; `consts` = k, c, h, μ, k_t, ζ_t, κ, μ_r, k_r, η_r,
/// μ_tw, k_tw, η_tw.
#[inline(always)]
pub(crate) fn check_model_parts(
    kernel: i32,
    sel: [i32; 4],
    consts: &[f64; 13],
    layout: super::model::Layout,
    step: bool,
) -> Result<(), Error> {
    let [tangential, rolling, twisting, carry] = sel;
    let has_state = stateful::has_state(kernel);
    if needs(kernel).is_none() && !has_state {
        return Err(Error::ContactModelInvalid);
    }
    let codes_ok = select::tangential::valid(tangential)
        && select::rolling::valid(rolling)
        && select::twisting::valid(twisting)
        && select::carry::valid(carry);
    // Integer reductions instead of a test and a branch per value (this runs on every call).
    let consts_ok = all_finite(consts) & none_negative(consts);
    let [.., kt, _, kappa, _, _, _, _, _, _] = *consts;
    let layout_ok = layout
        == super::model::Layout::of_model(tangential, rolling, twisting, has_state, step)
        && layout.len <= HISTORY_MAX
        && !(has_state && step);
    if !(codes_ok && consts_ok && layout_ok && kappa > 0.0) {
        return Err(Error::ContactModelInvalid);
    }
    if tangential != select::TANGENTIAL_NONE && !(kt > 0.0) {
        return Err(Error::ContactModelInvalid);
    }
    Ok(())
}

/// Checks a state: finite values (r2, m2 may be +∞), positive radii and masses, unit normal.
pub(crate) fn check_state(s: &ContactState) -> Result<(), Error> {
    // Integer reductions, no branch per value (this runs on every scalar call); the status is
    // then picked in the documented order.
    let [n1, n2, n3] = s.n;
    let [a1, a2, a3] = s.v1;
    let [b1, b2, b3] = s.v2;
    let [c1, c2, c3] = s.w1;
    let [d1, d2, d3] = s.w2;
    let all = [
        n1, n2, n3, s.overlap, a1, a2, a3, b1, b2, b3, c1, c2, c3, d1, d2, d3, s.r1, s.m1,
    ];
    // r2, m2: finite or +∞ (NaN and −∞ fail).
    let finite_ok = all_finite(&all) & (s.r2 > f64::NEG_INFINITY) & (s.m2 > f64::NEG_INFINITY);
    let positive_ok = s.r1.min(s.r2).min(s.m1.min(s.m2)) > 0.0;
    let [x, y, z] = s.n;
    let unit_ok = (x * x + y * y + z * z - 1.0).abs() <= 1e-6;
    if !finite_ok {
        return Err(Error::NotFinite);
    }
    if !positive_ok {
        return Err(Error::NotPositive);
    }
    if !unit_ok {
        return Err(Error::NotUnit);
    }
    Ok(())
}

fn get3(h: &[f64; HISTORY_MAX], at: usize) -> V3 {
    match h.get(at..at + 3) {
        Some(&[a, b, c]) => [a, b, c],
        _ => [0.0; 3],
    }
}

fn put3(h: &mut [f64; HISTORY_MAX], at: usize, v: V3) {
    if let Some(s) = h.get_mut(at..at + 3) {
        s.copy_from_slice(&v);
    }
}

/// The unchecked composition: `h` is the model's history (layout.len doubles used).
#[inline(always)]
pub(crate) fn evaluate(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    h: &mut [f64; HISTORY_MAX],
) -> ContactForce {
    let k = Kin::of(s);
    let pair = &m.normal;
    if !(s.overlap > 0.0) {
        // Not touching: the history is reset so that a new contact starts fresh (a normal law
        // with state keeps what its own force function leaves in its slot); only an adhesive
        // normal law still acts (no tangential, rolling or twisting force).
        let (f, kept) = match m.layout.normal_state {
            Some(at) => {
                let mut st = h.get(at).copied().unwrap_or(0.0);
                let f = stateful::force(
                    pair.kernel,
                    &pair.consts,
                    k.d,
                    k.vn,
                    k.r_eff,
                    k.m_eff,
                    &mut st,
                );
                (f, Some((at, st)))
            }
            None => (
                normal_force_raw(pair.kernel, pair.consts, k.d, k.vn, k.r_eff, k.m_eff),
                None,
            ),
        };
        *h = [0.0; HISTORY_MAX];
        if let Some((at, st)) = kept
            && let Some(x) = h.get_mut(at)
        {
            *x = st;
        }
        return ContactForce {
            fn_: f,
            force: normal_vector(f, k.n),
            ..ContactForce::default()
        };
    }
    let f = if let Some(slot) = m.layout.normal_state.and_then(|at| h.get_mut(at)) {
        stateful::force(pair.kernel, &pair.consts, k.d, k.vn, k.r_eff, k.m_eff, slot)
    } else {
        match m.layout.step.and_then(|at| h.get_mut(at)) {
            Some(slot) => step_exact::contact_normal(m, &k, dt, slot),
            None => normal_force_raw(pair.kernel, pair.consts, k.d, k.vn, k.r_eff, k.m_eff),
        }
    };
    let mut out = ContactForce {
        fn_: f,
        ..ContactForce::default()
    };
    if !m.layout.has_normal() && m.rolling == select::ROLLING_NONE {
        out.force = normal_vector(f, k.n);
        return out;
    }
    // The frame step reads the stored normal before it is replaced; only vector springs need
    // it (the tangential spring or the EPSD rolling torque).
    let frame = (m.layout.tangential.is_some() || m.layout.rolling.is_some())
        .then(|| Kin::frame(s, get3(h, 0), dt, m.carry));
    if m.layout.has_normal() {
        put3(h, 0, k.n);
    }
    // Operations in the order of the batch passes, so that both give the same bits (down to
    // the sign of zero).
    out.force = normal_vector(f, k.n);
    // The load of the Coulomb limits: |f|, or |f + 2 F_po| for an adhesive law.
    let fc = critical_load(pair.kernel, &pair.consts, k.r_eff, f);
    let (mut t1, mut t2) = ([0.0; 3], [0.0; 3]);
    if let (Some(at), Some(frame)) = (m.layout.tangential, &frame) {
        let rec = h.get_mut(at..).unwrap_or(&mut []);
        let t = select::tangential::dispatch!(
            m.tangential,
            |T| T::run(m, &k, fc, dt, frame, rec),
            TangentialOut {
                ft: [0.0; 3],
                sliding: false,
            },
        );
        out.ft = t.ft;
        out.sliding = t.sliding;
        out.force = add(out.force, t.ft);
        // Torques of the tangential force about each centre: the contact point is at −a1 n
        // from centre 1 and +a2 n from centre 2, so τ_i = −a_i n × F_t for both (body 2 gets
        // −F_t).
        let nft = cross(k.n, t.ft);
        t1 = scale(-k.a1, nft);
        if !k.wall {
            t2 = scale(-k.a2, nft);
        }
    }
    let mut moment = |mr: V3| {
        t1 = add(t1, mr);
        if !k.wall {
            t2 = sub(t2, mr);
        }
    };
    select::rolling::dispatch!(
        m.rolling,
        |EPSD| if !EPSD {
            let (t, on) = rolling_constant::torque(m, &k, fc);
            moment(t);
            out.rolling_sliding = on;
        } else if let (Some(at), Some(frame)) = (m.layout.rolling, &frame) {
            let kn = if m.k_r > 0.0 {
                0.0
            } else if m.layout.normal_state.is_some() {
                // A law with state has no dashpot: its force is elastic; p F/δ as for the
                // others (the secant of the branch it is on, scaled as Hertz's tangent).
                pair.p * f / k.d
            } else {
                // The normal law's elastic tangent stiffness p F_el/δ (vn = 0: no damping).
                let fe = normal_force_raw(pair.kernel, pair.consts, k.d, 0.0, k.r_eff, k.m_eff);
                pair.p * fe / k.d
            };
            let mut mk = get3(h, at);
            let (t, lim) = rolling_epsd::step(m, &k, fc, kn, dt, frame, &mut mk);
            put3(h, at, mk);
            moment(t);
            out.rolling_sliding = lim;
        },
        {},
    );
    if let Some(mk) = m.layout.twisting.and_then(|at| h.get_mut(at)) {
        let (t, lim) = twisting_sds::step(m, &k, fc, dt, mk);
        moment(scale(t, k.n));
        out.rolling_sliding |= lim;
    }
    out.torque1 = t1;
    out.torque2 = t2;
    out
}

/// One contact with every check; `history` (at least the model's length) is updated only on
/// success.
pub fn contact_force(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    history: &mut [f64],
) -> Result<ContactForce, Error> {
    check_model(m)?;
    contact_force_checked_model(m, s, dt, history)
}

/// [`contact_force`] and the energy ledger of the step ([`super::energy`]): what the dashpots
/// and slips removed, and the elastic energy left in the springs.
pub fn contact_force_energy(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    history: &mut [f64],
) -> Result<(ContactForce, ContactEnergy), Error> {
    check_model(m)?;
    checked_step::<true>(m, s, dt, history)
}

/// [`contact_force`] for a model that has passed [`check_model`] (or, at the C boundary,
/// [`check_model_parts`] on the fields it was built from): every other check is made.
#[inline(always)]
pub(crate) fn contact_force_checked_model(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    history: &mut [f64],
) -> Result<ContactForce, Error> {
    checked_step::<false>(m, s, dt, history).map(|(f, _)| f)
}

/// [`contact_force_energy`] for a model that has passed the model checks (as
/// [`contact_force_checked_model`]).
pub(crate) fn contact_force_energy_checked_model(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    history: &mut [f64],
) -> Result<(ContactForce, ContactEnergy), Error> {
    checked_step::<true>(m, s, dt, history)
}

/// The checked step; `ENERGY`: also the ledger (else a zero one, not computed).
#[inline(always)]
fn checked_step<const ENERGY: bool>(
    m: &ContactModel,
    s: &ContactState,
    dt: f64,
    history: &mut [f64],
) -> Result<(ContactForce, ContactEnergy), Error> {
    let len = m.layout.len;
    let hist = history.get_mut(..len).ok_or(Error::BufferTooShort)?;
    if !dt.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(dt > 0.0) {
        return Err(Error::NotPositive);
    }
    check_state(s)?;
    let mut h = [0.0; HISTORY_MAX];
    if let Some(dst) = h.get_mut(..len) {
        dst.copy_from_slice(hist);
    }
    if !all_finite(&h) {
        return Err(Error::NotFinite);
    }
    let old = h;
    let out = evaluate(m, s, dt, &mut h);
    let energy = if ENERGY {
        ledger(m, s, dt, &old, &h, &out)
    } else {
        ContactEnergy::default()
    };
    let [f1, f2, f3] = out.force;
    let [g1, g2, g3] = out.ft;
    let [t1, t2, t3] = out.torque1;
    let [u1, u2, u3] = out.torque2;
    let outs = [out.fn_, f1, f2, f3, g1, g2, g3, t1, t2, t3, u1, u2, u3];
    let ok = all_finite(&outs) & all_finite(&h) & (!ENERGY || all_finite(&energy.values()));
    if !ok {
        return Err(Error::ResultRange);
    }
    if let Some(src) = h.get(..len) {
        hist.copy_from_slice(src);
    }
    Ok((out, energy))
}
