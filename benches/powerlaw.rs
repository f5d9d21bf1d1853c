//! Cost of the power-law observables through the C ABI, against baselines measured in the same
//! run: the bare `ln` (for the closed forms) and the adaptive Dormand–Prince reference
//! (`demcontact::numerics::ode::integrate_to_event`) run at the loosest tolerance at which it
//! still reaches 1e-10 on the same quantity (tests/powerlaw_vs_ode.rs,
//! `reference_tolerance_for_*`, prints and checks those tolerances).
//! Case: p = 1.5 (Hertz), α from the force-end calibration, v0 = ω0 = 1. The planned duration
//! (`duration_force_end_planned`, plan built once outside the timed loop) and `trajectory_1000`
//! are the two figures the issue asks to be 100× the reference (docs/powerlaw.md).
//! Run: `cargo bench --bench powerlaw`; `scripts/bench_powerlaw_ratios.sh [runs]` prints the two
//! ratios from repeated runs.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

#[path = "../tests/common/mod.rs"]
mod common;

use demcontact::EndCriterion;
use demcontact::ffi::{calibration::*, powerlaw::*, status::*};
use divan::{Bencher, black_box, counter::ItemsCount};

fn main() {
    divan::main();
}

const ES: [f64; 8] = [0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999];
const P: f64 = 1.5;

fn alphas(crit: i32) -> [f64; 8] {
    let mut a = [0.0; 8];
    for (x, &e) in a.iter_mut().zip(&ES) {
        unsafe { dc_alpha_from_e(e, P, crit, x) };
    }
    a
}

#[divan::bench]
fn baseline_ln(b: Bencher) {
    b.counter(ItemsCount::new(ES.len()))
        .bench(|| ES.iter().map(|&e| black_box(e).ln()).sum::<f64>());
}

#[divan::bench]
fn max_overlap(b: Bencher) {
    let a = alphas(DC_END_FORCE);
    b.counter(ItemsCount::new(a.len())).bench(|| {
        let mut s = 0.0;
        for &al in &a {
            let mut d = 0.0;
            unsafe {
                dc_max_overlap(
                    black_box(P),
                    black_box(al),
                    black_box(1.0),
                    black_box(1.0),
                    &mut d,
                )
            };
            s += d;
        }
        s
    });
}

#[divan::bench]
fn energy_partition_force_end(b: Bencher) {
    let a = alphas(DC_END_FORCE);
    b.counter(ItemsCount::new(a.len())).bench(|| {
        let mut s = 0.0;
        for &al in &a {
            let mut en = dc_energy::default();
            unsafe { dc_energy_partition(black_box(P), black_box(al), DC_END_FORCE, &mut en) };
            s += en.unloading;
        }
        s
    });
}

#[divan::bench]
fn duration_overlap_end_closed_form(b: Bencher) {
    let a = alphas(DC_END_OVERLAP);
    b.counter(ItemsCount::new(a.len())).bench(|| {
        let mut s = 0.0;
        for &al in &a {
            let mut t = 0.0;
            unsafe {
                dc_contact_duration(
                    black_box(P),
                    black_box(al),
                    black_box(1.0),
                    black_box(1.0),
                    DC_END_OVERLAP,
                    &mut t,
                )
            };
            s += t;
        }
        s
    });
}

/// Force-end duration by quadrature; level 2 (13 evaluations) reaches ≤ 5e-13 against the
/// reference, level 4 is the default of dc_contact_duration.
#[divan::bench(args = [0, 1, 2, 3, 4])]
fn duration_force_end_level(b: Bencher, level: i32) {
    let a = alphas(DC_END_FORCE);
    b.counter(ItemsCount::new(a.len())).bench(|| {
        let mut s = 0.0;
        for &al in &a {
            let mut t = 0.0;
            unsafe {
                dc_contact_duration_level(
                    black_box(P),
                    black_box(al),
                    1.0,
                    1.0,
                    DC_END_FORCE,
                    level,
                    &mut t,
                )
            };
            s += t;
        }
        s
    });
}

/// Force-end duration with a plan built once for p (dc_duration_plan_init); level 2 (7 Gauss
/// nodes) reaches 1e-10 (tests/powerlaw_plan.rs, tests/powerlaw_vs_ode.rs `accuracy_levels`).
#[divan::bench(args = [0, 1, 2, 3, 4])]
fn duration_force_end_planned(b: Bencher, level: i32) {
    let a = alphas(DC_END_FORCE);
    let mut plan = dc_duration_plan::default();
    assert_eq!(unsafe { dc_duration_plan_init(P, level, &mut plan) }, DC_OK);
    b.counter(ItemsCount::new(a.len())).bench(|| {
        let mut s = 0.0;
        for &al in &a {
            let mut t = 0.0;
            unsafe {
                dc_contact_duration_planned(
                    black_box(&plan),
                    black_box(al),
                    1.0,
                    1.0,
                    DC_END_FORCE,
                    &mut t,
                )
            };
            s += t;
        }
        s
    });
}

/// Building a plan (once per exponent).
#[divan::bench]
fn duration_plan_init(b: Bencher) {
    b.bench(|| {
        let mut plan = dc_duration_plan::default();
        unsafe { dc_duration_plan_init(black_box(P), 2, &mut plan) };
        plan.weights[0]
    });
}

/// The reference for the same 8 durations at rtol 1e-9 (error ≤ 6.4e-11 on this case).
#[divan::bench]
fn duration_force_end_ode_reference(b: Bencher) {
    let a = alphas(DC_END_FORCE);
    b.counter(ItemsCount::new(a.len())).bench(|| {
        let mut s = 0.0;
        for &al in &a {
            s += common::collide(
                black_box(P),
                black_box(al),
                1.0,
                1.0,
                EndCriterion::Force,
                1e-9,
            )
            .tau;
        }
        s
    });
}

const N: usize = 1000;

/// A 1000-point trajectory (t, δ, v, F), level 2.
#[divan::bench]
fn trajectory_1000(b: Bencher) {
    let al = alphas(DC_END_FORCE)[3];
    let (mut t, mut d, mut v, mut f) = (vec![0.0; N], vec![0.0; N], vec![0.0; N], vec![0.0; N]);
    b.bench_local(|| {
        let st = unsafe {
            dc_contact_trajectory(
                black_box(P),
                black_box(al),
                1.0,
                1.0,
                1.0,
                DC_END_FORCE,
                2,
                N,
                t.as_mut_ptr(),
                d.as_mut_ptr(),
                v.as_mut_ptr(),
                f.as_mut_ptr(),
                N,
            )
        };
        assert_eq!(st, DC_OK);
        t[N / 2]
    });
}

/// Baseline for the trajectory: 1000 libm powers x^q = exp(q ln x), the one transcendental pair
/// each sample needs (δ = A x^q), over the same samples' x.
#[divan::bench]
fn baseline_pow_1000(b: Bencher) {
    let xs: Vec<f64> = (1..=N)
        .map(|j| (j as f64 / N as f64 * 3.0).sin() * 0.7 + 1e-3)
        .collect();
    let mut out = vec![0.0; N];
    let q = 2.0 / (P + 1.0);
    b.bench_local(|| {
        for (o, &x) in out.iter_mut().zip(black_box(&xs)) {
            *o = (q * x.ln()).exp();
        }
        out[N / 2]
    });
}

/// The same 1000 samples by the reference: one integration chained through events at the
/// samples' overlaps, at rtol 1e-12 (the loosest reaching 1e-10 on the sample times).
#[divan::bench]
fn trajectory_1000_ode_reference(b: Bencher) {
    let al = alphas(DC_END_FORCE)[3];
    let (mut t, mut d, mut v, mut f) = (vec![0.0; N], vec![0.0; N], vec![0.0; N], vec![0.0; N]);
    unsafe {
        dc_contact_trajectory(
            P,
            al,
            1.0,
            1.0,
            1.0,
            DC_END_FORCE,
            2,
            N,
            t.as_mut_ptr(),
            d.as_mut_ptr(),
            v.as_mut_ptr(),
            f.as_mut_ptr(),
            N,
        )
    };
    let targets = d[1..N - 1].to_vec();
    let ups: Vec<bool> = v[1..N - 1].iter().map(|&x| x > 0.0).collect();
    let mut tr = vec![0.0; N - 2];
    b.bench_local(|| {
        common::chained_reference(
            P,
            black_box(al),
            1.0,
            1.0,
            EndCriterion::Force,
            &targets,
            &ups,
            1e-12,
            &mut tr,
        )
    });
}

/// Per-restitution cost of the force-end duration at level 2 (one call per sample).
#[divan::bench(args = [0usize, 1, 2, 3, 4, 5, 6, 7])]
fn duration_force_end_by_e(b: Bencher, i: usize) {
    let al = alphas(DC_END_FORCE)[i];
    b.bench(|| {
        let mut t = 0.0;
        unsafe {
            dc_contact_duration_level(
                black_box(P),
                black_box(al),
                1.0,
                1.0,
                DC_END_FORCE,
                2,
                &mut t,
            )
        };
        t
    });
}
