"""Python conventions: broadcasting, dtype rules, enums, exceptions, help(), threads."""

from __future__ import annotations

import math
import pickle
import pydoc
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import demcontact as dc

F, O = dc.Criterion.FORCE, dc.Criterion.OVERLAP


def test_contract_example():
    a = dc.alpha_from_e(0.5, 1.5, dc.Criterion.FORCE)
    b = dc.alpha_from_e(0.5, 1.5, dc.Criterion.OVERLAP)
    assert isinstance(a, float) and a > b > 0
    # the round trip through the inverse, both criteria
    assert abs(dc.e_from_alpha(a, 1.5, F) - 0.5) < 1e-14
    assert abs(dc.e_from_alpha(b, 1.5, O) - 0.5) < 1e-14


def test_elastic_plastic_restitution():
    # e = 1 up to the yield speed; above, Thornton's closed form (the C export, bit for bit).
    assert dc.elastic_plastic_restitution(0.5) == 1.0 and dc.elastic_plastic_restitution(1.0) == 1.0
    x = np.array([2.0, 10.0, 100.0])
    e = dc.elastic_plastic_restitution(x)
    y = 1.0 / x
    want = math.sqrt(6 * math.sqrt(3) / 5) * np.sqrt(1 - y * y / 6) * (y / (y + 2 * np.sqrt(6 / 5 - y * y / 5))) ** 0.25
    assert np.all(np.abs(e - want) < 1e-15) and np.all(np.diff(e) < 0)
    assert dc.elastic_plastic_yield_speed(1e11, 1e-3, 1e-5, 1e9) > 0


def test_enums_match_header_constants():
    header = (dc.__file__ and __import__("pathlib").Path(__file__).resolve().parents[2] / "include" / "demcontact.h").read_text()
    import re

    consts = dict((m.group(1), int(m.group(2))) for m in re.finditer(r"#define DC_(\w+) (-?\d+)", header))
    # statuses: `enum dc_status { DC_OK = 0, ... }` (or #defines in older headers)
    consts.update((m.group(1), int(m.group(2))) for m in re.finditer(r"^\s*DC_((?:OK|ERR_\w+)) = (-?\d+),?$", header, re.M))
    assert int(dc.Criterion.OVERLAP) == consts["END_OVERLAP"] and int(dc.Criterion.FORCE) == consts["END_FORCE"]
    assert dc.LEVEL_MIN == consts["LEVEL_MIN"] and dc.LEVEL_MAX == consts["LEVEL_MAX"]
    for m in dc.Model:
        assert int(m) == consts["MODEL_" + m.name]
    status = {k: v for k, v in consts.items() if k == "OK" or k.startswith("ERR_")}
    assert {s.name: int(s) for s in dc.Status} == status
    # every error status has its own exception class
    assert set(dc.STATUS_CLASSES) == {v for k, v in status.items() if k != "OK"}


# ---- broadcasting ---------------------------------------------------------------------------


def test_broadcasting_shapes_and_values():
    e = np.array([0.2, 0.5, 0.8, 1.0])
    p = np.array([[1.0], [1.5], [3.0]])
    got = dc.alpha_from_e(e, p, F)
    assert got.shape == (3, 4) and got.dtype == np.float64
    for i in range(3):
        for j in range(4):
            assert got[i, j] == dc.alpha_from_e(float(e[j]), float(p[i, 0]), F)


def test_scalar_in_scalar_out_and_zero_d():
    assert type(dc.omega0(4.0, 1.0)) is float
    assert type(dc.omega0(np.float64(4.0), 1)) is float
    assert type(dc.omega0(np.array(4.0), 1.0)) is float  # 0-d like a ufunc gives a scalar
    assert dc.omega0([4.0], 1.0).shape == (1,)
    assert dc.omega0(np.empty((0, 3)), 1.0).shape == (0, 3)
    assert dc.omega0([[4.0, 9.0]], [[1.0], [4.0]]).tolist() == [[2.0, 3.0], [1.0, 1.5]]


def test_broadcast_mismatch_is_value_error():
    with pytest.raises(ValueError, match="could not be broadcast"):
        dc.alpha_from_e(np.ones(3) * 0.5, np.ones(4) * 1.5, F)
    with pytest.raises(ValueError, match="could not be broadcast"):
        dc.normal_force_batch(dc.pair_linear(1e4, 0.5, F), np.ones(3), np.ones(2), None, np.ones(3))


def test_non_contiguous_and_strided_inputs():
    base = np.linspace(0.05, 1.0, 40).reshape(5, 8)
    for view in (base[:, ::3], base.T, base[::-1, 1::2], np.broadcast_to(base[0], (4, 8))):
        assert not view.flags.c_contiguous or view.strides[0] == 0
        got = dc.alpha_from_e(view, 2.0, F)
        want = dc.alpha_from_e(np.ascontiguousarray(view), 2.0, F)
        assert got.shape == view.shape and got.tobytes() == want.tobytes()


@pytest.mark.parametrize("dtype", [np.int8, np.int32, np.int64, np.uint16, np.float16, np.float32, np.longdouble, ">f8"])
def test_real_dtypes_are_converted(dtype):
    k = np.array([1, 4, 9], dtype=dtype)
    got = dc.omega0(k, 1)
    assert got.dtype == np.float64
    assert got.tobytes() == dc.omega0(k.astype(np.float64), 1.0).tobytes()


@pytest.mark.parametrize(
    "bad",
    [True, np.array([True, False]), np.array([1 + 2j]), 1j, np.array(["a"]), "0.5", np.array([0.5], dtype=object), [0.5, None], None],
)
def test_non_real_inputs_rejected_with_type_error(bad):
    with pytest.raises(TypeError, match="argument 'e'"):
        dc.alpha_from_e(bad, 1.5, F)


def test_criterion_and_level_codes():
    assert dc.alpha_from_e(0.5, 1.5, 1) == dc.alpha_from_e(0.5, 1.5, F)  # IntEnum: ints work
    assert dc.alpha_from_e(0.5, 1.5, np.int64(1)) == dc.alpha_from_e(0.5, 1.5, F)
    with pytest.raises(dc.CriterionError):
        dc.alpha_from_e(0.5, 1.5, 2)
    with pytest.raises(dc.CriterionError):
        dc.alpha_from_e(0.5, 1.5, 2**40)
    for bad in ("force", 1.0, True, None):
        with pytest.raises(TypeError, match="criterion"):
            dc.alpha_from_e(0.5, 1.5, bad)
    with pytest.raises(dc.LevelError) as ei:
        dc.contact_duration_level(1.5, 1.0, 1.0, 1.0, F, 5)
    assert ei.value.code == 6112


# ---- errors ---------------------------------------------------------------------------------


def test_error_carries_code_message_and_location():
    e = np.array([[0.5, 0.7], [1.2, math.nan]])
    with pytest.raises(dc.RestitutionRangeError) as ei:
        dc.alpha_from_e(e, 1.5, F)
    err = ei.value
    assert err.code == 6103 == dc.Status.ERR_RESTITUTION_RANGE
    assert err.message == dc.status_str(6103)
    assert err.function == "alpha_from_e"
    assert "at index [1, 0]" in str(err) and "e=1.2" in str(err)
    assert isinstance(err, dc.InputError) and isinstance(err, ValueError) and isinstance(err, dc.DemcontactError)
    again = pickle.loads(pickle.dumps(err))
    assert type(again) is type(err) and again.code == err.code and str(again) == str(err)


@pytest.mark.parametrize(
    "call,cls,code",
    [
        (lambda: dc.alpha_from_e(math.nan, 1.5, F), dc.NotFiniteError, 6102),
        (lambda: dc.alpha_from_e(0.5, math.inf, F), dc.NotFiniteError, 6102),
        (lambda: dc.alpha_from_e(0.0, 1.5, F), dc.RestitutionRangeError, 6103),
        (lambda: dc.alpha_from_e(0.5, 0.99, F), dc.ExponentRangeError, 6104),
        (lambda: dc.omega0(-1.0, 1.0), dc.NotPositiveError, 6105),
        (lambda: dc.e_from_alpha(-0.1, 1.5, O), dc.NegativeError, 6106),
        (lambda: dc.elastic_plastic_restitution(-1.0), dc.NegativeError, 6106),
        (lambda: dc.elastic_plastic_yield_speed(1e11, 1e-3, 1e-5, math.nan), dc.NotFiniteError, 6102),
        (lambda: dc.omega0(1e308, 5e-324), dc.ResultRangeError, 6108),
        (lambda: dc.contact_duration(1.5, 10.0, 1.0, 1.0, O), dc.NoEventError, 6111),
        (lambda: dc.contact_trajectory(1.5, 1.0, 1.0, 1.0, 1.0, F, n=1), dc.BufferTooShortError, 6110),
        (lambda: dc.contact_trajectory(1.5, 1.0, 1.0, 1.0, 1.0, F, n=-3), dc.BufferTooShortError, 6110),
        (lambda: dc.duration_plan_init(1.5, -1), dc.LevelError, 6112),
        (lambda: dc.pair_hertz(1e7, 0.7, 1e7, 0.3, 0.5, F), dc.PoissonRangeError, 6114),
        (lambda: dc.normal_force(dc.pair_hertz(1e7, 0.3, 1e7, 0.3, 0.5, F), 1e-5, 0.1, -1e-3, 1e-3), dc.NotPositiveError, 6105),
        (lambda: dc.normal_force(dc.pair_linear(1e300, 0.5, O), 1e300, 1e300, None, 1.0), dc.ResultRangeError, 6108),
        (lambda: dc.normal_force_3d(dc.pair_linear(1e4, 0.5, F), [0, 0, 0], [0, 0, 0], 1e-3, 1.0, [0, 0, 0], [0, 0, 0], 1e-3, 1.0), dc.NotPositiveError, 6105),
    ],
)
def test_every_error_family(call, cls, code):
    with pytest.raises(cls) as ei:
        call()
    assert ei.value.code == code and type(ei.value) is dc.STATUS_CLASSES[code]


def test_wrong_shapes_and_scalar_only_arguments():
    with pytest.raises(TypeError, match="single number"):
        dc.pair_linear([1e4, 2e4], 0.5, F)
    with pytest.raises(TypeError, match="single number"):
        dc.contact_trajectory(1.5, [1.0, 2.0], 1.0, 1.0, 1.0, F)
    pair = dc.pair_linear(1e4, 0.5, F)
    with pytest.raises(ValueError, match="3-vector"):
        dc.normal_force_3d(pair, [0, 0], [0, 0, 0], 1e-3, 1.0, [1e-3, 0, 0], [0, 0, 0], 1e-3, 1.0)
    with pytest.raises(TypeError):
        dc.normal_force(object(), 1.0, 1.0, 1.0, 1.0)


def test_no_partial_results_on_error():
    # The first bad element raises; nothing is returned (the result never exists).
    e = np.full(1000, 0.5)
    e[700] = 2.0
    with pytest.raises(dc.RestitutionRangeError, match=r"at index \[700\]"):
        dc.alpha_from_e(e, 1.5, F)


# ---- pairs and the batch --------------------------------------------------------------------


def hertz():
    return dc.pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, F)


def test_pair_object():
    p = hertz()
    assert p.model is dc.Model.HERTZ and p.criterion is dc.Criterion.FORCE and p.clamp is True
    assert p.reads == ["vn", "r_eff", "m_eff"]
    assert dc.pair_powerlaw(1.5, 1e5, 1.0, O).reads == []  # undamped: overlap only
    assert dc.pair_powerlaw(1.5, 1e5, 0.5, O).reads == ["vn", "m_eff"]
    assert dc.pair_viscoelastic(1e7, 0.3, 1e7, 0.3, 1e-4, O).reads == ["vn", "r_eff"]
    assert "hertz" in repr(p)
    with pytest.raises(AttributeError):
        p.alpha = 1.0  # immutable
    with pytest.raises(TypeError):
        dc.Pair()  # only the constructors make pairs


def test_missing_required_input():
    with pytest.raises(TypeError, match="r_eff.*reads vn, r_eff, m_eff"):
        dc.normal_force(hertz(), 1e-5, 0.1, None, 1e-3)
    with pytest.raises(TypeError, match="m_eff"):
        dc.normal_force_batch(hertz(), np.ones(3) * 1e-6, np.ones(3), np.ones(3) * 1e-3)
    # inputs the pair does not read may be omitted
    lin = dc.pair_powerlaw(1.0, 1e4, 1.0, F)
    assert dc.normal_force(lin, 1e-3) == dc.normal_force_batch(lin, np.array([1e-3]))[0]


def test_batch_out_and_check():
    pair = hertz()
    rng = np.random.default_rng(1)
    n = 1000
    d, vn = rng.uniform(0, 1e-5, n), rng.uniform(-1, 1, n)
    r, m = np.full(n, 1e-3), np.full(n, 1e-5)
    want = dc.normal_force_batch(pair, d, vn, r, m)
    out = np.empty(n)
    res = dc.normal_force_batch(pair, d, vn, r, m, out=out)
    assert res is out and out.tobytes() == want.tobytes()
    # scalars broadcast (one copy of the broadcast run, same values)
    assert dc.normal_force_batch(pair, d, vn, 1e-3, 1e-5).tobytes() == want.tobytes()
    # non-contiguous and integer inputs are copied once, same values
    d2 = np.repeat(d, 2)[::2]
    assert dc.normal_force_batch(pair, d2, vn, r, m).tobytes() == want.tobytes()
    assert dc.normal_force_batch(pair, np.zeros(n, dtype=np.int32), vn, r, m).tolist() == [0.0] * n
    # out: wrong dtype, shape, layout, read-only, overlapping an input
    with pytest.raises(TypeError, match="out"):
        dc.normal_force_batch(pair, d, vn, r, m, out=np.empty(n, dtype=np.float32))
    with pytest.raises(ValueError, match="shape"):
        dc.normal_force_batch(pair, d, vn, r, m, out=np.empty(n + 1))
    with pytest.raises(ValueError, match="C-contiguous"):
        dc.normal_force_batch(pair, d, vn, r, m, out=np.empty(2 * n)[::2])
    ro = np.empty(n)
    ro.flags.writeable = False
    with pytest.raises(dc.BufferLayoutError):
        dc.normal_force_batch(pair, d, vn, r, m, out=ro)
    alias = d.copy()
    with pytest.raises(dc.BufferLayoutError):
        dc.normal_force_batch(pair, alias, vn, r, m, out=alias)
    # check=True: a NaN/inf force raises the checked kernel's status with the index
    r_bad = r.copy()
    r_bad[321] = -1.0
    d[321] = 1e-6
    with pytest.raises(dc.NotPositiveError, match=r"at index \[321\]"):
        dc.normal_force_batch(pair, d, vn, r_bad, m)
    raw = dc.normal_force_batch(pair, d, vn, r_bad, m, check=False)
    # check=False is the C batch: a clamped pair turns the NaN of sqrt(-1) into 0 silently,
    # an unclamped one returns NaN; check=True catches both.
    assert raw[321] == 0.0 and np.isfinite(raw).all()
    unclamped = dc.pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, O)
    assert math.isnan(dc.normal_force_batch(unclamped, d, vn, r_bad, m, check=False)[321])
    with pytest.raises(dc.NotPositiveError, match=r"at index \[321\]"):
        dc.normal_force_batch(unclamped, d, vn, r_bad, m)
    m_bad = m.copy()
    m_bad[5] = math.nan
    with pytest.raises(dc.NotFiniteError, match=r"at index \[5\]"):
        dc.normal_force_batch(pair, d, vn, r, m_bad)
    # empty input: empty output (the C batch rejects n = 0; numpy semantics here)
    assert dc.normal_force_batch(pair, np.empty(0), np.empty(0), np.empty(0), np.empty(0)).shape == (0,)
    # 2-D arrays keep their shape
    assert dc.normal_force_batch(pair, d.reshape(10, 100), vn.reshape(10, 100), 1e-3, 1e-5).shape == (10, 100)


def test_batch_zero_copy_reads_the_callers_memory():
    # Zero copy is observable: an input that is also `out` is detected as the same memory by
    # numpy's borrow tracking; a copied input would not be.
    pair = dc.pair_linear(1e4, 0.5, F)
    d = np.full(8, 1e-4)
    with pytest.raises(dc.BufferLayoutError):
        dc.normal_force_batch(pair, d, d, None, d, out=d)


def test_batch_hands_the_callers_memory_to_the_library():
    # Stronger than the borrow tracking above: two views of one buffer with different bases
    # (invisible to rust-numpy) as input and `out` are refused by dc_normal_force_batch's own
    # overlap check, which only sees them overlap if the caller's memory is passed uncopied.
    pair = dc.pair_linear(1e4, 0.5, F)
    n = 64
    buf = bytearray(8 * n)
    d = np.frombuffer(memoryview(buf), dtype=np.float64)
    out = np.frombuffer(memoryview(buf), dtype=np.float64)
    d[:] = 1e-4
    vn, m = np.full(n, 0.1), np.full(n, 1e-5)
    for check in (False, True):
        with pytest.raises(dc.BufferLayoutError) as ei:
            dc.normal_force_batch(pair, d, vn, None, m, out=out, check=check)
        assert "borrowed" not in str(ei.value)  # the library's check, not the borrow tracking
    dc.normal_force_batch(pair, d.copy(), vn, None, m, out=out)  # a copy passes


# ---- threads --------------------------------------------------------------------------------


def test_batch_calls_from_a_thread_pool_are_bit_identical():
    rng = np.random.default_rng(3)
    pairs = [hertz(), dc.pair_powerlaw(1.7, 3e5, 0.3, O), dc.pair_linear(1e4, 0.8, F), dc.pair_viscoelastic(1e7, 0.3, 1e7, 0.3, 1e-4, F)]
    n = 200_000
    shared = [rng.uniform(0, 1e-5, n), rng.uniform(-1, 1, n), rng.uniform(1e-4, 1e-3, n), rng.uniform(1e-6, 1e-4, n)]
    serial = [dc.normal_force_batch(p, *shared) for p in pairs]

    def work(i):
        p = pairs[i % len(pairs)]
        out = np.empty(n)
        dc.normal_force_batch(p, *shared, out=out)
        alpha = dc.alpha_from_e(np.linspace(0.01, 1.0, 1000), 1.5, F)
        return i % len(pairs), out, alpha

    with ThreadPoolExecutor(max_workers=8) as ex:
        results = list(ex.map(work, range(64)))
    alpha_ref = dc.alpha_from_e(np.linspace(0.01, 1.0, 1000), 1.5, F)
    for k, out, alpha in results:
        assert out.tobytes() == serial[k].tobytes()
        assert alpha.tobytes() == alpha_ref.tobytes()


def test_shared_out_from_two_threads_is_refused_not_raced():
    # Two calls writing the same `out` at once: the second is refused (BufferLayoutError) by
    # the borrow tracking, never a data race. Whichever wins, the array ends up correct.
    pair = hertz()
    n = 400_000
    d, vn = np.full(n, 1e-6), np.full(n, 0.1)
    out = np.empty(n)
    want = dc.normal_force_batch(pair, d, vn, 1e-3, 1e-5)

    def work(_):
        try:
            dc.normal_force_batch(pair, d, vn, np.full(n, 1e-3), np.full(n, 1e-5), out=out)
            return "ok"
        except dc.BufferLayoutError:
            return "refused"

    with ThreadPoolExecutor(max_workers=4) as ex:
        outcomes = list(ex.map(work, range(16)))
    assert "ok" in outcomes
    assert out.tobytes() == want.tobytes()


# ---- documentation --------------------------------------------------------------------------


def test_help_shows_signature_and_docstring():
    text = pydoc.render_doc(dc.alpha_from_e, renderer=pydoc.plaintext)
    assert "alpha_from_e(e, p, criterion)" in text and "Criterion.FORCE" in text
    for name in dc.__all__:
        obj = getattr(dc, name)
        if callable(obj) and not isinstance(obj, type):
            assert obj.__doc__ and len(obj.__doc__) > 40, name
    assert "Pair" in pydoc.render_doc(dc.Pair, renderer=pydoc.plaintext)


def test_stub_file_lists_every_public_function():
    import pathlib
    import re

    stub = (pathlib.Path(dc.__file__).parent / "__init__.pyi").read_text()
    defined = set(re.findall(r"^def (\w+)\(", stub, re.M)) | set(re.findall(r"^class (\w+)", stub, re.M))
    defined |= set(re.findall(r"^    (\w+) as \1,$", stub, re.M))
    if re.search(r"^from \._errors import \*$", stub, re.M):
        # The stub re-exports the exception classes from _errors, which lists them once.
        defined |= set(dc._errors.__all__)
    public = {n for n in dc.__all__ if not n.isupper()}
    missing = public - defined - {"Status"}
    assert not missing, missing


def test_stubs_match_the_runtime_module():
    # mypy's stubtest: every name, signature, default and class in demcontact/__init__.pyi
    # agrees with what the compiled module exports (and nothing public is missing).
    import subprocess
    import sys

    import mypy  # noqa: F401  (installed by scripts/test_python.sh; a missing one fails)
    r = subprocess.run([sys.executable, "-m", "mypy.stubtest", "demcontact"], capture_output=True, text=True, cwd="/")
    assert r.returncode == 0, r.stdout[-4000:] + r.stderr[-2000:]


def test_builtin_for_lammps_release():
    # damping tsuji multiplies eta by sqrt(2) from 2 Sep 2026: the release picks the builtin, and
    # the corrected value differs between them (each checked against an ODE in the Rust tests).
    for release in ["2026-09-02", "20260902", "2Sep2026", "2 Sep 2026", 20260902]:
        got = dc.builtin_for_lammps_release(dc.Builtin.LAMMPS_TSUJI_HERTZ, release)
        assert got is dc.Builtin.LAMMPS_TSUJI_HERTZ_SQRT2, release
    assert dc.builtin_for_lammps_release(4, "22Jul2025") is dc.Builtin.LAMMPS_TSUJI_HERTZ
    assert dc.builtin_for_lammps_release(5, "2027-01-01") is dc.Builtin.LAMMPS_TSUJI_HOOKE_SQRT2
    # Independently: LAMMPS' damp = scale * eta(typed e) (Marshall 2009 eq. 53), the Tsuji ratio
    # zeta = damp / sqrt(2 (p + 1)) at p = 3/2, and the force-end restitution of that ratio
    # (limit_damping), exp(-2 zeta arccos(zeta) / sqrt(1 - zeta^2)).
    def realised(typed, scale):
        c = [1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218]
        eta = sum(ci * typed**i for i, ci in enumerate(c))
        z = scale * eta / math.sqrt(5.0)
        return math.exp(-2.0 * z * math.acos(z) / math.sqrt(1.0 - z * z))

    old = float(dc.builtin_value_for_e(dc.Builtin.LAMMPS_TSUJI_HERTZ, True, 0.5))
    new = float(dc.builtin_value_for_e(dc.Builtin.LAMMPS_TSUJI_HERTZ_SQRT2, True, 0.5))
    assert abs(realised(old, 1.0) - 0.5) < 1e-12 and abs(realised(new, math.sqrt(2.0)) - 0.5) < 1e-12
    assert abs(realised(old, math.sqrt(2.0)) - 0.5) > 0.03, "the releases' values must differ"
    for release in ["2026-02-11", "2026-02-30", "yesterday", 2026_02_11]:
        with pytest.raises(dc.BuiltinVersionError) as ei:
            dc.builtin_for_lammps_release(dc.Builtin.LAMMPS_TSUJI_HERTZ, release)
        assert repr(release) in str(ei.value) and ei.value.code == 6134
    with pytest.raises(dc.BuiltinModelError):
        dc.builtin_for_lammps_release(dc.Builtin.LIGGGHTS_HERTZ, "2026-09-02")
