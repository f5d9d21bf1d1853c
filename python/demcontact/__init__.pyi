# Type stubs of the demcontact package (the functions are implemented in demcontact._native).
# Numeric arguments accept a float/int or any array-like of real numbers and broadcast like
# numpy ufuncs: all-scalar calls return float, otherwise an ndarray of the broadcast shape.

import enum
from typing import List, NamedTuple, Optional, Sequence, Union

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

Real = Union[float, int, np.floating, np.integer]
ArrayLike = Union[Real, npt.ArrayLike]
FloatOrArray = Union[float, npt.NDArray[np.float64]]
Code = Union[int, enum.IntEnum]

__version__: str
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
    e: FloatOrArray
    loading: FloatOrArray
    unloading: FloatOrArray
    returned: FloatOrArray
    clamped: FloatOrArray

class Trajectory(NamedTuple):
    t: npt.NDArray[np.float64]
    delta: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    force: npt.NDArray[np.float64]

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
        overlap: ArrayLike,
        vn: Optional[ArrayLike] = None,
        r_eff: Optional[ArrayLike] = None,
        m_eff: Optional[ArrayLike] = None,
    ) -> FloatOrArray: ...
    def normal_force_batch(
        self,
        overlap: ArrayLike,
        vn: Optional[ArrayLike] = None,
        r_eff: Optional[ArrayLike] = None,
        m_eff: Optional[ArrayLike] = None,
        *,
        out: Optional[npt.NDArray[np.float64]] = None,
        check: bool = True,
    ) -> npt.NDArray[np.float64]: ...

class DurationPlan:
    @property
    def p(self) -> float: ...
    @property
    def level(self) -> int: ...
    def contact_duration(self, alpha: ArrayLike, v0: ArrayLike, omega0: ArrayLike, criterion: Code) -> FloatOrArray: ...

# calibration
def alpha_from_e(e: ArrayLike, p: ArrayLike, criterion: Code) -> FloatOrArray: ...
def e_from_alpha(alpha: ArrayLike, p: ArrayLike, criterion: Code) -> FloatOrArray: ...

# material
def hertz_stiffness(E1: ArrayLike, nu1: ArrayLike, R1: ArrayLike, E2: ArrayLike, nu2: ArrayLike, R2: ArrayLike) -> FloatOrArray: ...
def effective_modulus(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike) -> FloatOrArray: ...
def omega0(k: ArrayLike, m: ArrayLike) -> FloatOrArray: ...

# observables
def max_overlap(p: ArrayLike, alpha: ArrayLike, v0: ArrayLike, omega0: ArrayLike) -> FloatOrArray: ...
def time_of_max_overlap(p: ArrayLike, alpha: ArrayLike, v0: ArrayLike, omega0: ArrayLike) -> FloatOrArray: ...
def contact_duration(p: ArrayLike, alpha: ArrayLike, v0: ArrayLike, omega0: ArrayLike, criterion: Code) -> FloatOrArray: ...
def contact_duration_level(p: ArrayLike, alpha: ArrayLike, v0: ArrayLike, omega0: ArrayLike, criterion: Code, level: int) -> FloatOrArray: ...
def duration_plan_init(p: Real, level: Optional[int] = None) -> DurationPlan: ...
def contact_duration_planned(plan: DurationPlan, alpha: ArrayLike, v0: ArrayLike, omega0: ArrayLike, criterion: Code) -> FloatOrArray: ...
def energy_partition(p: ArrayLike, alpha: ArrayLike, criterion: Code) -> EnergyPartition: ...
def contact_trajectory(
    p: Real, alpha: Real, v0: Real, omega0: Real, mass: Real, criterion: Code, level: Optional[int] = None, n: int = 256
) -> Trajectory: ...

# time steps
def dt_crit(p: ArrayLike, v0: ArrayLike, omega0: ArrayLike) -> FloatOrArray: ...
def dt_linearised(p: ArrayLike, v0: ArrayLike, omega0: ArrayLike) -> FloatOrArray: ...
def dt_static(p: ArrayLike, alpha: ArrayLike, omega0: ArrayLike, accel: ArrayLike) -> FloatOrArray: ...
def dt_for_accuracy(p: ArrayLike, e: ArrayLike, criterion: Code, v0: ArrayLike, omega0: ArrayLike, tol: ArrayLike) -> FloatOrArray: ...

# viscoelastic spheres
def viscoelastic_e(b: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_e_series(b: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_e_reference(b: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_b(k: ArrayLike, gamma: ArrayLike, v: ArrayLike) -> FloatOrArray: ...
def viscoelastic_e_of_speed(k: ArrayLike, gamma: ArrayLike, v: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_k_gamma(rho: ArrayLike, a: ArrayLike, m_eff: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]: ...
def viscoelastic_b_from_e(e: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_beta_from_e(e: ArrayLike, v_ref: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_a_from_e(e: ArrayLike, v_ref: ArrayLike, rho: ArrayLike, m_eff: ArrayLike, criterion: Code) -> FloatOrArray: ...
def viscoelastic_speed_for_e(e: ArrayLike, beta: ArrayLike, criterion: Code) -> FloatOrArray: ...

# force kernels
def pair_powerlaw(p: Real, k: Real, e: Real, criterion: Code) -> Pair: ...
def pair_powerlaw_alpha(p: Real, k: Real, alpha: Real, criterion: Code) -> Pair: ...
def pair_linear(k: Real, e: Real, criterion: Code) -> Pair: ...
def pair_hertz(E1: Real, nu1: Real, E2: Real, nu2: Real, e: Real, criterion: Code) -> Pair: ...
def pair_viscoelastic(E1: Real, nu1: Real, E2: Real, nu2: Real, A: Real, criterion: Code) -> Pair: ...
def normal_force(
    pair: Pair, overlap: ArrayLike, vn: Optional[ArrayLike] = None, r_eff: Optional[ArrayLike] = None, m_eff: Optional[ArrayLike] = None
) -> FloatOrArray: ...
def normal_force_checked(
    pair: Pair, overlap: ArrayLike, vn: Optional[ArrayLike] = None, r_eff: Optional[ArrayLike] = None, m_eff: Optional[ArrayLike] = None
) -> FloatOrArray: ...
def normal_force_batch(
    pair: Pair,
    overlap: ArrayLike,
    vn: Optional[ArrayLike] = None,
    r_eff: Optional[ArrayLike] = None,
    m_eff: Optional[ArrayLike] = None,
    *,
    out: Optional[npt.NDArray[np.float64]] = None,
    check: bool = True,
) -> npt.NDArray[np.float64]: ...
def normal_force_3d(
    pair: Pair, x1: Sequence[float], v1: Sequence[float], R1: Real, m1: Real, x2: Sequence[float], v2: Sequence[float], R2: Real, m2: Real
) -> npt.NDArray[np.float64]: ...

# status
def status_str(status: int) -> str: ...
def status_known(status: int) -> bool: ...
def version() -> str: ...
