//! Status codes and their messages.
//!
//! One code space for the whole library: `DC_OK` (0) or a `DC_ERR_*` code in 6101..=6199, a range
//! chosen to be unmistakable in a host code's log next to errno values or other libraries' codes.

use core::ffi::c_char;

/// Success.
pub const DC_OK: i32 = 0;
/// A required pointer argument was NULL.
pub const DC_ERR_NULL_POINTER: i32 = 6101;
/// An input was NaN or ±infinity.
pub const DC_ERR_NOT_FINITE: i32 = 6102;
/// The restitution coefficient e is outside (0, 1].
pub const DC_ERR_RESTITUTION_RANGE: i32 = 6103;
/// The force-law exponent p is below 1.
pub const DC_ERR_EXPONENT_RANGE: i32 = 6104;
/// A quantity that must be strictly positive (speed, stiffness, mass, omega0) was not.
pub const DC_ERR_NOT_POSITIVE: i32 = 6105;
/// A quantity that must not be negative (damping coefficient alpha, ...) was negative.
pub const DC_ERR_NEGATIVE: i32 = 6106;
/// The end-of-contact criterion is neither DC_END_OVERLAP nor DC_END_FORCE.
pub const DC_ERR_CRITERION: i32 = 6107;
/// The result overflows a double (inputs valid but extreme).
pub const DC_ERR_RESULT_RANGE: i32 = 6108;
/// An iteration failed to converge (not expected for valid input; please report).
pub const DC_ERR_NO_CONVERGENCE: i32 = 6109;
/// A caller-provided buffer is too short, or a requested sample count is zero.
pub const DC_ERR_BUFFER_TOO_SHORT: i32 = 6110;
/// The requested event never happens for these inputs, e.g. the overlap of an overdamped contact
/// never returns to zero under DC_END_OVERLAP.
pub const DC_ERR_NO_EVENT: i32 = 6111;
/// A dc_pair was not initialised by a dc_pair_* constructor (unknown kernel code), e.g. a
/// zero-filled struct.
pub const DC_ERR_PAIR_INVALID: i32 = 6120;
/// A caller buffer is misaligned for double, too large to address, or an output array overlaps an
/// input array.
pub const DC_ERR_BUFFER_LAYOUT: i32 = 6121;
/// A quadrature accuracy level is outside DC_LEVEL_MIN..=DC_LEVEL_MAX.
pub const DC_ERR_LEVEL: i32 = 6112;
/// A dc_duration_plan was not initialised by dc_duration_plan_init (or was modified afterwards),
/// e.g. a zero-filled struct.
pub const DC_ERR_PLAN: i32 = 6113;
/// A dc_contact_spec has an unsupported version or size (fill it with dc_contact_spec_init).
pub const DC_ERR_SPEC_VERSION: i32 = 6122;
/// A dc_contact_spec names an unknown sub-model or an invalid combination.
pub const DC_ERR_SPEC_MODEL: i32 = 6123;
/// A parameter the chosen sub-models need was left unset (NaN) in the dc_contact_spec.
pub const DC_ERR_SPEC_UNSET: i32 = 6124;
/// A dc_contact_model was not initialised by dc_contact_model_init (or was modified afterwards).
pub const DC_ERR_CONTACT_MODEL_INVALID: i32 = 6125;
/// A contact normal is not a unit vector (| |n|^2 - 1 | > 1e-6).
pub const DC_ERR_NOT_UNIT: i32 = 6126;
/// An internal error was caught at the boundary (not expected; please report).
pub const DC_ERR_INTERNAL: i32 = 6199;

/// Contact ends when the overlap returns to zero (solvers that do not clamp the normal force).
pub const DC_END_OVERLAP: i32 = 0;
/// Contact ends when the total normal force first reaches zero while unloading (solvers that clamp
/// attractive normal forces to zero: LIGGGHTS limitForce, LAMMPS limit_damping, Chrono, YADE).
pub const DC_END_FORCE: i32 = 1;

const fn message(status: i32) -> &'static str {
    match status {
        DC_OK => "ok\0",
        DC_ERR_NULL_POINTER => "a required pointer argument was NULL\0",
        DC_ERR_NOT_FINITE => "an input was NaN or infinite\0",
        DC_ERR_RESTITUTION_RANGE => "restitution coefficient e must be in (0, 1]\0",
        DC_ERR_EXPONENT_RANGE => "force-law exponent p must be >= 1\0",
        DC_ERR_NOT_POSITIVE => "a speed, stiffness, mass or frequency must be > 0\0",
        DC_ERR_NEGATIVE => "a damping coefficient or overlap must be >= 0\0",
        DC_ERR_CRITERION => "end-of-contact criterion must be DC_END_OVERLAP or DC_END_FORCE\0",
        DC_ERR_RESULT_RANGE => "the result is not representable as a finite double\0",
        DC_ERR_NO_CONVERGENCE => "an iteration did not converge (please report)\0",
        DC_ERR_BUFFER_TOO_SHORT => "a buffer is too short or a sample count is zero\0",
        DC_ERR_NO_EVENT => "the requested event never happens for these inputs\0",
        DC_ERR_PAIR_INVALID => "the dc_pair was not initialised by a dc_pair_* constructor\0",
        DC_ERR_BUFFER_LAYOUT => "a buffer is misaligned or an output overlaps an input\0",
        DC_ERR_LEVEL => "quadrature accuracy level out of range\0",
        DC_ERR_PLAN => "the dc_duration_plan was not initialised by dc_duration_plan_init\0",
        DC_ERR_SPEC_VERSION => {
            "dc_contact_spec version or size unsupported (use dc_contact_spec_init)\0"
        }
        DC_ERR_SPEC_MODEL => "dc_contact_spec: unknown sub-model or invalid combination\0",
        DC_ERR_SPEC_UNSET => {
            "dc_contact_spec: a parameter the chosen sub-models need is unset (NaN)\0"
        }
        DC_ERR_CONTACT_MODEL_INVALID => {
            "the dc_contact_model was not initialised by dc_contact_model_init\0"
        }
        DC_ERR_NOT_UNIT => "the contact normal is not a unit vector\0",
        DC_ERR_INTERNAL => "internal error caught at the C boundary (please report)\0",
        _ => "unknown demcontact status\0",
    }
}

/// A static, NUL-terminated English message for a status code; never NULL, never freed.
/// Unknown codes give "unknown demcontact status".
#[unsafe(no_mangle)]
pub extern "C" fn dc_status_str(status: i32) -> *const c_char {
    message(status).as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_message_is_nul_terminated_and_distinct() {
        let codes = [
            DC_OK,
            DC_ERR_NULL_POINTER,
            DC_ERR_NOT_FINITE,
            DC_ERR_RESTITUTION_RANGE,
            DC_ERR_EXPONENT_RANGE,
            DC_ERR_NOT_POSITIVE,
            DC_ERR_NEGATIVE,
            DC_ERR_CRITERION,
            DC_ERR_RESULT_RANGE,
            DC_ERR_NO_CONVERGENCE,
            DC_ERR_BUFFER_TOO_SHORT,
            DC_ERR_NO_EVENT,
            DC_ERR_PAIR_INVALID,
            DC_ERR_BUFFER_LAYOUT,
            DC_ERR_LEVEL,
            DC_ERR_PLAN,
            DC_ERR_SPEC_VERSION,
            DC_ERR_SPEC_MODEL,
            DC_ERR_SPEC_UNSET,
            DC_ERR_CONTACT_MODEL_INVALID,
            DC_ERR_NOT_UNIT,
            DC_ERR_INTERNAL,
        ];
        let unknown = message(-1);
        for (i, &a) in codes.iter().enumerate() {
            let m = message(a);
            assert!(m.ends_with('\0') && m[..m.len() - 1].find('\0').is_none());
            assert_ne!(m, unknown, "code {a} has no message");
            for &b in codes.iter().skip(i + 1) {
                assert_ne!(a, b);
                assert_ne!(m, message(b));
            }
        }
    }
}
