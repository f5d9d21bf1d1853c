//! The power-law Tsuji contact `m δ'' + α √(m k) δ^((p-1)/2) δ' + k δ^p = 0`, p ≥ 1,
//! δ(0) = 0, δ'(0) = v0 > 0, with ω0 = √(k/m).
//!
//! The substitution δ = A x^q, q = 2/(p+1), A = ((p+1)/2)^(1/(p+1)) turns its phase-space
//! equation into that of the LSD `v dv/dx + 2ζω0 v + ω0² x = 0` with ζ = α/√(2(p+1))
//! ([`transform`]). It also carries the force-zero condition F = 0 onto the LSD's
//! `ω0 x + 2ζ v = 0` (F/m = ω0² A^p x^(qp) + α ω0 A^((p-1)/2) x^(q(p-1)/2) v, and dividing by
//! A^((p-1)/2) x^(q(p-1)/2) leaves √((p+1)/2)·(ω0² x + 2ζ ω0 v)/ω0), so both end criteria of
//! every p reduce to [`crate::lsd`] ([`calibration`]).
//!
//! The observables of one collision: [`contact`] (validated inputs, the LSD image),
//! [`overlap`] (δ_max), [`duration`] (τ for both criteria, time of δ_max), [`energy`]
//! (energy partition), [`plan`] (reusable per-p duration plans), [`trajectory`] (δ, v, F, t sampled
//! over the contact), [`timestep`].

pub mod calibration;
pub mod contact;
pub mod duration;
pub mod energy;
mod overdamped_tail;
pub mod overlap;
pub mod plan;
pub mod timestep;
pub mod trajectory;
pub mod transform;

pub use calibration::{alpha_from_e, e_from_alpha};
pub use contact::Contact;
pub use duration::{contact_duration, time_of_max_overlap};
pub use energy::{EnergyPartition, energy_partition};
pub use overlap::max_overlap;
pub use plan::{DurationPlan, omega0};
pub use timestep::dt_crit_seed;
pub use transform::{
    alpha_from_zeta, check_exponent, damping_scale, transform_a, transform_q, zeta_from_alpha,
};
