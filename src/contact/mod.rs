//! Full contact of spheres and walls: the normal law of [`crate::force`] composed with
//! tangential friction, rolling and twisting resistance, with per-contact history owned by the
//! caller.
//!
//! One file per sub-model, and a stage per kind of sub-model (normal kernel → tangential →
//! rolling → twisting). Each stage is a monomorphised function chosen once per call (scalar) or
//! once per batch, so the number of compiled kernels is the *sum* of the sub-model counts, not
//! their product, and a scene pays only for the stages it switches on.
//!
//! * [`spec`]: the specification (sub-models and parameters by field) → validated model.
//! * [`model`]: the composed model, selectors and history layout.
//! * [`kinematics`]: contact geometry and relative motion from the bodies' state.
//! * [`frame`]: carries history vectors into the current tangent plane (frame indifference).
//! * [`tangential`]: the Coulomb-limited history spring step shared by the tangential laws, and
//!   the damping calibrated from a tangential restitution; laws [`tangential_linear`]
//!   (Cundall–Strack) and [`tangential_mindlin`] (k_t = 8 G* a); the stage
//!   [`tangential_mindlin_rescale`] (Mindlin in incremental force form, rescaled on unloading).
//! * [`rolling_constant`], [`rolling_epsd`]: rolling resistance; [`twisting_sds`]: twisting.
//! * [`step_exact`]: the normal damping corrected for the host's explicit step.
//! * [`evaluate`]: one contact through every stage; [`batch`]: structure-of-arrays batches.
//! * [`energy`]: the energy ledger of a step (dissipated work, energy left in the springs).

pub mod batch;
pub mod energy;
pub mod evaluate;
pub mod frame;
pub mod kinematics;
pub mod model;
pub mod rolling_constant;
pub mod rolling_epsd;
pub mod spec;
pub mod step_exact;
pub mod tangential;
pub mod tangential_linear;
pub mod tangential_mindlin;
pub mod tangential_mindlin_rescale;
pub mod twisting_sds;
pub mod vec3;

pub use energy::ContactEnergy;
pub use evaluate::{ContactForce, contact_force, contact_force_energy};
pub use kinematics::ContactState;
pub use model::{ContactModel, HISTORY_MAX, Layout};
pub use spec::{ContactSpec, contact_model};
