//! x^q over a slice: the one transcendental pair (ln, exp) per trajectory sample, written so that
//! the compiler vectorises it.
//!
//! libm's `ln` and `exp` are calls with branches inside; over a slice they cost ~11 ns per
//! element here (`cargo bench --bench powerlaw -- baseline_pow_1000`), half of a 1000-sample
//! trajectory. The kernels below are straight-line arithmetic, so a loop over them runs in SIMD
//! lanes (2 with SSE2, 4 with AVX2, the latter chosen at run time by [`vectorised`]). They use no fused
//! multiply–add, so both paths round identically: the result does not depend on the machine.
//!
//! * ln x: x = 2^e·m with m ∈ [√½, √2), s = (m−1)/(m+1), ln m = 2 atanh s = 2s Σ_k s^{2k}/(2k+1);
//!   |s| ≤ 0.1716, so s² ≤ 0.0295 and thirteen terms leave < 1e−20. ln x = e·ln2 + ln m with ln 2
//!   split in two (e·ln2_hi exact). Error ≤ 2 ulp of |ln x| (tests below).
//! * exp y: y = k ln2 + r with k = round(y/ln2) (by the 1.5·2^52 shifter, which leaves k in the
//!   low bits: no float→int conversion), |r| ≤ ln2/2, e^r by its Taylor series to r^13
//!   (remainder < 5e−18), times 2^k built from its exponent bits. Error ≈ 1 ulp + |y|·ε (the
//!   rounding of y itself).
//! * Polynomials by Estrin's scheme ([`super::estrin`]): by Horner the loop is bound by the
//!   latency of its chain.
//! * Outside x ∈ [2^−1000, 2^1000] (zero, subnormal, huge, non-finite) the caller uses libm
//!   ([`in_kernel_range`]); inside, |q ln x| ≤ 694 stays in exp's kernel range for q ≤ 1.

/// ln 2 with its low 21 mantissa bits cleared, so that e·LN2_HI is exact for |e| < 2^21.
const LN2_HI: f64 = f64::from_bits(core::f64::consts::LN_2.to_bits() & !((1u64 << 21) - 1));
/// ln 2 − LN2_HI to double precision (from ln 2 to 60 digits, 0.693147180559945309417232121458…).
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
use super::estrin::estrin;

const LOG2_E: f64 = core::f64::consts::LOG2_E;
/// 1.5·2^52: adding it rounds to an integer and leaves that integer in the low mantissa bits.
const SHIFTER: f64 = 6_755_399_441_055_744.0;
/// 2^52, for the integer-to-float trick in ln.
const TWO52: f64 = 4_503_599_627_370_496.0;
/// Range of x handled by the kernels.
const X_MIN: f64 = 9.332_636_185_032_189e-302; // 2^−1000
const X_MAX: f64 = 1.071_508_607_186_267_3e301; // 2^1000

/// 1/(2k+1), k = 1..=12: the atanh series after its leading term.
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

/// 1/k!, k = 2..=13: the exp series after 1 + r.
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

/// ln x for normal x in [X_MIN, X_MAX]; branch-free.
#[inline(always)]
fn ln_kernel(x: f64) -> f64 {
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
    // m − 1 is exact (Sterbenz), and s carries one rounding.
    let f = m - 1.0;
    let s = f / (2.0 + f);
    // ln m = 2s + 2s·z·T(z): the small correction added last, to the leading 2s.
    let z = s * s;
    let two_s = 2.0 * s;
    let ln_m = two_s + two_s * (z * estrin(z, &ATANH_TAIL));
    e * LN2_HI + (e * LN2_LO + ln_m)
}

/// Largest |y| for [`exp_kernel`].
pub(crate) const EXP_KERNEL_MAX: f64 = 700.0;

/// e^y for |y| ≤ [`EXP_KERNEL_MAX`]; branch-free (about 1 ulp).
#[inline(always)]
pub(crate) fn exp_kernel(y: f64) -> f64 {
    let kf = (y * LOG2_E + SHIFTER) - SHIFTER;
    let r = (y - kf * LN2_HI) - kf * LN2_LO;
    // e^r = 1 + (r + r²·T(r)): the exact 1 added last.
    let p = 1.0 + (r + r * r * estrin(r, &EXP_TAIL));
    // k + 1023 sits in the low bits of kf + SHIFTER + 1023 (an integer below 2^52 in magnitude
    // offset): shift it into the exponent field.
    let biased = (kf + (SHIFTER + 1023.0))
        .to_bits()
        .wrapping_sub(SHIFTER.to_bits())
        << 52;
    p * f64::from_bits(biased)
}

/// x^q = exp(q ln x) for x in [2^−1000, 2^1000] and 0 < q ≤ 1 (see [`in_kernel_range`]);
/// straight-line code for loops that vectorise. Any other x gives a finite stand-in (1) for the
/// caller to replace.
#[inline(always)]
pub(crate) fn pow_kernel(x: f64, q: f64) -> f64 {
    let safe = if in_kernel_range(x) { x } else { 1.0 };
    exp_kernel(q * ln_kernel(safe))
}

/// Whether [`pow_kernel`] is exact to a few ulp at x (for any 0 < q ≤ 1: |q ln x| ≤ 694 then).
#[inline(always)]
pub(crate) fn in_kernel_range(x: f64) -> bool {
    (X_MIN..=X_MAX).contains(&x)
}

/// A loop to run under [`vectorised`]. Implementations mark `run` `#[inline(always)]`: only code
/// inlined into the AVX2 wrapper is compiled for AVX2 (a closure would stay a separate, SSE2
/// function).
pub(crate) trait SimdLoop {
    /// Runs the loop.
    fn run(self);
}

/// # Safety
/// The CPU must support AVX2 ([`vectorised`] checks it before the call).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn run_avx2<L: SimdLoop>(l: L) {
    l.run();
}

/// Runs `l` compiled for AVX2 when the CPU has it (4 lanes instead of SSE2's 2), else as is. No
/// fused multiply–add is enabled, so both compile to the same roundings: results do not depend
/// on the machine.
#[inline(always)]
pub(crate) fn vectorised<L: SimdLoop>(l: L) {
    #[cfg(all(target_arch = "x86_64", not(miri)))]
    {
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above), the only requirement of the
            // target_feature function.
            unsafe { run_avx2(l) };
            return;
        }
    }
    l.run();
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

    #[test]
    fn ln2_split() {
        assert_eq!(LN2_HI + LN2_LO, core::f64::consts::LN_2);
        assert_eq!(LN2_HI.to_bits() & ((1 << 21) - 1), 0);
        // The split carries ln 2 beyond double precision: ln 2 − LN_2 ≈ 2.3e−17.
        assert!(
            ((LN2_HI - core::f64::consts::LN_2) + LN2_LO - 2.319_046_813_846_3e-17).abs() < 1e-24
        );
        assert_eq!(X_MIN, 2f64.powi(-1000));
        assert_eq!(X_MAX, 2f64.powi(1000));
    }

    #[test]
    fn ln_within_two_ulp_of_its_magnitude() {
        let mut worst: f64 = 0.0;
        for x in samples(200_000, -300.0, 300.0)
            .chain(samples(50_000, -1e-3, 1e-3))
            .chain([1.0, 2.0, 0.5, X_MIN, X_MAX])
        {
            let (got, want) = (ln_kernel(x), x.ln());
            // Absolute error in units of ulp(|ln x|) (what exp(q ln x) inherits); exact at x = 1.
            let ulp = (want.abs().max(f64::MIN_POSITIVE)) * f64::EPSILON;
            let err = (got - want).abs() / ulp;
            worst = worst.max(err);
        }
        println!("ln kernel: worst {worst:.2} ulp(|ln x|)");
        assert!(worst <= 2.0, "{worst}");
        assert_eq!(ln_kernel(1.0), 0.0);
    }

    #[test]
    fn exp_within_one_ulp() {
        let mut worst: f64 = 0.0;
        for y in samples(100_000, -6.0, 2.845).flat_map(|a| [a, -a]).chain([
            0.0,
            700.0,
            -700.0,
            0.5 * core::f64::consts::LN_2,
        ]) {
            let (got, want) = (exp_kernel(y), y.exp());
            let err = ((got - want) / want).abs() / f64::EPSILON;
            worst = worst.max(err);
        }
        println!("exp kernel: worst {worst:.2} ulp");
        assert!(worst <= 1.5, "{worst}");
    }

    /// The kernel over a slice, as the trajectory uses it (libm outside its range).
    struct PowLoop<'a>(&'a [f64], f64, &'a mut [f64]);
    impl SimdLoop for PowLoop<'_> {
        #[inline(always)]
        fn run(self) {
            for (o, &x) in self.2.iter_mut().zip(self.0) {
                *o = pow_kernel(x, self.1);
            }
        }
    }

    fn pow_slice(xs: &[f64], q: f64, out: &mut [f64]) {
        vectorised(PowLoop(xs, q, &mut *out));
        for (o, &x) in out.iter_mut().zip(xs) {
            if !in_kernel_range(x) {
                *o = (q * x.ln()).exp();
            }
        }
    }

    #[test]
    fn pow_matches_powf() {
        let xs: Vec<f64> = samples(100_000, -320.0, 308.0)
            .chain([0.0, 5e-324, 1e-310, f64::MAX, f64::INFINITY])
            .collect();
        let mut out = vec![0.0; xs.len()];
        for &q in &[1.0, 0.8, 2.0 / 3.0, 0.5, 1.0 / 3.0, 0.01] {
            pow_slice(&xs, q, &mut out);
            let mut worst: f64 = 0.0;
            for (&x, &got) in xs.iter().zip(&out) {
                let want = x.powf(q);
                if want == 0.0 || want.is_infinite() {
                    assert_eq!(got, want, "x={x} q={q}");
                    continue;
                }
                // Both sides round q·ln x: |q ln x|·ε relative, plus a few ulp.
                let bound = (3.0 + 2.0 * (q * x.ln()).abs()) * f64::EPSILON;
                let err = ((got - want) / want).abs();
                assert!(
                    err <= bound,
                    "x={x} q={q}: {got} vs {want} ({:.1} ulp)",
                    err / f64::EPSILON
                );
                worst = worst.max(err / bound);
            }
            println!("pow q={q}: worst {worst:.2} of the bound");
        }
    }

    #[test]
    fn vectorised_and_plain_agree_bitwise() {
        let xs: Vec<f64> = samples(10_000, -300.0, 300.0).collect();
        let (mut a, mut b) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
        for (o, &x) in a.iter_mut().zip(&xs) {
            *o = pow_kernel(x, 0.8);
        }
        pow_slice(&xs, 0.8, &mut b);
        assert!(a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()));
    }
}
