//! The range reductions and series of ln and exp of the trajectory's branch-free power kernel
//! ([`super::pow`]); the force kernels' δ^h ([`super::pow_dd`], table-driven:
//! [`super::pow_table`]) shares [`exp2i`] and the constants. Plain multiplication and addition only: Rust never contracts them into
//! fused multiply–adds, so the result does not depend on the CPU flavour a loop is compiled for.
//!
//! * ln: x = 2^e·m with m ∈ [√½, √2) ([`split`]); ln m = 2 atanh s, s = (m−1)/(m+1),
//!   |s| ≤ 0.1716: 2s + 2s·z·T(z), z = s² ([`ln_reduced`], the caller chooses the length of T).
//! * exp: y = k ln2 + r, k = round(y/ln2) by the 1.5·2^52 shifter (no float→int conversion),
//!   r = (y − k·LN2_HI) − k·LN2_LO with the first product exact (LN2_HI has 21 trailing zero
//!   bits) and the difference exact (Sterbenz), |r| ≤ ln2/2; e^r by its Taylor series to r^13
//!   (remainder < 5e−18) ([`exp_reduced`]); 2^k from its exponent bits ([`exp2i`]).
//! * Polynomials by Estrin's scheme ([`super::estrin`]).

use super::estrin::estrin;

/// ln 2 with its low 21 mantissa bits cleared, so that k·LN2_HI is exact for |k| < 2^21.
pub(crate) const LN2_HI: f64 =
    f64::from_bits(core::f64::consts::LN_2.to_bits() & !((1u64 << 21) - 1));
/// ln 2 − LN2_HI to double precision (from ln 2 to 60 digits, 0.693147180559945309417232121458…).
pub(crate) const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
const LOG2_E: f64 = core::f64::consts::LOG2_E;
/// 1.5·2^52: adding it rounds to an integer and leaves that integer in the low mantissa bits.
pub(crate) const SHIFTER: f64 = 6_755_399_441_055_744.0;
/// 2^52, for the integer-to-float trick in [`split`].
const TWO52: f64 = 4_503_599_627_370_496.0;

/// Σ_{k<12} x^k/(k+2)!: the exp series after 1 + r (remainder r^14/14! < 5e−18), by Estrin's
/// scheme written out: the same expression tree as [`estrin`] over 1/2!, …, 1/13! (so the
/// trajectory kernel keeps its bits), and straight-line code, which the batch loops need (LLVM
/// vectorises a loop only once every inner loop is gone; a generic polynomial loop is not always
/// unrolled first). The C header has the same tree.
#[inline(always)]
fn exp_tail(x: f64) -> f64 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let b0 = 1.0 / 2.0 + (1.0 / 6.0) * x;
    let b1 = 1.0 / 24.0 + (1.0 / 120.0) * x;
    let b2 = 1.0 / 720.0 + (1.0 / 5040.0) * x;
    let b3 = 1.0 / 40320.0 + (1.0 / 362_880.0) * x;
    let b4 = 1.0 / 3_628_800.0 + (1.0 / 39_916_800.0) * x;
    let b5 = 1.0 / 479_001_600.0 + (1.0 / 6_227_020_800.0) * x;
    let c0 = b0 + b1 * x2;
    let c1 = b2 + b3 * x2;
    let c2 = b4 + b5 * x2;
    (c0 + c1 * x4) + c2 * x8
}

/// Σ_{k<12} x^k/(2k+3) for the trajectory kernel ([`super::pow`]), by [`estrin`].
#[inline(always)]
pub(crate) fn atanh_tail12(x: f64) -> f64 {
    estrin(x, &ATANH_TAIL)
}

/// 1/(2k+1), k = 1..=12: the atanh series after its leading term (the first N are used).
const ATANH_TAIL: [f64; 12] = [
    1.0 / 3.0,
    1.0 / 5.0,
    1.0 / 7.0,
    1.0 / 9.0,
    1.0 / 11.0,
    1.0 / 13.0,
    1.0 / 15.0,
    1.0 / 17.0,
    1.0 / 19.0,
    1.0 / 21.0,
    1.0 / 23.0,
    1.0 / 25.0,
];

/// x = 2^e·m for a normal x > 0: (e as a float, m ∈ [√½, √2)). Branch-free (selects).
#[inline(always)]
pub(crate) fn split(x: f64) -> (f64, f64) {
    let bits = x.to_bits();
    // Biased exponent as a float via the 2^52 trick (no int→float conversion instruction).
    let e_biased = f64::from_bits(0x4330_0000_0000_0000 | (bits >> 52)) - TWO52;
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let big = m > core::f64::consts::SQRT_2;
    let m = if big { 0.5 * m } else { m };
    let e = if big {
        e_biased - 1022.0
    } else {
        e_biased - 1023.0
    };
    (e, m)
}

/// ln m for m ∈ [√½, √2) with the atanh series' tail `tail` ([`atanh_tail12`]).
#[inline(always)]
pub(crate) fn ln_reduced(m: f64, tail: impl Fn(f64) -> f64) -> f64 {
    // m − 1 is exact (Sterbenz), and s carries one rounding.
    let f = m - 1.0;
    let s = f / (2.0 + f);
    // ln m = 2s + 2s·z·T(z): the small correction added last, to the leading 2s.
    let z = s * s;
    let two_s = 2.0 * s;
    two_s + two_s * (z * tail(z))
}

/// e^y = 2^k · p for |y| ≤ 1000: (k as an integer-valued float, p ∈ (1/√2, √2)).
#[inline(always)]
pub(crate) fn exp_reduced(y: f64) -> (f64, f64) {
    let kf = (y * LOG2_E + SHIFTER) - SHIFTER;
    let r = (y - kf * LN2_HI) - kf * LN2_LO;
    // e^r = 1 + (r + r²·T(r)): the exact 1 added last.
    (kf, 1.0 + (r + r * r * exp_tail(r)))
}

/// 2^k for an integer-valued k in [−1022, 1023], from its exponent bits (k + 1023 sits in the
/// low bits of k + SHIFTER + 1023).
#[inline(always)]
pub(crate) fn exp2i(kf: f64) -> f64 {
    let biased = (kf + (SHIFTER + 1023.0))
        .to_bits()
        .wrapping_sub(SHIFTER.to_bits())
        << 52;
    f64::from_bits(biased)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_and_pieces() {
        assert_eq!(LN2_HI + LN2_LO, core::f64::consts::LN_2);
        assert_eq!(LN2_HI.to_bits() & ((1 << 21) - 1), 0);
        // The split carries ln 2 beyond double precision: ln 2 − LN_2 ≈ 2.3e−17.
        assert!(
            ((LN2_HI - core::f64::consts::LN_2) + LN2_LO - 2.319_046_813_846_3e-17).abs() < 1e-24
        );
        assert_eq!(SHIFTER, 1.5 * 2f64.powi(52));
        assert_eq!(exp2i(-1022.0), f64::MIN_POSITIVE);
        assert_eq!(exp2i(1023.0), 2f64.powi(1023));
        assert_eq!(exp2i(0.0), 1.0);
        for (x, e, m) in [
            (1.0, 0.0, 1.0),
            (1.5, 1.0, 0.75),
            (0.75, 0.0, 0.75),
            (0.7, -1.0, 1.4),
            (8.0, 3.0, 1.0),
        ] {
            assert_eq!(split(x), (e, m), "{x}");
        }
        assert_eq!(ln_reduced(1.0, atanh_tail12), 0.0);
        // The written-out series are the generic Estrin evaluation, bit for bit.
        for i in 0..=1000 {
            let x = -0.35 + 0.7 * i as f64 / 1000.0;
            let coef: [f64; 12] =
                core::array::from_fn(|k| 1.0 / (2..=k + 2).map(|j| j as f64).product::<f64>());
            assert_eq!(exp_tail(x).to_bits(), estrin(x, &coef).to_bits(), "{x}");
        }
        // Against libm's ln and exp (independent): within 1.5e−16 over the reduced ranges.
        for i in 0..=1000 {
            let m = core::f64::consts::FRAC_1_SQRT_2
                + (core::f64::consts::SQRT_2 - core::f64::consts::FRAC_1_SQRT_2) * i as f64
                    / 1001.0;
            assert!(
                (ln_reduced(m, atanh_tail12) - m.ln()).abs() < 1.2e-16,
                "{m}"
            );
            let y = -700.0 + 1400.0 * i as f64 / 1000.0;
            let (k, p) = exp_reduced(y);
            assert!((p * exp2i(k) / y.exp() - 1.0).abs() < 3e-16, "{y}");
        }
    }
}
