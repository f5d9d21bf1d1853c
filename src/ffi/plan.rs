//! Exports: the scene planner (docs/plan.md), a field-for-field copy of [`crate::plan`].

use super::status::dc_status;
use super::{guard, parse_criterion, read_in};
use crate::plan::{self, PlanField, PlanInput};

/// Version of dc_plan_input this library reads (dc_plan_input_init sets it).
pub const DC_PLAN_INPUT_VERSION: u32 = 1;

/// dc_plan's field codes (`field_out`): which dc_plan_input member a refusal is about.
/// DC_PLAN_FIELD_NONE: no single member (e.g. DC_ERR_RESULT_RANGE).
pub const DC_PLAN_FIELD_NONE: i32 = 0;
/// youngs.
pub const DC_PLAN_FIELD_YOUNGS: i32 = 1;
/// poisson.
pub const DC_PLAN_FIELD_POISSON: i32 = 2;
/// density.
pub const DC_PLAN_FIELD_DENSITY: i32 = 3;
/// restitution.
pub const DC_PLAN_FIELD_RESTITUTION: i32 = 4;
/// radius_min.
pub const DC_PLAN_FIELD_RADIUS_MIN: i32 = 5;
/// radius_max (also when radius_max < radius_min).
pub const DC_PLAN_FIELD_RADIUS_MAX: i32 = 6;
/// v_max.
pub const DC_PLAN_FIELD_V_MAX: i32 = 7;
/// depth.
pub const DC_PLAN_FIELD_DEPTH: i32 = 8;
/// gravity.
pub const DC_PLAN_FIELD_GRAVITY: i32 = 9;
/// pressure.
pub const DC_PLAN_FIELD_PRESSURE: i32 = 10;
/// solid_fraction.
pub const DC_PLAN_FIELD_SOLID_FRACTION: i32 = 11;
/// coordination.
pub const DC_PLAN_FIELD_COORDINATION: i32 = 12;
/// load_factor.
pub const DC_PLAN_FIELD_LOAD_FACTOR: i32 = 13;
/// friction.
pub const DC_PLAN_FIELD_FRICTION: i32 = 14;
/// rolling_friction.
pub const DC_PLAN_FIELD_ROLLING_FRICTION: i32 = 15;
/// overlap_tol (also DC_ERR_PLAN_INFEASIBLE: the real material misses it).
pub const DC_PLAN_FIELD_OVERLAP_TOL: i32 = 16;
/// e_tol.
pub const DC_PLAN_FIELD_E_TOL: i32 = 17;
/// static_tol (also DC_ERR_PLAN_INFEASIBLE).
pub const DC_PLAN_FIELD_STATIC_TOL: i32 = 18;
/// duration_tol.
pub const DC_PLAN_FIELD_DURATION_TOL: i32 = 19;
/// criterion.
pub const DC_PLAN_FIELD_CRITERION: i32 = 20;
/// stability_fraction.
pub const DC_PLAN_FIELD_STABILITY_FRACTION: i32 = 21;
/// conventional_divisor.
pub const DC_PLAN_FIELD_CONVENTIONAL_DIVISOR: i32 = 22;
/// walls (not 0 or 1).
pub const DC_PLAN_FIELD_WALLS: i32 = 23;

/// dc_plan_result.binding: the impact overlap tolerance sets the modulus.
pub const DC_PLAN_BINDING_OVERLAP: i32 = 0;
/// dc_plan_result.binding: the static overlap tolerance sets the modulus.
pub const DC_PLAN_BINDING_STATIC: i32 = 1;
/// dc_plan_result.binding: the duration tolerance sets the modulus.
pub const DC_PLAN_BINDING_DURATION: i32 = 2;
/// dc_plan_result.binding_dt: the restitution tolerance sets the step.
pub const DC_PLAN_STEP_RESTITUTION: i32 = 0;
/// dc_plan_result.binding_dt: the resting-contact stability limit sets the step.
pub const DC_PLAN_STEP_STABILITY: i32 = 1;

/// dc_plan_result pair codes: two spheres of radius_min.
pub const DC_PLAN_PAIR_MIN_MIN: i32 = 0;
/// radius_min against radius_max.
pub const DC_PLAN_PAIR_MIN_MAX: i32 = 1;
/// Two spheres of radius_max.
pub const DC_PLAN_PAIR_MAX_MAX: i32 = 2;
/// radius_min against a wall.
pub const DC_PLAN_PAIR_MIN_WALL: i32 = 3;
/// radius_max against a wall.
pub const DC_PLAN_PAIR_MAX_WALL: i32 = 4;
/// radius_min against min(radius_max, 2.7913 radius_min), the size ratio (1 + sqrt(21))/2 of
/// the largest impact overlap.
pub const DC_PLAN_PAIR_MIN_PEAK: i32 = 5;

/// A scene for dc_plan (docs/plan.md): fill it with dc_plan_input_init, then set the members by
/// name. Units SI. Members the init leaves NaN are required.
///
/// Versioned: `version` and `size` (set by dc_plan_input_init) let later library versions append
/// members (a step-aware option) without breaking callers compiled against this one; dc_plan
/// writes the dc_plan_result of the input's version.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_plan_input {
    /// DC_PLAN_INPUT_VERSION.
    pub version: u32,
    /// sizeof(dc_plan_input) as the caller compiled it.
    pub size: u32,
    /// Real Young's modulus E [Pa] > 0 (required).
    pub youngs: f64,
    /// Poisson's ratio in (-1, 0.5] (required).
    pub poisson: f64,
    /// Particle density [kg/m^3] > 0 (required).
    pub density: f64,
    /// Target restitution in (0, 1] (required).
    pub restitution: f64,
    /// Smallest radius [m] > 0 (required).
    pub radius_min: f64,
    /// Largest radius [m] >= radius_min (required).
    pub radius_max: f64,
    /// Largest impact speed [m/s] > 0 (required).
    pub v_max: f64,
    /// Bed depth [m] >= 0 (required).
    pub depth: f64,
    /// Gravity [m/s^2] >= 0 (init: 9.81).
    pub gravity: f64,
    /// Confining pressure added to the bed weight [Pa] >= 0 (init: 0).
    pub pressure: f64,
    /// Solid fraction of the bed in (0, 1) (init: 0.6).
    pub solid_fraction: f64,
    /// Coordination number > 0 (init: 6).
    pub coordination: f64,
    /// Largest over mean contact force >= 1 (init: 1).
    pub load_factor: f64,
    /// Sliding friction >= 0 (init: 0; recorded, not used by the bounds).
    pub friction: f64,
    /// Rolling friction >= 0 (init: 0; recorded, not used by the bounds).
    pub rolling_friction: f64,
    /// Largest delta_max/R at v_max, in (0, 1) (required).
    pub overlap_tol: f64,
    /// Largest relative error of the realised e at the step, in (0, 1) (required).
    pub e_tol: f64,
    /// Largest static delta/R, > 0; +INFINITY: no bound (init: +INFINITY; the CLI's default is
    /// overlap_tol).
    pub static_tol: f64,
    /// Largest tau_soft/tau_real - 1, > 0; +INFINITY: no bound (init: +INFINITY).
    pub duration_tol: f64,
    /// DC_END_FORCE or DC_END_OVERLAP (init: DC_END_FORCE).
    pub criterion: i32,
    /// 1: walls of the same material are part of the scene; 0: none (init: 1).
    pub walls: i32,
    /// Fraction of the resting-contact stability limit the step may use, in (0, 1] (init: 0.5).
    pub stability_fraction: f64,
    /// The conventional step is tau_real/conventional_divisor, >= 1 (init: 50).
    pub conventional_divisor: f64,
}

/// What dc_plan chooses and predicts (the members of docs/plan.md's JSON, same names).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_plan_result {
    /// Softest Young's modulus meeting every tolerance [Pa].
    pub youngs_soft: f64,
    /// youngs / youngs_soft.
    pub softening: f64,
    /// DC_PLAN_BINDING_*: the tolerance that sets youngs_soft.
    pub binding: i32,
    /// DC_PLAN_STEP_*: what sets dt.
    pub binding_dt: i32,
    /// Largest step [s].
    pub dt: f64,
    /// The e-tolerance step [s].
    pub dt_restitution: f64,
    /// Resting-contact stability limit [s] (+INFINITY without static load), before
    /// stability_fraction.
    pub dt_stability: f64,
    /// Conventional step: tau_real / conventional_divisor [s].
    pub dt_conventional: f64,
    /// dt / dt_conventional.
    pub speedup: f64,
    /// Damping coefficient alpha.
    pub alpha: f64,
    /// Largest delta_max/R at v_max at youngs_soft.
    pub max_overlap_ratio: f64,
    /// The same at the real modulus.
    pub max_overlap_ratio_real: f64,
    /// Largest static delta/R at youngs_soft.
    pub static_overlap_ratio: f64,
    /// The same at the real modulus.
    pub static_overlap_ratio_real: f64,
    /// DC_PLAN_PAIR_* of max_overlap_ratio.
    pub max_overlap_pair: i32,
    /// DC_PLAN_PAIR_* of static_overlap_ratio.
    pub static_pair: i32,
    /// Bed stress [Pa].
    pub stress: f64,
    /// Static force on static_pair's contact [N].
    pub static_force: f64,
    /// Contact duration at v_max, radius_min pair, youngs_soft [s].
    pub duration: f64,
    /// The same at the real modulus [s].
    pub duration_real: f64,
    /// duration / duration_real - 1.
    pub duration_change: f64,
    /// Elastic Hertz duration at v_max, radius_min pair, youngs_soft [s].
    pub t_hertz: f64,
    /// dt / t_hertz.
    pub dt_over_t_hertz: f64,
    /// duration / dt.
    pub steps_per_contact: f64,
    /// Realised e at dt (plain dashpot) farthest from the target over 64 onset phases.
    pub e_plain_at_dt: f64,
    /// Smallest realised e over the phases.
    pub e_plain_min: f64,
    /// Largest realised e over the phases.
    pub e_plain_max: f64,
    /// Mean realised e over the phases.
    pub e_plain_mean: f64,
}

fn default_input() -> dc_plan_input {
    let d = PlanInput::new();
    dc_plan_input {
        version: DC_PLAN_INPUT_VERSION,
        size: core::mem::size_of::<dc_plan_input>() as u32,
        youngs: d.youngs,
        poisson: d.poisson,
        density: d.density,
        restitution: d.restitution,
        radius_min: d.radius_min,
        radius_max: d.radius_max,
        v_max: d.v_max,
        depth: d.depth,
        gravity: d.gravity,
        pressure: d.pressure,
        solid_fraction: d.solid_fraction,
        coordination: d.coordination,
        load_factor: d.load_factor,
        friction: d.friction,
        rolling_friction: d.rolling_friction,
        overlap_tol: d.overlap_tol,
        e_tol: d.e_tol,
        static_tol: d.static_tol,
        duration_tol: d.duration_tol,
        criterion: d.criterion.code(),
        walls: i32::from(d.walls),
        stability_fraction: d.stability_fraction,
        conventional_divisor: d.conventional_divisor,
    }
}

/// Fills a dc_plan_input with its version, size and defaults (required members NaN).
///
/// @param input  receives the defaults; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER.
///
/// # Safety
/// `input` must be NULL or point to writable memory for one dc_plan_input.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_plan_input_init(input: *mut dc_plan_input) -> i32 {
    // SAFETY: forwarded caller contract on input.
    unsafe { super::write_result(input, || Ok(default_input())) }
}

/// The scene planner: the softest Young's modulus and the largest velocity-Verlet step that keep
/// delta_max/R at v_max, the static delta/R under the bed load, the contact duration's
/// lengthening and the realised e within the input's tolerances, and the per-contact figures at
/// that choice (docs/plan.md has the model: six extreme pairs, the bed load
/// f = pi (R1+R2)^2 (phi rho g H + P)/(phi Z), the exact scaling of each figure in E, and the
/// speed-up dt/dt_conventional at unchanged cost per step). Every figure comes from the
/// library's exact functions (dc_max_overlap, dc_contact_duration, dc_dt_for_accuracy,
/// dc_dt_static, and velocity-Verlet collisions at 64 onset phases).
///
/// Cost: one dc_dt_for_accuracy (up to ~200 ms for e ~ 0.1, e_tol ~ 1e-3; seconds where it
/// checks an extrapolated step, e_tol below about 1e-4 with strong damping) and 64 simulated
/// collisions of at most 2^22 steps each (a plan needing more steps per contact is refused:
/// DC_ERR_PLAN_INFEASIBLE); allocation-free, thread-safe. Call it at set-up.
///
/// @param input      the scene (dc_plan_input_init, then the members set by name).
/// @param out        receives the plan on DC_OK; untouched on error.
/// @param field_out  NULL, or receives DC_PLAN_FIELD_* of the member at fault on an error
///                   status (DC_PLAN_FIELD_NONE when no single member is); untouched on DC_OK.
/// @return DC_OK, DC_ERR_NULL_POINTER (input or out), DC_ERR_NOT_FINITE (a NaN or infinite member; +INFINITY is allowed
///         for static_tol and duration_tol), DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE,
///         DC_ERR_POISSON_RANGE, DC_ERR_RESTITUTION_RANGE, DC_ERR_CRITERION,
///         DC_ERR_PLAN_RANGE (version or size not this library's (field NONE), radius_max < radius_min, solid_fraction outside (0, 1), a
///         tolerance >= 1, load_factor < 1, stability_fraction outside (0, 1], conventional_divisor
///         < 1, walls not 0/1), DC_ERR_PLAN_INFEASIBLE (the real material misses the tolerance
///         named by field_out; DC_PLAN_FIELD_E_TOL: no step meets the e tolerance with at most
///         2^22 steps in a contact and its realised e within it at all 64 phases, as for e → 0
///         with DC_END_OVERLAP below about 1e-6 at e_tol 1e-2; DC_PLAN_FIELD_STABILITY_FRACTION:
///         the stability step so scaled puts more than 2^22 steps in a contact;
///         DC_PLAN_FIELD_RESTITUTION: a contact this damped does not converge, e → 0), DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `input` must be NULL or readable for its leading `version` and `size` members, and for the
/// `size` bytes they announce when they are this library's (`size` is then sizeof one
/// dc_plan_input); `out` NULL or writable for one dc_plan_result; `field_out` NULL or writable
/// for one int32_t.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_plan(
    input: *const dc_plan_input,
    out: *mut dc_plan_result,
    field_out: *mut i32,
) -> i32 {
    if out.is_null() {
        // An error status like any other: field_out says no single member is at fault.
        if !field_out.is_null() {
            // SAFETY: non-null; writability is the caller's contract.
            unsafe { field_out.write_unaligned(PlanField::None as i32) };
        }
        return dc_status::DC_ERR_NULL_POINTER.code();
    }
    let mut field = PlanField::None;
    let status = guard(|| {
        // The two leading u32 (version, size) first: a caller compiled against another
        // version's struct may have fewer bytes than this one, never read past them.
        // SAFETY: readability of the leading members is the caller's contract.
        let head = unsafe { read_in(input.cast::<[u32; 2]>()) }?;
        if head[0] != DC_PLAN_INPUT_VERSION
            || head[1] as usize != core::mem::size_of::<dc_plan_input>()
        {
            return Err(dc_status::DC_ERR_PLAN_RANGE);
        }
        // SAFETY: the caller's struct is this version's, readability its contract.
        let i = unsafe { read_in(input) }?;
        let criterion = parse_criterion(i.criterion).inspect_err(|_| {
            field = PlanField::Criterion;
        })?;
        if !(i.walls == 0 || i.walls == 1) {
            field = PlanField::Walls;
            return Err(dc_status::DC_ERR_PLAN_RANGE);
        }
        let inp = PlanInput {
            youngs: i.youngs,
            poisson: i.poisson,
            density: i.density,
            restitution: i.restitution,
            radius_min: i.radius_min,
            radius_max: i.radius_max,
            v_max: i.v_max,
            depth: i.depth,
            gravity: i.gravity,
            pressure: i.pressure,
            solid_fraction: i.solid_fraction,
            coordination: i.coordination,
            load_factor: i.load_factor,
            friction: i.friction,
            rolling_friction: i.rolling_friction,
            overlap_tol: i.overlap_tol,
            e_tol: i.e_tol,
            static_tol: i.static_tol,
            duration_tol: i.duration_tol,
            criterion,
            walls: i.walls == 1,
            stability_fraction: i.stability_fraction,
            conventional_divisor: i.conventional_divisor,
        };
        let p = plan::plan(&inp).map_err(|e| {
            field = e.field;
            dc_status::of(e.error)
        })?;
        let r = dc_plan_result {
            youngs_soft: p.youngs_soft,
            softening: p.softening,
            binding: p.binding as i32,
            binding_dt: p.binding_dt as i32,
            dt: p.dt,
            dt_restitution: p.dt_restitution,
            dt_stability: p.dt_stability,
            dt_conventional: p.dt_conventional,
            speedup: p.speedup,
            alpha: p.alpha,
            max_overlap_ratio: p.max_overlap_ratio,
            max_overlap_ratio_real: p.max_overlap_ratio_real,
            static_overlap_ratio: p.static_overlap_ratio,
            static_overlap_ratio_real: p.static_overlap_ratio_real,
            max_overlap_pair: p.max_overlap_pair as i32,
            static_pair: p.static_pair as i32,
            stress: p.stress,
            static_force: p.static_force,
            duration: p.duration,
            duration_real: p.duration_real,
            duration_change: p.duration_change,
            t_hertz: p.t_hertz,
            dt_over_t_hertz: p.dt_over_t_hertz,
            steps_per_contact: p.steps_per_contact,
            e_plain_at_dt: p.e_plain_at_dt,
            e_plain_min: p.e_plain_min,
            e_plain_max: p.e_plain_max,
            e_plain_mean: p.e_plain_mean,
        };
        // SAFETY: non-null checked above; writability is the caller's contract.
        unsafe { out.write_unaligned(r) };
        Ok(())
    });
    if status != dc_status::DC_OK.code() && !field_out.is_null() {
        // SAFETY: non-null; writability is the caller's contract.
        unsafe { field_out.write_unaligned(field as i32) };
    }
    status
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> dc_plan_input {
        dc_plan_input {
            youngs: 7e10,
            poisson: 0.22,
            density: 2500.0,
            restitution: 0.5,
            radius_min: 1e-3,
            radius_max: 2e-3,
            v_max: 2.0,
            depth: 0.5,
            overlap_tol: 0.01,
            e_tol: 0.01,
            ..default_input()
        }
    }

    #[test]
    fn codes_are_the_core_values() {
        use plan::{Binding, PairKind, StepBinding};
        let fields = [
            (DC_PLAN_FIELD_NONE, PlanField::None),
            (DC_PLAN_FIELD_YOUNGS, PlanField::Youngs),
            (DC_PLAN_FIELD_POISSON, PlanField::Poisson),
            (DC_PLAN_FIELD_DENSITY, PlanField::Density),
            (DC_PLAN_FIELD_RESTITUTION, PlanField::Restitution),
            (DC_PLAN_FIELD_RADIUS_MIN, PlanField::RadiusMin),
            (DC_PLAN_FIELD_RADIUS_MAX, PlanField::RadiusMax),
            (DC_PLAN_FIELD_V_MAX, PlanField::VMax),
            (DC_PLAN_FIELD_DEPTH, PlanField::Depth),
            (DC_PLAN_FIELD_GRAVITY, PlanField::Gravity),
            (DC_PLAN_FIELD_PRESSURE, PlanField::Pressure),
            (DC_PLAN_FIELD_SOLID_FRACTION, PlanField::SolidFraction),
            (DC_PLAN_FIELD_COORDINATION, PlanField::Coordination),
            (DC_PLAN_FIELD_LOAD_FACTOR, PlanField::LoadFactor),
            (DC_PLAN_FIELD_FRICTION, PlanField::Friction),
            (DC_PLAN_FIELD_ROLLING_FRICTION, PlanField::RollingFriction),
            (DC_PLAN_FIELD_OVERLAP_TOL, PlanField::OverlapTol),
            (DC_PLAN_FIELD_E_TOL, PlanField::ETol),
            (DC_PLAN_FIELD_STATIC_TOL, PlanField::StaticTol),
            (DC_PLAN_FIELD_DURATION_TOL, PlanField::DurationTol),
            (DC_PLAN_FIELD_CRITERION, PlanField::Criterion),
            (
                DC_PLAN_FIELD_STABILITY_FRACTION,
                PlanField::StabilityFraction,
            ),
            (
                DC_PLAN_FIELD_CONVENTIONAL_DIVISOR,
                PlanField::ConventionalDivisor,
            ),
            (DC_PLAN_FIELD_WALLS, PlanField::Walls),
        ];
        for (c, f) in fields {
            assert_eq!(c, f as i32, "{f:?}");
        }
        assert_eq!(DC_PLAN_BINDING_OVERLAP, Binding::Overlap as i32);
        assert_eq!(DC_PLAN_BINDING_STATIC, Binding::Static as i32);
        assert_eq!(DC_PLAN_BINDING_DURATION, Binding::Duration as i32);
        assert_eq!(DC_PLAN_STEP_RESTITUTION, StepBinding::Restitution as i32);
        assert_eq!(DC_PLAN_STEP_STABILITY, StepBinding::Stability as i32);
        let pairs = [
            DC_PLAN_PAIR_MIN_MIN,
            DC_PLAN_PAIR_MIN_MAX,
            DC_PLAN_PAIR_MAX_MAX,
            DC_PLAN_PAIR_MIN_WALL,
            DC_PLAN_PAIR_MAX_WALL,
            DC_PLAN_PAIR_MIN_PEAK,
        ];
        for (c, k) in pairs.into_iter().zip(PairKind::ALL) {
            assert_eq!(c, k as i32, "{k:?}");
        }
    }

    #[test]
    fn plan_matches_the_core_and_names_bad_fields() {
        let mut out = dc_plan_result::default();
        let mut field = -1;
        let inp = scene();
        // SAFETY: valid pointers.
        let s = unsafe { dc_plan(&inp, &mut out, &mut field) };
        assert_eq!(s, 0);
        assert_eq!(field, -1, "field_out written on success");
        let core = plan::plan(&PlanInput {
            youngs: 7e10,
            poisson: 0.22,
            density: 2500.0,
            restitution: 0.5,
            radius_min: 1e-3,
            radius_max: 2e-3,
            v_max: 2.0,
            depth: 0.5,
            overlap_tol: 0.01,
            e_tol: 0.01,
            ..PlanInput::new()
        });
        let core = core.unwrap_or_else(|_| unreachable!());
        assert_eq!(out.youngs_soft, core.youngs_soft);
        assert_eq!(out.dt, core.dt);
        assert_eq!(out.e_plain_mean, core.e_plain_mean);
        for (bad, code, want) in [
            (
                dc_plan_input {
                    radius_max: 5e-4,
                    ..scene()
                },
                dc_status::DC_ERR_PLAN_RANGE,
                DC_PLAN_FIELD_RADIUS_MAX,
            ),
            (
                dc_plan_input {
                    youngs: -1.0,
                    ..scene()
                },
                dc_status::DC_ERR_NOT_POSITIVE,
                DC_PLAN_FIELD_YOUNGS,
            ),
            (
                dc_plan_input {
                    e_tol: f64::NAN,
                    ..scene()
                },
                dc_status::DC_ERR_NOT_FINITE,
                DC_PLAN_FIELD_E_TOL,
            ),
            (
                dc_plan_input {
                    criterion: 7,
                    ..scene()
                },
                dc_status::DC_ERR_CRITERION,
                DC_PLAN_FIELD_CRITERION,
            ),
            (
                dc_plan_input {
                    overlap_tol: 1e-4,
                    ..scene()
                },
                dc_status::DC_ERR_PLAN_INFEASIBLE,
                DC_PLAN_FIELD_OVERLAP_TOL,
            ),
            (
                dc_plan_input { size: 8, ..scene() },
                dc_status::DC_ERR_PLAN_RANGE,
                DC_PLAN_FIELD_NONE,
            ),
        ] {
            let mut o = dc_plan_result::default();
            let mut f = -1;
            // SAFETY: valid pointers.
            let s = unsafe { dc_plan(&bad, &mut o, &mut f) };
            assert_eq!((s, f), (code.code(), want), "{bad:?}");
            assert_eq!(o, dc_plan_result::default(), "out written on error");
        }
        // Unset required members (init leaves them NaN) are refused, naming the first.
        let mut i = scene();
        // SAFETY: valid pointer.
        assert_eq!(unsafe { dc_plan_input_init(&mut i) }, 0);
        let mut f = -1;
        // SAFETY: valid pointers.
        let s = unsafe { dc_plan(&i, &mut out, &mut f) };
        assert_eq!(
            (s, f),
            (dc_status::DC_ERR_NOT_FINITE.code(), DC_PLAN_FIELD_YOUNGS)
        );
        // SAFETY: NULL pointers are reported.
        unsafe {
            assert_eq!(
                dc_plan(core::ptr::null(), &mut out, core::ptr::null_mut()),
                dc_status::DC_ERR_NULL_POINTER.code()
            );
            assert_eq!(
                dc_plan(&inp, core::ptr::null_mut(), core::ptr::null_mut()),
                dc_status::DC_ERR_NULL_POINTER.code()
            );
            // An error status names its field (none for a NULL pointer), NULL out included.
            for (input, o) in [
                (core::ptr::null(), &mut out as *mut dc_plan_result),
                (&inp as *const dc_plan_input, core::ptr::null_mut()),
            ] {
                let mut f = -1;
                assert_eq!(
                    dc_plan(input, o, &mut f),
                    dc_status::DC_ERR_NULL_POINTER.code()
                );
                assert_eq!(f, DC_PLAN_FIELD_NONE);
            }
        }
    }
}
