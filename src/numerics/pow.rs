//! x^q over a slice: the one transcendental pair (ln, exp) per trajectory sample, written so that
//! the compiler vectorises it.
//!
//! libm's `ln` and `exp` are calls with branches inside; over a slice they cost ~11 ns per
//! element here (`cargo bench --bench powerlaw -- baseline_pow_1000`), half of a 1000-sample
//! trajectory. The kernels below are straight-line arithmetic, so a loop over them runs in SIMD
//! lanes (2 with SSE2, 4 with AVX2, 8 with AVX-512, chosen at run time by [`super::simd`]). No
//! fused multiply–add is ever formed, so every path rounds identically: the result does not depend
//! on the machine.
//!
//! * ln x = e·ln2 + ln m, x = 2^e·m, ln m by the atanh series with thirteen terms (< 1e−20);
//!   error ≤ 2 ulp of |ln x| (tests below).
//! * exp y = 2^k e^r, e^r by its Taylor series to r^13; error ≈ 1 ulp + |y|·ε (the rounding of y
//!   itself).
//! * The reductions and series are [`super::reduce`]'s, shared with [`super::pow_dd`].
//! * Outside x ∈ [2^−1000, 2^1000] (zero, subnormal, huge, non-finite) the caller uses libm
//!   ([`in_kernel_range`]); inside, |q ln x| ≤ 694 stays in exp's kernel range for q ≤ 1.

use super::reduce::{LN2_HI, LN2_LO, atanh_tail12, exp_reduced, exp2i, ln_reduced, split};

/// Range of x handled by the kernels.
const X_MIN: f64 = 9.332_636_185_032_189e-302; // 2^−1000
const X_MAX: f64 = 1.071_508_607_186_267_3e301; // 2^1000

/// ln x for normal x in [X_MIN, X_MAX]; branch-free. ln x = e·ln2 + ln m with ln 2 split in two
/// (e·LN2_HI exact).
#[inline(always)]
fn ln_kernel(x: f64) -> f64 {
    let (e, m) = split(x);
    e * LN2_HI + (e * LN2_LO + ln_reduced(m, atanh_tail12))
}

/// Largest |y| for [`exp_kernel`].
pub(crate) const EXP_KERNEL_MAX: f64 = 700.0;

/// e^y for |y| ≤ [`EXP_KERNEL_MAX`]; branch-free (about 1 ulp).
#[inline(always)]
pub(crate) fn exp_kernel(y: f64) -> f64 {
    let (kf, p) = exp_reduced(y);
    p * exp2i(kf)
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

pub(crate) use super::simd::{SimdLoop, vectorised};

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
    fn kernel_range() {
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
