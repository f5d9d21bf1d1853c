//! Contract of the full-contact exports: every status, outputs and history untouched on error,
//! normal-only results bit-identical to dc_normal_force, batch = scalar bit for bit, the spheres
//! helper = the state form, and history handling.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::model;
use demcontact::ffi::contact::*;
use demcontact::ffi::force::*;
use demcontact::ffi::status::*;

fn spec() -> dc_contact_spec {
    let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { dc_contact_spec_init(&mut s) }, DC_OK);
    s
}

fn hertz(s: &mut dc_contact_spec) {
    s.normal = DC_NORMAL_HERTZ;
    s.E1 = 70e9;
    s.nu1 = 0.3;
    s.E2 = 70e9;
    s.nu2 = 0.3;
}

fn bytes<T>(x: &T) -> Vec<u8> {
    unsafe { std::slice::from_raw_parts((x as *const T).cast::<u8>(), std::mem::size_of::<T>()) }
        .to_vec()
}

fn init(s: &dc_contact_spec) -> (i32, dc_contact_model) {
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    m.mu = 12345.0;
    let before = bytes(&m);
    let st = unsafe { dc_contact_model_init(s, &mut m) };
    if st != DC_OK {
        assert_eq!(bytes(&m), before, "model touched on error {st}");
    }
    (st, m)
}

/// Every sub-model combination (and both criteria, damped or not).
fn all_models() -> Vec<dc_contact_model> {
    let mut v = Vec::new();
    for t in [
        DC_TANGENTIAL_NONE,
        DC_TANGENTIAL_LINEAR,
        DC_TANGENTIAL_MINDLIN,
    ] {
        for r in [DC_ROLLING_NONE, DC_ROLLING_CONSTANT, DC_ROLLING_EPSD] {
            for tw in [DC_TWISTING_NONE, DC_TWISTING_SDS] {
                for (damp, crit) in [
                    (DC_DAMPING_NONE, DC_END_FORCE),
                    (DC_DAMPING_RESTITUTION, DC_END_FORCE),
                    (DC_DAMPING_RESTITUTION, DC_END_OVERLAP),
                ] {
                    v.push(model(|s| {
                        hertz(s);
                        s.damping = damp;
                        s.e_n = 0.6;
                        s.criterion = crit;
                        s.tangential = t;
                        s.rolling = r;
                        s.twisting = tw;
                        s.mu = 0.3;
                        s.k_t = 2e5;
                        s.e_t = 0.7;
                        s.mu_r = 0.05;
                        s.eta_r = 0.3;
                        s.k_r = if tw == DC_TWISTING_SDS { 0.0 } else { 1e-3 };
                        s.mu_tw = 1e-5;
                        s.k_tw = 1e-3;
                        s.eta_tw = 0.2;
                    }));
                }
            }
        }
    }
    v
}

/// A set of contact states: sphere-sphere, sphere-wall, fixed sphere, separated, spinning.
fn states() -> Vec<dc_contact_state> {
    let s = |n: [f64; 3], d: f64, r2: f64, m2: f64| dc_contact_state {
        n,
        overlap: d,
        v1: [0.3, -0.2, 0.1],
        v2: [-0.1, 0.05, 0.2],
        w1: [10.0, -20.0, 5.0],
        w2: [3.0, 4.0, -50.0],
        r1: 1e-3,
        r2,
        m1: 1e-5,
        m2,
    };
    let c = 1.0 / 3f64.sqrt();
    vec![
        s([1.0, 0.0, 0.0], 1e-6, 2e-3, 8e-5),
        s([c, c, c], 3e-6, 1e-3, 1e-5),
        s([0.0, 1.0, 0.0], 2e-6, f64::INFINITY, f64::INFINITY),
        s([0.0, 0.0, 1.0], 2e-6, 1.5e-3, f64::INFINITY),
        s([0.6, 0.8, 0.0], 1e-7, f64::INFINITY, 1.0),
        s([1.0, 0.0, 0.0], -1e-6, 2e-3, 8e-5),
        s([0.0, 0.6, 0.8], 0.0, 2e-3, 8e-5),
    ]
}

const ZERO_RES: dc_contact_result = dc_contact_result {
    force: [0.0; 3],
    torque1: [0.0; 3],
    torque2: [0.0; 3],
    f_n: 0.0,
    ft: [0.0; 3],
    sliding: 0,
    rolling_sliding: 0,
};

fn sentinel_res() -> dc_contact_result {
    dc_contact_result {
        f_n: -7.5,
        ..ZERO_RES
    }
}

#[test]
fn spec_init_defaults_and_null() {
    let s = spec();
    assert_eq!(s.version, DC_CONTACT_SPEC_VERSION);
    assert_eq!(s.size as usize, std::mem::size_of::<dc_contact_spec>());
    assert_eq!(
        (s.normal, s.damping, s.criterion),
        (0, DC_DAMPING_NONE, DC_END_FORCE)
    );
    assert!(s.E1.is_nan() && s.mu.is_nan() && s.k_t.is_nan());
    assert_eq!((s.e_t, s.k_r, s.inertia_factor), (1.0, 0.0, 0.4));
    assert_eq!(
        unsafe { dc_contact_spec_init(std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
}

#[test]
fn model_init_statuses() {
    let base = {
        let mut s = spec();
        hertz(&mut s);
        s
    };
    assert_eq!(init(&base).0, DC_OK);
    // An unset normal law.
    assert_eq!(init(&spec()).0, DC_ERR_SPEC_MODEL);
    let cases: Vec<(Box<dyn Fn(&mut dc_contact_spec)>, i32)> = vec![
        (Box::new(|s| s.version = 2), DC_ERR_SPEC_VERSION),
        (Box::new(|s| s.version = 0), DC_ERR_SPEC_VERSION),
        (Box::new(|s| s.size -= 8), DC_ERR_SPEC_VERSION),
        (Box::new(|s| s.size += 8), DC_ERR_SPEC_VERSION),
        (Box::new(|s| s.normal = 99), DC_ERR_SPEC_MODEL),
        (Box::new(|s| s.damping = 2), DC_ERR_SPEC_MODEL),
        (Box::new(|s| s.tangential = 3), DC_ERR_SPEC_MODEL),
        (Box::new(|s| s.rolling = -1), DC_ERR_SPEC_MODEL),
        (Box::new(|s| s.twisting = 2), DC_ERR_SPEC_MODEL),
        (Box::new(|s| s.criterion = 2), DC_ERR_CRITERION),
        (Box::new(|s| s.E1 = f64::NAN), DC_ERR_SPEC_UNSET),
        (Box::new(|s| s.nu2 = f64::NAN), DC_ERR_SPEC_UNSET),
        (Box::new(|s| s.E1 = -1.0), DC_ERR_NOT_POSITIVE),
        (Box::new(|s| s.E1 = f64::NEG_INFINITY), DC_ERR_NOT_POSITIVE),
        (Box::new(|s| s.nu1 = 0.6), DC_ERR_NOT_POSITIVE),
        (Box::new(|s| s.nu1 = f64::INFINITY), DC_ERR_NOT_FINITE),
        (
            Box::new(|s| {
                s.E1 = f64::INFINITY;
                s.E2 = f64::INFINITY;
            }),
            DC_ERR_NOT_FINITE,
        ),
        (
            Box::new(|s| s.damping = DC_DAMPING_RESTITUTION),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.damping = DC_DAMPING_RESTITUTION;
                s.e_n = 1.5;
            }),
            DC_ERR_RESTITUTION_RANGE,
        ),
        (
            Box::new(|s| {
                s.damping = DC_DAMPING_RESTITUTION;
                s.e_n = 0.0;
            }),
            DC_ERR_RESTITUTION_RANGE,
        ),
        (
            Box::new(|s| s.tangential = DC_TANGENTIAL_LINEAR),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.tangential = DC_TANGENTIAL_LINEAR;
                s.mu = 0.5;
            }),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.tangential = DC_TANGENTIAL_LINEAR;
                s.mu = 0.5;
                s.k_t = 0.0;
            }),
            DC_ERR_NOT_POSITIVE,
        ),
        (
            Box::new(|s| {
                s.tangential = DC_TANGENTIAL_MINDLIN;
                s.mu = -0.5;
            }),
            DC_ERR_NEGATIVE,
        ),
        (
            Box::new(|s| {
                s.tangential = DC_TANGENTIAL_MINDLIN;
                s.mu = f64::INFINITY;
            }),
            DC_ERR_NOT_FINITE,
        ),
        (
            Box::new(|s| {
                s.tangential = DC_TANGENTIAL_MINDLIN;
                s.mu = 0.5;
                s.e_t = 0.0;
            }),
            DC_ERR_RESTITUTION_RANGE,
        ),
        (
            Box::new(|s| s.rolling = DC_ROLLING_CONSTANT),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.rolling = DC_ROLLING_EPSD;
                s.mu_r = 0.1;
                s.k_r = -1.0;
            }),
            DC_ERR_NEGATIVE,
        ),
        (
            Box::new(|s| {
                s.rolling = DC_ROLLING_EPSD;
                s.mu_r = 0.1;
                s.eta_r = f64::NAN;
            }),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.twisting = DC_TWISTING_SDS;
                s.mu_tw = 0.1;
            }),
            DC_ERR_SPEC_UNSET,
        ),
        // Found by fuzzing: a subnormal E gives kf = 0 (compliance overflows); the model was
        // accepted and then refused by every force call.
        (Box::new(|s| s.E1 = 1e-320), DC_ERR_RESULT_RANGE),
        (
            Box::new(|s| {
                s.normal = DC_NORMAL_LINEAR;
                s.k_n = 1e6;
                s.tangential = DC_TANGENTIAL_MINDLIN;
                s.mu = 0.3;
                s.E2 = 1e-320;
            }),
            DC_ERR_RESULT_RANGE,
        ),
        (Box::new(|s| s.inertia_factor = 0.0), DC_ERR_NOT_POSITIVE),
        (Box::new(|s| s.inertia_factor = 1.5), DC_ERR_SPEC_MODEL),
        (
            Box::new(|s| {
                s.normal = DC_NORMAL_VISCOELASTIC;
                s.visco_A = 1e-6;
                s.damping = DC_DAMPING_RESTITUTION;
                s.e_n = 0.5;
            }),
            DC_ERR_SPEC_MODEL,
        ),
        (
            Box::new(|s| s.normal = DC_NORMAL_VISCOELASTIC),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.normal = DC_NORMAL_VISCOELASTIC;
                s.visco_A = -1.0;
            }),
            DC_ERR_NEGATIVE,
        ),
        (
            Box::new(|s| s.normal = DC_NORMAL_POWERLAW),
            DC_ERR_SPEC_UNSET,
        ),
        (
            Box::new(|s| {
                s.normal = DC_NORMAL_POWERLAW;
                s.p = 0.5;
                s.k_n = 1e6;
            }),
            DC_ERR_EXPONENT_RANGE,
        ),
        (
            Box::new(|s| {
                s.normal = DC_NORMAL_LINEAR;
                s.k_n = -1e6;
            }),
            DC_ERR_NOT_POSITIVE,
        ),
    ];
    for (i, (edit, want)) in cases.iter().enumerate() {
        let mut s = base;
        edit(&mut s);
        assert_eq!(init(&s).0, *want, "case {i}");
    }
    // Valid: a rigid wall, each normal law, parameters of unchosen sub-models ignored.
    for edit in [
        Box::new(|s: &mut dc_contact_spec| s.E2 = f64::INFINITY)
            as Box<dyn Fn(&mut dc_contact_spec)>,
        Box::new(|s| {
            s.normal = DC_NORMAL_POWERLAW;
            s.p = 1.7;
            s.k_n = 1e6;
            s.E1 = f64::NAN;
        }),
        Box::new(|s| {
            s.normal = DC_NORMAL_LINEAR;
            s.k_n = 1e6;
            s.tangential = DC_TANGENTIAL_MINDLIN;
            s.mu = 0.2;
        }),
        Box::new(|s| {
            s.normal = DC_NORMAL_VISCOELASTIC;
            s.visco_A = 1e-6;
            s.mu_r = -5.0;
        }),
    ] {
        let mut s = base;
        edit(&mut s);
        assert_eq!(init(&s).0, DC_OK);
    }
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(
        unsafe { dc_contact_model_init(std::ptr::null(), &mut m) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(
        unsafe { dc_contact_model_init(&base, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
}

#[test]
fn history_len_per_model_and_invalid_models() {
    let len = |m: &dc_contact_model| {
        let mut l = 999usize;
        let s = unsafe { dc_contact_history_len(m, &mut l) };
        (s, l)
    };
    for m in all_models() {
        let want = match (m.tangential, m.rolling, m.twisting) {
            (0, 0 | 1, 0) => 0,
            (t, r, tw) => {
                3 + 3 * usize::from(t != 0) + 3 * usize::from(r == 2) + usize::from(tw != 0)
            }
        };
        assert_eq!(len(&m), (DC_OK, want));
        assert!(want <= DC_CONTACT_HISTORY_MAX);
    }
    let good = all_models()[20];
    let zero: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(len(&zero), (DC_ERR_CONTACT_MODEL_INVALID, 999));
    let edits: Vec<Box<dyn Fn(&mut dc_contact_model)>> = vec![
        Box::new(|m| m.magic ^= 1),
        Box::new(|m| m.history_len += 1),
        Box::new(|m| m.tangential = 7),
        Box::new(|m| m.normal.kernel = 0),
        Box::new(|m| m.normal.clamp ^= 1),
        Box::new(|m| m.mu = f64::NAN),
        Box::new(|m| m.kt = -1.0),
        Box::new(|m| m.kappa = 0.0),
        Box::new(|m| m.reserved[3] = 1.0),
    ];
    for (i, e) in edits.iter().enumerate() {
        let mut m = good;
        e(&mut m);
        assert_eq!(len(&m).0, DC_ERR_CONTACT_MODEL_INVALID, "edit {i}");
        let st = states()[0];
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
        let mut r = sentinel_res();
        let s = unsafe { dc_contact_force(&m, &st, 1e-7, h.as_mut_ptr(), h.len(), &mut r) };
        assert_eq!(s, DC_ERR_CONTACT_MODEL_INVALID, "edit {i}");
        assert_eq!(r, sentinel_res());
    }
    let mut l = 0usize;
    assert_eq!(
        unsafe { dc_contact_history_len(std::ptr::null(), &mut l) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(
        unsafe { dc_contact_history_len(&good, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
}

#[test]
fn normal_only_equals_dc_normal_force_bit_for_bit() {
    for crit in [DC_END_FORCE, DC_END_OVERLAP] {
        for e in [1.0, 0.3] {
            let m = model(|s| {
                hertz(s);
                s.damping = if e < 1.0 {
                    DC_DAMPING_RESTITUTION
                } else {
                    DC_DAMPING_NONE
                };
                s.e_n = e;
                s.criterion = crit;
                s.E2 = f64::INFINITY;
            });
            for st in states() {
                let mut r = sentinel_res();
                let s = unsafe { dc_contact_force(&m, &st, 1e-7, std::ptr::null_mut(), 0, &mut r) };
                assert_eq!(s, DC_OK);
                // R* and m* as documented: a b/(a + b), = a for b = +inf.
                let h = |a: f64, b: f64| {
                    if b == f64::INFINITY {
                        a
                    } else {
                        a * (b / (a + b))
                    }
                };
                let (reff, meff) = (h(st.r1, st.r2), h(st.m1, st.m2));
                let vn: f64 = (0..3).map(|i| (st.v2[i] - st.v1[i]) * st.n[i]).sum();
                let f = unsafe { dc_normal_force(&m.normal, st.overlap, vn, reff, meff) };
                assert_eq!(r.f_n.to_bits(), f.to_bits());
                for i in 0..3 {
                    assert_eq!(r.force[i].to_bits(), (f * st.n[i]).to_bits());
                    assert_eq!((r.ft[i], r.torque1[i], r.torque2[i]), (0.0, 0.0, 0.0));
                }
            }
        }
    }
}

#[test]
fn force_statuses_leave_outputs_and_history_untouched() {
    let m = all_models()
        .into_iter()
        .find(|m| m.history_len == 10)
        .unwrap();
    let good = states()[0];
    let hist0 = [0.25; DC_CONTACT_HISTORY_MAX];
    let run = |st: &dc_contact_state, dt: f64, hl: usize| {
        let mut h = hist0;
        let mut r = sentinel_res();
        let s = unsafe { dc_contact_force(&m, st, dt, h.as_mut_ptr(), hl, &mut r) };
        if s != DC_OK {
            assert_eq!(r, sentinel_res(), "result touched on {s}");
            assert_eq!(h, hist0, "history touched on {s}");
        }
        s
    };
    assert_eq!(run(&good, 1e-7, 10), DC_OK);
    assert_eq!(run(&good, 1e-7, 9), DC_ERR_BUFFER_TOO_SHORT);
    assert_eq!(run(&good, 0.0, 10), DC_ERR_NOT_POSITIVE);
    assert_eq!(run(&good, f64::NAN, 10), DC_ERR_NOT_FINITE);
    assert_eq!(run(&good, f64::INFINITY, 10), DC_ERR_NOT_FINITE);
    let edits: Vec<(Box<dyn Fn(&mut dc_contact_state)>, i32)> = vec![
        (Box::new(|s| s.n[1] = f64::NAN), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.n = [1.0, 1e-2, 0.0]), DC_ERR_NOT_UNIT),
        (Box::new(|s| s.n = [0.0; 3]), DC_ERR_NOT_UNIT),
        (Box::new(|s| s.overlap = f64::INFINITY), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.v1[2] = f64::NAN), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.v2[0] = f64::INFINITY), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.w1[0] = f64::NEG_INFINITY), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.w2[1] = f64::NAN), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.r1 = f64::INFINITY), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.m1 = f64::INFINITY), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.r2 = f64::NAN), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.m2 = f64::NEG_INFINITY), DC_ERR_NOT_FINITE),
        (Box::new(|s| s.r1 = 0.0), DC_ERR_NOT_POSITIVE),
        (Box::new(|s| s.m2 = -1.0), DC_ERR_NOT_POSITIVE),
        (Box::new(|s| s.r2 = -0.0), DC_ERR_NOT_POSITIVE),
        (
            Box::new(|s| {
                s.overlap = 1e300;
                s.v1 = [1e300, 0.0, 0.0];
            }),
            DC_ERR_RESULT_RANGE,
        ),
    ];
    for (i, (e, want)) in edits.iter().enumerate() {
        let mut st = good;
        e(&mut st);
        assert_eq!(run(&st, 1e-7, 10), *want, "edit {i}");
    }
    // A NaN in the history is reported, not propagated.
    let mut h = hist0;
    h[4] = f64::NAN;
    let mut r = sentinel_res();
    assert_eq!(
        unsafe { dc_contact_force(&m, &good, 1e-7, h.as_mut_ptr(), 10, &mut r) },
        DC_ERR_NOT_FINITE
    );
    // NULLs.
    let mut h = hist0;
    let null_cases = [
        unsafe { dc_contact_force(std::ptr::null(), &good, 1e-7, h.as_mut_ptr(), 10, &mut r) },
        unsafe { dc_contact_force(&m, std::ptr::null(), 1e-7, h.as_mut_ptr(), 10, &mut r) },
        unsafe { dc_contact_force(&m, &good, 1e-7, std::ptr::null_mut(), 10, &mut r) },
        unsafe { dc_contact_force(&m, &good, 1e-7, h.as_mut_ptr(), 10, std::ptr::null_mut()) },
    ];
    assert_eq!(null_cases, [DC_ERR_NULL_POINTER; 4]);
    // Misaligned history.
    let mut buf = [0u8; 8 * 12];
    let p = unsafe { buf.as_mut_ptr().add(1) }.cast::<f64>();
    assert_eq!(
        unsafe { dc_contact_force(&m, &good, 1e-7, p, 10, &mut r) },
        DC_ERR_BUFFER_LAYOUT
    );
}

#[test]
fn separation_resets_history_and_gives_zero() {
    for m in all_models() {
        let mut st = states()[0];
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
        let mut r = sentinel_res();
        for _ in 0..3 {
            assert_eq!(
                unsafe { dc_contact_force(&m, &st, 1e-6, h.as_mut_ptr(), 10, &mut r) },
                DC_OK
            );
        }
        if m.history_len > 0 {
            assert!(h.iter().any(|&x| x != 0.0));
        }
        st.overlap = -1e-9;
        assert_eq!(
            unsafe { dc_contact_force(&m, &st, 1e-6, h.as_mut_ptr(), 10, &mut r) },
            DC_OK
        );
        assert_eq!(r, ZERO_RES);
        assert_eq!(h, [0.0; DC_CONTACT_HISTORY_MAX]);
    }
}

fn flat(v: &[[f64; 3]]) -> Vec<f64> {
    v.iter().flatten().copied().collect()
}

struct Soa {
    n: Vec<f64>,
    d: Vec<f64>,
    v1: Vec<f64>,
    v2: Vec<f64>,
    w1: Vec<f64>,
    w2: Vec<f64>,
    r1: Vec<f64>,
    r2: Vec<f64>,
    m1: Vec<f64>,
    m2: Vec<f64>,
}

fn soa(st: &[dc_contact_state]) -> Soa {
    Soa {
        n: flat(&st.iter().map(|s| s.n).collect::<Vec<_>>()),
        d: st.iter().map(|s| s.overlap).collect(),
        v1: flat(&st.iter().map(|s| s.v1).collect::<Vec<_>>()),
        v2: flat(&st.iter().map(|s| s.v2).collect::<Vec<_>>()),
        w1: flat(&st.iter().map(|s| s.w1).collect::<Vec<_>>()),
        w2: flat(&st.iter().map(|s| s.w2).collect::<Vec<_>>()),
        r1: st.iter().map(|s| s.r1).collect(),
        r2: st.iter().map(|s| s.r2).collect(),
        m1: st.iter().map(|s| s.m1).collect(),
        m2: st.iter().map(|s| s.m2).collect(),
    }
}

#[test]
fn batch_equals_scalar_bit_for_bit() {
    let st = states();
    let nc = st.len();
    let a = soa(&st);
    let stride = 11;
    for m in all_models() {
        // Scalar reference over 4 steps (history evolving).
        let mut hs = vec![[0.0f64; DC_CONTACT_HISTORY_MAX]; nc];
        let mut hb = vec![0.0f64; nc * stride];
        for step in 0..4 {
            let mut want = Vec::new();
            for (i, s) in st.iter().enumerate() {
                let mut r = sentinel_res();
                assert_eq!(
                    unsafe { dc_contact_force(&m, s, 1e-6, hs[i].as_mut_ptr(), 10, &mut r) },
                    DC_OK
                );
                want.push(r);
            }
            let (mut f_n, mut force, mut t1, mut t2) = (
                vec![0.0; nc],
                vec![0.0; 3 * nc],
                vec![9.0; 3 * nc],
                vec![9.0; 3 * nc],
            );
            let b = dc_contact_batch {
                n: nc,
                history_stride: stride,
                normal: a.n.as_ptr(),
                overlap: a.d.as_ptr(),
                v1: a.v1.as_ptr(),
                v2: a.v2.as_ptr(),
                w1: a.w1.as_ptr(),
                w2: a.w2.as_ptr(),
                r1: a.r1.as_ptr(),
                r2: a.r2.as_ptr(),
                m1: a.m1.as_ptr(),
                m2: a.m2.as_ptr(),
                history: hb.as_mut_ptr(),
                f_n: f_n.as_mut_ptr(),
                force: force.as_mut_ptr(),
                torque1: t1.as_mut_ptr(),
                torque2: t2.as_mut_ptr(),
            };
            assert_eq!(unsafe { dc_contact_force_batch(&m, &b, 1e-6) }, DC_OK);
            for (i, w) in want.iter().enumerate() {
                assert_eq!(f_n[i].to_bits(), w.f_n.to_bits(), "step {step} contact {i}");
                for k in 0..3 {
                    assert_eq!(
                        force[3 * i + k].to_bits(),
                        w.force[k].to_bits(),
                        "force {i} {k} model {:?}",
                        (m.tangential, m.rolling, m.twisting)
                    );
                    assert_eq!(
                        t1[3 * i + k].to_bits(),
                        w.torque1[k].to_bits(),
                        "t1 {i} {k}"
                    );
                    assert_eq!(
                        t2[3 * i + k].to_bits(),
                        w.torque2[k].to_bits(),
                        "t2 {i} {k}"
                    );
                }
                let l = m.history_len as usize;
                for k in 0..l {
                    assert_eq!(
                        hb[i * stride + k].to_bits(),
                        hs[i][k].to_bits(),
                        "history {i} {k}"
                    );
                }
                assert_eq!(hb[i * stride + 10], 0.0, "stride padding touched");
            }
        }
    }
}

#[test]
fn batch_statuses_leave_everything_untouched() {
    let st = states();
    let nc = st.len();
    let a = soa(&st);
    let m = all_models()
        .into_iter()
        .find(|m| m.history_len == 10)
        .unwrap();
    let normal_only = all_models()[0];
    let (mut f_n, mut force, mut t1, mut t2, mut h) = (
        vec![5.0; nc],
        vec![5.0; 3 * nc],
        vec![5.0; 3 * nc],
        vec![5.0; 3 * nc],
        vec![0.5; 10 * nc],
    );
    let mk = |f_n: &mut Vec<f64>,
              force: &mut Vec<f64>,
              t1: &mut Vec<f64>,
              t2: &mut Vec<f64>,
              h: &mut Vec<f64>| dc_contact_batch {
        n: nc,
        history_stride: 10,
        normal: a.n.as_ptr(),
        overlap: a.d.as_ptr(),
        v1: a.v1.as_ptr(),
        v2: a.v2.as_ptr(),
        w1: a.w1.as_ptr(),
        w2: a.w2.as_ptr(),
        r1: a.r1.as_ptr(),
        r2: a.r2.as_ptr(),
        m1: a.m1.as_ptr(),
        m2: a.m2.as_ptr(),
        history: h.as_mut_ptr(),
        f_n: f_n.as_mut_ptr(),
        force: force.as_mut_ptr(),
        torque1: t1.as_mut_ptr(),
        torque2: t2.as_mut_ptr(),
    };
    let base = mk(&mut f_n, &mut force, &mut t1, &mut t2, &mut h);
    let bad_n = {
        let mut v = a.n.clone();
        v[4] = f64::NAN;
        v
    };
    let bad_r = {
        let mut v = a.r1.clone();
        v[2] = -1.0;
        v
    };
    let bad_unit = {
        let mut v = a.n.clone();
        v[0] = 1.1;
        v
    };
    let misaligned = vec![0.0f64; 3 * nc + 1];
    let mis_ptr = unsafe { misaligned.as_ptr().cast::<u8>().add(4).cast::<f64>() };
    let cases: Vec<(Box<dyn Fn(&mut dc_contact_batch)>, i32, &dc_contact_model)> = vec![
        (Box::new(|b| b.n = 0), DC_ERR_BUFFER_TOO_SHORT, &m),
        (
            Box::new(|b| b.history_stride = 9),
            DC_ERR_BUFFER_TOO_SHORT,
            &m,
        ),
        (
            Box::new(|b| b.normal = std::ptr::null()),
            DC_ERR_NULL_POINTER,
            &m,
        ),
        (
            Box::new(|b| b.w1 = std::ptr::null()),
            DC_ERR_NULL_POINTER,
            &m,
        ),
        (
            Box::new(|b| b.torque2 = std::ptr::null_mut()),
            DC_ERR_NULL_POINTER,
            &m,
        ),
        (
            Box::new(|b| b.history = std::ptr::null_mut()),
            DC_ERR_NULL_POINTER,
            &m,
        ),
        (
            Box::new(|b| b.f_n = std::ptr::null_mut()),
            DC_ERR_NULL_POINTER,
            &m,
        ),
        (Box::new(|b| b.n = usize::MAX / 2), DC_ERR_BUFFER_LAYOUT, &m),
        (Box::new(|b| b.torque1 = b.force), DC_ERR_BUFFER_LAYOUT, &m),
        (
            Box::new(|b| b.f_n = b.overlap.cast_mut()),
            DC_ERR_BUFFER_LAYOUT,
            &m,
        ),
        (
            Box::new(|b| b.history = unsafe { b.torque2.add(1) }),
            DC_ERR_BUFFER_LAYOUT,
            &m,
        ),
        (Box::new(move |b| b.v2 = mis_ptr), DC_ERR_BUFFER_LAYOUT, &m),
        (
            Box::new(|b| b.normal = bad_n.as_ptr()),
            DC_ERR_NOT_FINITE,
            &m,
        ),
        (
            Box::new(|b| b.normal = bad_unit.as_ptr()),
            DC_ERR_NOT_UNIT,
            &m,
        ),
        (Box::new(|b| b.r1 = bad_r.as_ptr()), DC_ERR_NOT_POSITIVE, &m),
        (
            Box::new(|b| b.normal = bad_n.as_ptr()),
            DC_ERR_NOT_FINITE,
            &normal_only,
        ),
    ];
    for (i, (e, want, model)) in cases.iter().enumerate() {
        let mut b = base;
        e(&mut b);
        assert_eq!(
            unsafe { dc_contact_force_batch(*model, &b, 1e-7) },
            *want,
            "case {i}"
        );
    }
    for dt in [0.0, -1.0, f64::NAN] {
        let s = unsafe { dc_contact_force_batch(&m, &base, dt) };
        assert!(s == DC_ERR_NOT_POSITIVE || s == DC_ERR_NOT_FINITE);
    }
    assert_eq!(
        unsafe { dc_contact_force_batch(std::ptr::null(), &base, 1e-7) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(
        unsafe { dc_contact_force_batch(&m, std::ptr::null(), 1e-7) },
        DC_ERR_NULL_POINTER
    );
    assert!(
        f_n.iter()
            .chain(&force)
            .chain(&t1)
            .chain(&t2)
            .all(|&x| x == 5.0)
    );
    assert!(h.iter().all(|&x| x == 0.5));
    // Normal-only: angular velocities, torques and history may be NULL.
    let mut b = base;
    b.w1 = std::ptr::null();
    b.w2 = std::ptr::null();
    b.torque1 = std::ptr::null_mut();
    b.torque2 = std::ptr::null_mut();
    b.history = std::ptr::null_mut();
    b.history_stride = 0;
    assert_eq!(
        unsafe { dc_contact_force_batch(&normal_only, &b, 1e-7) },
        DC_OK
    );
}

#[test]
fn spheres_helper_equals_state_form() {
    for m in all_models().into_iter().step_by(5) {
        let x1: [f64; 3] = [0.1, 0.2, 0.3];
        let x2 = [0.1 + 2.9e-3 * 0.6, 0.2 - 2.9e-3 * 0.8, 0.3];
        let mut st = states()[0];
        let d = [x1[0] - x2[0], x1[1] - x2[1], x1[2] - x2[2]];
        let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let (mut h1, mut h2) = ([0.0; 10], [0.0; 10]);
        let (mut r1, mut r2) = (sentinel_res(), sentinel_res());
        assert_eq!(
            unsafe {
                dc_contact_force_spheres(
                    &m,
                    x1.as_ptr(),
                    x2.as_ptr(),
                    &st,
                    1e-6,
                    h1.as_mut_ptr(),
                    10,
                    &mut r1,
                )
            },
            DC_OK
        );
        st.n = [d[0] / dist, d[1] / dist, d[2] / dist];
        st.overlap = st.r1 + st.r2 - dist;
        assert!(st.overlap > 0.0);
        assert_eq!(
            unsafe { dc_contact_force(&m, &st, 1e-6, h2.as_mut_ptr(), 10, &mut r2) },
            DC_OK
        );
        assert_eq!(r1, r2);
        assert_eq!(h1, h2);
        // Walls and coincident centres are refused.
        let mut wall = st;
        wall.r2 = f64::INFINITY;
        let mut r = sentinel_res();
        assert_eq!(
            unsafe {
                dc_contact_force_spheres(
                    &m,
                    x1.as_ptr(),
                    x2.as_ptr(),
                    &wall,
                    1e-6,
                    h1.as_mut_ptr(),
                    10,
                    &mut r,
                )
            },
            DC_ERR_NOT_FINITE
        );
        assert_eq!(
            unsafe {
                dc_contact_force_spheres(
                    &m,
                    x1.as_ptr(),
                    x1.as_ptr(),
                    &st,
                    1e-6,
                    h1.as_mut_ptr(),
                    10,
                    &mut r,
                )
            },
            DC_ERR_NOT_POSITIVE
        );
        assert_eq!(
            unsafe {
                dc_contact_force_spheres(
                    &m,
                    std::ptr::null(),
                    x1.as_ptr(),
                    &st,
                    1e-6,
                    h1.as_mut_ptr(),
                    10,
                    &mut r,
                )
            },
            DC_ERR_NULL_POINTER
        );
        assert_eq!(r, sentinel_res());
    }
}
