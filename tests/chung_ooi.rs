//! Chung & Ooi (2011) benchmark tests: the independent reference (tests/common/oblique.rs)
//! checked against the closed forms and limits derived in docs/benchmarks.md, against the
//! library's normal-damping calibration, and the committed reference table
//! (c_tests/data/chung_ooi_ref.csv, read by c_tests/test_chung_ooi.c) checked fresh.
//! Tolerances are stated per check; the reference runs at rtol 1e-11..1e-12.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

#[path = "common/oblique.rs"]
mod oblique;
use demcontact::EndCriterion;
use oblique::*;

const R4: f64 = 0.0025;
const V4: f64 = 3.9;
const MU: f64 = 0.092;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// Tests 1 and 2 (elastic, normal): the reference's peak overlap, peak force and duration equal
/// Hertz's closed forms (δ_m = (15 m* v²/(16 E* √R*))^(2/5), F_m = (4/3) E* √R* δ_m^(3/2),
/// τ = (4/5) B(2/5, 1/2) δ_m / v) within 1e-9.
#[test]
fn elastic_normal_impacts_match_hertz() {
    // Test 1: two equal spheres R = 10 mm, each at 10 m/s (approach speed 20 m/s).
    // Test 2: sphere R = 0.1 m at 0.2 m/s onto a rigid wall.
    let cases = [
        (GLASS.pair_normal(0.010), 20.0),
        (LIMESTONE.pair_normal(0.010), 20.0),
        (
            AL_ALLOY_T2.on_wall(0.1, 0.0, 0.0, End::Overlap, TangentRule::Displacement),
            0.2,
        ),
        (
            MG_ALLOY.on_wall(0.1, 0.0, 0.0, End::Overlap, TangentRule::Displacement),
            0.2,
        ),
    ];
    for (sp, v) in cases {
        let o = collide(&sp, v, 0.0, 1e-12).unwrap();
        let (dm, fm, tau) = hertz_elastic(sp.m, sp.r, sp.e_star, v);
        for (what, got, want) in [
            ("delta_max", o.delta_max, dm),
            ("F at max", o.f_at_max, fm),
            ("F peak (sampled)", o.f_peak, fm),
            ("tau", o.tau, tau),
            ("e", o.e_n, 1.0),
        ] {
            // The sampled peak sees only accepted steps and events; the rest is exact.
            let tol = if what.starts_with("F peak") {
                1e-6
            } else {
                1e-9
            };
            assert!(
                rel(got, want) < tol,
                "{what}: reference {got:e}, Hertz {want:e} (v = {v})"
            );
        }
    }
}

/// The published orders of magnitude (Chung & Ooi Fig. 2/3, digitised by Kratos' benchmark
/// data): glass ≈ 10 kN at ≈ 270 μm, Al alloy ≈ 11 kN at ≈ 50 μm. Our closed forms must land
/// there (5 %), which catches a wrong material table or a factor in E*, R*, m*.
#[test]
fn closed_forms_land_on_the_published_curves() {
    let g = GLASS.pair_normal(0.010);
    let (dm, fm, _) = hertz_elastic(g.m, g.r, g.e_star, 20.0);
    assert!(
        rel(dm, 2.74e-4) < 0.05 && rel(fm, 10.7e3) < 0.05,
        "glass {dm:e} {fm:e}"
    );
    let a = AL_ALLOY_T2.on_wall(0.1, 0.0, 0.0, End::Overlap, TangentRule::Displacement);
    let (dm, fm, _) = hertz_elastic(a.m, a.r, a.e_star, 0.2);
    assert!(
        rel(dm, 4.97e-5) < 0.05 && rel(fm, 11.6e3) < 0.05,
        "Al {dm:e} {fm:e}"
    );
}

/// The reference calibrates its normal damping itself (shooting on its own integration); it
/// must agree with the library's closed-form calibration (an independent derivation) to 1e-9.
#[test]
fn own_damping_calibration_matches_library() {
    for (e, end, crit) in [
        (0.98, End::Force, EndCriterion::Force),
        (0.5, End::Force, EndCriterion::Force),
        (0.1, End::Force, EndCriterion::Force),
        (0.98, End::Overlap, EndCriterion::Overlap),
        (0.5, End::Overlap, EndCriterion::Overlap),
    ] {
        let ours = alpha_for_e(e, end, 1e-13).unwrap();
        let lib = demcontact::powerlaw::alpha_from_e(e, 1.5, crit).unwrap();
        assert!(rel(ours, lib) < 1e-9, "e = {e} {end:?}: {ours} vs {lib}");
    }
}

/// Gross sliding throughout (tan θ ≥ 7/2 μ (1 + e), contact starting in slip): the impulse ratio
/// is exactly μ, so e_t, ω R / v_n and the rebound angle equal the rigid-body closed forms.
/// Exact in the reference when the Coulomb limit uses the elastic force (no initial stick), the
/// lever is R, e = 1: 1e-9. With the library's conventions (damped limit ⇒ a short initial
/// stick; lever R − δ/2) the departure is measured and bounded: 1e-5 on e_t, 3e-3 on ω.
#[test]
fn gross_sliding_limit() {
    for rule in [TangentRule::Displacement, TangentRule::Incremental] {
        for mat in [AL2O3, AL_ALLOY_T4] {
            let mut sp = mat.on_wall(R4, 0.0, MU, End::Overlap, rule);
            sp.coulomb = CoulombOn::Elastic;
            sp.lever = Lever::Radius;
            let th_s = tan_theta_sliding(MU, 1.0).atan().to_degrees();
            for deg in [th_s + 0.5, 40.0, 55.0, 70.0, 85.0, 89.0] {
                let th = f64::to_radians(deg);
                let (vn, vt) = (V4 * th.cos(), V4 * th.sin());
                let o = collide(&sp, vn, vt, 1e-12).unwrap();
                assert!(o.started_sliding && o.switches == 0, "{deg}: {o:?}");
                let (et, wr, tr) = gross_sliding(MU, 1.0, th.tan());
                let reb = (o.u_out - R4 * o.w_out) / o.vn_out;
                assert!((o.u_out / vt - et).abs() < 1e-9, "{rule:?} {deg}: e_t");
                assert!(rel(o.w_out * R4 / vn, wr) < 1e-9, "{rule:?} {deg}: omega");
                assert!(rel(reb, tr) < 1e-9, "{rule:?} {deg}: rebound");
            }
            // The bound is sufficient, not necessary, for a compliant contact: just below it the
            // contact-point velocity reverses near the end while the shrinking limit keeps the
            // force on it. 10° below, the slip stops and the closed form fails (so the check
            // above can fail).
            let th = tan_theta_sliding(MU, 1.0).atan() - 10f64.to_radians();
            let o = collide(&sp, V4 * th.cos(), V4 * th.sin(), 1e-12).unwrap();
            let (et, _, _) = gross_sliding(MU, 1.0, th.tan());
            assert!(
                o.switches >= 1 && (o.u_out / (V4 * th.sin()) - et).abs() > 1e-3,
                "10° below the bound: {o:?}"
            );
        }
    }
    let alpha = alpha_for_e(0.98, End::Force, 1e-13).unwrap();
    for mat in [AL2O3, AL_ALLOY_T4] {
        let sp = library_spec(&mat, R4, alpha, MU);
        for deg in [35.0, 50.0, 70.0, 85.0] {
            let (e_n, e_t, omega, _) = outcome_row(&sp, V4, deg, 1e-12).unwrap();
            let th = f64::to_radians(deg);
            let (et, wr, _) = gross_sliding(MU, e_n, th.tan());
            assert!((e_t - et).abs() < 1e-5, "{deg}: e_t {e_t} vs {et}");
            assert!(rel(omega * R4 / (V4 * th.cos()), wr) < 3e-3, "{deg}: omega");
        }
    }
}

/// Coulomb bounds that hold at every angle (|f| ≤ μ F_n at all times, F_n ≥ 0 with the
/// force-zero end): 1 − e_t ≤ μ(1 + e_n)/tan θ and ω R ≤ 5/2 μ (1 + e_n) v_n.
#[test]
fn coulomb_bounds_every_angle() {
    let alpha = alpha_for_e(0.98, End::Force, 1e-13).unwrap();
    for mat in [AL2O3, AL_ALLOY_T4] {
        let sp = library_spec(&mat, R4, alpha, MU);
        for i in 1..=89 {
            let deg = f64::from(i);
            let (e_n, e_t, omega, _) = outcome_row(&sp, V4, deg, 1e-11).unwrap();
            let th = deg.to_radians();
            let p = MU * (1.0 + e_n);
            assert!(
                (1.0 - e_t) * th.tan() <= p * (1.0 + 1e-9),
                "{deg}: e_t {e_t}"
            );
            assert!(
                omega * R4 <= 2.5 * p * V4 * th.cos() * (1.0 + 1e-9),
                "{deg}"
            );
        }
    }
}

/// Initial slip (derived in docs/benchmarks.md): with an undamped Coulomb limit both |f| and
/// μF_n grow as t^{3/2}; the contact starts sliding iff tan θ > μ E*/(6 G*) for the total
/// displacement spring and μ E*/(4 G*) for the incremental one.
#[test]
fn initial_slip_threshold() {
    for (rule, c) in [
        (TangentRule::Displacement, 6.0),
        (TangentRule::Incremental, 4.0),
    ] {
        let mut sp = AL2O3.on_wall(R4, 0.0, MU, End::Overlap, rule);
        sp.coulomb = CoulombOn::Elastic;
        let th_c = (MU * sp.e_star / (c * sp.g_star)).atan();
        for (f, slides) in [(0.99, false), (1.01, true)] {
            let th = f * th_c;
            let o = collide(&sp, V4 * th.cos(), V4 * th.sin(), 1e-12).unwrap();
            assert_eq!(o.started_sliding, slides, "{rule:?} θ = {f}·θc");
        }
    }
}

/// No-slip limit (μ → ∞): the contact-point tangential velocity leaves with factor β0(K, α),
/// computed by the dimensionless Hill equation; the reference in physical units (lever R) must
/// agree to 1e-9 for both spring rules, undamped and damped. For the symmetric elastic normal
/// history both rules give the same β0 (equal diagonal of the monodromy matrix), and β0 > 1 for
/// Al2O3: the Mindlin spring with k_t ∝ √δ pumps energy, ΔE/E = (2/7)(β0² − 1) sin²θ.
#[test]
fn no_slip_limit() {
    let alpha = alpha_for_e(0.98, End::Force, 1e-13).unwrap();
    for rule in [TangentRule::Displacement, TangentRule::Incremental] {
        for (a, end) in [(0.0, End::Overlap), (alpha, End::Force)] {
            for mat in [AL2O3, AL_ALLOY_T4] {
                let mut sp = mat.on_wall(R4, a, f64::INFINITY, end, rule);
                sp.lever = Lever::Radius;
                for deg in [5.0, 45.0, 80.0] {
                    let th = f64::to_radians(deg);
                    let (vn, vt) = (V4 * th.cos(), V4 * th.sin());
                    let o = collide(&sp, vn, vt, 1e-12).unwrap();
                    let beta = (o.u_out - R4 * o.w_out) / vt;
                    let b0 = no_slip_beta(k_ratio(&sp, vn), a, end, rule, 1e-12);
                    assert!(
                        (beta - b0).abs() < 1e-9,
                        "{rule:?} {end:?} {deg}: {beta} {b0}"
                    );
                    // e_t = (5 + 2 β0)/7 and ω R = (5/7)(1 − β0) u_in for a solid sphere.
                    assert!((o.u_out / vt - (5.0 + 2.0 * b0) / 7.0).abs() < 1e-9);
                    assert!((o.w_out * R4 - 5.0 / 7.0 * (1.0 - b0) * vt).abs() < 1e-9 * vt);
                    if a == 0.0 {
                        let e_in = 0.5 * sp.m * V4 * V4;
                        let e_out = 0.5 * sp.m * (o.vn_out.powi(2) + o.u_out.powi(2))
                            + 0.5 * sp.inertia * o.w_out.powi(2);
                        let de = (2.0 / 7.0) * (b0 * b0 - 1.0) * th.sin().powi(2);
                        assert!(((e_out - e_in) / e_in - de).abs() < 1e-9, "energy {deg}");
                    }
                }
            }
        }
    }
    let b = |rule| {
        let sp = AL2O3.on_wall(R4, 0.0, f64::INFINITY, End::Overlap, rule);
        no_slip_beta(k_ratio(&sp, V4), 0.0, End::Overlap, rule, 1e-13)
    };
    let (bd, bi) = (b(TangentRule::Displacement), b(TangentRule::Incremental));
    assert!((bd - bi).abs() < 1e-10 && bd > 1.01, "β0 {bd} {bi}");
}

/// The reference converges: rtol 1e-9 and 1e-12 agree to 1e-7 on every test-4 output.
#[test]
fn reference_converges() {
    let alpha = alpha_for_e(0.98, End::Force, 1e-13).unwrap();
    for mat in [AL2O3, AL_ALLOY_T4] {
        let sp = library_spec(&mat, R4, alpha, MU);
        for deg in [5.0, 10.0, 20.0, 30.0, 60.0] {
            let a = outcome_row(&sp, V4, deg, 1e-9).unwrap();
            let b = outcome_row(&sp, V4, deg, 1e-12).unwrap();
            assert!((a.1 - b.1).abs() < 1e-7, "{deg} e_t");
            assert!((a.2 - b.2).abs() < 1e-7 * 700.0, "{deg} omega");
            assert!((a.3 - b.3).abs() < 1e-5, "{deg} rebound");
        }
    }
}

/// The committed table (read by the C test) equals a fresh computation: 1e-8 on e_n, e_t,
/// 1e-8 relative on ω, 1e-6 deg on the rebound angle. Regenerate with
/// `cargo run --release --example chung_ooi_reference`.
#[test]
fn committed_reference_table_is_fresh() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/c_tests/data/chung_ooi_ref.csv"
    );
    let text = std::fs::read_to_string(path).expect("read the committed table");
    let committed = parse_csv(&text).unwrap();
    let fresh = reference_rows(1e-11).unwrap();
    assert_eq!(
        committed.len(),
        fresh.len(),
        "row count: regenerate the table"
    );
    for (c, f) in committed.iter().zip(&fresh) {
        let key = format!("{} {} {}°", c.case, c.material, c.theta_deg);
        assert!(
            c.case == f.case
                && c.material == f.material
                && c.young == f.young
                && c.poisson == f.poisson
                && c.density == f.density
                && c.radius == f.radius
                && c.speed == f.speed
                && c.theta_deg == f.theta_deg
                && c.mu == f.mu
                && c.e_n_target == f.e_n_target,
            "{key}: scenario changed: regenerate the table"
        );
        assert!((c.e_n - f.e_n).abs() < 1e-8, "{key}: e_n");
        assert!((c.e_t - f.e_t).abs() < 1e-8, "{key}: e_t");
        assert!(
            (c.omega - f.omega).abs() < 1e-8 * f.omega.abs().max(1.0),
            "{key}: omega"
        );
        assert!(
            (c.rebound_deg - f.rebound_deg).abs() < 1e-6,
            "{key}: rebound"
        );
    }
}

/// The table's parser rejects what it must (a stale header, a short row, a bad number).
#[test]
fn table_parser_rejects_bad_input() {
    assert!(parse_csv("case,material\n").is_err());
    assert!(parse_csv(&format!("{CSV_HEADER}\nt4,Al2O3,1\n")).is_err());
    let bad = format!("{CSV_HEADER}\nt4,Al2O3,x,0.23,4000,0.0025,3.9,5,0.092,0.98,1,1,1,1,NaN\n");
    assert!(parse_csv(&bad).is_err());
}

/// Two equal spheres (the normal turns during the contact): the total angular momentum about
/// the centre of mass, I ω1 + I ω2 + m* (p × u), is conserved by the model because the lever
/// r − δ/2 makes a1 + a2 = |x1 − x2|: 1e-10 relative to m* v R. With the lever r (rigid-body
/// theory) it is not (> 1e-6), so the check can fail.
#[test]
fn pair_conserves_angular_momentum() {
    let alpha = alpha_for_e(0.98, End::Force, 1e-13).unwrap();
    for (lever, conserved) in [(Lever::MidOverlap, true), (Lever::Radius, false)] {
        let mut sp = AL2O3.pair(R4, alpha, MU, End::Force, TangentRule::Displacement);
        sp.lever = lever;
        for deg in [5.0, 20.0, 45.0, 80.0] {
            let th = f64::to_radians(deg);
            let o = collide(&sp, V4 * th.cos(), V4 * th.sin(), 1e-12).unwrap();
            let scale = sp.m_eff() * V4 * R4;
            let dl = (o.l_out - o.l_in).abs() / scale;
            assert_eq!(
                dl < 1e-10,
                conserved,
                "{lever:?} {deg}°: ΔL/(m* v R) = {dl:e}"
            );
            // Equal spheres, no initial spin: both spin the same.
            assert!((o.w_out - o.w2_out).abs() < 1e-9 * o.w_out.abs().max(1.0));
        }
    }
}

/// Two equal spheres in gross sliding: relative velocities follow the wall's closed forms with
/// m* (e_t = 1 − μ(1+e)/tan θ) and each sphere spins with ω R/v_n = μ(1+e) m* R²/I = 5/4 μ(1+e),
/// up to the normal's turn during the contact (φ ≈ v_t τ/(2R) ≈ 7e-3 rad at 80°; the table's
/// velocities are in the first-touch frame) and the lever: 1e-2 on e_t, 1e-2 relative on ω.
#[test]
fn pair_gross_sliding() {
    let alpha = alpha_for_e(0.98, End::Force, 1e-13).unwrap();
    let sp = AL2O3.pair(R4, alpha, MU, End::Force, TangentRule::Displacement);
    for deg in [40.0, 60.0, 80.0] {
        let (e_n, e_t, omega, _) = outcome_row(&sp, V4, deg, 1e-11).unwrap();
        let th = f64::to_radians(deg);
        let p = MU * (1.0 + e_n);
        let (et, wr) = (1.0 - p / th.tan(), 1.25 * p);
        let w = omega * R4 / (V4 * th.cos());
        println!("pair {deg}°: e_t {e_t:.6} (rigid {et:.6}), ωR/v_n {w:.6} (rigid {wr:.6})");
        assert!((e_t - et).abs() < 1e-2, "{deg}: e_t {e_t}");
        assert!(rel(w, wr) < 1e-2, "{deg}: ω {omega}");
    }
}
