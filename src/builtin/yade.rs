//! YADE 2023.02a (`pkg/dem/ViscoelasticPM.cpp`, `pkg/dem/HertzMindlin.cpp`). Both laws clamp:
//! `if (normForceReal < 0) normalForce = 0` (ViscEl) and "no attraction force should be permitted
//! if particles are non-adhesive" (Mindlin), so the force-end criterion always applies.
//!
//! * `ViscElMat(tc, en, et)`: per material kn = 2 m_R (π² + ln²en)/tc², cn = −2·2 m_R ln(en)/tc
//!   (m_R = m1 m2/(m1 + m2)), combined in series (halved): the linear spring-dashpot with
//!   ζ = cn/(2√(m_R kn)) = |ln en|/√(π² + ln²en) = ζ_O(en), independent of tc.
//!   For explicit `kn`, `cn` see [`viscel_cn`].
//! * `Ip2_FrictMat_FrictMat_MindlinPhys(en=…)`: alpha = 2√(5/6)|β|√(2E√R), β = ln en/√(ln²en + π²),
//!   cn = alpha √m̄ δ^{1/4}; with Kno = (4/3) E √R, 2E√R = (3/2) Kno, so the damping is
//!   √5 |β| √(m̄ Kno) δ^{1/4}: Tsuji α = √5|β|, ζ = ζ_O(en).
//! * `Ip2_FrictMat_FrictMat_MindlinPhys(betan=…)`: cn = 2 betan √(m̄ kn) with the *tangent*
//!   stiffness kn = (3/2) Kno √δ, so α = 2√(3/2) betan = √6 betan, ζ = √(6/5) betan.

use super::check_typed_e;
use crate::{Error, lsd};

/// ζ of `ViscElMat(tc, en, et)` for a typed en ∈ (0, 1].
pub fn viscel_en_zeta(en: f64) -> Result<f64, Error> {
    Ok(lsd::zeta_overlap(check_typed_e(en)?))
}

/// ζ of `MindlinPhys` from a typed en ∈ (0, 1].
pub fn mindlin_en_zeta(en: f64) -> Result<f64, Error> {
    Ok(lsd::zeta_overlap(check_typed_e(en)?))
}

/// √(6/5): ζ per unit betan (α = √6 betan, ζ = α/√5).
const BETAN_TO_ZETA: f64 = 1.095_445_115_010_332_2;

/// ζ of `MindlinPhys` from a typed betan ≥ 0.
pub fn mindlin_betan_zeta(betan: f64) -> Result<f64, Error> {
    if !betan.is_finite() {
        return Err(Error::NotFinite);
    }
    if betan < 0.0 {
        return Err(Error::Negative);
    }
    Ok(betan * BETAN_TO_ZETA)
}

/// The betan that gives damping ratio ζ.
pub fn mindlin_betan_of_zeta(zeta: f64) -> f64 {
    zeta / BETAN_TO_ZETA
}

/// The contact damping cn [N s/m] for `ViscElMat(kn=…, cn=…)` (explicit linear law, always
/// clamped) realising e ∈ (0, 1], given the contact stiffness kn > 0 [N/m] and the reduced mass
/// m_R = m1 m2/(m1 + m2) > 0 [kg] (the dynamic body's mass against a wall). YADE combines the two
/// materials' values in series, so for two equal materials type 2·kn and 2·cn on each.
/// cn = 2 ζ_F(e) √(m_R kn); overdamped values (e < e⁻²) are fine.
pub fn viscel_cn(e: f64, kn: f64, m_reduced: f64) -> Result<f64, Error> {
    let e = check_typed_e(e)?;
    for x in [kn, m_reduced] {
        if !x.is_finite() {
            return Err(Error::NotFinite);
        }
        if !(x > 0.0) {
            return Err(Error::NotPositive);
        }
    }
    let zeta = lsd::zeta_force(e)?;
    let cn = 2.0 * zeta * (m_reduced.sqrt() * kn.sqrt());
    if cn.is_finite() {
        Ok(cn)
    } else {
        Err(Error::ResultRange)
    }
}

/// The restitution realised by `ViscElMat(kn=…, cn=…)` (clamped linear law).
pub fn viscel_e_of_cn(cn: f64, kn: f64, m_reduced: f64) -> Result<f64, Error> {
    if !cn.is_finite() || !kn.is_finite() || !m_reduced.is_finite() {
        return Err(Error::NotFinite);
    }
    if cn < 0.0 {
        return Err(Error::Negative);
    }
    if !(kn > 0.0 && m_reduced > 0.0) {
        return Err(Error::NotPositive);
    }
    let zeta = cn / (2.0 * m_reduced.sqrt() * kn.sqrt());
    Ok(lsd::e_force(zeta))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn betan_constant() {
        assert!((BETAN_TO_ZETA - (6.0f64 / 5.0).sqrt()).abs() < 1e-16);
    }

    #[test]
    fn cn_round_trip() {
        for e in [0.01, 0.1, 0.5, 0.9, 1.0] {
            let cn = viscel_cn(e, 1e5, 2e-3).unwrap_or(f64::NAN);
            let back = viscel_e_of_cn(cn, 1e5, 2e-3).unwrap_or(f64::NAN);
            assert!((back - e).abs() < 1e-14 * (1.0 + 1.0 / e), "{e} {back}");
        }
        assert_eq!(viscel_cn(0.5, 0.0, 1.0), Err(Error::NotPositive));
    }
}
