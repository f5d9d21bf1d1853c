//! Time-stepping a contact the way DEM codes do, and the step that a target accuracy allows.
//!
//! * [`integrator`]: one collision (or a resting contact under a constant load) integrated with
//!   velocity-Verlet in the LAMMPS/LIGGGHTS order (dashpot evaluated with the half-step velocity)
//!   or with symplectic Euler, using the library's own force kernels ([`crate::force`]), with
//!   contact starting at any sub-step phase. This is what a host code realises, so it is what the
//!   time-step experiments and [`dt_for_accuracy`] measure.
//! * [`accuracy`]: the largest step for which the realised restitution of a velocity-Verlet
//!   collision stays within a relative tolerance whatever the phase at which contact starts.

pub mod accuracy;
pub mod integrator;

pub use accuracy::{dt_for_accuracy, worst_restitution_error};
pub use integrator::{Collision, Scheme, collide, resting_contact_stable};
