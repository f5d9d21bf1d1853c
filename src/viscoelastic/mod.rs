//! Viscoelastic (Hertz + Kuwabara–Kono/Brilliantov) spheres:
//! `ξ'' + k ξ^{3/2} + γ √ξ ξ' = 0`, ξ(0) = 0, ξ'(0) = v.
//!
//! The restitution depends on k, γ and v only through b = β v^{1/5}, β = γ k^{−3/5}
//! ([`scaling`]). e(b) for both end-of-contact criteria is offered in three tiers:
//! * [`series`]: the published series of Schwager & Pöschel (2008), cheap, small b only;
//! * [`full_range`]: piecewise Chebyshev approximations generated from the reference
//!   (measured ≤ 6e-14 relative on [0, 1e6]) plus the large-b laws beyond (overlap
//!   e = C_O b^{−5}, C_O = 5.15838170426769 (`table::C_OVERLAP`, its one definition), exact
//!   from b = 8; force e → (3/2)^{2/3} b^{−5/3});
//! * [`reference`]: direct Taylor-series integration in regularised variables.
//!
//! [`calibration`] turns a measured e at a reference speed into β (or A), and finds the speed at
//! which e reaches a given value.

pub mod calibration;
pub mod full_range;
pub mod reference;
pub mod scaling;
pub mod series;
mod table;
