//! Energy partition of one collision, as fractions of the impact energy ½ m v0².
//!
//! The map carries the elastic energy exactly onto the LSD's: k δ^{p+1}/(p+1) = k A^{p+1} x²/(p+1)
//! = ½ m ω0² x² (A^{p+1} = (p+1)/2), and the kinetic energy is ½ m v² with v = dx/ds. So the
//! mechanical energy of the power-law contact is the LSD's ½ m (v² + ω0² x²) at every instant, and
//! its losses between events are the LSD's. In units of ½ m v0², with e_F = e^{−2g(ζ)}:
//!
//! * turning point (v = 0, X = e^{−g}): stored energy e^{−2g} = e_F, so **loading dissipates
//!   1 − e_F** — the force-end restitution of the same ζ appears here;
//! * overlap end (ζ < 1): returned e_O², unloading dissipates e_F − e_O²
//!   = e_F·(1 − e^{−2ζ(π − arccos ζ)/ω}); overdamped: the limit t → ∞, returned 0, unloading e_F;
//! * force end: at 2u_m, X = 2ζe_F and X' = −e_F: returned e_F², elastic energy still in the
//!   spring when the clamped force vanishes (4ζ²e_F², lost by the clamp: the force stays clamped
//!   at 0 while the bodies separate), and unloading dissipation by the dashpot
//!   e_F − (1+4ζ²)e_F² = e_F·(1 − e^{−2g + ln(1+4ζ²)}).
//!
//! Every difference is formed with expm1/ln_1p, so small damping keeps full relative precision.

use super::calibration;
use super::contact::{Contact, Regime};
use crate::criterion::EndCriterion;
use core::f64::consts::PI;

/// Fractions of ½ m v0²; they sum to 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnergyPartition {
    /// Realised restitution (|exit speed|/v0).
    pub e: f64,
    /// Dissipated by the dashpot while loading (impact → maximum overlap).
    pub loading: f64,
    /// Dissipated by the dashpot while unloading (maximum overlap → end).
    pub unloading: f64,
    /// Kinetic energy returned at the end: e².
    pub returned: f64,
    /// Elastic energy left in the spring at the force end, lost by clamping (0 for overlap end).
    pub clamped: f64,
}

/// The partition for `criterion`.
pub fn energy_partition(c: &Contact, criterion: EndCriterion) -> EnergyPartition {
    let g = c.g();
    let e_f = (-2.0 * g).exp();
    let loading = -(-2.0 * g).exp_m1();
    match criterion {
        EndCriterion::Overlap => match c.regime {
            Regime::Under(w) => {
                let theta = if c.zeta < 0.5 {
                    c.zeta.acos()
                } else {
                    g * w / c.zeta
                };
                let unloading = e_f * -(-2.0 * c.zeta * (PI - theta) / w).exp_m1();
                // From α directly (as dc_e_from_alpha): near critical damping e_O is so steep in ζ
                // that rounding ζ = α/√(2(p+1)) first cost 2.3e-13 at e = 1e-12
                // (tests/extremes.rs).
                let e_o = calibration::e_from_alpha(c.alpha, c.p, EndCriterion::Overlap)
                    .unwrap_or((-PI * c.zeta / w).exp());
                EnergyPartition {
                    e: e_o,
                    loading,
                    unloading,
                    returned: e_o * e_o,
                    clamped: 0.0,
                }
            }
            _ => EnergyPartition {
                e: 0.0,
                loading,
                unloading: e_f,
                returned: 0.0,
                clamped: 0.0,
            },
        },
        EndCriterion::Force => {
            let z2 = 4.0 * c.zeta * c.zeta;
            // For huge ζ (α beyond ~1e154) 4ζ² overflows while e_F underflows: form both in
            // logarithms there, ln(1 + 4ζ²) = 2 ln 2ζ to rounding (found by tests/proptest_ffi.rs).
            let (ln_1p_z2, clamped) = if z2.is_finite() {
                (z2.ln_1p(), z2 * e_f * e_f)
            } else {
                let l = 2.0 * (2.0 * c.zeta).ln();
                (l, (l - 4.0 * g).exp())
            };
            let unloading = e_f * -(-2.0 * g + ln_1p_z2).exp_m1();
            EnergyPartition {
                e: e_f,
                loading,
                unloading,
                returned: e_f * e_f,
                clamped,
            }
        }
    }
}
