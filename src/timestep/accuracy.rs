//! The largest velocity-Verlet step that keeps the realised restitution within a tolerance.
//!
//! Scaling: with δ* = (v0/ω0)^(2/(p+1)) and t* = δ*/v0 the power-law contact
//! `δ'' + α ω0 δ^((p−1)/2) δ' + ω0² δ^p = 0` becomes `x'' + α x^((p−1)/2) x' + x^p = 0` with
//! x'(0) = 1: the realised restitution at step dt depends only on (p, e, criterion, dt/t*, phase).
//! So the step is t* × h(p, e, criterion, tol), and h is measured here, by simulating that
//! dimensionless collision with the library's own kernels ([`super::integrator::collide`]).
//!
//! Error measure: `E(h) = max over N_PHASE start phases |e_realised − e|/e`, the phases evenly
//! spaced over [0, 1) with both ends included. The measurements (`docs/timestep.md`) show E ≈ C·h
//! for damped contacts (the dashpot force jumps at first contact, and at the end for the overlap
//! criterion, so velocity-Verlet is only first order in e), with a phase dependence that is often
//! a jump between two branches (N or N + 1 contact steps): hence many phases, including the ends.
//!
//! Search, aiming at SAFETY·tol: τ from one fine run (from the library's quadrature where that
//! run does not resolve the contact: [`reference_duration`]); then h = τ/8, τ/16, … down to τ/8192 until
//! E(h) passes, then 5 bisections in log h between the last failing and the first passing step,
//! returning the passing end (so the returned step passed at all sampled phases, and is within a
//! factor 2^(1/32) of the largest passing step on that bracket). Below τ/8192 (tol below ~1e-4
//! for strongly damped contacts) the last two measurements fix the local order k of E ∝ h^k
//! where they show one ([`K_MIN`] ≤ k ≤ [`K_MAX`] and an error below e itself; NoConvergence
//! otherwise; k clamped to [0.5, 2]) and h is extrapolated, then checked at the same phases and
//! stepped down along that law until it passes, while a collision at that step takes at most
//! [`VERIFY_MAX_STEPS`] contact steps (NoConvergence when none passes within that bound); a
//! step finer than the bound is returned as extrapolated, not verified, up to [`MAX_STEPS`]
//! steps per contact (NoConvergence beyond).
//! Cost: at most ~6·10⁶ force evaluations (tens of ms; up to a few hundred ms on a loaded
//! machine for e ≤ 0.1 and tol ≤ 1e-3), plus, where an extrapolated step is checked, up to 6
//! checks of 64 collisions of at most 2^18 contact steps (up to ~10⁸ more: seconds); no
//! allocation. Call it at set-up, once per pair.

use super::integrator::{Scheme, collide};
use crate::force::PairModel;
use crate::force::powerlaw::powerlaw_from_alpha;
use crate::powerlaw::plan::LEVEL_MAX;
use crate::powerlaw::{Contact, contact_duration};
use crate::powerlaw::{alpha_from_e, check_exponent};
use crate::{EndCriterion, Error};

/// Start phases sampled per step size.
pub(crate) const N_PHASE: u32 = 64;
/// The search aims at SAFETY·tol: the worst phase can fall between the sampled ones.
const SAFETY: f64 = 0.9;
/// Searched steps lie in [τ/FLOOR_DIV, τ/8]; below, the error law is extrapolated.
const FLOOR_DIV: f64 = 8192.0;
const TOP_DIV: f64 = 8.0;
const BISECTIONS: u32 = 5;
/// A run that has not separated after this many contact durations failed (e.g. a step so large
/// that the bodies stick numerically).
const MAX_DURATIONS: f64 = 64.0;

/// The dimensionless pair: k = 1, m = 1, v0 = 1, so ω0 = 1 and t* = δ* = 1.
fn unit_pair(p: f64, e: f64, criterion: EndCriterion) -> Result<PairModel, Error> {
    let alpha = alpha_from_e(e, p, criterion)?;
    powerlaw_from_alpha(p, 1.0, alpha, criterion)
}

fn max_steps(tau: f64, h: f64) -> u32 {
    let n = MAX_DURATIONS * tau / h + 64.0;
    if n < 4.0e9 { n as u32 } else { u32::MAX }
}

/// Worst relative restitution error over `n_phase` evenly spaced start phases from 0 to 1⁻ (both
/// ends), for the dimensionless collision (v0 = ω0 = 1) at step h, velocity-Verlet. `f64::INFINITY`
/// when a run does not separate within its step budget. `tau` is the contact duration (for the
/// budget).
pub fn worst_restitution_error(pair: &PairModel, e: f64, tau: f64, h: f64, n_phase: u32) -> f64 {
    let mut worst: f64 = 0.0;
    let steps = max_steps(tau, h);
    // Both ends of [0, 1) are included: the error is often piecewise smooth in the phase with a
    // jump where the number of contact steps changes, and one branch can be a sliver at an end.
    let last = f64::from(n_phase.max(2) - 1);
    for i in 0..n_phase {
        let phase = f64::from(i) / last * (1.0 - f64::EPSILON * 1024.0);
        match collide(pair, 1.0, 1.0, 1.0, h, phase, Scheme::VelocityVerlet, steps) {
            Ok(c) => worst = worst.max(((c.e - e) / e).abs()),
            Err(_) => return f64::INFINITY,
        }
    }
    if worst.is_nan() { f64::INFINITY } else { worst }
}

/// Contact steps up to which an extrapolated step is checked by simulation (each check: 64
/// collisions of at most this many contact steps); finer steps are returned as extrapolated.
const VERIFY_MAX_STEPS: f64 = 262_144.0;

/// Step of the reference run [t*], and the steps a contact duration must span in it to be
/// taken as resolved.
const REF_STEP: f64 = 1e-3;
const REF_RESOLVED: f64 = 100.0;

/// Checks of an extrapolated step before it is given up.
const VERIFY_TRIES: u32 = 6;
/// The halving slopes log2(E(2h)/E(h)) at the finest searched step that count as an error law
/// E ∝ h^k to extrapolate (first to second order, with margin).
const K_MIN: f64 = 0.4;
const K_MAX: f64 = 2.5;
/// No answer with more steps per contact than 2^52: such a step is below the double resolution
/// of the contact's own time and overlap (t + dt and δ + v dt round to t and δ).
const MAX_STEPS: f64 = 4_503_599_627_370_496.0;

/// The extrapolated step `h_ex` (error law E ∝ h^k), checked where affordable: while
/// τ/h ≤ [`VERIFY_MAX_STEPS`], up to [`VERIFY_TRIES`] checks, each failing one followed by the
/// step where E ∝ h^k would give 0.9 of `tol` (at least 10 % and at most a factor 2 smaller:
/// the extrapolation aims at `tol` itself, so a first check often fails by a few per cent);
/// NoConvergence when no checked step passes (the error is erratic in h there:
/// docs/timestep.md, finding 1); returned as it is when already finer than the bound.
fn verified(
    mut h: f64,
    k: f64,
    tau: f64,
    err: impl Fn(f64) -> f64,
    tol: f64,
) -> Result<f64, Error> {
    let mut checks = 0;
    while checks < VERIFY_TRIES && tau / h <= VERIFY_MAX_STEPS {
        let e_h = err(h);
        if e_h <= tol {
            return Ok(h);
        }
        checks += 1;
        // e_h > tol > 0 (∞ for a run that does not end: the factor is then 1/2).
        h *= (0.9 * tol / e_h).powf(1.0 / k).clamp(0.5, 0.9);
    }
    if checks == 0 {
        Ok(h)
    } else {
        Err(Error::NoConvergence)
    }
}

/// The contact duration τ of the dimensionless collision (v0 = ω0 = 1) from a run at
/// [`REF_STEP`] (a few per cent short for strongly damped contacts: τ only scales the search
/// grid). A contact shorter than [`REF_RESOLVED`] steps of that run (DC_END_FORCE with Hertz
/// below about e = 1.5e-6, with p = 1 below about 3e-5; under one step below about e = 1e-11,
/// 1.9e-6 t* at e = 1e-19 with Hertz), or a run that does not end, takes the library's
/// quadrature of the same contact instead ([`contact_duration`], 1e-10 relative).
pub(crate) fn reference_duration(pair: &PairModel) -> Result<f64, Error> {
    let run = collide(
        pair,
        1.0,
        1.0,
        1.0,
        REF_STEP,
        0.5,
        Scheme::VelocityVerlet,
        10_000_000,
    );
    let tau = match run {
        Ok(c) if c.duration >= REF_RESOLVED * REF_STEP => c.duration,
        _ => {
            let c = Contact::new(pair.p, pair.alpha, 1.0, 1.0)?;
            contact_duration(&c, pair.criterion, LEVEL_MAX as u32)?
        }
    };
    if tau > 0.0 && tau.is_finite() {
        Ok(tau)
    } else {
        Err(Error::NoConvergence)
    }
}

/// Dimensionless step h = dt/t* (see the module docs) and the contact duration τ/t*.
pub(crate) fn unit_step(
    p: f64,
    e: f64,
    criterion: EndCriterion,
    tol: f64,
) -> Result<(f64, f64), Error> {
    let pair = unit_pair(p, e, criterion)?;
    let tau = reference_duration(&pair)?;
    let err = |h: f64| worst_restitution_error(&pair, e, tau, h, N_PHASE);
    let tol = SAFETY * tol;
    let mut h = tau / TOP_DIV;
    let mut e_h = err(h);
    if e_h <= tol {
        // Coarser steps do not resolve the contact at all: the top of the range is the answer.
        return Ok((h, tau));
    }
    let (mut h_fail, mut e_fail) = (h, e_h);
    let floor = tau / FLOOR_DIV;
    loop {
        h *= 0.5;
        e_h = err(h);
        if e_h <= tol {
            break;
        }
        if h <= floor * 1.000001 {
            if !e_h.is_finite() {
                // The finest searched step's collisions do not end within their step budget
                // (e → 0 with DC_END_FORCE): no error law to extrapolate.
                return Err(Error::NoConvergence);
            }
            // Extrapolate E ∝ h^k from the two finest measurements, where they show such a law:
            // an error of e itself (≥ 100 %) or a halving that changes it by other than a
            // first- to second-order factor (with margin) is no asymptotic law, and its
            // extrapolation can miss by tens of decades (p = 1e6, e = 0.5: 1e-29 t* for 1e-6 t*).
            let k_raw = if e_fail.is_finite() && e_h > 0.0 {
                (e_fail / e_h).log2()
            } else {
                1.0
            };
            if !(e_h < 1.0 && (K_MIN..=K_MAX).contains(&k_raw)) {
                return Err(Error::NoConvergence);
            }
            let k = k_raw.clamp(0.5, 2.0);
            let h_ex = h * (tol / e_h).powf(1.0 / k);
            if !(tau / h_ex <= MAX_STEPS) {
                return Err(Error::NoConvergence);
            }
            return verified(h_ex, k, tau, err, tol).map(|h| (h, tau));
        }
        h_fail = h;
        e_fail = e_h;
    }
    let mut h_ok = h;
    for _ in 0..BISECTIONS {
        let mid = (h_ok * h_fail).sqrt();
        if err(mid) <= tol {
            h_ok = mid;
        } else {
            h_fail = mid;
        }
    }
    Ok((h_ok, tau))
}

/// The largest velocity-Verlet step [s] for which a power-law collision (exponent p, restitution
/// e calibrated exactly for `criterion`, impact speed v0, ω0 = √(k/m)) realises e within relative
/// tolerance `tol`, whatever the phase of first contact within a step. See the module docs.
pub fn dt_for_accuracy(
    p: f64,
    e: f64,
    criterion: EndCriterion,
    v0: f64,
    omega0: f64,
    tol: f64,
) -> Result<f64, Error> {
    if !(p.is_finite() && e.is_finite() && v0.is_finite() && omega0.is_finite() && tol.is_finite())
    {
        return Err(Error::NotFinite);
    }
    check_exponent(p)?;
    if !(e > 0.0 && e <= 1.0) {
        return Err(Error::RestitutionRange);
    }
    if !(v0 > 0.0 && omega0 > 0.0 && tol > 0.0) {
        return Err(Error::NotPositive);
    }
    // t* = δ*/v0 with δ* = (v0/ω0)^(2/(p+1)), in logs (the ratio alone may overflow).
    let ln_t = 2.0 / (p + 1.0) * (v0.ln() - omega0.ln()) - v0.ln();
    let (h, _) = unit_step(p, e, criterion, tol)?;
    let dt = (ln_t + h.ln()).exp();
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(dt)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The search's reference duration within 2 % of both the library's quadrature of the same
    /// contact ([`contact_duration`], 1e-10 relative) and a run at a step 2·10^4 times finer than
    /// the duration, including DC_END_FORCE contacts at small e that end within a few steps of
    /// the reference run (τ = 0.02 t* at e = 1e-8, 5.5e-5 t* at e = 1e-12 with p = 1, against its
    /// step of 1e-3 t*), where the reference takes the quadrature; and, shorter still (p = 1,
    /// e = 1e-15 and 1e-19), against the force-zero time of the overdamped linear contact.
    #[test]
    fn reference_duration_resolves_short_contacts() {
        for (p, e, crit) in [
            (1.5, 0.5, EndCriterion::Overlap),
            (1.5, 1e-3, EndCriterion::Force),
            (1.5, 1e-8, EndCriterion::Force),
            (1.0, 1e-12, EndCriterion::Force),
        ] {
            let pair = unit_pair(p, e, crit).unwrap();
            let tau = reference_duration(&pair).unwrap();
            let alpha = alpha_from_e(e, p, crit).unwrap();
            let exact = contact_duration(
                &Contact::new(p, alpha, 1.0, 1.0).unwrap(),
                crit,
                LEVEL_MAX as u32,
            )
            .unwrap();
            // And a run at a step 2·10^4 times finer than the duration (whichever of the two
            // the reference took, the other checks it).
            let fine = collide(
                &pair,
                1.0,
                1.0,
                1.0,
                exact / 2e4,
                0.5,
                Scheme::VelocityVerlet,
                1 << 26,
            )
            .unwrap()
            .duration;
            eprintln!(
                "p {p} e {e:e} {crit:?}: reference {tau:e}, quadrature {exact:e}, fine run {fine:e}"
            );
            assert!(
                (tau / exact - 1.0).abs() < 0.02,
                "p {p} e {e:e}: {tau:e} vs {exact:e}"
            );
            assert!(
                (tau / fine - 1.0).abs() < 0.02,
                "p {p} e {e:e}: {tau:e} vs {fine:e}"
            );
        }
        // Shorter still (an explicit run at any affordable step does not end there), p = 1: the
        // overdamped linear contact δ'' + α δ' + δ = 0, δ'(0) = 1, roots s± = −α/2 ± √(α²/4 − 1),
        // whose force −δ'' first vanishes at s₋² e^(s₋ t) = s₊² e^(s₊ t):
        // t = 2 ln(s₋/s₊)/(s₊ − s₋) (the quadrature's closed form is not used here).
        for e in [1e-15, 1e-19] {
            let alpha = alpha_from_e(e, 1.0, EndCriterion::Force).unwrap();
            let tau = reference_duration(&unit_pair(1.0, e, EndCriterion::Force).unwrap()).unwrap();
            let q = (0.25 * alpha * alpha - 1.0).sqrt();
            // s₊ from s₊ s₋ = 1 (−α/2 + q cancels).
            let sm = -0.5 * alpha - q;
            let sp = 1.0 / sm;
            let t = 2.0 * (sm / sp).ln() / (sp - sm);
            eprintln!("p 1 e {e:e} Force: reference {tau:e}, closed form {t:e}");
            assert!((tau / t - 1.0).abs() < 1e-6, "e {e:e}: {tau:e} vs {t:e}");
        }
    }

    /// An extrapolated step that misses by a few per cent (a first-order error 1.03 tol at
    /// h0, τ/h0 = 150 000: halving would leave the checked range) is refined to a passing step
    /// within the range; an error that never passes gives NoConvergence after at most
    /// VERIFY_TRIES checks; a step finer than the range is returned unchecked.
    #[test]
    fn extrapolated_step_refined_within_the_checked_range() {
        let (tau, tol, h0) = (1.0, 1e-4, 1.0 / 150_000.0);
        let checks = core::cell::Cell::new(0u32);
        let first_order = |h: f64| {
            checks.set(checks.get() + 1);
            1.03 * tol * h / h0
        };
        let h = verified(h0, 1.0, tau, first_order, tol).unwrap();
        assert!(first_order(h) <= tol && tau / h <= VERIFY_MAX_STEPS, "{h}");
        assert_eq!(checks.get(), 3, "two checks in the search, one here");

        checks.set(0);
        let never = |_: f64| {
            checks.set(checks.get() + 1);
            2.0 * tol
        };
        assert_eq!(
            verified(h0 * 4.0, 1.0, tau, never, tol),
            Err(Error::NoConvergence)
        );
        assert!(
            checks.get() >= 1 && checks.get() <= VERIFY_TRIES,
            "{}",
            checks.get()
        );

        checks.set(0);
        let fine = h0 / 4.0;
        assert_eq!(verified(fine, 1.0, tau, never, tol), Ok(fine));
        assert_eq!(checks.get(), 0);
    }
}
