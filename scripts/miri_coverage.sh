#!/usr/bin/env bash
# Checks that the thinned grids the Miri step runs (`cfg!(miri)` in tests/) still reach every region
# of src/ that the full native grids reach. Builds the library with -C instrument-coverage, compiles
# each test twice (as is, and with --cfg miri: the Miri grid, run natively), runs both and compares
# the covered regions of src/ (llvm-cov). Exits 1 if the Miri grid misses a region, listing them.
#   scripts/miri_coverage.sh [TEST...]   default: every tests/*.rs that branches on cfg!(miri)
# Needs the llvm-tools rustup component (installed here if missing) and python3. Not part of
# scripts/test.sh: run it after changing a test's grid or the code those tests reach.
set -euo pipefail
cd "$(dirname "$0")/.."
host=$(rustc -vV | sed -n "s/^host: //p")
bin="$(rustc --print sysroot)/lib/rustlib/$host/bin"
[ -x "$bin/llvm-cov" ] || rustup component add llvm-tools >/dev/null
out=target/miri-coverage
lib="$out/$host/release"
# --target keeps RUSTFLAGS off the build script; LTO off and many units only make it build faster.
RUSTFLAGS="-C instrument-coverage" CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 \
  CARGO_PROFILE_RELEASE_DEBUG=0 cargo build --release --lib --locked -q --target-dir "$out" --target "$host"
tests=("$@")
if ((${#tests[@]} == 0)); then
  for f in $(grep -l "cfg!(miri)" tests/*.rs); do tests+=("$(basename "$f" .rs)"); done
fi
regions() { # $1 = test binary; prints the covered regions of src/, one a line
  rm -f "$1.profraw"
  LLVM_PROFILE_FILE="$1.profraw" "$1" -q >/dev/null
  "$bin/llvm-profdata" merge -sparse "$1.profraw" -o "$1.profdata"
  "$bin/llvm-cov" export --format=text --instr-profile="$1.profdata" "$1" | python3 -c '
import json, sys
seen = set()
for fn in json.load(sys.stdin)["data"][0]["functions"]:
    for r in fn["regions"]:
        name = fn["filenames"][r[5]]
        if r[4] > 0 and "/src/" in name and "/tests/" not in name:
            seen.add("%s:%d:%d-%d:%d" % (name.split("/src/")[-1], r[0], r[1], r[2], r[3]))
print("\n".join(sorted(seen)))'
}
status=0
for t in "${tests[@]}"; do
  for grid in full miri; do
    flags=()
    [ "$grid" = miri ] && flags=(--cfg miri)
    rustc --edition 2024 --test "tests/$t.rs" -C instrument-coverage -C opt-level=1 "${flags[@]}" \
      --extern demcontact="$lib/libdemcontact.rlib" -L dependency="$lib/deps" -o "$out/$t.$grid"
    regions "$out/$t.$grid" > "$out/$t.$grid.regions"
  done
  missed=$(comm -23 "$out/$t.full.regions" "$out/$t.miri.regions")
  echo "$t: full grid $(wc -l < "$out/$t.full.regions") regions of src/, Miri grid $(wc -l < "$out/$t.miri.regions"), missed $(grep -c . <<< "$missed" || true)"
  if [ -n "$missed" ]; then
    echo "$missed" | sed 's/^/  missed: /'
    status=1
  fi
done
exit $status
