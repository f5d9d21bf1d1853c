//! Section 5: the MFiX DEM verification problems DEM01–DEM05 and Chung & Ooi tests 5–8, drawn
//! from the same runs that tests/verification.rs asserts (tests/common/verification.rs).

use crate::Report;
use crate::plot::{Kind, Panel, Res, Series, figure};
use plotters::prelude::SeriesLabelPosition;
use std::f64::consts::PI;
use std::fmt::Write;

#[path = "../../tests/common/verification.rs"]
mod verification;
use verification::*;

fn mass(r: f64, rho: f64) -> f64 {
    rho * 4.0 / 3.0 * PI * r.powi(3)
}

pub fn run(rep: &mut Report) -> Res<()> {
    let mut md = String::new();
    writeln!(
        md,
        "## 5. Verification problems: MFiX DEM01–DEM05, Chung & Ooi tests 5–8\n"
    )?;
    writeln!(
        md,
        "Each problem runs through `dc_contact_force` in a velocity-Verlet host (the LAMMPS order, \
gravity, plane walls; `tests/common/verification.rs`) beside a reference computed without the library: \
the closed form of the linear spring–dashpot with gravity (DEM01, DEM02), the matrix exponential of the \
stacked pair's linear system (DEM03), rigid-body theory (DEM04, the sliding limits of DEM05 and tests \
5–8), the independent no-slip Hill integration (tests 5–8). `cargo test --profile ci --test verification \
-- --nocapture` asserts every figure; the tolerances and measured errors are in \
[reference/verification.md](reference/verification.md#verification-problems).\n"
    )?;

    // DEM01
    let kn = 1e6;
    let m = mass(R01, RHO01);
    let e = 0.7;
    let tc = PI / (kn / m).sqrt() / (1.0 - zeta_linear(e).powi(2)).sqrt();
    let h0 = 0.5;
    let t1 = (2.0 * (h0 - R01) / G).sqrt();
    let mut p = Panel::new(
        "DEM01: a dropped ball bounces (e = 0.7, k_n = 1e6 N/m)",
        "t − t_impact [ms]",
        "centre height − r [mm]",
    )
    .legend(SeriesLabelPosition::LowerRight);
    for (div, color) in [(10.0, 1), (50.0, 2)] {
        let run = dem01(kn, e, h0, tc / div, t1 + 4.0 * tc);
        let near: Vec<(f64, f64)> = run
            .iter()
            .filter(|r| r.0 > t1 - tc)
            .map(|r| ((r.0 - t1) * 1e3, (r.1 - R01) * 1e3))
            .collect();
        p.add(Series::new(
            format!("library, dt = t_c/{div}"),
            near,
            Kind::Points,
            color,
        ));
    }
    let exact: Vec<(f64, f64)> = (0..=600)
        .map(|i| t1 - tc + f64::from(i) / 600.0 * 5.0 * tc)
        .map(|t| {
            (
                (t - t1) * 1e3,
                (dem01_exact(kn, m, zeta_linear(e), h0, t) - R01) * 1e3,
            )
        })
        .collect();
    p.add(Series::new("exact", exact, Kind::Line, 0));
    let file = "verification_dem01.png";
    figure(&rep.fig_path(file), &[p], 1, (720, 420))?;
    rep.figure(&mut md, file, "DEM01: free fall, contact and rebound", "read that the steps follow the exact three-stage solution through the contact; at t_c/10 the onset between steps shows as a small offset after the rebound (first order in dt)")?;

    // DEM02
    let mut p = Panel::new(
        "DEM02: apex heights (e = 0.9, k_n = 1e5 N/m)",
        "bounce k",
        "apex height − r [m]",
    )
    .log(false, true)
    .legend(SeriesLabelPosition::UpperRight);
    let (kn2, e2) = (1e5, 0.9);
    let tc2 = PI / (kn2 / m).sqrt();
    let (exact, hard) = dem02_exact(kn2, m, e2, h0, 8);
    let lib = dem02(kn2, e2, h0, tc2 / 500.0, 8);
    let pts = |v: &[f64]| {
        v.iter()
            .enumerate()
            .map(|(i, h)| ((i + 1) as f64, h - R01))
            .collect::<Vec<_>>()
    };
    p.add(Series::new(
        "hard sphere (h0 − r) e^{2k}",
        pts(&hard),
        Kind::Dashed,
        7,
    ));
    p.add(Series::new(
        "exact, linear spring with gravity",
        pts(&exact),
        Kind::Line,
        0,
    ));
    p.add(Series::new(
        "library, dt = t_c/500",
        pts(&lib),
        Kind::Points,
        1,
    ));
    let file = "verification_dem02.png";
    figure(&rep.fig_path(file), &[p], 1, (720, 420))?;
    rep.figure(&mut md, file, "DEM02: bouncing ball", "read that the library lands on the exact heights of the compliant contact; the hard-sphere formula is 2 % high here (gravity acts during the contact) and is reached only as k_n → ∞")?;

    // DEM03
    let m3 = mass(R03, RHO03);
    let tc3 = PI / (kn / m3).sqrt();
    let run = dem03(kn, 0.7, tc3 / 20.0, 10.0 * tc3);
    let mut p = Panel::new(
        "DEM03: two stacked particles between walls (e = 0.7)",
        "t / t_c",
        "centre height / r",
    )
    .legend(SeriesLabelPosition::UpperRight);
    let ex = |k: usize| -> Vec<(f64, f64)> {
        (0..=500)
            .map(|i| f64::from(i) / 500.0 * 10.0 * tc3)
            .map(|t| {
                let (a, b) = dem03_exact(kn, 0.7, m3, t);
                (t / tc3, if k == 0 { a } else { b } / R03)
            })
            .collect()
    };
    p.add(Series::new("exact, lower", ex(0), Kind::Line, 0));
    p.add(Series::new("exact, upper", ex(1), Kind::Line, 1));
    p.add(Series::new(
        "library (dt = t_c/20), lower",
        run.iter().map(|r| (r.0 / tc3, r.1 / R03)).collect(),
        Kind::Points,
        0,
    ));
    p.add(Series::new(
        "library (dt = t_c/20), upper",
        run.iter().map(|r| (r.0 / tc3, r.2 / R03)).collect(),
        Kind::Points,
        1,
    ));
    let file = "verification_dem03.png";
    figure(&rep.fig_path(file), &[p], 1, (720, 420))?;
    rep.figure(&mut md, file, "DEM03: stacked particles settle", "read that the damped oscillation of both particles follows the matrix-exponential solution even at a coarse t_c/20")?;

    // DEM04
    let (mu, v0) = (0.3, 1.0);
    let run = dem04(kn, mu, v0, PI / (kn / m).sqrt() / 100.0, 0.3);
    let mut p = Panel::new(
        "DEM04: slip to roll (μ = 0.3, v0 = 1 m/s)",
        "t [s]",
        "speed [m/s]",
    )
    .legend(SeriesLabelPosition::UpperRight);
    let tr = 2.0 * v0 / (7.0 * mu * G);
    let theory = |k: usize| -> Vec<(f64, f64)> {
        (0..=300)
            .map(|i| f64::from(i) / 300.0 * 0.3)
            .map(|t| {
                let ts = t.min(tr);
                (
                    t,
                    if k == 0 {
                        v0 - mu * G * ts
                    } else {
                        2.5 * mu * G * ts
                    },
                )
            })
            .collect()
    };
    p.add(Series::new("rigid body: v", theory(0), Kind::Dashed, 0));
    p.add(Series::new("rigid body: ω r", theory(1), Kind::Dashed, 1));
    let every = (run.len() / 60).max(1);
    p.add(Series::new(
        "library: v",
        run.iter().step_by(every).map(|r| (r.0, r.1)).collect(),
        Kind::Points,
        0,
    ));
    p.add(Series::new(
        "library: ω a",
        run.iter().step_by(every).map(|r| (r.0, r.2)).collect(),
        Kind::Points,
        1,
    ));
    let file = "verification_dem04.png";
    figure(&rep.fig_path(file), &[p], 1, (720, 420))?;
    rep.figure(&mut md, file, "DEM04: a sliding ball starts to roll", "read that the ball slides at constant deceleration μ g until v = ω a at t_r = 2 v0/(7 μ g), then rolls at 5/7 v0")?;

    // DEM05 and Chung & Ooi 5–8: contact-point velocity out against in.
    let mut panels = Vec::new();
    let kn5 = 1e8;
    let tc5 = PI / (kn5 / m).sqrt();
    let mut p = Panel::new(
        "DEM05: oblique impacts (linear, k_t = k_n/7, μ = 0.1, e_n = 1)",
        "incident angle θ [deg]",
        "u_out / u_in",
    )
    .legend(SeriesLabelPosition::LowerRight);
    let (mut lib, mut ns) = (Vec::new(), Vec::new());
    for deg in (5..=85).step_by(5) {
        let th = f64::from(deg).to_radians();
        let (vn, vt) = (th.cos(), th.sin());
        let lin = |mu: f64| {
            linear_model(kn5, 1.0, |s| {
                s.tangential = demcontact::ffi::contact::DC_TANGENTIAL_LINEAR;
                s.k_t = kn5 / 7.0;
                s.mu = mu;
            })
        };
        let o = wall_impact(lin(0.1), R01, RHO01, vn, vt, 0.0, tc5 / 400.0);
        lib.push((f64::from(deg), slip_wall(o, R01) / vt));
        let o = wall_impact(lin(1e12), R01, RHO01, vn, vt, 0.0, tc5 / 400.0);
        ns.push((f64::from(deg), slip_wall(o, R01) / vt));
    }
    let slide: Vec<(f64, f64)> = (5..=89)
        .map(f64::from)
        .map(|d| (d, 1.0 - 3.5 * 0.1 * 2.0 / d.to_radians().tan()))
        .filter(|p| p.1 > -0.7)
        .collect();
    p.add(Series::new(
        "gross sliding 1 − 7/2 μ (1+e)/tan θ",
        slide,
        Kind::Dashed,
        7,
    ));
    p.add(Series::new(
        "no slip β0 = cos(π/√2)",
        vec![
            (5.0, (PI / 2f64.sqrt()).cos()),
            (85.0, (PI / 2f64.sqrt()).cos()),
        ],
        Kind::Dashed,
        3,
    ));
    p.add(Series::new("library, μ = 0.1", lib, Kind::Points, 0));
    p.add(Series::new("library, μ = ∞", ns, Kind::Points, 3));
    panels.push(p);
    let file = "verification_dem05.png";
    figure(&rep.fig_path(file), &panels, 1, (720, 420))?;
    rep.figure(&mut md, file, "DEM05: contact-point rebound ratio against incident angle", "read that above tan θ = 7/2 μ (1 + e) the library follows the gross-sliding line, and with μ = ∞ it sits on the closed-form no-slip ratio at every angle")?;

    // Chung & Ooi 5–8
    let (young, poisson, rho) = (3.8e11, 0.23, 4000.0);
    let (r, vn, mu) = (0.0025, 3.9, 0.092);
    let m = mass(r, rho);
    let e_star = young / (1.0 - poisson * poisson);
    let dm = (15.0 * m * vn * vn / (16.0 * e_star * r.sqrt())).powf(0.4);
    let dt = 3.2 * dm / vn / 400.0;
    let cases = [
        ("test 5: wall, v_t = 0", 0.0, 0.0, 0.0),
        ("test 6: wall, v_t = 1 m/s", 0.0, 1.0, 0.0),
        ("test 7: equal spheres, ω2 = ω1", r, 0.0, 1.0),
        ("test 8: R and 2R, ω2 = ω1/2", 2.0 * r, 0.0, 0.5),
    ];
    let mut panels = Vec::new();
    for (name, r2, vt, k2) in cases {
        let wall = r2 == 0.0;
        let lever = r + r2 * k2;
        let mut p = Panel::new(format!("Chung & Ooi {name}"), "u_in [m/s]", "u_out [m/s]")
            .legend(SeriesLabelPosition::UpperLeft);
        let mut lib = Vec::new();
        for k in -12..=12 {
            let u_in = 0.5 * f64::from(k);
            let w1 = (u_in - vt) / lever;
            let model = hertz_mindlin(young, poisson, wall, mu, 0.98);
            let u_out = if wall {
                slip_wall(wall_impact(model, r, rho, vn, vt, w1, dt), r)
            } else {
                let (o1, o2) = pair_impact(model, r, r2, rho, vn, vt, w1, k2 * w1, dt);
                slip_pair(o1, o2, r, r2)
            };
            lib.push((u_in, u_out));
        }
        let lim = 3.5 * mu * 1.98 * vn;
        let line: Vec<(f64, f64)> = (-60..=60)
            .map(|i| 0.1 * f64::from(i))
            .filter(|u: &f64| u.abs() >= lim)
            .map(|u| (u, u - u.signum() * lim))
            .collect();
        let (neg, pos): (Vec<_>, Vec<_>) = line.into_iter().partition(|p| p.0 < 0.0);
        p.add(Series::new(
            "gross sliding u − 7/2 μ (1+e) v_n",
            pos,
            Kind::Dashed,
            7,
        ));
        p.add(Series::new("", neg, Kind::Dashed, 7));
        p.add(Series::new(
            "library (Hertz–Mindlin, e_n = 0.98)",
            lib,
            Kind::Points,
            0,
        ));
        panels.push(p);
    }
    let file = "verification_chung_ooi_5_8.png";
    figure(&rep.fig_path(file), &panels, 2, (620, 420))?;
    rep.figure(&mut md, file, "Chung & Ooi tests 5–8: contact-point velocity out against in", "read that only the contact-point velocity u_in = v_t + Σ r ω matters: with spin on a wall or between spheres of equal or unequal size, the library follows the gross-sliding line for |u_in| ≥ 7/2 μ (1 + e) v_n and reverses u_in by the no-slip ratio below it")?;
    rep.push(&md);
    Ok(())
}
