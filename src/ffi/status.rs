//! Status codes: the one table.
//!
//! `dc_status` below is the single place where a status is defined: its name and value (the C
//! header's constants come from it through cbindgen), its message (the exhaustive match in
//! [`dc_status::message`], so a new code without a message does not compile), the list of every
//! code ([`dc_status::ALL`], derived) and the test and fuzzer ranges (both ask
//! [`dc_status::from_repr`] / `dc_status_known`, never a hard-coded range).
//!
//! One code space for the whole library: `DC_OK` (0) or a `DC_ERR_*` code in 6101..=6199, a range
//! chosen to be unmistakable in a host code's log next to errno values or other libraries' codes.
//! Exported functions keep returning a plain `int32_t` (their signatures are ABI); the enum only
//! supplies the values.

use core::ffi::{CStr, c_char};

use crate::Error;

/// Status of a demcontact call: DC_OK (0) or a DC_ERR_* code in 6101..6199.
/// Functions return it as int32_t; dc_status_str() gives its message.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, strum::FromRepr, strum::EnumIter)]
#[allow(non_camel_case_types, clippy::upper_case_acronyms)]
pub enum dc_status {
    /// Success.
    DC_OK = 0,
    /// A required pointer argument was NULL.
    DC_ERR_NULL_POINTER = 6101,
    /// An input was NaN or ±infinity.
    DC_ERR_NOT_FINITE = 6102,
    /// The restitution coefficient e is outside (0, 1].
    DC_ERR_RESTITUTION_RANGE = 6103,
    /// The force-law exponent p is below 1.
    DC_ERR_EXPONENT_RANGE = 6104,
    /// A quantity that must be strictly positive (speed, stiffness, mass, omega0) was not.
    DC_ERR_NOT_POSITIVE = 6105,
    /// A quantity that must not be negative (damping coefficient alpha, ...) was negative.
    DC_ERR_NEGATIVE = 6106,
    /// The end-of-contact criterion is neither DC_END_OVERLAP nor DC_END_FORCE.
    DC_ERR_CRITERION = 6107,
    /// The result overflows a double (inputs valid but extreme).
    DC_ERR_RESULT_RANGE = 6108,
    /// A search or iteration found no answer within its bounds: e.g. dc_dt_for_accuracy where no
    /// step it can check meets the tolerance (e -> 0, very tight tolerances).
    DC_ERR_NO_CONVERGENCE = 6109,
    /// A caller-provided buffer is too short, or a requested sample count is zero.
    DC_ERR_BUFFER_TOO_SHORT = 6110,
    /// The requested event never happens for these inputs, e.g. the overlap of an overdamped
    /// contact never returns to zero under DC_END_OVERLAP.
    DC_ERR_NO_EVENT = 6111,
    /// A quadrature accuracy level is outside DC_LEVEL_MIN..=DC_LEVEL_MAX.
    DC_ERR_LEVEL = 6112,
    /// A dc_duration_plan was not initialised by dc_duration_plan_init (or was modified
    /// afterwards), e.g. a zero-filled struct.
    DC_ERR_PLAN = 6113,
    /// A Poisson ratio is outside (-1, 0.5], the range of an isotropic elastic solid (a library
    /// whose header lacks this constant reports such a ratio as DC_ERR_NOT_POSITIVE).
    DC_ERR_POISSON_RANGE = 6114,
    /// A dc_pair was not initialised by a dc_pair_* constructor (unknown kernel code), e.g. a
    /// zero-filled struct.
    DC_ERR_PAIR_INVALID = 6120,
    /// A caller buffer is misaligned for double, too large to address, or an output array
    /// overlaps an input array.
    DC_ERR_BUFFER_LAYOUT = 6121,
    /// A dc_contact_spec has an unsupported version or size (fill it with dc_contact_spec_init).
    DC_ERR_SPEC_VERSION = 6122,
    /// A dc_contact_spec names an unknown sub-model or an invalid combination.
    DC_ERR_SPEC_MODEL = 6123,
    /// A parameter the chosen sub-models need was left unset (NaN) in the dc_contact_spec.
    DC_ERR_SPEC_UNSET = 6124,
    /// A dc_contact_model was not initialised by dc_contact_model_init (or was modified
    /// afterwards).
    DC_ERR_CONTACT_MODEL_INVALID = 6125,
    /// A contact normal is not a unit vector (| |n|^2 - 1 | > 1e-6).
    DC_ERR_NOT_UNIT = 6126,
    /// Unknown DC_BUILTIN_* model code, or an option the model does not have (clamp not 0/1, or
    /// no clamp for YADE, whose laws always clamp).
    DC_ERR_BUILTIN_MODEL = 6130,
    /// The builtin model cannot realise this restitution: its parameter saturates before it.
    DC_ERR_BUILTIN_UNREACHABLE = 6131,
    /// A fit needs at least two data points.
    DC_ERR_FIT_TOO_FEW = 6132,
    /// The data cannot determine the fit (all impact speeds equal).
    DC_ERR_FIT_DEGENERATE = 6133,
    /// A LAMMPS release date that is not a date YYYYMMDD, or whose damping tsuji formula is not
    /// known: eta up to 22 Jul 2025, eta*sqrt(2) from 2 Sep 2026, unknown in between.
    DC_ERR_BUILTIN_VERSION = 6134,
    /// An integrator code other than DC_INTEGRATOR_VELOCITY_VERLET or
    /// DC_INTEGRATOR_SYMPLECTIC_EULER.
    DC_ERR_INTEGRATOR = 6135,
    /// The model's normal law has no step-aware form (only Tsuji power laws with p <= 3 and Hertz
    /// have one; viscoelastic, DMT, elastic-plastic, JKR and p > 3 do not): see
    /// dc_contact_model_set_step.
    DC_ERR_STEP_UNSUPPORTED = 6136,
    /// The host's explicit step cannot realise this restitution with the step-aware damping
    /// (strong damping, e well below 0.1, at steps near t_H/10).
    DC_ERR_STEP_UNREACHABLE = 6137,
    /// A dc_plan_input value is outside its documented range (radius_min > radius_max, a solid
    /// fraction outside (0, 1), a tolerance >= 1, ...; dc_plan names the member), or its version
    /// or size is not this library's.
    DC_ERR_PLAN_RANGE = 6140,
    /// No plan meets the planner's tolerances: the real material itself misses one (dc_plan
    /// names it), or no step a scene can run meets the e tolerance (DC_PLAN_FIELD_E_TOL; the
    /// step-per-contact bound with DC_PLAN_FIELD_STABILITY_FRACTION), or a contact this damped
    /// does not converge (DC_PLAN_FIELD_RESTITUTION).
    DC_ERR_PLAN_INFEASIBLE = 6141,
    /// An internal error was caught at the boundary (not expected; please report).
    DC_ERR_INTERNAL = 6199,
}

impl dc_status {
    /// Every status, in declaration order (derived from the enum: no hand-kept list).
    pub fn all() -> impl Iterator<Item = dc_status> {
        <dc_status as strum::IntoEnumIterator>::iter()
    }

    /// The C value of this status.
    pub const fn code(self) -> i32 {
        self as i32
    }

    /// The status's message as a static C string. Exhaustive: a status without a message does
    /// not compile.
    pub const fn message(self) -> &'static CStr {
        use dc_status::*;
        match self {
            DC_OK => c"ok",
            DC_ERR_NULL_POINTER => c"a required pointer argument was NULL",
            DC_ERR_NOT_FINITE => c"an input was NaN or infinite",
            DC_ERR_RESTITUTION_RANGE => c"restitution coefficient e must be in (0, 1]",
            DC_ERR_EXPONENT_RANGE => c"force-law exponent p must be >= 1",
            DC_ERR_NOT_POSITIVE => c"a speed, stiffness, mass or frequency must be > 0",
            DC_ERR_NEGATIVE => c"a damping coefficient or overlap must be >= 0",
            DC_ERR_CRITERION => c"end-of-contact criterion must be DC_END_OVERLAP or DC_END_FORCE",
            DC_ERR_RESULT_RANGE => c"the result is not representable as a finite double",
            DC_ERR_NO_CONVERGENCE => c"no answer within the search's bounds (no checked step or iterate converged)",
            DC_ERR_BUFFER_TOO_SHORT => c"a buffer is too short or a sample count is zero",
            DC_ERR_NO_EVENT => c"the requested event never happens for these inputs",
            DC_ERR_LEVEL => c"quadrature accuracy level out of range",
            DC_ERR_PLAN => c"the dc_duration_plan was not initialised by dc_duration_plan_init",
            DC_ERR_POISSON_RANGE => c"Poisson ratio must be in (-1, 0.5]",
            DC_ERR_PAIR_INVALID => c"the dc_pair was not initialised by a dc_pair_* constructor",
            DC_ERR_BUFFER_LAYOUT => c"a buffer is misaligned or an output overlaps an input",
            DC_ERR_SPEC_VERSION => {
                c"dc_contact_spec version or size unsupported (use dc_contact_spec_init)"
            }
            DC_ERR_SPEC_MODEL => c"dc_contact_spec: unknown sub-model or invalid combination",
            DC_ERR_SPEC_UNSET => {
                c"dc_contact_spec: a parameter the chosen sub-models need is unset (NaN)"
            }
            DC_ERR_CONTACT_MODEL_INVALID => {
                c"the dc_contact_model was not initialised by dc_contact_model_init"
            }
            DC_ERR_NOT_UNIT => c"the contact normal is not a unit vector",
            DC_ERR_BUILTIN_MODEL => c"unknown builtin model, or an option it does not have",
            DC_ERR_BUILTIN_UNREACHABLE => c"the builtin model cannot realise this restitution",
            DC_ERR_FIT_TOO_FEW => c"a fit needs at least two data points",
            DC_ERR_FIT_DEGENERATE => c"the data cannot determine the fit (all speeds equal)",
            DC_ERR_BUILTIN_VERSION => {
                c"unknown LAMMPS release: known are YYYYMMDD up to 20250722 (damping tsuji eta) and from 20260902 (eta*sqrt(2))"
            }
            DC_ERR_INTEGRATOR => {
                c"integrator must be DC_INTEGRATOR_VELOCITY_VERLET or DC_INTEGRATOR_SYMPLECTIC_EULER"
            }
            DC_ERR_STEP_UNSUPPORTED => c"the model's normal law has no step-aware form",
            DC_ERR_STEP_UNREACHABLE => {
                c"the explicit step cannot realise this restitution (step-aware damping)"
            }
            DC_ERR_PLAN_RANGE => c"a planner input (or dc_plan_input version/size) is out of range",
            DC_ERR_PLAN_INFEASIBLE => {
                c"no plan meets the tolerances: the real material misses one, or no step a scene can run meets the e tolerance"
            }
            DC_ERR_INTERNAL => c"internal error caught at the C boundary (please report)",
        }
    }

    /// The status of a core error. Exhaustive over [`Error`].
    pub const fn of(err: Error) -> dc_status {
        use dc_status::*;
        match err {
            Error::NotFinite => DC_ERR_NOT_FINITE,
            Error::RestitutionRange => DC_ERR_RESTITUTION_RANGE,
            Error::ExponentRange => DC_ERR_EXPONENT_RANGE,
            Error::NotPositive => DC_ERR_NOT_POSITIVE,
            Error::PoissonRange => DC_ERR_POISSON_RANGE,
            Error::Negative => DC_ERR_NEGATIVE,
            Error::Criterion => DC_ERR_CRITERION,
            Error::ResultRange => DC_ERR_RESULT_RANGE,
            Error::NoConvergence => DC_ERR_NO_CONVERGENCE,
            Error::BufferTooShort => DC_ERR_BUFFER_TOO_SHORT,
            Error::NoEvent => DC_ERR_NO_EVENT,
            Error::PairInvalid => DC_ERR_PAIR_INVALID,
            Error::BufferLayout => DC_ERR_BUFFER_LAYOUT,
            Error::Level => DC_ERR_LEVEL,
            Error::Plan => DC_ERR_PLAN,
            Error::SpecVersion => DC_ERR_SPEC_VERSION,
            Error::SpecModel => DC_ERR_SPEC_MODEL,
            Error::SpecUnset => DC_ERR_SPEC_UNSET,
            Error::ContactModelInvalid => DC_ERR_CONTACT_MODEL_INVALID,
            Error::NotUnit => DC_ERR_NOT_UNIT,
            Error::BuiltinModel => DC_ERR_BUILTIN_MODEL,
            Error::BuiltinUnreachable => DC_ERR_BUILTIN_UNREACHABLE,
            Error::FitTooFew => DC_ERR_FIT_TOO_FEW,
            Error::FitDegenerate => DC_ERR_FIT_DEGENERATE,
            Error::BuiltinVersion => DC_ERR_BUILTIN_VERSION,
            Error::Integrator => DC_ERR_INTEGRATOR,
            Error::StepUnsupported => DC_ERR_STEP_UNSUPPORTED,
            Error::StepUnreachable => DC_ERR_STEP_UNREACHABLE,
            Error::PlanRange => DC_ERR_PLAN_RANGE,
            Error::PlanInfeasible => DC_ERR_PLAN_INFEASIBLE,
        }
    }
}

impl From<Error> for dc_status {
    fn from(err: Error) -> Self {
        dc_status::of(err)
    }
}

// Rust names for the C values as plain `i32` (what the exports return), so boundary code and
// Rust tests read like the header. Aliases only: each value comes from the enum above. Hidden
// from cbindgen, which takes the C constants from the enum itself.
/// cbindgen:ignore
#[allow(missing_docs)]
mod codes {
    use super::dc_status;
    pub const DC_OK: i32 = dc_status::DC_OK as i32;
    pub const DC_ERR_NULL_POINTER: i32 = dc_status::DC_ERR_NULL_POINTER as i32;
    pub const DC_ERR_NOT_FINITE: i32 = dc_status::DC_ERR_NOT_FINITE as i32;
    pub const DC_ERR_RESTITUTION_RANGE: i32 = dc_status::DC_ERR_RESTITUTION_RANGE as i32;
    pub const DC_ERR_EXPONENT_RANGE: i32 = dc_status::DC_ERR_EXPONENT_RANGE as i32;
    pub const DC_ERR_NOT_POSITIVE: i32 = dc_status::DC_ERR_NOT_POSITIVE as i32;
    pub const DC_ERR_NEGATIVE: i32 = dc_status::DC_ERR_NEGATIVE as i32;
    pub const DC_ERR_CRITERION: i32 = dc_status::DC_ERR_CRITERION as i32;
    pub const DC_ERR_RESULT_RANGE: i32 = dc_status::DC_ERR_RESULT_RANGE as i32;
    pub const DC_ERR_NO_CONVERGENCE: i32 = dc_status::DC_ERR_NO_CONVERGENCE as i32;
    pub const DC_ERR_BUFFER_TOO_SHORT: i32 = dc_status::DC_ERR_BUFFER_TOO_SHORT as i32;
    pub const DC_ERR_NO_EVENT: i32 = dc_status::DC_ERR_NO_EVENT as i32;
    pub const DC_ERR_LEVEL: i32 = dc_status::DC_ERR_LEVEL as i32;
    pub const DC_ERR_PLAN: i32 = dc_status::DC_ERR_PLAN as i32;
    pub const DC_ERR_POISSON_RANGE: i32 = dc_status::DC_ERR_POISSON_RANGE as i32;
    pub const DC_ERR_PAIR_INVALID: i32 = dc_status::DC_ERR_PAIR_INVALID as i32;
    pub const DC_ERR_BUFFER_LAYOUT: i32 = dc_status::DC_ERR_BUFFER_LAYOUT as i32;
    pub const DC_ERR_SPEC_VERSION: i32 = dc_status::DC_ERR_SPEC_VERSION as i32;
    pub const DC_ERR_SPEC_MODEL: i32 = dc_status::DC_ERR_SPEC_MODEL as i32;
    pub const DC_ERR_SPEC_UNSET: i32 = dc_status::DC_ERR_SPEC_UNSET as i32;
    pub const DC_ERR_CONTACT_MODEL_INVALID: i32 = dc_status::DC_ERR_CONTACT_MODEL_INVALID as i32;
    pub const DC_ERR_NOT_UNIT: i32 = dc_status::DC_ERR_NOT_UNIT as i32;
    pub const DC_ERR_BUILTIN_MODEL: i32 = dc_status::DC_ERR_BUILTIN_MODEL as i32;
    pub const DC_ERR_BUILTIN_UNREACHABLE: i32 = dc_status::DC_ERR_BUILTIN_UNREACHABLE as i32;
    pub const DC_ERR_FIT_TOO_FEW: i32 = dc_status::DC_ERR_FIT_TOO_FEW as i32;
    pub const DC_ERR_FIT_DEGENERATE: i32 = dc_status::DC_ERR_FIT_DEGENERATE as i32;
    pub const DC_ERR_BUILTIN_VERSION: i32 = dc_status::DC_ERR_BUILTIN_VERSION as i32;
    pub const DC_ERR_INTEGRATOR: i32 = dc_status::DC_ERR_INTEGRATOR as i32;
    pub const DC_ERR_STEP_UNSUPPORTED: i32 = dc_status::DC_ERR_STEP_UNSUPPORTED as i32;
    pub const DC_ERR_STEP_UNREACHABLE: i32 = dc_status::DC_ERR_STEP_UNREACHABLE as i32;
    pub const DC_ERR_PLAN_RANGE: i32 = dc_status::DC_ERR_PLAN_RANGE as i32;
    pub const DC_ERR_PLAN_INFEASIBLE: i32 = dc_status::DC_ERR_PLAN_INFEASIBLE as i32;
    pub const DC_ERR_INTERNAL: i32 = dc_status::DC_ERR_INTERNAL as i32;
}
pub use codes::*;

/// Contact ends when the overlap returns to zero (solvers that do not clamp the normal force).
pub const DC_END_OVERLAP: i32 = 0;
/// Contact ends when the total normal force first reaches zero while unloading (solvers that clamp
/// attractive normal forces to zero: LIGGGHTS limitForce, LAMMPS limit_damping, Chrono, YADE).
pub const DC_END_FORCE: i32 = 1;

/// Velocity Verlet in the LAMMPS/LIGGGHTS order: half kick, drift, the force from the new
/// position and the half-step velocity, half kick (dc_contact_model_set_step).
pub const DC_INTEGRATOR_VELOCITY_VERLET: i32 = 0;
/// Symplectic Euler: the force from (x, v), then v += dt f/m, then x += dt v.
pub const DC_INTEGRATOR_SYMPLECTIC_EULER: i32 = 1;

const UNKNOWN: &CStr = c"unknown demcontact status";

/// A static, NUL-terminated English message for a status code; never NULL, never freed.
/// Unknown codes give "unknown demcontact status".
#[unsafe(no_mangle)]
pub extern "C" fn dc_status_str(status: i32) -> *const c_char {
    dc_status::from_repr(status)
        .map_or(UNKNOWN, dc_status::message)
        .as_ptr()
}

/// 1 if `status` is DC_OK or one of the documented DC_ERR_* codes, else 0 (for hosts and test
/// harnesses that check a status without hard-coding the code range).
#[unsafe(no_mangle)]
pub extern "C" fn dc_status_known(status: i32) -> i32 {
    i32::from(dc_status::from_repr(status).is_some())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_message_is_distinct_and_every_code_in_range() {
        let all: Vec<dc_status> = dc_status::all().collect();
        assert!(all.len() >= 17, "the table lost codes: {}", all.len());
        for (i, &a) in all.iter().enumerate() {
            let code = a.code();
            assert!(code == 0 || (6101..=6199).contains(&code), "{a:?} = {code}");
            assert_eq!(dc_status::from_repr(code), Some(a));
            assert_eq!(dc_status_known(code), 1);
            assert_ne!(a.message(), UNKNOWN, "{a:?} has no message");
            for &b in all.iter().skip(i + 1) {
                assert_ne!(code, b.code());
                assert_ne!(a.message(), b.message());
            }
        }
        for code in [-1, 1, 6100, 6115, 6138, 6142, 6200, i32::MIN, i32::MAX] {
            assert_eq!(dc_status_known(code), 0, "{code}");
            // SAFETY: dc_status_str returns a static NUL-terminated string.
            let s = unsafe { CStr::from_ptr(dc_status_str(code)) };
            assert_eq!(s, UNKNOWN);
        }
    }
}
