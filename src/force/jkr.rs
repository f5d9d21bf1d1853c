//! Adhesive JKR contact (Johnson, Kendall & Roberts 1971): the elastic contact of two spheres
//! whose surfaces stick with the work of adhesion w [J/m²]. A normal law with state
//! ([`super::stateful`]): one double per contact, whether the adhesive neck is formed.
//!
//! With E* the effective modulus, R* the effective radius and a the contact radius:
//!   δ(a) = a²/R* − √(2π w a/E*),     F(a) = 4E* a³/(3R*) − √(8π w E* a³)   (repulsive positive).
//! In the scales of the contact, a₀³ = 2π w R*²/E* (the contact radius at δ = 0), δ₀ = a₀²/R*,
//! F₀ = E* a₀³/R* = 2π w R* and u = √(a/a₀):
//!   δ = δ₀ (u⁴ − u),                 F = F₀ u³ ((4/3) u³ − 2).
//! dδ/du = δ₀ (4u³ − 1) vanishes at u_c = 4^{−1/3} (a_c³ = a₀³/16 = π w R*²/(8E*)): the
//! curve's overlap minimum δ_c = δ₀ (u_c⁴ − u_c) = −(3/4) u_c δ₀ = −(3/4)(π² w² R*/E*²)^{1/3}.
//! The stable branch is u ≥ u_c, where δ(u) increases: the law follows it. On it
//! * pull-off under load control: dF/du = 0 at u³ = 3/4, F = −(3/2) π w R* (the minimum force,
//!   reached at δ = −(1/4)(3/4)^{1/3} δ₀, inside the branch);
//! * breakage under displacement control: at δ_c, u³ = 1/4, F = −(5/6) π w R* (5/9 of pull-off);
//! * at δ = 0 (u = 1): F = −(4/3) π w R* (8/9 of pull-off).
//!
//! History (the state, one double): 0 = no neck (also the cleared history of a new contact),
//! 1 = neck formed. A contact forms at δ ≥ 0 (on approach: no force before), then follows the
//! branch, also at negative overlap, while δ ≥ δ_c; below δ_c (or NaN δ) it breaks: force 0,
//! state 0, and it forms again only at δ ≥ 0. The force is a function of (δ, state) alone.
//!
//! Energy: on the formed branch F = dU/dδ with the potential (0 at δ = 0)
//!   U(u) = F₀ δ₀ (P(u) + 3/10),  P(u) = (8/15) u¹⁰ − (4/3) u⁷ + (1/2) u⁴  (P(1) = −3/10),
//! so the branch creates and loses nothing ([`stored_energy`]). Formation at δ = 0 costs no
//! energy (the force jumps, U does not). Breakage drops the neck's potential at δ_c,
//!   W = U(u_c) = F₀ δ₀ (6 + u_c)/20 = (2π)^{5/3} (6 + 4^{−1/3})/20 (w⁵ R*⁴/E*²)^{1/3}
//!     ≈ 7.0922 (w⁵ R*⁴/E*²)^{1/3},
//! the whole loss of an undamped impact ([`dissipated`]): e = √(1 − v_s²/v²) above the sticking
//! speed v_s = √(2W/m*), sticking (no separation) below ([`restitution`], [`sticking_speed`]).
//!
//! Solving δ for u: with v = u − u_c ≥ 0 and σ = δ/δ₀ − s_c ≥ 0 (s_c = −(3/4) u_c), the branch
//! is v² (6u_c² + 4u_c v + v²) = σ, increasing and convex in v. From the upper bound
//! min(√(σ/(6u_c²)), √(u_c² + √σ) − u_c) (from 6u_c² v² ≤ σ and v²(v + 2u_c)² ≤ σ), four Newton
//! steps (monotone from above, written without cancellation) reach the root to within 2.1 ulp
//! of u times (1 + the condition number |s|/(u (4u³ − 1))) of the quartic, over s from s_c to
//! 10⁶⁰ (against 90-digit bisection; near δ_c the condition, ~1/√σ, is the f64 limit of
//! any method given δ). Plain arithmetic and `sqrt` only (the cube root of a₀ too:
//! [`cbrt_pos`]), so the C twin gives the same bits. The force is finite for δ/δ₀ < 1e200.
//!
//! Damping (optional): Hertz's dashpot with the JKR contact radius,
//! F_d = α √((4/3) E* m* a) vn, acting while the neck is formed, α calibrated for the
//! non-adhesive Hertz contact (the w → 0 limit, in which a → √(R* δ) and the law is Hertz's
//! damped law exactly). With adhesion the realised e is below that target and depends on the
//! impact speed (no closed form: documented approximation, as DMT). Never clamped (clamping
//! would remove the adhesion): only `EndCriterion::Overlap`.
//!
//! Constants: k = (4/3) E*, c = α √k (0 undamped), h = 2π w/E* [m] (a₀³ = h R*²;
//! F₀ = (3/4) k h R*).

use super::pair::{Consts, PairModel, Registered, SpecLaw, StateLaw};
use crate::powerlaw::alpha_from_e;
use crate::{EndCriterion, Error};

/// The JKR law of a contact specification (`DC_NORMAL_JKR`); its registry line gives it its
/// codes (`dc_pair.model` `DC_MODEL_JKR`, kernel `DC_KERNEL_JKR`: a law with state, so no
/// `dc_pair` path dispatches it).
pub(crate) struct Jkr;

impl SpecLaw for Jkr {
    const DOC: &'static str = "Normal law: adhesive JKR (Johnson, Kendall & Roberts 1971) with w = work_of_adhesion: the stable branch of d = a^2/R* - sqrt(2 pi w a/E*), F = 4 E* a^3/(3 R*) - sqrt(8 pi w E* a^3); the neck forms at d >= 0 and holds down to d_c = -(3/4)(pi^2 w^2 R* / E*^2)^(1/3) (force -(5/6) pi w R*), then breaks (loss W ~ 7.09 (w^5 R*^4/E*^2)^(1/3)); pull-off under load control -(3/2) pi w R*. One double of history (0 no neck, 1 formed). Optional Hertz dashpot with the JKR contact radius (e_n calibrated for w -> 0). Never clamped: requires DC_END_OVERLAP. Coulomb, rolling and twisting limits (while d > 0) on the adhesion-corrected load |F_n + 3 pi w R*|. Contact models only: no dc_pair constructor, no step-aware form (DC_ERR_STEP_UNSUPPORTED).";
    const MATERIALS: bool = true;
    const PARAMS: &'static [crate::laws::Param] = &[crate::laws::Param {
        field: "work_of_adhesion",
        unit: "J/m^2",
        doc: "work of adhesion w > 0 (pull-off force (3/2) pi w R*; w = 0 is DC_NORMAL_HERTZ)",
    }];
    const RESTITUTION: bool = true;
    const CLAMP: bool = false;
    const MODEL_DOC: &'static str = "dc_pair.model of a JKR pair (the normal law of a dc_contact_model built with DC_NORMAL_JKR). Its force needs per-contact state (whether the neck is formed), so it exists only inside a contact model: there is no dc_pair_* constructor, and every dc_pair path refuses its kernel (DC_ERR_PAIR_INVALID; NaN from the unchecked dc_normal_force).";
    fn build(
        s: &crate::contact::spec::ContactSpec,
        kf: f64,
        e_n: f64,
        crit: EndCriterion,
    ) -> Result<PairModel, Error> {
        jkr_from_factor(
            kf,
            crate::contact::spec::set(s.work_of_adhesion)?,
            e_n,
            crit,
        )
    }
}

impl StateLaw for Jkr {
    #[inline(always)]
    fn force(c: &Consts, d: f64, vn: f64, r: f64, m: f64, state: &mut f64) -> f64 {
        force_damped(c, d, vn, r, m, state)
    }
    #[inline(always)]
    fn dissipated(c: &Consts, r: f64, old: f64, new: f64) -> f64 {
        dissipated(c, r, old, new)
    }
    #[inline(always)]
    fn critical_load(c: &Consts, r: f64, f: f64) -> f64 {
        critical_load(c, r, f)
    }
    fn reach(c: &Consts, r: f64) -> f64 {
        -break_overlap(c, r)
    }
}

/// u_c = 4^{−1/3}, the branch's end (the f64 nearest).
const UC: f64 = 0.6299605249474366;
/// u_c² as a constant (rounded once).
const UC2: f64 = UC * UC;
/// s_c = −(3/4) u_c = δ_c/δ₀ (the f64 nearest).
const SC: f64 = -0.4724703937105774;
/// 6 u_c², 2·6 u_c², 2·4 u_c, 3·4 u_c (the f64 nearest of 6u_c², 4u_c; then exact or rounded once).
const A: f64 = 2.381101577952299;
const A2: f64 = 2.0 * A;
const B: f64 = 2.5198420997897464;
const B2: f64 = 2.0 * B;
const B3: f64 = 3.0 * B;
/// (6 + u_c)/20: W/(F₀ δ₀).
const WC: f64 = 0.33149802624737185;
/// Newton steps of the branch solve.
const NEWTON: usize = 4;

/// u = √(a/a₀) on the stable branch for s = δ/δ₀; s below s_c (or NaN) is taken as s_c.
#[inline(always)]
pub fn branch_root(s: f64) -> f64 {
    let s = if s > SC { s } else { SC };
    let sig = s - SC;
    let v1 = (sig / A).sqrt();
    let v2 = (UC2 + sig.sqrt()).sqrt() - UC;
    let mut v = if v1 < v2 { v1 } else { v2 };
    for _ in 0..NEWTON {
        // v − (h(v) − σ)/h'(v) = (v² (A + 2Bv + 3v²) + σ)/(v (2A + 3Bv + 4v²)).
        let num = v * v * (A + v * (B2 + 3.0 * v)) + sig;
        let den = v * (A2 + v * (B3 + 4.0 * v));
        v = if den > 0.0 { num / den } else { v };
    }
    UC + v
}

/// ∛x for a normal x in [2.2e-308, 1e300] (outside: no meaning) in plain arithmetic, so that
/// the C twin gives the same bits (libm's `cbrt` is not correctly rounded and Rust's own is:
/// they differ by an ulp): the exponent divided by 3 in the bits (the classic constant), then
/// three Halley steps y ← y (y³ + 2x)/(2y³ + x); within 1.6 ε of ∛x (tests/jkr_law.rs, over
/// the whole range).
#[inline(always)]
pub fn cbrt_pos(x: f64) -> f64 {
    let mut y = f64::from_bits(x.to_bits() / 3 + 0x2A9F_7893_782D_A1CE);
    for _ in 0..3 {
        let y3 = y * y * y;
        y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
    }
    y
}

/// (a₀, δ₀) of a contact of effective radius r: a₀ = ∛(h r²), δ₀ = a₀²/r; (0, 0) where h r²
/// is not in [2.2e-308, 1e300] (R* below ~1e-140 m or above ~1e140 m for any physical w/E*).
#[inline(always)]
fn scales(c: &Consts, r: f64) -> (f64, f64) {
    let x = c.h * r * r;
    if !(f64::MIN_POSITIVE..=1e300).contains(&x) {
        return (0.0, 0.0);
    }
    let a0 = cbrt_pos(x);
    (a0, a0 * a0 / r)
}

/// (F, a, u) at overlap d with the state updated (see the module's history); (0, 0, 0) when
/// there is no neck.
#[inline(always)]
fn contact(c: &Consts, d: f64, r: f64, state: &mut f64) -> (f64, f64, f64) {
    if !(d >= 0.0 || *state > 0.0) {
        *state = 0.0;
        return (0.0, 0.0, 0.0);
    }
    let (a0, d0) = scales(c, r);
    if !(d >= SC * d0 && d0 > 0.0) {
        *state = 0.0;
        return (0.0, 0.0, 0.0);
    }
    *state = 1.0;
    let u = branch_root(d / d0);
    let u3 = u * u * u;
    let f0 = 0.75 * c.k * c.h * r;
    (f0 * u3 * (4.0 / 3.0 * u3 - 2.0), a0 * u * u, u)
}

/// The elastic JKR force [N] at overlap `d` (any sign) for a contact whose neck state is
/// `*state` (0 none, 1 formed; updated): see the module's history. The undamped law's force.
#[inline(always)]
pub fn force(c: &Consts, d: f64, r: f64, state: &mut f64) -> f64 {
    contact(c, d, r, state).0
}

/// The force with the dashpot (the law's kernel; `vn` the overlap rate, positive while
/// compressing, `m` the effective mass): [`force`] + c √(m a) vn while the neck is formed
/// (c = 0: [`force`]'s bits).
#[inline(always)]
pub fn force_damped(c: &Consts, d: f64, vn: f64, r: f64, m: f64, state: &mut f64) -> f64 {
    let (f, a, _) = contact(c, d, r, state);
    if c.c > 0.0 {
        f + c.c * (m * a).sqrt() * vn
    } else {
        f
    }
}

/// The JKR contact radius a [m] at overlap `d` with neck state `state` (read only: 0 when the
/// neck would not be there after a step to d).
pub fn contact_radius(c: &Consts, d: f64, r: f64, state: f64) -> f64 {
    let mut s = state;
    contact(c, d, r, &mut s).1
}

/// The work W [J] lost when a formed neck breaks: U(u_c) = F₀ δ₀ (6 + u_c)/20, with
/// F₀ δ₀ = 2π w a₀² = (3/4) k h a₀².
#[inline(always)]
pub fn breakage_loss(c: &Consts, r: f64) -> f64 {
    let (a0, _) = scales(c, r);
    0.75 * c.k * c.h * (a0 * a0) * WC
}

/// The loss of a step that took the state from `old` to `new` [J] (the energy ledger's normal
/// term of the undamped law): W ([`breakage_loss`]) when the neck broke (old formed, new not),
/// else 0 (formation and the branch are lossless). The dashpot's work of the damped law is
/// not in it: the ledger adds (F − F_el) vn dt as for the stateless laws.
#[inline(always)]
pub fn dissipated(c: &Consts, r: f64, old: f64, new: f64) -> f64 {
    if old > 0.0 && !(new > 0.0) {
        breakage_loss(c, r)
    } else {
        0.0
    }
}

/// The neck's potential U [J] at overlap d with state `state` (after the step to d): the work
/// the branch returns on the way to δ = 0, F₀ δ₀ (P(u) + 3/10); 0 without a neck.
pub fn stored_energy(c: &Consts, d: f64, r: f64, state: f64) -> f64 {
    if !(state > 0.0) {
        return 0.0;
    }
    let mut s = state;
    let (_, a, u) = contact(c, d, r, &mut s);
    if !(s > 0.0) {
        return 0.0;
    }
    // a = a₀ u²: F₀ δ₀ = (3/4) k h a₀².
    let a0 = a / (u * u);
    let u3 = u * u * u;
    let p = u * u * u * u * (0.5 + u3 * (-4.0 / 3.0 + 8.0 / 15.0 * u3)) + 0.3;
    0.75 * c.k * c.h * (a0 * a0) * p
}

/// The pull-off force under load control [N]: −(3/2) π w R* (the branch's minimum force).
pub fn pull_off_force(c: &Consts, r: f64) -> f64 {
    -0.75 * (0.75 * c.k * c.h) * r
}

/// The critical load of the Coulomb limits (see [`super::pair::Law::critical_load`]):
/// |F + 2 F_po| with F_po = (3/2) π w R* (= −[`pull_off_force`]) and F the applied force
/// (dashpot included): |F + 3π w R*|, ≥ (3/2) π w R* on the undamped branch. The decision and
/// LAMMPS's convention: docs/force.md, "Friction with adhesion".
#[inline(always)]
pub fn critical_load(c: &Consts, r: f64, f: f64) -> f64 {
    (f + 2.0 * (0.75 * (0.75 * c.k * c.h) * r)).abs()
}

/// The overlap δ_c [m] (< 0) below which a formed neck breaks: −(3/4) u_c δ₀.
pub fn break_overlap(c: &Consts, r: f64) -> f64 {
    let (_, d0) = scales(c, r);
    SC * d0
}

/// The sticking speed v_s [m/s] of the undamped JKR law: ½ m* v_s² = W (the breakage loss),
/// from E* [Pa], R* [m], m* [kg] and w [J/m²] (all finite, > 0). A head-on impact slower than
/// v_s does not separate.
pub fn sticking_speed(e_star: f64, r: f64, m: f64, w: f64) -> Result<f64, Error> {
    let all = [e_star, r, m, w];
    if !all.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    if !all.iter().all(|&x| x > 0.0) {
        return Err(Error::NotPositive);
    }
    let tw = 2.0 * core::f64::consts::PI * w;
    let x = tw / e_star * r * r;
    if !(f64::MIN_POSITIVE..=1e300).contains(&x) {
        return Err(Error::ResultRange);
    }
    let a0 = cbrt_pos(x);
    let loss = tw * (a0 * a0) * WC;
    let v = (2.0 * loss / m).sqrt();
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Error::ResultRange)
    }
}

/// The restitution of a head-on impact of the undamped JKR law at speed v [m/s] with sticking
/// speed v_s [m/s] (both finite, ≥ 0): e = √(1 − v_s²/v²) for v > v_s, else 0 (sticking).
pub fn restitution(v: f64, v_s: f64) -> Result<f64, Error> {
    if !(v.is_finite() && v_s.is_finite()) {
        return Err(Error::NotFinite);
    }
    if !(v >= 0.0 && v_s >= 0.0) {
        return Err(Error::Negative);
    }
    if v <= v_s {
        return Ok(0.0);
    }
    let y = v_s / v;
    Ok(((1.0 - y) * (1.0 + y)).sqrt())
}

/// A JKR pair from kf = (4/3) E* (finite, > 0; checked by the caller), the work of adhesion
/// w > 0 [J/m²] (w = 0 is the Hertz law: `DC_NORMAL_HERTZ`) and the target restitution e of
/// the non-adhesive Hertz damping (1: undamped). Only `EndCriterion::Overlap` (no clamping:
/// it would remove the adhesion) is accepted.
pub fn jkr_from_factor(
    kf: f64,
    w: f64,
    e: f64,
    criterion: EndCriterion,
) -> Result<PairModel, Error> {
    if !w.is_finite() {
        return Err(Error::NotFinite);
    }
    if !(w > 0.0) {
        return Err(Error::NotPositive);
    }
    if criterion != EndCriterion::Overlap {
        return Err(Error::SpecModel);
    }
    let alpha = alpha_from_e(e, 1.5, criterion)?;
    let c = alpha * kf.sqrt();
    // 2π w/E* = 2π w · (4/3)/kf.
    let h = 2.0 * core::f64::consts::PI * w * (4.0 / 3.0) / kf;
    if !(c.is_finite() && h.is_finite() && h >= f64::MIN_POSITIVE) {
        return Err(Error::ResultRange);
    }
    Ok(PairModel {
        model: Jkr::MODEL,
        kernel: Jkr::STATE_KERNEL,
        criterion,
        p: 1.5,
        stiffness: kf,
        alpha,
        damping_a: 0.0,
        e,
        consts: Consts { k: kf, c, h },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_the_nearest_doubles() {
        // u_c³ = 1/4 and s_c = −(3/4) u_c to the rounding of the literals.
        assert!((UC * UC * UC - 0.25).abs() < 1e-16);
        assert!((SC + 0.75 * UC).abs() <= 1e-16);
        assert!((A - 6.0 * UC * UC).abs() <= 4e-16);
        assert!((B - 4.0 * UC).abs() <= 4e-16);
        assert!((WC - (6.0 + UC) / 20.0).abs() <= 1e-16);
    }
}
