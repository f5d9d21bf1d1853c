//! The report's truth for δ_max and τ: the tests' own adaptive Dormand–Prince reference
//! (tests/common), integrating the physical equation of motion with m = 1, k = ω0², events at
//! v = 0 (maximum overlap) and at the criterion's end.

#[path = "../../tests/common/mod.rs"]
mod common;

pub use common::{
    Collision as RefCollision, try_collide as collide, try_collide_observed as collide_observed,
};
