#!/usr/bin/env bash
# The header-only contact (include/demcontact_inline.h) on a GPU against the library, bit for bit,
# and its throughput (examples_cpp/gpu/gpu_check.cu; docs/gpu.md says what it checks and reads).
#   scripts/gpu_check.sh [ARGS]               build with nvcc, run on the GPU (needs one)
#   scripts/gpu_check.sh --cpu-smoke [ARGS]   the same program on the CPU alone (no nvcc, no GPU)
# ARGS go to the program (gpu_check --help-like usage on a bad one). Exit status: the program's
# (0 identical, 1 a bit difference or a regime not reached, 2 bad arguments, 3 CUDA or set-up
# error); 3 also when a tool is missing; 124 when the run outlasts DC_GPU_CHECK_TIMEOUT seconds
# (default 420: the full run must end well inside 8 minutes on one H100/H200).
#
# What it needs:
#  - the library: target/release/libdemcontact.a (linked statically: the binary needs nothing of
#    the repository at run time). Built with `cargo build --release --lib` where cargo exists; where
#    it does not, or the build fails (the device machine: no network), the one found there is used
#    as it is, with its date printed.
#  - nvcc (GPU mode): DC_NVCC, else the venv of scripts/setup_cuda.sh (DC_CUDA_VENV, default
#    .venv-cuda: NVIDIA's wheels from PyPI), else nvcc on PATH or /usr/local/cuda/bin; none found:
#    scripts/setup_cuda.sh is run once, then it fails clearly. Flags: -fmad=false (no fused
#    products in device code besides the header's own __dmul_rn), host side -ffp-contract=off.
#    DC_GPU_ARCH (default sm_90: H100 and H200).
#
# On the device machine (the device tool: one call, a copy of the working tree, 16 cores, nvcc
# on PATH, no network, cargo probably absent), from a checkout where target/release/libdemcontact.a
# was built (cargo build --release --lib; 32 MB, ignored, so it must be carried):
#   command: set -o pipefail; scripts/gpu_check.sh 2>&1 | tee $OUT/gpu_check.log; rc=$?;
#            build-gpu/gpu_check --plant-ulp --contacts 100000 --normals 100000 --steps 20
#            --bench 65536 >$OUT/plant.log 2>&1; echo "plant run: exit $? (must be 1)"; exit $rc
#            (one line; the second run shows that the comparison catches a one-ulp difference
#            planted on the GPU)
#   carry:   ["target/release/libdemcontact.a"]
#   timeout_s: 540
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=build-gpu
mkdir -p "$out"
smoke=0
for a in "$@"; do [ "$a" = --cpu-smoke ] && smoke=1; done
fail() {
  echo "gpu_check.sh: $*" >&2
  exit 3
}

# the library
lib=target/release/libdemcontact.a
if command -v cargo >/dev/null 2>&1; then
  if ! nice cargo build --release --lib; then
    # a machine with cargo but without the crates (no network): the library found there, said so
    [ -f "$lib" ] || fail "cargo build --release --lib failed and there is no $lib"
    echo "gpu_check.sh: cargo build failed: using $lib as found ($(date -u -r "$lib" '+%F %T UTC'))"
  fi
elif [ -f "$lib" ]; then
  echo "gpu_check.sh: no cargo here: using $lib as found ($(date -u -r "$lib" '+%F %T UTC'))"
else
  fail "neither cargo nor $lib: build the library (cargo build --release --lib) or carry $lib"
fi
[ -f "$lib" ] || fail "$lib missing after the build"
# what a Rust static library needs beyond it (rustc --print native-static-libs, Linux)
native=(-lgcc_s -lutil -lrt -lpthread -lm -ldl)

if [ "$smoke" = 1 ]; then
  cxx=${CXX:-c++}
  command -v "$cxx" >/dev/null 2>&1 || fail "no C++ compiler ($cxx)"
  echo "gpu_check.sh: $cxx (host build: the CPU stand-in)"
  nice "$cxx" -std=c++17 -O2 -Wall -Wextra -Werror -ffp-contract=off -Iinclude \
    examples_cpp/gpu/gpu_check_cpu.cpp "$lib" "${native[@]}" -o "$out/gpu_check_cpu" ||
    fail "the host build failed"
  bin=$out/gpu_check_cpu
else
  nvcc_in() { compgen -G "$1/lib/python3*/site-packages/nvidia/cu*/bin/nvcc" | head -n 1; }
  find_nvcc() {
    local n=${DC_NVCC:-}
    [ -n "$n" ] || n=$(nvcc_in "${DC_CUDA_VENV:-$root/.venv-cuda}")
    [ -n "$n" ] || n=$(command -v nvcc || true)
    [ -n "$n" ] || { [ -x /usr/local/cuda/bin/nvcc ] && n=/usr/local/cuda/bin/nvcc; }
    echo "$n"
  }
  nvcc=$(find_nvcc)
  if [ -z "$nvcc" ]; then
    scripts/setup_cuda.sh
    nvcc=$(find_nvcc)
  fi
  [ -n "$nvcc" ] && [ -x "$nvcc" ] || fail "no nvcc (scripts/setup_cuda.sh could not install one; set DC_NVCC)"
  arch=${DC_GPU_ARCH:-sm_90}
  echo "gpu_check.sh: $nvcc ($("$nvcc" --version | tail -n 1)), -arch=$arch"
  # static cudart: next to a PyPI nvcc in ../lib, in a toolkit in lib64 (nvcc finds that itself)
  nvlib=$(dirname "$nvcc")/../lib
  # warnings shown, not fatal: the device machine's nvcc and host compiler are not the pinned ones
  # (ctest gpu_check_nvcc builds with -Werror against the pinned nvcc)
  nice "$nvcc" -std=c++17 -O3 -arch="$arch" -fmad=false \
    -Xcompiler -Wall,-Wextra,-ffp-contract=off -Iinclude examples_cpp/gpu/gpu_check.cu \
    "$lib" -L"$nvlib" "${native[@]}" -o "$out/gpu_check" || fail "the nvcc build failed"
  bin=$out/gpu_check
  if command -v nvidia-smi >/dev/null 2>&1; then
    nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader ||
      echo "gpu_check.sh: nvidia-smi failed (the program reports the device itself)"
  fi
fi
timeout "${DC_GPU_CHECK_TIMEOUT:-420}" "$bin" "$@"
rc=$?
[ "$rc" = 124 ] && echo "gpu_check.sh: the run outlasted ${DC_GPU_CHECK_TIMEOUT:-420} s" >&2
exit "$rc"
