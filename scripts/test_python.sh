#!/usr/bin/env bash
# Builds and tests the Python package (python/): a venv (.venv-python), maturin/numpy/pytest/
# matplotlib from PyPI, `pip install ./python`, the C library for the ctypes reference, then
# pytest (python/tests, including the YADE client test, which skips only where YADE cannot be
# installed). Exits non-zero when any step or any test fails.
#
#   scripts/test_python.sh            # everything
#   scripts/test_python.sh -k batch   # extra arguments go to pytest
set -euo pipefail
cd "$(dirname "$0")/.."

PY="${PYTHON:-python3}"
VENV=.venv-python
if [ ! -x "$VENV/bin/python" ]; then
    "$PY" -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install -q --upgrade pip
"$VENV/bin/python" -m pip install -q "maturin>=1.9.4,<2" numpy pytest matplotlib mypy
# The package, built by maturin through pip from the workspace (release profile).
"$VENV/bin/python" -m pip install -q --force-reinstall --no-deps ./python
# The C library the tests compare against, bit for bit.
cargo build --release --locked --lib -p demcontact
# Run from the repository root so that `import demcontact` is the installed package.
"$VENV/bin/pytest" -q python/tests "$@"
