//! Section 4: Chung & Ooi (2011) test 4 — oblique impacts of a sphere on a rigid wall — through
//! the full-contact C ABI (velocity-Verlet, as c_tests/test_chung_ooi.c), beside the
//! independent reference (tests/common/oblique.rs) and the analytic limits of
//! docs/benchmarks.md.

use crate::Report;
use crate::plot::{Kind, Panel, Res, Series, figure};
use demcontact::ffi::contact::*;
use demcontact::ffi::status::{DC_END_FORCE, DC_OK};
use plotters::prelude::SeriesLabelPosition;
use std::fmt::Write;

#[path = "../../tests/common/oblique.rs"]
mod oblique;
use oblique::{End, Material, TangentRule};

const R: f64 = 0.0025;
const V: f64 = 3.9;
const MU: f64 = 0.092;
const EN: f64 = 0.98;

/// One test-4 collision through dc_contact_force: (e_t, ω, rebound angle [deg], e_n).
fn library(mat: &Material, theta_deg: f64, steps: f64) -> Res<(f64, f64, f64, f64)> {
    let mut spec = std::mem::MaybeUninit::<dc_contact_spec>::uninit();
    // SAFETY: spec is writable; dc_contact_spec_init fills every field on DC_OK.
    if unsafe { dc_contact_spec_init(spec.as_mut_ptr()) } != DC_OK {
        return Err(crate::plot::Fail("dc_contact_spec_init".into()));
    }
    // SAFETY: initialised by dc_contact_spec_init above.
    let mut spec = unsafe { spec.assume_init() };
    spec.normal = DC_NORMAL_HERTZ;
    spec.damping = DC_DAMPING_RESTITUTION;
    spec.criterion = DC_END_FORCE;
    spec.tangential = DC_TANGENTIAL_MINDLIN;
    spec.E1 = mat.young;
    spec.nu1 = mat.poisson;
    spec.E2 = f64::INFINITY;
    spec.nu2 = mat.poisson;
    spec.e_n = EN;
    spec.mu = MU;
    let mut model = std::mem::MaybeUninit::<dc_contact_model>::uninit();
    // SAFETY: valid spec, writable output.
    if unsafe { dc_contact_model_init(&spec, model.as_mut_ptr()) } != DC_OK {
        return Err(crate::plot::Fail("dc_contact_model_init".into()));
    }
    // SAFETY: initialised on DC_OK.
    let model = unsafe { model.assume_init() };
    let m = mat.mass(R);
    let inertia = 0.4 * m * R * R;
    let (_, _, tau) =
        oblique::hertz_elastic(m, R, mat.young / (1.0 - mat.poisson * mat.poisson), V);
    let dt = tau / steps;
    let th = theta_deg.to_radians();
    let (vn, vt) = (V * th.cos(), V * th.sin());
    let (mut z, mut v, mut w) = (R + 0.37 * vn * dt, [vt, 0.0, -vn], [0.0f64; 3]);
    let (mut f, mut t) = ([0.0f64; 3], [0.0f64; 3]);
    let mut hist = [0.0f64; DC_CONTACT_HISTORY_MAX];
    let mut touched = false;
    for _ in 0..10_000_000u64 {
        for k in 0..3 {
            v[k] += 0.5 * dt * f[k] / m;
            w[k] += 0.5 * dt * t[k] / inertia;
        }
        z += dt * v[2];
        let state = dc_contact_state {
            n: [0.0, 0.0, 1.0],
            overlap: R - z,
            v1: v,
            v2: [0.0; 3],
            w1: w,
            w2: [0.0; 3],
            r1: R,
            r2: f64::INFINITY,
            m1: m,
            m2: f64::INFINITY,
        };
        let mut out = std::mem::MaybeUninit::<dc_contact_result>::uninit();
        // SAFETY: valid model and state, history of its documented length, writable output.
        let s = unsafe {
            dc_contact_force(
                &model,
                &state,
                dt,
                hist.as_mut_ptr(),
                hist.len(),
                out.as_mut_ptr(),
            )
        };
        if s != DC_OK {
            return Err(crate::plot::Fail(format!("dc_contact_force: {s}")));
        }
        // SAFETY: written on DC_OK.
        let out = unsafe { out.assume_init() };
        (f, t) = (out.force, out.torque1);
        for k in 0..3 {
            v[k] += 0.5 * dt * f[k] / m;
            w[k] += 0.5 * dt * t[k] / inertia;
        }
        if state.overlap > 0.0 {
            touched = true;
        } else if touched {
            let reb = ((v[0] - R * w[1]) / v[2]).atan().to_degrees();
            return Ok((v[0] / vt, w[1], reb, v[2] / vn));
        }
    }
    Err(crate::plot::Fail("no separation".into()))
}

pub fn run(rep: &mut Report) -> Res<()> {
    let mut md = String::new();
    writeln!(
        md,
        "## 4. Chung & Ooi (2011) test 4: oblique impacts through the contact ABI\n"
    )?;
    writeln!(
        md,
        "A sphere (R = 2.5 mm, 3.9 m/s, no spin) hits a rigid wall (E = +∞) at θ = 5°…85° from the normal; \
Hertz + damping for e_n = 0.98 (DC_END_FORCE), Mindlin k_t = 8 G* √(R δ) with μ = 0.092 (parameters and \
derivations: [benchmarks.md](benchmarks.md)). Markers: `dc_contact_force` in a velocity-Verlet loop with \
dt = τ_Hertz/4000 (as `c_tests/test_chung_ooi.c`); lines: the independent reference (adaptive \
Dormand–Prince, stick/slip as events, rtol 1e-11) with the library's conventions; dashed: the analytic \
limits — gross sliding (impulse ratio μ(1 + e_n), exact above tan θ* = 7/2 μ (1 + e_n), θ* = 32.5°) and \
no slip (μ → ∞: e_t = (5 + 2β0)/7, β0 from the Hertz–Mindlin Hill equation).\n"
    )?;
    let alpha = oblique::alpha_for_e(EN, End::Force, 1e-13).map_err(crate::plot::Fail)?;
    let fine: Vec<f64> = (1..=89).map(f64::from).collect();
    let coarse: Vec<f64> = (1..=17).map(|i| 5.0 * f64::from(i)).collect();
    let mut panels = vec![
        Panel::new(
            "tangential restitution e_t = u_out/u_in",
            "incident angle θ [deg]",
            "e_t",
        )
        .legend(SeriesLabelPosition::LowerRight)
        .yrange(0.4, 1.1),
        Panel::new(
            "rebound angular velocity ω",
            "incident angle θ [deg]",
            "ω [rad/s]",
        )
        .legend(SeriesLabelPosition::UpperRight)
        .yrange(0.0, 800.0),
        Panel::new(
            "rebound angle of the contact point",
            "incident angle θ [deg]",
            "atan((u − Rω)/v_n) [deg]",
        )
        .legend(SeriesLabelPosition::UpperLeft),
        Panel::new(
            "impulse ratio J_t/(μ J_n)",
            "incident angle θ [deg]",
            "J_t/(μ J_n)",
        )
        .legend(SeriesLabelPosition::LowerRight)
        .yrange(0.0, 1.1),
    ];
    let mut worst = [0.0f64; 3];
    for (mi, mat) in [oblique::AL2O3, oblique::AL_ALLOY_T4].iter().enumerate() {
        let sp = oblique::library_spec(mat, R, alpha, MU);
        let mut curves: [Vec<(f64, f64)>; 4] = Default::default();
        for &th in &fine {
            let (e_n, e_t, om, reb) =
                oblique::outcome_row(&sp, V, th, 1e-11).map_err(crate::plot::Fail)?;
            let ratio = (1.0 - e_t) * th.to_radians().tan() / (MU * (1.0 + e_n));
            for (c, y) in curves.iter_mut().zip([e_t, om, reb, ratio]) {
                c.push((th, y));
            }
        }
        let mut marks: [Vec<(f64, f64)>; 4] = Default::default();
        for &th in &coarse {
            let (e_t, om, reb, e_n) = library(mat, th, 4000.0)?;
            let (_, re_t, rom, rreb) =
                oblique::outcome_row(&sp, V, th, 1e-11).map_err(crate::plot::Fail)?;
            worst[0] = worst[0].max((e_t - re_t).abs());
            worst[1] = worst[1].max((om - rom).abs());
            worst[2] = worst[2].max((reb - rreb).abs());
            let ratio = (1.0 - e_t) * th.to_radians().tan() / (MU * (1.0 + e_n));
            for (c, y) in marks.iter_mut().zip([e_t, om, reb, ratio]) {
                c.push((th, y));
            }
        }
        for (k, (c, mk)) in curves.into_iter().zip(marks).enumerate() {
            panels[k].add(Series::new(
                format!("reference, {}", mat.name),
                c,
                Kind::Line,
                mi,
            ));
            panels[k].add(Series::new(
                format!("dc_contact_force, {}", mat.name),
                mk,
                Kind::Points,
                mi,
            ));
        }
        // No-slip limit (μ → ∞, this material's K, the damped normal history).
        let sp_r = {
            let mut s = mat.on_wall(
                R,
                alpha,
                f64::INFINITY,
                End::Force,
                TangentRule::Displacement,
            );
            s.lever = oblique::Lever::Radius;
            s
        };
        let b0 = oblique::no_slip_beta(
            oblique::k_ratio(&sp_r, V),
            alpha,
            End::Force,
            TangentRule::Displacement,
            1e-12,
        );
        let small: Vec<f64> = (1..=12).map(f64::from).collect();
        let ns = |f: &dyn Fn(f64) -> f64| small.iter().map(|&t| (t, f(t))).collect::<Vec<_>>();
        panels[0].add(Series::new(
            format!("no slip, {} (β0 = {b0:.4})", mat.name),
            ns(&|_| (5.0 + 2.0 * b0) / 7.0),
            Kind::Dashed,
            mi + 2,
        ));
        panels[1].add(Series::new(
            format!("no slip, {}", mat.name),
            ns(&|t| 5.0 / 7.0 * (1.0 - b0) * V * t.to_radians().sin() / R),
            Kind::Dashed,
            mi + 2,
        ));
        panels[2].add(Series::new(
            format!("no slip, {}", mat.name),
            ns(&|t| (b0 * t.to_radians().tan() / EN).atan().to_degrees()),
            Kind::Dashed,
            mi + 2,
        ));
    }
    // Gross sliding (material independent).
    let gs: Vec<f64> = (10..=89).map(f64::from).collect();
    let g = |k: usize| -> Vec<(f64, f64)> {
        gs.iter()
            .map(|&t| {
                let th = t.to_radians();
                let (et, wr, tr) = oblique::gross_sliding(MU, EN, th.tan());
                let y = match k {
                    0 => et,
                    1 => wr * V * th.cos() / R,
                    2 => tr.atan().to_degrees(),
                    _ => 1.0,
                };
                (t, y)
            })
            .collect()
    };
    for (k, p) in panels.iter_mut().enumerate() {
        p.add(Series::new("gross sliding", g(k), Kind::Dashed, 7));
    }
    let file = "chung_ooi_test4.png";
    figure(&rep.fig_path(file), &panels, 2, (620, 460))?;
    rep.figure(
        &mut md,
        file,
        "Chung & Ooi test 4: e_t, ω, rebound angle and impulse ratio against incident angle",
        "read that the library (markers) sits on the reference (lines) at every angle; that above \
θ* ≈ 32.5° both materials follow the gross-sliding limit (impulse ratio 1), and that below it the \
contact sticks part of the time and the tangential compliance separates Al2O3 from the Al alloy, \
approaching the no-slip limit as θ → 0.",
    )?;
    writeln!(
        md,
        "Largest difference library − reference over the 34 impacts: e_t {:.1e}, ω {:.1e} rad/s, rebound angle \
{:.1e}°. The figures the C test checks, with their tolerances, are in [benchmarks.md](benchmarks.md).\n",
        worst[0], worst[1], worst[2]
    )?;
    rep.push(&md);
    Ok(())
}
