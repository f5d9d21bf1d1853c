//! Boundary contract of the force exports: batch = scalar bit for bit for every kernel, NULL for
//! unread arrays, statuses for bad pointers/layouts/pairs/inputs with outputs untouched, the
//! checked scalar, the constructors' statuses, and the 3D helper against geometry done here.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

use demcontact::ffi::force::*;
use demcontact::ffi::status::*;
use std::ptr::{null, null_mut};

const SENTINEL: f64 = -12345.678;

fn make(f: impl Fn(*mut dc_pair) -> i32) -> dc_pair {
    let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
    assert_eq!(f(pair.as_mut_ptr()), DC_OK);
    unsafe { pair.assume_init() }
}

fn pairs() -> Vec<dc_pair> {
    let mut v = Vec::new();
    for c in [DC_END_OVERLAP, DC_END_FORCE] {
        for e in [0.3, 1.0] {
            for p in [1.0, 1.5, 2.0, 2.7] {
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

/// Deterministic pseudo-random inputs (xorshift), including non-contacts and both signs of vn.
fn inputs(n: usize) -> [Vec<f64>; 4] {
    let mut s = 0x9E3779B97F4A7C15u64;
    let mut u = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut a: [Vec<f64>; 4] = Default::default();
    for _ in 0..n {
        let r = 1e-4 * (1.0 + 9.0 * u());
        a[0].push(r * (0.05 * u() - 0.005));
        a[1].push(2.0 * u() - 1.0);
        a[2].push(r);
        a[3].push(1e-6 * (1.0 + u()));
    }
    a
}

#[test]
fn batch_equals_scalar_bitwise() {
    // Under Miri (scripts/miri.sh, 10^4 to 10^6 times slower) without the long array: 64
    // contacts reach every loop of the batch (the general-p batch works in chunks of 256
    // contacts, src/force/batch.rs; 1001 also crosses chunk boundaries and, with AVX-512, ends
    // in a masked group of lanes) (scripts/miri_coverage.sh).
    let sizes: &[usize] = if cfg!(miri) {
        &[1, 2, 3, 7, 64]
    } else {
        &[1, 2, 3, 7, 64, 1001]
    };
    for &n in sizes {
        let [d, vn, r, m] = inputs(n);
        for pair in pairs() {
            let mut out = vec![SENTINEL; n];
            let s = unsafe {
                dc_normal_force_batch(
                    &pair,
                    n,
                    d.as_ptr(),
                    vn.as_ptr(),
                    r.as_ptr(),
                    m.as_ptr(),
                    out.as_mut_ptr(),
                )
            };
            assert_eq!(s, DC_OK);
            for i in 0..n {
                let want = unsafe { dc_normal_force(&pair, d[i], vn[i], r[i], m[i]) };
                assert_eq!(
                    out[i].to_bits(),
                    want.to_bits(),
                    "kernel {} i={i}",
                    pair.kernel
                );
            }
        }
    }
}

#[test]
fn batch_accepts_null_for_arrays_the_pair_does_not_read() {
    let n = 33;
    let [d, vn, r, m] = inputs(n);
    let mut out = vec![0.0; n];
    let lin = make(|o| unsafe { dc_pair_powerlaw(1.0, 1e5, 0.5, DC_END_FORCE, o) });
    assert_eq!(
        unsafe {
            dc_normal_force_batch(
                &lin,
                n,
                d.as_ptr(),
                vn.as_ptr(),
                null(),
                m.as_ptr(),
                out.as_mut_ptr(),
            )
        },
        DC_OK
    );
    let elastic = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 1.0, DC_END_FORCE, o) });
    assert_eq!(
        unsafe {
            dc_normal_force_batch(
                &elastic,
                n,
                d.as_ptr(),
                null(),
                r.as_ptr(),
                null(),
                out.as_mut_ptr(),
            )
        },
        DC_OK
    );
    let visco =
        make(|o| unsafe { dc_pair_viscoelastic(1e9, 0.3, 1e9, 0.3, 1e-5, DC_END_FORCE, o) });
    assert_eq!(
        unsafe {
            dc_normal_force_batch(
                &visco,
                n,
                d.as_ptr(),
                vn.as_ptr(),
                r.as_ptr(),
                null(),
                out.as_mut_ptr(),
            )
        },
        DC_OK
    );
    // ... but not for arrays it reads.
    let mut out = vec![SENTINEL; n];
    let hertz = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, o) });
    for (a, b, c) in [
        (null(), r.as_ptr(), m.as_ptr()),
        (vn.as_ptr(), null(), m.as_ptr()),
        (vn.as_ptr(), r.as_ptr(), null()),
    ] {
        assert_eq!(
            unsafe { dc_normal_force_batch(&hertz, n, d.as_ptr(), a, b, c, out.as_mut_ptr()) },
            DC_ERR_NULL_POINTER
        );
    }
    assert!(out.iter().all(|&x| x == SENTINEL));
}

#[test]
fn batch_statuses() {
    let n = 16;
    let [d, vn, r, m] = inputs(n);
    let hertz = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, o) });
    let zero: dc_pair = unsafe { std::mem::zeroed() };
    let mut out = vec![SENTINEL; n + 1];
    let o = out.as_mut_ptr();
    let call = |pair: *const dc_pair, n: usize, d: *const f64, o: *mut f64| unsafe {
        dc_normal_force_batch(pair, n, d, vn.as_ptr(), r.as_ptr(), m.as_ptr(), o)
    };
    assert_eq!(call(null(), n, d.as_ptr(), o), DC_ERR_NULL_POINTER);
    assert_eq!(call(&hertz, n, null(), o), DC_ERR_NULL_POINTER);
    assert_eq!(call(&hertz, n, d.as_ptr(), null_mut()), DC_ERR_NULL_POINTER);
    assert_eq!(call(&zero, n, d.as_ptr(), o), DC_ERR_PAIR_INVALID);
    assert_eq!(call(&hertz, 0, d.as_ptr(), o), DC_ERR_BUFFER_TOO_SHORT);
    assert_eq!(
        call(&hertz, usize::MAX / 4, d.as_ptr(), o),
        DC_ERR_BUFFER_LAYOUT
    );
    // Misaligned output.
    let mis = unsafe { (o as *mut u8).add(1) as *mut f64 };
    assert_eq!(call(&hertz, n - 1, d.as_ptr(), mis), DC_ERR_BUFFER_LAYOUT);
    assert!(out.iter().all(|&x| x == SENTINEL));
    // In place / partially overlapping output.
    let mut buf = d.clone();
    buf.push(0.0);
    let b = buf.as_mut_ptr();
    assert_eq!(call(&hertz, n, b, b), DC_ERR_BUFFER_LAYOUT);
    assert_eq!(
        call(&hertz, n, b, unsafe { b.add(1) }),
        DC_ERR_BUFFER_LAYOUT
    );
    assert_eq!(&buf[..n], &d[..]);
}

#[test]
fn scalar_garbage_is_defined() {
    let zero: dc_pair = unsafe { std::mem::zeroed() };
    assert!(unsafe { dc_normal_force(null(), 1e-6, 1.0, 1e-3, 1e-3) }.is_nan());
    assert!(unsafe { dc_normal_force(&zero, 1e-6, 1.0, 1e-3, 1e-3) }.is_nan());
    let mut garbage = zero;
    garbage.kernel = -77;
    assert!(unsafe { dc_normal_force(&garbage, 1e-6, 1.0, 1e-3, 1e-3) }.is_nan());
    // Documented: a clamped pair with NaN speed gives 0, an unclamped one NaN.
    let cl = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, o) });
    let un = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_OVERLAP, o) });
    assert_eq!(
        unsafe { dc_normal_force(&cl, 1e-6, f64::NAN, 1e-3, 1e-3) },
        0.0
    );
    assert!(unsafe { dc_normal_force(&un, 1e-6, f64::NAN, 1e-3, 1e-3) }.is_nan());
}

#[test]
fn checked_statuses() {
    let hertz = make(|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, o) });
    let lin = make(|o| unsafe { dc_pair_linear(1e5, 0.5, DC_END_OVERLAP, o) });
    let zero: dc_pair = unsafe { std::mem::zeroed() };
    let call = |p: *const dc_pair, d: f64, vn: f64, r: f64, m: f64| {
        let mut out = SENTINEL;
        let s = unsafe { dc_normal_force_checked(p, d, vn, r, m, &mut out) };
        if s != DC_OK {
            assert_eq!(out, SENTINEL);
        }
        (s, out)
    };
    let (s, f) = call(&hertz, 1e-6, 0.5, 1e-3, 1e-3);
    assert_eq!(s, DC_OK);
    assert_eq!(f, unsafe { dc_normal_force(&hertz, 1e-6, 0.5, 1e-3, 1e-3) });
    assert_eq!(call(&hertz, -1.0, 0.5, 1e-3, 1e-3), (DC_OK, 0.0));
    assert_eq!(call(null(), 1e-6, 0.5, 1e-3, 1e-3).0, DC_ERR_NULL_POINTER);
    assert_eq!(call(&zero, 1e-6, 0.5, 1e-3, 1e-3).0, DC_ERR_PAIR_INVALID);
    assert_eq!(call(&hertz, f64::NAN, 0.5, 1e-3, 1e-3).0, DC_ERR_NOT_FINITE);
    assert_eq!(
        call(&hertz, 1e-6, f64::INFINITY, 1e-3, 1e-3).0,
        DC_ERR_NOT_FINITE
    );
    assert_eq!(call(&hertz, 1e-6, 0.5, 0.0, 1e-3).0, DC_ERR_NOT_POSITIVE);
    assert_eq!(call(&hertz, 1e-6, 0.5, 1e-3, -1.0).0, DC_ERR_NOT_POSITIVE);
    assert_eq!(
        call(&hertz, 1e300, -1e300, 1e300, 1e300).0,
        DC_ERR_RESULT_RANGE
    );
    // r_eff is not read by fixed-k pairs, so it is not checked either.
    assert_eq!(call(&lin, 1e-6, 0.5, f64::NAN, 1e-3).0, DC_OK);
    assert_eq!(
        unsafe { dc_normal_force_checked(&hertz, 1e-6, 0.5, 1e-3, 1e-3, null_mut()) },
        DC_ERR_NULL_POINTER
    );
}

#[test]
fn constructor_statuses() {
    let run = |f: &dyn Fn(*mut dc_pair) -> i32| {
        let mut pair: dc_pair = unsafe { std::mem::zeroed() };
        pair.p = SENTINEL;
        let s = f(&mut pair);
        if s != DC_OK {
            assert_eq!(pair.p, SENTINEL, "output touched on error");
        }
        s
    };
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(1.5, 1e6, 0.5, DC_END_FORCE, o) }),
        DC_OK
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(0.9, 1e6, 0.5, DC_END_FORCE, o) }),
        DC_ERR_EXPONENT_RANGE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(1.5, 0.0, 0.5, DC_END_FORCE, o) }),
        DC_ERR_NOT_POSITIVE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(1.5, f64::NAN, 0.5, DC_END_FORCE, o) }),
        DC_ERR_NOT_FINITE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(1.5, 1e6, 0.0, DC_END_FORCE, o) }),
        DC_ERR_RESTITUTION_RANGE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(1.5, 1e6, 0.5, 3, o) }),
        DC_ERR_CRITERION
    );
    assert_eq!(
        unsafe { dc_pair_powerlaw(1.5, 1e6, 0.5, DC_END_FORCE, null_mut()) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw(1.5, f64::MAX, 5e-324, DC_END_FORCE, o) }),
        DC_ERR_RESULT_RANGE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_powerlaw_alpha(1.5, 1e6, -1.0, DC_END_FORCE, o) }),
        DC_ERR_NEGATIVE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_linear(-1.0, 0.5, DC_END_FORCE, o) }),
        DC_ERR_NOT_POSITIVE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_hertz(1e9, 0.7, 1e9, 0.3, 0.5, DC_END_FORCE, o) }),
        DC_ERR_POISSON_RANGE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 1.5, DC_END_FORCE, o) }),
        DC_ERR_RESTITUTION_RANGE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_viscoelastic(1e9, 0.3, 1e9, 0.3, -1e-6, DC_END_FORCE, o) }),
        DC_ERR_NEGATIVE
    );
    assert_eq!(
        run(&|o| unsafe { dc_pair_viscoelastic(1e9, 0.3, 1e9, 0.3, f64::NAN, DC_END_FORCE, o) }),
        DC_ERR_NOT_FINITE
    );
    // alpha given directly round-trips through its restitution.
    let a = make(|o| unsafe { dc_pair_powerlaw(2.0, 1e6, 0.37, DC_END_FORCE, o) });
    let b = make(|o| unsafe { dc_pair_powerlaw_alpha(2.0, 1e6, a.alpha, DC_END_FORCE, o) });
    assert_eq!((a.kernel, a.c), (b.kernel, b.c));
    assert!((b.e - 0.37).abs() < 1e-14);
    assert_eq!(
        (DC_MODEL_POWERLAW, DC_MODEL_HERTZ, DC_MODEL_VISCOELASTIC),
        (a.model, 2, 3)
    );
}

#[test]
fn three_d_helper_geometry_and_signs() {
    let hertz = make(|o| unsafe { dc_pair_hertz(5e8, 0.25, 2e9, 0.35, 0.6, DC_END_OVERLAP, o) });
    let (r1, r2, m1, m2) = (1e-3f64, 2.5e-3f64, 3e-6f64, 4e-5f64);
    // Sphere 2 at the origin, sphere 1 along a skew direction, overlapping by delta, approaching.
    let dir = [1.0f64, -2.0, 0.5];
    let len = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
    let u = dir.map(|c| c / len);
    let delta = 3e-6;
    let dist = r1 + r2 - delta;
    let x1 = u.map(|c| c * dist);
    let x2 = [0.0; 3];
    let w = [0.3, 0.1, -0.7]; // common tangential-ish drift, no effect on vn
    let v1 = [w[0] - 0.2 * u[0], w[1] - 0.2 * u[1], w[2] - 0.2 * u[2]]; // sphere 1 moves towards 2
    let v2 = w;
    let mut f = [SENTINEL; 3];
    let s = unsafe {
        dc_normal_force_3d(
            &hertz,
            x1.as_ptr(),
            v1.as_ptr(),
            r1,
            m1,
            x2.as_ptr(),
            v2.as_ptr(),
            r2,
            m2,
            f.as_mut_ptr(),
        )
    };
    assert_eq!(s, DC_OK);
    let reff = r1 * r2 / (r1 + r2);
    let meff = m1 * m2 / (m1 + m2);
    let fmag = unsafe { dc_normal_force(&hertz, delta, 0.2, reff, meff) };
    assert!(fmag > 0.0);
    for i in 0..3 {
        // Repulsive force on sphere 1 points away from sphere 2, i.e. along u.
        assert!(
            (f[i] - fmag * u[i]).abs() <= 1e-9 * fmag,
            "{i}: {} vs {}",
            f[i],
            fmag * u[i]
        );
    }
    // Separated spheres: zero vector.
    let far = u.map(|c| c * (r1 + r2 + 1e-9));
    let s = unsafe {
        dc_normal_force_3d(
            &hertz,
            far.as_ptr(),
            v1.as_ptr(),
            r1,
            m1,
            x2.as_ptr(),
            v2.as_ptr(),
            r2,
            m2,
            f.as_mut_ptr(),
        )
    };
    assert_eq!((s, f), (DC_OK, [0.0; 3]));
    // Bad input: statuses, output untouched.
    let mut f = [SENTINEL; 3];
    let bad = |x1: *const f64, r1: f64, m1: f64, f: *mut f64| unsafe {
        dc_normal_force_3d(
            &hertz,
            x1,
            v1.as_ptr(),
            r1,
            m1,
            x2.as_ptr(),
            v2.as_ptr(),
            r2,
            m2,
            f,
        )
    };
    assert_eq!(bad(null(), r1, m1, f.as_mut_ptr()), DC_ERR_NULL_POINTER);
    assert_eq!(bad(x1.as_ptr(), r1, m1, null_mut()), DC_ERR_NULL_POINTER);
    assert_eq!(
        bad(x1.as_ptr(), -r1, m1, f.as_mut_ptr()),
        DC_ERR_NOT_POSITIVE
    );
    assert_eq!(
        bad(x1.as_ptr(), r1, f64::NAN, f.as_mut_ptr()),
        DC_ERR_NOT_FINITE
    );
    assert_eq!(
        bad(x2.as_ptr(), r1, m1, f.as_mut_ptr()),
        DC_ERR_NOT_POSITIVE
    ); // coincident centres
    assert_eq!(f, [SENTINEL; 3]);
}
