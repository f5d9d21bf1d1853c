//! Shared by tests/step_exact.rs and examples/step_exact_table.rs: sphere–wall collisions
//! through the library's `contact_force`, velocity Verlet in the LAMMPS order or symplectic
//! Euler, 64 contact-onset phases; t_H (the elastic contact duration at the impact speed) by RK4
//! integration of the elastic contact, independent of the library's closed form.
#![allow(dead_code)]

use demcontact::contact::spec::{damping, normal};
use demcontact::contact::{ContactModel, ContactSpec, ContactState, contact_force};

/// Contact-onset phases per case.
pub const PHASES: usize = 64;
pub const M: f64 = 2.0e-3; // kg
pub const R: f64 = 2.0e-3; // m

/// The normal laws of the study.
#[derive(Clone, Copy, Debug)]
pub enum Law {
    Hertz,
    Linear,
    P2,
}

/// The contact specification of a law at restitution e.
pub fn spec(law: Law, e: f64, criterion: i32) -> ContactSpec {
    let mut s = ContactSpec {
        damping: damping::RESTITUTION,
        criterion,
        e_n: e,
        ..ContactSpec::default()
    };
    match law {
        Law::Hertz => {
            s.normal = normal::HERTZ;
            s.e1 = 1e8;
            s.nu1 = 0.3;
            s.e2 = f64::INFINITY;
            s.nu2 = 0.3;
        }
        Law::Linear => {
            s.normal = normal::LINEAR;
            s.k_n = 2e4;
        }
        Law::P2 => {
            s.normal = normal::POWERLAW;
            s.p = 2.0;
            s.k_n = 5e7;
        }
    }
    s
}

/// F = k δ^p of the law for a sphere of radius R on a rigid wall (E* = E/(1 − ν²)).
fn elastic(law: Law) -> (f64, f64) {
    match law {
        Law::Hertz => (4.0 / 3.0 * (1e8 / (1.0 - 0.09)) * R.sqrt(), 1.5),
        Law::Linear => (2e4, 1.0),
        Law::P2 => (5e7, 2.0),
    }
}

/// Elastic contact duration at impact speed v: RK4 on m δ'' = −k δ^p from δ = 0, δ' = v, the
/// crossing back through δ = 0 located by linear interpolation (4000 steps per contact).
pub fn t_h(law: Law, v: f64) -> f64 {
    let (k, p) = elastic(law);
    let dmax = ((p + 1.0) * M * v * v / (2.0 * k)).powf(1.0 / (p + 1.0));
    let h = 4.0 * dmax / v / 4000.0;
    let acc = |d: f64| -k * d.max(0.0).powf(p) / M;
    let (mut d, mut u, mut t) = (0.0f64, v, 0.0);
    loop {
        let (k1d, k1u) = (u, acc(d));
        let (k2d, k2u) = (u + 0.5 * h * k1u, acc(d + 0.5 * h * k1d));
        let (k3d, k3u) = (u + 0.5 * h * k2u, acc(d + 0.5 * h * k2d));
        let (k4d, k4u) = (u + h * k3u, acc(d + h * k3d));
        let dn = d + h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        let un = u + h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
        if t > 0.0 && dn <= 0.0 {
            return t + h * d / (d - dn);
        }
        (d, u, t) = (dn, un, t + h);
    }
}

/// Realised e of one sphere–wall collision at onset phase j (velocity Verlet in the LAMMPS
/// order, or symplectic Euler), through `contact_force` with the model's history.
pub fn collide(m: &ContactModel, v0: f64, dt: f64, j: usize, verlet: bool) -> f64 {
    let mut hist = [0.0; 16];
    // Sphere above the wall (normal +z), moving down: gap φ v0 dt before the first step.
    let mut d = -(j as f64) / PHASES as f64 * v0 * dt;
    let (mut v, mut acc, mut touched) = (-v0, 0.0, false);
    let force = |d: f64, v: f64, hist: &mut [f64; 16]| {
        let s = ContactState {
            n: [0.0, 0.0, 1.0],
            overlap: d,
            v1: [0.0, 0.0, v],
            v2: [0.0; 3],
            w1: [0.0; 3],
            w2: [0.0; 3],
            r1: R,
            r2: f64::INFINITY,
            m1: M,
            m2: f64::INFINITY,
        };
        contact_force(m, &s, dt, hist).unwrap().force[2]
    };
    for _ in 0..100_000 {
        if verlet {
            let vh = v + 0.5 * dt * acc;
            d -= dt * vh;
            touched |= d > 0.0;
            acc = force(d, vh, &mut hist) / M;
            v = vh + 0.5 * dt * acc;
        } else {
            let f = force(d, v, &mut hist);
            v += dt * f / M;
            d -= dt * v;
            touched |= d > 0.0;
        }
        if touched && d <= 0.0 {
            return v / v0;
        }
    }
    panic!("no separation");
}

/// Phase statistics relative to the target: mean − 1 and the largest |e/e_n − 1|.
pub struct Stat {
    /// Mean over phases, relative error.
    pub mean: f64,
    /// Worst phase, relative error (magnitude).
    pub worst: f64,
}

/// The phase statistics of one case.
pub fn stat(m: &ContactModel, law: Law, e: f64, v0: f64, n: f64, verlet: bool) -> Stat {
    let dt = t_h(law, v0) / n;
    let es: Vec<f64> = (0..PHASES).map(|j| collide(m, v0, dt, j, verlet)).collect();
    let mean = es.iter().sum::<f64>() / PHASES as f64;
    let worst = es.iter().map(|x| (x / e - 1.0).abs()).fold(0.0, f64::max);
    Stat {
        mean: mean / e - 1.0,
        worst,
    }
}
