//! Exports: material helpers (Hertz stiffness from E, ν, R of two spheres).

use super::write_result;
use crate::material;

/// Hertz stiffness k = (4/3) E* sqrt(R*) of two elastic spheres, with
/// 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 and R* = R1 R2/(R1 + R2); the Hertz force is k d^(3/2).
///
/// @param E1,E2    Young's moduli > 0 [Pa].
/// @param nu1,nu2  Poisson ratios in (-1, 0.5].
/// @param R1,R2    radii > 0 [m]; one of them may be +INFINITY for a flat wall (R* = the other).
/// @param k_out    receives k [N m^-3/2] on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE (NaN, or both radii infinite),
///         DC_ERR_NOT_POSITIVE (E <= 0, R <= 0 or nu out of range), DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `k_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
#[allow(non_snake_case)]
pub unsafe extern "C" fn dc_hertz_stiffness(
    E1: f64,
    nu1: f64,
    R1: f64,
    E2: f64,
    nu2: f64,
    R2: f64,
    k_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on k_out.
    unsafe {
        write_result(k_out, || {
            let es = material::effective_modulus(E1, nu1, E2, nu2)?;
            let rs = material::effective_radius(R1, R2)?;
            material::hertz_stiffness(es, rs)
        })
    }
}

/// Effective modulus E* of two materials: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `E_star_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
#[allow(non_snake_case)]
pub unsafe extern "C" fn dc_effective_modulus(
    E1: f64,
    nu1: f64,
    E2: f64,
    nu2: f64,
    E_star_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on E_star_out.
    unsafe { write_result(E_star_out, || material::effective_modulus(E1, nu1, E2, nu2)) }
}
