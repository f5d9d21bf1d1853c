#!/usr/bin/env bash
# Installs what a fresh machine lacks to build and test demcontact: CMake, C/C++/Fortran compilers,
# pkg-config, and the DejaVu font the report generator draws text with. Idempotent; uses apt-get when run as root (or via sudo), otherwise only checks.
set -euo pipefail
need=()
command -v cmake >/dev/null || need+=(cmake)
command -v cc >/dev/null || need+=(gcc)
command -v c++ >/dev/null || need+=(g++)
command -v gfortran >/dev/null || need+=(gfortran)
command -v pkg-config >/dev/null || need+=(pkg-config)
# The report generator (cargo run --release --example report) draws its text with this TTF.
[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || need+=(fonts-dejavu-core)
if ((${#need[@]})); then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  echo "setup: installing ${need[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
command -v cargo >/dev/null || { echo "setup: cargo (Rust toolchain) is required" >&2; exit 1; }
