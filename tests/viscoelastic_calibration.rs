//! Physical units, calibration and inverse, checked against an independent integration of the
//! physical equation of motion (the crate's Dormand–Prince reference, in SI units, not the
//! regularised Taylor integrator), and round trips.
//! Run: `cargo test --release --test viscoelastic_calibration -- --nocapture`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use demcontact::EndCriterion::{self, Force, Overlap};
use demcontact::Error;
use demcontact::numerics::ode::{Tolerance, integrate_to_event};
use demcontact::viscoelastic::{calibration, full_range::e_full, scaling};

/// m ξ'' = −ρ ξ^{3/2} − (3/2) A ρ √ξ ξ' in SI units, DP5(4) at rtol 1e-13, two phases.
fn collide_physical(rho: f64, a: f64, m: f64, v: f64, c: EndCriterion) -> f64 {
    let rhs = move |y: [f64; 2]| {
        let s = y[0].abs().sqrt();
        let f = rho * y[0] * s + 1.5 * a * rho * s * y[1];
        [y[1], -f / m]
    };
    let xs = (v * v * m / rho).powf(0.4);
    let tol = Tolerance {
        rtol: 1e-13,
        atol: [1e-16 * xs, 1e-16 * v],
    };
    let load = integrate_to_event(
        rhs,
        0.0,
        [0.0, v],
        |y| y[1],
        |_, _| {},
        &tol,
        1e-9 * xs / v,
        50_000_000,
    )
    .unwrap();
    let ev = move |y: [f64; 2]| match c {
        Overlap => y[0],
        Force => y[0] + 1.5 * a * y[1], // F/(ρ√ξ) = ξ + (3/2)A ξ'
    };
    let end = integrate_to_event(
        rhs,
        load.t,
        load.y,
        ev,
        |_, _| {},
        &tol,
        1e-3 * load.t,
        50_000_000,
    )
    .unwrap();
    -end.y[1] / v
}

#[test]
fn physical_units_match_direct_integration() {
    // Rubber-like and steel-like pairs at several speeds.
    let mut worst: f64 = 0.0;
    for &(rho, a, m) in &[(2.0e6, 1e-3, 0.01), (5.0e9, 2e-7, 0.05)] {
        for &v in &[0.01, 0.3, 1.0, 5.0] {
            let (k, g) = scaling::k_gamma_from_material(rho, a, m).unwrap();
            for c in [Force, Overlap] {
                let e = calibration::e_of_speed(k, g, v, c).unwrap();
                let r = collide_physical(rho, a, m, v, c);
                let b = scaling::b_from_beta_speed(scaling::beta_from_k_gamma(k, g).unwrap(), v)
                    .unwrap();
                let rel = ((e - r) / r).abs();
                println!(
                    "rho={rho:e} A={a:e} m={m} v={v} b={b:.4} {c:?}: e={e:.12} direct {r:.12} rel {rel:.1e}"
                );
                worst = worst.max(rel);
            }
        }
    }
    println!("worst relative difference to the SI-unit DP5 integration: {worst:.1e}");
    assert!(worst < 1e-9);
}

#[test]
fn calibration_round_trips() {
    let mut worst: f64 = 0.0;
    for c in [Force, Overlap] {
        for i in 0..400 {
            let e = 10f64.powf(-14.0 * (i as f64 + 0.5) / 400.0); // 1e-14 … ~1
            let b = calibration::b_from_e(e, c).unwrap();
            let back = e_full(b, c).unwrap();
            worst = worst.max(((back - e) / e).abs());
        }
        // Exactly representable b values (b = 1 is s = ln b = 0 in the iteration) and e near 1.
        for &b in &[0.05, 0.3, 1.0, 2.0, 4.0, 8.0, 1024.0] {
            let e = e_full(b, c).unwrap();
            let back = calibration::b_from_e(e, c).unwrap();
            assert!((back / b - 1.0).abs() < 1e-12, "{c:?} b={b} back={back}");
        }
        for &e in &[1.0 - 1e-12, 0.999999, 0.99, 0.9, 0.8] {
            let b = calibration::b_from_e(e, c).unwrap();
            let back = e_full(b, c).unwrap();
            worst = worst.max(((back - e) / e).abs());
        }
    }
    println!("round trip e -> b -> e, e in [1e-14, 1): worst {worst:.1e}");
    assert!(worst < 1e-12);
    // The paper's example (Sec. VI): e = 0.8 at v = 1 m/s gives β ≈ 0.2 (force criterion).
    let beta = calibration::beta_from_e(0.8, 1.0, Force).unwrap();
    println!("paper example: e = 0.8 at 1 m/s -> beta = {beta:.6} (paper: 0.2)");
    assert!((beta - 0.2).abs() < 0.01);
    // Speed at which e falls to 0.5 for that material, and consistency with e(v).
    let v = calibration::speed_for_e(0.5, beta, Force).unwrap();
    let e_back = e_full(scaling::b_from_beta_speed(beta, v).unwrap(), Force).unwrap();
    println!("speed for e = 0.5: {v:.6} m/s (e there {e_back:.14})");
    assert!((e_back - 0.5).abs() < 1e-12);
    // A for a material: reproduces β.
    let (rho, m) = (2.0e6, 0.01);
    let a = calibration::a_from_e(0.8, 1.0, rho, m, Force).unwrap();
    let (k, g) = scaling::k_gamma_from_material(rho, a, m).unwrap();
    assert!((scaling::beta_from_k_gamma(k, g).unwrap() / beta - 1.0).abs() < 1e-14);
}

#[test]
fn bad_input_is_reported() {
    for c in [Force, Overlap] {
        assert_eq!(calibration::b_from_e(0.0, c), Err(Error::RestitutionRange));
        assert_eq!(calibration::b_from_e(1.5, c), Err(Error::RestitutionRange));
        assert_eq!(calibration::b_from_e(f64::NAN, c), Err(Error::NotFinite));
        assert_eq!(
            calibration::beta_from_e(0.5, 0.0, c),
            Err(Error::NotPositive)
        );
        assert_eq!(
            calibration::beta_from_e(0.5, -1.0, c),
            Err(Error::NotPositive)
        );
        assert_eq!(
            calibration::speed_for_e(0.5, 0.0, c),
            Err(Error::NotPositive)
        );
        assert_eq!(
            calibration::speed_for_e(0.5, f64::INFINITY, c),
            Err(Error::NotFinite)
        );
        assert_eq!(
            calibration::e_of_speed(-1.0, 1.0, 1.0, c),
            Err(Error::NotPositive)
        );
        assert_eq!(
            calibration::e_of_speed(1.0, -1.0, 1.0, c),
            Err(Error::Negative)
        );
        assert_eq!(
            calibration::e_of_speed(1.0, 1.0, f64::NAN, c),
            Err(Error::NotFinite)
        );
        assert_eq!(e_full(-1e-300, c), Err(Error::Negative));
        assert_eq!(e_full(f64::NAN, c), Err(Error::NotFinite));
        assert_eq!(e_full(f64::INFINITY, c), Err(Error::NotFinite));
        assert_eq!(calibration::speed_for_e(1.0, 0.3, c), Ok(0.0));
        assert_eq!(calibration::b_from_e(1.0, c), Ok(0.0));
    }
    // Very small e: b grows like e^{-3/5} (force) or e^{-1/5} (overlap), finite down to 5e-324.
    assert!(calibration::b_from_e(5e-324, Force).unwrap().is_finite());
    assert!(calibration::b_from_e(5e-324, Overlap).unwrap().is_finite());
}
