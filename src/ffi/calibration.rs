//! Exports: damping coefficient α for a target restitution e, and the inverse.

use super::{parse_criterion, write_result};
use crate::powerlaw;

/// Damping coefficient alpha that makes a power-law Tsuji contact
/// `m d'' + alpha sqrt(m k) d^((p-1)/2) d' + k d^p = 0` rebound with restitution `e`.
///
/// Exact for every p >= 1 and independent of impact speed, mass and stiffness.
/// - `DC_END_OVERLAP`: alpha = sqrt(2(p+1)) L / sqrt(pi^2 + L^2), L = -ln e (closed form).
/// - `DC_END_FORCE`: the root of e = exp(-2 zeta acos(zeta)/sqrt(1-zeta^2)),
///   zeta = alpha/sqrt(2(p+1)) (continued through critical damping as acosh), solved to full
///   double precision. Use this in solvers that clamp attractive normal forces to zero; it always
///   gives a larger alpha.
///
/// @param e          target restitution, 0 < e <= 1. e = 0 is rejected: under DC_END_OVERLAP every
///                   alpha >= sqrt(2(p+1)) (critical damping) gives e = 0, so it does not fix
///                   alpha; under DC_END_FORCE e = 0 is reached only as alpha -> infinity.
/// @param p          force-law exponent, p >= 1 (1 linear, 1.5 Hertz).
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param alpha_out  receives alpha >= 0 on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_EXPONENT_RANGE, DC_ERR_CRITERION, DC_ERR_RESULT_RANGE (e so small that alpha
///         overflows).
///
/// Precision: round trip e -> alpha -> e within 1e-13 relative for e in [1e-6, 1 - 1e-9].
///
/// # Safety
/// `alpha_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_alpha_from_e(
    e: f64,
    p: f64,
    criterion: i32,
    alpha_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on alpha_out.
    unsafe {
        write_result(alpha_out, || {
            powerlaw::alpha_from_e(e, p, parse_criterion(criterion)?)
        })
    }
}

/// Restitution e realised by a power-law Tsuji contact with damping coefficient `alpha`.
///
/// - `DC_END_OVERLAP`: e = exp(-pi zeta / sqrt(1 - zeta^2)) for zeta < 1, and e = 0 (no rebound:
///   the overlap never returns to zero) for zeta >= 1, zeta = alpha/sqrt(2(p+1)).
/// - `DC_END_FORCE`: e = exp(-2 zeta acos(zeta)/sqrt(1 - zeta^2)), continued as acosh above
///   critical damping; positive for every finite alpha (e = exp(-2) at zeta = 1, ~1/(4 zeta^2) for
///   large zeta).
///
/// @param alpha      damping coefficient, alpha >= 0, finite.
/// @param p          force-law exponent, p >= 1.
/// @param criterion  DC_END_OVERLAP or DC_END_FORCE.
/// @param e_out      receives e in [0, 1] on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NEGATIVE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_CRITERION.
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_e_from_alpha(
    alpha: f64,
    p: f64,
    criterion: i32,
    e_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe {
        write_result(e_out, || {
            powerlaw::e_from_alpha(alpha, p, parse_criterion(criterion)?)
        })
    }
}

/// Restitution of a head-on impact with the elastic-plastic normal law
/// (DC_NORMAL_ELASTIC_PLASTIC; Thornton 1997) at impact speed v, from x = v/v_y (v_y from
/// dc_elastic_plastic_yield_speed): e = 1 for x <= 1 (the contact stays elastic), else with
/// y = 1/x  e = (6 sqrt(3)/5)^(1/2) (1 - y^2/6)^(1/2) (y/(y + 2 sqrt(6/5 - y^2/5)))^(1/4).
/// Exact for the law as implemented (checked against an integration of the contact in
/// tests/elastic_plastic.rs).
///
/// @param x      v/v_y >= 0, finite.
/// @param e_out  receives e in (0, 1] on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NEGATIVE.
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_elastic_plastic_restitution(x: f64, e_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe { write_result(e_out, || crate::force::elastic_plastic::restitution(x)) }
}

/// Yield speed v_y [m/s] of the elastic-plastic normal law: the head-on impact speed at which
/// the contact first yields, 1/2 m* v_y^2 = (8/15) E* sqrt(R*) d_y^(5/2) with
/// d_y = (pi p_y/(2 E*))^2 R*.
///
/// @param e_star  effective modulus E* [Pa] (dc_effective_modulus), finite > 0.
/// @param r_eff   effective radius R* [m], finite > 0.
/// @param m_eff   effective mass m* [kg], finite > 0.
/// @param p_y     limiting contact pressure [Pa], finite > 0.
/// @param v_out   receives v_y on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE,
///         DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `v_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_elastic_plastic_yield_speed(
    e_star: f64,
    r_eff: f64,
    m_eff: f64,
    p_y: f64,
    v_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on v_out.
    unsafe {
        write_result(v_out, || {
            crate::force::elastic_plastic::yield_speed(e_star, r_eff, m_eff, p_y)
        })
    }
}
