//! The reference: the equation of motion integrated to (near) machine precision in regularised
//! variables by a Taylor-series method.
//!
//! In natural units ([`super::scaling`]) the collision is `X'' + X^{3/2} + b √X X' = 0`, X(0) = 0,
//! X'(0) = 1. The right-hand side is not smooth at X = 0 (√X), which is where a contact starts and,
//! under the overlap criterion, ends; a generic Runge–Kutta loses accuracy exactly there. Write
//! X = u² and stretch time by the overlap itself, dT = u dσ. Then, with V = X',
//!
//! ```text
//!   du/dσ = V/2,   dV/dσ = −u⁴ − b u² V,   dT/dσ = u,
//! ```
//!
//! a polynomial system: analytic everywhere, with u crossing 0 transversally (du/dσ = V/2 ≠ 0) at
//! both ends of the contact. Start (σ = 0): u = 0, V = 1, T = 0. The events are
//! * maximum compression: V = 0;
//! * overlap end (`DC_END_OVERLAP`): u = 0 while unloading, e = −V;
//! * force end (`DC_END_FORCE`): X^{3/2} + b √X X' = 0 with X > 0, i.e. u² + b V = 0; during
//!   loading both terms are positive, so its first zero is the physical end. e = −V.
//!
//! A Taylor method of order 30 integrates this system: coefficients by Cauchy-product recursion,
//! step from the size of the last two coefficients (local error ~1e-16 relative), and events
//! located by Newton's method on the step's own polynomial (exact dense output). The same code
//! runs with complex b, which [`integrate_complex`] uses to obtain series coefficients by Cauchy
//! integrals (the paper's tables, reproduced in the tests).

use crate::numerics::taylor::{Scalar, cauchy_term, horner, step_size};
use crate::{EndCriterion, Error};
use num_complex::Complex64;

/// Order of the Taylor expansion.
pub(crate) const ORDER: usize = 30;
const M: usize = ORDER + 1;
/// Sign-change probes per step (events cannot be missed between them for these smooth events).
const PROBES: usize = 8;
/// Default local tolerance (relative to max(|u|, |V|)).
pub(crate) const TOL_DEFAULT: f64 = 1e-18;
/// Step budget: b = 1e3 under the overlap criterion needs 18286 steps, 3e3 about 1.1e5
/// (tests/viscoelastic_accuracy.rs, `documented_step_counts_and_large_b_approach`).
pub(crate) const MAX_STEPS: u32 = 50_000_000;

/// Which event ends the integration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// Maximum compression, V = 0.
    MaxCompression,
    /// Overlap returns to zero, u = 0.
    Overlap,
    /// Total force returns to zero, u² + b V = 0.
    Force,
}

impl From<EndCriterion> for Event {
    fn from(c: EndCriterion) -> Self {
        match c {
            EndCriterion::Overlap => Event::Overlap,
            EndCriterion::Force => Event::Force,
        }
    }
}

/// Regularised state: u = √X, V = X' (natural units), T = natural time.
#[derive(Clone, Copy, Debug)]
pub struct State<T> {
    /// Square root of the overlap.
    pub u: T,
    /// Overlap rate X' (the restitution is −V at the end).
    pub v: T,
    /// Natural time T.
    pub t: T,
}

/// Where an integration stopped.
#[derive(Clone, Copy, Debug)]
pub struct Hit<T> {
    /// Regularised time σ of the event.
    pub sigma: T,
    /// State at the event.
    pub state: State<T>,
    /// Taylor steps taken.
    pub steps: u32,
}

struct Jet<T> {
    u: [T; M],
    v: [T; M],
    t: [T; M],
}

#[inline]
fn set<T>(a: &mut [T; M], k: usize, x: T) {
    if let Some(e) = a.get_mut(k) {
        *e = x;
    }
}

#[inline]
fn at<T: Scalar>(a: &[T; M], k: usize) -> T {
    a.get(k).copied().unwrap_or(T::from_f64(0.0))
}

/// Taylor coefficients of (u, V, T) around `s` in powers of δσ.
fn expand<T: Scalar>(b: T, s: State<T>) -> Jet<T> {
    let z = T::from_f64(0.0);
    let (mut u, mut v, mut t) = ([z; M], [z; M], [z; M]);
    let (mut p, mut q) = ([z; M], [z; M]);
    set(&mut u, 0, s.u);
    set(&mut v, 0, s.v);
    set(&mut t, 0, s.t);
    for k in 0..ORDER {
        let pk = cauchy_term(&u, &u, k); // u²
        set(&mut p, k, pk);
        let qk = cauchy_term(&p, &p, k); // u⁴
        set(&mut q, k, qk);
        let rk = cauchy_term(&p, &v, k); // u² V
        let kk = T::from_f64((k + 1) as f64);
        set(&mut u, k + 1, at(&v, k) / (kk * T::from_f64(2.0)));
        set(&mut v, k + 1, -(qk + b * rk) / kk);
        set(&mut t, k + 1, at(&u, k) / kk);
    }
    Jet { u, v, t }
}

impl<T: Scalar> Jet<T> {
    fn step(&self, tol: f64) -> f64 {
        let s0 = at(&self.u, 0).norm().max(at(&self.v, 0).norm());
        let mut both = [T::from_f64(0.0); M];
        for (k, o) in both.iter_mut().enumerate() {
            // max-norm of the two components, as a real coefficient
            *o = T::from_f64(at(&self.u, k).norm().max(at(&self.v, k).norm()));
        }
        step_size(&both, tol, s0)
    }

    /// State and (du/dσ, dV/dσ) at δ.
    fn eval(&self, d: T) -> (State<T>, T, T) {
        let (u, du) = horner(&self.u, d);
        let (v, dv) = horner(&self.v, d);
        let (t, _) = horner(&self.t, d);
        (State { u, v, t }, du, dv)
    }

    /// Event function and its σ-derivative at δ.
    fn event(&self, b: T, ev: Event, d: T) -> (T, T) {
        let (s, du, dv) = self.eval(d);
        match ev {
            Event::MaxCompression => (s.v, dv),
            Event::Overlap => (s.u, du),
            Event::Force => (s.u * s.u + b * s.v, T::from_f64(2.0) * s.u * du + b * dv),
        }
    }
}

fn start<T: Scalar>() -> State<T> {
    State {
        u: T::from_f64(0.0),
        v: T::from_f64(1.0),
        t: T::from_f64(0.0),
    }
}

/// Integrates the regularised collision with real b ≥ 0 to the first occurrence of `ev`.
///
/// `tol` is the local relative tolerance (1e-18, the default, gives ~1e-15 relative in e up to
/// b = 1e3 and 5e-14 at 1e6; 1e-16 leaves errors up to 2e-10 near b = 4e5 under the force
/// criterion).
pub fn integrate(b: f64, ev: Event, tol: f64, max_steps: u32) -> Result<Hit<f64>, Error> {
    let mut s = start::<f64>();
    let mut sigma = 0.0;
    for steps in 0..max_steps {
        let jet = expand(b, s);
        let h = jet.step(tol);
        if !(h > 0.0) || !h.is_finite() {
            return Err(Error::NoConvergence);
        }
        let mut lo = 0.0;
        for j in 1..=PROBES {
            let d = h * j as f64 / PROBES as f64;
            let (g, _) = jet.event(b, ev, d);
            // For small b the force dips below zero only in a window of width ~4√b around the
            // overlap root, which probes could step over; u ≤ 0 marks that the window was passed,
            // and at the overlap root g = bV < 0 closes the bracket.
            let passed = ev == Event::Force && jet.eval(d).0.u <= 0.0;
            if g <= 0.0 || passed {
                let hi = if g <= 0.0 {
                    d
                } else {
                    locate_real(&jet, b, Event::Overlap, lo, d)
                };
                let root = locate_real(&jet, b, ev, lo, hi);
                let (st, _, _) = jet.eval(root);
                return Ok(Hit {
                    sigma: sigma + root,
                    state: st,
                    steps: steps + 1,
                });
            }
            lo = d;
        }
        s = jet.eval(h).0;
        sigma += h;
    }
    Err(Error::NoConvergence)
}

/// Root of the event polynomial in (lo, hi] with g(lo) > 0 ≥ g(hi): Newton safeguarded by
/// bisection.
fn locate_real(jet: &Jet<f64>, b: f64, ev: Event, mut lo: f64, mut hi: f64) -> f64 {
    let mut x = hi;
    for _ in 0..200 {
        let (g, dg) = jet.event(b, ev, x);
        if g == 0.0 {
            return x;
        }
        if g > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - g / dg;
        let next = if newton.is_finite() && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - x).abs() <= 2.0 * f64::EPSILON * x.abs() || hi - lo <= 2.0 * f64::EPSILON * hi {
            return next;
        }
        x = next;
    }
    x
}

/// Integrates with complex b (analytic continuation of the real collision), for Cauchy integrals.
///
/// Marches along real σ until the real part of the marker (V for maximum compression, u for the
/// two ends) changes sign, then walks in complex σ and solves the event by Newton's method on the
/// local polynomials. For the force end the root is taken on the branch continuous with
/// √b = `w` > 0: near the overlap root σ_O, u ≈ (e/2)(σ_O − σ), so u² + bV = 0 at
/// σ ≈ σ_O − 2w/√e. Returns `NoConvergence` when the walk fails (|b| too large).
pub fn integrate_complex(
    w: Complex64,
    ev: Event,
    tol: f64,
    max_steps: u32,
) -> Result<Hit<Complex64>, Error> {
    let b = w * w;
    let mut s = start::<Complex64>();
    let mut sigma = Complex64::new(0.0, 0.0);
    let marker = |st: &State<Complex64>| match ev {
        Event::MaxCompression => st.v.re,
        _ => st.u.re,
    };
    for steps in 0..max_steps {
        let jet = expand(b, s);
        let h = jet.step(tol);
        if !(h > 0.0) || !h.is_finite() {
            return Err(Error::NoConvergence);
        }
        for j in 1..=PROBES {
            let d = h * j as f64 / PROBES as f64;
            if marker(&jet.eval(Complex64::new(d, 0.0)).0) <= 0.0 {
                // Real-axis estimate of the crossing of the marker, by bisection.
                let (mut lo, mut hi) = (d - h / PROBES as f64, d);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if marker(&jet.eval(Complex64::new(mid, 0.0)).0) > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let mut guess = Complex64::new(hi, 0.0);
                if ev == Event::Force {
                    let e0 = -jet.eval(guess).0.v;
                    guess -= w * 2.0 / e0.sqrt();
                }
                return walk_newton(b, ev, s, sigma, guess, tol).map(|(sg, st)| Hit {
                    sigma: sg,
                    state: st,
                    steps: steps + 1,
                });
            }
        }
        s = jet.eval(Complex64::new(h, 0.0)).0;
        sigma += h;
    }
    Err(Error::NoConvergence)
}

/// Newton's method for the event in complex σ, walking the base point towards the root in steps
/// no longer than the local Taylor step.
fn walk_newton(
    b: Complex64,
    ev: Event,
    mut base: State<Complex64>,
    mut base_sigma: Complex64,
    mut target: Complex64,
    tol: f64,
) -> Result<(Complex64, State<Complex64>), Error> {
    for _ in 0..2000 {
        let jet = expand(b, base);
        let h = jet.step(tol);
        if !(h > 0.0) || !h.is_finite() {
            return Err(Error::NoConvergence);
        }
        if target.norm() > h {
            let d = target * (0.9 * h / target.norm());
            base = jet.eval(d).0;
            base_sigma += d;
            target -= d;
            continue;
        }
        let mut x = target;
        let mut inside = true;
        for _ in 0..60 {
            let (g, dg) = jet.event(b, ev, x);
            let dx = g / dg;
            if !dx.re.is_finite() || !dx.im.is_finite() {
                return Err(Error::NoConvergence);
            }
            x -= dx;
            if x.norm() > h {
                inside = false;
                break;
            }
            if dx.norm() <= 4.0 * f64::EPSILON * (1.0 + (base_sigma + x).norm()) {
                let st = jet.eval(x).0;
                return Ok((base_sigma + x, st));
            }
        }
        if inside {
            // Newton stagnated at rounding level: accept.
            let st = jet.eval(x).0;
            return Ok((base_sigma + x, st));
        }
        target = x;
    }
    Err(Error::NoConvergence)
}

/// Reference restitution e(b) for a criterion, by direct integration at local tolerance `tol`.
/// b ≥ 0 finite; e(0) = 1.
pub fn e_reference_tol(b: f64, criterion: EndCriterion, tol: f64) -> Result<f64, Error> {
    if !b.is_finite() {
        return Err(Error::NotFinite);
    }
    if b < 0.0 {
        return Err(Error::Negative);
    }
    if b == 0.0 {
        return Ok(1.0);
    }
    let hit = integrate(b, Event::from(criterion), tol, MAX_STEPS)?;
    Ok(-hit.state.v)
}

/// Reference restitution e(b) at the default tolerance (about 1e-15 relative for b ≤ 10,
/// 1e-13 at b = 1e3; see docs/viscoelastic.md).
pub fn e_reference(b: f64, criterion: EndCriterion) -> Result<f64, Error> {
    e_reference_tol(b, criterion, TOL_DEFAULT)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn undamped_maximum_compression_is_exact() {
        // b = 0: X_max = (5/4)^(2/5) from energy conservation, V² + (4/5)X^(5/2) = 1.
        let hit = integrate(0.0, Event::MaxCompression, TOL_DEFAULT, 1000);
        let hit = hit.unwrap_or(Hit {
            sigma: f64::NAN,
            state: start(),
            steps: 0,
        });
        let xmax = hit.state.u * hit.state.u;
        assert!((xmax - 1.25f64.powf(0.4)).abs() < 2e-15, "{xmax}");
    }

    #[test]
    fn undamped_collision_is_elastic() {
        let e = integrate(0.0, Event::Overlap, TOL_DEFAULT, 1000)
            .map(|h| -h.state.v)
            .unwrap_or(f64::NAN);
        assert!((e - 1.0).abs() < 1e-15, "{e}");
    }

    #[test]
    fn complex_path_agrees_with_real_path_for_real_b() {
        for &b in &[0.05f64, 0.3, 1.0] {
            for ev in [Event::Overlap, Event::Force, Event::MaxCompression] {
                let r = integrate(b, ev, TOL_DEFAULT, 100_000)
                    .map(|h| h.state.v)
                    .unwrap_or(f64::NAN);
                let c = integrate_complex(Complex64::new(b.sqrt(), 0.0), ev, TOL_DEFAULT, 100_000)
                    .map(|h| h.state.v)
                    .unwrap_or(Complex64::new(f64::NAN, 0.0));
                assert!(
                    (c.re - r).abs() < 1e-14 && c.im.abs() < 1e-14,
                    "{b} {ev:?} {r} {c}"
                );
            }
        }
    }
}
