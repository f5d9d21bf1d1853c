//! Exports: the time step that a target accuracy of the realised restitution allows.

use super::{parse_criterion, write_result};
use crate::timestep;

/// The largest velocity-Verlet time step for which a power-law Tsuji collision realises its
/// restitution within relative tolerance `tol`, whatever the phase at which contact starts
/// between two steps.
///
/// The contact is `m d'' + alpha sqrt(m k) d^((p-1)/2) d' + k d^p = 0` with alpha calibrated
/// exactly for `e` and `criterion` (as dc_alpha_from_e / dc_pair_powerlaw do), integrated in the
/// LAMMPS/LIGGGHTS velocity-Verlet order (x += v dt + a dt^2/2; v_half = v + a dt/2; force from
/// x and v_half; v = v_half + a_new dt/2) with the library's force kernels; DC_END_FORCE pairs
/// clamp attractive forces. The realised e = |exit velocity|/v0 must satisfy
/// |e_realised - e| <= tol e.
///
/// How: the answer scales as dt = t* h(p, e, criterion, tol) with t* = (v0/omega0)^(2/(p+1))/v0;
/// h is measured inside the call by simulating the dimensionless collision at 64 start phases
/// (evenly spaced over [0, 1), both ends included) per trial step, stepping down by halves from
/// tau/8 and bisecting (5 times, in log dt) between the last failing and the first passing step,
/// aiming at 0.9 tol. The returned step passed at all 64 phases. Below tau/8192 (tol below about
/// 1e-4 for strongly damped contacts) the error law E ~ dt^k fitted on the two finest steps is
/// extrapolated where those two show one (an error below e itself, and a halving of the step
/// that divides it by 2^0.4 to 2^2.5: first to second order; k clamped to [0.5, 2]), then
/// checked at the 64 phases and stepped down (along the fitted law, by 10 % to a factor 2, up
/// to 6 checks) until it passes, as long as a collision at that step takes at most 2^18
/// contact steps (DC_ERR_NO_CONVERGENCE when none passes within that bound: the error is
/// erratic in dt there); a finer extrapolated step is returned unverified, up to 2^52 steps per
/// contact (a finer one would be below the double resolution of the contact's own time).
/// DC_ERR_NO_CONVERGENCE where the two finest steps show no such law (p = 1e6, e = 0.5) or the
/// law asks for more than 2^52 steps per contact
/// (tol = 1e-300). Never returns more than tau/8.
///
/// Accuracy (tests/step_accuracy.rs: p in {1, 1.5, 2, 3}, e in {0.1, 0.5, 0.9}, both criteria,
/// tol in {1e-2, 1e-3}, v0 = 0.7, omega0 = 13): at the returned dt a collision integrated
/// independently meets tol at each of 61 other start phases; at 2 dt it fails at some phase;
/// the same for strongly damped contacts under DC_END_FORCE (p in {1, 1.5}, e in {1e-2, 1e-3},
/// tol 1e-2: the force ends long before the bodies separate, and the search stops each
/// collision at the force's end, after which the exit velocity does not change). e → 0 needs
/// ever finer steps, most with DC_END_OVERLAP (near-critical damping), where the error at the
/// finest searched step nears e itself and halving the step stops lowering it at first order
/// (Hertz, tol 5e-2): answered to e = 1e-7, DC_ERR_NO_CONVERGENCE from 1e-8 (no error law to
/// extrapolate; tests/step_accuracy.rs, extrapolation_without_an_error_law_is_refused). With DC_END_FORCE the force ends ever sooner (Hertz: tau =
/// 0.02 t* at e = 1e-8, 2e-6 t* at 1e-19; the search's grid is scaled by tau, from the
/// library's quadrature where the force ends within 100 steps of the reference run, below
/// about e = 1.5e-6 with Hertz): answered to about e = 1e-12 (Hertz, tol 5e-2: 636 steps per
/// contact), then DC_ERR_NO_CONVERGENCE (the collisions at the search's finest steps do not end
/// within their step budget, so there is no error law to extrapolate). DC_ERR_RESULT_RANGE
/// only where dt itself over- or underflows (extreme v0/omega0).
/// scripts/extreme_restitution.sh prints the answers for e = 1e-1 ... 1e-20. Typical results (docs/report.md): dt/tau ~ 0.2 tol at e = 0.1, ~ tol at e = 0.5; weakly
/// damped contacts reach the tau/8 cap at loose tolerances.
///
/// Cost: up to ~6e6 force evaluations (tens of ms; more on a loaded machine), plus, where an
/// extrapolated step is checked (tol below about 1e-4 with strong damping), up to 6 checks of 64
/// collisions of at most 2^18 contact steps (up to ~1e8 more: seconds); allocation-free; call it
/// once per material pair at set-up, not per step.
///
/// @param p          force-law exponent, p >= 1.
/// @param e          target restitution, 0 < e <= 1.
/// @param criterion  DC_END_OVERLAP (no clamp) or DC_END_FORCE (attractive forces clamped).
/// @param v0         impact speed, > 0 [m/s] (use the largest expected; dt falls with v0
///                   for p > 1).
/// @param omega0     sqrt(k/m) > 0 [s^-1 m^((1-p)/2)].
/// @param tol        relative tolerance on e, > 0 (e.g. 0.01).
/// @param dt_out     receives the step [s] on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_RESTITUTION_RANGE, DC_ERR_NOT_POSITIVE, DC_ERR_CRITERION, DC_ERR_RESULT_RANGE,
///         DC_ERR_NO_CONVERGENCE (the collisions at the finest step searched do not end, they
///         show no error law to extrapolate, the law asks for more than 2^52 steps per contact,
///         or no checked extrapolated step passes: see above).
///
/// # Safety
/// `dt_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_dt_for_accuracy(
    p: f64,
    e: f64,
    criterion: i32,
    v0: f64,
    omega0: f64,
    tol: f64,
    dt_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on dt_out.
    unsafe {
        write_result(dt_out, || {
            timestep::dt_for_accuracy(p, e, parse_criterion(criterion)?, v0, omega0, tol)
        })
    }
}

/// dc_dt_for_accuracy for a model made step-aware by dc_contact_model_set_step: the largest
/// velocity-Verlet step at which the step-aware collision realises e within relative tolerance
/// `tol` at every contact-onset phase (64 phases), same arguments and meaning. Much larger than
/// the plain answer: about t_H/11 for tol = 1.5e-2 at e = 0.1 (Hertz, v0 = 1 m/s), where the
/// plain model needs a step some 18 times smaller (t_H: the elastic contact duration at v0;
/// docs/timestep.md, "The step a tolerance allows"). Searched on steps t_H/N,
/// N >= 10 (t_H/10 is returned when it passes: the correction is not designed beyond it); about
/// 0.1-1 s of set-up work; allocation-free. An undamped law (e = 1) gets dc_dt_for_accuracy's
/// answer. e -> 0 with DC_END_OVERLAP (near-critical damping) costs more: about 0.6 s at
/// e = 1e-9, 2.7 s at 1e-12, 6.4 s at 1e-15, 9.5 s at 1e-17, and a refusal after about 6 s from
/// 1e-18 (scripts/extreme_restitution.sh prints the times).
///
/// @return as dc_dt_for_accuracy; DC_ERR_STEP_UNSUPPORTED for p > 3 (no step-aware form);
///         DC_ERR_STEP_UNREACHABLE when no step down to t_H/8192 meets tol (or the step-aware
///         damping cannot realise e at all).
///
/// # Safety
/// `dt_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_dt_for_accuracy_step_aware(
    p: f64,
    e: f64,
    criterion: i32,
    v0: f64,
    omega0: f64,
    tol: f64,
    dt_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on dt_out.
    unsafe {
        write_result(dt_out, || {
            crate::contact::step_exact::dt_for_accuracy(
                p,
                e,
                parse_criterion(criterion)?,
                v0,
                omega0,
                tol,
            )
        })
    }
}
