"""What every simulator run shares: the collision geometry (R = 1 mm, rho = 2500, nu = 0.3; impact
speeds 0.1, 1, 10 m/s, E in {5e6, 2.5e7, 1e8} Pa, target e in {0.3, 0.5, 0.9}), running an
executable (serial or under mpirun), reading dumps and thermo output, the library's own expected
values (ctypes) and the scenario scripts' common command line. Exit code 77 (ctest
SKIP_RETURN_CODE) when a simulator is not installed.
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


def parse_thermo(text):
    """The thermo rows of each run of a LAMMPS/LIGGGHTS log: a list per run of dicts (strings)."""
    runs, rows, cols = [], [], None
    for line in text.splitlines():
        f = line.split()
        if f[:1] == ["Step"]:
            cols, rows = f, []
        elif cols and len(f) == len(cols) and re.match(r"^\d+$", f[0]):
            rows.append(dict(zip(cols, f)))
        elif line.startswith("Loop time"):
            runs.append(rows)
            cols, rows = None, []
    return runs


def worst_of(*xs):
    """The largest of xs (numbers, or one iterable of them), NaN when any of them is NaN.
    Python's max drops a NaN that is not its first argument (nan > x is False): an error that
    came out NaN must fail the check it feeds (written `not worst <= tol`), never pass it."""
    if len(xs) == 1 and not isinstance(xs[0], (int, float)):
        xs = tuple(xs[0])
    if any(math.isnan(x) for x in xs):
        return math.nan
    return max(xs)


def read_last_dump(path):
    """Last frame of a LAMMPS/LIGGGHTS 'dump custom id type vx ...' file: {id: [fields...]}.
    Exits with a FAIL naming the atom and column on a non-finite value (nan, inf): an atom whose
    state went non-finite is never lost through a wall and never compares as out of tolerance."""
    frames = open(path).read().split("ITEM: TIMESTEP")
    last = frames[-1].splitlines()
    i = next(k for k, l in enumerate(last) if l.startswith("ITEM: ATOMS"))
    cols = last[i].split()[2:]
    out = {}
    for l in last[i + 1:]:
        if l.strip():
            f = dict(zip(cols, l.split()))
            for c, v in f.items():
                try:
                    finite = math.isfinite(float(v))
                except ValueError:  # not a number (no numeric column is)
                    continue
                if not finite:
                    raise SystemExit("FAIL: %s: atom %s has %s = %s" % (path, f.get("id", "?"), c, v))
            out[int(f["id"])] = f
    return out


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


# With --exponent p (demcontact only; builtins stay Hertz) the stiffness is k = 4/3 E* R*^(2-p) and
# contacts last longer than Hertz's at low speed: run this many times longer (enough for p in [1, 2]).
EXPONENT_RUN_FACTOR = 4

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
                        worst = worst_of(worst, abs(r - want))
                        if expected:
                            row[-1] += " (%.5f)" % want
                print("| %g | %g | %g | %s |" % (E, v, e, " | ".join(row)))
    print()
    print("worst |e_realised - e_%s| of demcontact (all rows, both criteria): %.2e (tolerance %g)"
          % ("library (in brackets)" if expected else "target", worst, TOL))
    return worst


def arguments(what, doc=None):
    """The command line of the collision and bed scenarios (collision.py, bed.py): the parsed
    arguments and the absolute work directory (created)."""
    ap = argparse.ArgumentParser(prog=what, description=doc)
    ap.add_argument("--sim", choices=["liggghts", "lammps"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--workdir")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--lmp", help="LAMMPS executable")
    if what == "collision":
        ap.add_argument("--steps-per-contact", type=int, default=STEPS_PER_CONTACT,
                        help="time step = shortest Hertz contact time / this")
        ap.add_argument("--exponent", type=float, help="force-law exponent p of demcontact (default Hertz, 1.5)")
        ap.add_argument("--viscoelastic", action="store_true",
                        help="demcontact's viscoelastic law calibrated at v_ref = 1 m/s (ours only)")
    else:
        ap.add_argument("--n", type=int, default=5000)
        ap.add_argument("--steps", type=int, default=0)
        ap.add_argument("--resume", action="store_true",
                        help="keep settling runs whose log is complete (rerun only the rest)")
        ap.add_argument("--smoke", action="store_true", help="1000 spheres, 3000 steps, no settling checks")
    a = ap.parse_args()
    # absolute: the decks refer to files of other runs, and each run has its own cwd
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_%s_" % a.sim))
    os.makedirs(workdir, exist_ok=True)
    return a, workdir
