//! The paper's eq. (12): the linear spring-dashpot under the force-zero criterion, piecewise in
//! β_p = γ/(2m) against ω0 = √(k/m). The crate has ONE formula for it, `lsd::e_force(ζ)` with
//! ζ = β_p/ω0 (exported as `dc_e_from_alpha(alpha = 2ζ, p = 1, DC_END_FORCE)`); here it is checked
//! against eq. (12) as printed, and against a direct integration.
//! Run: `cargo test --release --test viscoelastic_lsd_eq12 -- --nocapture`.
#![allow(clippy::unwrap_used)]

use demcontact::ffi::{calibration::dc_e_from_alpha, status::*};
use demcontact::lsd::e_force;
use demcontact::numerics::ode::{Tolerance, integrate_to_event};

/// Eq. (12) with its middle branch as printed: exp(−(β/ω) arctan(2βω/(ω² − β²))).
fn eq12_printed(beta: f64, w0: f64) -> f64 {
    if beta < w0 / 2f64.sqrt() {
        let w = (w0 * w0 - beta * beta).sqrt();
        (-(beta / w) * (std::f64::consts::PI - (2.0 * beta * w / (w * w - beta * beta)).atan()))
            .exp()
    } else if beta < w0 {
        let w = (w0 * w0 - beta * beta).sqrt();
        (-(beta / w) * (2.0 * beta * w / (w * w - beta * beta)).atan()).exp()
    } else {
        let w = (beta * beta - w0 * w0).sqrt(); // ω_n continued: √(β² − ω0²)
        (-(beta / w) * ((beta + w) / (beta - w)).ln()).exp()
    }
}

/// The middle branch corrected: arctan of a negative argument is 2γ − π; the exponent must be
/// +(β/ω) arctan(…) (equivalently −(β/ω)(π + arctan(…) − π) … = −(β/ω)·2 arccos ζ).
fn eq12_corrected(beta: f64, w0: f64) -> f64 {
    if beta >= w0 / 2f64.sqrt() && beta < w0 {
        let w = (w0 * w0 - beta * beta).sqrt();
        ((beta / w) * (2.0 * beta * w / (w * w - beta * beta)).atan()).exp()
    } else {
        eq12_printed(beta, w0)
    }
}

fn e_direct(zeta: f64) -> f64 {
    // x'' + 2ζx' + x = 0, ends when x + 2ζ x' = 0 while unloading.
    let tol = Tolerance {
        rtol: 1e-13,
        atol: [1e-16, 1e-16],
    };
    let f = move |y: [f64; 2]| [y[1], -y[0] - 2.0 * zeta * y[1]];
    let l = integrate_to_event(
        f,
        0.0,
        [0.0, 1.0],
        |y| y[1],
        |_, _| {},
        &tol,
        1e-4,
        10_000_000,
    )
    .unwrap();
    let e = integrate_to_event(
        f,
        l.t,
        l.y,
        |y| y[0] + 2.0 * zeta * y[1],
        |_, _| {},
        &tol,
        1e-4,
        10_000_000,
    )
    .unwrap();
    -e.y[1]
}

#[test]
fn eq12_matches_the_single_formula() {
    let w0 = 3.0;
    let (mut worst_lo, mut worst_mid_printed, mut worst_mid, mut worst_hi, mut worst_direct) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for i in 1..400 {
        let zeta = 2.5 * i as f64 / 400.0;
        if (zeta - 1.0).abs() < 1e-9 || (zeta - 0.5f64.sqrt()).abs() < 1e-9 {
            continue;
        }
        let ours = e_force(zeta);
        let mut viac = 0.0;
        assert_eq!(
            unsafe { dc_e_from_alpha(2.0 * zeta, 1.0, DC_END_FORCE, &mut viac) },
            DC_OK
        );
        assert!(((viac - ours) / ours).abs() < 1e-14, "{zeta} {viac} {ours}");
        let printed = eq12_printed(zeta * w0, w0);
        let corrected = eq12_corrected(zeta * w0, w0);
        let rel_c = ((corrected - ours) / ours).abs();
        let rel_p = ((printed - ours) / ours).abs();
        if zeta < 0.5f64.sqrt() {
            worst_lo = worst_lo.max(rel_p);
        } else if zeta < 1.0 {
            worst_mid_printed = worst_mid_printed.max(rel_p);
            worst_mid = worst_mid.max(rel_c);
        } else {
            worst_hi = worst_hi.max(rel_p);
        }
        if i % 20 == 0 {
            worst_direct = worst_direct.max(((e_direct(zeta) - ours) / ours).abs());
        }
    }
    println!(
        "eq. 12 vs lsd::e_force: branch 1 {worst_lo:.1e}; branch 2 as printed {worst_mid_printed:.1e} (e > 1: sign lost), corrected {worst_mid:.1e}; branch 3 {worst_hi:.1e}; direct ODE {worst_direct:.1e}"
    );
    assert!(worst_lo < 1e-13 && worst_mid < 1e-13 && worst_hi < 1e-13 && worst_direct < 1e-10);
    assert!(
        worst_mid_printed > 0.1,
        "the printed middle branch is wrong"
    );
}
