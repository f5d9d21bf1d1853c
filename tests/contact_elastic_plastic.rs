//! The elastic–plastic normal law (Thornton 1997; a normal law with state): the restitution
//! closed form (dc_elastic_plastic_restitution) against an independent RK4 integration of a
//! head-on impact driven by the library's own force, e = 1 below the yield speed, the force as a
//! function of (δ, δ_max) only (reloading to the same δ_max gives the same force), the history
//! slot, the stateless paths that refuse the law, and bad input.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::calibration::{
    dc_elastic_plastic_restitution, dc_elastic_plastic_yield_speed,
};
use demcontact::ffi::contact::*;
use demcontact::ffi::force::{dc_normal_force, dc_normal_force_checked};
use demcontact::ffi::status::*;

const E: f64 = 7.0e10;
const NU: f64 = 0.33;
const R: f64 = 2.5e-3;
const RHO: f64 = 2700.0;
const P_Y: f64 = 1.0e9;

fn e_star() -> f64 {
    // A sphere on a rigid wall.
    E / (1.0 - NU * NU)
}

fn mass() -> f64 {
    RHO * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3)
}

fn ep(f: impl FnOnce(&mut dc_contact_spec)) -> dc_contact_model {
    model(|s| {
        s.normal = DC_NORMAL_ELASTIC_PLASTIC;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = f64::INFINITY;
        s.nu2 = 0.3;
        s.yield_pressure = P_Y;
        f(s);
    })
}

/// The library's normal force at overlap d for a contact whose history slot holds `dmax`
/// (the slot is the model's last double), through dc_contact_force; returns (F, new slot).
fn lib_force(m: &dc_contact_model, d: f64, dmax: f64) -> (f64, f64) {
    let len = m.history_len as usize;
    let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
    h[len - 1] = dmax;
    let st = dc_contact_state {
        n: [0.0, 0.0, 1.0],
        overlap: d,
        v1: [0.0; 3],
        v2: [0.0; 3],
        w1: [0.0; 3],
        w2: [0.0; 3],
        r1: R,
        r2: f64::INFINITY,
        m1: mass(),
        m2: f64::INFINITY,
    };
    let mut r = ZERO_RESULT;
    let s = unsafe { dc_contact_force(m, &st, 1e-9, h.as_mut_ptr(), len, &mut r) };
    assert_eq!(s, DC_OK);
    (r.f_n, h[len - 1])
}

/// One RK4 step of m d'' = −F(d) from (d, v) over h.
fn rk4(f: &dyn Fn(f64) -> f64, m: f64, d: f64, v: f64, h: f64) -> (f64, f64) {
    let a = |d: f64| -f(d) / m;
    let (k1d, k1v) = (v, a(d));
    let (k2d, k2v) = (v + 0.5 * h * k1v, a(d + 0.5 * h * k1d));
    let (k3d, k3v) = (v + 0.5 * h * k2v, a(d + 0.5 * h * k2d));
    let (k4d, k4v) = (v + h * k3v, a(d + h * k3d));
    (
        d + h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d),
        v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v),
    )
}

/// Head-on impact at v0 integrated with RK4 in two smooth phases, each with the library's force:
/// loading (the virgin curve, state = the current overlap) until the velocity vanishes (the
/// last step bisected onto v = 0), then unloading with the state fixed at the δ_max reached,
/// until the overlap is negative. Returns (rebound speed / v0, δ_max).
fn integrate(m: &dc_contact_model, v0: f64, steps: f64) -> (f64, f64) {
    let mm = mass();
    let es = e_star();
    // Hertz contact time scale at v0.
    let tc = 2.87 * (mm * mm / (R * es * es * v0)).powf(0.2);
    let h = tc / steps;
    let load = |d: f64| lib_force(m, d, 0.0).0;
    let (mut d, mut v) = (0.0, v0);
    loop {
        let (d1, v1) = rk4(&load, mm, d, v, h);
        if v1 <= 0.0 {
            // Bisect the step length onto v = 0.
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if rk4(&load, mm, d, v, mid).1 > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            d = rk4(&load, mm, d, v, lo).0;
            break;
        }
        (d, v) = (d1, v1);
    }
    let dmax = d;
    let unload = |x: f64| lib_force(m, x, dmax).0;
    let mut v = 0.0;
    while d > 0.0 {
        (d, v) = rk4(&unload, mm, d, v, h);
    }
    (-v / v0, dmax)
}

fn yield_speed() -> f64 {
    let mut vy = 0.0;
    assert_eq!(
        unsafe { dc_elastic_plastic_yield_speed(e_star(), R, mass(), P_Y, &mut vy) },
        DC_OK
    );
    vy
}

/// Thornton's closed form against the integration over v/v_y = 1…1000 (RK4, t_c/20000 per
/// step: the two agree to 4e-12; the bound 1e-10).
#[test]
fn restitution_closed_form_matches_integration() {
    let m = ep(|_| {});
    let vy = yield_speed();
    println!("v_y = {vy:.6e} m/s");
    let mut worst = 0.0f64;
    for i in 0..=24 {
        let x = 10f64.powf(3.0 * i as f64 / 24.0) * (1.0 + 1e-3);
        let (e_int, _) = integrate(&m, x * vy, 20_000.0);
        let mut e = 0.0;
        assert_eq!(unsafe { dc_elastic_plastic_restitution(x, &mut e) }, DC_OK);
        let err = (e_int - e).abs();
        worst = worst.max(err);
        println!("v/v_y = {x:9.3}: closed form {e:.9}, integration {e_int:.9}, |diff| {err:.1e}");
    }
    println!("worst |e_closed − e_integrated| = {worst:.2e}");
    assert!(worst < 1e-10, "{worst}");
}

/// Below the yield speed the contact is Hertz: e = 1 (integration and the closed form).
#[test]
fn below_yield_restitution_is_one() {
    let m = ep(|_| {});
    let vy = yield_speed();
    for x in [0.1, 0.5, 0.99] {
        let (e_int, dmax) = integrate(&m, x * vy, 20_000.0);
        let mut e = 0.0;
        assert_eq!(unsafe { dc_elastic_plastic_restitution(x, &mut e) }, DC_OK);
        assert_eq!(e, 1.0);
        println!("v/v_y = {x}: integrated e = {e_int:.12} (δ_max {dmax:.3e})");
        assert!((e_int - 1.0).abs() < 1e-9, "{e_int}");
    }
    assert_eq!(
        unsafe { dc_elastic_plastic_restitution(1.0, &mut 0.0) },
        DC_OK
    );
}

/// Just above yield the closed form is 1 minus roundings: e stays in (0, 1] (it rounded to
/// 1.0000000000000004 at x = 1.0000000000001885 before the clamp) and falls with x.
#[test]
fn restitution_just_above_yield_is_at_most_one() {
    let mut prev = 1.0;
    let mut x = 1.0f64;
    for _ in 0..20_000 {
        x = f64::from_bits(x.to_bits() + 1_000_000);
        let mut e = 7.0;
        assert_eq!(unsafe { dc_elastic_plastic_restitution(x, &mut e) }, DC_OK);
        assert!(e > 0.0 && e <= 1.0, "x {x:e}: e {e:e}");
        assert!(
            e <= prev + 4.0 * f64::EPSILON,
            "x {x:e}: e {e:e} above {prev:e}"
        );
        prev = e;
    }
    let mut e = 0.0;
    assert_eq!(
        unsafe { dc_elastic_plastic_restitution(1.0000000000001885, &mut e) },
        DC_OK
    );
    assert!(e <= 1.0, "{e:e}");
}

/// The force is a function of (δ, δ_max): an unload–reload cycle to the same δ_max gives the
/// same force, then the plastic branch continues as on a virgin load.
#[test]
fn reloading_follows_the_unloading_curve_to_the_same_force() {
    let m = ep(|_| {});
    let es = e_star();
    let dy = (std::f64::consts::PI * P_Y / (2.0 * es)).powi(2) * R;
    let d1 = 20.0 * dy;
    // Load step by step to d1.
    let mut st = 0.0;
    let mut f1 = 0.0;
    for i in 1..=100 {
        (f1, st) = lib_force(&m, d1 * i as f64 / 100.0, st);
    }
    assert_eq!(st, d1);
    // Definition, written independently: F_y + π p_y R* (δ − δ_y).
    let fy = 4.0 / 3.0 * es * R.sqrt() * dy.powf(1.5);
    let want = fy + std::f64::consts::PI * P_Y * R * (d1 - dy);
    assert!((f1 - want).abs() < 1e-12 * want, "{f1} vs {want}");
    // Unload to half, reload: the same force at each overlap both ways, F_max at d1 again.
    let path: Vec<f64> = (0..=100)
        .map(|i| d1 * (1.0 - 0.5 * i as f64 / 100.0))
        .collect();
    let down: Vec<f64> = path
        .iter()
        .map(|&d| {
            let (f, s) = lib_force(&m, d, st);
            assert_eq!(s, d1, "unloading keeps δ_max");
            f
        })
        .collect();
    for (k, &d) in path.iter().enumerate().rev() {
        let (f, _) = lib_force(&m, d, st);
        assert_eq!(f, down[k]);
    }
    assert_eq!(lib_force(&m, d1, st).0, f1);
    // The unloading curve meets (δ_max, F_max) and ends at δ_p = δ_max − F_max/((4/3)E* a_p).
    let ap = (R * d1).sqrt();
    let dp = d1 - f1 / (4.0 / 3.0 * es * ap);
    assert_eq!(lib_force(&m, dp * (1.0 - 1e-12), st).0, 0.0);
    assert!(lib_force(&m, dp + 1e-3 * (d1 - dp), st).0 > 0.0);
    // Beyond δ_max: the plastic branch, as on a virgin load to the same overlap.
    let d2 = 1.5 * d1;
    let (f2, s2) = lib_force(&m, d2, st);
    assert_eq!(s2, d2);
    assert_eq!(f2, lib_force(&m, d2, 0.0).0);
    // Separation resets the state.
    assert_eq!(lib_force(&m, -1e-9, st), (0.0, 0.0));
}

#[test]
fn history_slot_and_length() {
    let len = |m: &dc_contact_model| {
        let mut n = 99usize;
        assert_eq!(unsafe { dc_contact_history_len(m, &mut n) }, DC_OK);
        n
    };
    assert_eq!(len(&ep(|_| {})), 1);
    let full = ep(|s| {
        s.tangential = DC_TANGENTIAL_MINDLIN_RESCALE;
        s.mu = 0.3;
        s.rolling = DC_ROLLING_EPSD;
        s.mu_r = 0.02;
        s.twisting = DC_TWISTING_SDS;
        s.mu_tw = 1e-5;
        s.k_tw = 1e-4;
    });
    assert_eq!(len(&full), DC_CONTACT_HISTORY_MAX);
    let hertz = model(|s| {
        s.normal = DC_NORMAL_HERTZ;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = f64::INFINITY;
        s.nu2 = 0.3;
    });
    assert_eq!(len(&hertz), 0, "a stateless law pays nothing");
    // The slot of the full model is its last double and holds δ_max.
    let (_, s) = lib_force(&full, 1e-6, 0.0);
    assert_eq!(s, 1e-6);
}

#[test]
fn stateless_paths_refuse_the_law_and_bad_input_is_named() {
    let m = ep(|_| {});
    // dc_pair paths: no state, no force.
    assert!(unsafe { dc_normal_force(&m.normal, 1e-6, 0.0, R, 1e-3) }.is_nan());
    let mut f = 0.0;
    assert_eq!(
        unsafe { dc_normal_force_checked(&m.normal, 1e-6, 0.0, R, 1e-3, &mut f) },
        DC_ERR_PAIR_INVALID
    );
    let mut mm = m;
    assert_eq!(
        unsafe { dc_contact_model_set_step(&mut mm, 1e-7, DC_INTEGRATOR_VELOCITY_VERLET) },
        DC_ERR_STEP_UNSUPPORTED
    );
    assert_eq!(format!("{mm:?}"), format!("{m:?}"), "untouched on error");
    // The spec.
    let try_py = |p_y: f64, damping: i32| {
        let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
        unsafe { dc_contact_spec_init(&mut s) };
        s.normal = DC_NORMAL_ELASTIC_PLASTIC;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = E;
        s.nu2 = NU;
        s.yield_pressure = p_y;
        s.damping = damping;
        s.e_n = 0.5;
        let mut out: dc_contact_model = unsafe { std::mem::zeroed() };
        unsafe { dc_contact_model_init(&s, &mut out) }
    };
    assert_eq!(try_py(P_Y, DC_DAMPING_NONE), DC_OK);
    assert_eq!(try_py(f64::NAN, DC_DAMPING_NONE), DC_ERR_SPEC_UNSET);
    assert_eq!(try_py(f64::INFINITY, DC_DAMPING_NONE), DC_ERR_NOT_FINITE);
    assert_eq!(try_py(0.0, DC_DAMPING_NONE), DC_ERR_NOT_POSITIVE);
    assert_eq!(try_py(-1.0, DC_DAMPING_NONE), DC_ERR_NOT_POSITIVE);
    assert_eq!(try_py(P_Y, DC_DAMPING_RESTITUTION), DC_ERR_SPEC_MODEL);
    // A caller compiled before yield_pressure was appended: accepted, the field unset.
    let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
    unsafe { dc_contact_spec_init(&mut s) };
    s.size = std::mem::offset_of!(dc_contact_spec, yield_pressure) as u32;
    s.normal = DC_NORMAL_ELASTIC_PLASTIC;
    s.E1 = E;
    s.nu1 = NU;
    s.E2 = E;
    s.nu2 = NU;
    s.yield_pressure = P_Y; // beyond the declared size: not read
    let mut out: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(
        unsafe { dc_contact_model_init(&s, &mut out) },
        DC_ERR_SPEC_UNSET
    );
    s.normal = DC_NORMAL_HERTZ;
    assert_eq!(unsafe { dc_contact_model_init(&s, &mut out) }, DC_OK);
    s.size += 4;
    assert_eq!(
        unsafe { dc_contact_model_init(&s, &mut out) },
        DC_ERR_SPEC_VERSION
    );
    // A history with a non-finite state.
    let mut h = [f64::NAN];
    let st = dc_contact_state {
        n: [0.0, 0.0, 1.0],
        overlap: 1e-6,
        v1: [0.0; 3],
        v2: [0.0; 3],
        w1: [0.0; 3],
        w2: [0.0; 3],
        r1: R,
        r2: f64::INFINITY,
        m1: mass(),
        m2: f64::INFINITY,
    };
    let mut r = ZERO_RESULT;
    assert_eq!(
        unsafe { dc_contact_force(&m, &st, 1e-9, h.as_mut_ptr(), 1, &mut r) },
        DC_ERR_NOT_FINITE
    );
    // The library functions.
    let mut e = 7.0;
    assert_eq!(
        unsafe { dc_elastic_plastic_restitution(f64::NAN, &mut e) },
        DC_ERR_NOT_FINITE
    );
    assert_eq!(
        unsafe { dc_elastic_plastic_restitution(-1.0, &mut e) },
        DC_ERR_NEGATIVE
    );
    assert_eq!(
        unsafe { dc_elastic_plastic_restitution(2.0, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(e, 7.0);
    let mut v = 7.0;
    for (a, b, c, d, want) in [
        (f64::NAN, R, 1.0, P_Y, DC_ERR_NOT_FINITE),
        (e_star(), 0.0, 1.0, P_Y, DC_ERR_NOT_POSITIVE),
        (e_star(), R, 1.0, -P_Y, DC_ERR_NOT_POSITIVE),
        (e_star(), R, f64::INFINITY, P_Y, DC_ERR_NOT_FINITE),
    ] {
        assert_eq!(
            unsafe { dc_elastic_plastic_yield_speed(a, b, c, d, &mut v) },
            want
        );
    }
    assert_eq!(v, 7.0);
}
