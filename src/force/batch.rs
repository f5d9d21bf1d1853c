//! Structure-of-arrays batches: one dispatch per batch, then a plain loop over slices that the
//! compiler vectorises (square roots are IEEE instructions in Rust, never `errno` calls). The
//! general-p power is the branch-free, table-driven [`crate::numerics::pow_dd`] kernel, which
//! the general-p batch evaluates with explicit AVX-512 / AVX2 kernels of the same operations
//! (`run_pow`).
//!
//! **Runtime CPU dispatch** ([`crate::numerics::simd`]): each monomorphised loop is compiled for
//! the baseline x86-64 (SSE2, 2 lanes), AVX2 + FMA (4 lanes) and AVX-512F (8 lanes), and the
//! widest the CPU supports runs, so one portable binary runs at `target-cpu=native` speed. The
//! exact batch forms no fused multiply–add, so all flavours round exactly like the scalar call
//! and it stays bit-identical to [`super::normal_force`] (tests/force_contract.rs).
//!
//! **The fast batch** ([`normal_force_batch_fast`]) gives that up for speed: general p by
//! [`crate::numerics::pow_fast`] (tables of the exponent) and the laws' fused forms
//! ([`Law::raw_fused`]); its own flavours agree bit for bit (tests/force_batch_fast.rs).

use super::pair::{Consts, Law, Visit, eval, eval_fused, eval_pow};
use super::registry::dispatch;
use crate::Error;
use crate::numerics::pow_dd::{pow_exp, pow_ln, pow_ln_index};
use crate::numerics::pow_fast::{FastPow, pow_fast_slice};
use crate::numerics::pow_table::{exp_entries, exp_index, ln_entries};
use crate::numerics::simd::{SimdLoop, vectorised};
#[cfg(all(target_arch = "x86_64", not(miri)))]
use crate::numerics::simd::{has_avx2, has_avx512};
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
/// no branch on the model inside. `FUSED`: the fast batch's forces ([`eval_fused`]; it runs
/// `POW` laws elsewhere, [`run_pow_fast`]).
struct Loop<'a, L, const CLAMP: bool, const FUSED: bool> {
    b: Batch<'a>,
    law: PhantomData<L>,
}

impl<L: Law, const CLAMP: bool, const FUSED: bool> SimdLoop for Loop<'_, L, CLAMP, FUSED> {
    #[inline(always)]
    fn run(self) {
        if L::POW && !FUSED {
            return run_pow::<L, CLAMP>(self.b);
        }
        let Batch {
            c,
            d,
            vn,
            r,
            m,
            out,
        } = self.b;
        for ((((o, &d), &vn), &r), &m) in out.iter_mut().zip(d).zip(vn).zip(r).zip(m) {
            *o = if FUSED {
                eval_fused::<L, CLAMP>(&c, d, vn, r, m, 0.0)
            } else {
                eval::<L, CLAMP>(&c, d, vn, r, m)
            };
        }
    }
}

/// Contacts per chunk of a `POW` law's batch (scratch arrays on the stack: 4 × 2 KiB).
const CHUNK: usize = 256;

/// The batch of a law with the power s = d^h ([`crate::numerics::pow_dd`], whose ln and exp
/// read 32-entry tables), in chunks of [`CHUNK`] contacts: s by the AVX-512 or AVX2 kernel where
/// the CPU has one ([`run_pow_avx512`], [`run_pow_avx2`]); otherwise (baseline SSE2) the table
/// reads in their own scalar loops and the arithmetic in loops without table reads, which
/// vectorise (a loop with a table read is left scalar: LLVM's cost model for x86-64 does not
/// choose gathers). The same operations as the scalar `pow_dd` everywhere, so the same bits.
#[inline(always)]
fn run_pow<L: Law, const CLAMP: bool>(b: Batch<'_>) {
    #[cfg(all(target_arch = "x86_64", not(miri)))]
    if has_avx512() {
        // SAFETY: the CPU has AVX-512F and FMA (checked just above), the only requirement.
        unsafe { run_pow_avx512::<L, CLAMP>(b) };
        return;
    }
    #[cfg(all(target_arch = "x86_64", not(miri)))]
    if has_avx2() {
        // SAFETY: the CPU has AVX2 and FMA (checked just above), the only requirement.
        unsafe { run_pow_avx2::<L, CLAMP>(b) };
        return;
    }
    let Batch {
        c,
        d,
        vn,
        r,
        m,
        out,
    } = b;
    let (mut ta, mut tb) = ([0.0f64; CHUNK], [0.0f64; CHUNK]);
    let (mut nn, mut tt) = ([0.0f64; CHUNK], [0.0f64; CHUNK]);
    let chunks = out
        .chunks_mut(CHUNK)
        .zip(d.chunks(CHUNK))
        .zip(vn.chunks(CHUNK))
        .zip(r.chunks(CHUNK))
        .zip(m.chunks(CHUNK));
    for ((((out, d), vn), r), m) in chunks {
        // ln table reads (scalar), then x^h = 2^n e^t up to t (vectorised).
        for ((a, b), &x) in ta.iter_mut().zip(tb.iter_mut()).zip(d) {
            (*a, *b) = ln_entries(pow_ln_index(x));
        }
        for ((((nv, tv), &x), &a), &b) in nn.iter_mut().zip(tt.iter_mut()).zip(d).zip(&ta).zip(&tb)
        {
            (*nv, *tv) = pow_ln(x, c.h, (a, b));
        }
        // exp table reads (scalar), then s and the force (vectorised).
        for ((a, b), &t) in ta.iter_mut().zip(tb.iter_mut()).zip(&tt) {
            (*a, *b) = exp_entries(exp_index(t));
        }
        let rest = d
            .iter()
            .zip(vn)
            .zip(r)
            .zip(m)
            .zip(nn.iter().zip(&tt))
            .zip(ta.iter().zip(&tb));
        for (o, (((((&d, &vn), &r), &m), (&n, &t)), (&a, &b))) in out.iter_mut().zip(rest) {
            let s = pow_exp(d, n, t, (a, b));
            *o = eval_pow::<L, CLAMP>(&c, d, vn, r, m, s);
        }
    }
}

/// [`run_pow`] with AVX-512F: s = d^h by [`crate::numerics::pow_avx512`] (the tables in
/// registers, the same bits as the scalar `pow_dd`), then the force in a loop the compiler
/// vectorises.
///
/// # Safety
/// The CPU must support AVX-512F.
#[cfg(all(target_arch = "x86_64", not(miri)))]
#[target_feature(enable = "avx512f,avx2,fma")]
#[inline(never)]
unsafe fn run_pow_avx512<L: Law, const CLAMP: bool>(b: Batch<'_>) {
    use crate::numerics::pow_avx512::{Tables, pow_slice_x8};
    let (q, tables) = (b.c.h, Tables::load());
    pow_chunks::<L, CLAMP, false>(b, |d, s| pow_slice_x8(d, q, s, &tables));
}

/// [`run_pow`] with AVX2: s = d^h by [`crate::numerics::pow_avx2`] (table reads as gathers, the
/// same bits as the scalar `pow_dd`), then the force in a loop the compiler vectorises.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(all(target_arch = "x86_64", not(miri)))]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
unsafe fn run_pow_avx2<L: Law, const CLAMP: bool>(b: Batch<'_>) {
    use crate::numerics::pow_avx2::pow_slice_x4;
    let q = b.c.h;
    pow_chunks::<L, CLAMP, false>(b, |d, s| pow_slice_x4(d, q, s));
}

/// The force loop of a `POW` law in chunks of [`CHUNK`] contacts: s = d^h of a chunk by `power`
/// (into a stack array), then the chunk's forces by [`eval_pow`] (or [`eval_fused`] for the fast
/// batch) in a loop the compiler vectorises. Inlined into each flavour's `target_feature`
/// function, whose features the closure inherits.
#[inline(always)]
fn pow_chunks<L: Law, const CLAMP: bool, const FUSED: bool>(
    b: Batch<'_>,
    mut power: impl FnMut(&[f64], &mut [f64]),
) {
    let Batch {
        c,
        d,
        vn,
        r,
        m,
        out,
    } = b;
    let mut s = [0.0f64; CHUNK];
    let chunks = out
        .chunks_mut(CHUNK)
        .zip(d.chunks(CHUNK))
        .zip(vn.chunks(CHUNK))
        .zip(r.chunks(CHUNK))
        .zip(m.chunks(CHUNK));
    for ((((out, d), vn), r), m) in chunks {
        power(d, &mut s);
        let rest = d.iter().zip(vn).zip(r).zip(m).zip(&s);
        for (o, ((((&d, &vn), &r), &m), &s)) in out.iter_mut().zip(rest) {
            *o = if FUSED {
                eval_fused::<L, CLAMP>(&c, d, vn, r, m, s)
            } else {
                eval_pow::<L, CLAMP>(&c, d, vn, r, m, s)
            };
        }
    }
}

impl Visit for Batch<'_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        vectorised(Loop::<L, CLAMP, false> {
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
    let b = batch(c, d, vn, r, m, out)?;
    dispatch(kernel, b).ok_or(Error::PairInvalid)
}

/// [`normal_force_batch`] with the power of general-p laws by [`FastPow`] (tables of the
/// exponent, cached per thread; a few ulp from the exact power) where the exponent has tables;
/// every other law, and general p outside [`FastPow`]'s range of exponents, gives
/// [`normal_force_batch`]'s bits.
pub fn normal_force_batch_fast(
    kernel: i32,
    c: Consts,
    d: &[f64],
    vn: &[f64],
    r: &[f64],
    m: &[f64],
    out: &mut [f64],
) -> Result<(), Error> {
    let b = batch(c, d, vn, r, m, out)?;
    dispatch(kernel, Fast(b)).ok_or(Error::PairInvalid)
}

/// The batch over the first `out.len()` entries of each input (checked long enough, n > 0).
fn batch<'a>(
    c: Consts,
    d: &'a [f64],
    vn: &'a [f64],
    r: &'a [f64],
    m: &'a [f64],
    out: &'a mut [f64],
) -> Result<Batch<'a>, Error> {
    let n = out.len();
    match (d.get(..n), vn.get(..n), r.get(..n), m.get(..n)) {
        (Some(d), Some(vn), Some(r), Some(m)) if n > 0 => Ok(Batch {
            c,
            d,
            vn,
            r,
            m,
            out,
        }),
        _ => Err(Error::BufferTooShort),
    }
}

/// A batch for [`normal_force_batch_fast`].
struct Fast<'a>(Batch<'a>);

impl Visit for Fast<'_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        if !L::POW {
            return vectorised(Loop::<L, CLAMP, true> {
                b: self.0,
                law: PhantomData,
            });
        }
        // (An adhesive law would need x^q beyond contact: none is a POW law; exact if one were.)
        match FastPow::cached(self.0.c.h).filter(|_| !L::ADHESIVE) {
            Some(t) => run_pow_fast::<L, CLAMP>(self.0, &t),
            None => self.0.visit::<L, CLAMP>(),
        }
    }
}

/// The fast batch of a `POW` law: s = d^h by [`FastPow`] in chunks of [`CHUNK`] contacts (the
/// AVX-512 or the AVX2 kernel where they run, else the scalar table path in the baseline
/// flavour, where each fused multiply–add is a call to the C library's `fma`: slower than the
/// exact batch there), then the forces by [`eval_fused`].
#[inline(always)]
fn run_pow_fast<L: Law, const CLAMP: bool>(b: Batch<'_>, t: &FastPow) {
    #[cfg(all(target_arch = "x86_64", not(miri)))]
    if has_avx512() {
        // SAFETY: the CPU has AVX-512F and FMA (checked just above), the only requirement.
        unsafe { run_pow_fast_avx512::<L, CLAMP>(b, t) };
        return;
    }
    #[cfg(all(target_arch = "x86_64", not(miri)))]
    if has_avx2() {
        // SAFETY: the CPU has AVX2 and FMA (checked just above), the only requirement.
        unsafe { run_pow_fast_avx2::<L, CLAMP>(b, t) };
        return;
    }
    // Neither kernel runs: the baseline flavour (`vectorised` would choose it too).
    pow_chunks::<L, CLAMP, true>(b, |d, s| pow_fast_slice(d, t, s));
}

/// [`run_pow_fast`] with AVX2 and FMA: the power by [`crate::numerics::pow_fast_avx2`], then the
/// force in a loop the compiler vectorises.
///
/// # Safety
/// The CPU must support AVX2 and FMA.
#[cfg(all(target_arch = "x86_64", not(miri)))]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
unsafe fn run_pow_fast_avx2<L: Law, const CLAMP: bool>(b: Batch<'_>, t: &FastPow) {
    use crate::numerics::pow_fast_avx2::pow_fast_slice_x4;
    pow_chunks::<L, CLAMP, true>(b, |d, s| pow_fast_slice_x4(d, t, s));
}

/// [`run_pow_fast`] with AVX-512F and FMA.
///
/// # Safety
/// The CPU must support AVX-512F and FMA.
#[cfg(all(target_arch = "x86_64", not(miri)))]
#[target_feature(enable = "avx512f,avx2,fma")]
#[inline(never)]
unsafe fn run_pow_fast_avx512<L: Law, const CLAMP: bool>(b: Batch<'_>, t: &FastPow) {
    use crate::numerics::pow_fast_avx512::{Tables, pow_fast_slice_x8};
    let tables = Tables::load(t);
    pow_chunks::<L, CLAMP, true>(b, |d, s| pow_fast_slice_x8(d, &tables, t, s));
}
