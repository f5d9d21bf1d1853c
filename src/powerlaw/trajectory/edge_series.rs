//! Times next to a singular end of dt/du (u = 0, and u = π/ω when underdamped), where
//! dt/du ~ u^{q−1} would spoil the stencil: t(u) = P u^q G(u) with
//! G(u) = ∫_0^1 y^{q−1} h(uy) dy = Σ_k h_k u^k/(q+k), h_k the Taylor coefficients of the analytic
//! h(w) = e^{κw}(S(w)/w)^{q−1} = exp(κw + (q−1) ln sinc) (radius π/|ω|); the right end is the same
//! with κ → −κ subtracted from the full integral T(π/ω) (closed form). Where the edge reaches
//! beyond `TAYLOR_RATIO` of that radius (coarse sampling), the quadrature of
//! [`super::super::duration`] is used instead.

use super::super::contact::{Contact, LN_SINC, Regime};
use super::super::duration::{ln_full_integral, time_at_phase};
use crate::criterion::EndCriterion;
use crate::numerics::pow;
use crate::numerics::series::{exp_series, horner};
use core::f64::consts::PI;

/// Phase steps next to a singular end whose times are not taken from the stencil.
pub(super) const EDGE: usize = 24;
/// Taylor terms of G, and the largest u|ω|/π (and |κ|u/10) at which they are used: 0.3^32 ≈ 2e−17.
const TAYLOR_K: usize = 32;
const TAYLOR_RATIO: f64 = 0.3;

/// Taylor coefficients g_k of G(u) = Σ g_k u^k for h = exp(φ), φ(w) = κw + ν Σ_m a_m (λw²)^m,
/// λ = 1 − ζ². Only the first `kk` (≤ TAYLOR_K) are computed: the cost is O(kk²).
fn g_series(q: f64, kappa: f64, lam: f64, kk: usize) -> [f64; TAYLOR_K] {
    let nu = q - 1.0;
    let mut phi = [0.0f64; TAYLOR_K];
    if let Some(x) = phi.get_mut(1) {
        *x = kappa;
    }
    let mut lp = 1.0;
    for (m, &a) in LN_SINC.iter().enumerate() {
        lp *= lam;
        if let Some(x) = phi.get_mut(2 * (m + 1)) {
            *x = nu * a * lp;
        }
    }
    let h = exp_series(&phi, kk);
    let mut g = [0.0f64; TAYLOR_K];
    for (k, (gk, &hk)) in g.iter_mut().zip(h.iter()).enumerate() {
        // q + k, not ν + k + 1: exact for k = 0 however small q is (p → ∞).
        *gk = hk / (q + k as f64);
    }
    g
}

/// x^q for one x: the branch-free kernel where it applies (no libm call), else libm.
#[inline]
fn pow_one(x: f64, q: f64) -> f64 {
    if pow::in_kernel_range(x) {
        pow::pow_kernel(x, q)
    } else {
        (q * x.ln()).exp()
    }
}

/// Both edges of one sampling (phase step h), prepared once per call.
pub(super) struct Edges {
    /// Phase width of an edge: `EDGE` steps.
    pub(super) edge_u: f64,
    /// Underdamped: (ω, the phase left from the last sample to π/ω).
    pub(super) right: Option<(f64, f64)>,
    q: f64,
    /// The series converge fast enough over the edge (else the quadrature is used).
    taylor_ok: bool,
    kk: usize,
    g_left: [f64; TAYLOR_K],
    g_right: [f64; TAYLOR_K],
    /// T(π/ω) per unit P, and e^{κπ/ω}: the right edge is t = P (T − e^{κπ/ω} r^q G₋(r)).
    full: f64,
    right_factor: f64,
}

impl Edges {
    pub(super) fn new(c: &Contact, criterion: EndCriterion, h: f64) -> Self {
        let (q, zeta) = (c.q, c.zeta);
        let kappa = (1.0 - q) * zeta;
        let lam = (1.0 - zeta) * (1.0 + zeta);
        let radius = if lam == 0.0 {
            f64::INFINITY
        } else {
            PI / lam.abs().sqrt()
        };
        let edge_u = EDGE as f64 * h;
        let taylor_ok =
            edge_u <= TAYLOR_RATIO * radius && kappa.abs() * edge_u <= 10.0 * TAYLOR_RATIO;
        // Terms for the edge: the series' terms fall like (u/radius)^k (the zeros of S) and
        // (|κ|u)^k/k! (the exponential); stop where both are below 1e−18 at u = edge_u.
        let kk = {
            let (t, ku) = (edge_u / radius, kappa.abs() * edge_u);
            let (mut a, mut b, mut k) = (1.0f64, 1.0f64, 0usize);
            while k < TAYLOR_K && (a > 1e-18 || b > 1e-18) {
                k += 1;
                a *= t;
                b *= ku / k as f64;
            }
            k
        };
        let g_left = if taylor_ok {
            g_series(q, kappa, lam, kk)
        } else {
            [0.0; TAYLOR_K]
        };
        // Right singular end (underdamped): π/ω, and the phase left from the last sample to it.
        let right = match c.regime {
            Regime::Under(w) => {
                let r_end = match criterion {
                    EndCriterion::Overlap => 0.0,
                    EndCriterion::Force => 2.0 * zeta.asin() / w,
                };
                Some((w, r_end))
            }
            _ => None,
        };
        let right_near = right.is_some_and(|(_, r_end)| r_end <= edge_u);
        let (g_right, full, right_factor) = match right {
            Some((w, _)) if right_near && taylor_ok => (
                g_series(q, -kappa, lam, kk),
                ln_full_integral(c, w).exp(),
                (kappa * PI / w).exp(),
            ),
            _ => ([0.0; TAYLOR_K], 0.0, 0.0),
        };
        Self {
            edge_u,
            right,
            q,
            taylor_ok,
            kk,
            g_left,
            g_right,
            full,
            right_factor,
        }
    }

    /// The time at phase u of sample j, in an edge or wherever the stencil is not used; `r` is
    /// the phase left to π/ω (underdamped), `scale` the time scale P.
    pub(super) fn time(
        &self,
        c: &Contact,
        level: u32,
        scale: f64,
        j: usize,
        u: f64,
        r: Option<f64>,
    ) -> f64 {
        let (q, kk) = (self.q, self.kk);
        let g_left = self.g_left.get(..kk).unwrap_or(&[]);
        let g_right = self.g_right.get(..kk).unwrap_or(&[]);
        match (r, self.right) {
            (Some(r), Some((w, _))) if r <= self.edge_u && u * w > 0.5 * PI => {
                if self.taylor_ok {
                    scale * (self.full - self.right_factor * pow_one(r, q) * horner(g_right, r))
                } else {
                    time_at_phase(c, u, level)
                }
            }
            _ if j <= EDGE && self.taylor_ok => scale * pow_one(u, q) * horner(g_left, u),
            _ => time_at_phase(c, u, level),
        }
    }
}
