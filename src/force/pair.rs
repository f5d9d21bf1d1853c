//! The pair model: kernel codes, per-pair constants, and the one place that turns a law's raw
//! force into the contact force (zero without overlap, optional clamp of attraction).

use super::hertz::{HertzDamped, HertzElastic};
use super::powerlaw::{
    GenDamped, GenElastic, LinDamped, LinElastic, P2Damped, P2Elastic, P15Damped, P15Elastic,
};
use super::viscoelastic::Viscoelastic;
use crate::EndCriterion;

/// Model families, as stored in `dc_pair.model` (the C constants `DC_MODEL_*` equal these).
pub(crate) const MODEL_POWERLAW: i32 = 1;
pub(crate) const MODEL_HERTZ: i32 = 2;
pub(crate) const MODEL_VISCOELASTIC: i32 = 3;

/// Kernel codes: one per (law, damping, clamping) combination that a pair can need. Zero is
/// deliberately invalid so that a zero-initialised `dc_pair` is rejected, not silently elastic.
pub(crate) mod code {
    pub(crate) const LIN_ELASTIC: i32 = 1;
    pub(crate) const LIN_DAMPED: i32 = 2;
    pub(crate) const LIN_DAMPED_CLAMPED: i32 = 3;
    pub(crate) const P15_ELASTIC: i32 = 4;
    pub(crate) const P15_DAMPED: i32 = 5;
    pub(crate) const P15_DAMPED_CLAMPED: i32 = 6;
    pub(crate) const P2_ELASTIC: i32 = 7;
    pub(crate) const P2_DAMPED: i32 = 8;
    pub(crate) const P2_DAMPED_CLAMPED: i32 = 9;
    pub(crate) const GEN_ELASTIC: i32 = 10;
    pub(crate) const GEN_DAMPED: i32 = 11;
    pub(crate) const GEN_DAMPED_CLAMPED: i32 = 12;
    pub(crate) const HERTZ_ELASTIC: i32 = 13;
    pub(crate) const HERTZ_DAMPED: i32 = 14;
    pub(crate) const HERTZ_DAMPED_CLAMPED: i32 = 15;
    pub(crate) const VISCO_DAMPED: i32 = 16;
    pub(crate) const VISCO_DAMPED_CLAMPED: i32 = 17;
}

/// The three numbers a kernel needs per pair (their meaning depends on the law; see each law).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Consts {
    /// Elastic prefactor: k (fixed-stiffness laws) or (4/3) E* (laws with k = (4/3) E* √R*).
    pub k: f64,
    /// Damping prefactor: α √k (Tsuji laws), α √((4/3) E*) (Hertz), (3/2) A (viscoelastic).
    pub c: f64,
    /// Damping exponent (p − 1)/2 of the general-p law; unused by the others.
    pub h: f64,
}

/// A calibrated pair model: what `dc_pair` carries, in Rust form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairModel {
    /// Model family (`MODEL_*`).
    pub model: i32,
    /// Kernel code selected at construction.
    pub kernel: i32,
    /// End criterion; `Force` means attractive forces are clamped to zero.
    pub criterion: EndCriterion,
    /// Force-law exponent.
    pub p: f64,
    /// k [N/m^p] for fixed-stiffness pairs, (4/3) E* [Pa] for per-contact Hertz stiffness.
    pub stiffness: f64,
    /// Tsuji damping coefficient α (0 for the viscoelastic model).
    pub alpha: f64,
    /// Viscoelastic damping constant A [s] (0 for the other models).
    pub damping_a: f64,
    /// Target restitution (NaN for the viscoelastic model, whose e depends on impact speed).
    pub e: f64,
    /// Kernel constants.
    pub consts: Consts,
}

/// One contact law: the raw force for an overlap d > 0, before clamping.
///
/// The `NEEDS_*` flags say which per-contact arrays the law reads, so a batch does not require
/// (or touch) arrays the pair does not need.
pub(crate) trait Law {
    const NEEDS_VN: bool;
    const NEEDS_R: bool;
    const NEEDS_M: bool;
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64;
}

/// The contact force of law `L`: zero unless d > 0 (also for NaN d); with `CLAMP`, attractive
/// (and NaN) raw forces become zero. Written as selects so that batch loops vectorise.
#[inline(always)]
pub(crate) fn eval<L: Law, const CLAMP: bool>(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
    let f = L::raw(c, d, vn, r, m);
    let f = if CLAMP {
        if f > 0.0 { f } else { 0.0 }
    } else {
        f
    };
    if d > 0.0 { f } else { 0.0 }
}

/// Something to do with one monomorphised kernel (a scalar evaluation or a batch loop).
pub(crate) trait Visit {
    type Out;
    fn visit<L: Law, const CLAMP: bool>(self) -> Self::Out;
}

/// The only branch on the model kind: picks the monomorphised kernel for `kernel` once.
/// `None` for an unknown code (a `dc_pair` not made by a constructor).
#[inline(always)]
pub(crate) fn dispatch<V: Visit>(kernel: i32, v: V) -> Option<V::Out> {
    use code::*;
    Some(match kernel {
        LIN_ELASTIC => v.visit::<LinElastic, false>(),
        LIN_DAMPED => v.visit::<LinDamped, false>(),
        LIN_DAMPED_CLAMPED => v.visit::<LinDamped, true>(),
        P15_ELASTIC => v.visit::<P15Elastic, false>(),
        P15_DAMPED => v.visit::<P15Damped, false>(),
        P15_DAMPED_CLAMPED => v.visit::<P15Damped, true>(),
        P2_ELASTIC => v.visit::<P2Elastic, false>(),
        P2_DAMPED => v.visit::<P2Damped, false>(),
        P2_DAMPED_CLAMPED => v.visit::<P2Damped, true>(),
        GEN_ELASTIC => v.visit::<GenElastic, false>(),
        GEN_DAMPED => v.visit::<GenDamped, false>(),
        GEN_DAMPED_CLAMPED => v.visit::<GenDamped, true>(),
        HERTZ_ELASTIC => v.visit::<HertzElastic, false>(),
        HERTZ_DAMPED => v.visit::<HertzDamped, false>(),
        HERTZ_DAMPED_CLAMPED => v.visit::<HertzDamped, true>(),
        VISCO_DAMPED => v.visit::<Viscoelastic, false>(),
        VISCO_DAMPED_CLAMPED => v.visit::<Viscoelastic, true>(),
        _ => return None,
    })
}

/// The same law without clamping (for checks of the raw force); other codes unchanged.
pub(crate) const fn unclamped(kernel: i32) -> i32 {
    use code::*;
    match kernel {
        LIN_DAMPED_CLAMPED => LIN_DAMPED,
        P15_DAMPED_CLAMPED => P15_DAMPED,
        P2_DAMPED_CLAMPED => P2_DAMPED,
        GEN_DAMPED_CLAMPED => GEN_DAMPED,
        HERTZ_DAMPED_CLAMPED => HERTZ_DAMPED,
        VISCO_DAMPED_CLAMPED => VISCO_DAMPED,
        k => k,
    }
}

/// Which per-contact inputs a kernel reads: (vn, r_eff, m_eff). `None` for an unknown code.
pub(crate) fn needs(kernel: i32) -> Option<(bool, bool, bool)> {
    struct Needs;
    impl Visit for Needs {
        type Out = (bool, bool, bool);
        fn visit<L: Law, const CLAMP: bool>(self) -> Self::Out {
            (L::NEEDS_VN, L::NEEDS_R, L::NEEDS_M)
        }
    }
    dispatch(kernel, Needs)
}

struct Scalar {
    c: Consts,
    d: f64,
    vn: f64,
    r: f64,
    m: f64,
}

impl Visit for Scalar {
    type Out = f64;
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) -> f64 {
        eval::<L, CLAMP>(&self.c, self.d, self.vn, self.r, self.m)
    }
}

/// The normal force of one contact for kernel code `kernel` and constants `c`: the unchecked hot
/// path. Unknown kernel codes give NaN (never undefined behaviour).
#[inline(always)]
pub fn normal_force_raw(kernel: i32, c: Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
    dispatch(kernel, Scalar { c, d, vn, r, m }).unwrap_or(f64::NAN)
}

/// The normal force of one contact [N] (repulsive positive): see [`normal_force_raw`].
#[inline]
pub fn normal_force(pair: &PairModel, d: f64, vn: f64, r: f64, m: f64) -> f64 {
    normal_force_raw(pair.kernel, pair.consts, d, vn, r, m)
}

/// Chooses the kernel code for a Tsuji-type law family: `elastic` when there is no damping,
/// otherwise the damped law with or without clamping.
pub(crate) fn pick(
    damped: bool,
    criterion: EndCriterion,
    elastic: i32,
    free: i32,
    clamped: i32,
) -> i32 {
    match (damped, criterion) {
        (false, _) => elastic,
        (true, EndCriterion::Overlap) => free,
        (true, EndCriterion::Force) => clamped,
    }
}
