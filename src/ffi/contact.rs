//! Exports: full contact (normal, tangential, rolling, twisting) with caller-owned history.

pub use super::codes::*;
use super::status::*;
use super::{dc_status, guard, read_in, write_result};
use crate::contact::batch::{BatchIn, BatchOut, contact_force_batch, contact_force_batch_fused};
use crate::contact::energy::ContactEnergy;
use crate::contact::evaluate::{
    check_model_parts, contact_force_checked_model, contact_force_energy_checked_model,
};
use crate::contact::model::{HISTORY_MAX, Layout, select};
use crate::contact::spec::{ContactSpec, contact_model};
use crate::contact::step_exact::{StepExact, set_step};
use crate::contact::{ContactForce, ContactModel, ContactState};
use crate::force::pair::{MODEL_HERTZ, MODEL_POWERLAW};
use crate::force::{Consts, PairModel};
use crate::{EndCriterion, Error};

use super::force::dc_pair;

/// Version of dc_contact_spec this library reads (dc_contact_spec_init sets it).
pub const DC_CONTACT_SPEC_VERSION: u32 = 1;
/// Doubles of history per contact for the largest contact model
/// (dc_contact_history_len gives the exact, usually smaller, figure of one model). A normal law
/// with state (DC_NORMAL_ELASTIC_PLASTIC, DC_NORMAL_JKR) adds one double; it has no step-aware
/// form, so its double and the step-aware one never meet and 12 still bounds every model.
pub const DC_CONTACT_HISTORY_MAX: usize = 12;

const _: () = assert!(DC_CONTACT_HISTORY_MAX == HISTORY_MAX);

/// What a contact model is made of, named field by field: fill it with dc_contact_spec_init,
/// then set the fields your scene needs (by name: never positionally), then call
/// dc_contact_model_init. Parameters of sub-models you do not choose are ignored; a parameter a
/// chosen sub-model needs that is left unset (NaN) gives DC_ERR_SPEC_UNSET.
///
/// Versioned: `version` and `size` (set by dc_contact_spec_init) let later library versions
/// append fields without breaking callers compiled against this one.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types, non_snake_case)]
pub struct dc_contact_spec {
    /// DC_CONTACT_SPEC_VERSION.
    pub version: u32,
    /// sizeof(dc_contact_spec) as the caller compiled it.
    pub size: u32,
    /// DC_NORMAL_* (required: no default).
    pub normal: i32,
    /// DC_DAMPING_NONE (default) or DC_DAMPING_RESTITUTION (reads e_n). Viscoelastic: NONE only.
    pub damping: i32,
    /// DC_END_FORCE (default: attractive normal force clamped to zero) or DC_END_OVERLAP.
    pub criterion: i32,
    /// DC_TANGENTIAL_* (default NONE).
    pub tangential: i32,
    /// DC_ROLLING_* (default NONE).
    pub rolling: i32,
    /// DC_TWISTING_* (default NONE).
    pub twisting: i32,
    /// Young's modulus of body 1 [Pa], > 0; +INFINITY for a rigid body (Hertz, viscoelastic,
    /// Mindlin). Not both bodies rigid.
    pub E1: f64,
    /// Poisson ratio of body 1, in (-1, 0.5].
    pub nu1: f64,
    /// Young's modulus of body 2 [Pa] (+INFINITY: rigid, e.g. a wall).
    pub E2: f64,
    /// Poisson ratio of body 2.
    pub nu2: f64,
    /// Exponent p >= 1 of DC_NORMAL_POWERLAW.
    pub p: f64,
    /// Stiffness k_n > 0 of DC_NORMAL_POWERLAW [N m^-p] and DC_NORMAL_LINEAR [N/m].
    pub k_n: f64,
    /// Target normal restitution in (0, 1] (DC_DAMPING_RESTITUTION).
    pub e_n: f64,
    /// Viscoelastic damping constant A >= 0 [s] (DC_NORMAL_VISCOELASTIC).
    pub visco_A: f64,
    /// Sliding friction coefficient mu >= 0 (any tangential law).
    pub mu: f64,
    /// Tangential stiffness k_t > 0 [N/m] (DC_TANGENTIAL_LINEAR).
    pub k_t: f64,
    /// Target tangential restitution in (0, 1] in the sticking regime (default 1: undamped).
    pub e_t: f64,
    /// Rolling friction coefficient mu_r >= 0 (torque limit mu_r R* |Fn|).
    pub mu_r: f64,
    /// Rolling stiffness k_r >= 0 [N m/rad] (EPSD); 0 (default) = Ai et al.'s rule
    /// k_r = 2.25 k_n mu_r^2 R*^2 with k_n the normal law's elastic tangent stiffness.
    pub k_r: f64,
    /// Rolling damping ratio eta_r >= 0 (EPSD; default 0).
    pub eta_r: f64,
    /// Twisting friction coefficient mu_tw >= 0 [m] (torque limit mu_tw |Fn|).
    pub mu_tw: f64,
    /// Twisting stiffness k_tw > 0 [N m/rad].
    pub k_tw: f64,
    /// Twisting damping ratio eta_tw >= 0 (default 0).
    pub eta_tw: f64,
    /// Inertia factor kappa = I/(m r^2) of the bodies, in (0, 1] (default 0.4: solid spheres);
    /// enters only the damping calibrations (tangential mass m_t = kappa/(1 + kappa) m*).
    pub inertia_factor: f64,
    /// Work of adhesion w >= 0 [J/m^2] (DC_NORMAL_DMT: pull-off force 2 pi w R*).
    pub work_of_adhesion: f64,
    /// Limiting contact pressure p_y > 0 [Pa] (DC_NORMAL_ELASTIC_PLASTIC). Appended: a caller
    /// compiled without it passes the shorter size, and reads as unset (NaN).
    pub yield_pressure: f64,
}

/// sizeof(dc_contact_spec) before `yield_pressure` was appended (still accepted).
const SPEC_SIZE_V1_DMT: usize = core::mem::offset_of!(dc_contact_spec, yield_pressure);

/// The one list of the fields `dc_contact_spec` shares with [`ContactSpec`], as
/// `c_name <=> rust_name`, from which both conversions are generated (C → Rust: what
/// dc_contact_model_init reads; Rust → C: the defaults dc_contact_spec_init writes). Both are
/// exhaustive struct literals and the Rust → C one an exhaustive destructuring, so a field added
/// to either struct and not listed here (or listed and missing from one) does not compile. The
/// fields not shared: `version`, `size` (C only) and `carry` (Rust only; set on the model with
/// dc_contact_model_set_carry, the C layout being fixed).
macro_rules! spec_fields {
    ($($c:ident <=> $r:ident),* $(,)?) => {
        impl From<&dc_contact_spec> for ContactSpec {
            fn from(s: &dc_contact_spec) -> Self {
                ContactSpec {
                    $($r: s.$c,)*
                    carry: select::CARRY_ROTATE,
                }
            }
        }

        impl dc_contact_spec {
            /// The C form of `d` (its `carry` has no C field), with this library's version and
            /// size.
            fn of_spec(d: &ContactSpec) -> dc_contact_spec {
                let ContactSpec { $($r,)* carry: _ } = *d;
                dc_contact_spec {
                    version: DC_CONTACT_SPEC_VERSION,
                    size: core::mem::size_of::<dc_contact_spec>() as u32,
                    $($c: $r,)*
                }
            }
        }
    };
}

spec_fields! {
    normal <=> normal,
    damping <=> damping,
    criterion <=> criterion,
    tangential <=> tangential,
    rolling <=> rolling,
    twisting <=> twisting,
    E1 <=> e1,
    nu1 <=> nu1,
    E2 <=> e2,
    nu2 <=> nu2,
    p <=> p,
    k_n <=> k_n,
    e_n <=> e_n,
    visco_A <=> visco_a,
    mu <=> mu,
    k_t <=> k_t,
    e_t <=> e_t,
    mu_r <=> mu_r,
    k_r <=> k_r,
    eta_r <=> eta_r,
    mu_tw <=> mu_tw,
    k_tw <=> k_tw,
    eta_tw <=> eta_tw,
    inertia_factor <=> inertia_factor,
    work_of_adhesion <=> work_of_adhesion,
    yield_pressure <=> yield_pressure,
}

/// A composed contact model for one material pair: plain data built by dc_contact_model_init,
/// then only read (copy it freely; keep one per type pair). Do not edit the fields: they are
/// checked on every call (DC_ERR_CONTACT_MODEL_INVALID). A zero-filled one is invalid.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_contact_model {
    /// Set by dc_contact_model_init.
    pub magic: u32,
    /// Doubles of history per contact (as dc_contact_history_len).
    pub history_len: u32,
    /// DC_TANGENTIAL_* chosen.
    pub tangential: i32,
    /// DC_ROLLING_* chosen.
    pub rolling: i32,
    /// DC_TWISTING_* chosen.
    pub twisting: i32,
    /// DC_CARRY_* (DC_CARRY_ROTATE from dc_contact_model_init; change it with
    /// dc_contact_model_set_carry). This was `reserved_i` (always 0) before the projection carry.
    pub carry: i32,
    /// The normal law (usable on its own with dc_normal_force*).
    pub normal: dc_pair,
    /// Friction coefficient mu.
    pub mu: f64,
    /// k_t [N/m] (linear) or 8 G* [Pa] (both Mindlin laws, k_t = 8 G* sqrt(R* d)).
    pub kt: f64,
    /// Tangential damping ratio zeta_t from e_t.
    pub zeta_t: f64,
    /// Inertia factor kappa.
    pub kappa: f64,
    /// Rolling friction coefficient.
    pub mu_r: f64,
    /// Rolling stiffness (0: Ai's rule).
    pub k_r: f64,
    /// Rolling damping ratio.
    pub eta_r: f64,
    /// Twisting friction coefficient [m].
    pub mu_tw: f64,
    /// Twisting stiffness.
    pub k_tw: f64,
    /// Twisting damping ratio.
    pub eta_tw: f64,
    /// The step-aware damping set by dc_contact_model_set_step: reserved[0] = dt over the
    /// prefactor of the elastic contact duration t_H (0: not step-aware), reserved[1..6] the
    /// coefficients of the damping factor R(dt/t_H). All 0 from dc_contact_model_init.
    pub reserved: [f64; 6],
}

const MAGIC: u32 = 0x4443_4d31;

/// The one list of the fields `dc_contact_model` shares with [`ContactModel`] (same names), in
/// two groups: the selectors (`i32`) and the constants (`f64`) the model checks read, in the
/// order of [`check_model_parts`]. From it: both conversions and the checks' arrays of the C
/// model. The fields not shared are written out here once: C `magic`, `history_len`
/// (= `layout.len`), `normal` (a `dc_pair`) and `reserved` (the step-aware damping) against
/// Rust `normal` (a `PairModel`), `layout` and `step`. Exhaustive struct literals and an
/// exhaustive destructuring: a field added to either struct and not listed does not compile,
/// and one added to a group changes the arrays' length, which [`check_model_parts`] fixes.
macro_rules! model_fields {
    (sel [$($s:ident),* $(,)?] consts [$($f:ident),* $(,)?] $(,)?) => {
        impl From<ContactModel> for dc_contact_model {
            fn from(m: ContactModel) -> Self {
                let ContactModel {
                    normal,
                    layout,
                    step,
                    $($s,)*
                    $($f,)*
                } = m;
                dc_contact_model {
                    magic: MAGIC,
                    history_len: layout.len as u32,
                    normal: normal.into(),
                    reserved: {
                        let [c0, c1, c2, c3, c4] = step.coef;
                        [step.scale, c0, c1, c2, c3, c4]
                    },
                    $($s,)*
                    $($f,)*
                }
            }
        }

        impl dc_contact_model {
            /// The selectors and constants of the model checks ([`check_model_parts`]) as read
            /// from the caller's struct, after the normal law's k, c, h.
            #[inline(always)]
            fn check_parts(&self, k: f64, c: f64, h: f64) -> ([i32; 4], [f64; 13]) {
                ([$(self.$s,)*], [k, c, h, $(self.$f,)*])
            }

            /// The core model of these fields and the given non-shared ones.
            #[inline(always)]
            fn core(&self, normal: PairModel, layout: Layout, step: StepExact) -> ContactModel {
                ContactModel {
                    normal,
                    layout,
                    step,
                    $($s: self.$s,)*
                    $($f: self.$f,)*
                }
            }
        }
    };
}

model_fields! {
    sel [tangential, rolling, twisting, carry]
    consts [mu, kt, zeta_t, kappa, mu_r, k_r, eta_r, mu_tw, k_tw, eta_tw]
}

/// The core model of a C model, checked: structure here, values by the core's model checks
/// ([`check_model_parts`], the checks of [`crate::contact::evaluate::check_model`]).
fn model_of(m: &dc_contact_model) -> Result<ContactModel, Error> {
    let [scale, c0, c1, c2, c3, c4] = m.reserved;
    let step = StepExact {
        scale,
        coef: [c0, c1, c2, c3, c4],
    };
    let step_on = scale.to_bits() != 0;
    let p = &m.normal;
    let layout = Layout::of_model(
        m.tangential,
        m.rolling,
        m.twisting,
        crate::force::stateful::has_state(p.kernel),
        step_on,
    );
    let criterion = match (p.criterion, p.clamp) {
        (0, 0) => EndCriterion::Overlap,
        (1, 1) => EndCriterion::Force,
        _ => return Err(Error::ContactModelInvalid),
    };
    let step_ok = if step_on {
        // Set by dc_contact_model_set_step: a damped Tsuji law, finite coefficients.
        step.on()
            && m.reserved.iter().all(|x| x.is_finite())
            && matches!(p.model, MODEL_POWERLAW | MODEL_HERTZ)
            && p.alpha > 0.0
    } else {
        m.reserved.iter().all(|x| x.to_bits() == 0)
    };
    if m.magic != MAGIC || m.history_len as usize != layout.len || !step_ok {
        return Err(Error::ContactModelInvalid);
    }
    // The core's model checks, on the caller's fields as read (the core model built below is
    // then not checked again: see contact_force_checked_model).
    let (sel, consts) = m.check_parts(p.k, p.c, p.h);
    check_model_parts(p.kernel, sel, &consts, layout, step_on)?;
    let normal = PairModel {
        model: p.model,
        kernel: p.kernel,
        criterion,
        p: p.p,
        stiffness: p.stiffness,
        alpha: p.alpha,
        damping_a: p.damping_a,
        e: p.e,
        consts: Consts {
            k: p.k,
            c: p.c,
            h: p.h,
        },
    };
    Ok(m.core(normal, layout, step))
}

/// One contact's bodies. n is the unit normal pointing from body 2 to body 1; overlap > 0 in
/// contact (<= 0: no force, and the history is reset to zero). The contact point is at
/// a_i = r_i - overlap/2 from each centre. A plane wall is body 2 with r2 = +INFINITY (its
/// mass m2 may be +INFINITY: fixed): v2 is then the wall's velocity at the contact point, w2
/// its angular velocity (it only turns the spring with the wall; zero for a fixed wall), and
/// torque2 is 0. A fixed sphere: m2 = +INFINITY with finite r2.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_contact_state {
    /// Unit normal from body 2 to body 1 (| |n|^2 - 1 | <= 1e-6).
    pub n: [f64; 3],
    /// Overlap [m], > 0 in contact.
    pub overlap: f64,
    /// Centre velocity of body 1 [m/s].
    pub v1: [f64; 3],
    /// Centre velocity of body 2 [m/s] (wall: its velocity at the contact point).
    pub v2: [f64; 3],
    /// Angular velocity of body 1 [rad/s].
    pub w1: [f64; 3],
    /// Angular velocity of body 2 [rad/s].
    pub w2: [f64; 3],
    /// Radius of body 1 [m], finite > 0.
    pub r1: f64,
    /// Radius of body 2 [m], > 0 (+INFINITY: plane wall).
    pub r2: f64,
    /// Mass of body 1 [kg], finite > 0.
    pub m1: f64,
    /// Mass of body 2 [kg], > 0 (+INFINITY: fixed body or wall).
    pub m2: f64,
}

impl From<&dc_contact_state> for ContactState {
    fn from(s: &dc_contact_state) -> Self {
        ContactState {
            n: s.n,
            overlap: s.overlap,
            v1: s.v1,
            v2: s.v2,
            w1: s.w1,
            w2: s.w2,
            r1: s.r1,
            r2: s.r2,
            m1: s.m1,
            m2: s.m2,
        }
    }
}

/// Forces and torques of one contact.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_contact_result {
    /// Total force on body 1 [N] (body 2 receives -force).
    pub force: [f64; 3],
    /// Torque on body 1 [N m] (tangential force about its centre + rolling + twisting).
    pub torque1: [f64; 3],
    /// Torque on body 2 [N m] (0 for a wall).
    pub torque2: [f64; 3],
    /// Normal force [N] as applied (positive repulsive; >= 0 when clamped).
    pub f_n: f64,
    /// Tangential force on body 1 [N].
    pub ft: [f64; 3],
    /// 1 if the Coulomb limit was reached this step, else 0.
    pub sliding: i32,
    /// 1 if the rolling or twisting limit was reached (or the constant rolling torque acts).
    pub rolling_sliding: i32,
}

impl From<ContactForce> for dc_contact_result {
    fn from(f: ContactForce) -> Self {
        dc_contact_result {
            force: f.force,
            torque1: f.torque1,
            torque2: f.torque2,
            f_n: f.fn_,
            ft: f.ft,
            sliding: i32::from(f.sliding),
            rolling_sliding: i32::from(f.rolling_sliding),
        }
    }
}

/// The energy ledger of one contact step [J] (dc_contact_force_energy): what the dashpots and
/// the slips removed during the step, and the elastic energy left in the history springs, so
/// that a host can check that nothing is created: over a whole contact (springs empty and
/// overlap zero at both ends) the kinetic energy change is -(sum of `dissipated`) to the
/// integrator's error. Spring energies are |S|^2/(2k) of the stored force or torque S; the work
/// of a spring step is the trapezoid of its force before and after over the increment; the
/// energy a law creates is not counted (DC_TANGENTIAL_MINDLIN's gain, EPSD rolling under Ai's
/// stiffness rule), so it shows up as a gain. Definitions: docs/force.md.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(non_camel_case_types)]
pub struct dc_contact_energy {
    /// Everything removed this step: the sum of the damping and slip terms.
    pub dissipated: f64,
    /// Work of the normal dashpot, (F_n - F_el) vn dt.
    pub normal_damping: f64,
    /// Work of the tangential dashpot, c_t |v_t|^2 dt.
    pub tangential_damping: f64,
    /// Work of the tangential slip (and, DC_TANGENTIAL_MINDLIN_RESCALE, the loss of its force
    /// history when the contact radius changes; when the contact ends, the energy its reset
    /// spring held).
    pub tangential_slip: f64,
    /// Elastic energy left in the tangential spring.
    pub tangential_elastic: f64,
    /// Work of the EPSD rolling dashpot.
    pub rolling_damping: f64,
    /// Work of the rolling slip (EPSD at its limit, or the constant rolling torque).
    pub rolling_slip: f64,
    /// Elastic energy left in the EPSD rolling spring.
    pub rolling_elastic: f64,
    /// Work of the twisting dashpot.
    pub twisting_damping: f64,
    /// Work of the twisting slip.
    pub twisting_slip: f64,
    /// Elastic energy left in the twisting spring.
    pub twisting_elastic: f64,
}

impl From<ContactEnergy> for dc_contact_energy {
    fn from(e: ContactEnergy) -> Self {
        dc_contact_energy {
            dissipated: e.dissipated,
            normal_damping: e.normal_damping,
            tangential_damping: e.tangential_damping,
            tangential_slip: e.tangential_slip,
            tangential_elastic: e.tangential_elastic,
            rolling_damping: e.rolling_damping,
            rolling_slip: e.rolling_slip,
            rolling_elastic: e.rolling_elastic,
            twisting_damping: e.twisting_damping,
            twisting_slip: e.twisting_slip,
            twisting_elastic: e.twisting_elastic,
        }
    }
}

/// Fills a dc_contact_spec with its version, size and defaults: no normal law yet (you must
/// set `normal`), DC_DAMPING_NONE, DC_END_FORCE, no tangential/rolling/twisting, every
/// parameter unset (NaN) except e_t = 1, k_r = 0, eta_r = eta_tw = 0, inertia_factor = 0.4.
///
/// @return DC_OK or DC_ERR_NULL_POINTER.
///
/// # Safety
/// `spec` must be NULL or point to writable memory for one dc_contact_spec.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_spec_init(spec: *mut dc_contact_spec) -> i32 {
    // SAFETY: forwarded caller contract on spec.
    unsafe { write_result(spec, || Ok(dc_contact_spec::from_default())) }
}

impl dc_contact_spec {
    /// What dc_contact_spec_init writes.
    fn from_default() -> dc_contact_spec {
        dc_contact_spec::of_spec(&ContactSpec::default())
    }
}

/// Builds a contact model from a spec (once per material pair, at set-up): validates every
/// parameter the chosen sub-models read and calibrates the damping (normal: exact for the
/// criterion; tangential: from e_t, see docs/force.md).
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_SPEC_VERSION (version != DC_CONTACT_SPEC_VERSION or
///         size neither sizeof(dc_contact_spec) nor the size before yield_pressure was appended,
///         whose callers read as leaving it unset), DC_ERR_SPEC_MODEL (unknown selector,
///         viscoelastic or elastic-plastic with restitution damping, inertia_factor > 1),
///         DC_ERR_SPEC_UNSET, DC_ERR_CRITERION,
///         DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_NEGATIVE, DC_ERR_RESTITUTION_RANGE,
///         DC_ERR_EXPONENT_RANGE, DC_ERR_RESULT_RANGE. `out` is untouched on error.
///
/// # Safety
/// `spec` NULL or readable for its `size` bytes (at least the version and size fields); `out`
/// NULL or writable for one dc_contact_model.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_model_init(
    spec: *const dc_contact_spec,
    out: *mut dc_contact_model,
) -> i32 {
    if spec.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    // SAFETY: non-null; the two leading u32 fields are readable per the caller contract.
    let (version, size) = unsafe {
        let head = spec.cast::<[u32; 2]>().read_unaligned();
        (head[0], head[1])
    };
    let size = size as usize;
    let full = core::mem::size_of::<dc_contact_spec>();
    if version != DC_CONTACT_SPEC_VERSION || !(size == full || size == SPEC_SIZE_V1_DMT) {
        return if out.is_null() {
            DC_ERR_NULL_POINTER
        } else {
            DC_ERR_SPEC_VERSION
        };
    }
    // The caller's fields (`size` bytes), the ones appended after its version unset (NaN).
    let mut s = dc_contact_spec {
        yield_pressure: f64::NAN,
        ..dc_contact_spec::from_default()
    };
    // SAFETY: the caller declared `size` (<= sizeof, checked) bytes readable; `s` is a plain
    // struct of integers and doubles with no padding, so any bytes form a valid value.
    unsafe {
        core::ptr::copy_nonoverlapping(
            spec.cast::<u8>(),
            core::ptr::from_mut(&mut s).cast::<u8>(),
            size,
        );
    }
    // SAFETY: forwarded caller contract on out.
    unsafe { write_result(out, || Ok(contact_model(&ContactSpec::from(&s))?.into())) }
}

/// Chooses how the model's history springs follow the contact frame: DC_CARRY_ROTATE (what
/// dc_contact_model_init gives: objective) or DC_CARRY_PROJECT (LAMMPS' projection and
/// rescale: cheaper, not objective about the normal). The history layout and length do not
/// change, so a run may switch between the two. Call it at set-up, like dc_contact_model_init.
/// The rotation resolves spins up to |w1 + w2| dt/2 < 2^20 rad in one step; a step beyond it
/// (no physical spin) takes the projection alone, as a normal turned by more than 120 degrees
/// does.
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID (not a valid model),
///         DC_ERR_SPEC_MODEL (unknown carry). `model` is untouched on error.
///
/// # Safety
/// `model` NULL or readable and writable for one dc_contact_model.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_model_set_carry(
    model: *mut dc_contact_model,
    carry: i32,
) -> i32 {
    // SAFETY: forwarded caller contract on model (read by value, NULL checked).
    let m = match unsafe { read_in(model.cast_const()) } {
        Ok(m) => m,
        Err(s) => return s.code(),
    };
    // SAFETY: forwarded caller contract on model (written by value on success only).
    unsafe {
        write_result(model, || {
            // model_of runs every model check (those of check_model too).
            model_of(&m)?;
            if !matches!(carry, DC_CARRY_ROTATE | DC_CARRY_PROJECT) {
                return Err(Error::SpecModel);
            }
            Ok(dc_contact_model { carry, ..m })
        })
    }
}

/// Makes the model realise its target restitution e_n at the host's time step `dt` in the
/// host's `integrator`, not only in the continuous contact: the normal damping is calibrated
/// against the discrete map (a factor R(dt/t_H) on the damping, t_H the elastic contact duration
/// at the contact's impact speed), and the first and (DC_END_OVERLAP) last contact steps, which
/// fall between the host's steps, are corrected. The mean e over contact-onset phases is within
/// 0.2 % of e_n for dt up to t_H/10 (plain: 16 % low at t_H/20, e_n = 0.1); derivation and
/// measurements: docs/timestep.md. DC_INTEGRATOR_VELOCITY_VERLET (LAMMPS, LIGGGHTS: the force
/// from the new position and the half-step velocity) and DC_INTEGRATOR_SYMPLECTIC_EULER are one
/// map and get the same correction. Making a model step-aware adds one double to its history
/// (dc_contact_history_len): call this at set-up, before contacts exist. Call it again, on the
/// step-aware model, whenever the host changes dt: that call keeps the calibration (it depends
/// on p, the criterion and e_n only, not on dt), stores the new dt and leaves the history length
/// as it is. The force calls must then be given this same dt: R is calibrated for the dt given
/// here, while the dt of each force call sets the onset test and the onset and end corrections
/// (see dc_contact_force). An undamped normal law (e_n = 1) has nothing to correct and is
/// returned unchanged (not step-aware, the same history length). Near the elastic limit
/// (1 - e_n < 1e-3) a law whose calibration finds no damping factor (the dashpot weaker than the
/// step's own error: Hertz from 1 - e_n = 1e-7) takes R = 1, the onset and end corrections
/// alone: the phase mean of e within 2.3e-5 of e_n at t_H/10 (Hertz). Binary collisions are exact; an
/// enduring contact keeps its static overlap (the correction acts on the dashpot only). Set-up
/// cost of the first call: about 10 ms at e_n = 0.1; with DC_END_OVERLAP more as e_n -> 0 (near
/// critical damping): about 0.6 s at 1e-9, 2.7 s at 1e-12 (dc_dt_for_accuracy_step_aware runs the
/// same calibration; scripts/extreme_restitution.sh prints its times).
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID, DC_ERR_NOT_FINITE (dt),
///         DC_ERR_NOT_POSITIVE (dt <= 0), DC_ERR_INTEGRATOR, DC_ERR_STEP_UNSUPPORTED (a normal
///         law other than a Tsuji power law with p <= 3 or Hertz: viscoelastic, DMT,
///         elastic-plastic, JKR, p > 3), DC_ERR_STEP_UNREACHABLE (the explicit step cannot
///         realise e_n: strong damping, e_n well below 0.1), DC_ERR_RESULT_RANGE (dt so small that dt over the t_H prefactor underflows
///         to 0, e.g. a subnormal dt such as 5e-324). `model` is untouched on error.
///
/// # Safety
/// `model` NULL or readable and writable for one dc_contact_model.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_model_set_step(
    model: *mut dc_contact_model,
    dt: f64,
    integrator: i32,
) -> i32 {
    // SAFETY: forwarded caller contract on model (read by value, NULL checked).
    let m = match unsafe { read_in(model.cast_const()) } {
        Ok(m) => m,
        Err(s) => return s.code(),
    };
    // SAFETY: forwarded caller contract on model (written by value on success only).
    unsafe {
        write_result(model, || {
            let cm = model_of(&m)?;
            let stepped = set_step(&cm, dt, integrator)?;
            Ok(dc_contact_model {
                magic: m.magic,
                ..dc_contact_model::from(stepped)
            })
        })
    }
}

/// The number of doubles of history one contact of this model needs (0 for a normal-only or
/// constant-rolling model of a stateless normal law that is not step-aware; at most
/// DC_CONTACT_HISTORY_MAX). Layout
/// (for inspection only): normal of the last step (3), tangential spring [m] (3;
/// DC_TANGENTIAL_MINDLIN_RESCALE: its force [N] (3) and the last contact radius [m] (1)),
/// rolling spring torque [N m] (3), twisting spring torque [N m] (1), the state of a normal law
/// with state (1: the largest overlap [m] of DC_NORMAL_ELASTIC_PLASTIC), the step-aware damping
/// state (1), each present only if its sub-model is.
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID.
///
/// # Safety
/// `model` NULL or readable; `len_out` NULL or writable for a size_t.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_history_len(
    model: *const dc_contact_model,
    len_out: *mut usize,
) -> i32 {
    // SAFETY: null checked; any bit pattern of dc_contact_model is a valid value.
    let Some(m) = (unsafe { model.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    // SAFETY: forwarded caller contract on len_out.
    unsafe {
        write_result(len_out, || {
            // model_of runs every model check (those of check_model too).
            Ok(model_of(m)?.layout.len)
        })
    }
}

/// How far beyond touching this model's normal law acts [m], for a contact of effective radius
/// r_eff [m] (R1 R2/(R1 + R2); a sphere on a wall: its radius): the largest gap (−δ) at which
/// its force can be nonzero. 0 for a law that acts only while touching; DC_NORMAL_DMT: its
/// tail's length d_c = (3π w √R* / (2 E*))^(2/3); DC_NORMAL_JKR: |δ_c| = (3/4)(π² w² R* / E*²)^(1/3),
/// where a formed neck breaks. A host extends its neighbour search by this much (the value
/// grows with R*, as R*^(1/3), so the reach at the largest radii bounds every pair).
///
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID, DC_ERR_NOT_FINITE (r_eff
/// NaN or ±inf), DC_ERR_NOT_POSITIVE (r_eff ≤ 0), DC_ERR_RESULT_RANGE (the reach overflows);
/// `reach_out` is written only on DC_OK.
///
/// # Safety
/// `model` NULL or readable; `reach_out` NULL or writable for a double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_model_reach(
    model: *const dc_contact_model,
    r_eff: f64,
    reach_out: *mut f64,
) -> i32 {
    // SAFETY: null checked; any bit pattern of dc_contact_model is a valid value.
    let Some(m) = (unsafe { model.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    // SAFETY: forwarded caller contract on reach_out.
    unsafe {
        write_result(reach_out, || {
            let cm = model_of(m)?;
            if !r_eff.is_finite() {
                return Err(Error::NotFinite);
            }
            if !(r_eff > 0.0) {
                return Err(Error::NotPositive);
            }
            let reach = crate::force::registry::reach(cm.normal.kernel, &cm.normal.consts, r_eff);
            if !reach.is_finite() {
                return Err(Error::ResultRange);
            }
            Ok(reach)
        })
    }
}

/// Shared body of dc_contact_force and dc_contact_force_spheres.
///
/// # Safety
/// As dc_contact_force.
unsafe fn force_common(
    model: *const dc_contact_model,
    state: ContactState,
    dt: f64,
    history: *mut f64,
    history_len: usize,
    out: *mut dc_contact_result,
) -> i32 {
    // SAFETY: forwarded caller contract; no ledger.
    unsafe {
        force_common_with::<false>(
            model,
            state,
            dt,
            history,
            history_len,
            out,
            core::ptr::null_mut(),
        )
    }
}

/// [`force_common`], and with `ENERGY` the ledger written to `energy` (NULL checked).
///
/// # Safety
/// As dc_contact_force_energy (`energy` only read when `ENERGY`).
#[inline(always)]
unsafe fn force_common_with<const ENERGY: bool>(
    model: *const dc_contact_model,
    state: ContactState,
    dt: f64,
    history: *mut f64,
    history_len: usize,
    out: *mut dc_contact_result,
    energy: *mut dc_contact_energy,
) -> i32 {
    // SAFETY: null checked; any bit pattern is a valid value.
    let Some(m) = (unsafe { model.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    if out.is_null() || (ENERGY && energy.is_null()) {
        return DC_ERR_NULL_POINTER;
    }
    let cm = match model_of(m) {
        Ok(cm) => cm,
        Err(e) => return dc_status::of(e).code(),
    };
    let need = cm.layout.len;
    if need > 0 && history.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    if history_len < need {
        return DC_ERR_BUFFER_TOO_SHORT;
    }
    if need > 0 && !history.is_aligned() {
        return DC_ERR_BUFFER_LAYOUT;
    }
    let hist = || -> &mut [f64] {
        if need > 0 {
            // SAFETY: non-null, aligned, valid for history_len >= need doubles (caller
            // contract); nothing else refers to it during the call.
            unsafe { core::slice::from_raw_parts_mut(history, need) }
        } else {
            &mut []
        }
    };
    if ENERGY {
        return guard(|| {
            // cm passed the model checks in model_of.
            let (r, e) = contact_force_energy_checked_model(&cm, &state, dt, hist())?;
            // SAFETY: both non-null (checked above); writable per the caller contract.
            unsafe {
                out.write_unaligned(r.into());
                energy.write_unaligned(e.into());
            }
            Ok(())
        });
    }
    let body = || {
        // cm passed the model checks in model_of.
        contact_force_checked_model(&cm, &state, dt, hist()).map(dc_contact_result::from)
    };
    // SAFETY: forwarded caller contract on out (non-null).
    unsafe { write_result(out, body) }
}

/// Force and torques of one sphere-sphere or sphere-wall contact, with the sub-models of
/// `model`, advancing its history by one step of the host's time step dt.
///
/// Sign conventions: see dc_contact_state. Per step (details and derivations: docs/force.md):
/// normal force from the model's normal law (clamped if built with DC_END_FORCE); the history
/// springs are turned into the current tangent plane (frame indifference), incremented by the
/// contact point's tangential velocity times dt, and truncated at the Coulomb limit mu |Fn|
/// (rolling: mu_r R* |Fn|; twisting: mu_tw |Fn|), Fn the normal force applied.
///
/// @param model        from dc_contact_model_init.
/// @param state        the two bodies of this contact.
/// @param dt           the host's time step [s], finite > 0. For a step-aware model
///                     (dc_contact_model_set_step) pass the dt given to set_step: the damping
///                     factor R is calibrated for that dt (stored in the model, reserved[0]),
///                     while this dt sets the onset test (a = overlap/(vn dt) <= 2) and the onset
///                     and end corrections. A different dt is not detected: the force then mixes
///                     R for one step with corrections for the other, and the realised e_n is not
///                     the calibrated one. When the host's dt changes, call set_step again.
/// @param history      this contact's history: history_len doubles, all zero for a new contact;
///                     updated in place on success (reset to zero when overlap <= 0). May be NULL
///                     when the model needs none (dc_contact_history_len = 0).
/// @param history_len  the number of doubles at `history` (>= dc_contact_history_len).
/// @param out          receives the forces and torques on success.
/// @return DC_OK, DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID, DC_ERR_BUFFER_TOO_SHORT
///         (history_len), DC_ERR_BUFFER_LAYOUT (history misaligned), DC_ERR_NOT_FINITE (NaN/inf
///         in the state, dt or the history), DC_ERR_NOT_POSITIVE (radius, mass or dt <= 0),
///         DC_ERR_NOT_UNIT (n), DC_ERR_RESULT_RANGE. On error `out` and `history` are untouched.
///
/// # Safety
/// `model`, `state` NULL or readable; `out` NULL or writable; `history` NULL or valid for
/// history_len doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_force(
    model: *const dc_contact_model,
    state: *const dc_contact_state,
    dt: f64,
    history: *mut f64,
    history_len: usize,
    out: *mut dc_contact_result,
) -> i32 {
    // SAFETY: null checked; any bit pattern of dc_contact_state is a valid value.
    let Some(s) = (unsafe { state.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    // SAFETY: forwarded caller contract.
    unsafe { force_common(model, ContactState::from(s), dt, history, history_len, out) }
}

/// dc_contact_force with the energy ledger of the step (dc_contact_energy): the same force,
/// torques, history and statuses bit for bit, and what the step dissipated and left stored in
/// the springs. Allocation-free like dc_contact_force; it costs a second pass over the stages.
///
/// @param energy  receives the ledger on success (with `out`); untouched on error.
/// @return as dc_contact_force; DC_ERR_NULL_POINTER also for `energy` NULL; DC_ERR_RESULT_RANGE
///         also for a ledger value that is not finite.
///
/// # Safety
/// As dc_contact_force; `energy` NULL or writable for one dc_contact_energy.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_force_energy(
    model: *const dc_contact_model,
    state: *const dc_contact_state,
    dt: f64,
    history: *mut f64,
    history_len: usize,
    out: *mut dc_contact_result,
    energy: *mut dc_contact_energy,
) -> i32 {
    // SAFETY: null checked; any bit pattern of dc_contact_state is a valid value.
    let Some(s) = (unsafe { state.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    // SAFETY: forwarded caller contract.
    unsafe {
        force_common_with::<true>(
            model,
            ContactState::from(s),
            dt,
            history,
            history_len,
            out,
            energy,
        )
    }
}

/// dc_contact_force for two spheres given by their centres: n = (x1 - x2)/|x1 - x2| and
/// overlap = r1 + r2 - |x1 - x2| are computed here; the `n` and `overlap` fields of `state` are
/// ignored (velocities, radii and masses are read from it). Spheres only (finite r2).
///
/// @return as dc_contact_force; DC_ERR_NOT_FINITE also for non-finite x1, x2 or r2 = +INFINITY,
///         DC_ERR_NOT_POSITIVE for overlapping spheres with coincident centres.
///
/// # Safety
/// As dc_contact_force; `x1`, `x2` NULL or readable for 3 doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_force_spheres(
    model: *const dc_contact_model,
    x1: *const f64,
    x2: *const f64,
    state: *const dc_contact_state,
    dt: f64,
    history: *mut f64,
    history_len: usize,
    out: *mut dc_contact_result,
) -> i32 {
    if x1.is_null() || x2.is_null() {
        return DC_ERR_NULL_POINTER;
    }
    // SAFETY: null checked; any bit pattern is a valid value.
    let Some(s) = (unsafe { state.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    // SAFETY: non-null, readable for 3 doubles (caller contract); unaligned reads.
    let (a, b) = unsafe {
        (
            x1.cast::<[f64; 3]>().read_unaligned(),
            x2.cast::<[f64; 3]>().read_unaligned(),
        )
    };
    let mut st = ContactState::from(s);
    if !(a.iter().chain(b.iter()).all(|x| x.is_finite()) && st.r2.is_finite()) {
        return DC_ERR_NOT_FINITE;
    }
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    if !dist.is_finite() {
        return DC_ERR_RESULT_RANGE;
    }
    st.overlap = st.r1 + st.r2 - dist;
    if dist > 0.0 {
        st.n = [d[0] / dist, d[1] / dist, d[2] / dist];
    } else if st.overlap > 0.0 {
        return DC_ERR_NOT_POSITIVE;
    } else {
        st.n = [1.0, 0.0, 0.0];
    }
    // SAFETY: forwarded caller contract.
    unsafe { force_common(model, st, dt, history, history_len, out) }
}

/// n contacts of one model as a structure of arrays (one dc_contact_force_batch call). Vectors
/// are 3 consecutive doubles per contact (x, y, z; contact i at [3i, 3i+3)); scalars one double
/// per contact. Conventions per contact as in dc_contact_state / dc_contact_result.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
#[allow(non_camel_case_types)]
pub struct dc_contact_batch {
    /// Number of contacts, > 0.
    pub n: usize,
    /// Doubles per contact in `history` (>= dc_contact_history_len); contact i's history is at
    /// history[i * history_stride].
    pub history_stride: usize,
    /// Unit normals, 3n.
    pub normal: *const f64,
    /// Overlaps, n.
    pub overlap: *const f64,
    /// Velocities of body 1, 3n.
    pub v1: *const f64,
    /// Velocities of body 2, 3n.
    pub v2: *const f64,
    /// Angular velocities of body 1, 3n (normal-only models neither read nor check them: may be
    /// NULL).
    pub w1: *const f64,
    /// Angular velocities of body 2, 3n (idem).
    pub w2: *const f64,
    /// Radii of body 1, n.
    pub r1: *const f64,
    /// Radii of body 2, n (+INFINITY: wall).
    pub r2: *const f64,
    /// Masses of body 1, n.
    pub m1: *const f64,
    /// Masses of body 2, n (+INFINITY: fixed).
    pub m2: *const f64,
    /// History, n * history_stride doubles, updated in place (NULL if the model needs none).
    pub history: *mut f64,
    /// Out: normal forces, n.
    pub f_n: *mut f64,
    /// Out: forces on body 1, 3n.
    pub force: *mut f64,
    /// Out: torques on body 1, 3n (may be NULL for a normal-only model).
    pub torque1: *mut f64,
    /// Out: torques on body 2, 3n (idem).
    pub torque2: *mut f64,
}

/// Byte range of `count` doubles at `p`: None if misaligned or too large.
fn span(p: *const f64, count: usize) -> Option<(usize, usize)> {
    let bytes = count.checked_mul(core::mem::size_of::<f64>())?;
    if p.is_null() || !p.is_aligned() || bytes > isize::MAX as usize {
        return None;
    }
    let s = p as usize;
    Some((s, s.checked_add(bytes)?))
}

/// The pointer checks shared by the batch exports (NULLs, lengths, alignment, overlaps), then
/// `run` on the slices under the panic boundary. Its error (call-level) leaves everything
/// untouched; a per-contact report is `run`'s own business.
///
/// # Safety
/// As dc_contact_force_batch.
unsafe fn batch_common<F>(
    model: *const dc_contact_model,
    batch: *const dc_contact_batch,
    run: F,
) -> i32
where
    F: FnOnce(&ContactModel, &BatchIn<'_>, &mut BatchOut<'_>) -> Result<(), Error>,
{
    // SAFETY: null checked; any bit pattern of these plain structs is a valid value.
    let (Some(m), Some(b)) = (unsafe { model.as_ref() }, unsafe { batch.as_ref() }) else {
        return DC_ERR_NULL_POINTER;
    };
    let cm = match model_of(m) {
        Ok(cm) => cm,
        Err(e) => return dc_status::of(e).code(),
    };
    let len = cm.layout.len;
    // Normal-only by its selectors (no tangential, rolling or twisting stage), whatever its
    // history: a step-aware model or a law with state keeps one double and is still normal-only.
    let normal_only = !cm.layout.has_normal() && cm.rolling == select::ROLLING_NONE;
    let n = b.n;
    let (w1, w2) = if normal_only && (b.w1.is_null() || b.w2.is_null()) {
        (b.v1, b.v1) // never read by a normal-only model
    } else {
        (b.w1, b.w2)
    };
    let reqs = [
        b.normal, b.overlap, b.v1, b.v2, w1, w2, b.r1, b.r2, b.m1, b.m2,
    ];
    if reqs.iter().any(|p| p.is_null())
        || b.f_n.is_null()
        || b.force.is_null()
        || (!normal_only && (b.torque1.is_null() || b.torque2.is_null()))
        || (len > 0 && b.history.is_null())
    {
        return DC_ERR_NULL_POINTER;
    }
    if n == 0 || b.history_stride < len {
        return DC_ERR_BUFFER_TOO_SHORT;
    }
    let Some(n3) = n.checked_mul(3) else {
        return DC_ERR_BUFFER_LAYOUT;
    };
    let hist_n = if len > 0 {
        n.checked_mul(b.history_stride)
    } else {
        Some(0)
    };
    let Some(hist_n) = hist_n else {
        return DC_ERR_BUFFER_LAYOUT;
    };
    let ins = [
        (b.normal, n3),
        (b.overlap, n),
        (b.v1, n3),
        (b.v2, n3),
        (w1, n3),
        (w2, n3),
        (b.r1, n),
        (b.r2, n),
        (b.m1, n),
        (b.m2, n),
    ];
    let t1 = (!b.torque1.is_null()).then_some(b.torque1);
    let t2 = (!b.torque2.is_null()).then_some(b.torque2);
    let outs: [Option<(*mut f64, usize)>; 5] = [
        Some((b.f_n, n)),
        Some((b.force, n3)),
        t1.map(|p| (p, n3)),
        t2.map(|p| (p, n3)),
        (len > 0).then_some((b.history, hist_n)),
    ];
    let mut in_spans = [(0usize, 0usize); 10];
    for (s, &(p, c)) in in_spans.iter_mut().zip(ins.iter()) {
        match span(p, c) {
            Some(x) => *s = x,
            None => return DC_ERR_BUFFER_LAYOUT,
        }
    }
    let mut out_spans = [None; 5];
    for (s, o) in out_spans.iter_mut().zip(outs.iter()) {
        if let Some((p, c)) = o {
            match span(p.cast_const(), *c) {
                Some(x) => *s = Some(x),
                None => return DC_ERR_BUFFER_LAYOUT,
            }
        }
    }
    let disjoint = |a: (usize, usize), b: (usize, usize)| a.1 <= b.0 || b.1 <= a.0;
    for (i, o) in out_spans.iter().enumerate() {
        let Some(o) = *o else { continue };
        if in_spans.iter().any(|&s| !disjoint(o, s))
            || out_spans
                .iter()
                .skip(i + 1)
                .flatten()
                .any(|&s| !disjoint(o, s))
        {
            return DC_ERR_BUFFER_LAYOUT;
        }
    }
    let body = || {
        // SAFETY: every pointer is non-null, aligned and valid for its length (caller contract),
        // byte sizes fit isize (checked); outputs overlap no input and no other output
        // (checked), so the shared and the exclusive slices never alias.
        unsafe {
            let sl = |p: *const f64, c: usize| core::slice::from_raw_parts(p, c);
            // [f64; 3] has the alignment of f64: n vectors are the checked 3n doubles.
            let vl = |p: *const f64| core::slice::from_raw_parts(p.cast::<[f64; 3]>(), n);
            let vm = |p: *mut f64| core::slice::from_raw_parts_mut(p.cast::<[f64; 3]>(), n);
            let inp = BatchIn {
                normal: vl(b.normal),
                overlap: sl(b.overlap, n),
                v1: vl(b.v1),
                v2: vl(b.v2),
                w1: vl(w1),
                w2: vl(w2),
                r1: sl(b.r1, n),
                r2: sl(b.r2, n),
                m1: sl(b.m1, n),
                m2: sl(b.m2, n),
            };
            let mut empty: [f64; 0] = [];
            let mut o = BatchOut {
                f_n: core::slice::from_raw_parts_mut(b.f_n, n),
                force: vm(b.force),
                torque1: t1.map(vm),
                torque2: t2.map(vm),
                history: if len > 0 {
                    core::slice::from_raw_parts_mut(b.history, hist_n)
                } else {
                    &mut empty
                },
                stride: b.history_stride.max(1),
            };
            run(&cm, &inp, &mut o)
        }
    };
    guard(|| Ok(body()?))
}

/// dc_contact_force for n contacts of one model (group contacts by type pair): one pass per
/// stage the model has (normal, tangential, rolling, twisting), each a loop with no branch on
/// the model. Every value is checked first (as dc_contact_force; a branch-free pass that costs
/// about 4 ns per contact); on any error nothing is written (outputs and history untouched),
/// except DC_ERR_RESULT_RANGE, which only computing can find: then every contact is computed
/// and a contact whose force, torque or history overflowed has NaN outputs and its history
/// untouched (find it by its NaN f_n; the fused batch also returns its index).
///
/// @param dt  the host's time step [s], finite > 0, as for dc_contact_force (a step-aware model:
///            the dt given to dc_contact_model_set_step).
/// @return DC_OK, DC_ERR_NULL_POINTER (model, batch, a required array),
///         DC_ERR_CONTACT_MODEL_INVALID, DC_ERR_BUFFER_TOO_SHORT (n = 0, history_stride too small),
///         DC_ERR_BUFFER_LAYOUT (a misaligned array, n too large, or an output overlapping an input
///         or another output), DC_ERR_NOT_FINITE, DC_ERR_NOT_POSITIVE, DC_ERR_NOT_UNIT,
///         DC_ERR_RESULT_RANGE (outputs written, see above).
///
/// # Safety
/// `model`, `batch` NULL or readable; every non-NULL array valid for its documented length.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_force_batch(
    model: *const dc_contact_model,
    batch: *const dc_contact_batch,
    dt: f64,
) -> i32 {
    // SAFETY: forwarded caller contract.
    unsafe {
        batch_common(model, batch, |cm, inp, o| {
            contact_force_batch(cm, inp, dt, o)
        })
    }
}

/// dc_contact_force_batch reading every input from memory once (for large batches that do not
/// fit in cache; about 1.2x faster there): blocks of contacts are checked and computed while in
/// cache. Differs from dc_contact_force_batch only in what happens to a contact with a bad
/// value (NaN/inf, radius or mass <= 0, non-unit n, non-finite history) or whose result
/// overflows (DC_ERR_RESULT_RANGE, as dc_contact_force_batch): the other contacts are
/// still computed (exactly, bit for bit as dc_contact_force_batch), the bad contact's f_n,
/// force and torques are set to NaN and its history is left untouched, and the call returns
/// the status of the first bad contact with its index in *first_bad. Errors of the call itself
/// (NULL, model, buffer sizes or layout, a NaN, infinite or non-positive dt) are found before
/// any contact is computed and leave everything untouched, as dc_contact_force_batch: then no
/// output is NaN and *first_bad is not written. DC_ERR_NOT_FINITE and DC_ERR_NOT_POSITIVE can
/// be either kind; a caller that reads *first_bad on every error presets it (e.g. to SIZE_MAX)
/// and treats an unchanged value as a call-level error.
///
/// @param dt         as for dc_contact_force_batch.
/// @param first_bad  NULL, or receives the index of the first bad contact (written only when a
///                   per-contact status is returned).
/// @return DC_OK, or the statuses of dc_contact_force_batch: DC_ERR_NOT_FINITE,
///         DC_ERR_NOT_POSITIVE, DC_ERR_NOT_UNIT, DC_ERR_RESULT_RANGE for a bad contact (outputs
///         written, see above);
///         DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID, DC_ERR_BUFFER_TOO_SHORT,
///         DC_ERR_BUFFER_LAYOUT, DC_ERR_NOT_FINITE / DC_ERR_NOT_POSITIVE for dt (nothing
///         written; *first_bad untouched).
///
/// # Safety
/// As dc_contact_force_batch; `first_bad` NULL or writable for a size_t.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn dc_contact_force_batch_fused(
    model: *const dc_contact_model,
    batch: *const dc_contact_batch,
    dt: f64,
    first_bad: *mut usize,
) -> i32 {
    let run = |cm: &ContactModel, inp: &BatchIn<'_>, o: &mut BatchOut<'_>| {
        match contact_force_batch_fused(cm, inp, dt, o)? {
            None => Ok(()),
            Some((i, e)) => {
                if !first_bad.is_null() {
                    // SAFETY: non-null; writable for a size_t (caller contract); unaligned ok.
                    unsafe { first_bad.write_unaligned(i) };
                }
                Err(e)
            }
        }
    };
    // SAFETY: forwarded caller contract.
    unsafe { batch_common(model, batch, run) }
}

#[cfg(test)]
mod tests {
    //! The conversions generated by `spec_fields!` and `model_fields!` carry every field: a
    //! value per field, distinct from every other, survives C → Rust → C (and Rust → C → Rust).
    use super::*;

    #[test]
    fn spec_converts_every_field_both_ways() {
        let mut c = dc_contact_spec::from_default();
        // Distinct values in every field (an exchanged or dropped field changes the result).
        let [a, b, d, e, f, g] = [1, 2, 0, 3, 2, 1];
        (
            c.normal,
            c.damping,
            c.criterion,
            c.tangential,
            c.rolling,
            c.twisting,
        ) = (a, b, d, e, f, g);
        let xs = [
            &mut c.E1,
            &mut c.nu1,
            &mut c.E2,
            &mut c.nu2,
            &mut c.p,
            &mut c.k_n,
            &mut c.e_n,
            &mut c.visco_A,
            &mut c.mu,
            &mut c.k_t,
            &mut c.e_t,
            &mut c.mu_r,
            &mut c.k_r,
            &mut c.eta_r,
            &mut c.mu_tw,
            &mut c.k_tw,
            &mut c.eta_tw,
            &mut c.inertia_factor,
            &mut c.work_of_adhesion,
            &mut c.yield_pressure,
        ];
        for (i, x) in xs.into_iter().enumerate() {
            *x = 10.0 + i as f64;
        }
        let r = ContactSpec::from(&c);
        assert_eq!((r.e1, r.visco_a, r.yield_pressure), (10.0, 17.0, 29.0));
        assert_eq!(r.carry, select::CARRY_ROTATE);
        assert_eq!(dc_contact_spec::of_spec(&r), c);
        // The defaults (NaN for unset: compared as text).
        let d = ContactSpec::default();
        let back = ContactSpec::from(&dc_contact_spec::from_default());
        assert_eq!(format!("{back:?}"), format!("{d:?}"));
    }

    #[test]
    fn model_converts_every_field_both_ways() {
        let spec = ContactSpec {
            normal: crate::contact::spec::normal::HERTZ,
            damping: crate::contact::spec::damping::RESTITUTION,
            tangential: select::TANGENTIAL_MINDLIN_RESCALE,
            rolling: select::ROLLING_EPSD,
            twisting: select::TWISTING_SDS,
            e1: 7e10,
            nu1: 0.3,
            e2: 2e11,
            nu2: 0.25,
            e_n: 0.8,
            mu: 0.5,
            e_t: 0.7,
            mu_r: 0.1,
            k_r: 3.0,
            eta_r: 0.2,
            mu_tw: 1e-4,
            k_tw: 5.0,
            eta_tw: 0.3,
            ..ContactSpec::default()
        };
        let m = contact_model(&spec).expect("valid spec");
        let m = ContactModel {
            carry: select::CARRY_PROJECT,
            ..m
        };
        let c = dc_contact_model::from(m);
        assert_eq!(
            (c.tangential, c.rolling, c.twisting, c.carry),
            (m.tangential, m.rolling, m.twisting, m.carry)
        );
        assert_eq!(c.history_len as usize, m.layout.len);
        assert_eq!(model_of(&c), Ok(m));
        // Every shared constant is read from its own field: each changed alone changes the
        // core model's field of the same name and nothing else.
        let (sel, consts) = c.check_parts(1.0, 2.0, 3.0);
        assert_eq!(sel, [m.tangential, m.rolling, m.twisting, m.carry]);
        assert_eq!(
            consts,
            [
                1.0, 2.0, 3.0, m.mu, m.kt, m.zeta_t, m.kappa, m.mu_r, m.k_r, m.eta_r, m.mu_tw,
                m.k_tw, m.eta_tw
            ]
        );
    }
}
