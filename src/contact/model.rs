//! The composed contact model: one normal law (a force kernel) plus optional tangential,
//! rolling and twisting sub-models, with the layout of the caller-owned history.

use crate::force::PairModel;

/// Sub-model selectors (the C constants `DC_TANGENTIAL_*`, `DC_ROLLING_*`, `DC_TWISTING_*`
/// equal these). Rust-side names: hidden from cbindgen so the C header keeps only `DC_` names.
///
/// cbindgen:ignore
pub mod select {
    use crate::laws::{
        P_E_T, P_ETA_R, P_ETA_TW, P_K_R, P_K_T, P_K_TW, P_MU, P_MU_R, P_MU_TW, stages,
    };

    // Each law: `=> [its TangentialStage] history <doubles of its record>`.
    stages! {
        $ TANGENTIAL, tangential (type):
        /// No tangential force.
        TANGENTIAL_NONE (NONE) = 0, "none", "Tangential: none.", false, [];
        /// Cundall–Strack linear history spring k_t with dashpot and Coulomb limit.
        TANGENTIAL_LINEAR (LINEAR) = 1, "linear",
            "Tangential: Cundall-Strack linear history spring k_t, dashpot from e_t, Coulomb limit.",
            false, [P_MU, P_K_T, P_E_T]
            => [crate::contact::tangential_linear::Linear] history 3;
        /// Mindlin no-slip spring k_t = 8 G* a, a = √(R* δ), dashpot, Coulomb limit.
        TANGENTIAL_MINDLIN (MINDLIN) = 2, "mindlin",
            "Tangential: Mindlin k_t = 8 G* a, a = sqrt(R* d), dashpot from e_t, Coulomb limit. Kept as LAMMPS `mindlin` has it (total form k_t(d) xi); it creates energy when the contact grows (up to +0.27 % of the kinetic energy in an elastic oblique impact, docs/force.md): prefer DC_TANGENTIAL_MINDLIN_RESCALE.",
            true, [P_MU, P_E_T]
            => [crate::contact::tangential_mindlin::Mindlin] history 3;
        /// Mindlin spring in incremental force form, its force history rescaled by a/a_old when
        /// the contact radius shrinks (Thornton et al. 2013, eq. 18b; LAMMPS
        /// `mindlin_rescale/force`): creates no energy. History: the force (3) and the contact
        /// radius of the last step (1).
        TANGENTIAL_MINDLIN_RESCALE (MINDLIN_RESCALE) = 3, "mindlin_rescale",
            "Tangential: Mindlin k_t = 8 G* a in incremental force form, the force history rescaled by a/a_old when the contact shrinks (Thornton et al. 2013; LAMMPS `mindlin_rescale/force`), dashpot from e_t, Coulomb limit: creates no energy. 4 doubles of tangential history.",
            true, [P_MU, P_E_T]
            => [crate::contact::tangential_mindlin_rescale::MindlinRescale] history 4;
    }

    // Each law: `=> [EPSD] history <doubles>`, EPSD: whether it is the elastic-plastic spring
    // (`rolling_pass::<EPSD>`; false: the constant torque of `rolling_constant`).
    stages! {
        $ ROLLING, rolling (const bool):
        /// No rolling resistance.
        ROLLING_NONE (NONE) = 0, "none", "Rolling resistance: none.", false, [];
        /// Constant directional torque μ_r R* |Fn| opposing the rolling angular velocity.
        ROLLING_CONSTANT (CONSTANT) = 1, "constant",
            "Rolling resistance: constant torque mu_r R* |Fn| opposing the rolling angular velocity.",
            false, [P_MU_R]
            => [false] history 0;
        /// Elastic–plastic spring–dashpot (Ai et al. 2011, type C), own history, limit
        /// μ_r R* |Fn|.
        ROLLING_EPSD (EPSD) = 2, "epsd",
            "Rolling resistance: elastic-plastic spring-dashpot (Ai et al. 2011), limit mu_r R* |Fn|.",
            false, [P_MU_R, P_K_R, P_ETA_R]
            => [true] history 3;
    }

    // Each law: `=> [its marker type] history <doubles>`.
    stages! {
        $ TWISTING, twisting (type):
        /// No twisting resistance.
        TWISTING_NONE (NONE) = 0, "none", "Twisting resistance: none.", false, [];
        /// Spring–dashpot–slider about the normal, limit μ_tw |Fn|.
        TWISTING_SDS (SDS) = 1, "sds",
            "Twisting resistance: spring-dashpot-slider about n, limit mu_tw |Fn|.",
            false, [P_MU_TW, P_K_TW, P_ETA_TW]
            => [crate::contact::twisting_sds::Sds] history 1;
    }

    // Flags read by the frame step (`Kin::frame`): no stage, no history.
    stages! {
        $ CARRY, carry (type):
        /// History springs carried by the frame's rotation (spin, then tilt): objective.
        CARRY_ROTATE (ROTATE) = 0, "rotate",
            "History springs follow the contact frame by rotation (the bodies' mean spin, then the tilt of the normal): objective under any rigid rotation of the pair. Default.",
            false, [];
        /// History springs projected on the new tangent plane and rescaled to their old length
        /// (LAMMPS `granular`; LIGGGHTS `history` projects without rescaling): cheaper, not
        /// objective about the normal.
        CARRY_PROJECT (PROJECT) = 1, "project",
            "History springs projected on the new tangent plane and rescaled to their old length, as LAMMPS `granular` does (LIGGGHTS `tangential history` projects without rescaling): cheaper, but a pair turning about its normal loads its spring (see docs/force.md). Set with dc_contact_model_set_carry.",
            false, [];
    }
}

/// Doubles per contact of the largest model: normal of the last step (3), tangential spring (3,
/// and 1 more, the contact radius of the last step, for `TANGENTIAL_MINDLIN_RESCALE`), rolling
/// spring torque (3), twisting spring torque (1), and one of: the step-aware damping state (1)
/// or the state of a normal law with state (1; such laws have no step-aware form, so the two
/// never meet and 12 still bounds every model).
/// (C: `DC_CONTACT_HISTORY_MAX`.)
///
/// cbindgen:ignore
pub const HISTORY_MAX: usize = 12;

// The largest model of the registries fits: the normal, the longest record of each stage and
// the one double of the step-aware damping or of a normal law with state.
const _: () = {
    let (normal, state) = (3, 1);
    assert!(
        normal
            + select::tangential::MAX_HISTORY
            + select::rolling::MAX_HISTORY
            + select::twisting::MAX_HISTORY
            + state
            <= HISTORY_MAX
    );
};

/// Where each sub-model keeps its state in the caller's history array (offsets in doubles).
/// Only the parts a model uses are present, so a model's history is as short as it can be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Total doubles per contact (0 for a normal-only model).
    pub len: usize,
    /// Offset of the tangential spring, if any: ξ [m] (3 doubles), or for
    /// `TANGENTIAL_MINDLIN_RESCALE` the spring force [N] (3) and the last contact radius [m] (1).
    pub tangential: Option<usize>,
    /// Offset of the rolling spring torque [N m] (3 doubles), if any.
    pub rolling: Option<usize>,
    /// Offset of the twisting spring torque [N m] (1 double), if any.
    pub twisting: Option<usize>,
    /// Offset of the state of a normal law with state (1 double, e.g. δ_max of the
    /// elastic–plastic law: [`crate::force::stateful`]), if the law has one; after the springs.
    pub normal_state: Option<usize>,
    /// Offset of the step-aware damping state (1 double: 0 fresh, ±R), if the model is
    /// step-aware ([`super::step_exact`]); always last.
    pub step: Option<usize>,
}

impl Layout {
    /// The layout for the given selectors: the normal of the last step first (at offset 0,
    /// needed to rotate any vector spring), then each present spring in stage order, each as
    /// long as its registry line says (`select::<kind>::history`; an unknown code has none).
    pub fn of(tangential: i32, rolling: i32, twisting: i32) -> Layout {
        let t_len = select::tangential::history(tangential);
        let r_len = select::rolling::history(rolling);
        let tw_len = select::twisting::history(twisting);
        let (has_t, has_r, has_tw) = (t_len > 0, r_len > 0, tw_len > 0);
        let mut len = if has_t || has_r || has_tw { 3 } else { 0 };
        let mut take = |on: bool, n: usize| {
            on.then(|| {
                let at = len;
                len += n;
                at
            })
        };
        let t = take(has_t, t_len);
        let r = take(has_r, r_len);
        let tw = take(has_tw, tw_len);
        Layout {
            len,
            tangential: t,
            rolling: r,
            twisting: tw,
            normal_state: None,
            step: None,
        }
    }

    /// The layout of a model with the given selectors whose normal law has state
    /// (`normal_state`, [`crate::force::stateful`]) or not, step-aware (`step`) or not.
    pub fn of_model(
        tangential: i32,
        rolling: i32,
        twisting: i32,
        normal_state: bool,
        step: bool,
    ) -> Layout {
        let l = Layout::of(tangential, rolling, twisting);
        let l = if normal_state {
            Layout {
                len: l.len + 1,
                normal_state: Some(l.len),
                ..l
            }
        } else {
            l
        };
        if step {
            Layout {
                len: l.len + 1,
                step: Some(l.len),
                ..l
            }
        } else {
            l
        }
    }

    /// True when the history starts with the normal of the last step (vector springs present).
    #[inline(always)]
    pub fn has_normal(&self) -> bool {
        self.tangential.is_some() || self.rolling.is_some() || self.twisting.is_some()
    }
}

/// A complete, validated contact model (what `dc_contact_model` carries, in Rust form).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactModel {
    /// The normal law: kernel code and constants (as `dc_pair`).
    pub normal: PairModel,
    /// `select::TANGENTIAL_*`.
    pub tangential: i32,
    /// `select::ROLLING_*`.
    pub rolling: i32,
    /// `select::TWISTING_*`.
    pub twisting: i32,
    /// `select::CARRY_*`: how the history springs follow the contact frame.
    pub carry: i32,
    /// Sliding friction coefficient μ ≥ 0.
    pub mu: f64,
    /// Tangential stiffness constant: k_t [N/m] (linear) or 8 G* [Pa] (Mindlin: k_t = 8 G* a).
    pub kt: f64,
    /// Tangential damping ratio ζ_t from the target e_t (0: undamped).
    pub zeta_t: f64,
    /// Inertia factor κ = I/(m r²) of both bodies (2/5: solid spheres).
    pub kappa: f64,
    /// Rolling friction coefficient μ_r ≥ 0 (dimensionless; torque limit μ_r R* |Fn|).
    pub mu_r: f64,
    /// Rolling stiffness k_r [N m/rad]; 0 selects Ai et al.'s rule k_r = 2.25 k_n μ_r² R*².
    pub k_r: f64,
    /// Rolling damping ratio η_r ≥ 0 (EPSD).
    pub eta_r: f64,
    /// Twisting friction coefficient μ_tw [m] (torque limit μ_tw |Fn|).
    pub mu_tw: f64,
    /// Twisting stiffness k_tw [N m/rad].
    pub k_tw: f64,
    /// Twisting damping ratio η_tw ≥ 0.
    pub eta_tw: f64,
    /// History layout.
    pub layout: Layout,
    /// The step-aware damping (off unless `dc_contact_model_set_step` was called).
    pub step: super::step_exact::StepExact,
}
