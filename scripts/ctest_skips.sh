#!/usr/bin/env bash
# Prints one line "ctest <name>: <reason>" per ctest case that was skipped (exit code 77, ctest's
# SKIP_RETURN_CODE) in the given ctest log; the reason is the test's own "SKIP..." output line.
#   scripts/ctest_skips.sh BUILD_DIR CTEST_LOG
set -euo pipefail
build=$1
log=$2
# ctest's summary: "The following tests did not run:" then "  12 - name (Skipped)".
sed -n '/The following tests did not run:/,/^$/p' "$log" | sed -n 's/^[[:space:]]*[0-9]* - \(.*\) (Skipped)$/\1/p' |
  while read -r name; do
    reason=$(ctest --test-dir "$build" -R "^${name}\$" -V 2>/dev/null |
      grep -m1 -o "SKIP[A-Z]*:.*" || true)
    echo "ctest ${name}: ${reason:-exit 77 (no reason printed)}"
  done
