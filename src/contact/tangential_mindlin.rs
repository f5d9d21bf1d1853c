//! Mindlin's no-slip tangential stiffness of two elastic spheres: k_t = 8 G* a with the Hertz
//! contact radius a = √(R* δ) and 1/G* = (2 − ν1)/G1 + (2 − ν2)/G2, G = E/(2(1 + ν)).
//! The model stores 8 G*; a rigid body (E = +∞) contributes nothing to 1/G*.

use super::kinematics::Kin;
use super::model::ContactModel;
use super::spec::{ContactSpec, compliance};
use super::tangential::TangentialLaw;
use crate::Error;

/// k_t = 8 G* √(R* δ), varying with the overlap.
pub(crate) struct Mindlin;

impl TangentialLaw for Mindlin {
    #[inline(always)]
    fn stiffness(m: &ContactModel, k: &Kin) -> f64 {
        m.kt * (k.r_eff * k.d).sqrt()
    }

    /// 8 G* of the spec's materials (each checked as the normal law checks it).
    fn stiffness_constant(s: &ContactSpec) -> Result<f64, Error> {
        compliance(s.e1, s.nu1)?;
        compliance(s.e2, s.nu2)?;
        eight_g_star(s.e1, s.nu1, s.e2, s.nu2)
    }

    /// Unknown: k_t depends on the overlap the spring was stored at.
    fn stored_stiffness(_m: &ContactModel) -> f64 {
        0.0
    }
}

/// 8 G* of two materials; E = +∞ is a rigid body (both rigid: `NotFinite`).
pub fn eight_g_star(e1: f64, nu1: f64, e2: f64, nu2: f64) -> Result<f64, Error> {
    // (2 − ν)/G = 2 (2 − ν)(1 + ν)/E.
    let c = |e: f64, nu: f64| 2.0 * (2.0 - nu) * (1.0 + nu) / e;
    let g = 1.0 / (c(e1, nu1) + c(e2, nu2));
    let v = 8.0 * g;
    if !v.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(v > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(v)
}
