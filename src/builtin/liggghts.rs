//! LIGGGHTS-PUBLIC 3.8 (`/usr/include/liggghts/normal_model_hooke.h`, `normal_model_hertz.h`).
//!
//! * `model hertz`: kn = (4/3) Y* √(R*δ), damping γn = −2√(5/6) β √(Sn m*) with
//!   Sn = 2 Y* √(R*δ) and β = ln e/√(ln²e + π²). Since 2 Y*√R* = (3/2) k (k = (4/3) Y*√R*),
//!   γn = 2√(5/6)√(3/2) |β| √(m* k) δ^{1/4} = √5 |β| √(m* k) δ^{1/4}: a Tsuji contact with
//!   α = √5 |β|, i.e. ζ = α/√(2(p+1)) = |β| = ζ_O(e).
//! * `model hooke`: kn constant (from `characteristicVelocity`), γn = √(4 m* kn L²/(L² + π²)),
//!   L = ln e: the linear spring-dashpot with ζ = γn/(2√(m* kn)) = ζ_O(e).
//! * `limitForce on`: `if (Fn < 0) Fn = 0` — the force-end criterion. Off: no clamp.
//!
//! So both models realise e exactly without the clamp and e_F(ζ_O(e)) with it.

use super::check_typed_e;
use crate::{Error, lsd};

/// ζ of `model hooke` / `model hertz` for a typed `coefficientRestitution` e ∈ (0, 1].
pub fn zeta_of_e(e: f64) -> Result<f64, Error> {
    Ok(lsd::zeta_overlap(check_typed_e(e)?))
}
