#!/usr/bin/env bash
# Force-kernel benchmark: builds examples_cpp/bench/force_bench (CMake, Release) and prints its
# markdown table twice, linked against the shared and the static library.
#   scripts/bench_force.sh            portable build (baseline x86-64 for both Rust and C)
#   scripts/bench_force.sh --native   RUSTFLAGS=-C target-cpu=native and -march=native
# Uses its own build directory (build-bench or build-bench-native): the first run compiles the
# library (a few minutes on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
native=OFF
dir=build-bench
if [[ "${1:-}" == "--native" ]]; then
  native=ON
  dir=build-bench-native
fi
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DDEMCONTACT_NATIVE=$native >/dev/null
cmake --build "$dir" -j2 --target force_bench_shared force_bench_static >/dev/null
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), native=$native, $(gcc --version | head -1)"
for kind in shared static; do
  echo
  echo "### linked against the $kind library"
  echo
  "$dir/bench/force_bench_$kind"
done
