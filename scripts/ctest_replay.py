#!/usr/bin/env python3
"""Replays a ctest run's schedule under this build's test properties (docs/ci.md).

    scripts/ctest_replay.py BUILD_DIR CTEST_LOG [-j 2] [--split NAME=SECONDS ...] [--sleep SCALE]

CTEST_LOG is a `ctest --output-on-failure` log (scripts/test.sh writes build-ctest.log): its
"Test #N: NAME ... X sec" lines give each test's seconds. BUILD_DIR is a configured build: its
tests, their order and their COST, PROCESSORS and RUN_SERIAL come from
`ctest --show-only=json-v1`. A test missing from the log takes the seconds given by --split (for a
test split since the log was written; the seconds are the caller's estimate), else 0.

Prints the replayed wall time of `ctest -jJ` (list scheduling as ctest does it: the tests by COST,
highest first, then in registration order; a test starts when its PROCESSORS slots are free; a
RUN_SERIAL test starts alone and nothing starts beside it) and the bound for J cores, i.e. the
single-slot seconds / J + the seconds of the tests that claim every slot.
With --sleep SCALE it also writes a project of `sleep SECONDS/SCALE` tests with the same
properties into a scratch directory, runs the real `ctest -jJ` on it and prints its wall time
times SCALE, as a check of the replay. Exits 1 if the log holds no test times.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("log")
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("--split", action="append", default=[], help="NAME=SECONDS for a test not in the log")
    ap.add_argument("--sleep", type=float, help="also run the real ctest on sleeps, seconds divided by SCALE")
    a = ap.parse_args()
    secs = {}
    with open(a.log, errors="replace") as f:
        for line in f:
            m = re.search(r"Test +#\d+: (\S+) .*?([\d.]+) sec", line)
            if m:
                secs[m.group(1)] = float(m.group(2))
    if not secs:
        sys.exit("ctest_replay: no test times in %s" % a.log)
    for kv in a.split:
        name, _, value = kv.partition("=")
        secs[name] = float(value)
    out = subprocess.run(["ctest", "--test-dir", a.build, "--show-only=json-v1"], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    tests = []
    for t in json.loads(out)["tests"]:
        p = {q["name"]: q["value"] for q in t.get("properties", [])}
        tests.append((t["name"], float(p.get("COST", 0)), min(a.j, int(p.get("PROCESSORS", 1))),
                      bool(p.get("RUN_SERIAL", False))))
    dur = {n: secs.get(n, 0.0) for n, _, _, _ in tests}
    missing = [n for n, _, _, _ in tests if n not in secs]
    pending = sorted(tests, key=lambda t: -t[1])  # stable: registration order within a cost
    now, running = 0.0, []  # (end, slots, serial)
    while pending or running:
        started = True
        while started:
            started = False
            free = a.j - sum(r[1] for r in running)
            if any(r[2] for r in running):
                break
            for t in pending:
                name, _, slots, serial = t
                if (serial and running) or slots > free:
                    continue
                running.append((now + dur[name], slots, serial))
                pending.remove(t)
                started = True
                break
        running.sort()
        now = running.pop(0)[0]
    single = sum(dur[n] for n, _, s, ser in tests if s < a.j and not ser)
    whole = sum(dur[n] for n, _, s, ser in tests if s >= a.j or ser)
    print("tests: %d (%d not in the log, 0 s each: %s)" % (len(tests), len(missing), " ".join(missing) or "none"))
    print("sum of test seconds: %.0f (single-slot %.0f, claiming every slot or serial %.0f)" % (single + whole, single, whole))
    print("replayed ctest -j%d: %.0f s; bound for %d cores: %.0f s" % (a.j, now, a.j, single / a.j + whole))
    if a.sleep:
        with tempfile.TemporaryDirectory() as d:
            lines = ["cmake_minimum_required(VERSION 3.20)", "project(replay NONE)", "enable_testing()"]
            for name, cost, slots, serial in tests:
                lines.append("add_test(NAME %s COMMAND sleep %.3f)" % (name, dur[name] / a.sleep))
                props = ("COST %g " % cost if cost else "") + "PROCESSORS %d" % slots + (" RUN_SERIAL TRUE" if serial else "")
                lines.append("set_tests_properties(%s PROPERTIES %s)" % (name, props))
            with open(os.path.join(d, "CMakeLists.txt"), "w") as f:
                f.write("\n".join(lines) + "\n")
            subprocess.run(["cmake", "-S", d, "-B", d + "/b"], check=True, stdout=subprocess.DEVNULL)
            t0 = time.monotonic()
            subprocess.run(["ctest", "--test-dir", d + "/b", "-j%d" % a.j, "-Q"], check=True)
            print("real ctest -j%d on sleeps: %.0f s (x%g)" % (a.j, (time.monotonic() - t0) * a.sleep, a.sleep))


if __name__ == "__main__":
    main()
