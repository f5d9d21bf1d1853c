"""Speed of the Python binding against the C ABI in the same run (not a test).

    .venv-python/bin/python python/bench/bench_batch.py [n_contacts] [repeats]

1. Batch normal force over n contacts (default 1e6) for Hertz, power law p = 1.7 (pow) and the
   linear spring-dashpot: dc_normal_force_batch through ctypes (the C baseline: one call on the
   same numpy buffers) against demcontact.normal_force_batch with out= (check=False, the C
   semantics), check=True (default, screened in cache-sized blocks), and without out= (allocates
   the result). C and Python runs alternate; medians of `repeats` runs, ns per contact.
2. Scalar call overhead: demcontact.<f>(scalars) against the same C function through ctypes
   and the in-library cost (the batch/array path per element).
3. Full-contact batch over n contacts (same n) for three models (normal only; Hertz + Mindlin on
   walls; Hertz + Mindlin + EPSD rolling + SDS twisting): dc_contact_force_batch through ctypes
   on the same numpy buffers against demcontact.contact_force_batch with out= and without; each
   side keeps its own history (evolving over the runs, compared bit for bit at the end).
4. Full-contact scalar call overhead: demcontact.contact_force against dc_contact_force through
   ctypes (a prebuilt dc_contact_state) and the per-contact cost inside the batch.
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


# ---- 3. full-contact batch --------------------------------------------------------------------
import math  # noqa: E402

import cabi_contact as cc  # noqa: E402

INF = math.inf
contact_specs = {
    "hertz normal only": dict(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.5, E1=7e10, nu1=0.3, E2=7e10, nu2=0.3),
    "hertz+mindlin": dict(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.9, E1=7e10, nu1=0.3, E2=7e10, nu2=0.3,
                          tangential=dc.Tangential.MINDLIN, mu=0.3, e_t=0.7),
    "hertz+mindlin+epsd+sds": dict(normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.9, E1=7e10, nu1=0.3, E2=7e10, nu2=0.3,
                                   tangential=dc.Tangential.MINDLIN, mu=0.3, e_t=0.7, rolling=dc.Rolling.EPSD, mu_r=0.05, eta_r=0.3,
                                   twisting=dc.Twisting.SDS, mu_tw=1e-4, k_tw=0.01, eta_tw=0.2),
}
creps = max(3, reps // 3)
rng = np.random.default_rng(12)
nv = rng.normal(size=(n, 3))
normal = nv / np.linalg.norm(nv, axis=1)[:, None]
overlap = rng.uniform(-1e-6, 1e-5, n)
v1, v2 = rng.normal(0, 0.3, (n, 3)), rng.normal(0, 0.3, (n, 3))
w1, w2 = rng.normal(0, 300, (n, 3)), rng.normal(0, 300, (n, 3))
r1, r2 = rng.uniform(5e-4, 2e-3, n), rng.uniform(5e-4, 2e-3, n)
m1, m2 = 2500 * 4 / 3 * np.pi * r1**3, 2500 * 4 / 3 * np.pi * r2**3
ins = (normal, overlap, v1, v2, w1, w2, r1, r2, m1, m2)
DT = 1e-7
c_out = (np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3)))
py_out = (np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3)))

print()
print(f"contact batch, n = {n:.0e} contacts, {creps} alternating runs, median ns/contact (min)")
print(f"{'model':24} {'C batch':>14} {'py out=':>14} {'py alloc':>14} {'ratio (out=/C)':>15}")
for label, kw in contact_specs.items():
    model = dc.contact_model_init(dc.ContactSpec(**kw))
    st, cmodel = cc.c_model(**kw)
    assert st == 0 and model.to_bytes() == bytes(cmodel)
    L = model.history_len
    h_c, h_py = np.zeros((n, max(L, 1))), np.zeros((n, max(L, 1)))
    batch = cc.Batch(n, h_c.shape[1] if L else 0, *[cc.ptr(a) for a in ins], cc.ptr(h_c) if L else None, *[cc.ptr(a) for a in c_out])
    hp = h_py if L else None
    runs = {k: [] for k in ("c", "out", "alloc")}
    for _ in range(creps):
        runs["c"].append(t(lambda: cc.force_batch(C.byref(cmodel), C.byref(batch), DT)))
        runs["out"].append(t(lambda: dc.contact_force_batch(model, *ins, DT, hp, out=py_out)))
        runs["alloc"].append(t(lambda: dc.contact_force_batch(model, *ins, DT, hp)))
    # the same number of calls on each side: one more C call to match the alloc runs
    for _ in range(creps):
        cc.force_batch(C.byref(cmodel), C.byref(batch), DT)
    last = dc.contact_force_batch(model, *ins, DT, hp, out=py_out)
    cc.force_batch(C.byref(cmodel), C.byref(batch), DT)
    assert all(a.tobytes() == b.tobytes() for a, b in zip(py_out, c_out)) and h_c.tobytes() == h_py.tobytes()
    med = {k: statistics.median(v) / n * 1e9 for k, v in runs.items()}
    mn = {k: min(v) / n * 1e9 for k, v in runs.items()}
    cell = lambda k: f"{med[k]:.2f} ({mn[k]:.2f})"  # noqa: E731
    print(f"{label:24} {cell('c'):>14} {cell('out'):>14} {cell('alloc'):>14} {med['out'] / med['c']:>15.3f}")

# ---- 4. full-contact scalar call --------------------------------------------------------------
kw = contact_specs["hertz+mindlin+epsd+sds"]
model = dc.contact_model_init(dc.ContactSpec(**kw))
_, cmodel = cc.c_model(**kw)
args = (normal[0], 5e-6, v1[0], v2[0], w1[0], w2[0], float(r1[0]), float(r2[0]), float(m1[0]), float(m2[0]))
hist, chist = np.zeros(model.history_len), np.zeros(model.history_len)
cstate = cc.c_state(*args)
cres = cc.Result()
chp = cc.ptr(chist)
tp = min(timeit.repeat(lambda: dc.contact_force(model, *args, DT, hist), number=20000, repeat=7)) / 20000 * 1e9
tc = min(timeit.repeat(lambda: cc.force(C.byref(cmodel), C.byref(cstate), DT, chp, chist.size, C.byref(cres)), number=20000, repeat=7)) / 20000 * 1e9
m_small = 100_000
small = [a[:m_small].copy() for a in ins]
hs = np.zeros((m_small, model.history_len))
tb = min(timeit.repeat(lambda: dc.contact_force_batch(model, *small, DT, hs), number=3, repeat=5)) / 3 / m_small * 1e9
print()
print("contact_force scalar call (hertz+mindlin+epsd+sds): ns per call")
print(f"{'python contact_force':>22} {'ctypes dc_contact_force':>25} {'per contact in a batch of 1e5':>32}")
print(f"{tp:>22.0f} {tc:>25.0f} {tb:>32.1f}")
