//! Export: fit measured restitution against the viscoelastic and the constant-e models.

use super::{guard, parse_criterion, status::*};
use crate::Error;
use crate::fit::{self, Data, Fit, FitOptions, ModelChoice};

/// dc_fit_result.model: a constant e (power-law contact) represents the data within tol.
pub const DC_FIT_MODEL_CONSTANT: i32 = 0;
/// dc_fit_result.model: the speed dependence exceeds tol; use the viscoelastic model.
pub const DC_FIT_MODEL_VISCOELASTIC: i32 = 1;

/// Result of dc_fit_restitution. Viscoelastic model: e(v) = e_full(beta v^(1/5)) (see
/// dc_viscoelastic_e); constant model: e(v) = e_const.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct dc_fit_result {
    /// Viscoelastic constant beta [s^(1/5) m^(-1/5)], b = beta v^(1/5).
    pub beta: f64,
    /// Standard error of beta.
    pub beta_se: f64,
    /// Constant-e fit (weighted mean).
    pub e_const: f64,
    /// Standard error of e_const.
    pub e_const_se: f64,
    /// Weighted residual sum of squares of the viscoelastic fit.
    pub chi2_viscoelastic: f64,
    /// Weighted residual sum of squares of the constant fit.
    pub chi2_constant: f64,
    /// Largest |e_i - fitted| of the viscoelastic fit.
    pub max_residual_viscoelastic: f64,
    /// Largest |e_i - fitted| of the constant fit.
    pub max_residual_constant: f64,
    /// Smallest measured speed.
    pub v_min: f64,
    /// Largest measured speed.
    pub v_max: f64,
    /// Viscoelastic fit at v_min.
    pub e_viscoelastic_at_v_min: f64,
    /// Viscoelastic fit at v_max.
    pub e_viscoelastic_at_v_max: f64,
    /// Largest |e_viscoelastic(v) - e_const| over [v_min, v_max] (at an end: e(v) is monotone).
    pub max_model_deviation: f64,
    /// DC_FIT_MODEL_CONSTANT if max_model_deviation <= tol, else DC_FIT_MODEL_VISCOELASTIC.
    pub model: i32,
    /// 1 if the standard errors come from the residual scatter (sigma NULL), 0 if from sigma.
    pub se_from_scatter: i32,
    /// Gauss-Newton iterations used (summed over robust rounds).
    pub iterations: i32,
    /// 1 if the Huber-robust fit was used.
    pub robust: i32,
}

impl dc_fit_result {
    fn from(f: &Fit, robust: bool) -> Self {
        Self {
            beta: f.beta,
            beta_se: f.beta_se,
            e_const: f.e_const,
            e_const_se: f.e_const_se,
            chi2_viscoelastic: f.chi2_viscoelastic,
            chi2_constant: f.chi2_constant,
            max_residual_viscoelastic: f.max_residual_viscoelastic,
            max_residual_constant: f.max_residual_constant,
            v_min: f.v_min,
            v_max: f.v_max,
            e_viscoelastic_at_v_min: f.e_viscoelastic_at_v_min,
            e_viscoelastic_at_v_max: f.e_viscoelastic_at_v_max,
            max_model_deviation: f.max_model_deviation,
            model: match f.model {
                ModelChoice::Constant => DC_FIT_MODEL_CONSTANT,
                ModelChoice::Viscoelastic => DC_FIT_MODEL_VISCOELASTIC,
            },
            se_from_scatter: i32::from(f.se_from_scatter),
            iterations: i32::try_from(f.iterations).unwrap_or(i32::MAX),
            robust: i32::from(robust),
        }
    }
}

/// Byte range of n doubles at ptr, or None if misaligned or too large to address.
fn span(ptr: *const f64, n: usize) -> Option<(usize, usize)> {
    let bytes = n.checked_mul(core::mem::size_of::<f64>())?;
    if ptr.is_null() || !ptr.is_aligned() || bytes > isize::MAX as usize {
        return None;
    }
    let start = ptr as usize;
    Some((start, start.checked_add(bytes)?))
}

/// Fits measured restitution e_i at impact speeds v_i (optional standard uncertainties sigma_i)
/// with the viscoelastic model (one constant beta, full range of b = beta v^(1/5)) and with a
/// constant e, by weighted least squares (weights 1/sigma_i^2), and says which the data require:
/// the constant e when the viscoelastic fit departs from it by at most `tol` over [v_min, v_max].
/// Standard errors from the linearised covariance (sigma given: taken as known; NULL: from the
/// residual scatter, s^2 = RSS/(n-1)); for a 95 % interval multiply them by
/// dc_fit_quantile95(n, se_from_scatter) (Student t with n-1 degrees of freedom from the
/// scatter, not 2). `robust` = 1: Huber IRLS (c = 1.345; residuals scaled by
/// sigma, or by 1.4826 MAD without sigma). No allocation; O(n) model evaluations per iteration,
/// O(n^2) comparisons per robust round (median by rank counting).
///
/// @param n                    number of points, >= 2.
/// @param v                    n impact speeds > 0, not all equal.
/// @param e                    n measured restitutions in (0, 1].
/// @param sigma                n uncertainties > 0, or NULL (unweighted).
/// @param criterion            DC_END_OVERLAP or DC_END_FORCE (host clamps forces).
/// @param tol                  tolerance on e for the model choice, > 0.
/// @param robust               0: least squares; any other value: Huber.
/// @param resid_viscoelastic   NULL or n doubles: receives e_i - e_viscoelastic(v_i).
/// @param resid_constant       NULL or n doubles: receives e_i - e_const.
/// @param out                  receives the result.
/// @return DC_OK, DC_ERR_NULL_POINTER (v, e or out), DC_ERR_FIT_TOO_FEW (n < 2),
///         DC_ERR_FIT_DEGENERATE (all speeds equal), DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE
///         (v, sigma or tol <= 0), DC_ERR_RESTITUTION_RANGE, DC_ERR_CRITERION,
///         DC_ERR_BUFFER_LAYOUT (misaligned arrays, or a residual array overlapping an input or
///         the other), DC_ERR_NO_CONVERGENCE. Nothing is written on error.
///
/// Precision: exact model data give beta to 1e-13 relative (tests/fit.rs).
///
/// # Safety
/// v, e (and sigma if non-NULL) readable for n doubles; residual arrays NULL or writable for n
/// doubles; out NULL or writable for one dc_fit_result.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // the C signature: arrays and options, no builder in C
pub unsafe extern "C" fn dc_fit_restitution(
    n: usize,
    v: *const f64,
    e: *const f64,
    sigma: *const f64,
    criterion: i32,
    tol: f64,
    robust: i32,
    resid_viscoelastic: *mut f64,
    resid_constant: *mut f64,
    out: *mut dc_fit_result,
) -> i32 {
    if v.is_null() || e.is_null() || out.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    if n < 2 {
        return DC_ERR_FIT_TOO_FEW;
    }
    let robust = robust != 0;
    let mut inputs = [None; 3];
    for (slot, p) in inputs.iter_mut().zip([v, e, sigma]) {
        if !p.is_null() {
            match span(p, n) {
                Some(s) => *slot = Some(s),
                None => return DC_ERR_BUFFER_LAYOUT,
            }
        }
    }
    let mut outs = [None; 2];
    for (slot, p) in outs.iter_mut().zip([resid_viscoelastic, resid_constant]) {
        if !p.is_null() {
            match span(p, n) {
                Some(s) => *slot = Some(s),
                None => return DC_ERR_BUFFER_LAYOUT,
            }
        }
    }
    let disjoint = |a: (usize, usize), b: (usize, usize)| a.1 <= b.0 || b.1 <= a.0;
    for o in outs.iter().flatten() {
        if inputs.iter().flatten().any(|i| !disjoint(*o, *i)) {
            return DC_ERR_BUFFER_LAYOUT;
        }
    }
    if let [Some(a), Some(b)] = outs
        && !disjoint(a, b)
    {
        return DC_ERR_BUFFER_LAYOUT;
    }
    let body = || -> Result<(), Error> {
        let opt = FitOptions {
            criterion: parse_criterion(criterion)?,
            tol,
            robust,
        };
        // SAFETY: non-null, aligned, valid for n doubles (caller contract), size checked; the
        // outputs are disjoint from every input and from each other (checked above).
        let (vs, es, ss) = unsafe {
            (
                core::slice::from_raw_parts(v, n),
                core::slice::from_raw_parts(e, n),
                (!sigma.is_null()).then(|| core::slice::from_raw_parts(sigma, n)),
            )
        };
        let data = Data {
            v: vs,
            e: es,
            sigma: ss,
        };
        let f = fit::fit_restitution(&data, &opt)?;
        // SAFETY: as above, for the outputs.
        let (rv, rc): (&mut [f64], &mut [f64]) = unsafe {
            (
                if resid_viscoelastic.is_null() {
                    &mut []
                } else {
                    core::slice::from_raw_parts_mut(resid_viscoelastic, n)
                },
                if resid_constant.is_null() {
                    &mut []
                } else {
                    core::slice::from_raw_parts_mut(resid_constant, n)
                },
            )
        };
        fit::residuals(&data, &f, opt.criterion, rv, rc)?;
        // SAFETY: out non-null (checked), writable (caller contract).
        unsafe { out.write_unaligned(dc_fit_result::from(&f, robust)) };
        Ok(())
    };
    guard(|| body().map_err(dc_status::of))
}

/// The multiplier of dc_fit_result's standard errors for a two-sided 95 % confidence interval
/// (beta +- q beta_se, e_const +- q e_const_se): with sigma estimated from the scatter
/// (se_from_scatter = 1) the 0.975 quantile of Student's t with n - 1 degrees of freedom (one
/// parameter fitted; e.g. 2.5706 for n = 6, 2.2010 for n = 12), with sigma given (0) the normal
/// 1.959964. +-2 SE covers only 89.8 % at n = 6 (tests/fit.rs: the t interval covers 94.5 % of
/// 2000 seeded data sets there, +-2 SE 89.0 %).
///
/// @param n                number of points of the fit, >= 2.
/// @param se_from_scatter  dc_fit_result.se_from_scatter: 0 (sigma given) or any other value
///                         (sigma from the scatter).
/// @param q_out            receives q; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_FIT_TOO_FEW (n < 2).
///
/// Precision: 1e-13 relative against 30-digit references (src/fit/quantile.rs tests).
///
/// # Safety
/// `q_out` must be NULL or point to writable memory for one double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_fit_quantile95(n: usize, se_from_scatter: i32, q_out: *mut f64) -> i32 {
    // SAFETY: forwarded caller contract on q_out.
    unsafe {
        super::write_result(q_out, || {
            if n < 2 {
                return Err(Error::FitTooFew);
            }
            Ok(fit::quantile::quantile95(n, se_from_scatter != 0))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantile95_statuses() {
        let mut q = -1.0;
        // SAFETY: valid pointer to a local, or NULL.
        unsafe {
            assert_eq!(dc_fit_quantile95(1, 1, &mut q), DC_ERR_FIT_TOO_FEW);
            assert_eq!(q, -1.0);
            assert_eq!(
                dc_fit_quantile95(6, 1, core::ptr::null_mut()),
                DC_ERR_NULL_POINTER
            );
            assert_eq!(dc_fit_quantile95(6, 1, &mut q), DC_OK);
            assert!((q - 2.570581835636315).abs() < 1e-13, "{q}");
            assert_eq!(dc_fit_quantile95(6, 0, &mut q), DC_OK);
            assert!((q - 1.959963984540054).abs() < 1e-13, "{q}");
            assert_eq!(dc_fit_quantile95(usize::MAX, 7, &mut q), DC_OK);
            assert!((q - 1.959963984540054).abs() < 1e-13, "{q}");
        }
    }
}
