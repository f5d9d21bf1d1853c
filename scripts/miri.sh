#!/usr/bin/env bash
# The FFI layer's Rust tests under Miri (undefined-behaviour checker): the boundary unit tests and
# every tests/*contract*.rs and tests/no_alloc*.rs file, which drive each export through raw
# pointers, NULLs, unaligned outputs and bad inputs. Miri needs the nightly toolchain; where it
# cannot be installed the step says so and is skipped (exit 0).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! cargo +nightly miri --version >/dev/null 2>&1; then
  rustup component add --toolchain nightly miri rust-src >/dev/null 2>&1 || true
fi
if ! cargo +nightly miri --version >/dev/null 2>&1; then
  echo "miri: SKIPPED (nightly toolchain with the miri component is not available on this machine)"
  exit 0
fi
tests=()
for f in tests/*contract*.rs tests/no_alloc*.rs; do
  tests+=(--test "$(basename "$f" .rs)")
done
# Miri perturbs the results of float operations such as powf by a few ULPs on purpose (modelling
# libm differences between platforms); the bitwise batch-vs-scalar test needs them deterministic.
export MIRIFLAGS="${MIRIFLAGS:--Zmiri-strict-provenance -Zmiri-deterministic-floats}"
cargo +nightly miri test --locked --target-dir target/miri "${tests[@]}"
cargo +nightly miri test --locked --target-dir target/miri --lib ffi::
