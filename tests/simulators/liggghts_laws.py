#!/usr/bin/env python3
"""The registry's normal laws in LIGGGHTS (`model demcontact ... law KEYWORD`, parameters from
property/global named after their dc_contact_spec fields in camelCase), head-on collisions.

  liggghts_laws.py --plugin libdemcontact_liggghts.so [--workdir DIR] [--check] [--np 2]
                   [--example plugins/liggghts/examples/in.elastic_plastic]

R = 1 mm, rho = 2500 kg/m^3, E = 1e7 Pa, nu = 0.3 (spheres and walls); one LIGGGHTS run per
geometry (two equal spheres; a sphere and a zplane wall of the same material), every collision in
it far apart from the others, the realised e from LIGGGHTS' own dump of the final velocities.
Checks 1 and 3, the material and the library's reference are shared with lammps_laws.py
(harness/laws.py).

1. law elastic_plastic (yieldPressure P_Y): impact speeds SPEEDS_OVER_VY times the yield speed
   v_y (dc_elastic_plastic_yield_speed), dt = t_H(v_max)/STEPS. Compared with the library's own
   contact stepped the same way (velocity Verlet as LIGGGHTS' nve/sphere: half kick, drift, force
   at the new position and half-step velocity, half kick; the state of dc_contact_force the
   plugin builds: r_eff, m_eff, the other body infinite and at rest; its history double kept
   from step to step, zeroed when the contact ends): |e_liggghts - e_ref| <= TOL_REF. And with
   Thornton's closed form (dc_elastic_plastic_restitution), which assumes the continuous contact:
   |e - e_thornton| <= TOL_CLOSED. e < 1 at all requires the residual state to be carried from step
   to step in LIGGGHTS' contact history (with it lost each step the contact is elastic: e = 1).
2. law hertz against the default law (model demcontact, no law: dc_pair's Tsuji Hertz) and
   law linear (kN = 4/3 E* R*, the pair's) against the default law at exponent 1
   (k = 4/3 E* R*^(2-1)), target e 0.5, one speed: |e_law - e_default| <= TOL_SAME (two code
   paths, dc_pair's kernel and the full contact's normal law, with the same force formula).

3. A second impact of the same sphere on the same wall (gravity brings it back after it left the
   wall): the contact history starts from zero again, as the library's reference with the history
   zeroed at separation (TOL_REF); the reference that keeps it differs by more than 1e-3.
4. --example DECK (plugins/liggghts/examples/in.elastic_plastic): its printed e within TOL_CLOSED
   of Thornton's closed form.

With --check: exit 1 unless every comparison holds. Exit 77 when LIGGGHTS is not installed.
"""
import argparse
import os
import sys
import tempfile

import harness as H
from harness import laws as EP
from harness.laws import E, NU, R, RHO, SPACING, TOL_CLOSED

NP = 1  # MPI ranks (--np)
MODEL = "model demcontact tangential history"
TOL_SAME = 1e-12
E_TARGET, V_SAME = 0.5, 0.5


# ------------------------------------------------------------------ LIGGGHTS
def deck(geom, cols, dt, steps, model, settings, props, extra=()):
    """cols: [(atom ids, y, v, gap)]"""
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si"] + (["processors 2 1 1"] if NP == 2 else []) + [
         "region box block -0.01 0.01 -0.01 %.17g -0.002 0.01 units box" % (cols[-1][1] + 0.01),
         "create_box 1 box", "neighbor 0.0002 bin", "neigh_modify delay 0",
         "fix m1 all property/global youngsModulus peratomtype %.17g" % E,
         "fix m2 all property/global poissonsRatio peratomtype %.17g" % NU,
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 %.17g" % E_TARGET,
         "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5"] + props + [
         ("pair_style gran %s %s" % (model, settings)).strip(), "pair_coeff * *", "timestep %.17g" % dt]
    for ids, y, v, gap in cols:
        if geom == "pair":
            x = R + gap / 2
            L += ["create_atoms 1 single %.17g %.17g 0 units box" % (-x, y),
                  "create_atoms 1 single %.17g %.17g 0 units box" % (x, y),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[0], 2 * R, RHO, v / 2),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[1], 2 * R, RHO, -v / 2)]
        else:
            L += ["create_atoms 1 single 0 %.17g %.17g units box" % (y, R + gap),
                  "set atom %d diameter %.17g density %.17g vz %.17g" % (ids[0], 2 * R, RHO, -v)]
    if geom == "wall":
        # a wall takes its model settings after the wall
        L.append(("fix w all wall/gran %s primitive type 1 zplane 0.0 %s" % (model, settings)).strip())
    L += list(extra) + ["fix integr all nve/sphere", "thermo 1000", "run %d" % steps,
          "dump fin all custom 1 final.dump id type vx vy vz",
          "dump_modify fin format \"%d %d %.17g %.17g %.17g\"", "run 0"]
    return "\n".join(L) + "\n"


def run_collisions(plugin, workdir, label, geom, impacts, dt, steps, settings, props, extra=()):
    """{v: realised e} of impacts [(v, gap)] (EP.plan)"""
    exe, env = H.liggghts_cmd(plugin)
    cols, atom, y = [], 1, 0.0
    for v, gap in impacts:
        ids = (atom, atom + 1) if geom == "pair" else (atom,)
        cols.append((ids, y, v, gap))
        atom += len(ids)
        y += SPACING
    d = os.path.join(workdir, "%s_%s" % (label, geom))
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.laws"), "w").write(deck(geom, cols, dt, steps, MODEL, settings, props, extra))
    H.run(H.mpi_prefix(NP) + [exe, "-in", "in.laws", "-log", "log.liggghts"], d, env)
    final = H.read_last_dump(os.path.join(d, "final.dump"))
    out = {}
    for ids, y, v, gap in cols:
        if geom == "pair":
            out[v] = (float(final[ids[1]]["vx"]) - float(final[ids[0]]["vx"])) / v
        else:
            out[v] = float(final[ids[0]]["vz"]) / v
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--workdir")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--np", type=int, default=1, choices=(1, 2),
                    help="2: mpirun -np 2, processors 2 1 1 (the pairs straddle the rank boundary)")
    ap.add_argument("--example", help="plugins/liggghts/examples/in.elastic_plastic: run it, its printed e "
                                      "within TOL_CLOSED of Thornton's at its 0.2 m/s")
    a = ap.parse_args()
    global NP
    NP = a.np
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_laws_"))
    os.makedirs(workdir, exist_ok=True)
    lib = EP.Library(a.plugin)
    bad = []

    def check(ok, what):
        if not ok:
            bad.append(what)

    ep = "law elastic_plastic"
    prop = ["fix m6 all property/global yieldPressure peratomtypepair 1 %.17g" % EP.P_Y]

    def run_ep(label, geom, impacts, dt, steps, g):
        extra = ["fix gravi all gravity %.17g vector 0 0 -1" % g] if g else []
        return run_collisions(a.plugin, workdir, label, geom, impacts, dt, steps, ep, prop, extra)

    EP.compare(lib, run_ep, "LIGGGHTS", check)

    print("## law hertz / law linear against the default law (e %g at %g m/s)" % (E_TARGET, V_SAME))
    print("%-5s %-8s %18s %18s %10s" % ("geom", "law", "e law", "e default", "|diff|"))
    for geom in ("pair", "wall"):
        r_eff, _ = EP.geometry(geom)
        dt = EP.t_hertz(geom, V_SAME) / EP.STEPS
        impacts, steps = EP.plan(geom, [V_SAME], dt)
        for law, default, props in (
                ("hertz", "", []),
                ("linear", "exponent 1", ["fix m6 all property/global kN scalar %.17g" % (4.0 / 3.0 * EP.e_star() * r_eff)])):
            e_law = run_collisions(a.plugin, workdir, law, geom, impacts, dt, steps, "law " + law, props)
            e_def = run_collisions(a.plugin, workdir, law + "_default", geom, impacts, dt, steps, default, [])
            diff = abs(e_law[V_SAME] - e_def[V_SAME])
            print("%-5s %-8s %18.15f %18.15f %10.3g" % (geom, law, e_law[V_SAME], e_def[V_SAME], diff))
            check(diff <= TOL_SAME, "%s law %s vs default: %.3g > %g" % (geom, law, diff, TOL_SAME))
    if a.example:
        # the documented example deck as a user runs it: two spheres of the "pair" geometry at 0.2 m/s
        exe, env = H.liggghts_cmd(a.plugin)
        d = os.path.join(workdir, "example")
        os.makedirs(d, exist_ok=True)
        out, _ = H.run([exe, "-in", os.path.abspath(a.example), "-log", "log.liggghts"], d, env)
        e = [float(l.split("=")[1]) for l in out.splitlines() if l.startswith("realised e = ")]
        th = lib.thornton(0.2 / lib.yield_speed("pair"))
        print("## example %s: realised e %s, Thornton %.6f" % (os.path.basename(a.example), e, th))
        check(len(e) == 1 and abs(e[0] - th) <= TOL_CLOSED, "example: e %s vs Thornton %.6f" % (e, th))

    print("tolerances: library %g, Thornton %g, default law %g" % (EP.TOL_REF, TOL_CLOSED, TOL_SAME))
    if bad:
        print("FAIL:\n  " + "\n  ".join(bad))
        if a.check:
            sys.exit(1)
    else:
        print("all comparisons within tolerance")


if __name__ == "__main__":
    main()
