#!/usr/bin/env bash
# Proves that scripts/fuzz.sh can fail: with DC_FUZZ_PLANT_CRASH=1 the harness aborts on its first
# input, and fuzz.sh must then exit non-zero and say FAILED. Exits 0 only if that happened.
set -uo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
if DC_FUZZ_PLANT_CRASH=1 scripts/fuzz.sh 1000 60 >"$log" 2>&1; then
  cat "$log"
  echo "fuzz self-test: FAILED: fuzz.sh exited 0 although the harness aborted on purpose" >&2
  exit 1
fi
if ! grep -q "fuzz: FAILED" "$log" || ! grep -q "deadly signal" "$log" "build-fuzz/fuzz.log"; then
  cat "$log"
  echo "fuzz self-test: FAILED: fuzz.sh failed, but not because of the planted crash" >&2
  exit 1
fi
rm -f build-fuzz/crash-*
echo "fuzz self-test: ok (the planted crash made scripts/fuzz.sh fail)"
