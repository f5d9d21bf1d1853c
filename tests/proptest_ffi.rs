//! Property tests through the C ABI: for any bit pattern of the inputs no export panics or
//! returns DC_ERR_INTERNAL, errors leave the output untouched, successes are finite; and the
//! physics' monotonicity and round trips hold on the valid domain.

use demcontact::ffi::{calibration::*, force::*, material::*, status::*, timestep::*};
use proptest::prelude::*;

const SENTINEL: f64 = -9.87654321e123;

/// Every status an export may return: DC_OK or a documented DC_ERR_* code (never
/// DC_ERR_INTERNAL, which would mean a caught panic).
fn known(s: i32) -> bool {
    s == DC_OK || (6101..=6139).contains(&s)
}

fn pair_bytes(p: &dc_pair) -> Vec<u8> {
    let ptr = (p as *const dc_pair).cast::<u8>();
    unsafe { std::slice::from_raw_parts(ptr, std::mem::size_of::<dc_pair>()) }.to_vec()
}

/// A constructor's boundary contract: known status, output untouched on error.
fn pair_contract(f: impl Fn(*mut dc_pair) -> i32) -> Result<(i32, dc_pair), TestCaseError> {
    let mut pair: dc_pair = unsafe { std::mem::zeroed() };
    pair.p = SENTINEL;
    let before = pair_bytes(&pair);
    let s = f(&mut pair);
    prop_assert!(known(s), "unknown or internal status {}", s);
    if s != DC_OK {
        prop_assert_eq!(pair_bytes(&pair), before, "pair touched on error");
    }
    Ok((s, pair))
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

    #[test]
    fn pair_constructors_any_bits(a in any_f64(), b in any_f64(), c in any_f64(), crit in -1i32..3) {
        pair_contract(|o| unsafe { dc_pair_powerlaw(a, b, c, crit, o) })?;
        pair_contract(|o| unsafe { dc_pair_powerlaw_alpha(a, b, c, crit, o) })?;
        pair_contract(|o| unsafe { dc_pair_linear(a, b, crit, o) })?;
        pair_contract(|o| unsafe { dc_pair_hertz(a, b, a, b, c, crit, o) })?;
        pair_contract(|o| unsafe { dc_pair_viscoelastic(a, b, a, b, c, crit, o) })?;
    }

    #[test]
    fn checked_force_any_bits(p in 1.0f64..5.0, e in 0.01f64..1.0, crit in 0i32..2,
                              d in any_f64(), vn in any_f64(), r in any_f64(), m in any_f64()) {
        let (s, pair) = pair_contract(|o| unsafe { dc_pair_powerlaw(p, 1e4, e, crit, o) })?;
        prop_assert_eq!(s, DC_OK);
        let (s, f) = contract(|o| unsafe { dc_normal_force_checked(&pair, d, vn, r, m, o) })?;
        if s == DC_OK {
            // The unchecked kernel gives the same bits where the checked one succeeds.
            let g = unsafe { dc_normal_force(&pair, d, vn, r, m) };
            prop_assert_eq!(f.to_bits(), g.to_bits());
            if crit == DC_END_FORCE {
                prop_assert!(f >= 0.0, "clamped force negative: {}", f);
            }
        }
    }

    #[test]
    fn force_monotone_in_overlap_and_speed(p in 1.0f64..5.0, e in 0.01f64..1.0, crit in 0i32..2,
                                          d1 in 1e-9f64..1e-2, d2 in 1e-9f64..1e-2, v in -10.0f64..10.0, w in -10.0f64..10.0) {
        let (_, pair) = pair_contract(|o| unsafe { dc_pair_powerlaw(p, 1e5, e, crit, o) })?;
        let (lo, hi) = (d1.min(d2), d1.max(d2));
        // More overlap at zero speed: more force. Faster compression at fixed overlap: more force.
        let f_lo = unsafe { dc_normal_force(&pair, lo, 0.0, 1e-3, 1e-3) };
        let f_hi = unsafe { dc_normal_force(&pair, hi, 0.0, 1e-3, 1e-3) };
        prop_assert!(f_lo <= f_hi);
        let (vlo, vhi) = (v.min(w), v.max(w));
        let g_lo = unsafe { dc_normal_force(&pair, lo, vlo, 1e-3, 1e-3) };
        let g_hi = unsafe { dc_normal_force(&pair, lo, vhi, 1e-3, 1e-3) };
        prop_assert!(g_lo <= g_hi);
        prop_assert!(g_lo.is_finite() && g_hi.is_finite());
    }
}
