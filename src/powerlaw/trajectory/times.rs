//! Pass 2: the sample times from the samples' own dt/du, by 8-point Lagrange stencils (local
//! error O(h^9)) away from the singular ends, by the edge series ([`super::edge_series`]) or the
//! quadrature next to them, and exactly (0 and τ) at both ends. The stencil's error next to an
//! edge is about E^{−8} relative (u^{q−1}'s 8th derivative at E steps), 1e−11 for E = 24.

use super::super::contact::Contact;
use super::edge_series::{EDGE, Edges};
use crate::criterion::EndCriterion;
use crate::numerics::lagrange8::{STENCIL, centred_increments};

/// Below this many samples every time is computed directly (no stencil).
const MIN_STENCIL: usize = 2 * EDGE + 16;
/// Largest (|κ| + |ω|)·h at which the stencil is used.
const STENCIL_RATE_H: f64 = 0.025;

/// Overwrites `t` (dt/du per unit time scale on entry, n ≥ 2 samples at phases j·h, the last at
/// `u_end`) with the times; `tau` is the contact duration (the last sample's time).
pub(super) fn fill_times(
    c: &Contact,
    criterion: EndCriterion,
    level: u32,
    tau: f64,
    u_end: f64,
    t: &mut [f64],
) {
    let n = t.len();
    let last = n.saturating_sub(1);
    let h = u_end / last as f64;
    let scale = c.ln_time_scale().exp();
    if c.q == 1.0 {
        // p = 1: dt/du is the constant P.
        for (j, t) in t.iter_mut().enumerate() {
            *t = if j == last {
                tau
            } else {
                scale * (j as f64 * h)
            };
        }
        return;
    }
    let kappa = (1.0 - c.q) * c.zeta;
    let lam = (1.0 - c.zeta) * (1.0 + c.zeta);
    let edges = Edges::new(c, criterion, h);
    let edge_u = edges.edge_u;
    // The stencil interpolates the smooth factor e^{κu}(S(u)/u)^ν too: its 8th-order error is
    // ~7e−4 (rate·h)^8 per step, rate = |κ| + |ω|; keep rate·h ≤ 0.05 (≤ 3e−14), else (extreme
    // ζ → 1 with few samples) every time is computed directly.
    let stencil = n >= MIN_STENCIL && (kappa.abs() + lam.abs().sqrt()) * h <= STENCIL_RATE_H;
    let r_of = |j: usize| edges.right.map(|(_, r_end)| r_end + (last - j) as f64 * h);
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
        if j == 0 {
            0.0
        } else if j == last {
            tau
        } else if !stencil || j <= EDGE || in_right_edge(j) {
            edges.time(c, level, scale, j, u, r_of(j))
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
    // t holds dt/du on entry; each sample's value is overwritten by its time once used, so the
    // last 8 values of dt/du are kept in `hist` (index mod 8).
    let mut hist = [0.0f64; 8];
    let mut t_prev = 0.0;
    let mut j = 0;
    while j < n {
        if j == fast.start && !fast.is_empty() {
            t_prev = centred_run(t, &mut hist, t_prev, fast.clone(), scale * h);
            j = fast.end;
            continue;
        }
        let f_here = t.get(j).copied().unwrap_or(f64::NAN);
        let tj = general(j, f_here, &hist, t, t_prev);
        if let Some(slot) = hist.get_mut(j % 8) {
            *slot = f_here;
        }
        if let Some(slot) = t.get_mut(j) {
            *slot = tj;
        }
        t_prev = tj;
        j += 1;
    }
}

/// The times of samples `run` (each interval [j−1, j] by the centred row), from `t_prev` at
/// `run.start − 1`; `sh` = P·h. Returns the time at `run.end − 1`. Blocks of up to BLOCK
/// intervals: the block's nodes j−4..j+len+2 copied into `w` (the four before j from `hist`:
/// `t` holds their times already), every increment at once (independent of each other: the
/// loop vectorises), then the running sum.
fn centred_run(
    t: &mut [f64],
    hist: &mut [f64; 8],
    mut t_prev: f64,
    run: core::ops::Range<usize>,
    sh: f64,
) -> f64 {
    const BLOCK: usize = 64;
    let mut w = [0.0f64; BLOCK + 8];
    let mut inc = [0.0f64; BLOCK];
    let mut jb = run.start;
    while jb < run.end {
        let len = (run.end - jb).min(BLOCK);
        for (i, wi) in w.iter_mut().enumerate().take(4) {
            *wi = hist.get((jb + i - 4) % 8).copied().unwrap_or(f64::NAN);
        }
        if let (Some(dst), Some(src)) = (w.get_mut(4..len + 7), t.get(jb..jb + len + 3)) {
            dst.copy_from_slice(src);
        }
        if let Some(inc) = inc.get_mut(..len) {
            centred_increments(&w, inc);
        }
        // The block's last 8 nodes' dt/du (older ones in `hist` stay valid).
        for node in (jb + len).saturating_sub(8).max(jb)..jb + len {
            if let (Some(slot), Some(&wi)) = (hist.get_mut(node % 8), w.get(node + 4 - jb)) {
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
    t_prev
}
