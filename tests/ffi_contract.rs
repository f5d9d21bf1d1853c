//! The boundary contract of every export: status codes for bad input, output untouched on error,
//! finite outputs on success.

use demcontact::ffi::{calibration::*, powerlaw::*, status::*, timestep::*, version::*};
use std::ffi::CStr;

const SENTINEL: f64 = -12345.678;

fn call(f: impl Fn(*mut f64) -> i32) -> (i32, f64) {
    let mut out = SENTINEL;
    let s = f(&mut out);
    if s != DC_OK {
        assert_eq!(
            out.to_bits(),
            SENTINEL.to_bits(),
            "output touched on error {s}"
        );
    } else {
        assert!(out.is_finite(), "non-finite output on success");
    }
    (s, out)
}

#[test]
fn alpha_from_e_statuses() {
    let cases: [(f64, f64, i32, i32); 12] = [
        (0.5, 1.5, DC_END_OVERLAP, DC_OK),
        (0.5, 1.5, DC_END_FORCE, DC_OK),
        (1.0, 1.0, DC_END_FORCE, DC_OK),
        (0.0, 1.5, DC_END_OVERLAP, DC_ERR_RESTITUTION_RANGE),
        (-0.1, 1.5, DC_END_FORCE, DC_ERR_RESTITUTION_RANGE),
        (1.0000001, 1.5, DC_END_FORCE, DC_ERR_RESTITUTION_RANGE),
        (f64::NAN, 1.5, DC_END_FORCE, DC_ERR_NOT_FINITE),
        (f64::INFINITY, 1.5, DC_END_FORCE, DC_ERR_NOT_FINITE),
        (0.5, f64::NAN, DC_END_FORCE, DC_ERR_NOT_FINITE),
        (0.5, 0.99, DC_END_FORCE, DC_ERR_EXPONENT_RANGE),
        (0.5, -3.0, DC_END_OVERLAP, DC_ERR_EXPONENT_RANGE),
        (0.5, 1.5, 2, DC_ERR_CRITERION),
    ];
    for (e, p, c, want) in cases {
        let (s, _) = call(|o| unsafe { dc_alpha_from_e(e, p, c, o) });
        assert_eq!(s, want, "e={e} p={p} c={c}");
    }
    assert_eq!(
        unsafe { dc_alpha_from_e(0.5, 1.5, DC_END_FORCE, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
    // Null is reported before invalid input.
    assert_eq!(
        unsafe { dc_alpha_from_e(f64::NAN, 0.0, 9, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
    // Subnormal e: α stays finite under both criteria.
    for c in [DC_END_OVERLAP, DC_END_FORCE] {
        let (s, a) = call(|o| unsafe { dc_alpha_from_e(5e-324, 1.5, c, o) });
        assert_eq!(s, DC_OK);
        assert!(a > 0.0);
    }
    // Huge p with tiny e overflows α: a status, not inf.
    let (s, _) = call(|o| unsafe { dc_alpha_from_e(5e-324, 1e300, DC_END_FORCE, o) });
    assert_eq!(s, DC_ERR_RESULT_RANGE);
}

#[test]
fn e_from_alpha_statuses() {
    let cases: [(f64, f64, i32, i32); 8] = [
        (0.3, 1.5, DC_END_OVERLAP, DC_OK),
        (0.0, 1.5, DC_END_FORCE, DC_OK),
        (1e300, 1.5, DC_END_FORCE, DC_OK),
        (-1e-300, 1.5, DC_END_FORCE, DC_ERR_NEGATIVE),
        (f64::NAN, 1.5, DC_END_OVERLAP, DC_ERR_NOT_FINITE),
        (f64::INFINITY, 1.5, DC_END_OVERLAP, DC_ERR_NOT_FINITE),
        (0.3, 0.0, DC_END_OVERLAP, DC_ERR_EXPONENT_RANGE),
        (0.3, 1.5, -1, DC_ERR_CRITERION),
    ];
    for (a, p, c, want) in cases {
        let (s, e) = call(|o| unsafe { dc_e_from_alpha(a, p, c, o) });
        assert_eq!(s, want, "α={a} p={p} c={c}");
        if s == DC_OK {
            assert!((0.0..=1.0).contains(&e));
        }
    }
    assert_eq!(
        unsafe { dc_e_from_alpha(0.3, 1.5, DC_END_FORCE, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
}

#[test]
fn dt_crit_statuses() {
    let cases: [(f64, f64, f64, i32); 9] = [
        (1.5, 1.0, 1e3, DC_OK),
        (1.0, 1e-9, 1e-9, DC_OK),
        (1.5, 0.0, 1e3, DC_ERR_NOT_POSITIVE),
        (1.5, -1.0, 1e3, DC_ERR_NOT_POSITIVE),
        (1.5, 1.0, 0.0, DC_ERR_NOT_POSITIVE),
        (1.5, f64::NAN, 1e3, DC_ERR_NOT_FINITE),
        (1.5, 1.0, f64::INFINITY, DC_ERR_NOT_FINITE),
        (0.5, 1.0, 1e3, DC_ERR_EXPONENT_RANGE),
        (1.0, 1.0, 5e-324, DC_ERR_RESULT_RANGE),
    ];
    for (p, v0, w0, want) in cases {
        let (s, _) = call(|o| unsafe { dc_dt_crit(p, v0, w0, o) });
        assert_eq!(s, want, "p={p} v0={v0} ω0={w0}");
    }
    assert_eq!(
        unsafe { dc_dt_crit(1.5, 1.0, 1.0, std::ptr::null_mut()) },
        DC_ERR_NULL_POINTER
    );
}

#[test]
fn strings() {
    let v = unsafe { CStr::from_ptr(dc_version()) }
        .to_str()
        .unwrap_or("");
    assert_eq!(v, env!("CARGO_PKG_VERSION"));
    for s in [
        DC_OK,
        DC_ERR_NULL_POINTER,
        DC_ERR_INTERNAL,
        42,
        i32::MIN,
        i32::MAX,
    ] {
        let m = unsafe { CStr::from_ptr(dc_status_str(s)) }
            .to_str()
            .unwrap_or("");
        assert!(!m.is_empty());
    }
}

#[test]
fn unaligned_output_is_written() {
    // The boundary writes unaligned, so a packed host struct field works.
    let mut buf = [0u8; 16];
    let ptr = unsafe { buf.as_mut_ptr().add(1) }.cast::<f64>();
    assert_eq!(
        unsafe { dc_alpha_from_e(0.5, 1.5, DC_END_OVERLAP, ptr) },
        DC_OK
    );
    let a = unsafe { ptr.read_unaligned() };
    assert!(a > 0.0);
}

/// Found by the fuzzer: a trajectory whose samples overflow is refused with DC_ERR_RESULT_RANGE
/// after sampling; its first n samples are then NaN in every buffer (no plausible half result)
/// and nothing beyond n is touched.
#[test]
fn trajectory_overflow_leaves_nan_not_half_results() {
    let (n, len) = (5usize, 6usize);
    let sentinel = -7.25e101;
    let mut b = [[sentinel; 6]; 4];
    let [t, d, v, f] = &mut b;
    let s = unsafe {
        dc_contact_trajectory(
            1.07e155,
            3.3e-308,
            1.41e277,
            3.9e-317,
            1.40e277,
            DC_END_FORCE,
            0,
            n,
            t.as_mut_ptr(),
            d.as_mut_ptr(),
            v.as_mut_ptr(),
            f.as_mut_ptr(),
            len,
        )
    };
    assert_eq!(s, DC_ERR_RESULT_RANGE);
    for buf in &b {
        assert!(buf[..n].iter().all(|x| x.is_nan()), "{buf:?}");
        assert!(buf[n..].iter().all(|&x| x == sentinel), "{buf:?}");
    }
}

/// Found by the fuzzer: for p beyond ~9e307 the overlap-end restitution formed (s-α)(s+α) with
/// s = √(2(p+1)) > 1.3e154, which overflowed and gave e = 1 for any α; the energy partition's
/// fractions then summed to 1.44. e must be exp(-πζ/√(1-ζ²)) there as for any p, and the
/// fractions must sum to 1.
#[test]
fn overlap_end_restitution_at_the_largest_exponents() {
    let (p, alpha) = (1.6853375492571783e308, 1.6759775895427744e153);
    let (s, e) = call(|o| unsafe { dc_e_from_alpha(alpha, p, DC_END_OVERLAP, o) });
    assert_eq!(s, DC_OK);
    let zeta = alpha / (2f64.sqrt() * (p + 1.0).sqrt());
    let want = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
    assert!((e - want).abs() <= 1e-14 * want, "e = {e}, want {want}");
    let mut en = dc_energy::default();
    let s = unsafe { dc_energy_partition(p, alpha, DC_END_OVERLAP, &mut en) };
    assert_eq!(s, DC_OK);
    assert_eq!(en.e.to_bits(), e.to_bits());
    let sum = en.loading + en.unloading + en.returned + en.clamped;
    assert!((sum - 1.0).abs() <= 1e-14, "fractions sum to {sum}: {en:?}");
}
