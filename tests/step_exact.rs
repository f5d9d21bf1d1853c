//! The step-aware contact model (`dc_contact_model_set_step`) realises the target e_n at the
//! host's step: sphere–wall collisions through the library's `contact_force`, velocity Verlet in
//! the LAMMPS order and symplectic Euler, 64 contact-onset phases, Hertz, p = 1 and p = 2, both
//! criteria, impact speeds over three decades, dt = t_H/10, /20, /50, /100 with t_H the elastic
//! contact duration at the impact speed, computed here by RK4 integration of the elastic
//! contact (independent of the library's closed form).
//!
//! Asserted (docs/timestep.md): mean over phases within 0.2 % of e_n at t_H/10 and t_H/20,
//! 0.1 % at t_H/50, 0.05 % at t_H/100; worst phase ≤ 25 % at t_H/10, ≤ 1.5 % at t_H/20,
//! ≤ 0.25 % at t_H/50, ≤ 0.06 % at t_H/100; the plain model's mean at t_H/20 more than 10 % off
//! somewhere. Enduring contacts: a column of spheres settling under gravity on a wall keeps its
//! static overlaps (relative 1e-6) and comes to rest (below 1e-6 m/s), plain and step-aware.

#[path = "../examples/step_exact/harness.rs"]
mod harness;

use demcontact::contact::contact_model;
use demcontact::contact::step_exact::set_step;
use harness::{Law, spec, stat, t_h};

#[test]
fn mean_restitution_at_the_host_step() {
    // (step, largest |mean| corrected, largest worst phase corrected)
    let limits = [
        (10.0, 0.002, 0.25),
        (20.0, 0.002, 0.015),
        (50.0, 0.001, 0.0025),
        (100.0, 0.0005, 0.0006),
    ];
    let mut plain_worst_mean: f64 = 0.0;
    let mut report = Vec::new();
    for law in [Law::Hertz, Law::Linear, Law::P2] {
        for crit in [0, 1] {
            for e in [0.1, 0.3, 0.5, 0.7, 0.9, 0.95] {
                let plain = contact_model(&spec(law, e, crit)).unwrap();
                for (n, lim_mean, lim_worst) in limits {
                    let mut worst_mean: f64 = 0.0;
                    let mut worst_phase: f64 = 0.0;
                    for v0 in [0.01, 1.0, 10.0] {
                        let dt = t_h(law, v0) / n;
                        let stepped = set_step(&plain, dt, 0).unwrap();
                        for verlet in [true, false] {
                            let s = stat(&stepped, law, e, v0, n, verlet);
                            worst_mean = worst_mean.max(s.mean.abs());
                            worst_phase = worst_phase.max(s.worst);
                        }
                        if n == 20.0 {
                            let p = stat(&plain, law, e, v0, n, true);
                            plain_worst_mean = plain_worst_mean.max(p.mean.abs());
                        }
                    }
                    report.push(format!(
                        "{law:?} crit {crit} e {e} t_H/{n}: mean {:.3} %, worst {:.3} %",
                        worst_mean * 100.0,
                        worst_phase * 100.0
                    ));
                    assert!(
                        worst_mean <= lim_mean && worst_phase <= lim_worst,
                        "{}",
                        report.join("\n")
                    );
                }
            }
        }
    }
    println!("{}", report.join("\n"));
    println!(
        "plain: largest |mean| at t_H/20 {:.3} %",
        plain_worst_mean * 100.0
    );
    // The plain model misses by far more: the check above can tell the two apart.
    assert!(plain_worst_mean > 0.1, "{plain_worst_mean}");
}

/// A column of `n` spheres (the lowest on a wall) dropped with gaps, settling under gravity with
/// velocity Verlet at dt = t_H(v_ref)/20: returns the overlaps at the end and the largest speed
/// over the last tenth of the run.
fn settle(
    m: &demcontact::contact::ContactModel,
    n: usize,
    dt: f64,
    steps: usize,
) -> (Vec<f64>, f64) {
    use demcontact::contact::{ContactState, contact_force};
    let (mass, r, g) = (2.0e-3, 2.0e-3, 9.81);
    let len = m.layout.len.max(1);
    let mut z: Vec<f64> = (0..n).map(|i| r + i as f64 * 2.05 * r).collect();
    let mut v = vec![0.0; n];
    let mut acc = vec![-g; n];
    let mut hist = vec![vec![0.0; len]; n]; // contact i: sphere i on sphere i − 1 (0: the wall)
    let mut vmax_tail: f64 = 0.0;
    for step in 0..steps {
        for i in 0..n {
            v[i] += 0.5 * dt * acc[i];
            z[i] += dt * v[i];
        }
        let mut f = vec![-mass * g; n];
        for i in 0..n {
            let (zb, vb, r2, m2) = if i == 0 {
                (0.0, 0.0, f64::INFINITY, f64::INFINITY)
            } else {
                (z[i - 1], v[i - 1], r, mass)
            };
            let overlap = if i == 0 {
                r - z[i]
            } else {
                2.0 * r - (z[i] - zb)
            };
            let s = ContactState {
                n: [0.0, 0.0, 1.0],
                overlap,
                v1: [0.0, 0.0, v[i]],
                v2: [0.0, 0.0, vb],
                w1: [0.0; 3],
                w2: [0.0; 3],
                r1: r,
                r2,
                m1: mass,
                m2,
            };
            let fz = contact_force(m, &s, dt, &mut hist[i]).unwrap().force[2];
            f[i] += fz;
            if i > 0 {
                f[i - 1] -= fz;
            }
        }
        for i in 0..n {
            acc[i] = f[i] / mass;
            v[i] += 0.5 * dt * acc[i];
            if step >= steps - steps / 10 {
                vmax_tail = vmax_tail.max(v[i].abs());
            }
        }
    }
    let overlaps = (0..n)
        .map(|i| {
            if i == 0 {
                r - z[0]
            } else {
                2.0 * r - (z[i] - z[i - 1])
            }
        })
        .collect();
    (overlaps, vmax_tail)
}

#[test]
fn enduring_contacts_keep_their_static_overlaps() {
    // Hertz, both criteria, e_n 0.1 and 0.5: a column of 10 spheres (the lowest one resting on a
    // wall) settles; the static overlap of contact i carries the weight of the n − i spheres
    // above: δ = ((n − i) m g / k)^(2/3), k = (4/3) E* √R*.
    let n = 10;
    for crit in [0, 1] {
        for e in [0.1, 0.5] {
            let plain = contact_model(&spec(Law::Hertz, e, crit)).unwrap();
            let dt = t_h(Law::Hertz, 0.1) / 20.0;
            let stepped = set_step(&plain, dt, 0).unwrap();
            for (name, m) in [("plain", &plain), ("step-aware", &stepped)] {
                let (d, vmax) = settle(m, n, dt, 400_000);
                // The model's E* (sphere on a rigid body: E/(1 − ν²)) for every contact.
                let e_star = |_: usize| 1e8 / 0.91;
                let r_star = |i: usize| if i == 0 { 2.0e-3 } else { 1.0e-3 };
                let mut worst: f64 = 0.0;
                for (i, di) in d.iter().enumerate() {
                    let k = 4.0 / 3.0 * e_star(i) * f64::sqrt(r_star(i));
                    let want = ((n - i) as f64 * 2.0e-3 * 9.81 / k).powf(2.0 / 3.0);
                    worst = worst.max((di / want - 1.0).abs());
                }
                println!(
                    "crit {crit} e {e} {name}: static overlaps within {worst:.1e}, |v| tail {vmax:.1e} m/s"
                );
                assert!(
                    worst < 1e-6 && vmax < 1e-6,
                    "{name} crit {crit} e {e}: {worst:e} {vmax:e}"
                );
            }
        }
    }
}

#[test]
fn dt_for_accuracy_step_aware_is_larger_and_holds() {
    use demcontact::EndCriterion;
    use demcontact::contact::step_exact::dt_for_accuracy as dt_step;
    use demcontact::timestep::dt_for_accuracy as dt_plain;
    // Hertz sphere on a wall: F = k δ^1.5, ω0 = √(k/m); impact speed 1 m/s.
    let (k, p) = (4.0 / 3.0 * (1e8 / 0.91) * 2.0e-3f64.sqrt(), 1.5);
    let (m_, v0) = (2.0e-3, 1.0);
    let omega0 = (k / m_).sqrt();
    for (crit, code) in [(EndCriterion::Overlap, 0), (EndCriterion::Force, 1)] {
        for (e, tol) in [(0.1, 0.015), (0.5, 0.005), (0.9, 0.002)] {
            let ds = dt_step(p, e, crit, v0, omega0, tol).unwrap();
            let dp = dt_plain(p, e, crit, v0, omega0, tol).unwrap();
            let th = t_h(Law::Hertz, v0);
            // Independently: the library's contact at ds, 64 phases, must meet tol; at 2 ds
            // (unless capped at t_H/10) some phase must miss it.
            let plain = contact_model(&spec(Law::Hertz, e, code)).unwrap();
            let at = |dt: f64| {
                let stepped = set_step(&plain, dt, 0).unwrap();
                stat(&stepped, Law::Hertz, e, v0, th / dt, true).worst
            };
            let w1 = at(ds);
            println!(
                "crit {code} e {e} tol {tol}: step-aware dt = t_H/{:.1}, plain t_H/{:.1} ({:.1}x); worst at dt {:.2e}",
                th / ds,
                th / dp,
                ds / dp,
                w1
            );
            assert!(w1 <= tol, "{w1} > {tol}");
            if th / ds > 10.5 {
                assert!(at(2.0 * ds) > 0.9 * tol, "not the largest step");
            }
            assert!(ds >= 2.0 * dp, "step-aware {ds} vs plain {dp}");
        }
    }
}

/// Tangential restitution of an oblique sphere–wall impact (Chung & Ooi test 4 kind: sticking,
/// μ large; Hertz + Mindlin with e_t = 0.5): the contact point's tangential speed out over in,
/// e_t = −u_t,out/u_t,in with u_t = v_t − R ω (ω about the axis normal to the plane of impact).
/// Velocity Verlet (LAMMPS order), onset phase j of 32.
fn oblique_e_t(m: &demcontact::contact::ContactModel, dt: f64, j: usize) -> (f64, f64) {
    oblique_e_t_at(m, dt, j, 0.5)
}

/// [`oblique_e_t`] at tangential impact speed `vt0` (normal 1 m/s).
fn oblique_e_t_at(
    m: &demcontact::contact::ContactModel,
    dt: f64,
    j: usize,
    vt0: f64,
) -> (f64, f64) {
    use demcontact::contact::{ContactState, contact_force};
    let (mass, r) = (2.0e-3, 2.0e-3);
    let inertia = 0.4 * mass * r * r;
    let vn0 = 1.0; // normal speed (towards the wall)
    let mut hist = [0.0; 16];
    let mut d = -(j as f64) / 32.0 * vn0 * dt;
    // Wall normal +z; the sphere moves in x (tangential) and −z; spin about y.
    let (mut vz, mut vx, mut wy) = (-vn0, vt0, 0.0);
    let (mut az, mut ax, mut aw) = (0.0, 0.0, 0.0);
    let mut touched = false;
    for _ in 0..200_000 {
        let (vzh, vxh, wyh) = (vz + 0.5 * dt * az, vx + 0.5 * dt * ax, wy + 0.5 * dt * aw);
        d -= dt * vzh;
        touched |= d > 0.0;
        let s = ContactState {
            n: [0.0, 0.0, 1.0],
            overlap: d,
            v1: [vxh, 0.0, vzh],
            v2: [0.0; 3],
            w1: [0.0, wyh, 0.0],
            w2: [0.0; 3],
            r1: r,
            r2: f64::INFINITY,
            m1: mass,
            m2: f64::INFINITY,
        };
        let out = contact_force(m, &s, dt, &mut hist).unwrap();
        az = out.force[2] / mass;
        ax = out.force[0] / mass;
        aw = out.torque1[1] / inertia;
        vz = vzh + 0.5 * dt * az;
        vx = vxh + 0.5 * dt * ax;
        wy = wyh + 0.5 * dt * aw;
        if touched && d <= 0.0 {
            // Contact point velocity of the sphere at the wall: v_x + ω_y · (−R) × ... = v_x − R ω_y
            // with the point at −R z: v_point = v + ω × (−R ẑ), x-part = −R ω_y.
            let ut_in = vt0;
            let ut_out = vx - r * wy;
            return (vz / vn0, ut_out / ut_in);
        }
    }
    panic!("no separation");
}

#[test]
fn tangential_restitution_at_the_host_step() {
    // Measured, not corrected: the step-aware option acts on the normal dashpot only. Reference:
    // the plain model at t_H/2000. Asserted: the option changes e_t by less than the plain
    // model's own step error at t_H/20 plus 0.5 %, and e_n is the target (mean over phases).
    let mut s = spec(Law::Hertz, 0.5, 1);
    s.tangential = demcontact::contact::model::select::TANGENTIAL_MINDLIN;
    s.mu = 10.0;
    s.e_t = 0.5;
    let plain = contact_model(&s).unwrap();
    let th = t_h(Law::Hertz, 1.0);
    let mean = |m: &demcontact::contact::ContactModel, n: f64| {
        let (mut en, mut et) = (0.0, 0.0);
        for j in 0..32 {
            let (a, b) = oblique_e_t(m, th / n, j);
            en += a / 32.0;
            et += b / 32.0;
        }
        (en, et)
    };
    let (_, et_ref) = mean(&plain, 2000.0);
    for n in [20.0, 50.0] {
        let stepped = set_step(&plain, th / n, 0).unwrap();
        let (en_p, et_p) = mean(&plain, n);
        let (en_s, et_s) = mean(&stepped, n);
        println!(
            "t_H/{n}: e_n plain {en_p:.4} step-aware {en_s:.4}; e_t plain {et_p:.4} step-aware {et_s:.4} (reference t_H/2000: {et_ref:.4})"
        );
        assert!((en_s / 0.5 - 1.0).abs() < 0.01, "e_n {en_s}");
        assert!(
            (et_s - et_ref).abs() <= (et_p - et_ref).abs() + 0.005,
            "e_t {et_s} vs {et_p}"
        );
    }
}

/// The batch of a step-aware model (its steady loop over every contact, then the exact path for
/// the contacts at onset, flagged or at their predicted last step) equals the scalar
/// `contact_force` bit for bit: 700 bouncing spheres on a wall under gravity (more than one
/// chunk and one guard block), impact speeds 0.3–3 m/s and every onset phase, so the run has
/// onsets, steady steps, the end handling (C) and its flag, separated contacts and resting ones;
/// Hertz (normal-only and Mindlin), p = 1 and p = 2, both criteria, records of the model's own
/// length and wider than DC_CONTACT_HISTORY_MAX. Each step's forces move both copies the same
/// way (velocity Verlet), so equal bits keep the two runs on one trajectory.
#[test]
fn batch_equals_scalar_bit_for_bit() {
    use demcontact::contact::batch::{BatchIn, BatchOut, contact_force_batch};
    use demcontact::contact::model::select;
    use demcontact::contact::{ContactState, HISTORY_MAX, contact_force};
    let (nc, steps) = (700usize, 400usize);
    let (rad, mass) = (2.0e-3, 2.0e-3);
    let mut counts = [0usize; 4]; // onset, steady, (C) fired, separated
    for (law, tangential) in [
        (Law::Hertz, select::TANGENTIAL_NONE),
        (Law::Hertz, select::TANGENTIAL_MINDLIN),
        (Law::Linear, select::TANGENTIAL_NONE),
        (Law::P2, select::TANGENTIAL_NONE),
    ] {
        for crit in [0, 1] {
            let mut s = spec(law, 0.5, crit);
            s.tangential = tangential;
            s.mu = 0.5;
            let dt = t_h(law, 1.0) / 20.0;
            let m = set_step(&contact_model(&s).unwrap(), dt, 0).unwrap();
            let at = m.layout.step.unwrap();
            for stride in [m.layout.len, HISTORY_MAX + 1] {
                // One flight of ~40 steps at 1 m/s.
                let g = 2.0 / (40.0 * dt);
                let speed = |i: usize| 0.3 * 10f64.powf(i as f64 / nc as f64);
                let mut d: Vec<f64> = (0..nc)
                    .map(|i| -((i % 64) as f64 / 64.0 + (i / 64) as f64) * speed(i) * dt)
                    .collect();
                let mut v: Vec<f64> = (0..nc).map(|i| -speed(i)).collect();
                let vt: Vec<f64> = (0..nc)
                    .map(|i| 0.1 * speed(i) * ((i % 7) as f64 - 3.0))
                    .collect();
                let mut acc = vec![-g; nc];
                let mut hb = vec![0.0; nc * stride];
                let mut hs = hb.clone();
                let n = vec![[0.0, 0.0, 1.0]; nc];
                let (r1, r2) = (vec![rad; nc], vec![f64::INFINITY; nc]);
                let (m1, m2) = (vec![mass; nc], vec![f64::INFINITY; nc]);
                let zero = vec![[0.0; 3]; nc];
                for _ in 0..steps {
                    let mut v1 = vec![[0.0; 3]; nc];
                    for i in 0..nc {
                        let vh = v[i] + 0.5 * dt * acc[i];
                        v[i] = vh;
                        d[i] -= dt * vh;
                        v1[i] = [vt[i], 0.0, vh];
                    }
                    let (mut f_n, mut force) = (vec![0.0; nc], vec![[0.0; 3]; nc]);
                    let (mut t1, mut t2) = (vec![[0.0; 3]; nc], vec![[0.0; 3]; nc]);
                    let before = hb.clone();
                    let inp = BatchIn {
                        normal: &n,
                        overlap: &d,
                        v1: &v1,
                        v2: &zero,
                        w1: &zero,
                        w2: &zero,
                        r1: &r1,
                        r2: &r2,
                        m1: &m1,
                        m2: &m2,
                    };
                    let mut out = BatchOut {
                        f_n: &mut f_n,
                        force: &mut force,
                        torque1: Some(&mut t1),
                        torque2: Some(&mut t2),
                        history: &mut hb,
                        stride,
                    };
                    contact_force_batch(&m, &inp, dt, &mut out).unwrap();
                    for i in 0..nc {
                        let st = ContactState {
                            n: n[i],
                            overlap: d[i],
                            v1: v1[i],
                            v2: [0.0; 3],
                            w1: [0.0; 3],
                            w2: [0.0; 3],
                            r1: rad,
                            r2: f64::INFINITY,
                            m1: mass,
                            m2: f64::INFINITY,
                        };
                        let h = &mut hs[i * stride..(i + 1) * stride];
                        let r = contact_force(&m, &st, dt, h).unwrap();
                        let same = r.fn_.to_bits() == f_n[i].to_bits()
                            && (0..3).all(|k| r.force[k].to_bits() == force[i][k].to_bits())
                            && h.iter()
                                .zip(&hb[i * stride..])
                                .all(|(a, b)| a.to_bits() == b.to_bits());
                        assert!(
                            same,
                            "{law:?} tangential {tangential} crit {crit} stride {stride} contact {i}: \
                             scalar {:e} batch {:e}",
                            r.fn_, f_n[i]
                        );
                        let (h0, h1) = (before[i * stride + at], hb[i * stride + at]);
                        let k = if d[i] <= 0.0 {
                            3
                        } else if h0 == 0.0 {
                            0
                        } else if h1 < 0.0 {
                            2
                        } else {
                            1
                        };
                        counts[k] += 1;
                        acc[i] = force[i][2] / mass - g;
                        v[i] += 0.5 * dt * acc[i];
                    }
                }
            }
        }
    }
    println!(
        "onset {} steady {} end (C) {} separated {}",
        counts[0], counts[1], counts[2], counts[3]
    );
    assert!(
        counts.iter().all(|&c| c > 1000),
        "every case exercised: {counts:?}"
    );
}

/// A step-aware normal-only batch (one history double per contact, saved in the guard's narrow
/// buffer) whose contacts 5 and 530 of 600 overflow (overlap 1e300 m): `ResultRange`, those
/// contacts' outputs NaN and their history double as it was, every other contact as the scalar
/// `contact_force`, bit for bit; records of 1 and of 13 doubles.
#[test]
fn batch_overflow_keeps_the_step_slot() {
    use demcontact::Error;
    use demcontact::contact::batch::{BatchIn, BatchOut, contact_force_batch};
    use demcontact::contact::{ContactState, contact_force};
    let nc = 600;
    let dt = t_h(Law::Hertz, 1.0) / 20.0;
    let m = set_step(&contact_model(&spec(Law::Hertz, 0.5, 0)).unwrap(), dt, 0).unwrap();
    assert_eq!(m.layout.len, 1);
    for stride in [1, 13] {
        let bad = |i: usize| i == 5 || i == 530;
        let d: Vec<f64> = (0..nc)
            .map(|i| {
                if bad(i) {
                    1e300
                } else {
                    1e-6 * (1.0 + i as f64 / nc as f64)
                }
            })
            .collect();
        let v1: Vec<[f64; 3]> = (0..nc)
            .map(|i| [0.0, 0.0, -0.5 + (i % 3) as f64 * 0.25])
            .collect();
        let n = vec![[0.0, 0.0, 1.0]; nc];
        let zero = vec![[0.0; 3]; nc];
        let (r1, r2) = (vec![2e-3; nc], vec![f64::INFINITY; nc]);
        let (m1, m2) = (vec![2e-3; nc], vec![f64::INFINITY; nc]);
        // Every other contact past its onset (R stored), the rest fresh.
        let h0: Vec<f64> = (0..nc * stride)
            .map(|k| {
                if k % stride == 0 && (k / stride) % 2 == 1 {
                    0.97
                } else {
                    0.0
                }
            })
            .collect();
        let mut hb = h0.clone();
        let (mut f_n, mut force) = (vec![0.0; nc], vec![[0.0; 3]; nc]);
        let inp = BatchIn {
            normal: &n,
            overlap: &d,
            v1: &v1,
            v2: &zero,
            w1: &zero,
            w2: &zero,
            r1: &r1,
            r2: &r2,
            m1: &m1,
            m2: &m2,
        };
        let mut out = BatchOut {
            f_n: &mut f_n,
            force: &mut force,
            torque1: None,
            torque2: None,
            history: &mut hb,
            stride,
        };
        assert_eq!(
            contact_force_batch(&m, &inp, dt, &mut out),
            Err(Error::ResultRange)
        );
        for i in 0..nc {
            let rec = i * stride..(i + 1) * stride;
            if bad(i) {
                assert!(
                    f_n[i].is_nan() && force[i].iter().all(|x| x.is_nan()),
                    "contact {i}"
                );
                assert_eq!(hb[rec.clone()], h0[rec], "contact {i}: history touched");
                continue;
            }
            let st = ContactState {
                n: n[i],
                overlap: d[i],
                v1: v1[i],
                v2: [0.0; 3],
                w1: [0.0; 3],
                w2: [0.0; 3],
                r1: 2e-3,
                r2: f64::INFINITY,
                m1: 2e-3,
                m2: f64::INFINITY,
            };
            let mut h = h0[rec.clone()].to_vec();
            let r = contact_force(&m, &st, dt, &mut h).unwrap();
            assert_eq!(
                r.fn_.to_bits(),
                f_n[i].to_bits(),
                "stride {stride} contact {i}"
            );
            assert!(
                h.iter()
                    .zip(&hb[rec])
                    .all(|(a, b)| a.to_bits() == b.to_bits()),
                "contact {i}"
            );
        }
    }
}

/// Whether the discrete-map calibration extends to the tangential dashpot: at t_H/20 a damping
/// change alone moves the realised e_t onto the reference. The same oblique impact at three
/// tangential speeds (0.25, 0.5, 1 m/s; normal 1 m/s), reference the plain model (spec e_t 0.5)
/// at t_H/2000, step-aware models at t_H/20 with spec e_t 0.5 (the tangential dashpot as built)
/// and 0.385 (a stronger tangential dashpot, one value for all three speeds). Asserted: with 0.5
/// every speed misses its reference by more than 0.05; with 0.385 every speed is within 0.01.
#[test]
fn tangential_damping_alone_can_correct_e_t() {
    let th = t_h(Law::Hertz, 1.0);
    let model = |et: f64| {
        let mut s = spec(Law::Hertz, 0.5, 1);
        s.tangential = demcontact::contact::model::select::TANGENTIAL_MINDLIN;
        s.mu = 10.0;
        s.e_t = et;
        contact_model(&s).unwrap()
    };
    let mean = |m: &demcontact::contact::ContactModel, n: f64, vt: f64| {
        (0..32)
            .map(|j| oblique_e_t_at(m, th / n, j, vt).1)
            .sum::<f64>()
            / 32.0
    };
    for vt in [0.25, 0.5, 1.0] {
        let reference = mean(&model(0.5), 2000.0, vt);
        let built = mean(&set_step(&model(0.5), th / 20.0, 0).unwrap(), 20.0, vt);
        let stronger = mean(&set_step(&model(0.385), th / 20.0, 0).unwrap(), 20.0, vt);
        println!(
            "v_t {vt}: reference {reference:.4}; t_H/20 step-aware, spec e_t 0.5: {built:.4}, 0.385: {stronger:.4}"
        );
        assert!(
            (built - reference).abs() > 0.05,
            "v_t {vt}: {built} vs {reference}"
        );
        assert!(
            (stronger - reference).abs() < 0.01,
            "v_t {vt}: {stronger} vs {reference}"
        );
    }
}

/// A pair whose first contact step is no onset (created overlapping: a = δ/(v dt) ≫ 1, or
/// receding) takes R = 1 and no onset correction: its force is the plain model's (relative
/// 1e-12) and its step slot holds 1. A true onset (a = 1/2 and a = 3/2, both ≤ ONSET_A_MAX = 2)
/// does get the correction. Linear, Hertz and p = 2, both criteria, e_n 0.1; a = 1e4 at
/// 1e-3 m/s.
#[test]
fn a_pair_created_overlapping_gets_no_onset_kick() {
    use demcontact::contact::{ContactState, contact_force};
    for law in [Law::Linear, Law::Hertz, Law::P2] {
        for crit in [0, 1] {
            let plain = contact_model(&spec(law, 0.1, crit)).unwrap();
            let dt = 1e-5;
            let m = set_step(&plain, dt, 0).unwrap();
            let at = m.layout.len as usize - 1;
            let state = |d: f64, v: f64| ContactState {
                n: [0.0, 0.0, 1.0],
                overlap: d,
                v1: [0.0, 0.0, -v],
                v2: [0.0; 3],
                w1: [0.0; 3],
                w2: [0.0; 3],
                r1: harness::R,
                r2: f64::INFINITY,
                m1: harness::M,
                m2: f64::INFINITY,
            };
            // (overlap, approach speed, an onset?)
            for (d, v, onset) in [
                (1e-4, 1e-3, false),
                (1e-4, -1e-3, false),
                (3e-5, 1.0, false),
                (0.5 * 1e-3 * dt, 1e-3, true),
                (1.5 * 1.0 * dt, 1.0, true),
            ] {
                let s = state(d, v);
                let mut hp = [0.0; 16];
                let mut hs = [0.0; 16];
                let fp = contact_force(&plain, &s, dt, &mut hp).unwrap().fn_;
                let fs = contact_force(&m, &s, dt, &mut hs).unwrap().fn_;
                let what = format!("{law:?} crit {crit} d {d:e} v {v:e}: plain {fp}, step {fs}");
                if onset {
                    assert!(hs[at] != 1.0 && (fs - fp).abs() > 1e-6 * fp.abs(), "{what}");
                } else {
                    assert_eq!(hs[at], 1.0, "{what}");
                    assert!((fs - fp).abs() <= 1e-12 * fp.abs(), "{what}");
                }
            }
        }
    }
}

/// A dt so small that dt over the t_H prefactor underflows to 0 (a subnormal dt) is refused with
/// DC_ERR_RESULT_RANGE (`Error::ResultRange`), on a plain model and on a step-aware one; the
/// smallest normal dt is accepted.
#[test]
fn subnormal_dt_is_a_range_error() {
    use demcontact::Error;
    for law in [Law::Hertz, Law::Linear, Law::P2] {
        let plain = contact_model(&spec(law, 0.5, 0)).unwrap();
        let stepped = set_step(&plain, 1e-6, 0).unwrap();
        for m in [&plain, &stepped] {
            assert!(
                matches!(set_step(m, 5e-324, 0), Err(Error::ResultRange)),
                "{law:?}"
            );
        }
        let ok = set_step(&stepped, f64::MIN_POSITIVE, 1).unwrap();
        assert!(ok.step.scale > 0.0, "{law:?}");
    }
}

/// Power laws beyond p = 3 have no step-aware form (the onset and end corrections' ζ(−β, x) is
/// built for β = (p − 1)/2 ≤ 1): `set_step` and the step-aware step search answer
/// DC_ERR_STEP_UNSUPPORTED, the model untouched; p = 3 itself is made step-aware. A dt whose
/// scale underflows is refused as a range error (before the calibration).
#[test]
fn step_aware_exponents_up_to_three() {
    use demcontact::Error;
    use demcontact::contact::step_exact::dt_for_accuracy;
    let with_p = |p: f64| {
        let mut s = spec(Law::P2, 0.5, 1);
        s.p = p;
        contact_model(&s).unwrap()
    };
    for p in [3.5, 10.0] {
        assert_eq!(
            set_step(&with_p(p), 1e-6, 0).err(),
            Some(Error::StepUnsupported),
            "p {p}"
        );
        assert_eq!(
            dt_for_accuracy(p, 0.5, demcontact::EndCriterion::Force, 1.0, 1.0, 0.01).err(),
            Some(Error::StepUnsupported),
            "p {p}"
        );
    }
    assert!(set_step(&with_p(3.0), 1e-6, 0).unwrap().step.on());
    assert_eq!(
        set_step(&with_p(2.0), 5e-324, 0).err(),
        Some(Error::ResultRange)
    );
}
