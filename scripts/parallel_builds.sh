#!/usr/bin/env bash
# N clean parallel builds in a row: each one configures an empty build directory and runs
# `cmake --build -j4`; the first failure stops the script with its log and a non-zero status.
#
# What each run rebuilds: every CMake target (the Fortran module library, all C/C++/Fortran tests
# and their sanitizer variants, the examples, the benchmark, the simulator plugins where the
# simulators are installed). The Rust library is built by cargo into one target directory
# outside the build directory, shared by the runs (DEMCONTACT_CARGO_TARGET_DIR), so after the
# first run cargo only checks that it is fresh: the races this looks for are in the CMake part.
#
#   scripts/parallel_builds.sh [N] [JOBS]     (default N = 3, JOBS = 4)
# Environment: DC_PB_DIR (scratch directory, default build-parallel) is removed at the start;
# DC_PB_CARGO_DIR (cargo target directory, default DC_PB_DIR/cargo; pass the repository's
# target/ to reuse its release library) is kept.
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-3}"
jobs="${2:-4}"
[[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [N>=1] [JOBS]" >&2; exit 2; }
root="${DC_PB_DIR:-$PWD/build-parallel}"
cargo_dir="${DC_PB_CARGO_DIR:-$root/cargo}"
rm -rf "$root/build"
mkdir -p "$root"
start=$(date +%s)
for i in $(seq 1 "$n"); do
  build="$root/build"
  rm -rf "$build"
  log="$root/run_$i.log"
  t0=$(date +%s)
  if ! { cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release \
           -DDEMCONTACT_CARGO_TARGET_DIR="$cargo_dir" &&
         cmake --build "$build" -j"$jobs"; } >"$log" 2>&1; then
    echo "parallel build $i of $n FAILED (log: $log); last lines:" >&2
    tail -n 40 "$log" >&2
    exit 1
  fi
  echo "parallel build $i of $n ok ($(( $(date +%s) - t0 )) s)"
done
echo "$n of $n clean parallel builds (-j$jobs) succeeded in $(( $(date +%s) - start )) s"
