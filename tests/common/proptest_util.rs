//! Shared by the property tests through the C ABI (tests/proptest_ffi.rs,
//! tests/proptest_contact.rs): the status check and the reproducible proptest configuration.
#![allow(dead_code)]

use demcontact::ffi::status::{DC_ERR_INTERNAL, dc_status_known};
use proptest::prelude::ProptestConfig;

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
