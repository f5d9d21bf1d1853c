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

pub mod builtin;
pub mod calibration;
pub mod codes;
pub mod contact;
pub mod fit;
pub mod force;
pub mod material;
pub mod plan;
pub mod powerlaw;
pub mod status;
pub mod step_accuracy;
pub mod timestep;
pub mod version;
pub mod viscoelastic;

use crate::{EndCriterion, Error};
pub use status::dc_status;
use status::*;

/// Parses a C criterion code.
pub(crate) fn parse_criterion(code: i32) -> Result<EndCriterion, Error> {
    EndCriterion::from_code(code).ok_or(Error::Criterion)
}

/// The one panic boundary of the library: runs `body` and returns its status. A core error maps
/// to its status through [`dc_status::of`] (so `?` works on core results inside `body`); a panic,
/// which the lints make unreachable, becomes `DC_ERR_INTERNAL` instead of unwinding into (and
/// aborting) the host. Every status-returning export goes through here.
#[inline]
pub(crate) fn guard<F>(body: F) -> i32
where
    F: FnOnce() -> Result<(), dc_status>,
{
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(body)) {
        Ok(Ok(())) => DC_OK,
        Ok(Err(s)) => s.code(),
        Err(_) => DC_ERR_INTERNAL,
    }
}

// The pointer policy, one way for every export:
// * a struct or vector the caller passes IN is read by value (`read_unaligned`) after a NULL
//   check: any alignment works and nothing borrows caller memory past the read; except the
//   per-contact hot path's dc_contact_model, dc_contact_state and dc_contact_batch, borrowed in
//   place (`as_ref`, no copy of the model per call): they must be aligned for their type, as the
//   header's conventions say (every object a C compiler places is);
// * a value the library passes OUT is written by value (`write_unaligned`), only on success,
//   after a NULL check made before any work;
// * arrays of doubles (batches, trajectories) must be aligned and must not overlap: see
//   [`force`]'s `span` checks, which turn them into slices.

/// Reads one caller input of type `T` by value. NULL gives `DC_ERR_NULL_POINTER`.
///
/// # Safety
/// `p` must be NULL or readable for one `T` (alignment not required); every bit pattern must be a
/// valid `T` (true of the plain-data structs of the header: integers and doubles only).
#[inline(always)]
pub(crate) unsafe fn read_in<T: Copy>(p: *const T) -> Result<T, dc_status> {
    if p.is_null() {
        return Err(dc_status::DC_ERR_NULL_POINTER);
    }
    // SAFETY: non-null checked; readability and validity are the caller's contract.
    Ok(unsafe { p.read_unaligned() })
}

/// Runs `f` behind the boundary ([`guard`]) and writes its value to `out` on success only.
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
    guard(|| {
        let v = f()?;
        // SAFETY: non-null checked above; validity for writes is the caller's contract.
        unsafe { out.write_unaligned(v) };
        Ok(())
    })
}
