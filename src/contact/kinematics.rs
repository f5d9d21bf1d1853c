//! One contact's geometry and relative motion, from the bodies' state.
//!
//! Conventions (stated once, in the header on `dc_contact_state`): n is the unit normal from
//! body 2 to body 1, δ > 0 the overlap, vn = (v2 − v1)·n the overlap rate (positive while
//! approaching). The contact point lies at distance a_i = r_i − δ/2 from centre i (mid-overlap,
//! LAMMPS's choice), so the relative velocity of the contact point of body 1 with respect to
//! body 2 is
//!   v_c = v1 − v2 − (a1 ω1 + a2 ω2) × n,
//! and its tangential part v_t = v_c − (v_c·n) n drives the tangential spring. A wall is body 2
//! with r2 = +∞: v2 is the wall's velocity at the contact point, ω2 only enters the twist of the
//! frame (see [`super::frame`]) and the relative rolling/twisting rates.
//!
//! R* = r1 r2/(r1 + r2) and m* = m1 m2/(m1 + m2), with an infinite radius or mass (wall, fixed
//! body) giving R* = r1, m* = m1 ([`harmonic`]).

use super::frame::FrameStep;
use super::vec3::{V3, add, cross, dot, scale, sub, tangential};

/// The bodies' state of one contact (see the module conventions).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// Unit normal from body 2 to body 1.
    pub n: V3,
    /// Overlap δ [m], > 0 in contact.
    pub overlap: f64,
    /// Centre velocities [m/s].
    pub v1: V3,
    /// Centre velocity of body 2 (a wall: its velocity at the contact point).
    pub v2: V3,
    /// Angular velocities [rad/s].
    pub w1: V3,
    /// Angular velocity of body 2.
    pub w2: V3,
    /// Radii [m]; r2 = +∞ for a plane wall.
    pub r1: f64,
    /// Radius of body 2.
    pub r2: f64,
    /// Masses [kg]; m2 = +∞ for a fixed body or wall.
    pub m1: f64,
    /// Mass of body 2.
    pub m2: f64,
}

/// What the stages need of one contact in contact (δ > 0).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Kin {
    pub n: V3,
    pub d: f64,
    pub vn: f64,
    pub r_eff: f64,
    pub m_eff: f64,
    /// Lever arms a1, a2 (a2 infinite for a wall).
    pub a1: f64,
    pub a2: f64,
    pub wall: bool,
    /// Tangential relative velocity of the contact point, body 1 relative to body 2.
    pub vt: V3,
    /// Rolling part of ω1 − ω2 (tangential to n).
    pub w_roll: V3,
    /// Relative angular velocity ω1 − ω2.
    pub w_rel: V3,
    pub m1: f64,
    pub m2: f64,
    pub r1: f64,
    pub r2: f64,
}

/// a b/(a + b) for finite a > 0 and b > 0 or +∞ (then a): R* and m*. One division, and no
/// overflow of a b (written a (b/(a + b))).
#[inline(always)]
pub(crate) fn harmonic(a: f64, b: f64) -> f64 {
    // Computed on both branches then selected (b = +∞ gives NaN, discarded): no branch, so the
    // batch loops can vectorise.
    let h = a * (b / (a + b));
    if b == f64::INFINITY { a } else { h }
}

impl Kin {
    /// The frame step from the stored normal `n_old` (zeros: new contact or no history) to the
    /// state's normal, with the bodies' mean spin over dt. Only the stages with vector history
    /// need it (a normal-only or twisting-only model never computes it). `carry`:
    /// `select::CARRY_*` (the projection reads neither the stored normal nor the spin).
    #[inline(always)]
    pub(crate) fn frame(s: &ContactState, n_old: V3, dt: f64, carry: i32) -> FrameStep {
        if carry == super::model::select::CARRY_PROJECT {
            FrameStep::projection(s.n)
        } else {
            FrameStep::new(n_old, s.n, scale(0.5 * dt, add(s.w1, s.w2)))
        }
    }

    /// Kinematics of a state with overlap > 0 (checked by the caller).
    #[inline(always)]
    pub(crate) fn of(s: &ContactState) -> Kin {
        let n = s.n;
        let d = s.overlap;
        let wall = s.r2 == f64::INFINITY;
        let a1 = s.r1 - 0.5 * d;
        let a2 = s.r2 - 0.5 * d;
        let vr = sub(s.v1, s.v2);
        let vn = -dot(vr, n);
        let arm = if wall {
            scale(a1, s.w1)
        } else {
            add(scale(a1, s.w1), scale(a2, s.w2))
        };
        let vc = sub(vr, cross(arm, n));
        let w_rel = sub(s.w1, s.w2);
        Kin {
            n,
            d,
            vn,
            r_eff: harmonic(s.r1, s.r2),
            m_eff: harmonic(s.m1, s.m2),
            a1,
            a2,
            wall,
            vt: tangential(vc, n),
            w_roll: tangential(w_rel, n),
            w_rel,
            m1: s.m1,
            m2: s.m2,
            r1: s.r1,
            r2: s.r2,
        }
    }
}
