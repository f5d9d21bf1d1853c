//! Property tests of the full-contact exports through the C ABI: for any bit pattern of every
//! spec field and state value, no export panics or returns DC_ERR_INTERNAL, errors leave
//! outputs and history untouched, successes are finite; on valid input the Coulomb, rolling and
//! twisting limits hold at every step and the batch equals the scalar bit for bit.
#![allow(clippy::indexing_slicing)]

use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;
use proptest::prelude::*;

#[path = "common/proptest_util.rs"]
mod proptest_util;
use proptest_util::{bytes, known, untouched_on_error};

fn config(cases: u32) -> ProptestConfig {
    proptest_util::config(cases, 20_261_123)
}

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<u64>().prop_map(f64::from_bits),
        prop::num::f64::ANY,
        Just(0.0),
        Just(-0.0),
        Just(1.0),
        Just(f64::INFINITY),
        Just(f64::NAN),
        1e-6f64..1e11,
    ]
}

fn v3() -> impl Strategy<Value = [f64; 3]> {
    [any_f64(), any_f64(), any_f64()]
}

fn state_any() -> impl Strategy<Value = dc_contact_state> {
    (
        v3(),
        any_f64(),
        v3(),
        v3(),
        v3(),
        v3(),
        [any_f64(), any_f64(), any_f64(), any_f64()],
    )
        .prop_map(
            |(n, overlap, v1, v2, w1, w2, [r1, r2, m1, m2])| dc_contact_state {
                n,
                overlap,
                v1,
                v2,
                w1,
                w2,
                r1,
                r2,
                m1,
                m2,
            },
        )
}

fn unit() -> impl Strategy<Value = [f64; 3]> {
    (0.0f64..std::f64::consts::TAU, -1.0f64..1.0).prop_map(|(phi, z)| {
        let s = (1.0 - z * z).sqrt();
        [s * phi.cos(), s * phi.sin(), z]
    })
}

fn vel() -> impl Strategy<Value = [f64; 3]> {
    [-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0]
}

fn spin() -> impl Strategy<Value = [f64; 3]> {
    [-500.0f64..500.0, -500.0f64..500.0, -500.0f64..500.0]
}

/// Valid states: spheres of 0.1–10 mm, walls, fixed bodies, overlaps up to 1 % of the radius
/// (and some separated).
fn state_valid() -> impl Strategy<Value = dc_contact_state> {
    (
        unit(),
        -1e-6f64..1e-5,
        vel(),
        vel(),
        spin(),
        spin(),
        1e-4f64..1e-2,
        prop_oneof![Just(f64::INFINITY), 1e-4f64..1e-2],
        1e-9f64..1e-2,
        prop_oneof![Just(f64::INFINITY), 1e-9f64..1e-2],
    )
        .prop_map(|(n, d, v1, v2, w1, w2, r1, r2, m1, m2)| dc_contact_state {
            n,
            overlap: d * r1 / 1e-3,
            v1,
            v2,
            w1,
            w2,
            r1,
            r2,
            m1,
            m2,
        })
}

#[derive(Debug, Clone, Copy)]
struct Choice {
    normal: i32,
    damping: i32,
    criterion: i32,
    tangential: i32,
    rolling: i32,
    twisting: i32,
    carry: i32,
}

fn choice_valid() -> impl Strategy<Value = Choice> {
    (
        // 1–4 as they are; 5 stands for the elastic–plastic law, 6 for JKR (laws with state).
        1i32..7,
        0i32..2,
        0i32..2,
        0i32..4,
        0i32..3,
        0i32..2,
        0i32..2,
    )
        .prop_map(
            |(normal, damping, criterion, tangential, rolling, twisting, carry)| Choice {
                normal: match normal {
                    5 => DC_NORMAL_ELASTIC_PLASTIC,
                    6 => DC_NORMAL_JKR,
                    n => n,
                },
                damping: if normal == DC_NORMAL_VISCOELASTIC || normal == 5 {
                    0
                } else {
                    damping
                },
                // JKR is never clamped.
                criterion: if normal == 6 {
                    DC_END_OVERLAP
                } else {
                    criterion
                },
                tangential,
                rolling,
                twisting,
                carry,
            },
        )
}

fn model_valid(c: Choice, mu: f64, e: f64) -> dc_contact_model {
    let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { dc_contact_spec_init(&mut s) }, DC_OK);
    s.normal = c.normal;
    s.damping = c.damping;
    s.criterion = c.criterion;
    s.tangential = c.tangential;
    s.rolling = c.rolling;
    s.twisting = c.twisting;
    s.E1 = 7e10;
    s.nu1 = 0.3;
    s.E2 = f64::INFINITY;
    s.nu2 = 0.25;
    s.p = 1.7;
    s.k_n = 1e7;
    s.e_n = e;
    s.visco_A = 1e-6;
    s.yield_pressure = 1e9;
    s.work_of_adhesion = 0.5;
    s.mu = mu;
    s.k_t = 1e6;
    s.e_t = e;
    s.mu_r = 0.5 * mu;
    s.eta_r = 0.3;
    s.mu_tw = 1e-4 * mu;
    s.k_tw = 1e-3;
    s.eta_tw = 0.3;
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { dc_contact_model_init(&s, &mut m) }, DC_OK, "{c:?}");
    assert_eq!(
        unsafe { dc_contact_model_set_carry(&mut m, c.carry) },
        DC_OK
    );
    m
}

proptest! {
    #![proptest_config(config(3_000))]

    #[test]
    fn model_init_any_bits(sel in prop::array::uniform6(-2i32..6), x in prop::collection::vec(any_f64(), 18), ver in 0u32..3) {
        let mut s: dc_contact_spec = unsafe { std::mem::zeroed() };
        unsafe { dc_contact_spec_init(&mut s) };
        s.version = ver;
        [s.normal, s.damping, s.criterion, s.tangential, s.rolling, s.twisting] = sel;
        [s.E1, s.nu1, s.E2, s.nu2, s.p, s.k_n, s.e_n, s.visco_A, s.mu, s.k_t, s.e_t, s.mu_r, s.k_r, s.eta_r, s.mu_tw, s.k_tw, s.eta_tw, s.inertia_factor] =
            [x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9], x[10], x[11], x[12], x[13], x[14], x[15], x[16], x[17]];
        let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
        m.kt = -3.25;
        let st = untouched_on_error(&mut m, |o| unsafe { dc_contact_model_init(&s, o) })?;
        if st == DC_OK {
            let mut len = 99usize;
            prop_assert_eq!(unsafe { dc_contact_history_len(&m, &mut len) }, DC_OK);
            prop_assert!(len <= DC_CONTACT_HISTORY_MAX);
        }
    }

    #[test]
    fn force_any_bits(c in choice_valid(), st in state_any(), dt in any_f64(), h0 in prop::array::uniform10(any_f64()), spheres in any::<bool>(), x in v3()) {
        let m = model_valid(c, 0.4, 0.6);
        let mut h = h0;
        let mut r: dc_contact_result = unsafe { std::mem::zeroed() };
        r.f_n = -1.25;
        let s = untouched_on_error(&mut r, |o| if spheres {
            let z = [0.0; 3];
            unsafe { dc_contact_force_spheres(&m, x.as_ptr(), z.as_ptr(), &st, dt, h.as_mut_ptr(), h.len(), o) }
        } else {
            unsafe { dc_contact_force(&m, &st, dt, h.as_mut_ptr(), h.len(), o) }
        })?;
        if s != DC_OK {
            prop_assert_eq!(bytes(&h), bytes(&h0), "history touched on error (status {})", s);
        } else {
            let fnv = [r.f_n];
            let all = r.force.iter().chain(&r.torque1).chain(&r.torque2).chain(&r.ft).chain(&fnv).chain(&h);
            prop_assert!(all.into_iter().all(|v| v.is_finite()));
        }
    }

    #[test]
    fn limits_hold_and_batch_equals_scalar(c in choice_valid(), mu in 0.0f64..2.0, e in 0.05f64..1.0, sts in prop::collection::vec(state_valid(), 1..6), steps in 1usize..6, step_aware in prop::bool::weighted(0.1), onset in prop::option::weighted(0.5, 0.05f64..2.0)) {
        let mut m = model_valid(c, mu, e);
        let mut sts = sts;
        let mut at_onset = false;
        if step_aware {
            // Step-aware where the law has the form (else refused with the model untouched).
            let m0 = m;
            let s = unsafe { dc_contact_model_set_step(&mut m, 1e-7, DC_INTEGRATOR_VELOCITY_VERLET) };
            prop_assert!(s == DC_OK || bytes(&m) == bytes(&m0), "refused set_step touched the model");
            at_onset = s == DC_OK && onset.is_some();
            // Half the step-aware cases start each approaching contact at the overlap a drift
            // reaches, δ = a·v·dt with a in (0, 2]: a true onset at the first step (the random
            // overlaps above are mostly far deeper, first steps that take no onset correction).
            if let Some(a) = onset {
                for st in sts.iter_mut() {
                    let vn = -((st.v1[0] - st.v2[0]) * st.n[0] + (st.v1[1] - st.v2[1]) * st.n[1] + (st.v1[2] - st.v2[2]) * st.n[2]);
                    let d = a * vn * 1e-7;
                    if vn > 0.0 && d.is_normal() {
                        st.overlap = d;
                    }
                }
            }
        }
        let nc = sts.len();
        let stride = DC_CONTACT_HISTORY_MAX;
        let mut hs = vec![0.0f64; nc * stride];
        let mut hb = hs.clone();
        let flat = |f: &dyn Fn(&dc_contact_state) -> [f64; 3]| sts.iter().flat_map(f).collect::<Vec<f64>>();
        let one = |f: &dyn Fn(&dc_contact_state) -> f64| sts.iter().map(f).collect::<Vec<f64>>();
        let (n, v1, v2, w1, w2) = (flat(&|s| s.n), flat(&|s| s.v1), flat(&|s| s.v2), flat(&|s| s.w1), flat(&|s| s.w2));
        let (d, r1, r2, m1, m2) = (one(&|s| s.overlap), one(&|s| s.r1), one(&|s| s.r2), one(&|s| s.m1), one(&|s| s.m2));
        for _ in 0..steps {
            let (mut f_n, mut force, mut t1, mut t2) = (vec![0.0; nc], vec![0.0; 3 * nc], vec![0.0; 3 * nc], vec![0.0; 3 * nc]);
            let b = dc_contact_batch {
                n: nc, history_stride: stride, normal: n.as_ptr(), overlap: d.as_ptr(), v1: v1.as_ptr(), v2: v2.as_ptr(),
                w1: w1.as_ptr(), w2: w2.as_ptr(), r1: r1.as_ptr(), r2: r2.as_ptr(), m1: m1.as_ptr(), m2: m2.as_ptr(),
                history: hb.as_mut_ptr(), f_n: f_n.as_mut_ptr(), force: force.as_mut_ptr(), torque1: t1.as_mut_ptr(), torque2: t2.as_mut_ptr(),
            };
            let hb0 = hb.clone();
            let sb = unsafe { dc_contact_force_batch(&m, &b, 1e-7) };
            let mut any_over = false;
            for (i, st) in sts.iter().enumerate() {
                let mut r: dc_contact_result = unsafe { std::mem::zeroed() };
                let s = unsafe { dc_contact_force(&m, st, 1e-7, hs[i * stride..].as_mut_ptr(), stride, &mut r) };
                if s != DC_OK {
                    // An overflow: the batch reports it, with NaN outputs and the history kept.
                    prop_assert_eq!(s, DC_ERR_RESULT_RANGE);
                    prop_assert_eq!(sb, DC_ERR_RESULT_RANGE);
                    prop_assert!(f_n[i].is_nan() && (0..3).all(|k| force[3 * i + k].is_nan()));
                    let kept = (i * stride..(i + 1) * stride).all(|k| hb[k].to_bits() == hb0[k].to_bits());
                    prop_assert!(kept, "history of overflowing contact {} touched", i);
                    any_over = true;
                    continue;
                }
                let ft = r.ft.iter().map(|x| x * x).sum::<f64>().sqrt();
                // The load of the Coulomb limit: |Fn + 2 F_po|, F_po the pull-off force of an
                // adhesive law (DMT 2π w R*, JKR (3/2) π w R*; w = 0.5), |Fn| otherwise.
                let r_star = 1.0 / (1.0 / st.r1 + 1.0 / st.r2);
                let po = match c.normal {
                    DC_NORMAL_DMT => 2.0 * std::f64::consts::PI * 0.5 * r_star,
                    DC_NORMAL_JKR => 1.5 * std::f64::consts::PI * 0.5 * r_star,
                    _ => 0.0,
                };
                let load = (r.f_n + 2.0 * po).abs();
                prop_assert!(ft <= mu * load * (1.0 + 1e-12) + 1e-300, "|Ft| {} > mu F_c {}", ft, mu * load);
                if c.normal != DC_NORMAL_VISCOELASTIC && c.criterion == DC_END_FORCE {
                    prop_assert!(r.f_n >= 0.0);
                }
                prop_assert_eq!(r.f_n.to_bits(), f_n[i].to_bits());
                for k in 0..3 {
                    prop_assert_eq!(r.force[k].to_bits(), force[3 * i + k].to_bits());
                    prop_assert_eq!(r.torque1[k].to_bits(), t1[3 * i + k].to_bits());
                    prop_assert_eq!(r.torque2[k].to_bits(), t2[3 * i + k].to_bits());
                }
            }
            if !any_over {
                prop_assert_eq!(sb, DC_OK);
            }
            // The onset correction of a valid state is finite (no overflow to report).
            prop_assert!(!(any_over && at_onset), "a step-aware contact overflowed at its onset");
            prop_assert!(hs.iter().zip(&hb).all(|(a, b)| a.to_bits() == b.to_bits()));
        }
    }

    /// set_step with any dt and integrator on a step-aware model: accepted exactly for a finite
    /// dt > 0 and a known integrator (the calibration kept), except a dt so small that dt over
    /// the t_H prefactor underflows to 0 (DC_ERR_RESULT_RANGE); otherwise refused with the model
    /// untouched and a documented status.
    #[test]
    fn set_step_any_bits(dt in any_f64(), integrator in -2i32..4, crit in 0i32..2) {
        static MODELS: std::sync::OnceLock<[dc_contact_model; 2]> = std::sync::OnceLock::new();
        let base = MODELS.get_or_init(|| {
            [0, 1].map(|crit| {
                let c = Choice { normal: DC_NORMAL_HERTZ, damping: DC_DAMPING_RESTITUTION, criterion: crit, tangential: DC_TANGENTIAL_MINDLIN, rolling: DC_ROLLING_EPSD, twisting: DC_TWISTING_SDS, carry: DC_CARRY_ROTATE };
                let mut m = model_valid(c, 0.5, 0.4);
                assert_eq!(unsafe { dc_contact_model_set_step(&mut m, 1e-7, 0) }, DC_OK);
                m
            })
        })[crit as usize];
        let mut m = base;
        let s = unsafe { dc_contact_model_set_step(&mut m, dt, integrator) };
        prop_assert!(known(s));
        let valid = dt.is_finite() && dt > 0.0 && (integrator == 0 || integrator == 1);
        if valid && s == DC_ERR_RESULT_RANGE {
            prop_assert!(dt < 1e-300, "DC_ERR_RESULT_RANGE at dt {dt:e}");
            prop_assert!(bytes(&m) == bytes(&base), "refused set_step touched the model");
        } else if valid {
            prop_assert_eq!(s, DC_OK);
            prop_assert_eq!(m.history_len, base.history_len);
            prop_assert!(m.reserved[0] > 0.0);
            prop_assert!(m.reserved[1..].iter().zip(&base.reserved[1..]).all(|(a, b)| a.to_bits() == b.to_bits()));
        } else {
            prop_assert!(s != DC_OK);
            prop_assert!(bytes(&m) == bytes(&base), "refused set_step touched the model");
        }
    }

    /// The fused batch over a mix of valid and any-bits contacts and histories: its status and
    /// first_bad are those of the first contact dc_contact_force refuses (for a value of its
    /// state or history, or DC_ERR_RESULT_RANGE for a result that overflows); that contact's
    /// and every refused contact's outputs are NaN and history untouched; every contact
    /// dc_contact_force accepts equals it bit for bit.
    #[test]
    fn fused_batch_any_bits(c in choice_valid(), sts in prop::collection::vec(prop_oneof![3 => state_valid(), 1 => state_any()], 1..6), hbad in prop::collection::vec(prop_oneof![3 => Just(0.0), 1 => any_f64()], 6 * DC_CONTACT_HISTORY_MAX)) {
        let m = model_valid(c, 0.5, 0.5);
        let nc = sts.len();
        let stride = DC_CONTACT_HISTORY_MAX;
        let mut hb: Vec<f64> = hbad[..nc * stride].to_vec();
        let h0 = hb.clone();
        let flat = |f: &dyn Fn(&dc_contact_state) -> [f64; 3]| sts.iter().flat_map(f).collect::<Vec<f64>>();
        let one = |f: &dyn Fn(&dc_contact_state) -> f64| sts.iter().map(f).collect::<Vec<f64>>();
        let (n, v1, v2, w1, w2) = (flat(&|s| s.n), flat(&|s| s.v1), flat(&|s| s.v2), flat(&|s| s.w1), flat(&|s| s.w2));
        let (d, r1, r2, m1, m2) = (one(&|s| s.overlap), one(&|s| s.r1), one(&|s| s.r2), one(&|s| s.m1), one(&|s| s.m2));
        let (mut f_n, mut force, mut t1, mut t2) = (vec![7.0; nc], vec![7.0; 3 * nc], vec![7.0; 3 * nc], vec![7.0; 3 * nc]);
        let b = dc_contact_batch {
            n: nc, history_stride: stride, normal: n.as_ptr(), overlap: d.as_ptr(), v1: v1.as_ptr(), v2: v2.as_ptr(),
            w1: w1.as_ptr(), w2: w2.as_ptr(), r1: r1.as_ptr(), r2: r2.as_ptr(), m1: m1.as_ptr(), m2: m2.as_ptr(),
            history: hb.as_mut_ptr(), f_n: f_n.as_mut_ptr(), force: force.as_mut_ptr(), torque1: t1.as_mut_ptr(), torque2: t2.as_mut_ptr(),
        };
        let mut bad = usize::MAX;
        let sf = unsafe { dc_contact_force_batch_fused(&m, &b, 1e-7, &mut bad) };
        prop_assert!(known(sf), "status {}", sf);
        let mut first: Option<(usize, i32)> = None;
        let len = m.history_len as usize;
        // A normal-only model's batch neither reads nor checks w1, w2 (header): the scalar
        // reference gets zeros there. Normal-only by its selectors (a law with state has a
        // history of one double and is still normal-only).
        let normal_only = m.tangential == DC_TANGENTIAL_NONE
            && m.rolling == DC_ROLLING_NONE
            && m.twisting == DC_TWISTING_NONE;
        for (i, st) in sts.iter().enumerate() {
            let mut hs = h0[i * stride..(i + 1) * stride].to_vec();
            let mut r: dc_contact_result = unsafe { std::mem::zeroed() };
            let st = &if normal_only { dc_contact_state { w1: [0.0; 3], w2: [0.0; 3], ..*st } } else { *st };
            let s = unsafe { dc_contact_force(&m, st, 1e-7, hs.as_mut_ptr(), stride, &mut r) };
            let hbi = &hb[i * stride..i * stride + len];
            if s == DC_OK {
                prop_assert_eq!(r.f_n.to_bits(), f_n[i].to_bits());
                for k in 0..3 {
                    prop_assert_eq!(r.force[k].to_bits(), force[3 * i + k].to_bits());
                    prop_assert_eq!(r.torque1[k].to_bits(), t1[3 * i + k].to_bits());
                    prop_assert_eq!(r.torque2[k].to_bits(), t2[3 * i + k].to_bits());
                }
                prop_assert!(hbi.iter().zip(&hs).all(|(a, b)| a.to_bits() == b.to_bits()));
            } else {
                prop_assert!([DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_NOT_UNIT, DC_ERR_RESULT_RANGE].contains(&s), "{}", s);
                first = first.or(Some((i, s)));
                prop_assert!(f_n[i].is_nan());
                prop_assert!((0..3).all(|k| force[3 * i + k].is_nan() && t1[3 * i + k].is_nan() && t2[3 * i + k].is_nan()));
                prop_assert!(hbi.iter().zip(&h0[i * stride..]).all(|(a, b)| a.to_bits() == b.to_bits()));
            }
        }
        match first {
            None => prop_assert_eq!((sf, bad), (DC_OK, usize::MAX)),
            Some((i, s)) => prop_assert_eq!((sf, bad), (s, i)),
        }
    }
}
