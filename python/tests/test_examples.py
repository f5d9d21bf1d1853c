"""The example scripts run and write their figures (PNG files, non-trivial size)."""

import pathlib
import subprocess
import sys

import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "examples"
SCRIPTS = {
    "clamping_realised_e.py": ["clamping_realised_e.png"],
    "seed_figures.py": [
        "seed_alpha_vs_e.png",
        "seed_force_history.png",
        "seed_dmax_vs_e.png",
        "seed_tau_vs_zeta.png",
        "seed_phase_portrait.png",
        "seed_viscoelastic_e.png",
    ],
    "dt_for_accuracy.py": ["dt_for_accuracy.png"],
    "chung_ooi_oblique.py": ["chung_ooi_oblique.png"],
}


@pytest.mark.parametrize("script", sorted(SCRIPTS))
def test_example_writes_its_figures(script, tmp_path):
    r = subprocess.run([sys.executable, script, str(tmp_path)], cwd=EXAMPLES, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    for png in SCRIPTS[script]:
        f = tmp_path / png
        assert f.exists() and f.stat().st_size > 10_000 and f.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", png


def test_quickstart_prints_independent_values():
    """The README's Python quick start (examples/quickstart.py) runs and prints what an independent
    computation gives: alpha from the force-zero calibration, e = exp(-2 z arccos(z) / sqrt(1 - z^2))
    solved for z by bisection (alpha = z sqrt(2 (p + 1))), and the third contact's force, at vn = 0
    purely elastic: (4/3) E* sqrt(R*) overlap^1.5 with E* = E / (2 (1 - nu^2)) for equal materials."""
    import math

    r = subprocess.run([sys.executable, "quickstart.py"], cwd=EXAMPLES, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    alpha = float(lines[0].split("=")[1])
    lo, hi = 1e-9, 1 - 1e-12
    for _ in range(200):
        z = 0.5 * (lo + hi)
        e = math.exp(-2 * z * math.acos(z) / math.sqrt(1 - z * z))
        lo, hi = (z, hi) if e > 0.5 else (lo, z)
    assert abs(alpha - z * math.sqrt(5)) <= 1e-12 * alpha, (alpha, z * math.sqrt(5))
    forces = [float(x) for x in lines[1].split("=")[1].strip(" []").split()]
    e_star = 63e9 / (2 * (1 - 0.23**2))
    elastic = 4 / 3 * e_star * math.sqrt(5e-4) * 1e-5**1.5
    assert len(forces) == 3 and abs(forces[2] - elastic) <= 1e-6 * elastic, (forces, elastic)
    assert 0 < forces[0] < forces[1] < forces[2]
