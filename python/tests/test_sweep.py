"""A parameter sweep on a Dask LocalCluster equals the same scenes run here."""

import pytest

distributed = pytest.importorskip("dask.distributed")

import layered_contact as lc  # noqa: E402
from layered_contact.sweep import run_scenes  # noqa: E402


def scene(radius):
    return {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "flat_punch", "radius": radius},
        "protocol": {"kind": "cycle", "max_depth": 1e-5, "steps": 2},
        "resolution": {"cells_across": 16},
    }


def test_sweep_on_a_local_cluster():
    radii = [0.5e-3, 1e-3, 2e-3]
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            results = run_scenes(client, [scene(a) for a in radii])
    assert len(results) == len(radii)
    for a, result in zip(radii, results):
        serial = lc.run_scene(scene(a))
        assert result["stiffness"] == serial.stiffness
        # 16 cells across: within 2 % of 2 E* a.
        assert result["stiffness"] == pytest.approx(2 * 1e6 / 0.75 * a, rel=0.02)
