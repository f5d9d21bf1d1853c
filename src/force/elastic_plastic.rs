//! Elastic–perfectly-plastic normal contact (Thornton 1997, J. Appl. Mech. 64:383): Hertz up to
//! the yield overlap, then a linear plastic branch; unloading along a Hertz curve of enlarged
//! curvature that leaves a residual overlap. A normal law with state ([`super::stateful`]): one
//! double per contact, the largest overlap δ_max of the contact so far.
//!
//! With E* the effective modulus, R* the effective radius and p_y the limiting contact pressure
//! (the peak Hertz pressure 2E* a/(π R*) at which the contact stops being elastic):
//! * yield overlap   δ_y = (π p_y/(2E*))² R* (the Hertz contact radius a_y = π p_y R*/(2E*));
//! * loading (δ = δ_max ≤ δ_y): F = (4/3) E* √R* δ^{3/2} (Hertz);
//! * loading (δ = δ_max > δ_y): F = F_y + π p_y R* (δ − δ_y), F_y the Hertz force at δ_y;
//! * unloading and reloading (δ < δ_max, after yield): F = (4/3) E* √R_p (δ − δ_p)^{3/2} for
//!   δ > δ_p, else 0, with the contact radius at δ_max a_p = √(R* δ_max) (Thornton's a² = R* δ
//!   on loading), R_p = 4E* a_p³/(3F_max) (the unloading Hertz curve meets (δ_max, F_max) with
//!   contact radius a_p) and the residual overlap δ_p = δ_max − a_p²/R_p = δ_max −
//!   F_max/((4/3)E* a_p). Below yield the unloading curve is the loading curve (no loss).
//!
//! Reloading follows the unloading curve back to (δ_max, F_max), then the plastic branch: the
//! force is a function of (δ, δ_max) only, so a contact loaded twice to the same δ_max feels the
//! same force. No viscous damping: the only loss is the plastic work, which the energy ledger
//! reports as the normal loss of the step ([`dissipated`]).
//!
//! Restitution of a head-on impact at speed v (exact for this law, [`restitution`]):
//! e = 1 for v ≤ v_y, where ½ m* v_y² = (8/15) E* √R* δ_y^{5/2} (the Hertz energy at yield);
//! above, Thornton's closed form in v_y/v.
//!
//! Constants: k = (4/3) E*, c = π p_y, h = (π p_y/(2E*))² (so δ_y = h R*).

use super::pair::{Consts, PairModel, Registered, SpecLaw, StateLaw};
use crate::{EndCriterion, Error};

/// The elastic–plastic law of a contact specification (`DC_NORMAL_ELASTIC_PLASTIC`); its
/// registry line gives it its codes (`dc_pair.model` `DC_MODEL_ELASTIC_PLASTIC`, kernel
/// `DC_KERNEL_ELASTIC_PLASTIC`: a law with state, so no `dc_pair` path dispatches it).
pub(crate) struct ElasticPlastic;

impl SpecLaw for ElasticPlastic {
    const DOC: &'static str = "Normal law: elastic-perfectly-plastic (Thornton 1997): Hertz up to the limiting contact pressure yield_pressure = p_y (yield overlap d_y = (pi p_y/(2 E*))^2 R*), then F = F_y + pi p_y R* (d - d_y); unloading and reloading along a Hertz curve of enlarged radius with a residual overlap. One double of history (the largest overlap); no dashpot (damping must be DC_DAMPING_NONE: the loss is plastic, e(v) from dc_elastic_plastic_restitution). Contact models only: no dc_pair constructor, no step-aware form (DC_ERR_STEP_UNSUPPORTED).";
    const MATERIALS: bool = true;
    const PARAMS: &'static [crate::laws::Param] = &[crate::laws::Param {
        field: "yield_pressure",
        unit: "Pa",
        doc: "limiting contact pressure p_y > 0",
    }];
    // The plastic work is this law's loss; a restitution target would be ignored.
    const RESTITUTION: bool = false;
    const CLAMP: bool = true;
    const MODEL_DOC: &'static str = "dc_pair.model of an elastic-plastic pair (the normal law of a dc_contact_model built with DC_NORMAL_ELASTIC_PLASTIC). Its force needs per-contact state (the largest overlap), so it exists only inside a contact model: there is no dc_pair_* constructor, and every dc_pair path refuses its kernel (DC_ERR_PAIR_INVALID; NaN from the unchecked dc_normal_force).";
    fn build(
        s: &crate::contact::spec::ContactSpec,
        kf: f64,
        _e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        elastic_plastic_from_factor(kf, crate::contact::spec::set(s.yield_pressure)?, crit)
    }
}

impl StateLaw for ElasticPlastic {
    #[inline(always)]
    fn force(c: &Consts, d: f64, _vn: f64, r: f64, _m: f64, dmax: &mut f64) -> f64 {
        force(c, d, r, dmax)
    }
    #[inline(always)]
    fn dissipated(c: &Consts, r: f64, old: f64, new: f64) -> f64 {
        dissipated(c, r, old, new)
    }
}

/// (δ_y, F_y, F_max, δ_p, R_p-term) of a contact that has yielded: δ_max > δ_y. Returns
/// (F_max, δ_p, kp) with the unloading curve F = kp (δ − δ_p)^{3/2}, kp = (4/3)E* √R_p.
#[inline(always)]
fn unloading(c: &Consts, r: f64, dmax: f64) -> (f64, f64, f64) {
    let dy = c.h * r;
    let fy = c.k * (r * dy).sqrt() * dy;
    let fmax = fy + c.c * r * (dmax - dy);
    let ap = (r * dmax).sqrt();
    // R_p = k a_p³/F_max; δ_max − δ_p = a_p²/R_p = F_max/(k a_p); kp = k √R_p.
    let rp = c.k * ap * ap * ap / fmax;
    let dp = dmax - fmax / (c.k * ap);
    (fmax, dp, c.k * rp.sqrt())
}

/// The force at overlap `d` for a contact whose largest overlap so far is `*dmax` (updated to
/// max(*dmax, d)); out of contact (d ≤ 0, or NaN) the force is 0 and the state resets to 0.
#[inline(always)]
pub(crate) fn force(c: &Consts, d: f64, r: f64, dmax: &mut f64) -> f64 {
    if !(d > 0.0) {
        *dmax = 0.0;
        return 0.0;
    }
    let m = if d > *dmax { d } else { *dmax };
    *dmax = m;
    let dy = c.h * r;
    if m <= dy {
        return c.k * (r * d).sqrt() * d;
    }
    if d >= m {
        let fy = c.k * (r * dy).sqrt() * dy;
        return fy + c.c * r * (d - dy);
    }
    let (_, dp, kp) = unloading(c, r, m);
    let s = d - dp;
    if s > 0.0 { kp * s.sqrt() * s } else { 0.0 }
}

/// D(δ_max): the work lost by a contact loaded to δ_max = the work of the loading curve minus
/// the elastic energy the unloading curve returns, (2/5) F_max (δ_max − δ_p). 0 below yield.
#[inline(always)]
fn lost(c: &Consts, r: f64, dmax: f64) -> f64 {
    let dy = c.h * r;
    if !(dmax > dy) {
        return 0.0;
    }
    let fy = c.k * (r * dy).sqrt() * dy;
    let x = dmax - dy;
    let w_load = 0.4 * fy * dy + fy * x + 0.5 * c.c * r * x * x;
    let (fmax, dp, _) = unloading(c, r, dmax);
    w_load - 0.4 * fmax * (dmax - dp)
}

/// The plastic work of a step that took the state from `old` to `new` δ_max (exact: the work
/// along the path minus the change of the elastic energy stored in the unloading curve);
/// 0 when δ_max did not grow (also on the reset at the end of a contact, whose loss was
/// counted while it was loaded).
#[inline(always)]
pub(crate) fn dissipated(c: &Consts, r: f64, old: f64, new: f64) -> f64 {
    if new > old {
        lost(c, r, new) - lost(c, r, old.max(0.0))
    } else {
        0.0
    }
}

/// The elastic energy stored at overlap d with state δ_max (the work the unloading curve
/// returns from d to its end): (2/5) F(d) (d − δ_p) after yield, Hertz's (2/5) F d before.
pub fn stored_energy(c: &Consts, d: f64, r: f64, dmax: f64) -> f64 {
    if !(d > 0.0) {
        return 0.0;
    }
    let mut m = dmax;
    let f = force(c, d, r, &mut m);
    let dy = c.h * r;
    if m <= dy {
        return 0.4 * f * d;
    }
    let (_, dp, _) = unloading(c, r, m);
    if d > dp { 0.4 * f * (d - dp) } else { 0.0 }
}

/// Thornton's (1997) restitution of the elastic–plastic law at impact speed v over the yield
/// speed v_y, x = v/v_y ≥ 0 (finite): 1 for x ≤ 1, else with y = v_y/v
///   e = (6√3/5)^{1/2} [1 − y²/6]^{1/2} [y/(y + 2√(6/5 − y²/5))]^{1/4}.
pub fn restitution(x: f64) -> Result<f64, Error> {
    if !x.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(x >= 0.0) {
        return Err(Error::Negative);
    }
    if x <= 1.0 {
        return Ok(1.0);
    }
    let y = 1.0 / x;
    let a = (6.0 * 3f64.sqrt() / 5.0).sqrt();
    let b = (1.0 - y * y / 6.0).sqrt();
    let q = y / (y + 2.0 * (6.0 / 5.0 - y * y / 5.0).sqrt());
    // The formula is 1 at x = 1 and falls from there; just above 1 its roundings can land an
    // ulp or two above 1 (1.0000000000000004 at x = 1.0000000000001885), outside (0, 1].
    Ok((a * b * q.sqrt().sqrt()).min(1.0))
}

/// The yield speed v_y [m/s] of a head-on impact: ½ m* v_y² = (8/15) E* √R* δ_y^{5/2},
/// δ_y = (π p_y/(2E*))² R*, from E* [Pa], R* [m], m* [kg] and p_y [Pa] (all finite, > 0).
pub fn yield_speed(e_star: f64, r: f64, m: f64, p_y: f64) -> Result<f64, Error> {
    let all = [e_star, r, m, p_y];
    if !all.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    if !all.iter().all(|&x| x > 0.0) {
        return Err(Error::NotPositive);
    }
    let dy = (core::f64::consts::PI * p_y / (2.0 * e_star)).powi(2) * r;
    let v = (16.0 / 15.0 * e_star * r.sqrt() * dy * dy * dy.sqrt() / m).sqrt();
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Error::ResultRange)
    }
}

/// The limiting contact pressure p_y [Pa] whose yield speed ([`yield_speed`]) is v_y, from
/// E* [Pa], R* [m], m* [kg] and v_y [m/s] (all finite, > 0): δ_y = (15 m* v_y²/(16 E* √R*))^{2/5},
/// p_y = (2E*/π) √(δ_y/R*).
pub fn yield_pressure_from_speed(e_star: f64, r: f64, m: f64, v_y: f64) -> Result<f64, Error> {
    let all = [e_star, r, m, v_y];
    if !all.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    if !all.iter().all(|&x| x > 0.0) {
        return Err(Error::NotPositive);
    }
    let dy = (15.0 * m * v_y * v_y / (16.0 * e_star * r.sqrt())).powf(0.4);
    let p = 2.0 * e_star / core::f64::consts::PI * (dy / r).sqrt();
    if p.is_finite() && p > 0.0 {
        Ok(p)
    } else {
        Err(Error::ResultRange)
    }
}

/// An elastic–plastic pair from kf = (4/3) E* (finite, > 0; checked by the caller) and the
/// limiting contact pressure p_y (finite, > 0). Only `EndCriterion::Overlap` is meaningful
/// (the force is never attractive): both criteria are accepted and give the same law.
pub fn elastic_plastic_from_factor(
    kf: f64,
    p_y: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    if !p_y.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(p_y > 0.0) {
        return Err(Error::NotPositive);
    }
    let c = core::f64::consts::PI * p_y;
    // π p_y/(2E*) = π p_y · (2/3)/kf.
    let q = c * (2.0 / 3.0) / kf;
    let h = q * q;
    if !(c.is_finite() && h.is_finite() && h > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(PairModel {
        model: ElasticPlastic::MODEL,
        kernel: ElasticPlastic::STATE_KERNEL,
        criterion,
        p: 1.5,
        stiffness: kf,
        alpha: 0.0,
        damping_a: 0.0,
        e: f64::NAN,
        consts: Consts { k: kf, c, h },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn restitution_is_one_at_yield_and_decreasing() {
        assert_eq!(restitution(1.0), Ok(1.0));
        assert!((restitution(1.0 + 1e-12).unwrap() - 1.0).abs() < 1e-5);
        let mut prev = 1.0;
        for i in 1..100 {
            let e = restitution(1.0 + i as f64).unwrap();
            assert!(e < prev);
            prev = e;
        }
    }
}
