#!/usr/bin/env bash
# demcontact inside LIGGGHTS and LAMMPS: prints the restitution tables (two-sphere collisions), the
# LIGGGHTS settling-bed table with the wall-time and pair-time ratios demcontact / builtin Hertz,
# and the LAMMPS settled-bed timing against pair_style granular (scripts/bench_lammps_bed.py),
# serial and 2 ranks, each timing the minimum of three alternating runs.
# Usage: scripts/bench_simulators.sh [--timing] [N spheres, default 5000]
#   --timing   only the timings: the LIGGGHTS bed (settled once, then reused: --resume) and the
#              LAMMPS bed from the same settled data; no collision tables
# Build directory: $DC_BENCH_BUILD (default build); work files under $DC_BENCH_BUILD/simulators/bench.
set -euo pipefail
cd "$(dirname "$0")/.."
timing_only=0
if [[ "${1:-}" == "--timing" ]]; then
  timing_only=1
  shift
fi
n="${1:-5000}"
b="${DC_BENCH_BUILD:-build}"
scripts/setup.sh
scripts/setup_simulators.sh
cmake -S . -B "$b" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$b" -j2 --target demcontact_liggghts demcontact_lammps >/dev/null
s=tests/simulators
out="$b/simulators/bench"
mkdir -p "$out"
lmp=()
resume=()
((timing_only)) && resume=(--resume)
[[ -n "${DC_LAMMPS_LMP:-}" ]] && lmp=(--lmp "$DC_LAMMPS_LMP")
if ((!timing_only)); then
  python3 $s/collision.py --sim liggghts --check --plugin "$b/simulators/libdemcontact_liggghts.so" --workdir "$out/liggghts_collision"
  echo
  python3 $s/collision.py --sim lammps --check "${lmp[@]}" --plugin "$b/simulators/demcontactplugin.so" --workdir "$out/lammps_collision"
  echo
fi
python3 $s/bed.py --sim liggghts --check --np 2 --n "$n" "${resume[@]}" --plugin "$b/simulators/libdemcontact_liggghts.so" --workdir "$out/liggghts_bed"
echo
python3 scripts/bench_lammps_bed.py "${lmp[@]}" --np 2 --reps 3 --plugin "$b/simulators/demcontactplugin.so" \
  --data "$out/liggghts_bed/bed_hertz/settled.data" --workdir "$out/lammps_bed"
