# Type stubs of the demcontact package (the functions are implemented in demcontact._native).
# Numeric arguments accept a float/int or any array-like of real numbers and broadcast like
# numpy ufuncs: all-scalar calls return float, otherwise an ndarray of the broadcast shape.

import enum
from typing import List, NamedTuple, Optional, Sequence, Union, final

import numpy as np
import numpy.typing as npt

from ._errors import (
    STATUS_CLASSES as STATUS_CLASSES,
    BufferLayoutError as BufferLayoutError,
    BufferTooShortError as BufferTooShortError,
    CriterionError as CriterionError,
    DemcontactError as DemcontactError,
    ExponentRangeError as ExponentRangeError,
    InputError as InputError,
    InternalError as InternalError,
    LevelError as LevelError,
    NegativeError as NegativeError,
    NoConvergenceError as NoConvergenceError,
    NoEventError as NoEventError,
    NotFiniteError as NotFiniteError,
    NotPositiveError as NotPositiveError,
    NullPointerError as NullPointerError,
    PairInvalidError as PairInvalidError,
    PanicError as PanicError,
    PlanError as PlanError,
    RestitutionRangeError as RestitutionRangeError,
    ResultRangeError as ResultRangeError,
    UsageError as UsageError,
)

_Real = Union[float, int, np.floating, np.integer]
_ArrayLike = Union[_Real, npt.ArrayLike]
_FloatOrArray = Union[float, npt.NDArray[np.float64]]
_Code = Union[int, enum.IntEnum]

__version__: str
__all__: list[str] = [
    "Criterion",
    "Model",
    "Status",
    "LEVEL_MIN",
    "LEVEL_MAX",
    "EnergyPartition",
    "Trajectory",
    "Pair",
    "DurationPlan",
    "alpha_from_e",
    "e_from_alpha",
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
    "status_str",
    "status_known",
    "version",
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
    "NegativeError",
    "CriterionError",
    "LevelError",
    "NullPointerError",
    "BufferTooShortError",
    "BufferLayoutError",
    "PairInvalidError",
    "PlanError",
    "NoConvergenceError",
    "PanicError",
    "STATUS_CLASSES",
]
LEVEL_MIN: int
LEVEL_MAX: int

class Criterion(enum.IntEnum):
    OVERLAP = 0
    FORCE = 1

class Model(enum.IntEnum):
    POWERLAW = 1
    HERTZ = 2
    VISCOELASTIC = 3

class Status(enum.IntEnum):
    OK = 0
    ERR_NULL_POINTER = 6101
    ERR_NOT_FINITE = 6102
    ERR_RESTITUTION_RANGE = 6103
    ERR_EXPONENT_RANGE = 6104
    ERR_NOT_POSITIVE = 6105
    ERR_NEGATIVE = 6106
    ERR_CRITERION = 6107
    ERR_RESULT_RANGE = 6108
    ERR_NO_CONVERGENCE = 6109
    ERR_BUFFER_TOO_SHORT = 6110
    ERR_NO_EVENT = 6111
    ERR_LEVEL = 6112
    ERR_PLAN = 6113
    ERR_PAIR_INVALID = 6120
    ERR_BUFFER_LAYOUT = 6121
    ERR_INTERNAL = 6199

class EnergyPartition(NamedTuple):
    e: _FloatOrArray
    loading: _FloatOrArray
    unloading: _FloatOrArray
    returned: _FloatOrArray
    clamped: _FloatOrArray

class Trajectory(NamedTuple):
    t: npt.NDArray[np.float64]
    delta: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    force: npt.NDArray[np.float64]

@final
class Pair:
    @property
    def model(self) -> Model: ...
    @property
    def kernel(self) -> int: ...
    @property
    def criterion(self) -> Criterion: ...
    @property
    def clamp(self) -> bool: ...
    @property
    def p(self) -> float: ...
    @property
    def stiffness(self) -> float: ...
    @property
    def alpha(self) -> float: ...
    @property
    def damping_a(self) -> float: ...
    @property
    def e(self) -> float: ...
    @property
    def k(self) -> float: ...
    @property
    def c(self) -> float: ...
    @property
    def h(self) -> float: ...
    @property
    def reads(self) -> List[str]: ...
    def normal_force(
        self,
        overlap: _ArrayLike,
        vn: Optional[_ArrayLike] = None,
        r_eff: Optional[_ArrayLike] = None,
        m_eff: Optional[_ArrayLike] = None,
    ) -> _FloatOrArray: ...
    def normal_force_batch(
        self,
        overlap: _ArrayLike,
        vn: Optional[_ArrayLike] = None,
        r_eff: Optional[_ArrayLike] = None,
        m_eff: Optional[_ArrayLike] = None,
        *,
        out: Optional[npt.NDArray[np.float64]] = None,
        check: bool = True,
    ) -> npt.NDArray[np.float64]: ...

@final
class DurationPlan:
    @property
    def p(self) -> float: ...
    @property
    def level(self) -> int: ...
    def contact_duration(self, alpha: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...

# calibration
def alpha_from_e(e: _ArrayLike, p: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def e_from_alpha(alpha: _ArrayLike, p: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...

# material
def hertz_stiffness(E1: _ArrayLike, nu1: _ArrayLike, R1: _ArrayLike, E2: _ArrayLike, nu2: _ArrayLike, R2: _ArrayLike) -> _FloatOrArray: ...
def effective_modulus(E1: _ArrayLike, nu1: _ArrayLike, E2: _ArrayLike, nu2: _ArrayLike) -> _FloatOrArray: ...
def omega0(k: _ArrayLike, m: _ArrayLike) -> _FloatOrArray: ...

# observables
def max_overlap(p: _ArrayLike, alpha: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike) -> _FloatOrArray: ...
def time_of_max_overlap(p: _ArrayLike, alpha: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike) -> _FloatOrArray: ...
def contact_duration(p: _ArrayLike, alpha: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def contact_duration_level(p: _ArrayLike, alpha: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike, criterion: _Code, level: int) -> _FloatOrArray: ...
def duration_plan_init(p: _Real, level: Optional[int] = None) -> DurationPlan: ...
def contact_duration_planned(plan: DurationPlan, alpha: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def energy_partition(p: _ArrayLike, alpha: _ArrayLike, criterion: _Code) -> EnergyPartition: ...
def contact_trajectory(
    p: _Real, alpha: _Real, v0: _Real, omega0: _Real, mass: _Real, criterion: _Code, level: Optional[int] = None, n: int = 256
) -> Trajectory: ...

# time steps
def dt_crit(p: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike) -> _FloatOrArray: ...
def dt_linearised(p: _ArrayLike, v0: _ArrayLike, omega0: _ArrayLike) -> _FloatOrArray: ...
def dt_static(p: _ArrayLike, alpha: _ArrayLike, omega0: _ArrayLike, accel: _ArrayLike) -> _FloatOrArray: ...
def dt_for_accuracy(p: _ArrayLike, e: _ArrayLike, criterion: _Code, v0: _ArrayLike, omega0: _ArrayLike, tol: _ArrayLike) -> _FloatOrArray: ...

# viscoelastic spheres
def viscoelastic_e(b: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_e_series(b: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_e_reference(b: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_b(k: _ArrayLike, gamma: _ArrayLike, v: _ArrayLike) -> _FloatOrArray: ...
def viscoelastic_e_of_speed(k: _ArrayLike, gamma: _ArrayLike, v: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_k_gamma(rho: _ArrayLike, a: _ArrayLike, m_eff: _ArrayLike) -> tuple[_FloatOrArray, _FloatOrArray]: ...
def viscoelastic_b_from_e(e: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_beta_from_e(e: _ArrayLike, v_ref: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_a_from_e(e: _ArrayLike, v_ref: _ArrayLike, rho: _ArrayLike, m_eff: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...
def viscoelastic_speed_for_e(e: _ArrayLike, beta: _ArrayLike, criterion: _Code) -> _FloatOrArray: ...

# force kernels
def pair_powerlaw(p: _Real, k: _Real, e: _Real, criterion: _Code) -> Pair: ...
def pair_powerlaw_alpha(p: _Real, k: _Real, alpha: _Real, criterion: _Code) -> Pair: ...
def pair_linear(k: _Real, e: _Real, criterion: _Code) -> Pair: ...
def pair_hertz(E1: _Real, nu1: _Real, E2: _Real, nu2: _Real, e: _Real, criterion: _Code) -> Pair: ...
def pair_viscoelastic(E1: _Real, nu1: _Real, E2: _Real, nu2: _Real, A: _Real, criterion: _Code) -> Pair: ...
def normal_force(
    pair: Pair, overlap: _ArrayLike, vn: Optional[_ArrayLike] = None, r_eff: Optional[_ArrayLike] = None, m_eff: Optional[_ArrayLike] = None
) -> _FloatOrArray: ...
def normal_force_checked(
    pair: Pair, overlap: _ArrayLike, vn: Optional[_ArrayLike] = None, r_eff: Optional[_ArrayLike] = None, m_eff: Optional[_ArrayLike] = None
) -> _FloatOrArray: ...
def normal_force_batch(
    pair: Pair,
    overlap: _ArrayLike,
    vn: Optional[_ArrayLike] = None,
    r_eff: Optional[_ArrayLike] = None,
    m_eff: Optional[_ArrayLike] = None,
    *,
    out: Optional[npt.NDArray[np.float64]] = None,
    check: bool = True,
) -> npt.NDArray[np.float64]: ...
def normal_force_3d(
    pair: Pair, x1: Sequence[float], v1: Sequence[float], R1: _Real, m1: _Real, x2: Sequence[float], v2: Sequence[float], R2: _Real, m2: _Real
) -> npt.NDArray[np.float64]: ...

# status
def status_str(status: int) -> str: ...
def status_known(status: int) -> bool: ...
def version() -> str: ...
