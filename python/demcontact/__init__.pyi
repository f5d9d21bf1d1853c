# Type stubs of the demcontact package (the functions are implemented in demcontact._native).
# Numeric arguments accept a float/int or any array-like of real numbers and broadcast like
# numpy ufuncs: all-scalar calls return float, otherwise an ndarray of the broadcast shape.

import enum
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Union, final

import numpy as np
import numpy.typing as npt

# The exception classes and their names in __all__ come from _errors (the one list of them):
# mypy takes `from m import __all__ as __all__` as this module's __all__, extended below.
from ._errors import *
from ._errors import __all__ as __all__

_Real = Union[float, int, np.floating, np.integer]
_ArrayLike = Union[_Real, npt.ArrayLike]
_FloatOrArray = Union[float, npt.NDArray[np.float64]]
_Code = Union[int, enum.IntEnum]

__version__: str
__all__ += [
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

class Builtin(enum.IntEnum):
    LIGGGHTS_HOOKE = 1
    LIGGGHTS_HERTZ = 2
    LAMMPS_COEFF_RESTITUTION = 3
    LAMMPS_TSUJI_HERTZ = 4
    LAMMPS_TSUJI_HOOKE = 5
    YADE_VISCEL_EN = 6
    YADE_MINDLIN_EN = 7
    YADE_MINDLIN_BETAN = 8
    LAMMPS_TSUJI_HERTZ_SQRT2 = 9
    LAMMPS_TSUJI_HOOKE_SQRT2 = 10

class FitModel(enum.IntEnum):
    CONSTANT = 0
    VISCOELASTIC = 1

# BEGIN GENERATED laws (cargo run -p xtask -- all)
class Normal(enum.IntEnum):
    HERTZ = 1
    POWERLAW = 2
    LINEAR = 3
    VISCOELASTIC = 4
    DMT = 5
    ELASTIC_PLASTIC = 6
    JKR = 7

class Damping(enum.IntEnum):
    NONE = 0
    RESTITUTION = 1

class Tangential(enum.IntEnum):
    NONE = 0
    LINEAR = 1
    MINDLIN = 2
    MINDLIN_RESCALE = 3

class Rolling(enum.IntEnum):
    NONE = 0
    CONSTANT = 1
    EPSD = 2

class Twisting(enum.IntEnum):
    NONE = 0
    SDS = 1

class Carry(enum.IntEnum):
    ROTATE = 0
    PROJECT = 1

# END GENERATED laws

class Integrator(enum.IntEnum):
    VELOCITY_VERLET = 0
    SYMPLECTIC_EULER = 1

CONTACT_HISTORY_MAX: int
CONTACT_SPEC_VERSION: int

class FitResult(NamedTuple):
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
    resid_viscoelastic: npt.NDArray[np.float64]
    resid_constant: npt.NDArray[np.float64]

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
    ERR_POISSON_RANGE = 6114
    ERR_PAIR_INVALID = 6120
    ERR_BUFFER_LAYOUT = 6121
    ERR_SPEC_VERSION = 6122
    ERR_SPEC_MODEL = 6123
    ERR_SPEC_UNSET = 6124
    ERR_CONTACT_MODEL_INVALID = 6125
    ERR_NOT_UNIT = 6126
    ERR_BUILTIN_MODEL = 6130
    ERR_BUILTIN_UNREACHABLE = 6131
    ERR_FIT_TOO_FEW = 6132
    ERR_FIT_DEGENERATE = 6133
    ERR_BUILTIN_VERSION = 6134
    ERR_INTEGRATOR = 6135
    ERR_STEP_UNSUPPORTED = 6136
    ERR_STEP_UNREACHABLE = 6137
    ERR_PLAN_RANGE = 6140
    ERR_PLAN_INFEASIBLE = 6141
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
        fast: bool = False,
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
def elastic_plastic_restitution(x: _ArrayLike) -> _FloatOrArray: ...
def elastic_plastic_yield_speed(
    e_star: _ArrayLike, r_eff: _ArrayLike, m_eff: _ArrayLike, p_y: _ArrayLike
) -> _FloatOrArray: ...

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
    fast: bool = False,
) -> npt.NDArray[np.float64]: ...
def normal_force_3d(
    pair: Pair, x1: Sequence[float], v1: Sequence[float], R1: _Real, m1: _Real, x2: Sequence[float], v2: Sequence[float], R2: _Real, m2: _Real
) -> npt.NDArray[np.float64]: ...

# corrected builtin inputs and the data fit
def builtin_value_for_e(model: _Code, clamp: Union[bool, int], e: _ArrayLike, wall: bool = ...) -> _FloatOrArray: ...
def builtin_for_lammps_release(model: _Code, release: Union[str, int]) -> Builtin: ...
def builtin_realised_e(model: _Code, clamp: Union[bool, int], value: _ArrayLike, wall: bool = ...) -> _FloatOrArray: ...
def builtin_yade_viscel_cn(e: _ArrayLike, kn: _ArrayLike, m_reduced: _ArrayLike) -> _FloatOrArray: ...
def fit_restitution(
    v: _ArrayLike,
    e: _ArrayLike,
    sigma: Optional[_ArrayLike] = None,
    criterion: Optional[_Code] = None,
    tol: Optional[_Real] = None,
    robust: bool = False,
) -> FitResult: ...

# status
def status_str(status: int) -> str: ...
def status_known(status: int) -> bool: ...
def version() -> str: ...

# full contact (normal + tangential + rolling + twisting, caller-owned history)
_Vec3 = Union[Sequence[float], npt.NDArray[np.floating]]
_F64 = npt.NDArray[np.float64]

class ContactResult(NamedTuple):
    force: _F64
    torque1: _F64
    torque2: _F64
    f_n: float
    ft: _F64
    sliding: bool
    rolling_sliding: bool

class ContactBatchResult(NamedTuple):
    f_n: _F64
    force: _F64
    torque1: _F64
    torque2: _F64

class ContactEnergy(NamedTuple):
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

@final
class ContactSpec:
    def __new__(
        cls,
        *,
        normal: Optional[_Code] = None,
        damping: Optional[_Code] = None,
        criterion: Optional[_Code] = None,
        tangential: Optional[_Code] = None,
        rolling: Optional[_Code] = None,
        twisting: Optional[_Code] = None,
        E1: Optional[_Real] = None,
        nu1: Optional[_Real] = None,
        E2: Optional[_Real] = None,
        nu2: Optional[_Real] = None,
        p: Optional[_Real] = None,
        k_n: Optional[_Real] = None,
        e_n: Optional[_Real] = None,
        visco_A: Optional[_Real] = None,
        mu: Optional[_Real] = None,
        k_t: Optional[_Real] = None,
        e_t: Optional[_Real] = None,
        mu_r: Optional[_Real] = None,
        k_r: Optional[_Real] = None,
        eta_r: Optional[_Real] = None,
        mu_tw: Optional[_Real] = None,
        k_tw: Optional[_Real] = None,
        eta_tw: Optional[_Real] = None,
        inertia_factor: Optional[_Real] = None,
        work_of_adhesion: Optional[_Real] = None,
        yield_pressure: Optional[_Real] = None,
        carry: Optional[_Code] = None,
    ) -> ContactSpec: ...
    @property
    def normal(self) -> int: ...
    @property
    def damping(self) -> int: ...
    @property
    def criterion(self) -> int: ...
    @property
    def tangential(self) -> int: ...
    @property
    def rolling(self) -> int: ...
    @property
    def twisting(self) -> int: ...
    @property
    def E1(self) -> float: ...
    @property
    def nu1(self) -> float: ...
    @property
    def E2(self) -> float: ...
    @property
    def nu2(self) -> float: ...
    @property
    def p(self) -> float: ...
    @property
    def k_n(self) -> float: ...
    @property
    def e_n(self) -> float: ...
    @property
    def visco_A(self) -> float: ...
    @property
    def mu(self) -> float: ...
    @property
    def k_t(self) -> float: ...
    @property
    def e_t(self) -> float: ...
    @property
    def mu_r(self) -> float: ...
    @property
    def k_r(self) -> float: ...
    @property
    def eta_r(self) -> float: ...
    @property
    def mu_tw(self) -> float: ...
    @property
    def k_tw(self) -> float: ...
    @property
    def eta_tw(self) -> float: ...
    @property
    def inertia_factor(self) -> float: ...
    @property
    def work_of_adhesion(self) -> float: ...
    @property
    def yield_pressure(self) -> float: ...
    @property
    def carry(self) -> int: ...
    def model(self) -> ContactModel: ...

@final
class ContactModel:
    @property
    def history_len(self) -> int: ...
    @property
    def normal(self) -> Pair: ...
    @property
    def tangential(self) -> int: ...
    @property
    def rolling(self) -> int: ...
    @property
    def twisting(self) -> int: ...
    @property
    def carry(self) -> int: ...
    @property
    def mu(self) -> float: ...
    @property
    def kt(self) -> float: ...
    @property
    def zeta_t(self) -> float: ...
    @property
    def kappa(self) -> float: ...
    @property
    def mu_r(self) -> float: ...
    @property
    def k_r(self) -> float: ...
    @property
    def eta_r(self) -> float: ...
    @property
    def mu_tw(self) -> float: ...
    @property
    def k_tw(self) -> float: ...
    @property
    def eta_tw(self) -> float: ...
    @property
    def step_aware(self) -> bool: ...
    def set_step(self, dt: _Real, integrator: Union[_Code, str, None] = None) -> ContactModel: ...
    def to_bytes(self) -> bytes: ...

def contact_spec_init() -> ContactSpec: ...
def contact_model_init(spec: ContactSpec) -> ContactModel: ...
def contact_model_set_step(model: ContactModel, dt: _Real, integrator: Union[_Code, str, None] = None) -> ContactModel: ...
def contact_history_len(model: ContactModel) -> int: ...
def contact_force_energy(
    model: ContactModel,
    n: _Vec3,
    overlap: _Real,
    v1: _Vec3,
    v2: _Vec3,
    w1: _Vec3,
    w2: _Vec3,
    r1: _Real,
    r2: _Real,
    m1: _Real,
    m2: _Real,
    dt: _Real,
    history: Optional[_F64] = None,
) -> tuple[ContactResult, ContactEnergy]: ...
def contact_force(
    model: ContactModel,
    n: _Vec3,
    overlap: _Real,
    v1: _Vec3,
    v2: _Vec3,
    w1: _Vec3,
    w2: _Vec3,
    r1: _Real,
    r2: _Real,
    m1: _Real,
    m2: _Real,
    dt: _Real,
    history: Optional[_F64] = None,
) -> ContactResult: ...
def contact_force_spheres(
    model: ContactModel,
    x1: _Vec3,
    x2: _Vec3,
    v1: _Vec3,
    v2: _Vec3,
    w1: _Vec3,
    w2: _Vec3,
    r1: _Real,
    r2: _Real,
    m1: _Real,
    m2: _Real,
    dt: _Real,
    history: Optional[_F64] = None,
) -> ContactResult: ...
def contact_force_batch(
    model: ContactModel,
    normal: _ArrayLike,
    overlap: _ArrayLike,
    v1: _ArrayLike,
    v2: _ArrayLike,
    w1: Optional[_ArrayLike],
    w2: Optional[_ArrayLike],
    r1: _ArrayLike,
    r2: _ArrayLike,
    m1: _ArrayLike,
    m2: _ArrayLike,
    dt: _Real,
    history: Optional[_F64] = None,
    *,
    out: Optional[tuple[_F64, _F64, _F64, _F64]] = None,
) -> ContactBatchResult: ...

# scene planner
def plan(
    *,
    youngs: _Real,
    poisson: _Real,
    density: _Real,
    restitution: _Real,
    radius_min: _Real,
    radius_max: _Real,
    v_max: _Real,
    depth: _Real,
    overlap_tol: _Real,
    e_tol: _Real,
    gravity: Optional[_Real] = None,
    pressure: Optional[_Real] = None,
    solid_fraction: Optional[_Real] = None,
    coordination: Optional[_Real] = None,
    load_factor: Optional[_Real] = None,
    friction: Optional[_Real] = None,
    rolling_friction: Optional[_Real] = None,
    static_tol: Optional[_Real] = None,
    duration_tol: Optional[_Real] = None,
    criterion: Optional[_Code] = None,
    walls: Union[bool, int, None] = None,
    stability_fraction: Optional[_Real] = None,
    conventional_divisor: Optional[_Real] = None,
) -> Dict[str, Any]: ...
