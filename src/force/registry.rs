//! THE registry of normal-force kernels: one line per law, the only place kernel codes appear.
//!
//! Each line `law => code[, clamped code];` gives a law (a type implementing
//! [`Law`](super::pair::Law)) its kernel code(s) — values stored in `dc_pair.kernel` and
//! therefore ABI: never renumber, only append. From this table the macro generates
//! * the [`Coded`] impl of each law (constructors ask their law for its code: a law without a
//!   registry line does not compile),
//! * [`dispatch`], the one branch on the kernel code (a jump table, then monomorphised code),
//! * [`unclamped`] (a clamped code → its unclamped twin) and [`KERNEL_CODES`] (for tests).
//!
//! Duplicate codes are a compile error (`unreachable_patterns` is denied in the generated match).

use super::pair::{Coded, Consts, Law, PairModel, Visit, eval};
use super::{dmt, hertz, powerlaw, viscoelastic};

macro_rules! registry {
    ($($law:ty => $code:literal $(, clamped $clamped:literal)?;)*) => {
        $(
            impl Coded for $law {
                const CODE: i32 = $code;
                const CLAMPED: i32 = registry!(@or0 $($clamped)?);
            }
        )*

        /// The only branch on the model kind: picks the monomorphised kernel for `kernel`
        /// once. `None` for an unknown code (a `dc_pair` not made by a constructor).
        #[inline(always)]
        #[deny(unreachable_patterns)]
        pub(crate) fn dispatch<V: Visit>(kernel: i32, v: V) -> Option<V::Out> {
            Some(match kernel {
                $(
                    $code => v.visit::<$law, false>(),
                    $($clamped => v.visit::<$law, true>(),)?
                )*
                _ => return None,
            })
        }

        /// The same law without clamping (for checks of the raw force); other codes unchanged.
        pub(crate) const fn unclamped(kernel: i32) -> i32 {
            match kernel {
                $($($clamped => $code,)?)*
                k => k,
            }
        }

        /// Every valid kernel code, in registry order.
        pub const KERNEL_CODES: &[i32] = &[$($code, $($clamped,)?)*];
    };
    (@or0) => { 0 };
    (@or0 $c:literal) => { $c };
}

registry! {
    powerlaw::LinElastic => 1;
    powerlaw::LinDamped => 2, clamped 3;
    powerlaw::P15Elastic => 4;
    powerlaw::P15Damped => 5, clamped 6;
    powerlaw::P2Elastic => 7;
    powerlaw::P2Damped => 8, clamped 9;
    powerlaw::GenElastic => 10;
    powerlaw::GenDamped => 11, clamped 12;
    hertz::HertzElastic => 13;
    hertz::HertzDamped => 14, clamped 15;
    viscoelastic::Viscoelastic => 16, clamped 17;
    dmt::DmtElastic => 18;
    dmt::DmtDamped => 19;
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
