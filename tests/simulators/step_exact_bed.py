#!/usr/bin/env python3
"""Enduring contacts and bulk results with demcontact's step-aware damping (`step_exact`) in LAMMPS.

  step_exact_bed.py --plugin demcontactplugin.so --lib libdemcontact.so [--lmp lmp] [--workdir DIR]
                    [--part bed|pour|all] [--seeds 3] [--smoke] [--check]

Spheres of one size (R = 1 mm, rho = 2500, nu = 0.3, e_n = 0.5, Mindlin friction mu = 0.5,
e_t = 0.5) in a vertical cylinder with a floor (`fix demcontact/wall`, the same model), Hertz from
E (`hertz/material`), velocity Verlet (`fix nve/sphere`), one rank. t_H is the elastic duration
of a sphere-sphere impact at v_ref, 2.868 (m*^2 / (R* E*^2 v_ref))^(1/5), m* = m/2, R* = R/2,
E* = E / (2 (1 - nu^2)).

Part `bed` (E = 5e6 Pa, v_ref = 0.3 m/s): a jittered simple-cubic lattice (2.2 mm spacing; 2000
spheres, --smoke 450) settles under gravity for 0.25 s (smoke 0.12 s) at dt = t_H/20, plain and
with `step_exact`; from the final dump: mean and largest overlap of every sphere-sphere and
sphere-wall contact, contacts per sphere, kinetic energy (thermo). Then the plain settled bed
(write_data) runs on at dt = dc_dt_crit (p = 3/2, v_ref, omega0 = sqrt(k/m*), k = (4/3) E* sqrt(R*),
from the library through --lib), t_H/5 and t_H/10 (smoke: dc_dt_crit only) for 2000 steps
(smoke 500), plain and step_exact: stable when no atom is lost and the kinetic energy stays below
1e-3 of m g R per sphere.
Check (--check): step_exact's mean overlap within 2 % of plain's, its largest within 10 %, its
kinetic energy after settling below 1e-3 m g R per sphere, as plain's; at each larger step,
stable exactly when plain is.

Part `pour` (E = 1e6 Pa, v_ref = 0.7 m/s, about the impact speed of the rain): 200 spheres
(--smoke 60) on a jittered lattice (2.6 mm spacing) in a 8 mm cylinder, random initial velocities
(+-0.05 m/s), fall and settle for 0.25 s: plain at t_H/400, t_H/200 and t_H/20, step_exact at
t_H/20, one run per seed (jitter and velocities); from the final dump: solid fraction in the
window r < 6 mm, 2 mm < z < 6 mm, and the bed height (mean z of the centres). Table: mean and
standard deviation over the seeds, and the seed-by-seed mean difference of step_exact t_H/20
and plain t_H/20 from plain t_H/200, next to plain t_H/200 against plain t_H/400.
Exit 77 (ctest SKIP) when LAMMPS is not installed.
"""
import argparse
import ctypes
import math
import os
import random
import tempfile

import harness as H

R, RHO, NU, E_N, MU, E_T = 1.0e-3, 2500.0, 0.3, 0.5, 0.5, 0.5
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
G = 9.81


def t_h(E, v):
    m_s, r_s, e_s = MASS / 2, R / 2, E / (2 * (1 - NU * NU))
    return 2.868265699 * (m_s * m_s / (r_s * e_s * e_s * v)) ** 0.2


def dt_crit(lib, E, v):
    """dc_dt_crit(p = 3/2, v, omega0) of the sphere-sphere contact, from the library."""
    dc = ctypes.CDLL(lib)
    dc.dc_dt_crit.argtypes = [ctypes.c_double] * 3 + [ctypes.POINTER(ctypes.c_double)]
    dc.dc_dt_crit.restype = ctypes.c_int32
    e_s = E / (2 * (1 - NU * NU))
    k = 4.0 / 3.0 * e_s * math.sqrt(R / 2)
    out = ctypes.c_double(0.0)
    s = dc.dc_dt_crit(1.5, v, math.sqrt(k / (MASS / 2)), ctypes.byref(out))
    if s != 0:
        raise SystemExit("dc_dt_crit failed with status %d" % s)
    return out.value


def model(E, step):
    c = "hertz/material %g %g %g tangential mindlin NULL %g %g" % (E, E_N, NU, E_T, MU)
    return c + (" step_exact" if step else "")


def head(plugin, E, step, dt, rc, box):
    m = model(E, step)
    return ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes"] + box + [
        "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact", "pair_coeff * * " + m,
        "neighbor 0.0004 bin", "neigh_modify delay 0", "timestep %.17g" % dt,
        "fix gravi all gravity %g vector 0 0 -1" % G, "fix integr all nve/sphere",
        "fix wf all demcontact/wall %s zplane 0 NULL" % m,
        "fix wc all demcontact/wall %s zcylinder %.17g" % (m, rc)]


def lattice_deck(plugin, E, step, dt, steps, rc, spacing, layers, seed, vjit):
    top = (layers + 2) * spacing + 0.01
    b = rc + 0.001
    L = head(plugin, E, step, dt, rc, ["region box block %g %g %g %g 0 %g units box" % (-b, b, -b, b, top),
                                       "create_box 1 box"])
    L += ["lattice sc %g" % spacing,
          "region fill cylinder z 0 0 %.17g %.17g %.17g units box"
          % (rc - 0.6 * spacing, 0.5 * spacing, (layers + 0.5) * spacing),
          "create_atoms 1 region fill",
          "set group all diameter %g density %g" % (2 * R, RHO),
          "displace_atoms all random %g %g %g %d" % (0.1 * (spacing - 2 * R), 0.1 * (spacing - 2 * R),
                                                      0.1 * (spacing - 2 * R), seed)]
    if vjit > 0:
        L.append("variable vx atom %g*(2*random(0,1,%d)-1)" % (vjit, seed + 1))
        L.append("variable vy atom %g*(2*random(0,1,%d)-1)" % (vjit, seed + 2))
        L.append("variable vz atom %g*(2*random(0,1,%d)-1)" % (vjit, seed + 3))
        L.append("velocity all set v_vx v_vy v_vz")
    L += ["compute ke all ke", "thermo_style custom step atoms c_ke", "thermo_modify lost error norm no",
          "thermo %d" % max(steps // 10, 1), "run %d" % steps,
          "write_dump all custom final.dump id x y z vx vy vz modify format float %.17g",
          "write_data settled.data"]
    return "\n".join(L) + "\n"


def rerun_deck(plugin, E, step, dt, steps, rc, data):
    """The settled bed run on at `dt`; lost atoms are counted (an unstable run loses them)."""
    L = head(plugin, E, step, dt, rc, ["read_data %s" % data])
    L += ["compute ke all ke", "thermo_style custom step atoms c_ke", "thermo_modify lost ignore norm no",
          "thermo %d" % max(steps // 10, 1), "run %d" % steps,
          "write_dump all custom final.dump id x y z vx vy vz modify format float %.17g"]
    return "\n".join(L) + "\n"


def run(exe, d, deck):
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.deck"), "w").write(deck)
    H.run([exe, "-in", "in.deck", "-log", "log.lammps"], d, H.mpi_env())
    ke = None
    for line in open(os.path.join(d, "log.lammps")):
        f = line.split()
        if len(f) == 3 and f[0].isdigit():
            ke = float(f[2])
    pos = H.read_last_dump(os.path.join(d, "final.dump"))
    return ke, [(float(v["x"]), float(v["y"]), float(v["z"])) for v in pos.values()]


def overlaps(xs, rc):
    """Overlaps of every sphere-sphere, sphere-floor and sphere-cylinder contact (cell list)."""
    cell = 2 * R
    grid = {}
    for i, (x, y, z) in enumerate(xs):
        grid.setdefault((int(math.floor(x / cell)), int(math.floor(y / cell)), int(math.floor(z / cell))), []).append(i)
    out = []
    for (cx, cy, cz), members in grid.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((cx + dx, cy + dy, cz + dz), ()):
                        for i in members:
                            if i < j:
                                d = math.dist(xs[i], xs[j])
                                if d < 2 * R:
                                    out.append(2 * R - d)
    for (x, y, z) in xs:
        if z < R:
            out.append(R - z)
        rr = math.hypot(x, y)
        if rr > rc - R:
            out.append(rr - (rc - R))
    return out


def bed(a, exe, workdir):
    E, v = 5e6, 0.3
    layers = 4 if a.smoke else 9
    rc = 0.020 if not a.smoke else 0.020
    dt = t_h(E, v) / 20
    t_end = 0.12 if a.smoke else 0.25
    steps = int(round(t_end / dt))
    if a.smoke:
        layers = 2
    ke_limit = 1e-3 * MASS * G * R
    res = {}
    for step in (False, True):
        name = "step_exact" if step else "plain"
        ke, xs = run(exe, os.path.join(workdir, "bed_" + name),
                     lattice_deck(a.plugin, E, step, dt, steps, rc, 0.0022, layers, 15485863, 0.0))
        ov = overlaps(xs, rc)
        res[name] = dict(n=len(xs), ke=ke, mean=sum(ov) / len(ov), max=max(ov), z=2.0 * len(ov) / len(xs))
    dtc = dt_crit(a.lib, E, v)
    data = os.path.join(workdir, "bed_plain", "settled.data")
    csteps = 500 if a.smoke else 2000
    steps_at = [("dc_dt_crit", dtc)] + ([] if a.smoke else [("t_H/5", t_h(E, v) / 5), ("t_H/10", t_h(E, v) / 10)])
    crit = {}
    for tag, dtx in steps_at:
        for step in (False, True):
            name = "step_exact" if step else "plain"
            d = os.path.join(workdir, "crit_%s_%s" % (tag.replace("/", ""), name))
            ke, xs = run(exe, d, rerun_deck(a.plugin, E, step, dtx, csteps, rc, data))
            ov = overlaps(xs, rc)
            crit[(tag, name)] = dict(ke=ke, max=max(ov) if ov else 0.0, n=len(xs), dt=dtx)
    n = res["plain"]["n"]
    print("## Settled bed: %d spheres, E = %g Pa, dt = t_H/20 = %.4g s, %d steps (%.3g s)" % (n, E, dt, steps, dt * steps))
    print()
    print("| variant | mean overlap / R | largest overlap / R | contacts per sphere | KE / (N m g R) |")
    print("|---|---|---|---|---|")
    for name, r in res.items():
        print("| %s | %.5f | %.5f | %.3f | %.3g |" % (name, r["mean"] / R, r["max"] / R, r["z"], r["ke"] / (n * MASS * G * R)))
    print()
    print("dc_dt_crit = %.4g s = t_H/%.2f. The plain settled bed run on for %d steps:" % (dtc, t_h(E, v) / dtc, csteps))
    print()
    print("| dt | variant | atoms kept | KE / (N m g R) | largest overlap / R |")
    print("|---|---|---|---|---|")
    for (tag, name), r in crit.items():
        print("| %s | %s | %d of %d | %.3g | %.5f |" % (tag, name, r["n"], n, r["ke"] / (n * MASS * G * R), r["max"] / R))
    print()
    bad = []
    p, s = res["plain"], res["step_exact"]
    print("step_exact / plain after settling: mean overlap %.4f, largest %.4f" % (s["mean"] / p["mean"], s["max"] / p["max"]))
    if not abs(s["mean"] / p["mean"] - 1) <= 0.02:
        bad.append("mean overlap step_exact/plain = %.4f" % (s["mean"] / p["mean"]))
    if not abs(s["max"] / p["max"] - 1) <= 0.10:
        bad.append("largest overlap step_exact/plain = %.4f" % (s["max"] / p["max"]))
    for name, r in res.items():
        if not r["ke"] < ke_limit * n:
            bad.append("%s not settled (KE %.3g J)" % (name, r["ke"]))
    stable = {key: r["n"] == n and r["ke"] < ke_limit * n for key, r in crit.items()}
    for tag, _ in steps_at:
        sp, ss = stable[(tag, "plain")], stable[(tag, "step_exact")]
        print("stable at %s: plain %s, step_exact %s" % (tag, sp, ss))
        if sp != ss:
            bad.append("stability at %s differs (plain %s, step_exact %s)" % (tag, sp, ss))
    return bad


def pour(a, exe, workdir):
    E, v = 1e6, 0.7
    th = t_h(E, v)
    rc, spacing, t_end = 0.008, 0.0026, 0.25
    layers = 3 if a.smoke else 10
    variants = [("plain t_H/400", False, 400), ("plain t_H/200", False, 200), ("plain t_H/20", False, 20),
                ("step_exact t_H/20", True, 20)]
    if a.smoke:
        variants = variants[1:]
    win = (rc - 0.002, 0.002, 0.006)
    vwin = math.pi * win[0] ** 2 * (win[2] - win[1])
    vp = 4.0 / 3.0 * math.pi * R ** 3
    out = {}
    for seed in range(a.seeds):
        for label, step, k in variants:
            dt = th / k
            d = os.path.join(workdir, "pour_s%d_%s" % (seed, label.replace(" ", "_").replace("/", "")))
            ke, xs = run(exe, d, lattice_deck(a.plugin, E, step, dt, int(round(t_end / dt)), rc, spacing, layers,
                                              1000003 + 7919 * seed, 0.05))
            inwin = sum(1 for (x, y, z) in xs if math.hypot(x, y) < win[0] and win[1] < z < win[2])
            out[(label, seed)] = (inwin * vp / vwin, sum(z for (_, _, z) in xs) / len(xs), len(xs))
    n = out[(variants[0][0], 0)][2]
    print("## Pour: %d spheres, E = %g Pa, t_H = %.4g s at %g m/s, %d seeds, %.2f s" % (n, E, th, v, a.seeds, t_end))
    print()
    print("| variant | solid fraction (mean +- sd) | bed height: mean z [mm] (mean +- sd) |")
    print("|---|---|---|")

    def ms(xs):
        m = sum(xs) / len(xs)
        sd = math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else 0.0
        return m, sd

    for label, _, _ in variants:
        phi = ms([out[(label, s)][0] for s in range(a.seeds)])
        z = ms([1e3 * out[(label, s)][1] for s in range(a.seeds)])
        print("| %s | %.4f +- %.4f | %.4f +- %.4f |" % (label, phi[0], phi[1], z[0], z[1]))
    print()
    ref = "plain t_H/200"
    print("| against plain t_H/200, same seed | solid fraction: mean diff (sd) | mean z [mm]: mean diff (sd) |")
    print("|---|---|---|")
    for label, _, _ in variants:
        if label == ref:
            continue
        dphi = ms([out[(label, s)][0] - out[(ref, s)][0] for s in range(a.seeds)])
        dz = ms([1e3 * (out[(label, s)][1] - out[(ref, s)][1]) for s in range(a.seeds)])
        print("| %s | %+.4f (%.4f) | %+.4f (%.4f) |" % (label, dphi[0], dphi[1], dz[0], dz[1]))
    print()
    bad = []
    for (label, seed), (_, _, count) in out.items():
        if count != n:
            bad.append("%s seed %d lost atoms" % (label, seed))
    return bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lib", required=True, help="libdemcontact.so (dc_dt_crit)")
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    ap.add_argument("--part", choices=["bed", "pour", "all"], default="all")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--smoke", action="store_true")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    if a.seeds < 1:
        ap.error("--seeds must be >= 1 (got %d)" % a.seeds)
    if not os.path.exists(a.lib):
        ap.error("--lib: no such file %r" % a.lib)
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_step_exact_bed_"))
    os.makedirs(workdir, exist_ok=True)
    bad = []
    if a.part in ("bed", "all"):
        bad += bed(a, exe, workdir)
    if a.part in ("pour", "all"):
        bad += pour(a, exe, workdir)
    if bad:
        print("FAILED: " + "; ".join(bad))
        if a.check:
            raise SystemExit(1)


if __name__ == "__main__":
    main()
