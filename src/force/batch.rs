//! Structure-of-arrays batches: one dispatch per batch, then a plain loop over slices that the
//! compiler vectorises (square roots are IEEE instructions in Rust, never `errno` calls).

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
        run::<L, CLAMP>(self.c, self.d, self.vn, self.r, self.m, self.out);
    }
}

// One monomorphised loop per kernel: no branch on the model inside. Not inlined into the
// dispatcher so that each loop is compiled (and vectorised) on its own.
#[inline(never)]
fn run<L: Law, const CLAMP: bool>(
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
