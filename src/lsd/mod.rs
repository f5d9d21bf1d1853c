//! The linear spring-dashpot (LSD) in dimensionless form, `x'' + 2ζ x' + x = 0`, x(0) = 0,
//! x'(0) = 1, with damping ratio ζ ≥ 0.
//!
//! The phase-space map of the power-law seed carries every power-law Tsuji contact, and both of
//! its end-of-contact events, exactly onto this oscillator; so the restitution of any p follows
//! from the functions here once α is converted to ζ ([`crate::powerlaw::zeta_from_alpha`]).

mod decay;
mod restitution;

pub use decay::{decay_to_turning_point, decay_to_turning_point_with_slope};
pub use restitution::{ZETA_CRITICAL, e_force, e_overlap, zeta_force, zeta_overlap};
