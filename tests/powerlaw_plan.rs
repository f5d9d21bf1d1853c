//! The duration plan (dc_duration_plan_init + dc_contact_duration_planned): same results as the
//! unplanned dc_contact_duration, and the same statuses, plus its own (NULL plan, bad plan).
//! The unplanned function is itself checked against the ODE reference (tests/powerlaw_vs_ode.rs);
//! here the two independent quadratures (Clenshaw–Curtis with 25 nodes vs Gauss–Jacobi) must agree.

use demcontact::ffi::{calibration::*, powerlaw::*, status::*};

const PS: [f64; 6] = [1.0, 1.25, 1.5, 2.0, 3.0, 5.0];
const ES: [f64; 12] = [
    0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.9, 0.99, 0.995, 0.999,
];

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn plan(p: f64, level: i32) -> dc_duration_plan {
    let mut pl = dc_duration_plan::default();
    assert_eq!(
        unsafe { dc_duration_plan_init(p, level, &mut pl) },
        DC_OK,
        "p={p} level={level}"
    );
    pl
}

/// All (α, criterion) cases of one p: both calibrations over ES, and ζ ∈ {1, 1.5, 4, 30} (force end).
fn cases(p: f64) -> Vec<(f64, i32)> {
    let mut out = Vec::new();
    for &e in &ES {
        for crit in [DC_END_OVERLAP, DC_END_FORCE] {
            let mut a = 0.0;
            assert_eq!(unsafe { dc_alpha_from_e(e, p, crit, &mut a) }, DC_OK);
            out.push((a, crit));
        }
    }
    let s = (2.0 * (p + 1.0)).sqrt();
    for z in [0.0, 1.0, 1.0 + 1e-9, 1.5, 4.0, 30.0, 1e4] {
        out.push((z * s, DC_END_FORCE));
    }
    out
}

/// Worst relative difference planned (at `level`) vs dc_contact_duration (default level).
fn worst_vs_unplanned(level: i32) -> f64 {
    let mut worst: f64 = 0.0;
    for &p in &PS {
        let pl = plan(p, level);
        for (alpha, crit) in cases(p) {
            for &(v0, w0) in &[(1.0, 1.0), (0.4, 30.0), (3e-3, 2e4)] {
                let (mut a, mut b) = (-1.0, -2.0);
                let sa = unsafe { dc_contact_duration(p, alpha, v0, w0, crit, &mut a) };
                let sb = unsafe { dc_contact_duration_planned(&pl, alpha, v0, w0, crit, &mut b) };
                assert_eq!(sa, sb, "p={p} α={alpha} crit={crit}");
                if sa == DC_OK {
                    worst = worst.max(rel(b, a));
                }
            }
        }
    }
    worst
}

#[test]
fn planned_equals_unplanned() {
    // Bound per plan level, quoted in docs/powerlaw.md and scripts/bench_powerlaw_ratios.sh
    // (measured 3.6e-8, 8.7e-10, 2.1e-11, 1.3e-14, 1.0e-15).
    const BOUND: [f64; 5] = [1e-7, 2e-9, 5e-11, 1e-13, 1e-13];
    let mut w = [0.0; 5];
    for (lv, x) in w.iter_mut().enumerate() {
        *x = worst_vs_unplanned(lv as i32);
        println!("plan level {lv}: worst relative difference from dc_contact_duration {x:.1e}");
    }
    for (lv, (x, b)) in w.iter().zip(BOUND).enumerate() {
        assert!(
            *x <= b,
            "plan level {lv}: {x:.1e} above its bound {b:.0e} ({w:?})"
        );
    }
}

#[test]
fn plan_statuses() {
    let mut pl = dc_duration_plan::default();
    // Init: bad p, bad level, NULL; output untouched on error.
    for (p, lv, want) in [
        (f64::NAN, 2, DC_ERR_NOT_FINITE),
        (f64::INFINITY, 2, DC_ERR_NOT_FINITE),
        (0.5, 2, DC_ERR_EXPONENT_RANGE),
        (1.5, -1, DC_ERR_LEVEL),
        (1.5, 5, DC_ERR_LEVEL),
    ] {
        assert_eq!(
            unsafe { dc_duration_plan_init(p, lv, &mut pl) },
            want,
            "p={p} lv={lv}"
        );
        assert_eq!(pl, dc_duration_plan::default());
    }
    assert_eq!(
        unsafe { dc_duration_plan_init(1.5, 2, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
    // Planned call: NULL plan / output, zero-filled or modified plan, and the input statuses of
    // dc_contact_duration (same codes as the unplanned call, output untouched).
    let mut tau = -1.0;
    let zero = dc_duration_plan::default();
    assert_eq!(
        unsafe {
            dc_contact_duration_planned(std::ptr::null(), 0.3, 1.0, 1.0, DC_END_FORCE, &mut tau)
        },
        DC_ERR_NULL_POINTER
    );
    let good = plan(1.5, 2);
    assert_eq!(
        unsafe {
            dc_contact_duration_planned(&good, 0.3, 1.0, 1.0, DC_END_FORCE, std::ptr::null_mut())
        },
        DC_ERR_NULL_POINTER
    );
    assert_eq!(
        unsafe { dc_contact_duration_planned(&zero, 0.3, 1.0, 1.0, DC_END_FORCE, &mut tau) },
        DC_ERR_PLAN
    );
    for edit in 0..4 {
        let mut bad = good;
        match edit {
            0 => bad.tag ^= 1,
            1 => bad.level = 3,
            2 => bad.p = 2.0,
            _ => bad.n = 16,
        }
        assert_eq!(
            unsafe { dc_contact_duration_planned(&bad, 0.3, 1.0, 1.0, DC_END_FORCE, &mut tau) },
            DC_ERR_PLAN,
            "edit {edit}"
        );
    }
    assert_eq!(tau, -1.0);
    for (alpha, v0, w0, crit) in [
        (f64::NAN, 1.0, 1.0, DC_END_FORCE),
        (0.3, f64::INFINITY, 1.0, DC_END_FORCE),
        (0.3, 0.0, 1.0, DC_END_FORCE),
        (0.3, 1.0, -1.0, DC_END_FORCE),
        (-0.1, 1.0, 1.0, DC_END_FORCE),
        (0.3, 1.0, 1.0, 7),
        (10.0, 1.0, 1.0, DC_END_OVERLAP),
    ] {
        let mut want_tau = -1.0;
        let want = unsafe { dc_contact_duration(1.5, alpha, v0, w0, crit, &mut want_tau) };
        assert_ne!(want, DC_OK);
        assert_eq!(
            unsafe { dc_contact_duration_planned(&good, alpha, v0, w0, crit, &mut tau) },
            want
        );
        assert_eq!(tau, -1.0);
    }
    let mut s = 0.0;
    assert_eq!(
        unsafe { dc_contact_duration_planned(&good, 0.3, 1.0, 1.0, DC_END_FORCE, &mut s) },
        DC_OK
    );
    assert!(s > 0.0);
}
