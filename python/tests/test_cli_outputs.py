"""NumPy reads back what the command-line tool writes (run when
LAYERED_CONTACT_CLI names the tool's binary, as .ci/run does)."""

import csv
import os
import subprocess

import numpy as np
import pytest

import layered_contact as lc

CLI = os.environ.get("LAYERED_CONTACT_CLI")

SCENE = """
[substrate]
kind = "layer_on_rigid_base"
youngs_modulus = 0.324e6
poisson_ratio = 0.48
thickness = 5e-3

[indenter]
kind = "paraboloid"
radius = 0.05

[protocol]
kind = "depth"
depth = 1e-4

[resolution]
cells_across = 32

[outputs.fields]
pressure = true
gap = true
"""


@pytest.mark.skipif(not CLI, reason="LAYERED_CONTACT_CLI is not set")
def test_fields_read_back_with_numpy(tmp_path):
    scene = tmp_path / "ball.toml"
    scene.write_text(SCENE)
    done = subprocess.run([CLI, "run", str(scene), "-o", str(tmp_path / "out")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    out = tmp_path / "out"
    pressure = np.load(out / "pressure.npy")
    gap = np.load(out / "gap.npy")
    x, y = np.load(out / "x.npy"), np.load(out / "y.npy")
    assert pressure.shape == gap.shape == (x.size, y.size)
    # The same scene from Python gives the same numbers.
    curve = lc.run_scene(str(scene))
    np.testing.assert_array_equal(pressure, curve.peak.pressure)
    np.testing.assert_array_equal(x, curve.peak.x)
    spacing = x[1] - x[0]
    with open(out / "curve.csv") as f:
        row = next(csv.DictReader(f))
    assert float(row["force_N"]) == pytest.approx(pressure.sum() * spacing**2, rel=1e-12)
    # The pressure is centred on the axis: its first moments vanish.
    assert abs((pressure.sum(axis=1) * x).sum()) < 1e-9 * np.abs(pressure.sum(axis=1) * x).sum() + 1e-30
