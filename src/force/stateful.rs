//! Normal laws with state: laws whose force depends on the contact's past (plastic hysteresis),
//! not only on (δ, vn, R*, m*). Each keeps one double per contact in the composed contact
//! model's history (the `normal_state` slot of [`crate::contact::Layout`]), present only for
//! these laws, so a model of a stateless law pays nothing.
//!
//! They are contact-model-only: their kernel codes are not in the stateless registry
//! ([`super::registry`]), so every `dc_pair` path (`dc_normal_force*`, the pair batches, the
//! integrator, `dc_contact_model_set_step`) refuses them (`DC_ERR_PAIR_INVALID`, NaN from the
//! unchecked force, `DC_ERR_STEP_UNSUPPORTED`) rather than compute a force without the state.
//! Their codes share the `dc_pair.kernel` number space (ABI: never renumber, only append); each
//! is declared in its law's file (which imports nothing of this one: no cycle) and gathered here.
//! A unit test below keeps [`STATEFUL_KERNEL_CODES`] apart from the registry's codes.
//!
//! To add one: a module with the law's force (reading and updating the state), its plastic or
//! hysteretic loss of a step for the energy ledger and its code, then the code below and one arm
//! in each function here, and the header's twin (`include/demcontact_inline.h`).

use super::elastic_plastic;
use super::pair::Consts;

/// Kernel code of the elastic–plastic law ([`elastic_plastic`]); state δ_max [m].
pub(crate) const KERNEL_ELASTIC_PLASTIC: i32 = elastic_plastic::KERNEL;

/// Every kernel code of a law with state.
pub const STATEFUL_KERNEL_CODES: &[i32] = &[KERNEL_ELASTIC_PLASTIC];

/// True for the kernel code of a law with state.
#[inline(always)]
pub(crate) fn has_state(kernel: i32) -> bool {
    kernel == KERNEL_ELASTIC_PLASTIC
}

/// The normal force of a law with state at overlap d (any sign: the law decides its range),
/// reading and updating `state`; NaN for a code that is not one of these laws.
#[inline(always)]
pub(crate) fn force(
    kernel: i32,
    c: &Consts,
    d: f64,
    _vn: f64,
    r: f64,
    _m: f64,
    state: &mut f64,
) -> f64 {
    match kernel {
        KERNEL_ELASTIC_PLASTIC => elastic_plastic::force(c, d, r, state),
        _ => f64::NAN,
    }
}

/// The energy the law removed in a step that took its state from `old` to `new` [J] (reported
/// by the energy ledger as the step's normal loss; ≥ 0).
#[inline(always)]
pub(crate) fn dissipated(kernel: i32, c: &Consts, r: f64, old: f64, new: f64) -> f64 {
    match kernel {
        KERNEL_ELASTIC_PLASTIC => elastic_plastic::dissipated(c, r, old, new),
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::STATEFUL_KERNEL_CODES;
    use crate::force::registry::KERNEL_CODES;

    #[test]
    fn stateful_codes_are_not_stateless_ones() {
        for c in STATEFUL_KERNEL_CODES {
            assert!(!KERNEL_CODES.contains(c), "{c}");
        }
    }
}
