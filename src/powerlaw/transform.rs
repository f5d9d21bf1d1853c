//! Constants of the phase-space map δ = A x^q, and the α ↔ ζ conversion.

use crate::Error;

/// Validates a force-law exponent: finite and p ≥ 1.
#[inline]
pub fn check_exponent(p: f64) -> Result<(), Error> {
    if !p.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(p >= 1.0) {
        return Err(Error::ExponentRange);
    }
    Ok(())
}

/// q = 2/(p+1): the exponent that makes the damping term of the mapped equation constant.
#[inline]
pub fn transform_q(p: f64) -> f64 {
    2.0 / (p + 1.0)
}

/// A = ((p+1)/2)^(1/(p+1)): the amplitude that makes the mapped spring term ω0² x.
#[inline]
pub fn transform_a(p: f64) -> f64 {
    (0.5 * (p + 1.0)).powf(1.0 / (p + 1.0))
}

/// √(2(p+1)): α = √(2(p+1))·ζ. Written as √2·√(p+1) so that huge p cannot overflow.
#[inline]
pub fn damping_scale(p: f64) -> f64 {
    core::f64::consts::SQRT_2 * (p + 1.0).sqrt()
}

/// The LSD damping ratio ζ of a power-law contact with damping coefficient α.
#[inline]
pub fn zeta_from_alpha(alpha: f64, p: f64) -> f64 {
    alpha / damping_scale(p)
}

/// The damping coefficient α of a power-law contact with LSD damping ratio ζ.
#[inline]
pub fn alpha_from_zeta(zeta: f64, p: f64) -> f64 {
    zeta * damping_scale(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_table_iii_constants() {
        // Table III of the seed: q, A, α_eff/α and f(p) for p = 1, 3/2, 2, 5/2, 3.
        let rows: [(f64, f64, f64, f64); 5] = [
            (1.0, 1.0, 1.0, 2.0),
            (1.5, 0.8, 1.25f64.powf(0.4), 5f64.sqrt()),
            (2.0, 2.0 / 3.0, 1.5f64.powf(1.0 / 3.0), 6f64.sqrt()),
            (2.5, 4.0 / 7.0, 1.75f64.powf(2.0 / 7.0), 7f64.sqrt()),
            (3.0, 0.5, 2f64.powf(0.25), 8f64.sqrt()),
        ];
        for (p, q, a, f) in rows {
            assert!((transform_q(p) - q).abs() < 1e-15);
            assert!((transform_a(p) - a).abs() < 1e-15);
            assert!((damping_scale(p) - f).abs() < 1e-15);
            assert!((zeta_from_alpha(1.0, p) - 1.0 / f).abs() < 1e-15);
        }
    }

    #[test]
    fn exponent_validation() {
        assert_eq!(check_exponent(1.0), Ok(()));
        assert_eq!(check_exponent(0.999), Err(Error::ExponentRange));
        assert_eq!(check_exponent(f64::NAN), Err(Error::NotFinite));
        assert_eq!(check_exponent(f64::INFINITY), Err(Error::NotFinite));
        assert!(damping_scale(f64::MAX).is_finite());
    }
}
