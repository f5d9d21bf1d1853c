//! `demcontact contact`: one Hertz collision from material data.

use crate::output::{Failure, Output, num};
use crate::refused;
use clap::ValueEnum;
use demcontact::powerlaw::{self, Contact};
use demcontact::{EndCriterion, material, timestep};
use serde_json::json;
use std::fmt::Write;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Crit {
    /// The solver clamps attractive forces (LIGGGHTS limitForce, LAMMPS limit_damping, YADE).
    Force,
    /// The force may turn attractive; the contact ends at zero overlap.
    Overlap,
}

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
    });
    Ok(Output { text, json })
}
