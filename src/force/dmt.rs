//! Adhesive DMT contact (Derjaguin, Muller & Toporov 1975): the Hertz force minus a constant
//! pull-off force 2π w R* (w the work of adhesion [J/m²]), never clamped to zero:
//!   d > 0:             F = (4/3) E* √R* d^{3/2} − 2π w R* [+ Hertz damping α √(m k) d^{1/4} vn]
//!   −d_c < d ≤ 0:      F = −2π w R* (1 + d/d_c)          (attraction beyond touching)
//!   d ≤ −d_c (or NaN): F = 0                              (separated)
//! with the DMT length d_c = (3π w √R*/(2 E*))^{2/3}, the overlap at which the Hertz force equals
//! the pull-off force: the attraction decays linearly to zero over one d_c of separation, so the
//! force is continuous everywhere (no jump at d = 0 or at d = −d_c) and the pull-off (most
//! attractive) force is the DMT value 2π w R*, reached at d = 0. This range is a modelling
//! decision (DMT theory has the surface forces act outside the contact over a range of the
//! order of the interatomic distance; the model needs a finite range that scales with the
//! contact, and d_c is the one length the law itself defines). Work done by the tail:
//! π w R* d_c.
//!
//! Damping (optional) is Hertz's, with α calibrated for the non-adhesive Hertz contact: with
//! adhesion the realised restitution differs (documented approximation). An adhesive law is
//! never clamped (clamping would remove the adhesion): only `DC_END_OVERLAP` is accepted.
//!
//! Constants: k = (4/3) E*, c = α √k (0 undamped), h = 2π w. Per contact in contact: 2 square
//! roots as Hertz; in the tail one power (`pow_dd`, the library's own: the same bits in the
//! header and on a GPU).

use super::pair::{Consts, Law, PairModel, Registered, SpecLaw, pick};
use crate::numerics::pow_dd::pow_dd;
use crate::powerlaw::alpha_from_e;
use crate::{EndCriterion, Error};

/// The DMT law of a contact specification (`DC_NORMAL_DMT`); its registry line gives it its
/// codes (`dc_pair.model`: `DC_MODEL_DMT`).
pub(crate) struct Dmt;

impl SpecLaw for Dmt {
    const DOC: &'static str = "Normal law: adhesive DMT, Hertz minus 2 pi w R* (w = work_of_adhesion), attraction also beyond touching (decaying linearly to 0 over d_c = (3 pi w sqrt(R*)/(2 E*))^(2/3) of separation); never clamped: requires DC_END_OVERLAP. Coulomb, rolling and twisting limits (while d > 0) on the adhesion-corrected load |F_n + 4 pi w R*|.";
    const MATERIALS: bool = true;
    const PARAMS: &'static [crate::laws::Param] = &[crate::laws::Param {
        field: "work_of_adhesion",
        unit: "J/m^2",
        doc: "work of adhesion w >= 0 (pull-off force 2 pi w R*)",
    }];
    const RESTITUTION: bool = true;
    const CLAMP: bool = false;
    const MODEL_DOC: &'static str = "dc_pair.model of an adhesive DMT pair (the normal law of a dc_contact_model built with DC_NORMAL_DMT; there is no dc_pair_* constructor for it).";
    fn build(
        s: &crate::contact::spec::ContactSpec,
        kf: f64,
        e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        dmt_from_factor(
            kf,
            crate::contact::spec::set(s.work_of_adhesion)?,
            e_n,
            crit,
        )
    }
}

pub(crate) struct DmtElastic;
pub(crate) struct DmtDamped;

/// The attraction beyond touching (d ≤ 0): −h r (1 + d/d_c), d_c = (h √r/k)^{2/3}; 0 beyond −d_c
/// and for NaN d.
#[inline(always)]
fn tail(c: &Consts, d: f64, r: f64) -> f64 {
    let dc = reach(c, r);
    let s = 1.0 + d / dc;
    if s > 0.0 { -c.h * r * s } else { 0.0 }
}

/// The tail's length d_c = (h √r/k)^{2/3} = (3π w √R*/(2E*))^{2/3} [m]: the law's reach
/// beyond touching (0 for w = 0). The power is the library's own `pow_dd` (the header's
/// `dc_pow_inline`), not libm's, so that the header gives these bits on a GPU too.
#[inline(always)]
pub fn reach(c: &Consts, r: f64) -> f64 {
    // pow_dd gives a finite number for a NaN argument (r < 0 or NaN in the unchecked force
    // call): NaN kept, so that the tail gives no force there, as libm's pow did.
    let x = c.h * r.sqrt() / c.k;
    if x >= 0.0 { pow_dd(x, 2.0 / 3.0) } else { x }
}

/// The critical load of the Coulomb limits (see [`Law::critical_load`]): |F + 2 F_po| with the
/// pull-off force F_po = 2π w R* = h r and F the applied force (dashpot included): in contact
/// the Hertz force (+ dashpot) + 2π w R*. The decision and LAMMPS's convention: docs/force.md,
/// "Friction with adhesion".
#[inline(always)]
pub fn critical_load(c: &Consts, r: f64, f: f64) -> f64 {
    (f + 2.0 * (c.h * r)).abs()
}

impl Law for DmtElastic {
    const NEEDS_VN: bool = false;
    const NEEDS_R: bool = true;
    const NEEDS_M: bool = false;
    const ADHESIVE: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, _vn: f64, r: f64, _m: f64) -> f64 {
        if d > 0.0 {
            c.k * (r * d).sqrt() * d - c.h * r
        } else {
            tail(c, d, r)
        }
    }
    #[inline(always)]
    fn critical_load(c: &Consts, r: f64, f: f64) -> f64 {
        critical_load(c, r, f)
    }
    fn reach(c: &Consts, r: f64) -> f64 {
        reach(c, r)
    }
}

impl Law for DmtDamped {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = true;
    const NEEDS_M: bool = true;
    const ADHESIVE: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
        if d > 0.0 {
            let q = (r * d).sqrt();
            c.k * q * d + c.c * (m * q).sqrt() * vn - c.h * r
        } else {
            tail(c, d, r)
        }
    }
    #[inline(always)]
    fn critical_load(c: &Consts, r: f64, f: f64) -> f64 {
        critical_load(c, r, f)
    }
    fn reach(c: &Consts, r: f64) -> f64 {
        reach(c, r)
    }
}

/// A DMT pair from kf = (4/3) E* (finite, > 0; checked by the caller), the work of adhesion
/// w ≥ 0 [J/m²] and the target restitution e of the non-adhesive Hertz damping (1: undamped).
/// Only `EndCriterion::Overlap` (no clamping) is accepted.
pub fn dmt_from_factor(
    kf: f64,
    w: f64,
    e: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    if !w.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(w >= 0.0) {
        return Err(Error::Negative);
    }
    if criterion != EndCriterion::Overlap {
        return Err(Error::SpecModel);
    }
    let alpha = alpha_from_e(e, 1.5, criterion)?;
    let c = alpha * kf.sqrt();
    let h = 2.0 * core::f64::consts::PI * w;
    if !(c.is_finite() && h.is_finite()) {
        return Err(Error::ResultRange);
    }
    Ok(PairModel {
        model: Dmt::MODEL,
        kernel: pick::<DmtElastic, DmtDamped>(alpha > 0.0, criterion),
        criterion,
        p: 1.5,
        stiffness: kf,
        alpha,
        damping_a: 0.0,
        e,
        consts: Consts { k: kf, c, h },
    })
}
