//! The full-contact exports never allocate: spec and model set-up, history length, scalar,
//! spheres and batch, on valid and invalid input, for every sub-model combination.

mod alloc_counter;
use alloc_counter::{Counting, assert_counter_works, count_allocations};
use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;
use demcontact::ffi::step_accuracy::dc_dt_for_accuracy_step_aware;
use std::hint::black_box;

#[global_allocator]
static ALLOC: Counting = Counting;

const V: [f64; 7] = [-1.0, 0.0, 1e-300, 1e-6, 0.5, f64::INFINITY, f64::NAN];

#[test]
fn contact_exports_do_not_allocate() {
    assert_counter_works();
    // Inputs prepared outside the counted region.
    let nc = 16;
    let normal: Vec<f64> = (0..nc).flat_map(|_| [0.0, 1.0, 0.0]).collect();
    let overlap: Vec<f64> = (0..nc).map(|i| 1e-7 * (i as f64 - 3.0)).collect();
    let vel: Vec<f64> = (0..3 * nc).map(|i| 0.1 * (i % 7) as f64 - 0.3).collect();
    let w: Vec<f64> = (0..3 * nc).map(|i| 10.0 * (i % 5) as f64 - 20.0).collect();
    let r1 = vec![1e-3; nc];
    let r2 = vec![f64::INFINITY; nc];
    let m1 = vec![1e-5; nc];
    let (mut f_n, mut force, mut t1, mut t2) = (
        vec![0.0; nc],
        vec![0.0; 3 * nc],
        vec![0.0; 3 * nc],
        vec![0.0; 3 * nc],
    );
    let mut hist = vec![0.0; DC_CONTACT_HISTORY_MAX * nc];
    let mut calls = 0usize;
    let n = count_allocations(|| {
        let mut spec: dc_contact_spec = unsafe { std::mem::zeroed() };
        let mut model: dc_contact_model = unsafe { std::mem::zeroed() };
        for (t, law) in [0, 1, 2, 3].into_iter().flat_map(|t| {
            [
                (t, DC_NORMAL_HERTZ),
                (t, DC_NORMAL_ELASTIC_PLASTIC),
                (t, DC_NORMAL_JKR),
            ]
        }) {
            for r in [0, 1, 2, 3] {
                for tw in [0, 1, 2] {
                    for &x in &V {
                        unsafe {
                            black_box(dc_contact_spec_init(&mut spec));
                            spec.normal = law;
                            spec.yield_pressure = 1e9;
                            spec.work_of_adhesion = 0.5;
                            if law == DC_NORMAL_JKR {
                                spec.criterion = DC_END_OVERLAP;
                            }
                            spec.E1 = 7e10;
                            spec.nu1 = 0.3;
                            spec.E2 = x;
                            spec.nu2 = 0.3;
                            spec.tangential = t;
                            spec.rolling = r;
                            spec.twisting = tw;
                            spec.mu = 0.3;
                            spec.k_t = x;
                            spec.mu_r = 0.1;
                            spec.mu_tw = 1e-5;
                            spec.k_tw = 1e-4;
                            let s = dc_contact_model_init(&spec, &mut model);
                            calls += 2;
                            if s != DC_OK {
                                continue;
                            }
                            let mut len = 0usize;
                            black_box(dc_contact_history_len(&model, &mut len));
                            let mut reach = 0.0;
                            black_box(dc_contact_model_reach(&model, x, &mut reach));
                            calls += 1;
                            // Both carries in the loop below (and set_carry counted).
                            black_box(dc_contact_model_set_carry(
                                &mut model,
                                (calls / 2 % 2) as i32,
                            ));
                            calls += 1;
                            let mut st = dc_contact_state {
                                n: [0.0, 1.0, 0.0],
                                overlap: x,
                                v1: [0.1, -0.2, x],
                                v2: [0.0; 3],
                                w1: [1.0, 2.0, 3.0],
                                w2: [0.0; 3],
                                r1: 1e-3,
                                r2: f64::INFINITY,
                                m1: 1e-5,
                                m2: f64::INFINITY,
                            };
                            let mut res: dc_contact_result = std::mem::zeroed();
                            let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
                            black_box(dc_contact_force(
                                &model,
                                &st,
                                1e-7,
                                h.as_mut_ptr(),
                                h.len(),
                                &mut res,
                            ));
                            black_box(dc_contact_force(
                                &model,
                                &st,
                                x,
                                h.as_mut_ptr(),
                                0,
                                &mut res,
                            ));
                            st.r2 = 2e-3;
                            st.m2 = 1e-4;
                            let (a, b) = ([0.0, 0.0, 0.0], [0.0, 1.9e-3, x]);
                            black_box(dc_contact_force_spheres(
                                &model,
                                a.as_ptr(),
                                b.as_ptr(),
                                &st,
                                1e-7,
                                h.as_mut_ptr(),
                                h.len(),
                                &mut res,
                            ));
                            let batch = dc_contact_batch {
                                n: nc,
                                history_stride: DC_CONTACT_HISTORY_MAX,
                                normal: normal.as_ptr(),
                                overlap: overlap.as_ptr(),
                                v1: vel.as_ptr(),
                                v2: vel.as_ptr(),
                                w1: w.as_ptr(),
                                w2: w.as_ptr(),
                                r1: r1.as_ptr(),
                                r2: r2.as_ptr(),
                                m1: m1.as_ptr(),
                                m2: r2.as_ptr(),
                                history: hist.as_mut_ptr(),
                                f_n: f_n.as_mut_ptr(),
                                force: force.as_mut_ptr(),
                                torque1: t1.as_mut_ptr(),
                                torque2: t2.as_mut_ptr(),
                            };
                            black_box(dc_contact_force_batch(&model, &batch, 1e-7));
                            black_box(dc_contact_force_batch(&model, &batch, x));
                            let mut bad = batch;
                            bad.n = 0;
                            black_box(dc_contact_force_batch(&model, &bad, 1e-7));
                            // The fused batch: valid, a bad dt / value of x, a call-level error.
                            let mut first = 0usize;
                            black_box(dc_contact_force_batch_fused(
                                &model, &batch, 1e-7, &mut first,
                            ));
                            black_box(dc_contact_force_batch_fused(&model, &batch, x, &mut first));
                            black_box(dc_contact_force_batch_fused(&model, &bad, 1e-7, &mut first));
                            calls += 10;
                        }
                    }
                }
            }
        }
    });
    assert_eq!(n, 0, "contact exports allocated {n} times in {calls} calls");
    assert!(calls > 500);
    println!("no_alloc_contact: {calls} calls, 0 allocations");
}

#[test]
#[cfg_attr(
    miri,
    ignore = "the calibration's 10^6 force evaluations are too slow under Miri; runs in cargo test"
)]
fn step_aware_exports_do_not_allocate() {
    assert_counter_works();
    let mut calls = 0usize;
    let n = count_allocations(|| {
        let mut spec: dc_contact_spec = unsafe { std::mem::zeroed() };
        let mut model: dc_contact_model = unsafe { std::mem::zeroed() };
        unsafe {
            black_box(dc_contact_spec_init(&mut spec));
            spec.normal = DC_NORMAL_HERTZ;
            spec.E1 = 7e10;
            spec.nu1 = 0.3;
            spec.E2 = 7e10;
            spec.nu2 = 0.3;
            spec.damping = DC_DAMPING_RESTITUTION;
            spec.e_n = 0.3;
            spec.tangential = DC_TANGENTIAL_MINDLIN;
            spec.mu = 0.3;
            assert_eq!(dc_contact_model_init(&spec, &mut model), DC_OK);
            for dt in [1e-7, 0.0, f64::NAN, 2e-7] {
                black_box(dc_contact_model_set_step(&mut model, dt, 0));
                calls += 1;
            }
            black_box(dc_contact_model_set_step(&mut model, 1e-7, 7));
            let st = dc_contact_state {
                n: [0.0, 1.0, 0.0],
                overlap: 1e-7,
                v1: [0.1, -0.2, 0.0],
                v2: [0.0; 3],
                w1: [1.0, 2.0, 3.0],
                w2: [0.0; 3],
                r1: 1e-3,
                r2: f64::INFINITY,
                m1: 1e-5,
                m2: f64::INFINITY,
            };
            let mut res: dc_contact_result = std::mem::zeroed();
            let mut h = [0.0; DC_CONTACT_HISTORY_MAX];
            for _ in 0..3 {
                black_box(dc_contact_force(
                    &model,
                    &st,
                    1e-7,
                    h.as_mut_ptr(),
                    h.len(),
                    &mut res,
                ));
                calls += 1;
            }
            let mut dt = 0.0;
            black_box(dc_dt_for_accuracy_step_aware(
                1.5,
                0.5,
                DC_END_FORCE,
                1.0,
                1e3,
                0.01,
                &mut dt,
            ));
            black_box(dc_dt_for_accuracy_step_aware(
                1.5,
                2.0,
                DC_END_FORCE,
                1.0,
                1e3,
                0.01,
                &mut dt,
            ));
            calls += 2;
        }
    });
    assert!(calls >= 9);
    assert_eq!(n, 0, "step-aware exports allocated {n} times");
}
