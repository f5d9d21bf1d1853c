#!/usr/bin/env python3
"""LAMMPS write_restart / read_restart keep demcontact's contact histories (pair and wall).

  restart.py --plugin demcontactplugin.so [--lmp lmp] [--np N] [--np-read M] [--wall region] [--workdir DIR]

Three spheres (R = 1 mm, rho = 2500, E = 5e6, nu = 0.3, e = 0.5, mu = 0.5, e_t = 0.5; pair model
with Mindlin tangential and EPSD rolling, so the history has all its parts), no gravity:
A and B touch along n = (1, 1, 0)/sqrt 2 across the plane x = 0 (on 2 ranks, `processors * 1 1`,
the contact is owned by both ranks), pressed together by F_n = 1e-3 N and sheared along z by
f_t = 1e-4 N = 0.2 mu F_n (fix addforce) so they stick; C sits on the wall z = 0 (fix
demcontact/wall; with --wall region, fix demcontact/wall/region on `region plane 0 0 0 0 0 1`,
defined again after read_restart), pressed on it by F_n and sheared along x by f_t. Rotation is not integrated
(fix nve). At rest the tangential springs carry exactly -f_t.

Runs: (U) uninterrupted, STEPS1 + STEPS2 steps; (R1) STEPS1 steps then write_restart; (R2) a new
process: read_restart, the same plugin/pair/wall/load lines, STEPS2 steps. U and R1 run on N
ranks, R2 on M (default N): users restart on another allocation, and the histories written by N
ranks must reach the atoms' new owners among M. Both dump the forces
every EVERY steps. Checks:
  - R2's log says both fixes (DEMCONTACT_HISTORY of the pair style, the wall fix) were reset
    from the restart file;
  - at the restart the springs are loaded: |F_t + f_t| <= 1e-2 f_t for A (pair) and C (wall) in U
    (so a history lost at the restart, which restarts the spring at zero, is a jump of ~f_t);
  - after the restart, the tangential pair force on A (z) and wall force on C (x) of R2 equal
    U's at every dumped step within TOL x f_t.
TOL: the restart is exact except for the `run` setup of R2, which evaluates the contacts once
more on a copy of the history (one more spring increment v_t dt, v_t ~ 0 when sticking), and,
with M != N, the order in which a rank sums an atom's forces (ulps): measured differences ~1e-12
f_t; a lost history gives ~1.
Exit 77 (ctest SKIP) when LAMMPS is missing.
"""
import argparse
import math
import os
import tempfile

import harness as H

R, RHO, E, NU, REST, MU, E_T, MU_R = 1e-3, 2500.0, 5e6, 0.3, 0.5, 0.5, 0.5, 0.1
FN, FT = 1e-3, 1e-4
DT, STEPS1, STEPS2, EVERY = 1e-6, 20000, 10000, 50
TOL = 1e-9          # relative to f_t (a lost history: ~1)
LOADED = 1e-2       # |F_t + f_t| / f_t at the restart: the springs carry the load


def positions():
    e_star = E / (2 * (1 - NU * NU))
    # A-B: Hertz overlap under FN between two spheres (R* = R/2); C on the rigid-material wall (R* = R)
    d_ab = (FN / (4.0 / 3.0 * e_star * math.sqrt(R / 2))) ** (2.0 / 3.0)
    d_cw = (FN / (4.0 / 3.0 * e_star * math.sqrt(R))) ** (2.0 / 3.0)
    c = (R - d_ab / 2) / math.sqrt(2)
    z = 0.005
    return (c, c, z), (-c, -c, z), (-0.006, 0.0, R - d_cw)


WALL = {"plane": "fix floor all demcontact/wall {model} zplane 0 NULL",
        "region": "region floorreg plane 0 0 0 0 0 1 side in units box\n"
                  "fix floor all demcontact/wall/region {model} region floorreg"}


def common(plugin, with_atoms, wall="plane"):
    a, b, c = positions()
    s = FN / math.sqrt(2)
    model = "hertz/material %g %g %g tangential mindlin NULL %g %g rolling sds NULL 0 %g" % (E, REST, NU, E_T, MU, MU_R)
    L = []
    if with_atoms:
        L += ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
              "processors * 1 1", "region box block -0.01 0.01 -0.005 0.005 0 0.01 units box", "create_box 1 box",
              "create_atoms 1 single %.17g %.17g %.17g units box" % a,
              "create_atoms 1 single %.17g %.17g %.17g units box" % b,
              "create_atoms 1 single %.17g %.17g %.17g units box" % c,
              "set group all diameter %g density %g" % (2 * R, RHO),
              "group A id 1", "group B id 2", "group C id 3"]
    else:
        L += ["comm_modify vel yes"]
    L += ["plugin load %s" % os.path.abspath(plugin), "pair_style demcontact", "pair_coeff * * " + model,
          "neighbor 0.0005 bin", "neigh_modify delay 0",
          WALL[wall].format(model=model),
          "fix la A addforce %.17g %.17g %.17g" % (-s, -s, FT), "fix lb B addforce %.17g %.17g %.17g" % (s, s, -FT),
          "fix lc C addforce %.17g 0 %.17g" % (FT, -FN),
          "fix integr all nve", "timestep %g" % DT,
          "dump d all custom %d traj.dump id x y z fx fy fz" % EVERY, "dump_modify d format float %.17g sort id",
          "thermo %d" % (EVERY * 100)]
    return L


def frames(path):
    out = {}
    for block in open(path).read().split("ITEM: TIMESTEP")[1:]:
        lines = block.strip().splitlines()
        step = int(lines[0])
        i = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        cols = lines[i].split()[2:]
        atoms = {}
        for l in lines[i + 1:]:
            f = dict(zip(cols, map(float, l.split())))
            atoms[int(f["id"])] = f
        out[step] = atoms
    return out


def tangential(atoms):
    """(pair force on A along z, wall force on C along x), the loads subtracted."""
    return atoms[1]["fz"] - FT, atoms[3]["fx"] - FT


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=1, help="ranks of the uninterrupted run and the one that writes")
    ap.add_argument("--np-read", type=int, help="ranks of the run that reads the restart (default: --np)")
    ap.add_argument("--steps2", type=int, default=STEPS2,
                    help="steps after the restart (default %d; fewer where the reading run oversubscribes the cores)" % STEPS2)
    ap.add_argument("--wall", choices=sorted(WALL), default="plane",
                    help="the wall of sphere C: fix demcontact/wall zplane or fix demcontact/wall/region")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    env = H.mpi_env()
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    pre = H.mpi_prefix(a.np, mpirun)
    np_read = a.np if a.np_read is None else a.np_read
    if a.np < 1 or np_read < 1:
        raise SystemExit("restart.py: --np and --np-read must be >= 1 (got %d, %d)" % (a.np, np_read))
    steps2 = a.steps2
    if steps2 < 10 * EVERY:
        raise SystemExit("restart.py: --steps2 must be >= %d (got %d)" % (10 * EVERY, steps2))
    pre_read = H.mpi_prefix(np_read, mpirun)
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_restart_"))
    runs = {
        "uninterrupted": common(a.plugin, True, a.wall) + ["run %d" % (STEPS1 + steps2)],
        "first": common(a.plugin, True, a.wall) + ["run %d" % STEPS1, "write_restart state.restart"],
    }
    for name, lines in runs.items():
        d = os.path.join(workdir, name)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.lmp"), "w").write("\n".join(lines) + "\n")
        H.run(pre + [exe, "-in", "in.lmp", "-log", "log.lammps"], d, env)
    d = os.path.join(workdir, "restarted")
    os.makedirs(d, exist_ok=True)
    lines = ["processors * 1 1", "read_restart %s" % os.path.join(workdir, "first", "state.restart")] + \
        common(a.plugin, False, a.wall) + \
        ["run %d" % steps2]
    open(os.path.join(d, "in.lmp"), "w").write("\n".join(lines) + "\n")
    H.run(pre_read + [exe, "-in", "in.lmp", "-log", "log.lammps"], d, env)

    log = open(os.path.join(d, "log.lammps")).read()
    reset = [fid for fid in ("DEMCONTACT_HISTORY", "floor")
             if any("fix ID: %s" % fid in l for l in log.splitlines())]
    u = frames(os.path.join(workdir, "uninterrupted", "traj.dump"))
    r = frames(os.path.join(workdir, "restarted", "traj.dump"))
    fa, fc = tangential(u[STEPS1])
    load = H.worst_of(abs(fa + FT), abs(fc + FT)) / FT
    steps = sorted(s for s in r if s > STEPS1)
    worst_a = worst_c = 0.0
    for s in steps:
        if s not in u or len(r[s]) != 3:
            raise SystemExit("FAIL: step %d missing or atoms lost" % s)
        ua, uc = tangential(u[s])
        ra, rc = tangential(r[s])
        worst_a = H.worst_of(worst_a, abs(ra - ua) / FT)
        worst_c = H.worst_of(worst_c, abs(rc - uc) / FT)
    ranks = ("%d rank(s)" % a.np) if np_read == a.np else ("written on %d rank(s), read on %d" % (a.np, np_read))
    # The read really ran on M ranks (`processors * 1 1`: LAMMPS prints "M by 1 by 1 MPI processor grid").
    grid_ok = ("%d by 1 by 1 MPI processor grid" % np_read) in log
    print("LAMMPS restart (wall: %s), %s: fixes reset from the restart file: %s"
          % (a.wall, ranks, ", ".join(reset) or "none"))
    print("at the restart (step %d): pair F_t,z on A = %.6g, wall F_t,x on C = %.6g (f_t = %g; |F_t + f_t|/f_t = %.2g, "
          "must be <= %g)" % (STEPS1, fa, fc, FT, load, LOADED))
    print("after the restart, %d dumped steps: max |F_t(restarted) - F_t(uninterrupted)| / f_t: pair %.3g, wall %.3g "
          "(tolerance %g)" % (len(steps), worst_a, worst_c, TOL))
    if not grid_ok:
        print("FAIL: the restarted run's log has no %d by 1 by 1 processor grid" % np_read)
    ok = grid_ok and len(reset) == 2 and load <= LOADED and len(steps) >= steps2 // EVERY and H.worst_of(worst_a, worst_c) <= TOL
    if not ok:
        raise SystemExit("FAIL: the contact histories did not survive write_restart/read_restart")
    print("ok")


if __name__ == "__main__":
    main()
