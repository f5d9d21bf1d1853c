//! x^q to about one ulp for the per-contact force kernels (δ^((p−1)/2) of the general-p law):
//! straight-line arithmetic (no libm, no branch) so that a batch loop over it vectorises, and the
//! same bits on every machine and in the C header (include/demcontact_inline.h).
//!
//! [`super::pow`]'s kernel computes e^(q ln x) with q·ln x rounded to a double, which costs
//! |q ln x| ulp in x^q: up to ~100 ulp for DEM overlaps (ln δ ≈ −14…−40). Here the large part of
//! q ln x never exists as a rounded double. With x = 2^e·z, z ∈ [0.6797, 1.3594):
//!
//! * x^q = 2^(q e) · z^q, and q·e is split exactly into P + Q (q cut into its high 26 and low 27
//!   bits; e has at most 11 bits, so both products are exact). With n = round(P) (P − n exact),
//!   x^q = 2^n · e^t, t = (P − n + Q)·ln 2 + q·ln z: |t| ≤ ln2/2 + 0.39 q, so its rounding costs
//!   about one ulp whatever |q ln x| is.
//! * ln z and e^t = 2^k·p by [`super::pow_table`]'s table-driven reductions (32-entry tables,
//!   series of 9 and 6 terms, no division); 2^(n+k) applied as two factors so that overflow
//!   gives ∞ and underflow a (gradually) subnormal or zero result, as IEEE arithmetic does.
//! * Plain multiplication and addition only, never contracted in Rust, so the result does not
//!   depend on the CPU: the batch's SSE2 flavour (table reads in their own loops,
//!   `force::batch`), its AVX2 kernel ([`super::pow_avx2`], gathers) and its AVX-512 kernel
//!   ([`super::pow_avx512`], tables in registers) give the same bits as this scalar function and
//!   the C header's `dc_pow_inline`.
//!
//! Measured error (tests below): ≤ 2 ulp against glibc's `pow` (itself < 1 ulp) over the whole
//! double range of x (subnormal x included) for q = 1e−9…2 (p ≤ 5), ≤ 1 + q ulp for larger q
//! (the rounding of q·ln z); subnormal results within one subnormal ulp. Range: every x ≥ 0 (0
//! and +∞ selected exactly) and finite q > 0 up to ~10^13 (the range of the 1.5·2^52 shifter).

use super::pow_table::{exp_entries, exp_index, exp_split, ln_entries, ln_index, ln_split};
use super::reduce::exp2i;

/// 1.5·2^52: adding it rounds to an integer.
const SHIFTER: f64 = super::reduce::SHIFTER;
/// 2^54, the prescale that makes a subnormal x normal.
pub(crate) const TWO54: f64 = 18_014_398_509_481_984.0;
/// |n + k| beyond which 2^(n+k)·p (1/2 < p < 2) is 0 or ∞ for sure; the two factors 2^k1, 2^k2
/// of the scale stay normal numbers.
pub(crate) const K_CLAMP: f64 = 2044.0;

/// x prepared for [`ln_split`]: a normal positive number (subnormal x times 2^54, and 1 in
/// place of 0, +∞, negative or NaN x), and whether it was prescaled.
#[inline(always)]
fn normal(x: f64) -> (f64, bool) {
    let pos = x > 0.0 && x < f64::INFINITY;
    let safe = if pos { x } else { 1.0 };
    let sub = safe < f64::MIN_POSITIVE;
    (if sub { safe * TWO54 } else { safe }, sub)
}

/// The ln table index of x (for a batch's table-reading loop; see [`pow_ln`]).
#[inline(always)]
pub(crate) fn pow_ln_index(x: f64) -> u64 {
    ln_index(normal(x).0)
}

/// First half of [`pow_dd`]: x^q = 2^n · e^t, (n, t), given x's ln table entries.
#[inline(always)]
pub(crate) fn pow_ln(x: f64, q: f64, entries: (f64, f64)) -> (f64, f64) {
    // x = 2^e · z, z ∈ [0.6797, 1.3594), and ln z; subnormal x prescaled by 2^54.
    let (xn, sub) = normal(x);
    let (e, ln_z) = ln_split(xn, entries);
    let e = if sub { e - 54.0 } else { e };
    // q·e exactly, as P + Q: q split into 26 high and 27 low bits, e has at most 11 bits.
    let qh = f64::from_bits(q.to_bits() & !((1u64 << 27) - 1));
    let ql = q - qh;
    let big_p = qh * e;
    let small_q = ql * e;
    // n = round(P) (|P| < 2^51); P − n is exact, so x^q = 2^n · e^t with |t| ≲ ln2/2 + q·0.39.
    let n = (big_p + SHIFTER) - SHIFTER;
    let frac = (big_p - n) + small_q;
    (n, frac * core::f64::consts::LN_2 + q * ln_z)
}

/// Second half of [`pow_dd`]: 2^n · e^t given t's exp table entries, and the exact results
/// at x = 0 and +∞.
#[inline(always)]
pub(crate) fn pow_exp(x: f64, n: f64, t: f64, entries: (f64, f64)) -> f64 {
    // e^t = 2^k · p.
    let (kf, p) = exp_split(t, entries);
    // 2^(n + k) as two factors, clamped where the result is 0 or ∞ anyway (p < 2).
    let total = n + kf;
    let total = total.clamp(-K_CLAMP, K_CLAMP);
    let k1 = (0.5 * total + SHIFTER) - SHIFTER;
    let v = (p * exp2i(k1)) * exp2i(total - k1);
    if x == 0.0 {
        0.0
    } else if x == f64::INFINITY {
        f64::INFINITY
    } else {
        v
    }
}

/// x^q for x ≥ 0 (including subnormal x and +∞) and finite q > 0: straight-line code, no libm.
/// Negative or NaN x give an unspecified finite number (the force kernels mask them).
#[inline(always)]
pub(crate) fn pow_dd(x: f64, q: f64) -> f64 {
    let (n, t) = pow_ln(x, q, ln_entries(pow_ln_index(x)));
    pow_exp(x, n, t, exp_entries(exp_index(t)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::ulps;

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

    #[test]
    fn constants() {
        assert_eq!(TWO54, 2f64.powi(54));
        // 2^±2044 · p is 0 / ∞ for p in (1/2, 2), and each half 2^±1022 is a normal number.
        assert_eq!(2f64.powi(-1022) * 2f64.powi(-1022) * 1.99, 0.0);
        assert_eq!(2f64.powi(1022) * 2f64.powi(1022) * 0.51, f64::INFINITY);
        assert_eq!(exp2i(-1022.0), f64::MIN_POSITIVE);
        assert_eq!(exp2i(1023.0), 2f64.powi(1023));
    }

    /// The overlap range of DEM contacts (1e−15…1 m) and the whole double range (subnormal x
    /// included) for the exponents (p−1)/2 of p = 1…21, against glibc's pow (< 1 ulp itself):
    /// within 2 ulp of it for q ≤ 2 (p ≤ 5), 1 + q ulp beyond (measured maxima printed).
    #[test]
    fn within_two_ulp_of_libm() {
        let mut worst: f64 = 0.0;
        let mut n = 0usize;
        for &q in &[1e-9, 0.05, 0.25, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.3, 10.0] {
            let mut worst_q: f64 = 0.0;
            for x in samples(100_000, -323.0, 308.0)
                .chain(samples(300_000, -15.0, 0.0))
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
                let (got, want) = (pow_dd(x, q), x.powf(q));
                let u = ulps(got, want);
                // The rounding of q·ln m grows with q: 2 ulp up to q = 2 (p = 5), 1 + q beyond.
                let bound = if q <= 2.0 { 2.0 } else { 1.0 + q };
                assert!(u <= bound, "x={x:e} q={q}: {got:e} vs {want:e} ({u} ulp)");
                worst_q = worst_q.max(u);
                n += 1;
            }
            println!("pow_dd q={q}: worst {worst_q} ulp");
            worst = worst.max(worst_q);
        }
        println!("pow_dd: worst {worst} ulp against libm over {n} points");
        assert_eq!(pow_dd(1.0, 0.7), 1.0);
        assert_eq!(pow_dd(0.0, 0.7), 0.0);
        assert_eq!(pow_dd(f64::INFINITY, 0.7), f64::INFINITY);
        assert_eq!(pow_dd(1e-300, 10.0), 0.0);
        assert_eq!(pow_dd(1e300, 10.0), f64::INFINITY);
        assert_eq!(pow_dd(4.0, 0.5), 2.0);
    }
}
