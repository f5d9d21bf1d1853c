//! demcontact: exact, allocation-free contact mechanics for discrete-element (DEM) solvers.
//!
//! The maths lives in small modules named after the physics; the C boundary lives alone in
//! [`ffi`]. Nothing in this crate allocates on the heap or keeps global mutable state, so every
//! function may be called from any number of threads at once.
//!
//! * [`lsd`]: the linear spring-dashpot (LSD) in dimensionless form. Every power-law Tsuji contact
//!   maps exactly onto it, so its restitution functions are the heart of the calibration.
//! * [`powerlaw`]: the power-law Tsuji contact `m δ'' + α √(m k) δ^((p-1)/2) δ' + k δ^p = 0`.
//! * [`force`]: per-contact normal-force kernels (scalar, batch, 3D), monomorphised per model.
//! * [`contact`]: full contact (normal, tangential, rolling, twisting) with caller-owned history.
//! * [`material`]: Hertz stiffness from two spheres' E, ν, R.
//! * [`timestep`]: a contact integrated as DEM hosts do (velocity-Verlet, symplectic Euler) with
//!   the library's kernels, and the largest step for a tolerance on the realised restitution.
//! * [`viscoelastic`]: speed-dependent restitution of viscoelastic Hertz spheres, e(β v^{1/5}),
//!   in three tiers (published series, full-range tables, reference integration), and calibration.
//! * [`numerics`]: root finding and the reference ODE integrator used to check everything else.
//! * [`ffi`]: the `extern "C"` functions exported as `include/demcontact.h`.

pub mod builtin;
pub mod contact;
pub mod criterion;
pub mod error;
pub mod ffi;
pub mod fit;
pub mod force;
pub mod laws;
pub mod lsd;
pub mod material;
pub mod numerics;
pub mod plan;
pub mod powerlaw;
pub mod timestep;
pub mod viscoelastic;

pub use criterion::EndCriterion;
pub use error::Error;
