#!/usr/bin/env bash
# Builds everything (Rust library, header, C/C++ tests and examples) and runs the main demo.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
./build/examples_cpp/alpha_table
