//! Table-driven ln and exp reductions for the force kernels' power [`super::pow_dd`]: 32-entry
//! tables shrink the ranges the series must cover, so both series are short (9 and 6 terms
//! instead of 21 and 13) and ln needs no division. Plain multiplication and addition only (never
//! contracted in Rust), so every CPU flavour of a batch loop rounds alike; a table read
//! vectorises as a gather. The C header (include/demcontact_inline.h, `dc_pow_inline`) has the
//! same tables and operations.
//!
//! * ln: x = 2^e·z with z ∈ [0.6797, 1.3594) (the bits of x minus those of [`OFF`], as in
//!   glibc's and ARM's log); the top five bits of z's mantissa field pick c_i (the middle of
//!   its 1/32 of the range, c_20 = 1), and ln z = ln c_i + ln(1 + u), u = (z − c_i)·RN(1/c_i),
//!   |u| ≤ 2^−6. z − c_i is exact (same binade, or Sterbenz), so u carries two roundings
//!   (≤ 2^−59 in ln z); ln(1 + u) by its Taylor series to u^9 (remainder < 2^−63).
//! * exp: t = (k + r·32/ln 2)·ln 2/32, k = round(t·32/ln 2) by the 1.5·2^52 shifter, whose low
//!   five bits index 2^(j/32) (stored as RN value + RN remainder), |r| ≤ ln 2/64;
//!   e^r − 1 by its Taylor series to r^6 (remainder < 4e−18); e^t = 2^((k−j)/32)·2^(j/32)·e^r.
//!
//! Tables from 300-bit arithmetic (mpmath); the tests check them independently.

use super::reduce::{LN2_HI, LN2_LO, SHIFTER};

/// Bits of 0.6796875 = c_0 − 2^−8: x − OFF (as integers) has e in its top 12 bits and the
/// table index in the next five; c_20 = 1 exactly.
pub(crate) const OFF: u64 = 0x3fe5_c000_0000_0000;
/// 2^52, for the integer-to-float trick.
pub(crate) const TWO52: f64 = 4_503_599_627_370_496.0;
/// ln 2/32 split as [`LN2_HI`]/32 (32 significant bits: k·LN2_32_HI is exact for |k| < 2^21)
/// and its remainder.
pub(crate) const LN2_32_HI: f64 = LN2_HI / 32.0;
pub(crate) const LN2_32_LO: f64 = LN2_LO / 32.0;
/// 32/ln 2 (any nearby value would do: it only picks k).
pub(crate) const INV_LN2_32: f64 = 32.0 * core::f64::consts::LOG2_E;

/// Table entry `i mod 32`.
#[inline(always)]
fn entry(t: &[f64; 32], i: u64) -> f64 {
    t.get((i & 31) as usize).copied().unwrap_or(0.0)
}

/// The ln table index of a normal x > 0 (its low five bits count; the same as [`ln_split`]'s).
#[inline(always)]
pub(crate) fn ln_index(x: f64) -> u64 {
    x.to_bits().wrapping_sub(OFF) >> 47
}

/// The ln table entries (RN(1/c_i), RN(ln c_i)) for an index of [`ln_index`].
#[inline(always)]
pub(crate) fn ln_entries(i: u64) -> (f64, f64) {
    (entry(&INVC, i), entry(&LOGC, i))
}

/// x = 2^e·z for a normal x > 0: (e as an integer-valued float, ln z), z ∈ [0.6797, 1.3594),
/// given the table entries of x ([`ln_entries`] of [`ln_index`]; passed in so that a batch can
/// read the tables in a separate loop: a loop with table reads does not vectorise).
/// Branch-free; ln z within about 0.6 ulp of |ln z| ≤ 0.39 (absolute ≤ 2^−55).
#[inline(always)]
pub(crate) fn ln_split(x: f64, (invc, logc): (f64, f64)) -> (f64, f64) {
    let ix = x.to_bits();
    let tmp = ix.wrapping_sub(OFF);
    // e = tmp >> 52 (arithmetic; −1023 ≤ e ≤ 1024), biased by 1024 to a non-negative integer,
    // as a float by the 2^52 trick (no int→float conversion instruction).
    let eb = tmp.wrapping_add(1024 << 52) >> 52;
    let e = f64::from_bits(0x4330_0000_0000_0000 | eb) - (TWO52 + 1024.0);
    let z = f64::from_bits(ix.wrapping_sub(tmp & (0xfff << 52)));
    let c = f64::from_bits(OFF + (tmp & (31 << 47)) + (1 << 46));
    // z − c exact; u carries the rounding of 1/c and of the product.
    let u = (z - c) * invc;
    // ln(1 + u) = u + u²·L(u), L = −1/2 + u/3 − … + u^7/9 by Estrin's scheme.
    let u2 = u * u;
    let u4 = u2 * u2;
    let b0 = -1.0 / 2.0 + (1.0 / 3.0) * u;
    let b1 = -1.0 / 4.0 + (1.0 / 5.0) * u;
    let b2 = -1.0 / 6.0 + (1.0 / 7.0) * u;
    let b3 = -1.0 / 8.0 + (1.0 / 9.0) * u;
    let c0 = b0 + b1 * u2;
    let c1 = b2 + b3 * u2;
    let l = c0 + c1 * u4;
    (e, logc + (u + u2 * l))
}

/// y = SHIFTER + k, k = round(t·32/ln 2), exactly: k mod 32 sits in the low five bits of y.
#[inline(always)]
fn exp_shifted(t: f64) -> f64 {
    t * INV_LN2_32 + SHIFTER
}

/// The exp table index of t (its low five bits count; the same as [`exp_split`]'s).
#[inline(always)]
pub(crate) fn exp_index(t: f64) -> u64 {
    exp_shifted(t).to_bits()
}

/// The exp table entries (RN(2^(j/32)), RN remainder) for an index of [`exp_index`].
#[inline(always)]
pub(crate) fn exp_entries(j: u64) -> (f64, f64) {
    (entry(&EXP2_HI, j), entry(&EXP2_LO, j))
}

/// e^t = 2^k·p: (k as an integer-valued float, p ∈ (0.98, 2)), for |t| < 2^20·ln 2/32 (where
/// k·ln 2/32 splits exactly; beyond, the caller's result is 0 or ∞ anyway), given the table
/// entries of t ([`exp_entries`] of [`exp_index`]). Branch-free.
#[inline(always)]
pub(crate) fn exp_split(t: f64, (hi, lo): (f64, f64)) -> (f64, f64) {
    let y = exp_shifted(t);
    let kf = y - SHIFTER;
    let jf = f64::from_bits(0x4330_0000_0000_0000 | (y.to_bits() & 31)) - TWO52;
    // (k − j)/32: the difference is a multiple of 32, both operations exact.
    let k_hi = (kf - jf) * (1.0 / 32.0);
    // r exact up to k·LN2_32_LO's rounding (the first difference exact by Sterbenz).
    let r = (t - kf * LN2_32_HI) - kf * LN2_32_LO;
    // e^r − 1 = r + r²·E(r), E = 1/2 + r/6 + … + r^4/720 by Estrin's scheme.
    let r2 = r * r;
    let b0 = 1.0 / 2.0 + (1.0 / 6.0) * r;
    let b1 = 1.0 / 24.0 + (1.0 / 120.0) * r;
    let c0 = b0 + b1 * r2;
    let w = r + r2 * (c0 + (1.0 / 720.0) * (r2 * r2));
    // 2^(j/32)·e^r = hi + (lo + hi·w): the remainder lo keeps the table exact to ~2^−106.
    (k_hi, hi + (lo + hi * w))
}

/// RN(1/c_i).
pub(crate) static INVC: [f64; 32] = [
    1.4545454545454546,
    1.4222222222222223,
    1.391304347826087,
    1.3617021276595744,
    1.3333333333333333,
    1.3061224489795917,
    1.28,
    1.2549019607843137,
    1.2307692307692308,
    1.2075471698113207,
    1.1851851851851851,
    1.1636363636363636,
    1.1428571428571428,
    1.1228070175438596,
    1.103448275862069,
    1.0847457627118644,
    1.0666666666666667,
    1.0491803278688525,
    1.032258064516129,
    1.0158730158730158,
    1.0,
    0.9696969696969697,
    0.9411764705882353,
    0.9142857142857143,
    0.8888888888888888,
    0.8648648648648649,
    0.8421052631578947,
    0.8205128205128205,
    0.8,
    0.7804878048780488,
    0.7619047619047619,
    0.7441860465116279,
];

/// RN(ln c_i).
pub(crate) static LOGC: [f64; 32] = [
    -0.3746934494414107,
    -0.3522205935893521,
    -0.33024168687057687,
    -0.3087354816496133,
    -0.2876820724517809,
    -0.26706278524904525,
    -0.24686007793152578,
    -0.22705745063534608,
    -0.2076393647782445,
    -0.18859116980755003,
    -0.16989903679539747,
    -0.15154989812720093,
    -0.13353139262452263,
    -0.1158318155251217,
    -0.09844007281325252,
    -0.0813456394539524,
    -0.06453852113757118,
    -0.048009219186360606,
    -0.0317486983145803,
    -0.015748356968139168,
    0.0,
    0.030771658666753687,
    0.06062462181643484,
    0.08961215868968714,
    0.11778303565638346,
    0.1451820098444979,
    0.17185025692665923,
    0.19782574332991987,
    0.22314355131420976,
    0.24783616390458127,
    0.27193371548364176,
    0.2954642128938359,
];

/// RN(2^(j/32)).
pub(crate) static EXP2_HI: [f64; 32] = [
    1.0,
    1.0218971486541166,
    1.0442737824274138,
    1.0671404006768237,
    1.0905077326652577,
    1.1143867425958924,
    1.1387886347566916,
    1.1637248587775775,
    1.189207115002721,
    1.215247359980469,
    1.241857812073484,
    1.2690509571917332,
    1.2968395546510096,
    1.3252366431597413,
    1.3542555469368927,
    1.383909881963832,
    core::f64::consts::SQRT_2,
    1.4451808069770467,
    1.4768261459394993,
    1.5091644275934228,
    1.5422108254079407,
    1.5759808451078865,
    1.6104903319492543,
    1.645755478153965,
    1.681792830507429,
    1.718619298122478,
    1.7562521603732995,
    1.7947090750031072,
    1.8340080864093424,
    1.8741676341103,
    1.9152065613971474,
    1.9571441241754002,
];

/// RN(2^(j/32) − RN(2^(j/32))): the remainder of each `EXP2_HI` entry.
pub(crate) static EXP2_LO: [f64; 32] = [
    0.0,
    5.109225028973444e-17,
    8.551889705537965e-17,
    -7.899853966841582e-17,
    -3.046782079812471e-17,
    1.0410278456845571e-16,
    8.912812676025408e-17,
    3.8292048369240935e-17,
    3.982015231465646e-17,
    -7.712630692681488e-17,
    4.658027591836937e-17,
    2.667932131342186e-18,
    2.5382502794888315e-17,
    -2.8587312100388614e-17,
    7.70094837980299e-17,
    -6.770511658794786e-17,
    -9.667293313452913e-17,
    -3.0237581349939873e-17,
    -3.483994556892796e-17,
    -1.016455327754295e-16,
    7.949834809697621e-17,
    -1.0136916471278304e-17,
    2.4707192569797888e-17,
    -1.0125679913674773e-16,
    8.199010020581497e-17,
    -1.851380418263111e-17,
    2.960140695448873e-17,
    1.8227458427912087e-17,
    3.283107224245627e-17,
    -6.122763413004143e-17,
    -1.0619946056195963e-16,
    8.960767791036668e-17,
];

#[cfg(test)]
mod tests {
    use super::*;

    /// c_i: the middle of the i-th 1/32 of the mantissa range of z (c_20 = 1).
    fn c(i: u64) -> f64 {
        f64::from_bits(OFF + (i << 47) + (1 << 46))
    }

    /// Double-double product (exact by FMA: the test needs it, the kernels do not).
    fn dd_mul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
        let p = a.0 * b.0;
        let e = a.0.mul_add(b.0, -p) + (a.0 * b.1 + a.1 * b.0);
        let s = p + e;
        (s, e - (s - p))
    }

    #[test]
    fn tables_are_what_they_say() {
        assert_eq!(c(0), 0.6875);
        assert_eq!(c(20), 1.0);
        assert_eq!(c(31), 1.34375);
        assert_eq!(LN2_32_HI * 32.0, LN2_HI);
        for i in 0..32u64 {
            let ci = c(i);
            // RN(1/c): IEEE division is correctly rounded.
            assert_eq!(entry(&INVC, i).to_bits(), (1.0 / ci).to_bits(), "INVC[{i}]");
            // ln c within libm's ln's error (< 1 ulp), and exactly 0 at c = 1.
            let (want, got) = (ci.ln(), entry(&LOGC, i));
            assert!(
                (got - want).abs() <= f64::EPSILON * want.abs(),
                "LOGC[{i}] {got:e} vs {want:e}"
            );
            // (hi + lo)^32 = 2^i in double-double (five squarings, error < 2^−100).
            let mut v = (entry(&EXP2_HI, i), entry(&EXP2_LO, i));
            assert!(
                v.1.abs() <= 0.5 * f64::EPSILON * v.0,
                "EXP2_LO[{i}] not a remainder"
            );
            for _ in 0..5 {
                v = dd_mul(v, v);
            }
            let want = 2f64.powi(i as i32);
            assert_eq!(v.0, want, "EXP2_HI[{i}]");
            assert!(
                v.1.abs() < want * 2f64.powi(-95),
                "EXP2 pair {i}: {:e}",
                v.1
            );
        }
        assert_eq!(LOGC[20], 0.0);
    }

    #[test]
    fn reductions_against_libm() {
        // ln: e and z = x/2^e, ln z against libm across binades and every table interval.
        let mut worst_ln: f64 = 0.0;
        let mut worst_exp: f64 = 0.0;
        for k in 0..=200_000u64 {
            let x = 10f64.powf(-300.0 + 600.0 * k as f64 / 200_000.0);
            let (e, lz) = ln_split(x, ln_entries(ln_index(x)));
            assert_eq!(e, e.round(), "{x:e}");
            let z = x / 2f64.powf(e);
            assert!((0.679..1.36).contains(&z), "{x:e}: z = {z}");
            worst_ln = worst_ln.max((lz - z.ln()).abs());
            // exp: p·2^k against libm over |t| ≤ 1.
            let t = -1.0 + 2.0 * k as f64 / 200_000.0;
            let (kh, p) = exp_split(t, exp_entries(exp_index(t)));
            assert!((0.98..2.0).contains(&p), "{t}: p = {p}");
            let rel = (p * 2f64.powf(kh) / t.exp() - 1.0).abs();
            worst_exp = worst_exp.max(rel);
        }
        println!("ln_split: {worst_ln:e} absolute; exp_split: {worst_exp:e} relative");
        assert!(worst_ln < 1.5 * f64::EPSILON * 0.39, "{worst_ln:e}");
        assert!(worst_exp < 1.5 * f64::EPSILON, "{worst_exp:e}");
        assert_eq!(ln_split(1.0, ln_entries(ln_index(1.0))), (0.0, 0.0));
        assert_eq!(exp_split(0.0, exp_entries(exp_index(0.0))), (0.0, 1.0));
    }
}
