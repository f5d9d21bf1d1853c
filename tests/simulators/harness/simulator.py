"""The one interface every simulator implements (harness/lammps.py, harness/liggghts.py): find its
executable (SKIP, exit 77, where it is missing), run a deck serially or under its mpirun, the
27-pair head-on collision of the collision scenario, a pour deck, and its thermo output."""
import os

from . import common


class Simulator:
    """A DEM code with the demcontact plugin loaded. Subclasses set `name`, `log` (the log file
    name their runs write) and `exe`, `env` (environment of every run) and `mpirun` in __init__."""

    name = None
    log = "log.txt"

    def __init__(self, plugin):
        self.plugin = os.path.abspath(plugin)
        self.exe, self.env, self.mpirun = None, common.mpi_env(), "mpirun"

    def command(self, np_=1, forward=()):
        """The command line that runs this code on np_ ranks (the deck's arguments follow)."""
        return common.mpi_prefix(np_, self.mpirun, forward) + [self.exe]

    def run_deck(self, text, workdir, np_=1, deck="in.deck", log=None):
        """Writes the deck text into workdir (created) and runs it; returns (screen output, wall
        time [s], log text). A failed run ends the script naming the command (common.run)."""
        log = log or self.log
        os.makedirs(workdir, exist_ok=True)
        with open(os.path.join(workdir, deck), "w") as f:
            f.write(text)
        out, wall = common.run(self.command(np_) + ["-in", deck, "-log", log], workdir, self.env)
        with open(os.path.join(workdir, log)) as f:
            return out, wall, f.read()

    def collision(self, workdir, np_=1, spc=common.STEPS_PER_CONTACT, exponent=None, visco=False):
        """The 27 head-on pairs of common.collision_setup, one run per contact model of this code
        (ours and its builtins): (dt, pairs, {label: {(E, e, v): realised e}}, [(label, ours?)])."""
        raise NotImplementedError

    def pour(self, text, workdir, np_=1, dump="final.dump"):
        """Runs a pour deck (scenes.py writes them) that dumps its final atoms to `dump`: (thermo
        rows of each run, {id: fields} of the last frame)."""
        _, _, log = self.run_deck(text, workdir, np_, deck="in.pour")
        return self.parse_thermo(log), common.read_last_dump(os.path.join(workdir, dump))

    @staticmethod
    def parse_thermo(text):
        return common.parse_thermo(text)
