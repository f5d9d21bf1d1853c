//! `demcontact fit`: the viscoelastic and constant-e fits of measured restitution, or
//! (`--model elastic-plastic`) the yield speed and limiting pressure of Thornton's law.

use crate::output::{Failure, Output, num};
use crate::{csv, plot, refused};
use demcontact::EndCriterion;
use demcontact::fit::{self, Data, FitOptions, ModelChoice};
use demcontact::viscoelastic::full_range::e_full;
use serde_json::json;
use std::fmt::Write;
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// CSV file: v [m/s], e[, sigma] (header optional, '#' comments).
    file: PathBuf,
    /// Tolerance on e: the constant-e model suffices when the speed dependence stays within it.
    #[arg(long, default_value_t = 0.02)]
    tol: f64,
    /// The host ends contacts at zero overlap (no force clamp); default: clamped (force end).
    #[arg(long)]
    overlap_end: bool,
    /// Huber-robust fit (IRLS, c = 1.345) instead of least squares.
    #[arg(long)]
    robust: bool,
    /// Write a PNG figure of the data and both fits.
    #[arg(long)]
    plot: Option<PathBuf>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
    /// Model to fit: `auto` (viscoelastic and constant e, the choice at --tol) or
    /// `elastic-plastic` (Thornton 1997: the yield speed v_y; p_y with --e-star, --r-eff, --m-eff).
    #[arg(long, value_enum, default_value_t = FitModel::Auto)]
    model: FitModel,
    /// Effective modulus E* [Pa] of the contact (elastic-plastic: gives p_y).
    #[arg(long)]
    e_star: Option<f64>,
    /// Effective radius R* [m] (elastic-plastic: gives p_y).
    #[arg(long)]
    r_eff: Option<f64>,
    /// Effective mass m* [kg] (elastic-plastic: gives p_y).
    #[arg(long)]
    m_eff: Option<f64>,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
enum FitModel {
    Auto,
    ElasticPlastic,
}

/// `--model elastic-plastic`: v_y by least squares, p_y when E*, R*, m* are given.
fn run_elastic_plastic(a: &Args, name: &str, t: &csv::Table) -> Result<Output, Failure> {
    use demcontact::fit::elastic_plastic::fit_yield_speed;
    use demcontact::force::elastic_plastic::{restitution, yield_pressure_from_speed};
    let data = Data {
        v: &t.v,
        e: &t.e,
        sigma: t.sigma.as_deref(),
    };
    let f = fit_yield_speed(&data).map_err(|e| refused(&format!("fit of {name}"), e))?;
    // p_y and its 95 % interval: p_y is increasing in v_y (∝ v_y^{2/5}), so the interval's ends
    // are the pressures of v_y's.
    let p_y = match (a.e_star, a.r_eff, a.m_eff) {
        (Some(es), Some(r), Some(m)) => {
            let p = |v| {
                yield_pressure_from_speed(es, r, m, v)
                    .map_err(|e| refused("p_y from --e-star, --r-eff, --m-eff", e))
            };
            Some((p(f.v_y)?, p(f.v_y_lo95)?, p(f.v_y_hi95)?))
        }
        (None, None, None) => None,
        _ => {
            return Err(Failure::usage(
                "--e-star, --r-eff and --m-eff go together (p_y needs all three)".into(),
            ));
        }
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{name}: {} points, elastic-plastic (Thornton 1997): v_y = {:.6e} m/s (chi2 {:.4e}, max |resid| {:.4})",
        t.v.len(),
        f.v_y,
        f.chi2,
        f.max_residual
    );
    let _ = writeln!(
        s,
        "v_y 95 % interval [{:.6e}, {:.6e}] m/s (SE of ln v_y {:.3e}, {})",
        f.v_y_lo95,
        f.v_y_hi95,
        f.ln_v_y_se,
        if f.se_from_scatter {
            "sigma from the scatter"
        } else {
            "sigma given"
        }
    );
    match p_y {
        Some((p, lo, hi)) => {
            let _ = writeln!(
                s,
                "limiting contact pressure p_y = {p:.6e} Pa, 95 % interval [{lo:.6e}, {hi:.6e}] Pa"
            );
        }
        None => {
            let _ = writeln!(s, "p_y: give --e-star, --r-eff, --m-eff");
        }
    }
    let mut rows = Vec::new();
    for (i, (&v, &e)) in t.v.iter().zip(&t.e).enumerate() {
        let g = restitution(v / f.v_y).unwrap_or(f64::NAN);
        let _ = writeln!(s, "{v:>10.4} {e:>8.4} {g:>10.5} {:>+9.5}", e - g);
        rows.push(json!({"line": t.line.get(i), "v": num(v), "e": num(e), "e_fit": num(g)}));
    }
    let json = json!({
        "command": "fit", "file": name, "model": "elastic-plastic", "v_y": num(f.v_y),
        "v_y_lo95": num(f.v_y_lo95), "v_y_hi95": num(f.v_y_hi95), "ln_v_y_se": num(f.ln_v_y_se),
        "quantile95": num(f.quantile95), "se_from_scatter": f.se_from_scatter,
        "p_y": p_y.map(|p| num(p.0)), "p_y_lo95": p_y.map(|p| num(p.1)),
        "p_y_hi95": p_y.map(|p| num(p.2)), "chi2": num(f.chi2), "max_residual": num(f.max_residual),
        "points": rows,
    });
    Ok(Output { text: s, json })
}

pub fn run(a: &Args) -> Result<Output, Failure> {
    let name = a.file.display().to_string();
    let text_in = std::fs::read_to_string(&a.file)
        .map_err(|e| Failure::input(&name, 0, 0, format!("cannot read: {e}")))?;
    let t = csv::parse(&name, &text_in)?;
    if a.model == FitModel::ElasticPlastic {
        return run_elastic_plastic(a, &name, &t);
    }
    let crit = if a.overlap_end {
        EndCriterion::Overlap
    } else {
        EndCriterion::Force
    };
    let data = Data {
        v: &t.v,
        e: &t.e,
        sigma: t.sigma.as_deref(),
    };
    let opt = FitOptions {
        criterion: crit,
        tol: a.tol,
        robust: a.robust,
    };
    let f = fit::fit_restitution(&data, &opt).map_err(|e| refused(&format!("fit of {name}"), e))?;
    let n = t.v.len();
    let (mut rv, mut rc) = (vec![0.0; n], vec![0.0; n]);
    fit::residuals(&data, &f, crit, &mut rv, &mut rc).map_err(|e| refused("residuals", e))?;
    let fitted = |v: f64| e_full(f.beta * v.powf(0.2), crit).unwrap_or(f64::NAN);
    let choice = match f.model {
        ModelChoice::Constant => "constant e (power law)",
        ModelChoice::Viscoelastic => "viscoelastic",
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{name}: {n} points, v = {} .. {} m/s, {}, {}{}",
        f.v_min,
        f.v_max,
        if t.sigma.is_some() {
            "weights 1/sigma^2"
        } else {
            "unweighted (errors from scatter)"
        },
        if a.overlap_end {
            "overlap end"
        } else {
            "force end (clamped)"
        },
        if a.robust { ", Huber-robust" } else { "" }
    );
    let _ = writeln!(
        s,
        "viscoelastic: beta = {:.6e} +- {:.2e} s^0.2 m^-0.2   (e = e(beta v^0.2); chi2 {:.4e}, max |resid| {:.4})",
        f.beta, f.beta_se, f.chi2_viscoelastic, f.max_residual_viscoelastic
    );
    let _ = writeln!(
        s,
        "              95 % interval {:.6e} .. {:.6e}   (beta +- {:.4} SE: {})",
        f.beta_lo95,
        f.beta_hi95,
        f.quantile95,
        if f.se_from_scatter {
            format!("Student t, {} degrees of freedom", n - 1)
        } else {
            "normal, sigma given".to_string()
        }
    );
    let _ = writeln!(
        s,
        "constant e:   e = {:.6} +- {:.2e}   (chi2 {:.4e}, max |resid| {:.4})",
        f.e_const, f.e_const_se, f.chi2_constant, f.max_residual_constant
    );
    let _ = writeln!(
        s,
        "speed dependence over the measured range: e = {:.4} .. {:.4}, largest deviation from constant {:.4}",
        f.e_viscoelastic_at_v_min, f.e_viscoelastic_at_v_max, f.max_model_deviation
    );
    let _ = writeln!(s, "model required at tol {}: {choice}", a.tol);
    let _ = writeln!(
        s,
        "{:>10} {:>8} {:>8} {:>10} {:>9} {:>9}",
        "v [m/s]", "e", "sigma", "e visco", "resid", "resid c"
    );
    let mut rows = Vec::new();
    for i in 0..n {
        let (v, e) = (
            t.v.get(i).copied().unwrap_or(f64::NAN),
            t.e.get(i).copied().unwrap_or(f64::NAN),
        );
        let sg = t.sigma.as_ref().and_then(|x| x.get(i).copied());
        let (r1, r2) = (
            rv.get(i).copied().unwrap_or(f64::NAN),
            rc.get(i).copied().unwrap_or(f64::NAN),
        );
        let _ = writeln!(
            s,
            "{v:>10.4} {e:>8.4} {:>8} {:>10.5} {r1:>+9.5} {r2:>+9.5}",
            sg.map_or("-".to_string(), |x| format!("{x:.4}")),
            fitted(v)
        );
        rows.push(json!({
            "line": t.line.get(i), "v": num(v), "e": num(e), "sigma": sg.map(num),
            "e_viscoelastic": num(fitted(v)), "residual_viscoelastic": num(r1),
            "residual_constant": num(r2),
        }));
    }
    if let Some(p) = &a.plot {
        plot::fit_figure(p, &t, &f, crit)?;
        let _ = writeln!(s, "figure: {}", p.display());
    }
    let json = json!({
        "command": "fit",
        "file": name,
        "n": n,
        "criterion": if a.overlap_end { "overlap" } else { "force" },
        "robust": a.robust,
        "tol": num(a.tol),
        "beta": num(f.beta), "beta_se": num(f.beta_se),
        "beta_lo95": num(f.beta_lo95), "beta_hi95": num(f.beta_hi95),
        "quantile95": num(f.quantile95),
        "e_const": num(f.e_const), "e_const_se": num(f.e_const_se),
        "chi2_viscoelastic": num(f.chi2_viscoelastic), "chi2_constant": num(f.chi2_constant),
        "max_residual_viscoelastic": num(f.max_residual_viscoelastic),
        "max_residual_constant": num(f.max_residual_constant),
        "v_min": num(f.v_min), "v_max": num(f.v_max),
        "e_viscoelastic_at_v_min": num(f.e_viscoelastic_at_v_min),
        "e_viscoelastic_at_v_max": num(f.e_viscoelastic_at_v_max),
        "max_model_deviation": num(f.max_model_deviation),
        "model": match f.model { ModelChoice::Constant => "constant", ModelChoice::Viscoelastic => "viscoelastic" },
        "se_from_scatter": f.se_from_scatter,
        "points": rows,
        "plot": a.plot.as_ref().map(|p| p.display().to_string()),
    });
    Ok(Output { text: s, json })
}
