//! Fit of the elastic–plastic law (Thornton 1997, [`crate::force::elastic_plastic`]) to measured
//! restitution: e(v) = g(v/v_y) with Thornton's closed form g (1 below the yield speed), one
//! parameter, the yield speed v_y, by weighted least squares (weights 1/σᵢ², or 1 without σ).
//! From v_y and the contact's E*, R*, m* the limiting pressure follows:
//! δ_y = (15 m* v_y²/(16 E* √R*))^{2/5}, p_y = (2E*/π) √(δ_y/R*).
//!
//! The sum of squares is scanned over ln v_y on a grid of 400 points from v_min·10⁻⁶ to v_max
//! (each residual is monotone in v_y, the sum need not be unimodal), then refined by golden
//! section between the best point's neighbours to 1e-12 relative in v_y: exact data are
//! recovered to rounding. Data all at e = 1 do not fix v_y (any v_y ≥ v_max fits):
//! [`Error::FitDegenerate`].
//!
//! Standard error, as the restitution fits give theirs ([`super`]): linearised in u = ln v_y,
//! Jᵢ = ∂g(vᵢe^{−u})/∂u by a central difference (step 1e-5 in u; g is smooth except at the yield
//! speed itself, where the one-sided slopes differ and the difference takes their mean),
//! SE(u)² = 1/Σ(Jᵢ²/σᵢ²) with σ given, s²/ΣJᵢ² with s² = RSS/(n−1) otherwise. The 95 % interval
//! is exp(u ± q·SE(u)) with q from [`super::quantile::quantile95`] (Student's t with n − 1 degrees
//! of freedom when σ comes from the scatter): positive, asymmetric in v_y. Since δ_y ∝ v_y^{4/5}
//! and p_y ∝ √δ_y ∝ v_y^{2/5} at fixed E*, R*, m*, SE(ln p_y) = (2/5)·SE(u), and p_y's interval
//! is the pressures of v_y's interval ends.
//! Seeded coverage studies in tests/fit_elastic_plastic.rs check the level.

use super::Data;
use super::quantile::quantile95;
use crate::Error;
use crate::force::elastic_plastic::restitution;

/// The result of [`fit_yield_speed`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticPlasticFit {
    /// Yield speed v_y [m/s].
    pub v_y: f64,
    /// Weighted residual sum of squares.
    pub chi2: f64,
    /// Largest |eᵢ − g(vᵢ/v_y)|.
    pub max_residual: f64,
    /// Standard error of ln v_y (relative standard error of v_y, to first order).
    pub ln_v_y_se: f64,
    /// The multiplier of `ln_v_y_se` for the two-sided 95 % interval.
    pub quantile95: f64,
    /// Lower end of the 95 % interval of v_y [m/s]: v_y·exp(−quantile95·ln_v_y_se).
    pub v_y_lo95: f64,
    /// Upper end of the 95 % interval of v_y [m/s]: v_y·exp(+quantile95·ln_v_y_se).
    pub v_y_hi95: f64,
    /// True when the standard error comes from the residual scatter (no σ given).
    pub se_from_scatter: bool,
}

/// g(v/v_y) for v_y = e^u (NaN outside the closed form's domain).
fn model(v: f64, u: f64) -> f64 {
    restitution(v / u.exp()).unwrap_or(f64::NAN)
}

/// SE of u = ln v_y at the fitted u (see the module documentation).
fn ln_v_y_se(d: &Data, u: f64, chi2: f64) -> f64 {
    const H: f64 = 1e-5;
    let mut jtwj = 0.0;
    for i in 0..d.n() {
        let j = (model(d.v(i), u + H) - model(d.v(i), u - H)) / (2.0 * H);
        jtwj += d.w(i) * j * j;
    }
    let s2 = match d.sigma {
        Some(_) => 1.0,
        None => chi2 / (d.n() as f64 - 1.0),
    };
    (s2 / jtwj).sqrt()
}

fn chi2(d: &Data, v_y: f64) -> f64 {
    (0..d.n())
        .map(|i| {
            let g = restitution(d.v(i) / v_y).unwrap_or(f64::NAN);
            d.w(i) * (d.e(i) - g) * (d.e(i) - g)
        })
        .sum()
}

/// Fits v_y; see the module documentation. Errors as [`super::fit_restitution`]'s input checks,
/// and [`Error::FitDegenerate`] when every eᵢ is 1 or the data do not fix v_y (infinite SE).
pub fn fit_yield_speed(d: &Data) -> Result<ElasticPlasticFit, Error> {
    d.validate()?;
    let n = d.n();
    if (0..n).all(|i| d.e(i) == 1.0) {
        return Err(Error::FitDegenerate);
    }
    let (mut v_min, mut v_max) = (f64::INFINITY, 0.0f64);
    for i in 0..n {
        v_min = v_min.min(d.v(i));
        v_max = v_max.max(d.v(i));
    }
    let (lo, hi) = ((v_min * 1e-6).ln(), v_max.ln());
    const GRID: usize = 400;
    let at = |k: usize| lo + (hi - lo) * k as f64 / GRID as f64;
    let f = |u: f64| chi2(d, u.exp());
    let mut best = (0usize, f64::INFINITY);
    for k in 0..=GRID {
        let c = f(at(k));
        if c < best.1 {
            best = (k, c);
        }
    }
    let (mut a, mut b) = (at(best.0.saturating_sub(1)), at((best.0 + 1).min(GRID)));
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut x1, mut x2) = (b - r * (b - a), a + r * (b - a));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..200 {
        if b - a <= 1e-12 {
            break;
        }
        if f1 <= f2 {
            (b, x2, f2) = (x2, x1, f1);
            x1 = b - r * (b - a);
            f1 = f(x1);
        } else {
            (a, x1, f1) = (x1, x2, f2);
            x2 = a + r * (b - a);
            f2 = f(x2);
        }
    }
    let u = 0.5 * (a + b);
    let v_y = u.exp();
    let max_residual = (0..n)
        .map(|i| (d.e(i) - restitution(d.v(i) / v_y).unwrap_or(f64::NAN)).abs())
        .fold(0.0, f64::max);
    let chi2 = chi2(d, v_y);
    if !(v_y.is_finite() && v_y > 0.0 && chi2.is_finite()) {
        return Err(Error::NoConvergence);
    }
    let se = ln_v_y_se(d, u, chi2);
    // ΣJ² = 0 (every point where g is flat at the fit) leaves v_y undetermined: SE +∞.
    if !se.is_finite() {
        return Err(Error::FitDegenerate);
    }
    let se_from_scatter = d.sigma.is_none();
    let q = quantile95(n, se_from_scatter);
    Ok(ElasticPlasticFit {
        v_y,
        chi2,
        max_residual,
        ln_v_y_se: se,
        quantile95: q,
        v_y_lo95: (u - q * se).exp(),
        v_y_hi95: (u + q * se).exp(),
        se_from_scatter,
    })
}
