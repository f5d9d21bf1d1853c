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
/// LAMMPS `pair_style granular hertz[/material] ... damping tsuji`, releases up to 22 Jul 2025
/// (damp = eta(e)); value = e to type. dc_builtin_for_lammps_release picks by release.
pub const DC_BUILTIN_LAMMPS_TSUJI_HERTZ: i32 = 4;
/// LAMMPS `pair_style granular hooke ... damping tsuji`, releases up to 22 Jul 2025; value = e to
/// type.
pub const DC_BUILTIN_LAMMPS_TSUJI_HOOKE: i32 = 5;
/// YADE `ViscElMat(tc=, en=, et=)` + `Law2_ScGeom_ViscElPhys_Basic` (always clamps); value = en.
pub const DC_BUILTIN_YADE_VISCEL_EN: i32 = 6;
/// YADE `Ip2_FrictMat_FrictMat_MindlinPhys(en=)` + `Law2_ScGeom_MindlinPhys_Mindlin` (always
/// clamps); value = en.
pub const DC_BUILTIN_YADE_MINDLIN_EN: i32 = 7;
/// YADE `Ip2_FrictMat_FrictMat_MindlinPhys(betan=)` + `Law2_ScGeom_MindlinPhys_Mindlin` (always
/// clamps); value = betan.
pub const DC_BUILTIN_YADE_MINDLIN_BETAN: i32 = 8;
/// LAMMPS `pair_style granular hertz[/material] ... damping tsuji` from the 2 Sep 2026 release on,
/// which multiplies Tsuji's eta(e) by sqrt(2); value = e to type.
pub const DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2: i32 = 9;
/// LAMMPS `pair_style granular hooke ... damping tsuji` from the 2 Sep 2026 release on (damp =
/// sqrt(2) eta(e)); value = e to type.
pub const DC_BUILTIN_LAMMPS_TSUJI_HOOKE_SQRT2: i32 = 10;

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

/// The DC_BUILTIN_* code of a LAMMPS model as a given LAMMPS release runs it: `damping tsuji`
/// multiplies Tsuji's eta(e) by sqrt(2) from the 2 Sep 2026 release on, so
/// DC_BUILTIN_LAMMPS_TSUJI_HERTZ becomes DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2 there (and back for
/// an older release; the same for HOOKE); DC_BUILTIN_LAMMPS_COEFF_RESTITUTION is unchanged.
///
/// @param model      a LAMMPS DC_BUILTIN_* code (3, 4, 5, 9 or 10).
/// @param yyyymmdd   the release as a number, e.g. 20250722 for "22 Jul 2025" (the date `lmp -h`
///                   and the first line of log.lammps print).
/// @param model_out  receives the code to pass to dc_builtin_value_for_e; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_BUILTIN_MODEL (not a LAMMPS model),
///         DC_ERR_BUILTIN_VERSION (not a calendar date in 2000..2099, or a date after 22 Jul 2025
///         and before 2 Sep 2026, where releases and development snapshots differ: read whether
///         that source's GranSubModDampingTsuji::init has `damp *= MY_SQRT2` and pick the code).
///
/// # Safety
/// `model_out` must be NULL or point to writable memory for one int32_t.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_builtin_for_lammps_release(
    model: i32,
    yyyymmdd: i32,
    model_out: *mut i32,
) -> i32 {
    // SAFETY: forwarded caller contract on model_out.
    unsafe {
        write_result(model_out, || {
            let b = Builtin::from_code(model).ok_or(Error::BuiltinModel)?;
            Ok(b.for_lammps_release(yyyymmdd)?.code())
        })
    }
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
            (
                DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2,
                Builtin::LammpsTsujiHertzSqrt2,
            ),
            (
                DC_BUILTIN_LAMMPS_TSUJI_HOOKE_SQRT2,
                Builtin::LammpsTsujiHookeSqrt2,
            ),
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
                dc_builtin_value_for_e(11, 1, 0.5, &mut v),
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

    #[test]
    fn lammps_release_codes() {
        let mut m = -1;
        // SAFETY: valid pointer to a local, or NULL.
        unsafe {
            assert_eq!(dc_builtin_for_lammps_release(4, 20260902, &mut m), DC_OK);
            assert_eq!(m, DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2);
            assert_eq!(dc_builtin_for_lammps_release(9, 20240829, &mut m), DC_OK);
            assert_eq!(m, DC_BUILTIN_LAMMPS_TSUJI_HERTZ);
            assert_eq!(dc_builtin_for_lammps_release(5, 20270101, &mut m), DC_OK);
            assert_eq!(m, DC_BUILTIN_LAMMPS_TSUJI_HOOKE_SQRT2);
            assert_eq!(dc_builtin_for_lammps_release(3, 20260902, &mut m), DC_OK);
            assert_eq!(m, DC_BUILTIN_LAMMPS_COEFF_RESTITUTION);
            m = -1;
            assert_eq!(
                dc_builtin_for_lammps_release(4, 20260211, &mut m),
                DC_ERR_BUILTIN_VERSION
            );
            assert_eq!(
                dc_builtin_for_lammps_release(4, 20260230, &mut m),
                DC_ERR_BUILTIN_VERSION
            );
            assert_eq!(
                dc_builtin_for_lammps_release(2, 20260902, &mut m),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(
                dc_builtin_for_lammps_release(0, 20260902, &mut m),
                DC_ERR_BUILTIN_MODEL
            );
            assert_eq!(m, -1, "untouched on error");
            assert_eq!(
                dc_builtin_for_lammps_release(4, 20260902, core::ptr::null_mut()),
                DC_ERR_NULL_POINTER
            );
        }
    }
}
