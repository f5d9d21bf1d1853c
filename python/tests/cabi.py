"""The C ABI through ctypes: the reference every Python function is compared against.

Loads target/release/libdemcontact.so built by `cargo build --release --lib` (scripts/
test_python.sh does it; DEMCONTACT_CLIB overrides the path). Nothing here computes physics.
"""

from __future__ import annotations

import ctypes as C
import os
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _load() -> C.CDLL:
    path = os.environ.get("DEMCONTACT_CLIB") or str(ROOT / "target" / "release" / "libdemcontact.so")
    if not os.path.exists(path):
        raise RuntimeError(
            f"C library not found at {path}: run `cargo build --release --lib` (scripts/test_python.sh does)"
        )
    return C.CDLL(path)


lib = _load()
D = C.c_double
I32 = C.c_int32
PD = C.POINTER(D)


class Pair(C.Structure):
    _fields_ = [
        ("model", I32),
        ("kernel", I32),
        ("criterion", I32),
        ("clamp", I32),
        ("p", D),
        ("stiffness", D),
        ("alpha", D),
        ("damping_a", D),
        ("e", D),
        ("k", D),
        ("c", D),
        ("h", D),
    ]


class Energy(C.Structure):
    _fields_ = [("e", D), ("loading", D), ("unloading", D), ("returned", D), ("clamped", D)]


class Plan(C.Structure):
    _fields_ = [
        ("tag", C.c_uint64),
        ("p", D),
        ("q", D),
        ("amp", D),
        ("lgamma_q", D),
        ("ln_aq", D),
        ("level", I32),
        ("n", I32),
        ("nodes", D * 16),
        ("weights", D * 16),
    ]


def fn(name: str, argtypes, restype=I32):
    f = getattr(lib, "dc_" + name)
    f.argtypes = argtypes
    f.restype = restype
    return f


lib.dc_status_str.argtypes = [I32]
lib.dc_status_str.restype = C.c_char_p
lib.dc_version.argtypes = []
lib.dc_version.restype = C.c_char_p


def call_scalar(name: str, order: str, args):
    """Calls dc_<name> whose parameters follow `order` ('d' double, 'i' int32), then one
    double*. Returns (status, value or None)."""
    f = fn(name, [D if ch == "d" else I32 for ch in order] + [PD])
    out = D(-12345.0)
    s = f(*args, C.byref(out))
    return s, (out.value if s == 0 else None)
