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
