//! The parametric time solution sampled over one contact, into caller buffers.
//!
//! Samples are uniform in the LSD phase u = ω0 s over [0, u_end] (u_end = π/ω for the overlap end,
//! 2u_m for the force end), dense where the contact is slow (near δ = 0 for p > 1).
//!
//! Cost: about one ln and one exp per sample. The pieces, in the order [`sample_trajectory`]
//! runs them:
//! * [`states`]: X(u) = e^{−ζu}S(u) and v(u) by recurrences: S(u), S'(u) (sin/cos, or sinh/cosh,
//!   of the phase) advance by a rotation by the step angle and e^{−ζu} by multiplication, both
//!   reseeded exactly every 16 samples (the rounding of a recurrence grows with the number of
//!   steps).
//! * [`values`]: ln X (one ln) gives X^q = e^{q ln X} (one exp), and everything else follows by
//!   products: δ = A x0^q X^q, δ^{(p−1)/2} = A^{(p−1)/2} x0^{1−q} X/X^q, δ^p = δ (δ^{(p−1)/2})²,
//!   dt/du = P X^q/X.
//! * [`times`]: t integrated from the samples' own dt/du by an 8-point Lagrange stencil
//!   ([`crate::numerics::lagrange8`]), except within 24 steps of a singular end of dt/du (u = 0,
//!   and u = π/ω when underdamped), where dt/du ~ u^{q−1} would spoil the stencil: there
//!   [`edge_series`] gives t(u) as u^q times a power series (or the quadrature of
//!   [`super::duration`] where the series would converge too slowly).
//! * a final check that every value is finite.

mod edge_series;
mod states;
mod times;
mod values;

use super::contact::Contact;
use super::duration::contact_duration;
use crate::Error;
use crate::criterion::EndCriterion;

/// Output buffers of [`sample_trajectory`]; all four must have the same length n ≥ 2.
pub struct TrajectoryOut<'a> {
    /// Time since impact [s].
    pub t: &'a mut [f64],
    /// Overlap δ [m].
    pub delta: &'a mut [f64],
    /// Overlap rate v = dδ/dt [m/s] (positive while compressing).
    pub v: &'a mut [f64],
    /// Total normal force F = k δ^p + α √(m k) δ^((p−1)/2) v [N].
    pub force: &'a mut [f64],
}

/// Fills `out` with n samples over the contact ending by `criterion`; `mass` > 0 scales the force.
/// Errors are detected before anything is written, except `ResultRange` from a sample that
/// overflowed or whose state underflowed (found after sampling; the buffers then hold no valid
/// data).
pub fn sample_trajectory(
    c: &Contact,
    criterion: EndCriterion,
    mass: f64,
    level: u32,
    mut out: TrajectoryOut<'_>,
) -> Result<(), Error> {
    check_mass_and_buffers(mass, &out)?;
    let tau = contact_duration(c, criterion, level)?;
    let u_end = match criterion {
        EndCriterion::Overlap => c.u_overlap()?,
        EndCriterion::Force => c.u_force(),
    };
    let k = mass * c.omega0 * c.omega0;
    let damp = c.alpha * mass * c.omega0;
    if !(k.is_finite() && damp.is_finite()) {
        return Err(Error::ResultRange);
    }
    let last = out.t.len() - 1;
    let h = u_end / last as f64;
    // Pass 1: X(u) parked in out.delta and v in out.v, then δ, F, and dt/du parked in out.t.
    states::fill_states(c, h, u_end, out.delta, out.v);
    values::fill_values(c, criterion, k, damp, &mut out);
    // Pass 2: times.
    times::fill_times(c, criterion, level, tau, u_end, out.t);
    all_finite(&out)
}

/// `mass` finite and > 0; all four buffers of one length n ≥ 2.
fn check_mass_and_buffers(mass: f64, out: &TrajectoryOut<'_>) -> Result<(), Error> {
    if !mass.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(mass > 0.0) {
        return Err(Error::NotPositive);
    }
    let n = out.t.len();
    if n < 2 || out.delta.len() != n || out.v.len() != n || out.force.len() != n {
        return Err(Error::BufferTooShort);
    }
    Ok(())
}

/// The last line of defence: a sample that overflowed or could not be computed (extreme inputs
/// beyond what the checks before sampling catch) turns the call into `ResultRange` rather than
/// a NaN or an infinity handed back as success.
fn all_finite(out: &TrajectoryOut<'_>) -> Result<(), Error> {
    // An integer OR over the exponent fields (all ones only for ±inf and NaN): a reduction the
    // compiler vectorises, unlike a chain of is_finite.
    const EXP: u64 = 0x7ff0_0000_0000_0000;
    let finite = |s: &[f64]| {
        s.iter()
            .fold(0u64, |acc, x| acc | u64::from(x.to_bits() & EXP == EXP))
            == 0
    };
    if finite(out.t) && finite(out.delta) && finite(out.v) && finite(out.force) {
        Ok(())
    } else {
        Err(Error::ResultRange)
    }
}

#[cfg(test)]
mod tests {
    use super::super::contact::Regime;
    use super::super::duration::time_at_phase;
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn all_finite_flags_every_non_finite_value() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -f64::NAN] {
            for buf in 0..4 {
                for pos in [0usize, 3, 6] {
                    let mut b = [[1.0f64, -0.0, 5e-324, f64::MAX, -f64::MAX, 1e-300, 2.0]; 4];
                    if let Some(x) = b.get_mut(buf).and_then(|r| r.get_mut(pos)) {
                        *x = bad;
                    }
                    let [t, d, v, f] = &mut b;
                    let out = TrajectoryOut {
                        t,
                        delta: d,
                        v,
                        force: f,
                    };
                    assert!(all_finite(&out).is_err(), "{bad} in buffer {buf} at {pos}");
                }
            }
        }
        let mut b = [[1.0f64, -0.0, 5e-324, f64::MAX, -f64::MAX, 1e-300, 2.0]; 4];
        let [t, d, v, f] = &mut b;
        assert!(
            all_finite(&TrajectoryOut {
                t,
                delta: d,
                v,
                force: f
            })
            .is_ok()
        );
    }
    use crate::numerics::jacobi_cc::MAX_LEVEL;

    /// Every sample time against the direct singularity-free quadrature of t(u) at the highest
    /// level (each sample on its own, no stencil, no recurrence): the stencil, the Taylor edges and
    /// the recurrences of the state must not cost accuracy. Also δ and v against their closed forms
    /// evaluated directly with sin/exp/powf.
    #[test]
    fn samples_match_direct_evaluation() {
        let mut worst_t: f64 = 0.0;
        let mut worst_d: f64 = 0.0;
        let mut worst_v: f64 = 0.0;
        let mut at = String::new();
        let mut at_d = String::new();
        for &p in &[1.0f64, 1.25, 1.5, 2.0, 3.0, 5.0] {
            for &z in &[
                0.0, 1e-3, 0.05, 0.2, 0.5, 0.7, 0.72, 0.9, 0.999, 1.0, 1.2, 4.0, 30.0,
            ] {
                let alpha = z * crate::powerlaw::damping_scale(p);
                let c = Contact::new(p, alpha, 0.4, 30.0).unwrap_or_else(|_| unreachable!());
                for crit in [EndCriterion::Overlap, EndCriterion::Force] {
                    if crit == EndCriterion::Overlap && z >= 1.0 {
                        continue;
                    }
                    for &n in &[41usize, 64, 65, 100, 401, 1000, 4000] {
                        let (mut t, mut d, mut v, mut f) =
                            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
                        let out = TrajectoryOut {
                            t: &mut t,
                            delta: &mut d,
                            v: &mut v,
                            force: &mut f,
                        };
                        sample_trajectory(&c, crit, 2.5, MAX_LEVEL, out)
                            .unwrap_or_else(|e| panic!("{e:?}"));
                        let u_end = match crit {
                            EndCriterion::Overlap => c.u_overlap().unwrap_or(f64::NAN),
                            EndCriterion::Force => c.u_force(),
                        };
                        let h = u_end / (n - 1) as f64;
                        for j in 1..n - 1 {
                            let u = j as f64 * h;
                            let want = time_at_phase(&c, u, MAX_LEVEL);
                            // Beyond ωu = π/2 the direct value is T(π/ω) − tail, which loses
                            // digits as T(π/ω)/T(u) (≈ e^{κπ/ω}, ζ → 1): skip where > 1e2.
                            if let Regime::Under(w) = c.regime {
                                let full = contact_duration(&c, EndCriterion::Overlap, MAX_LEVEL)
                                    .unwrap_or(f64::NAN);
                                if w * u > 0.5 * PI && full / want > 1e2 {
                                    continue;
                                }
                            }
                            let e = ((t[j] - want) / want).abs();
                            assert!(
                                e < 1e-10,
                                "p={p} ζ={z} {crit:?} n={n} j={j}: t {} vs {want} ({e:.1e})",
                                t[j]
                            );
                            if e > worst_t {
                                worst_t = e;
                                at = format!("p={p} ζ={z} {crit:?} n={n} j={j}");
                            }
                            let (s, ds) = c.s_and_slope(u);
                            let x = c.ln_x0.exp() * (-c.zeta * u).exp() * s;
                            let dd = c.amp * x.powf(c.q);
                            // δ ∝ S(u)^q near the zero of S at π/ω (the overlap end) inherits the
                            // rounding of the phase: relative error ~ε·(π/ω)/(π/ω − u) in both
                            // values compared. Measured in units of that conditioning.
                            let cond = match c.regime {
                                Regime::Under(w) if u * w > 0.5 * PI => (PI / w) / (PI / w - u),
                                _ => 1.0,
                            };
                            let ed = ((d[j] - dd) / dd).abs() / cond;
                            if ed > worst_d {
                                worst_d = ed;
                                at_d = format!("p={p} ζ={z} {crit:?} n={n} j={j}");
                            }
                            let vv = c.v0 * (-c.zeta * u).exp() * (ds - c.zeta * s);
                            worst_v = worst_v.max((v[j] - vv).abs() / c.v0);
                        }
                    }
                }
            }
        }
        println!(
            "trajectory vs direct: worst rel t {worst_t:.1e} ({at}), rel δ per conditioning {worst_d:.1e} ({at_d}), |Δv|/v0 {worst_v:.1e}"
        );
        assert!(worst_t < 2e-11 && worst_d < 1e-13 && worst_v < 1e-13);
    }
}
