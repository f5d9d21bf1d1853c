"""Settling bed: N spheres (R = 1 mm, rho = 2500, E = 5e6, nu = 0.3, e = 0.5, friction 0.5) start
on a jittered simple-cubic lattice in a 44 x 44 mm box with frictional walls and settle under
gravity. Same input for demcontact and the builtin Hertz model (same `tangential history`, walls
use the same model), serial and under `mpirun -np 2`. Packing statistics and energies come from the
simulator's thermo output, the wall time from its own "Loop time" line.

Without limitForce, demcontact's alpha (DC_END_OVERLAP) equals LIGGGHTS' Hertz damping exactly, so
the two runs integrate the same physics: any difference in the statistics is chaos, not the model.
"""
import math
import os
import re

import harness as H

HALF = 0.022        # box half width [m]
SPACING = 0.0022    # initial lattice spacing [m]
E_BED, E_REST, MU = 5e6, 0.5, 0.5
STEPS_PER_CONTACT = 50
# Statistics window: central columns, away from floor and free surface.
WIN = (-0.015, 0.015, -0.015, 0.015, 0.004, 0.010)
# Tolerances for "same packing" (serial vs MPI, demcontact vs hertz).
TOL_PHI = 0.015     # absolute, solid fraction in the window (~770 centres: +-0.004 run to run)
TOL_Z = 0.01        # relative, mean height
TOL_CN = 0.15       # absolute, mean contacts per particle


def setup(n, steps):
    """Lattice layers for at least n spheres (whole layers), time step and step count."""
    per_layer = int((2 * HALF - 2 * 1.5e-3) / SPACING) ** 2
    layers = int(math.ceil(n / per_layer))
    tc = H.hertz_contact_time(E_BED, 0.5)
    dt = tc / STEPS_PER_CONTACT
    if steps <= 0:
        steps = int(math.ceil(0.25 / dt))  # 0.25 s of settling
    return per_layer, layers, dt, steps


def deck_head(model, dt, box):
    """The input deck up to the particles, shared by the settling and the timing runs: settings,
    the `box` lines (create it, or read a data file), materials, contact model, time step, gravity
    and the five frictional walls (floor and sides) with the same model."""
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si"] + box + [
         "neighbor 0.0004 bin", "neigh_modify delay 0",
         "fix m1 all property/global youngsModulus peratomtype %g" % E_BED,
         "fix m2 all property/global poissonsRatio peratomtype %g" % H.NU,
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 %g" % E_REST,
         "fix m4 all property/global coefficientFriction peratomtypepair 1 %g" % MU,
         "pair_style gran " + model, "pair_coeff * *", "timestep %.17g" % dt,
         "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0"]
    for i, (kind, pos) in enumerate([("zplane", 0.0), ("xplane", -HALF), ("xplane", HALF),
                                     ("yplane", -HALF), ("yplane", HALF)]):
        L.append("fix w%d all wall/gran %s primitive type 1 %s %g" % (i, model, kind, pos))
    return L


def liggghts_deck(model, n, dt, steps):
    per_layer, layers, _, _ = setup(n, steps)
    side = int(math.sqrt(per_layer))
    # Lattice points sit at integer multiples of SPACING; region faces half-way between them so
    # that the count is exact: side x side columns, layers k = 1..layers (first at z = SPACING).
    lo = (-(side // 2) - 0.5) * SPACING
    z0 = 0.5 * SPACING
    thermo = max(steps // 10, 1)
    vwin = (WIN[1] - WIN[0]) * (WIN[3] - WIN[2]) * (WIN[5] - WIN[4])
    vp = 4.0 / 3.0 * math.pi * H.R ** 3
    L = deck_head(model, dt, ["region box block %g %g %g %g 0 %g units box"
                              % (-HALF, HALF, -HALF, HALF, z0 + layers * SPACING + 0.005),
                              "create_box 1 box"])
    L += ["lattice sc %g" % SPACING,
          "region fill block %g %g %g %g %g %g units box"
          % (lo, lo + side * SPACING, lo, lo + side * SPACING, z0, z0 + layers * SPACING),
          # whole layers only: which atoms a rank creates depends on the decomposition, so
          # deleting "the last ones" would make the serial and MPI inputs differ.
          "create_atoms 1 region fill",
          "set group all diameter %g density %g" % (2 * H.R, H.RHO),
          "displace_atoms all random 0.0001 0.0001 0.0001 15485863",
          "fix integr all nve/sphere",
          "compute cn all contact/atom", "compute mcn all reduce ave c_cn",
          "compute rke all erotate/sphere",
          "region win block %g %g %g %g %g %g units box" % WIN,
          "variable phi equal count(all,win)*%.17g" % (vp / vwin),
          "variable zm equal xcm(all,z)",
          "variable ztop equal bound(all,zmax)",
          "thermo_style custom step atoms ke c_rke c_mcn v_zm v_ztop v_phi",
          "thermo_modify norm no lost error",
          "thermo %d" % thermo, "run %d" % steps,
          "write_data settled.data"]
    return "\n".join(L) + "\n"


def timing_deck(model, data, dt, steps):
    """The settled bed (every sphere in contact) run on for `steps` with the given model: the
    timing comparison, free of the settling transient. Contact history starts from zero for both."""
    L = deck_head(model, dt, ["read_data %s" % data])
    L += ["fix integr all nve/sphere", "thermo %d" % steps, "run %d" % steps]
    return "\n".join(L) + "\n"


def timing(exe, env, workdir, dt, nps, reps, steps):
    """Minimum loop and pair time over `reps` alternating runs per model and rank count (the
    machine is shared: the minimum is the least disturbed run)."""
    data = os.path.join(workdir, "bed_hertz", "settled.data")
    d = os.path.join(workdir, "timing")
    os.makedirs(d, exist_ok=True)
    best = {}
    for label, model in MODELS:
        open(os.path.join(d, "in.%s" % label), "w").write(timing_deck(model, data, dt, steps))
    for np_ in nps:
        for r in range(reps):
            for label, _ in MODELS:
                log = "log.%s.np%d.%d" % (label, np_, r)
                H.run(H.mpi_prefix(np_) + [exe, "-in", "in.%s" % label, "-log", log], d, env)
                loop, _, pair = log_times(open(os.path.join(d, log)).read())
                old = best.get((label, np_), (float("inf"), float("inf")))
                best[(label, np_)] = (min(old[0], loop), min(old[1], pair))
    return best


MODELS = [("demcontact", "model demcontact tangential history"),
          ("hertz", "model hertz tangential history")]


def parse_log(text):
    cols, last = None, None
    for line in text.splitlines():
        f = line.split()
        if f[:2] == ["Step", "Atoms"]:  # thermo_style custom step atoms ke c_rke c_mcn v_zm v_ztop v_phi
            cols = ["step", "Atoms", "KinEng", "c_rke", "c_mcn", "v_zm", "v_ztop", "v_phi"]
        elif cols and len(f) == len(cols) and re.match(r"^\d+$", f[0]):
            last = dict(zip(cols, map(float, f)))
    loop, procs, last["pair_time"] = log_times(text)
    return last, loop, procs


def log_times(text):
    """Loop wall time [s], rank count and pair time [s] from the simulator's own log."""
    loop = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs", text)
    pair = re.search(r"Pair  time \(%\) = ([0-9.eE+-]+)", text)
    return float(loop.group(1)), int(loop.group(2)), float(pair.group(1))


def main(a, workdir):
    if a.sim != "liggghts":
        raise SystemExit("bed: only --sim liggghts")
    exe, env = H.liggghts_cmd(a.plugin)
    if a.smoke:
        a.n, a.steps = 1000, 3000
    per_layer, layers, dt, steps = setup(a.n, a.steps)
    a.n = per_layer * layers
    nps = [1] + ([a.np] if a.np > 1 else [])
    rows = {}
    for label, model in MODELS:
        d = os.path.join(workdir, "bed_" + label)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.bed"), "w").write(liggghts_deck(model, a.n, dt, steps))
        for np_ in nps:
            log = os.path.join(d, "log.np%d" % np_)
            done = os.path.exists(log) and "Loop time" in open(log).read() and \
                os.path.exists(os.path.join(d, "settled.data"))
            if not (a.resume and done):
                H.run(H.mpi_prefix(np_) + [exe, "-in", "in.bed", "-log", "log.np%d" % np_], d, env)
            rows[(label, np_)] = parse_log(open(os.path.join(d, "log.np%d" % np_)).read())
    print("## liggghts settling bed: %d spheres, dt = %.3g s, %d steps (%.3g s), thermo output"
          % (a.n, dt, steps, dt * steps))
    print()
    print("| model | ranks | atoms | KE [J] | rot KE [J] | mean contacts | mean z [mm] | top z [mm] | solid fraction | loop time [s] | pair time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for (label, np_), (t, loop, procs) in rows.items():
        print("| %s | %d | %d | %.3g | %.3g | %.3f | %.3f | %.3f | %.4f | %.2f | %.2f |"
              % (label, procs, t["Atoms"], t["KinEng"], t["c_rke"], t["c_mcn"], 1e3 * t["v_zm"],
                 1e3 * t["v_ztop"], t["v_phi"], loop, t["pair_time"]))
    print()
    ref = rows[("hertz", 1)][0]
    ok = True
    for key, (t, loop, procs) in rows.items():
        bad = []
        if t["Atoms"] != a.n:
            bad.append("atoms")
        if not abs(t["v_phi"] - ref["v_phi"]) <= TOL_PHI:
            bad.append("solid fraction")
        if not abs(t["v_zm"] / ref["v_zm"] - 1) <= TOL_Z:
            bad.append("mean z")
        if not abs(t["c_mcn"] - ref["c_mcn"]) <= TOL_CN:
            bad.append("contacts")
        # settled: kinetic energy far below the potential energy released (order m g h N)
        if not a.smoke and not (t["KinEng"] < 1e-3 * a.n * H.RHO * 4.19e-9 * 9.81 * 0.01):
            bad.append("not settled")
        if bad:
            ok = False
            print("MISMATCH %s np=%d vs hertz serial: %s" % (key[0], key[1], ", ".join(bad)))
    for np_ in nps:
        ours, ref_ = rows[("demcontact", np_)], rows[("hertz", np_)]
        print("settling runs, wall-time ratio demcontact / hertz (%d rank%s): loop %.3f, pair %.3f"
              % (np_, "s" if np_ > 1 else "", ours[1] / ref_[1], ours[0]["pair_time"] / ref_[0]["pair_time"]))
    reps, tsteps = (1, 200) if a.smoke else (3, 2000)
    best = timing(exe, env, workdir, dt, nps, reps, tsteps)
    print()
    print("Timing on the settled bed (%d steps, tangential history, walls with the same model; "
          "minimum of %d alternating runs):" % (tsteps, reps))
    print()
    print("| ranks | demcontact loop [s] | hertz loop [s] | ratio loop | demcontact pair [s] | hertz pair [s] | ratio pair |")
    print("|---|---|---|---|---|---|---|")
    for np_ in nps:
        o, h = best[("demcontact", np_)], best[("hertz", np_)]
        print("| %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |" % (np_, o[0], h[0], o[0] / h[0], o[1], h[1], o[1] / h[1]))
    print()
    print("tolerances vs hertz serial: solid fraction +-%g, mean z +-%g%%, mean contacts +-%g"
          % (TOL_PHI, 100 * TOL_Z, TOL_CN))
    if a.check and not ok:
        raise SystemExit("FAIL: packing statistics differ beyond tolerance")


if __name__ == "__main__":
    main(*H.arguments("bed", __doc__.splitlines()[0]))
