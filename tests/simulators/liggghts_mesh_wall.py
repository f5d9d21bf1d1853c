#!/usr/bin/env python3
"""LIGGGHTS 3.8's mesh walls take the demcontact model as they are: `fix wall/gran model demcontact
tangential demcontact rolling_friction demcontact mesh n_meshes 1 meshes cad` (a two-triangle STL
plane from `fix mesh/surface`) goes through the same contact-model factory as the primitive wall.

  liggghts_mesh_wall.py --plugin libdemcontact_liggghts.so [--workdir DIR]

One sphere (r = 1 mm, 2500 kg/m^3, E = 5e6, nu = 0.3, e = 0.5, mu = 0.5) hits the wall z = -5 mm
obliquely (v = (0.3, 0, -0.5) m/s) once against the mesh and once against `primitive type 1 zplane`.
Checks: the rebound velocity and spin after the mesh contact equal the primitive wall's within
1e-9 (relative to |v0|), and the normal rebound is e |v_z0| within 1e-3 relative (the model's
calibration). Exit 77 (ctest SKIP) when LIGGGHTS is not installed.
"""
import argparse
import os
import re
import sys
import tempfile

import harness as H

STL = """solid plane
facet normal 0 0 1
outer loop
vertex -0.02 -0.02 -0.005
vertex 0.02 -0.02 -0.005
vertex 0.02 0.02 -0.005
endloop
endfacet
facet normal 0 0 1
outer loop
vertex -0.02 -0.02 -0.005
vertex 0.02 0.02 -0.005
vertex -0.02 0.02 -0.005
endloop
endfacet
endsolid plane
"""
E_REST, V0 = 0.5, (0.3, 0.0, -0.5)
MODEL = "model demcontact tangential demcontact rolling_friction demcontact"


def deck(wall):
    return "\n".join([
        "atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
        "communicate single vel yes", "units si",
        "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box", "create_box 1 box",
        "neighbor 0.0002 bin",
        "fix m1 all property/global youngsModulus peratomtype 5e6",
        "fix m2 all property/global poissonsRatio peratomtype 0.3",
        "fix m3 all property/global coefficientRestitution peratomtypepair 1 %g" % E_REST,
        "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5",
        "fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.1",
        "pair_style gran " + MODEL, "pair_coeff * *",
        "fix cad all mesh/surface file plane.stl type 1",
        "fix w all wall/gran %s %s" % (MODEL, wall),
        "create_atoms 1 single 0 0 0 units box", "set group all diameter 0.002 density 2500",
        "velocity all set %g %g %g" % V0, "fix integr all nve/sphere", "timestep 1e-7",
        "thermo 20000", "thermo_style custom step ke",
        "variable vx equal vx[1]", "variable vz equal vz[1]", "variable wy equal omegay[1]",
        "run 100000", 'print "OUT ${vx} ${vz} ${wy}"']) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--workdir")
    a = ap.parse_args()
    exe, env = H.liggghts_cmd(a.plugin)
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_ligmesh_"))
    out = {}
    for label, wall in (("mesh", "mesh n_meshes 1 meshes cad"), ("primitive", "primitive type 1 zplane -0.005")):
        d = os.path.join(workdir, label)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "plane.stl"), "w").write(STL)
        open(os.path.join(d, "in.deck"), "w").write(deck(wall))
        H.run([exe, "-in", "in.deck", "-log", "log.liggghts"], d, env)
        m = re.findall(r"^OUT (\S+) (\S+) (\S+)", open(os.path.join(d, "log.liggghts")).read(), re.M)
        if not m:
            raise SystemExit("FAIL: %s wall: no result line (see %s)" % (label, d))
        out[label] = [float(x) for x in m[-1]]
        print("%-9s wall: v_x %.12g, v_z %.12g, omega_y %.12g" % (label, *out[label]))
    v0 = (V0[0] ** 2 + V0[2] ** 2) ** 0.5
    # velocities as they are, the spin times R
    diff = H.worst_of(abs(a_ - b_) * (1.0 if k < 2 else 0.001)
               for k, (a_, b_) in enumerate(zip(out["mesh"], out["primitive"])))
    ok_same = diff <= 1e-9 * v0
    want = E_REST * abs(V0[2])
    rel = abs(out["mesh"][1] - want) / want
    ok_e = rel <= 1e-3
    print("%s mesh vs primitive: largest difference %.3g (v, omega x r), tolerance %.3g" % (
        "ok  " if ok_same else "FAIL", diff, 1e-9 * v0))
    print("%s normal rebound %.9g vs e |v_z0| = %.9g: relative %.3g, tolerance 1e-3" % (
        "ok  " if ok_e else "FAIL", out["mesh"][1], want, rel))
    sys.exit(0 if ok_same and ok_e else 1)


if __name__ == "__main__":
    main()
