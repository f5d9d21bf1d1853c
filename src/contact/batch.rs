//! Structure-of-arrays batches of contacts of one model, one pass per stage.
//!
//! Pass 1 (normal) is monomorphised per normal kernel (the registry's dispatch, once per
//! batch) and touches only what the normal force needs; passes 2–4 (tangential, rolling,
//! twisting) run only when the model has them, each monomorphised on its own law. So the
//! compiled code is the sum of the sub-model counts, and a normal-only batch runs one loop.
//! A final pass stores the current normal in each history (the stages read the previous one)
//! and resets the history of separated contacts.
//!
//! Every value is validated in a first pass (nothing is written on error).

use super::evaluate::{check_model, check_state};
use super::kinematics::{ContactState, Kin};
use super::model::{ContactModel, select};
use super::tangential::{TangentialLaw, step};
use super::tangential_linear::Linear;
use super::tangential_mindlin::Mindlin;
use super::vec3::{V3, add, cross, scale, sub};
use super::{rolling_constant, rolling_epsd, twisting_sds};
use crate::Error;
use crate::force::pair::{Consts, Law, Visit, eval};
use crate::force::registry::{dispatch, normal_force_raw};

/// Inputs of n contacts: vectors are 3 consecutive doubles per contact (x, y, z).
#[derive(Clone, Copy, Debug)]
pub struct BatchIn<'a> {
    /// Unit normals (3n).
    pub normal: &'a [f64],
    /// Overlaps (n).
    pub overlap: &'a [f64],
    /// Velocities of body 1 (3n).
    pub v1: &'a [f64],
    /// Velocities of body 2 (3n).
    pub v2: &'a [f64],
    /// Angular velocities of body 1 (3n; any 3n array if the model is normal-only).
    pub w1: &'a [f64],
    /// Angular velocities of body 2 (3n; idem).
    pub w2: &'a [f64],
    /// Radii of body 1 (n).
    pub r1: &'a [f64],
    /// Radii of body 2 (n; +∞ for walls).
    pub r2: &'a [f64],
    /// Masses of body 1 (n).
    pub m1: &'a [f64],
    /// Masses of body 2 (n; +∞ for fixed bodies).
    pub m2: &'a [f64],
}

/// Outputs and history of n contacts.
#[derive(Debug)]
pub struct BatchOut<'a> {
    /// Normal forces (n).
    pub f_n: &'a mut [f64],
    /// Forces on body 1 (3n).
    pub force: &'a mut [f64],
    /// Torques on body 1 (3n); may be absent for a normal-only model.
    pub torque1: Option<&'a mut [f64]>,
    /// Torques on body 2 (3n); idem.
    pub torque2: Option<&'a mut [f64]>,
    /// History, `stride` doubles per contact (empty when the model needs none).
    pub history: &'a mut [f64],
    /// Doubles per contact in `history` (≥ the model's history length).
    pub stride: usize,
}

fn v3(c: &[f64]) -> V3 {
    match c {
        &[x, y, z] => [x, y, z],
        _ => [f64::NAN; 3],
    }
}

/// The states of the batch, in order.
fn states<'a>(b: &BatchIn<'a>) -> impl Iterator<Item = ContactState> + 'a {
    let b = *b;
    b.normal
        .chunks_exact(3)
        .zip(b.overlap)
        .zip(b.v1.chunks_exact(3).zip(b.v2.chunks_exact(3)))
        .zip(b.w1.chunks_exact(3).zip(b.w2.chunks_exact(3)))
        .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
        .map(
            |((((n, &d), (v1, v2)), (w1, w2)), ((&r1, &r2), (&m1, &m2)))| ContactState {
                n: v3(n),
                overlap: d,
                v1: v3(v1),
                v2: v3(v2),
                w1: v3(w1),
                w2: v3(w2),
                r1,
                r2,
                m1,
                m2,
            },
        )
}

/// Pass 1 for one normal kernel: f_n and the normal force vector.
struct NormalPass<'a, 'b> {
    c: Consts,
    inp: &'b BatchIn<'a>,
    f_n: &'b mut [f64],
    force: &'b mut [f64],
}

impl Visit for NormalPass<'_, '_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        normal_pass::<L, CLAMP>(self.c, self.inp, self.f_n, self.force);
    }
}

#[inline(never)]
fn normal_pass<L: Law, const CLAMP: bool>(
    c: Consts,
    b: &BatchIn<'_>,
    f_n: &mut [f64],
    force: &mut [f64],
) {
    let it = b
        .normal
        .chunks_exact(3)
        .zip(b.overlap)
        .zip(b.v1.chunks_exact(3).zip(b.v2.chunks_exact(3)))
        .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
        .zip(f_n.iter_mut().zip(force.chunks_exact_mut(3)));
    for ((((n, &d), (v1, v2)), ((&r1, &r2), (&m1, &m2))), (fo, fv)) in it {
        let (n, v1, v2) = (v3(n), v3(v1), v3(v2));
        let vn = (v2[0] - v1[0]) * n[0] + (v2[1] - v1[1]) * n[1] + (v2[2] - v1[2]) * n[2];
        let r = 1.0 / (1.0 / r1 + 1.0 / r2);
        let m = 1.0 / (1.0 / m1 + 1.0 / m2);
        let f = eval::<L, CLAMP>(&c, d, vn, r, m);
        *fo = f;
        // Separated contacts get +0 (as the scalar call), not f·n = ±0.
        let v = scale(f, n);
        fv.copy_from_slice(&if d > 0.0 { v } else { [0.0; 3] });
    }
}

fn put(c: &mut [f64], v: V3) {
    c.copy_from_slice(&v);
}

/// Pass 2 for one tangential law: adds F_t to the force, writes the torques of F_t, updates ξ.
#[inline(never)]
fn tangential_pass<T: TangentialLaw>(
    m: &ContactModel,
    b: &BatchIn<'_>,
    dt: f64,
    o: &mut BatchOut<'_>,
) {
    let (Some(at), Some(t1), Some(t2)) = (
        m.layout.tangential,
        o.torque1.as_deref_mut(),
        o.torque2.as_deref_mut(),
    ) else {
        return;
    };
    let it = states(b)
        .zip(o.f_n.iter())
        .zip(o.force.chunks_exact_mut(3))
        .zip(t1.chunks_exact_mut(3).zip(t2.chunks_exact_mut(3)))
        .zip(o.history.chunks_exact_mut(o.stride));
    for ((((s, &f), fv), (t1, t2)), h) in it {
        if !(s.overlap > 0.0) {
            continue;
        }
        let (k, frame) = Kin::of(&s, v3(h.get(0..3).unwrap_or(&[])), dt);
        let Some(xs) = h.get_mut(at..at + 3) else {
            continue;
        };
        let mut xi = v3(xs);
        let r = step::<T>(m, &k, f, dt, &frame, &mut xi);
        put(xs, xi);
        put(fv, add(v3(fv), r.ft));
        let nft = cross(k.n, r.ft);
        put(t1, scale(-k.a1, nft));
        put(t2, if k.wall { [0.0; 3] } else { scale(-k.a2, nft) });
    }
}

/// Pass 3: rolling torque added to both torques.
#[inline(never)]
fn rolling_pass<const EPSD: bool>(
    m: &ContactModel,
    b: &BatchIn<'_>,
    dt: f64,
    o: &mut BatchOut<'_>,
) {
    let (Some(t1), Some(t2)) = (o.torque1.as_deref_mut(), o.torque2.as_deref_mut()) else {
        return;
    };
    let at = m.layout.rolling.unwrap_or(0);
    let pair = &m.normal;
    let it = states(b)
        .zip(o.f_n.iter())
        .zip(t1.chunks_exact_mut(3).zip(t2.chunks_exact_mut(3)))
        .zip(
            o.history
                .chunks_exact_mut(o.stride.max(1))
                .map(Some)
                .chain(core::iter::repeat_with(|| None)),
        );
    for (((s, &f), (t1, t2)), h) in it {
        if !(s.overlap > 0.0) {
            continue;
        }
        let n_old = h.as_deref().and_then(|h| h.get(0..3)).map_or([0.0; 3], v3);
        let (k, frame) = Kin::of(&s, n_old, dt);
        let mr = if EPSD {
            let Some(h) = h else { continue };
            let kn = if m.k_r > 0.0 {
                0.0
            } else {
                let fe = normal_force_raw(pair.kernel, pair.consts, k.d, 0.0, k.r_eff, k.m_eff);
                pair.p * fe / k.d
            };
            let Some(ms) = h.get_mut(at..at + 3) else {
                continue;
            };
            let mut mk = v3(ms);
            let (t, _) = rolling_epsd::step(m, &k, f, kn, dt, &frame, &mut mk);
            put(ms, mk);
            t
        } else {
            rolling_constant::torque(m, &k, f).0
        };
        put(t1, add(v3(t1), mr));
        if !k.wall {
            put(t2, sub(v3(t2), mr));
        }
    }
}

/// Pass 4: twisting torque about n.
#[inline(never)]
fn twisting_pass(m: &ContactModel, b: &BatchIn<'_>, dt: f64, o: &mut BatchOut<'_>) {
    let (Some(at), Some(t1), Some(t2)) = (
        m.layout.twisting,
        o.torque1.as_deref_mut(),
        o.torque2.as_deref_mut(),
    ) else {
        return;
    };
    let it = states(b)
        .zip(o.f_n.iter())
        .zip(t1.chunks_exact_mut(3).zip(t2.chunks_exact_mut(3)))
        .zip(o.history.chunks_exact_mut(o.stride));
    for (((s, &f), (t1, t2)), h) in it {
        if !(s.overlap > 0.0) {
            continue;
        }
        let (k, _) = Kin::of(&s, [0.0; 3], dt);
        let Some(mk) = h.get_mut(at) else { continue };
        let (t, _) = twisting_sds::step(m, &k, f, dt, mk);
        let mt = scale(t, k.n);
        put(t1, add(v3(t1), mt));
        if !k.wall {
            put(t2, sub(v3(t2), mt));
        }
    }
}

/// Final pass: the current normal becomes the stored one; separated contacts start afresh.
fn frame_pass(m: &ContactModel, b: &BatchIn<'_>, o: &mut BatchOut<'_>) {
    let len = m.layout.len;
    if len == 0 {
        return;
    }
    let it = b
        .normal
        .chunks_exact(3)
        .zip(b.overlap)
        .zip(o.history.chunks_exact_mut(o.stride));
    for ((n, &d), h) in it {
        let Some(h) = h.get_mut(..len) else { continue };
        if d > 0.0 {
            if let Some(hn) = h.get_mut(0..3) {
                hn.copy_from_slice(n);
            }
        } else {
            h.fill(0.0);
        }
    }
}

/// Forces of n contacts of one model (n = `inp.overlap.len()`); every slice must have the
/// documented length (checked). Nothing is written on error.
pub fn contact_force_batch(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<(), Error> {
    check_model(m)?;
    let n = inp.overlap.len();
    let len = m.layout.len;
    let needs_torque = m.layout.len > 0 || m.rolling != select::ROLLING_NONE;
    let three = [inp.normal, inp.v1, inp.v2, inp.w1, inp.w2];
    let one = [inp.r1, inp.r2, inp.m1, inp.m2];
    let torque_ok = |t: &Option<&mut [f64]>| match t {
        Some(t) => t.len() == 3 * n,
        None => !needs_torque,
    };
    if n == 0
        || three.iter().any(|a| a.len() != 3 * n)
        || one.iter().any(|a| a.len() != n)
        || out.f_n.len() != n
        || out.force.len() != 3 * n
        || !torque_ok(&out.torque1)
        || !torque_ok(&out.torque2)
        || out.stride < len
        || (len > 0 && out.history.len() != n * out.stride)
    {
        return Err(Error::BufferTooShort);
    }
    if !dt.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(dt > 0.0) {
        return Err(Error::NotPositive);
    }
    for s in states(inp) {
        check_state(&s)?;
    }
    if len > 0
        && !out
            .history
            .chunks_exact(out.stride)
            .all(|h| h.iter().take(len).all(|x| x.is_finite()))
    {
        return Err(Error::NotFinite);
    }
    let pair = &m.normal;
    dispatch(
        pair.kernel,
        NormalPass {
            c: pair.consts,
            inp,
            f_n: out.f_n,
            force: out.force,
        },
    )
    .ok_or(Error::ContactModelInvalid)?;
    {
        for t in [out.torque1.as_deref_mut(), out.torque2.as_deref_mut()]
            .into_iter()
            .flatten()
        {
            t.fill(0.0);
        }
    }
    match m.tangential {
        select::TANGENTIAL_LINEAR => tangential_pass::<Linear>(m, inp, dt, out),
        select::TANGENTIAL_MINDLIN => tangential_pass::<Mindlin>(m, inp, dt, out),
        _ => {}
    }
    match m.rolling {
        select::ROLLING_CONSTANT => rolling_pass::<false>(m, inp, dt, out),
        select::ROLLING_EPSD => rolling_pass::<true>(m, inp, dt, out),
        _ => {}
    }
    if m.twisting == select::TWISTING_SDS {
        twisting_pass(m, inp, dt, out);
    }
    frame_pass(m, inp, out);
    Ok(())
}
