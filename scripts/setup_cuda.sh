#!/usr/bin/env bash
# Installs NVIDIA's CUDA compiler from PyPI into a virtual environment (default .venv-cuda in the
# repository; override with DC_CUDA_VENV) for ctest's inline_cuda: nvcc compiles
# include/demcontact_inline.h as CUDA (device code to PTX and cubins, host side run against the
# library). No GPU and no driver needed. Pinned: CUDA 13.0.88 (nvcc, cicc/libnvvm, the crt and
# runtime headers, static cudart), whose nvcc accepts GCC up to 15 as host compiler (here GCC 12).
# Idempotent (an existing venv with this nvcc is kept). Without network it says so and exits 0:
# inline_cuda then reports SKIPPED (listed by scripts/test.sh).
set -uo pipefail
cd "$(dirname "$0")/.."
venv="${DC_CUDA_VENV:-$PWD/.venv-cuda}"
version=13.0.88
pins=(nvidia-cuda-nvcc==$version nvidia-nvvm==$version nvidia-cuda-crt==$version
      nvidia-cuda-runtime==$version)
nvcc_in() { compgen -G "$1/lib/python3*/site-packages/nvidia/cu13/bin/nvcc" | head -n 1; }
nvcc=$(nvcc_in "$venv")
if [ -n "$nvcc" ] && "$nvcc" --version 2>/dev/null | grep -q "V$version"; then
  echo "setup_cuda: nvcc $version present in $venv"
  exit 0
fi
echo "setup_cuda: pip install ${pins[*]} into $venv"
if ! { python3 -m venv "$venv" && "$venv/bin/pip" install -q "${pins[@]}"; }; then
  echo "setup_cuda: could not install nvcc from PyPI: ctest inline_cuda will SKIP" >&2
  exit 0
fi
nvcc=$(nvcc_in "$venv")
if [ -z "$nvcc" ] || ! "$nvcc" --version | grep -q "V$version"; then
  echo "setup_cuda: the wheels installed no working nvcc $version: ctest inline_cuda will SKIP" >&2
fi
exit 0
