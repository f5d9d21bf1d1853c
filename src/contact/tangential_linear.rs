//! Cundall–Strack linear tangential spring: a constant k_t [N/m] per material pair.

use super::kinematics::Kin;
use super::model::ContactModel;
use super::spec::{ContactSpec, positive};
use super::tangential::TangentialLaw;
use crate::Error;

/// k_t fixed by the spec.
pub(crate) struct Linear;

impl TangentialLaw for Linear {
    #[inline(always)]
    fn stiffness(m: &ContactModel, _k: &Kin) -> f64 {
        m.kt
    }

    /// k_t > 0 from the spec.
    fn stiffness_constant(s: &ContactSpec) -> Result<f64, Error> {
        positive(s.k_t)
    }

    fn stored_stiffness(m: &ContactModel) -> f64 {
        m.kt
    }
}
