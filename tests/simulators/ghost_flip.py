#!/usr/bin/env python3
"""A sliding contact across a periodic boundary (serial) or a rank boundary (2 ranks) whose
evaluating side changes: with LAMMPS' newton-on neighbour list the contact of an owned atom and a
ghost is in one rank's list only, the side where the ghost is "above" (larger z first); when the
spheres' z order flips, the other atom's owner takes over, and its copy of the contact history must
be current (pair_style demcontact sends it there: fix demcontact/history's send_ghosts()).

  ghost_flip.py --plugin demcontactplugin.so [--lmp lmp] [--np 1|2] [--workdir DIR]

Two spheres (R = 1 mm, rho = 2500, E = 5e6, nu = 0.3, e = 0.5, e_t = 0.5, mu = 0.5) touch along x
across the periodic boundary x = +-L/2 (A just inside -L/2, B just inside +L/2; on 2 ranks,
`processors 2 1 1`, A and B on different ranks), overlap DELTA, moved by `fix move` (no
integration): A up and B down at V, so the contact slides and its tangential spring sits at the
Coulomb limit; A's centre passes B's half way (z order flips). Neighbour lists are rebuilt every
REBUILD steps. Check, every dumped step after the spring reached the limit: the pair force on A
(from the dump; fix move adds none) has |F_t| = mu |F_n| within TOL. A history lost at the flip
restarts the spring at zero: |F_t| drops to ~k_t 2 V dt, far below mu |F_n|.
Exit 77 (ctest SKIP) when LAMMPS is missing.
"""
import argparse
import math
import os
import tempfile

import harness as H

R, RHO, E, NU, REST, MU, E_T = 1e-3, 2500.0, 5e6, 0.3, 0.5, 0.5, 0.5
L = 0.02              # periodic box length along x
DELTA = 1e-6          # normal overlap at equal height
V = 1e-3              # speed of each sphere along z (A up, B down)
DZ0 = 2e-5            # initial height of B above A
DT, STEPS, EVERY, REBUILD = 1e-6, 20000, 10, 100
T_SLIDE = 2e-3        # the spring reaches the Coulomb limit after ~0.3 ms
TOL = 1e-3            # relative; a lost history gives ~1


def deck(plugin):
    x = R - DELTA / 2
    c = "hertz/material %g %g %g tangential mindlin NULL %g %g" % (E, REST, NU, E_T, MU)
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary p p f", "comm_modify vel yes",
             "processors * 1 1",
             "region box block %g %g -0.005 0.005 -0.005 0.005 units box" % (-L / 2, L / 2),
             "create_box 1 box", "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact",
             "pair_coeff * * " + c, "neighbor 0.0005 bin", "neigh_modify every %d delay 0 check no" % REBUILD,
             "create_atoms 1 single %.17g 0 %.17g units box" % (-L / 2 + x, -DZ0 / 2),
             "create_atoms 1 single %.17g 0 %.17g units box" % (L / 2 - x, DZ0 / 2),
             "set group all diameter %g density %g" % (2 * R, RHO),
             "group A id 1", "group B id 2",
             "fix ma A move linear 0 0 %g units box" % V, "fix mb B move linear 0 0 %g units box" % -V,
             "timestep %g" % DT,
             "dump d all custom %d traj.dump id x y z fx fy fz" % EVERY,
             "dump_modify d format float %.17g sort id",
             "thermo %d" % (STEPS // 10), "run %d" % STEPS]
    return "\n".join(lines) + "\n"


def frames(path):
    out = []
    for fr in open(path).read().split("ITEM: TIMESTEP")[1:]:
        ls = fr.splitlines()
        step = int(ls[1])
        i = next(k for k, l in enumerate(ls) if l.startswith("ITEM: ATOMS"))
        atoms = {}
        for l in ls[i + 1:]:
            f = l.split()
            if f:
                atoms[int(f[0])] = [float(v) for v in f[1:]]
        out.append((step, atoms))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--workdir")
    a = ap.parse_args()
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    d = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_ghost_flip_"))
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.flip"), "w").write(deck(a.plugin))
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    H.run(H.mpi_prefix(a.np, mpirun) + [exe, "-in", "in.flip", "-log", "log.lammps"], d, H.mpi_env())
    worst, n, flipped, below, above = 0.0, 0, False, 0, 0
    for step, at in frames(os.path.join(d, "traj.dump")):
        if len(at) != 2:
            raise SystemExit("FAIL: %d atoms at step %d" % (len(at), step))
        xa, xb = at[1][:3], at[2][:3]
        dx = xa[0] - (xb[0] - L)  # B's periodic image next to A
        dz = xa[2] - xb[2]
        below += dz < 0
        above += dz > 0
        if step * DT < T_SLIDE:
            continue
        r = math.hypot(dx, dz)
        nx, nz = dx / r, dz / r
        f = at[1][3:6]
        fn = f[0] * nx + f[2] * nz
        ft = math.sqrt(max(f[0] ** 2 + f[1] ** 2 + f[2] ** 2 - fn * fn, 0.0))
        if not fn > 0:
            raise SystemExit("FAIL: no compressive contact force at step %d (F_n = %g)" % (step, fn))
        worst = H.worst_of(worst, abs(ft - MU * fn) / (MU * fn))
        n += 1
    flipped = below > 0 and above > 0
    print("lammps, %d rank(s): %d samples while sliding; z order flipped: %s (A below %d, above %d dumps)"
          % (a.np, n, flipped, below, above))
    print("max | |F_t| - mu F_n | / (mu F_n) = %.3g (tolerance %g)" % (worst, TOL))
    if not flipped or n < 100:
        raise SystemExit("FAIL: the scene did not flip the z order while sliding")
    if not worst <= TOL:
        raise SystemExit("FAIL: the sliding contact's history was lost (tangential force off the Coulomb limit)")
    print("ok")


if __name__ == "__main__":
    main()
