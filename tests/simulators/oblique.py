#!/usr/bin/env python3
"""Oblique sphere-wall impacts (Chung & Ooi 2011, test 4 conditions) in LIGGGHTS and LAMMPS with
demcontact's full contact, against the library's own impact (oblique_ref: dc_contact_force
integrated in the hosts' velocity-Verlet order).

  oblique.py --sim lammps   --plugin demcontactplugin.so --ref oblique_ref [--lmp lmp]
  oblique.py --sim liggghts --plugin libdemcontact_liggghts.so --ref oblique_ref
             [--step-exact] [--rescale] [--steps-per-contact N]

--step-exact: the plugins' step_exact / stepExact on, the reference's dc_contact_model_set_step;
--rescale: LAMMPS' tangential mindlin_rescale, LIGGGHTS' tangentialRescale on; the reference's
DC_TANGENTIAL_MINDLIN_RESCALE.

Conditions: alumina sphere R = 2.5 mm, rho = 4000 kg/m^3, E = 380 GPa, nu = 0.23, onto a flat wall of
the same material, impact speed 3.9 m/s at 5..85 degrees from the wall normal, normal restitution
0.98, friction 0.092, Mindlin tangential stiffness, no tangential damping (e_t = 1). All 17
spheres hit the wall in one run, far apart. Tangential restitution e_t = rebound tangential speed of
the contact point / incident one, and the rebound spin, from the code's own dump.

Checks: (1) every angle within ABS_SAME of the library integrated with the same time step (the
plugin is wired right: same forces, torques, history, frames); (2) within TOL (2 % of the incident
tangential speed, i.e. |delta e_t| <= 0.02) of the library's converged curve (time step / 8).
"""
import argparse
import math
import os
import subprocess
import tempfile

import harness as H

E, NU, RHO, R, REST, MU, E_T, V = 3.8e11, 0.23, 4000.0, 2.5e-3, 0.98, 0.092, 1.0, 3.9
ANGLES = list(range(5, 90, 5))
ABS_SAME = 1e-6
TOL = 0.02
SPACING = 0.01


def timing(spc=500):
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    es = E / (2 * (1 - NU * NU))
    vn = [V * math.cos(math.radians(a)) for a in ANGLES]
    tc = [2.87 * (m * m / (R * es * es * v)) ** 0.2 for v in vn]
    dt = min(tc) / spc
    t_end = max(1e-3 * R / v + 1.5 * t for v, t in zip(vn, tc))
    return dt, int(math.ceil(t_end / dt))


def reference(ref, dt, flags=()):
    out = subprocess.run([ref] + list(flags) + ["%.17g" % x for x in (E, NU, RHO, R, REST, MU, E_T, V, dt)] +
                         [str(a) for a in ANGLES], stdout=subprocess.PIPE, text=True, check=True).stdout
    res = {}
    for line in out.splitlines():
        a, et, wy, en = line.split()
        res[int(float(a))] = (float(et), float(wy), float(en))
    return res


def atoms_lines(create):
    L = []
    for k, a in enumerate(ANGLES):
        th = math.radians(a)
        L.append(create % (k * SPACING, R * 1.001))
        L.append("set atom %d diameter %.17g density %.17g vx %.17g vy 0 vz %.17g" %
                 (k + 1, 2 * R, RHO, V * math.sin(th), -V * math.cos(th)))
    return L


def lammps_deck(plugin, dt, steps, step_exact=False, rescale=False):
    c = "hertz/material %.17g %.17g %.17g tangential %s NULL %.17g %.17g" % (
        E, REST, NU, "mindlin_rescale" if rescale else "mindlin", E_T, MU)
    if step_exact:
        c += " step_exact"
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
         "region box block -0.01 0.01 -0.01 %g -0.001 0.01 units box" % (len(ANGLES) * SPACING),
         "create_box 1 box", "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact",
         "pair_coeff * * " + c, "neighbor 0.001 bin"]
    L += atoms_lines("create_atoms 1 single 0 %.17g %.17g units box")
    L += ["fix w all demcontact/wall %s zplane 0 NULL" % c, "fix integr all nve/sphere",
          "timestep %.17g" % dt, "run %d" % steps,
          "write_dump all custom final.dump id vx vy vz omegax omegay omegaz modify format float %.17g"]
    return "\n".join(L) + "\n"


def liggghts_deck(dt, steps, step_exact=False, rescale=False):
    model = "model demcontact tangential demcontact"
    settings = "tangentialRestitution %.17g" % E_T  # walls take their settings after the wall
    if step_exact:
        settings += " stepExact on"
    if rescale:
        settings += " tangentialRescale on"
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si",
         "region box block -0.01 0.01 -0.01 %g -0.001 0.01 units box" % (len(ANGLES) * SPACING),
         "create_box 1 box", "neighbor 0.001 bin",
         "fix m1 all property/global youngsModulus peratomtype %.17g" % E,
         "fix m2 all property/global poissonsRatio peratomtype %.17g" % NU,
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 %.17g" % REST,
         "fix m4 all property/global coefficientFriction peratomtypepair 1 %.17g" % MU,
         "pair_style gran %s %s" % (model, settings), "pair_coeff * *"]
    L += atoms_lines("create_atoms 1 single 0 %.17g %.17g units box")
    L += ["fix w all wall/gran %s primitive type 1 zplane 0.0 %s" % (model, settings), "fix integr all nve/sphere",
          "timestep %.17g" % dt, "run %d" % steps,
          "dump fin all custom 1 final.dump id vx vy vz omegax omegay omegaz",
          "dump_modify fin format \"%d %.17g %.17g %.17g %.17g %.17g %.17g\"", "run 0"]
    return "\n".join(L) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", choices=["liggghts", "lammps"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--ref", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    ap.add_argument("--step-exact", action="store_true")
    ap.add_argument("--rescale", action="store_true",
                    help="LAMMPS: tangential mindlin_rescale; LIGGGHTS: tangentialRescale on")
    ap.add_argument("--steps-per-contact", type=float, default=500.0,
                    help="dt = the shortest contact duration / this (default 500)")
    a = ap.parse_args()
    if not a.steps_per_contact > 1:
        ap.error("--steps-per-contact must be > 1 (got %g)" % a.steps_per_contact)
    flags = (["--step-exact"] if a.step_exact else []) + (["--rescale"] if a.rescale else [])
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_oblique_"))
    os.makedirs(workdir, exist_ok=True)
    dt, steps = timing(a.steps_per_contact)
    if a.sim == "lammps":
        from harness import lammps as lammps_runs
        exe = lammps_runs.find_lmp(a.lmp)
        env = H.mpi_env()
        deck = lammps_deck(a.plugin, dt, steps, a.step_exact, a.rescale)
    else:
        exe, env = H.liggghts_cmd(a.plugin)
        deck = liggghts_deck(dt, steps, a.step_exact, a.rescale)
    open(os.path.join(workdir, "in.oblique"), "w").write(deck)
    H.run([exe, "-in", "in.oblique", "-log", "log.oblique"], workdir, env)
    final = H.read_last_dump(os.path.join(workdir, "final.dump"))
    same, conv = reference(a.ref, dt, flags), reference(a.ref, dt / 8, flags)
    print("## %s: oblique impacts, alumina R = 2.5 mm at %.1f m/s, mu = %g, e = %g (dt = %.3g s)%s%s"
          % (a.sim, V, MU, REST, dt, ", step-aware" if a.step_exact else "",
             ", mindlin_rescale" if a.rescale else ""))
    print()
    print("| angle [deg] | e_t %s | e_t library (same dt) | e_t library (dt/8) | omega_y %s [rad/s] | omega_y library (dt/8) |"
          % (a.sim, a.sim))
    print("|---|---|---|---|---|---|")
    worst_same, worst_conv = 0.0, 0.0
    for k, ang in enumerate(ANGLES):
        f = final[k + 1]
        th = math.radians(ang)
        vt_in = V * math.sin(th)
        wy = float(f["omegay"])
        et = (float(f["vx"]) - R * wy) / vt_in
        worst_same = max(worst_same, abs(et - same[ang][0]))
        worst_conv = max(worst_conv, abs(et - conv[ang][0]))
        print("| %d | %.6f | %.6f | %.6f | %.3f | %.3f |" % (ang, et, same[ang][0], conv[ang][0], wy, conv[ang][1]))
    print()
    print("max |e_t - library, same dt| = %.2e (tolerance %g); max |e_t - library, dt/8| = %.2e (tolerance %g)"
          % (worst_same, ABS_SAME, worst_conv, TOL))
    if not (worst_same <= ABS_SAME and worst_conv <= TOL):
        raise SystemExit("FAIL: oblique impacts differ from the library's")


if __name__ == "__main__":
    main()
