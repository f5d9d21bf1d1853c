//! Power-law Tsuji contact with a fixed stiffness k per pair:
//! `F = k δ^p + α √(m k) δ^((p−1)/2) vn`, p ≥ 1 (p = 1 is the linear spring-dashpot).
//!
//! Per contact only δ, vn and the effective mass m vary, so the pair stores k and c = α √k and
//! each contact pays one √m. Exponent paths, all exact up to rounding (no `pow` for p = 1, 3/2, 2):
//! * p = 1:   k δ + c √m vn
//! * p = 3/2: with q = √δ, k δ q + c √(m q) vn   (δ^(1/4) √m = √(m √δ): two square roots)
//! * p = 2:   k δ² + c √(m δ) vn
//! * other p: with s = δ^((p−1)/2) (the one power), k δ s² + c √m s vn. The power is
//!   [`crate::numerics::pow_dd`]'s branch-free kernel (≤ 2 ulp from libm's `pow`,
//!   no libm call), so the batch loop vectorises it like the square roots.
//!
//! α comes from the exact calibration [`crate::powerlaw::alpha_from_e`] for the pair's end
//! criterion, which also decides clamping: `Force` clamps attractive force to zero, and its α is
//! the force-zero one, so a clamping solver realises the target e.

use super::pair::{Consts, Law, MODEL_POWERLAW, PairModel, SpecLaw, pick};
use crate::numerics::pow_dd::pow_dd;
use crate::powerlaw::{alpha_from_e, check_exponent, e_from_alpha};
use crate::{EndCriterion, Error};

pub(crate) struct LinElastic;
pub(crate) struct LinDamped;
pub(crate) struct P15Elastic;
pub(crate) struct P15Damped;
pub(crate) struct P2Elastic;
pub(crate) struct P2Damped;
pub(crate) struct GenElastic;
pub(crate) struct GenDamped;

impl Law for LinElastic {
    const NEEDS_VN: bool = false;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = false;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, _vn: f64, _r: f64, _m: f64) -> f64 {
        c.k * d
    }
}

impl Law for LinDamped {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, _r: f64, m: f64) -> f64 {
        c.k * d + c.c * m.sqrt() * vn
    }
}

impl Law for P15Elastic {
    const NEEDS_VN: bool = false;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = false;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, _vn: f64, _r: f64, _m: f64) -> f64 {
        c.k * d * d.sqrt()
    }
}

impl Law for P15Damped {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, _r: f64, m: f64) -> f64 {
        let q = d.sqrt();
        c.k * d * q + c.c * (m * q).sqrt() * vn
    }
}

impl Law for P2Elastic {
    const NEEDS_VN: bool = false;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = false;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, _vn: f64, _r: f64, _m: f64) -> f64 {
        c.k * d * d
    }
}

impl Law for P2Damped {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, _r: f64, m: f64) -> f64 {
        c.k * d * d + c.c * (m * d).sqrt() * vn
    }
}

impl Law for GenElastic {
    const NEEDS_VN: bool = false;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = false;
    const POW: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
        Self::raw_pow(c, d, vn, r, m, pow_dd(d, c.h))
    }
    #[inline(always)]
    fn raw_pow(c: &Consts, d: f64, _vn: f64, _r: f64, _m: f64, s: f64) -> f64 {
        // δ^p = δ (δ^h)², h = (p−1)/2: the same single power as the damped law.
        c.k * d * s * s
    }
}

impl Law for GenDamped {
    const NEEDS_VN: bool = true;
    const NEEDS_R: bool = false;
    const NEEDS_M: bool = true;
    const POW: bool = true;
    #[inline(always)]
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
        Self::raw_pow(c, d, vn, r, m, pow_dd(d, c.h))
    }
    #[inline(always)]
    fn raw_pow(c: &Consts, d: f64, vn: f64, _r: f64, m: f64, s: f64) -> f64 {
        c.k * d * s * s + c.c * m.sqrt() * s * vn
    }
    #[inline(always)]
    fn raw_fused(c: &Consts, d: f64, vn: f64, _r: f64, m: f64, s: f64) -> f64 {
        (c.k * d * s).mul_add(s, c.c * m.sqrt() * s * vn)
    }
}

fn check_stiffness(k: f64) -> Result<(), Error> {
    if !k.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(k > 0.0) {
        return Err(Error::NotPositive);
    }
    Ok(())
}

/// A power-law pair from its damping coefficient α directly (for hosts that already have α).
pub fn powerlaw_from_alpha(
    p: f64,
    k: f64,
    alpha: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    check_exponent(p)?;
    check_stiffness(k)?;
    // e_from_alpha validates α (finite, ≥ 0) and gives the e this pair realises.
    let e = e_from_alpha(alpha, p, criterion)?;
    let c = alpha * k.sqrt();
    if !c.is_finite() {
        return Err(Error::ResultRange);
    }
    let damped = alpha > 0.0;
    let kernel = if p == 1.0 {
        pick::<LinElastic, LinDamped>(damped, criterion)
    } else if p == 1.5 {
        pick::<P15Elastic, P15Damped>(damped, criterion)
    } else if p == 2.0 {
        pick::<P2Elastic, P2Damped>(damped, criterion)
    } else {
        pick::<GenElastic, GenDamped>(damped, criterion)
    };
    Ok(PairModel {
        model: MODEL_POWERLAW,
        kernel,
        criterion,
        p,
        stiffness: k,
        alpha,
        damping_a: 0.0,
        e,
        consts: Consts {
            k,
            c,
            h: 0.5 * (p - 1.0),
        },
    })
}

/// A power-law pair calibrated to restitution e (exact for the end criterion, speed independent).
pub fn powerlaw(p: f64, k: f64, e: f64, criterion: EndCriterion) -> Result<PairModel, Error> {
    check_exponent(p)?;
    check_stiffness(k)?;
    let alpha = alpha_from_e(e, p, criterion)?;
    let mut pair = powerlaw_from_alpha(p, k, alpha, criterion)?;
    // Keep the caller's target rather than the round-tripped value (they agree to ~1e-14).
    pair.e = e;
    Ok(pair)
}

/// The linear spring-dashpot `F = k δ + α √(m k) vn` (p = 1), calibrated to e.
pub fn linear(k: f64, e: f64, criterion: EndCriterion) -> Result<PairModel, Error> {
    powerlaw(1.0, k, e, criterion)
}

/// The power law of a contact specification (`DC_NORMAL_POWERLAW`).
pub(crate) struct Powerlaw;

/// The linear spring of a contact specification (`DC_NORMAL_LINEAR`).
pub(crate) struct Linear;

const K_N: crate::laws::Param = crate::laws::Param {
    field: "k_n",
    unit: "N/m^p",
    doc: "normal stiffness k_n > 0",
};

impl SpecLaw for Powerlaw {
    const DOC: &'static str = "Normal law: power law F = k_n d^p (fixed k_n, exponent p >= 1).";
    const MODEL_DOC: &'static str = "dc_pair.model of a power-law Tsuji pair with fixed stiffness (including the linear spring-dashpot, p = 1).";
    const MATERIALS: bool = false;
    const PARAMS: &'static [crate::laws::Param] = &[
        crate::laws::Param {
            field: "p",
            unit: "1",
            doc: "force-law exponent p >= 1",
        },
        K_N,
    ];
    const RESTITUTION: bool = true;
    const CLAMP: bool = true;
    fn build(
        s: &crate::contact::spec::ContactSpec,
        _kf: f64,
        e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        use crate::contact::spec::set;
        powerlaw(set(s.p)?, set(s.k_n)?, e_n, crit)
    }
}

impl SpecLaw for Linear {
    const DOC: &'static str = "Normal law: linear spring F = k_n d.";
    const MATERIALS: bool = false;
    const PARAMS: &'static [crate::laws::Param] = &[crate::laws::Param {
        field: "k_n",
        unit: "N/m",
        doc: "normal stiffness k_n > 0",
    }];
    const RESTITUTION: bool = true;
    const CLAMP: bool = true;
    fn build(
        s: &crate::contact::spec::ContactSpec,
        _kf: f64,
        e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        linear(crate::contact::spec::set(s.k_n)?, e_n, crit)
    }
}
