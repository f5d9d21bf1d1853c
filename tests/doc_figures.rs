//! Figures quoted in the docs that no other test recomputed (audit of docs/calibration.md,
//! docs/powerlaw.md, docs/robustness.md and README.md): each is recomputed here, by a route
//! independent of the code that produced it where one exists, and asserted to the digits quoted.
//! Run: `cargo test --release --test doc_figures -- --nocapture`.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

use demcontact::ffi::{fit::*, powerlaw::*, status::*, viscoelastic::*};
use std::f64::consts::PI;

fn call(f: impl FnOnce(*mut f64) -> i32) -> (i32, f64) {
    let mut out = f64::NAN;
    let s = f(&mut out);
    (s, out)
}

/// P(|T_ν| ≤ t) for Student's t with an odd number ν of degrees of freedom, in closed form
/// (θ = atan(t/√ν): (2/π)[θ + sin θ cos θ Σ_{k<(ν−1)/2} a_k cos^{2k} θ], a_0 = 1,
/// a_k = a_{k−1}·2k/(2k+1)); independent of the library's incomplete-beta quantile.
fn t_coverage_odd(nu: u32, t: f64) -> f64 {
    assert!(nu % 2 == 1);
    let th = (t / f64::from(nu).sqrt()).atan();
    let (s, c) = th.sin_cos();
    let (mut sum, mut a, mut c2k) = (0.0, 1.0, 1.0);
    for k in 0..(nu - 1) / 2 {
        if k > 0 {
            a *= 2.0 * f64::from(k) / (2.0 * f64::from(k) + 1.0);
            c2k *= c * c;
        }
        sum += a * c2k;
    }
    2.0 / PI * (th + s * c * sum)
}

/// docs/calibration.md and README ("Command-line tool"): ±2·SE covers 89.8 % at n = 6 and 92.9 %
/// at n = 12 when σ comes from the scatter (ν = n − 1), and the library's t quantile gives 95 %.
#[test]
fn two_se_coverage_and_t_quantile() {
    let p6 = t_coverage_odd(5, 2.0);
    let p12 = t_coverage_odd(11, 2.0);
    println!(
        "P(|T_5| <= 2) = {:.4} %, P(|T_11| <= 2) = {:.4} %",
        100.0 * p6,
        100.0 * p12
    );
    assert!((100.0 * p6 - 89.8).abs() < 0.05, "{p6}");
    assert!((100.0 * p12 - 92.9).abs() < 0.05, "{p12}");
    // The closed form against known values: ν = 1 is the Cauchy law, P(|T| ≤ 1) = 1/2.
    assert!((t_coverage_odd(1, 1.0) - 0.5).abs() < 1e-15);
    for (n, quoted) in [(6usize, 2.5706), (12, 2.2010)] {
        let (s, q) = call(|o| unsafe { dc_fit_quantile95(n, 1, o) });
        assert_eq!(s, DC_OK);
        let cov = t_coverage_odd(n as u32 - 1, q);
        println!("n = {n}: q = {q:.6}, coverage {cov:.15}");
        assert!((cov - 0.95).abs() < 1e-12, "n={n}: {cov}");
        assert!((q - quoted).abs() < 5e-5, "n={n}: {q} vs quoted {quoted}");
    }
}

/// docs/robustness.md: below b = 1e-5 `dc_viscoelastic_e` switches from the table to the series;
/// at the switch e steps up by 1.0e-15 (overlap end) and 1.1e-16 (force end).
#[test]
fn viscoelastic_step_at_series_switch() {
    let b_hi: f64 = 1e-5;
    let b_lo = f64::from_bits(b_hi.to_bits() - 1);
    for (crit, quoted) in [(DC_END_OVERLAP, 1.0e-15), (DC_END_FORCE, 1.1e-16)] {
        let (s1, e_lo) = call(|o| unsafe { dc_viscoelastic_e(b_lo, crit, o) });
        let (s2, e_hi) = call(|o| unsafe { dc_viscoelastic_e(b_hi, crit, o) });
        assert_eq!((s1, s2), (DC_OK, DC_OK));
        let step = e_hi - e_lo;
        println!("criterion {crit}: e(1e-5) - e(1e-5 - ulp) = {step:.2e}");
        assert!(
            step > 0.0 && (step - quoted).abs() < 0.05 * quoted,
            "criterion {crit}: step {step:e} vs quoted {quoted:e}"
        );
    }
}

/// docs/robustness.md: over ζ ∈ [0, 5] (steps of 0.0025) the time of maximum overlap first grows
/// with α from p ≈ 4.8 on and the force-end duration from p ≈ 5 (p scanned 4.0 … 5.5 by 0.1).
#[test]
fn monotonicity_onset_in_p() {
    let grows = |p: f64, f: &dyn Fn(f64) -> f64| {
        let mut prev = f64::INFINITY;
        (0..=2000).any(|i| {
            let z = 0.0025 * f64::from(i);
            let v = f(z * (2.0 * (p + 1.0)).sqrt());
            let up = v > prev * (1.0 + 1e-12);
            prev = v;
            up
        })
    };
    let onset = |f: &dyn Fn(f64, f64) -> f64| {
        (0..=15)
            .map(|k| 4.0 + 0.1 * f64::from(k))
            .find(|&p| grows(p, &|a| f(p, a)))
    };
    let t_max = |p: f64, a: f64| {
        let (s, t) = call(|o| unsafe { dc_time_of_max_overlap(p, a, 1.0, 1.0, o) });
        assert_eq!(s, DC_OK);
        t
    };
    let tau_f = |p: f64, a: f64| {
        let (s, t) = call(|o| unsafe { dc_contact_duration(p, a, 1.0, 1.0, DC_END_FORCE, o) });
        assert_eq!(s, DC_OK);
        t
    };
    let (o_tmax, o_tau) = (onset(&t_max).unwrap(), onset(&tau_f).unwrap());
    println!(
        "first p (grid 0.1) where the quantity grows with alpha: t_max {o_tmax:.1}, force-end tau {o_tau:.1}"
    );
    assert!((o_tmax - 4.8).abs() < 0.05, "{o_tmax}");
    assert!((o_tau - 5.0).abs() < 0.05, "{o_tau}");
}

/// docs/powerlaw.md ("Contract decisions"): near critical damping the overlap-end trajectory of a
/// p > 1 contact underflows mid-contact (`DC_ERR_RESULT_RANGE`) from 1 − ζ ≈ 8.6e-6 on
/// (p = 1.5, v0 = ω0 = 1, 64 samples), where τ ≈ 5e66 — long before τ itself overflows
/// (1 − ζ ≈ 4e-7, docs/robustness.md).
#[test]
fn near_critical_trajectory_limit() {
    let p: f64 = 1.5;
    let s = (2.0 * (p + 1.0)).sqrt();
    let mut last_ok = None;
    let mut first_bad = None;
    for k in 0..=400 {
        // 1 − ζ from 1e-4 down to 1e-8, log-spaced.
        let gap = 10f64.powf(-4.0 - 4.0 * f64::from(k) / 400.0);
        let a = (1.0 - gap) * s;
        let (st_tau, tau) =
            call(|o| unsafe { dc_contact_duration(p, a, 1.0, 1.0, DC_END_OVERLAP, o) });
        const N: usize = 64;
        let (mut t, mut d, mut v, mut f) = ([0.0; N], [0.0; N], [0.0; N], [0.0; N]);
        let st = unsafe {
            dc_contact_trajectory(
                p,
                a,
                1.0,
                1.0,
                1.0,
                DC_END_OVERLAP,
                4,
                N,
                t.as_mut_ptr(),
                d.as_mut_ptr(),
                v.as_mut_ptr(),
                f.as_mut_ptr(),
                N,
            )
        };
        if st == DC_OK {
            assert!(
                first_bad.is_none(),
                "OK again after RESULT_RANGE at 1-ζ = {gap:e}"
            );
            last_ok = Some((gap, tau, st_tau));
        } else {
            assert_eq!(st, DC_ERR_RESULT_RANGE, "1-ζ = {gap:e}");
            first_bad.get_or_insert((gap, tau, st_tau));
        }
    }
    println!(
        "last trajectory OK: {last_ok:?}; first RESULT_RANGE: {first_bad:?} (1-ζ, τ, status of τ)"
    );
    let (gap_ok, _, _) = last_ok.unwrap();
    let (gap_bad, tau_bad, st_tau) = first_bad.unwrap();
    assert!(gap_ok < 9e-6 && gap_bad > 8e-6, "{gap_ok:e} {gap_bad:e}");
    assert!(
        st_tau == DC_OK && tau_bad > 1e66 && tau_bad < 1e67,
        "{tau_bad:e}"
    );
}

/// README ("Builtin models of LIGGGHTS, LAMMPS and YADE"): what each builtin realises for a typed
/// 0.5 (the force laws themselves are integrated independently in tests/builtin_vs_ode.rs), and
/// the floor e⁻² of a force-clamping `hertz`.
#[test]
fn builtin_uncorrected_values_quoted_in_readme() {
    use demcontact::Error;
    use demcontact::builtin::{Builtin::*, realised_e, value_for_e};
    let l = -(0.5f64.ln());
    let textbook_betan = l / (PI * PI + l * l).sqrt();
    let rows = [
        (
            "LIGGGHTS hertz limitForce on",
            realised_e(LiggghtsHertz, true, 0.5),
            0.550,
        ),
        (
            "LAMMPS coeff_restitution limit_damping",
            realised_e(LammpsCoeffRestitution, true, 0.5),
            0.550,
        ),
        (
            "LAMMPS tsuji",
            realised_e(LammpsTsujiHertz, false, 0.5),
            0.616,
        ),
        (
            "LAMMPS tsuji limit_damping",
            realised_e(LammpsTsujiHertz, true, 0.5),
            0.646,
        ),
        ("YADE ViscElMat", realised_e(YadeViscElEn, true, 0.5), 0.550),
        (
            "YADE MindlinPhys(betan), textbook betan",
            realised_e(YadeMindlinBetan, true, textbook_betan),
            0.523,
        ),
    ];
    for (name, got, quoted) in rows {
        let got = got.unwrap();
        println!("{name}: typed for 0.5 realises {got:.4} (quoted {quoted})");
        assert!((got - quoted).abs() < 5e-4, "{name}: {got} vs {quoted}");
    }
    let floor = realised_e(LiggghtsHertz, true, f64::MIN_POSITIVE).unwrap();
    println!(
        "hertz limitForce on: lowest realisable e {floor:.4} (e^-2 = {:.4})",
        (-2f64).exp()
    );
    assert!((floor - (-2f64).exp()).abs() < 1e-3, "{floor}");
    assert_eq!(
        value_for_e(LiggghtsHertz, true, 0.13),
        Err(Error::BuiltinUnreachable)
    );
}
