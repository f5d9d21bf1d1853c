//! Structure-of-arrays batches: one dispatch per batch, then a plain loop over slices that the
//! compiler vectorises (square roots are IEEE instructions in Rust, never `errno` calls; the
//! general-p power is the branch-free [`crate::numerics::pow_dd`] kernel).
//!
//! **Runtime CPU dispatch** ([`crate::numerics::simd`]): each monomorphised loop is compiled for
//! the baseline x86-64 (SSE2, 2 lanes), AVX2 + FMA (4 lanes) and AVX-512F (8 lanes), and the
//! widest the CPU supports runs, so one portable binary runs at `target-cpu=native` speed. No
//! fused multiply–add is ever formed, so all flavours round exactly like the scalar call and the
//! batch stays bit-identical to [`super::normal_force`] (tests/force_contract.rs).

use super::pair::{Consts, Law, Visit, eval};
use super::registry::dispatch;
use crate::Error;
use crate::numerics::simd::{SimdLoop, vectorised};
use core::marker::PhantomData;

struct Batch<'a> {
    c: Consts,
    d: &'a [f64],
    vn: &'a [f64],
    r: &'a [f64],
    m: &'a [f64],
    out: &'a mut [f64],
}

/// The loop over one batch for law `L`: one monomorphised loop per kernel and CPU flavour, with
/// no branch on the model inside.
struct Loop<'a, L, const CLAMP: bool> {
    b: Batch<'a>,
    law: PhantomData<L>,
}

impl<L: Law, const CLAMP: bool> SimdLoop for Loop<'_, L, CLAMP> {
    #[inline(always)]
    fn run(self) {
        let Batch {
            c,
            d,
            vn,
            r,
            m,
            out,
        } = self.b;
        for ((((o, &d), &vn), &r), &m) in out.iter_mut().zip(d).zip(vn).zip(r).zip(m) {
            *o = eval::<L, CLAMP>(&c, d, vn, r, m);
        }
    }
}

impl Visit for Batch<'_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        vectorised(Loop::<L, CLAMP> {
            b: self,
            law: PhantomData,
        });
    }
}

/// Normal forces of `out.len()` contacts of one pair model: `out[i] = F(d[i], vn[i], r[i], m[i])`.
///
/// Arrays the kernel does not read (see [`super::pair`]'s `NEEDS_*`) may be any slice of the
/// same length, e.g. `d` itself. Every input must be at least as long as `out`.
pub fn normal_force_batch(
    kernel: i32,
    c: Consts,
    d: &[f64],
    vn: &[f64],
    r: &[f64],
    m: &[f64],
    out: &mut [f64],
) -> Result<(), Error> {
    let n = out.len();
    if n == 0 || d.len() < n || vn.len() < n || r.len() < n || m.len() < n {
        return Err(Error::BufferTooShort);
    }
    let (d, vn, r, m) = match (d.get(..n), vn.get(..n), r.get(..n), m.get(..n)) {
        (Some(d), Some(vn), Some(r), Some(m)) => (d, vn, r, m),
        _ => return Err(Error::BufferTooShort),
    };
    dispatch(
        kernel,
        Batch {
            c,
            d,
            vn,
            r,
            m,
            out,
        },
    )
    .ok_or(Error::PairInvalid)
}
