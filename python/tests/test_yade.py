"""The YADE client: python/examples/yade/restitution.py run by Debian's YADE 2023.02a with this
package built for YADE's interpreter (/usr/bin/python3). Skips only where YADE cannot be
installed (prints `SKIPPED: yade_client (<reason>)`).

Checks: with demcontact's parameters YADE realises the target e within 2e-3 in a sphere-wall and
a sphere-sphere collision (e = 0.3, 0.5, 0.9). YADE's own `ViscElMat(tc, en, et)` calibration
realises what demcontact predicts for it (the overlap-zero damping under YADE's force clamp, and
against a wall with YADE's reduced mass m/2 in place of m), to the same 2e-3.
"""

from __future__ import annotations

import glob
import math
import os
import pathlib
import shutil
import subprocess
import sys
import zipfile

import pytest

import demcontact as dc

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "python" / "examples" / "yade" / "restitution.py"
TARGETS = [0.3, 0.5, 0.9]


def find_yade():
    if shutil.which("yade"):
        return shutil.which("yade"), ""
    if os.name == "posix" and os.geteuid() == 0 and shutil.which("apt-get"):
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        for cmd in (["apt-get", "update"], ["apt-get", "install", "-y", "--no-install-recommends", "yade"]):
            r = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=1800)
            if r.returncode != 0:
                return None, f"`{' '.join(cmd)}` failed: {r.stderr.strip().splitlines()[-1:] or r.returncode}"
        if shutil.which("yade"):
            return shutil.which("yade"), ""
        return None, "apt-get installed no `yade` executable"
    return None, "no `yade` on PATH and no root apt-get to install Debian's yade"


def skip(reason):
    print(f"SKIPPED: yade_client ({reason})", flush=True)
    pytest.skip(reason)


@pytest.fixture(scope="module")
def yade_results(tmp_path_factory):
    yade, why = find_yade()
    if yade is None:
        skip(why)
    tmp = tmp_path_factory.mktemp("yade")
    # The package for YADE's interpreter: an abi3 wheel from maturin, unpacked on PYTHONPATH.
    maturin = shutil.which("maturin", path=os.path.dirname(sys.executable)) or shutil.which("maturin")
    assert maturin, "maturin not installed (scripts/test_python.sh installs it)"
    subprocess.run(
        [maturin, "build", "--release", "-q", "-m", str(ROOT / "python" / "Cargo.toml"), "-o", str(tmp / "wheel")],
        check=True,
    )
    (wheel,) = glob.glob(str(tmp / "wheel" / "*.whl"))
    zipfile.ZipFile(wheel).extractall(tmp / "site")
    env = dict(os.environ, PYTHONPATH=str(tmp / "site"))
    r = subprocess.run(
        [yade, "-n", "-x", str(SCRIPT), *map(str, TARGETS)],
        env=env,
        capture_output=True,
        text=True,
        timeout=1800,
        cwd=tmp,
    )
    rows = {}
    for line in r.stdout.splitlines():
        if line.startswith("RESULT "):
            _, scene, route, e, got = line.split()
            rows[(scene, route, float(e))] = float(got)
            print(line)
    assert r.returncode == 0 and rows, f"yade failed ({r.returncode}):\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return rows


@pytest.mark.parametrize("scene", ["sphere-wall", "sphere-sphere"])
@pytest.mark.parametrize("e", TARGETS)
def test_yade_realises_target_with_demcontact_parameters(yade_results, scene, e):
    got = yade_results[(scene, "demcontact", e)]
    assert abs(got - e) <= 2e-3, (scene, e, got)


@pytest.mark.parametrize("scene", ["sphere-wall", "sphere-sphere"])
@pytest.mark.parametrize("e", TARGETS)
def test_yade_builtin_tc_en_realises_what_demcontact_predicts(yade_results, scene, e):
    # ViscElMat(tc, en): zeta = zeta_O(en) for the reduced mass YADE uses, m/2 against a
    # massless fixed wall where the true one is m: zeta_true = zeta_O(en) / sqrt(2) there.
    alpha = dc.alpha_from_e(e, 1.0, dc.Criterion.OVERLAP)
    if scene == "sphere-wall":
        alpha /= math.sqrt(2.0)
    predicted = dc.e_from_alpha(alpha, 1.0, dc.Criterion.FORCE)
    got = yade_results[(scene, "yade_tc_en", e)]
    assert abs(got - predicted) <= 2e-3, (scene, e, got, predicted)
    if e < 0.9:
        assert abs(got - e) > 2e-2  # the uncorrected input misses the target
