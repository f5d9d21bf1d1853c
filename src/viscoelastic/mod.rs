//! Viscoelastic (Hertz + Kuwabara–Kono/Brilliantov) spheres:
//! `ξ'' + k ξ^{3/2} + γ √ξ ξ' = 0`, ξ(0) = 0, ξ'(0) = v.
//!
//! The restitution depends on k, γ and v only through b = β v^{1/5}, β = γ k^{−3/5}
//! ([`scaling`]). e(b) for both end-of-contact criteria is offered in three tiers:
//! * [`series`]: the published series of Schwager & Pöschel (2008), cheap, small b only;
//! * [`full_range`]: piecewise Chebyshev approximations generated from the reference
//!   (1e-10 relative for every b in [0, 1e4]) plus the large-b asymptotic law beyond;
//! * [`reference`]: direct Taylor-series integration in regularised variables.
//!
//! [`calibration`] turns a measured e at a reference speed into β (or A), and finds the speed at
//! which e reaches a given value.

pub mod reference;
pub mod scaling;
pub mod calibration;
pub mod full_range;
pub mod series;
mod table;
