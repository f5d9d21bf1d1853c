#!/usr/bin/env bash
# Checks too long for every CI run (scripts/test.sh), for a release or after a change to the CMake
# graph: more clean parallel CMake builds in a row than CI's one. CI's build (step cmake_build) is
# one clean -j4 build on a fresh clone; a race between targets that fails a given build with
# probability p is caught by one CI run with probability p, by this script with
# 1 - (1 - p)^N. Exits non-zero at the first failure.
#
#   scripts/long_checks.sh [N]     (default N = 5 clean builds, -j4)
# Environment: as scripts/parallel_builds.sh (DC_PB_DIR, DC_PB_CARGO_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-5}"
scripts/parallel_builds.sh "$n" 4
echo "long checks: ok"
