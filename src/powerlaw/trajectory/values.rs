//! δ, F and dt/du at every sample from the state X (one power X^q per sample), and the δ = 0
//! samples at impact and at the overlap end.

use super::super::contact::Contact;
use super::TrajectoryOut;
use crate::criterion::EndCriterion;
use crate::numerics::pow;

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

/// Pass 1 after [`super::states::fill_states`]: X (in `out.delta`) and v (in `out.v`) become δ
/// and F, and `out.t` receives dt/du per unit time scale P, from X^q, the one transcendental pair
/// per sample: a branch-free kernel in a loop compiled for SIMD ([`pow`]), or libm where some X
/// lies outside the kernel's range. `k` = m ω0², `damp` = α m ω0.
pub(super) fn fill_values(
    c: &Contact,
    criterion: EndCriterion,
    k: f64,
    damp: f64,
    out: &mut TrajectoryOut<'_>,
) {
    let q = c.q;
    let last = out.t.len().saturating_sub(1);
    // δ = A x0^q X^q and δ^((p−1)/2) = A^((p−1)/2) x0^(1−q) X^(1−q): constant factors once.
    let ln_amp = c.amp.ln();
    let c_delta = (ln_amp + q * c.ln_x0).exp();
    let c_dh = (0.5 * (c.p - 1.0) * ln_amp + (1.0 - q) * c.ln_x0).exp();
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
    zero_overlap_ends(c, criterion, damp, out);
}

/// δ = 0 at impact (and at the end under the overlap criterion): only the linear dashpot (p = 1)
/// still acts there; dt/du is not used at these samples (their times are exact).
fn zero_overlap_ends(c: &Contact, criterion: EndCriterion, damp: f64, out: &mut TrajectoryOut<'_>) {
    let last = out.t.len().saturating_sub(1);
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
}
