//! Structure-of-arrays batches: one dispatch per batch, then a plain loop over slices that the
//! compiler vectorises (square roots are IEEE instructions in Rust, never `errno` calls; the
//! general-p power is the branch-free [`crate::numerics::pow_dd`] kernel).
//!
//! **Runtime CPU dispatch.** Each monomorphised loop is compiled three times: for the baseline
//! x86-64 (SSE2, 2 lanes), for AVX2 + FMA (4 lanes) and for AVX-512F (8 lanes). The widest the
//! CPU supports is used, so one portable binary runs at `target-cpu=native` speed. The detection
//! is std's `is_x86_feature_detected!`, which queries `cpuid` once and then reads its cached
//! answer (one load and a test per batch call, not per contact). Enabling these features never
//! changes a result: Rust does not contract `a * b + c` into a fused multiply–add (only an
//! explicit `mul_add` would), so all three flavours round exactly like the scalar call and
//! the batch stays bit-identical to [`super::normal_force`] (tests/force_contract.rs).

use super::pair::{Consts, Law, Visit, eval};
use super::registry::dispatch;
use crate::Error;

struct Batch<'a> {
    c: Consts,
    d: &'a [f64],
    vn: &'a [f64],
    r: &'a [f64],
    m: &'a [f64],
    out: &'a mut [f64],
}

impl Visit for Batch<'_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        let Batch {
            c,
            d,
            vn,
            r,
            m,
            out,
        } = self;
        #[cfg(all(target_arch = "x86_64", not(miri)))]
        {
            if std::is_x86_feature_detected!("avx512f") {
                // SAFETY: the CPU supports AVX-512F (checked just above), the only requirement
                // of the target_feature function.
                unsafe { run_avx512::<L, CLAMP>(c, d, vn, r, m, out) };
                return;
            }
            if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
                // SAFETY: the CPU supports AVX2 and FMA (checked just above).
                unsafe { run_avx2::<L, CLAMP>(c, d, vn, r, m, out) };
                return;
            }
        }
        run::<L, CLAMP>(c, d, vn, r, m, out);
    }
}

/// The loop body, inlined into each CPU flavour below (only code inlined into a
/// `target_feature` function is compiled for its features).
#[inline(always)]
fn body<L: Law, const CLAMP: bool>(
    c: Consts,
    d: &[f64],
    vn: &[f64],
    r: &[f64],
    m: &[f64],
    out: &mut [f64],
) {
    for ((((o, &d), &vn), &r), &m) in out.iter_mut().zip(d).zip(vn).zip(r).zip(m) {
        *o = eval::<L, CLAMP>(&c, d, vn, r, m);
    }
}

// One monomorphised loop per kernel and CPU flavour: no branch on the model inside. Not inlined
// into the dispatcher so that each loop is compiled (and vectorised) on its own.
#[inline(never)]
fn run<L: Law, const CLAMP: bool>(
    c: Consts,
    d: &[f64],
    vn: &[f64],
    r: &[f64],
    m: &[f64],
    out: &mut [f64],
) {
    body::<L, CLAMP>(c, d, vn, r, m, out);
}

/// # Safety
/// The CPU must support AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
unsafe fn run_avx2<L: Law, const CLAMP: bool>(
    c: Consts,
    d: &[f64],
    vn: &[f64],
    r: &[f64],
    m: &[f64],
    out: &mut [f64],
) {
    body::<L, CLAMP>(c, d, vn, r, m, out);
}

/// # Safety
/// The CPU must support AVX-512F (which implies AVX2 and FMA).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx2,fma")]
#[inline(never)]
unsafe fn run_avx512<L: Law, const CLAMP: bool>(
    c: Consts,
    d: &[f64],
    vn: &[f64],
    r: &[f64],
    m: &[f64],
    out: &mut [f64],
) {
    body::<L, CLAMP>(c, d, vn, r, m, out);
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
