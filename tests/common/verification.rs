//! The MFiX DEM verification problems DEM01–DEM05 and Chung & Ooi (2011) tests 5–8, run through
//! the C ABI (`dc_contact_force`) by a small host (velocity Verlet in the LAMMPS order, gravity,
//! plane walls, one history per contact), each beside a reference computed independently of the
//! library: closed forms of the linear spring–dashpot with gravity, the matrix exponential of the
//! stacked pair's linear system, rigid-body impulse limits. Shared by tests/verification.rs
//! (which asserts every figure) and the report (examples/report/verification.rs, which draws them).
#![allow(
    dead_code,
    clippy::unwrap_used,
    clippy::indexing_slicing,
    clippy::too_many_arguments
)]

use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;
use std::f64::consts::PI;

pub type V = [f64; 3];

fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sc(s: f64, a: V) -> V {
    [s * a[0], s * a[1], s * a[2]]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A solid sphere.
#[derive(Clone, Copy, Debug)]
pub struct Ball {
    pub x: V,
    pub v: V,
    pub w: V,
    pub r: f64,
    pub m: f64,
    pub i: f64,
}

impl Ball {
    pub fn new(x: V, v: V, w: V, r: f64, rho: f64) -> Ball {
        let m = rho * 4.0 / 3.0 * PI * r.powi(3);
        Ball {
            x,
            v,
            w,
            r,
            m,
            i: 0.4 * m * r * r,
        }
    }
}

/// A fixed plane `n · x = c` (n unit, pointing into the domain).
#[derive(Clone, Copy, Debug)]
pub struct Wall {
    pub n: V,
    pub c: f64,
}

/// One ball above the floor y = 0 (normal +y).
pub fn on_floor(ball: Ball, g: f64, dt: f64, model: dc_contact_model) -> Scene {
    let floor = Wall {
        n: [0.0, 1.0, 0.0],
        c: 0.0,
    };
    Scene::new(vec![ball], vec![floor], g, dt, model)
}

/// The model from a spec edited by `f` (panics on a refused spec: a test set-up error).
pub fn model(f: impl FnOnce(&mut dc_contact_spec)) -> dc_contact_model {
    let mut spec: dc_contact_spec = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { dc_contact_spec_init(&mut spec) }, DC_OK);
    f(&mut spec);
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { dc_contact_model_init(&spec, &mut m) }, DC_OK);
    m
}

/// A scene: balls, walls, gravity along −y, one model for every contact.
pub struct Scene {
    pub balls: Vec<Ball>,
    pub walls: Vec<Wall>,
    pub g: f64,
    pub dt: f64,
    pub model: dc_contact_model,
    pub t: f64,
    force: Vec<V>,
    torque: Vec<V>,
    /// History per (ball, wall) then per ball pair (i < j).
    hist: Vec<[f64; DC_CONTACT_HISTORY_MAX]>,
}

impl Scene {
    pub fn new(
        balls: Vec<Ball>,
        walls: Vec<Wall>,
        g: f64,
        dt: f64,
        model: dc_contact_model,
    ) -> Self {
        let nb = balls.len();
        let nh = nb * walls.len() + nb * (nb.saturating_sub(1)) / 2;
        let mut s = Scene {
            force: vec![[0.0; 3]; nb],
            torque: vec![[0.0; 3]; nb],
            hist: vec![[0.0; DC_CONTACT_HISTORY_MAX]; nh],
            balls,
            walls,
            g,
            dt,
            model,
            t: 0.0,
        };
        s.forces();
        s
    }

    /// Forces at the current positions and (half-step) velocities; returns the contact count.
    fn forces(&mut self) -> usize {
        let nb = self.balls.len();
        for f in &mut self.force {
            *f = [0.0; 3];
        }
        for t in &mut self.torque {
            *t = [0.0; 3];
        }
        // (ball, the other ball or None for a wall, the state) per contact, in history order
        let mut contacts = Vec::with_capacity(self.hist.len());
        for bi in 0..nb {
            for w in &self.walls {
                let b = self.balls[bi];
                let st = dc_contact_state {
                    n: w.n,
                    overlap: b.r - (dot(w.n, b.x) - w.c),
                    v1: b.v,
                    v2: [0.0; 3],
                    w1: b.w,
                    w2: [0.0; 3],
                    r1: b.r,
                    r2: f64::INFINITY,
                    m1: b.m,
                    m2: f64::INFINITY,
                };
                contacts.push((bi, None, st));
            }
        }
        for i in 0..nb {
            for j in i + 1..nb {
                let (a, b) = (self.balls[i], self.balls[j]);
                let d = sub(a.x, b.x);
                let dist = dot(d, d).sqrt();
                let st = dc_contact_state {
                    n: sc(1.0 / dist, d),
                    overlap: a.r + b.r - dist,
                    v1: a.v,
                    v2: b.v,
                    w1: a.w,
                    w2: b.w,
                    r1: a.r,
                    r2: b.r,
                    m1: a.m,
                    m2: b.m,
                };
                contacts.push((i, Some(j), st));
            }
        }
        let mut touching = 0;
        let mut res = unsafe { std::mem::zeroed::<dc_contact_result>() };
        for ((i, j, st), hist) in contacts.into_iter().zip(self.hist.iter_mut()) {
            if st.overlap <= 0.0 {
                *hist = [0.0; DC_CONTACT_HISTORY_MAX];
                continue;
            }
            let s = unsafe {
                dc_contact_force(
                    &self.model,
                    &st,
                    self.dt,
                    hist.as_mut_ptr(),
                    hist.len(),
                    &mut res,
                )
            };
            assert_eq!(s, DC_OK);
            self.force[i] = add(self.force[i], res.force);
            self.torque[i] = add(self.torque[i], res.torque1);
            if let Some(j) = j {
                self.force[j] = sub(self.force[j], res.force);
                self.torque[j] = add(self.torque[j], res.torque2);
            }
            touching += 1;
        }
        touching
    }

    /// Steps until every contact that opened has closed again (one impact; at most 1 s).
    pub fn run_impact(&mut self) {
        let mut touched = false;
        loop {
            let n = self.step();
            touched |= n > 0;
            if touched && n == 0 {
                return;
            }
            assert!(self.t < 1.0, "impact did not end");
        }
    }

    /// One velocity-Verlet step (LAMMPS order: half kick, drift, forces, half kick); returns the
    /// number of contacts that carried force.
    pub fn step(&mut self) -> usize {
        let dt = self.dt;
        let g = [0.0, -self.g, 0.0];
        for (b, (f, tq)) in self
            .balls
            .iter_mut()
            .zip(self.force.iter().zip(&self.torque))
        {
            b.v = add(b.v, sc(0.5 * dt, add(sc(1.0 / b.m, *f), g)));
            b.w = add(b.w, sc(0.5 * dt / b.i, *tq));
            b.x = add(b.x, sc(dt, b.v));
        }
        let n = self.forces();
        for (b, (f, tq)) in self
            .balls
            .iter_mut()
            .zip(self.force.iter().zip(&self.torque))
        {
            b.v = add(b.v, sc(0.5 * dt, add(sc(1.0 / b.m, *f), g)));
            b.w = add(b.w, sc(0.5 * dt / b.i, *tq));
        }
        self.t += dt;
        n
    }
}

/// Damping ratio of the linear spring–dashpot that realises `e` when the contact ends at zero
/// overlap: ζ = −ln e / √(π² + ln² e) (the textbook closed form, derived independently of the
/// library's power-law calibration).
pub fn zeta_linear(e: f64) -> f64 {
    let l = e.ln();
    -l / (PI * PI + l * l).sqrt()
}

/// A linear spring–dashpot model (overlap criterion), frictionless unless `f` adds parts.
pub fn linear_model(kn: f64, e: f64, f: impl FnOnce(&mut dc_contact_spec)) -> dc_contact_model {
    model(|s| {
        s.normal = DC_NORMAL_LINEAR;
        s.k_n = kn;
        s.criterion = DC_END_OVERLAP;
        if e < 1.0 {
            s.damping = DC_DAMPING_RESTITUTION;
            s.e_n = e;
        }
        f(s)
    })
}

// ---------------------------------------------------------------------------------------------
// DEM01: freely falling particle (free fall, contact with the floor, rebound).

/// Parameters of DEM01/DEM02: diameter 0.2 m, density 2600 kg/m³ (MFiX's), our kn and e.
pub const R01: f64 = 0.1;
pub const RHO01: f64 = 2600.0;
pub const G: f64 = 9.81;

/// The exact contact stage of a ball hitting the floor at speed `vc` (> 0) with gravity:
/// δ'' + 2ζω δ' + ω² δ = g, δ(0) = 0, δ'(0) = vc. Returns (δ(t), δ'(t)).
pub fn contact_stage(kn: f64, m: f64, zeta: f64, vc: f64, t: f64) -> (f64, f64) {
    let w0 = (kn / m).sqrt();
    let wd = w0 * (1.0 - zeta * zeta).sqrt();
    let s = g_over_w2(w0);
    let a = -s;
    let b = (vc + zeta * w0 * a) / wd;
    let ex = (-zeta * w0 * t).exp();
    let (sn, cs) = (wd * t).sin_cos();
    let d = s + ex * (a * cs + b * sn);
    let dd = ex * ((-zeta * w0) * (a * cs + b * sn) + wd * (-a * sn + b * cs));
    (d, dd)
}

fn g_over_w2(w0: f64) -> f64 {
    G / (w0 * w0)
}

/// End of the exact contact stage (first return of δ to 0 after t = 0, by bracketing and
/// bisection to 1e-15 relative) and the rebound speed there.
pub fn contact_end(kn: f64, m: f64, zeta: f64, vc: f64) -> (f64, f64) {
    let w0 = (kn / m).sqrt();
    let wd = w0 * (1.0 - zeta * zeta).sqrt();
    // δ > 0 on (0, t_end): scan from a small time in steps of a hundredth of the period.
    let h = PI / wd / 200.0;
    let mut lo = h * 1e-3;
    let mut hi = lo;
    while contact_stage(kn, m, zeta, vc, hi).0 > 0.0 {
        lo = hi;
        hi += h;
        assert!(hi < 10.0 * PI / wd, "no end of contact");
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if contact_stage(kn, m, zeta, vc, mid).0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-15 * hi {
            break;
        }
    }
    let te = 0.5 * (lo + hi);
    (te, -contact_stage(kn, m, zeta, vc, te).1)
}

/// The exact centre height y(t) of DEM01 (dropped at rest from centre height h0): free fall,
/// the contact stage, free flight after the rebound (one bounce).
pub fn dem01_exact(kn: f64, m: f64, zeta: f64, h0: f64, t: f64) -> f64 {
    let t1 = (2.0 * (h0 - R01) / G).sqrt();
    if t <= t1 {
        return h0 - 0.5 * G * t * t;
    }
    let vc = G * t1;
    let (te, vr) = contact_end(kn, m, zeta, vc);
    if t <= t1 + te {
        return R01 - contact_stage(kn, m, zeta, vc, t - t1).0;
    }
    let s = t - t1 - te;
    R01 + vr * s - 0.5 * G * s * s
}

/// DEM01 through the library: (t, y_dem, y_exact) per step for `t_end`, at `dt`.
pub fn dem01(kn: f64, e: f64, h0: f64, dt: f64, t_end: f64) -> Vec<(f64, f64, f64)> {
    let b = Ball::new([0.0, h0, 0.0], [0.0; 3], [0.0; 3], R01, RHO01);
    let m = b.m;
    let mut sc = on_floor(b, G, dt, linear_model(kn, e, |_| {}));
    let z = zeta_linear(e);
    let mut out = Vec::new();
    while sc.t < t_end {
        sc.step();
        out.push((sc.t, sc.balls[0].x[1], dem01_exact(kn, m, z, h0, sc.t)));
    }
    out
}

// ---------------------------------------------------------------------------------------------
// DEM02: bouncing particle.

/// The apex heights after bounces 1..=k: exact for the linear spring–dashpot with gravity (the
/// contact stage in closed form), and the hard-sphere limit (h0 − r) e^{2k} + r.
pub fn dem02_exact(kn: f64, m: f64, e: f64, h0: f64, k: usize) -> (Vec<f64>, Vec<f64>) {
    let z = zeta_linear(e);
    let mut v = (2.0 * G * (h0 - R01)).sqrt();
    let (mut exact, mut hard) = (Vec::new(), Vec::new());
    for i in 1..=k {
        let (_, vr) = contact_end(kn, m, z, v);
        exact.push(R01 + vr * vr / (2.0 * G));
        hard.push((h0 - R01) * e.powi(2 * i as i32) + R01);
        v = vr;
    }
    (exact, hard)
}

/// DEM02 through the library: the apex heights of the first `k` bounces (each the parabola
/// through the three samples around the discrete maximum, so the step does not bias it).
pub fn dem02(kn: f64, e: f64, h0: f64, dt: f64, k: usize) -> Vec<f64> {
    let b = Ball::new([0.0, h0, 0.0], [0.0; 3], [0.0; 3], R01, RHO01);
    let mut sc = on_floor(b, G, dt, linear_model(kn, e, |_| {}));
    let mut apex = Vec::new();
    let mut ys = [h0, h0, h0];
    let mut bounced = false;
    while apex.len() < k {
        let touching = sc.step() > 0;
        bounced |= touching;
        ys = [ys[1], ys[2], sc.balls[0].x[1]];
        if bounced && !touching && ys[1] > ys[0] && ys[1] >= ys[2] {
            // vertex of the parabola through three equally spaced samples
            let (a, b, c) = (ys[0], ys[1], ys[2]);
            let den = a - 2.0 * b + c;
            apex.push(b - (a - c) * (a - c) / (8.0 * den));
            bounced = false;
        }
        assert!(sc.t < 100.0, "DEM02 did not bounce {k} times");
    }
    apex
}

// ---------------------------------------------------------------------------------------------
// DEM03: two stacked particles compressed between two walls.

/// Wall distance and initial centres as MFiX sets them: y_w = 3.6 r, y1 = y_w/4, y2 = 3 y_w/4.
pub const R03: f64 = 0.05;
pub const RHO03: f64 = 2600.0;

/// The exact DEM03 trajectory (y1, y2) at `t`: the linear system x' = A x + b solved as
/// x(t) = x_eq + exp(A t)(x0 − x_eq), exp by scaling and squaring of the Taylor series (18
/// terms after scaling below 0.5: error < 1e-16 relative), independent of the library.
pub fn dem03_exact(kn: f64, e: f64, m: f64, t: f64) -> (f64, f64) {
    use nalgebra::{Matrix4, Vector4};
    let yw = 3.6 * R03;
    let z = zeta_linear(e);
    let eta_w = 2.0 * z * (kn * m).sqrt();
    let eta_p = 2.0 * z * (kn * 0.5 * m).sqrt();
    // state (y1, y2, y1', y2'); forces:
    // m y1'' = −m g + kn (r − y1) − eta_w y1' − kn (2r − y2 + y1) + eta_p (y2' − y1')
    // m y2'' = −m g + kn (2r − y2 + y1) − eta_p (y2' − y1') − kn (r − yw + y2) − eta_w y2'
    let (k, r) = (kn / m, R03);
    #[rustfmt::skip]
    let a = Matrix4::new(
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
        -2.0 * k, k, -(eta_w + eta_p) / m, eta_p / m,
        k, -2.0 * k, eta_p / m, -(eta_w + eta_p) / m,
    );
    let bvec = Vector4::new(
        0.0,
        0.0,
        -G + k * r - 2.0 * k * r,
        -G + 2.0 * k * r - k * (r - yw),
    );
    // equilibrium: A x_eq + b = 0
    let x_eq = -a.try_inverse().expect("DEM03 system is regular") * bvec;
    let x0 = Vector4::new(0.25 * yw, 0.75 * yw, 0.0, 0.0);
    let at = a * t;
    let norm = at.abs().max();
    let mut s = 0;
    while norm / f64::from(1u32 << s.min(31)) > 0.5 && s < 60 {
        s += 1;
    }
    let scaled = at / 2f64.powi(s);
    let mut term = Matrix4::identity();
    let mut ex = Matrix4::identity();
    for n in 1..=18 {
        term = term * scaled / f64::from(n);
        ex += term;
    }
    for _ in 0..s {
        ex = ex * ex;
    }
    let x = x_eq + ex * (x0 - x_eq);
    (x[0], x[1])
}

/// DEM03 through the library: (t, y1, y2, y1_exact, y2_exact) per step; also asserts that all
/// three contacts stay closed (the exact solution assumes it).
pub fn dem03(kn: f64, e: f64, dt: f64, t_end: f64) -> Vec<(f64, f64, f64, f64, f64)> {
    let yw = 3.6 * R03;
    let b1 = Ball::new([0.0, 0.25 * yw, 0.0], [0.0; 3], [0.0; 3], R03, RHO03);
    let b2 = Ball::new([0.0, 0.75 * yw, 0.0], [0.0; 3], [0.0; 3], R03, RHO03);
    let m = b1.m;
    let walls = vec![
        Wall {
            n: [0.0, 1.0, 0.0],
            c: 0.0,
        },
        Wall {
            n: [0.0, -1.0, 0.0],
            c: -yw,
        },
    ];
    let mut sc = Scene::new(vec![b1, b2], walls, G, dt, linear_model(kn, e, |_| {}));
    let mut out = Vec::new();
    while sc.t < t_end {
        let n = sc.step();
        assert_eq!(n, 3, "DEM03: a contact opened at t = {}", sc.t);
        let (e1, e2) = dem03_exact(kn, e, m, sc.t);
        out.push((sc.t, sc.balls[0].x[1], sc.balls[1].x[1], e1, e2));
    }
    out
}

// ---------------------------------------------------------------------------------------------
// DEM04: slip to roll.

/// DEM04 through the library: a ball resting on the floor (settled first) is given a speed v0
/// along x without spin; returns (t, v_x, ω_z·a) per step from that moment, a = r − δ/2 the
/// lever of the contact point.
pub fn dem04(kn: f64, mu: f64, v0: f64, dt: f64, t_end: f64) -> Vec<(f64, f64, f64)> {
    let r = R01;
    let m0 = Ball::new([0.0; 3], [0.0; 3], [0.0; 3], r, RHO01).m;
    let d_static = m0 * G / kn;
    let b = Ball::new([0.0, r - d_static, 0.0], [0.0; 3], [0.0; 3], r, RHO01);
    let model = linear_model(kn, 0.3, |s| {
        s.tangential = DC_TANGENTIAL_LINEAR;
        s.k_t = 2.0 / 7.0 * kn;
        s.e_t = 0.3;
        s.mu = mu;
    });
    let mut sc = on_floor(b, G, dt, model);
    sc.balls[0].v = [v0, 0.0, 0.0];
    sc.t = 0.0;
    let mut out = Vec::new();
    while sc.t < t_end {
        sc.step();
        let b = sc.balls[0];
        let lever = b.r - 0.5 * (b.r - b.x[1]);
        // rolling along +x on a floor with normal +y: ω_z = −v_x / a
        out.push((sc.t, b.v[0], -b.w[2] * lever));
    }
    out
}

// ---------------------------------------------------------------------------------------------
// DEM05 and Chung & Ooi 5–8: oblique impacts with spin.

/// The outcome of one impact on the floor: final (v_x, v_y, ω_z).
#[derive(Clone, Copy, Debug)]
pub struct Out {
    pub vx: f64,
    pub vy: f64,
    pub wz: f64,
}

/// A ball of radius r hits the floor with (vt along x, −vn along y) and spin ω_z = w0, no
/// gravity; the ball starts 0.37 of a step's travel above contact (a generic onset phase).
pub fn wall_impact(
    model: dc_contact_model,
    r: f64,
    rho: f64,
    vn: f64,
    vt: f64,
    w0: f64,
    dt: f64,
) -> Out {
    let b = Ball::new(
        [0.0, r + 0.37 * vn * dt, 0.0],
        [vt, -vn, 0.0],
        [0.0, 0.0, w0],
        r,
        rho,
    );
    let mut sc = on_floor(b, 0.0, dt, model);
    sc.run_impact();
    let b = sc.balls[0];
    Out {
        vx: b.v[0],
        vy: b.v[1],
        wz: b.w[2],
    }
}

/// Two balls (radii r1, r2, same density) approach along y with relative normal speed vn
/// (ball 1 above, moving down), each with spin ω_z; ball 1 also with tangential speed vt along
/// x. Returns the final (ball 1, ball 2).
pub fn pair_impact(
    model: dc_contact_model,
    r1: f64,
    r2: f64,
    rho: f64,
    vn: f64,
    vt: f64,
    w1: f64,
    w2: f64,
    dt: f64,
) -> (Out, Out) {
    let b1 = Ball::new(
        [0.0, r1 + r2 + 0.37 * vn * dt, 0.0],
        [vt, -vn, 0.0],
        [0.0, 0.0, w1],
        r1,
        rho,
    );
    let b2 = Ball::new([0.0; 3], [0.0; 3], [0.0, 0.0, w2], r2, rho);
    let mut sc = Scene::new(vec![b1, b2], vec![], 0.0, dt, model);
    sc.run_impact();
    let o = |b: Ball| Out {
        vx: b.v[0],
        vy: b.v[1],
        wz: b.w[2],
    };
    (o(sc.balls[0]), o(sc.balls[1]))
}

/// A Hertz–Mindlin model (total-displacement spring, `DC_TANGENTIAL_MINDLIN`) of one material
/// (E, ν), against a rigid wall (`wall`) or a sphere of the same material; e_n = 1 undamped,
/// else calibrated with the force criterion.
pub fn hertz_mindlin(young: f64, poisson: f64, wall: bool, mu: f64, e_n: f64) -> dc_contact_model {
    model(|s| {
        s.normal = DC_NORMAL_HERTZ;
        s.E1 = young;
        s.nu1 = poisson;
        s.E2 = if wall { f64::INFINITY } else { young };
        s.nu2 = poisson;
        s.criterion = DC_END_FORCE;
        if e_n < 1.0 {
            s.damping = DC_DAMPING_RESTITUTION;
            s.e_n = e_n;
        }
        s.tangential = DC_TANGENTIAL_MINDLIN;
        s.mu = mu;
    })
}

/// The contact-point tangential velocity (along x) of ball 1 on the floor: v_x + r ω_z.
pub fn slip_wall(o: Out, r: f64) -> f64 {
    o.vx + r * o.wz
}

/// The contact-point tangential velocity of ball 1 (above) relative to ball 2 (below):
/// v1x − v2x + r1 ω1z + r2 ω2z.
pub fn slip_pair(o1: Out, o2: Out, r1: f64, r2: f64) -> f64 {
    o1.vx - o2.vx + r1 * o1.wz + r2 * o2.wz
}
