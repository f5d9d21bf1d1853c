//! Restitution of the dimensionless LSD under both end-of-contact criteria, and its inverses.
//!
//! Solution (ζ < 1, ω = √(1-ζ²)): `x = e^{-ζs} sin(ωs)/ω`, `x' = e^{-ζs}(cos ωs - (ζ/ω) sin ωs)`.
//!
//! * Overlap end (x = 0 at ωs = π): `e_O = exp(-πζ/√(1-ζ²))`; for ζ ≥ 1 x never returns to 0
//!   (it decays towards 0 as s → ∞) and e_O = 0.
//! * Force end (x + 2ζx' = 0 while unloading). Writing ζ = sin γ, the force is proportional to
//!   `e^{-ζs}[cos 2γ sin ωs + sin 2γ cos ωs]/ω = e^{-ζs} sin(ωs + 2γ)/ω`, which vanishes at
//!   `ωs_F = π - 2γ = 2 arccos ζ`: exactly twice the phase of maximum compression
//!   (ωs_m = arccos ζ). There `x' = -e^{-ζ s_F}`, so
//!   `e_F = exp(-2ζ arccos(ζ)/√(1-ζ²)) = exp(-2 g(ζ))` with g from `decay.rs`. The overdamped
//!   branch (ζ = cosh γ, sinh instead of sin) gives the same analytic function,
//!   `exp(-2ζ arccosh(ζ)/√(ζ²-1))`: the force always returns to zero in finite time,
//!   e_F > 0 for every finite ζ, e_F(1) = e⁻², and e_F ≈ 1/(4ζ²) as ζ → ∞. This is eq. 12 of
//!   Schwager & Pöschel (2008) in one formula valid for every ζ ≥ 0.
//!
//! Both criteria agree as ζ → 0; for e = 0.5 the overlap-calibrated ζ realises e_F ≈ 0.550 in a
//! solver that clamps forces, which is why the force criterion needs its own inverse.

use super::decay::decay_to_turning_point_with_slope;
use crate::Error;
use crate::numerics::newton_bracketed;
use core::f64::consts::PI;

/// Critical damping ratio: the overlap criterion has no rebound at and above it.
pub const ZETA_CRITICAL: f64 = 1.0;

/// Overlap-end restitution `e_O(ζ)`; 0 for ζ ≥ 1 (no rebound). ζ ≥ 0, finite.
#[inline]
pub fn e_overlap(zeta: f64) -> f64 {
    if zeta >= ZETA_CRITICAL {
        return 0.0;
    }
    (-PI * zeta / ((1.0 - zeta) * (1.0 + zeta)).sqrt()).exp()
}

/// Force-end restitution `e_F(ζ) = exp(-2 g(ζ))`, positive for every finite ζ ≥ 0.
#[inline]
pub fn e_force(zeta: f64) -> f64 {
    (-2.0 * decay_to_turning_point_with_slope(zeta).0).exp()
}

/// The damping ratio whose overlap-end restitution is e, for e in (0, 1]:
/// `ζ = L/√(π² + L²)`, L = -ln e. Exact closed form; ζ < 1 for every e > 0.
#[inline]
pub fn zeta_overlap(e: f64) -> f64 {
    let l = -e.ln();
    l / PI.hypot(l)
}

/// The damping ratio whose force-end restitution is e, for e in (0, 1], to full double precision.
///
/// Solves g(ζ) = -ln(e)/2 by Newton's method safeguarded by a bracket: for e ≥ e⁻² the root lies
/// in [ζ_O(e), 1] (the force criterion always needs more damping than the overlap one), below e⁻²
/// in [1, 1/(2e)] because g(ζ) > ln 2ζ. g is increasing and concave, so Newton converges
/// monotonically once it is left of the root.
pub fn zeta_force(e: f64) -> Result<f64, Error> {
    let target = -0.5 * e.ln();
    if target == 0.0 {
        return Ok(0.0);
    }
    let f = |z: f64| {
        let (g, dg) = decay_to_turning_point_with_slope(z);
        (g - target, dg)
    };
    if target <= 1.0 {
        let lo = zeta_overlap(e);
        newton_bracketed(f, lo, 1.0, lo, 60)
    } else {
        // e^target / 2 = 1/(2 sqrt(e)): finite for every positive double e.
        let hi = 0.5 * target.exp();
        // Start from the asymptote g ≈ ln 2ζ + (ln 2ζ - 1/2)/(2ζ²), one fixed-point step in.
        let z0 = hi;
        let x0 = z0 * (-(target - 0.5) / (2.0 * z0 * z0)).exp();
        newton_bracketed(f, 1.0, hi, x0.clamp(1.0, hi), 200)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn critical_values() {
        assert_eq!(e_overlap(1.0), 0.0);
        assert_eq!(e_overlap(0.0), 1.0);
        assert_eq!(e_force(0.0), 1.0);
        assert!((e_force(1.0) - (-2.0f64).exp()).abs() < 1e-16);
    }

    #[test]
    fn force_criterion_always_bounces_higher() {
        // At the same ζ the force-end exit comes earlier, at higher speed.
        for i in 1..1000 {
            let z = i as f64 * 1e-3;
            assert!(e_force(z) > e_overlap(z));
        }
    }

    #[test]
    fn issue_example_half() {
        // A solver clamping forces with the overlap calibration for e = 0.5 realises ≈ 0.55.
        let e = e_force(zeta_overlap(0.5));
        assert!((e - 0.5503).abs() < 5e-4, "{e}");
    }

    #[test]
    fn inverse_force_round_trip() {
        let mut e = 1.0;
        while e > 1e-300 {
            let z = zeta_force(e).unwrap_or(f64::NAN);
            let back = e_force(z);
            // e = exp(-2g): one ulp of g ≈ |ln e|/2 costs |ln e|·ε relative in e.
            let tol = 8.0 * f64::EPSILON * (1.0 - e.ln());
            assert!(((back - e) / e).abs() < tol, "e={e:e} ζ={z} back={back:e}");
            e *= 0.93;
        }
    }

    #[test]
    fn overdamped_asymptote() {
        // e_F ≈ 1/(4ζ²) as ζ → ∞
        let z = 1e6;
        assert!((e_force(z) * 4.0 * z * z - 1.0).abs() < 1e-10);
    }
}
