//! Contract of `dc_normal_force_batch_fast`: the exact batch's statuses for every bad call, its
//! bits for every pair without a general-p power, and for general p a force within the stated
//! bound of the exact batch (measured against the force's terms computed here with glibc's
//! `pow`) over overlaps from 1e-30 m to 1 m and speeds over nine decades; the per-thread table
//! cache gives the same bits whatever exponent ran before and on any thread.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

use demcontact::ffi::force::*;
use demcontact::ffi::status::*;
use demcontact::ffi::version::{DC_DISPATCH_AVX2, DC_DISPATCH_BASELINE};
use std::ptr::{null, null_mut};

const SENTINEL: f64 = -12345.678;
/// The tested bound: |F_fast - F_exact| <= BOUND_ULP * 2^-52 * (|elastic| + |damping|), i.e.
/// BOUND_ULP ulp of the terms' sum (measured maximum 5.64, at p = 1.7; 1.0 for damped Hertz).
const BOUND_ULP: f64 = 8.0;

type BatchFn = unsafe extern "C" fn(
    *const dc_pair,
    usize,
    *const f64,
    *const f64,
    *const f64,
    *const f64,
    *mut f64,
) -> i32;

fn make(f: impl Fn(*mut dc_pair) -> i32) -> dc_pair {
    let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
    assert_eq!(f(pair.as_mut_ptr()), DC_OK);
    unsafe { pair.assume_init() }
}

fn pairs() -> Vec<dc_pair> {
    let mut v = Vec::new();
    for c in [DC_END_OVERLAP, DC_END_FORCE] {
        for e in [0.05, 0.3, 1.0] {
            for p in [1.0, 1.5, 1.7, 2.0, 2.7, 5.0, 9.0, 9.5] {
                v.push(make(|o| unsafe { dc_pair_powerlaw(p, 1e6, e, c, o) }));
            }
            v.push(make(|o| unsafe {
                dc_pair_hertz(1e9, 0.3, 2e9, 0.2, e, c, o)
            }));
        }
        v.push(make(|o| unsafe {
            dc_pair_viscoelastic(1e9, 0.3, 1e9, 0.3, 2e-4, c, o)
        }));
    }
    v
}

/// Deterministic inputs: overlaps log-uniform over 1e-30 .. 1 m (a tenth of them not
/// touching: -0, 0, negative or NaN), vn of both signs over 1e-6 .. 1e3 m/s, r and m positive.
fn inputs(n: usize, seed: u64) -> [Vec<f64>; 4] {
    let mut s = seed;
    let mut u = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut a: [Vec<f64>; 4] = Default::default();
    for i in 0..n {
        let d = match i % 10 {
            0 => [0.0, -0.0, -1e-6, f64::NAN][i / 10 % 4],
            _ => 10f64.powf(-30.0 + 30.0 * u()),
        };
        let vn = 10f64.powf(-6.0 + 9.0 * u()) * if u() < 0.5 { -1.0 } else { 1.0 };
        a[0].push(d);
        a[1].push(vn);
        a[2].push(1e-4 * (1.0 + 9.0 * u()));
        a[3].push(10f64.powf(-9.0 + 6.0 * u()));
    }
    a
}

fn run(f: BatchFn, pair: &dc_pair, a: &[Vec<f64>; 4]) -> (i32, Vec<f64>) {
    let n = a[0].len();
    let mut out = vec![SENTINEL; n];
    let s = unsafe {
        f(
            pair,
            n,
            a[0].as_ptr(),
            a[1].as_ptr(),
            a[2].as_ptr(),
            a[3].as_ptr(),
            out.as_mut_ptr(),
        )
    };
    (s, out)
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

fn is_general_p(pair: &dc_pair) -> bool {
    pair.model == DC_MODEL_POWERLAW && ![1.0, 1.5, 2.0].contains(&pair.p)
}

/// Pairs whose fast batch differs from the exact one: general p with tables (p <= 9), whose
/// power is the table path, and damped Hertz, whose two terms are summed by a fused
/// multiply-add. Every other pair must give the exact batch's bits.
fn differs(pair: &dc_pair) -> bool {
    (is_general_p(pair) && pair.p <= 9.0) || (pair.model == DC_MODEL_HERTZ && pair.alpha > 0.0)
}

#[test]
fn same_bits_as_the_exact_batch_where_nothing_differs() {
    let sizes: &[usize] = if cfg!(miri) {
        &[1, 9, 64]
    } else {
        &[1, 2, 3, 7, 64, 1001, 5000]
    };
    let mut seen = 0;
    for &n in sizes {
        let a = inputs(n, 0x9E37_79B9_7F4A_7C15 ^ n as u64);
        for pair in pairs().iter().filter(|p| !differs(p)) {
            let (s1, exact) = run(dc_normal_force_batch, pair, &a);
            let (s2, fast) = run(dc_normal_force_batch_fast, pair, &a);
            assert_eq!((s1, s2), (DC_OK, DC_OK));
            for i in 0..n {
                assert_eq!(
                    fast[i].to_bits(),
                    exact[i].to_bits(),
                    "kernel {} i={i}",
                    pair.kernel
                );
            }
            seen += 1;
        }
    }
    assert!(seen >= 20 * sizes.len(), "{seen}");
}

/// |elastic| + |damping| of the force at one contact, computed here (glibc's pow).
fn terms(pair: &dc_pair, d: f64, vn: f64, r: f64, m: f64) -> f64 {
    if pair.model == DC_MODEL_HERTZ {
        let q = (r * d).sqrt();
        return (pair.k * q * d).abs() + (pair.c * (m * q).sqrt() * vn).abs();
    }
    let s = d.powf(pair.h);
    (pair.k * d * s * s).abs() + (pair.c * m.sqrt() * s * vn).abs()
}

/// The largest |F_fast - F_exact| / (2^-52 (|elastic| + |damping|)) of one pair.
fn worst_ulps(pair: &dc_pair, a: &[Vec<f64>; 4]) -> f64 {
    let (s1, exact) = run(dc_normal_force_batch, pair, a);
    let (s2, fast) = run(dc_normal_force_batch_fast, pair, a);
    assert_eq!((s1, s2), (DC_OK, DC_OK));
    let mut worst: f64 = 0.0;
    for i in 0..a[0].len() {
        let (d, vn, r, m) = (a[0][i], a[1][i], a[2][i], a[3][i]);
        if !(d > 0.0) {
            assert_eq!(fast[i].to_bits(), 0.0f64.to_bits(), "no contact, i={i}");
            assert_eq!(exact[i].to_bits(), 0.0f64.to_bits(), "no contact, i={i}");
            continue;
        }
        let e = (fast[i] - exact[i]).abs() / (terms(pair, d, vn, r, m) * f64::EPSILON);
        assert!(
            e.is_finite(),
            "p = {}, i = {i}: {} vs {}",
            pair.p,
            fast[i],
            exact[i]
        );
        worst = worst.max(e);
    }
    worst
}

#[test]
fn within_the_bound_of_the_exact_batch() {
    let n = if cfg!(miri) { 40 } else { 200_000 };
    let a = inputs(n, 7);
    let mut worst: f64 = 0.0;
    let mut seen = 0;
    for pair in pairs().iter().filter(|p| differs(p)) {
        let w = worst_ulps(pair, &a);
        println!(
            "model {}, p = {}, e = {}, kernel {}: max {w:.2} ulp of the terms",
            pair.model, pair.p, pair.e, pair.kernel
        );
        worst = worst.max(w);
        seen += 1;
    }
    assert!(seen >= 16, "{seen} pairs");
    assert!(worst <= BOUND_ULP, "{worst} > {BOUND_ULP}");
}

#[test]
fn p_beyond_the_tables_is_the_exact_batch() {
    // p = 9.5 (q = 4.25 > 4): no tables, the exact power.
    let a = inputs(if cfg!(miri) { 9 } else { 3000 }, 3);
    let pair = make(|o| unsafe { dc_pair_powerlaw(9.5, 1e6, 0.4, DC_END_FORCE, o) });
    let (_, exact) = run(dc_normal_force_batch, &pair, &a);
    let (_, fast) = run(dc_normal_force_batch_fast, &pair, &a);
    assert!(
        exact
            .iter()
            .zip(&fast)
            .all(|(x, y)| x.to_bits() == y.to_bits())
    );
}

#[test]
fn the_table_cache_changes_no_bit() {
    let a = inputs(if cfg!(miri) { 17 } else { 3001 }, 11);
    // Eleven exponents, more than a thread caches (8): each comes back after being evicted.
    let ps = [1.7, 2.7, 3.1, 4.4, 5.2, 1.3, 6.1, 7.3, 8.8, 1.1, 2.05];
    let pairs: Vec<dc_pair> = ps
        .iter()
        .map(|&p| make(|o| unsafe { dc_pair_powerlaw(p, 1e6, 0.4, DC_END_FORCE, o) }))
        .collect();
    let first: Vec<Vec<u64>> = pairs
        .iter()
        .map(|p| bits(&run(dc_normal_force_batch_fast, p, &a).1))
        .collect();
    for round in 0..3 {
        for (k, p) in pairs.iter().enumerate().rev() {
            let again = bits(&run(dc_normal_force_batch_fast, p, &a).1);
            assert_eq!(again, first[k], "round {round}, p = {}", ps[k]);
        }
    }
    // On fresh threads at the same time.
    std::thread::scope(|sc| {
        let hs: Vec<_> = (0..4)
            .map(|k| {
                let (a, pairs) = (&a, &pairs);
                sc.spawn(move || (k, bits(&run(dc_normal_force_batch_fast, &pairs[k], a).1)))
            })
            .collect();
        for h in hs {
            let (k, out) = h.join().unwrap();
            assert_eq!(out, first[k], "thread {k}");
        }
    });
    // And the fast batch of each differs from the exact one somewhere (the cache holds tables,
    // not a fallback to the exact power).
    for (k, p) in pairs.iter().enumerate() {
        let exact = bits(&run(dc_normal_force_batch, p, &a).1);
        assert_ne!(exact, first[k], "p = {}", ps[k]);
    }
}

#[test]
fn statuses_and_untouched_output_as_the_exact_batch() {
    let n = 16;
    let a = inputs(n, 5);
    let [d, vn, r, m] = &a;
    let gen17 = make(|o| unsafe { dc_pair_powerlaw(1.7, 1e6, 0.4, DC_END_FORCE, o) });
    let hertz = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, o) });
    let zero: dc_pair = unsafe { std::mem::zeroed() };
    for pair in [&gen17, &hertz] {
        let mut statuses = Vec::new();
        for f in [dc_normal_force_batch as BatchFn, dc_normal_force_batch_fast] {
            let mut out = vec![SENTINEL; n + 1];
            let o = out.as_mut_ptr();
            let call = |pair: *const dc_pair, n: usize, d: *const f64, vn: *const f64, o| unsafe {
                f(pair, n, d, vn, r.as_ptr(), m.as_ptr(), o)
            };
            let mis = unsafe { (o as *mut u8).add(1) as *mut f64 };
            let got = [
                call(null(), n, d.as_ptr(), vn.as_ptr(), o),
                call(pair, n, null(), vn.as_ptr(), o),
                call(pair, n, d.as_ptr(), null(), o),
                call(pair, n, d.as_ptr(), vn.as_ptr(), null_mut()),
                call(&zero, n, d.as_ptr(), vn.as_ptr(), o),
                call(pair, 0, d.as_ptr(), vn.as_ptr(), o),
                call(pair, usize::MAX / 4, d.as_ptr(), vn.as_ptr(), o),
                call(pair, n - 1, d.as_ptr(), vn.as_ptr(), mis),
            ];
            assert!(out.iter().all(|&x| x == SENTINEL), "output touched");
            let mut buf = d.clone();
            buf.push(0.0);
            let b = buf.as_mut_ptr();
            let in_place = unsafe { f(pair, n, b, vn.as_ptr(), r.as_ptr(), m.as_ptr(), b) };
            assert_eq!(&buf[..n], &d[..], "input overwritten");
            statuses.push((got, in_place));
        }
        let want = [
            DC_ERR_NULL_POINTER,
            DC_ERR_NULL_POINTER,
            DC_ERR_NULL_POINTER,
            DC_ERR_NULL_POINTER,
            DC_ERR_PAIR_INVALID,
            DC_ERR_BUFFER_TOO_SHORT,
            DC_ERR_BUFFER_LAYOUT,
            DC_ERR_BUFFER_LAYOUT,
        ];
        assert_eq!(statuses[0], (want, DC_ERR_BUFFER_LAYOUT));
        assert_eq!(statuses[1], statuses[0]);
    }
}

/// FNV-1a over the bits of the exact and the fast batch of every pair on inputs with special
/// values, and the flavour that ran (dc_dispatch_level).
fn digest() -> (i32, u64) {
    let mut a = inputs(if cfg!(miri) { 20 } else { 4099 }, 21);
    for (i, x) in [
        f64::INFINITY,
        5e-324,
        1e-310,
        1e-39,
        1e39,
        f64::MAX,
        f64::NAN,
    ]
    .into_iter()
    .enumerate()
    {
        a[0][3 * i + 1] = x;
    }
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for pair in pairs() {
        for f in [dc_normal_force_batch as BatchFn, dc_normal_force_batch_fast] {
            let (s, out) = run(f, &pair, &a);
            assert_eq!(s, DC_OK);
            for b in bits(&out) {
                h = (h ^ b).wrapping_mul(0x0000_0100_0000_01b3);
            }
        }
    }
    (demcontact::ffi::version::dc_dispatch_level(), h)
}

#[test]
fn same_bits_in_every_vector_flavour() {
    // In a child process (DEMCONTACT_DISPATCH is read once per process): print the digest.
    if std::env::var_os("DC_FLAVOUR_CHILD").is_some() {
        let (level, h) = digest();
        println!("flavour {level} digest {h:016x}");
        return;
    }
    if cfg!(miri) || !cfg!(target_arch = "x86_64") {
        println!("skipped: one flavour only (Miri or not x86-64)");
        return;
    }
    let exe = std::env::current_exe().unwrap();
    let mut seen = Vec::new();
    for cap in ["baseline", "avx2", "auto"] {
        let out = std::process::Command::new(&exe)
            .args([
                "--exact",
                "same_bits_in_every_vector_flavour",
                "--nocapture",
                "--test-threads=1",
            ])
            .env("DC_FLAVOUR_CHILD", "1")
            .env("DEMCONTACT_DISPATCH", cap)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{cap}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8_lossy(&out.stdout);
        // (libtest may print its "test ... " prefix on the same line)
        let line = text
            .lines()
            .find_map(|l| {
                l.rfind("flavour ")
                    .filter(|_| l.contains(" digest "))
                    .map(|k| &l[k..])
            })
            .unwrap_or_else(|| panic!("{cap}: {text}"));
        let mut w = line.split_whitespace();
        let level: i32 = w.nth(1).unwrap().parse().unwrap();
        let h = w.nth(1).unwrap().to_string();
        println!("DEMCONTACT_DISPATCH={cap}: flavour {level}, digest {h}");
        seen.push((cap, level, h));
    }
    // The cap is honoured (as far as the CPU goes), and the bits do not depend on it.
    let (l0, l1, l2) = (seen[0].1, seen[1].1, seen[2].1);
    assert_eq!(l0, DC_DISPATCH_BASELINE);
    assert!(l1 <= DC_DISPATCH_AVX2 && l2 >= l1, "{seen:?}");
    if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
        assert_eq!(l1, DC_DISPATCH_AVX2);
    }
    assert!(seen.iter().all(|s| s.2 == seen[0].2), "{seen:?}");
}
