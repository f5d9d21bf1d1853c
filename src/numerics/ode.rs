//! Adaptive Dormand–Prince 5(4) integration of a planar autonomous system `y' = f(y)` up to an
//! event, without heap allocation.
//!
//! This is the project's reference: closed forms and quadratures are checked against it, never
//! against themselves. It is deliberately plain (explicit RK, local error control in the max norm,
//! event located by re-stepping from the last accepted point), so that it shares no algebra with
//! the phase-space map that the rest of the crate relies on.
//!
//! Contact equations have non-smooth right-hand sides at zero overlap (δ^((p-1)/2) for p > 1); the
//! error control resolves them by shrinking the step there, and callers extend the force law oddly
//! to δ < 0 so that trial stages beyond the end of contact stay finite.

use crate::Error;

/// Planar state `[position, velocity]` (or any two components).
pub type Vec2 = [f64; 2];

/// Local error tolerances: a step is accepted when `|err_i| ≤ atol_i + rtol·|y_i|` for both i.
#[derive(Clone, Copy, Debug)]
pub struct Tolerance {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per component.
    pub atol: Vec2,
}

/// Cost counters of one integration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: u32,
    /// Rejected steps.
    pub rejected: u32,
    /// Right-hand-side evaluations.
    pub evals: u32,
}

/// The state where the event fired.
#[derive(Clone, Copy, Debug)]
pub struct EventHit {
    /// Time of the event.
    pub t: f64,
    /// State at the event.
    pub y: Vec2,
    /// Cost counters.
    pub stats: Stats,
}

// Dormand–Prince 5(4) tableau (Dormand & Prince 1980); B5 is the propagated solution.
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// Error coefficients: 5th-order minus 4th-order weights (the 7th stage is f at the new point).
const E1: f64 = 35.0 / 384.0 - 5179.0 / 57600.0;
const E3: f64 = 500.0 / 1113.0 - 7571.0 / 16695.0;
const E4: f64 = 125.0 / 192.0 - 393.0 / 640.0;
const E5: f64 = -2187.0 / 6784.0 + 92097.0 / 339200.0;
const E6: f64 = 11.0 / 84.0 - 187.0 / 2100.0;
const E7: f64 = -1.0 / 40.0;
const _: () = assert!(C2 > 0.0 && C3 > C2 && C4 > C3 && C5 > C4);

#[inline]
fn axpy(y: Vec2, h: f64, terms: &[(f64, Vec2)]) -> Vec2 {
    let mut out = y;
    for &(c, k) in terms {
        out[0] += h * c * k[0];
        out[1] += h * c * k[1];
    }
    out
}

/// One Dormand–Prince step of size h: the 5th-order solution and the local error estimate.
pub fn dopri_step<F: FnMut(Vec2) -> Vec2>(f: &mut F, y: Vec2, h: f64) -> (Vec2, Vec2) {
    let k1 = f(y);
    let k2 = f(axpy(y, h, &[(A21, k1)]));
    let k3 = f(axpy(y, h, &[(A31, k1), (A32, k2)]));
    let k4 = f(axpy(y, h, &[(A41, k1), (A42, k2), (A43, k3)]));
    let k5 = f(axpy(y, h, &[(A51, k1), (A52, k2), (A53, k3), (A54, k4)]));
    let k6 = f(axpy(
        y,
        h,
        &[(A61, k1), (A62, k2), (A63, k3), (A64, k4), (A65, k5)],
    ));
    let y_new = axpy(y, h, &[(B1, k1), (B3, k3), (B4, k4), (B5, k5), (B6, k6)]);
    let k7 = f(y_new);
    let err = axpy(
        [0.0, 0.0],
        h,
        &[(E1, k1), (E3, k3), (E4, k4), (E5, k5), (E6, k6), (E7, k7)],
    );
    (y_new, err)
}

fn error_ratio(y: Vec2, y_new: Vec2, err: Vec2, tol: &Tolerance) -> f64 {
    let mut r: f64 = 0.0;
    for i in 0..2 {
        let (yi, yn, ei, ai) = match i {
            0 => (y[0], y_new[0], err[0], tol.atol[0]),
            _ => (y[1], y_new[1], err[1], tol.atol[1]),
        };
        let sc = ai + tol.rtol * yi.abs().max(yn.abs());
        r = r.max(ei.abs() / sc);
    }
    r
}

/// Integrates `y' = f(y)` from `(t0, y0)` until `event(y)` first becomes ≤ 0 (it must be > 0 at
/// the start), and returns the state there. `observe(t, y)` sees every accepted point, the start
/// included, but not the event point. The event is located to about 1e-15 relative in time.
#[allow(clippy::too_many_arguments)] // one call site per phase; a builder would only hide them
pub fn integrate_to_event<F, G, O>(
    mut f: F,
    t0: f64,
    y0: Vec2,
    mut event: G,
    mut observe: O,
    tol: &Tolerance,
    h0: f64,
    max_steps: u32,
) -> Result<EventHit, Error>
where
    F: FnMut(Vec2) -> Vec2,
    G: FnMut(Vec2) -> f64,
    O: FnMut(f64, Vec2),
{
    let mut stats = Stats::default();
    let mut f_counted = |y: Vec2| {
        stats.evals += 1;
        f(y)
    };
    let (mut t, mut y, mut h) = (t0, y0, h0);
    observe(t, y);
    let mut ev = event(y);
    if !(ev > 0.0) || !(h > 0.0) {
        return Err(Error::NoConvergence);
    }
    for _ in 0..max_steps {
        let (y_new, err) = dopri_step(&mut f_counted, y, h);
        let ratio = error_ratio(y, y_new, err, tol);
        if !(ratio <= 1.0) {
            stats.rejected += 1;
            let fac = if ratio.is_finite() {
                (0.9 * ratio.powf(-0.2)).max(0.1)
            } else {
                0.1
            };
            h *= fac;
            if !(h > 0.0) || t + h == t {
                return Err(Error::NoConvergence);
            }
            continue;
        }
        let ev_new = event(y_new);
        if ev_new <= 0.0 {
            // Locate the crossing inside (0, h] with the Illinois variant of false position,
            // re-stepping from the accepted point; falls back to bisection on stagnation.
            let (mut a, mut fa, mut b, mut fb) = (0.0, ev, h, ev_new);
            let mut side = 0i8;
            let mut y_b = y_new;
            for _ in 0..200 {
                if b - a <= 1e-16 * (t + b).abs().max(b) {
                    break;
                }
                let mut m = (a * fb - b * fa) / (fb - fa);
                if !(m > a && m < b) {
                    m = 0.5 * (a + b);
                }
                let (y_m, _) = dopri_step(&mut f_counted, y, m);
                let fm = event(y_m);
                if fm > 0.0 {
                    a = m;
                    fa = fm;
                    if side == 1 {
                        fb *= 0.5;
                    }
                    side = 1;
                } else {
                    b = m;
                    fb = fm;
                    y_b = y_m;
                    if side == -1 {
                        fa *= 0.5;
                    }
                    side = -1;
                    if fm == 0.0 {
                        break;
                    }
                }
            }
            stats.accepted += 1;
            return Ok(EventHit {
                t: t + b,
                y: y_b,
                stats,
            });
        }
        stats.accepted += 1;
        t += h;
        y = y_new;
        ev = ev_new;
        observe(t, y);
        let fac = if ratio > 0.0 {
            (0.9 * ratio.powf(-0.2)).clamp(0.2, 5.0)
        } else {
            5.0
        };
        h *= fac;
    }
    Err(Error::NoConvergence)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harmonic_oscillator_quarter_period() {
        // x'' = -x from x=0, v=1: v reaches 0 at t = π/2 with x = 1.
        let tol = Tolerance {
            rtol: 1e-13,
            atol: [1e-15, 1e-15],
        };
        let hit = integrate_to_event(
            |y| [y[1], -y[0]],
            0.0,
            [0.0, 1.0],
            |y| y[1],
            |_, _| {},
            &tol,
            1e-3,
            100_000,
        );
        let hit = hit.unwrap_or(EventHit {
            t: f64::NAN,
            y: [f64::NAN; 2],
            stats: Stats::default(),
        });
        assert!(
            (hit.t - core::f64::consts::FRAC_PI_2).abs() < 1e-12,
            "{}",
            hit.t
        );
        assert!((hit.y[0] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn fifth_order_convergence() {
        // Halving h must shrink the single-step error of y' = y by about 2⁶ (local order 6).
        let mut f = |y: Vec2| [y[0], y[1]];
        let e1 = (dopri_step(&mut f, [1.0, 1.0], 0.2).0[0] - 0.2f64.exp()).abs();
        let e2 = (dopri_step(&mut f, [1.0, 1.0], 0.1).0[0] - 0.1f64.exp()).abs();
        let ratio = e1 / e2;
        assert!(ratio > 50.0 && ratio < 80.0, "ratio {ratio}");
    }

    #[test]
    fn damped_oscillator_exit() {
        // LSD with ζ = 0.3: x returns to 0 at t = π/ω with x' = -exp(-ζπ/ω).
        let z: f64 = 0.3;
        let w = (1.0 - z * z).sqrt();
        let tol = Tolerance {
            rtol: 1e-13,
            atol: [1e-16, 1e-16],
        };
        let hit = integrate_to_event(
            |y| [y[1], -y[0] - 2.0 * z * y[1]],
            0.0,
            [1e-300, 1.0],
            |y| y[0],
            |_, _| {},
            &tol,
            1e-4,
            100_000,
        );
        let hit = hit.unwrap_or(EventHit {
            t: f64::NAN,
            y: [f64::NAN; 2],
            stats: Stats::default(),
        });
        assert!((hit.t - core::f64::consts::PI / w).abs() < 1e-11);
        assert!((-hit.y[1] - (-z * core::f64::consts::PI / w).exp()).abs() < 1e-12);
    }
}
