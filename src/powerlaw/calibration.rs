//! The damping coefficient α for a target restitution e, and e for a given α, under both
//! end-of-contact criteria, exact for every p ≥ 1 and independent of the impact speed.
//!
//! * Overlap end: `α = √(2(p+1))·L/√(π² + L²)`, L = -ln e (the seed's result). e = 0 is reached by
//!   every α ≥ √(2(p+1)) (critical damping and above: the overlap never returns to zero), so it
//!   does not determine α and is rejected; [`e_from_alpha`] returns 0 there.
//! * Force end: `e = exp(-2ζ arccos(ζ)/√(1-ζ²))` with ζ = α/√(2(p+1)), continued analytically
//!   through critical damping (see [`crate::lsd`]); it is positive for every finite α, so e = 0
//!   corresponds to α → ∞ and is rejected too.

use super::transform::{alpha_from_zeta, check_exponent, damping_scale, zeta_from_alpha};
use crate::Error;
use crate::criterion::EndCriterion;
use crate::lsd;

/// α for target restitution e ∈ (0, 1] and exponent p ≥ 1 under `criterion`.
pub fn alpha_from_e(e: f64, p: f64, criterion: EndCriterion) -> Result<f64, Error> {
    if !e.is_finite() {
        return Err(Error::NotFinite);
    }
    check_exponent(p)?;
    if !(e > 0.0 && e <= 1.0) {
        return Err(Error::RestitutionRange);
    }
    let zeta = match criterion {
        EndCriterion::Overlap => lsd::zeta_overlap(e),
        EndCriterion::Force => lsd::zeta_force(e)?,
    };
    let alpha = alpha_from_zeta(zeta, p);
    if !alpha.is_finite() {
        return Err(Error::ResultRange);
    }
    Ok(alpha)
}

/// Realised restitution e ∈ [0, 1] for damping coefficient α ≥ 0 and exponent p ≥ 1.
pub fn e_from_alpha(alpha: f64, p: f64, criterion: EndCriterion) -> Result<f64, Error> {
    if !alpha.is_finite() {
        return Err(Error::NotFinite);
    }
    check_exponent(p)?;
    if alpha < 0.0 {
        return Err(Error::Negative);
    }
    Ok(match criterion {
        EndCriterion::Overlap => {
            // e = exp(-πζ/√(1-ζ²)) written with α and s = √(2(p+1)) directly, because near
            // critical damping (e → 0) e is a steep function of α: 1 - ζ² = (s-α)(s+α)/s² keeps
            // s - α exact (Sterbenz) instead of rounding ζ = α/s first.
            let s = damping_scale(p);
            if alpha >= s {
                0.0
            } else {
                // For p beyond ~9e307 (s > ~1.3e154) the product overflows, which gave e = 1 for
                // any α (found by the fuzzer through the energy partition, whose fractions then
                // summed to 1.44): there the two roots are taken apart. Below, the bits are kept.
                let d = (s - alpha) * (s + alpha);
                let root = if d.is_finite() {
                    d.sqrt()
                } else {
                    (s - alpha).sqrt() * (s + alpha).sqrt()
                };
                (-core::f64::consts::PI * alpha / root).exp()
            }
        }
        EndCriterion::Force => lsd::e_force(zeta_from_alpha(alpha, p)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn antypov_elliott_hertz() {
        // p = 3/2, e = 0.5: α = √5·ln2/√(π² + ln²2)
        let l = 2f64.ln();
        let want = 5f64.sqrt() * l / (core::f64::consts::PI.powi(2) + l * l).sqrt();
        let got = alpha_from_e(0.5, 1.5, EndCriterion::Overlap).unwrap_or(f64::NAN);
        assert!((got - want).abs() < 1e-15);
    }

    #[test]
    fn rejects() {
        use EndCriterion::*;
        assert_eq!(
            alpha_from_e(0.0, 1.5, Overlap),
            Err(Error::RestitutionRange)
        );
        assert_eq!(
            alpha_from_e(1.0 + f64::EPSILON, 1.5, Force),
            Err(Error::RestitutionRange)
        );
        assert_eq!(alpha_from_e(f64::NAN, 1.5, Force), Err(Error::NotFinite));
        assert_eq!(alpha_from_e(0.5, 0.5, Force), Err(Error::ExponentRange));
        assert_eq!(e_from_alpha(-1.0, 1.5, Force), Err(Error::Negative));
        assert_eq!(
            e_from_alpha(f64::INFINITY, 1.5, Force),
            Err(Error::NotFinite)
        );
        assert_eq!(e_from_alpha(1e300, 1.5, Overlap), Ok(0.0));
    }

    #[test]
    fn elastic_limit() {
        assert_eq!(alpha_from_e(1.0, 2.0, EndCriterion::Force), Ok(0.0));
        assert_eq!(alpha_from_e(1.0, 2.0, EndCriterion::Overlap), Ok(0.0));
        assert_eq!(e_from_alpha(0.0, 2.0, EndCriterion::Force), Ok(1.0));
    }
}
