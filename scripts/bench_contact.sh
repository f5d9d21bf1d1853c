#!/usr/bin/env bash
# Full-contact benchmark: builds examples_cpp/bench/contact_bench (CMake, Release) and prints its
# markdown table: dc_contact_force_batch normal-only, + Mindlin tangential, + EPSD rolling, in ns
# per contact, against hand-written C loops of the same formulas (-O3 and -O3 -fno-math-errno)
# and the plain normal-force path, all in the same run, with the ratios.
#   scripts/bench_contact.sh            portable build
#   scripts/bench_contact.sh --native   RUSTFLAGS=-C target-cpu=native and -march=native
set -euo pipefail
cd "$(dirname "$0")/.."
native=OFF
dir=build-bench
if [[ "${1:-}" == "--native" ]]; then
  native=ON
  dir=build-bench-native
fi
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DDEMCONTACT_NATIVE=$native >/dev/null
cmake --build "$dir" -j2 --target contact_bench >/dev/null
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), native=$native, $(gcc --version | head -1)"
"$dir/bench/contact_bench" --smoke
"$dir/bench/contact_bench"
