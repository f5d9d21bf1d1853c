//! [`super::pow_dd`] for four lanes with AVX2: the same operations in the same order as the
//! scalar kernel (plain multiplication and addition, no fused multiply–add), so the same bits;
//! the 32-entry tables of [`super::pow_table`] read by memory gathers (`vgatherqpd`; AVX2 has no
//! two-register permute for 32 entries), which LLVM does not choose by itself for x86-64 (the
//! loop would stay scalar).
//! The AVX-512 twin is [`super::pow_avx512`].

use super::pow_dd::{K_CLAMP, TWO54};
use super::pow_table::{
    EXP2_HI, EXP2_LO, INV_LN2_32, INVC, LN2_32_HI, LN2_32_LO, LOGC, OFF, TWO52,
};
use super::reduce::SHIFTER;
use core::arch::x86_64::*;

/// Table entry `i mod 32` per lane.
#[target_feature(enable = "avx2")]
#[inline]
fn gather(t: &[f64; 32], i: __m256i) -> __m256d {
    let i = _mm256_and_si256(i, _mm256_set1_epi64x(31));
    // SAFETY: every index is in 0..32 (masked just above), within the 32-entry table.
    unsafe { _mm256_i64gather_pd::<8>(t.as_ptr(), i) }
}

/// `b` where the lane mask `k` is set, else `a`.
#[target_feature(enable = "avx2")]
#[inline]
fn blend(k: __m256d, a: __m256d, b: __m256d) -> __m256d {
    _mm256_blendv_pd(a, b, k)
}

#[target_feature(enable = "avx2")]
#[inline]
fn c(x: f64) -> __m256d {
    _mm256_set1_pd(x)
}

#[target_feature(enable = "avx2")]
#[inline]
fn ci(x: u64) -> __m256i {
    _mm256_set1_epi64x(x as i64)
}

#[target_feature(enable = "avx2")]
#[inline]
fn add(a: __m256d, b: __m256d) -> __m256d {
    _mm256_add_pd(a, b)
}

#[target_feature(enable = "avx2")]
#[inline]
fn sub(a: __m256d, b: __m256d) -> __m256d {
    _mm256_sub_pd(a, b)
}

#[target_feature(enable = "avx2")]
#[inline]
fn mul(a: __m256d, b: __m256d) -> __m256d {
    _mm256_mul_pd(a, b)
}

#[target_feature(enable = "avx2")]
#[inline]
fn bits(a: __m256d) -> __m256i {
    _mm256_castpd_si256(a)
}

#[target_feature(enable = "avx2")]
#[inline]
fn float(a: __m256i) -> __m256d {
    _mm256_castsi256_pd(a)
}

/// [`super::reduce::exp2i`] per lane.
#[target_feature(enable = "avx2")]
#[inline]
fn exp2i(kf: __m256d) -> __m256d {
    let b = _mm256_sub_epi64(bits(add(kf, c(SHIFTER + 1023.0))), ci(SHIFTER.to_bits()));
    float(_mm256_slli_epi64::<52>(b))
}

/// [`super::pow_dd::pow_dd`] of four lanes (q the same for all), bit for bit.
#[target_feature(enable = "avx2")]
#[inline]
pub(crate) fn pow_x4(x: __m256d, q: f64) -> __m256d {
    let zero = _mm256_setzero_pd();
    let inf = c(f64::INFINITY);
    // pow_dd::normal
    let pos = _mm256_and_pd(
        _mm256_cmp_pd::<_CMP_GT_OQ>(x, zero),
        _mm256_cmp_pd::<_CMP_LT_OQ>(x, inf),
    );
    let safe = blend(pos, c(1.0), x);
    let sub_n = _mm256_cmp_pd::<_CMP_LT_OQ>(safe, c(f64::MIN_POSITIVE));
    let xn = blend(sub_n, safe, mul(safe, c(TWO54)));
    // pow_table::ln_split
    let ix = bits(xn);
    let tmp = _mm256_sub_epi64(ix, ci(OFF));
    let eb = _mm256_srli_epi64::<52>(_mm256_add_epi64(tmp, ci(1024 << 52)));
    let e = sub(
        float(_mm256_or_si256(ci(0x4330_0000_0000_0000), eb)),
        c(TWO52 + 1024.0),
    );
    let z = float(_mm256_sub_epi64(ix, _mm256_and_si256(tmp, ci(0xfff << 52))));
    let cc = float(_mm256_add_epi64(
        _mm256_add_epi64(ci(OFF), _mm256_and_si256(tmp, ci(31 << 47))),
        ci(1 << 46),
    ));
    let i = _mm256_srli_epi64::<47>(tmp);
    let u = mul(sub(z, cc), gather(&INVC, i));
    let u2 = mul(u, u);
    let u4 = mul(u2, u2);
    let b0 = add(c(-1.0 / 2.0), mul(c(1.0 / 3.0), u));
    let b1 = add(c(-1.0 / 4.0), mul(c(1.0 / 5.0), u));
    let b2 = add(c(-1.0 / 6.0), mul(c(1.0 / 7.0), u));
    let b3 = add(c(-1.0 / 8.0), mul(c(1.0 / 9.0), u));
    let c0 = add(b0, mul(b1, u2));
    let c1 = add(b2, mul(b3, u2));
    let l = add(c0, mul(c1, u4));
    let ln_z = add(gather(&LOGC, i), add(u, mul(u2, l)));
    // pow_dd::pow_ln
    let e = blend(sub_n, e, sub(e, c(54.0)));
    let qh = f64::from_bits(q.to_bits() & !((1u64 << 27) - 1));
    let ql = q - qh;
    let big_p = mul(c(qh), e);
    let small_q = mul(c(ql), e);
    let n = sub(add(big_p, c(SHIFTER)), c(SHIFTER));
    let frac = add(sub(big_p, n), small_q);
    let tt = add(mul(frac, c(core::f64::consts::LN_2)), mul(c(q), ln_z));
    // pow_table::exp_split
    let y = add(mul(tt, c(INV_LN2_32)), c(SHIFTER));
    let kf = sub(y, c(SHIFTER));
    let yb = bits(y);
    let jf = sub(
        float(_mm256_or_si256(
            ci(0x4330_0000_0000_0000),
            _mm256_and_si256(yb, ci(31)),
        )),
        c(TWO52),
    );
    let k_hi = mul(sub(kf, jf), c(1.0 / 32.0));
    let r = sub(sub(tt, mul(kf, c(LN2_32_HI))), mul(kf, c(LN2_32_LO)));
    let r2 = mul(r, r);
    let b0 = add(c(1.0 / 2.0), mul(c(1.0 / 6.0), r));
    let b1 = add(c(1.0 / 24.0), mul(c(1.0 / 120.0), r));
    let c0 = add(b0, mul(b1, r2));
    let w = add(r, mul(r2, add(c0, mul(c(1.0 / 720.0), mul(r2, r2)))));
    let hi = gather(&EXP2_HI, yb);
    let p = add(hi, add(gather(&EXP2_LO, yb), mul(hi, w)));
    // pow_dd::pow_exp (the clamp: total is never NaN here)
    let total = add(n, k_hi);
    let total = _mm256_min_pd(_mm256_max_pd(total, c(-K_CLAMP)), c(K_CLAMP));
    let k1 = sub(add(mul(c(0.5), total), c(SHIFTER)), c(SHIFTER));
    let v = mul(mul(p, exp2i(k1)), exp2i(sub(total, k1)));
    let v = blend(_mm256_cmp_pd::<_CMP_EQ_OQ>(x, inf), v, inf);
    blend(_mm256_cmp_pd::<_CMP_EQ_OQ>(x, zero), v, zero)
}

/// `out[i] = x[i]^q` (as many as the shorter slice), four lanes at a time, the last one to
/// three elements by the scalar kernel (the same bits).
#[target_feature(enable = "avx2")]
pub(crate) fn pow_slice_x4(x: &[f64], q: f64, out: &mut [f64]) {
    let n = out.len().min(x.len());
    let (x, out) = (
        x.get(..n).unwrap_or(&[]),
        out.get_mut(..n).unwrap_or(&mut []),
    );
    let mut xs = x.chunks_exact(4);
    let mut os = out.chunks_exact_mut(4);
    for (o, x) in (&mut os).zip(&mut xs) {
        // SAFETY: both slices have four elements.
        unsafe { _mm256_storeu_pd(o.as_mut_ptr(), pow_x4(_mm256_loadu_pd(x.as_ptr()), q)) };
    }
    for (o, &x) in os.into_remainder().iter_mut().zip(xs.remainder()) {
        *o = super::pow_dd::pow_dd(x, q);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lane gives the scalar kernel's bits, over the whole double range, special values
    /// and exponents (runs where the CPU has AVX2; says so where it does not).
    #[test]
    fn lanes_match_scalar_bitwise() {
        if !std::is_x86_feature_detected!("avx2") {
            println!("SKIPPED: no AVX2 on this CPU");
            return;
        }
        let mut s: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut xs: Vec<f64> = (0..200_003)
            .map(|_| {
                s = s
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                f64::from_bits(s >> 1)
            })
            .collect();
        xs.extend([
            0.0,
            -0.0,
            5e-324,
            1e-310,
            f64::MIN_POSITIVE,
            1.0,
            f64::MAX,
            f64::INFINITY,
        ]);
        xs.extend([-1.0, f64::NAN, f64::NEG_INFINITY, 1e-15, 1e-12, 0.3]);
        let mut out = vec![0.0; xs.len()];
        for q in [1e-9, 0.35, 0.5, 0.7, 2.0, 3.3, 10.0] {
            // SAFETY: the CPU has AVX2 (checked above).
            unsafe { pow_slice_x4(&xs, q, &mut out) };
            for (&x, &got) in xs.iter().zip(&out) {
                let want = super::super::pow_dd::pow_dd(x, q);
                assert_eq!(
                    got.to_bits(),
                    want.to_bits(),
                    "x={x:e} q={q}: {got:e} vs {want:e}"
                );
            }
        }
    }
}
