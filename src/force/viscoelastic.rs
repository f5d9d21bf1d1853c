//! Viscoelastic Hertz contact (Brilliantov, Spahn, Hertzsch, Pöschel 1996; Schwager & Pöschel
//! 2008, eqs. 13–14): `F = ρ ξ^(3/2) + (3/2) A ρ √ξ ξ'` with ρ = (4/3) E* √R_eff.
//!
//! The seed writes ρ = 2Y √R_eff / (3(1 − ν²)) for two spheres of one material; with
//! E* = Y/(2(1 − ν²)) for identical materials that is (4/3) E* √R_eff, which is the form used
//! here for two materials. With kf = (4/3) E* and q = √(R ξ):
//! `F = kf q (ξ + (3/2) A ξ')` — one square root per contact, no mass needed.
//!
//! The damping constant A [s] is given directly: its calibration from a measured e(v) is a
//! separate problem (e depends on impact speed for this model). The criterion only decides
//! clamping (`Force`: attractive force clamped to zero, the physically consistent choice of
//! Schwager & Pöschel).

use super::hertz::{HertzElastic, hertz_factor};
use super::pair::{Consts, Law, MODEL_VISCOELASTIC, PairModel, SpecLaw, pick};
use crate::{EndCriterion, Error};

pub(crate) struct Viscoelastic;

impl Law for Viscoelastic {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = true;
    const NEEDS_M: bool = false;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, _m: f64) -> f64 {
        c.k * (r * d).sqrt() * (d + c.c * vn)
    }
}

/// A viscoelastic pair of materials (E1, ν1), (E2, ν2) with damping constant A ≥ 0 [s].
/// A = 0 gives the purely elastic Hertz kernel.
pub fn viscoelastic(
    e1: f64,
    nu1: f64,
    e2: f64,
    nu2: f64,
    a: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    viscoelastic_from_factor(hertz_factor(e1, nu1, e2, nu2)?, a, criterion)
}

/// A viscoelastic pair from kf = (4/3) E* (finite, > 0; checked by the caller) and A ≥ 0 [s].
pub fn viscoelastic_from_factor(
    kf: f64,
    a: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    if !a.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(a >= 0.0) {
        return Err(Error::Negative);
    }
    let c = 1.5 * a;
    if !c.is_finite() {
        return Err(Error::ResultRange);
    }
    let kernel = pick::<HertzElastic, Viscoelastic>(a > 0.0, criterion);
    Ok(PairModel {
        model: MODEL_VISCOELASTIC,
        kernel,
        criterion,
        p: 1.5,
        stiffness: kf,
        alpha: 0.0,
        damping_a: a,
        e: f64::NAN,
        consts: Consts { k: kf, c, h: 0.25 },
    })
}

/// The viscoelastic law of a contact specification (`DC_NORMAL_VISCOELASTIC`): its damping is
/// A, so a restitution target (which it would ignore) is refused.
pub(crate) struct Visco;

impl SpecLaw for Visco {
    const DOC: &'static str =
        "Normal law: viscoelastic Hertz (Brilliantov et al.) with damping constant visco_A.";
    const MATERIALS: bool = true;
    const PARAMS: &'static [crate::laws::Param] = &[crate::laws::Param {
        field: "visco_A",
        unit: "s",
        doc: "viscoelastic damping constant A >= 0",
    }];
    const RESTITUTION: bool = false;
    const CLAMP: bool = true;
    const MODEL_DOC: &'static str =
        "dc_pair.model of a viscoelastic Hertz pair (Brilliantov et al.).";
    fn build(
        s: &crate::contact::spec::ContactSpec,
        kf: f64,
        _e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        viscoelastic_from_factor(kf, crate::contact::spec::set(s.visco_a)?, crit)
    }
}
