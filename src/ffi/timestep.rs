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

/// The linearised time-step bound of a collision: 2/omega_lin, omega_lin = omega0 sqrt(p)
/// delta0^((p-1)/2), delta0 = ((p+1) v0^2/(2 omega0^2))^(1/(p+1)) the undamped maximum overlap.
/// For p = 1 it is 2/omega0. It is smaller than dc_dt_crit by sqrt(2p/(p+1)); velocity-Verlet
/// experiments (docs/powerlaw.md) show how far below it one must stay for accuracy.
///
/// @param p, v0, omega0  p >= 1, v0 > 0 (the largest impact speed expected), omega0 > 0.
/// @param dt_out  receives the step [s]; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `dt_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_dt_linearised(p: f64, v0: f64, omega0: f64, dt_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on dt_out.
    unsafe { write_result(dt_out, || powerlaw::timestep::dt_linearised(p, v0, omega0)) }
}

/// The velocity-Verlet stability limit of a persistent contact pressed by a constant load
/// (LAMMPS/LIGGGHTS scheme: dashpot evaluated with the half-step velocity):
/// dt = (2/omega_eq)(sqrt(1 + z^2) - z), omega_eq = omega0 sqrt(p) delta_eq^((p-1)/2),
/// delta_eq = (accel/omega0^2)^(1/p), z = alpha/(2 sqrt(p)) the linearised damping ratio.
/// Damping lowers the limit (to 0.35 x 2/omega_eq at e = 0.1); measured limits agree within
/// 1% (docs/powerlaw.md). Unlike dc_dt_crit, which ignores damping and grows without bound as
/// v0 -> 0 for p > 1, it is finite for resting contacts. Stay below it with a safety margin.
///
/// @param p       force-law exponent, p >= 1.
/// @param alpha   damping coefficient, alpha >= 0.
/// @param omega0  sqrt(k/m) > 0.
/// @param accel   load divided by the effective mass (e.g. g for a particle resting on a
///                wall), > 0.
/// @param dt_out  receives the step [s]; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `dt_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_dt_static(
    p: f64,
    alpha: f64,
    omega0: f64,
    accel: f64,
    dt_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on dt_out.
    unsafe {
        write_result(dt_out, || {
            powerlaw::timestep::dt_static(p, alpha, omega0, accel)
        })
    }
}
