//! [`super::pow_fast`] for four lanes with AVX2 + FMA: the same operations lane for lane (the
//! fused multiply–adds as `vfmadd`, each rounding once like `f64::mul_add`), so the same bits as
//! [`FastPow::pow`]. The four 16-entry tables are read by memory gathers (`vgatherqpd`; AVX2 has
//! no in-register permute over 16 doubles), with the indices masked to 0..15.

use super::pow_fast::{DEGREE, E_MIN, E_SPAN, FastPow};
use core::arch::x86_64::*;

/// Entry `i & 15` per lane.
#[target_feature(enable = "avx2")]
#[inline]
fn gather(t: &[f64; 16], i: __m256i) -> __m256d {
    let i = _mm256_and_si256(i, _mm256_set1_epi64x(15));
    // SAFETY: every index is in 0..16 (masked just above) and `t` has 16 entries.
    unsafe { _mm256_i64gather_pd::<8>(t.as_ptr(), i) }
}

/// x^q of four lanes by the table path, and whether a lane needs the exact power (positive x
/// outside the table range). Lanes with x ≤ 0 or NaN get some finite number.
#[target_feature(enable = "avx2,fma")]
#[inline]
fn pow_x4(x: __m256d, t: &FastPow, binom: &[__m256d; DEGREE + 1]) -> (__m256d, bool) {
    let bits = _mm256_castpd_si256(x);
    // Unsigned bits − E_MIN·2^52 < E_SPAN·2^52, by the signed compare of both sides offset by 2^63.
    let flip = _mm256_set1_epi64x(i64::MIN);
    let off = _mm256_xor_si256(
        _mm256_sub_epi64(bits, _mm256_set1_epi64x((E_MIN << 52) as i64)),
        flip,
    );
    let in_range = _mm256_cmpgt_epi64(_mm256_set1_epi64x(((E_SPAN << 52) as i64) ^ i64::MIN), off);
    let positive = _mm256_castpd_si256(_mm256_cmp_pd::<_CMP_GT_OQ>(x, _mm256_setzero_pd()));
    let slow =
        _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_andnot_si256(in_range, positive))) != 0;
    let m = _mm256_or_si256(
        _mm256_and_si256(bits, _mm256_set1_epi64x((1 << 52) - 1)),
        _mm256_set1_epi64x(1.0f64.to_bits() as i64),
    );
    let m = _mm256_castsi256_pd(m);
    let i = _mm256_srli_epi64::<48>(bits);
    let r = _mm256_fmadd_pd(m, gather(&t.inv_c, i), _mm256_set1_pd(-1.0));
    let mut p = binom[DEGREE];
    for b in binom[..DEGREE].iter().rev() {
        p = _mm256_fmadd_pd(p, r, *b);
    }
    let mq = _mm256_mul_pd(p, gather(&t.c_q, i));
    let scale = _mm256_mul_pd(
        gather(&t.scale_b, _mm256_srli_epi64::<52>(bits)),
        gather(&t.scale_a, _mm256_srli_epi64::<56>(bits)),
    );
    (_mm256_mul_pd(scale, mq), slow)
}

/// `out[i] = x[i]^q` by [`FastPow::pow`], bit for bit where x[i] > 0 (elsewhere some finite
/// number; the batch's force is zero there), as many as the shorter slice.
#[target_feature(enable = "avx2,fma")]
#[inline]
pub(crate) fn pow_fast_slice_x4(x: &[f64], t: &FastPow, out: &mut [f64]) {
    let n = out.len().min(x.len());
    let (x, out) = (
        x.get(..n).unwrap_or(&[]),
        out.get_mut(..n).unwrap_or(&mut []),
    );
    let binom = t.binom.map(|b| _mm256_set1_pd(b));
    // Two groups of four lanes per step: two independent chains, which the core overlaps.
    let mut xs = x.chunks_exact(8);
    let mut os = out.chunks_exact_mut(8);
    for (xc, oc) in (&mut xs).zip(&mut os) {
        // SAFETY: both chunks are eight doubles.
        let (v0, v1) = unsafe {
            (
                _mm256_loadu_pd(xc.as_ptr()),
                _mm256_loadu_pd(xc.as_ptr().add(4)),
            )
        };
        let (s0, slow0) = pow_x4(v0, t, &binom);
        let (s1, slow1) = pow_x4(v1, t, &binom);
        // SAFETY: as above.
        unsafe {
            _mm256_storeu_pd(oc.as_mut_ptr(), s0);
            _mm256_storeu_pd(oc.as_mut_ptr().add(4), s1);
        }
        if slow0 || slow1 {
            t.exact_lanes(xc, oc);
        }
    }
    for (o, &x) in os.into_remainder().iter_mut().zip(xs.remainder()) {
        *o = t.pow(x);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernel against the scalar function, bit for bit where x > 0, over random bit
    /// patterns, log-uniform overlaps and the range's ends.
    #[test]
    fn same_bits_as_the_scalar_function() {
        if !(std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")) {
            println!("skipped: no AVX2 + FMA on this CPU");
            return;
        }
        let x = crate::numerics::pow_fast::tests::samples();
        for q in [0.35, 1e-9, 0.25, 1.0, 2.0, 3.7, 4.0] {
            let t = FastPow::new(q).unwrap();
            let mut out = vec![0.0; x.len()];
            // SAFETY: the CPU has AVX2 and FMA (checked above).
            unsafe { pow_fast_slice_x4(&x, &t, &mut out) };
            let bad = x
                .iter()
                .zip(&out)
                .filter(|&(&x, &o)| x > 0.0 && o.to_bits() != t.pow(x).to_bits())
                .count();
            assert_eq!(bad, 0, "q = {q}: {bad} of {} differ", x.len());
        }
    }
}
