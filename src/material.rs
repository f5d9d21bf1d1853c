//! Material helpers: Hertz stiffness of two elastic spheres from their moduli, Poisson ratios
//! and radii, for host codes that carry materials rather than stiffnesses.
//!
//! `1/E* = (1-ν1²)/E1 + (1-ν2²)/E2`, `1/R* = 1/R1 + 1/R2`, and the Hertz force
//! `F = k δ^(3/2)` with `k = (4/3) E* √R*`.

use crate::Error;

/// One isotropic elastic material: E finite and > 0, ν in (−1, 1/2]. A bad ν is reported first
/// ([`Error::PoissonRange`]), then a bad E ([`Error::NotPositive`]), so every host names the same
/// fault.
pub fn check_material(e: f64, nu: f64) -> Result<(), Error> {
    if !e.is_finite() || !nu.is_finite() {
        return Err(Error::NotFinite);
    }
    // Thermodynamic bounds of an isotropic solid: E > 0 and -1 < ν < 1/2 (ν = 1/2 incompressible
    // is allowed: it only enters as 1 - ν²).
    if !(nu > -1.0 && nu <= 0.5) {
        return Err(Error::PoissonRange);
    }
    if !(e > 0.0) {
        return Err(Error::NotPositive);
    }
    Ok(())
}

/// Effective modulus E* of a contact between materials (E1, ν1) and (E2, ν2).
pub fn effective_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> Result<f64, Error> {
    check_material(e1, nu1)?;
    check_material(e2, nu2)?;
    // Written as a harmonic combination so that E up to f64::MAX cannot overflow.
    let c1 = (1.0 - nu1) * (1.0 + nu1) / e1;
    let c2 = (1.0 - nu2) * (1.0 + nu2) / e2;
    let es = 1.0 / (c1 + c2);
    if !es.is_finite() {
        return Err(Error::ResultRange);
    }
    Ok(es)
}

/// Effective radius R* = R1 R2/(R1 + R2). A flat wall is R = +inf on one side: pass it as
/// `f64::INFINITY`, which gives R* = the other radius.
pub fn effective_radius(r1: f64, r2: f64) -> Result<f64, Error> {
    if r1.is_nan() || r2.is_nan() || (r1.is_infinite() && r2.is_infinite()) {
        return Err(Error::NotFinite);
    }
    if !(r1 > 0.0 && r2 > 0.0) {
        return Err(Error::NotPositive);
    }
    let rs = if r1.is_infinite() {
        r2
    } else if r2.is_infinite() {
        r1
    } else {
        1.0 / (1.0 / r1 + 1.0 / r2)
    };
    Ok(rs)
}

/// Hertz stiffness k = (4/3) E* √R* [N/m^(3/2)].
pub fn hertz_stiffness(e_star: f64, r_star: f64) -> Result<f64, Error> {
    if !e_star.is_finite() || !r_star.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(e_star > 0.0 && r_star > 0.0) {
        return Err(Error::NotPositive);
    }
    let k = 4.0 / 3.0 * e_star * r_star.sqrt();
    if !k.is_finite() {
        return Err(Error::ResultRange);
    }
    Ok(k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glass_beads() {
        // Two identical spheres: E* = E/(2(1-ν²)), R* = R/2.
        let (e, nu, r) = (63e9, 0.23, 1e-3);
        let es = effective_modulus(e, nu, e, nu).unwrap_or(f64::NAN);
        assert!((es - e / (2.0 * (1.0 - nu * nu))).abs() < 1e-15 * es);
        let rs = effective_radius(r, r).unwrap_or(f64::NAN);
        assert!((rs - r / 2.0).abs() < 1e-18);
        let k = hertz_stiffness(es, rs).unwrap_or(f64::NAN);
        assert!((k - 4.0 / 3.0 * es * (r / 2.0f64).sqrt()).abs() < 1e-15 * k);
    }

    #[test]
    fn wall_and_bad_input() {
        assert_eq!(effective_radius(f64::INFINITY, 2e-3), Ok(2e-3));
        assert_eq!(
            effective_radius(f64::INFINITY, f64::INFINITY),
            Err(Error::NotFinite)
        );
        assert_eq!(effective_radius(-1.0, 1.0), Err(Error::NotPositive));
        for nu in [0.6, 0.5000000000000001, -1.0, -7.0] {
            assert_eq!(
                effective_modulus(1e9, 0.3, 1e9, nu),
                Err(Error::PoissonRange),
                "nu = {nu}"
            );
        }
        // The range's ends: 1/2 (incompressible) is allowed, -1 is not.
        assert!(effective_modulus(1e9, 0.5, 1e9, -0.999_999).is_ok());
        // A bad ratio is named even when the modulus is bad too.
        assert_eq!(
            effective_modulus(-1e9, 0.6, 1e9, 0.3),
            Err(Error::PoissonRange)
        );
        assert_eq!(
            effective_modulus(0.0, 0.3, 1e9, 0.3),
            Err(Error::NotPositive)
        );
        assert_eq!(
            effective_modulus(f64::NAN, 0.3, 1e9, 0.3),
            Err(Error::NotFinite)
        );
        assert!(effective_modulus(f64::MAX, 0.3, f64::MAX, 0.3).is_ok());
    }
}
