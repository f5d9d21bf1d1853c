//! Cundall–Strack linear tangential spring: a constant k_t [N/m] per material pair.

use super::kinematics::Kin;
use super::model::ContactModel;
use super::tangential::TangentialLaw;

/// k_t fixed by the spec.
pub(crate) struct Linear;

impl TangentialLaw for Linear {
    #[inline(always)]
    fn stiffness(m: &ContactModel, _k: &Kin) -> f64 {
        m.kt
    }
}
