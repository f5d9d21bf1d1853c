//! Exports: restitution of viscoelastic spheres (`xi'' + k xi^(3/2) + gamma sqrt(xi) xi' = 0`)
//! as a function of b = beta v^(1/5), beta = gamma k^(-3/5), in three accuracy tiers, the
//! physical-units form, and the calibrations.

use super::status::DC_ERR_NULL_POINTER;
use super::{guard, parse_criterion, write_result};
use crate::viscoelastic::{calibration, full_range, reference, scaling, series};

/// Restitution e(b) of colliding viscoelastic spheres, full-range tier.
///
/// e depends on stiffness k, damping gamma (both per unit effective mass) and impact speed v only
/// through b = beta v^(1/5), beta = gamma k^(-3/5) (see dc_viscoelastic_b).
/// - DC_END_OVERLAP: contact ends when the overlap returns to 0 (it always does, in finite time);
///   e = 5.15838170426769 b^-5 for large b (exact to 1e-15 for b >= 8).
/// - DC_END_FORCE: contact ends when the total force first returns to 0 (clamped solvers);
///   e ~ 1.3103707 b^(-5/3) for large b.
///
/// Precision: relative error below 1e-10 for every b >= 0: measured max 6e-14 against the
/// reference integration on [0, 1e6] (force) and 4e-15 on [0, 3e3] (overlap;
/// beyond b = 8 the overlap law is exact to 1e-16); beyond 2^20 the force law
/// 1.3103707 b^(-5/3) (1 - 12.7 b^-1.59), 7e-12 on [2^20, 2^21.5]. Below b = 1e-5 the series
/// 1 - 1.15344885809528 b + ..., so e(0) = 1 exactly, 1 - e keeps full relative precision and e is
/// non-increasing on [0, 1e300] (tests/extremes.rs).
/// Cost: one Chebyshev sum of 20 terms, about 40 ns (overlap) / 60 ns (force) per call.
///
/// @param b          dimensionless damping-speed parameter, b >= 0, finite.
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param e_out      receives e in (0, 1] (may underflow to 0 for b > 1e60); untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NEGATIVE, DC_ERR_CRITERION.
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_e(b: f64, criterion: i32, e_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe { write_result(e_out, || full_range::e_full(b, parse_criterion(criterion)?)) }
}

/// Restitution e(b) from the published series of Schwager & Poschel (2008), series tier.
///
/// DC_END_FORCE: sum_{k=0}^{20} h_k b^(k/2) (their Table V); DC_END_OVERLAP:
/// 1 + sum_{k=1}^{10} c_k b^k (their Table III), coefficients as printed.
/// Precision: within 1e-6 of the reference only for b <= 0.48 (force) / 0.41 (overlap), within
/// 1e-3 for b <= 0.76 / 0.78; meaningless beyond b ~ 1. Prefer dc_viscoelastic_e.
///
/// @param b          b >= 0, finite.
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param e_out      receives the series value; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NEGATIVE, DC_ERR_CRITERION,
///         DC_ERR_RESULT_RANGE (the polynomial overflows, b beyond ~1e30).
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_e_series(b: f64, criterion: i32, e_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe { write_result(e_out, || series::e_series(b, parse_criterion(criterion)?)) }
}

/// Restitution e(b) by direct integration of the equation of motion, reference tier.
///
/// Taylor-series integration (order 30) of the regularised system X = u^2, dT = u dsigma, in which
/// the equation is polynomial; events located on the local polynomial. Relative accuracy about
/// 1e-15 for b <= 1e3 (convergence in tolerance), 2e-14 up to 4e5 and 5e-12 at 1e6 (force). Cost
/// grows with b: ~30 microseconds for b <= 10; under DC_END_OVERLAP about 0.2 s at b = 1e3 and
/// 0.8 s at 3e3 (the contact lasts ~b (10/3) ln b); prefer dc_viscoelastic_e.
///
/// @param b          b >= 0, finite (practical limits: 3e3 overlap, 1e6 force).
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param e_out      receives e; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NEGATIVE, DC_ERR_CRITERION,
///         DC_ERR_NO_CONVERGENCE (step budget exhausted, very large b).
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_e_reference(
    b: f64,
    criterion: i32,
    e_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe {
        write_result(e_out, || {
            reference::e_reference(b, parse_criterion(criterion)?)
        })
    }
}

/// The parameter b = gamma k^(-3/5) v^(1/5) of a viscoelastic collision.
///
/// @param k      Hertz stiffness per unit effective mass (rho/m_eff), > 0 [m^(-1/2) s^-2].
/// @param gamma  damping per unit effective mass (3 A rho / (2 m_eff)), >= 0 [m^(-1/2) s^-1].
/// @param v      impact speed, > 0 [m/s].
/// @param b_out  receives b >= 0; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE,
///         DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `b_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_b(k: f64, gamma: f64, v: f64, b_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on b_out.
    unsafe {
        write_result(b_out, || {
            let beta = scaling::beta_from_k_gamma(k, gamma)?;
            scaling::b_from_beta_speed(beta, v)
        })
    }
}

/// Restitution at impact speed v in physical units (full-range tier): e(gamma k^(-3/5) v^(1/5)).
///
/// @param k, gamma, v  as for dc_viscoelastic_b (k > 0, gamma >= 0, v > 0).
/// @param criterion    DC_END_OVERLAP or DC_END_FORCE.
/// @param e_out        receives e; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE,
///         DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_e_of_speed(
    k: f64,
    gamma: f64,
    v: f64,
    criterion: i32,
    e_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe {
        write_result(e_out, || {
            calibration::e_of_speed(k, gamma, v, parse_criterion(criterion)?)
        })
    }
}

/// Stiffness and damping per unit mass from the material law F = rho xi^(3/2) + (3/2) A rho
/// sqrt(xi) xi': k = rho / m_eff, gamma = 3 A rho / (2 m_eff).
///
/// @param rho        Hertz constant 2 Y sqrt(R_eff) / (3 (1 - nu^2)), > 0 [N m^(-3/2)].
/// @param a          dissipative constant A, >= 0 [s].
/// @param m_eff      effective mass, > 0 [kg].
/// @param k_out      receives k; @param gamma_out receives gamma. Both untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER (either output NULL), DC_ERR_NOT_FINITE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `k_out` and `gamma_out` must each be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_k_gamma(
    rho: f64,
    a: f64,
    m_eff: f64,
    k_out: *mut f64,
    gamma_out: *mut f64,
) -> i32 {
    if k_out.is_null() || gamma_out.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    guard(|| {
        let (k, g) = scaling::k_gamma_from_material(rho, a, m_eff)?;
        // SAFETY: both non-null; validity for writes is the caller's contract.
        unsafe {
            k_out.write_unaligned(k);
            gamma_out.write_unaligned(g);
        }
        Ok(())
    })
}

/// The b at which the restitution equals e (inverse of dc_viscoelastic_e).
///
/// @param e          target restitution, 0 < e <= 1 (e = 1 gives b = 0).
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param b_out      receives b >= 0; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_CRITERION, DC_ERR_RESULT_RANGE (e so small that b overflows).
/// Precision: dc_viscoelastic_e(b) reproduces e to 1e-12 relative.
///
/// # Safety
/// `b_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_b_from_e(e: f64, criterion: i32, b_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on b_out.
    unsafe {
        write_result(b_out, || {
            calibration::b_from_e(e, parse_criterion(criterion)?)
        })
    }
}

/// Calibration: beta = gamma k^(-3/5) such that a collision at speed v_ref rebounds with e.
///
/// @param e          measured restitution, 0 < e <= 1.
/// @param v_ref      impact speed of the measurement, > 0 [m/s].
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE (the criterion of the solver that will use
///                   beta).
/// @param beta_out   receives beta >= 0 [s^(1/5) m^(-1/5)]; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `beta_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_beta_from_e(
    e: f64,
    v_ref: f64,
    criterion: i32,
    beta_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on beta_out.
    unsafe {
        write_result(beta_out, || {
            calibration::beta_from_e(e, v_ref, parse_criterion(criterion)?)
        })
    }
}

/// Calibration for a given material: the dissipative constant A such that a collision at v_ref
/// rebounds with e, for Hertz constant rho and effective mass m_eff (A = beta / (1.5 rho^0.4
/// m_eff^-0.4)).
///
/// @param e, v_ref, criterion  as for dc_viscoelastic_beta_from_e.
/// @param rho                  Hertz constant, > 0. @param m_eff effective mass, > 0.
/// @param a_out                receives A >= 0 [s]; untouched on error.
/// @return as dc_viscoelastic_beta_from_e.
///
/// # Safety
/// `a_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_a_from_e(
    e: f64,
    v_ref: f64,
    rho: f64,
    m_eff: f64,
    criterion: i32,
    a_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on a_out.
    unsafe {
        write_result(a_out, || {
            calibration::a_from_e(e, v_ref, rho, m_eff, parse_criterion(criterion)?)
        })
    }
}

/// The impact speed at which the restitution equals e, for a material with beta > 0:
/// v = (b(e)/beta)^5 (faster impacts are more dissipative). e = 1 gives v = 0.
///
/// @param e          0 < e <= 1.
/// @param beta       gamma k^(-3/5) > 0.
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param v_out      receives v >= 0 [m/s]; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `v_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_viscoelastic_speed_for_e(
    e: f64,
    beta: f64,
    criterion: i32,
    v_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on v_out.
    unsafe {
        write_result(v_out, || {
            calibration::speed_for_e(e, beta, parse_criterion(criterion)?)
        })
    }
}
