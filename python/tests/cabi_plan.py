"""The scene planner's C ABI through ctypes (dc_plan_input_init, dc_plan), the reference
test_plan.py compares plan() against. Struct layouts follow include/demcontact.h; sizeof(Input)
is checked against the size dc_plan_input_init writes. Nothing here computes physics."""

from __future__ import annotations

import ctypes as C

from cabi import D, I32, fn

U32 = C.c_uint32

INPUT_REALS_A = [
    "youngs", "poisson", "density", "restitution", "radius_min", "radius_max", "v_max", "depth", "gravity",
    "pressure", "solid_fraction", "coordination", "load_factor", "friction", "rolling_friction", "overlap_tol",
    "e_tol", "static_tol", "duration_tol",
]
INPUT_REALS_B = ["stability_fraction", "conventional_divisor"]


class Input(C.Structure):
    _fields_ = (
        [("version", U32), ("size", U32)]
        + [(f, D) for f in INPUT_REALS_A]
        + [("criterion", I32), ("walls", I32)]
        + [(f, D) for f in INPUT_REALS_B]
    )


# (name, ctype) of dc_plan_result in order.
RESULT_FIELDS = [
    ("youngs_soft", D), ("softening", D), ("binding", I32), ("binding_dt", I32), ("dt", D), ("dt_restitution", D),
    ("dt_stability", D), ("dt_conventional", D), ("speedup", D), ("alpha", D), ("max_overlap_ratio", D),
    ("max_overlap_ratio_real", D), ("static_overlap_ratio", D), ("static_overlap_ratio_real", D),
    ("max_overlap_pair", I32), ("static_pair", I32), ("stress", D), ("static_force", D), ("duration", D),
    ("duration_real", D), ("duration_change", D), ("t_hertz", D), ("dt_over_t_hertz", D), ("steps_per_contact", D),
    ("e_plain_at_dt", D), ("e_plain_min", D), ("e_plain_max", D), ("e_plain_mean", D),
]


class Result(C.Structure):
    _fields_ = RESULT_FIELDS


input_init = fn("plan_input_init", [C.POINTER(Input)])
plan = fn("plan", [C.POINTER(Input), C.POINTER(Result), C.POINTER(I32)])


def c_plan(**members):
    """(status, Result or None, field code) of dc_plan on dc_plan_input_init's input with these
    members set."""
    i = Input()
    assert input_init(C.byref(i)) == 0
    for k, v in members.items():
        setattr(i, k, int(v) if k in ("criterion", "walls") else float(v))
    r = Result()
    field = I32(-1)
    st = plan(C.byref(i), C.byref(r), C.byref(field))
    return st, (r if st == 0 else None), field.value
