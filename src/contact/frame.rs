//! Frame indifference of the history springs, and second-order increments.
//!
//! Every step, each stored tangential vector (the tangential spring ξ, the rolling spring
//! torque) is carried by the rotation of the contact frame since the last step, so that a rigid
//! rotation of both bodies rotates the spring with them and neither stretches nor shortens it.
//! The frame rotation of one step is composed of two exact rotations (norm preserving to
//! rounding), then a projection:
//! 1. *spin*: the rotation by the mean spin of the two bodies ω̄ = ½ (ω1 + ω2) over the step,
//!    the rotation vector q = ω̄ dt with its true angle |q| (Rodrigues,
//!    v' = v + s q×v + c q×(q×v), s = sin|q|/|q|, c = (1 − cos|q|)/|q|², from their Taylor series
//!    for |q|² < 1e-3, accurate to rounding there, else from our own sin/cos, `numerics::trig`). For a rigid motion this
//!    *is* the step rotation of the frame, whatever its axis.
//! 2. *tilt*: the minimal rotation taking the spun old normal R n_old to the current normal n
//!    (Rodrigues about R n_old × n): the non-rigid remainder (the bodies rolling or sliding over
//!    each other, so that n turns at another rate than the bodies spin).
//! 3. the projection on the plane ⊥ n (removes rounding and the 1e-6 tolerance of a unit n).
//!
//! The increment of a step (v_t dt) is the contact point's relative velocity projected on the
//! current tangent plane, with the lever-arm term (a1 ω1 + a2 ω2) × n formed with the current
//! normal too. Then a rigid rotation Ω superposed on any contact (v_i → R v_i + Ω × R x_i,
//! ω_i → R ω_i + Ω) leaves the contact point's relative velocity exactly R v_c (the Ω terms
//! cancel because |x1 − x2| = a1 + a2), and the spring is carried by exp((R ω̄ + Ω) dt), which
//! differs from the true exp(R ω̄ dt) exp(Ω dt) only by the commutator ½ (R ω̄ × Ω) dt² — the
//! product of the bodies' own mean spin and the superposed one, zero when they are parallel
//! (every planar motion, and any rigid rotation of a contact whose bodies do not spin on
//! average). The previous carry (tilt n_old → n, then a Cayley twist by ½(ω1 + ω2)·n dt) left
//! ½ (Δn·Ω) dt² per step instead (Δn: the normal's rate), and its Cayley angle 2 atan(θ/2) ≠ θ
//! made a rigidly spinning stuck pair drift by 2.9e-8 over 90° (now 8e-13, rounding).
//! (Forming the increment on the mid-step plane n_old + n, a midpoint rule, was tried: it lowers
//! the energy error of an elastic sticking collision by 3–22 % but breaks the exact cancellation
//! above, so it was dropped.)
//!
//! The cheaper carry, `select::CARRY_PROJECT` (what LAMMPS's `granular` does; LIGGGHTS'
//! `tangential history` projects too but never rescales), skips steps 1 and 2: the spring is
//! projected on the current tangent plane and rescaled to its old length, but only while more
//! than half of its length stays in the plane (|P v|² > ¼ |v|²: e.g. a spring in the
//! plane of the turn, for a normal turned by less than 60° in the step); otherwise it is projected
//! only, as the rotation's fallback does. It needs neither the stored normal nor the spin, but it
//! is not objective: the spring keeps its direction in space while the pair turns about n, so a
//! stuck pair spinning rigidly about its normal loads its spring by the angle turned (measured in
//! tests/contact_physics.rs, docs/force.md). Unlike LAMMPS, which rescales only when the normal
//! component exceeds a small threshold, it rescales whenever that half is kept (the factor is 1
//! to rounding when nothing turned).

use super::vec3::{V3, add, cross, dot, norm2, scale, tangential};
use crate::numerics::trig::sin_cos;

/// Below this |q|² the Taylor series of s and c (to q⁶) are exact to rounding (the first
/// omitted terms are q⁸/9! and q⁸/10!, < 3e-18).
const SERIES_Q2: f64 = 1e-3;

/// The frame motion of one step.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrameStep {
    /// Spin rotation vector q = ω̄ dt and its Rodrigues coefficients s, c.
    q: V3,
    s: f64,
    c: f64,
    /// Tilt R n_old → n: cos and R n_old × n.
    tc: f64,
    tk: V3,
    /// false: a new contact (nothing stored) or a normal turned by more than 120° in one step.
    carry: bool,
    /// Current normal.
    n: V3,
    /// `select::CARRY_PROJECT`: project and rescale only (the other fields unused).
    project: bool,
}

/// Rotation by the vector q: v + s q×v + c q×(q×v).
#[inline(always)]
fn spin(q: V3, s: f64, c: f64, v: V3) -> V3 {
    let qv = cross(q, v);
    let qqv = cross(q, qv);
    add(v, add(scale(s, qv), scale(c, qqv)))
}

/// Rodrigues about k = a × b (|k| = sin φ, c = a·b = cos φ), exact for unit a, b:
/// v' = c v + k × v + (k·v)/(1 + c) k (no division by sin φ).
#[inline(always)]
fn tilt(c: f64, k: V3, v: V3) -> V3 {
    add(
        add(scale(c, v), cross(k, v)),
        scale(dot(k, v) / (1.0 + c), k),
    )
}

/// s = sin θ/θ and c = (1 − cos θ)/θ² for θ² = `q2`.
#[inline(always)]
fn rodrigues_coefficients(q2: f64) -> (f64, f64) {
    if q2 < SERIES_Q2 {
        // Horner forms of 1 − θ²/6 + θ⁴/120 − θ⁶/5040 and ½ − θ²/24 + θ⁴/720 − θ⁶/40320.
        // (Divisions, as include/demcontact_inline.h has them bit for bit: keep the order.)
        let s = 1.0 - q2 / 6.0 * (1.0 - q2 / 20.0 * (1.0 - q2 / 42.0));
        let c = 0.5 * (1.0 - q2 / 12.0 * (1.0 - q2 / 30.0 * (1.0 - q2 / 56.0)));
        (s, c)
    } else {
        // sin θ = 2 sin(θ/2) cos(θ/2) and 1 − cos θ = 2 sin²(θ/2) (no cancellation), from one
        // reduction of θ/2, so that the rotation stays orthogonal to rounding; our own sin and
        // cos, not libm's, so that the header gives these bits on a GPU too. θ ≥ 2^20 (a spin
        // no step resolves): NaN, so that `new` finds no carry and the projection alone applies,
        // as for a normal turned by more than 120°.
        let th = q2.sqrt();
        let (sh, ch) = sin_cos(0.5 * th);
        (2.0 * (sh * ch) / th, 2.0 * (sh * sh) / q2)
    }
}

impl FrameStep {
    /// The step from the stored normal `n_old` (all zeros for a new contact) to `n`, with the
    /// mean spin rotation vector `q` = ½ (ω1 + ω2) dt.
    #[inline(always)]
    pub(crate) fn new(n_old: V3, n: V3, q: V3) -> Self {
        let (s, c) = rodrigues_coefficients(norm2(q));
        let spun = spin(q, s, c, n_old);
        let tc = dot(spun, n);
        // A new contact (n_old = 0) or a normal turned by more than 120° in one step (no unique
        // minimal rotation): no carry, the projection alone applies.
        let carry = tc > -0.5 && norm2(n_old) > 0.25;
        FrameStep {
            q,
            s,
            c,
            tc,
            tk: cross(spun, n),
            carry,
            n,
            project: false,
        }
    }

    /// The projection carry onto the plane ⊥ `n` (`select::CARRY_PROJECT`).
    #[inline(always)]
    pub(crate) fn projection(n: V3) -> Self {
        FrameStep {
            q: [0.0; 3],
            s: 0.0,
            c: 0.0,
            tc: 0.0,
            tk: [0.0; 3],
            carry: false,
            n,
            project: true,
        }
    }

    /// Carries a tangential vector of the last step's frame into the current tangent plane.
    #[inline(always)]
    pub(crate) fn carry(&self, v: V3) -> V3 {
        if self.project {
            // |v|² / |w|² in one division and one root (include/demcontact_inline.h: same order).
            // Rescaled only while more than half the length stays in the plane (e.g. a normal
            // turned by less than 60° in the plane of the spring since the last step): a spring that lost more is projected only,
            // as the rotation's fallback does, instead of blowing a rounding residual up to its
            // old length in a random direction (LAMMPS rescales any nonzero projection).
            let l2 = norm2(v);
            let w = tangential(v, self.n);
            let p2 = norm2(w);
            return if p2 > 0.25 * l2 {
                scale((l2 / p2).sqrt(), w)
            } else {
                w
            };
        }
        let v = if self.carry {
            tilt(self.tc, self.tk, spin(self.q, self.s, self.c, v))
        } else {
            v
        };
        tangential(v, self.n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series branch against sin/cos at the switch and below, and the rotation it gives
    /// against an independent one (rotating a vector ⊥ the axis by θ: cos θ, sin θ).
    #[test]
    fn rodrigues_coefficients_are_exact_to_rounding_on_both_branches() {
        for q2 in [1e-20, 1e-8, 1e-5, 9.999e-4, 1e-3, 1.0001e-3, 0.5, 4.0, 30.0] {
            let (s, c) = rodrigues_coefficients(q2);
            let th: f64 = q2.sqrt();
            let (s_ref, c_ref) = (th.sin() / th, (1.0 - th.cos()) / q2);
            // 1 − cos θ cancels for small θ: compare against its own accuracy.
            let c_tol = 4e-16 + 2.3e-16 / q2;
            assert!((s - s_ref).abs() <= 4e-16, "q2 {q2}: s {s} vs {s_ref}");
            assert!((c - c_ref).abs() <= c_tol, "q2 {q2}: c {c} vs {c_ref}");
            // x rotated about z by θ.
            let v = spin([0.0, 0.0, th], s, c, [1.0, 0.0, 0.0]);
            let want = [th.cos(), th.sin(), 0.0];
            let err = (0..3).fold(0.0f64, |e, i| {
                e.max(
                    (v.get(i).copied().unwrap_or(0.0) - want.get(i).copied().unwrap_or(0.0)).abs(),
                )
            });
            assert!(err <= 4e-16, "q2 {q2}: rotation off by {err}");
        }
    }

    /// A frame carried by a spin and a tilt keeps tangential vectors tangential and their length.
    #[test]
    fn carry_preserves_length_and_lands_in_the_tangent_plane() {
        let n_old = [0.0, 0.0, 1.0];
        let n = {
            let v = [0.01, -0.02, 1.0];
            let l = norm2(v).sqrt();
            scale(1.0 / l, v)
        };
        let f = FrameStep::new(n_old, n, [0.003, -0.001, 0.02]);
        let v = [0.6, -0.8, 0.0];
        let w = f.carry(v);
        assert!((norm2(w) - 1.0).abs() < 1e-15, "|w|² = {}", norm2(w));
        assert!(dot(w, n).abs() < 1e-16, "w·n = {}", dot(w, n));
        // A new contact (no stored normal) only projects.
        let g = FrameStep::new([0.0; 3], n, [1.0, 2.0, 3.0]);
        assert_eq!(g.carry(v), tangential(v, n));
    }

    /// The projection carry against LAMMPS's own formulation of the same rule (project, then
    /// scale by |v|/|projection| from two roots), within 2 ulp per component; it ignores the spin,
    /// keeps the length, and drops a spring with no tangential part.
    #[test]
    fn projection_carry_is_lammps_project_and_rescale() {
        let n = {
            let v: V3 = [0.2, -0.3, 0.9];
            scale(1.0 / norm2(v).sqrt(), v)
        };
        let f = FrameStep::projection(n);
        let mut worst = 0.0f64;
        for (i, v) in [
            [0.6, -0.8, 0.0],
            [1e-9, 3e-10, -2e-9],
            [5.0, 1.0, 0.3],
            [-1e-3, 2e-3, 7e-4],
        ]
        .into_iter()
        .enumerate()
        {
            let w = f.carry(v);
            let rsht = dot(v, n);
            let proj = [v[0] - rsht * n[0], v[1] - rsht * n[1], v[2] - rsht * n[2]];
            let fac = norm2(v).sqrt() / norm2(proj).sqrt();
            for (a, b) in w.iter().zip(proj.iter().map(|x| x * fac)) {
                let ulp = (a - b).abs() / (b.abs().max(f64::MIN_POSITIVE) * f64::EPSILON);
                worst = worst.max(ulp);
            }
            assert!(
                (norm2(w) / norm2(v) - 1.0).abs() < 1e-15,
                "case {i}: length not kept"
            );
            assert!(dot(w, n).abs() < 1e-15 * norm2(v).sqrt(), "case {i}: w·n");
        }
        assert!(worst <= 2.0, "{worst} ulp from LAMMPS's formulation");
        // Parallel to n: only a rounding residual is left, and it is not blown up to length 3;
        // a normal turned by more than 60° projects only, by less rescales.
        assert!(norm2(f.carry(scale(3.0, n))).sqrt() < 1e-15);
        assert_eq!(f.carry([0.0; 3]), [0.0; 3]);
        let t = [n[1], -n[0], 0.0]; // ⊥ n
        let t = scale(1.0 / norm2(t).sqrt(), t);
        for (deg, rescaled) in [(59.9f64, true), (60.1, false)] {
            let a = deg.to_radians();
            let v = add(scale(a.cos(), t), scale(a.sin(), n)); // |v| = 1, angle a out of the plane
            let l = norm2(f.carry(v)).sqrt();
            let want = if rescaled { 1.0 } else { a.cos() };
            assert!((l - want).abs() < 1e-15, "{deg}°: length {l}, want {want}");
        }
    }
}
