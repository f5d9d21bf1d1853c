//! The scene planner: the softest Young's modulus and the largest velocity-Verlet step that keep
//! every per-contact observable of a Hertz scene within the user's tolerances, and what the
//! scene's contacts then realise. Every number comes from the library's exact per-contact
//! functions ([`crate::powerlaw`], [`crate::timestep`], [`crate::material`]); this module only
//! chooses which pair and which load to ask them about, and inverts their exact scaling in E.
//!
//! # The scene
//! One material (E, ν, ρ, target restitution e calibrated exactly for the end criterion), spheres
//! with radii in [R_min, R_max], walls of the same material (unless `walls` is off), impacts up
//! to v_max, and a static load from a bed of depth H under gravity g plus an optional confining
//! pressure P. Each observable is evaluated for six pairs ([`PairKind`]): R_min–R_min,
//! R_min–R_max, R_max–R_max, R_min–wall, R_max–wall and R_min against the partner size that
//! maximises the impact overlap, and the worst is kept. Ratios δ/R divide by the smaller sphere
//! radius of the pair. Why these suffice: at fixed size ratio r = R2/R1 every ratio δ/R1 is
//! independent of R1 (δ ∝ R1 at fixed v and stress), so only r matters. The impact overlap goes as
//! (m*/√R*)^(2/5) ∝ f(r)^(2/5) with f(r) = r^(5/2)(1 + r)^(1/2)/(1 + r³), which is *not* monotone:
//! 1/√2 at r = 1, largest (1.113) at r = (1 + √21)/2 ([`PEAK_RATIO`]), 1 for a wall; hence the
//! sixth pair. The static ratio goes as ((1 + r)^(5/2)/√r)^(2/3), increasing in r: worst at
//! R_min–R_max (a wall, l = 2R and R* = R, gives less). The time scale 1/ω0 ∝ (R1^(5/2) f(r))^(1/2)
//! is shortest for R_min–R_min. `tests/plan.rs` checks on random radii in between that no pair
//! does worse than the six.
//!
//! # Static load
//! Vertical stress at the bottom of the bed, Janssen-free (no wall friction relief, so an upper
//! bound for a silo): σ = φ ρ g H + P, with φ the solid fraction. The mean contact force follows
//! from the micromechanical stress of a packing, σ = (N_c/V)⟨f l⟩/3 (l the branch vector, l = 2R
//! for equal spheres; N_c/V = φ Z/(2·(4/3)πR³)), i.e. f = 4πR² σ/(φ Z) for equal spheres, written
//! f = π l² σ/(φ Z) with l = R1 + R2 for a pair (l = 2R for a sphere on a wall, its mirror
//! image). Z is the coordination number. `load_factor` multiplies it: contact forces in a static
//! packing are spread around the mean (exponential tail), so the largest are a few times the mean.
//! With P = 0, f = π l² ρ g H/Z: the solid fraction cancels. The static overlap is the Hertz
//! equilibrium k δ^(3/2) = f.
//!
//! # Choice
//! Softening E to E_s scales E* (ν kept), hence k and ω0 ∝ E_s^(1/2): δ_max ∝ E_s^(−2/5) (closed
//! form [`crate::powerlaw::max_overlap`]), the static δ ∝ E_s^(−2/3), every duration and the
//! accuracy step ∝ E_s^(−2/5) (the scale t* of [`crate::timestep::accuracy`]); e does not change
//! (α depends on e only). So each tolerance on an observable is a lower bound on E_s, computed
//! from the real modulus by the exact exponent and re-checked at the result with the library's
//! functions (nudged up by ulps when rounding lands a hair outside). E_s is the largest of these
//! bounds (never above the real E; if a bound is above it, the real material itself misses that
//! tolerance: [`Error::PlanInfeasible`]). The step is then the smaller of
//! [`crate::timestep::dt_for_accuracy`] for the R_min pair at v_max (the e tolerance) and
//! `stability_fraction` × the resting-contact velocity-Verlet limit
//! [`crate::powerlaw::timestep::dt_static`] under the static load (smallest over the pairs).
//!
//! # Speed-up
//! Against the conventional choice, the real modulus at `τ_real/conventional_divisor` (τ_real
//! the R_min–R_min contact duration at v_max under the chosen criterion, real E): speedup =
//! dt / dt_conventional. The cost per step does not change with E or dt (same contacts, same
//! force law), so the ratio of steps is the ratio of wall times, to first order (softer
//! particles overlap more, which can add neighbour-list entries; not counted).
//!
//! # Step-aware restitution
//! `e_plain_*` is the restitution velocity-Verlet realises at the chosen step with the plain
//! (continuously calibrated) dashpot, over 64 onset phases. [`step_aware`] gives the step the
//! step-aware dashpot (`dc_contact_model_set_step`, [`crate::contact::step_exact`]) allows at
//! the same modulus and tolerance: [`crate::contact::step_exact::dt_for_accuracy`] for the
//! fastest pair at v_max, capped by the same stability limit. It is a separate call because its
//! calibration costs 0.1–1 s; the modulus does not depend on it.

use crate::force::powerlaw::powerlaw_from_alpha;
use crate::material;
use crate::powerlaw::{self, Contact};
use crate::timestep::{self, Scheme};
use crate::{EndCriterion, Error};

/// Hertz exponent.
const P: f64 = 1.5;
/// Quadrature level of the durations (the library's highest: ~1e-12 relative).
const LEVEL: u32 = 4;
/// Onset phases over which the realised e is reported (as [`crate::timestep::accuracy`] samples).
///
/// cbindgen:ignore
pub const N_PHASE: u32 = 64;
/// The most steps per contact (the fastest pair's duration over dt) a plan accepts: a step below
/// the contact duration over 2^22 is one no scene can afford (and the plan's check would
/// simulate 64 collisions of that many steps: seconds to minutes). Reached by e → 0 with
/// DC_END_OVERLAP (near-critical damping: e = 1e-6 needs 6.3·10^5 steps per contact at
/// e_tol 1e-2, e = 1e-7 8·10^6), refused as infeasible at the e tolerance (test
/// `vanishing_restitution_is_planned_or_refused_at_once`).
///
/// cbindgen:ignore
pub const MAX_STEPS_PER_CONTACT: f64 = 4_194_304.0;

/// What the planner is told about the scene. See the module docs for the model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanInput {
    /// Real Young's modulus E [Pa], > 0.
    pub youngs: f64,
    /// Poisson's ratio ν in (−1, 0.5].
    pub poisson: f64,
    /// Particle density ρ [kg/m³], > 0.
    pub density: f64,
    /// Target restitution e in (0, 1].
    pub restitution: f64,
    /// Smallest radius [m], > 0.
    pub radius_min: f64,
    /// Largest radius [m], ≥ radius_min.
    pub radius_max: f64,
    /// Largest impact speed [m/s], > 0.
    pub v_max: f64,
    /// Bed depth H [m], ≥ 0.
    pub depth: f64,
    /// Gravity g [m/s²], ≥ 0.
    pub gravity: f64,
    /// Confining pressure P [Pa] added to the bed's weight, ≥ 0.
    pub pressure: f64,
    /// Solid fraction φ of the bed, in (0, 1).
    pub solid_fraction: f64,
    /// Coordination number Z (contacts per particle), > 0.
    pub coordination: f64,
    /// Largest contact force over the mean contact force, ≥ 1.
    pub load_factor: f64,
    /// Sliding friction μ, ≥ 0 (recorded; does not enter the normal-contact bounds).
    pub friction: f64,
    /// Rolling friction μ_r, ≥ 0 (recorded; does not enter the normal-contact bounds).
    pub rolling_friction: f64,
    /// Largest δ_max/R at v_max, in (0, 1).
    pub overlap_tol: f64,
    /// Largest relative error of the realised e at the step, in (0, 1).
    pub e_tol: f64,
    /// Largest static δ/R under the bed load, > 0 (+∞: no bound).
    pub static_tol: f64,
    /// Largest relative lengthening of the contact duration by softening, τ_s/τ_real − 1, > 0
    /// (+∞: no bound).
    pub duration_tol: f64,
    /// How the host ends a contact (the calibration of α follows it).
    pub criterion: EndCriterion,
    /// Whether walls (same material) are part of the scene.
    pub walls: bool,
    /// Fraction of the resting-contact stability limit the step may use, in (0, 1].
    pub stability_fraction: f64,
    /// The conventional step is τ_real/conventional_divisor, ≥ 1.
    pub conventional_divisor: f64,
}

impl PlanInput {
    /// The defaults of the optional inputs (g = 9.81, P = 0, φ = 0.6, Z = 6, load factor 1,
    /// μ = μ_r = 0, no static or duration bound, force-end criterion, walls on, stability
    /// fraction 0.5, conventional divisor 50) with the required ones NaN (unset).
    pub const fn new() -> Self {
        Self {
            youngs: f64::NAN,
            poisson: f64::NAN,
            density: f64::NAN,
            restitution: f64::NAN,
            radius_min: f64::NAN,
            radius_max: f64::NAN,
            v_max: f64::NAN,
            depth: f64::NAN,
            gravity: 9.81,
            pressure: 0.0,
            solid_fraction: 0.6,
            coordination: 6.0,
            load_factor: 1.0,
            friction: 0.0,
            rolling_friction: 0.0,
            overlap_tol: f64::NAN,
            e_tol: f64::NAN,
            static_tol: f64::INFINITY,
            duration_tol: f64::INFINITY,
            criterion: EndCriterion::Force,
            walls: true,
            stability_fraction: 0.5,
            conventional_divisor: 50.0,
        }
    }
}

impl Default for PlanInput {
    fn default() -> Self {
        Self::new()
    }
}

/// Which input a refusal is about (the C ABI's `DC_PLAN_FIELD_*` codes are these values).
///
/// cbindgen:ignore
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(i32)]
pub enum PlanField {
    /// Not one input: the computation (e.g. the tolerances cannot all be met).
    None = 0,
    /// [`PlanInput::youngs`].
    Youngs = 1,
    /// [`PlanInput::poisson`].
    Poisson = 2,
    /// [`PlanInput::density`].
    Density = 3,
    /// [`PlanInput::restitution`].
    Restitution = 4,
    /// [`PlanInput::radius_min`].
    RadiusMin = 5,
    /// [`PlanInput::radius_max`].
    RadiusMax = 6,
    /// [`PlanInput::v_max`].
    VMax = 7,
    /// [`PlanInput::depth`].
    Depth = 8,
    /// [`PlanInput::gravity`].
    Gravity = 9,
    /// [`PlanInput::pressure`].
    Pressure = 10,
    /// [`PlanInput::solid_fraction`].
    SolidFraction = 11,
    /// [`PlanInput::coordination`].
    Coordination = 12,
    /// [`PlanInput::load_factor`].
    LoadFactor = 13,
    /// [`PlanInput::friction`].
    Friction = 14,
    /// [`PlanInput::rolling_friction`].
    RollingFriction = 15,
    /// [`PlanInput::overlap_tol`].
    OverlapTol = 16,
    /// [`PlanInput::e_tol`].
    ETol = 17,
    /// [`PlanInput::static_tol`].
    StaticTol = 18,
    /// [`PlanInput::duration_tol`].
    DurationTol = 19,
    /// [`PlanInput::criterion`].
    Criterion = 20,
    /// [`PlanInput::stability_fraction`].
    StabilityFraction = 21,
    /// [`PlanInput::conventional_divisor`].
    ConventionalDivisor = 22,
    /// [`PlanInput::walls`] (C ABI only: an int that is not 0 or 1).
    Walls = 23,
}

/// A refusal: the library error and the input at fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanError {
    /// The input at fault ([`PlanField::None`] when no single input is).
    pub field: PlanField,
    /// Why.
    pub error: Error,
}

impl PlanError {
    fn at(field: PlanField) -> impl Fn(Error) -> PlanError {
        move |error| PlanError { field, error }
    }
}

/// The extreme pairs the planner evaluates.
///
/// cbindgen:ignore
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(i32)]
pub enum PairKind {
    /// Two spheres of R_min.
    MinMin = 0,
    /// R_min against R_max.
    MinMax = 1,
    /// Two spheres of R_max.
    MaxMax = 2,
    /// R_min against a wall.
    MinWall = 3,
    /// R_max against a wall.
    MaxWall = 4,
    /// R_min against the partner of radius min(R_max, r_peak·R_min) that maximises δ_max/R_min,
    /// r_peak = (1 + √21)/2 ([`PEAK_RATIO`]).
    MinPeak = 5,
}

/// The size ratio r = R2/R1 ≥ 1 at which δ_max/R1 of an impact is largest: δ_max ∝ (m*/√R*)^(2/5)
/// and m*/√R* ∝ R1^(5/2) f(r), f(r) = r^(5/2) (1 + r)^(1/2)/(1 + r³), whose logarithmic derivative
/// vanishes where r³ − 6r − 5 = (r + 1)(r² − r − 5) = 0: r = (1 + √21)/2 ≈ 2.791 (f = 1.113 there,
/// against 1/√2 for equal spheres and 1 for a wall).
///
/// cbindgen:ignore
pub const PEAK_RATIO: f64 = 2.791_287_847_477_92;

impl PairKind {
    /// All six, in code order.
    pub const ALL: [PairKind; 6] = [
        PairKind::MinMin,
        PairKind::MinMax,
        PairKind::MaxMax,
        PairKind::MinWall,
        PairKind::MaxWall,
        PairKind::MinPeak,
    ];

    /// A short name ("min-min", "min-max", "max-max", "min-wall", "max-wall").
    pub const fn name(self) -> &'static str {
        match self {
            PairKind::MinMin => "min-min",
            PairKind::MinMax => "min-max",
            PairKind::MaxMax => "max-max",
            PairKind::MinWall => "min-wall",
            PairKind::MaxWall => "max-wall",
            PairKind::MinPeak => "min-peak",
        }
    }

    fn is_wall(self) -> bool {
        matches!(self, PairKind::MinWall | PairKind::MaxWall)
    }
}

/// What sets the softest modulus.
///
/// cbindgen:ignore
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(i32)]
pub enum Binding {
    /// δ_max/R at v_max reaches `overlap_tol`.
    Overlap = 0,
    /// The static δ/R reaches `static_tol`.
    Static = 1,
    /// The duration lengthening reaches `duration_tol`.
    Duration = 2,
}

impl Binding {
    /// The tolerance's name as the CLI flag spells it, without dashes ("overlap-tol", …).
    pub const fn name(self) -> &'static str {
        match self {
            Binding::Overlap => "overlap-tol",
            Binding::Static => "static-tol",
            Binding::Duration => "duration-tol",
        }
    }
}

/// What sets the step.
///
/// cbindgen:ignore
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(i32)]
pub enum StepBinding {
    /// The e tolerance ([`crate::timestep::dt_for_accuracy`]).
    Restitution = 0,
    /// The resting-contact stability limit × `stability_fraction`.
    Stability = 1,
}

impl StepBinding {
    /// "e-tol" or "stability-fraction".
    pub const fn name(self) -> &'static str {
        match self {
            StepBinding::Restitution => "e-tol",
            StepBinding::Stability => "stability-fraction",
        }
    }
}

/// The planner's choice and what the scene's contacts realise with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    /// Softest Young's modulus meeting every tolerance [Pa].
    pub youngs_soft: f64,
    /// Real E over youngs_soft (≥ 1).
    pub softening: f64,
    /// The tolerance that sets youngs_soft.
    pub binding: Binding,
    /// Largest step meeting every tolerance at youngs_soft [s].
    pub dt: f64,
    /// What sets dt.
    pub binding_dt: StepBinding,
    /// The e-tolerance step at youngs_soft [s].
    pub dt_restitution: f64,
    /// The resting-contact stability limit at youngs_soft (smallest over the pairs; +∞ without
    /// a static load) [s], before `stability_fraction`.
    pub dt_stability: f64,
    /// The conventional step: τ_real/conventional_divisor [s].
    pub dt_conventional: f64,
    /// dt/dt_conventional.
    pub speedup: f64,
    /// Damping coefficient α of the calibrated dashpot.
    pub alpha: f64,
    /// Largest δ_max/R at v_max over the pairs, at youngs_soft.
    pub max_overlap_ratio: f64,
    /// The pair where it occurs.
    pub max_overlap_pair: PairKind,
    /// The same at the real modulus.
    pub max_overlap_ratio_real: f64,
    /// Largest static δ/R under the bed load over the pairs, at youngs_soft (0 without load).
    pub static_overlap_ratio: f64,
    /// The pair where it occurs.
    pub static_pair: PairKind,
    /// The same at the real modulus.
    pub static_overlap_ratio_real: f64,
    /// Bed stress σ = φρgH + P at the bottom [Pa].
    pub stress: f64,
    /// Static force on the contact of `static_pair` [N].
    pub static_force: f64,
    /// Contact duration at v_max, R_min–R_min pair, chosen criterion, youngs_soft [s].
    pub duration: f64,
    /// The same at the real modulus [s].
    pub duration_real: f64,
    /// duration/duration_real − 1.
    pub duration_change: f64,
    /// Elastic (undamped) Hertz duration at v_max, R_min–R_min pair, youngs_soft [s].
    pub t_hertz: f64,
    /// dt/t_hertz.
    pub dt_over_t_hertz: f64,
    /// Steps per contact: duration/dt.
    pub steps_per_contact: f64,
    /// Realised e at dt (plain dashpot, R_min–R_min pair at v_max) farthest from the target over
    /// [`N_PHASE`] onset phases.
    pub e_plain_at_dt: f64,
    /// Smallest realised e over the phases.
    pub e_plain_min: f64,
    /// Largest realised e over the phases.
    pub e_plain_max: f64,
    /// Mean realised e over the phases.
    pub e_plain_mean: f64,
}

/// One pair of the scene at one modulus.
#[derive(Clone, Copy, Debug)]
struct Pair {
    kind: PairKind,
    /// Smaller sphere radius (the ratios divide by it).
    r_small: f64,
    m_star: f64,
    k: f64,
    omega0: f64,
    /// Static contact force [N].
    force: f64,
}

fn sphere_mass(rho: f64, r: f64) -> f64 {
    rho * (4.0 / 3.0 * core::f64::consts::PI) * r * r * r
}

fn finite_pos(x: f64) -> Result<f64, Error> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(Error::ResultRange)
    }
}

impl PlanInput {
    /// Every input checked, in field order; the first fault is reported with its field.
    pub fn check(&self) -> Result<(), PlanError> {
        use PlanField as F;
        let fin = |x: f64, f: F| {
            if x.is_finite() {
                Ok(())
            } else {
                Err(PlanError {
                    field: f,
                    error: Error::NotFinite,
                })
            }
        };
        let err = |f: F, error: Error| Err(PlanError { field: f, error });
        fin(self.youngs, F::Youngs)?;
        fin(self.poisson, F::Poisson)?;
        if !(self.poisson > -1.0 && self.poisson <= 0.5) {
            return err(F::Poisson, Error::PoissonRange);
        }
        if !(self.youngs > 0.0) {
            return err(F::Youngs, Error::NotPositive);
        }
        for (x, f) in [
            (self.density, F::Density),
            (self.restitution, F::Restitution),
        ] {
            fin(x, f)?;
        }
        if !(self.density > 0.0) {
            return err(F::Density, Error::NotPositive);
        }
        if !(self.restitution > 0.0 && self.restitution <= 1.0) {
            return err(F::Restitution, Error::RestitutionRange);
        }
        for (x, f) in [
            (self.radius_min, F::RadiusMin),
            (self.radius_max, F::RadiusMax),
        ] {
            fin(x, f)?;
            if !(x > 0.0) {
                return err(f, Error::NotPositive);
            }
        }
        if self.radius_min > self.radius_max {
            return err(F::RadiusMax, Error::PlanRange);
        }
        fin(self.v_max, F::VMax)?;
        if !(self.v_max > 0.0) {
            return err(F::VMax, Error::NotPositive);
        }
        for (x, f) in [
            (self.depth, F::Depth),
            (self.gravity, F::Gravity),
            (self.pressure, F::Pressure),
        ] {
            fin(x, f)?;
            if x < 0.0 {
                return err(f, Error::Negative);
            }
        }
        fin(self.solid_fraction, F::SolidFraction)?;
        if !(self.solid_fraction > 0.0 && self.solid_fraction < 1.0) {
            return err(F::SolidFraction, Error::PlanRange);
        }
        fin(self.coordination, F::Coordination)?;
        if !(self.coordination > 0.0) {
            return err(F::Coordination, Error::NotPositive);
        }
        fin(self.load_factor, F::LoadFactor)?;
        if !(self.load_factor >= 1.0) {
            return err(F::LoadFactor, Error::PlanRange);
        }
        for (x, f) in [
            (self.friction, F::Friction),
            (self.rolling_friction, F::RollingFriction),
        ] {
            fin(x, f)?;
            if x < 0.0 {
                return err(f, Error::Negative);
            }
        }
        for (x, f) in [(self.overlap_tol, F::OverlapTol), (self.e_tol, F::ETol)] {
            fin(x, f)?;
            if !(x > 0.0) {
                return err(f, Error::NotPositive);
            }
            if !(x < 1.0) {
                return err(f, Error::PlanRange);
            }
        }
        for (x, f) in [
            (self.static_tol, F::StaticTol),
            (self.duration_tol, F::DurationTol),
        ] {
            // +∞ is "no bound"; NaN is not a tolerance.
            if x.is_nan() {
                return err(f, Error::NotFinite);
            }
            if !(x > 0.0) {
                return err(f, Error::NotPositive);
            }
        }
        fin(self.stability_fraction, F::StabilityFraction)?;
        if !(self.stability_fraction > 0.0 && self.stability_fraction <= 1.0) {
            return err(F::StabilityFraction, Error::PlanRange);
        }
        fin(self.conventional_divisor, F::ConventionalDivisor)?;
        if !(self.conventional_divisor >= 1.0) {
            return err(F::ConventionalDivisor, Error::PlanRange);
        }
        Ok(())
    }

    /// Bed stress at the bottom, σ = φ ρ g H + P [Pa].
    pub fn stress(&self) -> f64 {
        self.solid_fraction * self.density * self.gravity * self.depth + self.pressure
    }

    /// The pairs of the scene at Young's modulus `youngs` (walls only when on).
    fn pairs(&self, youngs: f64) -> Result<[Option<Pair>; 6], Error> {
        let e_star = material::effective_modulus(youngs, self.poisson, youngs, self.poisson)?;
        let stress = self.stress();
        let mut out = [None; 6];
        for (slot, kind) in out.iter_mut().zip(PairKind::ALL) {
            if kind.is_wall() && !self.walls {
                continue;
            }
            let (r1, r2) = match kind {
                PairKind::MinMin => (self.radius_min, self.radius_min),
                PairKind::MinMax => (self.radius_min, self.radius_max),
                PairKind::MaxMax => (self.radius_max, self.radius_max),
                PairKind::MinWall => (self.radius_min, f64::INFINITY),
                PairKind::MaxWall => (self.radius_max, f64::INFINITY),
                PairKind::MinPeak => (
                    self.radius_min,
                    (PEAK_RATIO * self.radius_min).min(self.radius_max),
                ),
            };
            let r_star = material::effective_radius(r1, r2)?;
            let k = material::hertz_stiffness(e_star, r_star)?;
            let m1 = finite_pos(sphere_mass(self.density, r1))?;
            let m_star = if r2.is_infinite() {
                m1
            } else {
                let m2 = finite_pos(sphere_mass(self.density, r2))?;
                finite_pos(m1 * m2 / (m1 + m2))?
            };
            let omega0 = powerlaw::omega0(k, m_star)?;
            // Branch length l = R1 + R2 (2R on a wall: the mirror image).
            let l = if r2.is_infinite() { 2.0 * r1 } else { r1 + r2 };
            let force = core::f64::consts::PI * l * l * stress
                / (self.solid_fraction * self.coordination)
                * self.load_factor;
            if !force.is_finite() {
                return Err(Error::ResultRange);
            }
            *slot = Some(Pair {
                kind,
                r_small: r1,
                m_star,
                k,
                omega0,
                force,
            });
        }
        Ok(out)
    }
}

/// Largest of f over the pairs, with the pair.
fn worst(
    pairs: &[Option<Pair>; 6],
    f: impl Fn(&Pair) -> Result<f64, Error>,
) -> Result<(f64, PairKind), Error> {
    let mut best = (f64::NEG_INFINITY, PairKind::MinMin);
    for p in pairs.iter().flatten() {
        let x = f(p)?;
        if x > best.0 {
            best = (x, p.kind);
        }
    }
    if best.0.is_nan() || best.0 == f64::NEG_INFINITY {
        return Err(Error::ResultRange);
    }
    Ok(best)
}

/// δ_max/R at v_max for one pair (closed form, damped as calibrated).
fn overlap_ratio(p: &Pair, alpha: f64, v: f64) -> Result<f64, Error> {
    let c = Contact::new(P, alpha, v, p.omega0)?;
    Ok(powerlaw::max_overlap(&c)? / p.r_small)
}

/// Static δ/R: the Hertz equilibrium k δ^(3/2) = f (0 without load).
fn static_ratio(p: &Pair) -> Result<f64, Error> {
    if p.force == 0.0 {
        return Ok(0.0);
    }
    Ok((p.force / p.k).powf(1.0 / P) / p.r_small)
}

/// The R_min–R_min pair (always present).
fn min_pair(pairs: &[Option<Pair>; 6]) -> Result<Pair, Error> {
    pairs.first().copied().flatten().ok_or(Error::ResultRange)
}

/// The smallest-time-scale pair: largest ω0 (t* ∝ ω0^(−4/5) at a common v).
fn fastest_pair(pairs: &[Option<Pair>; 6]) -> Result<Pair, Error> {
    let mut best = min_pair(pairs)?;
    for p in pairs.iter().flatten() {
        if p.omega0 > best.omega0 {
            best = *p;
        }
    }
    Ok(best)
}

/// Contact duration of a pair at v_max under `criterion`.
fn duration(p: &Pair, alpha: f64, v: f64, criterion: EndCriterion) -> Result<f64, Error> {
    let c = Contact::new(P, alpha, v, p.omega0)?;
    powerlaw::contact_duration(&c, criterion, LEVEL)
}

/// The per-contact figures of the scene at one Young's modulus (see [`evaluate`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Evaluation {
    /// Largest δ_max/R at v_max over the pairs.
    pub max_overlap_ratio: f64,
    /// Where.
    pub max_overlap_pair: PairKind,
    /// Largest static δ/R over the pairs (0 without load).
    pub static_overlap_ratio: f64,
    /// Where.
    pub static_pair: PairKind,
    /// Contact duration of the R_min–R_min pair at v_max under the criterion [s].
    pub duration: f64,
}

/// The scene's per-contact figures at Young's modulus `youngs` (the inputs are checked first;
/// `youngs` must be finite and > 0, reported as [`PlanField::Youngs`]).
pub fn evaluate(inp: &PlanInput, youngs: f64) -> Result<Evaluation, PlanError> {
    inp.check()?;
    let alpha = powerlaw::alpha_from_e(inp.restitution, P, inp.criterion)
        .map_err(PlanError::at(PlanField::Restitution))?;
    evaluate_checked(inp, youngs, alpha).map_err(PlanError::at(PlanField::Youngs))
}

fn evaluate_checked(inp: &PlanInput, youngs: f64, alpha: f64) -> Result<Evaluation, Error> {
    let pairs = inp.pairs(youngs)?;
    let (ov, ov_pair) = worst(&pairs, |p| overlap_ratio(p, alpha, inp.v_max))?;
    let (st, st_pair) = worst(&pairs, static_ratio)?;
    let tau = duration(&min_pair(&pairs)?, alpha, inp.v_max, inp.criterion)?;
    Ok(Evaluation {
        max_overlap_ratio: ov,
        max_overlap_pair: ov_pair,
        static_overlap_ratio: st,
        static_pair: st_pair,
        duration: tau,
    })
}

/// The planner. See the module docs.
pub fn plan(inp: &PlanInput) -> Result<Plan, PlanError> {
    inp.check()?;
    // A refusal with no single input at fault, except that a computation which does not
    // converge at this restitution (e → 0: the contact's duration or a collision that does not
    // end) refuses the restitution as infeasible.
    let none = |e: Error| match e {
        Error::NoConvergence => PlanError {
            field: PlanField::Restitution,
            error: Error::PlanInfeasible,
        },
        e => PlanError::at(PlanField::None)(e),
    };
    let alpha = powerlaw::alpha_from_e(inp.restitution, P, inp.criterion)
        .map_err(PlanError::at(PlanField::Restitution))?;
    let e_real = inp.youngs;
    let real = evaluate_checked(inp, e_real, alpha).map_err(&none)?;
    let (ov_real, st_real, tau_real) = (
        real.max_overlap_ratio,
        real.static_overlap_ratio,
        real.duration,
    );
    // Lower bounds on E from each tolerance, by the exact exponents of the module docs.
    let static_bound = if st_real > 0.0 && inp.static_tol.is_finite() {
        e_real * (st_real / inp.static_tol).powf(1.5)
    } else {
        0.0
    };
    let duration_bound = if inp.duration_tol.is_finite() {
        e_real * (1.0 + inp.duration_tol).powf(-2.5)
    } else {
        0.0
    };
    let bounds = [
        (
            e_real * (ov_real / inp.overlap_tol).powf(2.5),
            Binding::Overlap,
        ),
        (static_bound, Binding::Static),
        (duration_bound, Binding::Duration),
    ];
    let (mut youngs, binding) =
        bounds.iter().copied().fold(
            (0.0, Binding::Overlap),
            |b, x| if x.0 > b.0 { x } else { b },
        );
    // Which tolerance an evaluation misses, if any.
    let missed = |ev: &Evaluation| {
        if !(ev.max_overlap_ratio <= inp.overlap_tol) {
            Some(PlanField::OverlapTol)
        } else if !(ev.static_overlap_ratio <= inp.static_tol) {
            Some(PlanField::StaticTol)
        } else if !(ev.duration / tau_real - 1.0 <= inp.duration_tol) {
            Some(PlanField::DurationTol)
        } else {
            None
        }
    };
    let infeasible = |field| PlanError {
        field,
        error: Error::PlanInfeasible,
    };
    if youngs >= e_real {
        // The real material must meet the tolerances itself.
        if let Some(f) = missed(&real) {
            return Err(infeasible(f));
        }
        youngs = e_real;
    }
    // After the real material's check: a bound that overflows (a tolerance far below what the
    // real material gives, 1e-300) is that tolerance's infeasibility, named, not a range error.
    if !(youngs.is_finite() && youngs > 0.0) {
        return Err(none(Error::ResultRange));
    }
    // Re-check with the library's functions at the chosen modulus; rounding in the inversion can
    // land a few ulps outside a tolerance: step up until inside (never above the real E).
    let mut chosen = None;
    for _ in 0..64 {
        let ev = evaluate_checked(inp, youngs, alpha).map_err(&none)?;
        match missed(&ev) {
            None => {
                chosen = Some(ev);
                break;
            }
            Some(f) if youngs >= e_real => return Err(infeasible(f)),
            Some(_) => youngs = (youngs * (1.0 + 4.0 * f64::EPSILON)).min(e_real),
        }
    }
    let Some(ev) = chosen else {
        return Err(none(Error::NoConvergence));
    };
    let (ov, ov_pair, st, st_pair, tau) = (
        ev.max_overlap_ratio,
        ev.max_overlap_pair,
        ev.static_overlap_ratio,
        ev.static_pair,
        ev.duration,
    );
    let pairs = inp.pairs(youngs).map_err(&none)?;
    // The step: e tolerance on the fastest pair, and the resting-contact stability limit.
    let fast = fastest_pair(&pairs).map_err(&none)?;
    let dt_e = timestep::dt_for_accuracy(
        P,
        inp.restitution,
        inp.criterion,
        inp.v_max,
        fast.omega0,
        inp.e_tol,
    )
    .map_err(|e| match e {
        // e → 0 (DC_END_OVERLAP from about 1e-8, DC_END_FORCE from about 1e-13), or a
        // tolerance below the damping's first-order error: the search's fine collision does not
        // end, its finest steps show no error law, no checked extrapolated step meets the
        // tolerance, or the step is not a double: no step resolves the tolerance.
        Error::NoConvergence | Error::ResultRange => infeasible(PlanField::ETol),
        e => none(e),
    })?;
    let mut dt_stab = f64::INFINITY;
    for p in pairs.iter().flatten() {
        if p.force > 0.0 {
            let d = powerlaw::timestep::dt_static(P, alpha, p.omega0, p.force / p.m_star)
                .map_err(&none)?;
            dt_stab = dt_stab.min(d);
        }
    }
    let dt_stab_used = inp.stability_fraction * dt_stab;
    let (dt, binding_dt) = if dt_stab_used < dt_e {
        (dt_stab_used, StepBinding::Stability)
    } else {
        (dt_e, StepBinding::Restitution)
    };
    // What the plain dashpot realises at dt: the fastest pair at v_max, N_PHASE onset phases.
    let pm = powerlaw_from_alpha(P, fast.k, alpha, inp.criterion).map_err(&none)?;
    let (mut e_min, mut e_max, mut e_sum, mut e_far) =
        (f64::INFINITY, f64::NEG_INFINITY, 0.0, inp.restitution);
    let tau_fast = duration(&fast, alpha, inp.v_max, inp.criterion).map_err(&none)?;
    if !(tau_fast / dt <= MAX_STEPS_PER_CONTACT) {
        let field = match binding_dt {
            StepBinding::Restitution => PlanField::ETol,
            StepBinding::Stability => PlanField::StabilityFraction,
        };
        return Err(infeasible(field));
    }
    let budget = (64.0 * tau_fast / dt + 64.0).min(4.0e9) as u32;
    let last = f64::from(N_PHASE - 1);
    for i in 0..N_PHASE {
        let phase = f64::from(i) / last * (1.0 - f64::EPSILON * 1024.0);
        let c = timestep::collide(
            &pm,
            fast.m_star,
            fast.r_small,
            inp.v_max,
            dt,
            phase,
            Scheme::VelocityVerlet,
            budget,
        )
        .map_err(&none)?;
        e_min = e_min.min(c.e);
        e_max = e_max.max(c.e);
        e_sum += c.e;
        if (c.e - inp.restitution).abs() > (e_far - inp.restitution).abs() {
            e_far = c.e;
        }
    }
    // The step is dt_for_accuracy's, verified at these phases where its search simulated it;
    // where it returned an extrapolated step finer than it checks (tolerances far below the
    // damping's first-order error, e → 0 with DC_END_OVERLAP) the realised e can miss: refused,
    // not reported as a plan that holds.
    if !((e_far - inp.restitution).abs() <= inp.e_tol * inp.restitution) {
        return Err(infeasible(PlanField::ETol));
    }
    let min_p = min_pair(&pairs).map_err(&none)?;
    let t_hertz = {
        let c = Contact::new(P, 0.0, inp.v_max, min_p.omega0).map_err(&none)?;
        powerlaw::contact_duration(&c, EndCriterion::Overlap, LEVEL).map_err(&none)?
    };
    let dt_conv = tau_real / inp.conventional_divisor;
    let static_force = pairs
        .iter()
        .flatten()
        .find(|p| p.kind == st_pair)
        .map_or(0.0, |p| p.force);
    Ok(Plan {
        youngs_soft: youngs,
        softening: e_real / youngs,
        binding,
        dt,
        binding_dt,
        dt_restitution: dt_e,
        dt_stability: dt_stab,
        dt_conventional: dt_conv,
        speedup: dt / dt_conv,
        alpha,
        max_overlap_ratio: ov,
        max_overlap_pair: ov_pair,
        max_overlap_ratio_real: ov_real,
        static_overlap_ratio: st,
        static_pair: st_pair,
        static_overlap_ratio_real: st_real,
        stress: inp.stress(),
        static_force,
        duration: tau,
        duration_real: tau_real,
        duration_change: tau / tau_real - 1.0,
        t_hertz,
        dt_over_t_hertz: dt / t_hertz,
        steps_per_contact: tau / dt,
        e_plain_at_dt: e_far,
        e_plain_min: e_min,
        e_plain_max: e_max,
        e_plain_mean: e_sum / f64::from(N_PHASE),
    })
}

/// The step with the step-aware dashpot (see the module docs), at the plan's modulus.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepAware {
    /// Largest step meeting every tolerance with the step-aware dashpot [s]: the smaller of
    /// `dt_restitution` and `stability_fraction` × the plan's `dt_stability`.
    pub dt: f64,
    /// What sets dt.
    pub binding_dt: StepBinding,
    /// The e-tolerance step of the step-aware dashpot, fastest pair at v_max [s].
    pub dt_restitution: f64,
    /// dt over the plan's (plain) dt.
    pub gain: f64,
    /// dt/dt_conventional.
    pub speedup: f64,
    /// dt over the elastic Hertz duration at v_max (R_min–R_min pair, youngs_soft).
    pub dt_over_t_hertz: f64,
    /// Steps per contact at v_max: the plan's duration/dt.
    pub steps_per_contact: f64,
}

/// The step-aware counterpart of the plan's step (`pl` must be `plan(inp)`): the inputs are
/// checked again; the refusals are [`plan`]'s, and [`Error::StepUnreachable`] (field
/// [`PlanField::ETol`]) when no step down to t_H/8192 meets the e tolerance.
pub fn step_aware(inp: &PlanInput, pl: &Plan) -> Result<StepAware, PlanError> {
    inp.check()?;
    let none = PlanError::at(PlanField::None);
    let pairs = inp.pairs(pl.youngs_soft).map_err(&none)?;
    let fast = fastest_pair(&pairs).map_err(&none)?;
    let dt_e = crate::contact::step_exact::dt_for_accuracy(
        P,
        inp.restitution,
        inp.criterion,
        inp.v_max,
        fast.omega0,
        inp.e_tol,
    )
    .map_err(|e| match e {
        Error::StepUnreachable => PlanError {
            field: PlanField::ETol,
            error: e,
        },
        e => none(e),
    })?;
    let dt_stab_used = inp.stability_fraction * pl.dt_stability;
    let (dt, binding_dt) = if dt_stab_used < dt_e {
        (dt_stab_used, StepBinding::Stability)
    } else {
        (dt_e, StepBinding::Restitution)
    };
    Ok(StepAware {
        dt,
        binding_dt,
        dt_restitution: dt_e,
        gain: dt / pl.dt,
        speedup: dt / pl.dt_conventional,
        dt_over_t_hertz: dt / pl.t_hertz,
        steps_per_contact: pl.duration / dt,
    })
}
