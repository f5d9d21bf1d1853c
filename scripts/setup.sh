#!/usr/bin/env bash
# Installs what a fresh machine lacks to build and test demcontact: CMake, C/C++/Fortran compilers,
# clang (with its fuzzer runtime), pkg-config, and the DejaVu font the report generator draws text with. Idempotent; uses apt-get when run as root (or via sudo), otherwise only checks.
set -euo pipefail
need=()
command -v cmake >/dev/null || need+=(cmake)
command -v cc >/dev/null || need+=(gcc)
command -v c++ >/dev/null || need+=(g++)
command -v gfortran >/dev/null || need+=(gfortran)
command -v pkg-config >/dev/null || need+=(pkg-config)
# The report generator (cargo run --release --example report) draws its text with this TTF.
[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || need+=(fonts-dejavu-core)
# clang for ctest's inline_clang / inline_cuda_stub and its fuzzer runtime for scripts/fuzz.sh:
# installed here, before ctest, so that a fresh machine's first run skips neither.
command -v clang >/dev/null || need+=(clang)
ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1 || need+=(libclang-rt-14-dev)
if ((${#need[@]})); then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  echo "setup: installing ${need[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
command -v cargo >/dev/null || { echo "setup: cargo (Rust toolchain) is required" >&2; exit 1; }
