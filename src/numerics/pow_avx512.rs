//! [`super::pow_dd`] for eight lanes with AVX-512F: the same operations in the same order (plain
//! multiplication and addition, no fused multiply–add), so the same bits as the scalar kernel
//! and the C header. The one difference is how the 32-entry tables of [`super::pow_table`] are
//! read: from four registers by two in-register permutes (`vpermt2pd`) and a blend, where the
//! compiler would use memory gathers (which cost more than the series the tables save) or not
//! vectorise at all.

use super::pow_dd::{K_CLAMP, TWO54};
use super::pow_table::{
    EXP2_HI, EXP2_LO, INV_LN2_32, INVC, LN2_32_HI, LN2_32_LO, LOGC, OFF, TWO52,
};
use super::reduce::SHIFTER;
use core::arch::x86_64::*;

/// A 32-entry table in four registers.
#[derive(Clone, Copy)]
struct Table32(__m512d, __m512d, __m512d, __m512d);

impl Table32 {
    #[target_feature(enable = "avx512f")]
    fn load(t: &[f64; 32]) -> Self {
        let [a, b, c, d] = [0usize, 8, 16, 24].map(|k| {
            let mut v = [0.0f64; 8];
            for (o, x) in v.iter_mut().zip(t.iter().skip(k)) {
                *o = *x;
            }
            // SAFETY: `v` is eight readable doubles.
            unsafe { _mm512_loadu_pd(v.as_ptr()) }
        });
        Self(a, b, c, d)
    }

    /// Entry `i mod 32` per lane.
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn get(&self, i: __m512i) -> __m512d {
        let lo = _mm512_permutex2var_pd(self.0, i, self.1);
        let hi = _mm512_permutex2var_pd(self.2, i, self.3);
        let upper = _mm512_test_epi64_mask(i, _mm512_set1_epi64(16));
        _mm512_mask_blend_pd(upper, lo, hi)
    }
}

/// The four tables of [`super::pow_table`], loaded once per batch.
#[derive(Clone, Copy)]
pub(crate) struct Tables {
    invc: Table32,
    logc: Table32,
    hi: Table32,
    lo: Table32,
}

impl Tables {
    /// Loads the tables into registers.
    #[target_feature(enable = "avx512f")]
    pub(crate) fn load() -> Self {
        Self {
            invc: Table32::load(&INVC),
            logc: Table32::load(&LOGC),
            hi: Table32::load(&EXP2_HI),
            lo: Table32::load(&EXP2_LO),
        }
    }
}

#[target_feature(enable = "avx512f")]
#[inline]
fn c(x: f64) -> __m512d {
    _mm512_set1_pd(x)
}

#[target_feature(enable = "avx512f")]
#[inline]
fn ci(x: u64) -> __m512i {
    _mm512_set1_epi64(x as i64)
}

#[target_feature(enable = "avx512f")]
#[inline]
fn add(a: __m512d, b: __m512d) -> __m512d {
    _mm512_add_pd(a, b)
}

#[target_feature(enable = "avx512f")]
#[inline]
fn sub(a: __m512d, b: __m512d) -> __m512d {
    _mm512_sub_pd(a, b)
}

#[target_feature(enable = "avx512f")]
#[inline]
fn mul(a: __m512d, b: __m512d) -> __m512d {
    _mm512_mul_pd(a, b)
}

#[target_feature(enable = "avx512f")]
#[inline]
fn bits(a: __m512d) -> __m512i {
    _mm512_castpd_si512(a)
}

#[target_feature(enable = "avx512f")]
#[inline]
fn float(a: __m512i) -> __m512d {
    _mm512_castsi512_pd(a)
}

/// [`super::reduce::exp2i`] per lane.
#[target_feature(enable = "avx512f")]
#[inline]
fn exp2i(kf: __m512d) -> __m512d {
    let b = _mm512_sub_epi64(bits(add(kf, c(SHIFTER + 1023.0))), ci(SHIFTER.to_bits()));
    float(_mm512_slli_epi64::<52>(b))
}

/// [`super::pow_dd::pow_dd`] of eight lanes (q the same for all), bit for bit.
#[target_feature(enable = "avx512f")]
#[inline]
pub(crate) fn pow_x8(x: __m512d, q: f64, t: &Tables) -> __m512d {
    let zero = _mm512_setzero_pd();
    let inf = c(f64::INFINITY);
    // pow_dd::normal
    let pos = _mm512_cmp_pd_mask::<_CMP_GT_OQ>(x, zero) & _mm512_cmp_pd_mask::<_CMP_LT_OQ>(x, inf);
    let safe = _mm512_mask_blend_pd(pos, c(1.0), x);
    let sub_n = _mm512_cmp_pd_mask::<_CMP_LT_OQ>(safe, c(f64::MIN_POSITIVE));
    let xn = _mm512_mask_blend_pd(sub_n, safe, mul(safe, c(TWO54)));
    // pow_table::ln_split
    let ix = bits(xn);
    let tmp = _mm512_sub_epi64(ix, ci(OFF));
    let eb = _mm512_srli_epi64::<52>(_mm512_add_epi64(tmp, ci(1024 << 52)));
    let e = sub(
        float(_mm512_or_si512(ci(0x4330_0000_0000_0000), eb)),
        c(TWO52 + 1024.0),
    );
    let z = float(_mm512_sub_epi64(ix, _mm512_and_si512(tmp, ci(0xfff << 52))));
    let cc = float(_mm512_add_epi64(
        _mm512_add_epi64(ci(OFF), _mm512_and_si512(tmp, ci(31 << 47))),
        ci(1 << 46),
    ));
    let i = _mm512_srli_epi64::<47>(tmp);
    let u = mul(sub(z, cc), t.invc.get(i));
    let u2 = mul(u, u);
    let u4 = mul(u2, u2);
    let b0 = add(c(-1.0 / 2.0), mul(c(1.0 / 3.0), u));
    let b1 = add(c(-1.0 / 4.0), mul(c(1.0 / 5.0), u));
    let b2 = add(c(-1.0 / 6.0), mul(c(1.0 / 7.0), u));
    let b3 = add(c(-1.0 / 8.0), mul(c(1.0 / 9.0), u));
    let c0 = add(b0, mul(b1, u2));
    let c1 = add(b2, mul(b3, u2));
    let l = add(c0, mul(c1, u4));
    let ln_z = add(t.logc.get(i), add(u, mul(u2, l)));
    // pow_dd::pow_ln
    let e = _mm512_mask_blend_pd(sub_n, e, sub(e, c(54.0)));
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
        float(_mm512_or_si512(
            ci(0x4330_0000_0000_0000),
            _mm512_and_si512(yb, ci(31)),
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
    let hi = t.hi.get(yb);
    let p = add(hi, add(t.lo.get(yb), mul(hi, w)));
    // pow_dd::pow_exp (the clamp: total is never NaN here)
    let total = add(n, k_hi);
    let total = _mm512_min_pd(_mm512_max_pd(total, c(-K_CLAMP)), c(K_CLAMP));
    let k1 = sub(add(mul(c(0.5), total), c(SHIFTER)), c(SHIFTER));
    let v = mul(mul(p, exp2i(k1)), exp2i(sub(total, k1)));
    let v = _mm512_mask_blend_pd(_mm512_cmp_pd_mask::<_CMP_EQ_OQ>(x, inf), v, inf);
    _mm512_mask_blend_pd(_mm512_cmp_pd_mask::<_CMP_EQ_OQ>(x, zero), v, zero)
}

/// `out[i] = x[i]^q` (as many as the shorter slice): two groups of eight lanes per step (two
/// independent dependency chains, which the core overlaps), the last groups masked.
#[target_feature(enable = "avx512f")]
pub(crate) fn pow_slice_x8(x: &[f64], q: f64, out: &mut [f64], t: &Tables) {
    let n = out.len().min(x.len());
    let (x, out) = (
        x.get(..n).unwrap_or(&[]),
        out.get_mut(..n).unwrap_or(&mut []),
    );
    let mut pairs_x = x.chunks_exact(16);
    let mut pairs_o = out.chunks_exact_mut(16);
    for (o, x) in (&mut pairs_o).zip(&mut pairs_x) {
        // SAFETY: both slices have 16 elements: loads and stores of 8 at offsets 0 and 8.
        unsafe {
            let a = _mm512_loadu_pd(x.as_ptr());
            let b = _mm512_loadu_pd(x.as_ptr().add(8));
            let (a, b) = (pow_x8(a, q, t), pow_x8(b, q, t));
            _mm512_storeu_pd(o.as_mut_ptr(), a);
            _mm512_storeu_pd(o.as_mut_ptr().add(8), b);
        }
    }
    for (o, x) in pairs_o
        .into_remainder()
        .chunks_mut(8)
        .zip(pairs_x.remainder().chunks(8))
    {
        let k = o.len().min(x.len());
        let mask = ((1u16 << k) - 1) as u8;
        // SAFETY: the masked load reads and the masked store writes only the first k ≤ 8
        // elements, which both slices have.
        unsafe {
            let v = _mm512_maskz_loadu_pd(mask, x.as_ptr());
            _mm512_mask_storeu_pd(o.as_mut_ptr(), mask, pow_x8(v, q, t));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lane gives the scalar kernel's bits, over the whole double range, special values
    /// and exponents (runs where the CPU has AVX-512F; says so where it does not).
    #[test]
    fn lanes_match_scalar_bitwise() {
        if !std::is_x86_feature_detected!("avx512f") {
            println!("SKIPPED: no AVX-512F on this CPU");
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
            // SAFETY: the CPU has AVX-512F (checked above).
            unsafe {
                let t = Tables::load();
                pow_slice_x8(&xs, q, &mut out, &t);
            }
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
