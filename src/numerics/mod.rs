//! Small numerical building blocks, each tested on its own.
//!
//! * [`roots`]: a bracketed Newton iteration for monotone functions.
//! * [`ode`]: an adaptive Dormand–Prince 5(4) integrator with event location, used as the
//!   independent reference that every closed form and quadrature in this crate is checked against.

pub mod ode;
pub mod roots;

pub use roots::newton_bracketed;
