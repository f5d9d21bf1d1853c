//! Natural units of the viscoelastic collision and the one parameter b.
//!
//! `ξ'' + k ξ^{3/2} + γ √ξ ξ' = 0`, ξ(0) = 0, ξ'(0) = v. Put ξ = ξ* X, t = t* T with
//! ξ* = (v/√k)^{4/5} = v^{4/5} k^{−2/5} and t* = ξ*/v = v^{−1/5} k^{−2/5}. Dividing by ξ*/t*²:
//!
//! `X'' + (k ξ*^{1/2} t*²) X^{3/2} + (γ ξ*^{1/2} t*) √X X' = 0`,
//!
//! with k ξ*^{1/2} t*² = k · v^{2/5}k^{−1/5} · v^{−2/5}k^{−4/5} = 1 and
//! γ ξ*^{1/2} t* = γ · v^{2/5}k^{−1/5} · v^{−1/5}k^{−2/5} = γ k^{−3/5} v^{1/5}. So
//! `X'' + X^{3/2} + b √X X' = 0`, X(0) = 0, X'(0) = 1, **b = β v^{1/5}, β = γ k^{−3/5}**, and
//! e = −X'(end) depends on b alone.
//!
//! Material form (Brilliantov et al. 1996): F = ρ ξ^{3/2} + (3/2) A ρ √ξ ξ', m_eff ξ'' = −F, so
//! k = ρ/m_eff and γ = 3Aρ/(2 m_eff), hence β = (3/2) A ρ^{2/5} m_eff^{−2/5}.

use crate::Error;

fn positive(x: f64) -> Result<f64, Error> {
    if !x.is_finite() {
        Err(Error::NotFinite)
    } else if !(x > 0.0) {
        Err(Error::NotPositive)
    } else {
        Ok(x)
    }
}

fn non_negative(x: f64) -> Result<f64, Error> {
    if !x.is_finite() {
        Err(Error::NotFinite)
    } else if x < 0.0 {
        Err(Error::Negative)
    } else {
        Ok(x)
    }
}

fn finite(x: f64) -> Result<f64, Error> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::ResultRange)
    }
}

/// β = γ k^{−3/5} from the stiffness per unit mass k > 0 and damping per unit mass γ ≥ 0.
pub fn beta_from_k_gamma(k: f64, gamma: f64) -> Result<f64, Error> {
    let k = positive(k)?;
    let gamma = non_negative(gamma)?;
    finite(gamma * k.powf(-0.6))
}

/// (k, γ) = (ρ/m_eff, 3Aρ/(2 m_eff)) from the Hertz constant ρ > 0, the dissipative constant
/// A ≥ 0 (a time) and the effective mass m_eff > 0.
pub fn k_gamma_from_material(rho: f64, a: f64, m_eff: f64) -> Result<(f64, f64), Error> {
    let rho = positive(rho)?;
    let a = non_negative(a)?;
    let m = positive(m_eff)?;
    let k = finite(rho / m)?;
    let gamma = finite(1.5 * a * rho / m)?;
    Ok((k, gamma))
}

/// b = β v^{1/5} for β ≥ 0 and impact speed v > 0.
pub fn b_from_beta_speed(beta: f64, v: f64) -> Result<f64, Error> {
    let beta = non_negative(beta)?;
    let v = positive(v)?;
    finite(beta * v.powf(0.2))
}

/// Natural length and time scales (ξ*, t*) = (v^{4/5} k^{−2/5}, v^{−1/5} k^{−2/5}).
pub fn natural_scales(k: f64, v: f64) -> Result<(f64, f64), Error> {
    let k = positive(k)?;
    let v = positive(v)?;
    let kk = k.powf(-0.4);
    Ok((finite(v.powf(0.8) * kk)?, finite(v.powf(-0.2) * kk)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn material_to_beta() {
        // β from (k, γ) equals (3/2) A ρ^{2/5} m^{-2/5}
        let (rho, a, m) = (3.0e7, 2.0e-5, 0.01);
        let (k, g) = k_gamma_from_material(rho, a, m).unwrap_or((f64::NAN, f64::NAN));
        let beta = beta_from_k_gamma(k, g).unwrap_or(f64::NAN);
        let direct = 1.5 * a * rho.powf(0.4) * m.powf(-0.4);
        assert!(((beta - direct) / direct).abs() < 1e-14);
    }

    #[test]
    fn rejects_bad_input() {
        assert_eq!(beta_from_k_gamma(0.0, 1.0), Err(Error::NotPositive));
        assert_eq!(beta_from_k_gamma(1.0, -1.0), Err(Error::Negative));
        assert_eq!(b_from_beta_speed(f64::NAN, 1.0), Err(Error::NotFinite));
        assert_eq!(b_from_beta_speed(1.0, 0.0), Err(Error::NotPositive));
    }
}
