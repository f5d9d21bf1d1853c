//! A safeguarded Newton iteration: quadratic convergence from a good start, and never leaves its
//! bracket, so a poor derivative cannot send it to infinity or NaN.

use crate::Error;

/// Root of an increasing function `f` in `[lo, hi]`, given `f(x) -> (f(x), f'(x))` with
/// `f(lo) ≤ 0 ≤ f(hi)`, starting from `x0` in the bracket.
///
/// A Newton step that leaves the current bracket, or is not finite, is replaced by bisection
/// (geometric once the bracket spans more than a factor 4 with lo > 0, so that brackets over many
/// decades shrink quickly). Stops when the step is below 2 ulp of x or the bracket has collapsed.
pub fn newton_bracketed<F>(
    mut f: F,
    mut lo: f64,
    mut hi: f64,
    x0: f64,
    max_iter: u32,
) -> Result<f64, Error>
where
    F: FnMut(f64) -> (f64, f64),
{
    if !(lo <= hi) || !lo.is_finite() || !hi.is_finite() {
        return Err(Error::NoConvergence);
    }
    let mut x = x0.clamp(lo, hi);
    let mut prev_step = f64::INFINITY;
    let (mut best_x, mut best_f) = (x, f64::INFINITY);
    for _ in 0..max_iter {
        let (fx, dfx) = f(x);
        if fx == 0.0 {
            return Ok(x);
        }
        if fx.abs() < best_f {
            best_x = x;
            best_f = fx.abs();
        }
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - fx / dfx;
        let is_newton = newton.is_finite() && newton >= lo && newton <= hi;
        let next = if is_newton {
            newton
        } else if lo > 0.0 && hi > 4.0 * lo {
            (lo * hi).sqrt()
        } else {
            0.5 * (lo + hi)
        };
        let step = (next - x).abs();
        x = next;
        if step <= 2.0 * f64::EPSILON * x.abs() || hi - lo <= 2.0 * f64::EPSILON * x.abs() {
            return Ok(x);
        }
        if is_newton && step < 1e-9 * x.abs() && step > 0.5 * prev_step {
            return Ok(best_x);
        }
        prev_step = step;
    }
    Err(Error::NoConvergence)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sqrt_two() {
        let r = newton_bracketed(|x| (x * x - 2.0, 2.0 * x), 0.0, 2.0, 1.0, 50).unwrap_or(f64::NAN);
        assert!((r - 2f64.sqrt()).abs() <= f64::EPSILON * 2.0, "{r}");
    }

    #[test]
    fn bad_derivative_falls_back_to_bisection() {
        // Zero derivative everywhere: pure bisection must still find the root of x - 0.3.
        let r = newton_bracketed(|x| (x - 0.3, 0.0), 0.0, 1.0, 0.9, 200).unwrap_or(f64::NAN);
        assert!((r - 0.3).abs() < 1e-15);
    }

    #[test]
    fn wide_bracket_geometric() {
        let r = newton_bracketed(|x: f64| (x.ln() - 300.0, 1.0 / x), 1.0, 1e300, 1e300, 200)
            .unwrap_or(f64::NAN);
        // ln x is known to ±ulp(300) ≈ 6e-14, so x only to that relative precision.
        assert!((r.ln() - 300.0).abs() <= 1.2e-13, "{r}");
    }

    #[test]
    fn noisy_function_stalls_gracefully() {
        // f has rounding noise far above one ulp of x: must stop near the root, not fail.
        let r = newton_bracketed(
            |x: f64| ((x - 1.0) + 1e-12 * (x * 1e15).sin(), 1.0),
            0.0,
            3.0,
            3.0,
            100,
        );
        let r = r.unwrap_or(f64::NAN);
        assert!((r - 1.0).abs() < 1e-11, "{r}");
    }

    #[test]
    fn invalid_bracket() {
        assert_eq!(
            newton_bracketed(|x| (x, 1.0), 1.0, 0.0, 0.5, 10),
            Err(Error::NoConvergence)
        );
        assert_eq!(
            newton_bracketed(|x| (x, 1.0), f64::NAN, 1.0, 0.5, 10),
            Err(Error::NoConvergence)
        );
    }
}
