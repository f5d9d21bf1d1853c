//! One contact through every stage of a model: normal kernel → tangential → rolling →
//! twisting. Each stage picks its monomorphised law once per call (a jump), so a contact pays
//! only for the stages its model switches on.

use super::kinematics::{ContactState, Kin};
use super::model::{ContactModel, HISTORY_MAX, select};
use super::tangential::{TangentialOut, step};
use super::tangential_linear::Linear;
use super::tangential_mindlin::Mindlin;
use super::vec3::{V3, add, cross, finite, normal_vector, scale, sub};
use super::{rolling_constant, rolling_epsd, twisting_sds};
use crate::Error;
use crate::force::registry::{needs, normal_force_raw};

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
    needs(m.normal.kernel).ok_or(Error::ContactModelInvalid)?;
    let codes_ok = matches!(
        m.tangential,
        select::TANGENTIAL_NONE | select::TANGENTIAL_LINEAR | select::TANGENTIAL_MINDLIN
    ) && matches!(
        m.rolling,
        select::ROLLING_NONE | select::ROLLING_CONSTANT | select::ROLLING_EPSD
    ) && matches!(m.twisting, select::TWISTING_NONE | select::TWISTING_SDS);
    let consts = [
        m.normal.consts.k,
        m.normal.consts.c,
        m.normal.consts.h,
        m.mu,
        m.kt,
        m.zeta_t,
        m.kappa,
        m.mu_r,
        m.k_r,
        m.eta_r,
        m.mu_tw,
        m.k_tw,
        m.eta_tw,
    ];
    let consts_ok = consts.iter().all(|x| x.is_finite() && *x >= 0.0);
    let layout_ok = m.layout == super::model::Layout::of(m.tangential, m.rolling, m.twisting)
        && m.layout.len <= HISTORY_MAX;
    if !(codes_ok && consts_ok && layout_ok && m.kappa > 0.0) {
        return Err(Error::ContactModelInvalid);
    }
    if m.tangential != select::TANGENTIAL_NONE && !(m.kt > 0.0) {
        return Err(Error::ContactModelInvalid);
    }
    Ok(())
}

/// Checks a state: finite values (r2, m2 may be +∞), positive radii and masses, unit normal.
pub(crate) fn check_state(s: &ContactState) -> Result<(), Error> {
    let body2 = |x: f64| x.is_finite() || x == f64::INFINITY;
    if !(finite(s.n)
        && s.overlap.is_finite()
        && finite(s.v1)
        && finite(s.v2)
        && finite(s.w1)
        && finite(s.w2)
        && s.r1.is_finite()
        && s.m1.is_finite()
        && body2(s.r2)
        && body2(s.m2))
    {
        return Err(Error::NotFinite);
    }
    if !(s.r1 > 0.0 && s.r2 > 0.0 && s.m1 > 0.0 && s.m2 > 0.0) {
        return Err(Error::NotPositive);
    }
    let [x, y, z] = s.n;
    if !((x * x + y * y + z * z - 1.0).abs() <= 1e-6) {
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
    let (k, frame) = Kin::of(s, get3(h, 0), dt);
    let pair = &m.normal;
    let f = normal_force_raw(pair.kernel, pair.consts, k.d, k.vn, k.r_eff, k.m_eff);
    if !(s.overlap > 0.0) {
        // Not touching: the history is reset so that a new contact starts fresh; only an
        // adhesive normal law still acts (no tangential, rolling or twisting force).
        *h = [0.0; HISTORY_MAX];
        return ContactForce {
            fn_: f,
            force: normal_vector(f, k.n),
            ..ContactForce::default()
        };
    }
    let mut out = ContactForce {
        fn_: f,
        ..ContactForce::default()
    };
    if m.layout.len == 0 && m.rolling == select::ROLLING_NONE {
        out.force = normal_vector(f, k.n);
        return out;
    }
    if m.layout.len > 0 {
        put3(h, 0, k.n);
    }
    // Operations in the order of the batch passes, so that both give the same bits (down to
    // the sign of zero).
    out.force = normal_vector(f, k.n);
    let (mut t1, mut t2) = ([0.0; 3], [0.0; 3]);
    if let Some(at) = m.layout.tangential {
        let mut xi = get3(h, at);
        let t = match m.tangential {
            select::TANGENTIAL_LINEAR => step::<Linear>(m, &k, f, dt, &frame, &mut xi),
            select::TANGENTIAL_MINDLIN => step::<Mindlin>(m, &k, f, dt, &frame, &mut xi),
            _ => TangentialOut {
                ft: [0.0; 3],
                sliding: false,
            },
        };
        put3(h, at, xi);
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
    match m.rolling {
        select::ROLLING_CONSTANT => {
            let (t, on) = rolling_constant::torque(m, &k, f);
            moment(t);
            out.rolling_sliding = on;
        }
        select::ROLLING_EPSD => {
            if let Some(at) = m.layout.rolling {
                let kn = if m.k_r > 0.0 {
                    0.0
                } else {
                    // The normal law's elastic tangent stiffness p F_el/δ (vn = 0: no damping).
                    let fe = normal_force_raw(pair.kernel, pair.consts, k.d, 0.0, k.r_eff, k.m_eff);
                    pair.p * fe / k.d
                };
                let mut mk = get3(h, at);
                let (t, lim) = rolling_epsd::step(m, &k, f, kn, dt, &frame, &mut mk);
                put3(h, at, mk);
                moment(t);
                out.rolling_sliding = lim;
            }
        }
        _ => {}
    }
    if let Some(mk) = m.layout.twisting.and_then(|at| h.get_mut(at)) {
        let (t, lim) = twisting_sds::step(m, &k, f, dt, mk);
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
    if !h.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    let out = evaluate(m, s, dt, &mut h);
    let ok = out.fn_.is_finite()
        && finite(out.force)
        && finite(out.ft)
        && finite(out.torque1)
        && finite(out.torque2)
        && h.iter().all(|x| x.is_finite());
    if !ok {
        return Err(Error::ResultRange);
    }
    if let Some(src) = h.get(..len) {
        hist.copy_from_slice(src);
    }
    Ok(out)
}
