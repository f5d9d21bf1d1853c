//! Frame indifference of the history springs, and second-order increments.
//!
//! Every step, each stored tangential vector (the tangential spring ξ, the rolling spring
//! torque) is carried by the rotation of the contact frame since the last step, so that a rigid
//! rotation of both bodies rotates the spring with them and neither stretches nor shortens it.
//! The frame rotation of one step is composed of two exact rotations (norm preserving to
//! rounding):
//! 1. *tilt*: the minimal rotation taking the stored normal n_old to the current normal n
//!    (Rodrigues' formula about n_old × n). Exact for any rotation whose axis is perpendicular to
//!    n (every planar motion, for instance), for any step size.
//! 2. *twist*: the rotation about n by the mean spin of the two bodies about the normal,
//!    θ = ½ (ω1 + ω2)·n dt (YADE's choice; LAMMPS and LIGGGHTS omit it), applied as the Cayley
//!    rotation by 2 atan(θ/2) = θ − θ³/12 + …, an exact rotation that needs no sin/cos.
//!
//! The increment of a step (v_t dt) is the contact point's relative velocity projected on the
//! current tangent plane, with the lever-arm term (a1 ω1 + a2 ω2) × n formed with the current
//! normal too. Then a rigid rotation Ω superposed on any contact (v_i → R v_i + Ω × R x_i,
//! ω_i → R ω_i + Ω) leaves the contact point's relative velocity exactly R v_c (the Ω terms
//! cancel because |x1 − x2| = a1 + a2), so with an axis perpendicular to n the whole update is
//! exactly objective. (Forming the increment on the mid-step plane n_old + n, a midpoint rule,
//! was tried: it lowers the energy error of an elastic sticking collision by 3–22 % but breaks
//! this exact cancellation, so it was dropped.)
//!
//! For a rigid rotation whose axis has a component along n, tilt-then-twist differs from the
//! true step rotation by O(dt²) per step; see docs/force.md for the measured figure.

use super::vec3::{V3, add, cross, dot, norm2, scale, tangential};

/// The frame motion of one step.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrameStep {
    /// Tilt old → new: cos and n_old × n (`tilt` false: nothing to tilt).
    c: f64,
    k: V3,
    tilt: bool,
    /// Cayley half-angle of the twist.
    t: f64,
    /// Current normal.
    n: V3,
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

/// Cayley rotation about the unit n by 2 atan(t): v' = v + 2/(1+t²) (t n×v + t² n×(n×v)).
#[inline(always)]
fn twist(n: V3, t: f64, v: V3) -> V3 {
    if t == 0.0 {
        return v;
    }
    let nv = cross(n, v);
    let nnv = cross(n, nv);
    add(
        v,
        scale(2.0 / (1.0 + t * t), add(scale(t, nv), scale(t * t, nnv))),
    )
}

impl FrameStep {
    /// The step from the stored normal `n_old` (all zeros for a new contact) to `n`, with the
    /// twist angle `theta` about n.
    #[inline(always)]
    pub(crate) fn new(n_old: V3, n: V3, theta: f64) -> Self {
        let c = dot(n_old, n);
        // A new contact (n_old = 0) or a normal turned by more than 120° in one step (no unique
        // minimal rotation): no tilt, the projection alone applies.
        let tilt = c > -0.5 && norm2(n_old) > 0.25;
        FrameStep {
            c,
            k: cross(n_old, n),
            tilt,
            t: 0.5 * theta,
            n,
        }
    }

    /// Carries a tangential vector of the last step's frame into the current tangent plane.
    #[inline(always)]
    pub(crate) fn carry(&self, v: V3) -> V3 {
        let v = if self.tilt {
            tilt(self.c, self.k, v)
        } else {
            v
        };
        tangential(twist(self.n, self.t, v), self.n)
    }
}
