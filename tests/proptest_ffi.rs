//! Property tests through the C ABI: for any bit pattern of the inputs no export panics or
//! returns DC_ERR_INTERNAL, errors leave the output untouched, successes are finite; and the
//! physics' monotonicity and round trips hold on the valid domain.

use demcontact::ffi::{calibration::*, material::*, status::*, timestep::*};
use proptest::prelude::*;

const SENTINEL: f64 = -9.87654321e123;

/// Every status an export may return.
fn known(s: i32) -> bool {
    matches!(s, DC_OK | 6101..=6111)
}

/// Runs an export with one output and checks the boundary contract; returns (status, output).
fn contract(f: impl Fn(*mut f64) -> i32) -> Result<(i32, f64), TestCaseError> {
    let mut out = SENTINEL;
    let s = f(&mut out);
    prop_assert!(known(s), "unknown or internal status {}", s);
    if s == DC_OK {
        prop_assert!(out.is_finite(), "non-finite output on success");
    } else {
        prop_assert_eq!(out.to_bits(), SENTINEL.to_bits(), "output touched on error");
    }
    Ok((s, out))
}

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<u64>().prop_map(f64::from_bits),
        prop::num::f64::ANY,
        Just(0.0),
        Just(-0.0),
        Just(1.0),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20_000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn calibration_any_bits(a in any_f64(), b in any_f64(), c in -2i32..4) {
        contract(|o| unsafe { dc_alpha_from_e(a, b, c, o) })?;
        contract(|o| unsafe { dc_e_from_alpha(a, b, c, o) })?;
    }

    #[test]
    fn timestep_and_material_any_bits(a in any_f64(), b in any_f64(), c in any_f64(), d in any_f64()) {
        contract(|o| unsafe { dc_dt_crit(a, b, c, o) })?;
        contract(|o| unsafe { dc_hertz_stiffness(a, b, c, d, b, c, o) })?;
        contract(|o| unsafe { dc_effective_modulus(a, b, c, d, o) })?;
    }

    #[test]
    fn alpha_falls_as_e_rises(e1 in 1e-12f64..1.0, e2 in 1e-12f64..1.0, p in 1.0f64..20.0, c in 0i32..2) {
        let (e1, e2) = (e1.min(e2), e1.max(e2));
        let (s1, a1) = contract(|o| unsafe { dc_alpha_from_e(e1, p, c, o) })?;
        let (s2, a2) = contract(|o| unsafe { dc_alpha_from_e(e2, p, c, o) })?;
        prop_assert_eq!((s1, s2), (DC_OK, DC_OK));
        prop_assert!(a1 >= a2, "alpha({}) = {} < alpha({}) = {}", e1, a1, e2, a2);
    }

    #[test]
    fn e_falls_as_damping_grows(a1 in 0.0f64..50.0, a2 in 0.0f64..50.0, p in 1.0f64..20.0, c in 0i32..2) {
        let (a1, a2) = (a1.min(a2), a1.max(a2));
        let (_, e1) = contract(|o| unsafe { dc_e_from_alpha(a1, p, c, o) })?;
        let (_, e2) = contract(|o| unsafe { dc_e_from_alpha(a2, p, c, o) })?;
        prop_assert!(e1 >= e2);
        prop_assert!((0.0..=1.0).contains(&e1) && (0.0..=1.0).contains(&e2));
    }

    #[test]
    fn round_trip(le in -6.0f64..-1e-9, p in 1.0f64..20.0, c in 0i32..2) {
        // e log-uniform in [1e-6, 1): the contract range of the round-trip precision.
        let e = 10f64.powf(le);
        let (_, a) = contract(|o| unsafe { dc_alpha_from_e(e, p, c, o) })?;
        let (_, back) = contract(|o| unsafe { dc_e_from_alpha(a, p, c, o) })?;
        prop_assert!(((back - e) / e).abs() <= 1e-13, "e={} back={}", e, back);
    }
}
