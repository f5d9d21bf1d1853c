//! Section 1: cost against error for every quantity that has more than one way to compute it.

use crate::Report;
use crate::plot::{Kind, Panel, Res, Series, figure};
use crate::reference;
use demcontact::EndCriterion;
use demcontact::force::powerlaw::powerlaw_from_alpha;
use demcontact::powerlaw::{alpha_from_e, e_from_alpha};
use demcontact::timestep::{Scheme, collide};
use plotters::prelude::SeriesLabelPosition;
use std::fmt::Write;
use std::hint::black_box;

/// Wall-clock ns per call: repeats `f` until 20 ms have passed (at least 3 calls).
pub fn ns_per_call(mut f: impl FnMut() -> f64) -> f64 {
    black_box(f());
    let t0 = std::time::Instant::now();
    let mut n = 0u64;
    loop {
        black_box(f());
        n += 1;
        let el = t0.elapsed().as_secs_f64();
        if (el > 0.02 && n >= 3) || el > 0.5 {
            return el * 1e9 / n as f64;
        }
    }
}

pub struct Row {
    pub quantity: &'static str,
    pub method: String,
    pub family: &'static str,
    pub ns: f64,
    pub err: f64,
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs().max(1e-17)
}

/// The power-law rows: e, δ_max, τ of one collision (p = 3/2, e = 0.5, both criteria mixed in
/// the table by quantity), by closed form, reference ODE at several rtol, and velocity-Verlet.
fn powerlaw_rows(rows: &mut Vec<Row>) -> Res<()> {
    let (p, e_t, crit) = (1.5, 0.5, EndCriterion::Force);
    let alpha = alpha_from_e(e_t, p, crit)?;
    let truth = reference::collide(p, alpha, 1.0, 1.0, crit, 1e-13).ok_or("reference")?;
    rows.push(Row {
        quantity: "e",
        method: "closed form e_from_alpha".into(),
        family: "closed form",
        ns: ns_per_call(|| e_from_alpha(black_box(alpha), p, crit).unwrap_or(0.0)),
        err: rel(e_from_alpha(alpha, p, crit)?, e_t),
    });
    for &rtol in &[1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
        let r = reference::collide(p, alpha, 1.0, 1.0, crit, rtol).ok_or("reference")?;
        let ns = ns_per_call(|| {
            reference::collide(p, black_box(alpha), 1.0, 1.0, crit, rtol).map_or(0.0, |r| r.e)
        });
        let m = format!("ODE reference rtol {rtol:.0e}");
        rows.push(Row {
            quantity: "e",
            method: m.clone(),
            family: "ODE reference",
            ns,
            err: rel(r.e, e_t),
        });
        rows.push(Row {
            quantity: "δ_max",
            method: m.clone(),
            family: "ODE reference",
            ns,
            err: rel(r.delta_max, truth.delta_max),
        });
        rows.push(Row {
            quantity: "τ (force end)",
            method: m,
            family: "ODE reference",
            ns,
            err: rel(r.tau, truth.tau),
        });
    }
    let pair = powerlaw_from_alpha(p, 1.0, alpha, crit)?;
    for &f in &[0.1, 0.03, 0.01, 0.003, 0.001] {
        let dt = f * truth.tau;
        let steps = (100.0 / f) as u32;
        let mut w = [0.0f64; 3];
        for i in 0..16 {
            let c = collide(
                &pair,
                1.0,
                1.0,
                1.0,
                dt,
                (i as f64 + 0.5) / 16.0,
                Scheme::VelocityVerlet,
                steps,
            )?;
            w[0] = w[0].max(rel(c.e, e_t));
            w[1] = w[1].max(rel(c.delta_max, truth.delta_max));
            w[2] = w[2].max(rel(c.duration, truth.tau));
        }
        let ns = ns_per_call(|| {
            collide(
                &pair,
                1.0,
                1.0,
                1.0,
                black_box(dt),
                0.5,
                Scheme::VelocityVerlet,
                steps,
            )
            .map_or(0.0, |c| c.e)
        });
        let m = format!("velocity-Verlet dt = {f}·τ (worst of 16 phases)");
        rows.push(Row {
            quantity: "e",
            method: m.clone(),
            family: "velocity-Verlet",
            ns,
            err: w[0],
        });
        rows.push(Row {
            quantity: "δ_max",
            method: m.clone(),
            family: "velocity-Verlet",
            ns,
            err: w[1],
        });
        rows.push(Row {
            quantity: "τ (force end)",
            method: m,
            family: "velocity-Verlet",
            ns,
            err: w[2],
        });
    }
    Ok(())
}

pub fn run(rep: &mut Report) -> Res<()> {
    let mut rows = Vec::new();
    powerlaw_rows(&mut rows)?;
    extra_rows(&mut rows)?;
    let mut md = String::new();
    writeln!(md, "## 1. Cost against error\n")?;
    writeln!(
        md,
        "Power-law rows: one Hertz-exponent collision (p = 3/2, e = 0.5, DC_END_FORCE unless the row says overlap end, \
v0 = ω0 = 1). Truth: the calibrated e itself (exact by construction), and δ_max, τ from the reference at rtol 1e-13 \
(so errors below ~1e-12 are the reference's own). Closed-form and quadrature rows include `Contact::new` (the \
validated set-up of one collision). A velocity-Verlet row \
costs one whole simulated collision; its error is the worst over 16 start phases.\n"
    )?;
    writeln!(
        md,
        "| quantity | method | ns per call | relative error |\n|---|---|---|---|"
    )?;
    for r in &rows {
        writeln!(
            md,
            "| {} | {} | {:.3e} | {:.1e} |",
            r.quantity, r.method, r.ns, r.err
        )?;
    }
    writeln!(md)?;
    let mut quantities: Vec<&str> = Vec::new();
    for r in &rows {
        if !quantities.contains(&r.quantity) {
            quantities.push(r.quantity);
        }
    }
    let mut panels = Vec::new();
    for q in &quantities {
        let mut pn = Panel::new(
            format!("{q}"),
            "cost (ns per call, this machine)",
            "relative error (dimensionless)",
        )
        .log(true, true)
        .legend(SeriesLabelPosition::UpperRight);
        let mut fams: Vec<&str> = Vec::new();
        for r in rows.iter().filter(|r| r.quantity == *q) {
            if !fams.contains(&r.family) {
                fams.push(r.family);
            }
        }
        for (i, fam) in fams.iter().enumerate() {
            let pts: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.quantity == *q && r.family == *fam)
                .map(|r| (r.ns, r.err))
                .collect();
            let kind = if pts.len() > 1 {
                Kind::LinePoints
            } else {
                Kind::Points
            };
            pn.add(Series::new(*fam, pts, kind, i));
        }
        panels.push(pn);
    }
    let file = "cost_vs_error.png";
    figure(&rep.fig_path(file), &panels, 2, (600, 440))?;
    rep.figure(
        &mut md,
        file,
        "cost against relative error, one panel per quantity",
        "read the cheapest method that meets your error: the closed forms sit at the bottom left (ns, full precision); the reference buys accuracy with microseconds; a DEM time step buys it with steps, at first order.",
    )?;
    rep.push(&md);
    Ok(())
}

/// Rows from the contact calculus: δ_max in closed form, τ under the force end by
/// Jacobi–Clenshaw–Curtis quadrature at levels 0..=4 and under the overlap end in closed form
/// (complex log-gamma), against the reference.
fn calculus_rows(rows: &mut Vec<Row>) -> Res<()> {
    use demcontact::numerics::jacobi_cc::evaluations;
    use demcontact::powerlaw::{Contact, contact_duration, max_overlap};
    let p = 1.5;
    for (crit, e_t, q) in [
        (EndCriterion::Force, 0.5, "τ (force end)"),
        (EndCriterion::Overlap, 0.5, "τ (overlap end)"),
    ] {
        let alpha = alpha_from_e(e_t, p, crit)?;
        let truth = reference::collide(p, alpha, 1.0, 1.0, crit, 1e-13).ok_or("reference")?;
        let c = Contact::new(p, alpha, 1.0, 1.0)?;
        if crit == EndCriterion::Force {
            let ns = ns_per_call(|| {
                Contact::new(p, black_box(alpha), 1.0, 1.0)
                    .and_then(|c| max_overlap(&c))
                    .unwrap_or(0.0)
            });
            rows.push(Row {
                quantity: "δ_max",
                method: "max_overlap (closed form, with Contact::new)".into(),
                family: "closed form",
                ns,
                err: rel(max_overlap(&c)?, truth.delta_max),
            });
            for level in 0..=4u32 {
                let ns = ns_per_call(|| {
                    Contact::new(p, black_box(alpha), 1.0, 1.0)
                        .and_then(|c| contact_duration(&c, crit, level))
                        .unwrap_or(0.0)
                });
                rows.push(Row {
                    quantity: q,
                    method: format!(
                        "contact_duration, quadrature level {level} ({} evaluations)",
                        evaluations(level)
                    ),
                    family: "quadrature",
                    ns,
                    err: rel(contact_duration(&c, crit, level)?, truth.tau),
                });
            }
        } else {
            let ns = ns_per_call(|| {
                Contact::new(p, black_box(alpha), 1.0, 1.0)
                    .and_then(|c| contact_duration(&c, crit, 4))
                    .unwrap_or(0.0)
            });
            rows.push(Row {
                quantity: q,
                method: "contact_duration (closed form, complex log-gamma)".into(),
                family: "closed form",
                ns,
                err: rel(contact_duration(&c, crit, 4)?, truth.tau),
            });
            for &rtol in &[1e-4, 1e-8, 1e-12] {
                let r = reference::collide(p, alpha, 1.0, 1.0, crit, rtol).ok_or("reference")?;
                let ns = ns_per_call(|| {
                    reference::collide(p, black_box(alpha), 1.0, 1.0, crit, rtol)
                        .map_or(0.0, |r| r.tau)
                });
                rows.push(Row {
                    quantity: q,
                    method: format!("ODE reference rtol {rtol:.0e}"),
                    family: "ODE reference",
                    ns,
                    err: rel(r.tau, truth.tau),
                });
            }
        }
    }
    Ok(())
}

/// Rows from the viscoelastic module: e(b) by the published series, the full-range
/// Chebyshev tables and the reference integrator at several tolerances; truth = the reference at
/// its default tolerance.
fn viscoelastic_rows(rows: &mut Vec<Row>) -> Res<()> {
    use demcontact::viscoelastic::full_range::e_full;
    use demcontact::viscoelastic::reference::{e_reference, e_reference_tol};
    use demcontact::viscoelastic::series::e_series;
    let crit = EndCriterion::Force;
    for (b, q) in [
        (0.1, "viscoelastic e(b = 0.1), force end"),
        (0.6, "viscoelastic e(b = 0.6), force end"),
    ] {
        let truth = e_reference(b, crit)?;
        rows.push(Row {
            quantity: q,
            method: "published series (Schwager & Pöschel)".into(),
            family: "series",
            ns: ns_per_call(|| e_series(black_box(b), crit).unwrap_or(0.0)),
            err: rel(e_series(b, crit)?, truth),
        });
        rows.push(Row {
            quantity: q,
            method: "full-range Chebyshev tables".into(),
            family: "tables",
            ns: ns_per_call(|| e_full(black_box(b), crit).unwrap_or(0.0)),
            err: rel(e_full(b, crit)?, truth),
        });
        for &tol in &[1e-6, 1e-10, 1e-14] {
            rows.push(Row {
                quantity: q,
                method: format!("reference integrator, tol {tol:.0e}"),
                family: "reference integrator",
                ns: ns_per_call(|| e_reference_tol(black_box(b), crit, tol).unwrap_or(0.0)),
                err: rel(e_reference_tol(b, crit, tol)?, truth),
            });
        }
    }
    Ok(())
}

fn extra_rows(rows: &mut Vec<Row>) -> Res<()> {
    calculus_rows(rows)?;
    viscoelastic_rows(rows)
}
