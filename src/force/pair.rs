//! The pair model and what every law shares: per-pair constants, the [`Law`] trait, the one
//! place that turns a law's raw force into the contact force (zero without overlap, optional
//! clamp of attraction), and the [`Coded`] trait through which a law learns its kernel codes.
//!
//! This module imports no other module of `force`: the laws import it, the registry
//! ([`super::registry`]) imports the laws, and nothing imports back (no cycle).

use crate::EndCriterion;

/// Model families, as stored in `dc_pair.model` (the C constants `DC_MODEL_*` equal these).
pub(crate) const MODEL_POWERLAW: i32 = 1;
pub(crate) const MODEL_HERTZ: i32 = 2;
pub(crate) const MODEL_VISCOELASTIC: i32 = 3;

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
    /// True for a law that acts beyond touching (adhesion): its `raw` is then also called for
    /// d ≤ 0 and must itself return 0 where the law ends (and for NaN d). False for every
    /// repulsive law: the force is zero unless d > 0.
    const ADHESIVE: bool = false;
    fn raw(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64;
    /// The critical load [N] of the Coulomb limits (tangential μ F_c, rolling μ_r R* F_c,
    /// twisting μ_tw F_c) of a touching contact of effective radius r whose applied normal
    /// force is f: |f| for a law without adhesion (this default); an adhesive law overrides it
    /// with the adhesion-corrected load |f + 2 F_po|, F_po its pull-off force (docs/force.md,
    /// "Friction with adhesion"). Dispatched by [`super::registry`]'s `critical_load`.
    #[inline(always)]
    fn critical_load(_c: &Consts, _r: f64, f: f64) -> f64 {
        f.abs()
    }
    /// The reach [m] of a contact of effective radius r: the largest gap (−δ) at which the
    /// law's force can be nonzero; 0 for a law that acts only while touching (this default).
    /// Dispatched by [`super::registry`]'s `reach` (`dc_contact_model_reach`).
    fn reach(_c: &Consts, _r: f64) -> f64 {
        0.0
    }
    /// True for a law whose raw force needs the power s = d^h ([`crate::numerics::pow_dd`]):
    /// a batch then computes s in separate loops ([`super::batch`]) and calls [`Law::raw_pow`].
    const POW: bool = false;
    /// The raw force given s = d^h (for `POW` laws; `raw` = `raw_pow` with s = `pow_dd(d, h)`).
    #[inline(always)]
    fn raw_pow(c: &Consts, d: f64, vn: f64, r: f64, m: f64, _s: f64) -> f64 {
        Self::raw(c, d, vn, r, m)
    }
    /// The raw force of the fast batch (`normal_force_batch_fast`): `raw`
    /// with the elastic and damping terms summed by one fused multiply–add where the law
    /// overrides it (what a C compiler contracts to with FMA hardware), else `raw`'s bits.
    #[inline(always)]
    fn raw_fused(c: &Consts, d: f64, vn: f64, r: f64, m: f64, s: f64) -> f64 {
        Self::raw_pow(c, d, vn, r, m, s)
    }
}

/// The contact force of law `L`: zero unless d > 0 (also for NaN d) for non-adhesive laws; an
/// adhesive law decides its own range (see [`Law::ADHESIVE`]); with `CLAMP`, attractive
/// (and NaN) raw forces become zero. Written as selects so that batch loops vectorise.
#[inline(always)]
pub(crate) fn eval<L: Law, const CLAMP: bool>(c: &Consts, d: f64, vn: f64, r: f64, m: f64) -> f64 {
    select::<L, CLAMP>(d, L::raw(c, d, vn, r, m))
}

/// The raw force f where the law keeps it (d > 0 unless adhesive; f > 0 with `CLAMP`), else +0,
/// as one condition: with AVX-512, a compare masked by the other (the form a C compiler gives
/// the hand-written loop). NaN d or (with `CLAMP`) NaN f give +0.
#[inline(always)]
fn select<L: Law, const CLAMP: bool>(d: f64, f: f64) -> f64 {
    let keep = match (L::ADHESIVE, CLAMP) {
        (true, true) => f > 0.0,
        (true, false) => true,
        (false, true) => d > 0.0 && f > 0.0,
        (false, false) => d > 0.0,
    };
    if keep { f } else { 0.0 }
}

/// [`eval`] for a `POW` law given s = d^h: the same force, bit for bit.
#[inline(always)]
pub(crate) fn eval_pow<L: Law, const CLAMP: bool>(
    c: &Consts,
    d: f64,
    vn: f64,
    r: f64,
    m: f64,
    s: f64,
) -> f64 {
    select::<L, CLAMP>(d, L::raw_pow(c, d, vn, r, m, s))
}

/// [`eval_pow`] with [`Law::raw_fused`] (the fast batch; `s` unused by laws without a power).
#[inline(always)]
pub(crate) fn eval_fused<L: Law, const CLAMP: bool>(
    c: &Consts,
    d: f64,
    vn: f64,
    r: f64,
    m: f64,
    s: f64,
) -> f64 {
    select::<L, CLAMP>(d, L::raw_fused(c, d, vn, r, m, s))
}

/// Something to do with one monomorphised kernel (a scalar evaluation or a batch loop).
pub(crate) trait Visit {
    type Out;
    fn visit<L: Law, const CLAMP: bool>(self) -> Self::Out;
}

/// The kernel codes of a law, assigned in one place: the registry line of the law
/// ([`super::registry`]) implements this trait. `CLAMPED` is 0 (invalid) for laws that have no
/// clamped variant (undamped laws, whose force is never attractive).
pub(crate) trait Coded {
    /// Code of the law without clamping.
    const CODE: i32;
    /// Code of the law with attractive forces clamped to zero.
    const CLAMPED: i32;
}

/// Chooses the kernel code of a law family: the elastic law `E` when there is no damping,
/// otherwise the damped law `D` with clamping for the force criterion.
pub(crate) fn pick<E: Coded, D: Coded>(damped: bool, criterion: EndCriterion) -> i32 {
    match (damped, criterion) {
        (false, _) => E::CODE,
        (true, EndCriterion::Overlap) => D::CODE,
        (true, EndCriterion::Force) => D::CLAMPED,
    }
}

/// A normal law as the contact specification sees it: what it reads and how it is built. One
/// type per law (`dmt::Dmt`), named by the law's line in the registry ([`super::registry`]),
/// which generates the validation dispatch and the metadata ([`crate::laws::NORMAL`]) from it.
pub(crate) trait SpecLaw {
    /// One paragraph: what the law is (becomes the comment of `DC_NORMAL_<NAME>`).
    const DOC: &'static str;
    /// Whether the law reads the bodies' materials (E1, ν1, E2, ν2: (4/3) E* is passed to
    /// [`SpecLaw::build`]).
    const MATERIALS: bool;
    /// The other specification fields it reads (checked by [`SpecLaw::build`]).
    const PARAMS: &'static [crate::laws::Param];
    /// Whether `DC_DAMPING_RESTITUTION` is accepted (else `DC_ERR_SPEC_MODEL`).
    const RESTITUTION: bool;
    /// Whether `DC_END_FORCE` is accepted (else [`SpecLaw::build`] refuses it).
    const CLAMP: bool;
    /// The comment of `DC_MODEL_<NAME>` for the law that introduces its `dc_pair.model` (its
    /// registry line's `model`); empty for a law that shares another law's model.
    const MODEL_DOC: &'static str = "";
    /// The pair of this law from the specification: kf = (4/3) E* (when `MATERIALS`, else
    /// NaN), the target restitution e_n (1 without damping), the end criterion.
    fn build(
        s: &crate::contact::spec::ContactSpec,
        kf: f64,
        e_n: f64,
        criterion: EndCriterion,
    ) -> Result<PairModel, crate::Error>;
}

/// A normal law with one double of per-contact state (contact models only; its kernel code is
/// given by its registry line's `state` and is never a stateless kernel).
pub(crate) trait StateLaw {
    /// The force at overlap d (any sign: the law decides its range), reading and updating the
    /// state.
    fn force(c: &Consts, d: f64, vn: f64, r: f64, m: f64, state: &mut f64) -> f64;
    /// The energy the law removed in a step that took its state from `old` to `new` [J] (≥ 0).
    fn dissipated(c: &Consts, r: f64, old: f64, new: f64) -> f64;
    /// The critical load [N] of the Coulomb limits for applied normal force f: |f| unless the
    /// law is adhesive (see [`Law::critical_load`]).
    #[inline(always)]
    fn critical_load(_c: &Consts, _r: f64, f: f64) -> f64 {
        f.abs()
    }
    /// The reach [m] beyond touching (see [`Law::reach`]): 0 unless the law acts at δ < 0.
    fn reach(_c: &Consts, _r: f64) -> f64 {
        0.0
    }
}

/// The codes the registry line of a law gives it: its `dc_pair.model` and (laws with state) its
/// kernel code, 0 for a stateless law.
pub(crate) trait Registered {
    const MODEL: i32;
    const STATE_KERNEL: i32;
}
