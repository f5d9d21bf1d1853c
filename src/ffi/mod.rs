//! The C boundary, and only the C boundary: every `extern "C"` function of `include/demcontact.h`.
//!
//! Rules every export follows (rustls-ffi style):
//! * status return (`int32_t`, `DC_OK` = 0, errors in the distinctive `DC_ERR_*` 6100 range);
//! * every pointer checked for null before anything else; outputs written only on success,
//!   so on error the caller's output is left untouched;
//! * every input validated by the core, which reports an [`crate::Error`] mapped here to a status;
//! * the body runs under `catch_unwind`: the core has no panic path by construction (clippy denies
//!   unwrap/expect/indexing/panic in `src/`), and should one ever appear it becomes
//!   `DC_ERR_INTERNAL` instead of unwinding into (and aborting) the host simulation;
//! * no heap allocation, no global mutable state: callable from any thread at any time.

pub mod calibration;
pub mod contact;
pub mod force;
pub mod material;
pub mod powerlaw;
pub mod status;
pub mod step_accuracy;
pub mod timestep;
pub mod version;
pub mod viscoelastic;

use crate::{EndCriterion, Error};
use status::*;

/// Maps a core error to its C status code.
pub(crate) const fn status_of(err: Error) -> i32 {
    match err {
        Error::NotFinite => DC_ERR_NOT_FINITE,
        Error::RestitutionRange => DC_ERR_RESTITUTION_RANGE,
        Error::ExponentRange => DC_ERR_EXPONENT_RANGE,
        Error::NotPositive => DC_ERR_NOT_POSITIVE,
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
    }
}

/// Parses a C criterion code.
pub(crate) fn parse_criterion(code: i32) -> Result<EndCriterion, Error> {
    EndCriterion::from_code(code).ok_or(Error::Criterion)
}

/// Runs `f` behind the boundary rules and writes its value to `out` on success.
///
/// # Safety
/// `out` must be null or valid for a write of one `T` (alignment is not required).
#[inline]
pub(crate) unsafe fn write_result<T, F>(out: *mut T, f: F) -> i32
where
    F: FnOnce() -> Result<T, Error>,
{
    if out.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(v)) => {
            // SAFETY: non-null checked above; validity for writes is the caller's contract.
            unsafe { out.write_unaligned(v) };
            DC_OK
        }
        Ok(Err(e)) => status_of(e),
        Err(_) => DC_ERR_INTERNAL,
    }
}
