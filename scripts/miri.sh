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
tests=()
for f in tests/*contract*.rs tests/no_alloc*.rs; do
  tests+=(--test "$(basename "$f" .rs)")
done
# Deterministic floats: Miri otherwise perturbs libm results by a few ulps on purpose, which
# breaks the bit-for-bit comparisons (batch vs scalar) that the contract tests make.
export MIRIFLAGS="${MIRIFLAGS:--Zmiri-strict-provenance -Zmiri-deterministic-floats}"
cargo +nightly miri test --locked --target-dir target/miri "${tests[@]}"
cargo +nightly miri test --locked --target-dir target/miri --lib ffi::
