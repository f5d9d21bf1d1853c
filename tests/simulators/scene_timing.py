#!/usr/bin/env python3
"""Wall time of the pour/settle scene's settled bed, demcontact against the builtin Hertz-Mindlin of
the same code (and optionally an older build of the plugin), without re-running the settling:

  scene_timing.py --sim lammps   --plugin demcontactplugin.so      --data settled.data [--before old.so]
  scene_timing.py --sim liggghts --plugin libdemcontact_liggghts.so --data settled.data [--before old.so]
                  [--before LABEL=other.so ...]   (several older builds, each in the alternation)
                  [--np 2] [--reps 3] [--steps 2000] [--workdir DIR] [--lmp lmp]
                  [--surface-default]   (LIGGGHTS: ours also with `surface default`, the
                                         relative velocities computed for nothing; older builds
                                         given by --before run with it, unless
                  [--before-same-decks]  (older builds run ours' decks, both carries)

The decks are those of scenes.py's timing (the bed from write_data of a settling run, 2000 steps,
the same pair/wall lines); the models run alternately (builtin, ours, ours with the projection
carry (demcontact_project: LAMMPS `carry project`, LIGGGHTS `projectionCarry on`, same plugin),
[before], builtin, ...), each
`--reps` times for each rank count (1, and --np when > 1); the minimum is kept. Printed per model:
the loop time ("Loop time"), the pair time (LAMMPS: Pair row of the task timing breakdown, average
over ranks; LIGGGHTS: "Pair time"), and the CPU time (user + sys of all processes of the run minus
that of the same deck with `run 0`, i.e. without start-up and setup; with 2 ranks it includes MPI's
waiting), and their ratios to the builtin model. Exit 77 when the simulator is not installed.
"""
import argparse
import os
import re
import resource
import tempfile

import harness as H
import scenes as S


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def times(log, sim):
    t = open(log).read()
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+) on", t).group(1))
    if sim == "lammps":
        m = re.search(r"^Pair\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)", t, re.M)
    else:
        m = re.search(r"Pair\s+time \(%\) = ([0-9.eE+-]+)", t)
    if not m:
        raise SystemExit("scene_timing: no pair time in %s" % log)
    return loop, float(m.group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", choices=["liggghts", "lammps"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--before", action="append", default=[],
                    help="an older build of the plugin (PATH, or LABEL=PATH), timed in the same alternation; "
                         "repeatable")
    ap.add_argument("--data", required=True, help="settled bed (write_data of a scenes.py settling run)")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--workdir")
    ap.add_argument("--lmp")
    ap.add_argument("--surface-default", action="store_true",
                    help="LIGGGHTS: also time ours with `surface default` instead of `surface demcontact`")
    ap.add_argument("--before-same-decks", action="store_true",
                    help="LIGGGHTS: older builds (which have `surface demcontact`, 7b20b6b or later) run ours' "
                         "decks, both carries (LABEL, LABEL_project), instead of the rotate deck with `surface "
                         "default`")
    a = ap.parse_args()
    if a.reps < 1 or a.steps < 1:
        raise SystemExit("scene_timing: --reps and --steps must be >= 1")
    d = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_scene_timing_"))
    os.makedirs(d, exist_ok=True)
    data = os.path.abspath(a.data)
    if not os.path.exists(data):
        raise SystemExit("scene_timing: no settled bed %s" % data)
    g = S.geometry(False)
    plugins = [("demcontact", os.path.abspath(a.plugin))]
    for b in a.before:
        lab, _, p = b.partition("=") if "=" in b else ("before", "", b)
        reserved = ("granular", "hertz", "demcontact_project", "demcontact_surfdefault",
                    "demcontact_project_surfdefault")
        if lab in [q[0] for q in plugins] or lab in reserved or lab.endswith("_project"):
            raise SystemExit("scene_timing: label %s used twice, reserved, or ending in _project" % lab)
        plugins.append((lab, os.path.abspath(p)))
    # (label, deck(steps), env, exe)
    models = []
    if a.sim == "lammps":
        from harness import lammps as lammps_runs
        exe = lammps_runs.find_lmp(a.lmp)
        mpirun = os.path.join(os.path.dirname(exe), "mpirun")
        lm = {m[0]: m for m in S.lammps_models()}
        (_, _, co, wa), (_, bst, bco, bwa) = lm["demcontact"], lm["granular"]
        pco, pwa = lm["demcontact_project"][2:] if "demcontact_project" in lm else (None, None)
        env = H.mpi_env()
        ref = "granular"
        # the builtin deck loads the plugin too (unused by pair granular), as in scenes.py
        models.append((ref, lambda n: S.lammps_timing_deck(a.plugin, bst, bco, bwa, g, data, n), env))
        for lab, p in plugins:
            models.append((lab, lambda n, p=p: S.lammps_timing_deck(p, "demcontact", co, wa, g, data, n), env))
            if lab == "demcontact" and pco:  # the same plugin with `carry project`
                models.append(("demcontact_project",
                               lambda n, p=p: S.lammps_timing_deck(p, "demcontact", pco, pwa, g, data, n), env))
    else:
        mpirun = "mpirun"
        lm = {m[0]: m for m in S.liggghts_models()}
        (_, mo, se), (ref, bmo, bse), (_, pmo, pse) = lm["demcontact"], lm["hertz"], lm["demcontact_project"]
        exe, env = H.liggghts_cmd(a.plugin)
        sd = S.liggghts_surface_default
        models.append((ref, lambda n: S.liggghts_timing_deck(bmo, bse, g, data, n), env))
        for lab, p in plugins:
            e = dict(env)
            e["LD_PRELOAD"] = p
            if lab != "demcontact" and a.before_same_decks:  # an older build, ours' decks
                models.append((lab, lambda n: S.liggghts_timing_deck(mo, se, g, data, n), e))
                models.append((lab + "_project", lambda n: S.liggghts_timing_deck(pmo, pse, g, data, n), e))
                continue
            if lab != "demcontact":  # an older build: `surface default` (it may predate surface demcontact)
                models.append((lab, lambda n: S.liggghts_timing_deck(sd(mo), se, g, data, n), e))
                continue
            models.append((lab, lambda n: S.liggghts_timing_deck(mo, se, g, data, n), e))
            # the same plugin with `projectionCarry on`
            models.append(("demcontact_project", lambda n: S.liggghts_timing_deck(pmo, pse, g, data, n), e))
            if a.surface_default:  # and both again with LIGGGHTS' `surface default`
                models.append(("demcontact_surfdefault",
                               lambda n: S.liggghts_timing_deck(sd(mo), se, g, data, n), e))
                models.append(("demcontact_project_surfdefault",
                               lambda n: S.liggghts_timing_deck(sd(pmo), pse, g, data, n), e))
    for lab, deck, _ in models:
        open(os.path.join(d, "in.%s" % lab), "w").write(deck(a.steps))
        open(os.path.join(d, "in0.%s" % lab), "w").write(deck(0))
    nps = [1] + ([a.np] if a.np > 1 else [])
    best = {}
    for np_ in nps:
        for r in range(a.reps):
            for lab, _, env in models:
                cpu = []
                for deck, log in (("in0.%s" % lab, "log0.%s.np%d.%d" % (lab, np_, r)),
                                  ("in.%s" % lab, "log.%s.np%d.%d" % (lab, np_, r))):
                    c0 = child_cpu()
                    H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", deck, "-log", log], d, env)
                    cpu.append(child_cpu() - c0)
                loop, pair = times(os.path.join(d, "log.%s.np%d.%d" % (lab, np_, r)), a.sim)
                key = (lab, np_)
                b = best.get(key, (float("inf"),) * 3)
                best[key] = (min(b[0], loop), min(b[1], pair), min(b[2], cpu[1] - cpu[0]))
    load = open("/proc/loadavg").read().split()[:3] if os.path.exists("/proc/loadavg") else ["?"] * 3
    print("## %s settled bed (%s), %d steps, minimum of %d alternating runs (load average at the end: %s)"
          % (a.sim, data, a.steps, a.reps, " ".join(load)))
    print()
    print("| model | ranks | loop [s] | pair [s] | CPU [s] | loop ratio | pair ratio | CPU ratio |")
    print("|---|---|---|---|---|---|---|---|")
    for np_ in nps:
        r = best[(ref, np_)]
        for lab, _, _ in models:
            b = best[(lab, np_)]
            print("| %s | %d | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f |"
                  % (lab, np_, b[0], b[1], b[2], b[0] / r[0], b[1] / r[1], b[2] / r[2]))


if __name__ == "__main__":
    main()
