#!/usr/bin/env python3
"""Runs demcontact inside real DEM codes and compares it with their builtin contact models.

  harness.py collision --sim liggghts --plugin libdemcontact_liggghts.so [--check]
  harness.py collision --sim lammps   --plugin demcontactplugin.so      [--check]
  harness.py bed       --sim liggghts --plugin ... [--n 5000] [--np 2]

collision: two-sphere head-on collisions (R = 1 mm, rho = 2500, nu = 0.3) at impact speeds
0.1, 1, 10 m/s, E in {5e6, 2.5e7, 1e8} Pa, target e in {0.3, 0.5, 0.9}. All 27 pairs collide in
one simulator run per contact model (pairs far apart, one atom type per (E, e)); the realised e is
read from the simulator's own dump of the final velocities. With --check, exits 1 unless demcontact
(clamped and unclamped) realises every target within TOL.

Exit code 77 (ctest SKIP_RETURN_CODE) when the simulator is not installed.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

SKIP = 77
TOL = 1e-3
R, RHO, NU = 1e-3, 2500.0, 0.3
SPEEDS = (0.1, 1.0, 10.0)
MODULI = (5e6, 2.5e7, 1e8)
TARGETS = (0.3, 0.5, 0.9)
STEPS_PER_CONTACT = 2000  # time step = shortest Hertz contact time / this


def hertz_contact_time(E, v):
    """Elastic Hertz contact duration of two equal spheres, 2.868 (m*^2/(R* E*^2 v))^(1/5)."""
    m = RHO * 4.0 / 3.0 * math.pi * R**3
    m_eff, r_eff, e_eff = m / 2, R / 2, E / (2 * (1 - NU * NU))
    return 2.868265699 * (m_eff**2 / (r_eff * e_eff**2 * v)) ** 0.2


def types():
    """Atom type (1-based) for every (E, e) combination."""
    return [(E, e) for E in MODULI for e in TARGETS]


def collision_setup(spc=STEPS_PER_CONTACT):
    """Time step (shortest contact / spc), step count, initial gap and the 27 pairs."""
    tc_min = min(hertz_contact_time(E, v) for E in MODULI for v in SPEEDS)
    dt = tc_min / spc
    gap = 1e-6  # surface gap at t = 0 [m]
    t_end = max(gap / v + 2.0 * hertz_contact_time(E, v) for E in MODULI for v in SPEEDS)
    pairs = []  # (id_left, id_right, type, E, e, v, y)
    atom = 1
    y = 0.0
    for t, (E, e) in enumerate(types(), start=1):
        for v in SPEEDS:
            pairs.append((atom, atom + 1, t, E, e, v, y))
            atom += 2
            y += 4 * R
    return dt, int(math.ceil(t_end / dt)), gap, pairs


def which(name):
    return shutil.which(name)


def run(cmd, cwd, env=None, timeout=3600):
    # LIGGGHTS/LAMMPS print the reason of an error to the screen, then MPI_Abort: unbuffer it.
    if which("stdbuf"):
        cmd = ["stdbuf", "-oL", "-eL"] + cmd
    t0 = time.time()
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=timeout)
    wall = time.time() - t0
    if p.returncode != 0:
        sys.stderr.write(p.stdout[-4000:])
        raise SystemExit("harness: %s failed (exit %d)" % (" ".join(cmd), p.returncode))
    return p.stdout, wall


def mpi_env():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "0")
    # A busy-polling rank that shares its core with other work stalls its partner: yield instead.
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


def read_last_dump(path):
    """Last frame of a LAMMPS/LIGGGHTS 'dump custom id type vx ...' file: {id: [fields...]}."""
    frames = open(path).read().split("ITEM: TIMESTEP")
    last = frames[-1].splitlines()
    i = next(k for k, l in enumerate(last) if l.startswith("ITEM: ATOMS"))
    cols = last[i].split()[2:]
    out = {}
    for l in last[i + 1:]:
        if l.strip():
            f = dict(zip(cols, l.split()))
            out[int(f["id"])] = f
    return out


# ------------------------------------------------------------------ LIGGGHTS
def liggghts_collision_deck(model, dt, steps, gap, pairs):
    n = len(types())
    Es = " ".join("%g" % E for E, _ in types())
    nus = " ".join("%g" % NU for _ in types())
    # Cross-type pairs never touch; give them the geometric mean of the two targets.
    rest = " ".join("%.17g" % math.sqrt(a[1] * b[1]) for a in types() for b in types())
    fric = " ".join("0" for _ in range(n * n))
    L = []
    L += ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
          "communicate single vel yes", "units si",
          "region box block -0.05 0.05 -0.01 %g -0.005 0.005 units box" % (pairs[-1][6] + 0.01),
          "create_box %d box" % n, "neighbor 0.0002 bin", "neigh_modify delay 0",
          "fix m1 all property/global youngsModulus peratomtype " + Es,
          "fix m2 all property/global poissonsRatio peratomtype " + nus,
          "fix m3 all property/global coefficientRestitution peratomtypepair %d %s" % (n, rest),
          "fix m4 all property/global coefficientFriction peratomtypepair %d %s" % (n, fric),
          "pair_style gran " + model, "pair_coeff * *", "timestep %.17g" % dt]
    for a, b, t, E, e, v, y in pairs:
        x = R + gap / 2
        L += ["create_atoms %d single %.17g %.17g 0 units box" % (t, -x, y),
              "create_atoms %d single %.17g %.17g 0 units box" % (t, x, y),
              "set atom %d diameter %g density %g vx %.17g" % (a, 2 * R, RHO, v / 2),
              "set atom %d diameter %g density %g vx %.17g" % (b, 2 * R, RHO, -v / 2)]
    L += ["fix integr all nve/sphere", "thermo %d" % steps,
          "dump d all custom %d final.dump id type vx vy vz" % steps, "run %d" % steps]
    return "\n".join(L) + "\n"


# With --exponent p (demcontact only; builtins stay Hertz) the stiffness is k = 4/3 E* R*^(2-p) and
# contacts last longer than Hertz's at low speed: run this many times longer (enough for p in [1, 2]).
EXPONENT_RUN_FACTOR = 4

LIGGGHTS_MODELS = [  # (label, pair_style arguments after 'gran', ours?, clamps?)
    ("demcontact", "model demcontact tangential history", True, False),
    ("demcontact limitForce", "model demcontact tangential history limitForce on", True, True),
    ("hertz", "model hertz tangential history", False, False),
    ("hertz limitForce", "model hertz tangential history limitForce on", False, True),
]


def liggghts_cmd(plugin):
    exe = which("liggghts")
    if not exe:
        print("SKIPPED: liggghts (not installed; scripts/setup_simulators.sh installs it)")
        raise SystemExit(SKIP)
    env = mpi_env()
    env["LD_PRELOAD"] = os.path.abspath(plugin)
    return exe, env


def mpi_prefix(np_, mpirun="mpirun", forward=()):
    """mpirun prefix for np_ > 1 ranks (never more ranks than the 2 cores of the CI machine).
    Open MPI: LD_PRELOAD and the variables in forward named with -x, so that they reach the ranks
    wherever they start (on this one node Open MPI passes its environment anyway; MPICH passes it
    everywhere)."""
    if np_ <= 1:
        return []
    exe = which(mpirun) or mpirun
    openmpi = "openmpi" in os.path.realpath(exe) or os.path.realpath(exe).endswith("orterun")
    return [exe, "-np", str(np_)] + (sum((["-x", v] for v in ("LD_PRELOAD",) + tuple(forward)), [])
                                     if openmpi else [])


def collision_liggghts(plugin, workdir, np_=1, spc=STEPS_PER_CONTACT, exponent=None, visco=False):
    exe, env = liggghts_cmd(plugin)
    dt, steps, gap, pairs = collision_setup(spc)
    if exponent is not None or visco:
        steps *= EXPONENT_RUN_FACTOR
    results = {}
    models = [m for m in LIGGGHTS_MODELS if m[2] or not visco]
    for label, model, ours, _ in models:
        if ours and exponent is not None:
            model += " exponent %.17g" % exponent
        if visco:
            model += " viscoelastic on vRef %.17g rRef %.17g densityRef %.17g" % (VISCO_VREF, R, RHO)
        d = os.path.join(workdir, re.sub(r"\W+", "_", label))
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.collision"), "w").write(
            liggghts_collision_deck(model, dt, steps, gap, pairs))
        run(mpi_prefix(np_) + [exe, "-in", "in.collision", "-log", "log.liggghts"], d, env)
        results[label] = realised(read_last_dump(os.path.join(d, "final.dump")), pairs)
    return dt, pairs, results, [(m[0], m[2]) for m in models]


# --viscoelastic: demcontact's viscoelastic law, calibrated so that e(VISCO_VREF) = target; the
# other speeds must rebound with the library's own e(b), b = beta v^(1/5).
VISCO_VREF = 1.0


def demcontact_lib(plugin):
    """The libdemcontact the plugin links (ctypes), for expected values computed by the library."""
    import ctypes
    out = subprocess.run(["ldd", os.path.abspath(plugin)], stdout=subprocess.PIPE, text=True).stdout
    m = re.search(r"libdemcontact\.so\S*\s*=>\s*(\S+)", out)
    if not m:
        raise SystemExit("harness: %s does not link libdemcontact (ldd)" % plugin)
    return ctypes.CDLL(m.group(1))


def visco_expected(plugin, clamp):
    """{(e_target, v): e} of viscoelastic spheres calibrated at VISCO_VREF, from the library."""
    import ctypes
    lib = demcontact_lib(plugin)
    crit = 1 if clamp else 0  # DC_END_FORCE / DC_END_OVERLAP
    out = {}
    for e in TARGETS:
        beta, ev = ctypes.c_double(), ctypes.c_double()
        assert lib.dc_viscoelastic_beta_from_e(ctypes.c_double(e), ctypes.c_double(VISCO_VREF), crit,
                                               ctypes.byref(beta)) == 0
        for v in SPEEDS:
            b = beta.value * v ** 0.2
            assert lib.dc_viscoelastic_e(ctypes.c_double(b), crit, ctypes.byref(ev)) == 0
            out[(e, v)] = ev.value
    return out


def realised(final, pairs):
    """Realised e per pair from the dumped final velocities: e = (v_right - v_left)/v_impact."""
    out = {}
    for a, b, t, E, e, v, y in pairs:
        out[(E, e, v)] = (float(final[b]["vx"]) - float(final[a]["vx"])) / v
    return out


def print_collision(sim, dt, pairs, results, models, spc, expected=None):
    """expected: {label: {(E, e, v): e_expected}} for our models (default: the target e)."""
    print("## %s: realised restitution (dt = %.3g s, %d steps per shortest contact)"
          % (sim, dt, spc))
    print()
    print("| E [Pa] | v [m/s] | target e | " + " | ".join(m for m, _ in models) + " |")
    print("|---|---|---|" + "---|" * len(models))
    worst = 0.0
    for E in MODULI:
        for v in SPEEDS:
            for e in TARGETS:
                row = []
                for m, ours in models:
                    r = results[m][(E, e, v)]
                    row.append("%.5f" % r)
                    if ours:
                        want = expected[m][(E, e, v)] if expected else e
                        worst = max(worst, abs(r - want))
                        if expected:
                            row[-1] += " (%.5f)" % want
                print("| %g | %g | %g | %s |" % (E, v, e, " | ".join(row)))
    print()
    print("worst |e_realised - e_%s| of demcontact (all rows, both criteria): %.2e (tolerance %g)"
          % ("library (in brackets)" if expected else "target", worst, TOL))
    return worst


# ------------------------------------------------------------------ main
def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=["collision", "bed"])
    ap.add_argument("--sim", choices=["liggghts", "lammps"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--workdir")
    ap.add_argument("--n", type=int, default=5000)
    ap.add_argument("--steps", type=int, default=0)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--steps-per-contact", type=int, default=STEPS_PER_CONTACT,
                    help="collision: time step = shortest Hertz contact time / this")
    ap.add_argument("--exponent", type=float,
                    help="collision: force-law exponent p of demcontact (default Hertz, 1.5)")
    ap.add_argument("--viscoelastic", action="store_true",
                    help="collision: demcontact's viscoelastic law calibrated at v_ref = 1 m/s (ours only)")
    ap.add_argument("--resume", action="store_true",
                    help="bed: keep settling runs whose log is complete (rerun only the rest)")
    ap.add_argument("--smoke", action="store_true", help="bed: 1000 spheres, 3000 steps, no settling checks")
    ap.add_argument("--lmp", help="LAMMPS executable")
    a = ap.parse_args()
    # absolute: the decks refer to files of other runs, and each run has its own cwd
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_%s_" % a.sim))
    os.makedirs(workdir, exist_ok=True)
    if a.what == "collision":
        if a.sim == "liggghts":
            dt, pairs, results, models = collision_liggghts(a.plugin, workdir, a.np, a.steps_per_contact, a.exponent,
                                                            a.viscoelastic)
        else:
            import lammps_runs  # noqa
            dt, pairs, results, models = lammps_runs.collision(a.plugin, a.lmp, workdir, a.np,
                                                                 a.steps_per_contact, a.exponent, a.viscoelastic)
        expected = None
        if a.viscoelastic:
            expected = {}
            for m, ours in models:
                clamp = "limit" in m
                ev = visco_expected(a.plugin, clamp)
                expected[m] = {(E, e, v): ev[(e, v)] for E in MODULI for e in TARGETS for v in SPEEDS}
        worst = print_collision("%s, %d MPI rank%s%s" % (a.sim, a.np, "s" if a.np > 1 else "",
                                                        ", viscoelastic" if a.viscoelastic else ""),
                                dt, pairs, results, models, a.steps_per_contact, expected)
        if a.check and not worst <= TOL:
            raise SystemExit("FAIL: demcontact misses a target by %.3g > %g" % (worst, TOL))
    else:
        import bed
        bed.main(a, workdir)


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
