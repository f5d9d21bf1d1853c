//! Contact duration and time of maximum overlap.
//!
//! Physical time along the LSD image (see [`super::contact`]): `t(U) = P·T(U)`,
//! `P = (A q/ω0)(v0/ω0)^{q−1}`, `T(U) = ∫_0^U e^{(1−q)ζu} S(u)^{q−1} du`.
//!
//! * p = 1 (q = 1): T(U) = U, every time is closed form.
//! * Overlap end, ζ < 1: with φ = ωu, `T(π/ω) = ω^{−q} ∫_0^π e^{cφ} sin^{q−1}φ dφ`, c = (1−q)ζ/ω,
//!   and (Gradshteyn & Ryzhik 3.892) `∫_0^π e^{cφ} sin^ν φ dφ = π e^{cπ/2} Γ(ν+1) /
//!   (2^ν |Γ(1 + ν/2 + ic/2)|²)`: closed form, evaluated in logarithms (τ → ∞ as ζ → 1).
//!   Undamped it is the seed's Beta function, √π Γ(q/2)/Γ((q+1)/2) = B(1/(p+1), 1/2).
//!   ζ ≥ 1: the overlap never returns to zero (t diverges as x → 0): `Error::NoEvent`.
//! * Time of maximum overlap (U = u_m) and force end (U = 2u_m): quadrature. The integrand is
//!   singular like u^{q−1} at u = 0 only when ωU ≤ π/2; beyond, T(U) = T(π/ω) − tail, and the
//!   tail ∫_U^{π/ω} is the same kind of integral with its singularity at its own origin
//!   (sin(ω(π/ω − w)) = sin ωw). The singular factor is split off exactly:
//!   `∫_0^W w^{q−1} h(w) dw = W^q ∫_0^1 y^{q−1} h(W y) dy`, h = e^{κw}(S(w)/w)^{q−1} analytic,
//!   and y^{q−1} is integrated exactly by Clenshaw–Curtis with modified moments
//!   ([`crate::numerics::jacobi_cc`]): the only error is the Chebyshev interpolation of h, whose
//!   nearest singularities (zeros of S at ±π/ω) lie ≥ 4 interval lengths away: ρ ≈ 9.9.
//!   Overdamped, the first panel ends at π/(2ω₂) (S has complex zeros at w = ikπ/ω₂ only);
//!   beyond it the integral is an exact, positive series ([`super::overdamped_tail`]).

use super::contact::ln_sinc_poly;
use super::contact::{Contact, Regime};
use super::overdamped_tail::overdamped_tail;
use crate::Error;
use crate::criterion::EndCriterion;
use crate::numerics::gamma::ln_gamma_re;
use crate::numerics::jacobi_cc::integrate_weighted_nu1;
use crate::numerics::pow::{EXP_KERNEL_MAX, exp_kernel};
use core::f64::consts::{FRAC_PI_2, LN_2, PI};

/// ∫_0^W e^{κw} S(w)^{q−1} dw for W ≥ 0 (ωW ≤ π/2 when underdamped).
fn singular_integral(c: &Contact, kappa: f64, big_w: f64, level: u32) -> f64 {
    let nu = c.q - 1.0;
    // First panel: W1^{ν+1} ∫_0^1 y^ν h(W1 y) dy, h = e^{κw}(S(w)/w)^ν analytic; the weight y^ν
    // is integrated exactly by the modified moments.
    let h = |w: f64| (kappa * w + nu * c.ln_sinc(w)).exp();
    by_panels(c, big_w, |first| {
        integrate_weighted_nu1(|y| h(first * y), c.q, level)
    })
}

/// ∫_0^W e^{κw} S(w)^{q−1} dw split where its rules apply: a first panel [0, W1] holding the
/// singularity, W1 = W but at most π/(2ω₂) when overdamped (S has complex zeros at ikπ/ω₂), which
/// contributes W1^q·`first_panel(W1)` (the rule's ∫_0^1 y^{q−1} h(W1 y) dy); beyond it, overdamped
/// only, the exact series of [`super::overdamped_tail`].
fn by_panels(c: &Contact, big_w: f64, first_panel: impl FnOnce(f64) -> f64) -> f64 {
    if big_w <= 0.0 {
        return 0.0;
    }
    let (first, tail) = match c.regime {
        Regime::Over(w2) if big_w > FRAC_PI_2 / w2 => {
            let first = FRAC_PI_2 / w2;
            (first, overdamped_tail(c.q - 1.0, c.zeta, w2, first, big_w))
        }
        _ => (big_w, 0.0),
    };
    (c.q * first.ln()).exp() * first_panel(first) + tail
}

/// ln T(π/ω), the full underdamped integral, in closed form (Gradshteyn 3.892).
pub(crate) fn ln_full_integral(c: &Contact, w: f64) -> f64 {
    ln_full_integral_with(c, w, libm::lgamma(c.q))
}

/// [`ln_full_integral`] with ln Γ(q) supplied (cached by a plan).
fn ln_full_integral_with(c: &Contact, w: f64, lgamma_q: f64) -> f64 {
    let q = c.q;
    let cc = (1.0 - q) * c.zeta / w;
    -q * w.ln() + PI.ln() + 0.5 * PI * cc + lgamma_q
        - (q - 1.0) * LN_2
        - 2.0 * ln_gamma_re(0.5 * (q + 1.0), 0.5 * cc)
}

/// T(U) for 0 ≤ U (U < π/ω when underdamped); `tail` optionally gives π/ω − U exactly.
fn time_integral(c: &Contact, big_u: f64, tail: Option<f64>, level: u32) -> f64 {
    if c.q == 1.0 {
        return big_u;
    }
    let kappa = (1.0 - c.q) * c.zeta;
    match c.regime {
        Regime::Under(w) if w * big_u > FRAC_PI_2 => {
            let rest = tail.unwrap_or(PI / w - big_u).max(0.0);
            let full = ln_full_integral(c, w);
            // T(π/ω) − e^{κπ/ω} ∫_0^{rest} e^{−κw} S(w)^{q−1} dw
            full.exp() - (kappa * PI / w).exp() * singular_integral(c, -kappa, rest, level)
        }
        _ => singular_integral(c, kappa, big_u, level),
    }
}

/// Physical time at LSD phase u (u < π/ω when underdamped), quadrature at `level`.
pub fn time_at_phase(c: &Contact, u: f64, level: u32) -> f64 {
    (c.ln_time_scale()).exp() * time_integral(c, u, None, level)
}

fn finish(ln_scale: f64, t: f64) -> Result<f64, Error> {
    let out = (ln_scale + t.ln()).exp();
    if !(out.is_finite() && out > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(out)
}

/// Time of maximum overlap, quadrature at `level` (0..=4; closed form when p = 1).
pub fn time_of_max_overlap(c: &Contact, level: u32) -> Result<f64, Error> {
    finish(c.ln_time_scale(), time_integral(c, c.u_max(), None, level))
}

/// Contact duration under `criterion`, quadrature at `level` (0..=4) where one is needed.
pub fn contact_duration(c: &Contact, criterion: EndCriterion, level: u32) -> Result<f64, Error> {
    match criterion {
        EndCriterion::Overlap => {
            let Regime::Under(w) = c.regime else {
                return Err(Error::NoEvent);
            };
            if c.q == 1.0 {
                return finish(c.ln_time_scale(), PI / w);
            }
            let ln_t = c.ln_time_scale() + ln_full_integral(c, w);
            let out = ln_t.exp();
            if !(out.is_finite() && out > 0.0) {
                return Err(Error::ResultRange);
            }
            Ok(out)
        }
        EndCriterion::Force => {
            let u = c.u_force();
            // Beyond π/2 the remaining phase to π/ω is 2 arcsin(ζ)/ω, computed without
            // cancellation.
            let tail = match c.regime {
                Regime::Under(w) => Some(2.0 * c.zeta.asin() / w),
                _ => None,
            };
            finish(c.ln_time_scale(), time_integral(c, u, tail, level))
        }
    }
}

/// A quadrature rule for ∫_0^1 y^ν f(y) dy, borrowed from a plan.
#[derive(Clone, Copy, Debug)]
pub struct Rule<'a> {
    /// Nodes in (0, 1).
    pub nodes: &'a [f64],
    /// Weights, same length.
    pub weights: &'a [f64],
}

/// What a duration plan caches for one exponent p: the constants of the transform, ln Γ(q), and
/// the Gauss rule for the weight y^{q−1} (the singular first panel).
#[derive(Clone, Copy, Debug)]
pub struct Plan<'a> {
    /// q = 2/(p+1).
    pub q: f64,
    /// A = ((p+1)/2)^(1/(p+1)).
    pub amp: f64,
    /// ln Γ(q).
    pub lgamma_q: f64,
    /// ln(A q).
    pub ln_aq: f64,
    /// Gauss–Jacobi rule for y^{q−1}.
    pub singular: Rule<'a>,
}

/// Gauss nodes of a plan per accuracy level (a rule of n nodes is exact to degree 2n − 1, like
/// Clenshaw–Curtis with 2n − 1 intervals).
pub(crate) const PLAN_NODES: [usize; 5] = [5, 6, 7, 9, 12];

/// Largest rule a plan holds.
pub(crate) const PLAN_MAX_NODES: usize = crate::numerics::gauss_jacobi::MAX_NODES;

/// ∫_0^1 y^ν h(W y) dy (h = e^{κw}(S(w)/w)^ν) by the plan's Gauss–Jacobi rule, for a first
/// panel W (|1 − ζ²| W² ≤ π²/4). Per node the exponent κw + ν ln(S(w)/w) takes the ln-sinc
/// series in z = (1 − ζ²)w² by Estrin's scheme and the exponential the branch-free kernel: no
/// libm call and no branch, so the nodes run side by side in SIMD lanes.
fn first_panel_planned(c: &Contact, kappa: f64, first: f64, pl: &Plan<'_>) -> f64 {
    let nu = c.q - 1.0;
    // z signed: ln(sin(ωw)/(ωw)) below critical damping, ln(sinh(ω₂w)/(ω₂w)) above.
    let lf2 = (1.0 - c.zeta) * (1.0 + c.zeta) * first * first;
    let kf = kappa * first;
    let mut args = [0.0f64; PLAN_MAX_NODES];
    for (a, &y) in args.iter_mut().zip(pl.singular.nodes) {
        let z = lf2 * y * y;
        *a = kf * y + nu * ln_sinc_poly(z);
    }
    let n = pl.singular.nodes.len().min(PLAN_MAX_NODES);
    let in_range = args.iter().take(n).all(|a| a.abs() <= EXP_KERNEL_MAX);
    // Exponentials in place first (an element-wise loop vectorises; an ordered sum would not).
    if in_range {
        args.iter_mut().for_each(|a| *a = exp_kernel(*a));
    } else {
        args.iter_mut().for_each(|a| *a = a.exp());
    }
    args.iter()
        .zip(pl.singular.weights)
        .map(|(&e, &wt)| wt * e)
        .sum()
}

/// [`singular_integral`] with a plan's rule for the first panel.
fn singular_integral_planned(c: &Contact, kappa: f64, big_w: f64, pl: &Plan<'_>) -> f64 {
    by_panels(c, big_w, |first| first_panel_planned(c, kappa, first, pl))
}

fn positive_finite(t: f64) -> Result<f64, Error> {
    if t.is_finite() && t > 0.0 {
        Ok(t)
    } else {
        Err(Error::ResultRange)
    }
}

/// [`contact_duration`] with a plan: same branches and formulas, the plan's Gauss rules and cached
/// constants, and the scale factors merged in logarithms (one exp per term instead of three).
pub fn contact_duration_planned(
    pl: &Plan<'_>,
    c: &Contact,
    criterion: EndCriterion,
) -> Result<f64, Error> {
    let ln_scale = pl.ln_aq + (c.q - 1.0) * c.ln_x0 - c.omega0.ln();
    match criterion {
        EndCriterion::Overlap => {
            let Regime::Under(w) = c.regime else {
                return Err(Error::NoEvent);
            };
            if c.q == 1.0 {
                return finish(ln_scale, PI / w);
            }
            positive_finite((ln_scale + ln_full_integral_with(c, w, pl.lgamma_q)).exp())
        }
        EndCriterion::Force => {
            let u = c.u_force();
            if c.q == 1.0 {
                return finish(ln_scale, u);
            }
            let kappa = (1.0 - c.q) * c.zeta;
            match c.regime {
                Regime::Under(w) if w * u > FRAC_PI_2 => {
                    // τ = P T(π/ω) − P e^{κπ/ω} rest^q ∫_0^1 y^ν h₋(rest·y) dy
                    let rest = 2.0 * c.zeta.asin() / w;
                    let full = (ln_scale + ln_full_integral_with(c, w, pl.lgamma_q)).exp();
                    if rest <= 0.0 {
                        return positive_finite(full);
                    }
                    let tail = (ln_scale + kappa * PI / w + c.q * rest.ln()).exp()
                        * first_panel_planned(c, -kappa, rest, pl);
                    positive_finite(full - tail)
                }
                Regime::Over(w2) if u > FRAC_PI_2 / w2 => {
                    finish(ln_scale, singular_integral_planned(c, kappa, u, pl))
                }
                _ => positive_finite(
                    (ln_scale + c.q * u.ln()).exp() * first_panel_planned(c, kappa, u, pl),
                ),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::jacobi_cc::MAX_LEVEL as DEFAULT_LEVEL;

    #[test]
    fn undamped_beta_function() {
        // τ0 = (2A/((p+1)ω0)) (v0/ω0)^{−(p−1)/(p+1)} B(1/(p+1), 1/2), B via libm's lgamma.
        for &p in &[1.0f64, 1.25, 1.5, 2.0, 3.0, 5.0, 11.0] {
            let (v0, w0) = (0.37, 21.0);
            let c = Contact::new(p, 0.0, v0, w0).unwrap_or_else(|_| unreachable!());
            let a = 1.0 / (p + 1.0);
            let beta = (libm::lgamma(a) + libm::lgamma(0.5) - libm::lgamma(a + 0.5)).exp();
            let want =
                2.0 * c.amp / ((p + 1.0) * w0) * (v0 / w0).powf(-(p - 1.0) / (p + 1.0)) * beta;
            let got =
                contact_duration(&c, EndCriterion::Overlap, DEFAULT_LEVEL).unwrap_or(f64::NAN);
            assert!(
                ((got - want) / want).abs() < 1e-14,
                "p={p}: {got} vs {want}"
            );
            // Undamped: both criteria coincide, and the maximum is reached at half time.
            let f = contact_duration(&c, EndCriterion::Force, DEFAULT_LEVEL).unwrap_or(f64::NAN);
            assert!(
                ((f - want) / want).abs() < 1e-14,
                "p={p}: force {f} vs {want}"
            );
            let tm = time_of_max_overlap(&c, DEFAULT_LEVEL).unwrap_or(f64::NAN);
            assert!(
                ((2.0 * tm - want) / want).abs() < 1e-14,
                "p={p}: 2 t_max {} vs {want}",
                2.0 * tm
            );
        }
    }
}

#[cfg(test)]
mod quadrature_vs_gamma {
    use super::*;

    /// Two independent routes to the full underdamped integral: Gradshteyn's Gamma closed form,
    /// and the quadrature of its two halves (each singular at its own origin). Their agreement
    /// measures the quadrature error free of any ODE reference.
    fn worst_at(level: u32) -> f64 {
        let mut worst: f64 = 0.0;
        for &p in &[1.25f64, 1.5, 2.0, 3.0, 5.0, 20.0] {
            // ζ ≤ 0.9: beyond, e^{κw} grows by e^{κπ/(2ω)} over the half interval, a regime the
            // library never integrates (it integrates at most to arccos(ζ)/ω ≈ 1 there).
            for &z in &[1e-4, 0.05, 0.3, 0.6, 0.707, 0.9] {
                let c = Contact::new(p, z * crate::powerlaw::damping_scale(p), 1.0, 1.0)
                    .unwrap_or_else(|_| unreachable!());
                let Regime::Under(w) = c.regime else {
                    unreachable!()
                };
                let kappa = (1.0 - c.q) * c.zeta;
                let half = FRAC_PI_2 / w;
                let quad = singular_integral(&c, kappa, half, level)
                    + (kappa * PI / w).exp() * singular_integral(&c, -kappa, half, level);
                let closed = ln_full_integral(&c, w).exp();
                let err = ((quad - closed) / closed).abs();
                worst = worst.max(err);
            }
        }
        worst
    }

    /// Bound per level, quoted in docs/powerlaw.md (measured 1.1e-6, 7.9e-9, 2.7e-12, 9.8e-15,
    /// 9.8e-15).
    #[test]
    fn levels() {
        const BOUND: [f64; 5] = [3e-6, 2e-8, 1e-11, 3e-14, 3e-14];
        for (level, b) in (0..=crate::numerics::jacobi_cc::MAX_LEVEL).zip(BOUND) {
            let w = worst_at(level);
            println!("level {level}: worst relative difference {w:.1e}");
            assert!(w <= b, "level {level}: {w:.1e} above its bound {b:.0e}");
        }
    }
}
