//! `dc_contact_model_reach`: how far beyond touching a model's normal law acts. The expected
//! reaches are written here from the textbook DMT and JKR relations (not from the library), and
//! each is also checked by what the contact does: DMT's tail pulls just inside its reach and is
//! zero just outside; a formed JKR neck holds just inside and breaks just outside. Repulsive
//! laws reach 0. Bad input gets its status and leaves the output untouched.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;
use std::f64::consts::PI;

const E: f64 = 7.0e10;
const NU: f64 = 0.25;
const W: f64 = 0.2;
const RHO: f64 = 2500.0;

/// E* of a sphere (E, ν) on a rigid wall.
fn e_star() -> f64 {
    E / (1.0 - NU * NU)
}

fn law(normal: i32) -> dc_contact_model {
    model(|s| {
        s.normal = normal;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = f64::INFINITY;
        s.nu2 = 0.3;
        s.work_of_adhesion = W;
        s.criterion = DC_END_OVERLAP;
        if normal == DC_NORMAL_POWERLAW {
            s.p = 1.5;
            s.k_n = 1e9;
        }
        if normal == DC_NORMAL_LINEAR {
            s.k_n = 1e4;
        }
        if normal == DC_NORMAL_ELASTIC_PLASTIC {
            s.yield_pressure = 1e8;
        }
        if normal == DC_NORMAL_VISCOELASTIC {
            s.visco_A = 1e-7;
        }
    })
}

fn reach(m: &dc_contact_model, r: f64) -> (i32, f64) {
    let mut out = -7.0;
    let s = unsafe { dc_contact_model_reach(m, r, &mut out) };
    (s, out)
}

/// Textbook DMT tail length: F_el(d_c) = 0 for the linear tail −2πwR*(1 + δ/d_c) joined to
/// Hertz at δ = 0 with the Hertz stiffness scale: d_c = (3π w √R* / (2E*))^{2/3}.
fn dmt_reach(r: f64) -> f64 {
    (3.0 * PI * W * r.sqrt() / (2.0 * e_star())).powf(2.0 / 3.0)
}

/// Textbook JKR breakage overlap under displacement control: |δ_c| = (3/4)(π² w² R*/E*²)^{1/3}.
fn jkr_reach(r: f64) -> f64 {
    0.75 * (PI * PI * W * W * r / (e_star() * e_star())).cbrt()
}

fn wall_state(d: f64, r: f64) -> dc_contact_state {
    dc_contact_state {
        n: [0.0, 1.0, 0.0],
        overlap: d,
        v1: [0.0; 3],
        v2: [0.0; 3],
        w1: [0.0; 3],
        w2: [0.0; 3],
        r1: r,
        r2: f64::INFINITY,
        m1: RHO * 4.0 / 3.0 * PI * r.powi(3),
        m2: f64::INFINITY,
    }
}

fn force(m: &dc_contact_model, d: f64, r: f64, h: &mut [f64; DC_CONTACT_HISTORY_MAX]) -> f64 {
    let mut out = ZERO_RESULT;
    let st = wall_state(d, r);
    let s = unsafe { dc_contact_force(m, &st, 1e-9, h.as_mut_ptr(), h.len(), &mut out) };
    assert_eq!(s, DC_OK);
    out.f_n
}

#[test]
fn reach_matches_the_textbook_and_the_contact() {
    let dmt = law(DC_NORMAL_DMT);
    let jkr = law(DC_NORMAL_JKR);
    for r in [1e-7, 1e-5, 1e-3, 1.0] {
        // DMT: the closed form to a few ulps (pow of a rounded ratio), and the tail itself.
        let (s, got) = reach(&dmt, r);
        assert_eq!(s, DC_OK);
        let want = dmt_reach(r);
        assert!(
            ((got - want) / want).abs() < 1e-14,
            "DMT r {r}: {got} vs {want}"
        );
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
        assert!(
            force(&dmt, -got * (1.0 - 1e-9), r, &mut h) < 0.0,
            "DMT r {r}: no pull inside"
        );
        let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
        assert_eq!(
            force(&dmt, -got * (1.0 + 1e-9), r, &mut h),
            0.0,
            "DMT r {r}: pull outside"
        );

        // JKR: the closed form, and a neck formed at δ > 0 then pulled to just inside (holds)
        // and just outside (breaks) its reach.
        let (s, got) = reach(&jkr, r);
        assert_eq!(s, DC_OK);
        let want = jkr_reach(r);
        assert!(
            ((got - want) / want).abs() < 1e-14,
            "JKR r {r}: {got} vs {want}"
        );
        for (scale, holds) in [(1.0 - 1e-9, true), (1.0 + 1e-9, false)] {
            let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
            force(&jkr, got, r, &mut h);
            let f = force(&jkr, -got * scale, r, &mut h);
            assert_eq!(
                f != 0.0,
                holds,
                "JKR r {r} at {scale} of the reach: force {f}"
            );
        }
        // The reach grows as R*^(1/3) for both laws.
        let (_, r8) = reach(&jkr, 8.0 * r);
        assert!((r8 / got - 2.0).abs() < 1e-13, "JKR scaling {}", r8 / got);
        let (_, d8) = reach(&dmt, 8.0 * r);
        assert!((d8 / reach(&dmt, r).1 - 2.0).abs() < 1e-13);
    }
}

#[test]
fn repulsive_laws_reach_zero() {
    for normal in [
        DC_NORMAL_HERTZ,
        DC_NORMAL_POWERLAW,
        DC_NORMAL_LINEAR,
        DC_NORMAL_VISCOELASTIC,
        DC_NORMAL_ELASTIC_PLASTIC,
    ] {
        assert_eq!(reach(&law(normal), 1e-3), (DC_OK, 0.0), "law {normal}");
    }
    // DMT without adhesion is Hertz: no tail.
    let hertz_like = model(|s| {
        s.normal = DC_NORMAL_DMT;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = E;
        s.nu2 = NU;
        s.work_of_adhesion = 0.0;
        s.criterion = DC_END_OVERLAP;
    });
    assert_eq!(reach(&hertz_like, 1e-3), (DC_OK, 0.0));
}

#[test]
fn bad_input_gets_a_status_and_no_output() {
    let jkr = law(DC_NORMAL_JKR);
    for (r, want) in [
        (f64::NAN, DC_ERR_NOT_FINITE),
        (f64::INFINITY, DC_ERR_NOT_FINITE),
        (f64::NEG_INFINITY, DC_ERR_NOT_FINITE),
        (0.0, DC_ERR_NOT_POSITIVE),
        (-1e-3, DC_ERR_NOT_POSITIVE),
    ] {
        assert_eq!(reach(&jkr, r), (want, -7.0), "r_eff {r}");
    }
    let zero: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(reach(&zero, 1e-3), (DC_ERR_CONTACT_MODEL_INVALID, -7.0));
    let mut out = -7.0;
    assert_eq!(
        unsafe { dc_contact_model_reach(std::ptr::null(), 1e-3, &mut out) },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(out, -7.0);
    assert_eq!(
        unsafe { dc_contact_model_reach(&jkr, 1e-3, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
}
