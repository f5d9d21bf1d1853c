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
