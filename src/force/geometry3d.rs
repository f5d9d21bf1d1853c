//! Two spheres in 3D → the normal contact force vector, for host codes without their own
//! contact geometry.
//!
//! Conventions: n = (x1 − x2)/|x1 − x2| points from sphere 2 to sphere 1; the overlap is
//! δ = R1 + R2 − |x1 − x2|; its rate vn = dδ/dt = (v2 − v1)·n (positive while approaching);
//! R* = R1 R2/(R1 + R2), m* = m1 m2/(m1 + m2). The result F n is the force on sphere 1 (repulsive:
//! along n); sphere 2 receives −F n.

use super::pair::PairModel;
use super::registry::{needs, normal_force_raw};
use crate::Error;
use nalgebra::Vector3;

/// One sphere: centre [m], velocity [m/s], radius [m], mass [kg].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Centre position.
    pub x: [f64; 3],
    /// Velocity of the centre.
    pub v: [f64; 3],
    /// Radius > 0.
    pub r: f64,
    /// Mass > 0.
    pub m: f64,
}

fn check(s: &Sphere) -> Result<(), Error> {
    if !(s.x.iter().chain(s.v.iter()).all(|a| a.is_finite()) && s.r.is_finite() && s.m.is_finite())
    {
        return Err(Error::NotFinite);
    }
    if !(s.r > 0.0 && s.m > 0.0) {
        return Err(Error::NotPositive);
    }
    Ok(())
}

/// The normal force on sphere 1 (see the module conventions); zero vector without overlap.
pub fn normal_force_3d(pair: &PairModel, s1: &Sphere, s2: &Sphere) -> Result<[f64; 3], Error> {
    needs(pair.kernel).ok_or(Error::PairInvalid)?;
    check(s1)?;
    check(s2)?;
    let x12 = Vector3::from(s1.x) - Vector3::from(s2.x);
    let dist = x12.norm();
    if !dist.is_finite() {
        return Err(Error::ResultRange);
    }
    let overlap = s1.r + s2.r - dist;
    if !(overlap > 0.0) {
        return Ok([0.0; 3]);
    }
    // Overlapping spheres with coincident centres have no normal direction.
    if !(dist > 0.0) {
        return Err(Error::NotPositive);
    }
    let n = x12 / dist;
    let vn = (Vector3::from(s2.v) - Vector3::from(s1.v)).dot(&n);
    let r_eff = s1.r * s2.r / (s1.r + s2.r);
    let m_eff = s1.m * s2.m / (s1.m + s2.m);
    let f = normal_force_raw(pair.kernel, pair.consts, overlap, vn, r_eff, m_eff);
    let fv = n * f;
    if !(f.is_finite() && fv.iter().all(|a| a.is_finite())) {
        return Err(Error::ResultRange);
    }
    Ok([fv.x, fv.y, fv.z])
}
