//! [`super::pow_fast`] for eight lanes with AVX-512F: the same operations lane for lane (the
//! fused multiply–adds as `vfmadd`, each rounding once like `f64::mul_add`), so the same bits
//! as [`FastPow::pow`]. The four 16-entry tables sit in registers and are read by one
//! in-register permute each (`vpermt2pd`, which reads only an index's low four bits: the
//! indices are x's bits shifted, never masked).

use super::pow_fast::{DEGREE, E_MIN, E_SPAN, FastPow};
use core::arch::x86_64::*;

/// A 16-entry table in two registers.
#[derive(Clone, Copy)]
struct Table16(__m512d, __m512d);

impl Table16 {
    #[target_feature(enable = "avx512f")]
    fn load(t: &[f64; 16]) -> Self {
        let (lo, hi) = t.split_at(8);
        // SAFETY: both halves are eight readable doubles.
        unsafe { Self(_mm512_loadu_pd(lo.as_ptr()), _mm512_loadu_pd(hi.as_ptr())) }
    }

    /// Entry `i mod 16` per lane.
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn get(&self, i: __m512i) -> __m512d {
        _mm512_permutex2var_pd(self.0, i, self.1)
    }
}

/// The tables of one [`FastPow`] in registers.
#[derive(Clone, Copy)]
pub(crate) struct Tables {
    scale_a: Table16,
    scale_b: Table16,
    inv_c: Table16,
    c_q: Table16,
    binom: [__m512d; DEGREE + 1],
}

impl Tables {
    /// Loads `t` into registers.
    #[target_feature(enable = "avx512f")]
    pub(crate) fn load(t: &FastPow) -> Self {
        Self {
            scale_a: Table16::load(&t.scale_a),
            scale_b: Table16::load(&t.scale_b),
            inv_c: Table16::load(&t.inv_c),
            c_q: Table16::load(&t.c_q),
            binom: t.binom.map(|b| _mm512_set1_pd(b)),
        }
    }
}

/// x^q of eight lanes by the table path, and the lanes that need the exact power (positive x
/// outside the table range). Lanes with x ≤ 0 or NaN get some finite number.
#[target_feature(enable = "avx512f,fma")]
#[inline]
fn pow_x8(x: __m512d, t: &Tables) -> (__m512d, __mmask8) {
    let bits = _mm512_castpd_si512(x);
    let in_range = _mm512_cmplt_epu64_mask(
        _mm512_sub_epi64(bits, _mm512_set1_epi64((E_MIN << 52) as i64)),
        _mm512_set1_epi64((E_SPAN << 52) as i64),
    );
    let positive = _mm512_cmp_pd_mask::<_CMP_GT_OQ>(x, _mm512_setzero_pd());
    let m = _mm512_or_si512(
        _mm512_and_si512(bits, _mm512_set1_epi64((1 << 52) - 1)),
        _mm512_set1_epi64(1.0f64.to_bits() as i64),
    );
    let m = _mm512_castsi512_pd(m);
    let i = _mm512_srli_epi64::<48>(bits);
    let r = _mm512_fmadd_pd(m, t.inv_c.get(i), _mm512_set1_pd(-1.0));
    let mut p = t.binom[DEGREE];
    for b in t.binom[..DEGREE].iter().rev() {
        p = _mm512_fmadd_pd(p, r, *b);
    }
    let mq = _mm512_mul_pd(p, t.c_q.get(i));
    let scale = _mm512_mul_pd(
        t.scale_b.get(_mm512_srli_epi64::<52>(bits)),
        t.scale_a.get(_mm512_srli_epi64::<56>(bits)),
    );
    let s = _mm512_mul_pd(scale, mq);
    (s, positive & !in_range)
}

/// `out[i] = x[i]^q` by [`FastPow::pow`], bit for bit where x[i] > 0 (elsewhere some finite
/// number; the batch's force is zero there), as many as the shorter slice.
#[target_feature(enable = "avx512f,fma")]
#[inline]
pub(crate) fn pow_fast_slice_x8(x: &[f64], t: &Tables, fallback: &FastPow, out: &mut [f64]) {
    let n = out.len().min(x.len());
    let (x, out) = (
        x.get(..n).unwrap_or(&[]),
        out.get_mut(..n).unwrap_or(&mut []),
    );
    // Two groups of eight lanes per step: two independent chains of fused multiply–adds,
    // which the core overlaps (one chain is latency-bound).
    let mut xs = x.chunks_exact(16);
    let mut os = out.chunks_exact_mut(16);
    for (xc, oc) in (&mut xs).zip(&mut os) {
        // SAFETY: both chunks are sixteen doubles.
        let (v0, v1) = unsafe {
            (
                _mm512_loadu_pd(xc.as_ptr()),
                _mm512_loadu_pd(xc.as_ptr().add(8)),
            )
        };
        let (s0, slow0) = pow_x8(v0, t);
        let (s1, slow1) = pow_x8(v1, t);
        // SAFETY: as above.
        unsafe {
            _mm512_storeu_pd(oc.as_mut_ptr(), s0);
            _mm512_storeu_pd(oc.as_mut_ptr().add(8), s1);
        }
        if slow0 | slow1 != 0 {
            fallback.exact_lanes(xc, oc);
        }
    }
    for (o, &x) in os.into_remainder().iter_mut().zip(xs.remainder()) {
        *o = fallback.pow(x);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::pow_fast::tests::samples;

    /// The kernel against the scalar function, bit for bit, over random bit patterns (every
    /// special value, subnormals, both signs), log-uniform overlaps and the range's ends.
    #[test]
    fn same_bits_as_the_scalar_function() {
        if !(std::is_x86_feature_detected!("avx512f") && std::is_x86_feature_detected!("fma")) {
            println!("skipped: no AVX-512F + FMA on this CPU");
            return;
        }
        let x = samples();
        for q in [0.35, 1e-9, 0.25, 1.0, 2.0, 3.7, 4.0] {
            let t = FastPow::new(q).unwrap();
            let mut out = vec![0.0; x.len()];
            // SAFETY: the CPU has AVX-512F and FMA (checked above).
            unsafe { pow_fast_slice_x8(&x, &Tables::load(&t), &t, &mut out) };
            // Lanes with x <= 0 or NaN are unspecified (the batch zeroes those forces).
            let bad = x
                .iter()
                .zip(&out)
                .filter(|&(&x, &o)| x > 0.0 && o.to_bits() != t.pow(x).to_bits())
                .count();
            assert_eq!(bad, 0, "q = {q}: {bad} of {} differ", x.len());
        }
    }
}
