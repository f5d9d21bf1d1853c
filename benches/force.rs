//! Force kernels from Rust (the C-side comparison against gcc loops is
//! `scripts/bench_force.sh`). Each sample evaluates N = 1024 contacts (in cache); divan reports
//! items/s, ns per contact = time / N. Baseline in the same run: a hand-written Rust loop of the
//! same clamped Hertz expression, so that ratios survive a noisy shared machine.
//! Run: `cargo bench --bench force`.

use demcontact::ffi::{force::*, status::*};
use divan::{Bencher, black_box, counter::ItemsCount};

fn main() {
    divan::main();
}

const N: usize = 1024;

struct Data {
    d: Vec<f64>,
    vn: Vec<f64>,
    r: Vec<f64>,
    m: Vec<f64>,
}

fn data() -> Data {
    let mut s = 0x243F6A8885A308D3u64;
    let mut u = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut x = Data {
        d: vec![],
        vn: vec![],
        r: vec![],
        m: vec![],
    };
    for _ in 0..N {
        let r = 1e-4 * (1.0 + 9.0 * u());
        x.r.push(r);
        x.d.push(r * (0.011 * u() - 0.001));
        x.vn.push(2.0 * u() - 1.0);
        x.m.push(1e-6 * (1.0 + 99.0 * u()));
    }
    x
}

fn pair(p: f64) -> dc_pair {
    let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
    let s = unsafe {
        if p == 1.5 {
            dc_pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, DC_END_FORCE, pair.as_mut_ptr())
        } else {
            dc_pair_powerlaw(p, 1e8, 0.5, DC_END_FORCE, pair.as_mut_ptr())
        }
    };
    assert_eq!(s, DC_OK);
    unsafe { pair.assume_init() }
}

#[divan::bench]
fn baseline_hertz_loop(b: Bencher) {
    let (x, p) = (data(), pair(1.5));
    let mut out = vec![0.0; N];
    b.counter(ItemsCount::new(N)).bench_local(|| {
        let (kf, c) = (black_box(p.k), black_box(p.c));
        for ((((o, &d), &vn), &r), &m) in out.iter_mut().zip(&x.d).zip(&x.vn).zip(&x.r).zip(&x.m) {
            let q = (r * d).sqrt();
            let f = kf * q * d + c * (m * q).sqrt() * vn;
            let f = if f > 0.0 { f } else { 0.0 };
            *o = if d > 0.0 { f } else { 0.0 };
        }
        black_box(&mut out);
    });
}

/// A batch entry point of the C ABI (`dc_normal_force_batch` or `dc_normal_force_batch_fast`).
type BatchFn = unsafe extern "C" fn(
    *const dc_pair,
    usize,
    *const f64,
    *const f64,
    *const f64,
    *const f64,
    *mut f64,
) -> i32;

/// `f` over the N contacts through the C symbol.
fn bench_batch(b: Bencher, p: f64, f: BatchFn) {
    let (x, pair) = (data(), pair(p));
    let mut out = vec![0.0; N];
    b.counter(ItemsCount::new(N)).bench_local(|| {
        let s = unsafe {
            f(
                black_box(&pair),
                N,
                x.d.as_ptr(),
                x.vn.as_ptr(),
                x.r.as_ptr(),
                x.m.as_ptr(),
                out.as_mut_ptr(),
            )
        };
        black_box(s);
        black_box(&mut out);
    });
}

/// Batch through the C symbol, for the Hertz pair and the fixed-k exponent paths.
#[divan::bench(args = [1.0, 1.5, 2.0, 1.7])]
fn batch(b: Bencher, p: f64) {
    bench_batch(b, p, dc_normal_force_batch);
}

/// The fast batch (`dc_normal_force_batch_fast`: general p from per-exponent tables, FMA); compare
/// with `batch` of the same p in the same run.
#[divan::bench(args = [1.0, 1.5, 2.0, 1.7])]
fn batch_fast(b: Bencher, p: f64) {
    bench_batch(b, p, dc_normal_force_batch_fast);
}

/// One call per contact through the C symbol.
#[divan::bench(args = [1.0, 1.5, 2.0, 1.7])]
fn scalar(b: Bencher, p: f64) {
    let (x, pair) = (data(), pair(p));
    let mut out = vec![0.0; N];
    b.counter(ItemsCount::new(N)).bench_local(|| {
        let pp = black_box(&pair) as *const dc_pair;
        for ((((o, &d), &vn), &r), &m) in out.iter_mut().zip(&x.d).zip(&x.vn).zip(&x.r).zip(&x.m) {
            *o = unsafe { dc_normal_force(pp, d, vn, r, m) };
        }
        black_box(&mut out);
    });
}
