"""The batch calls release the GIL: a second Python thread makes progress while one runs.

How it can fail: the switch interval is set huge (1000 s), so the interpreter never forces a
thread switch; the only way another Python thread can run is that the running thread releases
the GIL itself (a blocking call, or an extension's `allow_threads`/`detach`). A worker thread
blocked on an Event is released just before the batch call and stamps the time as soon as it
holds the GIL. If the batch keeps the GIL, the worker can only run once the main thread blocks in
`join()` after the call, so its stamp is later than the end of the call; if the batch releases
it, the stamp falls inside the call. (Checked once by removing `py.detach` from the batch
functions: these tests then fail on every attempt.) A released call too short for the OS to
schedule the worker in time would be a false negative, hence the long calls and the retries
with a doubled size; a held GIL can never pass.
"""

from __future__ import annotations

import math
import sys
import threading
import time

import numpy as np
import pytest

import demcontact as dc


def worker_ran_during(call) -> bool:
    old = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        go = threading.Event()
        stamps: list[float] = []

        def worker():
            go.wait()
            stamps.append(time.perf_counter())

        t = threading.Thread(target=worker)
        t.start()  # returns once the worker is blocked in go.wait() (it then drops the GIL)
        go.set()  # the worker is runnable from now on, but needs the GIL
        start = time.perf_counter()
        call()
        end = time.perf_counter()
        t.join()
    finally:
        sys.setswitchinterval(old)
    assert len(stamps) == 1
    return stamps[0] < end and end - start > 0


def released(make_call, sizes) -> bool:
    for n in sizes:
        if worker_ran_during(make_call(n)):
            return True
    return False


def test_control_a_gil_holding_call_never_lets_the_worker_run():
    # The detector itself: a pure-Python busy loop (GIL held throughout) is never "released".
    def busy():
        deadline = time.perf_counter() + 0.05
        while time.perf_counter() < deadline:
            pass

    assert not worker_ran_during(busy)
    # ... and a call known to release the GIL (time.sleep) is.
    assert released(lambda s: (lambda: time.sleep(s)), [0.05, 0.2, 0.5])


@pytest.mark.parametrize("check", [False, True])
def test_normal_force_batch_releases_the_gil(check):
    pair = dc.pair_powerlaw(1.7, 1e8, 0.5, dc.Criterion.FORCE)

    def make(n):
        rng = np.random.default_rng(0)
        d, vn = rng.uniform(0, 2e-5, n), rng.uniform(-1, 1, n)
        r, m, out = np.full(n, 1e-3), np.full(n, 1e-5), np.empty(n)
        return lambda: dc.normal_force_batch(pair, d, vn, r, m, out=out, check=check)

    assert released(make, [1_000_000, 2_000_000, 4_000_000])


def test_contact_force_batch_releases_the_gil():
    spec = dc.ContactSpec(
        normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=0.8, E1=7e10, nu1=0.3, E2=math.inf, nu2=0.3,
        tangential=dc.Tangential.MINDLIN, mu=0.3, rolling=dc.Rolling.EPSD, mu_r=0.05, twisting=dc.Twisting.SDS, mu_tw=1e-4, k_tw=0.01,
    )
    model = dc.contact_model_init(spec)

    def make(n):
        rng = np.random.default_rng(1)
        normal = np.tile([0.0, 0.0, 1.0], (n, 1))
        vel = rng.normal(0, 0.3, (n, 3))  # read-only inputs may share memory
        d = rng.uniform(0, 1e-5, n)
        r, mass = np.full(n, 1e-3), np.full(n, 1e-5)
        h = np.zeros((n, model.history_len))
        out = (np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3)))
        return lambda: dc.contact_force_batch(model, normal, d, vel, vel, vel, vel, r, math.inf, mass, math.inf, 1e-7, h, out=out)

    assert released(make, [200_000, 400_000, 800_000])
