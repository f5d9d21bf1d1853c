#!/usr/bin/env python3
"""Pour and settle: polydisperse frictional spheres with rolling resistance poured into a cylinder,
in LIGGGHTS and LAMMPS, demcontact against each code's builtin Hertz-Mindlin, serial and 2 ranks.

  scenes.py --sim lammps   --plugin demcontactplugin.so      [--lmp lmp] [--np 2] [--check] [--smoke]
  scenes.py --sim liggghts --plugin libdemcontact_liggghts.so [--np 2] [--check] [--smoke]
            [--reps 3] [--pour-reps 3] [--resume] [--workdir DIR]

Scene (both codes, both models): N spheres (2000; --smoke 300), radius 1.0-1.5 mm (ratio 1.5; LAMMPS
fix pour: uniform in diameter; LIGGGHTS insert/pack: five discrete radii, equal mass fractions),
rho = 2500, E = 5e6 Pa, nu = 0.3, e = 0.5, friction mu = 0.5, rolling resistance mu_r = 0.1,
inserted as a loose cloud (volume fraction 0.1) above a flat floor inside a vertical cylinder
(radius 20 mm; smoke 10 mm)
whose floor and side are walls with the same contact model; gravity; dt = 5e-6 s (about 1/45 of
the shortest Hertz contact at the impact speeds); 0.45 s (smoke 0.35 s). `processors * 1 1`: the
rank boundary x = 0 cuts the bed through its axis, so contacts, and atoms, cross it all the time.

Measured from the code's own dump of the final state: atoms kept (lost atoms are an error),
solid fraction in a central window (centre-in-window sphere volumes / window volume; window:
r < R - 4 mm, 4 mm < z < 0.7 x the bed height estimated at phi = 0.6), mean coordination number
(compute contact/atom) inside the window and over all atoms, mean height of the centres, kinetic
energy; wall time from the code's "Loop time". Timing: the settled bed of the builtin run
(write_data) run on for 2000 steps with each model, alternately, three times; minimum kept; also the
CPU time of the run minus that of the same deck with `run 0` (less sensitive to other jobs on a
shared machine than the wall time). --pour-reps N: the whole pour/settle timed too, each model's
settling deck run again N times per rank count, the models alternating; minimum loop time.

Models:
  LIGGGHTS builtin   pair_style gran model hertz tangential history rolling_friction cdt
  LIGGGHTS ours      pair_style gran model demcontact tangential demcontact rolling_friction demcontact
                     surface demcontact tangentialRestitution 0.5 rollingConstant on
                     (constant rolling torque, as cdt; `surface demcontact`: LIGGGHTS' relative
                     velocities, which demcontact does not read, not computed; --check runs 100 steps
                     of the settled bed with it and with `surface default` and requires the same
                     dump, bit for bit)
  LAMMPS builtin     pair_style granular, hertz/material E e nu tangential mindlin NULL 1.0 mu
                     rolling sds 3.0 0 mu_r damping coeff_restitution (+ fix wall/gran granular)
  LAMMPS ours        pair_style demcontact, hertz/material E e nu tangential mindlin NULL 0.5 mu
                     rolling sds NULL 0 mu_r (EPSD, Ai's stiffness rule) (+ fix demcontact/wall)
  *_project          ours with the builtin's frame carry of the history springs (projection and
                     rescale): LAMMPS `carry project`, LIGGGHTS `projectionCarry on`
The tangential damping differs in form (builtin: the normal damping coefficient; ours: e_t = 0.5
calibrated in the sticking regime), so "same input" means same materials, e, mu, mu_r.
Exit 77 (ctest SKIP) when the simulator is not installed.
"""
import argparse
import math
import os
import re
import resource
import tempfile

import harness as H

RHO, E, NU, REST, MU, MU_R = 2500.0, 5e6, 0.3, 0.5, 0.5, 0.1
RMIN, RMAX = 1.0e-3, 1.5e-3
DT = 5e-6
# Tolerances of "same packing" against the builtin model, serial (the scene is chaotic: two runs
# of one model on 1 and 2 ranks differ by as much as two models; see docs/simulators.md).
TOL_PHI = 0.02      # absolute solid fraction in the window
TOL_Z = 0.03        # relative mean height of the centres
TOL_CN = 0.35       # absolute mean coordination number in the window
# --smoke (300 spheres, ~120 in the window): statistical noise is larger, tolerances too
SMOKE_TOL = dict(phi=0.08, z=0.05, cn=0.6)
FRICTIONLESS = False  # True: LAMMPS runs without friction/rolling (both models)
E_T = 0.5            # ours: tangential restitution in the sticking regime (= e_n)
K_ROLL = 3.0         # LAMMPS builtin sds rolling stiffness [N/m] ~ Ai's rule 2.25 k_n mu_r^2 at k_n ~ 135 N/m


def geometry(smoke):
    n = 300 if smoke else 2000
    rc = 0.010 if smoke else 0.020
    t_end = 0.35 if smoke else 0.45
    # mean sphere volume, radius uniform in diameter on [RMIN, RMAX]: E[r^3] = (b^4 - a^4)/(4 (b - a))
    v_mean = 4.0 / 3.0 * math.pi * (RMAX ** 4 - RMIN ** 4) / (4 * (RMAX - RMIN))
    h_bed = n * v_mean / (0.6 * math.pi * rc * rc)
    r_ins = rc - 1.1 * RMAX
    # the insertion cylinder holds the whole cloud at volume fraction 0.1 (one insertion)
    z0 = h_bed + 0.01
    z1 = z0 + n * v_mean / (0.1 * math.pi * r_ins * r_ins)
    return dict(n=n, rc=rc, r_ins=r_ins, z0=z0, z1=z1, top=z1 + 0.01, h_bed=h_bed,
                steps=int(round(t_end / DT)),
                # smoke: a wider window (~120 centres instead of ~45) to keep the noise below tolerance
                win=(rc - 0.002, 0.0025, 0.8 * h_bed) if smoke else (rc - 0.004, 0.004, 0.7 * h_bed))


# ------------------------------------------------------------------ LAMMPS
def lammps_models():
    c = "hertz/material %g %g %g" % (E, REST, NU)
    ours = " tangential mindlin NULL %g %g rolling sds NULL 0 %g" % (E_T, MU, MU_R)
    fric = " tangential mindlin NULL 1.0 %g rolling sds %g %g %g" % (MU, K_ROLL, 0.0, MU_R)
    if FRICTIONLESS:
        return [("demcontact", "demcontact", c, "demcontact/wall " + c),
                ("granular", "granular", c + " tangential linear_nohistory 0 0 damping coeff_restitution",
                 "wall/gran granular " + c + " tangential linear_nohistory 0 0 damping coeff_restitution")]
    proj = ours + " carry project"
    return [("demcontact", "demcontact", c + ours, "demcontact/wall " + c + ours),
            ("granular", "granular", c + fric + " damping coeff_restitution",
             "wall/gran granular " + c + fric + " damping coeff_restitution"),
            # ours with the builtin's frame carry (projection and rescale of the history springs)
            ("demcontact_project", "demcontact", c + proj, "demcontact/wall " + c + proj)]


def lammps_head(plugin, style, coeff, wall, g, box):
    L = ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes", "processors * 1 1"]
    L += box
    L += ["plugin load %s" % os.path.abspath(plugin), "pair_style " + style, "pair_coeff * * " + coeff,
          "neighbor 0.0005 bin", "neigh_modify delay 0", "timestep %.17g" % DT,
          "fix gravi all gravity 9.81 vector 0 0 -1", "fix integr all nve/sphere",
          "fix wf all %s zplane 0 NULL" % wall, "fix wc all %s zcylinder %.17g" % (wall, g["rc"])]
    return L


def lammps_deck(plugin, style, coeff, wall, g):
    b = g["rc"] + 0.001
    L = lammps_head(plugin, style, coeff, wall, g,
                    ["region box block %g %g %g %g 0 %g units box" % (-b, b, -b, b, g["top"]), "create_box 1 box"])
    L += ["region ins cylinder z 0 0 %.17g %.17g %.17g units box" % (g["r_ins"], g["z0"], g["z1"]),
          "fix ins all pour %d 1 4767548 region ins diam range %g %g dens %g %g vol 0.1 200"
          % (g["n"], 2 * RMIN, 2 * RMAX, RHO, RHO),
          # c_cns in the thermo output keeps c_cn current on the last step: write_dump of the
          # 2022 releases refuses a compute not invoked on it
          "compute cn all contact/atom", "compute cns all reduce sum c_cn", "compute ke all ke",
          "thermo_style custom step atoms c_ke c_cns", "thermo_modify lost error norm no",
          "thermo %d" % (g["steps"] // 10), "run %d" % g["steps"],
          "write_dump all custom final.dump id type radius x y z vx vy vz c_cn modify format float %.17g",
          "write_data settled.data"]
    return "\n".join(L) + "\n"


def lammps_timing_deck(plugin, style, coeff, wall, g, data, steps):
    L = lammps_head(plugin, style, coeff, wall, g, ["read_data %s" % data])
    L += ["thermo %d" % steps, "run %d" % steps]
    return "\n".join(L) + "\n"


# ------------------------------------------------------------------ LIGGGHTS
LIGGGHTS_OURS = "model demcontact tangential demcontact rolling_friction demcontact surface demcontact"


def liggghts_surface_default(model):
    """The same model line with LIGGGHTS' `surface default` (the plugin before `surface demcontact`)."""
    return model.replace(" surface demcontact", "")


def liggghts_models():
    # (label, model, settings): a wall/gran takes the settings after its wall definition
    return [("demcontact", LIGGGHTS_OURS, "tangentialRestitution %g rollingConstant on" % E_T),
            ("hertz", "model hertz tangential history rolling_friction cdt", ""),
            # ours with the builtin's frame carry (projection and rescale of the tangential spring)
            ("demcontact_project", LIGGGHTS_OURS,
             "tangentialRestitution %g rollingConstant on projectionCarry on" % E_T)]


def cpu_is_x86_64_v4():
    """Whether this CPU has the x86-64-v4 level's AVX-512 subsets (Linux: /proc/cpuinfo), where the
    plugin (a build with run-time dispatch) must run its x86-64-v4 contact body."""
    try:
        flags = next(l for l in open("/proc/cpuinfo") if l.startswith("flags")).split()
    except (OSError, StopIteration):
        return False
    return all(f in flags for f in ("avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"))


def liggghts_surface_identity(exe, env, mpirun, nps, g, data, workdir, steps=100):
    """Our models with `surface demcontact` and with `surface default` from the same settled bed,
    and with the plugin's run-time dispatch forced to its baseline variants
    (DEMCONTACT_DISPATCH=baseline, plugins/common/cpu_dispatch.h): the final dumps (positions,
    velocities, forces, torques, %.17g) must be the same bytes. Returns the list of mismatches
    (empty: identical)."""
    bad = []
    d = os.path.join(workdir, "surface_identity")
    os.makedirs(d, exist_ok=True)
    # the dispatched runs without the variable (a caller's own setting would make them baseline)
    env = {k: v for k, v in env.items() if k != "DEMCONTACT_DISPATCH"}
    base_env = dict(env, DEMCONTACT_DISPATCH="baseline")
    v4_cpu = cpu_is_x86_64_v4()
    for label, model, settings in liggghts_models():
        if "surface demcontact" not in model:
            continue
        for np_ in nps:
            dumps, bodies = [], []
            for run, mo, e in (("demcontact", model, env), ("default", liggghts_surface_default(model), env),
                               ("baseline", model, base_env)):
                name = "%s_%s_np%d" % (label, run, np_)
                # the timing deck, then the final state dumped (LIGGGHTS' dump_modify takes a whole
                # line's format, no `format float`)
                L = ["dump fin all custom 1 %s.dump id x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz"
                     % name, "dump_modify fin sort id format \"%d" + " %.17g" * 15 + "\"", "run 0"]
                open(os.path.join(d, "in.%s" % name), "w").write(
                    liggghts_timing_deck(mo, settings, g, data, steps) + "\n".join(L) + "\n")
                H.run(H.mpi_prefix(np_, mpirun, ("DEMCONTACT_DISPATCH",) if "DEMCONTACT_DISPATCH" in e else ())
                      + [exe, "-in", "in.%s" % name, "-log", "log.%s" % name], d, e)
                dumps.append(open(os.path.join(d, "%s.dump" % name), "rb").read())
                said = re.findall(r"demcontact: contact body compiled for ([^\n]*)",
                                  open(os.path.join(d, "log.%s" % name)).read())
                bodies.append(said[0] if said else "?")
            n = dumps[0].count(b"\n") - 9  # the dump's 9 header lines
            if n != g["n"]:
                bad.append("%s np=%d: %d atoms in the dump, not %d" % (label, np_, n, g["n"]))
            elif dumps[0] != dumps[1]:
                bad.append("%s np=%d: surface demcontact and surface default differ" % (label, np_))
            elif "?" in bodies:
                bad.append("%s np=%d: a run did not say which contact body it ran" % (label, np_))
            elif dumps[0] != dumps[2]:
                bad.append("%s np=%d: the contact body of %s and the baseline one differ" % (label, np_, bodies[0]))
            elif not bodies[2].startswith(("the baseline", "the build's target")):
                bad.append("%s np=%d: DEMCONTACT_DISPATCH=baseline ran the body of %s" % (label, np_, bodies[2]))
            elif v4_cpu and bodies[0].startswith("the baseline"):
                bad.append("%s np=%d: this CPU is x86-64-v4 but the plugin ran %s" % (label, np_, bodies[0]))
            else:
                print("surface identity %s np=%d: %d atoms, %d steps: same dump bytes" % (label, np_, n, steps))
                print("dispatch identity %s np=%d: contact body for %s vs the baseline: same dump bytes%s"
                      % (label, np_, bodies[0], "" if bodies[0] != bodies[2] else
                         " (this CPU or build runs the baseline only: nothing else to compare)"))
    return bad


def liggghts_head(model, settings, g, box):
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si", "processors * 1 1"] + box + [
        "neighbor 0.0005 bin", "neigh_modify delay 0",
        "fix m1 all property/global youngsModulus peratomtype %g" % E,
        "fix m2 all property/global poissonsRatio peratomtype %g" % NU,
        "fix m3 all property/global coefficientRestitution peratomtypepair 1 %g" % REST,
        "fix m4 all property/global coefficientFriction peratomtypepair 1 %g" % MU,
        "fix m5 all property/global coefficientRollingFriction peratomtypepair 1 %g" % MU_R,
        ("pair_style gran %s %s" % (model, settings)).strip(), "pair_coeff * *", "timestep %.17g" % DT,
        "fix gravi all gravity 9.81 vector 0.0 0.0 -1.0",
        ("fix wf all wall/gran %s primitive type 1 zplane 0.0 %s" % (model, settings)).strip(),
        ("fix wc all wall/gran %s primitive type 1 zcylinder %.17g 0 0 %s" % (model, g["rc"], settings)).strip(),
        "fix integr all nve/sphere"]
    return L


def liggghts_deck(model, settings, g):
    b = g["rc"] + 0.001
    L = liggghts_head(model, settings, g, ["region box block %g %g %g %g 0 %g units box" % (-b, b, -b, b, g["top"]),
                                 "create_box 1 box"])
    primes = [15485863, 15485867, 32452843, 32452867, 49979687]
    radii = [RMIN + k * (RMAX - RMIN) / 4 for k in range(5)]
    for k, r in enumerate(radii):
        L.append("fix pts%d all particletemplate/sphere %d atom_type 1 density constant %g radius constant %.17g"
                 % (k, primes[k], RHO, r))
    L.append("fix pdd all particledistribution/discrete 67867967 5 " + " ".join("pts%d 0.2" % k for k in range(5)))
    L += ["region ins cylinder z 0 0 %.17g %.17g %.17g units box" % (g["r_ins"], g["z0"], g["z1"]),
          "fix ins all insert/pack seed 86028121 distributiontemplate pdd maxattempt 200 insert_every once "
          "overlapcheck yes all_in yes vel constant 0 0 0 region ins particles_in_region %d" % g["n"],
          "compute cn all contact/atom", "compute ke all ke",
          "thermo_style custom step atoms c_ke", "thermo_modify lost error norm no",
          "thermo %d" % (g["steps"] // 10), "run %d" % g["steps"],
          "dump fin all custom 1 final.dump id type radius x y z vx vy vz c_cn",
          "run 0", "undump fin", "write_data settled.data"]
    return "\n".join(L) + "\n"


def liggghts_timing_deck(model, settings, g, data, steps):
    L = liggghts_head(model, settings, g, ["read_data %s" % data])
    L += ["thermo %d" % steps, "run %d" % steps]
    return "\n".join(L) + "\n"


# ------------------------------------------------------------------ analysis
def stats(dump, g):
    atoms = H.read_last_dump(dump)
    rw, zlo, zhi = g["win"]
    vwin = math.pi * rw * rw * (zhi - zlo)
    vin, cn_in, n_in, cn_all, zsum, ke = 0.0, 0.0, 0, 0.0, 0.0, 0.0
    for f in atoms.values():
        r, x, y, z = (float(f[k]) for k in ("radius", "x", "y", "z"))
        cn = float(f["c_cn"])
        m = RHO * 4.0 / 3.0 * math.pi * r ** 3
        ke += 0.5 * m * sum(float(f[k]) ** 2 for k in ("vx", "vy", "vz"))
        cn_all += cn
        zsum += z
        if x * x + y * y < rw * rw and zlo < z < zhi:
            vin += 4.0 / 3.0 * math.pi * r ** 3
            cn_in += cn
            n_in += 1
    n = len(atoms)
    return dict(atoms=n, phi=vin / vwin, cn_win=cn_in / max(n_in, 1), cn_all=cn_all / max(n, 1),
                zmean=zsum / max(n, 1), ke=ke, n_win=n_in)


def child_cpu():
    """user + sys CPU seconds of all finished child processes (and theirs) so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def loop_time(log):
    m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs", open(log).read())
    return float(m.group(1))


def pour_timing(models, nps, reps, mpirun, exe, env, workdir, ref_label):
    """Wall time of the whole pour/settle (the settling decks as run above), the models alternating
    (builtin, ours, ours with the projection, builtin, ...) `reps` times per rank count; minimum of
    the loop times, and its ratio to the builtin's."""
    best = {}
    for np_ in nps:
        for r in range(reps):
            for label, deck, _ in models:
                d = os.path.join(workdir, "pour_timing", "%s_np%d_%d" % (label, np_, r))
                os.makedirs(d, exist_ok=True)
                open(os.path.join(d, "in.scene"), "w").write(deck)
                H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.scene", "-log", "log.scene"], d, env)
                t = loop_time(os.path.join(d, "log.scene"))
                best[(label, np_)] = min(best.get((label, np_), float("inf")), t)
    load = open("/proc/loadavg").read().split()[:3] if os.path.exists("/proc/loadavg") else ["?"] * 3
    print()
    print("Wall time of the whole pour/settle, minimum of %d alternating runs (load average at the end: %s):"
          % (reps, " ".join(load)))
    print()
    print("| model | ranks | loop [s] | %s loop [s] | ratio |" % ref_label)
    print("|---|---|---|---|---|")
    for np_ in nps:
        for label, _, _ in models:
            if label != ref_label:
                o, h = best[(label, np_)], best[(ref_label, np_)]
                print("| %s | %d | %.2f | %.2f | %.3f |" % (label, np_, o, h, o / h))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", choices=["liggghts", "lammps"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--smoke", action="store_true")
    ap.add_argument("--reps", type=int, default=3, help="timing: alternating runs per model (0: none)")
    ap.add_argument("--workdir")
    ap.add_argument("--resume", action="store_true",
                    help="keep the settling runs already complete in --workdir (rerun only the rest)")
    ap.add_argument("--pour-reps", type=int, default=0,
                    help="time the whole pour/settle: the settling decks again, the models alternating, "
                         "this many times for each rank count; minimum loop time (0: none)")
    a = ap.parse_args()
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_scene_"))
    g = geometry(a.smoke)
    if a.sim == "lammps":
        from harness import lammps as lammps_runs
        exe = lammps_runs.find_lmp(a.lmp)
        env = H.mpi_env()
        mpirun = os.path.join(os.path.dirname(exe), "mpirun")
        models = [(lab, lammps_deck(a.plugin, st, co, wa, g),
                   lambda data, steps, st=st, co=co, wa=wa: lammps_timing_deck(a.plugin, st, co, wa, g, data, steps))
                  for lab, st, co, wa in lammps_models()]
        ref_label = "granular"
    else:
        exe, env = H.liggghts_cmd(a.plugin)
        mpirun = "mpirun"
        models = [(lab, liggghts_deck(mo, se, g),
                   lambda data, steps, mo=mo, se=se: liggghts_timing_deck(mo, se, g, data, steps))
                  for lab, mo, se in liggghts_models()]
        ref_label = "hertz"
    nps = [1] + ([a.np] if a.np > 1 else [])
    rows = {}
    for label, deck, _ in list(models):
        for np_ in nps:
            d = os.path.join(workdir, "%s_np%d" % (label, np_))
            os.makedirs(d, exist_ok=True)
            log = os.path.join(d, "log.scene")
            done = os.path.exists(log) and "Loop time" in open(log).read() and \
                os.path.exists(os.path.join(d, "final.dump")) and open(os.path.join(d, "in.scene")).read() == deck
            if not (a.resume and done):
                open(os.path.join(d, "in.scene"), "w").write(deck)
                try:
                    H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.scene", "-log", "log.scene"], d, env)
                except SystemExit:
                    # an older LAMMPS without the builtin reference model (pair granular's damping
                    # coeff_restitution: 2024 releases on): demcontact serial is the reference
                    why = a.sim == "lammps" and label == ref_label and lammps_runs.builtin_unavailable(
                        d, False, "log.scene")
                    if not why:
                        raise
                    print("REFERENCE UNAVAILABLE: %s left out (this LAMMPS: %s); reference: demcontact serial"
                          % (label, why))
                    models = [m for m in models if m[0] != label]
                    ref_label = "demcontact"
                    break
            s = stats(os.path.join(d, "final.dump"), g)
            s["loop"] = loop_time(os.path.join(d, "log.scene"))
            rows[(label, np_)] = s
    print("## %s pour/settle: %d spheres, r %.1f-%.1f mm, cylinder R = %.0f mm, dt = %g s, %d steps"
          % (a.sim, g["n"], 1e3 * RMIN, 1e3 * RMAX, 1e3 * g["rc"], DT, g["steps"]))
    print()
    print("| model | ranks | atoms | solid fraction (window) | coordination (window) | coordination (all) "
          "| mean z [mm] | KE [J] | loop time [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (label, np_), s in rows.items():
        print("| %s | %d | %d | %.4f | %.3f | %.3f | %.3f | %.3g | %.2f |" % (
            label, np_, s["atoms"], s["phi"], s["cn_win"], s["cn_all"], 1e3 * s["zmean"], s["ke"], s["loop"]))
    print()
    ref = rows[(ref_label, 1)]
    tol_phi, tol_z, tol_cn = (SMOKE_TOL["phi"], SMOKE_TOL["z"], SMOKE_TOL["cn"]) if a.smoke else (TOL_PHI, TOL_Z, TOL_CN)
    ok = True
    for (label, np_), s in rows.items():
        bad = []
        if s["atoms"] != g["n"]:
            bad.append("atoms %d != %d" % (s["atoms"], g["n"]))
        # settled: KE below 1 % of the potential energy released by the fall (no explosion, no
        # bed still flying; a frictionless bed keeps sloshing at ~1e-3 of it)
        m_mean = RHO * 4.0 / 3.0 * math.pi * (RMAX ** 4 - RMIN ** 4) / (4 * (RMAX - RMIN))
        if not s["ke"] < 1e-2 * g["n"] * m_mean * 9.81 * (0.5 * (g["z0"] + g["z1"]) - 0.5 * g["h_bed"]):
            bad.append("not settled (KE %.3g J)" % s["ke"])
        if not abs(s["phi"] - ref["phi"]) <= tol_phi:
            bad.append("solid fraction")
        if not abs(s["zmean"] / ref["zmean"] - 1) <= tol_z:
            bad.append("mean z")
        if not abs(s["cn_win"] - ref["cn_win"]) <= tol_cn:
            bad.append("coordination")
        if bad:
            ok = False
            print("MISMATCH %s np=%d vs %s serial: %s" % (label, np_, ref_label, ", ".join(bad)))
    print("tolerances vs %s serial: solid fraction +-%g, mean z +-%g%%, coordination (window) +-%g"
          % (ref_label, tol_phi, 100 * tol_z, tol_cn))
    if a.check and a.sim == "liggghts":
        for b in liggghts_surface_identity(exe, env, mpirun, nps, g,
                                           os.path.join(workdir, "%s_np1" % ref_label, "settled.data"), workdir):
            ok = False
            print("MISMATCH " + b)
    if a.reps > 0:
        steps = 200 if a.smoke else 2000
        data = os.path.join(workdir, "%s_np1" % ref_label, "settled.data")
        d = os.path.join(workdir, "timing")
        os.makedirs(d, exist_ok=True)
        best, cpu = {}, {}
        for label, _, tdeck in models:
            open(os.path.join(d, "in.%s" % label), "w").write(tdeck(data, steps))
            # the same deck with `run 0`: start-up and setup only, subtracted from the CPU time
            open(os.path.join(d, "in0.%s" % label), "w").write(tdeck(data, 0))
        for np_ in nps:
            for r in range(a.reps):
                for label, _, _ in models:
                    t_cpu = []
                    for deck, log in (("in0.%s" % label, "log0.%s.np%d.%d" % (label, np_, r)),
                                      ("in.%s" % label, "log.%s.np%d.%d" % (label, np_, r))):
                        c0 = child_cpu()
                        H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", deck, "-log", log], d, env)
                        t_cpu.append(child_cpu() - c0)
                    t = loop_time(os.path.join(d, "log.%s.np%d.%d" % (label, np_, r)))
                    best[(label, np_)] = min(best.get((label, np_), float("inf")), t)
                    cpu[(label, np_)] = min(cpu.get((label, np_), float("inf")), t_cpu[1] - t_cpu[0])
        print()
        print("Wall time on the settled bed (%d steps, minimum of %d alternating runs); CPU: user + sys of all "
              "processes of the run minus that of the same deck with `run 0` (start-up, setup), minimum; "
              "with 2 ranks it includes MPI's busy waiting:" % (steps, a.reps))
        print()
        print("| model | ranks | loop [s] | %s loop [s] | ratio | CPU [s] | %s CPU [s] | CPU ratio |"
              % (ref_label, ref_label))
        print("|---|---|---|---|---|---|---|---|")
        for np_ in nps:
            for label, _, _ in models:
                if label == ref_label:
                    continue
                o, h = best[(label, np_)], best[(ref_label, np_)]
                co, ch = cpu[(label, np_)], cpu[(ref_label, np_)]
                print("| %s | %d | %.3f | %.3f | %.3f | %.2f | %.2f | %.3f |"
                      % (label, np_, o, h, o / h, co, ch, co / ch))
    if a.pour_reps > 0:
        pour_timing(models, nps, a.pour_reps, mpirun, exe, env, workdir, ref_label)
    if a.check and not ok:
        raise SystemExit("FAIL: packing statistics differ beyond tolerance")


if __name__ == "__main__":
    main()
