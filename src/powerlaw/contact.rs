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
use crate::Error;
use crate::lsd;

/// Taylor coefficients a_n of ln(sin y / y) = Σ_{n≥1} a_n y^{2n},
/// a_n = (−1)^n 2^{2n−1} B_{2n}/(n (2n)!) (exact fractions from the Bernoulli numbers, rounded);
/// radius of convergence π. Used only for small |y| (≤ 0.35, where sin y / y loses relative
/// digits to cancellation in ln): twelve terms leave < 1e−25 there. With y² → −y² the same
/// series is ln(sinh y / y). The table keeps 30 terms for the test over |y| ≤ 1.7.
pub(crate) const LN_SINC: [f64; 30] = [
    -0.16666666666666666,
    -0.005555555555555556,
    -0.0003527336860670194,
    -2.6455026455026456e-05,
    -2.1377799155576935e-06,
    -1.803670234005331e-07,
    -1.5661391322766983e-08,
    -1.3884130493737299e-09,
    -1.2504359176004997e-10,
    -1.1402575602296091e-11,
    -1.0502923908637557e-12,
    -9.754877841593701e-14,
    -9.123468230859098e-15,
    -8.5837197618956095e-16,
    -8.117318009727789e-17,
    -7.710527514116273e-18,
    -7.352844932712002e-19,
    -7.036101210390652e-20,
    -6.753847290217444e-21,
    -6.500924115034318e-22,
    -6.273155486703286e-23,
    -6.067124691266807e-24,
    -5.880009395889198e-25,
    -5.709457821604065e-26,
    -5.553494634632887e-27,
    -5.410448555118999e-28,
    -5.278896052835726e-29,
    -5.157617108125312e-30,
    -5.045560125771855e-31,
    -4.941813866123941e-32,
];

/// |y| up to which the (short) series is used.
const LN_SINC_SERIES_MAX: f64 = 0.35;

/// Σ_{n ≤ terms} a_n z^n by Horner (z = y² for sin, −y² for sinh).
#[inline]
fn ln_sinc_series_n(z: f64, terms: usize) -> f64 {
    let mut acc = 0.0;
    for &a in LN_SINC.iter().take(terms).rev() {
        acc = acc * z + a;
    }
    acc * z
}

/// ln(sin y / y) for z = y² (ln(sinh y / y) for z = −y²), |z| ≤ (π/2)², to < 1e−17 absolute: all
/// 30 terms (they fall like (|z|/π²)^n/n) by Estrin's scheme, branch-free, for loops over
/// quadrature nodes that run in SIMD lanes.
#[inline(always)]
pub(crate) fn ln_sinc_poly(z: f64) -> f64 {
    z * crate::numerics::estrin::estrin(z, &LN_SINC)
}

#[inline]
fn ln_sinc_series(z: f64) -> f64 {
    ln_sinc_series_n(z, 12)
}

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
        Self::with_constants(p, alpha, v0, omega0, None)
    }

    /// As [`Contact::new`], with (q, A) of this p supplied by a caller that cached them (a
    /// duration plan) instead of recomputed (A costs a `powf`).
    pub(crate) fn with_constants(
        p: f64,
        alpha: f64,
        v0: f64,
        omega0: f64,
        qa: Option<(f64, f64)>,
    ) -> Result<Self, Error> {
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
        let (q, amp) = qa.unwrap_or_else(|| (transform_q(p), transform_a(p)));
        Ok(Self {
            p,
            alpha,
            v0,
            omega0,
            q,
            amp,
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
                if y <= LN_SINC_SERIES_MAX {
                    ln_sinc_series(y * y)
                } else {
                    (y.sin() / y).ln()
                }
            }
            Regime::Critical => 0.0,
            Regime::Over(w2) => {
                let y = w2 * u;
                if y <= LN_SINC_SERIES_MAX {
                    ln_sinc_series(-y * y)
                } else if y < 20.0 {
                    (y.sinh() / y).ln()
                } else {
                    y - core::f64::consts::LN_2 - y.ln() + (-(-2.0 * y).exp()).ln_1p()
                }
            }
        }
    }

    /// ln of the time scale (A q/ω0)(v0/ω0)^{q−1}: dt = exp(this)·X(u)^{q−1} du.
    pub fn ln_time_scale(&self) -> f64 {
        (self.amp * self.q).ln() + (self.q - 1.0) * self.ln_x0 - self.omega0.ln()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_sinc_series_matches_direct() {
        // Against sin/sinh and ln directly, where those are accurate (y not tiny).
        let mut y = 0.05;
        while y <= 1.7 {
            let terms = if y <= LN_SINC_SERIES_MAX { 12 } else { 30 };
            let s = ln_sinc_series_n(y * y, terms);
            let d = (y.sin() / y).ln();
            assert!((s - d).abs() < 4e-16, "sin y={y}: {s} vs {d}");
            if y <= core::f64::consts::FRAC_PI_2 {
                let s = ln_sinc_poly(y * y);
                assert!((s - d).abs() < 4e-16, "poly sin y={y}: {s} vs {d}");
                let s = ln_sinc_poly(-y * y);
                let d = (y.sinh() / y).ln();
                assert!((s - d).abs() < 4e-16, "poly sinh y={y}: {s} vs {d}");
            }
            let s = ln_sinc_series_n(-y * y, terms);
            let d = (y.sinh() / y).ln();
            assert!((s - d).abs() < 4e-16, "sinh y={y}: {s} vs {d}");
            y += 0.01;
        }
    }
}
