//! Normal laws with state: laws whose force depends on the contact's past (plastic hysteresis),
//! not only on (δ, vn, R*, m*). Each keeps one double per contact in the composed contact
//! model's history (the `normal_state` slot of [`crate::contact::Layout`]), present only for
//! these laws, so a model of a stateless law pays nothing.
//!
//! They are contact-model-only: their kernel codes are not stateless kernels, so every
//! `dc_pair` path (`dc_normal_force*`, the pair batches, the integrator,
//! `dc_contact_model_set_step`) refuses them (`DC_ERR_PAIR_INVALID`, NaN from the unchecked
//! force, `DC_ERR_STEP_UNSUPPORTED`) rather than compute a force without the state. Their codes
//! share the `dc_pair.kernel` number space (ABI: never renumber, only append) and are given by
//! the law's line in the registry (`state <code>`, [`super::registry`]), which generates the
//! dispatch re-exported here. A law with state implements [`super::pair::StateLaw`] in its own
//! file (e.g. [`super::elastic_plastic`]).

pub use super::registry::STATEFUL_KERNEL_CODES;
pub(crate) use super::registry::{has_state, state_dissipated as dissipated, state_force as force};
