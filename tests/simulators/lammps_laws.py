#!/usr/bin/env python3
"""The normal law elastic_plastic in LAMMPS (`pair_coeff * * hertz/material E 1 nu elastic_plastic
P_Y`, `fix demcontact/wall ... elastic_plastic P_Y zplane 0 NULL`), head-on collisions.

  lammps_laws.py --plugin demcontactplugin.so [--lmp lmp] [--workdir DIR] [--check] [--np 2]
                 [--newton on|off ...]

The impacts, material and checks are those of liggghts_laws.py (shared: harness/laws.py): R = 1 mm,
rho = 2500 kg/m^3, E = 1e7 Pa, nu = 0.3 (spheres and wall), P_Y = 2e5 Pa; one LAMMPS run per
geometry (two equal spheres on the x axis; a sphere above the plane z = 0), every collision in it
far apart from the others, the realised e from LAMMPS' own dump of the final velocities.

1. Impact speeds SPEEDS_OVER_VY times the yield speed v_y (dc_elastic_plastic_yield_speed),
   dt = t_H(v_max)/STEPS. Compared with the library's own contact stepped the same way (velocity
   Verlet as fix nve/sphere; dc_contact_force with its history double kept from step to step,
   zeroed when the contact ends): |e_lammps - e_ref| <= TOL_REF (1e-12). And with Thornton's closed
   form (dc_elastic_plastic_restitution), which assumes the continuous contact: |e - e_thornton|
   <= TOL_CLOSED (1e-4). e < 1 at all requires the residual state carried from step to step in
   the contact's history (lost each step, the contact is elastic: e = 1).
3. A second impact of the same sphere on the same wall (fix gravity brings it back after it left
   the wall): the wall fix's history starts from zero again, as the library's reference with the
   history zeroed at separation (TOL_REF); the reference that keeps it differs by more than 1e-3.
(Check 2 of liggghts_laws.py, LIGGGHTS' `law hertz`/`law linear` against its default law, has no
LAMMPS counterpart: the style's hertz/powerlaw laws are dc_pair's, checked by lammps_collision.)

--np 2: mpirun -np 2 with `processors 2 1 1`: the box split at x = 0, each sphere of a pair on its
own rank (every pair contact across the rank boundary), the wall spheres alternately on either
rank. --newton: the pair runs with each setting given (default on; newton off: both owners of a
contact across the boundary evaluate it).

With --check: exit 1 unless every comparison holds. Exit 77 when LAMMPS is not installed.
"""
import argparse
import os
import sys
import tempfile

import harness as H
from harness import lammps as lammps_runs
from harness import laws as EP
from harness.laws import E, NU, P_Y, R, RHO, SPACING


def coeff():
    return "hertz/material %.17g 1 %.17g elastic_plastic %.17g" % (E, NU, P_Y)


def deck(plugin, geom, cols, dt, steps, np_, newton, g):
    """cols: [(atom ids, y, v, gap)]"""
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
         "newton %s" % newton] + (["processors %d 1 1" % np_] if np_ > 1 else []) + [
         "region box block -0.01 0.01 -0.01 %.17g -0.002 0.01 units box" % (cols[-1][1] + 0.01),
         "create_box 1 box", "neighbor 0.0002 bin", "neigh_modify delay 0",
         "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact", "pair_coeff * * " + coeff(),
         "timestep %.17g" % dt]
    for k, (ids, y, v, gap) in enumerate(cols):
        if geom == "pair":
            x = R + gap / 2
            L += ["create_atoms 1 single %.17g %.17g 0 units box" % (-x, y),
                  "create_atoms 1 single %.17g %.17g 0 units box" % (x, y),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[0], 2 * R, RHO, v / 2),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[1], 2 * R, RHO, -v / 2)]
        else:
            # alternately left and right of x = 0 (with 2 ranks: on either)
            L += ["create_atoms 1 single %.17g %.17g %.17g units box" % ((-1) ** k * 2 * R, y, R + gap),
                  "set atom %d diameter %.17g density %.17g vz %.17g" % (ids[0], 2 * R, RHO, -v)]
    if geom == "wall":
        L.append("fix w all demcontact/wall %s zplane 0 NULL" % coeff())
    if g:
        L.append("fix gravi all gravity %.17g vector 0 0 -1" % g)  # after the wall, as the reference adds it
    L += ["fix integr all nve/sphere", "thermo %d" % steps, "run %d" % steps,
          "write_dump all custom final.dump id type vx vy vz modify format float %.17g"]
    return "\n".join(L) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--np", type=int, default=1, choices=(1, 2),
                    help="2: mpirun -np 2, processors 2 1 1 (the pairs straddle the rank boundary)")
    ap.add_argument("--newton", nargs="+", default=["on"], choices=["on", "off"],
                    help="the pair runs with each of these newton settings")
    a = ap.parse_args()
    exe = lammps_runs.find_lmp(a.lmp)
    env = H.mpi_env()
    pre = H.mpi_prefix(a.np, os.path.join(os.path.dirname(exe), "mpirun"))  # the mpich wheel's, next to lmp
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_lammps_laws_"))
    os.makedirs(workdir, exist_ok=True)
    lib = EP.Library(a.plugin)
    bad = []

    def check(ok, what):
        if not ok:
            bad.append(what)

    def run_ep(label, geom, impacts, dt, steps, g, newton):
        cols, atom, y = [], 1, 0.0
        for v, gap in impacts:
            ids = (atom, atom + 1) if geom == "pair" else (atom,)
            cols.append((ids, y, v, gap))
            atom += len(ids)
            y += SPACING
        d = os.path.join(workdir, "%s_%s_newton_%s" % (label, geom, newton))
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.laws"), "w").write(deck(a.plugin, geom, cols, dt, steps, a.np, newton, g))
        H.run(pre + [exe, "-in", "in.laws", "-log", "log.lammps"], d, env)
        final = H.read_last_dump(os.path.join(d, "final.dump"))
        if geom == "pair":
            return {v: (float(final[ids[1]]["vx"]) - float(final[ids[0]]["vx"])) / v for ids, y, v, gap in cols}
        return {v: float(final[ids[0]]["vz"]) / v for ids, y, v, gap in cols}

    for i, newton in enumerate(a.newton):
        print("# newton %s, %d rank(s)%s" % (newton, a.np, "" if i == 0 else ": the pair runs"))
        EP.compare(lib, lambda *r: run_ep(*r, newton=newton), "LAMMPS", check,
                   geoms=("pair", "wall") if i == 0 else ("pair",), second=i == 0)

    print("tolerances: library %g, Thornton %g" % (EP.TOL_REF, EP.TOL_CLOSED))
    if bad:
        print("FAIL:\n  " + "\n  ".join(bad))
        if a.check:
            sys.exit(1)
    else:
        print("all comparisons within tolerance")


if __name__ == "__main__":
    main()
