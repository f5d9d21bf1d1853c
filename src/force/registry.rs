//! THE registry of normal laws: one line per law, the only place their codes appear.
//!
//! Each line
//! `NAME = selector, "keyword", law::Type, model M [kernels [K: law::Kernel => code[, clamped
//! code]; …]] [state code];` gives the law `law::Type` (implementing
//! [`SpecLaw`](super::pair::SpecLaw), and [`StateLaw`](super::pair::StateLaw) for a law with
//! state) its selector (`DC_NORMAL_NAME`, the field `normal` of the specification), the
//! `dc_pair.model` of its pairs (`DC_MODEL_NAME` for the first law of that model), its kernel
//! codes (values stored in `dc_pair.kernel`: `DC_KERNEL_K`, `DC_KERNEL_K_CLAMPED`; a law with
//! state has one, `DC_KERNEL_NAME`) and its keyword. All are ABI: never renumber, only append.
//! From this table the macro generates
//! * the [`Coded`] impl of each kernel type (constructors ask their law for its code: a law
//!   without a registry line does not compile) and the [`Registered`] impl of each law,
//! * [`dispatch`], the one branch on a stateless kernel code (a jump table, then monomorphised
//!   code), [`unclamped`] and [`KERNEL_CODES`],
//! * the dispatch of the laws with state ([`has_state`], [`state_force`], [`state_dissipated`],
//!   [`STATEFUL_KERNEL_CODES`]),
//! * [`critical_load`], the load of the Coulomb limits from each law's `critical_load` hook,
//! * [`reach`], how far beyond touching each law acts (its `reach` hook),
//! * the selectors [`normal`] and the specification's normal-law validation ([`from_spec`]),
//! * the metadata table [`NORMAL`] (= [`crate::laws::NORMAL`]), from which `xtask` writes the C
//!   constants, the Python enum, the inline header's codes and dispatch and the plugins' table.
//!
//! Duplicate codes are a compile error (`unreachable_patterns` is denied in the generated
//! matches).

use super::pair;
use super::pair::{Coded, Consts, Law, PairModel, Registered, SpecLaw, StateLaw, Visit, eval};
use crate::contact::spec::{ContactSpec, damping, hertz_factor, set};
use crate::laws::{KernelInfo, LawInfo};
use crate::{EndCriterion, Error};

// The law files, one per law, declared here next to their lines below (reached as
// `force::<law>` by re-export). A law file imports `super::pair` (and `super::<other law>`) as
// if it sat in `force`: `pair` is imported here.
#[path = "dmt.rs"]
pub mod dmt;
#[path = "elastic_plastic.rs"]
pub mod elastic_plastic;
#[path = "hertz.rs"]
pub mod hertz;
#[path = "jkr.rs"]
pub mod jkr;
#[path = "powerlaw.rs"]
pub mod powerlaw;
#[path = "viscoelastic.rs"]
pub mod viscoelastic;

/// The law modules, re-exported by `force` (`force::dmt`, …).
pub mod law_files {
    pub use super::{dmt, elastic_plastic, hertz, jkr, powerlaw, viscoelastic};
}

macro_rules! normal_laws {
    ($(
        $name:ident = $sel:literal, $kw:literal, $law:ty, model $model:literal
        $(kernels [$($kname:ident: $kty:ty => $code:literal $(, clamped $clamped:literal)?;)*])?
        $(state $state:literal)?;
    )*) => {
        $($($(
            impl Coded for $kty {
                const CODE: i32 = $code;
                const CLAMPED: i32 = normal_laws!(@or0 $($clamped)?);
            }
        )*)?)*

        $(
            impl Registered for $law {
                const MODEL: i32 = $model;
                const STATE_KERNEL: i32 = normal_laws!(@or0 $($state)?);
            }
        )*

        /// The only branch on a stateless kernel code: picks the monomorphised kernel for
        /// `kernel` once. `None` for an unknown code (a `dc_pair` not made by a constructor)
        /// and for the code of a law with state.
        #[inline(always)]
        #[deny(unreachable_patterns)]
        pub(crate) fn dispatch<V: Visit>(kernel: i32, v: V) -> Option<V::Out> {
            Some(match kernel {
                $($($(
                    $code => v.visit::<$kty, false>(),
                    $($clamped => v.visit::<$kty, true>(),)?
                )*)?)*
                _ => return None,
            })
        }

        /// The same law without clamping (for checks of the raw force); other codes unchanged.
        pub(crate) const fn unclamped(kernel: i32) -> i32 {
            match kernel {
                $($($($($clamped => $code,)?)*)?)*
                k => k,
            }
        }

        /// Every valid stateless kernel code, in registry order.
        pub const KERNEL_CODES: &[i32] = &[$($($($code, $($clamped,)?)*)?)*];

        /// Every kernel code of a law with state.
        pub const STATEFUL_KERNEL_CODES: &[i32] = &[$($($state,)?)*];

        /// True for the kernel code of a law with state.
        #[inline(always)]
        #[deny(unreachable_patterns)]
        pub(crate) fn has_state(kernel: i32) -> bool {
            match kernel {
                $($($state => true,)?)*
                $($($($code => false, $($clamped => false,)?)*)?)*
                _ => false,
            }
        }

        /// The normal force of a law with state at overlap d (any sign: the law decides its
        /// range), reading and updating `state`; NaN for a code that is not one of these laws.
        #[inline(always)]
        #[allow(unused_variables)]
        pub(crate) fn state_force(
            kernel: i32,
            c: &Consts,
            d: f64,
            vn: f64,
            r: f64,
            m: f64,
            state: &mut f64,
        ) -> f64 {
            match kernel {
                $($($state => <$law as StateLaw>::force(c, d, vn, r, m, state),)?)*
                _ => f64::NAN,
            }
        }

        /// The energy the law with state removed in a step that took its state from `old` to
        /// `new` [J] (the energy ledger's normal loss of the step; ≥ 0); 0 for other codes.
        #[inline(always)]
        #[allow(unused_variables)]
        pub(crate) fn state_dissipated(kernel: i32, c: &Consts, r: f64, old: f64, new: f64) -> f64 {
            match kernel {
                $($($state => <$law as StateLaw>::dissipated(c, r, old, new),)?)*
                _ => 0.0,
            }
        }

        /// The critical load [N] of the Coulomb limits (tangential, rolling, twisting) of a
        /// touching contact of effective radius `r` with applied normal force `f`, from the
        /// law's own [`Law::critical_load`] / [`StateLaw::critical_load`]: |f| for every law
        /// without adhesion (and for an unknown code), |f + 2 F_po| for an adhesive one.
        #[inline(always)]
        #[deny(unreachable_patterns)]
        #[allow(unused_variables)]
        pub(crate) fn critical_load(kernel: i32, c: &Consts, r: f64, f: f64) -> f64 {
            match kernel {
                $($($(
                    $code => <$kty as Law>::critical_load(c, r, f),
                    $($clamped => <$kty as Law>::critical_load(c, r, f),)?
                )*)?)*
                $($($state => <$law as StateLaw>::critical_load(c, r, f),)?)*
                _ => f.abs(),
            }
        }

        /// The reach [m] of a contact of effective radius `r`: the largest gap (−δ) at which
        /// the law's force can be nonzero, from the law's own [`Law::reach`] /
        /// [`StateLaw::reach`]: 0 for every law that acts only while touching (and for an
        /// unknown code).
        #[deny(unreachable_patterns)]
        #[allow(unused_variables)]
        pub(crate) fn reach(kernel: i32, c: &Consts, r: f64) -> f64 {
            match kernel {
                $($($(
                    $code => <$kty as Law>::reach(c, r),
                    $($clamped => <$kty as Law>::reach(c, r),)?
                )*)?)*
                $($($state => <$law as StateLaw>::reach(c, r),)?)*
                _ => 0.0,
            }
        }

        /// Normal-law selectors: the field `normal` of the specification (the C constants
        /// `DC_NORMAL_*`, generated from [`NORMAL`], equal these).
        ///
        /// cbindgen:ignore
        pub mod normal {
            $(
                #[doc = concat!("`", $kw, "`: see [`crate::laws::NORMAL`].")]
                pub const $name: i32 = $sel;
            )*
        }

        /// The pair of the specification's normal law: the damping selector checked (e_n read
        /// for `DC_DAMPING_RESTITUTION`), refused by a law that does not accept it, the
        /// materials' (4/3) E* for a law that reads them, then the law's own checks.
        #[deny(unreachable_patterns)]
        pub(crate) fn from_spec(s: &ContactSpec, crit: EndCriterion) -> Result<PairModel, Error> {
            let e_n = match s.damping {
                damping::NONE => 1.0,
                damping::RESTITUTION => set(s.e_n)?,
                _ => return Err(Error::SpecModel),
            };
            match s.normal {
                $($sel => build::<$law>(s, e_n, crit),)*
                _ => Err(Error::SpecModel),
            }
        }

        /// Every normal law, in registry order (see [`crate::laws::LawInfo`]).
        pub const NORMAL: &[LawInfo] = &[$(
            LawInfo {
                name: stringify!($name),
                code: $sel,
                keyword: $kw,
                doc: <$law as SpecLaw>::DOC,
                materials: <$law as SpecLaw>::MATERIALS,
                params: <$law as SpecLaw>::PARAMS,
                model: $model,
                model_doc: <$law as SpecLaw>::MODEL_DOC,
                restitution: <$law as SpecLaw>::RESTITUTION,
                clamp: <$law as SpecLaw>::CLAMP,
                state_kernel: normal_laws!(@or0 $($state)?),
                kernels: &[$($(KernelInfo {
                    name: stringify!($kname),
                    code: $code,
                    clamped: normal_laws!(@or0 $($clamped)?),
                    rust_type: stringify!($kty),
                },)*)?],
            },
        )*];
    };
    (@or0) => { 0 };
    (@or0 $c:literal) => { $c };
}

/// One law's pair from the specification (the generic part of [`from_spec`]).
fn build<L: SpecLaw>(s: &ContactSpec, e_n: f64, crit: EndCriterion) -> Result<PairModel, Error> {
    if !L::RESTITUTION && s.damping != damping::NONE {
        return Err(Error::SpecModel);
    }
    let kf = if L::MATERIALS {
        hertz_factor(s)?
    } else {
        f64::NAN
    };
    L::build(s, kf, e_n, crit)
}

normal_laws! {
    HERTZ = 1, "hertz", hertz::Hertz, model 2
        kernels [HERTZ_ELASTIC: hertz::HertzElastic => 13; HERTZ_DAMPED: hertz::HertzDamped => 14, clamped 15;];
    POWERLAW = 2, "powerlaw", powerlaw::Powerlaw, model 1
        kernels [
            LIN_ELASTIC: powerlaw::LinElastic => 1;
            LIN_DAMPED: powerlaw::LinDamped => 2, clamped 3;
            P15_ELASTIC: powerlaw::P15Elastic => 4;
            P15_DAMPED: powerlaw::P15Damped => 5, clamped 6;
            P2_ELASTIC: powerlaw::P2Elastic => 7;
            P2_DAMPED: powerlaw::P2Damped => 8, clamped 9;
            GEN_ELASTIC: powerlaw::GenElastic => 10;
            GEN_DAMPED: powerlaw::GenDamped => 11, clamped 12;
        ];
    LINEAR = 3, "linear", powerlaw::Linear, model 1;
    VISCOELASTIC = 4, "viscoelastic", viscoelastic::Visco, model 3
        kernels [VISCO_DAMPED: viscoelastic::Viscoelastic => 16, clamped 17;];
    DMT = 5, "dmt", dmt::Dmt, model 4
        kernels [DMT_ELASTIC: dmt::DmtElastic => 18; DMT_DAMPED: dmt::DmtDamped => 19;];
    ELASTIC_PLASTIC = 6, "elastic_plastic", elastic_plastic::ElasticPlastic, model 5 state 20;
    JKR = 7, "jkr", jkr::Jkr, model 6 state 21;
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

#[cfg(test)]
mod tests {
    use super::{KERNEL_CODES, NORMAL, STATEFUL_KERNEL_CODES};

    #[test]
    fn stateful_codes_are_not_stateless_ones() {
        for c in STATEFUL_KERNEL_CODES {
            assert!(!KERNEL_CODES.contains(c), "{c}");
        }
    }

    #[test]
    fn selectors_keywords_and_names_are_unique() {
        for (i, a) in NORMAL.iter().enumerate() {
            for b in &NORMAL[..i] {
                assert!(a.code != b.code && a.keyword != b.keyword && a.name != b.name);
            }
        }
    }
}
