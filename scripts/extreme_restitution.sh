#!/usr/bin/env bash
# The set-up exports (dc_dt_for_accuracy, its step-aware form, dc_plan) at e = 1e-1 ... 1e-K,
# both end criteria: status, answer and wall time, as a markdown table (scripts/extreme_restitution.c).
#   scripts/extreme_restitution.sh [K]     default K = 20; about 5 minutes (the step-aware search at
#                                           e -> 0 with the overlap criterion is the slow part)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --locked --lib -q
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cc -O2 -Iinclude scripts/extreme_restitution.c target/release/libdemcontact.a -lm -lpthread -ldl -o "$out/extreme"
"$out/extreme" "${1:-20}"
