//! The JKR normal law (`DC_NORMAL_JKR`, a normal law with state) through the C ABI
//! (`dc_contact_spec` → `dc_contact_model` → `dc_contact_force`): the pull-off force under load
//! control (the minimum force of an overlap sweep), breakage under displacement control at δ_c
//! (the force just above, 0 and the state reset just below, no re-forming at negative overlap),
//! an undamped head-on impact in a velocity-Verlet host against the closed form
//! e = √(1 − v_s²/v²) and sticking below v_s, and the specification's bad input. Every
//! reference value is written here from the textbook JKR relations, not from the library.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::contact::*;
use demcontact::ffi::force::dc_normal_force_checked;
use demcontact::ffi::status::*;
use std::f64::consts::PI;

/// Silica-like sphere of radius 10 µm on a rigid wall: R* = R, m* = m.
const E: f64 = 7.0e10;
const NU: f64 = 0.25;
const R: f64 = 1.0e-5;
const RHO: f64 = 2500.0;
const W: f64 = 0.2;

fn e_star() -> f64 {
    E / (1.0 - NU * NU)
}

fn mass() -> f64 {
    RHO * 4.0 / 3.0 * PI * R.powi(3)
}

/// Textbook δ_c = −(3/4)(π² w² R*/E*²)^{1/3}.
fn delta_c() -> f64 {
    -0.75 * (PI * PI * W * W * R / (e_star() * e_star())).cbrt()
}

/// Textbook sticking speed: ½ m* v_s² = W = (2π)^{5/3} (6 + 4^{−1/3})/20 (w⁵ R*⁴/E*²)^{1/3}.
fn sticking_speed() -> f64 {
    let wl = (2.0 * PI).powf(5.0 / 3.0) * (6.0 + 0.25f64.cbrt()) / 20.0
        * (W.powi(5) * R.powi(4) / (e_star() * e_star())).cbrt();
    (2.0 * wl / mass()).sqrt()
}

fn jkr(f: impl FnOnce(&mut dc_contact_spec)) -> dc_contact_model {
    model(|s| {
        s.normal = DC_NORMAL_JKR;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = f64::INFINITY;
        s.nu2 = 0.3;
        s.work_of_adhesion = W;
        s.criterion = DC_END_OVERLAP;
        f(s);
    })
}

fn wall_state(d: f64, v: f64) -> dc_contact_state {
    dc_contact_state {
        n: [0.0, 1.0, 0.0],
        overlap: d,
        v1: [0.0, -v, 0.0],
        v2: [0.0; 3],
        w1: [0.0; 3],
        w2: [0.0; 3],
        r1: R,
        r2: f64::INFINITY,
        m1: mass(),
        m2: f64::INFINITY,
    }
}

/// One step of dc_contact_force at overlap d (at rest) with the history `h`: the force.
fn step(m: &dc_contact_model, d: f64, h: &mut [f64; DC_CONTACT_HISTORY_MAX]) -> f64 {
    let mut r = ZERO_RESULT;
    let st = wall_state(d, 0.0);
    let s = unsafe { dc_contact_force(m, &st, 1e-9, h.as_mut_ptr(), h.len(), &mut r) };
    assert_eq!(s, DC_OK);
    r.f_n
}

/// The force at d of a contact whose neck is formed (a fresh history with the state slot 1).
fn formed(m: &dc_contact_model, d: f64) -> f64 {
    let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
    h[m.history_len as usize - 1] = 1.0;
    step(m, d, &mut h)
}

#[test]
fn pull_off_under_load_control_and_breakage_under_displacement_control() {
    let m = jkr(|_| {});
    assert_eq!(m.history_len, 1, "normal-only: the neck's double alone");
    let fpo = 1.5 * PI * W * R;
    let dc = delta_c();
    // Load control: the minimum force over the formed branch [δ_c, 0]: a sweep of 2001 overlaps,
    // then golden section around the smallest.
    let n = 2000;
    let (mut imin, mut fmin) = (0, f64::INFINITY);
    for i in 0..=n {
        let f = formed(&m, dc * (1.0 - i as f64 / n as f64));
        if f < fmin {
            (imin, fmin) = (i, f);
        }
    }
    assert!(imin > 0 && imin < n, "the minimum is inside the branch");
    let at = |i: usize| dc * (1.0 - i as f64 / n as f64);
    let (mut lo, mut hi) = (at(imin - 1), at(imin + 1));
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let x1 = hi - g * (hi - lo);
        let x2 = lo + g * (hi - lo);
        if formed(&m, x1) < formed(&m, x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let fmin = formed(&m, 0.5 * (lo + hi));
    println!(
        "load control: min F = {fmin:.12e} N, -(3/2) pi w R* = {:.12e} N, at d/|d_c| = {:.6}",
        -fpo,
        0.5 * (lo + hi) / dc.abs()
    );
    assert!(
        (fmin / -fpo - 1.0).abs() < 1e-12,
        "pull-off {fmin} vs {}",
        -fpo
    );
    // Displacement control: one contact pulled apart step by step from δ = 0 (formed there).
    let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
    let slot = m.history_len as usize - 1;
    assert_eq!(
        step(&m, -1e-3 * dc.abs(), &mut h),
        0.0,
        "no force before touching"
    );
    assert_eq!(h[slot], 0.0);
    let f0 = step(&m, 0.0, &mut h);
    assert!(
        (f0 / (-8.0 / 9.0 * fpo) - 1.0).abs() < 1e-12,
        "at δ = 0: {f0}"
    );
    assert_eq!(h[slot], 1.0, "formed at δ = 0");
    for i in 1..1000 {
        let f = step(&m, dc * i as f64 / 1000.0, &mut h);
        assert!(f < 0.0 && h[slot] == 1.0);
    }
    // Just above δ_c (σ = 1e-10 of |δ_c|): −(5/6) π w R* to the branch's √σ conditioning.
    let above = dc * (1.0 - 1e-10);
    let fb = step(&m, above, &mut h);
    println!(
        "displacement control: F(δ_c + 1e-10|δ_c|) = {fb:.9e} N, -(5/6) pi w R* = {:.9e} N",
        -5.0 / 6.0 * PI * W * R
    );
    assert!((fb / (-5.0 / 6.0 * PI * W * R) - 1.0).abs() < 1e-4, "{fb}");
    assert_eq!(h[slot], 1.0);
    // Just below: broken, force 0, state reset; no re-forming at negative overlap.
    assert_eq!(step(&m, dc * (1.0 + 1e-10), &mut h), 0.0);
    assert_eq!(h[slot], 0.0);
    assert_eq!(step(&m, 0.5 * dc, &mut h), 0.0);
    assert_eq!(h[slot], 0.0);
    assert!(
        step(&m, 1e-15, &mut h) < 0.0 && h[slot] == 1.0,
        "re-formed on touching"
    );
}

/// Head-on impact on the wall at speed v, undamped, velocity Verlet (LAMMPS order) at dt:
/// Some(rebound speed) once the neck breaks, None while still stuck after `steps`.
fn impact(m: &dc_contact_model, v: f64, dt: f64, steps: usize) -> Option<f64> {
    let mut b = Body::sphere([0.0, R + v * dt, 0.0], [0.0, -v, 0.0], [0.0; 3], R, RHO);
    let mut res = ZERO_RESULT;
    let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
    let slot = m.history_len as usize - 1;
    let mut formed = false;
    for _ in 0..steps {
        b.v[1] += 0.5 * dt * res.force[1] / b.m;
        b.x[1] += dt * b.v[1];
        let st = state(&b, &Other::Wall);
        let s = unsafe { dc_contact_force(m, &st, dt, h.as_mut_ptr(), h.len(), &mut res) };
        assert_eq!(s, DC_OK);
        b.v[1] += 0.5 * dt * res.force[1] / b.m;
        if h[slot] > 0.0 {
            formed = true;
        } else if formed {
            return Some(b.v[1]);
        }
    }
    None
}

#[test]
fn undamped_impact_realises_the_closed_form_restitution_and_sticks_below_v_s() {
    let m = jkr(|_| {});
    let (es, mm) = (e_star(), mass());
    let vs = sticking_speed();
    println!("v_s = {vs:.6e} m/s");
    let mut worst = 0.0f64;
    for k in [1.5, 2.0, 3.0, 5.0, 10.0, 20.0] {
        let v = k * vs;
        let tc = 2.87 * (mm * mm / (R * es * es * v)).powf(0.2);
        let dt = tc / 20_000.0;
        let out = impact(&m, v, dt, 2_000_000).expect("separates above v_s");
        let e = out / v;
        let ec = (1.0 - (vs / v).powi(2)).sqrt();
        // Stated tolerance from dt: the force jumps at formation ((4/3) pi w R*, at speed ≤ v)
        // and at breakage ((5/6) pi w R*, at speed ≤ v): a Verlet step misplaces each jump's
        // work by at most |jump| v dt, so |Δ(e²)| ≤ 2 (13/6) pi w R* v dt/(½ m v²) and
        // |Δe| ≤ that/(2 e) (the smooth part's O(dt²) error is far below).
        let tol = 2.0 * (13.0 / 6.0 * PI * W * R) * v * dt / (0.5 * mm * v * v) / (2.0 * ec);
        println!(
            "v/v_s = {k}: e = {e:.9}, closed form {ec:.9}, |diff| = {:.2e} (tolerance {tol:.2e})",
            (e - ec).abs()
        );
        assert!((e - ec).abs() <= tol, "{k}: {e} vs {ec} (tol {tol})");
        worst = worst.max((e - ec).abs() / tol);
    }
    println!("largest |e - e_closed|/tolerance: {worst:.3}");
    for k in [0.5, 0.9] {
        let v = k * vs;
        let tc = 2.87 * (mm * mm / (R * es * es * vs)).powf(0.2);
        let dt = tc / 20_000.0;
        assert!(
            impact(&m, v, dt, 50 * 20_000).is_none(),
            "{k} v_s: separated below the sticking speed"
        );
    }
}

#[test]
fn spec_bad_input_gets_its_status_and_stateless_paths_refuse_the_law() {
    let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
    unsafe { dc_contact_spec_init(&mut s) };
    s.normal = DC_NORMAL_JKR;
    s.E1 = E;
    s.nu1 = NU;
    s.E2 = E;
    s.nu2 = NU;
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    let init =
        |s: &dc_contact_spec, m: &mut dc_contact_model| unsafe { dc_contact_model_init(s, m) };
    // w unset (NaN is the unset marker), then w ≤ 0 and w infinite.
    assert_eq!(init(&s, &mut m), DC_ERR_SPEC_UNSET);
    s.work_of_adhesion = f64::NAN;
    assert_eq!(init(&s, &mut m), DC_ERR_SPEC_UNSET);
    for (w, st) in [
        (0.0, DC_ERR_NOT_POSITIVE),
        (-0.0, DC_ERR_NOT_POSITIVE),
        (-1.0, DC_ERR_NOT_POSITIVE),
        (f64::INFINITY, DC_ERR_NOT_FINITE),
        (f64::NEG_INFINITY, DC_ERR_NOT_FINITE),
    ] {
        s.work_of_adhesion = w;
        assert_eq!(init(&s, &mut m), st, "w = {w}");
    }
    s.work_of_adhesion = W;
    // Clamping would delete the adhesion: refused as DMT.
    s.criterion = DC_END_FORCE;
    assert_eq!(init(&s, &mut m), DC_ERR_SPEC_MODEL);
    s.criterion = DC_END_OVERLAP;
    // Restitution damping: accepted with a valid e_n, its range checked.
    s.damping = DC_DAMPING_RESTITUTION;
    s.e_n = 1.5;
    assert_eq!(init(&s, &mut m), DC_ERR_RESTITUTION_RANGE);
    s.e_n = 0.5;
    assert_eq!(init(&s, &mut m), DC_OK);
    assert_eq!(m.normal.kernel, 21);
    assert!(m.normal.alpha > 0.0);
    s.damping = DC_DAMPING_NONE;
    s.E1 = f64::NAN;
    assert_eq!(init(&s, &mut m), DC_ERR_SPEC_UNSET);
    s.E1 = E;
    assert_eq!(init(&s, &mut m), DC_OK);
    assert_eq!(m.history_len, 1);
    // A law with state: no dc_pair path, no step-aware form.
    let mut f = 0.0;
    assert_eq!(
        unsafe { dc_normal_force_checked(&m.normal, 1e-9, 0.0, R, 1e-12, &mut f) },
        DC_ERR_PAIR_INVALID
    );
    let mut mm = m;
    assert_eq!(
        unsafe { dc_contact_model_set_step(&mut mm, 1e-9, DC_INTEGRATOR_VELOCITY_VERLET) },
        DC_ERR_STEP_UNSUPPORTED
    );
}
