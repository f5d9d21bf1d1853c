//! Section 3: the seeds' figures recomputed by the library, and the clamping-solver figure.

use crate::Report;
use crate::plot::{Kind, Panel, Res, Series, figure};
use crate::reference;
use demcontact::EndCriterion;
use demcontact::force::powerlaw::powerlaw_from_alpha;
use demcontact::lsd::{decay_to_turning_point, zeta_overlap};
use demcontact::powerlaw::{
    Contact, alpha_from_e, alpha_from_zeta, contact_duration, damping_scale, transform_q,
};
use demcontact::timestep::{Scheme, collide};
use plotters::prelude::SeriesLabelPosition;
use std::fmt::Write;

const CRITS: [(EndCriterion, &str); 2] = [
    (EndCriterion::Overlap, "DC_END_OVERLAP"),
    (EndCriterion::Force, "DC_END_FORCE"),
];

fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
        .collect()
}

pub fn run(rep: &mut Report) -> Res<()> {
    let mut md = String::new();
    writeln!(md, "## 3. The seeds' figures, recomputed\n")?;
    writeln!(
        md,
        "Lines are the library's closed forms; markers are the Dormand–Prince reference (rtol 1e-11) or a simulation with the library's kernels, as stated.\n"
    )?;

    // 3.1 α against e.
    let ps = [1.0, 1.5, 2.0, 3.0, 5.0];
    let es = linspace(0.02, 1.0, 50);
    let mut panels = Vec::new();
    for (crit, name) in CRITS {
        let mut pn = Panel::new(
            format!("{name}: α(e)"),
            "restitution e (dimensionless)",
            "damping coefficient α (dimensionless)",
        )
        .legend(SeriesLabelPosition::UpperRight);
        for (i, &p) in ps.iter().enumerate() {
            let pts: Vec<(f64, f64)> = es
                .iter()
                .map(|&e| (e, alpha_from_e(e, p, crit).unwrap_or(f64::NAN)))
                .collect();
            pn.add(Series::new(format!("p = {p}"), pts, Kind::Line, i));
        }
        // Markers: the e the reference realises with α(e), p = 3/2.
        let pts: Vec<(f64, f64)> = [0.1, 0.3, 0.5, 0.7, 0.9]
            .iter()
            .map(|&e| {
                let a = alpha_from_e(e, 1.5, crit).unwrap_or(f64::NAN);
                (
                    reference::collide(1.5, a, 1.0, 1.0, crit, 1e-11).map_or(f64::NAN, |r| r.e),
                    a,
                )
            })
            .collect();
        pn.add(Series::new(
            "reference realises (p = 1.5)",
            pts,
            Kind::Points,
            7,
        ));
        panels.push(pn);
    }
    let file = "seed_alpha_vs_e.png";
    figure(&rep.fig_path(file), &panels, 2, (600, 440))?;
    rep.figure(&mut md, file, "damping coefficient α against restitution e", "read α for a target e; the force-end calibration needs more damping than the overlap-end one for every e < 1, and markers (e realised by the reference with that α) sit on the lines.")?;

    // 3.2 Normalised force-time history.
    let mut panels = Vec::new();
    for &p in &[1.5, 2.0] {
        let mut pn = Panel::new(
            format!("p = {p}, DC_END_OVERLAP calibration, no clamp"),
            "t/τ (dimensionless)",
            "F/F_max (dimensionless)",
        )
        .legend(SeriesLabelPosition::UpperRight);
        for (i, &e) in [1.0, 0.9, 0.7, 0.5, 0.3].iter().enumerate() {
            let a = alpha_from_e(e, p, EndCriterion::Overlap)?;
            let mut pts = Vec::new();
            let r = reference::collide_observed(
                p,
                a,
                1.0,
                1.0,
                EndCriterion::Overlap,
                1e-12,
                |t, d, v| {
                    let d = d.max(0.0);
                    pts.push((t, d.powf(p) + a * d.powf(0.5 * (p - 1.0)) * v));
                },
            )
            .ok_or("reference")?;
            let fmax = pts.iter().map(|q| q.1).fold(0.0, f64::max);
            let pts: Vec<(f64, f64)> = pts.iter().map(|&(t, f)| (t / r.tau, f / fmax)).collect();
            pn.add(Series::new(format!("e = {e}"), pts, Kind::Line, i));
        }
        panels.push(pn);
    }
    let file = "seed_force_history.png";
    figure(&rep.fig_path(file), &panels, 2, (600, 440))?;
    rep.figure(&mut md, file, "normalised force-time history (reference trajectory)", "read how damping moves the force peak earlier and makes the force attractive (negative) before δ returns to 0: that tail is what clamping solvers cut off.")?;

    // 3.3 δ_max against e.
    let mut panels = Vec::new();
    for (crit, name) in CRITS {
        let mut pn = Panel::new(
            format!("{name} calibration"),
            "restitution e (dimensionless)",
            "δ_max / δ_max(undamped) (dimensionless)",
        )
        .legend(SeriesLabelPosition::LowerRight);
        for (i, &p) in [1.0, 1.5, 2.0, 3.0].iter().enumerate() {
            let q = transform_q(p);
            let closed = |e: f64| {
                let z = alpha_from_e(e, p, crit).unwrap_or(f64::NAN) / damping_scale(p);
                (-q * decay_to_turning_point(z)).exp()
            };
            pn.add(Series::new(
                format!("p = {p}: exp(−q g(ζ))"),
                es.iter().map(|&e| (e, closed(e))).collect(),
                Kind::Line,
                i,
            ));
            let d0 = reference::collide(p, 0.0, 1.0, 1.0, crit, 1e-11)
                .ok_or("reference")?
                .delta_max;
            let pts: Vec<(f64, f64)> = [0.05, 0.2, 0.4, 0.6, 0.8, 0.95]
                .iter()
                .map(|&e| {
                    let a = alpha_from_e(e, p, crit).unwrap_or(f64::NAN);
                    (
                        e,
                        reference::collide(p, a, 1.0, 1.0, crit, 1e-11)
                            .map_or(f64::NAN, |r| r.delta_max / d0),
                    )
                })
                .collect();
            pn.add(Series::new("", pts, Kind::Points, i));
        }
        panels.push(pn);
    }
    let file = "seed_dmax_vs_e.png";
    figure(&rep.fig_path(file), &panels, 2, (600, 440))?;
    rep.figure(&mut md, file, "maximum overlap against restitution (lines: closed form; markers: reference)", "read how much damping reduces the peak overlap at a given e; for the force criterion the reduction is larger because α is.")?;

    // 3.4 τ(α)/τ(0) against ζ.
    let mut panels = Vec::new();
    for (crit, name) in CRITS {
        let zmax = if crit == EndCriterion::Overlap {
            0.95
        } else {
            2.0
        };
        let zs = linspace(0.0, zmax, 28);
        let mut pn = Panel::new(
            format!("{name}"),
            "effective damping ratio ζ = α/√(2(p+1)) (dimensionless)",
            "τ(α)/τ(0) (dimensionless)",
        )
        .legend(SeriesLabelPosition::UpperLeft);
        for (i, &p) in [1.0, 1.5, 2.0, 3.0].iter().enumerate() {
            let t0 = reference::collide(p, 0.0, 1.0, 1.0, crit, 1e-11)
                .ok_or("reference")?
                .tau;
            let pts: Vec<(f64, f64)> = zs
                .iter()
                .step_by(3)
                .map(|&z| {
                    (
                        z,
                        reference::collide(p, alpha_from_zeta(z, p), 1.0, 1.0, crit, 1e-11)
                            .map_or(f64::NAN, |r| r.tau / t0),
                    )
                })
                .collect();
            let fine = linspace(0.0, zmax, 120);
            let lib: Vec<(f64, f64)> = fine
                .iter()
                .map(|&z| {
                    let c = Contact::new(p, alpha_from_zeta(z, p), 1.0, 1.0);
                    (
                        z,
                        c.and_then(|c| contact_duration(&c, crit, 4))
                            .map_or(f64::NAN, |t| t / t0),
                    )
                })
                .collect();
            pn.add(Series::new(
                format!("p = {p}: contact_duration"),
                lib,
                Kind::Line,
                i,
            ));
            pn.add(Series::new("", pts, Kind::Points, i));
        }
        panels.push(pn);
    }
    let file = "seed_tau_vs_zeta.png";
    figure(&rep.fig_path(file), &panels, 2, (600, 440))?;
    rep.figure(&mut md, file, "contact duration relative to the undamped one, against ζ (lines: library, markers: reference)", "read that under the overlap end τ grows without bound as ζ → 1 (critical damping), the faster the larger p, while under the force end it shrinks with damping for every ζ, most for p = 1.")?;

    // 3.5 Phase portrait, p = 3/2.
    let mut panels = Vec::new();
    for (crit, name) in CRITS {
        let mut pn = Panel::new(
            format!("p = 3/2, {name} calibration"),
            "δ/δ_max(undamped) (dimensionless)",
            "v/v0 (dimensionless)",
        )
        .legend(SeriesLabelPosition::LowerLeft);
        let d0 = reference::collide(1.5, 0.0, 1.0, 1.0, crit, 1e-11)
            .ok_or("reference")?
            .delta_max;
        for (i, &e) in [0.9, 0.7, 0.5, 0.3].iter().enumerate() {
            let a = alpha_from_e(e, 1.5, crit)?;
            let mut pts = Vec::new();
            reference::collide_observed(1.5, a, 1.0, 1.0, crit, 1e-12, |_, d, v| {
                pts.push((d / d0, v))
            })
            .ok_or("reference")?;
            if crit == EndCriterion::Force {
                // After the force zero a clamping solver leaves the body in free flight.
                let last = *pts.last().ok_or("empty")?;
                pts.push((0.0, last.1));
            }
            pn.add(Series::new(format!("e = {e}"), pts, Kind::Line, i));
        }
        panels.push(pn);
    }
    let file = "seed_phase_portrait.png";
    figure(&rep.fig_path(file), &panels, 2, (600, 460))?;
    rep.figure(&mut md, file, "phase portrait of the Hertz (p = 3/2) contact (reference)", "read the exit speed v/v0 = −e where each curve meets δ = 0; with the force end the curve leaves the contact law at F = 0 and flies out at constant speed.")?;

    // 3.6 f(p) = √(2(p+1)).
    let mut pn = Panel::new(
        "universal factor f(p): α = f(p)·ζ",
        "force-law exponent p (dimensionless)",
        "f(p) (dimensionless)",
    )
    .legend(SeriesLabelPosition::UpperLeft);
    let pgrid = linspace(1.0, 5.0, 41);
    pn.add(Series::new(
        "√(2(p+1))",
        pgrid.iter().map(|&p| (p, damping_scale(p))).collect(),
        Kind::Line,
        0,
    ));
    // Markers: α that makes the reference realise e = 0.5 (overlap end), found by secant, over ζ_O(0.5).
    let mut pts = Vec::new();
    for &p in &[1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0] {
        let f = |a: f64| {
            reference::collide(p, a, 1.0, 1.0, EndCriterion::Overlap, 1e-11)
                .map_or(f64::NAN, |r| r.e)
                - 0.5
        };
        let (mut a0, mut a1) = (0.5, 1.0);
        let (mut f0, mut f1) = (f(a0), f(a1));
        for _ in 0..30 {
            if f1 == f0 || f1.abs() < 1e-13 {
                break;
            }
            let a2 = a1 - f1 * (a1 - a0) / (f1 - f0);
            a0 = a1;
            f0 = f1;
            a1 = a2;
            f1 = f(a1);
        }
        pts.push((p, a1 / zeta_overlap(0.5)));
    }
    pn.add(Series::new(
        "α(e = 0.5 in the reference)/ζ_LSD(0.5)",
        pts,
        Kind::Points,
        1,
    ));
    let file = "seed_universal_factor.png";
    figure(&rep.fig_path(file), &[pn], 1, (640, 440))?;
    rep.figure(&mut md, file, "the universal factor f(p)", "read f(p) to convert an LSD damping ratio into α for any p; markers are α found by shooting the reference to e = 0.5, divided by the LSD's ζ.")?;

    // 3.7 Viscoelastic e(v): the published series beside the full-range evaluation.
    {
        use demcontact::viscoelastic::full_range::e_full;
        use demcontact::viscoelastic::reference::e_reference;
        use demcontact::viscoelastic::series::e_series;
        let mut panels = Vec::new();
        for (crit, name) in CRITS {
            let mut pn = Panel::new(
                format!("viscoelastic spheres, {name}"),
                "b = β v^(1/5) (dimensionless; v impact speed)",
                "restitution e (dimensionless)",
            )
            .log(true, false)
            .yrange(0.0, 1.05)
            .legend(SeriesLabelPosition::LowerLeft);
            let bs: Vec<f64> = (0..=120)
                .map(|i| 10f64.powf(-3.0 + 5.0 * i as f64 / 120.0))
                .collect();
            pn.add(Series::new(
                "full range (Chebyshev tables)",
                bs.iter()
                    .map(|&b| (b, e_full(b, crit).unwrap_or(f64::NAN)))
                    .collect(),
                Kind::Line,
                0,
            ));
            pn.add(Series::new(
                "published series",
                bs.iter()
                    .filter(|&&b| b <= 1.6)
                    .map(|&b| (b, e_series(b, crit).unwrap_or(f64::NAN)))
                    .collect(),
                Kind::Dashed,
                1,
            ));
            let marks: Vec<(f64, f64)> = [1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0]
                .iter()
                .map(|&b| (b, e_reference(b, crit).unwrap_or(f64::NAN)))
                .collect();
            pn.add(Series::new("reference integrator", marks, Kind::Points, 2));
            panels.push(pn);
        }
        let file = "seed_viscoelastic_e.png";
        figure(&rep.fig_path(file), &panels, 2, (620, 460))?;
        rep.figure(&mut md, file, "viscoelastic restitution against b = β v^(1/5): series beside full range", "read where the published series stops being usable (it leaves the full-range curve near b ≈ 0.8 and diverges beyond b ≈ 1), and that the full-range tables follow the reference to the largest b.")?;
    }

    // 3.8 Realised e against target e in a clamping solver.
    let mut pn = Panel::new(
        "clamping solver (attractive force clamped), velocity-Verlet dt = τ/2000",
        "target restitution e (dimensionless)",
        "realised restitution (dimensionless)",
    )
    .legend(SeriesLabelPosition::UpperLeft);
    let targets = linspace(0.05, 1.0, 20);
    writeln!(
        md,
        "Realised restitution in a clamping solver (velocity-Verlet, dt = τ/2000, contact at mid-step):\n\n| p | target e | δ=0 calibration | ours (force end) |\n|---|---|---|---|"
    )?;
    pn.add(Series::new(
        "realised = target",
        vec![(0.0, 0.0), (1.0, 1.0)],
        Kind::Line,
        7,
    ));
    let mut dev = Panel::new(
        "deviation from the target (same runs)",
        "target restitution e (dimensionless)",
        "realised e − target e (dimensionless)",
    )
    .legend(SeriesLabelPosition::UpperRight);
    for (i, &p) in [1.0, 1.5, 3.0].iter().enumerate() {
        let mut o = Vec::new();
        let mut f = Vec::new();
        for &e in &targets {
            let sim = |alpha: f64| -> Res<f64> {
                let pair = powerlaw_from_alpha(p, 1.0, alpha, EndCriterion::Force)?;
                let tau = collide(
                    &pair,
                    1.0,
                    1.0,
                    1.0,
                    1e-2,
                    0.5,
                    Scheme::VelocityVerlet,
                    1_000_000,
                )?
                .duration;
                Ok(collide(
                    &pair,
                    1.0,
                    1.0,
                    1.0,
                    tau / 2000.0,
                    0.5,
                    Scheme::VelocityVerlet,
                    10_000_000,
                )?
                .e)
            };
            let eo = sim(alpha_from_e(e, p, EndCriterion::Overlap)?)?;
            let ef = sim(alpha_from_e(e, p, EndCriterion::Force)?)?;
            if [0.1, 0.5, 0.9].iter().any(|&x| (x - e).abs() < 1e-6) {
                writeln!(md, "| {p} | {e:.2} | {eo:.4} | {ef:.4} |")?;
            }
            o.push((e, eo));
            f.push((e, ef));
        }
        dev.add(Series::new(
            format!("δ=0 calibration, p = {p}"),
            o.iter().map(|&(t, r)| (t, r - t)).collect(),
            Kind::LinePoints,
            i,
        ));
        dev.add(Series::new(
            format!("ours (force end), p = {p}"),
            f.iter().map(|&(t, r)| (t, r - t)).collect(),
            Kind::Points,
            i + 3,
        ));
        pn.add(Series::new(
            format!("δ=0 calibration, p = {p}"),
            o,
            Kind::LinePoints,
            i,
        ));
        pn.add(Series::new(
            format!("ours (force end), p = {p}"),
            f,
            Kind::Points,
            i + 3,
        ));
    }
    writeln!(md)?;
    let file = "clamping_realised_e.png";
    figure(&rep.fig_path(file), &[pn, dev], 2, (640, 480))?;
    rep.figure(&mut md, file, "realised e against target e in a clamping solver (simulated with the library's clamped kernels)", "read the bias of the δ=0 calibration (realised e above target, 0.55 for 0.5, 0.25 for 0.1; the curves of all p coincide because e does not depend on p) and that the force-end calibration lands on the target to within the step's error.")?;
    rep.push(&md);
    Ok(())
}
