"""Speed of the Python binding against the C ABI in the same run (not a test).

    .venv-python/bin/python python/bench/bench_batch.py [n_contacts] [repeats]

1. Batch normal force over n contacts (default 1e6) for Hertz, power law p = 1.7 (pow) and the
   linear spring-dashpot: dc_normal_force_batch through ctypes (the C baseline: one call on the
   same numpy buffers) against demcontact.normal_force_batch with out= (check=False, the C
   semantics), check=True (default, screened in cache-sized blocks), and without out= (allocates
   the result). C and Python runs alternate; medians of `repeats` runs, ns per contact.
2. Scalar call overhead: demcontact.<f>(scalars) against the same C function through ctypes
   and the in-library cost (the batch/array path per element).
"""

from __future__ import annotations

import ctypes as C
import statistics
import sys
import time
import timeit

import numpy as np

import demcontact as dc

sys.path.insert(0, str(__import__("pathlib").Path(__file__).resolve().parents[1] / "tests"))
from cabi import D, PD, Pair, fn  # noqa: E402

n = int(float(sys.argv[1])) if len(sys.argv) > 1 else 1_000_000
reps = int(sys.argv[2]) if len(sys.argv) > 2 else 21
F = dc.Criterion.FORCE

rng = np.random.default_rng(11)
d = rng.uniform(-1e-6, 2e-5, n)
vn = rng.uniform(-1.0, 1.0, n)
r = rng.uniform(5e-4, 2e-3, n)
m = rng.uniform(1e-6, 1e-4, n)
out_c = np.empty(n)
out_py = np.empty(n)
ptr = lambda a: a.ctypes.data_as(PD)  # noqa: E731
c_batch = fn("normal_force_batch", [C.POINTER(Pair), C.c_size_t, PD, PD, PD, PD, PD])

cases = {
    "hertz": ("pair_hertz", "dddddi", (63e9, 0.23, 63e9, 0.23, 0.5, 1)),
    "powerlaw p=1.7": ("pair_powerlaw", "dddi", (1.7, 1e8, 0.5, 1)),
    "linear": ("pair_linear", "ddi", (1e4, 0.5, 1)),
}


def t(f):
    s = time.perf_counter()
    f()
    return time.perf_counter() - s


print(f"batch normal force, n = {n:.0e} contacts, {reps} alternating runs, median ns/contact (min)")
print(f"{'pair':16} {'C batch':>14} {'py out=,check=False':>22} {'py out=,check=True':>20} {'py alloc,check=True':>20} {'ratio (F/C)':>11}")
for label, (ctor, order, args) in cases.items():
    cp = Pair()
    f = fn(ctor, [D if ch == "d" else C.c_int32 for ch in order] + [C.POINTER(Pair)])
    assert f(*args, C.byref(cp)) == 0
    pair = getattr(dc, ctor)(*args)
    runs = {k: [] for k in ("c", "fast", "checked", "alloc")}
    for _ in range(reps):
        runs["c"].append(t(lambda: c_batch(C.byref(cp), n, ptr(d), ptr(vn), ptr(r), ptr(m), ptr(out_c))))
        runs["fast"].append(t(lambda: dc.normal_force_batch(pair, d, vn, r, m, out=out_py, check=False)))
        runs["checked"].append(t(lambda: dc.normal_force_batch(pair, d, vn, r, m, out=out_py)))
        runs["alloc"].append(t(lambda: dc.normal_force_batch(pair, d, vn, r, m)))
    assert out_py.tobytes() == out_c.tobytes()
    med = {k: statistics.median(v) / n * 1e9 for k, v in runs.items()}
    mn = {k: min(v) / n * 1e9 for k, v in runs.items()}
    cell = lambda k: f"{med[k]:.2f} ({mn[k]:.2f})"  # noqa: E731
    print(f"{label:16} {cell('c'):>14} {cell('fast'):>22} {cell('checked'):>20} {cell('alloc'):>20} {med['fast'] / med['c']:>11.3f}")

print()
print("scalar calls: ns per call (median of 7 x 20000)")
c_alpha = fn("alpha_from_e", [D, D, C.c_int32, PD])
c_omega = fn("omega0", [D, D, PD])
out = D()
hertz = dc.pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, F)
arr_e = np.full(100_000, 0.5)
arr_k = np.full(100_000, 4.0)
rows = [
    ("alpha_from_e(0.5, 1.5, FORCE)", lambda: dc.alpha_from_e(0.5, 1.5, F), lambda: c_alpha(0.5, 1.5, 1, C.byref(out)),
     lambda: dc.alpha_from_e(arr_e, 1.5, F), arr_e.size),
    ("omega0(4.0, 1.0)", lambda: dc.omega0(4.0, 1.0), lambda: c_omega(4.0, 1.0, C.byref(out)),
     lambda: dc.omega0(arr_k, 1.0), arr_k.size),
    ("normal_force(hertz, ...)", lambda: dc.normal_force(hertz, 1e-5, 0.1, 1e-3, 1e-5), None,
     lambda: dc.normal_force(hertz, np.full(100_000, 1e-5), 0.1, 1e-3, 1e-5), 100_000),
]
print(f"{'call':32} {'python scalar':>14} {'ctypes C':>10} {'per element in an array call':>30}")
for label, py, cc, arr, size in rows:
    tp = min(timeit.repeat(py, number=20000, repeat=7)) / 20000 * 1e9
    tc = min(timeit.repeat(cc, number=20000, repeat=7)) / 20000 * 1e9 if cc else float("nan")
    ta = min(timeit.repeat(arr, number=3, repeat=5)) / 3 / size * 1e9
    print(f"{label:32} {tp:>14.0f} {tc:>10.0f} {ta:>30.1f}")
