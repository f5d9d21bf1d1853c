//! A minimal two-body DEM integrator driven through the C ABI (dc_contact_force), for the
//! physics tests of the full contact: velocity-Verlet in the LAMMPS order (half kick, drift,
//! force from the half-step velocities, half kick), translation and rotation of spheres, and a
//! plane wall through the origin with normal +y (body 2 with r2 = m2 = +inf).
#![allow(dead_code, clippy::unwrap_used, clippy::indexing_slicing)]

use demcontact::ffi::contact::*;
use demcontact::ffi::status::DC_OK;

pub type V = [f64; 3];

/// The all-zero contact result (what a separated contact gives).
pub const ZERO_RESULT: dc_contact_result = dc_contact_result {
    force: [0.0; 3],
    torque1: [0.0; 3],
    torque2: [0.0; 3],
    f_n: 0.0,
    ft: [0.0; 3],
    sliding: 0,
    rolling_sliding: 0,
};

pub fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn sc(s: f64, a: V) -> V {
    [s * a[0], s * a[1], s * a[2]]
}
pub fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn norm(a: V) -> f64 {
    dot(a, a).sqrt()
}

/// Rotation of v by angle θ about the unit axis u (Rodrigues).
pub fn rot(u: V, th: f64, v: V) -> V {
    let (s, c) = th.sin_cos();
    add(
        add(sc(c, v), sc(s, cross(u, v))),
        sc(dot(u, v) * (1.0 - c), u),
    )
}

#[derive(Clone, Copy, Debug)]
pub struct Body {
    pub x: V,
    pub v: V,
    pub w: V,
    pub r: f64,
    pub m: f64,
    /// Moment of inertia (2/5 m r² for a solid sphere).
    pub i: f64,
}

impl Body {
    pub fn sphere(x: V, v: V, w: V, r: f64, rho: f64) -> Body {
        let m = rho * 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
        Body {
            x,
            v,
            w,
            r,
            m,
            i: 0.4 * m * r * r,
        }
    }
    pub fn kinetic(&self) -> f64 {
        0.5 * self.m * dot(self.v, self.v) + 0.5 * self.i * dot(self.w, self.w)
    }
}

/// What to collide body 1 with.
#[derive(Clone, Copy, Debug)]
pub enum Other {
    /// A second sphere.
    Sphere(Body),
    /// The fixed plane y = 0 (normal +y).
    Wall,
}

/// One step's record.
#[derive(Clone, Copy, Debug)]
pub struct Sample {
    pub t: f64,
    /// The state the kernel was called with, and the centres at that moment.
    pub state: dc_contact_state,
    pub x1: V,
    pub x2: V,
    pub res: dc_contact_result,
    pub overlap: f64,
    pub hist: [f64; DC_CONTACT_HISTORY_MAX],
}

/// The state for the ABI.
pub fn state(b1: &Body, other: &Other) -> dc_contact_state {
    match other {
        Other::Sphere(b2) => {
            let d = sub(b1.x, b2.x);
            let dist = norm(d);
            dc_contact_state {
                n: sc(1.0 / dist, d),
                overlap: b1.r + b2.r - dist,
                v1: b1.v,
                v2: b2.v,
                w1: b1.w,
                w2: b2.w,
                r1: b1.r,
                r2: b2.r,
                m1: b1.m,
                m2: b2.m,
            }
        }
        Other::Wall => dc_contact_state {
            n: [0.0, 1.0, 0.0],
            overlap: b1.r - b1.x[1],
            v1: b1.v,
            v2: [0.0; 3],
            w1: b1.w,
            w2: [0.0; 3],
            r1: b1.r,
            r2: f64::INFINITY,
            m1: b1.m,
            m2: f64::INFINITY,
        },
    }
}

/// Integrates from the given (non-touching or just touching) state until the contact ends
/// (overlap ≤ 0 after having been > 0) or `max_steps`. `each` sees every contact step.
pub fn collide(
    model: &dc_contact_model,
    b1: &mut Body,
    other: &mut Other,
    dt: f64,
    max_steps: usize,
    mut each: impl FnMut(&Sample, &Body, &Other),
) -> usize {
    let mut hist = [0.0f64; DC_CONTACT_HISTORY_MAX];
    let mut res = ZERO_RESULT;
    let mut touched = false;
    for step in 0..max_steps {
        // half kick with the last force, drift
        let kick = |b: &mut Body, f: V, tq: V| {
            b.v = add(b.v, sc(0.5 * dt / b.m, f));
            b.w = add(b.w, sc(0.5 * dt / b.i, tq));
        };
        kick(b1, res.force, res.torque1);
        if let Other::Sphere(b2) = other {
            kick(b2, sc(-1.0, res.force), res.torque2);
            b2.x = add(b2.x, sc(dt, b2.v));
        }
        b1.x = add(b1.x, sc(dt, b1.v));
        let st = state(b1, other);
        let s =
            unsafe { dc_contact_force(model, &st, dt, hist.as_mut_ptr(), hist.len(), &mut res) };
        assert_eq!(s, DC_OK);
        kick(b1, res.force, res.torque1);
        if let Other::Sphere(b2) = other {
            kick(b2, sc(-1.0, res.force), res.torque2);
        }
        if st.overlap > 0.0 {
            touched = true;
            each(
                &Sample {
                    t: step as f64 * dt,
                    state: st,
                    x1: b1.x,
                    x2: match other {
                        Other::Sphere(b2) => b2.x,
                        Other::Wall => [b1.x[0], 0.0, b1.x[2]],
                    },
                    res,
                    overlap: st.overlap,
                    hist,
                },
                b1,
                other,
            );
        } else if touched {
            return step;
        }
    }
    max_steps
}

/// A model from a spec edited by `f`.
pub fn model(f: impl FnOnce(&mut dc_contact_spec)) -> dc_contact_model {
    let mut spec: dc_contact_spec = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { dc_contact_spec_init(&mut spec) }, DC_OK);
    f(&mut spec);
    let mut m: dc_contact_model = unsafe { std::mem::zeroed() };
    let s = unsafe { dc_contact_model_init(&spec, &mut m) };
    assert_eq!(s, DC_OK, "model_init");
    m
}
