//! Section 2: the time-step trade of velocity-Verlet (LAMMPS/LIGGGHTS order) and symplectic Euler,
//! the stability of a resting contact, and dc_dt_for_accuracy.

use crate::Report;
use crate::plot::{Kind, Panel, Res, Series, figure};
use crate::reference;
use demcontact::EndCriterion;
use demcontact::force::powerlaw::{powerlaw, powerlaw_from_alpha};
use demcontact::powerlaw::timestep::dt_static;
use demcontact::powerlaw::{alpha_from_e, dt_crit_seed};
use demcontact::timestep::{
    Scheme, collide, dt_for_accuracy, resting_contact_stable, worst_restitution_error,
};
use plotters::prelude::SeriesLabelPosition;
use std::fmt::Write;

pub const PS: [f64; 4] = [1.0, 1.5, 2.0, 3.0];
pub const ES: [f64; 3] = [0.1, 0.5, 0.9];
const CRITS: [EndCriterion; 2] = [EndCriterion::Overlap, EndCriterion::Force];
const N_PHASE: u32 = 8;

fn crit_name(c: EndCriterion) -> &'static str {
    match c {
        EndCriterion::Overlap => "DC_END_OVERLAP",
        EndCriterion::Force => "DC_END_FORCE (clamped)",
    }
}

fn scheme_name(s: Scheme) -> &'static str {
    match s {
        Scheme::VelocityVerlet => "velocity-Verlet",
        Scheme::SymplecticEuler => "symplectic Euler",
    }
}

/// Worst relative errors (e, δ_max, τ) over N_PHASE start phases at step dt; v0 = ω0 = 1.
fn worst_errors(
    p: f64,
    e: f64,
    crit: EndCriterion,
    scheme: Scheme,
    dt: f64,
    r: &reference::RefCollision,
) -> [f64; 3] {
    let pair = powerlaw(p, 1.0, e, crit).expect("pair");
    let mut w = [0.0f64; 3];
    for i in 0..N_PHASE {
        let phase = (i as f64 + 0.5) / N_PHASE as f64;
        let steps = (64.0 * r.tau / dt) as u32 + 64;
        match collide(&pair, 1.0, 1.0, 1.0, dt, phase, scheme, steps) {
            Ok(c) => {
                w[0] = w[0].max(((c.e - e) / e).abs());
                w[1] = w[1].max(((c.delta_max - r.delta_max) / r.delta_max).abs());
                w[2] = w[2].max(((c.duration - r.tau) / r.tau).abs());
            }
            Err(_) => return [f64::INFINITY; 3],
        }
    }
    w
}

pub fn dt_grid() -> Vec<f64> {
    (0..15)
        .map(|i| 1e-3 * 10f64.powf(i as f64 * (2.5 / 14.0)))
        .collect()
}

pub fn trade(rep: &mut Report) -> Res<()> {
    let grid = dt_grid();
    let quantities = ["realised e", "δ_max", "contact duration τ"];
    let files = ["e", "dmax", "tau"];
    let mut md = String::new();
    writeln!(md, "## 2. The time-step trade\n")?;
    writeln!(
        md,
        "Each collision is integrated with the library's own force kernels (`crate::force`, k = 1, m = 1, v0 = 1) by \
`demcontact::timestep::collide`: velocity-Verlet in the LAMMPS/LIGGGHTS order (x += v dt + ½a dt²; v½ = v + ½a dt; \
force from x and v½; v = v½ + ½a_new dt) and symplectic Euler (v += a(x, v) dt; x += v dt). Contact starts at a \
fraction φ of a step; every point is the **worst relative error over {N_PHASE} phases** φ = (i+½)/{N_PHASE}. The truth: \
the calibrated e (exact), δ_max and τ from the Dormand–Prince reference at rtol 1e-12. δ_max is the largest overlap \
seen at a step; τ is interpolated linearly at the criterion's zero crossing. DC_END_FORCE pairs clamp attractive \
forces (their kernel), so the realised e is that of a clamping solver.\n"
    )?;
    // results[scheme][crit][p][e][dt] = [3]
    let mut table_c = String::new();
    writeln!(
        table_c,
        "First-order error constants, velocity-Verlet: C = (worst relative error)/(dt/τ) at dt/τ = 0.01 (e | δ_max | τ):\n"
    )?;
    writeln!(
        table_c,
        "| criterion | p | e = 0.1 | e = 0.5 | e = 0.9 |\n|---|---|---|---|---|"
    )?;
    for scheme in [Scheme::VelocityVerlet, Scheme::SymplecticEuler] {
        let mut panels: Vec<Vec<Panel>> = vec![Vec::new(), Vec::new(), Vec::new()];
        for crit in CRITS {
            let mut rows: Vec<String> = PS
                .iter()
                .map(|p| format!("| {} | {p} |", crit_name(crit)))
                .collect();
            for &e in &ES {
                let mut ps: Vec<Panel> = (0..3)
                    .map(|q| {
                        Panel::new(
                            format!("{}, e = {e}", crit_name(crit)),
                            "dt/τ (dimensionless)",
                            format!("worst |rel. error| of {} (dimensionless)", quantities[q]),
                        )
                        .log(true, true)
                        .legend(SeriesLabelPosition::LowerRight)
                    })
                    .collect();
                for (ip, &p) in PS.iter().enumerate() {
                    let alpha = alpha_from_e(e, p, crit)?;
                    let r =
                        reference::collide(p, alpha, 1.0, 1.0, crit, 1e-12).ok_or("reference")?;
                    let mut pts: [Vec<(f64, f64)>; 3] = Default::default();
                    for &f in &grid {
                        let w = worst_errors(p, e, crit, scheme, f * r.tau, &r);
                        for q in 0..3 {
                            pts[q].push((f, w[q].max(1e-16)));
                        }
                    }
                    if scheme == Scheme::VelocityVerlet {
                        let w = worst_errors(p, e, crit, scheme, 0.01 * r.tau, &r);
                        write!(
                            rows[ip],
                            " {:.2} \\| {:.2} \\| {:.2} |",
                            w[0] / 0.01,
                            w[1] / 0.01,
                            w[2] / 0.01
                        )?;
                    }
                    for q in 0..3 {
                        ps[q].add(Series::new(
                            format!("p = {p}"),
                            pts[q].clone(),
                            Kind::LinePoints,
                            ip,
                        ));
                    }
                }
                for q in 0..3 {
                    let slope1: Vec<(f64, f64)> = vec![(1e-3, 1e-3), (0.3, 0.3)];
                    let mut pn = std::mem::replace(&mut ps[q], Panel::new("", "", ""));
                    pn.add(Series::new(
                        "slope 1: error = dt/τ",
                        slope1,
                        Kind::Dashed,
                        7,
                    ));
                    panels[q].push(pn);
                }
            }
            if scheme == Scheme::VelocityVerlet {
                for r in rows {
                    writeln!(table_c, "{r}")?;
                }
            }
        }
        let sname = match scheme {
            Scheme::VelocityVerlet => "vv",
            Scheme::SymplecticEuler => "se",
        };
        for q in 0..3 {
            let file = format!("dt_{sname}_{}.png", files[q]);
            figure(&rep.fig_path(&file), &panels[q], 3, (560, 420))?;
            rep.figure(
                &mut md,
                &file,
                &format!("{}: worst relative error of {} against dt/τ", scheme_name(scheme), quantities[q]),
                &match q {
                    0 => format!("read the dt/τ at which your tolerance on e is crossed; {} errors in e grow linearly in dt (first order: the dashpot term switches on non-smoothly at impact and, for the overlap end, off while attractive), so halving dt halves the error.", scheme_name(scheme)),
                    1 => "read the δ_max error (largest overlap seen at a step): first order too for damped contacts, of the same size as the e error, because the first contact step already mis-applies the dashpot force; only at e = 0.9 and large steps does the second-order sampling of the peak dominate.".into(),
                    _ => "read the τ error: first order (the end of contact is located only to within a step), similar for both criteria.".into(),
                },
            )?;
        }
    }
    // The two schemes produce the same positions (see docs/timestep.md): measure the difference.
    let mut diff = [0.0f64; 3];
    for crit in CRITS {
        for &p in &PS {
            for &e in &ES {
                let pair = powerlaw(p, 1.0, e, crit)?;
                for &dt in &[0.003, 0.03, 0.3] {
                    for i in 0..8 {
                        let ph = (i as f64 + 0.5) / 8.0;
                        let a = collide(
                            &pair,
                            1.0,
                            1.0,
                            1.0,
                            dt,
                            ph,
                            Scheme::VelocityVerlet,
                            1_000_000,
                        )?;
                        let b = collide(
                            &pair,
                            1.0,
                            1.0,
                            1.0,
                            dt,
                            ph,
                            Scheme::SymplecticEuler,
                            1_000_000,
                        )?;
                        diff[0] = diff[0].max(((a.e - b.e) / a.e).abs());
                        diff[1] = diff[1].max(((a.delta_max - b.delta_max) / a.delta_max).abs());
                        diff[2] = diff[2].max(((a.duration - b.duration) / a.duration).abs());
                    }
                }
            }
        }
    }
    writeln!(
        md,
        "**The two schemes give the same collision.** Velocity-Verlet with the dashpot fed the half-step velocity is \
symplectic Euler (kick then drift) in disguise: both produce x_{{n+1}} = x_n + dt·v_{{n+½}}, v_{{n+½}} = v_{{n−½}} + dt·a(x_n, v_{{n−½}}), \
and after separation the reported velocity is the half-step one. Largest relative difference over the whole grid \
(both criteria, p, e, dt ∈ {{0.003, 0.03, 0.3}}, 8 phases): e {:.1e}, δ_max {:.1e}, τ {:.1e}. So the symplectic Euler \
figures equal the velocity-Verlet ones.\n",
        diff[0], diff[1], diff[2]
    )?;
    md.push_str(&table_c);
    md.push('\n');
    rep.push(&md);
    Ok(())
}

/// The largest stable step of a resting contact under load g = 1 (δ_eq = 1, ω_eq = √p), by bisection.
fn unstable_dt(p: f64, e: f64, scheme: Scheme) -> f64 {
    let pair = powerlaw(p, 1.0, e, EndCriterion::Force).expect("pair");
    let scale = 2.0 / p.sqrt();
    let stable =
        |dt: f64| resting_contact_stable(&pair, 1.0, 1.0, 1.0, 1.0, 1.001, dt, scheme, 20_000);
    let (mut lo, mut hi) = (0.05 * scale, 3.0 * scale);
    if !stable(lo) {
        return f64::NAN;
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if stable(mid) { lo = mid } else { hi = mid }
    }
    lo
}

pub fn stability(rep: &mut Report) -> Res<()> {
    let mut md = String::new();
    writeln!(
        md,
        "### Resting contact under a constant load: where the integration becomes unstable\n"
    )?;
    writeln!(
        md,
        "A body pressed by a constant load (g = 1, k = 1, m = 1, so δ_eq = 1 and ω_eq = ω0 √p δ_eq^((p−1)/2) = √p) starts \
at rest at 1.001 δ_eq; a step is stable when, over the second half of 20 000 steps, |δ − δ_eq| stays within 10× the \
initial deviation (bisection, 40 halvings; a bounded limit cycle of the clamped force counts as unstable). \
The ratio to the linearised bound 2/ω_eq is shown, next to `dc_dt_crit` for the impact speed whose undamped δ_max \
equals δ_eq (v0 = ω0 √(2/(p+1)) δ_eq^((p+1)/2)), and next to the linear analysis of velocity-Verlet with the \
dashpot at the half-step velocity, `powerlaw::timestep::dt_static` = (2/ω_eq)(√(1+ζ_eq²) − ζ_eq), ζ_eq = α/(2√p) \
(markers). Clamped (DC_END_FORCE) pairs.\n"
    )?;
    let es: Vec<f64> = (1..=10).map(|i| i as f64 / 10.0).collect();
    let mut panels = Vec::new();
    let mut theory_rows: Vec<String> = Vec::new();
    writeln!(
        md,
        "| p | scheme | e = 0.1 | 0.3 | 0.5 | 0.7 | 0.9 | 1.0 | dc_dt_crit/(2/ω_eq) |\n|---|---|---|---|---|---|---|---|---|"
    )?;
    for scheme in [Scheme::VelocityVerlet, Scheme::SymplecticEuler] {
        let mut pn = Panel::new(
            format!(
                "{}: stability limit of a resting contact",
                scheme_name(scheme)
            ),
            "target restitution e (dimensionless)",
            "dt / (2/ω_eq) (dimensionless)",
        )
        .legend(SeriesLabelPosition::UpperLeft)
        .yrange(0.0, 2.0);
        for (ip, &p) in PS.iter().enumerate() {
            let pts: Vec<(f64, f64)> = es
                .iter()
                .map(|&e| (e, unstable_dt(p, e, scheme) / (2.0 / p.sqrt())))
                .collect();
            let v0 = (2.0 / (p + 1.0)).sqrt();
            let crit_ratio = dt_crit_seed(p, v0, 1.0)? / (2.0 / p.sqrt());
            let mut row = format!("| {p} | {} |", scheme_name(scheme));
            for &(e, r) in &pts {
                if [0.1, 0.3, 0.5, 0.7, 0.9, 1.0]
                    .iter()
                    .any(|&x| (x - e).abs() < 1e-9)
                {
                    write!(row, " {r:.3} |")?;
                }
            }
            writeln!(md, "{row} {crit_ratio:.3} |")?;
            pn.add(Series::new(
                format!("measured, p = {p}"),
                pts,
                Kind::Line,
                ip,
            ));
            let name = |s: &str| {
                if ip == 0 {
                    s.to_string()
                } else {
                    String::new()
                }
            };
            pn.add(Series::new(
                name("dc_dt_crit (dashed, colour = p)"),
                vec![(0.1, crit_ratio), (1.0, crit_ratio)],
                Kind::Dashed,
                ip,
            ));
            // The linear analysis of velocity-Verlet with half-step damping (powerlaw::timestep::dt_static).
            let lin: Vec<(f64, f64)> = es
                .iter()
                .map(|&e| {
                    let a = alpha_from_e(e, p, EndCriterion::Force).unwrap_or(f64::NAN);
                    (
                        e,
                        dt_static(p, a, 1.0, 1.0).unwrap_or(f64::NAN) / (2.0 / p.sqrt()),
                    )
                })
                .collect();
            if scheme == Scheme::VelocityVerlet {
                let mut row = format!("| {p} | linear theory (dt_static) |");
                for &(e, r) in &lin {
                    if [0.1, 0.3, 0.5, 0.7, 0.9, 1.0]
                        .iter()
                        .any(|&x| (x - e).abs() < 1e-9)
                    {
                        write!(row, " {r:.3} |")?;
                    }
                }
                theory_rows.push(row + " |");
            }
            pn.add(Series::new(
                name("linear theory dt_static (markers)"),
                lin,
                Kind::Points,
                ip,
            ));
        }
        pn.add(Series::new(
            "linearised bound 2/ω_eq",
            vec![(0.1, 1.0), (1.0, 1.0)],
            Kind::Line,
            7,
        ));
        panels.push(pn);
    }
    for r in theory_rows {
        writeln!(md, "{r}")?;
    }
    writeln!(md)?;
    let file = "stability_resting.png";
    figure(&rep.fig_path(file), &panels, 2, (760, 600))?;
    rep.figure(
        &mut md,
        file,
        "largest stable step of a resting contact, relative to 2/ω_eq",
        "read that the measured limit (lines) follows the damped linear theory (markers) and falls well below 2/ω_eq with damping, while dc_dt_crit (seed eq. 32) lies above the limit for p > 1 and is therefore unsafe there.",
    )?;
    rep.push(&md);
    Ok(())
}

pub fn accuracy(rep: &mut Report) -> Res<()> {
    let mut md = String::new();
    writeln!(
        md,
        "### `dc_dt_for_accuracy`: the step for a tolerance on e\n"
    )?;
    writeln!(
        md,
        "`dc_dt_for_accuracy(p, e, criterion, v0, omega0, tol, &dt)` (v0 = ω0 = 1 here). Check columns: the worst relative \
error of e over 61 evenly spaced start phases (a different set from the function's 64, sharing only 0 and 1⁻) at the returned dt and at 2 dt, divided by tol; the time per call is this machine's wall clock.\n"
    )?;
    writeln!(
        md,
        "| criterion | p | e | tol | dt/τ | E(dt)/tol | E(2dt)/tol | time per call |\n|---|---|---|---|---|---|---|---|"
    )?;
    let tols = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4];
    let mut panels = Vec::new();
    for crit in CRITS {
        let mut pn = Panel::new(
            format!("{}: dt_for_accuracy", crit_name(crit)),
            "tolerance on e (relative, dimensionless)",
            "returned dt / τ (dimensionless)",
        )
        .log(true, true)
        .legend(SeriesLabelPosition::LowerRight);
        let mut color = 0;
        for &p in &[1.0, 1.5, 3.0] {
            for &e in &[0.1, 0.5, 0.9] {
                let alpha = alpha_from_e(e, p, crit)?;
                let r = reference::collide(p, alpha, 1.0, 1.0, crit, 1e-12).ok_or("reference")?;
                let pair = powerlaw_from_alpha(p, 1.0, alpha, crit)?;
                let mut pts = Vec::new();
                for &tol in &tols {
                    let t0 = std::time::Instant::now();
                    let dt = dt_for_accuracy(p, e, crit, 1.0, 1.0, tol)?;
                    let el = t0.elapsed();
                    pts.push((tol, dt / r.tau));
                    if tol == 1e-2 || tol == 1e-3 {
                        let a = worst_restitution_error(&pair, e, r.tau, dt, 61) / tol;
                        let b = worst_restitution_error(&pair, e, r.tau, 2.0 * dt, 61) / tol;
                        writeln!(
                            md,
                            "| {} | {p} | {e} | {tol:.0e} | {:.3e} | {a:.2} | {b:.2} | {:.1} ms |",
                            crit_name(crit),
                            dt / r.tau,
                            el.as_secs_f64() * 1e3
                        )?;
                    }
                }
                pn.add(Series::new(
                    format!("p = {p}, e = {e}"),
                    pts,
                    Kind::LinePoints,
                    color,
                ));
                color += 1;
            }
        }
        panels.push(pn);
    }
    writeln!(md)?;
    let file = "dt_for_accuracy.png";
    figure(&rep.fig_path(file), &panels, 2, (640, 480))?;
    rep.figure(
        &mut md,
        file,
        "the step dc_dt_for_accuracy returns, against the tolerance",
        "read dt/τ for your tolerance: proportional to tol (first-order error), about 0.2·tol at e = 0.1 and about tol at e = 0.5; weakly damped contacts reach the τ/8 cap.",
    )?;
    rep.push(&md);
    Ok(())
}
