//! `demcontact plan`: the softest Young's modulus and the largest step that meet a scene's
//! tolerances (the library's [`demcontact::plan`]; docs/plan.md).

use crate::output::{Failure, Output, describe, num};
use demcontact::EndCriterion;
use demcontact::plan::{self, PlanError, PlanField, PlanInput};
use serde_json::json;
use std::fmt::Write;

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Crit {
    /// The solver clamps attractive forces (LIGGGHTS limitForce, LAMMPS limit_damping, YADE).
    Force,
    /// The force may turn attractive; the contact ends at zero overlap.
    Overlap,
}

#[derive(clap::Args, Debug)]
#[allow(non_snake_case)]
pub struct Args {
    /// Real Young's modulus of the particles (and walls) [Pa].
    #[arg(long = "E1")]
    E1: f64,
    /// Poisson's ratio.
    #[arg(long)]
    nu1: f64,
    /// Particle density [kg/m³].
    #[arg(long)]
    rho1: f64,
    /// Target restitution, 0 < e ≤ 1 (calibrated exactly for --criterion).
    #[arg(long)]
    e: f64,
    /// Smallest particle radius [m].
    #[arg(long = "R-min")]
    R_min: f64,
    /// Largest particle radius [m] (≥ --R-min).
    #[arg(long = "R-max")]
    R_max: f64,
    /// Largest impact speed [m/s].
    #[arg(long = "v-max")]
    v_max: f64,
    /// Bed depth for the static load [m] (0: no bed).
    #[arg(long)]
    depth: f64,
    /// Gravity [m/s²].
    #[arg(long, default_value_t = 9.81)]
    g: f64,
    /// Sliding friction (recorded; does not enter the normal-contact bounds).
    #[arg(long, default_value_t = 0.0)]
    mu: f64,
    /// Rolling friction (recorded; does not enter the normal-contact bounds).
    #[arg(long = "mu-r", default_value_t = 0.0)]
    mu_r: f64,
    /// Largest δ_max/R at --v-max, 0 < X < 1.
    #[arg(long = "overlap-tol")]
    overlap_tol: f64,
    /// Largest relative error of the realised e at the step, 0 < Y < 1.
    #[arg(long = "e-tol")]
    e_tol: f64,
    /// Largest static δ/R under the bed load (default: --overlap-tol).
    #[arg(long = "static-tol")]
    static_tol: Option<f64>,
    /// Largest lengthening of the contact duration by softening, τ_soft/τ_real − 1 (default:
    /// no bound).
    #[arg(long = "duration-tol")]
    duration_tol: Option<f64>,
    /// Confining pressure added to the bed's weight [Pa].
    #[arg(long, default_value_t = 0.0)]
    pressure: f64,
    /// Solid fraction of the bed, 0 < φ < 1 (matters only with --pressure).
    #[arg(long, default_value_t = 0.6)]
    phi: f64,
    /// Coordination number Z (contacts per particle).
    #[arg(long, default_value_t = 6.0)]
    coordination: f64,
    /// Largest contact force over the mean contact force, ≥ 1.
    #[arg(long = "load-factor", default_value_t = 1.0)]
    load_factor: f64,
    /// How the host ends a contact.
    #[arg(long, value_enum, default_value = "force")]
    criterion: Crit,
    /// No walls in the scene (default: walls of the same material).
    #[arg(long = "no-walls")]
    no_walls: bool,
    /// Fraction of the resting-contact stability limit the step may use, 0 < f ≤ 1.
    #[arg(long = "stability-fraction", default_value_t = 0.5)]
    stability_fraction: f64,
    /// The conventional step for the speed-up: τ_real / this (real E).
    #[arg(long = "conventional-divisor", default_value_t = 50.0)]
    conventional_divisor: f64,
    /// Choose the step of the step-aware dashpot (dc_contact_model_set_step) instead of the
    /// plain one; both are reported either way.
    #[arg(long = "step-aware")]
    step_aware: bool,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

impl Args {
    fn input(&self) -> PlanInput {
        PlanInput {
            youngs: self.E1,
            poisson: self.nu1,
            density: self.rho1,
            restitution: self.e,
            radius_min: self.R_min,
            radius_max: self.R_max,
            v_max: self.v_max,
            depth: self.depth,
            gravity: self.g,
            pressure: self.pressure,
            solid_fraction: self.phi,
            coordination: self.coordination,
            load_factor: self.load_factor,
            friction: self.mu,
            rolling_friction: self.mu_r,
            overlap_tol: self.overlap_tol,
            e_tol: self.e_tol,
            static_tol: self.static_tol.unwrap_or(self.overlap_tol),
            duration_tol: self.duration_tol.unwrap_or(f64::INFINITY),
            criterion: match self.criterion {
                Crit::Force => EndCriterion::Force,
                Crit::Overlap => EndCriterion::Overlap,
            },
            walls: !self.no_walls,
            stability_fraction: self.stability_fraction,
            conventional_divisor: self.conventional_divisor,
        }
    }

    /// The flag (with its value) of a field, and the range it must lie in.
    fn flag(&self, f: PlanField) -> (String, &'static str) {
        let i = self.input();
        let v = |name: &str, x: f64| format!("{name} {x}");
        match f {
            PlanField::None => (String::new(), ""),
            PlanField::Youngs => (v("--E1", i.youngs), "must be > 0"),
            PlanField::Poisson => (v("--nu1", i.poisson), "must be in (-1, 0.5]"),
            PlanField::Density => (v("--rho1", i.density), "must be > 0"),
            PlanField::Restitution => (v("--e", i.restitution), "must be in (0, 1]"),
            PlanField::RadiusMin => (v("--R-min", i.radius_min), "must be > 0"),
            PlanField::RadiusMax => (
                format!("--R-min {} --R-max {}", i.radius_min, i.radius_max),
                "--R-max must be > 0 and >= --R-min",
            ),
            PlanField::VMax => (v("--v-max", i.v_max), "must be > 0"),
            PlanField::Depth => (v("--depth", i.depth), "must be >= 0"),
            PlanField::Gravity => (v("--g", i.gravity), "must be >= 0"),
            PlanField::Pressure => (v("--pressure", i.pressure), "must be >= 0"),
            PlanField::SolidFraction => (v("--phi", i.solid_fraction), "must be in (0, 1)"),
            PlanField::Coordination => (v("--coordination", i.coordination), "must be > 0"),
            PlanField::LoadFactor => (v("--load-factor", i.load_factor), "must be >= 1"),
            PlanField::Friction => (v("--mu", i.friction), "must be >= 0"),
            PlanField::RollingFriction => (v("--mu-r", i.rolling_friction), "must be >= 0"),
            PlanField::OverlapTol => (v("--overlap-tol", i.overlap_tol), "must be in (0, 1)"),
            PlanField::ETol => (v("--e-tol", i.e_tol), "must be in (0, 1)"),
            PlanField::StaticTol => (v("--static-tol", i.static_tol), "must be > 0"),
            PlanField::DurationTol => (v("--duration-tol", i.duration_tol), "must be > 0"),
            PlanField::Criterion => ("--criterion".into(), "force or overlap"),
            PlanField::Walls => ("--no-walls".into(), "a switch"),
            PlanField::StabilityFraction => (
                v("--stability-fraction", i.stability_fraction),
                "must be in (0, 1]",
            ),
            PlanField::ConventionalDivisor => (
                v("--conventional-divisor", i.conventional_divisor),
                "must be >= 1",
            ),
        }
    }

    fn failure(&self, pe: PlanError) -> Failure {
        let (flag, range) = self.flag(pe.field);
        let message = match (pe.field, pe.error) {
            (PlanField::None, e) => format!("plan: {}", describe(e)),
            (PlanField::ETol, e @ demcontact::Error::PlanInfeasible) => format!(
                "{flag}: {}: no step a scene can run meets it (the step puts more than {} steps \
                 in a contact, or its realised e misses the tolerance: e -> 0 with --criterion \
                 overlap needs ever finer steps; a looser --e-tol or --criterion force does not)",
                describe(e),
                plan::MAX_STEPS_PER_CONTACT
            ),
            (PlanField::StabilityFraction, e @ demcontact::Error::PlanInfeasible) => format!(
                "{flag}: {}: the step it leaves puts more than {} steps in a contact",
                describe(e),
                plan::MAX_STEPS_PER_CONTACT
            ),
            (PlanField::Restitution, e @ demcontact::Error::PlanInfeasible) => format!(
                "{flag}: {}: a contact this strongly damped does not converge (its duration or \
                 its collision at the step)",
                describe(e)
            ),
            (_, demcontact::Error::PlanInfeasible) => {
                // Name the real material's figure that misses the tolerance.
                let real = plan::evaluate(&self.input(), self.E1).ok();
                let figure = match (pe.field, real) {
                    (PlanField::OverlapTol, Some(r)) => format!(
                        "; the real modulus gives delta_max/R = {:.6e} ({} pair)",
                        r.max_overlap_ratio,
                        r.max_overlap_pair.name()
                    ),
                    (PlanField::StaticTol, Some(r)) => format!(
                        "; the real modulus gives static delta/R = {:.6e} ({} pair)",
                        r.static_overlap_ratio,
                        r.static_pair.name()
                    ),
                    _ => String::new(),
                };
                format!("{flag}: {}{figure}", describe(pe.error))
            }
            (PlanField::ETol, e @ demcontact::Error::StepUnreachable) => format!(
                "{flag}: {} (the step-aware dashpot meets it at no step down to t_H/8192)",
                describe(e)
            ),
            (_, e @ (demcontact::Error::RestitutionRange | demcontact::Error::PoissonRange)) => {
                format!("{flag}: {}", describe(e))
            }
            (_, e) => format!("{flag}: {} ({range})", describe(e)),
        };
        Failure::refused(message, pe.error)
    }
}

pub fn run(a: &Args) -> Result<Output, Failure> {
    let inp = a.input();
    let plain = plan::plan(&inp).map_err(|e| a.failure(e))?;
    // The step-aware step: always reported (null when unreachable), chosen with --step-aware
    // where it is the larger step.
    let sa = match plan::step_aware(&inp, &plain) {
        Ok(s) => Some(s),
        Err(e) if a.step_aware => return Err(a.failure(e)),
        Err(_) => None,
    };
    // Chosen only where it is the larger step: the step-aware calibration stops at t_H/10, and
    // where the plain dashpot meets --e-tol beyond that the plain step is kept.
    let chosen = a.step_aware && sa.is_some_and(|s| s.dt > plain.dt);
    let mut p = plain;
    let mut binding_dt = p.binding_dt.name().to_string();
    if let (true, Some(s)) = (chosen, sa) {
        p.dt = s.dt;
        p.speedup = s.speedup;
        p.dt_over_t_hertz = s.dt_over_t_hertz;
        p.steps_per_contact = s.steps_per_contact;
        binding_dt = format!("{} (step-aware)", s.binding_dt.name());
    }
    let crit = match a.criterion {
        Crit::Force => "force",
        Crit::Overlap => "overlap",
    };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Scene: E = {:e} Pa, nu = {}, rho = {} kg/m^3, e = {} ({crit} end), R = {:e} .. {:e} m, \
         v_max = {} m/s, bed {} m (stress {:.6e} Pa){}",
        inp.youngs,
        inp.poisson,
        inp.density,
        inp.restitution,
        inp.radius_min,
        inp.radius_max,
        inp.v_max,
        inp.depth,
        p.stress,
        if inp.walls { ", walls" } else { "" }
    );
    let _ = writeln!(
        t,
        "Tolerances: delta_max/R <= {}, |de/e| <= {}, static delta/R <= {}, duration change <= {}",
        inp.overlap_tol, inp.e_tol, inp.static_tol, inp.duration_tol
    );
    let row = |t: &mut String, name: &str, value: String, note: String| {
        let _ = writeln!(t, "  {name:<30} {value:<14} {note}");
    };
    row(
        &mut t,
        "Young's modulus (soft)",
        format!("{:.6e}", p.youngs_soft),
        format!(
            "Pa  ({:.4}x softer; binding: {})",
            p.softening,
            p.binding.name()
        ),
    );
    row(
        &mut t,
        "time step",
        format!("{:.6e}", p.dt),
        format!("s   (binding: {binding_dt})"),
    );
    match sa {
        Some(s) => row(
            &mut t,
            "  step-aware step",
            format!("{:.6e}", s.dt),
            format!(
                "s   ({:.4}x the plain {:.6e} s; speed-up {:.4}; dt = t_Hertz/{:.2}{})",
                s.gain,
                plain.dt,
                s.speedup,
                1.0 / s.dt_over_t_hertz,
                if chosen {
                    ", chosen"
                } else if a.step_aware {
                    "; not chosen: the plain step is larger"
                } else {
                    "; --step-aware to choose it"
                }
            ),
        ),
        None => row(
            &mut t,
            "  step-aware step",
            "none".into(),
            "(no step down to t_Hertz/8192 meets --e-tol)".into(),
        ),
    }
    row(
        &mut t,
        "  e-tol step",
        format!("{:.6e}", p.dt_restitution),
        "s".into(),
    );
    row(
        &mut t,
        "  resting-contact stability",
        format!("{:.6e}", p.dt_stability),
        format!("s   (x {} allowed)", inp.stability_fraction),
    );
    row(
        &mut t,
        "conventional step",
        format!("{:.6e}", p.dt_conventional),
        format!("s   (real E, tau_real/{})", inp.conventional_divisor),
    );
    row(
        &mut t,
        "speed-up",
        format!("{:.4}", p.speedup),
        "(dt ratio; cost per step unchanged)".into(),
    );
    row(
        &mut t,
        "max delta_max/R at v_max",
        format!("{:.6e}", p.max_overlap_ratio),
        format!(
            "({} pair; real E: {:.6e})",
            p.max_overlap_pair.name(),
            p.max_overlap_ratio_real
        ),
    );
    row(
        &mut t,
        "static delta/R",
        format!("{:.6e}", p.static_overlap_ratio),
        format!(
            "({} pair, force {:.6e} N; real E: {:.6e})",
            p.static_pair.name(),
            p.static_force,
            p.static_overlap_ratio_real
        ),
    );
    row(
        &mut t,
        "contact duration at v_max",
        format!("{:.6e}", p.duration),
        format!(
            "s   (min-min pair; real E: {:.6e} s, change {:+.4e})",
            p.duration_real, p.duration_change
        ),
    );
    row(
        &mut t,
        "steps per contact",
        format!("{:.2}", p.steps_per_contact),
        format!("(dt = t_Hertz/{:.2})", 1.0 / p.dt_over_t_hertz),
    );
    row(
        &mut t,
        if chosen {
            "e at the plain step (plain)"
        } else {
            "e realised at dt (plain)"
        },
        format!("{:.6}", p.e_plain_at_dt),
        format!(
            "(farthest of {} onset phases; range {:.6} .. {:.6}, mean {:.6})",
            plan::N_PHASE,
            p.e_plain_min,
            p.e_plain_max,
            p.e_plain_mean
        ),
    );
    let json = json!({
        "command": "plan",
        "criterion": crit,
        "walls": inp.walls,
        "youngs_real": num(inp.youngs),
        "youngs_soft": num(p.youngs_soft),
        "softening": num(p.softening),
        "binding": p.binding.name(),
        "dt": num(p.dt),
        "binding_dt": binding_dt,
        "step_aware_chosen": chosen,
        "dt_plain": num(plain.dt),
        "step_aware": sa.map(|s| json!({
            "dt": num(s.dt),
            "binding_dt": s.binding_dt.name(),
            "dt_restitution": num(s.dt_restitution),
            "gain": num(s.gain),
            "speedup": num(s.speedup),
            "dt_over_t_hertz": num(s.dt_over_t_hertz),
            "steps_per_contact": num(s.steps_per_contact),
        })),
        "dt_restitution": num(p.dt_restitution),
        "dt_stability": num(p.dt_stability),
        "dt_conventional": num(p.dt_conventional),
        "speedup": num(p.speedup),
        "alpha": num(p.alpha),
        "max_overlap_ratio": num(p.max_overlap_ratio),
        "max_overlap_pair": p.max_overlap_pair.name(),
        "max_overlap_ratio_real": num(p.max_overlap_ratio_real),
        "static_overlap_ratio": num(p.static_overlap_ratio),
        "static_pair": p.static_pair.name(),
        "static_overlap_ratio_real": num(p.static_overlap_ratio_real),
        "stress": num(p.stress),
        "static_force": num(p.static_force),
        "duration": num(p.duration),
        "duration_real": num(p.duration_real),
        "duration_change": num(p.duration_change),
        "t_hertz": num(p.t_hertz),
        "dt_over_t_hertz": num(p.dt_over_t_hertz),
        "steps_per_contact": num(p.steps_per_contact),
        "e_target": num(inp.restitution),
        "e_plain_at_dt": num(p.e_plain_at_dt),
        "e_plain_min": num(p.e_plain_min),
        "e_plain_max": num(p.e_plain_max),
        "e_plain_mean": num(p.e_plain_mean),
        "tolerances": {
            "overlap_tol": num(inp.overlap_tol),
            "e_tol": num(inp.e_tol),
            "static_tol": num(inp.static_tol),
            "duration_tol": num(inp.duration_tol),
        },
        "mu": num(inp.friction),
        "mu_r": num(inp.rolling_friction),
    });
    Ok(Output { text: t, json })
}
