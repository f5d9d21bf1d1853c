#!/usr/bin/env bash
# Coverage-guided fuzzing of the C ABI with libFuzzer (clang from Debian).
#   scripts/fuzz.sh [RUNS] [SECONDS]     default: 200000 executions, at most 120 s
# The Rust library is built with SanitizerCoverage instrumentation (stable rustc flags) plus
# debug assertions and overflow checks, so libFuzzer sees Rust branches and any arithmetic panic
# surfaces as DC_ERR_INTERNAL, which the harness treats as a crash. The C harness runs under
# AddressSanitizer and UBSan. Prints the execution count; exits non-zero on any finding.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-200000}
secs=${2:-120}
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
mkdir -p "$out/corpus"
RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=3 \
 -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
 -Cllvm-args=-sanitizer-coverage-trace-compares -Cdebug-assertions -Coverflow-checks -Cforce-frame-pointers" \
  CARGO_PROFILE_RELEASE_LTO=false cargo build --release --lib --no-default-features --locked \
    --target-dir "$out/cargo" -q --target "$target"
clang -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -Iinclude \
  c_tests/fuzz/fuzz_abi.c "$out/cargo/$target/release/libdemcontact.a" -lpthread -ldl -lm -o "$out/fuzz_abi"
# The fuzzer's own exit status decides: libFuzzer exits non-zero on a crash, a sanitizer report,
# a leak or a timeout (it also prints its final stats from the crash handler, so the stats line
# alone proves nothing). Crash inputs go to $out/ (artifact_prefix), not the working directory.
set +e
"$out/fuzz_abi" -runs="$runs" -max_total_time="$secs" -max_len=384 -print_final_stats=1 \
  -artifact_prefix="$out/" "$out/corpus" >"$out/fuzz.log" 2>&1
rc=$?
set -e
grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==|SUMMARY|artifact_prefix|Test unit written)" \
  "$out/fuzz.log" || true  # display only; the verdict is $rc below
if [ "$rc" -ne 0 ]; then
  echo "fuzz: FAILED: the fuzzer exited with status $rc (log: $out/fuzz.log)" >&2
  exit 1
fi
grep -q "stat::number_of_executed_units" "$out/fuzz.log" || { echo "fuzz: fuzzer did not finish" >&2; exit 1; }
execs=$(grep "stat::number_of_executed_units" "$out/fuzz.log" | awk '{print $2}')
echo "fuzz: $execs executions, 0 crashes"
