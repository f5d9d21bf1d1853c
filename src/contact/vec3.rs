//! The few 3-vector operations the contact stages need, on plain `[f64; 3]` (no allocation, no
//! indexing that could panic, and code LLVM keeps in registers).

/// A 3-vector.
pub type V3 = [f64; 3];

/// a + b.
#[inline(always)]
pub fn add(a: V3, b: V3) -> V3 {
    let [ax, ay, az] = a;
    let [bx, by, bz] = b;
    [ax + bx, ay + by, az + bz]
}

/// a − b.
#[inline(always)]
pub fn sub(a: V3, b: V3) -> V3 {
    let [ax, ay, az] = a;
    let [bx, by, bz] = b;
    [ax - bx, ay - by, az - bz]
}

/// s a.
#[inline(always)]
pub fn scale(s: f64, a: V3) -> V3 {
    let [ax, ay, az] = a;
    [s * ax, s * ay, s * az]
}

/// a · b.
#[inline(always)]
pub fn dot(a: V3, b: V3) -> f64 {
    let [ax, ay, az] = a;
    let [bx, by, bz] = b;
    ax * bx + ay * by + az * bz
}

/// a × b.
#[inline(always)]
pub fn cross(a: V3, b: V3) -> V3 {
    let [ax, ay, az] = a;
    let [bx, by, bz] = b;
    [ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx]
}

/// |a|².
#[inline(always)]
pub fn norm2(a: V3) -> f64 {
    dot(a, a)
}

/// The part of a in the plane normal to the unit vector n: a − (a·n) n.
#[inline(always)]
pub fn tangential(a: V3, n: V3) -> V3 {
    sub(a, scale(dot(a, n), n))
}

/// True when every component is finite.
#[inline(always)]
pub fn finite(a: V3) -> bool {
    a.iter().all(|x| x.is_finite())
}

/// The normal force vector f n, with +0 (not ±0) components when f = 0, so that every path
/// (scalar, batch, separated or clamped) gives the same bits.
#[inline(always)]
pub fn normal_vector(f: f64, n: V3) -> V3 {
    if f == 0.0 { [0.0; 3] } else { scale(f, n) }
}

const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
const SIGN: u64 = 1 << 63;

/// True when every value is finite. Branch-free, and an OR reduction (which the compiler may
/// split into parallel chains or vectorise, unlike a float sum or a min chain): the exponent
/// field plus one unit of the exponent reaches the sign bit exactly when it is all ones (NaN, ±∞).
#[inline(always)]
pub fn all_finite(xs: &[f64]) -> bool {
    bits_finite(finite_bits(xs))
}

/// The OR reduction of [`all_finite`], to be combined over several arrays with `|` and judged
/// once by [`bits_finite`].
#[inline(always)]
pub fn finite_bits(xs: &[f64]) -> u64 {
    xs.iter()
        .fold(0u64, |acc, x| acc | ((x.to_bits() & EXPONENT) + (1 << 52)))
}

/// True when the OR of [`finite_bits`] results saw only finite values.
#[inline(always)]
pub fn bits_finite(acc: u64) -> bool {
    acc & SIGN == 0
}

/// True when no value is below zero (−0.0 counts as zero; NaN must be excluded first, e.g. by
/// [`all_finite`]). Branch-free OR reduction: sign bit set and a nonzero magnitude (the
/// magnitude plus 2^63 − 1 reaches the sign bit exactly when it is ≥ 1).
#[inline(always)]
pub fn none_negative(xs: &[f64]) -> bool {
    xs.iter().fold(0u64, |acc, x| {
        let b = x.to_bits();
        acc | (b & ((b & !SIGN) + (SIGN - 1)))
    }) & SIGN
        == 0
}

/// True when every value is > 0 (+∞ included; 0, −0, negatives fail; a NaN passes or fails by
/// its sign bit: exclude NaN separately). Branch-free OR reduction: b | (b − 1) has the sign bit
/// set exactly when b = 0 or the sign bit of b is set.
#[inline(always)]
pub fn all_positive(xs: &[f64]) -> bool {
    xs.iter().fold(0u64, |acc, x| {
        let b = x.to_bits();
        acc | b | b.wrapping_sub(1)
    }) & SIGN
        == 0
}

/// True when no value is NaN (±∞ allowed). Branch-free OR reduction: the magnitude's bits plus
/// 2^52 − 1 reach the sign bit exactly when they exceed those of +∞.
#[inline(always)]
pub fn no_nan(xs: &[f64]) -> bool {
    xs.iter().fold(0u64, |acc, x| {
        acc | ((x.to_bits() & !SIGN) + ((1 << 52) - 1))
    }) & SIGN
        == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finite_and_sign_reductions_match_the_plain_tests() {
        let vals = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        for &a in &vals {
            for &b in &vals {
                let xs = [1.5, a, -0.0, b];
                assert_eq!(all_finite(&xs), a.is_finite() && b.is_finite(), "{a} {b}");
                if a.is_finite() && b.is_finite() {
                    assert_eq!(none_negative(&xs), a >= 0.0 && b >= 0.0, "{a} {b}");
                }
                assert_eq!(no_nan(&xs), !a.is_nan() && !b.is_nan(), "{a} {b}");
                let ys = [1.5, a, b];
                if !a.is_nan() && !b.is_nan() {
                    assert_eq!(all_positive(&ys), a > 0.0 && b > 0.0, "{a} {b}");
                }
            }
        }
        assert!(all_finite(&[]) && none_negative(&[]));
    }
}
