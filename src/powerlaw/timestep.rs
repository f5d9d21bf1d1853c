//! The seed's critical time step for explicit integration of a power-law contact.
//!
//! In the mapped LSD the central-difference limit is Δs < 2/ω0; physical time runs at
//! dt/ds = A q x^(q-1), smallest at the largest x, taken as the undamped x_max = v0/ω0:
//!
//! ```text
//! Δt_crit = (4/(p+1)) · A · (1/ω0) · (v0/ω0)^(-(p-1)/(p+1))
//! ```
//!
//! Note (checked, not taken from the seed): this equals √(2p/(p+1)) times 2/ω_lin, where ω_lin is
//! the linearised frequency √(p k δ_max^(p-1)/m) at the undamped maximum overlap, so for p > 1 it
//! is *larger* than the linearised bound, not more conservative as the seed states.

use super::transform::{check_exponent, transform_a};
use crate::Error;

/// The seed's Δt_crit for exponent p ≥ 1, impact speed v0 > 0 and ω0 = √(k/m) > 0.
pub fn dt_crit_seed(p: f64, v0: f64, omega0: f64) -> Result<f64, Error> {
    if !v0.is_finite() || !omega0.is_finite() {
        return Err(Error::NotFinite);
    }
    check_exponent(p)?;
    if !(v0 > 0.0 && omega0 > 0.0) {
        return Err(Error::NotPositive);
    }
    let expo = -(p - 1.0) / (p + 1.0);
    // (v0/ω0)^expo / ω0 in logs: the ratio alone may overflow for extreme but valid inputs.
    let ln_dt =
        (4.0 / (p + 1.0) * transform_a(p)).ln() + expo * (v0.ln() - omega0.ln()) - omega0.ln();
    let dt = ln_dt.exp();
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(dt)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_case_is_two_over_omega() {
        let dt = dt_crit_seed(1.0, 3.7, 250.0).unwrap_or(f64::NAN);
        assert!((dt - 2.0 / 250.0).abs() < 1e-17);
    }

    #[test]
    fn ratio_to_linearised_bound() {
        // Independent: δ_max^(p+1) = (p+1) v0²/(2 ω0²) from energy, ω_lin = ω0 √p δ_max^((p-1)/2).
        for &p in &[1.25f64, 1.5, 2.0, 3.0, 5.0] {
            let (v0, w0) = (0.7f64, 13.0f64);
            let dmax = ((p + 1.0) * v0 * v0 / (2.0 * w0 * w0)).powf(1.0 / (p + 1.0));
            let wl = w0 * p.sqrt() * dmax.powf(0.5 * (p - 1.0));
            let ratio = dt_crit_seed(p, v0, w0).unwrap_or(f64::NAN) / (2.0 / wl);
            assert!(
                (ratio - (2.0 * p / (p + 1.0)).sqrt()).abs() < 1e-14,
                "p={p}: {ratio}"
            );
        }
    }
}

fn finite_positive(ln_dt: f64) -> Result<f64, Error> {
    let dt = ln_dt.exp();
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(dt)
}

/// 2/ω_lin with ω_lin = ω0 √p δ0^((p−1)/2) the linearised frequency at the undamped maximum
/// overlap δ0 = ((p+1) v0²/(2ω0²))^(1/(p+1)) (damping only lowers δ_max, so this is the stiffest
/// point any collision at speed ≤ v0 reaches).
pub fn dt_linearised(p: f64, v0: f64, omega0: f64) -> Result<f64, Error> {
    if !v0.is_finite() || !omega0.is_finite() {
        return Err(Error::NotFinite);
    }
    check_exponent(p)?;
    if !(v0 > 0.0 && omega0 > 0.0) {
        return Err(Error::NotPositive);
    }
    let ln_d0 = ((0.5 * (p + 1.0)).ln() + 2.0 * (v0.ln() - omega0.ln())) / (p + 1.0);
    finite_positive(core::f64::consts::LN_2 - omega0.ln() - 0.5 * p.ln() - 0.5 * (p - 1.0) * ln_d0)
}

/// Velocity-Verlet stability limit of a contact pressed by a constant load (accel = load/m > 0):
/// `(2/ω_eq)(√(1+ζ_eq²) − ζ_eq)`, with δ_eq = (accel/ω0²)^(1/p), ω_eq = ω0 √p δ_eq^((p−1)/2) and
/// ζ_eq = α/(2√p) the damping ratio of the contact linearised at δ_eq.
///
/// Derivation: linearised, x'' = −ω²x − 2ζω v; velocity-Verlet with the dashpot evaluated at the
/// half-step velocity (LAMMPS/LIGGGHTS) maps (x_{n+1}, v_{n+1/2}) by a matrix with trace
/// 2 − h²ω² − 2ζhω and determinant 1 − 2ζhω; |λ| ≤ 1 (Jury) fails first at λ = −1, where
/// h²ω² + 4ζhω = 4. Damping *lowers* the limit.
pub fn dt_static(p: f64, alpha: f64, omega0: f64, accel: f64) -> Result<f64, Error> {
    if !accel.is_finite() || !omega0.is_finite() || !alpha.is_finite() {
        return Err(Error::NotFinite);
    }
    check_exponent(p)?;
    if !(accel > 0.0 && omega0 > 0.0) {
        return Err(Error::NotPositive);
    }
    if alpha < 0.0 {
        return Err(Error::Negative);
    }
    let ln_deq = (accel.ln() - 2.0 * omega0.ln()) / p;
    let z = alpha / (2.0 * p.sqrt());
    // √(1+ζ²) − ζ = 1/(√(1+ζ²) + ζ): no cancellation for large ζ.
    let factor = 1.0 / (z.hypot(1.0) + z);
    finite_positive(
        core::f64::consts::LN_2 + factor.ln()
            - omega0.ln()
            - 0.5 * p.ln()
            - 0.5 * (p - 1.0) * ln_deq,
    )
}
