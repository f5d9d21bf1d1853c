//! Property tests through the C ABI: for any bit pattern of the inputs no export panics or
//! returns DC_ERR_INTERNAL, errors leave the output untouched, successes are finite; and the
//! physics' monotonicity and round trips hold on the valid domain.

use demcontact::ffi::{
    calibration::*, force::*, material::*, powerlaw::*, status::*, timestep::*, viscoelastic::*,
};
use proptest::prelude::*;

#[path = "common/proptest_util.rs"]
mod proptest_util;
use proptest_util::{SENTINEL, contract, known, untouched_on_error};

/// A constructor's boundary contract: known status, output untouched on error.
fn pair_contract(f: impl Fn(*mut dc_pair) -> i32) -> Result<(i32, dc_pair), TestCaseError> {
    let mut pair: dc_pair = unsafe { std::mem::zeroed() };
    pair.p = SENTINEL;
    let s = untouched_on_error(&mut pair, f)?;
    Ok((s, pair))
}

fn config(cases: u32) -> ProptestConfig {
    proptest_util::config(cases, 20_261_121)
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
    #![proptest_config(config(20_000))]

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

// ---------------------------------------------------------------------------------------------
// Power-law calculus and viscoelastic exports.

/// Any bit pattern, or a value in a physically meaningful range (so that the valid branches are
/// reached as often as the rejections).
fn mixed(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    prop_oneof![any_f64(), (lo.ln()..hi.ln()).prop_map(f64::exp)]
}

/// Damping coefficient: any bits, or α spanning underdamped, critical and overdamped contacts.
fn mixed_alpha() -> impl Strategy<Value = f64> {
    prop_oneof![any_f64(), 0.0f64..20.0, Just(2.0), Just(0.0)]
}

/// dc_energy contract: known status, untouched on error, finite and summing to 1 on success.
fn energy_contract(f: impl Fn(*mut dc_energy) -> i32) -> Result<(i32, dc_energy), TestCaseError> {
    let sentinel = dc_energy {
        e: SENTINEL,
        loading: SENTINEL,
        unloading: SENTINEL,
        returned: SENTINEL,
        clamped: SENTINEL,
    };
    let mut out = sentinel;
    let s = untouched_on_error(&mut out, f)?;
    if s == DC_OK {
        let parts = [out.e, out.loading, out.unloading, out.returned, out.clamped];
        prop_assert!(
            parts.iter().all(|x| x.is_finite()),
            "non-finite partition {:?}",
            out
        );
        // Each fraction in [0, 1] up to rounding, and the four energies sum to 1.
        prop_assert!(
            parts.iter().all(|x| (-1e-15..=1.0 + 1e-15).contains(x)),
            "fraction out of [0,1]: {:?}",
            out
        );
        let sum = out.loading + out.unloading + out.returned + out.clamped;
        prop_assert!((sum - 1.0).abs() <= 4e-15, "fractions sum to {}", sum);
        prop_assert!(
            (out.returned - out.e * out.e).abs() <= 4e-16,
            "returned != e^2: {:?}",
            out
        );
    }
    Ok((s, out))
}

/// A two-output export (dc_viscoelastic_k_gamma): both untouched on error, both finite on success.
fn contract2(f: impl Fn(*mut f64, *mut f64) -> i32) -> Result<(i32, f64, f64), TestCaseError> {
    let (mut a, mut b) = (SENTINEL, SENTINEL);
    let s = f(&mut a, &mut b);
    prop_assert!(known(s), "unknown or internal status {}", s);
    if s == DC_OK {
        prop_assert!(a.is_finite() && b.is_finite());
    } else {
        prop_assert_eq!(
            (a.to_bits(), b.to_bits()),
            (SENTINEL.to_bits(), SENTINEL.to_bits()),
            "output touched on error"
        );
    }
    Ok((s, a, b))
}

proptest! {
    #![proptest_config(config(5_000))]

    #[test]
    fn powerlaw_any_bits(p in mixed(1.0, 20.0), a in mixed_alpha(), v0 in mixed(1e-9, 1e4),
                         w in mixed(1e-3, 1e9), crit in -1i32..3, level in -1i32..6) {
        contract(|o| unsafe { dc_max_overlap(p, a, v0, w, o) })?;
        contract(|o| unsafe { dc_time_of_max_overlap(p, a, v0, w, o) })?;
        let (s, tau) = contract(|o| unsafe { dc_contact_duration(p, a, v0, w, crit, o) })?;
        let (sl, tau_l) = contract(|o| unsafe { dc_contact_duration_level(p, a, v0, w, crit, level, o) })?;
        // At the highest level the knob is the same computation as the level-free export.
        if level == 4 {
            prop_assert_eq!((s, tau.to_bits()), (sl, tau_l.to_bits()));
        }
        energy_contract(|o| unsafe { dc_energy_partition(p, a, crit, o) })?;
        contract(|o| unsafe { dc_dt_linearised(p, v0, w, o) })?;
        contract(|o| unsafe { dc_dt_static(p, a, w, v0, o) })?;
        contract(|o| unsafe { dc_omega0(v0, w, o) })?;
        prop_assert_eq!(unsafe { dc_max_overlap(p, a, v0, w, std::ptr::null_mut()) }, DC_ERR_NULL_POINTER);
    }

    #[test]
    fn trajectory_buffers(p in mixed(1.0, 20.0), a in mixed_alpha(), v0 in mixed(1e-3, 1e3),
                          w in mixed(1e-1, 1e5), m in mixed(1e-6, 1e3), crit in -1i32..3, level in -1i32..6,
                          n in prop_oneof![0usize..10, Just(usize::MAX)], buf_len in 0usize..=8, nulls in 0u8..16) {
        // Four buffers of 8 doubles; any of them may be passed as NULL; buf_len never exceeds 8.
        let mut bufs = [[SENTINEL; 8]; 4];
        let ptr = |b: &mut [f64; 8], k: u8| if nulls & (1 << k) != 0 { std::ptr::null_mut() } else { b.as_mut_ptr() };
        let [b0, b1, b2, b3] = &mut bufs;
        let (t, d, v, f) = (ptr(b0, 0), ptr(b1, 1), ptr(b2, 2), ptr(b3, 3));
        let s = unsafe { dc_contact_trajectory(p, a, v0, w, m, crit, level, n, t, d, v, f, buf_len) };
        prop_assert!(known(s), "unknown or internal status {}", s);
        if nulls != 0 {
            prop_assert_eq!(s, DC_ERR_NULL_POINTER);
        } else if n < 2 || buf_len < n {
            prop_assert_eq!(s, DC_ERR_BUFFER_TOO_SHORT);
        }
        for b in &bufs {
            for (i, x) in b.iter().enumerate() {
                if s == DC_OK && i < n {
                    prop_assert!(x.is_finite(), "non-finite sample {} on success", i);
                } else if s == DC_ERR_RESULT_RANGE && i < n {
                    // The one documented exception: an overflowing sample is found after
                    // sampling, so the first n doubles may have been written.
                } else {
                    prop_assert_eq!(x.to_bits(), SENTINEL.to_bits(), "buffer written at {} (status {})", i, s);
                }
            }
        }
        if s == DC_OK {
            // First sample is the impact: t = 0, delta = 0, v = v0.
            prop_assert_eq!((bufs[0][0], bufs[1][0], bufs[2][0]), (0.0, 0.0, v0));
        }
    }

    #[test]
    fn viscoelastic_any_bits(x in mixed(1e-6, 1e3), y in mixed(1e-6, 1e3), z in mixed(1e-6, 1e3),
                             u in mixed(1e-6, 1.0), crit in -1i32..3) {
        contract(|o| unsafe { dc_viscoelastic_e(x, crit, o) })?;
        contract(|o| unsafe { dc_viscoelastic_e_series(x, crit, o) })?;
        contract(|o| unsafe { dc_viscoelastic_b(x, y, z, o) })?;
        contract(|o| unsafe { dc_viscoelastic_e_of_speed(x, y, z, crit, o) })?;
        contract2(|k, g| unsafe { dc_viscoelastic_k_gamma(x, y, z, k, g) })?;
        contract(|o| unsafe { dc_viscoelastic_b_from_e(u, crit, o) })?;
        contract(|o| unsafe { dc_viscoelastic_beta_from_e(u, x, crit, o) })?;
        contract(|o| unsafe { dc_viscoelastic_a_from_e(u, x, y, z, crit, o) })?;
        contract(|o| unsafe { dc_viscoelastic_speed_for_e(u, x, crit, o) })?;
        let (mut k, mut g) = (SENTINEL, SENTINEL);
        prop_assert_eq!(unsafe { dc_viscoelastic_k_gamma(x, y, z, &mut k, std::ptr::null_mut()) }, DC_ERR_NULL_POINTER);
        prop_assert_eq!(unsafe { dc_viscoelastic_k_gamma(x, y, z, std::ptr::null_mut(), &mut g) }, DC_ERR_NULL_POINTER);
        prop_assert_eq!((k.to_bits(), g.to_bits()), (SENTINEL.to_bits(), SENTINEL.to_bits()));
    }

    #[test]
    fn viscoelastic_reference_any_bits(bits in any::<u64>(), b in 0.0f64..10.0, crit in -1i32..3) {
        // The reference integrator's cost grows with b (0.8 s at 3e3): any bit pattern whose value
        // would be a valid b above 10 is replaced by a b in [0, 10].
        let raw = f64::from_bits(bits);
        let x = if raw.is_finite() && raw > 10.0 { b } else { raw };
        contract(|o| unsafe { dc_viscoelastic_e_reference(x, crit, o) })?;
        contract(|o| unsafe { dc_viscoelastic_e_reference(b, crit, o) })?;
    }

    #[test]
    fn max_overlap_falls_with_damping_and_grows_with_speed(p in 1.0f64..20.0, a1 in 0.0f64..30.0, a2 in 0.0f64..30.0,
                                                            lv1 in -9.0f64..4.0, lv2 in -9.0f64..4.0, lw in -3.0f64..9.0) {
        let (a1, a2) = (a1.min(a2), a1.max(a2));
        let (v1, v2) = (10f64.powf(lv1.min(lv2)), 10f64.powf(lv1.max(lv2)));
        let w = 10f64.powf(lw);
        let (_, d1) = contract(|o| unsafe { dc_max_overlap(p, a1, v1, w, o) })?;
        let (_, d2) = contract(|o| unsafe { dc_max_overlap(p, a2, v1, w, o) })?;
        let (_, d3) = contract(|o| unsafe { dc_max_overlap(p, a1, v2, w, o) })?;
        prop_assert!(d1 >= d2, "delta_max grew with alpha: {} -> {}", d1, d2);
        prop_assert!(d3 >= d1, "delta_max fell with v0: {} -> {}", d1, d3);
    }

    #[test]
    fn durations_monotone_in_damping(p in 1.0f64..20.0, z1 in 0.0f64..0.999, z2 in 0.0f64..0.999,
                                      lv in -6.0f64..3.0, lw in -2.0f64..6.0) {
        // Verified numerically first (scan of zeta in [0, 5] step 0.0025, p = 1..20): the
        // overlap-end duration grows with alpha for every p (diverging at critical damping);
        // the force-end duration and the time of maximum overlap fall as alpha grows only for
        // p <= 4 — from p = 5 on both first *grow* with alpha (docs/robustness.md).
        let s = std::f64::consts::SQRT_2 * (p + 1.0).sqrt();
        let (a1, a2) = (s * z1.min(z2), s * z1.max(z2));
        let (v0, w) = (10f64.powf(lv), 10f64.powf(lw));
        let (_, to1) = contract(|o| unsafe { dc_contact_duration(p, a1, v0, w, DC_END_OVERLAP, o) })?;
        let (_, to2) = contract(|o| unsafe { dc_contact_duration(p, a2, v0, w, DC_END_OVERLAP, o) })?;
        prop_assert!(to2 >= to1 * (1.0 - 1e-13), "overlap-end tau fell with alpha: {} -> {}", to1, to2);
        let (_, tf1) = contract(|o| unsafe { dc_contact_duration(p, a1, v0, w, DC_END_FORCE, o) })?;
        let (_, tf2) = contract(|o| unsafe { dc_contact_duration(p, a2, v0, w, DC_END_FORCE, o) })?;
        let (_, tm1) = contract(|o| unsafe { dc_time_of_max_overlap(p, a1, v0, w, o) })?;
        let (_, tm2) = contract(|o| unsafe { dc_time_of_max_overlap(p, a2, v0, w, o) })?;
        if p <= 4.0 {
            prop_assert!(tf2 <= tf1 * (1.0 + 1e-12), "force-end tau grew with alpha: {} -> {}", tf1, tf2);
            prop_assert!(tm2 <= tm1 * (1.0 + 1e-12), "t_max grew with alpha: {} -> {}", tm1, tm2);
        }
        // Maximum overlap comes before the force end, which comes before the overlap end (at it
        // when undamped: the force and the overlap vanish together).
        prop_assert!(tm1 < tf1 && tf1 <= to1, "t_max {} tau_F {} tau_O {}", tm1, tf1, to1);
    }

    #[test]
    fn timesteps_monotone(p in 1.0f64..20.0, a1 in 0.0f64..30.0, a2 in 0.0f64..30.0, lv1 in -9.0f64..4.0, lv2 in -9.0f64..4.0) {
        let (a1, a2) = (a1.min(a2), a1.max(a2));
        let (v1, v2) = (10f64.powf(lv1.min(lv2)), 10f64.powf(lv1.max(lv2)));
        // Faster impacts overlap more, stiffen the contact and shorten the linearised step;
        // more damping shortens the static step.
        let (_, d1) = contract(|o| unsafe { dc_dt_linearised(p, v1, 1e3, o) })?;
        let (_, d2) = contract(|o| unsafe { dc_dt_linearised(p, v2, 1e3, o) })?;
        prop_assert!(d2 <= d1 * (1.0 + 1e-15));
        let (_, s1) = contract(|o| unsafe { dc_dt_static(p, a1, 1e3, 9.81, o) })?;
        let (_, s2) = contract(|o| unsafe { dc_dt_static(p, a2, 1e3, 9.81, o) })?;
        prop_assert!(s2 <= s1 * (1.0 + 1e-15));
    }

    #[test]
    fn energy_and_trajectory_agree_with_calibration(le in -6.0f64..-1e-9, p in 1.0f64..20.0, c in 0i32..2) {
        // e -> alpha, then the energy partition and the sampled trajectory realise that e.
        let e = 10f64.powf(le);
        let (_, a) = contract(|o| unsafe { dc_alpha_from_e(e, p, c, o) })?;
        let (_, en) = energy_contract(|o| unsafe { dc_energy_partition(p, a, c, o) })?;
        prop_assert!(((en.e - e) / e).abs() <= 1e-13, "partition e {} vs {}", en.e, e);
        let mut b = [[0.0f64; 5]; 4];
        let [t, d, v, f] = &mut b;
        let s = unsafe { dc_contact_trajectory(p, a, 0.5, 300.0, 0.01, c, 4, 5, t.as_mut_ptr(), d.as_mut_ptr(), v.as_mut_ptr(), f.as_mut_ptr(), 5) };
        prop_assert_eq!(s, DC_OK);
        // 1e-10: the exit speed is summed from the trajectory's own formulas (measured worst in
        // tests/extremes.rs); e itself round-trips to 1e-13 above.
        prop_assert!(((-b[2][4] / 0.5 - e) / e).abs() <= 1e-10, "exit speed {} vs e {}", -b[2][4] / 0.5, e);
        prop_assert!(b[0].windows(2).all(|w| w[0] < w[1]), "times not increasing {:?}", b[0]);
    }

    #[test]
    fn viscoelastic_e_falls_as_b_grows(lb1 in -6.0f64..6.0, lb2 in -6.0f64..6.0, c in 0i32..2) {
        let (b1, b2) = (10f64.powf(lb1.min(lb2)), 10f64.powf(lb1.max(lb2)));
        let (_, e1) = contract(|o| unsafe { dc_viscoelastic_e(b1, c, o) })?;
        let (_, e2) = contract(|o| unsafe { dc_viscoelastic_e(b2, c, o) })?;
        prop_assert!(e1 >= e2, "e({}) = {} < e({}) = {}", b1, e1, b2, e2);
        prop_assert!(e2 > 0.0 && e1 <= 1.0);
    }

    #[test]
    fn viscoelastic_round_trips(le in -12.0f64..-1e-9, c in 0i32..2, lv in -6.0f64..3.0, lk in 0.0f64..12.0) {
        // e -> b -> e within the contract's 1e-12 relative, over e in [1e-12, 1).
        let e = 10f64.powf(le);
        let (_, b) = contract(|o| unsafe { dc_viscoelastic_b_from_e(e, c, o) })?;
        let (_, back) = contract(|o| unsafe { dc_viscoelastic_e(b, c, o) })?;
        prop_assert!(((back - e) / e).abs() <= 1e-12, "e={} b={} back={}", e, b, back);
        // Calibration in physical units: beta at v_ref, then e of that speed for a stiffness k.
        let (v, k) = (10f64.powf(lv), 10f64.powf(lk));
        let (_, beta) = contract(|o| unsafe { dc_viscoelastic_beta_from_e(e, v, c, o) })?;
        let gamma = beta * k.powf(0.6);
        let (_, e2) = contract(|o| unsafe { dc_viscoelastic_e_of_speed(k, gamma, v, c, o) })?;
        prop_assert!(((e2 - e) / e).abs() <= 1e-11, "physical round trip e={} -> {}", e, e2);
        let (_, vs) = contract(|o| unsafe { dc_viscoelastic_speed_for_e(e, beta, c, o) })?;
        prop_assert!(((vs - v) / v).abs() <= 1e-11, "speed_for_e {} vs {}", vs, v);
    }
}
