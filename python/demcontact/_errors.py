"""Exceptions: one class per status family of the C ABI, one subclass per status code.

Every status the library can return maps to exactly one class below (``STATUS_CLASSES``); each
exception carries the numeric ``code`` (6101..6199, as in ``include/demcontact.h``), the
library's ``message`` (``dc_status_str``), the Python ``function`` that raised it and a ``detail``
naming the inputs (and, for arrays, the index of the first failing element). Family classes also
derive from the built-in exception a Python user would expect (``ValueError`` for bad inputs,
``ArithmeticError`` for overflow, ``RuntimeError`` for failures that should never happen), so
``except ValueError`` keeps working in generic code.
"""

from __future__ import annotations

from typing import Dict, Optional, Type


class DemcontactError(Exception):
    """Base class of every error reported by the demcontact library (a status code != DC_OK)."""

    #: status code of this class (None on family classes covering several codes)
    status: Optional[int] = None

    def __init__(self, code: int, message: str, function: str = "", detail: str = "") -> None:
        self.code = int(code)
        self.message = message
        self.function = function
        self.detail = detail
        where = f"{function}: " if function else ""
        tail = f" {detail}" if detail else ""
        super().__init__(f"{where}{message} (status {self.code}){tail}")

    def __reduce__(self):  # picklable (multiprocessing)
        return (type(self), (self.code, self.message, self.function, self.detail))


# ---- families -------------------------------------------------------------------------------


class InputError(DemcontactError, ValueError):
    """An input is outside the function's domain (NaN/inf, e outside (0, 1], p < 1, ...)."""


class ResultRangeError(DemcontactError, ArithmeticError):
    """Valid but extreme input whose result is not representable as a finite double (6108)."""

    status = 6108


class NoEventError(DemcontactError, ValueError):
    """The requested event never happens (e.g. an overdamped contact under Criterion.OVERLAP, 6111)."""

    status = 6111


class UsageError(DemcontactError, ValueError):
    """A buffer, pair or plan handed to the library is unusable (size, layout, not initialised)."""


class InternalError(DemcontactError, RuntimeError):
    """A search with no answer within its bounds (NoConvergenceError), or a caught panic
    (PanicError: never seen, please report)."""


# ---- one class per code ---------------------------------------------------------------------


class NotFiniteError(InputError):
    """An input was NaN or +-infinity (6102)."""

    status = 6102


class RestitutionRangeError(InputError):
    """The restitution coefficient e is outside (0, 1] (6103)."""

    status = 6103


class ExponentRangeError(InputError):
    """The force-law exponent p is below 1 (6104)."""

    status = 6104


class NotPositiveError(InputError):
    """A speed, stiffness, mass, omega0 (...) that must be > 0 was not (6105)."""

    status = 6105


class PoissonRangeError(NotPositiveError):
    """A Poisson ratio outside (-1, 0.5] (6114). A subclass of NotPositiveError, the status such a
    ratio had before it had its own, so ``except NotPositiveError`` still catches it."""

    status = 6114


class NegativeError(InputError):
    """A quantity that must be >= 0 (damping coefficient alpha, A, b, ...) was negative (6106)."""

    status = 6106


class CriterionError(InputError):
    """The criterion is neither Criterion.OVERLAP nor Criterion.FORCE (6107)."""

    status = 6107


class LevelError(InputError):
    """A quadrature accuracy level outside LEVEL_MIN..LEVEL_MAX (6112)."""

    status = 6112


class BuiltinModelError(InputError):
    """Unknown Builtin code, or an option the builtin model does not have (6130)."""

    status = 6130


class BuiltinUnreachableError(InputError):
    """The builtin's own parameter saturates before the target e (6131)."""

    status = 6131


class FitTooFewError(InputError):
    """Fewer than two data points to fit (6132)."""

    status = 6132


class FitDegenerateError(InputError):
    """All measured speeds are equal: the speed dependence cannot be fitted (6133)."""

    status = 6133


class BuiltinVersionError(InputError):
    """A LAMMPS release that is not a date or whose damping tsuji formula is not known (6134)."""

    status = 6134


class IntegratorError(InputError):
    """An integrator other than Integrator.VELOCITY_VERLET or Integrator.SYMPLECTIC_EULER (6135)."""

    status = 6135


class StepUnsupportedError(InputError):
    """ContactModel.set_step on a normal law with no step-aware form (viscoelastic, DMT,
    elastic-plastic, JKR, a power law with p > 3; 6136)."""

    status = 6136


class StepUnreachableError(InputError):
    """The host's explicit step cannot realise this e_n with the step-aware damping (strong
    damping, e_n well below 0.1, at steps near t_H/10; 6137)."""

    status = 6137


class PlanRangeError(InputError):
    """A plan() input outside its documented range (radius_max < radius_min, a tolerance >= 1,
    ...; 6140). The exception's ``field`` names the input."""

    status = 6140


class PlanInfeasibleError(InputError):
    """plan(): no plan meets the tolerances: the real material itself misses the one named by
    the exception's ``field``, or no step a scene can run meets the e tolerance (6141)."""

    status = 6141


class NotUnitError(InputError):
    """A contact normal that is not a unit vector (| |n|^2 - 1 | > 1e-6, 6126)."""

    status = 6126


class SpecModelError(InputError):
    """ContactSpec: unknown sub-model or an invalid combination of sub-models (6123)."""

    status = 6123


class SpecUnsetError(InputError):
    """ContactSpec: a parameter the chosen sub-models need was left unset (6124)."""

    status = 6124


class SpecVersionError(UsageError):
    """A dc_contact_spec of another version or size (6122; cannot happen through ContactSpec)."""

    status = 6122


class ContactModelInvalidError(UsageError):
    """A contact model not made by contact_model_init, or altered since (6125)."""

    status = 6125


class NullPointerError(UsageError):
    """A required buffer was missing (6101)."""

    status = 6101


class BufferTooShortError(UsageError):
    """A buffer is too short or a sample count too small (6110)."""

    status = 6110


class BufferLayoutError(UsageError):
    """A buffer is misaligned, or an output overlaps an input (6121)."""

    status = 6121


class PairInvalidError(UsageError):
    """A pair not made by a pair_* constructor (6120)."""

    status = 6120


class PlanError(UsageError):
    """A duration plan not made by duration_plan_init (6113)."""

    status = 6113


class NoConvergenceError(InternalError):
    """A search or iteration found no answer within its bounds (6109), e.g. dt_for_accuracy at
    e -> 0 or very tight tolerances, where no step it can check meets the tolerance."""

    status = 6109


class PanicError(InternalError):
    """A panic caught at the library boundary (6199; never seen: please report)."""

    status = 6199


STATUS_CLASSES: Dict[int, Type[DemcontactError]] = {
    cls.status: cls
    for cls in (
        NotFiniteError,
        RestitutionRangeError,
        ExponentRangeError,
        NotPositiveError,
        PoissonRangeError,
        NegativeError,
        CriterionError,
        LevelError,
        BuiltinModelError,
        BuiltinUnreachableError,
        FitTooFewError,
        FitDegenerateError,
        BuiltinVersionError,
        IntegratorError,
        StepUnsupportedError,
        StepUnreachableError,
        PlanRangeError,
        PlanInfeasibleError,
        NotUnitError,
        SpecModelError,
        SpecUnsetError,
        SpecVersionError,
        ContactModelInvalidError,
        ResultRangeError,
        NoEventError,
        NullPointerError,
        BufferTooShortError,
        BufferLayoutError,
        PairInvalidError,
        PlanError,
        NoConvergenceError,
        PanicError,
    )
    if cls.status is not None
}


def _from_status(code: int, message: str, function: str, detail: str) -> DemcontactError:
    """The exception instance for a status code (called by the extension module)."""
    cls = STATUS_CLASSES.get(int(code), DemcontactError)
    return cls(code, message, function, detail)


__all__ = [
    "DemcontactError",
    "InputError",
    "ResultRangeError",
    "NoEventError",
    "UsageError",
    "InternalError",
    "NotFiniteError",
    "RestitutionRangeError",
    "ExponentRangeError",
    "NotPositiveError",
    "PoissonRangeError",
    "NegativeError",
    "CriterionError",
    "LevelError",
    "BuiltinModelError",
    "BuiltinUnreachableError",
    "FitTooFewError",
    "FitDegenerateError",
    "BuiltinVersionError",
    "IntegratorError",
    "StepUnsupportedError",
    "StepUnreachableError",
    "PlanRangeError",
    "PlanInfeasibleError",
    "NotUnitError",
    "SpecModelError",
    "SpecUnsetError",
    "SpecVersionError",
    "ContactModelInvalidError",
    "NullPointerError",
    "BufferTooShortError",
    "BufferLayoutError",
    "PairInvalidError",
    "PlanError",
    "NoConvergenceError",
    "PanicError",
    "STATUS_CLASSES",
]
