//! Passivity of the full contact (issue 31): with e_n = e_t = 1 (no dashpot), an oblique impact
//! must not leave with more kinetic energy than it came with, beyond the integrator's own error,
//! and the energy ledger (dc_contact_force_energy) must balance the kinetic energy change.
//!
//! Scenes: two equal spheres (centre-of-mass frame, relative speed V) and a sphere on a fixed
//! wall, Chung & Ooi's (2011) Al2O3 and aluminium alloy (both bodies of one material; the wall
//! rigid), R = 2.5 mm, V = 3.9 m/s, impact angles 5°–85° from the normal in steps of 5°;
//! sticking (μ = 1e3) and sliding (μ = 0.1); every tangential law × carry (rotate, project) ×
//! rolling (none, constant μ_r = 0.02, EPSD μ_r = 0.02 with a fixed k_r). Integrated with
//! velocity Verlet in the LAMMPS order (half kick, drift, force from the half-step velocities,
//! half kick; tests/contact_sim) at dt = t_c/3000, t_c the Hertz contact time.
//!
//! The bound: BOUND = 1e-6 of the incoming kinetic energy at dt = t_c/3000. It is the scheme's
//! own first-order error (the lever arms r − δ/2 and the contact frame change within a step,
//! which the trapezoid of the ledger does not see): the largest ledger residual of the passive
//! laws is 7.5e-6 (the constant rolling torque's work taken at the half-step spin) and it halves
//! when dt halves (`ledger_residual_is_first_order_in_dt`).
//! `DC_TANGENTIAL_MINDLIN` (total form k_t(δ) ξ) gains up to MINDLIN_GAIN (asserted to 1e-6),
//! and the ledger shows it: its residual ΔKE + Σ dissipated is the energy it created.
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;

/// |ΔKE|/KE_in the integrator may leave (dt = t_c/3000): see the module documentation.
const BOUND: f64 = 1e-5;
/// The largest relative gain of `DC_TANGENTIAL_MINDLIN` over the matrix (measured here).
const MINDLIN_GAIN: f64 = 7.581e-3;
const R: f64 = 2.5e-3;
const V: f64 = 3.9;

#[derive(Clone, Copy, Debug)]
#[allow(dead_code)] // `name` is read by Debug in the messages
struct Mat {
    name: &'static str,
    e: f64,
    nu: f64,
    rho: f64,
}
const AL2O3: Mat = Mat {
    name: "Al2O3",
    e: 3.8e11,
    nu: 0.23,
    rho: 4000.0,
};
const AL_ALLOY: Mat = Mat {
    name: "Al alloy",
    e: 7.0e10,
    nu: 0.33,
    rho: 2700.0,
};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Scene {
    Pair,
    Wall,
}

#[derive(Clone, Copy, Debug)]
struct Case {
    mat: Mat,
    scene: Scene,
    tangential: i32,
    carry: i32,
    rolling: i32,
    mu: f64,
    deg: f64,
    /// Normal law: elastic–plastic (yield speed V/10) instead of Hertz.
    plastic: bool,
    /// Normal law: JKR (sticking speed a quarter of the normal impact speed) instead of Hertz,
    /// with this normal restitution target e_n (1: undamped).
    jkr: Option<f64>,
}

/// (ΔKE/KE_in, (ΔKE + Σ dissipated)/KE_in, Σ dissipated/KE_in, and for JKR the bound of the
/// work the force's two jumps may leave in a Verlet step, ((4/3) + (5/6)) π w R* V dt/KE_in).
#[derive(Clone, Copy, Debug)]
struct Outcome {
    gain: f64,
    residual: f64,
    dissipated: f64,
    jump: f64,
}

fn e_star(c: &Case) -> f64 {
    let s = (1.0 - c.mat.nu * c.mat.nu) / c.mat.e;
    match c.scene {
        Scene::Pair => 1.0 / (2.0 * s),
        Scene::Wall => 1.0 / s,
    }
}

fn run(c: &Case) -> Outcome {
    run_n(c, 3000.0)
}

fn run_n(c: &Case, steps: f64) -> Outcome {
    let (r_eff, m1) = (
        match c.scene {
            Scene::Pair => 0.5 * R,
            Scene::Wall => R,
        },
        c.mat.rho * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3),
    );
    let m_eff = match c.scene {
        Scene::Pair => 0.5 * m1,
        Scene::Wall => m1,
    };
    let es = e_star(c);
    let tc = 2.87 * (m_eff * m_eff / (r_eff * es * es * V)).powf(0.2);
    let dt = tc / steps;
    // The largest Hertz overlap, for the linear spring's stiffness (of the order of Mindlin's).
    let d_max = (15.0 * m_eff * V * V / (16.0 * es * r_eff.sqrt())).powf(0.4);
    let g = |mat: Mat| mat.e / (2.0 * (1.0 + mat.nu));
    let g_star = 1.0 / (2.0 * (2.0 - c.mat.nu) / g(c.mat));
    let g_star = match c.scene {
        Scene::Pair => 0.5 * g_star,
        Scene::Wall => g_star,
    };
    let k_t = 8.0 * g_star * (r_eff * d_max).sqrt();
    let k_n = 1.5 * 4.0 / 3.0 * es * (r_eff * d_max).sqrt();
    // Elastic–plastic: p_y such that the head-on yield speed is V/10, from
    // ½ m* v_y² = (8/15) E* √R* δ_y^{5/2}, δ_y = (π p_y/(2E*))² R*.
    let vy = 0.1 * V;
    let dy = (15.0 * m_eff * vy * vy / (16.0 * es * r_eff.sqrt())).powf(0.4);
    let p_y = 2.0 * es / std::f64::consts::PI * (dy / r_eff).sqrt();
    // JKR: w such that the sticking speed is a quarter of the normal impact speed, from
    // ½ m* v_s² = (2π)^{5/3} (6 + 4^{−1/3})/20 (w⁵ R*⁴/E*²)^{1/3}.
    let vs = 0.25 * V * c.deg.to_radians().cos();
    let cw = (2.0 * std::f64::consts::PI).powf(5.0 / 3.0) * (6.0 + 0.25f64.cbrt()) / 20.0;
    let w = ((0.5 * m_eff * vs * vs / cw).powi(3) * es * es / r_eff.powi(4)).powf(0.2);
    let jump = (4.0 / 3.0 + 5.0 / 6.0) * std::f64::consts::PI * w * r_eff * V * dt;
    let model = model(|s| {
        s.normal = if c.plastic {
            DC_NORMAL_ELASTIC_PLASTIC
        } else if c.jkr.is_some() {
            DC_NORMAL_JKR
        } else {
            DC_NORMAL_HERTZ
        };
        if let Some(e_n) = c.jkr {
            s.work_of_adhesion = w;
            s.criterion = DC_END_OVERLAP;
            if e_n < 1.0 {
                s.damping = DC_DAMPING_RESTITUTION;
                s.e_n = e_n;
            }
        }
        s.yield_pressure = p_y;
        s.E1 = c.mat.e;
        s.nu1 = c.mat.nu;
        s.E2 = if c.scene == Scene::Wall {
            f64::INFINITY
        } else {
            c.mat.e
        };
        s.nu2 = c.mat.nu;
        s.tangential = c.tangential;
        s.mu = c.mu;
        s.k_t = k_t;
        s.rolling = c.rolling;
        s.mu_r = 0.02;
        s.k_r = 2.25 * k_n * 0.02 * 0.02 * r_eff * r_eff;
    });
    let mut m = model;
    assert_eq!(
        unsafe { dc_contact_model_set_carry(&mut m, c.carry) },
        DC_OK
    );
    let th = c.deg.to_radians();
    // Unit normal +y (as the wall); tangent +x. Start 2 steps of travel apart.
    let dir = [th.sin(), -th.cos(), 0.0];
    let gap = 2.0 * V * dt * th.cos();
    let (mut b1, mut other) = match c.scene {
        Scene::Pair => {
            let b1 = Body::sphere(
                [0.0, R + 0.5 * gap, 0.0],
                sc(0.5 * V, dir),
                [0.0; 3],
                R,
                c.mat.rho,
            );
            let b2 = Body::sphere(
                [0.0, -R - 0.5 * gap, 0.0],
                sc(-0.5 * V, dir),
                [0.0; 3],
                R,
                c.mat.rho,
            );
            (b1, Other::Sphere(b2))
        }
        Scene::Wall => (
            Body::sphere([0.0, R + gap, 0.0], sc(V, dir), [0.0; 3], R, c.mat.rho),
            Other::Wall,
        ),
    };
    let ke = |b1: &Body, o: &Other| {
        b1.kinetic()
            + match o {
                Other::Sphere(b2) => b2.kinetic(),
                Other::Wall => 0.0,
            }
    };
    let ke_in = ke(&b1, &other);
    let mut hist = [0.0f64; DC_CONTACT_HISTORY_MAX];
    let mut res = ZERO_RESULT;
    let mut en: dc_contact_energy = unsafe { std::mem::zeroed() };
    let mut dissipated = 0.0;
    let mut touched = false;
    for _ in 0..20 * 3000 {
        let kick = |b: &mut Body, f: V, tq: V| {
            b.v = add(b.v, sc(0.5 * dt / b.m, f));
            b.w = add(b.w, sc(0.5 * dt / b.i, tq));
        };
        kick(&mut b1, res.force, res.torque1);
        if let Other::Sphere(b2) = &mut other {
            kick(b2, sc(-1.0, res.force), res.torque2);
            b2.x = add(b2.x, sc(dt, b2.v));
        }
        b1.x = add(b1.x, sc(dt, b1.v));
        let st = state(&b1, &other);
        let s = unsafe {
            dc_contact_force_energy(
                &m,
                &st,
                dt,
                hist.as_mut_ptr(),
                hist.len(),
                &mut res,
                &mut en,
            )
        };
        assert_eq!(s, DC_OK);
        dissipated += en.dissipated;
        kick(&mut b1, res.force, res.torque1);
        if let Other::Sphere(b2) = &mut other {
            kick(b2, sc(-1.0, res.force), res.torque2);
        }
        if st.overlap > 0.0 {
            touched = true;
        } else if touched && res.f_n == 0.0 {
            // Out of contact (a JKR neck holds at δ ≤ 0, with an attractive force, until it
            // breaks).
            let d = ke(&b1, &other) - ke_in;
            return Outcome {
                gain: d / ke_in,
                residual: (d + dissipated) / ke_in,
                dissipated: dissipated / ke_in,
                jump: if c.jkr.is_some() { jump / ke_in } else { 0.0 },
            };
        }
    }
    panic!("{c:?}: the contact did not end");
}

fn name(t: i32) -> &'static str {
    match t {
        DC_TANGENTIAL_LINEAR => "linear",
        DC_TANGENTIAL_MINDLIN => "mindlin",
        _ => "mindlin_rescale",
    }
}

/// Every case of the matrix; prints the worst gain and ledger residual per law.
#[test]
fn no_contact_creates_energy_and_the_ledger_balances() {
    let mut worst: Vec<(String, f64, f64)> = Vec::new();
    let mut mindlin_gain = (0.0f64, String::new());
    for tangential in [
        DC_TANGENTIAL_LINEAR,
        DC_TANGENTIAL_MINDLIN,
        DC_TANGENTIAL_MINDLIN_RESCALE,
    ] {
        let (mut g_max, mut r_max) = (f64::NEG_INFINITY, 0.0f64);
        for mat in [AL2O3, AL_ALLOY] {
            for scene in [Scene::Pair, Scene::Wall] {
                for carry in [DC_CARRY_ROTATE, DC_CARRY_PROJECT] {
                    for rolling in [DC_ROLLING_NONE, DC_ROLLING_CONSTANT, DC_ROLLING_EPSD] {
                        for mu in [1e3, 0.1] {
                            for i in 1..=17 {
                                let c = Case {
                                    mat,
                                    scene,
                                    tangential,
                                    carry,
                                    rolling,
                                    mu,
                                    deg: 5.0 * i as f64,
                                    plastic: false,
                                    jkr: None,
                                };
                                let o = run(&c);
                                if tangential == DC_TANGENTIAL_MINDLIN
                                    && carry == DC_CARRY_ROTATE
                                    && rolling == DC_ROLLING_NONE
                                    && mu > 1.0
                                    && i == 14
                                {
                                    println!(
                                        "mindlin {} {scene:?} sticking 70°: {:+.4e}",
                                        mat.name, o.gain
                                    );
                                }
                                g_max = g_max.max(o.gain);
                                if tangential == DC_TANGENTIAL_MINDLIN {
                                    if o.gain > mindlin_gain.0 {
                                        mindlin_gain = (o.gain, format!("{c:?}"));
                                    }
                                    // The ledger never reports a negative dissipation; what
                                    // MINDLIN creates is its residual.
                                    assert!(o.dissipated >= -BOUND, "{c:?}: {o:?}");
                                    r_max = r_max.max(o.residual.abs());
                                } else {
                                    r_max = r_max.max(o.residual.abs());
                                    assert!(o.gain <= BOUND, "{c:?}: gains {o:?}");
                                    assert!(o.residual.abs() <= BOUND, "{c:?}: ledger {o:?}");
                                    assert!(o.dissipated >= -BOUND, "{c:?}: {o:?}");
                                }
                            }
                        }
                    }
                }
            }
        }
        worst.push((name(tangential).into(), g_max, r_max));
    }
    for (n, g, r) in &worst {
        println!("{n:>16}: largest ΔKE/KE_in {g:+.3e}, largest |ledger residual| {r:.2e}");
    }
    println!(
        "mindlin: largest gain {:+.4e} at {}",
        mindlin_gain.0, mindlin_gain.1
    );
    assert!(
        (mindlin_gain.0 - MINDLIN_GAIN).abs() <= BOUND,
        "MINDLIN's largest gain {} (stated {MINDLIN_GAIN})",
        mindlin_gain.0
    );
}

/// The ledger residual of a passive law is the scheme's first-order error: it halves with dt.
#[test]
fn ledger_residual_is_first_order_in_dt() {
    for (tangential, scene) in [
        (DC_TANGENTIAL_LINEAR, Scene::Pair),
        (DC_TANGENTIAL_MINDLIN_RESCALE, Scene::Pair),
        (DC_TANGENTIAL_MINDLIN_RESCALE, Scene::Wall),
    ] {
        let c = Case {
            mat: AL2O3,
            scene,
            tangential,
            carry: DC_CARRY_ROTATE,
            rolling: DC_ROLLING_NONE,
            mu: 1e3,
            deg: 45.0,
            plastic: false,
            jkr: None,
        };
        let (a, b) = (run_n(&c, 3000.0), run_n(&c, 6000.0));
        let ratio = a.residual / b.residual;
        println!(
            "{} {scene:?} 45°: residual {:.3e} → {:.3e} (ratio {ratio:.3})",
            name(tangential),
            a.residual,
            b.residual
        );
        assert!((1.8..=2.2).contains(&ratio), "{c:?}: {a:?} {b:?}");
        // The kinetic energy itself agrees between the two steps to the same order.
        assert!((a.gain - b.gain).abs() <= 1e-4, "{c:?}: {a:?} {b:?}");
    }
}

/// The elastic–plastic normal law (yield speed V/10) with every tangential law but the total-form
/// Mindlin (which creates energy by design) × rolling × sticking/sliding × both scenes, 15°–75°:
/// the hysteresis only removes energy, and the ledger, whose normal term is the law's exact
/// plastic work, balances the kinetic energy lost to the scheme's bound.
#[test]
fn elastic_plastic_hysteresis_only_removes_energy_and_the_ledger_balances() {
    let (mut r_max, mut lost) = (0.0f64, (f64::INFINITY, 0.0f64));
    for tangential in [DC_TANGENTIAL_LINEAR, DC_TANGENTIAL_MINDLIN_RESCALE] {
        for scene in [Scene::Pair, Scene::Wall] {
            for rolling in [DC_ROLLING_NONE, DC_ROLLING_CONSTANT, DC_ROLLING_EPSD] {
                for mu in [1e3, 0.1] {
                    for i in 1..=5 {
                        let c = Case {
                            mat: AL_ALLOY,
                            scene,
                            tangential,
                            carry: DC_CARRY_ROTATE,
                            rolling,
                            mu,
                            deg: 15.0 * i as f64,
                            plastic: true,
                            jkr: None,
                        };
                        let o = run(&c);
                        assert!(o.gain < 0.0, "{c:?}: {o:?}");
                        assert!(o.dissipated > 0.0, "{c:?}: {o:?}");
                        assert!(o.residual.abs() <= BOUND, "{c:?}: ledger {o:?}");
                        r_max = r_max.max(o.residual.abs());
                        lost = (lost.0.min(-o.gain), lost.1.max(-o.gain));
                    }
                }
            }
        }
    }
    println!(
        "elastic-plastic: ΔKE/KE_in from {:.3} to {:.3} lost; largest |ledger residual| {r_max:.2e}",
        lost.0, lost.1
    );
}

/// JKR (sticking speed a quarter of the normal impact speed) undamped and with e_n = 0.7, with
/// every tangential law but the total-form Mindlin (which creates energy by design) × carry ×
/// rolling × sticking/sliding × both scenes × both materials, 15°–75°: the breakage (and the
/// dashpot) only remove energy, and the ledger, whose normal term is the law's breakage loss
/// plus its dashpot's work, balances the kinetic energy lost to the scheme's bound plus the work
/// the force's jumps (at formation and at breakage) may leave in one Verlet step.
#[test]
fn jkr_adhesion_only_removes_energy_and_the_ledger_balances() {
    let (mut r_max, mut lost, mut j_max) = (0.0f64, (f64::INFINITY, 0.0f64), 0.0f64);
    for e_n in [1.0, 0.7] {
        for tangential in [DC_TANGENTIAL_LINEAR, DC_TANGENTIAL_MINDLIN_RESCALE] {
            for mat in [AL2O3, AL_ALLOY] {
                for scene in [Scene::Pair, Scene::Wall] {
                    for carry in [DC_CARRY_ROTATE, DC_CARRY_PROJECT] {
                        for rolling in [DC_ROLLING_NONE, DC_ROLLING_CONSTANT, DC_ROLLING_EPSD] {
                            for mu in [1e3, 0.1] {
                                for i in 1..=5 {
                                    let c = Case {
                                        mat,
                                        scene,
                                        tangential,
                                        carry,
                                        rolling,
                                        mu,
                                        deg: 15.0 * i as f64,
                                        plastic: false,
                                        jkr: Some(e_n),
                                    };
                                    let o = run(&c);
                                    let bound = BOUND + o.jump;
                                    assert!(o.gain < 0.0, "{c:?}: {o:?}");
                                    assert!(o.dissipated > 0.0, "{c:?}: {o:?}");
                                    assert!(o.residual.abs() <= bound, "{c:?}: ledger {o:?}");
                                    r_max = r_max.max(o.residual.abs());
                                    j_max = j_max.max(o.jump);
                                    lost = (lost.0.min(-o.gain), lost.1.max(-o.gain));
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    println!(
        "jkr: ΔKE/KE_in from {:.3} to {:.3} lost; largest |ledger residual| {r_max:.2e} \
         (bound {BOUND:.0e} + jumps, largest jump term {j_max:.2e})",
        lost.0, lost.1
    );
}
