//! sin x and cos x for the contact frame's rotation by the mean spin ([`crate::contact::frame`]),
//! in plain + − × and `floor` only: no libm, never contracted in Rust, so that the library and
//! the C header's twin `dci_sin_cos` give the same bits on every CPU and on a GPU. CUDA's `sin`
//! is not glibc's: with each side calling its platform's `sin`, the header on an H200 gives
//! results one to many ulp from the library's in the rotate carry's large-angle steps
//! (docs/gpu.md, "With libm on the device").
//!
//! * Reduction (Cody–Waite): k = ⌊x·2/π + ½⌋, r = ((x − k P1) − k P2) − k P3 with π/2 =
//!   P1 + P2 + P3 + O(2^−122), P1 and P2 of at most 33 significant bits, so k·P1 and k·P2 are
//!   exact for |k| < 2^20: r is x − kπ/2 within its own last rounding and |k|·2^−122 (P3's), so its
//!   relative error stays small next to the zeros of sin and cos; |r| ≤ π/4 (+ the rounding of
//!   x·2/π).
//! * sin r and cos r by their Taylor series to r^17 and r^16 (coefficients 1/n! rounded to
//!   double): on |r| ≤ π/4 the first omitted terms are about 1.2e−19 and 2.0e−18, far under an
//!   ulp. The reduction's own rounding error rl is carried into both (sin(r + rl) ≈ sin r + rl,
//!   cos(r + rl) ≈ cos r − r rl), and cos r's large term 1 − r²/2 is compensated, so that Horner's
//!   rounding is what remains.
//! * The quadrant k mod 4 selects ±sin r or ±cos r.
//!
//! Range: |x| < [`X_MAX`] = 2^19, a chosen bound (the frame rotates by 2x: a step turning it
//! by 2^20 rad or more is no physical spin; the products k·P1, k·P2 stay exact well beyond it).
//! There, and for NaN or ±∞, both results are NaN (the frame then finds no carry: the
//! projection alone applies). Measured error against glibc (tests below): within 1 ulp, also
//! next to multiples of π/2.

/// |x| from which [`sin_cos`] returns NaN.
pub(crate) const X_MAX: f64 = 524_288.0;
/// 2/π rounded to double.
const TWO_OVER_PI: f64 = f64::from_bits(0x3FE4_5F30_6DC9_C883);
/// π/2 = P1 + P2 + P3 (P1, P2: at most 33 significant bits).
const P1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
const P2: f64 = f64::from_bits(0x3DD0_B461_1A60_0000);
const P3: f64 = f64::from_bits(0x3BA3_198A_2E03_7073);
/// (−1)^n/(2n+1)! for n = 1..8 (sin) and (−1)^n/(2n)! for n = 2..8 (cos), rounded to double.
const S3: f64 = -f64::from_bits(0x3FC5_5555_5555_5555);
const S5: f64 = f64::from_bits(0x3F81_1111_1111_1111);
const S7: f64 = -f64::from_bits(0x3F2A_01A0_1A01_A01A);
const S9: f64 = f64::from_bits(0x3EC7_1DE3_A556_C734);
const S11: f64 = -f64::from_bits(0x3E5A_E645_67F5_44E4);
const S13: f64 = f64::from_bits(0x3DE6_1246_13A8_6D09);
const S15: f64 = -f64::from_bits(0x3D6A_E7F3_E733_B81F);
const S17: f64 = f64::from_bits(0x3CE9_52C7_7030_AD4A);
const C4: f64 = f64::from_bits(0x3FA5_5555_5555_5555);
const C6: f64 = -f64::from_bits(0x3F56_C16C_16C1_6C17);
const C8: f64 = f64::from_bits(0x3EFA_01A0_1A01_A01A);
const C10: f64 = -f64::from_bits(0x3E92_7E4F_B778_9F5C);
const C12: f64 = f64::from_bits(0x3E21_EED8_EFF8_D898);
const C14: f64 = -f64::from_bits(0x3DA9_3974_A8C0_7C9D);
const C16: f64 = f64::from_bits(0x3D2A_E7F3_E733_B81F);

/// (sin x, cos x) for |x| < [`X_MAX`]; (NaN, NaN) otherwise. The operations, in this order,
/// are those of `dci_sin_cos` in include/demcontact_inline.h.
#[inline(always)]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if !(x.abs() < X_MAX) {
        return (f64::NAN, f64::NAN);
    }
    let k = (x * TWO_OVER_PI + 0.5).floor();
    // r + rl = x − kπ/2: t exact, u its difference with k P2 rounded, (t − u) − k P2 that
    // rounding's error exactly, then P3's part; r = u + v with its own rounding error rl (|u| ≥ |v|).
    let t = x - k * P1;
    let u = t - k * P2;
    let v = ((t - u) - k * P2) - k * P3;
    let r = u + v;
    let rl = (u - r) + v;
    let z = r * r;
    let ps = S3 + z * (S5 + z * (S7 + z * (S9 + z * (S11 + z * (S13 + z * (S15 + z * S17))))));
    let pc = C4 + z * (C6 + z * (C8 + z * (C10 + z * (C12 + z * (C14 + z * C16)))));
    // sin(r + rl) = sin r + rl cos r ≈ sin r + rl; cos(r + rl) ≈ cos r − r rl.
    let s = r + (rl + (r * z) * ps);
    // cos r = w + ((1 − w − z/2) + z² pc) with w = 1 − z/2 rounded: (1 − w) − z/2 is w's
    // rounding error, exactly, so that the large term costs no ulp.
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    let c = w + (((1.0 - w) - hz) + ((z * z) * pc - r * rl));
    let q = k - 4.0 * (0.25 * k).floor();
    if q == 0.0 {
        (s, c)
    } else if q == 1.0 {
        (c, -s)
    } else if q == 2.0 {
        (-s, -c)
    } else {
        (-c, s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::ulps;

    #[test]
    fn constants_are_what_they_say() {
        // P1 and P2 have 33 significant bits (20 trailing zero bits of 52).
        assert_eq!(P1.to_bits() & 0xF_FFFF, 0);
        assert_eq!(P2.to_bits() & 0xF_FFFF, 0);
        // P1 + P2 + P3 is π/2: P1 + P2 rounds to the double nearest π/2 and P3 is below its ulp.
        assert_eq!(P1 + P2, std::f64::consts::FRAC_PI_2);
        assert!(P3.abs() < 2f64.powi(-60));
        assert_eq!(TWO_OVER_PI, std::f64::consts::FRAC_2_PI);
        let fact = |n: u32| (1..=n).map(f64::from).product::<f64>();
        for (c, n) in [
            (S3, 3),
            (S5, 5),
            (S7, 7),
            (S9, 9),
            (S11, 11),
            (S13, 13),
            (S15, 15),
        ] {
            assert!(ulps(c.abs(), 1.0 / fact(n)) <= 1.0, "1/{n}!");
        }
        for (c, n) in [
            (C4, 4),
            (C6, 6),
            (C8, 8),
            (C10, 10),
            (C12, 12),
            (C14, 14),
            (C16, 16),
        ] {
            assert!(ulps(c.abs(), 1.0 / fact(n)) <= 1.0, "1/{n}!");
        }
        assert!(ulps(S17.abs(), 1.0 / fact(17)) <= 1.0);
    }

    /// Within 1 ulp of glibc's sin and cos (themselves within an ulp) over the range, log-uniform
    /// from 1e−6 to X_MAX, both signs, and next to multiples of π/2 (where the reduction's
    /// cancellation is): the largest error printed (`-- --nocapture`).
    #[test]
    fn within_one_ulp_of_libm() {
        let mut s: u64 = 0x2545_f491_4f6c_dd1d;
        let mut uni = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst: f64 = 0.0;
        let mut check = |x: f64| {
            let (sn, cs) = sin_cos(x);
            let e = ulps(sn, x.sin()).max(ulps(cs, x.cos()));
            assert!(
                e <= 1.0,
                "x = {x:e}: sin {sn:e} / {:e}, cos {cs:e} / {:e}",
                x.sin(),
                x.cos()
            );
            worst = worst.max(e);
        };
        for _ in 0..400_000 {
            let x = 10f64.powf(-6.0 + (X_MAX.log10() + 6.0) * uni());
            check(if uni() < 0.5 { x } else { -x });
        }
        for k in 1..4000 {
            let m = f64::from(k) * std::f64::consts::FRAC_PI_2;
            for d in [-1e-9, -1e-12, 0.0, 1e-12, 1e-9] {
                check(m * (1.0 + d));
            }
        }
        println!("sin_cos: largest error against libm {worst:.2} ulp");
    }

    #[test]
    fn out_of_range_is_nan() {
        for x in [
            X_MAX,
            -X_MAX,
            1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
        let (s, c) = sin_cos(X_MAX - 0.5);
        assert!(s.is_finite() && c.is_finite() && (s * s + c * c - 1.0).abs() < 1e-15);
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
    }
}
