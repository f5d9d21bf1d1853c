//! The Coulomb limits with adhesion (docs/force.md, "Friction with adhesion") through the C ABI
//! (`dc_contact_spec` → `dc_contact_model` → `dc_contact_force`, and `dc_contact_force_batch`
//! bit for bit): a 10 µm silica-like sphere held on a rigid wall at a fixed overlap, its
//! tangential displacement (or its rolling and twisting angles) ramped step by step, must slide
//! at exactly μ F_c (μ_r R* F_c, μ_tw F_c) with the critical load F_c = |F_n + 2 F_po| of an
//! adhesive law (DMT: F_po = 2π w R*; JKR: F_po = (3/2) π w R*) and F_c = |F_n| of Hertz. Every
//! reference value (F_n from the textbook DMT force and the JKR contact-radius relations, F_po,
//! the Hertz value) is written here, not taken from the library. The overlaps include the
//! zero-net-load point of each law, where the limit on |F_n| alone would let the contact slide
//! at once.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;
use std::f64::consts::PI;

const E: f64 = 7.0e10;
const NU: f64 = 0.25;
const R: f64 = 1.0e-5;
const RHO: f64 = 2500.0;
const W: f64 = 0.2;
const MU: f64 = 0.3;
const DT: f64 = 1e-9;
/// Tolerance of a limit against its reference: 1e-12 of μ F_po (the library's F_n at a given
/// overlap agrees with the textbook force to ~1e-15 F_po; the JKR branch solve is well
/// conditioned away from δ_c).
const TOL: f64 = 1e-12;

fn e_star() -> f64 {
    E / (1.0 - NU * NU)
}

fn mass() -> f64 {
    RHO * 4.0 / 3.0 * PI * R.powi(3)
}

/// The pull-off force F_po of the law [N] (0 for Hertz).
fn pull_off(normal: i32) -> f64 {
    match normal {
        DC_NORMAL_DMT => 2.0 * PI * W * R,
        DC_NORMAL_JKR => 1.5 * PI * W * R,
        _ => 0.0,
    }
}

/// Textbook DMT force at δ > 0 (undamped): Hertz minus 2π w R*.
fn dmt_force(d: f64) -> f64 {
    4.0 / 3.0 * e_star() * R.sqrt() * d.powf(1.5) - 2.0 * PI * W * R
}

/// Textbook JKR (δ, F) at contact radius a: δ = a²/R* − √(2π w a/E*),
/// F = 4E* a³/(3R*) − √(8π w E* a³).
fn jkr_at(a: f64) -> (f64, f64) {
    let es = e_star();
    let d = a * a / R - (2.0 * PI * W * a / es).sqrt();
    let f = 4.0 * es * a.powi(3) / (3.0 * R) - (8.0 * PI * W * es * a.powi(3)).sqrt();
    (d, f)
}

/// The cases: (law, overlap δ > 0, textbook F_n at δ), zero net load among them.
fn cases() -> Vec<(i32, f64, f64)> {
    let es = e_star();
    // DMT: F_n = 0 where the Hertz force equals 2π w R*: δ = (3π w √R*/(2E*))^{2/3}.
    let d0 = (3.0 * PI * W * R.sqrt() / (2.0 * es)).powf(2.0 / 3.0);
    // JKR: F = 0 at a³ = 9π w R*²/(2E*); a₀³ = 2π w R*²/E* is δ = 0 (F = −(4/3)π w R*).
    let a_zero = (4.5 * PI * W * R * R / es).cbrt();
    let a0 = (2.0 * PI * W * R * R / es).cbrt();
    let mut out = Vec::new();
    for d in [d0, 0.05 * d0, 3.0 * d0] {
        out.push((DC_NORMAL_DMT, d, dmt_force(d)));
    }
    for a in [a_zero, 1.02 * a0, 2.0 * a_zero] {
        let (d, f) = jkr_at(a);
        assert!(d > 0.0);
        out.push((DC_NORMAL_JKR, d, f));
    }
    out
}

fn adhesive_model(normal: i32, f: impl FnOnce(&mut dc_contact_spec)) -> dc_contact_model {
    model(|s| {
        s.normal = normal;
        s.E1 = E;
        s.nu1 = NU;
        s.E2 = f64::INFINITY;
        s.nu2 = 0.3;
        s.work_of_adhesion = W;
        s.criterion = DC_END_OVERLAP;
        f(s);
    })
}

fn wall_state(d: f64, v: [f64; 3], w: [f64; 3]) -> dc_contact_state {
    dc_contact_state {
        n: [0.0, 1.0, 0.0],
        overlap: d,
        v1: v,
        v2: [0.0; 3],
        w1: w,
        w2: [0.0; 3],
        r1: R,
        r2: f64::INFINITY,
        m1: mass(),
        m2: f64::INFINITY,
    }
}

/// One step through dc_contact_force and, on a second history, dc_contact_force_batch (n = 1):
/// the same bits, returned once.
fn step2(
    m: &dc_contact_model,
    st: &dc_contact_state,
    hs: &mut [f64; DC_CONTACT_HISTORY_MAX],
    hb: &mut [f64; DC_CONTACT_HISTORY_MAX],
) -> dc_contact_result {
    let mut r = ZERO_RESULT;
    let s = unsafe { dc_contact_force(m, st, DT, hs.as_mut_ptr(), hs.len(), &mut r) };
    assert_eq!(s, DC_OK);
    let (mut f_n, mut force, mut t1, mut t2) = (0.0, [0.0; 3], [0.0; 3], [0.0; 3]);
    let b = dc_contact_batch {
        n: 1,
        history_stride: DC_CONTACT_HISTORY_MAX,
        normal: st.n.as_ptr(),
        overlap: &st.overlap,
        v1: st.v1.as_ptr(),
        v2: st.v2.as_ptr(),
        w1: st.w1.as_ptr(),
        w2: st.w2.as_ptr(),
        r1: &st.r1,
        r2: &st.r2,
        m1: &st.m1,
        m2: &st.m2,
        history: hb.as_mut_ptr(),
        f_n: &mut f_n,
        force: force.as_mut_ptr(),
        torque1: t1.as_mut_ptr(),
        torque2: t2.as_mut_ptr(),
    };
    assert_eq!(unsafe { dc_contact_force_batch(m, &b, DT) }, DC_OK);
    assert_eq!(f_n.to_bits(), r.f_n.to_bits());
    for k in 0..3 {
        assert_eq!(force[k].to_bits(), r.force[k].to_bits());
        assert_eq!(t1[k].to_bits(), r.torque1[k].to_bits());
        assert_eq!(t2[k].to_bits(), r.torque2[k].to_bits());
    }
    assert!(
        hs.iter()
            .zip(hb.iter())
            .all(|(a, b)| a.to_bits() == b.to_bits())
    );
    r
}

/// 8 G* √(R* δ) of Mindlin against a rigid wall: 1/G* = (2 − ν)/G, G = E/(2(1 + ν)).
fn mindlin_kt(d: f64) -> f64 {
    let g = E / (2.0 * (1.0 + NU));
    8.0 * g / (2.0 - NU) * (R * d).sqrt()
}

/// Ramps the tangential displacement at overlap d (no dashpot: e_t = 1) until the contact
/// slides; returns (|F_t| at the first sliding step and 10 steps on, F_n, the number of
/// sticking steps, the displacement per step). Checks that it sticks below the limit first.
fn ramp(normal: i32, tangential: i32, d: f64, limit_ref: f64) -> ([f64; 2], f64, usize, f64) {
    let kt_lin = 1.0e4;
    let m = adhesive_model(normal, |s| {
        s.tangential = tangential;
        s.mu = MU;
        s.k_t = kt_lin;
        s.e_t = 1.0;
    });
    let kt = if tangential == DC_TANGENTIAL_LINEAR {
        kt_lin
    } else {
        mindlin_kt(d)
    };
    // About 500 sticking steps.
    let v = limit_ref / kt / DT / 500.37;
    let st = wall_state(d, [v, 0.0, 0.0], [0.0; 3]);
    let (mut hs, mut hb) = ([0.0; DC_CONTACT_HISTORY_MAX], [0.0; DC_CONTACT_HISTORY_MAX]);
    let mut sticking = 0;
    let mut f_n = f64::NAN;
    let mut at = [f64::NAN; 2];
    for i in 1..=2000usize {
        let r = step2(&m, &st, &mut hs, &mut hb);
        f_n = r.f_n;
        let ft = norm(r.ft);
        if r.sliding == 0 {
            assert!(at[0].is_nan(), "sticks again after sliding at step {i}");
            assert!(
                ft <= limit_ref * (1.0 + TOL),
                "{ft} above the limit {limit_ref}"
            );
            if tangential == DC_TANGENTIAL_LINEAR {
                let want = kt * (i as f64) * v * DT;
                assert!((ft - want).abs() <= 1e-12 * want, "{ft} vs k_t xi {want}");
            }
            sticking = i;
        } else if at[0].is_nan() {
            at[0] = ft;
        } else if i == sticking + 11 {
            at[1] = ft;
            break;
        }
    }
    (at, f_n, sticking, v * DT)
}

#[test]
fn adhesive_contacts_slide_at_mu_times_the_adhesion_corrected_load() {
    let mut zero_load = 0;
    for (normal, d, f_ref) in cases() {
        let po = pull_off(normal);
        let load = (f_ref + 2.0 * po).abs();
        let limit = MU * load;
        for tangential in [
            DC_TANGENTIAL_LINEAR,
            DC_TANGENTIAL_MINDLIN,
            DC_TANGENTIAL_MINDLIN_RESCALE,
        ] {
            let (at, f_n, sticking, step) = ramp(normal, tangential, d, limit);
            let tag = format!("law {normal} tangential {tangential} d {d:e}");
            assert!(
                (f_n - f_ref).abs() <= 1e-13 * po,
                "{tag}: F_n {f_n} vs textbook {f_ref}"
            );
            for ft in at {
                assert!(
                    (ft - limit).abs() <= TOL * MU * po,
                    "{tag}: slides at {ft}, want mu |F_n + 2 F_po| = {limit}"
                );
            }
            // It stuck up to the limit: ~500 steps (the threshold crossed within one step).
            if tangential == DC_TANGENTIAL_LINEAR {
                let n_ref = limit / 1.0e4 / step;
                assert!(
                    (sticking as f64 - n_ref.floor()).abs() <= 1.0,
                    "{tag}: stuck {sticking} steps, threshold at {n_ref}"
                );
            } else {
                assert!(sticking > 100, "{tag}: stuck only {sticking} steps");
            }
            // At zero net load the limit on |F_n| alone is ~0 (this test tells them apart).
            if f_ref.abs() < 1e-9 * po {
                assert!(load - f_n.abs() > 1.9 * po, "{tag}");
                zero_load += 1;
            }
        }
    }
    // Both laws' zero-load overlaps, each with the three tangential laws.
    assert_eq!(zero_load, 6);
}

#[test]
fn rolling_and_twisting_limits_use_the_adhesion_corrected_load() {
    let (mu_r, mu_tw, k_r, k_tw) = (0.1, 2.0e-6, 1.0e-5, 1.0e-5);
    for (normal, d, f_ref) in cases() {
        let load = (f_ref + 2.0 * pull_off(normal)).abs();
        for rolling in [DC_ROLLING_CONSTANT, DC_ROLLING_EPSD] {
            let m = adhesive_model(normal, |s| {
                s.rolling = rolling;
                s.mu_r = mu_r;
                s.k_r = k_r;
                s.eta_r = 0.3;
                s.twisting = DC_TWISTING_SDS;
                s.mu_tw = mu_tw;
                s.k_tw = k_tw;
                s.eta_tw = 0.3;
            });
            let (roll_lim, twist_lim) = (mu_r * R * load, mu_tw * load);
            // Both springs reach their limit after ~100 steps (n = +y: rolling about z,
            // twisting about y).
            let w_roll = roll_lim / k_r / DT / 100.3;
            let w_tw = twist_lim / k_tw / DT / 100.3;
            let st = wall_state(d, [0.0; 3], [0.0, w_tw, w_roll]);
            let (mut hs, mut hb) = ([0.0; DC_CONTACT_HISTORY_MAX], [0.0; DC_CONTACT_HISTORY_MAX]);
            let mut r = ZERO_RESULT;
            for _ in 0..300 {
                r = step2(&m, &st, &mut hs, &mut hb);
            }
            let tag = format!("law {normal} rolling {rolling} d {d:e}");
            assert_eq!(r.rolling_sliding, 1, "{tag}");
            let po = pull_off(normal);
            // The rolling torque lies in the tangent plane (x, z: the spring is carried with
            // the spin about n), the twisting torque along n (y).
            let [mx, my, mz] = r.torque1;
            let (mz, my) = ((mx * mx + mz * mz).sqrt(), my.abs());
            assert!(
                (mz - roll_lim).abs() <= TOL * mu_r * R * po,
                "{tag}: rolling {mz} vs mu_r R* F_c {roll_lim}"
            );
            assert!(
                (my - twist_lim).abs() <= TOL * mu_tw * po,
                "{tag}: twisting {my} vs mu_tw F_c {twist_lim}"
            );
        }
    }
}

/// A law without adhesion keeps μ|F_n|: Hertz at δ = 1e-8 m slides at
/// μ (4/3) E* √R* δ^{3/2} = 9.444669278369560e-5 N (μ = 0.3; 40-digit evaluation of the
/// formula, written here), the value of the limit before adhesion changed anything.
#[test]
fn hertz_slides_at_mu_times_its_normal_force() {
    let d: f64 = 1.0e-8;
    let hard = 9.444_669_278_369_560e-5;
    let formula = MU * 4.0 / 3.0 * e_star() * R.sqrt() * d.powf(1.5);
    assert!((formula - hard).abs() <= 1e-15 * hard);
    for tangential in [
        DC_TANGENTIAL_LINEAR,
        DC_TANGENTIAL_MINDLIN,
        DC_TANGENTIAL_MINDLIN_RESCALE,
    ] {
        let (at, f_n, sticking, _) = ramp(DC_NORMAL_HERTZ, tangential, d, hard);
        assert!((MU * f_n - hard).abs() <= 1e-14 * hard, "F_n {f_n}");
        for ft in at {
            assert!(
                (ft - hard).abs() <= 1e-14 * hard,
                "slides at {ft}, want {hard}"
            );
            // μ|F_n| of the library's own F_n to the rounding of the scaling (bits before).
            assert!((ft - MU * f_n.abs()).abs() <= 4.0 * f64::EPSILON * ft);
        }
        assert!(sticking > 100);
    }
}

/// EPSD rolling with Ai's stiffness rule (k_r = 0: k_r = 2.25 k_n μ_r² R*², k_n = p F/δ) on an
/// adhesive law: where the neck pulls (F_n < 0 at δ > 0) p F/δ is negative, and a negative
/// spring would drive the rolling it should resist (with η_r > 0 its dashpot would be NaN).
/// The library takes k_n = 0 there (docs/force.md, JKR): no rolling torque while F_n < 0, a
/// resisting one once the load is compressive. Through the C ABI, scalar and batch bit for bit.
#[test]
fn epsd_by_ais_rule_never_drives_rolling_where_the_neck_pulls() {
    for (normal, d, f_ref) in cases() {
        for eta_r in [0.0, 0.3] {
            let m = adhesive_model(normal, |s| {
                s.rolling = DC_ROLLING_EPSD;
                s.mu_r = 0.1;
                s.k_r = 0.0;
                s.eta_r = eta_r;
            });
            let w_roll = 10.0;
            let st = wall_state(d, [0.0; 3], [0.0, 0.0, w_roll]);
            let (mut hs, mut hb) = ([0.0; DC_CONTACT_HISTORY_MAX], [0.0; DC_CONTACT_HISTORY_MAX]);
            let tag = format!("law {normal} eta_r {eta_r} d {d:e} F_n {f_ref:e}");
            for step in 0..50 {
                let r = step2(&m, &st, &mut hs, &mut hb);
                let t = r.torque1;
                assert!(t.iter().all(|x| x.is_finite()), "{tag} step {step}: {t:?}");
                // The rolling torque's work rate on body 1 (spin about z).
                let power = t[2] * w_roll;
                if f_ref < 0.0 {
                    assert_eq!(
                        t, [0.0; 3],
                        "{tag} step {step}: torque where the neck pulls"
                    );
                } else if f_ref > 1e-3 * pull_off(normal) {
                    assert!(
                        power < 0.0,
                        "{tag} step {step}: torque {t:?} does not resist"
                    );
                } else {
                    assert!(
                        power <= 0.0,
                        "{tag} step {step}: torque {t:?} drives rolling"
                    );
                }
            }
        }
    }
}
