"""plan() (the scene planner, C: dc_plan) against the C ABI through ctypes on the same inputs:
the same status and, on success, the same bits in every field; the dict has exactly the fields
of `demcontact plan --json` (docs/plan.md's table); a refusal names the member at fault (the
field code dc_plan writes, read from include/demcontact.h's DC_PLAN_FIELD_* names)."""

from __future__ import annotations

import math
import pathlib
import re
import zlib

import numpy as np
import pytest

import demcontact as dc

import cabi_plan as cp

ROOT = pathlib.Path(__file__).resolve().parents[2]

SCENE = dict(youngs=7e10, poisson=0.22, density=2500, restitution=0.5, radius_min=1e-3, radius_max=2e-3,
             v_max=2.0, depth=0.5, overlap_tol=0.01, e_tol=0.01)

# DC_PLAN_FIELD_<NAME> <code> from the header: code -> member name (NONE -> None).
FIELD_NAMES = {
    int(code): (None if name == "NONE" else name.lower())
    for name, code in re.findall(r"#define DC_PLAN_FIELD_(\w+) (\d+)", (ROOT / "include" / "demcontact.h").read_text())
}
PAIRS = {0: "min-min", 1: "min-max", 2: "max-max", 3: "min-wall", 4: "max-wall", 5: "min-peak"}
BINDING = {0: "overlap-tol", 1: "static-tol", 2: "duration-tol"}
BINDING_DT = {0: "e-tol", 1: "stability-fraction"}


def bits(x) -> bytes:
    return np.float64(x).tobytes()


def check_equal_c(kw):
    """plan(**kw) and dc_plan on the same members: the same status and bits, or the same error."""
    st, r, field = cp.c_plan(**kw)
    if st != 0:
        with pytest.raises(dc.DemcontactError) as ei:
            dc.plan(**kw)
        assert ei.value.code == st and type(ei.value) is dc.STATUS_CLASSES[st], kw
        assert ei.value.field == FIELD_NAMES[field], (kw, field)
        if ei.value.field is not None:
            assert f"field {ei.value.field} = " in str(ei.value)
        return st
    p = dc.plan(**kw)
    for name, ctype in cp.RESULT_FIELDS:
        c = getattr(r, name)
        if name in ("max_overlap_pair", "static_pair"):
            assert p[name] == PAIRS[c], name
        elif name == "binding":
            assert p[name] == BINDING[c]
        elif name == "binding_dt":
            assert p[name] == BINDING_DT[c]
        else:
            assert bits(p[name]) == bits(c), name
    # Echoed inputs.
    assert bits(p["youngs_real"]) == bits(kw["youngs"]) and bits(p["e_target"]) == bits(kw["restitution"])
    assert p["criterion"] == ("overlap" if kw.get("criterion", dc.Criterion.FORCE) == dc.Criterion.OVERLAP else "force")
    assert p["walls"] == bool(kw.get("walls", True))
    assert bits(p["tolerances"]["static_tol"]) == bits(kw.get("static_tol", math.inf))
    assert bits(p["mu"]) == bits(kw.get("friction", 0.0))
    return 0


def test_input_mirror_matches_library_size():
    i = cp.Input()
    assert cp.input_init(i) == 0 and i.size == cp.C.sizeof(cp.Input) and i.version == dc._native.PLAN_INPUT_VERSION
    assert len(FIELD_NAMES) == 24 and FIELD_NAMES[6] == "radius_max" and FIELD_NAMES[0] is None


def test_doc_example_and_keys():
    # docs/plan.md's example (the CLI's default static_tol is overlap_tol).
    p = dc.plan(**SCENE, static_tol=0.01)
    assert f"{p['youngs_soft']:.6e}" == "4.068248e+09" and p["binding"] == "overlap-tol"
    assert f"{p['dt']:.6e}" == "3.848480e-07" and p["binding_dt"] == "e-tol"
    assert f"{p['speedup']:.4f}" == "4.1898" and p["max_overlap_pair"] == "min-max"
    assert f"{p['e_plain_at_dt']:.6f}" == "0.495729"
    # Exactly the JSON fields of `demcontact plan --json` as docs/plan.md lists them, but the
    # CLI's own (the step-aware step: not in dc_plan's versioned result).
    doc = (ROOT / "docs" / "plan.md").read_text()
    table = doc.split("## JSON fields", 1)[1].split("\n\n", 2)[1]
    names = set()
    for line in table.splitlines()[2:]:
        if "CLI only" in line.split("|")[2]:
            continue
        names |= set(re.findall(r"`(\w+)`", line.split("|")[1]))
    assert set(p) == names, (set(p) ^ names)
    assert set(p["tolerances"]) == {"overlap_tol", "e_tol", "static_tol", "duration_tol"}


def test_plan_equals_c_on_random_scenes():
    rng = np.random.default_rng(zlib.crc32(b"plan scenes"))
    ok = err = 0
    for _ in range(24):
        r_min = float(10 ** rng.uniform(-4, -2))
        kw = dict(
            youngs=float(10 ** rng.uniform(8, 11.5)), poisson=float(rng.uniform(0.0, 0.45)),
            density=float(rng.uniform(1000, 8000)), restitution=float(rng.uniform(0.2, 0.95)),
            radius_min=r_min, radius_max=r_min * float(rng.uniform(1, 4)), v_max=float(10 ** rng.uniform(-1, 1)),
            depth=float(rng.uniform(0, 2)), overlap_tol=float(10 ** rng.uniform(-3, -1.5)),
            e_tol=float(10 ** rng.uniform(-2.5, -1.3)),
        )
        if rng.random() < 0.5:
            kw["static_tol"] = kw["overlap_tol"]
        if rng.random() < 0.3:
            kw["duration_tol"] = float(rng.uniform(0.5, 5))
        if rng.random() < 0.3:
            kw["criterion"] = dc.Criterion.OVERLAP
        if rng.random() < 0.3:
            kw["walls"] = False
        st = check_equal_c(kw)
        ok += st == 0
        err += st != 0
    assert ok >= 8 and err >= 2, (ok, err)  # both paths exercised


@pytest.mark.parametrize(
    "change,cls,field",
    [
        (dict(radius_max=5e-4), dc.PlanRangeError, "radius_max"),
        (dict(solid_fraction=1.0), dc.PlanRangeError, "solid_fraction"),
        (dict(e_tol=1.0), dc.PlanRangeError, "e_tol"),
        (dict(load_factor=0.5), dc.PlanRangeError, "load_factor"),
        (dict(walls=2), dc.PlanRangeError, "walls"),
        (dict(overlap_tol=1e-4), dc.PlanInfeasibleError, "overlap_tol"),
        (dict(youngs=-1.0), dc.NotPositiveError, "youngs"),
        (dict(v_max=math.nan), dc.NotFiniteError, "v_max"),
        (dict(static_tol=-math.inf), dc.NotPositiveError, "static_tol"),
        (dict(duration_tol=math.nan), dc.NotFiniteError, "duration_tol"),
        (dict(poisson=0.7), dc.PoissonRangeError, "poisson"),
        (dict(restitution=0.0), dc.RestitutionRangeError, "restitution"),
        (dict(criterion=7), dc.CriterionError, "criterion"),
        (dict(depth=-1.0), dc.NegativeError, "depth"),
    ],
)
def test_bad_members_raise_the_c_status_naming_the_member(change, cls, field):
    kw = {**SCENE, **change}
    with pytest.raises(cls) as ei:
        dc.plan(**kw)
    assert ei.value.field == field and f"field {field} = " in str(ei.value), str(ei.value)
    assert check_equal_c(kw) == cls.status


def test_argument_types():
    with pytest.raises(TypeError):
        dc.plan(**{k: v for k, v in SCENE.items() if k != "depth"})  # a required member missing
    with pytest.raises(TypeError, match="youngs"):
        dc.plan(**{**SCENE, "youngs": "7e10"})
    with pytest.raises(TypeError, match="criterion"):
        dc.plan(**SCENE, criterion=True)
    with pytest.raises(TypeError):
        dc.plan(7e10)  # type: ignore[misc]  # keyword only
    # walls takes a bool (or 0/1); the same plan as without walls when False.
    assert dc.plan(**SCENE, walls=False) == dc.plan(**SCENE, walls=0)
