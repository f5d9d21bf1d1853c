#!/usr/bin/env bash
# The FFI layer's Rust tests under Miri (undefined-behaviour checker): the boundary unit tests and
# every tests/*contract*.rs and tests/no_alloc*.rs file, which drive each export through raw
# pointers, NULLs, unaligned outputs and bad inputs. Miri needs the nightly toolchain; where it
# cannot be installed the step says so, is skipped (exit 0) and is named in the skipped-step
# summary at the end of scripts/test.sh (through $DC_SKIP_LOG).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! cargo +nightly miri --version >/dev/null 2>&1; then
  rustup component add --toolchain nightly miri rust-src >/dev/null 2>&1 || true
fi
if ! cargo +nightly miri --version >/dev/null 2>&1; then
  reason="nightly toolchain with the miri component is not available on this machine"
  echo "miri: SKIPPED ($reason)"
  # scripts/test.sh lists every skipped step at the end of its output from this file.
  [ -n "${DC_SKIP_LOG:-}" ] && echo "miri: $reason" >>"$DC_SKIP_LOG"
  exit 0
fi
# Miri interprets on one core: the files run as two groups side by side (two processes), each
# about half of the interpreted time. Group a: the largest file and the library's boundary unit
# tests; group b: every other file.
heavy=(contact_contract no_alloc_step_accuracy)
all=() group_a=() group_b=()
for f in tests/*contract*.rs tests/no_alloc*.rs; do
  t=$(basename "$f" .rs)
  all+=(--test "$t")
  if [[ " ${heavy[*]} " == *" $t "* ]]; then group_a+=(--test "$t"); else group_b+=(--test "$t"); fi
done
# Deterministic floats: Miri otherwise perturbs libm results by a few ulps on purpose, which
# breaks the bit-for-bit comparisons (batch vs scalar) that the contract tests make.
export MIRIFLAGS="${MIRIFLAGS:--Zmiri-strict-provenance -Zmiri-deterministic-floats}"
# Both groups must exist: an empty one would run every test file (cargo test with no --test).
if [ ${#group_a[@]} = 0 ] || [ ${#group_b[@]} = 0 ]; then
  echo "miri: a group is empty (a: ${group_a[*]:-none}; b: ${group_b[*]:-none})" >&2
  exit 1
fi
miri=(cargo +nightly miri test --locked --target-dir target/miri)
# Build once (cargo holds its build lock while compiling, not while the tests run).
"${miri[@]}" --no-run "${all[@]}"
"${miri[@]}" --no-run --lib
log_a=$(mktemp) log_b=$(mktemp)
pid_a='' pid_b=''
# Killed or interrupted: stop both groups and print what they had written.
on_signal() {
  local p
  for p in $pid_a $pid_b; do
    pkill -TERM -P "$p" 2>/dev/null || true
    kill "$p" 2>/dev/null || true
  done
  echo "== miri interrupted; group a so far:"
  cat "$log_a"
  echo "== group b so far:"
  cat "$log_b"
  rm -f "$log_a" "$log_b"
  exit 130
}
trap on_signal INT TERM
{ "${miri[@]}" "${group_a[@]}" && "${miri[@]}" --lib ffi::; } >"$log_a" 2>&1 &
pid_a=$!
"${miri[@]}" "${group_b[@]}" >"$log_b" 2>&1 &
pid_b=$!
rc_a=0 rc_b=0
wait "$pid_a" || rc_a=$?
wait "$pid_b" || rc_b=$?
echo "== miri group a (${group_a[*]} and --lib ffi::): exit $rc_a"
cat "$log_a"
echo "== miri group b (${group_b[*]}): exit $rc_b"
cat "$log_b"
rm -f "$log_a" "$log_b"
[ "$rc_a" = 0 ] && [ "$rc_b" = 0 ]
