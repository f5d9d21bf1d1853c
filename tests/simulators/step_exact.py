#!/usr/bin/env python3
"""Restitution realised at the host's own time step, inside LAMMPS and LIGGGHTS, with and without
demcontact's step-aware damping (dc_contact_model_set_step through the plugins' `step_exact` /
`stepExact on`).

  step_exact.py --sim lammps   --plugin demcontactplugin.so [--lmp lmp] [--np 2]
  step_exact.py --sim liggghts --plugin libdemcontact_liggghts.so
                [--phases 32] [--targets 0.1,0.5,0.9] [--steps-per-contact 20] [--check TOL]

Head-on collisions at v = 1 m/s of two equal spheres and of a sphere with a flat wall of the same
material (R = 1 mm, rho = 2500 kg/m^3, E = 1e7 Pa, nu = 0.3), Hertz, for each target e_n and both
end criteria (overlap; force: LAMMPS' limit_damping, LIGGGHTS' limitForce on). The time step is
dt = t_H / steps-per-contact, t_H the elastic Hertz contact duration at the impact speed,
2.868265699 (m*^2 / (R* E*^2 v))^(1/5), of that geometry (two spheres: m* = m/2, R* = R/2; wall:
m* = m, R* = R; E* = E / (2 (1 - nu^2)) in both: the wall has the sphere's material). The contact
onset falls at phase phi = j/phases of a step: the surfaces start (2 + phi) v dt apart (j = 0 ..
phases - 1). Every (target, phase) collides in one simulator run per geometry, criterion and
variant (plain, step-aware), far apart. Realised e from the simulator's own dump of the final
velocities: (v_right - v_left)/v (pairs), v_z / v (wall).

Prints the mean realised e over the phases and the worst phase, as relative errors to e_n. With
--check TOL: exit 1 unless every step-aware mean is within TOL (relative) of its e_n, and the
plain model's mean at the smallest target misses it by more than 10 TOL (the test can see the
effect it checks). Exit 77 (ctest SKIP) when the simulator is not installed.
"""
import argparse
import math
import os
import re
import tempfile

import harness as H

R, RHO, E, NU, V = 1e-3, 2500.0, 1e7, 0.3, 1.0
SPACING = 4 * R  # between the collisions of one run
GEOMETRIES = ("pair", "wall")
DT_RESET_FACTOR = 3.0
CRITERIA = ("overlap", "force")
VARIANTS = ("plain", "step_exact")


def t_hertz(geom):
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    m_eff, r_eff = (m / 2, R / 2) if geom == "pair" else (m, R)
    e_eff = E / (2 * (1 - NU * NU))
    return 2.868265699 * (m_eff ** 2 / (r_eff * e_eff ** 2 * V)) ** 0.2


def setup(geom, spc, phases):
    dt = t_hertz(geom) / spc
    gaps = [(2.0 + j / phases) * V * dt for j in range(phases)]
    steps = int(math.ceil((max(gaps) / V + 3.0 * t_hertz(geom)) / dt)) + 5
    return dt, gaps, steps


def collisions(geom, targets, gaps):
    """[(type, e, gap, atom ids, y)]: one collision per (target, phase)."""
    out, atom, y = [], 1, 0.0
    for t, e in enumerate(targets, start=1):
        for g in gaps:
            ids = (atom, atom + 1) if geom == "pair" else (atom,)
            out.append((t, e, g, ids, y))
            atom += len(ids)
            y += SPACING
    return out


def atoms_lines(geom, cols, create):
    L = []
    for t, e, g, ids, y in cols:
        if geom == "pair":
            x = R + g / 2
            L += [create % (t, -x, y, 0.0), create % (t, x, y, 0.0),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[0], 2 * R, RHO, V / 2),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[1], 2 * R, RHO, -V / 2)]
        else:
            L += [create % (t, 0.0, y, R + g),
                  "set atom %d diameter %.17g density %.17g vz %.17g" % (ids[0], 2 * R, RHO, -V)]
    return L


def box(cols):
    return "region box block -0.01 0.01 -0.01 %.17g -0.002 0.01 units box" % (cols[-1][4] + 0.01)


# ------------------------------------------------------------------ LAMMPS
def lammps_deck(plugin, geom, crit, variant, targets, dt, steps, cols, np_, dt_reset=False):
    def coeff(e):
        c = "hertz/material %.17g %.17g %.17g" % (E, e, NU)
        if crit == "force":
            c += " limit_damping"
        if variant == "step_exact":
            c += " step_exact"
        return c

    n = len(targets)
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes"]
    if np_ == 2:
        L.append("processors 2 1 1")  # the pair contacts (at x = 0) straddle the two ranks
    L += [box(cols), "create_box %d box" % n, "neighbor 0.0002 bin", "neigh_modify delay 0",
          "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact"]
    # explicit cross-type pairs (never in contact): the types differ in e only
    for i in range(1, n + 1):
        for j in range(i, n + 1):
            L.append("pair_coeff %d %d %s" % (i, j, coeff(math.sqrt(targets[i - 1] * targets[j - 1]))))
    L += atoms_lines(geom, cols, "create_atoms %d single %.17g %.17g %.17g units box")
    if geom == "wall":
        for t, e in enumerate(targets, start=1):
            L += ["group g%d type %d" % (t, t), "fix w%d g%d demcontact/wall %s zplane 0 NULL" % (t, t, coeff(e))]
    L += dt_lines(dt, dt_reset)
    L += ["fix integr all nve/sphere", "thermo_style custom step dt time", "thermo 1", "run %d" % steps,
          "write_dump all custom final.dump id type vx vy vz modify format float %.17g"]
    return "\n".join(L) + "\n"


def run_lammps(a, geom, crit, variant, targets, workdir):
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    dt, gaps, steps = setup(geom, a.steps_per_contact, a.phases)
    cols = collisions(geom, targets, gaps)
    d = os.path.join(workdir, "%s_%s_%s" % (geom, crit, variant))
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.step"), "w").write(lammps_deck(a.plugin, geom, crit, variant, targets, dt, steps, cols,
                                                            a.np, a.dt_reset))
    pre = H.mpi_prefix(a.np, os.path.join(os.path.dirname(exe), "mpirun"))
    H.run(pre + [exe, "-in", "in.step", "-log", "log.lammps"], d, H.mpi_env())
    if a.dt_reset:
        check_dt_reset(os.path.join(d, "log.lammps"), dt)
    return realised(geom, cols, H.read_last_dump(os.path.join(d, "final.dump")))


def check_dt_reset(log, dt):
    """--dt-reset's premise: fix dt/reset did set the step the collisions ran at (the thermo
    column Dt of every step after the first equals dt to its printed digits, 1e-6: the deck's
    timestep is DT_RESET_FACTOR dt), else the run is a plain one at the deck's larger timestep and
    proves nothing about the models following the reset."""
    runs = H.parse_thermo(open(log).read())
    rows = [r for r in (runs[0] if runs else []) if int(r["Step"]) >= 1]
    bad = [r for r in rows if not abs(float(r["Dt"]) / dt - 1.0) <= 1e-6]
    if not rows or bad:
        raise SystemExit("FAIL: %s: fix dt/reset did not set dt = %.17g (%d rows after step 0; first off: %s)"
                         % (log, dt, len(rows), bad[0] if bad else "none"))


# ------------------------------------------------------------------ LIGGGHTS
def dt_lines(dt, dt_reset):
    """timestep (and --dt-reset's fix dt/reset), the same in both codes"""
    if not dt_reset:
        return ["timestep %.17g" % dt]
    # the styles' init sees DT_RESET_FACTOR dt; fix dt/reset (at most dt; Xmax = 1 m: always that
    # bound) sets dt in its setup, after that init: the models must follow (LAMMPS: reset_dt;
    # LIGGGHTS: at the first contact after the change)
    return ["timestep %.17g" % (DT_RESET_FACTOR * dt), "fix dtr all dt/reset 1 %.17g %.17g 1.0 units box" % (0.5 * dt, dt)]


def liggghts_deck(geom, crit, variant, targets, dt, steps, cols, submodels, np_, dt_reset=False):
    n = len(targets)
    model = "model demcontact " + submodels
    settings = ""
    if crit == "force":
        settings += " limitForce on"
    if variant == "step_exact":
        settings += " stepExact on"
    rest = " ".join("%.17g" % math.sqrt(a * b) for a in targets for b in targets)
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si"]
    if np_ == 2:
        L.append("processors 2 1 1")  # the pair contacts (at x = 0) straddle the two ranks
    L += [box(cols), "create_box %d box" % n,
         "neighbor 0.0002 bin", "neigh_modify delay 0",
         "fix m1 all property/global youngsModulus peratomtype " + " ".join("%.17g" % E for _ in targets),
         "fix m2 all property/global poissonsRatio peratomtype " + " ".join("%.17g" % NU for _ in targets),
         "fix m3 all property/global coefficientRestitution peratomtypepair %d %s" % (n, rest),
         "fix m4 all property/global coefficientFriction peratomtypepair %d %s" % (n, " ".join("0" for _ in
                                                                                               range(n * n))),
         "fix m5 all property/global coefficientRollingFriction peratomtypepair %d %s" % (
             n, " ".join("0" for _ in range(n * n))),
         "pair_style gran " + model + settings, "pair_coeff * *"] + dt_lines(dt, dt_reset)
    L += atoms_lines(geom, cols, "create_atoms %d single %.17g %.17g %.17g units box")
    if geom == "wall":
        # one wall per atom type, of that type (its e with the wall: coefficientRestitution t-t);
        # a wall takes its model settings after the wall
        for t in range(1, n + 1):
            L += ["group g%d type %d" % (t, t),
                  "fix w%d g%d wall/gran %s primitive type %d zplane 0.0%s" % (t, t, model, t, settings)]
    L += ["fix integr all nve/sphere", "thermo_style custom step dt time", "thermo 1", "run %d" % steps,
          "dump fin all custom 1 final.dump id type vx vy vz",
          "dump_modify fin format \"%d %d %.17g %.17g %.17g\"", "run 0"]
    return "\n".join(L) + "\n"


def run_liggghts(a, geom, crit, variant, targets, workdir):
    exe, env = H.liggghts_cmd(a.plugin)
    dt, gaps, steps = setup(geom, a.steps_per_contact, a.phases)
    cols = collisions(geom, targets, gaps)
    d = os.path.join(workdir, "%s_%s_%s" % (geom, crit, variant))
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.step"), "w").write(liggghts_deck(geom, crit, variant, targets, dt, steps, cols,
                                                              a.liggghts_submodels, a.np, a.dt_reset))
    H.run(H.mpi_prefix(a.np) + [exe, "-in", "in.step", "-log", "log.liggghts"], d, env)
    if a.dt_reset:
        check_dt_reset(os.path.join(d, "log.liggghts"), dt)
    return realised(geom, cols, H.read_last_dump(os.path.join(d, "final.dump")))


# ------------------------------------------------------------------ table
def realised(geom, cols, final):
    """{e: [realised e per phase]}"""
    out = {}
    for t, e, g, ids, y in cols:
        if geom == "pair":
            r = (float(final[ids[1]]["vx"]) - float(final[ids[0]]["vx"])) / V
        else:
            r = float(final[ids[0]]["vz"]) / V
        out.setdefault(e, []).append(r)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", choices=["lammps", "liggghts"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--workdir")
    ap.add_argument("--phases", type=int, default=32)
    ap.add_argument("--targets", default="0.1,0.5,0.9")
    ap.add_argument("--steps-per-contact", type=float, default=20.0)
    ap.add_argument("--geometries", default=",".join(GEOMETRIES))
    ap.add_argument("--criteria", default=",".join(CRITERIA))
    ap.add_argument("--check", type=float, help="relative tolerance on the step-aware means")
    ap.add_argument("--liggghts-submodels", default="tangential no_history",
                    help="LIGGGHTS: the sub-models after 'model demcontact' (e.g. 'tangential demcontact "
                         "rolling_friction demcontact')")
    ap.add_argument("--dt-reset", action="store_true",
                    help="timestep %g dt, fix dt/reset sets dt after the styles' init" % DT_RESET_FACTOR)
    a = ap.parse_args()
    if a.np not in (1, 2):
        ap.error("--np must be 1 or 2 (got %d)" % a.np)
    if a.phases < 1:
        ap.error("--phases must be >= 1 (got %d)" % a.phases)
    if not a.steps_per_contact > 1:
        ap.error("--steps-per-contact must be > 1 (got %g)" % a.steps_per_contact)
    try:
        targets = [float(x) for x in a.targets.split(",")]
    except ValueError:
        ap.error("--targets: comma-separated numbers in (0, 1) (got %r)" % a.targets)
    if not all(0.0 < e < 1.0 for e in targets):
        ap.error("--targets: each in (0, 1) (got %r)" % a.targets)
    geoms = a.geometries.split(",")
    crits = a.criteria.split(",")
    if not set(geoms) <= set(GEOMETRIES) or not set(crits) <= set(CRITERIA):
        ap.error("--geometries from %s, --criteria from %s" % (GEOMETRIES, CRITERIA))
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_step_exact_"))
    os.makedirs(workdir, exist_ok=True)
    runner = run_lammps if a.sim == "lammps" else run_liggghts
    print("## %s%s, %d MPI rank%s: realised e at dt = t_H/%g, %d contact-onset phases%s" %
          (a.sim, " (model demcontact %s)" % a.liggghts_submodels if a.sim == "liggghts" else "",
           a.np, "s" if a.np > 1 else "", a.steps_per_contact, a.phases,
           ", dt set by fix dt/reset from timestep %g dt" % DT_RESET_FACTOR if a.dt_reset else ""))
    print()
    print("| collision | criterion | e_n | plain: mean e | plain: mean err | plain: worst phase | "
          "step_exact: mean e | step_exact: mean err | step_exact: worst phase |")
    print("|---|---|---|---|---|---|---|---|---|")
    worst_mean, plain_low = 0.0, []
    for geom in geoms:
        for crit in crits:
            res = {v: runner(a, geom, crit, v, targets, workdir) for v in VARIANTS}
            for e in targets:
                row = []
                for v in VARIANTS:
                    rs = res[v][e]
                    if not all(math.isfinite(r) for r in rs):
                        raise SystemExit("FAIL: %s %s %s e = %g: a realised e is not finite" % (geom, crit, v, e))
                    mean = sum(rs) / len(rs)
                    err = mean / e - 1.0
                    worst = max((r / e - 1.0 for r in rs), key=abs)
                    row.append("%.5f | %+.3f %% | %+.2f %%" % (mean, 100 * err, 100 * worst))
                    if v == "step_exact":
                        worst_mean = max(worst_mean, abs(err))
                    elif e == min(targets):
                        plain_low.append(abs(err))
                print("| %s | %s | %g | %s |" % ("two spheres" if geom == "pair" else "sphere-wall",
                                                  "force (limit_damping)" if crit == "force" else "overlap",
                                                  e, " | ".join(row)))
    print()
    print("worst |mean e / e_n - 1| with step_exact: %.3f %%; plain at e_n = %g: %.2f %% .. %.2f %%"
          % (100 * worst_mean, min(targets), 100 * min(plain_low), 100 * max(plain_low)))
    if a.check is not None:
        if not worst_mean <= a.check:
            raise SystemExit("FAIL: a step_exact mean misses e_n by %.3g > %g (relative)" % (worst_mean, a.check))
        if not min(plain_low) > 10 * a.check:
            raise SystemExit("FAIL: the plain model's mean at e_n = %g is within %.3g of it: this run cannot "
                             "show the step-aware correction (tolerance %g)" % (min(targets), min(plain_low),
                                                                                 a.check))
        print("PASS (tolerance %g)" % a.check)


if __name__ == "__main__":
    main()
