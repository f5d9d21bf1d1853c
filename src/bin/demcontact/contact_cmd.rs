//! `demcontact contact`: one Hertz collision from material data; with `--dt`, the same
//! collision simulated at the host's step (the library's contact model, 64 onset phases) and the
//! restitution it realises, plain and (`--step-aware`) with dc_contact_model_set_step.

use crate::output::{Failure, Output, num};
use crate::refused;
use clap::ValueEnum;
use demcontact::contact::spec::{damping, normal};
use demcontact::contact::step_exact::{H_MAX, integrator, set_step};
use demcontact::contact::{ContactModel, ContactSpec, ContactState, contact_force, contact_model};
use demcontact::powerlaw::{self, Contact};
use demcontact::{EndCriterion, material, timestep};
use serde_json::{Value, json};
use std::fmt::Write;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Crit {
    /// The solver clamps attractive forces (LIGGGHTS limitForce, LAMMPS limit_damping, YADE).
    Force,
    /// The force may turn attractive; the contact ends at zero overlap.
    Overlap,
}

/// The host's integrator for `--dt`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Integ {
    /// Velocity Verlet in the LAMMPS/LIGGGHTS order (the force from the new position and the
    /// half-step velocity).
    Verlet,
    /// Symplectic Euler: the force from (x, v), then v, then x.
    Euler,
}

/// Contact-onset phases of the `--dt` collisions (the first contact step at a gap of j/64 of one
/// step's travel, j = 0..63), as dc_plan and docs/timestep.md.
const PHASES: usize = 64;
/// Largest t_H/dt `--dt` accepts: 64 collisions of that many steps stay under a second.
const MAX_STEPS_PER_CONTACT: f64 = 1e5;

/// Quadrature level for durations (DC_LEVEL_MAX: ~1e-12 relative).
const LEVEL: u32 = 4;
/// Trajectory samples for the peak force (flat at its maximum: relative error ~(π/n)²/2 ≈ 3e-7).
const SAMPLES: usize = 4001;

#[derive(clap::Args, Debug)]
#[allow(non_snake_case)]
pub struct Args {
    /// Young's modulus of body 1 [Pa].
    #[arg(long = "E1")]
    E1: f64,
    /// Poisson's ratio of body 1.
    #[arg(long)]
    nu1: f64,
    /// Density of body 1 [kg/m³].
    #[arg(long)]
    rho1: f64,
    /// Radius of body 1 [m].
    #[arg(long = "R1")]
    R1: f64,
    /// Young's modulus of body 2 (default: E1).
    #[arg(long = "E2")]
    E2: Option<f64>,
    /// Poisson's ratio of body 2 (default: nu1).
    #[arg(long)]
    nu2: Option<f64>,
    /// Density of body 2 (default: rho1; not used with --wall).
    #[arg(long)]
    rho2: Option<f64>,
    /// Radius of body 2 (default: R1; not used with --wall).
    #[arg(long = "R2")]
    R2: Option<f64>,
    /// Body 2 is a flat wall (infinite radius and mass) of material E2, nu2.
    #[arg(long)]
    wall: bool,
    /// Impact speed [m/s].
    #[arg(long)]
    v: f64,
    /// Target restitution, 0 < e ≤ 1.
    #[arg(long)]
    e: f64,
    /// How the host ends a contact.
    #[arg(long, value_enum, default_value = "force")]
    criterion: Crit,
    /// Relative accuracy of the realised e for the time step.
    #[arg(long, default_value_t = 1e-3)]
    tol: f64,
    /// The host's time step [s]: simulate the collision at this step (the library's contact
    /// model, 64 contact-onset phases) and print the restitution it realises.
    #[arg(long)]
    dt: Option<f64>,
    /// With --dt: also simulate with the step-aware damping (dc_contact_model_set_step), which
    /// realises the target e at that step.
    #[arg(long = "step-aware", requires = "dt")]
    step_aware: bool,
    /// With --dt: the host's integrator.
    #[arg(long, value_enum, default_value = "verlet", requires = "dt")]
    integrator: Integ,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

pub fn run(a: &Args) -> Result<Output, Failure> {
    let crit = match a.criterion {
        Crit::Force => EndCriterion::Force,
        Crit::Overlap => EndCriterion::Overlap,
    };
    let (e2, nu2) = (a.E2.unwrap_or(a.E1), a.nu2.unwrap_or(a.nu1));
    // Each body's material on its own first, so the message names the flag and value at fault.
    material::check_material(a.E1, a.nu1)
        .map_err(|e| refused(&format!("--E1 {} --nu1 {}", a.E1, a.nu1), e))?;
    material::check_material(e2, nu2).map_err(|e| refused(&format!("--E2 {e2} --nu2 {nu2}"), e))?;
    let e_star = material::effective_modulus(a.E1, a.nu1, e2, nu2)
        .map_err(|e| refused("effective modulus from --E1 --nu1 --E2 --nu2", e))?;
    let sphere_mass = |rho: f64, r: f64| rho * 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
    let m1 = sphere_mass(a.rho1, a.R1);
    if !(m1.is_finite() && m1 > 0.0) {
        return Err(refused(
            &format!("mass from --rho1 {} --R1 {}", a.rho1, a.R1),
            demcontact::Error::NotPositive,
        ));
    }
    let (r_star, m_star) = if a.wall {
        (
            material::effective_radius(a.R1, f64::INFINITY).map_err(|e| refused("--R1", e))?,
            m1,
        )
    } else {
        let (rho2, r2) = (a.rho2.unwrap_or(a.rho1), a.R2.unwrap_or(a.R1));
        let m2 = sphere_mass(rho2, r2);
        if !(m2.is_finite() && m2 > 0.0) {
            return Err(refused(
                &format!("mass from --rho2 {rho2} --R2 {r2}"),
                demcontact::Error::NotPositive,
            ));
        }
        (
            material::effective_radius(a.R1, r2).map_err(|e| refused("--R1 --R2", e))?,
            m1 * m2 / (m1 + m2),
        )
    };
    let k = material::hertz_stiffness(e_star, r_star).map_err(|e| refused("Hertz stiffness", e))?;
    let omega0 = (k / m_star).sqrt();
    let p = 1.5;
    let alpha = powerlaw::alpha_from_e(a.e, p, crit).map_err(|e| refused("alpha from --e", e))?;
    let c = Contact::new(p, alpha, a.v, omega0).map_err(|e| refused("collision (--v)", e))?;
    let d_max = powerlaw::max_overlap(&c).map_err(|e| refused("max overlap", e))?;
    let t_max =
        powerlaw::time_of_max_overlap(&c, LEVEL).map_err(|e| refused("t(max overlap)", e))?;
    let tau_overlap = powerlaw::contact_duration(&c, EndCriterion::Overlap, LEVEL).ok();
    let tau_force = powerlaw::contact_duration(&c, EndCriterion::Force, LEVEL)
        .map_err(|e| refused("force-end duration", e))?;
    // Peak total force along the trajectory that ends by the chosen criterion.
    let (mut t, mut d, mut v, mut f) = (
        vec![0.0; SAMPLES],
        vec![0.0; SAMPLES],
        vec![0.0; SAMPLES],
        vec![0.0; SAMPLES],
    );
    powerlaw::trajectory::sample_trajectory(
        &c,
        EndCriterion::Force,
        m_star,
        LEVEL,
        powerlaw::trajectory::TrajectoryOut {
            t: &mut t,
            delta: &mut d,
            v: &mut v,
            force: &mut f,
        },
    )
    .map_err(|e| refused("trajectory", e))?;
    let (i_peak, f_peak) = f
        .iter()
        .copied()
        .enumerate()
        .fold((0, f64::NEG_INFINITY), |b, x| if x.1 > b.1 { x } else { b });
    let t_peak = t.get(i_peak).copied().unwrap_or(f64::NAN);
    let dt = timestep::accuracy::dt_for_accuracy(p, a.e, crit, a.v, omega0, a.tol)
        .map_err(|e| refused("dt for --tol", e))?;
    let crit_s = match a.criterion {
        Crit::Force => "force end (clamped)",
        Crit::Overlap => "overlap end",
    };
    let stepped = match a.dt {
        Some(h) => {
            let elastic =
                Contact::new(p, 0.0, a.v, omega0).map_err(|e| refused("collision (--v)", e))?;
            let t_h = powerlaw::contact_duration(&elastic, EndCriterion::Overlap, LEVEL)
                .map_err(|e| refused("elastic contact duration", e))?;
            Some(at_step(a, crit, m1, t_h, h)?)
        }
        None => None,
    };
    let mut text = String::new();
    let _ = writeln!(
        text,
        "Hertz contact ({}): E* = {e_star:.6e} Pa, R* = {r_star:.6e} m, m* = {m_star:.6e} kg, k = {k:.6e} N/m^1.5",
        if a.wall {
            "sphere on wall"
        } else {
            "two spheres"
        }
    );
    let _ = writeln!(
        text,
        "impact speed {} m/s, target e = {} ({crit_s})",
        a.v, a.e
    );
    let _ = writeln!(text, "  alpha                  {alpha:.12}");
    let _ = writeln!(
        text,
        "  max overlap            {d_max:.6e} m  at t = {t_max:.6e} s"
    );
    let _ = writeln!(
        text,
        "  peak force             {f_peak:.6e} N  at t = {t_peak:.6e} s"
    );
    match tau_overlap {
        Some(x) => {
            let _ = writeln!(text, "  duration, overlap end  {x:.6e} s");
        }
        None => {
            let _ = writeln!(
                text,
                "  duration, overlap end  none (overdamped: the overlap never returns to 0)"
            );
        }
    }
    let _ = writeln!(text, "  duration, force end    {tau_force:.6e} s");
    let _ = writeln!(
        text,
        "  dt for |Δe/e| <= {}    {dt:.6e} s  (velocity Verlet, any contact phase)",
        a.tol
    );
    if let Some(st) = &stepped {
        let _ = writeln!(
            text,
            "  e realised at dt = {:.6e} s ({}, dt = t_Hertz/{:.2}, {PHASES} onset phases):",
            st.dt,
            match a.integrator {
                Integ::Verlet => "velocity Verlet",
                Integ::Euler => "symplectic Euler",
            },
            st.t_hertz / st.dt
        );
        let mut row = |name: &str, r: &Realised| {
            let _ = writeln!(
                text,
                "    {name:<11} mean {:.6}  range {:.6} .. {:.6}  (mean {:+.3} % from target)",
                r.mean,
                r.min,
                r.max,
                100.0 * (r.mean / a.e - 1.0)
            );
        };
        row("plain", &st.plain);
        if let Some(r) = &st.step_aware {
            row("step-aware", r);
        }
        if st.dt > H_MAX * st.t_hertz {
            let _ = writeln!(
                text,
                "    note: dt > t_Hertz/{}: beyond the step-aware calibration (docs/timestep.md)",
                1.0 / H_MAX
            );
        }
    }
    let json = json!({
        "command": "contact",
        "criterion": format!("{:?}", a.criterion).to_lowercase(),
        "wall": a.wall,
        "e_star": num(e_star), "r_star": num(r_star), "m_star": num(m_star), "k": num(k),
        "omega0": num(omega0), "p": p, "v": num(a.v), "e": num(a.e),
        "alpha": num(alpha),
        "max_overlap": num(d_max), "time_of_max_overlap": num(t_max),
        "peak_force": num(f_peak), "time_of_peak_force": num(t_peak),
        "duration_overlap_end": tau_overlap.map_or(serde_json::Value::Null, num),
        "duration_force_end": num(tau_force),
        "dt_tol": num(a.tol), "dt": num(dt),
        "at_step": stepped.as_ref().map_or(Value::Null, |st| json!({
            "dt": num(st.dt),
            "integrator": format!("{:?}", a.integrator).to_lowercase(),
            "t_hertz": num(st.t_hertz),
            "dt_over_t_hertz": num(st.dt / st.t_hertz),
            "within_calibration": st.dt <= H_MAX * st.t_hertz,
            "phases": PHASES,
            "plain": st.plain.json(),
            "step_aware": st.step_aware.as_ref().map_or(Value::Null, Realised::json),
        })),
    });
    Ok(Output { text, json })
}

/// Realised restitution over the onset phases.
struct Realised {
    mean: f64,
    min: f64,
    max: f64,
    /// One per phase, j = 0..PHASES.
    phases: Vec<f64>,
}

impl Realised {
    fn json(&self) -> Value {
        json!({
            "mean": num(self.mean), "min": num(self.min), "max": num(self.max),
            "phases": self.phases.iter().map(|&x| num(x)).collect::<Vec<_>>(),
        })
    }
}

/// The `--dt` figures.
struct AtStep {
    dt: f64,
    t_hertz: f64,
    plain: Realised,
    step_aware: Option<Realised>,
}

/// The collision of `a` at the host's step `h` through the library's contact model (Hertz,
/// restitution damping for `crit`): plain, and step-aware with `--step-aware`.
fn at_step(a: &Args, crit: EndCriterion, m1: f64, t_h: f64, h: f64) -> Result<AtStep, Failure> {
    let flag = format!("--dt {h:e}");
    if !h.is_finite() {
        return Err(refused(&flag, demcontact::Error::NotFinite));
    }
    if !(h > 0.0) {
        return Err(refused(&flag, demcontact::Error::NotPositive));
    }
    if t_h / h > MAX_STEPS_PER_CONTACT {
        return Err(Failure::usage(format!(
            "{flag}: t_Hertz/dt = {:.3e} steps per contact, more than {MAX_STEPS_PER_CONTACT:e}: \
             use a larger --dt (t_Hertz = {t_h:.6e} s)",
            t_h / h
        )));
    }
    let (e2, nu2) = (a.E2.unwrap_or(a.E1), a.nu2.unwrap_or(a.nu1));
    let spec = ContactSpec {
        normal: normal::HERTZ,
        damping: damping::RESTITUTION,
        criterion: crit.code(),
        e1: a.E1,
        nu1: a.nu1,
        e2,
        nu2,
        e_n: a.e,
        ..ContactSpec::default()
    };
    let model = contact_model(&spec)
        .map_err(|e| refused("contact model from --E1 --nu1 --E2 --nu2 --e", e))?;
    let (r2, m2) = if a.wall {
        (f64::INFINITY, f64::INFINITY)
    } else {
        let (rho2, r2) = (a.rho2.unwrap_or(a.rho1), a.R2.unwrap_or(a.R1));
        (r2, rho2 * 4.0 / 3.0 * std::f64::consts::PI * r2 * r2 * r2)
    };
    let verlet = a.integrator == Integ::Verlet;
    let bodies = Bodies {
        r1: a.R1,
        m1,
        r2,
        m2,
    };
    // Steps allowed per collision: ten elastic durations and some (the damped contact lasts
    // less than the elastic one; the approach takes one step).
    let cap = (10.0 * t_h / h) as usize + 1000;
    let realise = |m: &ContactModel| -> Result<Realised, Failure> {
        let mut phases = Vec::with_capacity(PHASES);
        for j in 0..PHASES {
            let e = collide(m, &bodies, a.v, h, j, verlet, cap).map_err(|e| refused(&flag, e))?;
            phases.push(e);
        }
        let mean = phases.iter().sum::<f64>() / PHASES as f64;
        let min = phases.iter().copied().fold(f64::INFINITY, f64::min);
        let max = phases.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Ok(Realised {
            mean,
            min,
            max,
            phases,
        })
    };
    let plain = realise(&model)?;
    let step_aware = if a.step_aware {
        let code = if verlet {
            integrator::VELOCITY_VERLET
        } else {
            integrator::SYMPLECTIC_EULER
        };
        let stepped =
            set_step(&model, h, code).map_err(|e| refused(&format!("{flag} --step-aware"), e))?;
        Some(realise(&stepped)?)
    } else {
        None
    };
    Ok(AtStep {
        dt: h,
        t_hertz: t_h,
        plain,
        step_aware,
    })
}

/// Body 1 (radius, mass) against body 2 (a sphere, or a wall: both infinite).
struct Bodies {
    r1: f64,
    m1: f64,
    r2: f64,
    m2: f64,
}

/// Realised e of one head-on collision at onset phase j: body 1 approaches body 2 (at rest)
/// at speed v along the normal, the first step starting at a gap of j/PHASES of one step's
/// travel; the integrator advances both bodies with the force of `contact_force` (the model's
/// history carried), until the overlap is back to zero. e = separation speed / v.
fn collide(
    m: &ContactModel,
    b: &Bodies,
    v: f64,
    h: f64,
    j: usize,
    verlet: bool,
    cap: usize,
) -> Result<f64, demcontact::Error> {
    let mut hist = [0.0; demcontact::contact::HISTORY_MAX];
    let len = m.layout.len.min(hist.len());
    let mut d = -(j as f64) / PHASES as f64 * v * h;
    // Velocities along the normal (from body 2 to body 1): body 1 moves towards body 2.
    let (mut u1, mut u2) = (-v, 0.0);
    let (mut a1, mut a2) = (0.0, 0.0);
    let mut touched = false;
    let mut force = |d: f64, u1: f64, u2: f64| -> Result<f64, demcontact::Error> {
        let s = ContactState {
            n: [0.0, 0.0, 1.0],
            overlap: d,
            v1: [0.0, 0.0, u1],
            v2: [0.0, 0.0, u2],
            w1: [0.0; 3],
            w2: [0.0; 3],
            r1: b.r1,
            r2: b.r2,
            m1: b.m1,
            m2: b.m2,
        };
        let hs = hist.get_mut(..len).unwrap_or_default();
        Ok(contact_force(m, &s, h, hs)?.force[2])
    };
    for _ in 0..cap {
        if verlet {
            let (h1, h2) = (u1 + 0.5 * h * a1, u2 + 0.5 * h * a2);
            d -= h * (h1 - h2);
            touched |= d > 0.0;
            let f = force(d, h1, h2)?;
            (a1, a2) = (f / b.m1, -f / b.m2);
            (u1, u2) = (h1 + 0.5 * h * a1, h2 + 0.5 * h * a2);
        } else {
            let f = force(d, u1, u2)?;
            u1 += h * f / b.m1;
            u2 -= h * f / b.m2;
            d -= h * (u1 - u2);
            touched |= d > 0.0;
        }
        if touched && d <= 0.0 {
            return Ok((u1 - u2) / v);
        }
    }
    Err(demcontact::Error::NoEvent)
}
