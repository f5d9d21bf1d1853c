//! The one error type of the core. The FFI layer maps each variant to a `DC_ERR_*` status code.

/// Why a computation was refused or failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Error {
    /// An input was NaN or ±infinity.
    NotFinite,
    /// The restitution coefficient is outside its valid range (0, 1].
    RestitutionRange,
    /// The force-law exponent p is below 1.
    ExponentRange,
    /// A quantity that must be positive (speed, stiffness, mass, frequency, ...) was not.
    NotPositive,
    /// A Poisson ratio outside (−1, 1/2], the range of an isotropic elastic solid.
    PoissonRange,
    /// A quantity that must not be negative (damping coefficient, overlap, ...) was negative.
    Negative,
    /// The end-of-contact criterion code is unknown.
    Criterion,
    /// The result is not representable as a finite double (overflow).
    ResultRange,
    /// A search or iterative method found no answer within its bounds (e.g. no step
    /// `dt_for_accuracy` can check meets the tolerance); reported rather than hidden.
    NoConvergence,
    /// A caller-provided buffer is too short, or a requested count is zero.
    BufferTooShort,
    /// The requested event never happens: e.g. the end of an overdamped contact under the overlap
    /// criterion (the overlap only tends to zero as t → ∞).
    NoEvent,
    /// A pair model (`dc_pair`) was not made by a `dc_pair_*` constructor (unknown kernel code).
    PairInvalid,
    /// Caller buffers are misaligned for their type or an output overlaps an input.
    BufferLayout,
    /// A quadrature accuracy level outside the supported range.
    Level,
    /// A duration plan was not made by `dc_duration_plan_init` (or was modified afterwards).
    Plan,
    /// A contact specification has an unsupported version or size.
    SpecVersion,
    /// A contact specification names an unknown sub-model or an invalid combination.
    SpecModel,
    /// A parameter the chosen sub-models need was left unset (NaN).
    SpecUnset,
    /// A contact model was not made by `dc_contact_model_init` (or was modified afterwards).
    ContactModelInvalid,
    /// A contact normal is not a unit vector.
    NotUnit,
    /// A builtin model code is unknown, or an option it does not have was asked for (e.g. no
    /// force clamp for YADE, whose laws always clamp).
    BuiltinModel,
    /// The builtin cannot realise this restitution: its parameter saturates before it.
    BuiltinUnreachable,
    /// A simulator release that is not a date or whose formula is not known (see
    /// [`crate::builtin::lammps::release_scale`]).
    BuiltinVersion,
    /// An integrator code other than `DC_INTEGRATOR_*`.
    Integrator,
    /// The normal law has no step-aware form (only Tsuji power laws with p ≤ 3 and Hertz have
    /// one; viscoelastic, adhesive DMT, elastic-plastic, JKR and p > 3 do not).
    StepUnsupported,
    /// The host's explicit step cannot realise this restitution with the step-aware damping
    /// (strong damping at steps near t_H/10).
    StepUnreachable,
    /// A planner input is outside its documented range (e.g. R_min > R_max, a solid fraction
    /// outside (0, 1), a tolerance ≥ 1).
    PlanRange,
    /// No plan meets the planner's tolerances: the real material itself misses one, no step a
    /// scene can run meets the e tolerance, or a contact this damped does not converge.
    PlanInfeasible,
    /// A fit got fewer than two points.
    FitTooFew,
    /// A fit's data cannot determine the model: all speeds equal, or all weights zero.
    FitDegenerate,
}
