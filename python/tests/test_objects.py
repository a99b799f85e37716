"""Value types print as the constructor calls that rebuild them and survive
pickling (multiprocessing, Dask)."""

import pickle

import layered_contact as lc

RUBBER = lc.Material(0.324e6, 0.48)
GLASS = lc.Material(70e9, 0.22)
NAMES = {"Substrate": lc.Substrate, "Material": lc.Material}


def test_materials_and_substrates_round_trip():
    # Each body, pickled and rebuilt from its repr, has the exact flat-punch
    # stiffness of the original to the last bit (a solution of the layered
    # Fredholm equation, so every parameter of the body enters it).
    bodies = [
        lc.Substrate.half_space(RUBBER),
        lc.Substrate.layer_on_rigid_base(RUBBER, 5e-3),
        lc.Substrate.layer_on_elastic_base(RUBBER, 5e-3, GLASS),
        lc.Substrate.layer_resting_on_rigid_base(RUBBER, 5e-3),
        lc.Substrate.layer_resting_on_elastic_base(RUBBER, 5e-3, GLASS),
        lc.Substrate.stack([(RUBBER, 1e-3), (GLASS, 2e-3)], RUBBER),
        lc.Substrate.stack([(RUBBER, 1e-3), (GLASS, 2e-3)]),
    ]
    stiffnesses = set()
    for body in bodies:
        text = repr(body)
        assert text.startswith("Substrate.") and "Stack {" not in text and "Some(" not in text
        exact = lc.analytic.flat_punch_stiffness(body, 2e-3)
        stiffnesses.add(exact)
        for copy in (pickle.loads(pickle.dumps(body)), eval(text, NAMES)):
            assert repr(copy) == text
            assert lc.analytic.flat_punch_stiffness(copy, 2e-3) == exact
    assert len(stiffnesses) == len(bodies)
    material = pickle.loads(pickle.dumps(RUBBER))
    assert (material.youngs_modulus, material.poisson_ratio) == (0.324e6, 0.48)
    assert eval(repr(RUBBER), NAMES).contact_modulus == RUBBER.contact_modulus


def test_a_curve_prints_its_stiffness_as_a_number():
    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "flat_punch", "radius": 1e-3},
        "protocol": {"kind": "depth", "depth": 1e-5},
        "resolution": {"cells_across": 16},
    }
    curve = lc.run_scene(scene)
    assert "Some(" not in repr(curve) and repr(curve).startswith("Curve(1 steps")


def test_a_contact_at_the_grid_edge_warns():
    # A flat punch wider than its isolated grid is in contact on every cell
    # (16 x 16 = 256) and reaches the edge: a warning, an error on request;
    # a punch inside the grid (its cells within the radius) does not warn.
    import warnings

    import pytest

    body = lc.Substrate.half_space(RUBBER)
    solver = lc.ContactSolver(body, 16, 16, 1e-4)
    with pytest.warns(lc.EdgeContactWarning, match="reaches the edge"):
        s = solver.solve_depth(lc.Indenter.flat_punch(5e-3), 1e-5)
    assert s.edge_contact and s.contact_cells == 256
    with warnings.catch_warnings():
        warnings.simplefilter("error", lc.EdgeContactWarning)
        with pytest.raises(lc.EdgeContactWarning):
            solver.solve_depth(lc.Indenter.flat_punch(5e-3), 1e-5)
        inside = solver.solve_depth(lc.Indenter.flat_punch(0.4e-3), 1e-5)
    assert not inside.edge_contact and 0 < inside.contact_cells < 256


def test_a_curve_as_a_table_and_as_csv(tmp_path):
    # The columns hold the curve's values (the same floats); the CSV has the
    # tool's curve.csv header and reads back to the last bit.
    import csv

    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "sphere", "radius": 0.01},
        "protocol": {"kind": "cycle", "max_depth": 1e-5, "steps": 4},
        "resolution": {"cells_across": 16},
    }
    curve = lc.run_scene(scene)
    table = lc.curve_table(curve)
    assert {len(v) for v in table.values()} == {len(curve)}
    assert list(table["force"]) == list(curve.force)
    path = tmp_path / "curve.csv"
    lc.write_curve_csv(curve, path)
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    assert rows[0] == ["phase", "depth_m", "force_N", "contact_area_m2", "contact_radius_m", "iterations"]
    assert [float(r[2]) for r in rows[1:]] == list(curve.force)
    assert [float(r[1]) for r in rows[1:]] == list(curve.depth)
    assert [r[0] for r in rows[1:]] == list(curve.phase)
    assert [int(r[5]) for r in rows[1:]] == list(curve.iterations)


def test_curves_and_their_fields_survive_pickling():
    # An adhesive cycle with the peak's fields and the stresses below it:
    # every array, dict and number comes back equal to the last bit.
    import numpy as np

    scene = {
        "substrate": {"kind": "layer_on_rigid_base", "youngs_modulus": 1e6, "poisson_ratio": 0.48,
                      "thickness": 1e-3},
        "indenter": {"kind": "paraboloid", "radius": 0.01},
        "adhesion": {"kind": "constant", "work_of_adhesion": 0.05},
        "protocol": {"kind": "cycle", "max_depth": 2e-6, "steps": 4},
        "resolution": {"cells_across": 16},
        "outputs": {"fields": {"pressure": True, "gap": True}, "stresses": {"depths": [1e-5]}},
    }
    curve = lc.run_scene(scene)
    copy = pickle.loads(pickle.dumps(curve))
    assert repr(copy) == repr(curve) and len(copy) == len(curve)
    for name in ("depth", "force", "contact_area", "contact_radius"):
        np.testing.assert_array_equal(getattr(copy, name), getattr(curve, name))
    for name in ("phase", "iterations", "stiffness", "pull_off", "grid", "caveats"):
        assert getattr(copy, name) == getattr(curve, name)
    assert curve.pull_off["force"] < 0
    np.testing.assert_array_equal(copy.peak.pressure, curve.peak.pressure)
    np.testing.assert_array_equal(copy.peak.gap, curve.peak.gap)
    assert copy.peak.displacement is None and copy.peak.force == curve.peak.force
    assert repr(copy.peak) == repr(curve.peak)
    np.testing.assert_array_equal(copy.stresses["von_mises"], curve.stresses["von_mises"])


def test_indenters_survive_pickling():
    # Each kind, tilted twice included, has the same heights after the
    # round trip, to the last bit, and prints the same.
    import numpy as np

    x, y = np.meshgrid(np.linspace(-4e-4, 4e-4, 9), np.linspace(-3e-4, 3e-4, 7))
    heights = np.add.outer(np.linspace(0.0, 1e-6, 8), np.linspace(0.0, 2e-6, 6)) ** 1.5
    indenters = [
        lc.Indenter.flat_punch(5e-4),
        lc.Indenter.sphere(1e-3),
        lc.Indenter.paraboloid(1e-3),
        lc.Indenter.cone(1.2, 5e-4),
        lc.Indenter.height_map(heights, 1e-4),
        lc.Indenter.rough_surface(0.8, 4e-4, 4e-5, 7, 16, 1e-5, rms_height=1e-7),
        lc.Indenter.paraboloid(1e-3).tilted(0.01, -0.02).tilted(0.0, 0.03),
    ]
    for indenter in indenters:
        copy = pickle.loads(pickle.dumps(indenter))
        assert repr(copy) == repr(indenter)
        np.testing.assert_array_equal(copy.height(x, y), indenter.height(x, y))
        assert copy.bounding_radius == indenter.bounding_radius


def test_rough_surfaces_are_the_scenes_own():
    # The heights have the asked rms and zero mean; the indenter is the
    # surface upside down; and a scene's rough_surface indenter is the same
    # surface: the same solve on the same grid gives the same force.
    import numpy as np
    import pytest

    args = dict(hurst=0.8, long_cutoff=3.2e-4, short_cutoff=4e-5, seed=11, cells=32, spacing=1e-5)
    h = lc.rough_surface_heights(**args, rms_height=2e-7)
    assert h.shape == (32, 32)
    assert np.sqrt(np.mean(h**2)) == pytest.approx(2e-7, rel=1e-12)
    assert abs(h.mean()) < 1e-15 * 2e-7 * h.size
    again = lc.rough_surface_heights(**args, rms_height=2e-7)
    np.testing.assert_array_equal(again, h)
    other = lc.rough_surface_heights(**dict(args, seed=12), rms_height=2e-7)
    assert np.abs(other - h).max() > 1e-8
    indenter = lc.Indenter.rough_surface(**args, rms_height=2e-7)
    centres = (np.arange(32) + 0.5 - 16) * 1e-5
    x, y = np.meshgrid(centres, centres, indexing="ij")
    np.testing.assert_allclose(indenter.height(x, y), h.max() - h, rtol=0, atol=1e-22)
    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": dict(kind="rough_surface", amplitude={"rms_height": 2e-7}, **args),
        "protocol": {"kind": "depth", "depth": 2e-7},
        "boundary": "periodic",
    }
    curve = lc.run_scene(scene)
    solver = lc.ContactSolver(lc.Substrate.half_space(lc.Material(1e6, 0.5)), 32, 32, 1e-5, periodic=True)
    assert solver.solve_depth(indenter, 2e-7).force == pytest.approx(curve.force[0], rel=1e-9)
    with pytest.raises(lc.InvalidInputError, match="exactly one"):
        lc.rough_surface_heights(**args, rms_height=1e-7, rms_slope=0.1)
    with pytest.raises(lc.InvalidInputError, match="exactly one"):
        lc.Indenter.rough_surface(**args)
    with pytest.raises(lc.InvalidInputError, match="cells"):
        lc.rough_surface_heights(**dict(args, cells=1), rms_slope=0.1)


def test_refined_heights_sample_the_same_surface():
    # A band-limited surface (two modes below the coarse Nyquist) sampled at
    # the centres of 6 x 8 cells, refined 3 times: the same surface at the
    # centres of the finer cells, to the FFTs' rounding (1e-13 of the
    # amplitude); the coarse heights come back at the middle fine cells.
    import numpy as np
    import pytest

    def sampled(rows, columns):
        x = (np.arange(rows) + 0.5) / rows
        y = (np.arange(columns) + 0.5) / columns
        x, y = np.meshgrid(x, y, indexing="ij")
        return 1e-6 * (np.cos(2 * np.pi * (x + 2 * y) + 0.4) + 0.5 * np.sin(2 * np.pi * 2 * x))

    coarse = sampled(6, 8)
    fine = lc.refine_heights(coarse, 3)
    assert fine.shape == (18, 24)
    np.testing.assert_allclose(fine, sampled(18, 24), rtol=0, atol=1e-19)
    np.testing.assert_allclose(fine[1::3, 1::3], coarse, rtol=0, atol=1e-19)
    with pytest.raises(lc.InvalidInputError, match="refinement factor"):
        lc.refine_heights(coarse, 0)
