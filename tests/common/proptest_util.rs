//! Shared by the property tests through the C ABI (tests/proptest_ffi.rs,
//! tests/proptest_contact.rs, tests/proptest_builtin_fit.rs): the status check, the
//! outputs-untouched-on-error contract and the reproducible proptest configuration.
#![allow(dead_code)]

use demcontact::ffi::status::{DC_ERR_INTERNAL, DC_OK, dc_status_known};
use proptest::prelude::{ProptestConfig, TestCaseError, prop_assert, prop_assert_eq};

/// What an output starts as, so that a write on error shows.
pub const SENTINEL: f64 = -9.87654321e123;

/// Every status an export may return: DC_OK or a documented DC_ERR_* code (never
/// DC_ERR_INTERNAL, which would mean a caught panic). The library's status table decides (no
/// hard-coded range).
pub fn known(s: i32) -> bool {
    dc_status_known(s) == 1 && s != DC_ERR_INTERNAL
}

/// `cases` cases from the fixed `seed`, so that `cargo test` (and CI) is reproducible; set
/// PROPTEST_RNG_SEED (a number) to explore other inputs, e.g.
/// `for s in $(seq 1 50); do PROPTEST_RNG_SEED=$s cargo test --release --test proptest_ffi || break; done`.
pub fn config(cases: u32, seed: u64) -> ProptestConfig {
    let mut c = ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        c.rng_seed = proptest::test_runner::RngSeed::Fixed(seed);
    }
    c
}

/// The bytes of a value, to compare an output before and after a failed call (padding included:
/// the value is compared in place, never copied, so zeroed padding stays zeroed).
pub fn bytes<T>(x: &T) -> Vec<u8> {
    // SAFETY: a live value of that size, read as bytes; the outputs compared are plain data
    // (doubles and integers) prepared with every byte initialised.
    unsafe { std::slice::from_raw_parts((x as *const T).cast::<u8>(), std::mem::size_of::<T>()) }
        .to_vec()
}

/// Runs an export writing `out` (prepared in place by the caller) and checks the boundary
/// contract: a known status, and on error not one byte of `out` changed. Returns the status.
pub fn untouched_on_error<T>(
    out: &mut T,
    f: impl FnOnce(*mut T) -> i32,
) -> Result<i32, TestCaseError> {
    let before = bytes(out);
    let s = f(out);
    prop_assert!(known(s), "unknown or internal status {}", s);
    if s != DC_OK {
        prop_assert_eq!(bytes(out), before, "output touched on error (status {})", s);
    }
    Ok(s)
}

/// The contract of an export with one double output: as [`untouched_on_error`] from
/// [`SENTINEL`], and a finite output on success. Returns (status, output).
pub fn contract(f: impl FnOnce(*mut f64) -> i32) -> Result<(i32, f64), TestCaseError> {
    let mut out = SENTINEL;
    let s = untouched_on_error(&mut out, f)?;
    if s == DC_OK {
        prop_assert!(out.is_finite(), "non-finite output on success");
    }
    Ok((s, out))
}
