//! From a specification (sub-models and parameters named by field) to a validated
//! [`ContactModel`]. Every parameter a chosen sub-model reads is checked here, once, at set-up;
//! parameters of sub-models that are not chosen are ignored (they may stay unset = NaN).

use super::model::{ContactModel, Layout, select};
use super::tangential::zeta_from_e_t;
use super::tangential_mindlin::eight_g_star;
use crate::force::{PairModel, dmt, elastic_plastic, hertz, powerlaw, stateful, viscoelastic};
use crate::{EndCriterion, Error};

/// Normal-law selectors (the C constants `DC_NORMAL_*` equal these).
///
/// cbindgen:ignore
pub mod normal {
    /// Hertz from E, ν of both bodies: k = (4/3) E* √R* per contact.
    pub const HERTZ: i32 = 1;
    /// Power law F = k_n δ^p (fixed k_n, p ≥ 1).
    pub const POWERLAW: i32 = 2;
    /// Linear spring F = k_n δ.
    pub const LINEAR: i32 = 3;
    /// Viscoelastic Hertz (Brilliantov et al.), damping constant A.
    pub const VISCOELASTIC: i32 = 4;
    /// Adhesive DMT: Hertz minus 2π w R*, attraction beyond touching ([`crate::force::dmt`]).
    pub const DMT: i32 = 5;
    /// Elastic–plastic (Thornton 1997): Hertz to the yield pressure p_y, then plastic; one
    /// double of state ([`crate::force::elastic_plastic`]).
    pub const ELASTIC_PLASTIC: i32 = 6;
}

/// Normal-damping selectors (`DC_DAMPING_*`).
///
/// cbindgen:ignore
pub mod damping {
    /// Undamped (e_n = 1).
    pub const NONE: i32 = 0;
    /// α calibrated exactly from e_n for the end criterion.
    pub const RESTITUTION: i32 = 1;
}

/// The specification, field by field (the Rust form of `dc_contact_spec`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactSpec {
    /// `normal::*`.
    pub normal: i32,
    /// `damping::*`.
    pub damping: i32,
    /// End criterion code (0 overlap, 1 force: clamp).
    pub criterion: i32,
    /// `select::TANGENTIAL_*`.
    pub tangential: i32,
    /// `select::ROLLING_*`.
    pub rolling: i32,
    /// `select::TWISTING_*`.
    pub twisting: i32,
    /// `select::CARRY_*` (default rotate).
    pub carry: i32,
    /// Young's modulus of body 1 [Pa] (+∞: rigid).
    pub e1: f64,
    /// Poisson ratio of body 1.
    pub nu1: f64,
    /// Young's modulus of body 2 [Pa] (+∞: rigid).
    pub e2: f64,
    /// Poisson ratio of body 2.
    pub nu2: f64,
    /// Power-law exponent.
    pub p: f64,
    /// Normal stiffness of power-law and linear laws.
    pub k_n: f64,
    /// Target normal restitution.
    pub e_n: f64,
    /// Viscoelastic damping constant A [s].
    pub visco_a: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Linear tangential stiffness [N/m].
    pub k_t: f64,
    /// Target tangential restitution in the sticking regime (1: undamped).
    pub e_t: f64,
    /// Rolling friction coefficient.
    pub mu_r: f64,
    /// Rolling stiffness [N m/rad] (0: Ai et al.'s rule).
    pub k_r: f64,
    /// Rolling damping ratio.
    pub eta_r: f64,
    /// Twisting friction coefficient [m].
    pub mu_tw: f64,
    /// Twisting stiffness [N m/rad].
    pub k_tw: f64,
    /// Twisting damping ratio.
    pub eta_tw: f64,
    /// Inertia factor κ = I/(m r²) of the bodies (2/5 solid spheres).
    pub inertia_factor: f64,
    /// Work of adhesion w [J/m²] (DMT).
    pub work_of_adhesion: f64,
    /// Limiting contact pressure p_y [Pa] (elastic–plastic).
    pub yield_pressure: f64,
}

impl Default for ContactSpec {
    /// No normal law chosen yet (must be set), no damping, clamping criterion, no tangential,
    /// rolling or twisting, springs carried by rotation; every parameter unset (NaN) except e_t = 1 (no tangential damping),
    /// k_r = 0 (Ai's rule), η_r = η_tw = 0 and κ = 2/5.
    fn default() -> Self {
        let u = f64::NAN;
        ContactSpec {
            normal: 0,
            damping: damping::NONE,
            criterion: EndCriterion::Force.code(),
            tangential: select::TANGENTIAL_NONE,
            rolling: select::ROLLING_NONE,
            twisting: select::TWISTING_NONE,
            carry: select::CARRY_ROTATE,
            e1: u,
            nu1: u,
            e2: u,
            nu2: u,
            p: u,
            k_n: u,
            e_n: u,
            visco_a: u,
            mu: u,
            k_t: u,
            e_t: 1.0,
            mu_r: u,
            k_r: 0.0,
            eta_r: 0.0,
            mu_tw: u,
            k_tw: u,
            eta_tw: 0.0,
            inertia_factor: 0.4,
            work_of_adhesion: u,
            yield_pressure: u,
        }
    }
}

/// A required parameter: NaN means "not set".
fn set(x: f64) -> Result<f64, Error> {
    if x.is_nan() {
        Err(Error::SpecUnset)
    } else {
        Ok(x)
    }
}

/// A finite parameter ≥ 0.
fn non_negative(x: f64) -> Result<f64, Error> {
    let x = set(x)?;
    if !x.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(x >= 0.0) {
        return Err(Error::Negative);
    }
    Ok(x)
}

/// A finite parameter > 0.
fn positive(x: f64) -> Result<f64, Error> {
    let x = set(x)?;
    if !x.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(x > 0.0) {
        return Err(Error::NotPositive);
    }
    Ok(x)
}

/// One material: E > 0 (+∞ allowed: rigid), −1 < ν ≤ 1/2. Returns (1 − ν²)/E.
fn compliance(e: f64, nu: f64) -> Result<f64, Error> {
    let (e, nu) = (set(e)?, set(nu)?);
    if !nu.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(nu > -1.0 && nu <= 0.5) {
        return Err(Error::PoissonRange);
    }
    if !(e > 0.0) {
        return Err(Error::NotPositive);
    }
    Ok((1.0 - nu) * (1.0 + nu) / e)
}

/// (4/3) E* of the spec's materials; one body may be rigid (E = +∞), not both.
fn hertz_factor(s: &ContactSpec) -> Result<f64, Error> {
    let c = compliance(s.e1, s.nu1)? + compliance(s.e2, s.nu2)?;
    let kf = 4.0 / 3.0 * (1.0 / c);
    if !kf.is_finite() {
        return Err(Error::NotFinite);
    }
    // A subnormal E makes the compliance overflow and kf underflow to 0 (found by fuzzing).
    if !(kf > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(kf)
}

fn normal_law(s: &ContactSpec, crit: EndCriterion) -> Result<PairModel, Error> {
    let e_n = match s.damping {
        damping::NONE => 1.0,
        damping::RESTITUTION => set(s.e_n)?,
        _ => return Err(Error::SpecModel),
    };
    match s.normal {
        normal::HERTZ => hertz::hertz_from_factor(hertz_factor(s)?, e_n, crit),
        normal::POWERLAW => powerlaw::powerlaw(set(s.p)?, set(s.k_n)?, e_n, crit),
        normal::LINEAR => powerlaw::linear(set(s.k_n)?, e_n, crit),
        normal::VISCOELASTIC => {
            // A is the damping of this law; a restitution target would be silently ignored.
            if s.damping != damping::NONE {
                return Err(Error::SpecModel);
            }
            viscoelastic::viscoelastic_from_factor(hertz_factor(s)?, set(s.visco_a)?, crit)
        }
        normal::DMT => dmt::dmt_from_factor(hertz_factor(s)?, set(s.work_of_adhesion)?, e_n, crit),
        normal::ELASTIC_PLASTIC => {
            // The plastic work is this law's loss; a restitution target would be ignored.
            if s.damping != damping::NONE {
                return Err(Error::SpecModel);
            }
            elastic_plastic::elastic_plastic_from_factor(
                hertz_factor(s)?,
                set(s.yield_pressure)?,
                crit,
            )
        }
        _ => Err(Error::SpecModel),
    }
}

/// Builds and validates a contact model.
pub fn contact_model(s: &ContactSpec) -> Result<ContactModel, Error> {
    let crit = EndCriterion::from_code(s.criterion).ok_or(Error::Criterion)?;
    let normal = normal_law(s, crit)?;
    let kappa = positive(s.inertia_factor)?;
    if !(kappa <= 1.0) {
        return Err(Error::SpecModel);
    }
    let mut m = ContactModel {
        normal,
        tangential: s.tangential,
        rolling: s.rolling,
        twisting: s.twisting,
        carry: s.carry,
        mu: 0.0,
        kt: 0.0,
        zeta_t: 0.0,
        kappa,
        mu_r: 0.0,
        k_r: 0.0,
        eta_r: 0.0,
        mu_tw: 0.0,
        k_tw: 0.0,
        eta_tw: 0.0,
        layout: Layout::of_model(
            s.tangential,
            s.rolling,
            s.twisting,
            stateful::has_state(normal.kernel),
            false,
        ),
        step: super::step_exact::StepExact::default(),
    };
    if !matches!(s.carry, select::CARRY_ROTATE | select::CARRY_PROJECT) {
        return Err(Error::SpecModel);
    }
    match s.tangential {
        select::TANGENTIAL_NONE => {}
        select::TANGENTIAL_LINEAR
        | select::TANGENTIAL_MINDLIN
        | select::TANGENTIAL_MINDLIN_RESCALE => {
            m.mu = non_negative(s.mu)?;
            m.zeta_t = zeta_from_e_t(set(s.e_t)?)?;
            m.kt = if s.tangential == select::TANGENTIAL_LINEAR {
                positive(s.k_t)?
            } else {
                compliance(s.e1, s.nu1)?;
                compliance(s.e2, s.nu2)?;
                eight_g_star(s.e1, s.nu1, s.e2, s.nu2)?
            };
        }
        _ => return Err(Error::SpecModel),
    }
    match s.rolling {
        select::ROLLING_NONE => {}
        select::ROLLING_CONSTANT => m.mu_r = non_negative(s.mu_r)?,
        select::ROLLING_EPSD => {
            m.mu_r = non_negative(s.mu_r)?;
            m.k_r = non_negative(s.k_r)?;
            m.eta_r = non_negative(s.eta_r)?;
        }
        _ => return Err(Error::SpecModel),
    }
    match s.twisting {
        select::TWISTING_NONE => {}
        select::TWISTING_SDS => {
            m.mu_tw = non_negative(s.mu_tw)?;
            m.k_tw = positive(s.k_tw)?;
            m.eta_tw = non_negative(s.eta_tw)?;
        }
        _ => return Err(Error::SpecModel),
    }
    Ok(m)
}
