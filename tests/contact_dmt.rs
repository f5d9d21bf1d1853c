//! The adhesive DMT normal law (added last, by the steps of docs/force.md): the force against
//! its definition computed here independently, continuity, the pull-off force 2π w R*, an
//! elastic adhesive impact that returns all its energy, capture of a slow damped impact, and the
//! spec rules (never clamped).
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::contact::*;
use demcontact::ffi::force::dc_normal_force;
use demcontact::ffi::status::*;

const E: f64 = 1e7; // soft (rubber-like) so that adhesion matters at mm scale
const NU: f64 = 0.45;
const W: f64 = 0.05; // work of adhesion, J/m²
const R: f64 = 1e-3;

fn dmt(damping: i32, e_n: f64) -> dc_contact_model {
    model(|s| {
        s.normal = DC_NORMAL_DMT;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = f64::INFINITY;
        s.nu2 = 0.3;
        s.work_of_adhesion = W;
        s.criterion = DC_END_OVERLAP;
        s.damping = damping;
        s.e_n = e_n;
    })
}

/// The definition, written independently: E* of a sphere on a rigid wall, Hertz minus
/// 2π w R*, linear tail over d_c = (3π w √R*/(2 E*))^{2/3}.
fn reference(d: f64, r: f64) -> f64 {
    let es = E / (1.0 - NU * NU);
    let pull = 2.0 * std::f64::consts::PI * W * r;
    let dc = (3.0 * std::f64::consts::PI * W * r.sqrt() / (2.0 * es)).powf(2.0 / 3.0);
    if d > 0.0 {
        4.0 / 3.0 * es * r.sqrt() * d.powf(1.5) - pull
    } else if d > -dc {
        -pull * (1.0 + d / dc)
    } else {
        0.0
    }
}

#[test]
fn force_matches_definition_and_is_continuous() {
    let m = dmt(DC_DAMPING_NONE, 1.0);
    let es = E / (1.0 - NU * NU);
    let pull = 2.0 * std::f64::consts::PI * W * R;
    let dc = (3.0 * std::f64::consts::PI * W * R.sqrt() / (2.0 * es)).powf(2.0 / 3.0);
    println!("d_c = {dc:.3e} m, pull-off {pull:.3e} N");
    let mut worst = 0.0f64;
    let mut most_attractive = 0.0f64;
    for i in -3000..=3000 {
        let d = dc * i as f64 / 1000.0;
        let f = unsafe { dc_normal_force(&m.normal, d, 0.0, R, 1e-6) };
        let want = reference(d, R);
        worst = worst.max((f - want).abs() / pull);
        most_attractive = most_attractive.min(f);
    }
    println!(
        "worst |F - definition| / pull-off = {worst:.2e}; most attractive {most_attractive:.6e}"
    );
    assert!(worst < 1e-13, "{worst}");
    assert!(
        (most_attractive + pull).abs() < 1e-14 * pull,
        "pull-off {most_attractive} vs {pull}"
    );
    // Continuity at touching and at the end of the range.
    let f = |d: f64| unsafe { dc_normal_force(&m.normal, d, 0.0, R, 1e-6) };
    assert!((f(1e-300) - f(0.0)).abs() < 1e-12 * pull);
    assert!(f(-dc * (1.0 - 1e-12)).abs() < 1e-10 * pull && f(-dc * 1.000001) == 0.0);
    assert_eq!(f(f64::NAN), 0.0);
    assert_eq!(f(-1.0), 0.0);
    // The unchecked call with a bad radius (r_eff < 0 or NaN): the tail's reach is NaN, so no
    // tail force (the library's own power gives a finite number for a NaN argument; the reach
    // keeps the NaN).
    for r in [-1e-3, f64::NAN] {
        let t = unsafe { dc_normal_force(&m.normal, -0.5 * dc, 0.0, r, 1e-6) };
        assert!(t == 0.0 || t.is_nan(), "r_eff {r}: tail force {t}");
    }
}

/// A sphere onto the wall at v0 (normal incidence), velocity-Verlet; returns the rebound speed
/// ratio, or None if it is still attached after many contact times.
fn bounce(m: &dc_contact_model, v0: f64) -> Option<f64> {
    let es = E / (1.0 - NU * NU);
    let dc = (3.0 * std::f64::consts::PI * W * R.sqrt() / (2.0 * es)).powf(2.0 / 3.0);
    let mut b = Body::sphere(
        [0.0, R + 2.0 * dc, 0.0],
        [0.0, -v0, 0.0],
        [0.0; 3],
        R,
        1000.0,
    );
    let tc = 2.87 * (b.m * b.m / (R * es * es * v0)).powf(0.2);
    let dt = tc / 4000.0;
    let mut res: dc_contact_result = unsafe { std::mem::zeroed() };
    let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
    let mut entered = false;
    for _ in 0..400_000 {
        b.v[1] += 0.5 * dt * res.force[1] / b.m;
        b.x[1] += dt * b.v[1];
        let st = state(&b, &Other::Wall);
        assert_eq!(
            unsafe { dc_contact_force(m, &st, dt, h.as_mut_ptr(), h.len(), &mut res) },
            DC_OK
        );
        b.v[1] += 0.5 * dt * res.force[1] / b.m;
        entered |= st.overlap > 0.0;
        if entered && st.overlap < -1.5 * dc {
            return Some(b.v[1] / v0);
        }
    }
    None
}

#[test]
fn elastic_adhesive_impact_returns_its_energy_and_damped_slow_impact_is_captured() {
    let elastic = dmt(DC_DAMPING_NONE, 1.0);
    for v0 in [0.01, 0.1, 1.0] {
        let e = bounce(&elastic, v0).expect("an undamped impact must leave again");
        println!("undamped DMT, v0 = {v0}: rebound/impact speed {e:.8}");
        assert!((e - 1.0).abs() < 1e-4, "conservative force: e = {e}");
    }
    let damped = dmt(DC_DAMPING_RESTITUTION, 0.5);
    let fast = bounce(&damped, 1.0).expect("fast damped impact escapes");
    println!("damped (e_n 0.5 of the non-adhesive law), v0 = 1: e = {fast:.4}");
    assert!(
        fast < 0.5 && fast > 0.3,
        "adhesion lowers the rebound below the non-adhesive e: {fast}"
    );
    assert!(
        bounce(&damped, 1e-3).is_none(),
        "a slow damped adhesive impact is captured"
    );
}

#[test]
fn spec_rules_and_tail_contact() {
    let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
    unsafe { dc_contact_spec_init(&mut s) };
    s.normal = DC_NORMAL_DMT;
    s.E1 = E;
    s.nu1 = NU;
    s.E2 = E;
    s.nu2 = NU;
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    s.criterion = DC_END_OVERLAP;
    assert_eq!(
        unsafe { dc_contact_model_init(&s, &mut m) },
        DC_ERR_SPEC_UNSET
    );
    s.work_of_adhesion = -1.0;
    assert_eq!(
        unsafe { dc_contact_model_init(&s, &mut m) },
        DC_ERR_NEGATIVE
    );
    s.work_of_adhesion = W;
    s.criterion = DC_END_FORCE; // clamping would remove the adhesion
    assert_eq!(
        unsafe { dc_contact_model_init(&s, &mut m) },
        DC_ERR_SPEC_MODEL
    );
    s.criterion = DC_END_OVERLAP;
    s.tangential = DC_TANGENTIAL_MINDLIN;
    s.mu = 0.5;
    assert_eq!(unsafe { dc_contact_model_init(&s, &mut m) }, DC_OK);
    // In the attractive tail (d < 0): attraction along -n, no tangential force, history reset.
    let st = dc_contact_state {
        n: [0.0, 0.0, 1.0],
        overlap: -1e-9,
        v1: [0.3, 0.0, 0.0],
        v2: [0.0; 3],
        w1: [0.0; 3],
        w2: [0.0; 3],
        r1: R,
        r2: R,
        m1: 1e-6,
        m2: 1e-6,
    };
    let mut h = [1.0; DC_CONTACT_HISTORY_MAX];
    let mut r: dc_contact_result = unsafe { std::mem::zeroed() };
    assert_eq!(
        unsafe { dc_contact_force(&m, &st, 1e-7, h.as_mut_ptr(), h.len(), &mut r) },
        DC_OK
    );
    assert!(r.f_n < 0.0 && r.force[2] == r.f_n && r.ft == [0.0; 3] && r.torque1 == [0.0; 3]);
    assert!(h[..6].iter().all(|&x| x == 0.0));
}
