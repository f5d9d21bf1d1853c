//! Fitting measured restitution: which model do the data require?
//!
//! Given measured pairs (impact speed vᵢ, restitution eᵢ) with optional standard uncertainties σᵢ,
//! two models are fitted by weighted least squares (weights 1/σᵢ², or 1 without σ):
//!
//! * **viscoelastic** (one material constant β): e(v) = e_full(β v^{1/5}) over the full range of
//!   b ([`crate::viscoelastic::full_range`]), under the host's end criterion. β is found by
//!   Gauss–Newton with step halving, started from the median of the single-point calibrations
//!   βᵢ = b(eᵢ)/vᵢ^{1/5}; ∂e/∂β = e'(b) v^{1/5} by central differences (only the search direction
//!   uses it: with exact data the fixed point is the zero-residual β, so exact data are recovered
//!   to rounding).
//! * **constant e** (the power-law Tsuji contact, any p): the weighted mean.
//!
//! Standard errors: with σᵢ given, the linearised covariance 1/Σ(Jᵢ²/σᵢ²) (σ taken as known);
//! without, s²/ΣJᵢ² with s² = RSS/(n−1). The reported 95 % interval is β ± q·SE with q the
//! 0.975 quantile of Student's t with n − 1 degrees of freedom when σ comes from the scatter (one
//! parameter fitted; the ratio (β̂ − β)/SE is t-distributed there, not normal), and of the normal
//! distribution (1.959964) when σ is given ([`quantile`]). Seeded coverage studies in
//! tests/fit.rs check the level. Robust option: Huber IRLS (c = 1.345) on residuals
//! standardised by σᵢ (given) or by 1.4826·MAD (not given); the reported standard error is then the
//! weighted one at the final Huber weights (approximate for outlying points).
//!
//! Model choice ("model only what a scene requires"): over the measured speed range the
//! viscoelastic fit is monotone in v, so its largest deviation from the constant-e fit is at
//! v_min or v_max. If that deviation is ≤ tol, a constant e (the power law) represents what the
//! data support within the user's tolerance; otherwise the speed dependence is required.

pub mod elastic_plastic;
pub mod quantile;
pub mod robust;

use crate::viscoelastic::{calibration::b_from_e, full_range::e_full};
use crate::{EndCriterion, Error};
use robust::{MAD_TO_SIGMA, huber_weight, median};

/// Which model the data require at the user's tolerance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelChoice {
    /// Constant e (power-law contact): the viscoelastic speed dependence over the measured range
    /// stays within tol.
    Constant,
    /// The speed dependence exceeds tol over the measured range: use the viscoelastic model.
    Viscoelastic,
}

/// Options of [`fit_restitution`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitOptions {
    /// End-of-contact criterion of the host (clamping codes: [`EndCriterion::Force`]).
    pub criterion: EndCriterion,
    /// Tolerance on e for the model choice, > 0.
    pub tol: f64,
    /// Huber IRLS instead of plain weighted least squares.
    pub robust: bool,
}

/// The result of [`fit_restitution`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// Viscoelastic constant β [s^{1/5} m^{-1/5}]: e = e_full(β v^{1/5}).
    pub beta: f64,
    /// Standard error of β.
    pub beta_se: f64,
    /// The multiplier of the standard errors for a two-sided 95 % interval: t_{0.975, n−1}
    /// (σ from the scatter) or z_{0.975} = 1.959964 (σ given).
    pub quantile95: f64,
    /// β − quantile95·beta_se: lower end of the 95 % interval of β (may be below 0, β's bound).
    pub beta_lo95: f64,
    /// β + quantile95·beta_se: upper end of the 95 % interval of β.
    pub beta_hi95: f64,
    /// Constant-e fit.
    pub e_const: f64,
    /// Standard error of the constant e.
    pub e_const_se: f64,
    /// Weighted residual sum of squares, viscoelastic.
    pub chi2_viscoelastic: f64,
    /// Weighted residual sum of squares, constant e.
    pub chi2_constant: f64,
    /// Largest |eᵢ − fitted| of the viscoelastic fit.
    pub max_residual_viscoelastic: f64,
    /// Largest |eᵢ − fitted| of the constant-e fit.
    pub max_residual_constant: f64,
    /// Smallest measured speed.
    pub v_min: f64,
    /// Largest measured speed.
    pub v_max: f64,
    /// Viscoelastic fit at v_min.
    pub e_viscoelastic_at_v_min: f64,
    /// Viscoelastic fit at v_max.
    pub e_viscoelastic_at_v_max: f64,
    /// Largest |e_viscoelastic(v) − e_const| over [v_min, v_max].
    pub max_model_deviation: f64,
    /// The model the data require at tol.
    pub model: ModelChoice,
    /// True when the standard errors come from the residual scatter (no σ given).
    pub se_from_scatter: bool,
    /// Gauss–Newton iterations of the viscoelastic fit (summed over IRLS rounds).
    pub iterations: u32,
}

/// A view of the measurements: speeds, restitutions, optional uncertainties.
#[derive(Clone, Copy, Debug)]
pub struct Data<'a> {
    /// Impact speeds vᵢ > 0.
    pub v: &'a [f64],
    /// Measured restitution eᵢ ∈ (0, 1].
    pub e: &'a [f64],
    /// Standard uncertainties σᵢ > 0 of eᵢ, or `None`.
    pub sigma: Option<&'a [f64]>,
}

impl Data<'_> {
    fn n(&self) -> usize {
        self.v.len()
    }
    fn v(&self, i: usize) -> f64 {
        self.v.get(i).copied().unwrap_or(f64::NAN)
    }
    fn e(&self, i: usize) -> f64 {
        self.e.get(i).copied().unwrap_or(f64::NAN)
    }
    /// Base weight 1/σᵢ² (1 without σ).
    fn w(&self, i: usize) -> f64 {
        match self.sigma {
            Some(s) => {
                let si = s.get(i).copied().unwrap_or(f64::NAN);
                1.0 / (si * si)
            }
            None => 1.0,
        }
    }

    fn validate(&self) -> Result<(), Error> {
        let n = self.n();
        if self.e.len() != n || self.sigma.is_some_and(|s| s.len() != n) {
            return Err(Error::BufferTooShort);
        }
        if n < 2 {
            return Err(Error::FitTooFew);
        }
        for i in 0..n {
            let (v, e) = (self.v(i), self.e(i));
            let s = self
                .sigma
                .map_or(1.0, |s| s.get(i).copied().unwrap_or(f64::NAN));
            if !v.is_finite() || !e.is_finite() || !s.is_finite() {
                return Err(Error::NotFinite);
            }
            if !(v > 0.0) || !(s > 0.0) {
                return Err(Error::NotPositive);
            }
            if !(e > 0.0 && e <= 1.0) {
                return Err(Error::RestitutionRange);
            }
            if !(self.w(i) > 0.0 && self.w(i).is_finite()) {
                return Err(Error::FitDegenerate);
            }
        }
        let v0 = self.v(0);
        if (1..n).all(|i| self.v(i) == v0) {
            return Err(Error::FitDegenerate);
        }
        Ok(())
    }
}

/// The viscoelastic model e(β, v).
fn model(beta: f64, v: f64, c: EndCriterion) -> Result<f64, Error> {
    e_full(beta * v.powf(0.2), c)
}

/// ∂e/∂β at (β, v) by a central difference in b (one-sided at b = 0).
fn slope(beta: f64, v: f64, c: EndCriterion) -> Result<f64, Error> {
    let s = v.powf(0.2);
    let b = beta * s;
    let h = 1e-6 * b.max(1e-3);
    let d = if b > h {
        (e_full(b + h, c)? - e_full(b - h, c)?) / (2.0 * h)
    } else {
        (e_full(b + h, c)? - e_full(b, c)?) / h
    };
    Ok(d * s)
}

/// Σ wᵢ hᵢ (eᵢ − model)² for the viscoelastic model with IRLS weights h(i).
fn rss(d: &Data, beta: f64, c: EndCriterion, h: &impl Fn(usize) -> f64) -> Result<f64, Error> {
    let mut s = 0.0;
    for i in 0..d.n() {
        let r = d.e(i) - model(beta, d.v(i), c)?;
        s += d.w(i) * h(i) * r * r;
    }
    Ok(s)
}

/// Weighted Gauss–Newton for β from `beta0` with IRLS weights h(i). Returns (β, iterations).
fn gauss_newton(
    d: &Data,
    beta0: f64,
    c: EndCriterion,
    h: &impl Fn(usize) -> f64,
) -> Result<(f64, u32), Error> {
    let mut beta = beta0;
    let mut s = rss(d, beta, c, h)?;
    for it in 1..=200u32 {
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..d.n() {
            let v = d.v(i);
            let r = d.e(i) - model(beta, v, c)?;
            let j = slope(beta, v, c)?;
            let w = d.w(i) * h(i);
            num += w * j * r;
            den += w * j * j;
        }
        if !(den > 0.0) {
            return Err(Error::FitDegenerate);
        }
        let step = num / den;
        // Step halving keeps S strictly decreasing and β ≥ 0. Strictly: at the minimum S is flat
        // to rounding over a few ulps of β, and accepting equal S let the numerically
        // differentiated step cycle between two such β (seen on noisy n = 6 data) until the
        // iteration limit.
        let mut t = 1.0;
        let mut accepted = None;
        for _ in 0..60 {
            let cand = (beta + t * step).max(0.0);
            let sc = rss(d, cand, c, h)?;
            if sc < s {
                accepted = Some((cand, sc));
                break;
            }
            t *= 0.5;
        }
        let Some((cand, sc)) = accepted else {
            // No strict decrease: S is flat to rounding here, over a band of β whose width
            // (≈ √ε·SE) depends on rounding, e.g. on the order of the points. A small
            // Gauss–Newton step lands on the stationary point (zero gradient), which does not:
            // take it and stop.
            if step.abs() <= 1e-6 * beta.max(f64::MIN_POSITIVE) {
                return Ok(((beta + step).max(0.0), it));
            }
            return Ok((beta, it)); // no decrease possible: at the minimum to rounding
        };
        let moved = (cand - beta).abs();
        beta = cand;
        s = sc;
        if moved <= 4.0 * f64::EPSILON * beta.max(f64::MIN_POSITIVE) || s == 0.0 {
            return Ok((beta, it));
        }
    }
    Err(Error::NoConvergence)
}

/// Fits both models to the data; see the module documentation.
///
/// Errors: [`Error::BufferTooShort`] (slices of different lengths), [`Error::FitTooFew`] (n < 2),
/// [`Error::NotFinite`], [`Error::NotPositive`] (v or σ ≤ 0, tol ≤ 0),
/// [`Error::RestitutionRange`] (e ∉ (0, 1]), [`Error::FitDegenerate`] (all speeds equal),
/// [`Error::NoConvergence`].
pub fn fit_restitution(d: &Data, opt: &FitOptions) -> Result<Fit, Error> {
    if !opt.tol.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(opt.tol > 0.0) {
        return Err(Error::NotPositive);
    }
    d.validate()?;
    let n = d.n();
    let c = opt.criterion;

    // Start: the median of the one-point calibrations.
    let beta_i = |i: usize| match b_from_e(d.e(i), c) {
        Ok(b) => b / d.v(i).powf(0.2),
        Err(_) => f64::NAN,
    };
    let beta0 = median(n, beta_i);
    let beta0 = if beta0.is_finite() { beta0 } else { 0.0 };

    let se_from_scatter = d.sigma.is_none();
    let mut iterations = 0u32;
    let ones = |_: usize| 1.0;
    let (mut beta, it) = gauss_newton(d, beta0, c, &ones)?;
    iterations += it;
    let mut e_const = weighted_mean(d, &ones);

    // Huber IRLS: weights from the current residuals, refit, until β settles.
    let mut hw_beta = beta;
    let mut hw_const = e_const;
    if opt.robust {
        for _ in 0..50 {
            let scale_ve = residual_scale(d, |i| {
                d.e(i) - model(hw_beta, d.v(i), c).unwrap_or(f64::NAN)
            });
            let scale_c = residual_scale(d, |i| d.e(i) - hw_const);
            let (b_prev, c_prev) = (hw_beta, hw_const);
            let h_ve = |i: usize| {
                let r = d.e(i) - model(b_prev, d.v(i), c).unwrap_or(f64::NAN);
                irls_weight(r * d.w(i).sqrt(), scale_ve)
            };
            let (nb, it) = gauss_newton(d, b_prev, c, &h_ve)?;
            iterations += it;
            let h_c = |i: usize| irls_weight((d.e(i) - c_prev) * d.w(i).sqrt(), scale_c);
            hw_const = weighted_mean(d, &h_c);
            hw_beta = nb;
            if (hw_beta - b_prev).abs() <= 1e-12 * hw_beta.max(f64::MIN_POSITIVE)
                && (hw_const - c_prev).abs() <= 1e-14
            {
                break;
            }
        }
        beta = hw_beta;
        e_const = hw_const;
    }
    // Final weights (Huber at the final residuals, or 1).
    let scale_ve = residual_scale(d, |i| d.e(i) - model(beta, d.v(i), c).unwrap_or(f64::NAN));
    let scale_c = residual_scale(d, |i| d.e(i) - e_const);
    let h_ve = |i: usize| {
        if opt.robust {
            let r = d.e(i) - model(beta, d.v(i), c).unwrap_or(f64::NAN);
            irls_weight(r * d.w(i).sqrt(), scale_ve)
        } else {
            1.0
        }
    };
    let h_c = |i: usize| {
        if opt.robust {
            irls_weight((d.e(i) - e_const) * d.w(i).sqrt(), scale_c)
        } else {
            1.0
        }
    };

    let (mut chi2_ve, mut chi2_c, mut jj, mut ww) = (0.0, 0.0, 0.0, 0.0);
    let (mut max_ve, mut max_c) = (0.0f64, 0.0f64);
    let (mut v_min, mut v_max) = (f64::INFINITY, 0.0f64);
    for i in 0..n {
        let v = d.v(i);
        let r_ve = d.e(i) - model(beta, v, c)?;
        let r_c = d.e(i) - e_const;
        let j = slope(beta, v, c)?;
        chi2_ve += d.w(i) * r_ve * r_ve;
        chi2_c += d.w(i) * r_c * r_c;
        jj += d.w(i) * h_ve(i) * j * j;
        ww += d.w(i) * h_c(i);
        max_ve = max_ve.max(r_ve.abs());
        max_c = max_c.max(r_c.abs());
        v_min = v_min.min(v);
        v_max = v_max.max(v);
    }
    let dof = (n - 1) as f64;
    let (var_beta, var_c) = if se_from_scatter {
        (chi2_ve / dof / jj, chi2_c / dof / ww)
    } else {
        (1.0 / jj, 1.0 / ww)
    };
    let e_lo = model(beta, v_min, c)?;
    let e_hi = model(beta, v_max, c)?;
    let dev = (e_lo - e_const).abs().max((e_hi - e_const).abs());
    let beta_se = var_beta.sqrt();
    let q95 = quantile::quantile95(n, se_from_scatter);
    let fit = Fit {
        beta,
        beta_se,
        quantile95: q95,
        beta_lo95: beta - q95 * beta_se,
        beta_hi95: beta + q95 * beta_se,
        e_const,
        e_const_se: var_c.sqrt(),
        chi2_viscoelastic: chi2_ve,
        chi2_constant: chi2_c,
        max_residual_viscoelastic: max_ve,
        max_residual_constant: max_c,
        v_min,
        v_max,
        e_viscoelastic_at_v_min: e_lo,
        e_viscoelastic_at_v_max: e_hi,
        max_model_deviation: dev,
        model: if dev <= opt.tol {
            ModelChoice::Constant
        } else {
            ModelChoice::Viscoelastic
        },
        se_from_scatter,
        iterations,
    };
    if [
        fit.beta,
        fit.beta_se,
        fit.beta_lo95,
        fit.beta_hi95,
        fit.e_const,
        fit.e_const_se,
        fit.chi2_viscoelastic,
    ]
    .iter()
    .all(|x| x.is_finite())
    {
        Ok(fit)
    } else {
        Err(Error::FitDegenerate)
    }
}

/// Residuals eᵢ − fitted of both models into `viscoelastic` and `constant` (each ≥ n long; an
/// empty slice skips that model). Nothing is written on error.
pub fn residuals(
    d: &Data,
    fit: &Fit,
    criterion: EndCriterion,
    viscoelastic: &mut [f64],
    constant: &mut [f64],
) -> Result<(), Error> {
    d.validate()?;
    let n = d.n();
    for out in [&*viscoelastic, &*constant] {
        if !out.is_empty() && out.len() < n {
            return Err(Error::BufferTooShort);
        }
    }
    // Evaluate first (errors possible), write after.
    for i in 0..n {
        model(fit.beta, d.v(i), criterion)?;
    }
    for (i, slot) in viscoelastic.iter_mut().take(n).enumerate() {
        *slot = d.e(i) - model(fit.beta, d.v(i), criterion).unwrap_or(f64::NAN);
    }
    for (i, slot) in constant.iter_mut().take(n).enumerate() {
        *slot = d.e(i) - fit.e_const;
    }
    Ok(())
}

fn weighted_mean(d: &Data, h: &impl Fn(usize) -> f64) -> f64 {
    let (mut s, mut w) = (0.0, 0.0);
    for i in 0..d.n() {
        let wi = d.w(i) * h(i);
        s += wi * d.e(i);
        w += wi;
    }
    s / w
}

/// Residual scale for the IRLS: 1 when σ is given (residuals are standardised by it), else
/// 1.4826·MAD of the residuals.
fn residual_scale(d: &Data, r: impl Fn(usize) -> f64) -> f64 {
    if d.sigma.is_some() {
        return 1.0;
    }
    let med = median(d.n(), &r);
    MAD_TO_SIGMA * median(d.n(), |i| (r(i) - med).abs())
}

/// Huber weight of a (σ-standardised) residual at scale s; 1 when s is 0 (exact data).
fn irls_weight(r: f64, s: f64) -> f64 {
    if s > 0.0 && r.is_finite() {
        huber_weight(r / s)
    } else {
        1.0
    }
}
