//! ln x in double-double (about 104 bits), to round the fast power's tables correctly
//! ([`super::pow_fast`]): a table entry y ≈ x^q from [`super::pow_dd`] (within a few ulp) is
//! moved by one Newton step on ln y = q ln x, which needs both logarithms to far better than
//! one ulp. Not for hot paths (a double-double division and 24 double-double steps per call).

/// A double-double number hi + lo, |lo| ≤ ulp(hi)/2.
pub(crate) type Dd = (f64, f64);

/// ln 2 as a double-double.
const LN2: Dd = (
    f64::from_bits(0x3fe6_2e42_fefa_39ef),
    f64::from_bits(0x3c7a_bc9e_3b39_803f),
);

/// a + b exactly, as a double-double.
fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a · b exactly, as a double-double (Dekker's product with Veltkamp's split: no fused
/// multiply–add, so the tables do not depend on how a C library implements `fma`).
fn two_prod(a: f64, b: f64) -> Dd {
    let split = |x: f64| {
        let c = 134_217_729.0 * x; // 2^27 + 1
        let hi = c - (c - x);
        (hi, x - hi)
    };
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

pub(crate) fn add(a: Dd, b: Dd) -> Dd {
    let (s, e) = two_sum(a.0, b.0);
    let (t, f) = two_sum(a.1, b.1);
    let (s, e) = two_sum(s, e + t);
    two_sum(s, e + f)
}

pub(crate) fn mul(a: Dd, b: Dd) -> Dd {
    let (p, e) = two_prod(a.0, b.0);
    two_sum(p, e + (a.0 * b.1 + a.1 * b.0))
}

fn div(a: Dd, b: Dd) -> Dd {
    let q1 = a.0 / b.0;
    let r = add(a, mul(b, (-q1, 0.0)));
    let q2 = r.0 / b.0;
    let r = add(r, mul(b, (-q2, 0.0)));
    let q3 = r.0 / b.0;
    add(two_sum(q1, q2), (q3, 0.0))
}

/// ln x for a positive, finite, normal x: x = 2^e f with f ∈ [√½, √2), then
/// ln f = 2 atanh(u) = 2 Σ u^(2j+1)/(2j+1), u = (f − 1)/(f + 1), |u| ≤ 0.172 (24 terms:
/// u^49/49 < 2^−130).
pub(crate) fn ln_dd(x: f64) -> Dd {
    let bits = x.to_bits();
    let mut e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let mut f = f64::from_bits((bits & ((1 << 52) - 1)) | 1.0f64.to_bits());
    if f > core::f64::consts::SQRT_2 {
        f *= 0.5;
        e += 1;
    }
    // f − 1 is exact (Sterbenz), f + 1 is not: both as double-doubles.
    let u = div((f - 1.0, 0.0), two_sum(f, 1.0));
    let u2 = mul(u, u);
    let mut s: Dd = (1.0 / 49.0, 0.0);
    for j in (0..24).rev() {
        // 1/k as a double-double: the residual 1 − k·(1/k) is exact in one fused multiply–add.
        let k = (2 * j + 1) as f64;
        let r = 1.0 / k;
        let (p, e) = two_prod(r, k);
        let inv = (r, ((1.0 - p) - e) / k);
        s = add(mul(s, u2), inv);
    }
    let ln_f = mul(mul(s, u), (2.0, 0.0));
    add(mul(LN2, (e as f64, 0.0)), ln_f)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ln x to 50 digits by mpmath, split into two doubles (the hex literals).
    const REFERENCE: [(f64, u64, u64); 7] = [
        (1.03125, 0x3f9f_829b_0e78_3300, 0x3c33_3e3f_04f1_ef23),
        (0.7, 0xbfd6_d3c3_24e1_3f50, 0x3c56_4105_2af5_fd8d),
        (
            1.4142135623730951,
            0x3fd6_2e42_fefa_39f0,
            0x3c7c_2e0e_1b15_48c2,
        ),
        (3.0, 0x3ff1_93ea_7aad_030b, 0xbc9a_256f_99ca_abeb),
        (1e-300, 0xc085_9634_47f8_7fb5, 0xbd1a_a670_d353_24e6),
        (
            1.586548151455472e-301,
            0xc085_a4ee_b2fa_1769,
            0xbd1a_fda9_1afc_f51f,
        ),
        (123456.789, 0x4027_7281_cad8_a844, 0xbcbd_8fe0_707e_837c),
    ];

    #[test]
    fn against_mpmath_to_104_bits() {
        for (x, hi, lo) in REFERENCE {
            let want = (f64::from_bits(hi), f64::from_bits(lo));
            let got = ln_dd(x);
            let err = add(got, (-want.0, -want.1)).0.abs() / want.0.abs();
            assert!(
                err < 2f64.powi(-100),
                "ln {x}: {got:?} vs {want:?} ({err:e})"
            );
        }
    }

    #[test]
    fn high_part_is_the_rounded_logarithm() {
        let mut x = 1e-300;
        while x < 1e300 {
            let (hi, lo) = ln_dd(x);
            assert!((hi - x.ln()).abs() <= f64::EPSILON * hi.abs(), "{x:e}");
            assert!(lo.abs() <= f64::EPSILON * hi.abs(), "{x:e}");
            x *= 1.37;
        }
    }
}
