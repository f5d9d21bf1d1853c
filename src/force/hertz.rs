//! Hertz contact from material data: the stiffness varies per contact with the effective radius,
//! k = (4/3) E* √R*, so `F = k δ^(3/2) + α √(m k) δ^(1/4) vn`.
//!
//! With kf = (4/3) E* stored per pair and q = √(R* δ) per contact:
//! * elastic: k δ^(3/2) = kf √R* δ^(3/2) = kf q δ;
//! * damping: √(m k) δ^(1/4) = √(m kf) R*^(1/4) δ^(1/4) = √kf · √(m q).
//!
//! So one contact costs two square roots (q and √(m q)) and no `pow`; c = α √kf per pair. α is
//! the exact p = 3/2 calibration (speed independent: one α per pair).

use super::pair::{Consts, Law, MODEL_HERTZ, PairModel, SpecLaw, pick};
use crate::material::effective_modulus;
use crate::powerlaw::alpha_from_e;
use crate::{EndCriterion, Error};

/// The Hertz law of a contact specification (`DC_NORMAL_HERTZ`).
pub(crate) struct Hertz;

impl SpecLaw for Hertz {
    const DOC: &'static str =
        "Normal law: Hertz from E, nu of both bodies, k = (4/3) E* sqrt(R*) per contact.";
    const MATERIALS: bool = true;
    const PARAMS: &'static [crate::laws::Param] = &[];
    const RESTITUTION: bool = true;
    const CLAMP: bool = true;
    const MODEL_DOC: &'static str =
        "dc_pair.model of a Hertz pair from material data (k = (4/3) E* sqrt(R*) per contact).";
    fn build(
        _s: &crate::contact::spec::ContactSpec,
        kf: f64,
        e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        hertz_from_factor(kf, e_n, crit)
    }
}

pub(crate) struct HertzElastic;
pub(crate) struct HertzDamped;

impl Law for HertzElastic {
    const NEEDS_VN: bool = false;
    const NEEDS_R: bool = true;
    const NEEDS_M: bool = false;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, _vn: f64, r: f64, _m: f64) -> f64 {
        c.k * (r * d).sqrt() * d
    }
}

impl Law for HertzDamped {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = true;
    const NEEDS_M: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
        let q = (r * d).sqrt();
        c.k * q * d + c.c * (m * q).sqrt() * vn
    }
    #[inline(always)]
    fn raw_fused(c: &Consts, d: f64, vn: f64, r: f64, m: f64, _s: f64) -> f64 {
        let q = (r * d).sqrt();
        (c.k * q).mul_add(d, c.c * (m * q).sqrt() * vn)
    }
}

/// (4/3) E* for two materials, checked finite.
pub(crate) fn hertz_factor(e1: f64, nu1: f64, e2: f64, nu2: f64) -> Result<f64, Error> {
    let kf = 4.0 / 3.0 * effective_modulus(e1, nu1, e2, nu2)?;
    if !kf.is_finite() {
        return Err(Error::ResultRange);
    }
    Ok(kf)
}

/// A Hertz pair of materials (E1, ν1), (E2, ν2) calibrated to restitution e.
pub fn hertz(
    e1: f64,
    nu1: f64,
    e2: f64,
    nu2: f64,
    e: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    hertz_from_factor(hertz_factor(e1, nu1, e2, nu2)?, e, criterion)
}

/// A Hertz pair from kf = (4/3) E* (finite, > 0; checked by the caller) calibrated to e.
pub fn hertz_from_factor(kf: f64, e: f64, criterion: EndCriterion) -> Result<PairModel, Error> {
    let alpha = alpha_from_e(e, 1.5, criterion)?;
    let c = alpha * kf.sqrt();
    if !c.is_finite() {
        return Err(Error::ResultRange);
    }
    let kernel = pick::<HertzElastic, HertzDamped>(alpha > 0.0, criterion);
    Ok(PairModel {
        model: MODEL_HERTZ,
        kernel,
        criterion,
        p: 1.5,
        stiffness: kf,
        alpha,
        damping_a: 0.0,
        e,
        consts: Consts { k: kf, c, h: 0.25 },
    })
}
