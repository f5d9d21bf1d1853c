#!/usr/bin/env python3
"""fix demcontact/wall/region against independent references: one sphere's oblique impact on a
floor (R = 1 mm, rho = 2500, E = 5e6, nu = 0.3, e = 0.5, Mindlin e_t = 0.5, mu = 0.5, EPSD rolling
mu_r = 0.1; v = (0.3, 0, -0.5) m/s; the floor z = -5 mm; 2e5 steps of 1e-8 s, the contact lasts
~1e-4 s), the rebound velocity and spin compared:

  lammps_region_wall.py --plugin demcontactplugin.so [--lmp lmp] [--workdir DIR]

  plane      `region plane` floor                  = fix demcontact/wall zplane (same contact)
  block      the bottom face of a `region block`     = fix demcontact/wall zplane
  moving     `region plane ... move v_dx NULL NULL`, dx = U t (U = 0.2 m/s), the sphere at
             v + (U, 0, 0)                           = zplane with v, plus U on v_x (Galilean)
  rotating   `region plane ... rotate v_th 1 0 0 0 0 1` (axis z through x = 1 m, W = 0.2 rad/s:
             the floor's surface at the contact moves at (0, -W, 0))
                                                     = zplane with v + (0, W, 0), plus -W on v_y

Tolerances (relative to |v0|, spin times R): plane and block 1e-12 (the region's distance and
normal are the plane's up to rounding); moving 1e-8 (Region::set_velocity differentiates the
position, dx/dt, in floating point); rotating 1e-3 (the contact point drifts by ~3e-5 m during the
contact, 3e-5 of the 1 m lever). A wall whose velocity were ignored misses by U / |v0| ~ 0.3.
Exit 77 (ctest SKIP) when LAMMPS is missing.
"""
import argparse
import math
import os
import re
import sys
import tempfile

import harness as H

R, V0, U, W = 1e-3, (0.3, 0.0, -0.5), 0.2, 0.2
MODEL = "hertz/material 5e6 0.5 0.3 tangential mindlin NULL 0.5 0.5 rolling sds NULL 0 0.1"
WALLS = {
    "zplane": "fix w all demcontact/wall %s zplane -0.005 NULL" % MODEL,
    "plane": "region fl plane 0 0 -0.005 0 0 1 side in units box\n"
             "fix w all demcontact/wall/region %s region fl" % MODEL,
    "block": "region fl block -1 1 -1 1 -0.005 1 side in units box\n"
             "fix w all demcontact/wall/region %s region fl" % MODEL,
    "moving": "variable dx equal %g*time\n"
              "region fl plane 0 0 -0.005 0 0 1 side in units box move v_dx NULL NULL\n"
              "fix w all demcontact/wall/region %s region fl" % (U, MODEL),
    "rotating": "variable th equal %g*time\n"
                "region fl plane 0 0 -0.005 0 0 1 side in units box rotate v_th 1 0 0 0 0 1\n"
                "fix w all demcontact/wall/region %s region fl" % (W, MODEL),
}
# (case, its wall, the sphere's velocity, reference wall, reference velocity, shift of the
# reference's v added before comparing, tolerance)
CASES = [
    ("plane", "plane", V0, "zplane", V0, (0, 0, 0), 1e-12),
    ("block", "block", V0, "zplane", V0, (0, 0, 0), 1e-12),
    ("moving", "moving", (V0[0] + U, V0[1], V0[2]), "zplane", V0, (U, 0, 0), 1e-8),
    ("rotating", "rotating", V0, "zplane", (V0[0], V0[1] + W, V0[2]), (0, -W, 0), 1e-3),
]


def deck(plugin, wall, v):
    return "\n".join([
        "units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
        "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box", "create_box 1 box",
        "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact", "pair_coeff * * " + MODEL,
        wall, "create_atoms 1 single 0 0 -0.0039 units box",
        "set group all diameter %g density 2500" % (2 * R),
        "velocity all set %.17g %.17g %.17g" % v, "fix integr all nve/sphere", "timestep 1e-8",
        "thermo 100000",
        "variable vx equal vx[1]", "variable vy equal vy[1]", "variable vz equal vz[1]",
        "compute om all property/atom omegax omegay omegaz",
        "compute oms all reduce sum c_om[1] c_om[2] c_om[3]",  # (the one atom's spin)
        "variable wx equal c_oms[1]", "variable wy equal c_oms[2]", "variable wz equal c_oms[3]",
        "thermo_style custom step ke v_wx v_wy v_wz",  # (thermo at the last step invokes the compute)
        "run 200000", 'print "OUT ${vx} ${vy} ${vz} ${wx} ${wy} ${wz}"']) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    env = H.mpi_env()
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_regwall_"))
    cache = {}

    def result(wall, v):
        key = (wall, v)
        if key not in cache:
            d = os.path.join(workdir, "%s_%d" % (wall, len(cache)))
            os.makedirs(d, exist_ok=True)
            open(os.path.join(d, "in.deck"), "w").write(deck(a.plugin, WALLS[wall], v))
            H.run([exe, "-in", "in.deck", "-log", "log.lammps"], d, env)
            m = re.findall(r"^OUT " + " ".join([r"(\S+)"] * 6), open(os.path.join(d, "log.lammps")).read(), re.M)
            if not m:
                raise SystemExit("FAIL: %s: no result line (see %s)" % (wall, d))
            cache[key] = [float(x) for x in m[-1]]
        return cache[key]

    v0 = math.sqrt(sum(c * c for c in V0))
    ok = True
    for name, wall, v, ref, vref, shift, tol in CASES:
        got, want = result(wall, v), result(ref, vref)
        want = [want[k] + (shift[k] if k < 3 else 0.0) for k in range(6)]
        if not got[2] > 0.0:
            print("FAIL %-9s the sphere did not rebound (v_z = %g)" % (name, got[2]))
            ok = False
            continue
        err = H.worst_of(abs(g - w) * (1.0 if k < 3 else R) for k, (g, w) in enumerate(zip(got, want))) / v0
        good = err <= tol
        ok &= good
        print("%s %-9s v = (%.9g, %.9g, %.9g), omega = (%.6g, %.6g, %.6g); vs %s: %.3g of |v0| (tolerance %g)"
              % ("ok  " if good else "FAIL", name, *got, ref, err, tol))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
