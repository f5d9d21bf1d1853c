//! Exports: observables of one power-law Tsuji collision
//! `m d'' + alpha sqrt(m k) d^((p-1)/2) d' + k d^p = 0`, d(0) = 0, d'(0) = v0: maximum overlap and
//! its time, contact duration for both end criteria, energy partition, the sampled trajectory.
//!
//! Inputs shared by all: p >= 1 finite; alpha >= 0 finite; v0 > 0 [m/s]; omega0 = sqrt(k/m) > 0
//! [s^-1 m^((1-p)/2)] (see dc_omega0). Damping ratio of the image: zeta = alpha/sqrt(2(p+1));
//! zeta > 1 is overdamped, zeta = 1 critical (a continuous limit, no special case for callers).

use super::status::*;
use super::{guard, parse_criterion, read_in, write_result};
use crate::powerlaw::DurationPlan;
use crate::powerlaw::trajectory::{TrajectoryOut, sample_trajectory};
use crate::powerlaw::{self, Contact};
use crate::{EndCriterion, Error};

/// Lowest quadrature accuracy level (fastest; see docs/powerlaw.md for its measured error).
pub const DC_LEVEL_MIN: i32 = 0;
/// Highest quadrature accuracy level, used by the functions without a level argument.
pub const DC_LEVEL_MAX: i32 = 4;

// cbindgen needs literals; they must equal the core's.
const _: () =
    assert!(DC_LEVEL_MIN == powerlaw::plan::LEVEL_MIN && DC_LEVEL_MAX == powerlaw::plan::LEVEL_MAX);

fn level(l: i32) -> Result<u32, Error> {
    powerlaw::plan::level(l)
}

/// Energy partition of one collision, each as a fraction of the impact energy m v0^2 / 2.
/// The five fractions loading + unloading + returned + clamped sum to 1.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct dc_energy {
    /// Realised restitution e = |exit speed|/v0 (e^2 = returned).
    pub e: f64,
    /// Dissipated by the dashpot while loading (impact to maximum overlap): 1 - e_F.
    pub loading: f64,
    /// Dissipated by the dashpot while unloading (maximum overlap to the end event).
    pub unloading: f64,
    /// Kinetic energy returned at the end event: e^2.
    pub returned: f64,
    /// DC_END_FORCE only: elastic energy still stored when the total force reaches zero,
    /// (2 zeta e_F)^2; a solver that clamps the force loses it. 0 for DC_END_OVERLAP.
    pub clamped: f64,
}

/// Maximum overlap of a collision, in closed form for every p >= 1 and every alpha >= 0
/// (underdamped, critical and overdamped):
/// delta_max = A ((v0/omega0) exp(-g(zeta)))^q, q = 2/(p+1), A = ((p+1)/2)^(1/(p+1)),
/// g(zeta) = zeta acos(zeta)/sqrt(1-zeta^2) (acosh form above critical damping).
///
/// @param p, alpha, v0, omega0  see the file header: p >= 1, alpha >= 0, v0 > 0, omega0 > 0.
/// @param delta_max_out  receives delta_max [m]; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE, DC_ERR_RESULT_RANGE.
///
/// Precision: 1e-12 relative against an adaptive integration of the equation of motion.
///
/// # Safety
/// `delta_max_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_max_overlap(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    delta_max_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on delta_max_out.
    unsafe {
        write_result(delta_max_out, || {
            powerlaw::max_overlap(&Contact::new(p, alpha, v0, omega0)?)
        })
    }
}

/// Time from impact to maximum overlap [s], at the highest accuracy level (closed form for p = 1
/// and for alpha = 0, where it is half the contact duration; quadrature otherwise).
///
/// @return as dc_max_overlap.
///
/// # Safety
/// `t_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_time_of_max_overlap(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    t_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on t_out.
    unsafe {
        write_result(t_out, || {
            powerlaw::time_of_max_overlap(
                &Contact::new(p, alpha, v0, omega0)?,
                DC_LEVEL_MAX.unsigned_abs(),
            )
        })
    }
}

/// Contact duration tau [s] under `criterion`, at the highest accuracy level.
///
/// - DC_END_OVERLAP (overlap returns to 0): closed form for every p (Gamma functions of complex
///   argument; the Beta function B(1/(p+1), 1/2) when undamped). An overdamped or critically
///   damped contact (zeta >= 1) never returns to zero overlap (tau = infinity): DC_ERR_NO_EVENT.
/// - DC_END_FORCE (total force first reaches 0 while unloading): exact singularity-free quadrature
///   (closed form for p = 1); finite for every alpha.
///
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param tau_out    receives tau; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE, DC_ERR_CRITERION, DC_ERR_NO_EVENT,
///         DC_ERR_RESULT_RANGE (tau overflows). Near critical damping a p > 1 contact creeps
///         back: ln tau ~ pi (1-q) zeta/sqrt(1-zeta^2), q = 2/(p+1), so the overlap-end tau
///         exceeds DBL_MAX once sqrt(1-zeta^2) < ~pi (1-q)/709, e.g. zeta > 1 - 4e-7 at p = 1.5
///         (v0 = omega0 = 1); for p = 1 only within ~1e-300 of 1.
///
/// Precision: 1e-12 relative (closed forms) and 1e-10 (quadrature) against an adaptive
/// integration of the equation of motion; see docs/powerlaw.md.
///
/// # Safety
/// `tau_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_duration(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: i32,
    tau_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on tau_out.
    unsafe { dc_contact_duration_level(p, alpha, v0, omega0, criterion, DC_LEVEL_MAX, tau_out) }
}

/// dc_contact_duration with a cost/accuracy knob: `level` in DC_LEVEL_MIN..=DC_LEVEL_MAX selects
/// the Chebyshev interpolation order N = 6, 8, 12, 16, 24 (N + 1 integrand evaluations per panel;
/// one panel except strongly overdamped contacts). Closed-form cases ignore it.
/// Measured errors per level are tabulated in docs/powerlaw.md.
///
/// @return as dc_contact_duration, plus DC_ERR_LEVEL.
///
/// # Safety
/// `tau_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_duration_level(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: i32,
    level: i32,
    tau_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on tau_out.
    unsafe {
        write_result(tau_out, || {
            let c = Contact::new(p, alpha, v0, omega0)?;
            let crit = parse_criterion(criterion)?;
            powerlaw::contact_duration(&c, crit, self::level(level)?)
        })
    }
}

/// A contact-duration plan: everything dc_contact_duration_level computes from the exponent p and
/// the accuracy level alone (transform constants, ln Gamma(q), Gauss-Jacobi nodes and weights for
/// the integrand's end singularity), built once by dc_duration_plan_init and then reused by
/// dc_contact_duration_planned for any alpha, v0, omega0 and criterion. Plain data (copy it
/// freely, share it between threads read-only); treat the fields as opaque.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct dc_duration_plan {
    /// Set by dc_duration_plan_init; any other value makes dc_contact_duration_planned return
    /// DC_ERR_PLAN (e.g. a zero-filled struct).
    pub tag: u64,
    /// Force-law exponent p >= 1.
    pub p: f64,
    /// q = 2/(p+1).
    pub q: f64,
    /// A = ((p+1)/2)^(1/(p+1)).
    pub amp: f64,
    /// ln Gamma(q).
    pub lgamma_q: f64,
    /// ln(A q).
    pub ln_aq: f64,
    /// Accuracy level, DC_LEVEL_MIN..=DC_LEVEL_MAX.
    pub level: i32,
    /// Nodes in use in each rule: 5, 6, 7, 9, 12 for levels 0..4.
    pub n: i32,
    /// Gauss-Jacobi nodes in (0, 1) for the weight y^(q-1).
    pub nodes: [f64; 16],
    /// Their weights.
    pub weights: [f64; 16],
}

impl From<DurationPlan> for dc_duration_plan {
    fn from(pl: DurationPlan) -> Self {
        dc_duration_plan {
            tag: pl.tag,
            p: pl.p,
            q: pl.q,
            amp: pl.amp,
            lgamma_q: pl.lgamma_q,
            ln_aq: pl.ln_aq,
            level: pl.level,
            n: pl.n,
            nodes: pl.nodes,
            weights: pl.weights,
        }
    }
}

impl From<dc_duration_plan> for DurationPlan {
    fn from(pl: dc_duration_plan) -> Self {
        DurationPlan {
            tag: pl.tag,
            p: pl.p,
            q: pl.q,
            amp: pl.amp,
            lgamma_q: pl.lgamma_q,
            ln_aq: pl.ln_aq,
            level: pl.level,
            n: pl.n,
            nodes: pl.nodes,
            weights: pl.weights,
        }
    }
}

/// Builds a contact-duration plan for exponent p at accuracy `level` (the costly, p-dependent
/// part of dc_contact_duration_level: Gauss-Jacobi rules by Newton iteration, ln Gamma(q), A).
/// Build it once per exponent (a few microseconds) and pass it to dc_contact_duration_planned.
///
/// @param p         force-law exponent, p >= 1 finite.
/// @param level     DC_LEVEL_MIN..=DC_LEVEL_MAX: n = 5, 6, 7, 9, 12 Gauss nodes (exact for
///                  polynomials of degree 2n - 1); errors per level in docs/powerlaw.md.
/// @param plan_out  receives the plan; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE, DC_ERR_LEVEL,
///         DC_ERR_NO_CONVERGENCE (the node iteration failed: p too large, beyond about 1e6).
///
/// # Safety
/// `plan_out` must be NULL or point to writable memory for one dc_duration_plan.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_duration_plan_init(
    p: f64,
    level: i32,
    plan_out: *mut dc_duration_plan,
) -> i32 {
    // SAFETY: forwarded caller contract on plan_out.
    unsafe { write_result(plan_out, || Ok(DurationPlan::new(p, level)?.into())) }
}

/// Contact duration tau [s] with a plan from dc_duration_plan_init: the result of
/// dc_contact_duration_level for the plan's p, at a fraction of the cost (per call only the
/// integrand at the plan's n nodes, one exp each; closed forms as in dc_contact_duration).
/// Agrees with dc_contact_duration to 1e-13 relative at the plan's levels 3 and 4.
///
/// @param plan       a plan from dc_duration_plan_init (its p is the exponent used).
/// @param alpha, v0, omega0, criterion, tau_out  as dc_contact_duration.
/// @return as dc_contact_duration, plus DC_ERR_NULL_POINTER (plan NULL), DC_ERR_PLAN (plan not
///         made by dc_duration_plan_init, or modified). The plan is read by value: any alignment
///         works (earlier versions returned DC_ERR_BUFFER_LAYOUT for a misaligned plan).
///
/// # Safety
/// `plan` must be NULL or point to a readable dc_duration_plan; `tau_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_duration_planned(
    plan: *const dc_duration_plan,
    alpha: f64,
    v0: f64,
    omega0: f64,
    criterion: i32,
    tau_out: *mut f64,
) -> i32 {
    if tau_out.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    // SAFETY: readability is the caller's contract; every bit pattern of the plan is a value.
    let plan: DurationPlan = match unsafe { read_in(plan) } {
        Ok(pl) => pl.into(),
        Err(s) => return s.code(),
    };
    // SAFETY: forwarded caller contract on tau_out.
    unsafe {
        write_result(tau_out, || {
            let c = plan.contact(alpha, v0, omega0)?;
            plan.duration(&c, parse_criterion(criterion)?)
        })
    }
}

/// Energy partition of a collision as fractions of m v0^2/2 (independent of v0, m and k):
/// loading = 1 - e_F, with e_F = exp(-2 g(zeta)) the force-end restitution;
/// DC_END_OVERLAP: returned = e_O^2, unloading = e_F - e_O^2 (overdamped: the t -> infinity
/// limit, returned 0, e = 0); DC_END_FORCE: returned = e_F^2, clamped = (2 zeta e_F)^2,
/// unloading = e_F - (1 + 4 zeta^2) e_F^2.
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NEGATIVE, DC_ERR_CRITERION.
///
/// # Safety
/// `energy_out` must be NULL or point to writable memory for one dc_energy.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_energy_partition(
    p: f64,
    alpha: f64,
    criterion: i32,
    energy_out: *mut dc_energy,
) -> i32 {
    // SAFETY: forwarded caller contract on energy_out.
    unsafe {
        write_result(energy_out, || {
            let c = Contact::new(p, alpha, 1.0, 1.0)?;
            let e = powerlaw::energy_partition(&c, parse_criterion(criterion)?);
            Ok(dc_energy {
                e: e.e,
                loading: e.loading,
                unloading: e.unloading,
                returned: e.returned,
                clamped: e.clamped,
            })
        })
    }
}

/// Samples one collision at n points, uniform in the phase of the linear image (dense near
/// delta = 0 where p > 1 contacts move fastest), from impact (t = 0, delta = 0, v = v0) to the end
/// event of `criterion` (last sample: t = tau, v = -e v0; delta = 0 for DC_END_OVERLAP, force = 0
/// to rounding for DC_END_FORCE).
///
/// @param mass       effective mass m > 0 [kg] (k = m omega0^2 and the damping alpha sqrt(m k)).
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param level      DC_LEVEL_MIN..=DC_LEVEL_MAX, quadrature accuracy of the times.
/// @param n          number of samples, n >= 2.
/// @param t_out, delta_out, v_out, force_out  caller buffers of buf_len doubles each: time [s],
///                   overlap [m], overlap rate [m/s], total normal force [N].
/// @param buf_len    length of each buffer; must be >= n.
/// @return DC_OK, DC_ERR_NULL_POINTER (any buffer NULL), DC_ERR_BUFFER_TOO_SHORT (n < 2 or
///         buf_len < n), DC_ERR_LEVEL, and the statuses of dc_contact_duration. On error no
///         buffer is written, with one exception: DC_ERR_RESULT_RANGE because a sample overflowed
///         or its state underflowed (extreme inputs: a force beyond 1.8e308 N; the overlap end
///         within ~1e-6 of critical damping for p > 1, where e^(-zeta u) underflows mid-contact
///         and tau is ~1e193 time scales), found after sampling; the first n doubles of each
///         buffer then hold no valid data. DC_OK guarantees every sample finite.
///
/// # Safety
/// Each non-NULL buffer must be valid for writes of buf_len doubles and not overlap the others.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn dc_contact_trajectory(
    p: f64,
    alpha: f64,
    v0: f64,
    omega0: f64,
    mass: f64,
    criterion: i32,
    level: i32,
    n: usize,
    t_out: *mut f64,
    delta_out: *mut f64,
    v_out: *mut f64,
    force_out: *mut f64,
    buf_len: usize,
) -> i32 {
    if t_out.is_null() || delta_out.is_null() || v_out.is_null() || force_out.is_null() {
        return super::status::DC_ERR_NULL_POINTER;
    }
    if n < 2 || buf_len < n {
        return super::status::DC_ERR_BUFFER_TOO_SHORT;
    }
    guard(|| {
        let c = Contact::new(p, alpha, v0, omega0)?;
        let crit: EndCriterion = parse_criterion(criterion)?;
        let lv = self::level(level)?;
        // SAFETY: non-null checked above; the caller guarantees n <= buf_len writable doubles in
        // each buffer and no overlap between them.
        let out = unsafe {
            TrajectoryOut {
                t: core::slice::from_raw_parts_mut(t_out, n),
                delta: core::slice::from_raw_parts_mut(delta_out, n),
                v: core::slice::from_raw_parts_mut(v_out, n),
                force: core::slice::from_raw_parts_mut(force_out, n),
            }
        };
        Ok(sample_trajectory(&c, crit, mass, lv, out)?)
    })
}

/// omega0 = sqrt(k/m) from a stiffness k > 0 [N m^-p] and an effective mass m > 0 [kg], for hosts
/// that carry k and m (with Hertz, k from dc_hertz_stiffness).
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `omega0_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_omega0(k: f64, m: f64, omega0_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on omega0_out.
    unsafe { write_result(omega0_out, || powerlaw::omega0(k, m)) }
}
