//! Exports: the value to type into a DEM code's builtin contact model so that it realises a target
//! restitution, and the restitution a typed value realises.

use super::write_result;
use crate::Error;
use crate::builtin::{self, Builtin};

/// LIGGGHTS `pair_style gran model hooke`; value = `coefficientRestitution` to type.
pub const DC_BUILTIN_LIGGGHTS_HOOKE: i32 = 1;
/// LIGGGHTS `pair_style gran model hertz`; value = `coefficientRestitution` to type.
pub const DC_BUILTIN_LIGGGHTS_HERTZ: i32 = 2;
/// LAMMPS `pair_style granular ... damping coeff_restitution` (hooke or hertz); value = e to type.
pub const DC_BUILTIN_LAMMPS_COEFF_RESTITUTION: i32 = 3;
/// LAMMPS `pair_style granular hertz[/material] ... damping tsuji` (22 Jul 2025 release); value =
/// e to type.
pub const DC_BUILTIN_LAMMPS_TSUJI_HERTZ: i32 = 4;
/// LAMMPS `pair_style granular hooke ... damping tsuji`; value = e to type.
pub const DC_BUILTIN_LAMMPS_TSUJI_HOOKE: i32 = 5;
/// YADE `ViscElMat(tc=, en=, et=)` + `Law2_ScGeom_ViscElPhys_Basic` (always clamps); value = en.
pub const DC_BUILTIN_YADE_VISCEL_EN: i32 = 6;
/// YADE `Ip2_FrictMat_FrictMat_MindlinPhys(en=)` + `Law2_ScGeom_MindlinPhys_Mindlin` (always
/// clamps); value = en.
pub const DC_BUILTIN_YADE_MINDLIN_EN: i32 = 7;
/// YADE `Ip2_FrictMat_FrictMat_MindlinPhys(betan=)` + `Law2_ScGeom_MindlinPhys_Mindlin` (always
/// clamps); value = betan.
pub const DC_BUILTIN_YADE_MINDLIN_BETAN: i32 = 8;

fn parse(model: i32, clamp: i32) -> Result<(Builtin, bool), Error> {
    let b = Builtin::from_code(model).ok_or(Error::BuiltinModel)?;
    Ok((b, flag(clamp)?))
}

/// The value to type into a builtin model so that it realises restitution `e` in a head-on
/// collision, at every impact speed (every builtin here is a power-law Tsuji contact, so the
/// realised e does not depend on speed, stiffness or mass).
///
/// @param model      a DC_BUILTIN_* code.
/// @param clamp      1 if the code clamps attractive normal forces (LIGGGHTS `limitForce on`,
///                   LAMMPS `limit_damping`; YADE always: must be 1), else 0.
/// @param e          target restitution, 0 < e <= 1.
/// @param value_out  receives the value to type (e or en in (0, 1], or betan >= 0); untouched on
///                   error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_BUILTIN_MODEL (unknown model, clamp not 0/1, or 0 for YADE),
///         DC_ERR_BUILTIN_UNREACHABLE (the builtin's parameter saturates before e: with a clamp,
///         the e-typed models of LIGGGHTS, LAMMPS coeff_restitution and YADE en cannot go below
///         e = exp(-2) = 0.1353; LAMMPS tsuji covers damping 0.0003 <= alpha < 1.2728 only: Hertz
///         e in (0.1136, 0.99958), (0.2628, 0.99958) with limit_damping).
///
/// Precision: the builtin's own formula applied to the value realises e within 1e-13.
///
/// # Safety
/// `value_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_builtin_value_for_e(
    model: i32,
    clamp: i32,
    e: f64,
    value_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on value_out.
    unsafe {
        write_result(value_out, || {
            let (b, c) = parse(model, clamp)?;
            builtin::value_for_e(b, c, e)
        })
    }
}

/// The restitution a builtin model realises (in continuous time) when `value` is typed: the
/// forward map of dc_builtin_value_for_e, e.g. to show what an uncorrected input gives.
///
/// @param model   a DC_BUILTIN_* code.
/// @param clamp   1 if the code clamps attractive forces (YADE: must be 1), else 0.
/// @param value   the typed value (e or en in (0, 1], or betan >= 0).
/// @param e_out   receives the realised e in [0, 1]; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE (typed e),
///         DC_ERR_NEGATIVE (betan), DC_ERR_BUILTIN_MODEL.
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_builtin_realised_e(
    model: i32,
    clamp: i32,
    value: f64,
    e_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe {
        write_result(e_out, || {
            let (b, c) = parse(model, clamp)?;
            builtin::realised_e(b, c, value)
        })
    }
}

fn flag(x: i32) -> Result<bool, Error> {
    match x {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(Error::BuiltinModel),
    }
}

/// dc_builtin_value_for_e for a particle hitting a wall (`wall` = 1: a fixed massless wall or
/// facet, or a fixed body of the particle's own mass) or another particle (`wall` = 0, the same
/// as dc_builtin_value_for_e). Only YADE `ViscElMat(tc, en, et)` needs another value against a
/// wall: it calibrates with the reduced mass m/2 there (a zero mass is replaced by the other
/// body's) while the sphere moves with m, so its damping ratio is zeta_O(en)/sqrt(2); targets
/// e <= exp(-pi/2) = 0.2079 are unreachable against a wall. The other builtins use the dynamic
/// body's mass against walls (YADE Mindlin: `isDynamic`), so `wall` does not change their value.
///
/// @param model      a DC_BUILTIN_* code.
/// @param clamp      1 if the code clamps attractive normal forces (YADE: must be 1), else 0.
/// @param wall       1: against a wall; 0: against a particle.
/// @param e          target restitution, 0 < e <= 1.
/// @param value_out  receives the value to type; untouched on error.
/// @return as dc_builtin_value_for_e; DC_ERR_BUILTIN_MODEL also for `wall` not 0 or 1.
///
/// # Safety
/// `value_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_builtin_value_for_e_wall(
    model: i32,
    clamp: i32,
    wall: i32,
    e: f64,
    value_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on value_out.
    unsafe {
        write_result(value_out, || {
            let (b, c) = parse(model, clamp)?;
            builtin::value_for_e_wall(b, c, flag(wall)?, e)
        })
    }
}

/// dc_builtin_realised_e against a wall (`wall` = 1) or a particle (0): the forward map of
/// dc_builtin_value_for_e_wall.
///
/// @param model   a DC_BUILTIN_* code.
/// @param clamp   1 if the code clamps attractive forces (YADE: must be 1), else 0.
/// @param wall    1: against a wall; 0: against a particle.
/// @param value   the typed value.
/// @param e_out   receives the realised e in [0, 1]; untouched on error.
/// @return as dc_builtin_realised_e; DC_ERR_BUILTIN_MODEL also for `wall` not 0 or 1.
///
/// # Safety
/// `e_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_builtin_realised_e_wall(
    model: i32,
    clamp: i32,
    wall: i32,
    value: f64,
    e_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on e_out.
    unsafe {
        write_result(e_out, || {
            let (b, c) = parse(model, clamp)?;
            builtin::realised_e_wall(b, c, flag(wall)?, value)
        })
    }
}

/// Contact damping cn [N s/m] for YADE `ViscElMat(kn=, cn=)` (linear law, always clamped) that
/// realises restitution `e`: cn = 2 zeta_F(e) sqrt(m_reduced kn). YADE combines the two materials'
/// kn and cn in series, so for two equal materials type 2 kn and 2 cn on each.
///
/// @param e           target restitution, 0 < e <= 1 (overdamped values below exp(-2) are fine).
/// @param kn          contact normal stiffness [N/m], > 0.
/// @param m_reduced   m1 m2 / (m1 + m2) [kg], > 0 (the dynamic body's mass against a wall).
/// @param cn_out      receives cn >= 0; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `cn_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_builtin_yade_viscel_cn(
    e: f64,
    kn: f64,
    m_reduced: f64,
    cn_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract on cn_out.
    unsafe { write_result(cn_out, || builtin::yade::viscel_cn(e, kn, m_reduced)) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::status::*;

    #[test]
    fn codes_match_the_enum() {
        for (c, b) in [
            (DC_BUILTIN_LIGGGHTS_HOOKE, Builtin::LiggghtsHooke),
            (DC_BUILTIN_LIGGGHTS_HERTZ, Builtin::LiggghtsHertz),
            (
                DC_BUILTIN_LAMMPS_COEFF_RESTITUTION,
                Builtin::LammpsCoeffRestitution,
            ),
            (DC_BUILTIN_LAMMPS_TSUJI_HERTZ, Builtin::LammpsTsujiHertz),
            (DC_BUILTIN_LAMMPS_TSUJI_HOOKE, Builtin::LammpsTsujiHooke),
            (DC_BUILTIN_YADE_VISCEL_EN, Builtin::YadeViscElEn),
            (DC_BUILTIN_YADE_MINDLIN_EN, Builtin::YadeMindlinEn),
            (DC_BUILTIN_YADE_MINDLIN_BETAN, Builtin::YadeMindlinBetan),
        ] {
            assert_eq!(b.code(), c);
        }
    }

    #[test]
    fn statuses_and_untouched_output() {
        let mut v = -7.0;
        // SAFETY: valid pointer to a local.
        unsafe {
            assert_eq!(dc_builtin_value_for_e(2, 1, 0.5, &mut v), DC_OK);
            assert!(v > 0.4 && v < 0.5, "{v}"); // below the target: the clamp adds bounce
            let keep = v;
            assert_eq!(
                dc_builtin_value_for_e(9, 1, 0.5, &mut v),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(
                dc_builtin_value_for_e(2, 2, 0.5, &mut v),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(
                dc_builtin_value_for_e(6, 0, 0.5, &mut v),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(
                dc_builtin_value_for_e(2, 1, 0.1, &mut v),
                DC_ERR_BUILTIN_UNREACHABLE
            );
            assert_eq!(
                dc_builtin_value_for_e(2, 1, f64::NAN, &mut v),
                DC_ERR_NOT_FINITE
            );
            assert_eq!(
                dc_builtin_value_for_e(2, 1, 0.0, &mut v),
                DC_ERR_RESTITUTION_RANGE
            );
            assert_eq!(
                dc_builtin_value_for_e(2, 1, 0.5, core::ptr::null_mut()),
                DC_ERR_NULL_POINTER
            );
            assert_eq!(v, keep);
            assert_eq!(
                dc_builtin_value_for_e_wall(6, 1, 2, 0.5, &mut v),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(
                dc_builtin_value_for_e_wall(6, 1, 1, 0.2, &mut v),
                DC_ERR_BUILTIN_UNREACHABLE
            );
            assert_eq!(
                dc_builtin_realised_e_wall(6, 1, -1, 0.5, &mut v),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(v, keep);
            assert_eq!(dc_builtin_value_for_e_wall(6, 1, 1, 0.3, &mut v), DC_OK);
            let mut back = -1.0;
            assert_eq!(dc_builtin_realised_e_wall(6, 1, 1, v, &mut back), DC_OK);
            assert!((back - 0.3).abs() < 1e-13, "{back}");
            v = keep;
            assert_eq!(
                dc_builtin_yade_viscel_cn(0.5, -1.0, 1.0, &mut v),
                DC_ERR_NOT_POSITIVE
            );
            assert_eq!(v, keep);
        }
    }
}
