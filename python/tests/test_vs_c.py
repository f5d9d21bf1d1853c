"""Every function against the C ABI on the same inputs: the same status, and on success the
same double bit for bit (scalar calls and one array call per integer-code combination)."""

from __future__ import annotations

import ctypes as C
import math
import struct
import zlib

import numpy as np
import pytest

import demcontact as dc

from cabi import D, I32, PD, Energy, Pair, Plan, call_scalar, fn, lib

GOOD = [0.3, 0.5, 0.9, 1.0, 1.5, 2.0, 3.0, 10.0, 1e-3, 1e3, 0.999, 1e-6]
BAD = [0.0, -1.0, math.nan, math.inf, -math.inf, 1e300, 5e-324, -0.0]
CRIT = [0, 1, 0, 1, 2, -1]
LEVEL = [0, 1, 2, 3, 4, 5, -1]

# name, parameter order ('d' double, 'i' int), int pools in order, number of draws, good pool
SPECS = [
    ("alpha_from_e", "ddi", [CRIT], 300, GOOD),
    ("e_from_alpha", "ddi", [CRIT], 300, GOOD),
    ("hertz_stiffness", "dddddd", [], 300, GOOD + [0.23, 0.49, math.inf]),
    ("effective_modulus", "dddd", [], 300, GOOD + [0.23, -0.5]),
    ("omega0", "dd", [], 200, GOOD),
    ("max_overlap", "dddd", [], 300, GOOD),
    ("time_of_max_overlap", "dddd", [], 300, GOOD),
    ("contact_duration", "ddddi", [CRIT], 300, GOOD),
    ("contact_duration_level", "ddddii", [CRIT, LEVEL], 300, GOOD),
    ("dt_crit", "ddd", [], 200, GOOD),
    ("dt_linearised", "ddd", [], 200, GOOD),
    ("dt_static", "dddd", [], 200, GOOD),
    ("dt_for_accuracy", "ddiddd", [[0, 1, 1, 0, 3]], 16, [1.0, 1.0, 0.9, 0.5, 0.2]),
    ("viscoelastic_e", "di", [CRIT], 200, GOOD),
    ("viscoelastic_e_series", "di", [CRIT], 200, GOOD),
    ("viscoelastic_e_reference", "di", [CRIT], 60, [0.0, 0.1, 0.5, 1.0, 2.0, 5.0]),
    ("viscoelastic_b", "ddd", [], 200, GOOD),
    ("viscoelastic_e_of_speed", "dddi", [CRIT], 200, GOOD),
    ("viscoelastic_b_from_e", "di", [CRIT], 200, GOOD),
    ("viscoelastic_beta_from_e", "ddi", [CRIT], 200, GOOD),
    ("viscoelastic_a_from_e", "ddddi", [CRIT], 200, GOOD),
    ("viscoelastic_speed_for_e", "ddi", [CRIT], 200, GOOD),
    ("builtin_value_for_e", "iid", [[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 0, 11], [0, 1, 1, 2]], 300, GOOD + [0.05, 0.1353, 0.2]),
    ("builtin_realised_e", "iid", [[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 0, 11], [0, 1, 1, 2]], 300, GOOD + [0.05, 0.1353, 0.2]),
    ("builtin_yade_viscel_cn", "ddd", [], 200, GOOD),
]


def bits(x: float) -> bytes:
    return struct.pack("<d", x)


def draws(name, order, int_pools, n, good):
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    bad = [b for b in BAD if not (name == "viscoelastic_e_reference" and b == 1e300)]
    out = []
    for _ in range(n):
        args, ii = [], 0
        for ch in order:
            if ch == "i":
                pool = int_pools[ii]
                ii += 1
                args.append(int(pool[rng.integers(len(pool))]))
            elif rng.random() < (0.97 if n <= 16 else 0.85):
                args.append(float(good[rng.integers(len(good))]))
            else:
                args.append(float(bad[rng.integers(len(bad))]))
        out.append(tuple(args))
    return out


@pytest.mark.parametrize("name,order,int_pools,n,good", SPECS, ids=[s[0] for s in SPECS])
def test_scalar_calls_equal_c(name, order, int_pools, n, good):
    py = getattr(dc, name)
    ok = err = 0
    for args in draws(name, order, int_pools, n, good):
        s, v = call_scalar(name, order, args)
        if s == 0:
            r = py(*args)
            assert type(r) is float, (name, args)
            assert bits(r) == bits(v), (name, args, r, v)
            ok += 1
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                py(*args)
            assert ei.value.code == s, (name, args)
            assert ei.value.message == dc.status_str(s)
            assert isinstance(ei.value, dc.STATUS_CLASSES[s])
            err += 1
    # Neither branch may be vacuous.
    assert ok >= (3 if n <= 16 else 5), (name, ok)
    assert err >= 1 or n <= 16, (name, err)


@pytest.mark.parametrize("name,order,int_pools,n,good", SPECS, ids=[s[0] for s in SPECS])
def test_array_calls_equal_c(name, order, int_pools, n, good):
    py = getattr(dc, name)
    groups = {}
    for args in draws(name, order, int_pools, n, good):
        key = tuple(a for a, ch in zip(args, order) if ch == "i")
        groups.setdefault(key, []).append(args)
    checked = 0
    for key, rows in groups.items():
        cols = list(zip(*rows))
        results = [call_scalar(name, order, r) for r in rows]
        call = [np.array(c, dtype=np.float64) if ch == "d" else c[0] for c, ch in zip(cols, order)]
        bad = [i for i, (s, _) in enumerate(results) if s != 0]
        if not bad:
            got = py(*call)
            assert isinstance(got, np.ndarray) and got.shape == (len(rows),)
            want = np.array([v for _, v in results])
            assert got.tobytes() == want.tobytes(), name
            checked += len(rows)
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                py(*call)
            assert ei.value.code == results[bad[0]][0]
            assert f"at index [{bad[0]}]" in str(ei.value)
            # The valid rows alone give the C values.
            good_rows = [i for i, (s, _) in enumerate(results) if s == 0]
            if good_rows:
                sub = [c[good_rows] if isinstance(c, np.ndarray) else c for c in call]
                got = py(*sub)
                want = np.array([results[i][1] for i in good_rows])
                assert np.asarray(got).tobytes() == want.tobytes(), name
                checked += len(good_rows)
    assert checked > 0, name


def test_energy_partition_equals_c():
    f = fn("energy_partition", [D, D, I32, C.POINTER(Energy)])
    rows = [(p, a, c) for p in (1.0, 1.5, 2.0, 5.0) for a in (0.0, 0.3, 1.0, 2.2, 4.0, 30.0) for c in (0, 1)]
    for p, a, c in rows:
        en = Energy()
        assert f(p, a, c, C.byref(en)) == 0
        got = dc.energy_partition(p, a, dc.Criterion(c))
        for field in Energy._fields_:
            assert bits(getattr(got, field[0])) == bits(getattr(en, field[0]))
    # arrays: every field an array of the broadcast shape
    ps = np.array([1.0, 1.5, 2.0])[:, None]
    al = np.array([0.0, 0.5, 3.0])
    got = dc.energy_partition(ps, al, dc.Criterion.FORCE)
    for i in range(3):
        for j in range(3):
            en = Energy()
            assert f(float(ps[i, 0]), float(al[j]), 1, C.byref(en)) == 0
            assert bits(got.clamped[i, j]) == bits(en.clamped)
            assert bits(got.e[i, j]) == bits(en.e)
    for bad, code in [((0.5, 1.0, 1), 6104), ((1.5, -1.0, 1), 6106), ((1.5, 1.0, 7), 6107), ((math.nan, 1.0, 0), 6102)]:
        en = Energy()
        assert f(*bad, C.byref(en)) == code
        with pytest.raises(dc.DemcontactError) as ei:
            dc.energy_partition(*bad)
        assert ei.value.code == code


def test_k_gamma_equals_c():
    f = fn("viscoelastic_k_gamma", [D, D, D, PD, PD])
    for rho, a, m in [(1e6, 1e-4, 1e-3), (2.0, 0.0, 3.0), (1e300, 1e10, 1e-300), (1.0, -1.0, 1.0), (0.0, 1.0, 1.0)]:
        k, g = D(), D()
        s = f(rho, a, m, C.byref(k), C.byref(g))
        if s == 0:
            gk, gg = dc.viscoelastic_k_gamma(rho, a, m)
            assert bits(gk) == bits(k.value) and bits(gg) == bits(g.value)
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                dc.viscoelastic_k_gamma(rho, a, m)
            assert ei.value.code == s


def test_trajectory_equals_c():
    f = fn(
        "contact_trajectory",
        [D, D, D, D, D, I32, I32, C.c_size_t, PD, PD, PD, PD, C.c_size_t],
    )
    for args in [
        (1.5, 1.0, 1.0, 10.0, 2.0, 1, 4, 64),
        (1.0, 0.5, 0.3, 100.0, 1e-3, 0, 2, 5),
        (2.0, 5.0, 2.0, 3.0, 1.0, 1, 0, 2),
        (1.5, 5.0, 2.0, 3.0, 1.0, 0, 4, 16),  # overdamped, overlap end: no event
        (1.5, 1.0, 1.0, 1.0, 1.0, 1, 9, 16),  # bad level
        (1.5, 1.0, 1.0, 1.0, 1.0, 1, 4, 1),  # n < 2
        (0.5, 1.0, 1.0, 1.0, 1.0, 1, 4, 16),  # p < 1
    ]:
        n = args[-1]
        bufs = [(D * max(n, 1))() for _ in range(4)]
        s = f(*args[:-1], n, *bufs, n)
        if s == 0:
            tr = dc.contact_trajectory(*args[:6], level=args[6], n=n)
            for got, want in zip(tr, bufs):
                assert got.dtype == np.float64 and got.shape == (n,)
                assert got.tobytes() == bytes(want)
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                dc.contact_trajectory(*args[:6], level=args[6], n=n)
            assert ei.value.code == s


def test_duration_plan_equals_c():
    init = fn("duration_plan_init", [D, I32, C.POINTER(Plan)])
    planned = fn("contact_duration_planned", [C.POINTER(Plan), D, D, D, I32, PD])
    for p in (1.0, 1.25, 1.5, 3.0):
        for level in range(dc.LEVEL_MIN, dc.LEVEL_MAX + 1):
            cp = Plan()
            assert init(p, level, C.byref(cp)) == 0
            plan = dc.duration_plan_init(p, level)
            assert plan.p == p and plan.level == level
            for a in (0.0, 0.4, 1.9, 2.5, 6.0):
                for c in (0, 1):
                    out = D()
                    s = planned(C.byref(cp), a, 0.7, 13.0, c, C.byref(out))
                    if s == 0:
                        got = dc.contact_duration_planned(plan, a, 0.7, 13.0, dc.Criterion(c))
                        assert bits(got) == bits(out.value)
                        assert bits(plan.contact_duration(a, 0.7, 13.0, c)) == bits(out.value)
                    else:
                        with pytest.raises(dc.DemcontactError) as ei:
                            dc.contact_duration_planned(plan, a, 0.7, 13.0, c)
                        assert ei.value.code == s
    for p, level, code in [(0.5, 4, 6104), (1.5, 5, 6112), (math.nan, 1, 6102)]:
        cp = Plan()
        assert init(p, level, C.byref(cp)) == code
        with pytest.raises(dc.DemcontactError) as ei:
            dc.duration_plan_init(p, level)
        assert ei.value.code == code


PAIR_CASES = [
    ("pair_powerlaw", "dddi", [(1.5, 1e5, 0.5, 1), (1.0, 2e3, 0.9, 0), (2.0, 7.0, 1.0, 1), (2.7, 1e6, 0.1, 0),
                               (0.5, 1.0, 0.5, 1), (1.5, -1.0, 0.5, 1), (1.5, 1.0, 0.0, 1), (1.5, 1.0, 0.5, 3)]),
    ("pair_powerlaw_alpha", "dddi", [(1.5, 1e5, 0.7, 1), (1.0, 2e3, 0.0, 0), (1.5, 1.0, -0.1, 1)]),
    ("pair_linear", "ddi", [(1e4, 0.5, 1), (1e4, 0.5, 0), (1e4, 1.0, 1), (math.nan, 0.5, 1)]),
    ("pair_hertz", "dddddi", [(63e9, 0.23, 63e9, 0.23, 0.5, 1), (1e7, 0.3, 2e11, 0.29, 0.9, 0),
                              (1e7, 0.6, 1e7, 0.3, 0.5, 1), (-1.0, 0.3, 1e7, 0.3, 0.5, 1)]),
    ("pair_viscoelastic", "dddddi", [(1e7, 0.3, 1e7, 0.3, 1e-4, 1), (1e7, 0.3, 1e7, 0.3, 0.0, 0),
                                     (1e7, 0.3, 1e7, 0.3, -1e-4, 0)]),
]


def c_pair(name, order, args):
    f = fn(name, [D if ch == "d" else I32 for ch in order] + [C.POINTER(Pair)])
    cp = Pair()
    return f(*args, C.byref(cp)), cp


def all_pairs():
    out = []
    for name, order, rows in PAIR_CASES:
        for args in rows:
            s, cp = c_pair(name, order, args)
            if s == 0:
                out.append((getattr(dc, name)(*args), cp))
    return out


@pytest.mark.parametrize("name,order,rows", PAIR_CASES, ids=[c[0] for c in PAIR_CASES])
def test_pair_constructors_equal_c(name, order, rows):
    for args in rows:
        s, cp = c_pair(name, order, args)
        if s == 0:
            pair = getattr(dc, name)(*args)
            for field, _ in Pair._fields_:
                got = getattr(pair, field)
                want = getattr(cp, field)
                if field in ("model", "criterion"):
                    assert int(got) == want
                elif field == "clamp":
                    assert got == bool(want)
                elif field == "kernel":
                    assert got == want
                else:
                    assert bits(got) == bits(want), (name, args, field)
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                getattr(dc, name)(*args)
            assert ei.value.code == s, (name, args)


def test_forces_equal_c():
    checked = fn("normal_force_checked", [C.POINTER(Pair), D, D, D, D, PD])
    batch = fn("normal_force_batch", [C.POINTER(Pair), C.c_size_t, PD, PD, PD, PD, PD])
    rng = np.random.default_rng(7)
    n = 2000
    d = rng.uniform(-1e-5, 1e-4, n)
    vn = rng.uniform(-3, 3, n)
    r = rng.uniform(1e-4, 1e-2, n)
    m = rng.uniform(1e-6, 1e-2, n)
    ptr = lambda a: a.ctypes.data_as(PD)  # noqa: E731
    pairs = all_pairs()
    assert len(pairs) >= 10
    for pair, cp in pairs:
        want = np.empty(n)
        assert batch(C.byref(cp), n, ptr(d), ptr(vn), ptr(r), ptr(m), ptr(want)) == 0
        got = dc.normal_force_batch(pair, d, vn, r, m)
        assert got.tobytes() == want.tobytes()
        got_scalarwise = dc.normal_force(pair, d, vn, r, m)
        assert got_scalarwise.tobytes() == want.tobytes()
        for i in range(0, n, 97):
            out = D()
            assert checked(C.byref(cp), d[i], vn[i], r[i], m[i], C.byref(out)) == 0
            assert bits(dc.normal_force(pair, d[i], vn[i], r[i], m[i])) == bits(out.value)
            assert bits(pair.normal_force(d[i], vn[i], r[i], m[i])) == bits(out.value)
        # invalid per-contact inputs: the C checked status, and the batch's unchecked value
        for bad in [(1e-5, 0.1, -1.0, 1e-3), (1e-5, math.nan, 1e-3, 1e-3), (1e-5, 0.1, 1e-3, 0.0), (math.inf, 0.1, 1e-3, 1e-3)]:
            out = D()
            s = checked(C.byref(cp), *bad, C.byref(out))
            if s == 0:
                assert bits(dc.normal_force(pair, *bad)) == bits(out.value)
            else:
                with pytest.raises(dc.DemcontactError) as ei:
                    dc.normal_force(pair, *bad)
                assert ei.value.code == s
            arrs = [np.array([x]) for x in bad]
            want1 = np.empty(1)
            assert batch(C.byref(cp), 1, *(ptr(a) for a in arrs), ptr(want1)) == 0
            got1 = dc.normal_force_batch(pair, *arrs, check=False)
            assert got1.tobytes() == want1.tobytes()


def test_fast_batch_equals_c_and_is_near_the_exact_one():
    """fast=True is dc_normal_force_batch_fast bit for bit; it moves general-p and damped Hertz
    forces by at most 8 ulp of the force's terms and leaves every other pair's bits alone."""
    fast = fn("normal_force_batch_fast", [C.POINTER(Pair), C.c_size_t, PD, PD, PD, PD, PD])
    rng = np.random.default_rng(11)
    n = 3000
    d = rng.uniform(-1e-5, 1e-4, n)
    vn = rng.uniform(-3, 3, n)
    r = rng.uniform(1e-4, 1e-2, n)
    m = rng.uniform(1e-6, 1e-2, n)
    ptr = lambda a: a.ctypes.data_as(PD)  # noqa: E731
    moved = 0
    # every pair of the other tests, and general p over its range (p = 1.7 in both criteria, p = 9)
    extra = [(1.7, 1e8, 0.4, 1), (1.7, 1e8, 0.4, 0), (1.3, 1e5, 0.05, 1), (9.0, 1e12, 0.6, 1)]
    pairs = all_pairs() + [(dc.pair_powerlaw(*a), c_pair("pair_powerlaw", "dddi", a)[1]) for a in extra]
    d[::7] = 10.0 ** rng.uniform(-40, -38, d[::7].size)  # outside the table range: the exact power
    for pair, cp in pairs:
        want = np.empty(n)
        assert fast(C.byref(cp), n, ptr(d), ptr(vn), ptr(r), ptr(m), ptr(want)) == 0
        got = dc.normal_force_batch(pair, d, vn, r, m, fast=True)
        assert got.tobytes() == want.tobytes()
        assert dc.normal_force_batch(pair, d, vn, r, m, fast=True, check=False).tobytes() == want.tobytes()
        assert pair.normal_force_batch(d, vn, r, m, fast=True).tobytes() == want.tobytes()
        exact = dc.normal_force_batch(pair, d, vn, r, m)
        touching = d > 0
        if pair.model == dc.Model.HERTZ:
            q = np.sqrt(r * d, where=touching, out=np.zeros(n))
            terms = np.abs(pair.k * q * d) + np.abs(pair.c * np.sqrt(m * q) * vn)
        else:
            s = np.power(d, pair.h, where=touching, out=np.zeros(n))
            terms = np.abs(pair.k * d * s * s) + np.abs(pair.c * np.sqrt(m) * s * vn)
        assert np.all(np.abs(got - exact) <= 8 * np.finfo(float).eps * terms)
        general_p = pair.model == dc.Model.POWERLAW and pair.p not in (1.0, 1.5, 2.0) and pair.p <= 9
        if not (general_p or (pair.model == dc.Model.HERTZ and pair.alpha > 0)):
            assert got.tobytes() == exact.tobytes()
        moved += int(got.tobytes() != exact.tobytes())
    assert moved >= 6


def test_force_3d_equals_c():
    f = fn("normal_force_3d", [C.POINTER(Pair), PD, PD, D, D, PD, PD, D, D, PD])
    v3 = lambda *x: (D * 3)(*x)  # noqa: E731
    for pair, cp in all_pairs():
        for x1, v1, R1, m1, x2, v2, R2, m2 in [
            ((0, 0, 0), (0.1, 0, 0), 1e-3, 1e-5, (1.99e-3, 0, 0), (-0.1, 0, 0), 1e-3, 1e-5),
            ((0, 0, 0), (0, 0, 0), 1e-3, 1e-5, (5e-3, 0, 0), (0, 0, 0), 1e-3, 1e-5),
            ((0, 0, 0), (0, 0, 0), 1e-3, 1e-5, (0, 0, 0), (0, 0, 0), 1e-3, 1e-5),
            ((0, 0, 0), (0, 0, 0), -1e-3, 1e-5, (1e-3, 0, 0), (0, 0, 0), 1e-3, 1e-5),
        ]:
            out = (D * 3)()
            s = f(C.byref(cp), v3(*x1), v3(*v1), R1, m1, v3(*x2), v3(*v2), R2, m2, out)
            if s == 0:
                got = dc.normal_force_3d(pair, x1, v1, R1, m1, x2, v2, R2, m2)
                assert got.shape == (3,) and got.tobytes() == bytes(out)
            else:
                with pytest.raises(dc.DemcontactError) as ei:
                    dc.normal_force_3d(pair, x1, v1, R1, m1, x2, v2, R2, m2)
                assert ei.value.code == s


def test_status_strings_and_version_equal_c():
    for code in list(dc.Status) + [1, 6100, 6198, -5]:
        assert dc.status_str(int(code)) == lib.dc_status_str(int(code)).decode()
    assert dc.version() == lib.dc_version().decode() == dc.__version__
    lib.dc_status_known.argtypes = [I32]
    lib.dc_status_known.restype = I32
    for code in list(dc.Status) + [1, 6100, 6115, 6198, -5, 2**31 - 1, -(2**31)]:
        assert dc.status_known(int(code)) == bool(lib.dc_status_known(int(code)))
    assert dc.status_known(2**40) is False


class FitResultC(C.Structure):
    _fields_ = [
        (name, D)
        for name in (
            "beta", "beta_se", "e_const", "e_const_se", "chi2_viscoelastic", "chi2_constant",
            "max_residual_viscoelastic", "max_residual_constant", "v_min", "v_max",
            "e_viscoelastic_at_v_min", "e_viscoelastic_at_v_max", "max_model_deviation",
        )
    ] + [("model", I32), ("se_from_scatter", I32), ("iterations", I32), ("robust", I32)]


def test_fit_restitution_equals_c():
    f = fn("fit_restitution", [C.c_size_t, PD, PD, PD, I32, D, I32, PD, PD, C.POINTER(FitResultC)])
    rng = np.random.default_rng(5)
    v = np.geomspace(0.05, 5.0, 12)
    e_visc = np.array([dc.viscoelastic_e(0.4 * x**0.2, dc.Criterion.FORCE) for x in v]) + rng.normal(0, 0.003, v.size)
    e_const = 0.7 + rng.normal(0, 0.002, v.size)
    ptr = lambda a: None if a is None else a.ctypes.data_as(PD)  # noqa: E731
    cases = [
        (v, e_visc, None, 1, 0.01, False),
        (v, e_visc, np.full(v.size, 0.003), 1, 0.01, True),
        (v, e_const, None, 0, 0.05, False),
        (v[:1], e_const[:1], None, 1, 0.01, False),  # too few
        (np.full(5, 1.0), e_const[:5], None, 1, 0.01, False),  # degenerate
        (v, np.where(np.arange(v.size) == 3, 1.5, e_const), None, 1, 0.01, False),  # e > 1
        (v, e_const, None, 1, -1.0, False),  # tol <= 0
        (v, e_const, None, 5, 0.01, False),  # bad criterion
    ]
    ok = 0
    for vv, ee, ss, crit, tol, robust in cases:
        vv, ee = np.ascontiguousarray(vv), np.ascontiguousarray(ee)
        rv, rc, out = np.empty(vv.size), np.empty(vv.size), FitResultC()
        st = f(vv.size, ptr(vv), ptr(ee), ptr(ss), crit, tol, int(robust), ptr(rv), ptr(rc), C.byref(out))
        if st == 0:
            got = dc.fit_restitution(vv, ee, ss, dc.Criterion(crit), tol, robust)
            for name, _ in FitResultC._fields_:
                g, w = getattr(got, name), getattr(out, name)
                if isinstance(w, float):
                    assert bits(g) == bits(w), name
                else:
                    assert int(g) == w, name
            assert got.model in (dc.FitModel.CONSTANT, dc.FitModel.VISCOELASTIC)
            assert got.resid_viscoelastic.tobytes() == rv.tobytes()
            assert got.resid_constant.tobytes() == rc.tobytes()
            ok += 1
        else:
            with pytest.raises(dc.DemcontactError) as ei:
                dc.fit_restitution(vv, ee, ss, crit, tol, robust)
            assert ei.value.code == st
    assert ok == 3
