#!/usr/bin/env bash
# Builds everything (Rust library, header, C/C++ tests and examples) and runs the main demo.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >build/configure.log
# What was left out and why (a simulator plugin without its simulator), not CMake's whole log.
sed -n 's/^-- demcontact: /demcontact: /p' build/configure.log
cmake --build build -j2
./build/examples_cpp/alpha_table
