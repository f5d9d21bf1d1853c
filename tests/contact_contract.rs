//! Contract of the full-contact exports: every status, outputs and history untouched on error,
//! normal-only results bit-identical to dc_normal_force, batch = scalar bit for bit, the spheres
//! helper = the state form, and history handling.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::{ZERO_RESULT, model};
use demcontact::ffi::contact::*;
use demcontact::ffi::force::*;
use demcontact::ffi::status::*;

/// A table of edits and what each must give: `edits![x: T; [f = v, g[i] = w] => want, ...]`
/// is a Vec of (boxed closure setting those fields of `x: &mut T`, want). Values may read `x`.
macro_rules! edits {
    ($x:ident: $T:ty; $([$($($f:ident).+ $([$i:expr])? = $v:expr),+ $(,)?] => $want:expr),* $(,)?) => {
        vec![$((
            Box::new(|$x: &mut $T| { $($x.$($f).+ $([$i])? = $v;)+ }) as Box<dyn Fn(&mut $T) + '_>,
            $want,
        )),*]
    };
}

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
        DC_TANGENTIAL_MINDLIN_RESCALE,
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

fn sentinel_res() -> dc_contact_result {
    dc_contact_result {
        f_n: -7.5,
        ..ZERO_RESULT
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
    const INF: f64 = f64::INFINITY;
    const NAN: f64 = f64::NAN;
    let (restitution, linear, mindlin, epsd) = (
        DC_DAMPING_RESTITUTION,
        DC_TANGENTIAL_LINEAR,
        DC_TANGENTIAL_MINDLIN,
        DC_ROLLING_EPSD,
    );
    let (visco, powerlaw) = (DC_NORMAL_VISCOELASTIC, DC_NORMAL_POWERLAW);
    #[rustfmt::skip]
    let cases = edits![s: dc_contact_spec;
        [version = 2] => DC_ERR_SPEC_VERSION,
        [version = 0] => DC_ERR_SPEC_VERSION,
        [size = s.size - 16] => DC_ERR_SPEC_VERSION,
        // The size before yield_pressure was appended (8 bytes): a caller compiled then.
        [size = s.size - 8] => DC_OK,
        [size = s.size + 8] => DC_ERR_SPEC_VERSION,
        [normal = 99] => DC_ERR_SPEC_MODEL,
        [damping = 2] => DC_ERR_SPEC_MODEL,
        [tangential = 4] => DC_ERR_SPEC_MODEL,
        [rolling = -1] => DC_ERR_SPEC_MODEL,
        [twisting = 2] => DC_ERR_SPEC_MODEL,
        [criterion = 2] => DC_ERR_CRITERION,
        [E1 = NAN] => DC_ERR_SPEC_UNSET,
        [nu2 = NAN] => DC_ERR_SPEC_UNSET,
        [E1 = -1.0] => DC_ERR_NOT_POSITIVE,
        [E1 = -INF] => DC_ERR_NOT_POSITIVE,
        [nu1 = 0.6] => DC_ERR_POISSON_RANGE,
        [nu2 = -1.0] => DC_ERR_POISSON_RANGE,
        [E1 = -1.0, nu1 = 0.6] => DC_ERR_POISSON_RANGE,
        [nu1 = INF] => DC_ERR_NOT_FINITE,
        [E1 = INF, E2 = INF] => DC_ERR_NOT_FINITE,
        [damping = restitution] => DC_ERR_SPEC_UNSET,
        [damping = restitution, e_n = 1.5] => DC_ERR_RESTITUTION_RANGE,
        [damping = restitution, e_n = 0.0] => DC_ERR_RESTITUTION_RANGE,
        [tangential = linear] => DC_ERR_SPEC_UNSET,
        [tangential = linear, mu = 0.5] => DC_ERR_SPEC_UNSET,
        [tangential = linear, mu = 0.5, k_t = 0.0] => DC_ERR_NOT_POSITIVE,
        [tangential = mindlin, mu = -0.5] => DC_ERR_NEGATIVE,
        [tangential = mindlin, mu = INF] => DC_ERR_NOT_FINITE,
        [tangential = mindlin, mu = 0.5, e_t = 0.0] => DC_ERR_RESTITUTION_RANGE,
        [rolling = DC_ROLLING_CONSTANT] => DC_ERR_SPEC_UNSET,
        [rolling = epsd, mu_r = 0.1, k_r = -1.0] => DC_ERR_NEGATIVE,
        [rolling = epsd, mu_r = 0.1, eta_r = NAN] => DC_ERR_SPEC_UNSET,
        [twisting = DC_TWISTING_SDS, mu_tw = 0.1] => DC_ERR_SPEC_UNSET,
        // Found by fuzzing: a subnormal E gives kf = 0 (compliance overflows); the model was
        // accepted and then refused by every force call.
        [E1 = 1e-320] => DC_ERR_RESULT_RANGE,
        [normal = DC_NORMAL_LINEAR, k_n = 1e6, tangential = mindlin, mu = 0.3, E2 = 1e-320]
            => DC_ERR_RESULT_RANGE,
        [inertia_factor = 0.0] => DC_ERR_NOT_POSITIVE,
        [inertia_factor = 1.5] => DC_ERR_SPEC_MODEL,
        [normal = visco, visco_A = 1e-6, damping = restitution, e_n = 0.5] => DC_ERR_SPEC_MODEL,
        [normal = visco] => DC_ERR_SPEC_UNSET,
        [normal = visco, visco_A = -1.0] => DC_ERR_NEGATIVE,
        [normal = powerlaw] => DC_ERR_SPEC_UNSET,
        [normal = powerlaw, p = 0.5, k_n = 1e6] => DC_ERR_EXPONENT_RANGE,
        [normal = DC_NORMAL_LINEAR, k_n = -1e6] => DC_ERR_NOT_POSITIVE,
        // Valid: a rigid wall, each normal law, parameters of unchosen sub-models ignored.
        [E2 = INF] => DC_OK,
        [normal = powerlaw, p = 1.7, k_n = 1e6, E1 = NAN] => DC_OK,
        [normal = DC_NORMAL_LINEAR, k_n = 1e6, tangential = mindlin, mu = 0.2] => DC_OK,
        [normal = visco, visco_A = 1e-6, mu_r = -5.0] => DC_OK,
    ];
    for (i, (edit, want)) in cases.iter().enumerate() {
        let mut s = base;
        edit(&mut s);
        assert_eq!(init(&s).0, *want, "case {i}");
    }
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    let null_cases = [
        unsafe { dc_contact_model_init(std::ptr::null(), &mut m) },
        unsafe { dc_contact_model_init(&base, std::ptr::null_mut()) },
    ];
    assert_eq!(null_cases, [DC_ERR_NULL_POINTER; 2]);
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
                3 + 3 * usize::from(t != 0)
                    + usize::from(t == DC_TANGENTIAL_MINDLIN_RESCALE)
                    + 3 * usize::from(r == 2)
                    + usize::from(tw != 0)
            }
        };
        assert_eq!(len(&m), (DC_OK, want));
        assert!(want <= DC_CONTACT_HISTORY_MAX);
    }
    let good = all_models()[20];
    let zero: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(len(&zero), (DC_ERR_CONTACT_MODEL_INVALID, 999));
    const INVALID: i32 = DC_ERR_CONTACT_MODEL_INVALID;
    #[rustfmt::skip]
    let edits = edits![m: dc_contact_model;
        [magic = m.magic ^ 1] => INVALID,
        [history_len = m.history_len + 1] => INVALID,
        [tangential = 7] => INVALID,
        [normal.kernel = 0] => INVALID,
        [normal.clamp = m.normal.clamp ^ 1] => INVALID,
        [mu = f64::NAN] => INVALID,
        [kt = -1.0] => INVALID,
        [kappa = 0.0] => INVALID,
        [reserved[3] = 1.0] => INVALID,
        [kt = 0.0] => INVALID,
        [normal.k = f64::INFINITY] => INVALID,
        [eta_tw = -1.0] => INVALID,
        [rolling = 9] => INVALID,
        [carry = 2] => INVALID,
        [carry = -1] => INVALID,
    ];
    for (i, (e, want)) in edits.iter().enumerate() {
        let mut m = good;
        e(&mut m);
        assert_eq!(len(&m).0, *want, "edit {i}");
        let st = states()[0];
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
        let mut r = sentinel_res();
        let s = unsafe { dc_contact_force(&m, &st, 1e-7, h.as_mut_ptr(), h.len(), &mut r) };
        assert_eq!(s, DC_ERR_CONTACT_MODEL_INVALID, "edit {i}");
        assert_eq!(r, sentinel_res());
    }
    let mut l = 0usize;
    let null_cases = [
        unsafe { dc_contact_history_len(std::ptr::null(), &mut l) },
        unsafe { dc_contact_history_len(&good, std::ptr::null_mut()) },
    ];
    assert_eq!(null_cases, [DC_ERR_NULL_POINTER; 2]);
}

#[test]
fn set_carry_statuses_and_effect() {
    for m0 in all_models() {
        assert_eq!(
            m0.carry, DC_CARRY_ROTATE,
            "dc_contact_model_init gives the rotation"
        );
        let mut m = m0;
        assert_eq!(
            unsafe { dc_contact_model_set_carry(&mut m, DC_CARRY_PROJECT) },
            DC_OK
        );
        // Only the carry changes: same history length, every other byte equal.
        assert_eq!(
            dc_contact_model {
                carry: m0.carry,
                ..m
            },
            m0
        );
        let (mut l0, mut l1) = (0usize, 1usize);
        assert_eq!(unsafe { dc_contact_history_len(&m0, &mut l0) }, DC_OK);
        assert_eq!(unsafe { dc_contact_history_len(&m, &mut l1) }, DC_OK);
        assert_eq!(l0, l1);
        for bad in [2, -1, i32::MIN, i32::MAX] {
            let mut mb = m;
            let s = unsafe { dc_contact_model_set_carry(&mut mb, bad) };
            assert_eq!(s, DC_ERR_SPEC_MODEL, "carry {bad}");
            assert_eq!(mb, m, "untouched on error");
        }
        assert_eq!(
            unsafe { dc_contact_model_set_carry(&mut m, DC_CARRY_ROTATE) },
            DC_OK
        );
        assert_eq!(m, m0);
    }
    let mut zero: dc_contact_model = unsafe { std::mem::zeroed() };
    let s = unsafe { dc_contact_model_set_carry(&mut zero, DC_CARRY_PROJECT) };
    assert_eq!(s, DC_ERR_CONTACT_MODEL_INVALID);
    assert_eq!(zero.carry, 0);
    let s = unsafe { dc_contact_model_set_carry(std::ptr::null_mut(), DC_CARRY_PROJECT) };
    assert_eq!(s, DC_ERR_NULL_POINTER);
    // The projection changes a contact whose normal turns (and only the springs' carry).
    let m0 = all_models()
        .into_iter()
        .find(|m| m.tangential == DC_TANGENTIAL_MINDLIN)
        .expect("a Mindlin model");
    let mut mp = m0;
    assert_eq!(
        unsafe { dc_contact_model_set_carry(&mut mp, DC_CARRY_PROJECT) },
        DC_OK
    );
    let run = |m: &dc_contact_model| {
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
        let mut last = sentinel_res();
        for k in 0..50 {
            let a = 0.02 * k as f64;
            let st = dc_contact_state {
                n: [a.cos(), a.sin(), 0.0],
                overlap: 1e-6,
                v1: [0.0, 0.0, 0.01],
                v2: [0.0; 3],
                w1: [0.0, 0.0, 30.0],
                w2: [0.0, 0.0, -10.0],
                r1: 1e-3,
                r2: 1e-3,
                m1: 1e-5,
                m2: 1e-5,
            };
            let s = unsafe { dc_contact_force(m, &st, 1e-6, h.as_mut_ptr(), h.len(), &mut last) };
            assert_eq!(s, DC_OK);
        }
        last
    };
    let (a, b) = (run(&m0), run(&mp));
    assert_eq!(
        a.f_n, b.f_n,
        "the normal force does not depend on the carry"
    );
    assert_ne!(
        a.ft, b.ft,
        "the carry must change the spring of a turning contact"
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
    const INF: f64 = f64::INFINITY;
    const NAN: f64 = f64::NAN;
    #[rustfmt::skip]
    let edits = edits![s: dc_contact_state;
        [n[1] = NAN] => DC_ERR_NOT_FINITE,
        [n = [1.0, 1e-2, 0.0]] => DC_ERR_NOT_UNIT,
        [n = [0.0; 3]] => DC_ERR_NOT_UNIT,
        [overlap = INF] => DC_ERR_NOT_FINITE,
        [v1[2] = NAN] => DC_ERR_NOT_FINITE,
        [v2[0] = INF] => DC_ERR_NOT_FINITE,
        [w1[0] = -INF] => DC_ERR_NOT_FINITE,
        [w2[1] = NAN] => DC_ERR_NOT_FINITE,
        [r1 = INF] => DC_ERR_NOT_FINITE,
        [m1 = INF] => DC_ERR_NOT_FINITE,
        [r2 = NAN] => DC_ERR_NOT_FINITE,
        [m2 = -INF] => DC_ERR_NOT_FINITE,
        [r1 = 0.0] => DC_ERR_NOT_POSITIVE,
        [m2 = -1.0] => DC_ERR_NOT_POSITIVE,
        [r2 = -0.0] => DC_ERR_NOT_POSITIVE,
        [overlap = 1e300, v1 = [1e300, 0.0, 0.0]] => DC_ERR_RESULT_RANGE,
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
        unsafe {
            dc_contact_force(
                &m,
                &good,
                1e-7,
                h.as_mut_ptr(),
                DC_CONTACT_HISTORY_MAX,
                &mut r,
            )
        },
        DC_ERR_NOT_FINITE
    );
    // NULLs.
    let mut h = hist0;
    let null_cases = [
        unsafe {
            dc_contact_force(
                std::ptr::null(),
                &good,
                1e-7,
                h.as_mut_ptr(),
                DC_CONTACT_HISTORY_MAX,
                &mut r,
            )
        },
        unsafe {
            dc_contact_force(
                &m,
                std::ptr::null(),
                1e-7,
                h.as_mut_ptr(),
                DC_CONTACT_HISTORY_MAX,
                &mut r,
            )
        },
        unsafe { dc_contact_force(&m, &good, 1e-7, std::ptr::null_mut(), 10, &mut r) },
        unsafe {
            dc_contact_force(
                &m,
                &good,
                1e-7,
                h.as_mut_ptr(),
                DC_CONTACT_HISTORY_MAX,
                std::ptr::null_mut(),
            )
        },
    ];
    assert_eq!(null_cases, [DC_ERR_NULL_POINTER; 4]);
    // Misaligned history.
    // The base is an f64 array so that one byte past it is misaligned on every run: a u8 array
    // may itself start one byte before an 8-byte boundary (Miri picks such addresses).
    let mut buf = [0.0f64; 12];
    let p = unsafe { buf.as_mut_ptr().cast::<u8>().add(1) }.cast::<f64>();
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
                unsafe {
                    dc_contact_force(
                        &m,
                        &st,
                        1e-6,
                        h.as_mut_ptr(),
                        DC_CONTACT_HISTORY_MAX,
                        &mut r,
                    )
                },
                DC_OK
            );
        }
        if m.history_len > 0 {
            assert!(h.iter().any(|&x| x != 0.0));
        }
        st.overlap = -1e-9;
        assert_eq!(
            unsafe {
                dc_contact_force(
                    &m,
                    &st,
                    1e-6,
                    h.as_mut_ptr(),
                    DC_CONTACT_HISTORY_MAX,
                    &mut r,
                )
            },
            DC_OK
        );
        assert_eq!(r, ZERO_RESULT);
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

impl Soa {
    /// The batch over these inputs with the given history (pointer, stride) and outputs. The
    /// outputs are taken as Vecs: `Vec::as_mut_ptr` makes no reference to the elements, so the
    /// pointers stay valid under Miri while the test reads the Vecs between calls.
    #[allow(clippy::ptr_arg)]
    fn batch(
        &self,
        history: (*mut f64, usize),
        f_n: &mut Vec<f64>,
        force: &mut Vec<f64>,
        t1: &mut Vec<f64>,
        t2: &mut Vec<f64>,
    ) -> dc_contact_batch {
        dc_contact_batch {
            n: self.d.len(),
            history_stride: history.1,
            normal: self.n.as_ptr(),
            overlap: self.d.as_ptr(),
            v1: self.v1.as_ptr(),
            v2: self.v2.as_ptr(),
            w1: self.w1.as_ptr(),
            w2: self.w2.as_ptr(),
            r1: self.r1.as_ptr(),
            r2: self.r2.as_ptr(),
            m1: self.m1.as_ptr(),
            m2: self.m2.as_ptr(),
            history: history.0,
            f_n: f_n.as_mut_ptr(),
            force: force.as_mut_ptr(),
            torque1: t1.as_mut_ptr(),
            torque2: t2.as_mut_ptr(),
        }
    }
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
    let stride = DC_CONTACT_HISTORY_MAX + 1;
    // Every model, and each damped one also step-aware (dc_contact_model_set_step).
    let mut models = all_models();
    for m in all_models() {
        let mut s = m;
        if m.normal.alpha > 0.0 {
            if cfg!(miri) {
                // Under Miri the calibration (about 10^6 force evaluations of safe code) is too
                // slow: the fields dc_contact_model_set_step writes, with fixed coefficients.
                s.reserved = [1e-9, -0.5, 0.1, 0.0, 0.0, 0.0];
                s.history_len += 1;
            } else {
                assert_eq!(unsafe { dc_contact_model_set_step(&mut s, 2e-6, 0) }, DC_OK);
            }
            assert_eq!(s.history_len, m.history_len + 1);
            models.push(s);
        }
    }
    for m in models {
        // Scalar reference over 4 steps (history evolving).
        let mut hs = vec![[0.0f64; DC_CONTACT_HISTORY_MAX]; nc];
        let mut hb = vec![0.0f64; nc * stride];
        for step in 0..4 {
            let mut want = Vec::new();
            for (i, s) in st.iter().enumerate() {
                let mut r = sentinel_res();
                assert_eq!(
                    unsafe { dc_contact_force(&m, s, 1e-6, hs[i].as_mut_ptr(), stride, &mut r) },
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
            let b = a.batch(
                (hb.as_mut_ptr(), stride),
                &mut f_n,
                &mut force,
                &mut t1,
                &mut t2,
            );
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
                assert_eq!(hb[i * stride + stride - 1], 0.0, "stride padding touched");
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
    let base = a.batch((h.as_mut_ptr(), 10), &mut f_n, &mut force, &mut t1, &mut t2);
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
    let null = std::ptr::null_mut::<f64>();
    let (short, layout) = (DC_ERR_BUFFER_TOO_SHORT, DC_ERR_BUFFER_LAYOUT);
    #[rustfmt::skip]
    let cases = edits![b: dc_contact_batch;
        [n = 0] => (short, &m),
        [history_stride = 9] => (short, &m),
        [normal = null] => (DC_ERR_NULL_POINTER, &m),
        [w1 = null] => (DC_ERR_NULL_POINTER, &m),
        [torque2 = null] => (DC_ERR_NULL_POINTER, &m),
        [history = null] => (DC_ERR_NULL_POINTER, &m),
        [f_n = null] => (DC_ERR_NULL_POINTER, &m),
        [n = usize::MAX / 2] => (layout, &m),
        [torque1 = b.force] => (layout, &m),
        [f_n = b.overlap.cast_mut()] => (layout, &m),
        [history = unsafe { b.torque2.add(1) }] => (layout, &m),
        [v2 = mis_ptr] => (layout, &m),
        [normal = bad_n.as_ptr()] => (DC_ERR_NOT_FINITE, &m),
        [normal = bad_unit.as_ptr()] => (DC_ERR_NOT_UNIT, &m),
        [r1 = bad_r.as_ptr()] => (DC_ERR_NOT_POSITIVE, &m),
        [normal = bad_n.as_ptr()] => (DC_ERR_NOT_FINITE, &normal_only),
    ];
    let mut bad = 77usize;
    for (i, (e, (want, model))) in cases.iter().enumerate() {
        let mut b = base;
        e(&mut b);
        assert_eq!(
            unsafe { dc_contact_force_batch(*model, &b, 1e-7) },
            *want,
            "case {i}"
        );
        // The fused batch: the same call-level statuses, nothing written (per-contact
        // statuses are its own test).
        if [
            DC_ERR_BUFFER_TOO_SHORT,
            DC_ERR_NULL_POINTER,
            DC_ERR_BUFFER_LAYOUT,
        ]
        .contains(want)
        {
            assert_eq!(
                unsafe { dc_contact_force_batch_fused(*model, &b, 1e-7, &mut bad) },
                *want,
                "fused case {i}"
            );
        }
    }
    for dt in [0.0, -1.0, f64::NAN] {
        let s = unsafe { dc_contact_force_batch(&m, &base, dt) };
        assert!(s == DC_ERR_NOT_POSITIVE || s == DC_ERR_NOT_FINITE);
        let s = unsafe { dc_contact_force_batch_fused(&m, &base, dt, &mut bad) };
        assert!(s == DC_ERR_NOT_POSITIVE || s == DC_ERR_NOT_FINITE);
    }
    assert_eq!(
        unsafe { dc_contact_force_batch_fused(std::ptr::null(), &base, 1e-7, &mut bad) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(
        unsafe { dc_contact_force_batch_fused(&m, std::ptr::null(), 1e-7, &mut bad) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(bad, 77, "first_bad written on a call-level error");
    let null_cases = [
        unsafe { dc_contact_force_batch(std::ptr::null(), &base, 1e-7) },
        unsafe { dc_contact_force_batch(&m, std::ptr::null(), 1e-7) },
    ];
    assert_eq!(null_cases, [DC_ERR_NULL_POINTER; 2]);
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
    // A normal-only model with a history (step-aware, one double): spins and torques may be
    // NULL as well, and the forces and histories are those of the call that gives them.
    let mut step = all_models()[1]; // Hertz, e_n 0.6, DC_END_FORCE, normal only
    assert_eq!(step.tangential, DC_TANGENTIAL_NONE);
    assert_eq!(
        unsafe { dc_contact_model_set_step(&mut step, 1e-7, DC_INTEGRATOR_VELOCITY_VERLET) },
        DC_OK
    );
    let mut len = 0usize;
    assert_eq!(unsafe { dc_contact_history_len(&step, &mut len) }, DC_OK);
    assert_eq!(len, 1);
    let (mut fa, mut fb) = (
        (vec![7.0; nc], vec![7.0; 3 * nc]),
        (vec![8.0; nc], vec![8.0; 3 * nc]),
    );
    let (mut ha, mut hb) = (vec![0.0; nc], vec![0.0; nc]);
    let (mut ta, mut tb) = (vec![9.0; 3 * nc], vec![9.0; 3 * nc]);
    let mut with = a.batch((ha.as_mut_ptr(), 1), &mut fa.0, &mut fa.1, &mut ta, &mut tb);
    let mut without = with;
    without.w1 = std::ptr::null();
    without.w2 = std::ptr::null();
    without.torque1 = std::ptr::null_mut();
    without.torque2 = std::ptr::null_mut();
    without.history = hb.as_mut_ptr();
    without.f_n = fb.0.as_mut_ptr();
    without.force = fb.1.as_mut_ptr();
    for _ in 0..3 {
        with.history = ha.as_mut_ptr();
        assert_eq!(unsafe { dc_contact_force_batch(&step, &with, 1e-7) }, DC_OK);
        assert_eq!(
            unsafe { dc_contact_force_batch(&step, &without, 1e-7) },
            DC_OK
        );
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&fa.0), bits(&fb.0));
        assert_eq!(bits(&fa.1), bits(&fb.1));
        assert_eq!(bits(&ha), bits(&hb));
    }
    assert!(
        ha.iter().any(|&x| x != 0.0),
        "the step-aware history is in use"
    );
}

#[test]
fn spheres_helper_equals_state_form() {
    for m in all_models().into_iter().step_by(5) {
        // dc_contact_force_spheres of this model at dt = 1e-6, with a history of DC_CONTACT_HISTORY_MAX doubles.
        let spheres = |a: *const f64,
                       b: *const f64,
                       st: &dc_contact_state,
                       h: &mut [f64; DC_CONTACT_HISTORY_MAX],
                       r: &mut dc_contact_result| unsafe {
            dc_contact_force_spheres(
                &m,
                a,
                b,
                st,
                1e-6,
                h.as_mut_ptr(),
                DC_CONTACT_HISTORY_MAX,
                r,
            )
        };
        let x1: [f64; 3] = [0.1, 0.2, 0.3];
        let x2 = [0.1 + 2.9e-3 * 0.6, 0.2 - 2.9e-3 * 0.8, 0.3];
        let mut st = states()[0];
        let d = [x1[0] - x2[0], x1[1] - x2[1], x1[2] - x2[2]];
        let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let (mut h1, mut h2) = ([0.0; DC_CONTACT_HISTORY_MAX], [0.0; DC_CONTACT_HISTORY_MAX]);
        let (mut r1, mut r2) = (sentinel_res(), sentinel_res());
        assert_eq!(
            spheres(x1.as_ptr(), x2.as_ptr(), &st, &mut h1, &mut r1),
            DC_OK
        );
        st.n = [d[0] / dist, d[1] / dist, d[2] / dist];
        st.overlap = st.r1 + st.r2 - dist;
        assert!(st.overlap > 0.0);
        assert_eq!(
            unsafe {
                dc_contact_force(
                    &m,
                    &st,
                    1e-6,
                    h2.as_mut_ptr(),
                    DC_CONTACT_HISTORY_MAX,
                    &mut r2,
                )
            },
            DC_OK
        );
        assert_eq!(r1, r2);
        assert_eq!(h1, h2);
        // Walls, coincident centres and a NULL centre are refused.
        let mut wall = st;
        wall.r2 = f64::INFINITY;
        let mut r = sentinel_res();
        let refused = [
            (x1.as_ptr(), x2.as_ptr(), &wall, DC_ERR_NOT_FINITE),
            (x1.as_ptr(), x1.as_ptr(), &st, DC_ERR_NOT_POSITIVE),
            (std::ptr::null(), x1.as_ptr(), &st, DC_ERR_NULL_POINTER),
        ];
        for (a, b, s, want) in refused {
            assert_eq!(spheres(a, b, s, &mut h1, &mut r), want);
        }
        assert_eq!(r, sentinel_res());
    }
}

/// `nc` states cycling through [`states`], each with its velocities and spins scaled a little
/// differently (so no two contacts are equal).
fn many_states(nc: usize) -> Vec<dc_contact_state> {
    let base = states();
    (0..nc)
        .map(|i| {
            let mut s = base[i % base.len()];
            let f = 1.0 + 1e-3 * i as f64;
            for k in 0..3 {
                s.v1[k] *= f;
                s.w2[k] *= f;
            }
            s
        })
        .collect()
}

struct Outs {
    f_n: Vec<f64>,
    force: Vec<f64>,
    t1: Vec<f64>,
    t2: Vec<f64>,
}

/// One batch call over `a` (checked or fused), outputs prefilled with 5.0.
fn call(
    m: &dc_contact_model,
    a: &Soa,
    h: &mut [f64],
    stride: usize,
    fused: Option<&mut usize>,
) -> (i32, Outs) {
    let nc = a.d.len();
    let mut o = Outs {
        f_n: vec![5.0; nc],
        force: vec![5.0; 3 * nc],
        t1: vec![5.0; 3 * nc],
        t2: vec![5.0; 3 * nc],
    };
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
        history: h.as_mut_ptr(),
        f_n: o.f_n.as_mut_ptr(),
        force: o.force.as_mut_ptr(),
        torque1: o.t1.as_mut_ptr(),
        torque2: o.t2.as_mut_ptr(),
    };
    let s = match fused {
        Some(bad) => unsafe { dc_contact_force_batch_fused(m, &b, 1e-6, bad) },
        None => unsafe { dc_contact_force_batch(m, &b, 1e-6) },
    };
    (s, o)
}

fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// The fused batch equals the checked batch bit for bit (outputs and history) over several
/// blocks (two full blocks of 1024 contacts and a partial one) and 3 steps, for every model.
#[test]
fn fused_batch_equals_checked_bit_for_bit() {
    // Under Miri (a UB check, ~10^5 times slower) one partial block of 40 contacts and every
    // 18th model: the sub-slicing and the per-block path, not the block boundaries.
    let (nc, every) = if cfg!(miri) { (40, 18) } else { (2085, 1) };
    let a = soa(&many_states(nc));
    let stride = 11;
    for m in all_models().into_iter().step_by(every) {
        let mut hc = vec![0.0f64; nc * stride];
        let mut hf = hc.clone();
        for step in 0..3 {
            let (sc, oc) = call(&m, &a, &mut hc, stride, None);
            let mut bad = 77usize;
            let (sf, of) = call(&m, &a, &mut hf, stride, Some(&mut bad));
            let what = (step, m.tangential, m.rolling, m.twisting);
            assert_eq!((sc, sf, bad), (DC_OK, DC_OK, 77), "{what:?}");
            assert!(same_bits(&oc.f_n, &of.f_n), "f_n {what:?}");
            assert!(same_bits(&oc.force, &of.force), "force {what:?}");
            assert!(same_bits(&oc.t1, &of.t1), "t1 {what:?}");
            assert!(same_bits(&oc.t2, &of.t2), "t2 {what:?}");
            assert!(same_bits(&hc, &hf), "history {what:?}");
        }
    }
}

/// Bad contacts in the fused batch: the first one's status and index are reported, every bad
/// contact's outputs are NaN and its history untouched, and every good contact equals
/// dc_contact_force on its own (bit for bit), also in the blocks that hold a bad contact.
#[test]
#[cfg_attr(
    miri,
    ignore = "2 x 1030 scalar calls plus batches take over 10 min under Miri; the same pointer paths run in fused_batch_equals_checked_bit_for_bit and batch_statuses_leave_everything_untouched"
)]
fn fused_batch_poisons_bad_contacts_and_names_the_first() {
    let models = all_models();
    // The full model (blocks) and a normal-only one (one fused loop).
    poisoned(models.iter().find(|m| m.history_len == 10).unwrap());
    poisoned(&models[0]);
}

fn poisoned(m: &dc_contact_model) {
    let nc = 1030;
    let st = many_states(nc);
    let stride = 10;
    // (index, how it is broken, the status dc_contact_force gives it)
    let mut a = soa(&st);
    let mut h = vec![0.0f64; nc * stride];
    a.r1[1023] = -1.0; // not positive
    a.n[3 * 7] = 1.1; // not unit
    a.v2[3 * 9 + 1] = f64::INFINITY; // not finite
    h[1024 * stride + 4] = f64::NAN; // history not finite
    // A model without history does not read it: contact 1024 is then good.
    let hist = m.history_len > 0;
    let bad_at: &[usize] = if hist {
        &[7, 9, 1023, 1024]
    } else {
        &[7, 9, 1023]
    };
    // The reference: each good contact alone through dc_contact_force, from the same history.
    let h0 = h.clone();
    let mut want = Vec::new();
    for (i, s) in st.iter().enumerate() {
        let mut hs = h0[i * stride..(i + 1) * stride].to_vec();
        let mut r = sentinel_res();
        let st_i = dc_contact_state {
            n: [a.n[3 * i], a.n[3 * i + 1], a.n[3 * i + 2]],
            v2: [a.v2[3 * i], a.v2[3 * i + 1], a.v2[3 * i + 2]],
            r1: a.r1[i],
            ..*s
        };
        let code = unsafe { dc_contact_force(m, &st_i, 1e-6, hs.as_mut_ptr(), stride, &mut r) };
        assert_eq!(code != DC_OK, bad_at.contains(&i), "contact {i}: {code}");
        want.push((code, r, hs));
    }
    let mut bad = 77usize;
    let (s, o) = call(m, &a, &mut h, stride, Some(&mut bad));
    assert_eq!((s, bad), (DC_ERR_NOT_UNIT, 7));
    assert_eq!(want[7].0, DC_ERR_NOT_UNIT);
    for (i, (code, r, hs)) in want.iter().enumerate() {
        let hb = &h[i * stride..(i + 1) * stride];
        if *code != DC_OK {
            assert!(o.f_n[i].is_nan(), "{i}");
            for k in 0..3 {
                assert!(o.force[3 * i + k].is_nan() && o.t1[3 * i + k].is_nan());
                assert!(o.t2[3 * i + k].is_nan());
            }
            assert!(same_bits(hb, &h0[i * stride..(i + 1) * stride]), "{i}");
        } else {
            assert_eq!(o.f_n[i].to_bits(), r.f_n.to_bits(), "{i}");
            assert!(same_bits(&o.force[3 * i..3 * i + 3], &r.force), "{i}");
            assert!(same_bits(&o.t1[3 * i..3 * i + 3], &r.torque1), "{i}");
            assert!(same_bits(&o.t2[3 * i..3 * i + 3], &r.torque2), "{i}");
            assert!(same_bits(hb, hs), "history {i}");
        }
    }
    // Statuses of the other kinds of bad contact, each first: history, radius, infinity.
    for (fix, want_i, want_s) in [
        (7usize, 9usize, DC_ERR_NOT_FINITE),
        (9, 1023, DC_ERR_NOT_POSITIVE),
        (1023, 1024, DC_ERR_NOT_FINITE),
    ]
    .into_iter()
    .take(if hist { 3 } else { 2 })
    {
        let b = soa(&st);
        match fix {
            7 => a.n[3 * 7] = b.n[3 * 7],
            9 => a.v2[3 * 9 + 1] = b.v2[3 * 9 + 1],
            _ => a.r1[1023] = b.r1[1023],
        }
        let mut hh = h0.clone();
        let mut bad = 77usize;
        let (s, o) = call(m, &a, &mut hh, stride, Some(&mut bad));
        assert_eq!((s, bad), (want_s, want_i));
        assert!(o.f_n[want_i].is_nan() && !o.f_n[0].is_nan());
    }
    // NULL first_bad: the status alone.
    a.r1[1023] = soa(&st).r1[1023];
    let mut hh = h0.clone();
    let nc = a.d.len();
    let (mut f_n, mut force, mut t1, mut t2) = (
        vec![0.0; nc],
        vec![0.0; 3 * nc],
        vec![0.0; 3 * nc],
        vec![0.0; 3 * nc],
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
        history: hh.as_mut_ptr(),
        f_n: f_n.as_mut_ptr(),
        force: force.as_mut_ptr(),
        torque1: t1.as_mut_ptr(),
        torque2: t2.as_mut_ptr(),
    };
    assert_eq!(
        unsafe { dc_contact_force_batch_fused(m, &b, 1e-6, std::ptr::null_mut()) },
        if hist { DC_ERR_NOT_FINITE } else { DC_OK }
    );
    assert!(f_n[1024].is_nan() == hist && !f_n[1023].is_nan());
}

/// A contact whose result overflows (valid inputs, DC_ERR_RESULT_RANGE from dc_contact_force)
/// is reported by both batches: DC_ERR_RESULT_RANGE, its outputs NaN, its history as it was;
/// every other contact equals dc_contact_force bit for bit; the fused batch names the first
/// bad contact of either kind. Overflows in two overflow-guard blocks of 512 contacts.
#[test]
fn batches_report_overflow_with_nan_and_history_kept() {
    let models = all_models();
    let full = *models.iter().find(|m| m.history_len == 10).unwrap();
    let rolling_only = *models
        .iter()
        .find(|m| m.history_len == 0 && m.rolling != DC_ROLLING_NONE)
        .unwrap();
    // Natively the two overflows sit in two guard blocks (512 contacts), and a short batch
    // (<= 32 contacts: its own small block) is tried too; under Miri, which looks for undefined
    // behaviour rather than at the blocking, a short batch and a 140-contact one.
    let sizes: &[(usize, [usize; 2])] = if cfg!(miri) {
        &[(20, [5, 12]), (140, [5, 130])]
    } else {
        &[(20, [5, 12]), (600, [5, 530])]
    };
    // 10: the record is copied aside whole; 13 (> DC_CONTACT_HISTORY_MAX): value by value.
    let strides: &[usize] = if cfg!(miri) { &[13] } else { &[10, 13] };
    let normal_only = models[0];
    for (&(nc, over), &stride, m) in sizes.iter().flat_map(|z| {
        strides
            .iter()
            .flat_map(move |s| [(z, s, full), (z, s, normal_only), (z, s, rolling_only)])
    }) {
        // The states once (the per-contact reference below reads them; many_states(k)[i] is the
        // same for every k > i, and rebuilding it per contact was quadratic, slow under Miri).
        let states_nc = many_states(nc);
        let good = soa(&states_nc);
        // A history that has something in it: two ordinary steps; the host's own values
        // past the model's record must survive too.
        let mut h0 = vec![0.0f64; nc * stride];
        for (k, v) in h0.iter_mut().enumerate() {
            if k % stride >= m.history_len as usize {
                *v = 7.25;
            }
        }
        for _ in 0..2 {
            assert_eq!(call(&m, &good, &mut h0, stride, None).0, DC_OK);
        }
        let mut a = soa(&states_nc);
        for &i in &over {
            a.d[i] = 1e300;
            a.v1[3 * i] = 1e300;
        }
        for fused in [false, true] {
            let mut h = h0.clone();
            let mut bad = 77usize;
            let (s, o) = call(&m, &a, &mut h, stride, fused.then_some(&mut bad));
            assert_eq!(s, DC_ERR_RESULT_RANGE, "fused {fused}");
            assert_eq!(bad, if fused { over[0] } else { 77 });
            for i in 0..nc {
                let st = dc_contact_state {
                    n: [a.n[3 * i], a.n[3 * i + 1], a.n[3 * i + 2]],
                    overlap: a.d[i],
                    v1: [a.v1[3 * i], a.v1[3 * i + 1], a.v1[3 * i + 2]],
                    ..states_nc[i]
                };
                let mut hs = h0[i * stride..(i + 1) * stride].to_vec();
                let mut r = sentinel_res();
                let code =
                    unsafe { dc_contact_force(&m, &st, 1e-6, hs.as_mut_ptr(), stride, &mut r) };
                let hb = &h[i * stride..(i + 1) * stride];
                let t = 3 * i..3 * i + 3;
                if over.contains(&i) {
                    assert_eq!(code, DC_ERR_RESULT_RANGE, "{i}");
                    assert!(o.f_n[i].is_nan(), "{i}");
                    assert!(o.force[t.clone()].iter().all(|x| x.is_nan()));
                    assert!(o.t1[t.clone()].iter().chain(&o.t2[t]).all(|x| x.is_nan()));
                    assert!(same_bits(hb, &h0[i * stride..(i + 1) * stride]), "{i}");
                } else {
                    assert_eq!(code, DC_OK, "{i}");
                    assert_eq!(o.f_n[i].to_bits(), r.f_n.to_bits(), "{i}");
                    assert!(same_bits(&o.force[t.clone()], &r.force), "{i}");
                    assert!(same_bits(&o.t1[t.clone()], &r.torque1), "{i}");
                    assert!(same_bits(&o.t2[t], &r.torque2), "{i}");
                    assert!(same_bits(hb, &hs), "history {i}");
                }
            }
        }
        // The fused batch names the first bad contact, whichever its kind.
        let mut h = h0.clone();
        let mut bad = 77usize;
        a.r1[2] = -1.0;
        let (s, _) = call(&m, &a, &mut h, stride, Some(&mut bad));
        assert_eq!((s, bad), (DC_ERR_NOT_POSITIVE, 2));
        a.r1[2] = good.r1[2];
        a.r1[nc - 1] = -1.0;
        let (s, _) = call(&m, &a, &mut h0.clone(), stride, Some(&mut bad));
        assert_eq!((s, bad), (DC_ERR_RESULT_RANGE, over[0]));
    }
}

/// A spin that turns the contact frame by |q| = |ω1 + ω2| dt/2 ≥ 2^20 rad in one step (no step
/// resolves it; the frame rotation's own sin and cos, `numerics::trig`, give NaN there): the
/// rotate carry falls back to the projection, as for a normal turned by more than 120°, so the
/// step is DC_OK with finite outputs and history, and the same as the projection carry's for a
/// contact whose normal did not turn (where the projection is no change).
#[test]
fn frame_rotations_beyond_two_to_the_twenty_fall_back_to_the_projection() {
    let mut s = spec();
    hertz(&mut s);
    s.tangential = DC_TANGENTIAL_MINDLIN;
    s.mu = 0.5;
    let (st, m) = init(&s);
    assert_eq!(st, DC_OK);
    let mut mp = m;
    assert_eq!(
        unsafe { dc_contact_model_set_carry(&mut mp, DC_CARRY_PROJECT) },
        DC_OK
    );
    let dt = 1e-6;
    // |q| = w dt/2 for w1 = (w, 0, 0), w2 = 0; the normal (1, 0, 0) the same in both steps.
    let at = |q: f64| dc_contact_state {
        w1: [2.0 * q / dt, 0.0, 0.0],
        w2: [0.0; 3],
        ..states()[0]
    };
    let step = |m: &dc_contact_model, st: &dc_contact_state| {
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX as usize];
        let mut out = sentinel_res();
        // a contact under way: the first step stores the normal and a spring, the second carries
        let first = dc_contact_state {
            w1: [0.0; 3],
            ..*st
        };
        assert_eq!(
            unsafe { dc_contact_force(m, &first, dt, h.as_mut_ptr(), h.len(), &mut out) },
            DC_OK
        );
        assert!(h[3..6].iter().any(|&x| x != 0.0), "a spring to carry");
        let status = unsafe { dc_contact_force(m, st, dt, h.as_mut_ptr(), h.len(), &mut out) };
        (status, h, out)
    };
    let two20 = 1_048_576.0;
    let (st_below, h_below, _) = step(&m, &at(two20 * 0.999));
    assert_eq!(st_below, DC_OK);
    let (_, h_proj_below, _) = step(&mp, &at(two20 * 0.999));
    assert_ne!(h_below, h_proj_below, "below 2^20 the spring is rotated");
    for q in [two20, 1e12, 1e300] {
        let (status, h, out) = step(&m, &at(q));
        assert_eq!(status, DC_OK, "rotate carry, |q| = {q:e}");
        assert!(
            h.iter().all(|x| x.is_finite()),
            "|q| = {q:e}: history {h:?}"
        );
        let (sp, hp, outp) = step(&mp, &at(q));
        assert_eq!(sp, DC_OK);
        assert_eq!((h, out), (hp, outp), "|q| = {q:e}: the projection's step");
    }
}
