//! The force kernels against their defining formulas, evaluated here independently with `powf`
//! (no square-root tricks, stiffness and E* recomputed from the material data), over overlaps
//! 1e-12..1e-1 of the radius, speeds 1e-3..1e3 m/s of both signs, masses and radii over decades.
//!
//! Tolerance: |F − F_ref| ≤ 1e-14 (|elastic| + |damping|), i.e. 1e-14 relative to the force
//! whenever the two terms do not cancel (when they do, no evaluation order can do better than
//! the rounding of the terms). Clamped pairs: where the reference is within that tolerance of
//! zero either side of the clamp is accepted.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

use demcontact::ffi::calibration::dc_alpha_from_e;
use demcontact::ffi::force::*;
use demcontact::ffi::status::*;

const TOL: f64 = 2e-15;

fn logspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a * (b / a).powf(i as f64 / (n - 1) as f64))
        .collect()
}

fn alpha(e: f64, p: f64, crit: i32) -> f64 {
    let mut a = f64::NAN;
    assert_eq!(unsafe { dc_alpha_from_e(e, p, crit, &mut a) }, DC_OK);
    a
}

/// Checks one evaluation; returns the error relative to |el| + |damp|.
fn check(got: f64, el: f64, damp: f64, clamp: bool, what: &str) -> f64 {
    assert!(got.is_finite(), "{what}: non-finite force {got}");
    let scale = el.abs() + damp.abs();
    let raw = el + damp;
    let want = if clamp && raw < 0.0 { 0.0 } else { raw };
    let err = (got - want).abs() / scale;
    if clamp && raw.abs() <= TOL * scale {
        assert!(
            got >= 0.0 && got <= 2.0 * TOL * scale,
            "{what}: near-zero clamp {got}"
        );
        return 0.0;
    }
    assert!(
        err <= TOL,
        "{what}: got {got:e} want {want:e} (el {el:e} damp {damp:e}) err {err:e}"
    );
    err
}

struct Grid {
    radii: Vec<f64>,
    rel_overlaps: Vec<f64>,
    speeds: Vec<f64>,
    masses: Vec<f64>,
}

fn grid() -> Grid {
    let mut speeds = vec![0.0];
    for s in logspace(1e-3, 1e3, 13) {
        speeds.push(s);
        speeds.push(-s);
    }
    Grid {
        radii: vec![1e-5, 1e-3, 0.1],
        rel_overlaps: logspace(1e-12, 1e-1, 34),
        speeds,
        masses: vec![1e-12, 1e-3, 10.0],
    }
}

#[test]
fn powerlaw_equals_defining_formula() {
    let g = grid();
    let mut worst = 0.0f64;
    let mut count = 0usize;
    for p in [1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 5.0] {
        for crit in [DC_END_OVERLAP, DC_END_FORCE] {
            for e in [0.2, 0.5, 0.9, 1.0] {
                for k in [1e3, 1e10] {
                    let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
                    assert_eq!(
                        unsafe { dc_pair_powerlaw(p, k, e, crit, pair.as_mut_ptr()) },
                        DC_OK
                    );
                    let pair = unsafe { pair.assume_init() };
                    let a = alpha(e, p, crit);
                    assert_eq!(pair.alpha, a);
                    assert_eq!(pair.clamp, i32::from(crit == DC_END_FORCE));
                    for &r in &g.radii {
                        for &rel in &g.rel_overlaps {
                            let d = rel * r;
                            for &m in &g.masses {
                                for &vn in &g.speeds {
                                    let el = k * d.powf(p);
                                    let damp = a * (m * k).sqrt() * d.powf(0.5 * (p - 1.0)) * vn;
                                    // r_eff is ignored by fixed-k pairs: pass garbage.
                                    let got = unsafe { dc_normal_force(&pair, d, vn, f64::NAN, m) };
                                    let what = format!(
                                        "p={p} crit={crit} e={e} k={k} d={d:e} m={m} vn={vn}"
                                    );
                                    worst = worst.max(check(
                                        got,
                                        el,
                                        damp,
                                        crit == DC_END_FORCE,
                                        &what,
                                    ));
                                    count += 1;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    println!("power law: {count} forces, worst error {worst:.2e} of |el|+|damp|");
}

/// E* from the material data, written independently of the library.
fn e_star(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
}

#[test]
fn hertz_equals_defining_formula() {
    let g = grid();
    let mut worst = 0.0f64;
    let mut count = 0usize;
    let mats = [
        (63e9, 0.23, 63e9, 0.23),
        (210e9, 0.3, 5e6, 0.49),
        (1e7, 0.0, 1e12, -0.5),
    ];
    for &(e1, nu1, e2, nu2) in &mats {
        for crit in [DC_END_OVERLAP, DC_END_FORCE] {
            for e in [0.2, 0.5, 0.9, 1.0] {
                let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
                assert_eq!(
                    unsafe { dc_pair_hertz(e1, nu1, e2, nu2, e, crit, pair.as_mut_ptr()) },
                    DC_OK
                );
                let pair = unsafe { pair.assume_init() };
                let a = alpha(e, 1.5, crit);
                for &r in &g.radii {
                    let k = 4.0 / 3.0 * e_star(e1, nu1, e2, nu2) * r.sqrt();
                    for &rel in &g.rel_overlaps {
                        let d = rel * r;
                        for &m in &g.masses {
                            for &vn in &g.speeds {
                                let el = k * d.powf(1.5);
                                let damp = a * (m * k).sqrt() * d.powf(0.25) * vn;
                                let got = unsafe { dc_normal_force(&pair, d, vn, r, m) };
                                let what = format!(
                                    "E*={} crit={crit} e={e} r={r} d={d:e} m={m} vn={vn}",
                                    pair.stiffness
                                );
                                worst =
                                    worst.max(check(got, el, damp, crit == DC_END_FORCE, &what));
                                count += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    println!("Hertz: {count} forces, worst error {worst:.2e} of |el|+|damp|");
}

#[test]
fn viscoelastic_equals_seed_formula() {
    // Schwager & Pöschel eq. (13)-(14) for one material: rho = 2 Y sqrt(R_eff) / (3 (1 - nu^2)),
    // F = rho xi^(3/2) + (3/2) A rho sqrt(xi) xi'.
    let g = grid();
    let (y, nu) = (1e8, 0.3);
    let mut worst = 0.0f64;
    for crit in [DC_END_OVERLAP, DC_END_FORCE] {
        for a_damp in [1e-7, 1e-5, 1e-3] {
            let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
            assert_eq!(
                unsafe { dc_pair_viscoelastic(y, nu, y, nu, a_damp, crit, pair.as_mut_ptr()) },
                DC_OK
            );
            let pair = unsafe { pair.assume_init() };
            assert!(pair.e.is_nan() && pair.alpha == 0.0 && pair.damping_a == a_damp);
            for &r in &g.radii {
                let rho = 2.0 * y * r.sqrt() / (3.0 * (1.0 - nu * nu));
                for &rel in &g.rel_overlaps {
                    let d = rel * r;
                    for &vn in &g.speeds {
                        let el = rho * d.powf(1.5);
                        let damp = 1.5 * a_damp * rho * d.sqrt() * vn;
                        // m_eff is not read by this model: pass garbage.
                        let got = unsafe { dc_normal_force(&pair, d, vn, r, f64::NAN) };
                        let what = format!("visco A={a_damp} crit={crit} r={r} d={d:e} vn={vn}");
                        worst = worst.max(check(got, el, damp, crit == DC_END_FORCE, &what));
                    }
                }
            }
        }
    }
    println!("viscoelastic: worst error {worst:.2e} of |el|+|damp|");
}

fn all_pairs() -> Vec<(String, dc_pair)> {
    let mut v = Vec::new();
    let mut push = |name: String, f: &dyn Fn(*mut dc_pair) -> i32| {
        let mut pair = std::mem::MaybeUninit::<dc_pair>::zeroed();
        assert_eq!(f(pair.as_mut_ptr()), DC_OK, "{name}");
        v.push((name, unsafe { pair.assume_init() }));
    };
    for crit in [DC_END_OVERLAP, DC_END_FORCE] {
        for e in [0.3, 1.0] {
            for p in [1.0, 1.5, 2.0, 1.7] {
                push(format!("powerlaw p={p} e={e} c={crit}"), &|o| unsafe {
                    dc_pair_powerlaw(p, 1e6, e, crit, o)
                });
            }
            push(format!("linear e={e} c={crit}"), &|o| unsafe {
                dc_pair_linear(1e4, e, crit, o)
            });
            push(format!("hertz e={e} c={crit}"), &|o| unsafe {
                dc_pair_hertz(1e9, 0.3, 2e9, 0.2, e, crit, o)
            });
        }
        for a in [0.0, 1e-4] {
            push(format!("visco A={a} c={crit}"), &|o| unsafe {
                dc_pair_viscoelastic(1e9, 0.3, 1e9, 0.3, a, crit, o)
            });
        }
    }
    v
}

#[test]
fn kernels_are_specialised() {
    // Distinct kernel per (exponent path, damping, clamp); undamped pairs have no clamp variant.
    let pairs = all_pairs();
    let mut kernels: Vec<i32> = pairs.iter().map(|(_, p)| p.kernel).collect();
    kernels.sort();
    kernels.dedup();
    assert_eq!(kernels.len(), 17, "{kernels:?}");
}

#[test]
fn zero_force_without_overlap_and_never_nan_for_finite_input() {
    for (name, pair) in all_pairs() {
        for d in [
            0.0,
            -0.0,
            -1e-300,
            -1e-3,
            -1e300,
            f64::NAN,
            f64::NEG_INFINITY,
        ] {
            for vn in [0.0, 1e3, -1e3] {
                let f = unsafe { dc_normal_force(&pair, d, vn, 1e-3, 1e-3) };
                assert_eq!(
                    f.to_bits(),
                    0.0f64.to_bits(),
                    "{name}: d={d} vn={vn} gave {f}"
                );
            }
        }
        // Finite physical input at the edges: smallest positive overlaps, subnormals, huge speeds.
        for d in [5e-324, 1e-300, 1e-200, 1e-20, 1e-3] {
            for vn in [-1e6, -1e-300, 0.0, 1e-300, 1e6] {
                for r in [1e-9, 1.0] {
                    for m in [1e-20, 1e3] {
                        let f = unsafe { dc_normal_force(&pair, d, vn, r, m) };
                        assert!(f.is_finite(), "{name}: d={d} vn={vn} r={r} m={m} gave {f}");
                        if pair.clamp == 1 {
                            assert!(f >= 0.0);
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn fixed_k_hertz_agrees_with_material_hertz() {
    // The power law at p = 3/2 with k = (4/3) E* sqrt(R) is the material Hertz pair at radius R:
    // two different kernels (sqrt(d), sqrt(m sqrt d) vs sqrt(R d), sqrt(m q)) must agree.
    let (e1, nu1, e2, nu2, r, m): (f64, f64, f64, f64, f64, f64) =
        (70e9, 0.33, 200e9, 0.29, 2.5e-3, 4e-4);
    let k = 4.0 / 3.0 * e_star(e1, nu1, e2, nu2) * r.sqrt();
    for crit in [DC_END_OVERLAP, DC_END_FORCE] {
        let (mut a, mut b) = (
            std::mem::MaybeUninit::zeroed(),
            std::mem::MaybeUninit::zeroed(),
        );
        assert_eq!(
            unsafe { dc_pair_powerlaw(1.5, k, 0.4, crit, a.as_mut_ptr()) },
            DC_OK
        );
        assert_eq!(
            unsafe { dc_pair_hertz(e1, nu1, e2, nu2, 0.4, crit, b.as_mut_ptr()) },
            DC_OK
        );
        let (a, b): (dc_pair, dc_pair) = unsafe { (a.assume_init(), b.assume_init()) };
        for d in logspace(1e-12 * r, 0.1 * r, 20) {
            for vn in [-3.0, -0.01, 0.2, 10.0] {
                let fa = unsafe { dc_normal_force(&a, d, vn, r, m) };
                let fb = unsafe { dc_normal_force(&b, d, vn, r, m) };
                let scale = k * d.powf(1.5) + a.alpha * (m * k).sqrt() * d.powf(0.25) * vn.abs();
                assert!(
                    (fa - fb).abs() <= 1e-14 * scale,
                    "d={d:e} vn={vn}: {fa:e} vs {fb:e}"
                );
            }
        }
    }
}
