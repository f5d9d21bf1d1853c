"""Named results (tuples, so they unpack like the C output arguments)."""

from __future__ import annotations

from typing import NamedTuple, Union

import numpy as np

FloatOrArray = Union[float, np.ndarray]


class EnergyPartition(NamedTuple):
    """Energy partition of a collision as fractions of the impact energy m v0^2/2.

    loading + unloading + returned + clamped = 1; e is the restitution under the criterion.
    """

    e: FloatOrArray
    loading: FloatOrArray
    unloading: FloatOrArray
    returned: FloatOrArray
    clamped: FloatOrArray


class Trajectory(NamedTuple):
    """One sampled collision: time [s], overlap [m], overlap rate [m/s], normal force [N]."""

    t: np.ndarray
    delta: np.ndarray
    v: np.ndarray
    force: np.ndarray


class FitResult(NamedTuple):
    """Result of fit_restitution: the C dc_fit_result's fields and the residuals.

    Viscoelastic model e(v) = viscoelastic_e(beta v^(1/5)); constant model e(v) = e_const;
    model is FitModel.CONSTANT when the two differ by at most tol over [v_min, v_max].
    """

    beta: float
    beta_se: float
    e_const: float
    e_const_se: float
    chi2_viscoelastic: float
    chi2_constant: float
    max_residual_viscoelastic: float
    max_residual_constant: float
    v_min: float
    v_max: float
    e_viscoelastic_at_v_min: float
    e_viscoelastic_at_v_max: float
    max_model_deviation: float
    model: int
    se_from_scatter: bool
    iterations: int
    robust: bool
    resid_viscoelastic: np.ndarray
    resid_constant: np.ndarray


class ContactResult(NamedTuple):
    """One contact (C: dc_contact_result): force, torques [N, N m] on body 1 / body 2 and the
    tangential force on body 1 (numpy 3-vectors), the applied normal force f_n [N] (positive
    repulsive), whether the Coulomb limit (sliding) or the rolling/twisting limit was reached."""

    force: np.ndarray
    torque1: np.ndarray
    torque2: np.ndarray
    f_n: float
    ft: np.ndarray
    sliding: bool
    rolling_sliding: bool


class ContactBatchResult(NamedTuple):
    """n contacts (C: dc_contact_batch outputs): f_n (n,), force, torque1, torque2 (n, 3)."""

    f_n: np.ndarray
    force: np.ndarray
    torque1: np.ndarray
    torque2: np.ndarray


class ContactEnergy(NamedTuple):
    """The energy ledger of one contact step [J] (C: dc_contact_energy, from
    contact_force_energy): what the dashpots and slips removed during the step (``dissipated`` is
    their sum) and the elastic energy left in the history springs. Energy a law creates
    (Tangential.MINDLIN's gain) is not counted, so it shows up as a gain. Definitions:
    docs/force.md."""

    dissipated: float
    normal_damping: float
    tangential_damping: float
    tangential_slip: float
    tangential_elastic: float
    rolling_damping: float
    rolling_slip: float
    rolling_elastic: float
    twisting_damping: float
    twisting_slip: float
    twisting_elastic: float
