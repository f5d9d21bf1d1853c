//! x^q to about one ulp for the per-contact force kernels: straight-line arithmetic (no libm, no
//! branch) so that a batch loop over it vectorises, and the same bits on every machine.
//!
//! [`super::pow`]'s kernel rounds q·ln x to a double, which costs |q ln x| ulp in x^q: up to
//! ~100 ulp for the overlaps of a DEM contact (ln δ ≈ −14…−40). Here ln x and q·ln x are carried
//! as unevaluated sums hi + lo (double-double) until the exponential's argument reduction, where
//! the lo part is added to the reduced argument r (|r| ≤ ln2/2), so the rounding of y = q ln x
//! costs nothing:
//!
//! * ln x = e·ln2 + 2 atanh s, s = f/(2+f), f = m − 1, m ∈ [√½, √2). s is computed as f·(1/(2+f))
//!   and then corrected by its exact residual f − s(2+f) (an error-free product), so 2s is known
//!   to ~2^−106 relative; the atanh tail 2s·z·T(z), z = s², is < 0.0034 and needs only its own
//!   rounding. e·LN2_HI is exact; the sum e·LN2_HI + 2s is an exact two-sum.
//! * y = q·ln x: an error-free product of q and hi, plus q·lo.
//! * e^y = 2^k e^r, r = (y_hi − k·LN2_HI) + (y_lo − k·LN2_LO): the first difference is exact
//!   (Sterbenz), so r carries one rounding of a number ≤ 0.35; e^r by its Taylor series to r^13.
//!
//! Measured error (tests below): ≤ 1 ulp against glibc's `pow` (itself < 1 ulp) for
//! x over the whole double range and q = 1e−9…10, independent of |q ln x| (subnormal results: within
//! one subnormal ulp).
//!
//! **Error-free products, FMA or not.** The exact error of a product a·b is `fma(a, b, −a·b)`
//! with fused multiply–add, or Dekker's split product without: both give the *same* (exact)
//! number, so the `FMA` flavour (used where the CPU has it) and the plain one return identical
//! bits. Everything else is plain multiplication and addition, never contracted in Rust.
//!
//! Range: every x ≥ 0 (subnormal x are prescaled by 2^54; 0 and +∞ selected exactly) and finite
//! q > 0, so no libm fallback and no branch: results that overflow give +∞, results below
//! 2^−1022 come out subnormal through one more rounding (within one subnormal ulp).

use super::estrin::estrin;

/// ln 2 with its low 21 mantissa bits cleared, so that k·LN2_HI is exact for |k| < 2^21.
const LN2_HI: f64 = f64::from_bits(core::f64::consts::LN_2.to_bits() & !((1u64 << 21) - 1));
/// ln 2 − LN2_HI to double precision (from ln 2 to 60 digits, 0.693147180559945309417232121458…).
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
const LOG2_E: f64 = core::f64::consts::LOG2_E;
/// 1.5·2^52: adding it rounds to an integer and leaves that integer in the low mantissa bits.
const SHIFTER: f64 = 6_755_399_441_055_744.0;
/// 2^52, for the integer-to-float trick in ln.
const TWO52: f64 = 4_503_599_627_370_496.0;
/// 2^27 + 1: Dekker's splitting constant for doubles.
const SPLITTER: f64 = 134_217_729.0;

/// 1/(2k+1), k = 1..=10: the atanh series after its leading term (z^11/23 · 2s < 2e−19).
const ATANH_TAIL: [f64; 10] = [
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
];

/// 1/k!, k = 2..=13: the exp series after 1 + r (remainder r^14/14! < 5e−18).
const EXP_TAIL: [f64; 12] = [
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
    1.0 / 362_880.0,
    1.0 / 3_628_800.0,
    1.0 / 39_916_800.0,
    1.0 / 479_001_600.0,
    1.0 / 6_227_020_800.0,
];

/// The rounding error of a·b (exact: a·b = fl(a·b) + err), given p = fl(a·b). With `FMA` one
/// fused multiply–add, else Dekker's product (exact for |a|, |b| < 2^995 and no underflow of the
/// error term — true for every product in this file).
#[inline(always)]
fn prod_err<const FMA: bool>(a: f64, b: f64, p: f64) -> f64 {
    if FMA {
        a.mul_add(b, -p)
    } else {
        let ca = SPLITTER * a;
        let ah = ca - (ca - a);
        let al = a - ah;
        let cb = SPLITTER * b;
        let bh = cb - (cb - b);
        let bl = b - bh;
        ((ah * bh - p) + ah * bl + al * bh) + al * bl
    }
}

/// 2^54, the prescale that makes a subnormal x normal.
const TWO54: f64 = 18_014_398_509_481_984.0;
/// |y| at which e^y is 0 or ∞ for sure (and the two-factor scale 2^k1·2^k2 stays representable).
const Y_CLAMP: f64 = 1400.0;

/// ln x as hi + lo for 0 < x < ∞ (subnormal x prescaled by 2^54); branch-free.
#[inline(always)]
fn ln_dd<const FMA: bool>(x: f64) -> (f64, f64) {
    let sub = x < f64::MIN_POSITIVE;
    let x = if sub { x * TWO54 } else { x };
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
    let e = if sub { e - 54.0 } else { e };
    // f = m − 1 exact (Sterbenz); u = 2 + f as uh + ul exactly (|f| < 2).
    let f = m - 1.0;
    let uh = 2.0 + f;
    let ul = f - (uh - 2.0);
    let inv = 1.0 / uh;
    let s = f * inv;
    // Residual f − s·u: f − s·uh is exact (s·uh ≈ f), its product error exact, s·ul tiny.
    let p = s * uh;
    let res = ((f - p) - prod_err::<FMA>(s, uh, p)) - s * ul;
    let s_lo = res * inv;
    let z = s * s;
    let two_s = 2.0 * s;
    let tail = 2.0 * s_lo + two_s * (z * estrin(z, &ATANH_TAIL));
    // e·LN2_HI exact; two-sum with 2s, then everything small.
    let a = e * LN2_HI;
    let hi = a + two_s;
    let bb = hi - a;
    let err = (a - (hi - bb)) + (two_s - bb);
    (hi, err + (e * LN2_LO + tail))
}

/// 2^k for an integer-valued k in [−1022, 1023], from its exponent bits.
#[inline(always)]
fn exp2i(kf: f64) -> f64 {
    let biased = (kf + (SHIFTER + 1023.0))
        .to_bits()
        .wrapping_sub(SHIFTER.to_bits())
        << 52;
    f64::from_bits(biased)
}

/// e^(yh + yl) for |yh| ≤ Y_CLAMP, |yl| ≤ ulp(yh); branch-free. 2^k is applied as two factors so
/// that results that overflow or underflow (also gradually) come out as IEEE arithmetic does.
#[inline(always)]
fn exp_dd(yh: f64, yl: f64) -> f64 {
    let kf = (yh * LOG2_E + SHIFTER) - SHIFTER;
    // yh − k·LN2_HI is exact (k·LN2_HI exact; Sterbenz); the small rest joins yl.
    let r = (yh - kf * LN2_HI) + (yl - kf * LN2_LO);
    let p = 1.0 + (r + r * r * estrin(r, &EXP_TAIL));
    let k1 = (0.5 * kf + SHIFTER) - SHIFTER;
    let k2 = kf - k1;
    (p * exp2i(k1)) * exp2i(k2)
}

/// x^q for x ≥ 0 (including subnormal x and +∞) and finite q > 0: straight-line code, no libm.
/// Negative or NaN x give an unspecified finite number (the force kernels mask them).
#[inline(always)]
pub(crate) fn pow_dd<const FMA: bool>(x: f64, q: f64) -> f64 {
    let pos = x > 0.0 && x < f64::INFINITY;
    let safe = if pos { x } else { 1.0 };
    let (lh, ll) = ln_dd::<FMA>(safe);
    let yh = q * lh;
    let yl = prod_err::<FMA>(q, lh, yh) + q * ll;
    let big = yh.abs() > Y_CLAMP;
    let v = exp_dd(
        if big { Y_CLAMP.copysign(yh) } else { yh },
        if big { 0.0 } else { yl },
    );
    if x == 0.0 {
        0.0
    } else if x == f64::INFINITY {
        f64::INFINITY
    } else {
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic log-uniform samples over [10^lo, 10^hi].
    fn samples(n: usize, lo: f64, hi: f64) -> impl Iterator<Item = f64> {
        let mut s: u64 = 0x9e37_79b9_7f4a_7c15;
        (0..n).map(move |_| {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let u = (s >> 11) as f64 / (1u64 << 53) as f64;
            10f64.powf(lo + (hi - lo) * u)
        })
    }

    /// |got − want| in units of the spacing of doubles at want (the subnormal spacing 2^−1074
    /// below 2^−1022).
    fn ulps(got: f64, want: f64) -> f64 {
        if got == want {
            return 0.0;
        }
        let e = want.abs().log2().floor().max(-1022.0);
        (got - want).abs() / 2f64.powf(e - 52.0)
    }

    #[test]
    fn constants() {
        assert_eq!(LN2_HI + LN2_LO, core::f64::consts::LN_2);
        assert_eq!(SPLITTER, 2f64.powi(27) + 1.0);
        assert_eq!(TWO54, 2f64.powi(54));
        // Y_CLAMP: e^±1400 is beyond the double range, and 2^k1, 2^k2 stay normal.
        assert!(Y_CLAMP * LOG2_E / 2.0 + 1.0 < 1022.0 && (-Y_CLAMP).exp() == 0.0);
    }

    /// The overlap range of DEM contacts (1e−15…1 m), the whole double range (subnormal x
    /// included) for the exponents (p−1)/2 of p = 1…21, against glibc's pow (< 1 ulp itself):
    /// the kernel stays within 1 ulp of it.
    #[test]
    fn within_one_ulp_of_libm() {
        let mut worst: f64 = 0.0;
        let mut n = 0usize;
        for &q in &[1e-9, 0.05, 0.25, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.3, 10.0] {
            for x in samples(100_000, -323.0, 308.0)
                .chain(samples(200_000, -15.0, 0.0))
                .chain([
                    1.0,
                    2.0,
                    0.5,
                    f64::MIN_POSITIVE,
                    5e-324,
                    f64::MAX,
                    1.0 + f64::EPSILON,
                    1.0 - 1e-16,
                ])
            {
                let (got, want) = (pow_dd::<false>(x, q), x.powf(q));
                let u = ulps(got, want);
                assert!(u <= 1.0, "x={x:e} q={q}: {got:e} vs {want:e} ({u} ulp)");
                worst = worst.max(u);
                n += 1;
            }
        }
        println!("pow_dd: worst {worst} ulp against libm over {n} points");
        assert_eq!(pow_dd::<false>(1.0, 0.7), 1.0);
        assert_eq!(pow_dd::<false>(0.0, 0.7), 0.0);
        assert_eq!(pow_dd::<false>(f64::INFINITY, 0.7), f64::INFINITY);
        assert_eq!(pow_dd::<false>(1e-300, 10.0), 0.0);
        assert_eq!(pow_dd::<false>(1e300, 10.0), f64::INFINITY);
    }

    #[test]
    fn fma_and_plain_flavours_agree_bitwise() {
        for &q in &[0.35, 1.0, 4.5] {
            for x in samples(50_000, -323.0, 308.0) {
                let (a, b) = (pow_dd::<false>(x, q), pow_dd::<true>(x, q));
                assert_eq!(a.to_bits(), b.to_bits(), "x={x:e} q={q}");
            }
        }
    }
}
