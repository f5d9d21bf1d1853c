//! Small numerical building blocks, each tested on its own.
//!
//! * [`roots`]: a bracketed Newton iteration for monotone functions.
//! * [`ode`]: an adaptive Dormand–Prince 5(4) integrator with event location, used as the
//!   independent reference that every closed form and quadrature in this crate is checked against.
//! * [`gamma`]: Re ln Γ(a + ib), for the closed-form contact duration.
//! * [`tanh_sinh`]: double-exponential quadrature on [0, 1], for the damped time integrals.

pub mod gamma;
pub mod ode;
pub mod roots;
pub mod tanh_sinh;

pub use roots::newton_bracketed;
