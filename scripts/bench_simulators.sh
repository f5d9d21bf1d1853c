#!/usr/bin/env bash
# demcontact inside LIGGGHTS and LAMMPS: prints the restitution tables (two-sphere collisions) and
# the settling-bed table with the wall-time ratio demcontact / builtin Hertz, serial and 2 ranks.
# Usage: scripts/bench_simulators.sh [N spheres, default 5000]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/setup_simulators.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target demcontact_liggghts demcontact_lammps >/dev/null
h=examples_cpp/sim/harness.py
out=build/simulators/bench
mkdir -p "$out"
python3 $h collision --sim liggghts --check --plugin build/simulators/libdemcontact_liggghts.so --workdir "$out/liggghts_collision"
echo
python3 $h collision --sim lammps --check --plugin build/simulators/demcontact_lammps.so --workdir "$out/lammps_collision"
echo
python3 $h bed --sim liggghts --check --np 2 --n "${1:-5000}" --plugin build/simulators/libdemcontact_liggghts.so --workdir "$out/liggghts_bed"
