"""LIGGGHTS (Debian's liggghts 3.8) with the plugin LD_PRELOADed: the two-sphere collisions next to
its builtin `model hertz`, with and without limitForce. Same geometry as the LAMMPS runs
(common.collision_setup)."""
import math
import os
import re

from .common import (NU, R, RHO, SKIP, STEPS_PER_CONTACT, EXPONENT_RUN_FACTOR, VISCO_VREF, mpi_env, mpi_prefix,
                     read_last_dump, realised, run, types, which, collision_setup)
from .simulator import Simulator


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


class Liggghts(Simulator):
    name = "liggghts"
    log = "log.liggghts"

    def __init__(self, plugin):
        super().__init__(plugin)
        self.exe, self.env = liggghts_cmd(plugin)

    def collision(self, workdir, np_=1, spc=STEPS_PER_CONTACT, exponent=None, visco=False):
        return collision_liggghts(self.plugin, workdir, np_, spc, exponent, visco)
