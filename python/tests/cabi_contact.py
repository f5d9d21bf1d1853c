"""The full-contact C ABI through ctypes (dc_contact_*), the reference test_contact.py compares
the Python binding against. Struct layouts follow include/demcontact.h; sizeof(Spec) is checked
against the size dc_contact_spec_init writes. Nothing here computes physics."""

from __future__ import annotations

import ctypes as C

import numpy as np

from cabi import D, I32, PD, Pair, fn

U32 = C.c_uint32
V3 = D * 3

SPEC_INTS = ["normal", "damping", "criterion", "tangential", "rolling", "twisting"]
SPEC_REALS = [
    "E1", "nu1", "E2", "nu2", "p", "k_n", "e_n", "visco_A", "mu", "k_t", "e_t",
    "mu_r", "k_r", "eta_r", "mu_tw", "k_tw", "eta_tw", "inertia_factor", "work_of_adhesion",
    "yield_pressure",
]


class Spec(C.Structure):
    _fields_ = [("version", U32), ("size", U32)] + [(f, I32) for f in SPEC_INTS] + [(f, D) for f in SPEC_REALS]


MODEL_REALS = ["mu", "kt", "zeta_t", "kappa", "mu_r", "k_r", "eta_r", "mu_tw", "k_tw", "eta_tw"]


class Model(C.Structure):
    _fields_ = (
        [("magic", U32), ("history_len", U32), ("tangential", I32), ("rolling", I32), ("twisting", I32), ("carry", I32), ("normal", Pair)]
        + [(f, D) for f in MODEL_REALS]
        + [("reserved", D * 6)]
    )


class State(C.Structure):
    _fields_ = [("n", V3), ("overlap", D), ("v1", V3), ("v2", V3), ("w1", V3), ("w2", V3), ("r1", D), ("r2", D), ("m1", D), ("m2", D)]


class Result(C.Structure):
    _fields_ = [("force", V3), ("torque1", V3), ("torque2", V3), ("f_n", D), ("ft", V3), ("sliding", I32), ("rolling_sliding", I32)]


class Batch(C.Structure):
    _fields_ = [("n", C.c_size_t), ("history_stride", C.c_size_t)] + [
        (f, PD) for f in ["normal", "overlap", "v1", "v2", "w1", "w2", "r1", "r2", "m1", "m2", "history", "f_n", "force", "torque1", "torque2"]
    ]


spec_init = fn("contact_spec_init", [C.POINTER(Spec)])
model_init = fn("contact_model_init", [C.POINTER(Spec), C.POINTER(Model)])
history_len = fn("contact_history_len", [C.POINTER(Model), C.POINTER(C.c_size_t)])
force = fn("contact_force", [C.POINTER(Model), C.POINTER(State), D, PD, C.c_size_t, C.POINTER(Result)])
force_spheres = fn("contact_force_spheres", [C.POINTER(Model), PD, PD, C.POINTER(State), D, PD, C.c_size_t, C.POINTER(Result)])
force_batch = fn("contact_force_batch", [C.POINTER(Model), C.POINTER(Batch), D])
set_carry = fn("contact_model_set_carry", [C.POINTER(Model), I32])
set_step = fn("contact_model_set_step", [C.POINTER(Model), D, I32])


class Energy(C.Structure):
    _fields_ = [(f, D) for f in [
        "dissipated", "normal_damping", "tangential_damping", "tangential_slip", "tangential_elastic",
        "rolling_damping", "rolling_slip", "rolling_elastic", "twisting_damping", "twisting_slip", "twisting_elastic",
    ]]


force_energy = fn("contact_force_energy", [C.POINTER(Model), C.POINTER(State), D, PD, C.c_size_t, C.POINTER(Result), C.POINTER(Energy)])


def c_spec(**fields) -> Spec:
    s = Spec()
    assert spec_init(C.byref(s)) == 0
    for k, v in fields.items():
        setattr(s, k, int(v) if k in SPEC_INTS else float(v))
    return s


def c_model(**fields):
    """(status, Model or None) of dc_contact_model_init on a spec with these fields, then
    dc_contact_model_set_carry with `carry` (not a C spec field) when given, then
    dc_contact_model_set_step with `step` = (dt, integrator) when given."""
    carry = fields.pop("carry", None)
    step = fields.pop("step", None)
    s = c_spec(**fields)
    m = Model()
    st = model_init(C.byref(s), C.byref(m))
    if st == 0 and carry is not None:
        st = set_carry(C.byref(m), int(carry))
    if st == 0 and step is not None:
        st = set_step(C.byref(m), float(step[0]), int(step[1]))
    return st, (m if st == 0 else None)


def c_state(n, overlap, v1, v2, w1, w2, r1, r2, m1, m2) -> State:
    return State(V3(*n), overlap, V3(*v1), V3(*v2), V3(*w1), V3(*w2), r1, r2, m1, m2)


def ptr(a):
    return None if a is None else a.ctypes.data_as(PD)


def c_batch(model: Model, normal, overlap, v1, v2, w1, w2, r1, r2, m1, m2, dt, history):
    """dc_contact_force_batch on C-contiguous float64 arrays: (status, f_n, force, t1, t2);
    `history` (n, L) is updated in place as in C."""
    n = overlap.shape[0]
    f_n, fo, t1, t2 = np.full(n, -7.0), np.full((n, 3), -7.0), np.full((n, 3), -7.0), np.full((n, 3), -7.0)
    b = Batch(
        n,
        0 if history is None else history.shape[1],
        *[ptr(a) for a in (normal, overlap, v1, v2, w1, w2, r1, r2, m1, m2, history, f_n, fo, t1, t2)],
    )
    st = force_batch(C.byref(model), C.byref(b), dt)
    return st, f_n, fo, t1, t2
