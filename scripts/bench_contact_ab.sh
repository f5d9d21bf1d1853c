#!/usr/bin/env bash
# Before/after of the full-contact batches: builds examples_cpp/bench/contact_bench at REV (a
# temporary git worktree) and at the working tree, then runs the two alternately ROUNDS times and
# prints the batch rows of each run. Compare the fastest of each variant: the two libraries are
# timed on the same machine within minutes of each other, which is what makes the ratio fair on
# a shared machine.
#   scripts/bench_contact_ab.sh REV [ROUNDS]      e.g. scripts/bench_contact_ab.sh 90a080b 3
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:?usage: scripts/bench_contact_ab.sh REV [ROUNDS]}
rounds=${2:-3}
old=$(mktemp -d)
trap 'git worktree remove --force "$old" >/dev/null 2>&1 || true' EXIT
git worktree add --detach "$old" "$rev" >/dev/null
for dir in "$old" "$PWD"; do
  cmake -S "$dir" -B "$dir/build-bench" -DCMAKE_BUILD_TYPE=Release -DDEMCONTACT_NATIVE=OFF >/dev/null
  cmake --build "$dir/build-bench" -j2 --target contact_bench >/dev/null
done
for i in $(seq "$rounds"); do
  for side in before after; do
    if [ "$side" = before ]; then dir=$old; else dir=$PWD; fi
    echo "== $side ($([ "$side" = before ] && echo "$rev" || echo "working tree")) round $i, $(date -u +%H:%M) UTC, load $(cut -d' ' -f1 /proc/loadavg)"
    "$dir/build-bench/bench/contact_bench" | grep -E 'dc_contact_force_batch(_fused)? \|'
  done
done
