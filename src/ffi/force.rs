//! Exports: per-contact normal-force kernels (pair constructors, scalar, checked, batch, 3D).

use super::status::*;
use super::{guard, parse_criterion, read_in, write_result};
use crate::force::batch::{normal_force_batch, normal_force_batch_fast};
use crate::force::geometry3d::{Sphere, normal_force_3d};
use crate::force::pair::{MODEL_HERTZ, MODEL_POWERLAW, MODEL_VISCOELASTIC};
use crate::force::registry::{needs, normal_force_raw, unclamped};
use crate::force::{Consts, PairModel, hertz, powerlaw, viscoelastic};
use crate::{EndCriterion, Error};

pub use super::codes::{
    DC_MODEL_DMT, DC_MODEL_ELASTIC_PLASTIC, DC_MODEL_HERTZ, DC_MODEL_POWERLAW,
    DC_MODEL_VISCOELASTIC,
};

// The generated C constants (src/ffi/codes.rs) must equal the core's of the pair constructors.
const _: () = assert!(
    DC_MODEL_POWERLAW == MODEL_POWERLAW
        && DC_MODEL_HERTZ == MODEL_HERTZ
        && DC_MODEL_VISCOELASTIC == MODEL_VISCOELASTIC
);

/// A calibrated contact model for one material pair (type pair): plain data, owned by the
/// caller, built once at set-up by a dc_pair_* constructor and then only read. Arrays of dc_pair
/// (one per type pair) are fine; copying one with memcpy or assignment is fine. Do not edit the
/// fields: `kernel`, `k`, `c`, `h` are what the force functions read, the others are for
/// inspection. A zero-filled dc_pair is invalid (DC_ERR_PAIR_INVALID / NaN force).
///
/// Sign conventions of every force function (per contact):
///  - overlap d [m]: positive when the bodies interpenetrate; d <= 0 (no contact) gives force 0.
///  - vn [m/s]: the rate dd/dt of the overlap, positive while compressing (approaching).
///  - r_eff = R1 R2/(R1 + R2) [m] and m_eff = m1 m2/(m1 + m2) [kg] of the two bodies.
///  - result: the normal force magnitude [N], positive = repulsive. Pairs built with
///    DC_END_FORCE clamp it to >= 0; pairs built with DC_END_OVERLAP return the raw value, which
///    turns negative (attractive) near the end of a damped contact.
///
/// Models (alpha calibrated exactly from e for the pair's criterion, speed independent):
///  - power law:    F = k d^p + alpha sqrt(m_eff k) d^((p-1)/2) vn      (r_eff ignored)
///  - Hertz:        same with p = 3/2 and k = (4/3) E* sqrt(r_eff) per contact
///  - viscoelastic: F = rho d^(3/2) + (3/2) A rho sqrt(d) vn, rho = (4/3) E* sqrt(r_eff),
///    m_eff ignored
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_pair {
    /// DC_MODEL_POWERLAW, DC_MODEL_HERTZ or DC_MODEL_VISCOELASTIC.
    pub model: i32,
    /// The specialised kernel chosen at construction (exponent path, damping, clamping).
    pub kernel: i32,
    /// DC_END_OVERLAP or DC_END_FORCE, as given to the constructor.
    pub criterion: i32,
    /// 1 if attractive forces are clamped to zero (criterion DC_END_FORCE), else 0.
    pub clamp: i32,
    /// Force-law exponent p (3/2 for Hertz and viscoelastic).
    pub p: f64,
    /// k [N m^-p] for power-law pairs; (4/3) E* [Pa] for Hertz and viscoelastic pairs.
    pub stiffness: f64,
    /// Tsuji damping coefficient alpha (0 for viscoelastic pairs and for e = 1).
    pub alpha: f64,
    /// Viscoelastic damping constant A [s] (0 for the other models).
    pub damping_a: f64,
    /// Target restitution e (NaN for viscoelastic pairs: their e depends on impact speed).
    pub e: f64,
    /// Kernel constant: elastic prefactor (k, or (4/3) E*).
    pub k: f64,
    /// Kernel constant: damping prefactor (alpha sqrt(k), alpha sqrt((4/3) E*), or (3/2) A).
    pub c: f64,
    /// Kernel constant: damping exponent (p - 1)/2.
    pub h: f64,
}

impl From<PairModel> for dc_pair {
    fn from(m: PairModel) -> Self {
        dc_pair {
            model: m.model,
            kernel: m.kernel,
            criterion: m.criterion.code(),
            clamp: i32::from(m.criterion == EndCriterion::Force),
            p: m.p,
            stiffness: m.stiffness,
            alpha: m.alpha,
            damping_a: m.damping_a,
            e: m.e,
            k: m.consts.k,
            c: m.consts.c,
            h: m.consts.h,
        }
    }
}

impl dc_pair {
    #[inline(always)]
    fn consts(&self) -> Consts {
        Consts {
            k: self.k,
            c: self.c,
            h: self.h,
        }
    }
}

/// Power-law Tsuji pair F = k d^p + alpha sqrt(m_eff k) d^((p-1)/2) vn with alpha calibrated so
/// that every collision of this pair has restitution `e` under `criterion` (exact, independent of
/// impact speed and mass). p = 1, 3/2 and 2 get dedicated kernels without pow; other p use one pow
/// per contact. e = 1 gives an undamped kernel that reads neither vn nor m_eff.
///
/// @param p          exponent, p >= 1 (1 linear spring-dashpot, 1.5 Hertz with fixed k).
/// @param k          stiffness > 0 [N m^-p].
/// @param e          target restitution, 0 < e <= 1.
/// @param criterion  DC_END_FORCE: attractive force clamped to zero, alpha from the force-zero
///                   criterion. DC_END_OVERLAP: no clamp, alpha from the overlap-zero criterion.
/// @param out        receives the pair on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_RESTITUTION_RANGE, DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `out` must be NULL or point to writable memory for one dc_pair.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_pair_powerlaw(
    p: f64,
    k: f64,
    e: f64,
    criterion: i32,
    out: *mut dc_pair,
) -> i32 {
    // SAFETY: forwarded caller contract on out.
    unsafe {
        write_result(out, || {
            Ok(powerlaw::powerlaw(p, k, e, parse_criterion(criterion)?)?.into())
        })
    }
}

/// Power-law Tsuji pair from its damping coefficient alpha >= 0 directly (for hosts that already
/// have alpha); `e` of the result is the restitution this alpha realises under `criterion`.
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_EXPONENT_RANGE,
///         DC_ERR_NOT_POSITIVE (k), DC_ERR_NEGATIVE (alpha), DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `out` must be NULL or point to writable memory for one dc_pair.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_pair_powerlaw_alpha(
    p: f64,
    k: f64,
    alpha: f64,
    criterion: i32,
    out: *mut dc_pair,
) -> i32 {
    // SAFETY: forwarded caller contract on out.
    unsafe {
        write_result(out, || {
            Ok(powerlaw::powerlaw_from_alpha(p, k, alpha, parse_criterion(criterion)?)?.into())
        })
    }
}

/// Linear spring-dashpot pair F = k d + alpha sqrt(m_eff k) vn (the power law with p = 1);
/// same contract as dc_pair_powerlaw.
///
/// # Safety
/// `out` must be NULL or point to writable memory for one dc_pair.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_pair_linear(k: f64, e: f64, criterion: i32, out: *mut dc_pair) -> i32 {
    // SAFETY: forwarded caller contract on out.
    unsafe {
        write_result(out, || {
            Ok(powerlaw::linear(k, e, parse_criterion(criterion)?)?.into())
        })
    }
}

/// Hertz pair of two materials: F = k d^(3/2) + alpha sqrt(m_eff k) d^(1/4) vn with
/// k = (4/3) E* sqrt(r_eff) per contact, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, and alpha calibrated
/// exactly for p = 3/2 so that every collision has restitution `e` under `criterion`.
/// Per contact: two square roots, no pow.
///
/// @param E1,E2      Young's moduli > 0 [Pa].
/// @param nu1,nu2    Poisson ratios in (-1, 0.5].
/// @param e          target restitution, 0 < e <= 1.
/// @param criterion  DC_END_FORCE (clamped, force-zero alpha) or DC_END_OVERLAP (no clamp).
/// @param out        receives the pair on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE (E, nu),
///         DC_ERR_RESTITUTION_RANGE, DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `out` must be NULL or point to writable memory for one dc_pair.
#[unsafe(no_mangle)]
#[allow(non_snake_case)]
pub unsafe extern "C" fn dc_pair_hertz(
    E1: f64,
    nu1: f64,
    E2: f64,
    nu2: f64,
    e: f64,
    criterion: i32,
    out: *mut dc_pair,
) -> i32 {
    // SAFETY: forwarded caller contract on out.
    unsafe {
        write_result(out, || {
            Ok(hertz::hertz(E1, nu1, E2, nu2, e, parse_criterion(criterion)?)?.into())
        })
    }
}

/// Viscoelastic Hertz pair (Brilliantov et al.): F = rho d^(3/2) + (3/2) A rho sqrt(d) vn with
/// rho = (4/3) E* sqrt(r_eff) per contact (for one material, rho = 2 E sqrt(r_eff)/(3(1-nu^2))).
/// The damping constant A [s] is given directly; e then depends on the impact speed, so there is
/// no calibration here. m_eff is not read. A = 0 gives the elastic Hertz kernel.
///
/// @param E1,E2,nu1,nu2  as for dc_pair_hertz.
/// @param A              damping constant >= 0 [s].
/// @param criterion      DC_END_FORCE clamps attractive force to zero; DC_END_OVERLAP does not.
/// @param out            receives the pair on success; untouched on error.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE (E, nu),
///         DC_ERR_NEGATIVE (A), DC_ERR_CRITERION, DC_ERR_RESULT_RANGE.
///
/// # Safety
/// `out` must be NULL or point to writable memory for one dc_pair.
#[unsafe(no_mangle)]
#[allow(non_snake_case)]
pub unsafe extern "C" fn dc_pair_viscoelastic(
    E1: f64,
    nu1: f64,
    E2: f64,
    nu2: f64,
    A: f64,
    criterion: i32,
    out: *mut dc_pair,
) -> i32 {
    // SAFETY: forwarded caller contract on out.
    unsafe {
        write_result(out, || {
            Ok(
                viscoelastic::viscoelastic(E1, nu1, E2, nu2, A, parse_criterion(criterion)?)?
                    .into(),
            )
        })
    }
}

/// Normal force [N] of one contact (sign conventions: see dc_pair). The hot path: no status, no
/// input checks beyond what keeps it defined.
///
/// Behaviour on every input (never undefined, never traps):
///  - overlap <= 0 or NaN: returns 0 (no contact).
///  - finite overlap > 0, vn, r_eff > 0, m_eff > 0 without overflow of the two force terms:
///    a finite force, equal to the model formula within a few ulp of |elastic| + |damping|.
///  - r_eff <= 0 (for Hertz/viscoelastic pairs) or m_eff < 0 (for damped Tsuji pairs), or NaN/inf
///    in vn, r_eff, m_eff: NaN or inf may result (clamped pairs turn NaN into 0). Use
///    dc_normal_force_checked to have these reported.
///  - pair NULL or not made by a dc_pair_* constructor: NaN.
///
/// @param pair     the pair model.
/// @param overlap  d [m], > 0 in contact.
/// @param vn       dd/dt [m/s], positive while compressing.
/// @param r_eff    effective radius [m]; ignored by power-law pairs (fixed k).
/// @param m_eff    effective mass [kg]; ignored by viscoelastic pairs and undamped pairs.
///
/// # Safety
/// `pair` must be NULL or point to a readable dc_pair.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_normal_force(
    pair: *const dc_pair,
    overlap: f64,
    vn: f64,
    r_eff: f64,
    m_eff: f64,
) -> f64 {
    // SAFETY: readability is the caller's contract; every bit pattern of dc_pair is valid.
    match unsafe { read_in(pair) } {
        Ok(p) => normal_force_raw(p.kernel, p.consts(), overlap, vn, r_eff, m_eff),
        Err(_) => f64::NAN,
    }
}

/// Checks a pair and the inputs it reads for dc_normal_force_checked.
fn checked_force(p: &dc_pair, overlap: f64, vn: f64, r_eff: f64, m_eff: f64) -> Result<f64, Error> {
    let (uses_vn, uses_r, uses_m) = needs(p.kernel).ok_or(Error::PairInvalid)?;
    let finite = |used: bool, x: f64| !used || x.is_finite();
    if !(overlap.is_finite()
        && finite(uses_vn, vn)
        && finite(uses_r, r_eff)
        && finite(uses_m, m_eff))
    {
        return Err(Error::NotFinite);
    }
    if (uses_r && !(r_eff > 0.0)) || (uses_m && !(m_eff > 0.0)) {
        return Err(Error::NotPositive);
    }
    // Overflow is judged on the unclamped force: a clamp would turn inf - inf = NaN into 0.
    let raw = normal_force_raw(unclamped(p.kernel), p.consts(), overlap, vn, r_eff, m_eff);
    if !raw.is_finite() {
        return Err(Error::ResultRange);
    }
    Ok(normal_force_raw(
        p.kernel,
        p.consts(),
        overlap,
        vn,
        r_eff,
        m_eff,
    ))
}

/// dc_normal_force with every check: the force is written to `force_out` only on success.
///
/// @return DC_OK, DC_ERR_NULL_POINTER (pair or force_out), DC_ERR_PAIR_INVALID,
///         DC_ERR_NOT_FINITE (overlap, or an input the pair reads), DC_ERR_NOT_POSITIVE (r_eff or
///         m_eff <= 0 where read), DC_ERR_RESULT_RANGE (a force term overflows, also when a
///         clamp would hide it).
///         overlap <= 0 is valid and gives 0.
///
/// # Safety
/// `pair` must be NULL or point to a readable dc_pair; `force_out` NULL or writable for a double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_normal_force_checked(
    pair: *const dc_pair,
    overlap: f64,
    vn: f64,
    r_eff: f64,
    m_eff: f64,
    force_out: *mut f64,
) -> i32 {
    if force_out.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    // SAFETY: readability is the caller's contract; any bit pattern is valid.
    let p = match unsafe { read_in(pair) } {
        Ok(p) => p,
        Err(s) => return s.code(),
    };
    // SAFETY: forwarded caller contract on force_out.
    unsafe { write_result(force_out, || checked_force(&p, overlap, vn, r_eff, m_eff)) }
}

/// Byte range of an array of n doubles, or None if misaligned or too large to address.
fn span(ptr: *const f64, n: usize) -> Option<(usize, usize)> {
    let bytes = n.checked_mul(core::mem::size_of::<f64>())?;
    if ptr.is_null() || !ptr.is_aligned() || bytes > isize::MAX as usize {
        return None;
    }
    let start = ptr as usize;
    Some((start, start.checked_add(bytes)?))
}

/// Structure-of-arrays normal forces of n contacts of one pair:
/// force_out[i] = dc_normal_force(pair, overlap[i], vn[i], r_eff[i], m_eff[i]) for i < n, with the
/// same per-value behaviour (no per-value checks: validate upstream or use the checked scalar).
/// One dispatch per call, then a loop the compiler vectorises. Group contacts by type pair.
///
/// Arrays the pair does not read may be NULL: vn and m_eff for undamped pairs, r_eff for
/// power-law pairs, m_eff for viscoelastic pairs.
///
/// @param n          number of contacts, > 0.
/// @param force_out  n doubles; must not overlap any input array (in-place is not supported).
/// @return DC_OK, DC_ERR_NULL_POINTER (pair, overlap, force_out, or an array the pair reads),
///         DC_ERR_PAIR_INVALID, DC_ERR_BUFFER_TOO_SHORT (n = 0),
///         DC_ERR_BUFFER_LAYOUT (a pointer misaligned for double, n too large, or force_out
///         overlapping an input). On error force_out is untouched.
///
/// # Safety
/// Every non-NULL array must be valid for n doubles (force_out writable); pair NULL or readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_normal_force_batch(
    pair: *const dc_pair,
    n: usize,
    overlap: *const f64,
    vn: *const f64,
    r_eff: *const f64,
    m_eff: *const f64,
    force_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract.
    unsafe {
        batch_with(
            normal_force_batch,
            pair,
            n,
            overlap,
            vn,
            r_eff,
            m_eff,
            force_out,
        )
    }
}

/// Fast structure-of-arrays normal forces: dc_normal_force_batch a few ulp from exact, for
/// speed (the trade is measured in docs/force.md). Same arguments, statuses and array rules
/// as dc_normal_force_batch.
///
/// - General p (1 < p <= 9, p not 3/2 or 2), overlaps in [2^-127, 2^129) m: the power from
///   correctly rounded tables of the exponent (built on a thread's first call with it, about
///   45 us; a thread keeps its last 8 exponents and rebuilds on every call if it cycles through
///   more), measured within 4 ulp of glibc's pow; other overlaps take the exact power. A pair
///   with p > 9 gets dc_normal_force_batch's bits.
/// - Damped Hertz and general p: elastic and damping terms summed by one fused multiply-add.
/// - Measured: the force within 5.64 ulp of (|elastic| + |damping|) of dc_normal_force_batch's
///   (tests assert 8; 1 for Hertz); every other pair gets dc_normal_force_batch's bits.
///
/// The same bits on every CPU and in every vector flavour (see dc_dispatch_level). In the
/// baseline x86-64 flavour (no FMA instruction: CPUs before 2013, or DEMCONTACT_DISPATCH=baseline)
/// each fused multiply-add calls the C library's fma: slower than dc_normal_force_batch there
/// (measured 20.7 against 13.8 ns/contact at p = 1.7); a host can ask dc_dispatch_level first.
///
/// # Safety
/// As dc_normal_force_batch.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_normal_force_batch_fast(
    pair: *const dc_pair,
    n: usize,
    overlap: *const f64,
    vn: *const f64,
    r_eff: *const f64,
    m_eff: *const f64,
    force_out: *mut f64,
) -> i32 {
    // SAFETY: forwarded caller contract.
    unsafe {
        batch_with(
            normal_force_batch_fast,
            pair,
            n,
            overlap,
            vn,
            r_eff,
            m_eff,
            force_out,
        )
    }
}

/// The batch's checks, then `f` over the arrays as slices.
///
/// # Safety
/// As dc_normal_force_batch.
#[allow(clippy::too_many_arguments)]
unsafe fn batch_with(
    f: BatchFn,
    pair: *const dc_pair,
    n: usize,
    overlap: *const f64,
    vn: *const f64,
    r_eff: *const f64,
    m_eff: *const f64,
    force_out: *mut f64,
) -> i32 {
    // SAFETY: readability is the caller's contract; any bit pattern is valid.
    let p = match unsafe { read_in(pair) } {
        Ok(p) => p,
        Err(s) => return s.code(),
    };
    if overlap.is_null() || force_out.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    let Some((uses_vn, uses_r, uses_m)) = needs(p.kernel) else {
        return DC_ERR_PAIR_INVALID;
    };
    // Arrays the kernel does not read are replaced by the overlap array (never read).
    let pick = |used: bool, a: *const f64| if used { a } else { overlap };
    let (vn, r_eff, m_eff) = (pick(uses_vn, vn), pick(uses_r, r_eff), pick(uses_m, m_eff));
    if vn.is_null() || r_eff.is_null() || m_eff.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    if n == 0 {
        return DC_ERR_BUFFER_TOO_SHORT;
    }
    let Some(out_span) = span(force_out, n) else {
        return DC_ERR_BUFFER_LAYOUT;
    };
    for a in [overlap, vn, r_eff, m_eff] {
        match span(a, n) {
            Some((s, e)) if e <= out_span.0 || s >= out_span.1 => {}
            _ => return DC_ERR_BUFFER_LAYOUT,
        }
    }
    let c = p.consts();
    let kernel = p.kernel;
    guard(|| {
        // SAFETY: each pointer is non-null, aligned, valid for n doubles (caller contract), the
        // byte size fits isize (checked), and the output does not overlap any input (checked),
        // so the shared and the exclusive slices never alias.
        let (d, vn, r, m, out) = unsafe {
            (
                core::slice::from_raw_parts(overlap, n),
                core::slice::from_raw_parts(vn, n),
                core::slice::from_raw_parts(r_eff, n),
                core::slice::from_raw_parts(m_eff, n),
                core::slice::from_raw_parts_mut(force_out, n),
            )
        };
        Ok(f(kernel, c, d, vn, r, m, out)?)
    })
}

/// A batch over slices ([`normal_force_batch`] or [`normal_force_batch_fast`]).
type BatchFn = fn(i32, Consts, &[f64], &[f64], &[f64], &[f64], &mut [f64]) -> Result<(), Error>;

/// Normal contact force between two spheres from their centres, velocities, radii and masses,
/// for codes without their own contact geometry (computed with nalgebra).
///
/// Conventions: n = (x1 - x2)/|x1 - x2| (unit vector from sphere 2 to sphere 1);
/// overlap d = R1 + R2 - |x1 - x2|; vn = (v2 - v1).n (positive while approaching);
/// r_eff = R1 R2/(R1 + R2), m_eff = m1 m2/(m1 + m2); force_out = F n is the force ON SPHERE 1
/// (repulsive: along n), sphere 2 receives -force_out. F as in dc_normal_force. Not in contact
/// (d <= 0): the zero vector and DC_OK.
///
/// @param x1,v1,x2,v2  3-vectors [m], [m/s].
/// @param R1,R2        radii > 0 [m] (finite: walls are not spheres).
/// @param m1,m2        masses > 0 [kg].
/// @param force_out    3 doubles, written only on success.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_PAIR_INVALID, DC_ERR_NOT_FINITE,
///         DC_ERR_NOT_POSITIVE (radius or mass <= 0, or overlapping spheres with coincident
///         centres), DC_ERR_RESULT_RANGE (distance or force overflows).
///
/// # Safety
/// Non-NULL vector pointers must be readable (force_out writable) for 3 doubles; pair NULL or
/// readable.
#[unsafe(no_mangle)]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub unsafe extern "C" fn dc_normal_force_3d(
    pair: *const dc_pair,
    x1: *const f64,
    v1: *const f64,
    R1: f64,
    m1: f64,
    x2: *const f64,
    v2: *const f64,
    R2: f64,
    m2: f64,
    force_out: *mut f64,
) -> i32 {
    // SAFETY: readability of each input is the caller's contract (read_in checks NULL).
    let read = || unsafe {
        let p = read_in(pair)?;
        let s1 = Sphere {
            x: read_in(x1.cast::<[f64; 3]>())?,
            v: read_in(v1.cast::<[f64; 3]>())?,
            r: R1,
            m: m1,
        };
        let s2 = Sphere {
            x: read_in(x2.cast::<[f64; 3]>())?,
            v: read_in(v2.cast::<[f64; 3]>())?,
            r: R2,
            m: m2,
        };
        Ok::<_, dc_status>((p, s1, s2))
    };
    let (p, s1, s2) = match read() {
        Ok(v) => v,
        Err(s) => return s.code(),
    };
    let model = PairModel {
        model: p.model,
        kernel: p.kernel,
        criterion: if p.clamp != 0 {
            EndCriterion::Force
        } else {
            EndCriterion::Overlap
        },
        p: p.p,
        stiffness: p.stiffness,
        alpha: p.alpha,
        damping_a: p.damping_a,
        e: p.e,
        consts: p.consts(),
    };
    // SAFETY: forwarded caller contract on force_out (null checked inside).
    unsafe {
        write_result(force_out.cast::<[f64; 3]>(), || {
            normal_force_3d(&model, &s1, &s2)
        })
    }
}
