#!/usr/bin/env bash
# Proves that scripts/fuzz.sh can fail through every one of its targets: for each target T
# (c_tests/fuzz/fuzz_*.c) it runs fuzz.sh with DC_FUZZ_PLANT_CRASH=T, which makes T alone abort
# on its first input. fuzz.sh must then exit non-zero, name T (and only T) as FAILED, and T's log
# must show the abort. Exits 0 only if that happened for every target.
set -uo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
trap 'rm -f "$log"' EXIT
targets=()
for src in c_tests/fuzz/fuzz_*.c; do targets+=("$(basename "$src" .c)"); done
if [ "${#targets[@]}" -eq 0 ]; then
  echo "fuzz self-test: FAILED: no targets in c_tests/fuzz" >&2
  exit 1
fi
for t in "${targets[@]}"; do
  if DC_FUZZ_PLANT_CRASH="$t" scripts/fuzz.sh 500 60 >"$log" 2>&1; then
    cat "$log"
    echo "fuzz self-test: FAILED: fuzz.sh exited 0 although $t aborted on purpose" >&2
    exit 1
  fi
  if ! grep -q "^fuzz: $t: FAILED" "$log" || ! grep -qx "fuzz: FAILED: $t" "$log" ||
    ! grep -q "deadly signal" "build-fuzz/$t.log"; then
    cat "$log"
    echo "fuzz self-test: FAILED: fuzz.sh failed, but not (only) because of the crash planted in $t" >&2
    exit 1
  fi
  rm -f "build-fuzz/$t"-crash-*
  echo "fuzz self-test: the crash planted in $t made scripts/fuzz.sh fail"
done
echo "fuzz self-test: ok (a planted crash in each of the ${#targets[@]} targets made scripts/fuzz.sh fail)"
