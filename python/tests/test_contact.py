"""The full-contact binding (ContactSpec, contact_model_init, contact_force, contact_force_spheres,
contact_force_batch) against the C ABI through ctypes on the same inputs: the same status, and on
success the same bytes (models, forces, torques, and the history after every step of a many-step
evolution); then every error path of the marshalling (shapes, dtypes, layouts, read-only history).
"""

from __future__ import annotations

import ctypes as C
import math
import zlib

import numpy as np
import pytest

import demcontact as dc

import cabi_contact as cc
from cabi import Pair as CPair

INF = math.inf
F, O = dc.Criterion.FORCE, dc.Criterion.OVERLAP

DT_STEP = 2e-7  # the host step of the step-aware specs below

# Specs exercising every sub-model (as keyword dicts usable by both ContactSpec and c_spec).
HERTZ_FULL = dict(
    normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.8, E1=7e10, nu1=0.3, E2=2e11, nu2=0.28,
    tangential=dc.Tangential.MINDLIN, mu=0.3, e_t=0.6, rolling=dc.Rolling.EPSD, mu_r=0.05, eta_r=0.3,
    twisting=dc.Twisting.SDS, mu_tw=2e-4, k_tw=0.02, eta_tw=0.2,
)
SPECS = {
    "hertz_full": HERTZ_FULL,
    "hertz_wall_mindlin": dict(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.98, E1=3.8e11, nu1=0.23, E2=INF, nu2=0.23, tangential=dc.Tangential.MINDLIN, mu=0.092),
    "linear_linear_constant": dict(normal=dc.Normal.LINEAR, k_n=1e4, damping=dc.Damping.RESTITUTION, e_n=0.5, criterion=O, tangential=dc.Tangential.LINEAR, k_t=8e3, e_t=0.4, mu=0.5, rolling=dc.Rolling.CONSTANT, mu_r=0.02),
    "powerlaw_linear_epsd": dict(normal=dc.Normal.POWERLAW, p=1.7, k_n=3e7, damping=dc.Damping.RESTITUTION, e_n=0.3, tangential=dc.Tangential.LINEAR, k_t=5e3, mu=0.2, rolling=dc.Rolling.EPSD, mu_r=0.1, k_r=1e-3),
    "viscoelastic_mindlin": dict(normal=dc.Normal.VISCOELASTIC, visco_A=2e-6, E1=1e8, nu1=0.45, E2=1e8, nu2=0.45, tangential=dc.Tangential.MINDLIN, mu=0.8, e_t=0.9, twisting=dc.Twisting.SDS, mu_tw=1e-4, k_tw=1e-3),
    "elastic_plastic_full": dict(normal=dc.Normal.ELASTIC_PLASTIC, yield_pressure=2e8, E1=7e10, nu1=0.3, E2=7e10, nu2=0.3, tangential=dc.Tangential.MINDLIN_RESCALE, mu=0.3, rolling=dc.Rolling.EPSD, mu_r=0.05, twisting=dc.Twisting.SDS, mu_tw=2e-4, k_tw=0.02),
    "elastic_plastic_normal_only": dict(normal=dc.Normal.ELASTIC_PLASTIC, yield_pressure=2e8, E1=7e10, nu1=0.3, E2=INF, nu2=0.3),
    "dmt_mindlin": dict(normal=dc.Normal.DMT, criterion=O, E1=1e9, nu1=0.3, E2=1e9, nu2=0.3, work_of_adhesion=0.05, tangential=dc.Tangential.MINDLIN, mu=0.4),
    "hertz_full_project": dict(HERTZ_FULL, carry=dc.Carry.PROJECT),
    "powerlaw_linear_epsd_project": dict(normal=dc.Normal.POWERLAW, p=1.7, k_n=3e7, damping=dc.Damping.RESTITUTION, e_n=0.3, tangential=dc.Tangential.LINEAR, k_t=5e3, mu=0.2, rolling=dc.Rolling.EPSD, mu_r=0.1, k_r=1e-3, carry=dc.Carry.PROJECT),
    "hertz_normal_only": dict(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.5, E1=7e10, nu1=0.3, E2=7e10, nu2=0.3),
    "linear_constant_rolling_only": dict(normal=dc.Normal.LINEAR, k_n=1e4, rolling=dc.Rolling.CONSTANT, mu_r=0.1),
    # The rescaled Mindlin law, and step-aware models (dc_contact_model_set_step: `step` =
    # (dt, integrator), applied after contact_model_init by both sides).
    "hertz_full_rescale": dict(HERTZ_FULL, tangential=dc.Tangential.MINDLIN_RESCALE),
    "hertz_wall_rescale_step": dict(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.3, E1=3.8e11, nu1=0.23, E2=INF, nu2=0.23, tangential=dc.Tangential.MINDLIN_RESCALE, mu=0.092, step=(DT_STEP, dc.Integrator.VELOCITY_VERLET)),
    "hertz_full_step_euler": dict(HERTZ_FULL, step=(DT_STEP, dc.Integrator.SYMPLECTIC_EULER)),
    "linear_overlap_step": dict(normal=dc.Normal.LINEAR, k_n=1e4, damping=dc.Damping.RESTITUTION, e_n=0.5, criterion=O, tangential=dc.Tangential.LINEAR, k_t=8e3, e_t=0.4, mu=0.5, step=(DT_STEP, dc.Integrator.VELOCITY_VERLET)),
    "powerlaw_normal_only_step": dict(normal=dc.Normal.POWERLAW, p=1.7, k_n=3e7, damping=dc.Damping.RESTITUTION, e_n=0.3, step=(DT_STEP, dc.Integrator.VELOCITY_VERLET)),
}


def model(name):
    kw = dict(SPECS[name])
    step = kw.pop("step", None)
    m = dc.contact_model_init(dc.ContactSpec(**kw))
    return m if step is None else m.set_step(*step)


def c_model(name):
    st, m = cc.c_model(**SPECS[name])
    assert st == 0
    return m


def bits(a) -> bytes:
    return np.asarray(a, dtype=np.float64).tobytes()


# ---- spec and model ---------------------------------------------------------------------------


def test_spec_struct_mirror_matches_library_size():
    s = cc.c_spec()
    assert s.size == C.sizeof(cc.Spec) and s.version == dc.CONTACT_SPEC_VERSION


def test_default_spec_equals_c_spec_init():
    c = cc.c_spec()
    for spec in (dc.ContactSpec(), dc.contact_spec_init()):
        for f in cc.SPEC_INTS:
            assert getattr(spec, f) == getattr(c, f), f
        for f in cc.SPEC_REALS:
            assert bits(getattr(spec, f)) == bits(getattr(c, f)), f


def test_every_c_spec_field_is_a_keyword_and_attribute():
    for f in cc.SPEC_INTS + cc.SPEC_REALS:
        v = 2 if f in cc.SPEC_INTS else 0.125
        assert getattr(dc.ContactSpec(**{f: v}), f) == v, f
    with pytest.raises(TypeError):
        dc.ContactSpec(E3=1.0)
    with pytest.raises(TypeError):  # keyword only: never positional (the C rule too)
        dc.ContactSpec(1)  # type: ignore[misc]


def test_enums_match_header_constants():
    assert [int(x) for x in dc.Normal] == [1, 2, 3, 4, 5, 6, 7]
    assert [int(x) for x in dc.Damping] == [0, 1]
    assert [int(x) for x in dc.Tangential] == [0, 1, 2, 3]
    assert [int(x) for x in dc.Rolling] == [0, 1, 2]
    assert [int(x) for x in dc.Twisting] == [0, 1]
    assert [int(x) for x in dc.Carry] == [0, 1]
    assert [int(x) for x in dc.Integrator] == [0, 1]
    assert dc.CONTACT_HISTORY_MAX == 12


@pytest.mark.parametrize("name", sorted(SPECS))
def test_models_equal_c(name):
    m, cm = model(name), c_model(name)
    assert m.to_bytes() == bytes(cm)
    assert m.history_len == cm.history_len == dc.contact_history_len(m)
    for f in cc.MODEL_REALS:
        assert bits(getattr(m, f)) == bits(getattr(cm, f)), f
    assert (m.tangential, m.rolling, m.twisting, m.carry) == (cm.tangential, cm.rolling, cm.twisting, cm.carry)
    assert m.carry == SPECS[name].get("carry", dc.Carry.ROTATE)
    assert m.step_aware == ("step" in SPECS[name])
    p = m.normal
    for f in ("p", "stiffness", "alpha", "damping_a", "e", "k", "c", "h"):
        assert bits(getattr(p, f)) == bits(getattr(cm.normal, f)), f


# Random specs, valid and not: the same status as C, and on success the same model bytes.
SEL = {  # valid codes, then invalid ones
    "normal": ([1, 2, 3, 4, 5, 6], [0, 7, -1]),
    "damping": ([0, 1], [2, -1]),
    "criterion": ([0, 1], [2, -1]),
    "tangential": ([0, 1, 2, 3], [4]),
    "rolling": ([0, 1, 2], [3]),
    "twisting": ([0, 1], [2]),
}
GOOD = {
    "E1": [7e10, 1e9, INF], "nu1": [0.3, 0.5, -0.5], "E2": [2e11, INF, 1e8], "nu2": [0.25, 0.0],
    "p": [1.0, 1.5, 2.5], "k_n": [1e4, 3e7], "e_n": [0.5, 1.0, 1e-3], "visco_A": [0.0, 1e-6], "mu": [0.0, 0.3],
    "k_t": [1e3, 8e3], "e_t": [1.0, 0.5], "mu_r": [0.0, 0.1], "k_r": [0.0, 1e-3], "eta_r": [0.0, 0.5],
    "mu_tw": [0.0, 1e-4], "k_tw": [0.01, 1.0], "eta_tw": [0.0, 0.3], "inertia_factor": [0.4, 1.0, 0.1],
    "work_of_adhesion": [0.0, 0.05], "yield_pressure": [1e8, 1e9],
}
BAD = [math.nan, -1.0, 0.0, INF, -INF, 1.5, 1e300, -0.0, 5e-324]


def test_random_specs_equal_c():
    rng = np.random.default_rng(zlib.crc32(b"contact specs"))
    ok = err = 0
    codes = set()
    for _ in range(3000):
        kw = {}
        for k, (valid, invalid) in SEL.items():
            pool = valid if rng.random() < 0.97 else invalid
            kw[k] = int(pool[rng.integers(len(pool))])
        for k, pool in GOOD.items():
            u = rng.random()
            if u < 0.015:
                kw[k] = float(BAD[rng.integers(len(BAD))])
            elif u < 0.985:  # else left unset (NaN or the library default)
                kw[k] = float(pool[rng.integers(len(pool))])
        st, cm = cc.c_model(**kw)
        if st == 0:
            ok += 1
            assert dc.ContactSpec(**kw).model().to_bytes() == bytes(cm), kw
        else:
            err += 1
            codes.add(st)
            with pytest.raises(dc.DemcontactError) as ei:
                dc.contact_model_init(dc.ContactSpec(**kw))
            assert ei.value.code == st, kw
            assert type(ei.value) is dc.STATUS_CLASSES[st]
    assert ok > 100 and err > 100
    # The spec statuses of the contact ABI all occur (and map to their own classes).
    assert {6123, 6124} <= codes, codes


@pytest.mark.parametrize(
    "change,cls",
    [
        (dict(e_n=math.nan), dc.SpecUnsetError),  # NaN means unset in a spec
        (dict(e_n=INF), dc.NotFiniteError),
        (dict(mu=INF), dc.NotFiniteError),
        (dict(e_t=0.0), dc.RestitutionRangeError),
        (dict(nu1=0.7), dc.PoissonRangeError),
        (dict(nu2=-1.0), dc.PoissonRangeError),
        (dict(e_n=1.5), dc.RestitutionRangeError),
        (dict(e_n=0.0), dc.RestitutionRangeError),
        (dict(normal=9), dc.SpecModelError),
        (dict(tangential=7), dc.SpecModelError),
        (dict(inertia_factor=2.0), dc.SpecModelError),
        (dict(mu=math.nan), dc.SpecUnsetError),
        (dict(criterion=5), dc.CriterionError),
        (dict(E1=-1.0), dc.NotPositiveError),
        (dict(mu=-0.1), dc.NegativeError),
    ],
)
def test_bad_spec_values_raise_the_c_status(change, cls):
    kw = {**SPECS["hertz_wall_mindlin"], **change}
    st, _ = cc.c_model(**kw)
    with pytest.raises(cls) as ei:
        dc.ContactSpec(**kw).model()
    assert ei.value.code == st != 0
    assert "contact_model_init" in str(ei.value)


def test_spec_argument_types():
    with pytest.raises(TypeError, match="normal"):
        dc.ContactSpec(normal=1.5)
    with pytest.raises(TypeError, match="bool"):
        dc.ContactSpec(normal=True)
    with pytest.raises(TypeError, match="mu"):
        dc.ContactSpec(mu="0.3")
    with pytest.raises(TypeError, match="single number"):
        dc.ContactSpec(mu=[0.3, 0.4])
    with pytest.raises(TypeError):
        dc.contact_model_init({"normal": 1})  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        dc.ContactModel()  # type: ignore[call-arg]


# ---- one contact -------------------------------------------------------------------------------


class Scene:
    """n evolving contacts: normals turning slowly, overlaps crossing zero now and then (history
    resets), random velocities and spins, a third of them sphere-wall contacts."""

    def __init__(self, seed, n):
        self.rng = rng = np.random.default_rng(seed)
        self.n = n
        nv = rng.normal(size=(n, 3))
        self.normal = nv / np.linalg.norm(nv, axis=1)[:, None]
        self.overlap = rng.uniform(-1e-6, 1e-5, n)
        self.r1 = rng.uniform(5e-4, 2e-3, n)
        self.r2 = rng.uniform(5e-4, 2e-3, n)
        self.m1 = 2500 * 4 / 3 * np.pi * self.r1**3
        self.m2 = 2500 * 4 / 3 * np.pi * self.r2**3
        wall = rng.random(n) < 1 / 3
        self.r2[wall] = INF
        self.m2[wall] = INF
        self.step()

    def step(self):
        rng, n = self.rng, self.n
        nv = self.normal + rng.normal(0, 0.02, (n, 3))
        self.normal = np.ascontiguousarray(nv / np.linalg.norm(nv, axis=1)[:, None])
        self.overlap = self.overlap + rng.normal(0, 1.5e-6, n)
        self.v1 = rng.normal(0, 0.3, (n, 3))
        self.v2 = rng.normal(0, 0.3, (n, 3))
        self.w1 = rng.normal(0, 300, (n, 3))
        self.w2 = rng.normal(0, 300, (n, 3))

    def arrays(self):
        return (self.normal, self.overlap, self.v1, self.v2, self.w1, self.w2, self.r1, self.r2, self.m1, self.m2)

    def contact(self, i):
        return (self.normal[i], float(self.overlap[i]), self.v1[i], self.v2[i], self.w1[i], self.w2[i],
                float(self.r1[i]), float(self.r2[i]), float(self.m1[i]), float(self.m2[i]))


DT = 2e-7


@pytest.mark.parametrize("name", sorted(SPECS))
def test_contact_force_equals_c_over_many_steps(name):
    m, cm = model(name), c_model(name)
    L = max(m.history_len, 1)
    scene = Scene(zlib.crc32(name.encode()), 12)
    hp = np.zeros((scene.n, L))
    hc = np.zeros((scene.n, L))
    sliding = resets = 0
    for _ in range(150):
        scene.step()
        for i in range(scene.n):
            args = scene.contact(i)
            r = dc.contact_force(m, *args, DT, hp[i] if m.history_len else None)
            out = cc.Result()
            st = cc.force(C.byref(cm), C.byref(cc.c_state(*args)), DT, cc.ptr(hc[i]), L if m.history_len else 0, C.byref(out))
            assert st == 0
            assert bits(r.force) == bits(out.force) and bits(r.torque1) == bits(out.torque1)
            assert bits(r.torque2) == bits(out.torque2) and bits(r.ft) == bits(out.ft)
            assert bits(r.f_n) == bits(out.f_n)
            assert (r.sliding, r.rolling_sliding) == (bool(out.sliding), bool(out.rolling_sliding))
            assert hp[i].tobytes() == hc[i].tobytes()
            sliding += r.sliding
            resets += args[1] <= 0
    assert resets > 0
    if m.tangential:
        assert sliding > 0 and np.any(hp != 0)  # the Coulomb limit and the springs were exercised


@pytest.mark.parametrize("carry", [2, -1, 7])
def test_bad_carry_raises_spec_model_and_names_it(carry):
    with pytest.raises(dc.SpecModelError, match="carry=%d" % carry):
        dc.contact_model_init(dc.ContactSpec(**dict(HERTZ_FULL, carry=carry)))
    assert cc.c_model(**dict(HERTZ_FULL, carry=carry))[0] == dc.SpecModelError.status


def test_projection_changes_only_the_springs_of_a_turning_contact():
    rot, proj = model("hertz_full"), model("hertz_full_project")
    hr, hp = np.zeros(rot.history_len), np.zeros(proj.history_len)
    for k in range(40):
        a = 0.03 * k
        args = ([math.cos(a), math.sin(a), 0.0], 1e-6, [0.0, 0.0, 0.01], [0.0] * 3, [0.0, 0.0, 30.0],
                [0.0, 0.0, -10.0], 1e-3, 1e-3, 1e-5, 1e-5)
        r = dc.contact_force(rot, *args, DT, hr)
        p = dc.contact_force(proj, *args, DT, hp)
        assert bits(r.f_n) == bits(p.f_n)
    assert bits(r.ft) != bits(p.ft)


def test_contact_force_spheres_equals_c():
    m, cm = model("hertz_full"), c_model("hertz_full")
    rng = np.random.default_rng(5)
    h, hc = np.zeros(m.history_len), np.zeros(m.history_len)
    for _ in range(300):
        x1 = rng.normal(0, 1e-3, 3)
        x2 = x1 + rng.normal(0, 1.2e-3, 3)
        v1, v2, w1, w2 = rng.normal(0, 0.3, 3), rng.normal(0, 0.3, 3), rng.normal(0, 100, 3), rng.normal(0, 100, 3)
        args = (v1, v2, w1, w2, 1e-3, 1.1e-3, 1e-5, 1.3e-5)
        out = cc.Result()
        st = cc.force_spheres(C.byref(cm), cc.ptr(x1), cc.ptr(x2), C.byref(cc.c_state([1, 0, 0], 0.0, *args)), DT, cc.ptr(hc), hc.size, C.byref(out))
        if st == 0:
            r = dc.contact_force_spheres(m, x1, x2, *args, DT, h)
            assert bits(r.force) == bits(out.force) and bits(r.torque1) == bits(out.torque1) and h.tobytes() == hc.tobytes()
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                dc.contact_force_spheres(m, x1, x2, *args, DT, h)
            assert ei.value.code == st


WALL = ([0.0, 0.0, 1.0], 1e-6, [0.1, 0.0, -1.0], [0.0, 0.0, 0.0], [0.0, 50.0, 0.0], [0.0, 0.0, 0.0], 1e-3, INF, 1e-5, INF)


@pytest.mark.parametrize(
    "index,value,cls",
    [
        (1, math.nan, dc.NotFiniteError),
        (2, [math.nan, 0.0, 0.0], dc.NotFiniteError),
        (4, [0.0, INF, 0.0], dc.NotFiniteError),
        (0, [0.0, 0.0, 1.1], dc.NotUnitError),
        (0, [0.0, 0.0, 0.0], dc.NotUnitError),
        (6, 0.0, dc.NotPositiveError),
        (6, -1e-3, dc.NotPositiveError),
        (8, math.nan, dc.NotFiniteError),
        (8, -1.0, dc.NotPositiveError),
        (6, INF, dc.NotFiniteError),
    ],
)
def test_contact_force_errors_equal_c_and_write_nothing(index, value, cls):
    m, cm = model("hertz_full"), c_model("hertz_full")
    args = list(WALL)
    args[index] = value
    h = np.arange(1.0, m.history_len + 1) * 1e-9  # a non-zero history that must stay untouched
    h[:3] = [0.0, 0.0, 1.0]
    before = h.tobytes()
    st = cc.force(C.byref(cm), C.byref(cc.c_state(*args)), DT, cc.ptr(h.copy()), h.size, C.byref(cc.Result()))
    with pytest.raises(cls) as ei:
        dc.contact_force(m, *args, DT, h)
    assert ei.value.code == st != 0
    assert h.tobytes() == before


@pytest.mark.parametrize("dt,cls", [(math.nan, dc.NotFiniteError), (0.0, dc.NotPositiveError), (-1e-7, dc.NotPositiveError), (INF, dc.NotFiniteError)])
def test_contact_force_bad_dt(dt, cls):
    m = model("hertz_full")
    with pytest.raises(cls):
        dc.contact_force(m, *WALL, dt, np.zeros(m.history_len))


def test_contact_force_history_rules():
    m = model("hertz_full")
    L = m.history_len
    with pytest.raises(TypeError, match="history.*required.*10 doubles"):
        dc.contact_force(m, *WALL, DT)
    with pytest.raises(dc.BufferTooShortError):
        dc.contact_force(m, *WALL, DT, np.zeros(L - 1))
    with pytest.raises(TypeError, match="float64"):
        dc.contact_force(m, *WALL, DT, np.zeros(L, dtype=np.int64))
    with pytest.raises(TypeError, match="float64"):
        dc.contact_force(m, *WALL, DT, np.zeros(L, dtype=np.float32))
    with pytest.raises(TypeError, match="numpy"):
        dc.contact_force(m, *WALL, DT, [0.0] * L)
    with pytest.raises(ValueError, match="C-contiguous"):
        dc.contact_force(m, *WALL, DT, np.zeros(2 * L)[::2])
    ro = np.zeros(L)
    ro.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        dc.contact_force(m, *WALL, DT, ro)
    # Longer and 2-D contiguous histories are fine (the first history_len doubles are used).
    a, b = np.zeros(L + 5), np.zeros((2, L))
    ra = dc.contact_force(m, *WALL, DT, a)
    rb = dc.contact_force(m, *WALL, DT, b)
    assert bits(ra.force) == bits(rb.force) and a[:L].tobytes() == b.ravel()[:L].tobytes() and np.any(a != 0)
    # A model without history takes None (and ignores a given array).
    m0 = model("hertz_normal_only")
    assert m0.history_len == 0
    r0 = dc.contact_force(m0, *WALL, DT)
    assert r0.f_n > 0 and bits(r0.torque1) == bits([0, 0, 0])


def test_contact_force_vector_arguments():
    m = model("hertz_full")
    h = np.zeros(m.history_len)
    args = list(WALL)
    args[2] = [0.1, 0.0]
    with pytest.raises(ValueError, match="v1 must be a 3-vector"):
        dc.contact_force(m, *args, DT, h)
    args = list(WALL)
    args[2] = np.array([1, 0, -1])  # integers: converted (numpy's rule)
    r_int = dc.contact_force(m, *args, DT, np.zeros(m.history_len))
    args[2] = np.array([1.0, 0.0, -1.0])
    r_f = dc.contact_force(m, *args, DT, np.zeros(m.history_len))
    assert bits(r_int.force) == bits(r_f.force)
    args[2] = np.array([True, False, True])
    with pytest.raises(TypeError, match="v1"):
        dc.contact_force(m, *args, DT, h)
    args[2] = [True, False, True]
    with pytest.raises(TypeError, match="v1"):
        dc.contact_force(m, *args, DT, h)
    # Every spelling of the same 3-vector gives the same bits: list, tuple, ints, float64 array,
    # strided float64 view, float32 array, numpy scalars.
    strided = np.array([[1.0, 9.0], [0.0, 9.0], [-1.0, 9.0]])[:, 0]
    for spelling in ([1.0, 0.0, -1.0], (1, 0, -1), strided, np.array([1, 0, -1], np.float32), [np.float64(1), 0.0, np.int64(-1)]):
        args[2] = spelling
        r = dc.contact_force(m, *args, DT, np.zeros(m.history_len))
        assert bits(r.force) == bits(r_f.force) and bits(r.torque1) == bits(r_f.torque1), spelling


# ---- batch -------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(SPECS))
def test_batch_equals_c_batch_over_many_steps(name):
    m, cm = model(name), c_model(name)
    L = m.history_len
    scene = Scene(zlib.crc32(name.encode()) + 1, 500)
    hp = np.zeros((scene.n, max(L, 1)))
    hc = hp.copy()
    normal_only = L == 0 and m.rolling == 0
    for _ in range(200):
        scene.step()
        a = list(scene.arrays())
        if normal_only:
            a[4] = a[5] = None  # w1, w2 may be omitted (NULL in C)
        r = dc.contact_force_batch(m, *a, DT, hp if L else None)
        st, f_n, fo, t1, t2 = cc.c_batch(cm, *a, DT, hc if L else None)
        assert st == 0
        assert r.f_n.tobytes() == f_n.tobytes() and r.force.tobytes() == fo.tobytes()
        assert r.torque1.tobytes() == t1.tobytes() and r.torque2.tobytes() == t2.tobytes()
        assert hp.tobytes() == hc.tobytes()
    assert r.force.shape == (scene.n, 3) and r.f_n.shape == (scene.n,)
    if L:
        assert np.any(hp != 0)


def batch_args(n=6, seed=1):
    s = Scene(seed, n)
    return list(s.arrays())


def test_batch_broadcast_and_conversions_equal_full_arrays():
    m = model("hertz_full")
    n = 40
    a = batch_args(n, 2)
    a[7], a[9] = np.full(n, INF), np.full(n, INF)  # all walls
    a[3], a[5] = np.zeros((n, 3)), np.zeros((n, 3))
    h0 = np.zeros((n, m.history_len))
    ref = dc.contact_force_batch(m, *a, DT, h0.copy())
    b = list(a)
    b[7], b[9] = INF, INF  # scalars broadcast
    b[3], b[5] = [0.0, 0.0, 0.0], np.zeros(3)  # one vector for every contact
    b[6] = np.asfortranarray(np.stack([a[6], a[6]], axis=1))[:, 0]  # strided view: copied
    b[2] = np.asfortranarray(a[2])  # Fortran order: copied
    r = dc.contact_force_batch(m, *b, DT, h0.copy())
    for x, y in zip(r, ref):
        assert x.tobytes() == y.tobytes()
    # integer arrays are converted like numpy ufuncs do
    ci = list(a)
    ci[3] = np.zeros((n, 3), dtype=np.int32)
    r = dc.contact_force_batch(m, *ci, DT, h0.copy())
    assert r.force.tobytes() == ref.force.tobytes()


def test_batch_zero_copy_and_history_in_place():
    m = model("hertz_full")
    n = 8
    a = batch_args(n, 3)
    a[1] = np.full(n, 5e-6)
    h = np.zeros((n, m.history_len))
    hid = id(h)
    dc.contact_force_batch(m, *a, DT, h)
    assert id(h) == hid and np.any(h != 0)  # updated in place
    # The caller's memory is handed to the library itself: two numpy views of one buffer with
    # different bases (invisible to rust-numpy's borrow tracking) as input v1 and output force
    # are refused by dc_contact_force_batch's own overlap check (a copied input would pass).
    buf = bytearray(8 * n * 3)
    v1 = np.frombuffer(memoryview(buf), dtype=np.float64).reshape(n, 3)
    force = np.frombuffer(memoryview(buf), dtype=np.float64).reshape(n, 3)
    v1[:] = a[2]
    alias = (np.empty(n), force, np.empty((n, 3)), np.empty((n, 3)))
    with pytest.raises(dc.BufferLayoutError, match="outputs and history untouched"):
        dc.contact_force_batch(m, a[0], a[1], v1, *a[3:], DT, h.copy(), out=alias)
    dc.contact_force_batch(m, a[0], a[1], v1.copy(), *a[3:], DT, h.copy(), out=alias)  # a copy passes
    # The same array given as input and output is also refused by the borrow tracking.
    out = (np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3)))
    with pytest.raises(dc.BufferLayoutError):
        dc.contact_force_batch(m, *a[:2], out[1], *a[3:], DT, h, out=out)
    with pytest.raises(dc.BufferLayoutError):
        dc.contact_force_batch(m, *a, DT, h, out=(a[1], *out[1:]))
    hv = np.zeros((n, 3))  # history aliasing the v1 input
    with pytest.raises((dc.BufferLayoutError, ValueError)):
        dc.contact_force_batch(m, a[0], a[1], hv, *a[3:], DT, hv.reshape(n, 3))
    # out= arrays are filled and returned
    r = dc.contact_force_batch(m, *a, DT, h.copy(), out=out)
    assert all(x is y for x, y in zip(r, out))


def test_batch_errors_name_the_contact_and_write_nothing():
    m, cm = model("hertz_full"), c_model("hertz_full")
    n = 10
    for idx, k, value, cls in [
        (1, 4, math.nan, dc.NotFiniteError),
        (0, 7, [0.0, 0.0, 2.0], dc.NotUnitError),
        (6, 3, -1.0, dc.NotPositiveError),
        (8, 9, 0.0, dc.NotPositiveError),
        (4, 2, [INF, 0, 0], dc.NotFiniteError),
    ]:
        a = batch_args(n, 4)
        a[idx] = a[idx].copy()
        a[idx][k] = value
        h = np.random.default_rng(1).normal(0, 1e-9, (n, m.history_len))
        h[:, :3] = a[0]
        out = tuple(np.full(s, 7.0) for s in [(n,), (n, 3), (n, 3), (n, 3)])
        before = [x.tobytes() for x in (h, *out)]
        st, *_ = cc.c_batch(cm, *a, DT, h.copy())
        with pytest.raises(cls, match=f"at contact {k} ") as ei:
            dc.contact_force_batch(m, *a, DT, h, out=out)
        assert ei.value.code == st != 0
        assert [x.tobytes() for x in (h, *out)] == before
    a = batch_args(n, 4)
    with pytest.raises(dc.NotFiniteError):
        dc.contact_force_batch(m, *a, math.nan, np.zeros((n, m.history_len)))


def test_batch_overflow_names_the_contact_and_keeps_its_history():
    # Valid inputs whose result overflows: ResultRangeError naming the first such contact; those
    # contacts NaN with their history kept, every other one computed (as the C batch does).
    m, cm = model("hertz_full"), c_model("hertz_full")
    n = 10
    a = batch_args(n, 4)
    a[1] = a[1].copy()
    a[2] = a[2].copy()
    for k in (3, 7):
        a[1][k] = 1e300
        a[2][k] = [1e300, 0.0, 0.0]
    h0 = np.random.default_rng(1).normal(0, 1e-9, (n, m.history_len))
    h0[:, :3] = a[0]
    h = h0.copy()
    out = tuple(np.full(s, 7.0) for s in [(n,), (n, 3), (n, 3), (n, 3)])
    st, cf, *_ = cc.c_batch(cm, *a, DT, hc := h0.copy())
    with pytest.raises(dc.ResultRangeError, match="at contact 3 .*history advanced") as ei:
        dc.contact_force_batch(m, *a, DT, h, out=out)
    assert ei.value.code == st == 6108
    for k in range(n):
        over = k in (3, 7)
        assert np.isnan(out[0][k]) == over
        assert all(np.isnan(x[k]).all() == over for x in out[1:])
    assert (h[[3, 7]] == h0[[3, 7]]).all()
    assert h.tobytes() == hc.tobytes() and out[0].tobytes() == cf.tobytes()


def test_batch_shape_and_type_errors():
    m = model("hertz_full")
    n, L = 6, m.history_len
    a = batch_args(n, 5)
    h = lambda: np.zeros((n, L))  # noqa: E731

    def call(i, value, hist=None, **kw):
        b = list(a)
        b[i] = value
        return dc.contact_force_batch(m, *b, DT, h() if hist is None else hist, **kw)

    with pytest.raises(ValueError, match=r"normal has shape \(6, 2\)"):
        call(0, np.zeros((n, 2)))
    with pytest.raises(ValueError, match="overlap must be a 1-D"):
        call(1, np.zeros((n, 1)))
    with pytest.raises(ValueError, match="overlap must be a 1-D"):
        call(1, 1e-6)
    with pytest.raises(ValueError, match=r"r1 has shape \(5,\)"):
        call(6, np.ones(n - 1))
    with pytest.raises(ValueError, match=r"v1 has shape \(18,\), expected \(6, 3\)"):
        call(2, a[2].ravel())
    with pytest.raises(TypeError, match="v2"):
        call(3, np.zeros((n, 3), dtype=complex))
    with pytest.raises(TypeError, match="w1.*required"):
        call(4, None)
    with pytest.raises(TypeError, match="history.*required"):
        dc.contact_force_batch(m, *a, DT)
    with pytest.raises(ValueError, match="history has shape"):
        call(0, a[0], hist=np.zeros((n + 1, L)))
    with pytest.raises(ValueError, match="history has shape"):
        call(0, a[0], hist=np.zeros(n * L))
    with pytest.raises(dc.BufferTooShortError):
        call(0, a[0], hist=np.zeros((n, L - 1)))
    with pytest.raises(TypeError, match="float64"):
        call(0, a[0], hist=np.zeros((n, L), dtype=np.int64))
    with pytest.raises(ValueError, match="C-contiguous"):
        call(0, a[0], hist=np.zeros((n, 2 * L))[:, ::2])
    with pytest.raises(ValueError, match="C-contiguous"):
        call(0, a[0], hist=np.asfortranarray(np.zeros((n, L))))
    ro = np.zeros((n, L))
    ro.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        call(0, a[0], hist=ro)
    good_out = [np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3))]
    with pytest.raises(TypeError, match="out"):
        call(0, a[0], out=good_out)  # a list, not a tuple
    with pytest.raises(TypeError, match="out"):
        call(0, a[0], out=tuple(good_out[:3]))
    with pytest.raises(ValueError, match=r"out\[1\] \(force\) has shape"):
        call(0, a[0], out=(good_out[0], np.empty((n, 4)), *good_out[2:]))
    with pytest.raises(TypeError, match=r"out\[0\].*float64"):
        call(0, a[0], out=(np.empty(n, dtype=np.float32), *good_out[1:]))
    ro_out = np.empty(n)
    ro_out.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        call(0, a[0], out=(ro_out, *good_out[1:]))
    # Wider history rows are fine (stride >= history_len), same forces.
    wide = np.zeros((n, L + 3))
    r1 = dc.contact_force_batch(m, *a, DT, wide)
    r2 = dc.contact_force_batch(m, *a, DT, h())
    assert r1.force.tobytes() == r2.force.tobytes()


def test_normal_only_models_with_history_need_no_spins():
    # Normal-only by its sub-models, whatever the history: a step-aware normal-only model keeps
    # one double and still takes w1 = w2 = None, with the forces of the call that gives them.
    m = model("powerlaw_normal_only_step")
    assert m.history_len == 1
    n = 12
    a = batch_args(n, 3)
    ha, hb = np.zeros((n, 1)), np.zeros((n, 1))
    for _ in range(3):
        ra = dc.contact_force_batch(m, *a, DT, ha)
        rb = dc.contact_force_batch(m, *a[:4], None, None, *a[6:], DT, hb)
        assert ra.f_n.tobytes() == rb.f_n.tobytes() and ra.force.tobytes() == rb.force.tobytes()
        assert ha.tobytes() == hb.tobytes()
    assert (ha != 0).any()  # the step-aware history is in use
    with pytest.raises(TypeError, match="w1.*required"):  # a tangential stage still needs them
        dc.contact_force_batch(model("hertz_full_step_euler"), *a[:4], None, None, *a[6:], DT, np.zeros((n, model("hertz_full_step_euler").history_len)))


def test_empty_batch_gives_empty_results():
    m = model("hertz_full")
    e1, e3 = np.empty(0), np.empty((0, 3))
    r = dc.contact_force_batch(m, e3, e1, e3, e3, e3, e3, e1, e1, e1, e1, DT, np.zeros((0, m.history_len)))
    assert r.f_n.shape == (0,) and r.force.shape == (0, 3)


def test_batch_from_a_thread_pool_is_bit_identical():
    from concurrent.futures import ThreadPoolExecutor

    m = model("hertz_full")
    n = 20_000
    a = batch_args(n, 6)
    h0 = np.random.default_rng(2).normal(0, 1e-8, (n, m.history_len))
    h0[:, :3] = a[0]
    want_h = h0.copy()
    want = dc.contact_force_batch(m, *a, DT, want_h)

    def work(_):
        h = h0.copy()
        r = dc.contact_force_batch(m, *a, DT, h)
        return r, h

    with ThreadPoolExecutor(max_workers=6) as ex:
        for r, h in ex.map(work, range(24)):
            assert h.tobytes() == want_h.tobytes()
            for x, y in zip(r, want):
                assert x.tobytes() == y.tobytes()


def test_reprs_name_the_sub_models():
    # Codes print as their enum members, an undamped tangential spring as zeta_t=0.0 (not -0.0).
    spec = dc.ContactSpec(
        normal=dc.Normal.HERTZ, E1=7e10, nu1=0.2, E2=7e10, nu2=0.2, damping=dc.Damping.RESTITUTION, e_n=0.5,
        tangential=dc.Tangential.MINDLIN, mu=0.5, e_t=1.0, rolling=dc.Rolling.NONE,
    )
    r = repr(spec)
    assert "tangential=Tangential.MINDLIN" in r and "normal=Normal.HERTZ" in r, r
    assert "carry=Carry.ROTATE" in r and "criterion=Criterion." in r, r
    m = repr(dc.contact_model_init(spec))
    assert m.startswith("ContactModel(tangential=Tangential.MINDLIN, rolling=Rolling.NONE,"), m
    assert "zeta_t=0.0)" in m, m
    # A code the enums do not have (the default spec's unset normal law 0, an unknown 7: accepted
    # by the spec, refused by contact_model_init) prints as its number.
    r = repr(dc.ContactSpec(tangential=7))
    assert "tangential=7" in r and "normal=0" in r, r


# ---- step-aware damping (dc_contact_model_set_step) --------------------------------------------


def test_set_step_equals_c_statuses_and_bytes():
    bases = ["hertz_full", "hertz_wall_mindlin", "linear_linear_constant", "powerlaw_linear_epsd", "viscoelastic_mindlin",
             "dmt_mindlin", "hertz_normal_only", "linear_constant_rolling_only", "hertz_full_rescale"]
    seen = set()
    for name in bases:
        for dt in (1e-7, 3e-6, 1e-3, 0.0, -1e-6, math.nan, INF):
            for integ in (0, 1, 2, -1):
                kw = dict(SPECS[name], step=(dt, integ))
                st, cm = cc.c_model(**kw)
                seen.add(st)
                if st == 0:
                    m = model(name).set_step(dt, integ)
                    assert m.to_bytes() == bytes(cm), (name, dt, integ)
                    assert m.history_len == cm.history_len == dc.contact_history_len(m)
                    # the function form and the names give the same model
                    word = {0: "velocity_verlet", 1: "symplectic_euler"}[integ]
                    assert dc.contact_model_set_step(model(name), dt, word).to_bytes() == bytes(cm)
                else:
                    with pytest.raises(dc.DemcontactError) as ei:
                        model(name).set_step(dt, integ)
                    assert ei.value.code == st and type(ei.value) is dc.STATUS_CLASSES[st], (name, dt, integ)
                    assert "set_step" in str(ei.value) and f"integrator={integ}" in str(ei.value)
    # every status of set_step occurs (OK, dt NaN/inf, dt <= 0, integrator, unsupported law)
    assert {0, 6102, 6105, 6135, 6136} <= seen, seen


def test_set_step_classes_defaults_and_immutability():
    base = model("hertz_wall_mindlin")
    m = base.set_step(1e-6)
    assert m.to_bytes() == base.set_step(1e-6, dc.Integrator.VELOCITY_VERLET).to_bytes()
    assert m.history_len == base.history_len + 1 and m.step_aware and not base.step_aware
    assert "step_aware=True" in repr(m) and "step_aware" not in repr(base)
    # an undamped normal law has nothing to correct: the model comes back unchanged
    el = dc.ContactSpec(normal=dc.Normal.HERTZ, E1=7e10, nu1=0.3, E2=INF, nu2=0.3).model()
    assert el.set_step(1e-6).to_bytes() == el.to_bytes()
    with pytest.raises(dc.IntegratorError, match="rk4"):
        base.set_step(1e-6, "rk4")
    with pytest.raises(dc.StepUnsupportedError):
        model("viscoelastic_mindlin").set_step(1e-6)
    with pytest.raises(TypeError, match="dt"):
        base.set_step("1e-6")
    assert issubclass(dc.StepUnreachableError, dc.InputError) and dc.StepUnreachableError.status == 6137
    assert dc.Status.ERR_STEP_UNREACHABLE == 6137 and dc.Status.ERR_INTEGRATOR == 6135
    assert dc.STATUS_CLASSES[6136] is dc.StepUnsupportedError


def test_set_step_unreachable_matches_c():
    # Strong damping at a large step: the explicit step cannot realise e_n.
    for e in (1e-3, 1e-2, 0.05):
        for dt in (1e-5, 1e-4):
            kw = dict(normal=dc.Normal.LINEAR, k_n=1e4, damping=dc.Damping.RESTITUTION, e_n=e, step=(dt, 0))
            st, _ = cc.c_model(**kw)
            if st == 6137:
                with pytest.raises(dc.StepUnreachableError):
                    dc.ContactSpec(**{k: v for k, v in kw.items() if k != "step"}).model().set_step(dt)
                return
    pytest.fail("no StepUnreachable case found among the tried ones")


def wall_collision_e(m, v0, dt, phase, mass=2e-3, radius=2e-3):
    """Realised e of one sphere-wall collision, velocity Verlet in the LAMMPS order through
    contact_force, the first step at a gap of `phase` (0..1) of one step's travel."""
    h = np.zeros(max(m.history_len, 1))
    d, v, acc, touched = -phase * v0 * dt, -v0, 0.0, False
    for _ in range(100000):
        vh = v + 0.5 * dt * acc
        d -= dt * vh
        touched |= d > 0
        r = dc.contact_force(m, [0.0, 0.0, 1.0], d, [0.0, 0.0, vh], [0.0] * 3, [0.0] * 3, [0.0] * 3, radius, INF, mass, INF, dt,
                             h if m.history_len else None)
        acc = r.force[2] / mass
        v = vh + 0.5 * dt * acc
        if touched and d <= 0:
            return v / v0
    raise AssertionError("no separation")


def test_step_aware_model_realises_e_at_the_step():
    # docs/timestep.md: at dt = t_H/20 and e_n = 0.1 the plain dashpot realises e ~16 % low; the
    # step-aware one within 0.2 % on the mean over onset phases. t_H here is the elastic Hertz
    # duration 2 (5m/(4k))^(2/5) v^(-1/5) (2/5) B(2/5, 1/2) (k = 4/3 E* sqrt(R)).
    e, v0, mass, radius = 0.1, 1.0, 2e-3, 2e-3
    spec = dc.ContactSpec(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=e, E1=1e8, nu1=0.3, E2=INF, nu2=0.3)
    k = 4 / 3 * 1e8 / (1 - 0.09) * math.sqrt(radius)
    beta = math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)
    t_h = 2 * (5 * mass / (4 * k)) ** 0.4 * v0**-0.2 * 0.4 * beta
    dt = t_h / 20
    plain, aware = spec.model(), spec.model().set_step(dt)
    phases = np.arange(16) / 16
    e_plain = np.mean([wall_collision_e(plain, v0, dt, ph, mass, radius) for ph in phases])
    e_aware = np.mean([wall_collision_e(aware, v0, dt, ph, mass, radius) for ph in phases])
    assert e_plain / e - 1 < -0.05, e_plain
    assert abs(e_aware / e - 1) < 5e-3, e_aware


# ---- energy ledger (dc_contact_force_energy) ---------------------------------------------------


@pytest.mark.parametrize("name", ["hertz_full", "hertz_full_rescale", "hertz_wall_rescale_step", "linear_linear_constant", "hertz_normal_only"])
def test_contact_force_energy_equals_c_and_contact_force(name):
    m, cm = model(name), c_model(name)
    L = max(m.history_len, 1)
    scene = Scene(zlib.crc32(b"energy " + name.encode()), 8)
    hp, hc, hf = np.zeros((scene.n, L)), np.zeros((scene.n, L)), np.zeros((scene.n, L))
    dissipated = 0.0
    for _ in range(100):
        scene.step()
        for i in range(scene.n):
            args = scene.contact(i)
            r, en = dc.contact_force_energy(m, *args, DT, hp[i] if m.history_len else None)
            rf = dc.contact_force(m, *args, DT, hf[i] if m.history_len else None)
            out, ce = cc.Result(), cc.Energy()
            st = cc.force_energy(C.byref(cm), C.byref(cc.c_state(*args)), DT, cc.ptr(hc[i]), L if m.history_len else 0,
                                 C.byref(out), C.byref(ce))
            assert st == 0
            assert bits(r.force) == bits(out.force) == bits(rf.force) and bits(r.torque1) == bits(out.torque1)
            assert hp[i].tobytes() == hc[i].tobytes() == hf[i].tobytes()
            assert isinstance(en, dc.ContactEnergy)
            for f, _ in cc.Energy._fields_:
                assert bits(getattr(en, f)) == bits(getattr(ce, f)), f
            dissipated += en.dissipated
    assert dissipated > 0


def test_contact_force_energy_errors_and_ledger_sum():
    m = model("hertz_full_rescale")
    h = np.zeros(m.history_len)
    with pytest.raises(dc.NotFiniteError, match="contact_force_energy"):
        dc.contact_force_energy(m, *WALL[:1], math.nan, *WALL[2:], DT, h)
    assert not h.any()  # untouched on error
    with pytest.raises(TypeError, match="history"):
        dc.contact_force_energy(m, *WALL, DT)
    r, en = dc.contact_force_energy(m, *WALL, DT, h)
    parts = (en.normal_damping + en.tangential_damping + en.tangential_slip + en.rolling_damping + en.rolling_slip
             + en.twisting_damping + en.twisting_slip)
    assert en.dissipated == pytest.approx(parts, rel=1e-15, abs=0)
