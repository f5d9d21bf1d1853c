//! Structure-of-arrays batches of contacts of one model, one pass per stage.
//!
//! Pass 1 (normal) is monomorphised per normal kernel (the registry's dispatch, once per
//! batch) and touches only what the normal force needs; passes 2–4 (tangential, rolling,
//! twisting) run only when the model has them, each monomorphised on its own law. So the
//! compiled code is the sum of the sub-model counts, and a normal-only batch runs one loop.
//! A final pass stores the current normal in each history (the stages read the previous one)
//! and resets the history of separated contacts.
//!
//! Every value is validated in a first pass (nothing is written on error). A contact whose
//! result overflows (finite inputs, non-finite force, torque or history: what
//! `dc_contact_force` refuses with `ResultRange`) is found after its stage passes: it gets NaN
//! outputs and its old history back (saved on the stack, [`GUARD`] contacts at a time), so no
//! overflow is ever silent and no history is left half-updated.

use super::evaluate::{check_model, check_state};
use super::kinematics::{ContactState, Kin, harmonic};
use super::model::{ContactModel, HISTORY_MAX, select};
use super::tangential::TangentialStage;
use super::vec3::{
    V3, add, all_finite, all_positive, bits_finite, cross, dot, finite_bits, no_nan, normal_vector,
    scale, sub,
};
use super::{rolling_constant, rolling_epsd, step_exact, twisting_sds};
use crate::force::pair::{Consts, Law, Visit, eval};
use crate::force::registry::{critical_load, dispatch, normal_force_raw, unclamped};
use crate::force::stateful;
use crate::numerics::simd::{SimdLoop, vectorised};
use crate::{EndCriterion, Error};
use core::marker::PhantomData;

/// Inputs of n contacts.
#[derive(Clone, Copy, Debug)]
pub struct BatchIn<'a> {
    /// Unit normals.
    pub normal: &'a [[f64; 3]],
    /// Overlaps (n).
    pub overlap: &'a [f64],
    /// Velocities of body 1.
    pub v1: &'a [[f64; 3]],
    /// Velocities of body 2.
    pub v2: &'a [[f64; 3]],
    /// Angular velocities of body 1 (any n vectors if the model is normal-only).
    pub w1: &'a [[f64; 3]],
    /// Angular velocities of body 2 (idem).
    pub w2: &'a [[f64; 3]],
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
    /// Forces on body 1.
    pub force: &'a mut [[f64; 3]],
    /// Torques on body 1; may be absent for a normal-only model.
    pub torque1: Option<&'a mut [[f64; 3]]>,
    /// Torques on body 2; idem.
    pub torque2: Option<&'a mut [[f64; 3]]>,
    /// History, `stride` doubles per contact (empty when the model needs none).
    pub history: &'a mut [f64],
    /// Doubles per contact in `history` (≥ the model's history length).
    pub stride: usize,
}

fn v3(c: &[f64]) -> V3 {
    match c {
        &[x, y, z] => [x, y, z],
        _ => [0.0; 3],
    }
}

/// The states of the batch, in order.
fn states<'a>(b: &BatchIn<'a>) -> impl Iterator<Item = ContactState> + 'a {
    let b = *b;
    b.normal
        .iter()
        .zip(b.overlap)
        .zip(b.v1.iter().zip(b.v2))
        .zip(b.w1.iter().zip(b.w2))
        .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
        .map(
            |((((&n, &d), (&v1, &v2)), (&w1, &w2)), ((&r1, &r2), (&m1, &m2)))| ContactState {
                n,
                overlap: d,
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

/// Pass 1 for one normal kernel: f_n and the normal force vector.
struct NormalPass<'a, 'b> {
    c: Consts,
    inp: &'b BatchIn<'a>,
    f_n: &'b mut [f64],
    force: &'b mut [[f64; 3]],
}

impl Visit for NormalPass<'_, '_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        vectorised(NormalLoop::<L, CLAMP> {
            p: self,
            law: PhantomData,
        });
    }
}

/// [`normal_pass`] run through [`vectorised`] (compiled for the CPU's widest vectors; every
/// flavour gives the same bits).
struct NormalLoop<'a, 'b, L, const CLAMP: bool> {
    p: NormalPass<'a, 'b>,
    law: PhantomData<L>,
}

impl<L: Law, const CLAMP: bool> SimdLoop for NormalLoop<'_, '_, L, CLAMP> {
    #[inline(always)]
    fn run(self) {
        let p = self.p;
        normal_pass::<L, CLAMP>(p.c, p.inp, p.f_n, p.force);
    }
}

#[inline(always)]
fn normal_pass<L: Law, const CLAMP: bool>(
    c: Consts,
    b: &BatchIn<'_>,
    f_n: &mut [f64],
    force: &mut [[f64; 3]],
) {
    let it = b
        .normal
        .iter()
        .zip(b.overlap)
        .zip(b.v1.iter().zip(b.v2))
        .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
        .zip(f_n.iter_mut().zip(force.iter_mut()));
    for ((((&n, &d), (&v1, &v2)), ((&r1, &r2), (&m1, &m2))), (fo, fv)) in it {
        // As Kin::of (same operations, same bits).
        let vn = -dot(sub(v1, v2), n);
        let f = eval::<L, CLAMP>(&c, d, vn, harmonic(r1, r2), harmonic(m1, m2));
        *fo = f;
        *fv = normal_vector(f, n);
    }
}

/// Pass 1 of the fused batch for a normal-only model: the check of each contact folded into
/// the loop that computes it (one read of each input); a bad contact's f_n and force are NaN.
struct NormalPassFused<'a, 'b> {
    c: Consts,
    inp: &'b BatchIn<'a>,
    f_n: &'b mut [f64],
    force: &'b mut [[f64; 3]],
}

impl Visit for NormalPassFused<'_, '_> {
    type Out = bool;
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) -> bool {
        normal_pass_fused::<L, CLAMP>(self.c, self.inp, self.f_n, self.force)
    }
}

/// The state of one contact valid, angular velocities aside (the conditions of
/// [`check_state`] with ω = 0 and of [`all_valid`])? Branch-free and in floating point, cheap
/// next to the kernel in one loop: 0·x is ±0 for finite x and NaN for NaN and ±∞, so the sum
/// of the products is 0 exactly when every value is finite (no overflow possible); `> 0`
/// is false for NaN, so r2, m2 > 0 also rejects NaN and admits +∞.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn state_ok(n: V3, d: f64, v1: V3, v2: V3, r1: f64, r2: f64, m1: f64, m2: f64) -> bool {
    let unit = (dot(n, n) - 1.0).abs() <= 1e-6;
    let [a1, a2, a3] = v1;
    let [b1, b2, b3] = v2;
    let z = 0.0 * d + 0.0 * a1 + 0.0 * a2 + 0.0 * a3 + 0.0 * b1 + 0.0 * b2 + 0.0 * b3;
    let finite = z + 0.0 * r1 + 0.0 * m1 == 0.0;
    unit & finite & (r1 > 0.0) & (m1 > 0.0) & (r2 > 0.0) & (m2 > 0.0)
}

/// Largest |f| whose vector f n is finite for every accepted normal (|n_i| <= 1 + 1e-6).
const F_SAFE: f64 = f64::MAX / 2.0;

/// Returns true if some contact was bad (poisoned) or its force may have overflowed (the
/// caller then checks contact by contact).
#[inline(never)]
fn normal_pass_fused<L: Law, const CLAMP: bool>(
    c: Consts,
    b: &BatchIn<'_>,
    f_n: &mut [f64],
    force: &mut [[f64; 3]],
) -> bool {
    let it = b
        .normal
        .iter()
        .zip(b.overlap)
        .zip(b.v1.iter().zip(b.v2))
        .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
        .zip(f_n.iter_mut().zip(force.iter_mut()));
    let mut bad = false;
    for ((((&n, &d), (&v1, &v2)), ((&r1, &r2), (&m1, &m2))), (fo, fv)) in it {
        let ok = state_ok(n, d, v1, v2, r1, r2, m1, m2);
        // As normal_pass (same operations, same bits) where ok.
        let vn = -dot(sub(v1, v2), n);
        let f = eval::<L, CLAMP>(&c, d, vn, harmonic(r1, r2), harmonic(m1, m2));
        let f = if ok { f } else { f64::NAN };
        *fo = f;
        // NaN f gives NaN components (f == 0 is false).
        *fv = normal_vector(f, n);
        // One compare finds both kinds: a bad contact (f is NaN) and a valid one whose force
        // may have overflowed, which goes to the exact per-contact check. |f| <= MAX/2 with
        // |n_i| <= 1 + 1e-6 keeps every component finite, so this only ever sends more
        // contacts there, never fewer; checking the three components here cost 1.2 ns per
        // contact (`scripts/bench_contact.sh`).
        bad |= !(f.abs() <= F_SAFE);
    }
    bad
}

/// All inputs valid? Separate passes per array with no early exit, each an OR reduction of bit
/// arithmetic (no float compare per value: a 64-bit compare has no packed form in the portable
/// x86-64 baseline, while the integer add/and/or do), which the compiler vectorises; the
/// detailed status is looked for only when one fails. Angular velocities are checked only when
/// the model reads them.
fn all_valid(b: &BatchIn<'_>, uses_w: bool) -> bool {
    // |n|² within 1e-6 of 1 also rejects NaN and ±∞ components.
    let unit = b
        .normal
        .iter()
        .fold(true, |ok, &n| ok & ((dot(n, n) - 1.0).abs() <= 1e-6));
    let w_ok = !uses_w || (all_finite(b.w1.as_flattened()) & all_finite(b.w2.as_flattened()));
    // Body 1: finite and > 0; body 2: > 0, +∞ allowed (a wall, a fixed body), no NaN.
    unit & all_finite(b.overlap)
        & all_finite(b.v1.as_flattened())
        & all_finite(b.v2.as_flattened())
        & w_ok
        & all_finite(b.r1)
        & all_positive(b.r1)
        & all_finite(b.m1)
        & all_positive(b.m1)
        & no_nan(b.r2)
        & all_positive(b.r2)
        & no_nan(b.m2)
        & all_positive(b.m2)
}

fn put(c: &mut [f64], v: V3) {
    c.copy_from_slice(&v);
}

/// Pass 2 for one tangential law: adds F_t to the force, writes the torques of F_t, updates ξ.
#[inline(never)]
fn tangential_pass<T: TangentialStage>(
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
        .zip(o.force.iter_mut())
        .zip(t1.iter_mut().zip(t2.iter_mut()))
        .zip(o.history.chunks_exact_mut(o.stride));
    for ((((s, &f), fv), (t1, t2)), h) in it {
        if !(s.overlap > 0.0) {
            continue;
        }
        let k = Kin::of(&s);
        let frame = Kin::frame(&s, v3(h.get(0..3).unwrap_or(&[])), dt, m.carry);
        let Some(rec) = h.get_mut(at..) else {
            continue;
        };
        let fc = critical_load(m.normal.kernel, &m.normal.consts, k.r_eff, f);
        let r = T::run(m, &k, fc, dt, &frame, rec);
        *fv = add(*fv, r.ft);
        let nft = cross(k.n, r.ft);
        *t1 = scale(-k.a1, nft);
        *t2 = if k.wall { [0.0; 3] } else { scale(-k.a2, nft) };
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
        .zip(t1.iter_mut().zip(t2.iter_mut()))
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
        let k = Kin::of(&s);
        let frame = Kin::frame(&s, n_old, dt, m.carry);
        let fc = critical_load(pair.kernel, &pair.consts, k.r_eff, f);
        let mr = if EPSD {
            let Some(h) = h else { continue };
            let kn = if m.k_r > 0.0 {
                0.0
            } else if m.layout.normal_state.is_some() {
                // As the scalar path: a law with state is elastic, p F/δ.
                pair.p * f / k.d
            } else {
                let fe = normal_force_raw(pair.kernel, pair.consts, k.d, 0.0, k.r_eff, k.m_eff);
                pair.p * fe / k.d
            };
            let Some(ms) = h.get_mut(at..at + 3) else {
                continue;
            };
            let mut mk = v3(ms);
            let (t, _) = rolling_epsd::step(m, &k, fc, kn, dt, &frame, &mut mk);
            put(ms, mk);
            t
        } else {
            rolling_constant::torque(m, &k, fc).0
        };
        *t1 = add(*t1, mr);
        if !k.wall {
            *t2 = sub(*t2, mr);
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
        .zip(t1.iter_mut().zip(t2.iter_mut()))
        .zip(o.history.chunks_exact_mut(o.stride));
    for (((s, &f), (t1, t2)), h) in it {
        if !(s.overlap > 0.0) {
            continue;
        }
        let k = Kin::of(&s);
        let Some(mk) = h.get_mut(at) else { continue };
        let fc = critical_load(m.normal.kernel, &m.normal.consts, k.r_eff, f);
        let (t, _) = twisting_sds::step(m, &k, fc, dt, mk);
        let mt = scale(t, k.n);
        *t1 = add(*t1, mt);
        if !k.wall {
            *t2 = sub(*t2, mt);
        }
    }
}

/// Pass 1 of a step-aware model: the normal force of each contact, the step-aware one
/// ([`step_exact::contact_normal_with`] with the law's monomorphised kernel) in contact, the
/// law's own force otherwise (as the scalar path computes them, bit for bit).
struct StepPass<'a, 'b, 'c> {
    m: &'b ContactModel,
    inp: &'b BatchIn<'a>,
    dt: f64,
    o: &'b mut BatchOut<'c>,
    at: usize,
}

impl Visit for StepPass<'_, '_, '_> {
    type Out = ();
    #[inline(always)]
    fn visit<L: Law, const CLAMP: bool>(self) {
        step_pass::<L>(self.m, self.inp, self.dt, self.o, self.at);
    }
}

/// Contacts per chunk of [`step_pass`]: its mask of contacts for the exact path lives on the
/// stack (one byte each).
const STEP_CHUNK: usize = 256;
const _: () = assert!(STEP_CHUNK.is_power_of_two() && STEP_CHUNK <= 1 << 16);

#[inline(never)]
fn step_pass<L: Law>(m: &ContactModel, b: &BatchIn<'_>, dt: f64, o: &mut BatchOut<'_>, at: usize) {
    let n = b.overlap.len();
    let mut a = 0;
    while a < n {
        let e = n.min(a + STEP_CHUNK);
        let len = if o.history.is_empty() { 0 } else { at + 1 };
        let (Some(ci), Some(mut co)) = (sub_in(b, a, e), sub_out(o, len, a, e)) else {
            // Unreachable after check_call (the slices have their lengths): the rest by the
            // exact path.
            step_exact_path::<L>(m, b, dt, o, at, a, None);
            return;
        };
        // 1 = this contact takes the exact path (a contact the steady loop does not reach
        // keeps it).
        let mut mask = [1u64; STEP_CHUNK];
        let mask = mask.get_mut(..e - a).unwrap_or(&mut []);
        // The history doubles gathered first (a strided load in the steady loop would keep it
        // from vectorising); records of one double back to back are read in place.
        let (c, f_n, force) = (m.normal.consts, &mut *co.f_n, &mut *co.force);
        let overlap = m.normal.criterion == EndCriterion::Overlap;
        match co.history.get(..e - a).filter(|_| co.stride == 1) {
            Some(slots) => steady::<L>(overlap, c, &ci, dt, f_n, force, slots, mask),
            None => {
                let mut gathered = [0.0f64; STEP_CHUNK];
                let held = co
                    .history
                    .get(at..)
                    .unwrap_or(&[])
                    .iter()
                    .step_by(co.stride);
                for (s, &x) in gathered.iter_mut().zip(held) {
                    *s = x;
                }
                let slots = gathered.get(..e - a).unwrap_or(&[]);
                steady::<L>(overlap, c, &ci, dt, f_n, force, slots, mask);
            }
        }
        // The marked contacts' indices, gathered without a branch per contact (a loop that
        // tests each mask entry mispredicts at every marked contact); groups of 8 contacts
        // with none marked (every group of a settled bed) are skipped whole.
        let mut idx = [0u16; STEP_CHUNK];
        let mut cnt = 0usize;
        for (j, group) in mask.chunks(8).enumerate() {
            if group.iter().fold(0, |acc, &mk| acc | mk) == 0 {
                continue;
            }
            for (k, &mk) in group.iter().enumerate() {
                // cnt ≤ 8j + k < STEP_CHUNK: the mask only shows the compiler that it is in bounds.
                if let Some(x) = idx.get_mut(cnt & (STEP_CHUNK - 1)) {
                    *x = (8 * j + k) as u16;
                }
                cnt += (mk != 0) as usize;
            }
        }
        let idx = idx.get(..cnt).unwrap_or(&[]);
        step_exact_path::<L>(m, &ci, dt, &mut co, at, 0, Some(idx));
        a = e;
    }
}

/// [`StepSteady`] for the model's end criterion (`overlap`: DC_END_OVERLAP), through
/// [`vectorised`].
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn steady<L: Law>(
    overlap: bool,
    consts: Consts,
    b: &BatchIn<'_>,
    dt: f64,
    f_n: &mut [f64],
    force: &mut [[f64; 3]],
    slots: &[f64],
    mask: &mut [u64],
) {
    if overlap {
        vectorised(StepSteady::<L, true> {
            consts,
            b,
            dt,
            f_n,
            force,
            slots,
            mask,
            law: PhantomData,
        });
    } else {
        vectorised(StepSteady::<L, false> {
            consts,
            b,
            dt,
            f_n,
            force,
            slots,
            mask,
            law: PhantomData,
        });
    }
}

/// The steady contact step of [`step_pass`] for every contact that `slots` (its history
/// doubles) reaches, branch-free: the force with the stored R (the history double's
/// magnitude), clamped at zero (DC_END_FORCE) or not (DC_END_OVERLAP), as [`step_exact::normal_force`] computes it for
/// a contact that is neither at its onset (history 0), nor flagged (history < 0), nor (with
/// `OVERLAP`) at its predicted last step; `mask` marks those, and separated contacts of an
/// adhesive law, for [`step_exact_path`].
///
/// Run through [`vectorised`] (compiled for the CPU's widest vectors: at SSE2's two lanes the
/// compiler's cost model keeps this loop scalar); every flavour gives the same bits.
struct StepSteady<'a, 'b, L, const OVERLAP: bool> {
    consts: Consts,
    b: &'b BatchIn<'a>,
    dt: f64,
    f_n: &'b mut [f64],
    force: &'b mut [[f64; 3]],
    slots: &'b [f64],
    mask: &'b mut [u64],
    law: PhantomData<L>,
}

impl<L: Law, const OVERLAP: bool> SimdLoop for StepSteady<'_, '_, L, OVERLAP> {
    #[inline(always)]
    fn run(self) {
        let StepSteady {
            consts,
            b,
            dt,
            f_n,
            force,
            slots,
            mask,
            ..
        } = self;
        let it = b
            .normal
            .iter()
            .zip(b.overlap)
            .zip(b.v1.iter().zip(b.v2))
            .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
            .zip(f_n.iter_mut().zip(force.iter_mut()))
            .zip(slots.iter().zip(mask.iter_mut()));
        for (((((&n, &d), (&v1, &v2)), ((&r1, &r2), (&m1, &m2))), (fo, fv)), (&s, mk)) in it {
            // As Kin::of (same operations, same bits).
            let vn = -dot(sub(v1, v2), n);
            let (r, mm) = (harmonic(r1, r2), harmonic(m1, m2));
            let c = Consts {
                c: consts.c * s.abs(),
                ..consts
            };
            // As step_exact::normal_force's steady step (same operations, same bits).
            let raw = L::raw(&c, d, vn, r, mm);
            let (f, end) = if OVERLAP {
                let vp = vn - dt * raw / mm;
                (raw, d + dt * vp <= 0.0)
            } else {
                (if raw > 0.0 { raw } else { 0.0 }, false)
            };
            let touching = d > 0.0;
            // Separated: the plain law's +0 (a repulsive law), else the exact path.
            let f = if touching { f } else { 0.0 };
            let exact = if touching {
                s <= 0.0 || end
            } else {
                L::ADHESIVE
            };
            *mk = u64::from(exact);
            *fo = f;
            *fv = normal_vector(f, n);
        }
    }
}

/// The contacts `idx` lists (all from `from` on for None) as the scalar path computes
/// them ([`step_exact::contact_normal_with`] with the law's monomorphised kernel in contact,
/// the law's own force otherwise), bit for bit.
#[inline(never)]
fn step_exact_path<L: Law>(
    m: &ContactModel,
    b: &BatchIn<'_>,
    dt: f64,
    o: &mut BatchOut<'_>,
    at: usize,
    from: usize,
    idx: Option<&[u16]>,
) {
    match idx {
        Some(list) => {
            for &i in list {
                exact_one::<L>(m, b, dt, o, at, usize::from(i));
            }
        }
        None => {
            for i in from..b.overlap.len() {
                exact_one::<L>(m, b, dt, o, at, i);
            }
        }
    }
}

/// Contact `i` of [`step_exact_path`].
#[inline(always)]
fn exact_one<L: Law>(
    m: &ContactModel,
    b: &BatchIn<'_>,
    dt: f64,
    o: &mut BatchOut<'_>,
    at: usize,
    i: usize,
) {
    let pair = &m.normal;
    let stride = o.stride;
    let (Some(&n), Some(&d), Some(&v1), Some(&v2)) =
        (b.normal.get(i), b.overlap.get(i), b.v1.get(i), b.v2.get(i))
    else {
        return;
    };
    let (Some(&r1), Some(&r2), Some(&m1), Some(&m2)) =
        (b.r1.get(i), b.r2.get(i), b.m1.get(i), b.m2.get(i))
    else {
        return;
    };
    let vn = -dot(sub(v1, v2), n);
    let (r, mm) = (harmonic(r1, r2), harmonic(m1, m2));
    let f = match o.history.get_mut(i * stride + at) {
        Some(slot) if d > 0.0 => {
            step_exact::contact_normal_with(m, d, vn, r, mm, dt, slot, |c, d, v, r, mm| {
                eval::<L, false>(&c, d, v, r, mm)
            })
        }
        _ => normal_force_raw(pair.kernel, pair.consts, d, vn, r, mm),
    };
    if let (Some(fo), Some(fv)) = (o.f_n.get_mut(i), o.force.get_mut(i)) {
        *fo = f;
        *fv = normal_vector(f, n);
    }
}

/// Pass 1 of a normal law with state ([`stateful`]): its force from, and its update of, the
/// state slot `at` of each contact's history (as the scalar path computes them, bit for bit).
#[inline(never)]
fn stateful_pass(m: &ContactModel, b: &BatchIn<'_>, o: &mut BatchOut<'_>, at: usize) {
    let pair = &m.normal;
    let it = b
        .normal
        .iter()
        .zip(b.overlap)
        .zip(b.v1.iter().zip(b.v2))
        .zip(b.r1.iter().zip(b.r2).zip(b.m1.iter().zip(b.m2)))
        .zip(o.f_n.iter_mut().zip(o.force.iter_mut()))
        .zip(o.history.chunks_exact_mut(o.stride.max(1)));
    for (((((&n, &d), (&v1, &v2)), ((&r1, &r2), (&m1, &m2))), (fo, fv)), h) in it {
        // As Kin::of (same operations, same bits).
        let vn = -dot(sub(v1, v2), n);
        let (r, mm) = (harmonic(r1, r2), harmonic(m1, m2));
        let f = match h.get_mut(at) {
            Some(slot) => stateful::force(pair.kernel, &pair.consts, d, vn, r, mm, slot),
            None => f64::NAN,
        };
        *fo = f;
        *fv = normal_vector(f, n);
    }
}

/// Final pass: the current normal becomes the stored one; separated contacts start afresh
/// (but for the state of a normal law with state, which its own pass has set).
fn frame_pass(m: &ContactModel, b: &BatchIn<'_>, o: &mut BatchOut<'_>) {
    let len = m.layout.len;
    if len == 0 {
        return;
    }
    if len == 1 && !m.layout.has_normal() && m.layout.normal_state.is_none() {
        // One value per contact (a step-aware normal-only model): zeroed where separated, by
        // a branch-free select (the same values as the general loop below); records back to
        // back by a contiguous loop, which vectorises (a strided one does not).
        if o.stride == 1 {
            for (h, &d) in o.history.iter_mut().zip(b.overlap) {
                *h = if d > 0.0 { *h } else { 0.0 };
            }
        } else {
            for (h, &d) in o.history.iter_mut().step_by(o.stride).zip(b.overlap) {
                *h = if d > 0.0 { *h } else { 0.0 };
            }
        }
        return;
    }
    let it = b
        .normal
        .iter()
        .zip(b.overlap)
        .zip(o.history.chunks_exact_mut(o.stride));
    for ((n, &d), h) in it {
        let Some(h) = h.get_mut(..len) else { continue };
        if d > 0.0 {
            if let Some(hn) = h.get_mut(0..3).filter(|_| m.layout.has_normal()) {
                hn.copy_from_slice(&n[..]);
            }
        } else {
            let keep = m.layout.normal_state.and_then(|at| h.get(at).copied());
            h.fill(0.0);
            if let (Some(at), Some(x)) = (m.layout.normal_state, keep)
                && let Some(slot) = h.get_mut(at)
            {
                *slot = x;
            }
        }
    }
}

/// The call-level checks (model, buffer lengths, dt): an error here is the whole call's.
fn check_call(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &BatchOut<'_>,
) -> Result<(), Error> {
    check_model(m)?;
    let n = inp.overlap.len();
    let len = m.layout.len;
    let needs_torque = needs_torque(m);
    let three = [inp.normal, inp.v1, inp.v2, inp.w1, inp.w2];
    let one = [inp.r1, inp.r2, inp.m1, inp.m2];
    let torque_ok = |t: &Option<&mut [[f64; 3]]>| match t {
        Some(t) => t.len() == n,
        None => !needs_torque,
    };
    if n == 0
        || three.iter().any(|a| a.len() != n)
        || one.iter().any(|a| a.len() != n)
        || out.f_n.len() != n
        || out.force.len() != n
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
    Ok(())
}

fn needs_torque(m: &ContactModel) -> bool {
    m.layout.has_normal() || m.rolling != select::ROLLING_NONE
}

/// Every state and history value valid? The status of the first bad state (states first, then
/// histories, as documented for the checked batch).
fn check_values(m: &ContactModel, inp: &BatchIn<'_>, out: &BatchOut<'_>) -> Result<(), Error> {
    let len = m.layout.len;
    let needs_torque = needs_torque(m);
    if !all_valid(inp, needs_torque) {
        for s in states(inp) {
            let s = if needs_torque {
                s
            } else {
                ContactState {
                    w1: [0.0; 3],
                    w2: [0.0; 3],
                    ..s
                }
            };
            check_state(&s)?;
        }
    }
    if len > 0 && !bits_finite(history_bits(out.history, out.stride, len)) {
        return Err(Error::NotFinite);
    }
    Ok(())
}

/// The stages over checked inputs.
fn compute(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<(), Error> {
    let pair = &m.normal;
    if let Some(at) = m.layout.normal_state {
        stateful_pass(m, inp, out, at);
    } else if let Some(at) = m.layout.step {
        dispatch(
            unclamped(pair.kernel),
            StepPass {
                m,
                inp,
                dt,
                o: out,
                at,
            },
        )
        .ok_or(Error::ContactModelInvalid)?;
    } else {
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
    }
    {
        for t in [out.torque1.as_deref_mut(), out.torque2.as_deref_mut()]
            .into_iter()
            .flatten()
        {
            t.fill([0.0; 3]);
        }
    }
    // One arm per registry line (`select`), each a monomorphised pass.
    select::tangential::dispatch!(m.tangential, |T| tangential_pass::<T>(m, inp, dt, out), {});
    select::rolling::dispatch!(m.rolling, |EPSD| rolling_pass::<EPSD>(m, inp, dt, out), {});
    select::twisting::dispatch!(m.twisting, |_Sds| twisting_pass(m, inp, dt, out), {});
    frame_pass(m, inp, out);
    Ok(())
}

/// Contacts whose histories [`compute_guarded`] saves on the stack at a time: 512 × 10
/// doubles = 40 KB of stack (within musl's 128 KB thread default). Blocks of 128 cost 10–12 %
/// streaming with Mindlin (short runs per array starve the hardware prefetcher); 512 cost 3–8 %
/// (`scripts/bench_contact_ab.sh`, docs/force.md).
const GUARD: usize = 512;

/// Block of a batch of at most this many contacts: a host calling the batch per neighbour
/// chunk should not zero 40 KB of stack per call for a few contacts.
const SHORT: usize = 32;

/// Every output of contact `i` (and its new history) finite?
fn contact_finite(o: &BatchOut<'_>, len: usize, i: usize) -> bool {
    let t = |t: &Option<&mut [[f64; 3]]>| t.as_ref().and_then(|t| t.get(i)).copied();
    let h = o
        .history
        .get(i * o.stride..i * o.stride + len)
        .unwrap_or(&[]);
    o.f_n.get(i).is_none_or(|f| f.is_finite())
        && o.force.get(i).is_none_or(|v| all_finite(v))
        && t(&o.torque1).is_none_or(|v| all_finite(&v))
        && t(&o.torque2).is_none_or(|v| all_finite(&v))
        && all_finite(h)
}

/// [`finite_bits`] of the first `len` values of each record of `stride` (values past `len`
/// are the host's: not judged). Branch-free, like [`finite_bits`]; one value per record (a
/// step-aware normal-only model) by a strided fold.
fn history_bits(history: &[f64], stride: usize, len: usize) -> u64 {
    if len == 0 {
        0
    } else if len == stride {
        finite_bits(history)
    } else if len == 1 {
        history
            .iter()
            .step_by(stride)
            .fold(0, |acc, x| acc | finite_bits(&[*x]))
    } else {
        history.chunks_exact(stride).fold(0, |acc, h| {
            acc | finite_bits(h.get(..len).unwrap_or(&[f64::NAN]))
        })
    }
}

/// Every output of the batch (and every new history value) finite? One OR reduction over all
/// arrays, no early exit: the common case costs a read of what was just written (in cache: the
/// guard runs block by block).
fn outputs_finite(o: &BatchOut<'_>, len: usize) -> bool {
    let torque =
        |t: &Option<&mut [[f64; 3]]>| t.as_ref().map_or(0, |t| finite_bits(t.as_flattened()));
    let history = history_bits(o.history, o.stride, len);
    bits_finite(
        finite_bits(o.f_n)
            | finite_bits(o.force.as_flattened())
            | torque(&o.torque1)
            | torque(&o.torque2)
            | history,
    )
}

/// [`compute`] with the overflow guard: a contact whose outputs or new history are not finite
/// (the inputs were checked, so its result overflowed) gets NaN outputs and its history as it
/// was; the index of the first such contact is returned. Bit for bit [`compute`] otherwise
/// (contacts are independent, so running them in groups changes no result). Blocks of
/// [`GUARD`] contacts, so the outputs are judged while still in cache.
fn compute_guarded(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<Option<usize>, Error> {
    let n = inp.overlap.len();
    if m.layout.len == 0 {
        // No history to keep: no stack buffer to fill.
        let mut first = None;
        for_blocks(inp, out, 0, GUARD, |a, ci, co| {
            compute(m, ci, dt, co)?;
            if !outputs_finite(co, 0) {
                first = first.or(poison_overflowed(co, 0, 0, &[])?.map(|i| a + i));
            }
            Ok(())
        })?;
        return Ok(first);
    }
    // The zeroed stack buffer is paid on every call: a short batch gets a short one.
    // A record of one or two doubles (a step-aware normal-only model) is saved in a buffer of
    // that width (value by value): the full-width buffer would cost a 48 KB fill per call.
    match (n <= SHORT, m.layout.len) {
        (true, 1) => guarded_with_history::<SHORT, 1>(m, inp, dt, out),
        (true, 2) => guarded_with_history::<SHORT, 2>(m, inp, dt, out),
        (true, _) => guarded_with_history::<SHORT, HISTORY_MAX>(m, inp, dt, out),
        (false, 1) => guarded_with_history::<GUARD, 1>(m, inp, dt, out),
        (false, 2) => guarded_with_history::<GUARD, 2>(m, inp, dt, out),
        (false, _) => guarded_with_history::<GUARD, HISTORY_MAX>(m, inp, dt, out),
    }
}

/// [`compute_guarded`] for a model with history, `G` contacts per block, records saved in a
/// buffer `W` doubles wide (`W` ≥ the model's history length).
fn guarded_with_history<const G: usize, const W: usize>(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<Option<usize>, Error> {
    let len = m.layout.len;
    // The block's history records copied aside in one memcpy (the records' tails past `len`
    // are the host's and come along unused); records wider than W, value by value.
    let mut saved = [[0.0; W]; G];
    let saved = saved.as_flattened_mut();
    let mut first = None;
    for_blocks(inp, out, len, G, |a, ci, co| {
        let stride = co.stride;
        let wide = stride > W;
        let rec = if wide { len } else { stride };
        if wide {
            for (s, h) in saved
                .chunks_exact_mut(len)
                .zip(co.history.chunks_exact(stride))
            {
                s.copy_from_slice(h.get(..len).ok_or(Error::BufferTooShort)?);
            }
        } else {
            let h = &*co.history;
            let s = saved.get_mut(..h.len()).ok_or(Error::BufferTooShort)?;
            s.copy_from_slice(h);
        }
        compute(m, ci, dt, co)?;
        if !outputs_finite(co, len) {
            let kept = saved
                .get(..co.f_n.len() * rec)
                .ok_or(Error::BufferTooShort)?;
            first = first.or(poison_overflowed(co, len, rec, kept)?.map(|i| a + i));
        }
        Ok(())
    })?;
    Ok(first)
}

/// Runs `f(a, in, out)` on the blocks [a, a + g) of the batch in order (the last one shorter),
/// outputs and history (records of `len` values) sliced to the block.
fn for_blocks(
    inp: &BatchIn<'_>,
    out: &mut BatchOut<'_>,
    len: usize,
    g: usize,
    mut f: impl FnMut(usize, &BatchIn<'_>, &mut BatchOut<'_>) -> Result<(), Error>,
) -> Result<(), Error> {
    let n = inp.overlap.len();
    let mut a = 0;
    while a < n {
        let b = n.min(a + g);
        let (Some(ci), Some(mut co)) = (sub_in(inp, a, b), sub_out(out, len, a, b)) else {
            return Err(Error::BufferTooShort);
        };
        f(a, &ci, &mut co)?;
        a = b;
    }
    Ok(())
}

/// The slow path of [`compute_guarded`]: each contact of the block whose outputs or first
/// `len` history values are not finite gets NaN outputs and those values back from `kept`
/// (records of `rec` values); returns the first such index.
fn poison_overflowed(
    co: &mut BatchOut<'_>,
    len: usize,
    rec: usize,
    kept: &[f64],
) -> Result<Option<usize>, Error> {
    let n = co.f_n.len();
    let stride = co.stride;
    let mut first = None;
    for i in 0..n {
        if contact_finite(co, len, i) {
            continue;
        }
        if len > 0 {
            let h = co.history.get_mut(i * stride..i * stride + len);
            let s = kept.get(i * rec..i * rec + len);
            let (Some(h), Some(s)) = (h, s) else {
                return Err(Error::BufferTooShort);
            };
            h.copy_from_slice(s);
        }
        poison(&mut sub_out(co, len, i, i + 1).ok_or(Error::BufferTooShort)?);
        first = first.or(Some(i));
    }
    Ok(first)
}

/// Forces of n contacts of one model (n = `inp.overlap.len()`); every slice must have the
/// documented length (checked). Nothing is written on error, except on `ResultRange`: then
/// the contacts whose result overflowed have NaN outputs and their history untouched, and
/// every other contact is computed.
pub fn contact_force_batch(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<(), Error> {
    check_call(m, inp, dt, out)?;
    check_values(m, inp, out)?;
    match compute_guarded(m, inp, dt, out)? {
        None => Ok(()),
        Some(_) => Err(Error::ResultRange),
    }
}

/// Contacts per block of [`contact_force_batch_fused`]: the inputs and outputs of one block
/// (≤ 330 bytes per contact for the largest model) stay in the L1/L2 cache between the check
/// and the stage passes, so each input is read from memory once.
pub(crate) const FUSED_BLOCK: usize = 1024;

/// Contacts `a..b` of a batch (a ≤ b ≤ n, else None).
fn sub_in<'a>(inp: &BatchIn<'a>, a: usize, b: usize) -> Option<BatchIn<'a>> {
    Some(BatchIn {
        normal: inp.normal.get(a..b)?,
        overlap: inp.overlap.get(a..b)?,
        v1: inp.v1.get(a..b)?,
        v2: inp.v2.get(a..b)?,
        w1: inp.w1.get(a..b)?,
        w2: inp.w2.get(a..b)?,
        r1: inp.r1.get(a..b)?,
        r2: inp.r2.get(a..b)?,
        m1: inp.m1.get(a..b)?,
        m2: inp.m2.get(a..b)?,
    })
}

/// Outputs of contacts `a..b` (history only when the model has one).
fn sub_out<'s>(out: &'s mut BatchOut<'_>, len: usize, a: usize, b: usize) -> Option<BatchOut<'s>> {
    let stride = out.stride;
    let torque = |t: &'s mut Option<&mut [[f64; 3]]>| match t {
        Some(t) => t.get_mut(a..b).map(Some),
        None => Some(None),
    };
    Some(BatchOut {
        f_n: out.f_n.get_mut(a..b)?,
        force: out.force.get_mut(a..b)?,
        torque1: torque(&mut out.torque1)?,
        torque2: torque(&mut out.torque2)?,
        history: if len > 0 {
            out.history.get_mut(a * stride..b * stride)?
        } else {
            &mut []
        },
        stride,
    })
}

/// NaN in every output of one contact (its history is left as it was).
fn poison(o: &mut BatchOut<'_>) {
    o.f_n.fill(f64::NAN);
    o.force.fill([f64::NAN; 3]);
    for t in [o.torque1.as_deref_mut(), o.torque2.as_deref_mut()]
        .into_iter()
        .flatten()
    {
        t.fill([f64::NAN; 3]);
    }
}

/// [`contact_force_batch`] reading each input once from memory: blocks of [`FUSED_BLOCK`]
/// contacts are checked and then computed while in cache. Call-level errors (model, lengths,
/// dt) leave everything untouched (`Err`). A contact with a bad state or history does not stop
/// the others: its outputs are NaN, its history is untouched, and the first such contact's
/// index and status are returned as `Ok(Some((i, e)))`; every other contact's outputs and
/// history are exactly those of [`contact_force_batch`] (bit for bit).
pub fn contact_force_batch_fused(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<Option<(usize, Error)>, Error> {
    check_call(m, inp, dt, out)?;
    if !needs_torque(m) && !m.step.on() && m.layout.normal_state.is_none() {
        return normal_only_fused(m, inp, dt, out);
    }
    let n = inp.overlap.len();
    let len = m.layout.len;
    let mut first = None;
    let mut a = 0;
    while a < n {
        let b = n.min(a + FUSED_BLOCK);
        let (Some(bi), Some(mut bo)) = (sub_in(inp, a, b), sub_out(out, len, a, b)) else {
            return Err(Error::BufferTooShort);
        };
        if check_values(m, &bi, &bo).is_ok() {
            let over = compute_guarded(m, &bi, dt, &mut bo)?;
            first = first.or(over.map(|i| (a + i, Error::ResultRange)));
        } else {
            // Contact by contact: the good ones exactly as in a batch, the bad ones poisoned.
            for i in a..b {
                let (Some(ci), Some(mut co)) = (sub_in(inp, i, i + 1), sub_out(out, len, i, i + 1))
                else {
                    return Err(Error::BufferTooShort);
                };
                match check_values(m, &ci, &co) {
                    Ok(()) => {
                        let over = compute_guarded(m, &ci, dt, &mut co)?;
                        first = first.or(over.map(|_| (i, Error::ResultRange)));
                    }
                    Err(e) => {
                        poison(&mut co);
                        first = first.or(Some((i, e)));
                    }
                }
            }
        }
        a = b;
    }
    Ok(first)
}

/// The fused batch of a normal-only model: one loop that checks and computes each contact;
/// only when a contact was bad, a second look for the statuses.
fn normal_only_fused(
    m: &ContactModel,
    inp: &BatchIn<'_>,
    dt: f64,
    out: &mut BatchOut<'_>,
) -> Result<Option<(usize, Error)>, Error> {
    let pair = &m.normal;
    let bad = dispatch(
        pair.kernel,
        NormalPassFused {
            c: pair.consts,
            inp,
            f_n: out.f_n,
            force: out.force,
        },
    )
    .ok_or(Error::ContactModelInvalid)?;
    for t in [out.torque1.as_deref_mut(), out.torque2.as_deref_mut()]
        .into_iter()
        .flatten()
    {
        t.fill([0.0; 3]);
    }
    if !bad {
        return Ok(None);
    }
    let mut first = None;
    for (i, s) in states(inp).enumerate() {
        if state_ok(s.n, s.overlap, s.v1, s.v2, s.r1, s.r2, s.m1, s.m2) {
            // A valid contact whose force overflowed.
            if !contact_finite(out, 0, i) {
                poison(&mut sub_out(out, 0, i, i + 1).ok_or(Error::BufferTooShort)?);
                first = first.or(Some((i, Error::ResultRange)));
            }
            continue;
        }
        let (Some(ci), Some(mut co)) = (sub_in(inp, i, i + 1), sub_out(out, 0, i, i + 1)) else {
            return Err(Error::BufferTooShort);
        };
        match check_values(m, &ci, &co) {
            Err(e) => {
                poison(&mut co);
                first = first.or(Some((i, e)));
            }
            // Not reachable (the two checks test the same conditions); recompute to be safe.
            Ok(()) => {
                if compute_guarded(m, &ci, dt, &mut co)?.is_some() {
                    first = first.or(Some((i, Error::ResultRange)));
                }
            }
        }
    }
    Ok(first)
}
