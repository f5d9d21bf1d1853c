"""demcontact: exact contact mechanics for discrete-element (DEM) simulations.

The Python face of the demcontact Rust library: the same functions as its C ABI (names without
``dc_``), computed by the same compiled core, with numpy conventions:

* numeric arguments are scalars or array-likes and broadcast like numpy ufuncs; scalars give a
  float, arrays an ndarray of the broadcast shape;
* criteria and models are enums (``Criterion.FORCE``, ``Criterion.OVERLAP``, ``Model.HERTZ``);
* a status other than DC_OK raises a ``DemcontactError`` subclass carrying ``code`` and
  ``message`` (e.g. ``RestitutionRangeError``), never a NaN;
* force kernels: ``pair_*`` constructors return a ``Pair``; ``normal_force`` (checked,
  broadcasting) and ``normal_force_batch`` (zero-copy over float64 arrays, GIL released);
* full contact (tangential, rolling, twisting with caller-owned history): a ``ContactSpec``
  built by keyword, ``contact_model_init`` -> ``ContactModel``, ``contact_force`` (one contact)
  and ``contact_force_batch`` (structure of arrays, zero-copy, GIL released).

>>> import demcontact
>>> round(demcontact.alpha_from_e(0.5, 1.5, demcontact.Criterion.FORCE), 12)
0.570813678782

Derivations, precision and costs: the repository's README.md and docs/.
"""

from __future__ import annotations

import enum as _enum

from . import _native
from ._errors import *  # noqa: F401,F403  (the exception hierarchy)
from ._errors import __all__ as _errors_all
from ._native import (
    ContactModel,
    ContactSpec,
    contact_force,
    contact_force_batch,
    contact_force_energy,
    contact_force_spheres,
    contact_history_len,
    contact_model_init,
    contact_model_set_step,
    plan,
    contact_spec_init,
    builtin_for_lammps_release as _builtin_for_lammps_release,
    builtin_realised_e,
    builtin_value_for_e,
    builtin_yade_viscel_cn,
    fit_restitution,
    DurationPlan,
    Pair,
    alpha_from_e,
    contact_duration,
    contact_duration_level,
    contact_duration_planned,
    contact_trajectory,
    dt_crit,
    dt_for_accuracy,
    dt_linearised,
    dt_static,
    duration_plan_init,
    e_from_alpha,
    elastic_plastic_restitution,
    elastic_plastic_yield_speed,
    effective_modulus,
    energy_partition,
    hertz_stiffness,
    max_overlap,
    normal_force,
    normal_force_3d,
    normal_force_batch,
    normal_force_checked,
    omega0,
    pair_hertz,
    pair_linear,
    pair_powerlaw,
    pair_powerlaw_alpha,
    pair_viscoelastic,
    status_known,
    status_str,
    time_of_max_overlap,
    version,
    viscoelastic_a_from_e,
    viscoelastic_b,
    viscoelastic_b_from_e,
    viscoelastic_beta_from_e,
    viscoelastic_e,
    viscoelastic_e_of_speed,
    viscoelastic_e_reference,
    viscoelastic_e_series,
    viscoelastic_k_gamma,
    viscoelastic_speed_for_e,
)
from ._laws import Carry, Damping, Normal, Rolling, Tangential, Twisting
from ._types import ContactBatchResult, ContactEnergy, ContactResult, EnergyPartition, FitResult, Trajectory


class Criterion(_enum.IntEnum):
    """When a contact ends (C: DC_END_OVERLAP / DC_END_FORCE).

    OVERLAP: when the overlap returns to zero (solvers that do not clamp the normal force).
    FORCE: when the total normal force first reaches zero while unloading (solvers that clamp
    attractive forces: LIGGGHTS limitForce, LAMMPS limit_damping, Chrono, YADE).
    """

    OVERLAP = _native.END_OVERLAP
    FORCE = _native.END_FORCE


class Model(_enum.IntEnum):
    """Model family of a Pair (C: DC_MODEL_*)."""

    POWERLAW = _native.MODEL_POWERLAW
    HERTZ = _native.MODEL_HERTZ
    VISCOELASTIC = _native.MODEL_VISCOELASTIC


class Integrator(_enum.IntEnum):
    """The host's time integrator for ContactModel.set_step (C: DC_INTEGRATOR_*): velocity Verlet
    in the LAMMPS/LIGGGHTS order, or symplectic Euler (one map: the same correction)."""

    VELOCITY_VERLET = _native.INTEGRATOR_VELOCITY_VERLET
    SYMPLECTIC_EULER = _native.INTEGRATOR_SYMPLECTIC_EULER


#: Doubles of history per contact of the largest contact model; version of dc_contact_spec read.
CONTACT_HISTORY_MAX: int = _native.CONTACT_HISTORY_MAX
CONTACT_SPEC_VERSION: int = _native.CONTACT_SPEC_VERSION

#: Simulators' builtin contact models (C: DC_BUILTIN_*), for builtin_value_for_e and
#: builtin_realised_e.
Builtin = _enum.IntEnum("Builtin", dict(_native.BUILTIN_CODES), module=__name__)


def builtin_for_lammps_release(model, release):
    """The Builtin a LAMMPS release runs for ``model``: ``damping tsuji`` multiplies Tsuji's eta
    by sqrt(2) from the 2 Sep 2026 release on, so Builtin.LAMMPS_TSUJI_HERTZ becomes
    Builtin.LAMMPS_TSUJI_HERTZ_SQRT2 there. ``release``: "2026-09-02", "20260902", "2Sep2026",
    "2 Sep 2026" (as ``lmp -h`` prints it) or the int 20260902. Raises BuiltinVersionError for a
    release whose formula is not known or that is not a date (C: dc_builtin_for_lammps_release).
    """
    return Builtin(_builtin_for_lammps_release(model, release))


class FitModel(_enum.IntEnum):
    """Which model fit_restitution says the data require (C: DC_FIT_MODEL_*)."""

    CONSTANT = _native.FIT_MODEL_CONSTANT
    VISCOELASTIC = _native.FIT_MODEL_VISCOELASTIC


#: Status codes of the C ABI (Status.OK = 0, Status.ERR_RESTITUTION_RANGE = 6103, ...), from
#: the library's own table.
Status = _enum.IntEnum("Status", dict(_native.STATUS_CODES), module=__name__)


def _class_for_new_statuses() -> None:
    # A status the library knows but _errors.py does not name yet (added by a newer core) still
    # gets its own class, a direct DemcontactError subclass named after it
    # (ERR_BUILTIN_MODEL -> BuiltinModelError), so `except` by code class always works.
    from . import _errors

    for name, code in _native.STATUS_CODES.items():
        if code == 0 or code in _errors.STATUS_CLASSES:
            continue
        cls_name = "".join(w.capitalize() for w in name.removeprefix("ERR_").split("_")) + "Error"
        cls = type(cls_name, (_errors.DemcontactError,), {"status": code, "__module__": "demcontact._errors"})
        setattr(_errors, cls_name, cls)
        _errors.STATUS_CLASSES[code] = cls
        globals()[cls_name] = cls


_class_for_new_statuses()

#: Quadrature accuracy levels accepted by contact_duration_level, duration_plan_init and
#: contact_trajectory (fastest .. most accurate; the functions without a level use LEVEL_MAX).
LEVEL_MIN: int = _native.LEVEL_MIN
LEVEL_MAX: int = _native.LEVEL_MAX

__version__: str = version()

__all__ = [
    "Criterion",
    "Model",
    "Status",
    "Builtin",
    "FitModel",
    "FitResult",
    "LEVEL_MIN",
    "LEVEL_MAX",
    "EnergyPartition",
    "Trajectory",
    "Pair",
    "DurationPlan",
    "Normal",
    "Damping",
    "Tangential",
    "Rolling",
    "Twisting",
    "Carry",
    "Integrator",
    "CONTACT_HISTORY_MAX",
    "CONTACT_SPEC_VERSION",
    "ContactSpec",
    "ContactModel",
    "ContactResult",
    "ContactBatchResult",
    "ContactEnergy",
    "contact_spec_init",
    "contact_model_init",
    "contact_model_set_step",
    "contact_history_len",
    "contact_force",
    "contact_force_energy",
    "contact_force_spheres",
    "contact_force_batch",
    "plan",
    "alpha_from_e",
    "e_from_alpha",
    "elastic_plastic_restitution",
    "elastic_plastic_yield_speed",
    "max_overlap",
    "time_of_max_overlap",
    "contact_duration",
    "contact_duration_level",
    "duration_plan_init",
    "contact_duration_planned",
    "energy_partition",
    "contact_trajectory",
    "omega0",
    "hertz_stiffness",
    "effective_modulus",
    "dt_crit",
    "dt_linearised",
    "dt_static",
    "dt_for_accuracy",
    "viscoelastic_e",
    "viscoelastic_e_series",
    "viscoelastic_e_reference",
    "viscoelastic_b",
    "viscoelastic_e_of_speed",
    "viscoelastic_k_gamma",
    "viscoelastic_b_from_e",
    "viscoelastic_beta_from_e",
    "viscoelastic_a_from_e",
    "viscoelastic_speed_for_e",
    "pair_powerlaw",
    "pair_powerlaw_alpha",
    "pair_linear",
    "pair_hertz",
    "pair_viscoelastic",
    "normal_force",
    "normal_force_checked",
    "normal_force_batch",
    "normal_force_3d",
    "builtin_value_for_e",
    "builtin_for_lammps_release",
    "builtin_realised_e",
    "builtin_yade_viscel_cn",
    "fit_restitution",
    "status_str",
    "status_known",
    "version",
    *_errors_all,
]
