//! LAMMPS `pair_style granular` (`src/GRANULAR/gran_sub_mod_damping.cpp`, `granular_model.cpp`).
//!
//! The damping force is `−damp·√(m* Fn/δ)·vn` for both `tsuji` and `coeff_restitution`
//! (`gran_damping_tsuji_prefactor`), where Fn is the elastic normal force, so √(m* Fn/δ) =
//! √(m* k) δ^{(p−1)/2}: `damp` *is* the Tsuji α.
//!
//! * `coeff_restitution`: damp = 2|L|/√(π² + L²) for `hooke` (α = 2ζ, p = 1) and
//!   √(3/2)·2√(5/6)·|L|/√(π² + L²) = √5 |L|/√(π² + L²) otherwise (p = 3/2), L = ln e: exactly
//!   ζ = ζ_O(e).
//! * `tsuji`: damp = η(e), Tsuji's polynomial fit (Marshall 2009 eq. 53)
//!   η = 1.2728 − 4.2783e + 11.087e² − 22.348e³ + 27.467e⁴ − 18.022e⁵ + 4.8218e⁶, so
//!   ζ = η(e)/√(2(p+1)). η falls strictly from 1.2728 (e = 0) to 0.0003 (e = 1) (η' ≤ −0.459 on
//!   [0, 1]), so it is inverted uniquely, and only α inside that range can be realised. This is the
//!   22 Jul 2025 release (the PyPI wheel the harness runs, measured 0.616 for 0.5); later
//!   development versions multiply η by √2, which this module does not model.
//! * `limit_damping`: `if (Fntot < 0) Fntot = 0` — the force-end criterion.
//!
//! Reachable with `tsuji` (e typed in (0, 1]): Hertz e ∈ (0.1136, 0.99958), with `limit_damping`
//! (0.2628, 0.99958); hooke (0.0749, 0.99953) and (0.2337, 0.99953).

use super::check_typed_e;
use crate::numerics::newton_bracketed;
use crate::powerlaw::transform::{damping_scale, zeta_from_alpha};
use crate::{Error, lsd};

/// Tsuji's fit coefficients, constant term first, as LAMMPS types them.
const TSUJI: [f64; 7] = [1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218];

/// η(e) and η'(e) by Horner's scheme.
pub fn tsuji_eta(e: f64) -> (f64, f64) {
    let mut v = 0.0;
    let mut d = 0.0;
    for c in TSUJI.iter().rev() {
        d = d * e + v;
        v = v * e + c;
    }
    (v, d)
}

/// ζ of `damping coeff_restitution` for a typed e ∈ (0, 1].
pub fn coeff_restitution_zeta(e: f64) -> Result<f64, Error> {
    Ok(lsd::zeta_overlap(check_typed_e(e)?))
}

/// ζ of `damping tsuji` at exponent p for a typed e ∈ (0, 1].
pub fn tsuji_zeta(e: f64, p: f64) -> Result<f64, Error> {
    let e = check_typed_e(e)?;
    Ok(zeta_from_alpha(tsuji_eta(e).0, p))
}

/// The e to type into `damping tsuji` for damping ratio ζ, or [`Error::BuiltinUnreachable`]
/// when α = √(2(p+1)) ζ lies outside η's range [η(1), η(0)).
pub fn tsuji_value(zeta: f64, p: f64) -> Result<f64, Error> {
    let alpha = zeta * damping_scale(p);
    let (lo_alpha, _) = tsuji_eta(1.0);
    let (hi_alpha, _) = tsuji_eta(0.0);
    if !(alpha >= lo_alpha && alpha < hi_alpha) {
        return Err(Error::BuiltinUnreachable);
    }
    // η decreasing, so f = α − η(x) is increasing: f(0) < 0 ≤ f(1). Linear interpolation as
    // the start.
    let f = |x: f64| {
        let (v, d) = tsuji_eta(x);
        (alpha - v, -d)
    };
    let x0 = (hi_alpha - alpha) / (hi_alpha - lo_alpha);
    let x = newton_bracketed(f, 0.0, 1.0, x0, 100)?;
    if x > 0.0 && x <= 1.0 {
        Ok(x)
    } else {
        Err(Error::BuiltinUnreachable)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eta_derivative_matches_difference() {
        for i in 0..=20 {
            let e = i as f64 / 20.0;
            let h = 1e-6;
            let fd = (tsuji_eta(e + h).0 - tsuji_eta(e - h).0) / (2.0 * h);
            assert!((fd - tsuji_eta(e).1).abs() < 1e-7);
        }
        assert!((tsuji_eta(1.0).0 - 0.0003).abs() < 1e-12);
    }
}
