//! Calibration: from a measured restitution at a reference impact speed to the damping constant,
//! and the inverse question, the impact speed at which e reaches a value.
//!
//! e depends on b = β v^{1/5} alone and is strictly decreasing in b (checked on a dense grid by
//! the tests), so a target e ∈ (0, 1] fixes b uniquely: b(e) is found by a bracketed Newton
//! iteration on ln e(b) against s = ln b with the full-range tier. Then β = b / v_ref^{1/5},
//! A = β / ((3/2) ρ^{2/5} m_eff^{−2/5}), and the speed at which e is reached is v = (b/β)^5.

use super::full_range::e_full;
use super::scaling;
use crate::{EndCriterion, Error};

fn check_e(e: f64) -> Result<f64, Error> {
    if !e.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(e > 0.0 && e <= 1.0) {
        return Err(Error::RestitutionRange);
    }
    Ok(e)
}

/// The b at which the restitution equals e ∈ (0, 1] (b = 0 for e = 1), to about 1e-13 relative
/// in e(b); the result is as accurate as the full-range tier (1e-10 relative in e).
pub fn b_from_e(e: f64, criterion: EndCriterion) -> Result<f64, Error> {
    let e = check_e(e)?;
    if e == 1.0 {
        return Ok(0.0);
    }
    let target = e.ln();
    let f = |s: f64| -> f64 {
        let b = s.exp();
        e_full(b, criterion).map_or(f64::NAN, |v| target - v.ln())
    };
    // Bracket in s = ln b: e(tiny b) ≈ 1 - 1.15 b, and above, the asymptotic laws (inverted,
    // with a safety factor) give a b where e has fallen below the target.
    let b_small = (1.0 - e) / 1.2;
    let lo_b = if b_small > 0.0 {
        b_small * 0.5
    } else {
        f64::MIN_POSITIVE
    };
    let hi_b = match criterion {
        EndCriterion::Force => (1.4 / e).powf(0.6).max(1.0) * 2.0,
        EndCriterion::Overlap => (5.2 / e).powf(0.2).max(1.0) * 2.0,
    };
    let (lo, hi) = (lo_b.max(1e-300).ln(), hi_b.min(1e300).ln());
    if !(f(lo) <= 0.0) || !(f(hi) >= 0.0) {
        // e so small that b overflows the double range
        return Err(Error::ResultRange);
    }
    let x0 = match criterion {
        _ if e > 0.5 => b_small.max(1e-300).ln(),
        EndCriterion::Force => (1.31 / e).powf(0.6).ln(),
        EndCriterion::Overlap => (5.16 / e).powf(0.2).ln(),
    };
    // Newton on s = ln b, safeguarded by the bracket. s is an absolute scale (its error is the
    // relative error of b), so convergence is tested absolutely: |Δs| ≤ 4ε·max(1, |s|); a
    // relative test would never end at b = 1 (s = 0).
    let (mut lo, mut hi) = (lo, hi);
    let mut s = x0.clamp(lo, hi);
    let mut done = false;
    for _ in 0..200 {
        let fs = f(s);
        if fs == 0.0 {
            done = true;
            break;
        }
        if fs < 0.0 {
            lo = s;
        } else {
            hi = s;
        }
        let h = 1e-6;
        let d = (f(s + h) - f(s - h)) / (2.0 * h);
        let newton = s - fs / d;
        let next = if newton.is_finite() && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let tol = 4.0 * f64::EPSILON * s.abs().max(1.0);
        let step = (next - s).abs();
        s = next;
        if step <= tol || hi - lo <= tol {
            done = true;
            break;
        }
    }
    if !done {
        return Err(Error::NoConvergence);
    }
    let b = s.exp();
    if b.is_finite() {
        Ok(b)
    } else {
        Err(Error::ResultRange)
    }
}

/// β = γ k^{−3/5} that makes a collision at `v_ref` > 0 rebound with e ∈ (0, 1].
pub fn beta_from_e(e: f64, v_ref: f64, criterion: EndCriterion) -> Result<f64, Error> {
    let b = b_from_e(e, criterion)?;
    let unit = scaling::b_from_beta_speed(1.0, v_ref)?;
    let beta = b / unit;
    if beta.is_finite() {
        Ok(beta)
    } else {
        Err(Error::ResultRange)
    }
}

/// The dissipative constant A (a time) of the material law F = ρ ξ^{3/2} + (3/2) A ρ √ξ ξ' for
/// which a collision at `v_ref` rebounds with e; ρ > 0, m_eff > 0.
pub fn a_from_e(
    e: f64,
    v_ref: f64,
    rho: f64,
    m_eff: f64,
    criterion: EndCriterion,
) -> Result<f64, Error> {
    let beta = beta_from_e(e, v_ref, criterion)?;
    // β = (3/2) A ρ^{2/5} m^{−2/5}: β for A = 1 is the conversion factor.
    let (k, gamma1) = scaling::k_gamma_from_material(rho, 1.0, m_eff)?;
    let beta_per_a = scaling::beta_from_k_gamma(k, gamma1)?;
    let a = beta / beta_per_a;
    if a.is_finite() {
        Ok(a)
    } else {
        Err(Error::ResultRange)
    }
}

/// The impact speed at which the restitution equals e ∈ (0, 1], for β > 0: v = (b(e)/β)^5
/// (0 for e = 1: only a vanishing speed is elastic).
pub fn speed_for_e(e: f64, beta: f64, criterion: EndCriterion) -> Result<f64, Error> {
    let e = check_e(e)?;
    if !beta.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(beta > 0.0) {
        return Err(Error::NotPositive);
    }
    let b = b_from_e(e, criterion)?;
    let r = b / beta;
    let v = (r * r) * (r * r) * r;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::ResultRange)
    }
}

/// Restitution at impact speed v > 0 for stiffness and damping per unit mass k > 0, γ ≥ 0.
pub fn e_of_speed(k: f64, gamma: f64, v: f64, criterion: EndCriterion) -> Result<f64, Error> {
    let beta = scaling::beta_from_k_gamma(k, gamma)?;
    let b = scaling::b_from_beta_speed(beta, v)?;
    e_full(b, criterion)
}
