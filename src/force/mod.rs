//! Per-contact normal-force kernels: the hot path of every DEM step.
//!
//! A pair model ([`PairModel`]) is built once per material pair at set-up; everything that does
//! not depend on the individual contact (calibrated damping, effective modulus, the choice of
//! exponent and of clamping) is folded into a *kernel code* and three constants there. Per
//! contact only the overlap δ, its rate vn (positive while compressing), the effective radius and
//! the effective mass vary.
//!
//! "Only what the scene requires": each kernel code names one monomorphised law with a fixed
//! exponent path (p = 1, 3/2, 2 without `pow`; `pow` only for other p), with or without damping,
//! with or without clamping. Scalar calls dispatch once per call, batches once per batch
//! ([`batch`]): no loop ever branches on the model kind.
//!
//! * [`pair`]: the constants, the [`pair::Law`] trait, the shared overlap/clamp finish (a leaf:
//!   imports no sibling).
//! * [`registry`]: the one table of kernel codes; generates the dispatch.
//! * [`powerlaw`]: Tsuji power-law contact with a fixed stiffness (linear spring-dashpot = p 1).
//! * [`hertz`]: Hertz from material data, k = (4/3) E* √R* per contact.
//! * [`viscoelastic`]: Brilliantov et al. viscoelastic Hertz, damping constant A.
//! * [`dmt`]: adhesive DMT (Hertz minus 2π w R*, attraction beyond touching; added last, by the
//!   steps of docs/force.md).
//! * [`stateful`]: normal laws with one double of per-contact state (contact-model only).
//! * [`elastic_plastic`]: Thornton's elastic–perfectly-plastic law (state δ_max).
//! * [`batch`]: structure-of-arrays loops.
//! * [`geometry3d`]: two spheres in 3D → normal force vector (nalgebra).

pub mod batch;
pub mod geometry3d;
pub mod pair;
pub mod registry;
pub mod stateful;

// The law files (`dmt.rs`, …) are declared in the registry next to their lines, so that a new
// law is one file and its registry entry; they are reached here as `force::<law>`.
pub use registry::law_files::*;

pub use pair::{Consts, PairModel};
pub use registry::normal_force;
