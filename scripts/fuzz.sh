#!/usr/bin/env bash
# Coverage-guided fuzzing of the C ABI with libFuzzer (clang from Debian), one fuzz target per
# export family: every c_tests/fuzz/fuzz_*.c is a target (fuzz_common.h holds what they share).
#   scripts/fuzz.sh [RUNS] [SECONDS]     default: 200000 executions, 120 s
# RUNS is per target: each fuzzer stops after RUNS executions. SECONDS is the wall budget of the
# whole script: the targets run DC_FUZZ_JOBS at a time (default 2, one per core of the CI
# machine; the next starts when one finishes) and each may run for its share of the budget,
# SECONDS / ceil(targets / jobs), so the fuzzing takes at most SECONDS. A target stops at
# whichever limit it reaches first: a slow target cannot starve the fast ones.
# The Rust library is built once for every target, with SanitizerCoverage instrumentation (stable
# rustc flags) plus debug assertions and overflow checks, so libFuzzer sees Rust branches and any
# arithmetic panic surfaces as DC_ERR_INTERNAL, which the targets treat as a crash. The C side runs
# under AddressSanitizer and UBSan. Prints each target's executions and exec/s and the total;
# exits non-zero if any fuzzer exits non-zero (a crash, a sanitizer report, a leak, a timeout).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-200000}
secs=${2:-120}
jobs=${DC_FUZZ_JOBS:-2}
if ! command -v clang >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends clang libclang-rt-14-dev >/dev/null
fi
out=build-fuzz
# An explicit --target keeps RUSTFLAGS off build scripts and proc macros; LTO off keeps the
# SanitizerCoverage instrumentation in the archive. --no-default-features: the library does not
# use the CLI's dependencies (clap, serde_json, plotters), so they need no instrumented build.
target=$(rustc -vV | sed -n "s/^host: //p")
mkdir -p "$out"
RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=3 \
 -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
 -Cllvm-args=-sanitizer-coverage-trace-compares -Cdebug-assertions -Coverflow-checks -Cforce-frame-pointers" \
  CARGO_PROFILE_RELEASE_LTO=false cargo build --release --lib --no-default-features --locked \
    --target-dir "$out/cargo" -q --target "$target"
lib="$out/cargo/$target/release/libdemcontact.a"
names=()
for src in c_tests/fuzz/fuzz_*.c; do
  t=$(basename "$src" .c)
  names+=("$t")
  # Relinked only when the target, the shared header, the library or this script (its flags)
  # changed.
  if [ ! -x "$out/$t" ] || [ "$src" -nt "$out/$t" ] || [ c_tests/fuzz/fuzz_common.h -nt "$out/$t" ] ||
    [ "$lib" -nt "$out/$t" ] || [ scripts/fuzz.sh -nt "$out/$t" ]; then
    clang -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -Iinclude \
      -DDC_FUZZ_NAME="\"$t\"" "$src" "$lib" -lpthread -ldl -lm -o "$out/$t"
  fi
done
ntargets=${#names[@]}
[ "$ntargets" -gt 0 ] || { echo "fuzz: no targets in c_tests/fuzz" >&2; exit 1; }
[ "$jobs" -ge 1 ] || jobs=1
[ "$jobs" -le "$ntargets" ] || jobs=$ntargets
rounds=$(((ntargets + jobs - 1) / jobs))
share=$((secs / rounds))
[ "$share" -ge 1 ] || share=1
echo "fuzz: $ntargets targets, $jobs at a time, each up to $runs executions or $share s"

# One target: its own corpus; crash inputs go to $out/<target>-crash-* (artifact_prefix), not
# the working directory. Its exit status is written to $out/<target>.rc for the verdict below.
run_target() {
  local t=$1
  mkdir -p "$out/corpus/$t"
  rm -f "$out/$t.rc" "$out/$t.time"
  local t0
  t0=$(date +%s.%N)
  set +e
  "$out/$t" -runs="$runs" -max_total_time="$share" -max_len=384 -print_final_stats=1 \
    -artifact_prefix="$out/$t-" "$out/corpus/$t" >"$out/$t.log" 2>&1
  local rc=$?
  set -e
  echo "$t0 $(date +%s.%N)" | awk '{print $2 - $1}' >"$out/$t.time"
  echo "$rc" >"$out/$t.rc"
}
start=$SECONDS
# A pool of $jobs: the next target starts as soon as one finishes.
next=0
running=0
while [ "$next" -lt "$ntargets" ] || [ "$running" -gt 0 ]; do
  if [ "$next" -lt "$ntargets" ] && [ "$running" -lt "$jobs" ]; then
    run_target "${names[$next]}" &
    next=$((next + 1))
    running=$((running + 1))
  else
    wait -n || true  # the verdict comes from each target's .rc below
    running=$((running - 1))
  fi
done

# The fuzzer's own exit status decides: libFuzzer exits non-zero on a crash, a sanitizer report,
# a leak or a timeout (it also prints its final stats from the crash handler, so the stats line
# alone proves nothing). A missing status file (its job died) is a failure too.
failed=()
total=0
total_secs=0
for t in "${names[@]}"; do
  rc=$(cat "$out/$t.rc" 2>/dev/null || echo missing)
  if [ "$rc" != 0 ]; then
    grep -E "^(==|SUMMARY|artifact_prefix|Test unit written)|deadly signal" "$out/$t.log" || true  # display only
    echo "fuzz: $t: FAILED: the fuzzer exited with status $rc (log: $out/$t.log)" >&2
    failed+=("$t")
    continue
  fi
  if ! grep -q "stat::number_of_executed_units" "$out/$t.log"; then
    echo "fuzz: $t: FAILED: the fuzzer did not finish (log: $out/$t.log)" >&2
    failed+=("$t")
    continue
  fi
  execs=$(awk '/stat::number_of_executed_units/ {print $2}' "$out/$t.log")
  # exec/s over the fuzzer's whole run (start-up and corpus loading included), to 0.01 s
  t_secs=$(cat "$out/$t.time")
  printf 'fuzz: %-18s %12d executions %8.1f s %9.0f exec/s\n' "$t" "$execs" "$t_secs" \
    "$(awk -v e="$execs" -v s="$t_secs" 'BEGIN {print e / s}')"
  total=$((total + execs))
  total_secs=$(awk -v a="$total_secs" -v b="$t_secs" 'BEGIN {print a + b}')
done
if [ "${#failed[@]}" -ne 0 ]; then
  echo "fuzz: FAILED: ${failed[*]}" >&2
  exit 1
fi
wall=$((SECONDS - start))
printf 'fuzz: total %d executions over %d targets in %d s wall (%.1f target-seconds, %.0f exec/s of wall time), 0 crashes\n' \
  "$total" "$ntargets" "$wall" "$total_secs" "$(awk -v e="$total" -v s="$wall" 'BEGIN {print e / (s > 0 ? s : 1)}')"
