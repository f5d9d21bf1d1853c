//! The step-aware contact model against the plain one, same inputs, same run: the batch
//! (`contact_force_batch`) of N = 1024 contacts of a Hertz + Mindlin model (normal-only too), the
//! histories in their steady state (every contact past its onset: the step slot holds R), a few
//! contacts per step at onset (fresh history) as in a host where a contact lasts ~20 steps; the
//! set-up of those histories is timed in both variants. The fresh contacts' random overlaps put
//! a = δ₁/(v dt) above 2 at most approaching contacts: first steps too deep for an
//! onset (a pair created overlapping), which take R = 1 and no correction. `*_physical`: the same
//! with the onset overlaps a drift gives (δ₁ ≤ v dt), every approaching fresh contact at onset.
//! Divan reports items/s; the ratio step-aware / plain is the cost of the option.
//! Run: `cargo bench --bench step_exact`.

use demcontact::contact::batch::{BatchIn, BatchOut, contact_force_batch};
use demcontact::contact::spec::{damping, normal};
use demcontact::contact::step_exact::set_step;
use demcontact::contact::{ContactModel, ContactSpec, contact_model, model::select};
use divan::{Bencher, black_box, counter::ItemsCount};

fn main() {
    divan::main();
}

const N: usize = 1024;
const STRIDE: usize = 12;
const DT: f64 = 2e-7;

struct Data {
    n: Vec<[f64; 3]>,
    d: Vec<f64>,
    v1: Vec<[f64; 3]>,
    v2: Vec<[f64; 3]>,
    w: Vec<[f64; 3]>,
    r: Vec<f64>,
    m: Vec<f64>,
}

fn data(physical: bool) -> Data {
    let mut s = 0x243F6A8885A308D3u64;
    let mut u = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut x = Data {
        n: vec![],
        d: vec![],
        v1: vec![],
        v2: vec![],
        w: vec![],
        r: vec![],
        m: vec![],
    };
    for _ in 0..N {
        let r = 1e-3 * (1.0 + u());
        let (z, ph) = (2.0 * u() - 1.0, 6.283185307179586 * u());
        let q = (1.0 - z * z).sqrt();
        let n = [q * ph.cos(), q * ph.sin(), z];
        x.n.push(n);
        let d = r * 1e-3 * (0.1 + u());
        let (v1, v2) = (
            [u() - 0.5, u() - 0.5, u() - 0.5],
            [u() - 0.5, u() - 0.5, u() - 0.5],
        );
        // The overlap rate as the kernel computes it (> 0 approaching).
        let vn = -((v1[0] - v2[0]) * n[0] + (v1[1] - v2[1]) * n[1] + (v1[2] - v2[2]) * n[2]);
        // Physical onsets: the first overlap of an approaching contact is reached within one
        // drift, δ₁ = a·v·dt with a ∈ (0, 1] (a = 0.05 … 1 here).
        x.d.push(if physical && vn > 0.0 {
            vn * DT * (0.05 + 0.95 * u())
        } else {
            d
        });
        x.v1.push(v1);
        x.v2.push(v2);
        x.w.push([10.0 * (u() - 0.5), 10.0 * (u() - 0.5), 10.0 * (u() - 0.5)]);
        x.r.push(r);
        x.m.push(2500.0 * 4.18879 * r * r * r);
    }
    x
}

fn model(tangential: i32, step: bool) -> ContactModel {
    let s = ContactSpec {
        normal: normal::HERTZ,
        damping: damping::RESTITUTION,
        criterion: 1,
        e_n: 0.5,
        e1: 7e10,
        nu1: 0.3,
        e2: 7e10,
        nu2: 0.3,
        tangential,
        mu: 0.5,
        ..ContactSpec::default()
    };
    let m = contact_model(&s).expect("model");
    if step {
        set_step(&m, DT, 0).expect("set_step")
    } else {
        m
    }
}

fn run(bencher: Bencher, tangential: i32, step: bool, onsets: bool, physical: bool) {
    run_with(bencher, tangential, step, onsets, physical, STRIDE);
}

/// [`run`] with the history records `stride` doubles apart.
fn run_with(
    bencher: Bencher,
    tangential: i32,
    step: bool,
    onsets: bool,
    physical: bool,
    stride: usize,
) {
    let x = data(physical);
    let m = model(tangential, step);
    let len = m.layout.len;
    let mut hist = vec![0.0; N * stride];
    let (mut f_n, mut force, mut t1, mut t2) = (
        vec![0.0; N],
        vec![[0.0; 3]; N],
        vec![[0.0; 3]; N],
        vec![[0.0; 3]; N],
    );
    // The steady-state set-up runs in both variants (the same stores; the plain model's
    // slot is a host value past its history), so the ratio is the option's cost alone.
    let at = m.layout.step.unwrap_or(stride - 1);
    assert!(m.layout.step.is_some() || len < stride);
    let mut tick = 0usize;
    bencher.counter(ItemsCount::new(N)).bench_local(|| {
        // Steady state: the step slot of every contact holds R, except 1 in 20 (onsets) unless
        // `onsets` is false (enduring contacts only).
        let mut k = tick;
        for h in hist.chunks_exact_mut(stride) {
            if let Some(slot) = h.get_mut(at) {
                *slot = if onsets && k == 0 { 0.0 } else { 0.97 };
            }
            k = if k == 19 { 0 } else { k + 1 };
        }
        tick = if tick == 19 { 0 } else { tick + 1 };
        let inp = BatchIn {
            normal: &x.n,
            overlap: &x.d,
            v1: &x.v1,
            v2: &x.v2,
            w1: &x.w,
            w2: &x.w,
            r1: &x.r,
            r2: &x.r,
            m1: &x.m,
            m2: &x.m,
        };
        let mut out = BatchOut {
            f_n: &mut f_n,
            force: &mut force,
            torque1: Some(&mut t1),
            torque2: Some(&mut t2),
            history: &mut hist,
            stride,
        };
        black_box(contact_force_batch(&m, black_box(&inp), DT, &mut out)).ok();
        black_box(len);
    });
}

#[divan::bench]
fn hertz_plain(b: Bencher) {
    run(b, select::TANGENTIAL_NONE, false, true, false);
}

#[divan::bench]
fn hertz_step_aware(b: Bencher) {
    run(b, select::TANGENTIAL_NONE, true, true, false);
}

#[divan::bench]
fn hertz_mindlin_plain(b: Bencher) {
    run(b, select::TANGENTIAL_MINDLIN, false, true, false);
}

#[divan::bench]
fn hertz_mindlin_step_aware(b: Bencher) {
    run(b, select::TANGENTIAL_MINDLIN, true, true, false);
}

/// Enduring contacts only (no onset in the batch: a settled bed): the step-aware model's
/// steady-state cost.
#[divan::bench]
fn hertz_step_aware_enduring(b: Bencher) {
    run(b, select::TANGENTIAL_NONE, true, false, false);
}

#[divan::bench]
fn hertz_mindlin_step_aware_enduring(b: Bencher) {
    run(b, select::TANGENTIAL_MINDLIN, true, false, false);
}

/// Physical onsets (δ₁ ≤ v dt, as a drift gives them: a ≤ 1) in place of the random overlaps
/// of the benches above (there mostly far deeper than a drift reaches): the same batch
/// otherwise.
#[divan::bench]
fn hertz_plain_physical(b: Bencher) {
    run(b, select::TANGENTIAL_NONE, false, true, true);
}

#[divan::bench]
fn hertz_step_aware_physical(b: Bencher) {
    run(b, select::TANGENTIAL_NONE, true, true, true);
}

#[divan::bench]
fn hertz_mindlin_plain_physical(b: Bencher) {
    run(b, select::TANGENTIAL_MINDLIN, false, true, true);
}

#[divan::bench]
fn hertz_mindlin_step_aware_physical(b: Bencher) {
    run(b, select::TANGENTIAL_MINDLIN, true, true, true);
}

/// Normal-only with the history as a host lays it out for that model: records of
/// `dc_contact_history_len` (one double) back to back, stride 1 (the benches above keep the
/// full-contact stride of 12 for every model). The plain model has no history; its slot is the
/// host's, written by the set-up as in the step-aware runs.
#[divan::bench]
fn hertz_plain_dense(b: Bencher) {
    run_with(b, select::TANGENTIAL_NONE, false, true, false, 1);
}

#[divan::bench]
fn hertz_step_aware_dense(b: Bencher) {
    run_with(b, select::TANGENTIAL_NONE, true, true, false, 1);
}

#[divan::bench]
fn hertz_step_aware_enduring_dense(b: Bencher) {
    run_with(b, select::TANGENTIAL_NONE, true, false, false, 1);
}

#[divan::bench]
fn hertz_plain_physical_dense(b: Bencher) {
    run_with(b, select::TANGENTIAL_NONE, false, true, true, 1);
}

#[divan::bench]
fn hertz_step_aware_physical_dense(b: Bencher) {
    run_with(b, select::TANGENTIAL_NONE, true, true, true, 1);
}
