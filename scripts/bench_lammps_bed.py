#!/usr/bin/env python3
"""LAMMPS settled-bed timing: pair_style demcontact (plugin) against pair_style granular, serial
and 2 ranks, minimum of `--reps` alternating runs (the machine is shared: the minimum is the least
disturbed run). Called by scripts/bench_simulators.sh.

  bench_lammps_bed.py --plugin demcontactplugin.so --data settled.data --workdir DIR
                      [--lmp lmp] [--np 2] [--reps 3] [--steps 2000]

The bed: the settled data file of the LIGGGHTS settling bed (tests/simulators/bed.py: 5184
spheres, R = 1 mm, rho = 2500, E = 5e6 Pa, nu = 0.3, e = 0.5, mu = 0.5, in a 44 x 44 mm box with
a floor and four side walls; LIGGGHTS writes the LAMMPS data format of atom_style sphere), run on
for `--steps` steps under gravity with the same time step as there (Hertz contact time / 50).
Two model pairs, each with its walls in the same model:
  full contact   ours:    pair_style demcontact, hertz/material E e nu tangential mindlin NULL 0.5 mu
                          (+ fix demcontact/wall)
                 builtin: pair_style granular, hertz/material E e nu tangential mindlin NULL 1.0 mu
                          damping tsuji (+ fix wall/gran granular)
  normal only    ours:    hertz/material E e nu (no history)
                 builtin: hertz/material E e nu tangential linear_nohistory 0 0 damping tsuji
Times from LAMMPS's own log: "Loop time" and the Pair row of the MPI task timing breakdown (avg).
Exit 77 when LAMMPS is not installed (as the other simulator scripts).
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "simulators"))
import harness as H  # noqa: E402
import bed  # noqa: E402
from harness import lammps as lammps_runs  # noqa: E402

MU = bed.MU
MODELS = [  # (label, plugin?, pair_style, contact arguments, wall fix style)
    ("full contact, demcontact", True, "demcontact",
     "hertz/material {E} {e} {nu} tangential mindlin NULL 0.5 {mu}", "demcontact/wall"),
    ("full contact, granular", False, "granular",
     "hertz/material {E} {e} {nu} tangential mindlin NULL 1.0 {mu} damping tsuji", "wall/gran granular"),
    ("normal only, demcontact", True, "demcontact", "hertz/material {E} {e} {nu}", "demcontact/wall"),
    ("normal only, granular", False, "granular",
     "hertz/material {E} {e} {nu} tangential linear_nohistory 0.0 0.0 damping tsuji", "wall/gran granular"),
]


def deck(plugin, data, dt, steps, ours, style, args, wall):
    a = args.format(E="%g" % bed.E_BED, e="%g" % bed.E_REST, nu="%g" % H.NU, mu="%g" % MU)
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "newton off",
         "comm_modify vel yes", "read_data %s" % os.path.abspath(data),
         "neighbor 0.0004 bin", "neigh_modify delay 0"]
    if ours:
        L.append("plugin load %s" % os.path.abspath(plugin))
    L += ["pair_style " + style, "pair_coeff * * " + a, "timestep %.17g" % dt,
          "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0",
          "fix w0 all %s %s zplane 0.0 NULL" % (wall, a),
          "fix w1 all %s %s xplane %g %g" % (wall, a, -bed.HALF, bed.HALF),
          "fix w2 all %s %s yplane %g %g" % (wall, a, -bed.HALF, bed.HALF),
          "fix integr all nve/sphere", "thermo_modify lost error", "thermo %d" % steps,
          "run %d" % steps]
    return "\n".join(L) + "\n"


def times(text):
    """(loop wall time, average Pair time) [s] from a LAMMPS log."""
    loop = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs", text)
    pair = re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)", text, re.M)
    if not (loop and pair):
        raise SystemExit("bench_lammps_bed: no Loop time / Pair row in the log")
    return float(loop.group(1)), float(pair.group(2))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--steps", type=int, default=2000)
    a = ap.parse_args()
    exe = lammps_runs.find_lmp(a.lmp)
    env = H.mpi_env()
    if not os.path.exists(a.data):
        raise SystemExit("bench_lammps_bed: no data file %s (run the LIGGGHTS settling bed first)" % a.data)
    dt = H.hertz_contact_time(bed.E_BED, 0.5) / bed.STEPS_PER_CONTACT
    wd = os.path.abspath(a.workdir)
    os.makedirs(wd, exist_ok=True)
    names = {}
    for i, (label, ours, style, args, wall) in enumerate(MODELS):
        names[label] = "in.m%d" % i
        open(os.path.join(wd, names[label]), "w").write(deck(a.plugin, a.data, dt, a.steps, ours, style, args, wall))
    nps = [1] + ([a.np] if a.np > 1 else [])
    best = {}
    for np_ in nps:
        for r in range(a.reps):
            for label, *_ in MODELS:
                log = "log.%s.np%d.%d" % (names[label], np_, r)
                pre = H.mpi_prefix(np_, os.path.join(os.path.dirname(exe), "mpirun"))
                H.run(pre + [exe, "-in", names[label], "-log", log], wd, env)
                loop, pair = times(open(os.path.join(wd, log)).read())
                old = best.get((label, np_), (float("inf"), float("inf")))
                best[(label, np_)] = (min(old[0], loop), min(old[1], pair))
    print("LAMMPS settled bed (%s): 5184 spheres, %d steps, dt = %.3g s; minimum of %d alternating runs"
          % (os.path.basename(exe), a.steps, dt, a.reps))
    print()
    print("| contact | ranks | demcontact loop [s] | granular loop [s] | ratio loop | demcontact pair [s] | granular pair [s] | ratio pair |")
    print("|---|---|---|---|---|---|---|---|")
    for kind in ("full contact", "normal only"):
        for np_ in nps:
            o, g = best[("%s, demcontact" % kind, np_)], best[("%s, granular" % kind, np_)]
            print("| %s | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |"
                  % (kind, np_, o[0], g[0], o[0] / g[0], o[1], g[1], o[1] / g[1]))


if __name__ == "__main__":
    main()
