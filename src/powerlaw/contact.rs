//! One collision of the power-law Tsuji contact, validated once, with the constants of its image
//! under the phase-space map.
//!
//! With u = ω0 s (s the LSD parameter) the image is x(u) = (v0/ω0)·X(u), X(u) = e^{−ζu} S(u):
//!
//! ```text
//! S(u) = sin(ωu)/ω     ω  = √(1−ζ²)   (ζ < 1)
//! S(u) = u                            (ζ = 1)
//! S(u) = sinh(ω₂u)/ω₂  ω₂ = √(ζ²−1)   (ζ > 1)
//! ```
//!
//! which is one analytic function of ζ (sin(ωu)/ω → u as ω → 0), so critical damping is a
//! continuous limit. Physical quantities: δ = A x^q, v = dx/ds = v0·X'(u),
//! dt = A q x^{q−1} ds = (A q/ω0)(v0/ω0)^{q−1} X(u)^{q−1} du.

use super::transform::{check_exponent, transform_a, transform_q, zeta_from_alpha};
use crate::lsd;
use crate::Error;

/// The damping regime of the LSD image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Regime {
    /// ζ < 1, with ω = √(1−ζ²).
    Under(f64),
    /// ζ = 1.
    Critical,
    /// ζ > 1, with ω₂ = √(ζ²−1).
    Over(f64),
}

/// A validated collision.
#[derive(Clone, Copy, Debug)]
pub struct Contact {
    /// Force-law exponent p ≥ 1.
    pub p: f64,
    /// Damping coefficient α ≥ 0.
    pub alpha: f64,
    /// Impact speed v0 > 0.
    pub v0: f64,
    /// ω0 = √(k/m) > 0.
    pub omega0: f64,
    /// q = 2/(p+1).
    pub q: f64,
    /// A = ((p+1)/2)^(1/(p+1)).
    pub amp: f64,
    /// LSD damping ratio ζ = α/√(2(p+1)).
    pub zeta: f64,
    /// ln(v0/ω0): the scale of x.
    pub ln_x0: f64,
    /// Damping regime.
    pub regime: Regime,
}

impl Contact {
    /// Validates (p, α, v0, ω0): all finite, p ≥ 1, α ≥ 0, v0 > 0, ω0 > 0.
    pub fn new(p: f64, alpha: f64, v0: f64, omega0: f64) -> Result<Self, Error> {
        if !(alpha.is_finite() && v0.is_finite() && omega0.is_finite()) {
            return Err(Error::NotFinite);
        }
        check_exponent(p)?;
        if !(v0 > 0.0 && omega0 > 0.0) {
            return Err(Error::NotPositive);
        }
        if alpha < 0.0 {
            return Err(Error::Negative);
        }
        let zeta = zeta_from_alpha(alpha, p);
        let regime = if zeta < 1.0 {
            Regime::Under(((1.0 - zeta) * (1.0 + zeta)).sqrt())
        } else if zeta == 1.0 {
            Regime::Critical
        } else {
            // √(ζ−1)·√(ζ+1): no overflow of ζ² for huge ζ.
            Regime::Over((zeta - 1.0).sqrt() * (zeta + 1.0).sqrt())
        };
        Ok(Self {
            p,
            alpha,
            v0,
            omega0,
            q: transform_q(p),
            amp: transform_a(p),
            zeta,
            ln_x0: v0.ln() - omega0.ln(),
            regime,
        })
    }

    /// g(ζ): ln of the decay of X from impact to the turning point, X(u_m) = e^{−g}.
    pub fn g(&self) -> f64 {
        lsd::decay_to_turning_point(self.zeta)
    }

    /// Phase u_m = ω0 s_m of maximum overlap: arccos(ζ)/ω, continued (= g/ζ, arccosh(ζ)/ω₂).
    pub fn u_max(&self) -> f64 {
        match self.regime {
            Regime::Under(w) if self.zeta < 0.5 => self.zeta.acos() / w,
            _ => self.g() / self.zeta,
        }
    }

    /// Phase of the force zero: exactly twice the phase of maximum overlap.
    pub fn u_force(&self) -> f64 {
        2.0 * self.u_max()
    }

    /// Phase at which the overlap returns to zero, π/ω; `NoEvent` when ζ ≥ 1.
    pub fn u_overlap(&self) -> Result<f64, Error> {
        match self.regime {
            Regime::Under(w) => Ok(core::f64::consts::PI / w),
            _ => Err(Error::NoEvent),
        }
    }

    /// (S(u), S'(u)) of the module docs.
    pub fn s_and_slope(&self, u: f64) -> (f64, f64) {
        match self.regime {
            Regime::Under(w) => {
                let (s, c) = (w * u).sin_cos();
                (s / w, c)
            }
            Regime::Critical => (u, 1.0),
            Regime::Over(w2) => ((w2 * u).sinh() / w2, (w2 * u).cosh()),
        }
    }

    /// ln(S(u)/u) for u ≥ 0 (0 at u = 0), accurate in absolute terms, no overflow for huge ω₂u.
    pub fn ln_sinc(&self, u: f64) -> f64 {
        match self.regime {
            Regime::Under(w) => {
                let y = w * u;
                if y < 1e-4 {
                    -y * y / 6.0
                } else {
                    (y.sin() / y).ln()
                }
            }
            Regime::Critical => 0.0,
            Regime::Over(w2) => {
                let y = w2 * u;
                if y < 1e-4 {
                    y * y / 6.0
                } else if y < 20.0 {
                    (y.sinh() / y).ln()
                } else {
                    y - core::f64::consts::LN_2 - y.ln() + (-(-2.0 * y).exp()).ln_1p()
                }
            }
        }
    }

    /// ln S(u) for u > 0.
    pub fn ln_s(&self, u: f64) -> f64 {
        u.ln() + self.ln_sinc(u)
    }

    /// ln of the time scale (A q/ω0)(v0/ω0)^{q−1}: dt = exp(this)·X(u)^{q−1} du.
    pub fn ln_time_scale(&self) -> f64 {
        (self.amp * self.q).ln() + (self.q - 1.0) * self.ln_x0 - self.omega0.ln()
    }
}
