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
