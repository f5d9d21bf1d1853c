//! The parametric time solution sampled over one contact, into caller buffers.
//!
//! Samples are uniform in the LSD phase u = ω0 s over [0, u_end] (u_end = π/ω for the overlap end,
//! 2u_m for the force end), dense where the contact is slow (near δ = 0 for p > 1).
//!
//! Cost: about one ln and one exp per sample.
//! * State: S(u), S'(u) (sin/cos, or sinh/cosh, of the phase) advance by a rotation by the step
//!   angle and e^{−ζu} by multiplication, both reseeded exactly every `RESEED` samples (the
//!   rounding of a recurrence grows with the number of steps). Then ln X (one ln) gives
//!   X^q = e^{q ln X} (one exp), and everything else follows by products: δ = A x0^q X^q,
//!   δ^{(p−1)/2} = A^{(p−1)/2} x0^{1−q} X/X^q, δ^p = δ (δ^{(p−1)/2})², dt/du = P X^q/X.
//! * Time: t is integrated from the samples' own dt/du by an 8-point Lagrange stencil (local
//!   error O(h^9)), except within `EDGE` steps of a singular end of dt/du (u = 0, and u = π/ω when
//!   underdamped), where dt/du ~ u^{q−1} would spoil the stencil: there t(u) = P u^q G(u) with
//!   G(u) = ∫_0^1 y^{q−1} h(uy) dy = Σ_k h_k u^k/(q+k), h_k the Taylor coefficients of the
//!   analytic h(w) = e^{κw}(S(w)/w)^{q−1} = exp(κw + (q−1) ln sinc) (exponential of a series by
//!   the recurrence k h_k = Σ i φ_i h_{k−i}), radius π/|ω|; the right end is the same with κ → −κ
//!   subtracted from the full integral T(π/ω) (closed form). Where the edge reaches beyond
//!   0.3 of that radius (coarse sampling), the edge samples take the quadrature of
//!   [`super::duration`] instead. The stencil's error next to the edge is about E^{−8} relative
//!   (u^{q−1}'s 8th derivative at E steps), 1e−11 for E = 24.

use super::contact::{Contact, LN_SINC, Regime};
use super::duration::{contact_duration, ln_full_integral, time_at_phase};
use crate::Error;
use crate::criterion::EndCriterion;
use crate::numerics::pow;
use core::f64::consts::PI;

/// Phase steps next to a singular end whose times are not taken from the stencil.
const EDGE: usize = 24;
/// Samples between exact reseeds of the rotation recurrences.
const RESEED: usize = 16;
/// Below this many samples every time is computed directly (no stencil).
const MIN_STENCIL: usize = 2 * EDGE + 16;
/// Largest (|κ| + |ω|)·h at which the stencil is used.
const STENCIL_RATE_H: f64 = 0.025;
/// Taylor terms of G, and the largest u|ω|/π (and |κ|u/10) at which they are used: 0.3^32 ≈ 2e−17.
const TAYLOR_K: usize = 32;
const TAYLOR_RATIO: f64 = 0.3;

/// ∫_0^1 of the Lagrange interpolant through nodes i − s (i = 0..8) over [0, 1], for s = 0..=6:
/// t(j+1) − t(j) = h Σ_i C[s][i] f(j − s + i). Exact rationals (rounded), each row sums to 1.
const STENCIL: [[f64; 8]; 7] = [
    [
        0.30422453703703706,
        1.1561590608465608,
        -1.0069196428571427,
        1.0179646164021163,
        -0.7320353835978836,
        0.3430803571428571,
        -0.09384093915343915,
        0.01136739417989418,
    ],
    [
        -0.01136739417989418,
        0.3951636904761905,
        0.8378720238095239,
        -0.3703455687830688,
        0.2222470238095238,
        -0.09546130952380952,
        0.024793320105820107,
        -0.0029017857142857144,
    ],
    [
        0.0029017857142857144,
        -0.034581679894179894,
        0.4764136904761905,
        0.6753720238095238,
        -0.1672205687830688,
        0.05974702380952381,
        -0.014211309523809524,
        0.0015790343915343915,
    ],
    [
        -0.0015790343915343915,
        0.015534060846560846,
        -0.07879464285714285,
        0.5648396164021164,
        0.5648396164021164,
        -0.07879464285714285,
        0.015534060846560846,
        -0.0015790343915343915,
    ],
    [
        0.0015790343915343915,
        -0.014211309523809524,
        0.05974702380952381,
        -0.1672205687830688,
        0.6753720238095238,
        0.4764136904761905,
        -0.034581679894179894,
        0.0029017857142857144,
    ],
    [
        -0.0029017857142857144,
        0.024793320105820107,
        -0.09546130952380952,
        0.2222470238095238,
        -0.3703455687830688,
        0.8378720238095239,
        0.3951636904761905,
        -0.01136739417989418,
    ],
    [
        0.01136739417989418,
        -0.09384093915343915,
        0.3430803571428571,
        -0.7320353835978836,
        1.0179646164021163,
        -1.0069196428571427,
        1.1561590608465608,
        0.30422453703703706,
    ],
];

/// Taylor coefficients g_k of G(u) = Σ g_k u^k (module docs) for h = exp(φ),
/// φ(w) = κw + ν Σ_m a_m (λw²)^m, λ = 1 − ζ².
/// Only the first `kk` (≤ TAYLOR_K) are computed: the cost is O(kk²).
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
    let mut h = [0.0f64; TAYLOR_K];
    if let Some(x) = h.get_mut(0) {
        *x = 1.0;
    }
    for k in 1..kk.min(TAYLOR_K) {
        let s: f64 = phi
            .iter()
            .enumerate()
            .skip(1)
            .take(k)
            .zip(h.iter().take(k).rev())
            .map(|((i, &f), &hh)| i as f64 * f * hh)
            .sum();
        if let Some(x) = h.get_mut(k) {
            *x = s / k as f64;
        }
    }
    let mut g = [0.0f64; TAYLOR_K];
    for (k, (gk, &hk)) in g.iter_mut().zip(h.iter()).enumerate() {
        // q + k, not ν + k + 1: exact for k = 0 however small q is (p → ∞).
        *gk = hk / (q + k as f64);
    }
    g
}

fn horner(g: &[f64; TAYLOR_K], u: f64, kk: usize) -> f64 {
    g.iter().take(kk).rev().fold(0.0, |acc, &c| acc * u + c)
}

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

/// (S, S') one phase step h further on, as a matrix acting on (S, S'): the rotation by ωh
/// (hyperbolic by ω₂h above critical damping, a shear at ζ = 1).
fn step_matrix(c: &Contact, h: f64) -> [f64; 4] {
    match c.regime {
        Regime::Under(w) => {
            let (s, co) = (w * h).sin_cos();
            [co, s / w, -w * s, co]
        }
        Regime::Critical => [1.0, h, 0.0, 1.0],
        Regime::Over(w2) => {
            let (s, co) = ((w2 * h).sinh(), (w2 * h).cosh());
            [co, s / w2, w2 * s, co]
        }
    }
}

/// X(u_j) = e^{−ζu}S(u) into `x` and v(u_j) into `v`, u_j = j·h (the last at u_end exactly). The
/// state advances by [`step_matrix`] and e^{−ζu} by a factor, reseeded exactly every `RESEED`
/// samples (a recurrence's rounding grows with its number of steps): no transcendental per sample.
fn fill_states(c: &Contact, h: f64, u_end: f64, x: &mut [f64], v: &mut [f64]) {
    let zeta = c.zeta;
    let [m11, m12, m21, m22] = step_matrix(c, h);
    let decay_step = (-zeta * h).exp();
    // LANES chunks advance side by side: four independent recurrence chains instead of one,
    // so the loop runs at the CPU's throughput rather than at one chain's latency.
    const LANES: usize = 4;
    // Only the group's first chunk is seeded exactly (a sin/cos and an exp); the other lanes
    // start from it by one exact step of l·RESEED phases each (computed once per call), so a
    // sample is at most 1 + 15 recurrence steps from an exact value instead of 15.
    let chunks = x.len().div_ceil(RESEED);
    let big: [([f64; 4], f64); LANES] = core::array::from_fn(|l| {
        let hl = (l * RESEED) as f64 * h;
        (step_matrix(c, hl), (-zeta * hl).exp())
    });
    for group in (0..chunks).step_by(LANES) {
        let mut st = [(0.0f64, 0.0f64, 0.0f64); LANES];
        let u0 = (group * RESEED) as f64 * h;
        let (s0, ds0) = c.s_and_slope(u0);
        let d0 = (-zeta * u0).exp();
        for (st, &([b11, b12, b21, b22], dl)) in st.iter_mut().zip(big.iter()) {
            *st = (b11 * s0 + b12 * ds0, b21 * s0 + b22 * ds0, d0 * dl);
        }
        for i in 0..RESEED {
            for (l, (s, ds, decay)) in st.iter_mut().enumerate() {
                let j = (group + l) * RESEED + i;
                if let (Some(xj), Some(vj)) = (x.get_mut(j), v.get_mut(j)) {
                    *xj = *decay * *s;
                    *vj = c.v0 * *decay * (*ds - zeta * *s);
                }
                (*s, *ds) = (m11 * *s + m12 * *ds, m21 * *s + m22 * *ds);
                *decay *= decay_step;
            }
        }
    }
    let last = x.len().saturating_sub(1);
    let at = |j: usize| if j == last { u_end } else { j as f64 * h };
    if let (Some(xl), Some(vl)) = (x.last_mut(), v.last_mut()) {
        let (s, ds) = c.s_and_slope(u_end);
        let decay = (-zeta * u_end).exp();
        *xl = decay * s;
        *vl = c.v0 * decay * (ds - zeta * s);
    }
    // Strongly overdamped: e^{−ζu}(cosh ω₂u − ζ sinh(ω₂u)/ω₂) as two decaying exponentials,
    // λ₂ = ζ + ω₂ and λ₁ = 1/λ₂ = ζ − ω₂. The cosh/sinh form cancels to ~4ζ²ε at the force end
    // (1.2e-10 relative exit speed at ζ = 400, tests/proptest_ffi.rs); this one only near critical
    // damping, hence the switch at ζ = 2 (both ≤ 16ε there).
    // X likewise: e^{−u/λ₂}(1 − e^{−2ω₂u})/(2ω₂), by expm1 (no cancellation at small u), which
    // also never forms sinh(ω₂u) (it overflows for ω₂u > 710 while e^{−ζu} underflows: NaN).
    if let Regime::Over(w2) = c.regime
        && zeta >= 2.0
    {
        let l2 = zeta + w2;
        for (j, (xj, vj)) in x.iter_mut().zip(v.iter_mut()).enumerate().skip(1) {
            let u = at(j);
            *xj = -(-u / l2).exp() * (-2.0 * w2 * u).exp_m1() / (2.0 * w2);
            *vj = c.v0 * 0.5 * ((1.0 + zeta / w2) * (-l2 * u).exp() - (-u / l2).exp() / (w2 * l2));
        }
    }
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

/// Constant factors from X to δ, δ^((p−1)/2) and F.
struct Scales {
    c_delta: f64,
    c_dh: f64,
    k: f64,
    damp: f64,
}

impl Scales {
    /// X (in `d`) → δ, F and dt/du (into `t`), given X^q = pow(X); generic so that `pow` inlines
    /// and the loop vectorises.
    #[inline(always)]
    fn fill<P: Fn(f64) -> f64>(
        &self,
        t: &mut [f64],
        d: &mut [f64],
        v: &[f64],
        f: &mut [f64],
        pow: P,
    ) {
        for (((t, d), &vj), f) in t.iter_mut().zip(d.iter_mut()).zip(v).zip(f.iter_mut()) {
            let x = *d;
            let xq = pow(x);
            let dj = self.c_delta * xq;
            let dh = self.c_dh * x / xq;
            *d = dj;
            *f = self.k * dj * dh * dh + self.damp * dh * vj;
            *t = xq / x;
        }
    }
}

/// [`Scales::fill`] with the branch-free power kernel, as a loop for [`pow::vectorised`].
struct KernelFill<'a> {
    scales: &'a Scales,
    q: f64,
    t: &'a mut [f64],
    d: &'a mut [f64],
    v: &'a [f64],
    f: &'a mut [f64],
}

impl pow::SimdLoop for KernelFill<'_> {
    #[inline(always)]
    fn run(self) {
        let q = self.q;
        self.scales
            .fill(self.t, self.d, self.v, self.f, |x| pow::pow_kernel(x, q));
    }
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
    out: TrajectoryOut<'_>,
) -> Result<(), Error> {
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
    let (q, zeta) = (c.q, c.zeta);
    let kappa = (1.0 - q) * zeta;
    let last = n - 1;
    let h = u_end / last as f64;
    let scale = c.ln_time_scale().exp();
    // δ = A x0^q X^q and δ^((p−1)/2) = A^((p−1)/2) x0^(1−q) X^(1−q): constant factors once.
    let ln_amp = c.amp.ln();
    let c_delta = (ln_amp + q * c.ln_x0).exp();
    let c_dh = (0.5 * (c.p - 1.0) * ln_amp + (1.0 - q) * c.ln_x0).exp();

    // Pass 1: X(u) parked in out.delta and v in out.v; then δ, F and dt/du (per unit P, parked in
    // out.t) from X^q, the one transcendental pair per sample: a branch-free kernel in a loop
    // compiled for SIMD ([`pow`]), or libm where some X lies outside the kernel's range.
    fill_states(c, h, u_end, out.delta, out.v);
    let scales = Scales {
        c_delta,
        c_dh,
        k,
        damp,
    };
    // Samples not overwritten below as δ = 0 ends.
    let kept = match criterion {
        EndCriterion::Overlap => out.delta.get(1..last),
        EndCriterion::Force => out.delta.get(1..),
    };
    if q == 1.0 {
        // p = 1: x^(1−q) = 1 exactly, also where e^{−ζu} has underflowed to x = 0 (near-critical
        // damping, u_end ~ π/ω huge), which x/xq would turn into 0/0.
        for (((t, d), &vj), f) in out
            .t
            .iter_mut()
            .zip(out.delta.iter_mut())
            .zip(out.v.iter())
            .zip(out.force.iter_mut())
        {
            let dj = c_delta * *d;
            *d = dj;
            *f = k * dj * c_dh * c_dh + damp * c_dh * vj;
            *t = 1.0;
        }
    } else if kept
        .unwrap_or(&[])
        .iter()
        .fold(0u64, |acc, &x| acc | u64::from(!pow::in_kernel_range(x)))
        == 0
    {
        // (An OR over the slice vectorises; a short-circuiting `all` does not.)
        pow::vectorised(KernelFill {
            scales: &scales,
            q,
            t: out.t,
            d: out.delta,
            v: out.v,
            f: out.force,
        });
    } else {
        scales.fill(out.t, out.delta, out.v, out.force, |x| (q * x.ln()).exp());
    }
    // δ = 0 at impact (and at the end under the overlap criterion): only the linear dashpot
    // (p = 1) still acts there.
    for j in [
        Some(0),
        (criterion == EndCriterion::Overlap).then_some(last),
    ]
    .into_iter()
    .flatten()
    {
        let vj = out.v.get(j).copied().unwrap_or(0.0);
        if let (Some(d), Some(f), Some(t)) =
            (out.delta.get_mut(j), out.force.get_mut(j), out.t.get_mut(j))
        {
            *d = 0.0;
            *f = if c.p == 1.0 { damp * vj } else { 0.0 };
            *t = 0.0;
        }
    }

    // Pass 2: times.
    if q == 1.0 {
        for (j, t) in out.t.iter_mut().enumerate() {
            *t = if j == last {
                tau
            } else {
                scale * (j as f64 * h)
            };
        }
        return all_finite(&out);
    }
    let lam = (1.0 - zeta) * (1.0 + zeta);
    let radius = if lam == 0.0 {
        f64::INFINITY
    } else {
        PI / lam.abs().sqrt()
    };
    let edge_u = EDGE as f64 * h;
    let taylor_ok = edge_u <= TAYLOR_RATIO * radius && kappa.abs() * edge_u <= 10.0 * TAYLOR_RATIO;
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
    // Right edge: t = P (T(π/ω) − e^{κπ/ω} r^q G₋(r)), r the phase left to π/ω; both factors once.
    let (g_right, full, right_factor) = match right {
        Some((w, _)) if right_near && taylor_ok => (
            g_series(q, -kappa, lam, kk),
            ln_full_integral(c, w).exp(),
            (kappa * PI / w).exp(),
        ),
        _ => ([0.0; TAYLOR_K], 0.0, 0.0),
    };
    // The stencil interpolates the smooth factor e^{κu}(S(u)/u)^ν too: its 8th-order error is
    // ~7e−4 (rate·h)^8 per step, rate = |κ| + |ω|; keep rate·h ≤ 0.05 (≤ 3e−14), else (extreme
    // ζ → 1 with few samples) every time is computed directly.
    let stencil = n >= MIN_STENCIL && (kappa.abs() + lam.abs().sqrt()) * h <= STENCIL_RATE_H;
    let r_of = |j: usize| right.map(|(_, r_end)| r_end + (last - j) as f64 * h);
    let in_right_edge = |j: usize| r_of(j).is_some_and(|r| r <= edge_u);
    // Samples whose interval [j−1, j] takes the centred stencil row (nodes j−4..j+3, none in an
    // edge): a loop with no per-sample branching. The rest go through `general`.
    let fast = if stencil {
        let lo = EDGE + 1;
        let mut hi = (n - 4).min(last - 1);
        while hi >= lo && in_right_edge(hi) {
            hi -= 1;
        }
        lo..hi + 1
    } else {
        0..0
    };
    let general = |j: usize, f_here: f64, hist: &[f64; 8], t: &[f64], t_prev: f64| -> f64 {
        let u = if j == last { u_end } else { j as f64 * h };
        let r = r_of(j);
        if j == 0 {
            0.0
        } else if j == last {
            tau
        } else if !stencil || j <= EDGE || in_right_edge(j) {
            match (r, right) {
                (Some(r), Some((w, _))) if r <= edge_u && u * w > 0.5 * PI => {
                    if taylor_ok {
                        scale * (full - right_factor * pow_one(r, q) * horner(&g_right, r, kk))
                    } else {
                        time_at_phase(c, u, level)
                    }
                }
                _ if j <= EDGE && taylor_ok => scale * pow_one(u, q) * horner(&g_left, u, kk),
                _ => time_at_phase(c, u, level),
            }
        } else {
            // Interval [j−1, j] by the stencil on nodes start..start+8 (centred when possible).
            let start = (j - 1).saturating_sub(3).min(n - 8);
            let srow = (j - 1 - start).min(6);
            let row = STENCIL.get(srow).copied().unwrap_or([f64::NAN; 8]);
            let mut acc = 0.0;
            for (i, &cw) in row.iter().enumerate() {
                let idx = start + i;
                let fv = if idx < j {
                    hist.get(idx % 8).copied().unwrap_or(f64::NAN)
                } else {
                    t.get(idx).copied().unwrap_or(f_here)
                };
                acc += cw * fv;
            }
            t_prev + scale * h * acc
        }
    };
    // out.t holds dt/du on entry; each sample's value is overwritten by its time once used, so
    // the last 8 values of dt/du are kept in `hist` (index mod 8).
    let mut hist = [0.0f64; 8];
    let mut t_prev = 0.0;
    let mut j = 0;
    while j < n {
        if j == fast.start && !fast.is_empty() {
            let [c0, c1, c2, c3, ..] = STENCIL[3];
            let sh = scale * h;
            let t = &mut *out.t;
            // Blocks of up to BLOCK intervals: the block's nodes j−4..j+len+2 copied into `w`
            // (the four before j from `hist`: t holds their times already), every increment at
            // once (independent of each other: the loop vectorises), then the running sum.
            const BLOCK: usize = 64;
            let mut w = [0.0f64; BLOCK + 8];
            let mut inc = [0.0f64; BLOCK];
            let mut jb = j;
            while jb < fast.end {
                let len = (fast.end - jb).min(BLOCK);
                for (i, wi) in w.iter_mut().enumerate().take(4) {
                    *wi = hist.get((jb + i - 4) % 8).copied().unwrap_or(f64::NAN);
                }
                if let (Some(dst), Some(src)) = (w.get_mut(4..len + 7), t.get(jb..jb + len + 3)) {
                    dst.copy_from_slice(src);
                }
                // inc[i] from w[i..i+8], as eight shifted slices zipped (vectorises; a window
                // per element does not). The centred row is symmetric: pair the nodes.
                let shifted = |k: usize| w.get(k..k + len).unwrap_or(&[]);
                inc.iter_mut()
                    .zip(shifted(0).iter().zip(shifted(7)))
                    .zip(shifted(1).iter().zip(shifted(6)))
                    .zip(shifted(2).iter().zip(shifted(5)))
                    .zip(shifted(3).iter().zip(shifted(4)))
                    .for_each(|((((x, (a0, a7)), (a1, a6)), (a2, a5)), (a3, a4))| {
                        *x = c0 * (a0 + a7) + c1 * (a1 + a6) + c2 * (a2 + a5) + c3 * (a3 + a4);
                    });
                // The block's last 8 nodes' dt/du (older ones in `hist` stay valid).
                for node in (jb + len).saturating_sub(8).max(jb)..jb + len {
                    if let (Some(slot), Some(&wi)) = (hist.get_mut(node % 8), w.get(node + 4 - jb))
                    {
                        *slot = wi;
                    }
                }
                // The running sum two samples a step: one dependent addition per pair.
                if let (Some(ts), Some(is)) = (t.get_mut(jb..jb + len), inc.get(..len)) {
                    let mut tc = ts.chunks_exact_mut(2);
                    let mut ic = is.chunks_exact(2);
                    for (tp, ip) in (&mut tc).zip(&mut ic) {
                        if let ([t0, t1], [i0, i1]) = (tp, ip) {
                            *t0 = t_prev + sh * i0;
                            t_prev += sh * (i0 + i1);
                            *t1 = t_prev;
                        }
                    }
                    for (ti, &x) in tc.into_remainder().iter_mut().zip(ic.remainder()) {
                        t_prev += sh * x;
                        *ti = t_prev;
                    }
                }
                jb += len;
            }
            j = fast.end;
            continue;
        }
        let f_here = out.t.get(j).copied().unwrap_or(f64::NAN);
        let tj = general(j, f_here, &hist, out.t, t_prev);
        if let Some(slot) = hist.get_mut(j % 8) {
            *slot = f_here;
        }
        if let Some(slot) = out.t.get_mut(j) {
            *slot = tj;
        }
        t_prev = tj;
        j += 1;
    }
    all_finite(&out)
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
    use super::*;

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
