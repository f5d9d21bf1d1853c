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
