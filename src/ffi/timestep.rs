//! Exports: time-step estimates.

use super::write_result;
use crate::powerlaw;

/// The seed's critical time step for explicit integration of a power-law contact:
/// dt = (4/(p+1)) A (1/omega0) (v0/omega0)^(-(p-1)/(p+1)), A = ((p+1)/2)^(1/(p+1)).
///
/// For p = 1 this is 2/omega0 (v0 drops out). For p > 1 it equals sqrt(2p/(p+1)) times
/// 2/omega_lin, the bound from the linearised stiffness at the undamped maximum overlap, i.e. it
/// is *less* conservative than that bound, contrary to the seed's claim; see the docs for which
/// step is safe for velocity-Verlet.
///
/// @param p       force-law exponent, p >= 1.
/// @param v0      impact speed, > 0 [m/s].
/// @param omega0  sqrt(k/m) > 0 [s^-1 m^((1-p)/2)].
/// @param dt_out  receives the step [s] on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `dt_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_dt_crit(p: f64, v0: f64, omega0: f64, dt_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on dt_out.
    unsafe { write_result(dt_out, || powerlaw::dt_crit_seed(p, v0, omega0)) }
}
