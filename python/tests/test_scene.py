"""Scenes from dicts and files, progress callbacks, references, errors."""

import math

import pytest

import layered_contact as lc

PUNCH = {
    "substrate": {"kind": "layer_on_rigid_base", "youngs_modulus": 0.324e6, "poisson_ratio": 0.48, "thickness": 5e-3},
    "indenter": {"kind": "flat_punch", "radius": 2.5e-3},
    "protocol": {"kind": "cycle", "max_depth": 1e-4, "steps": 4},
    "resolution": {"cells_across": 32},
    "outputs": {"fields": {"pressure": True}},
}


def test_punch_cycle_against_the_exact_stiffness():
    steps = []
    curve = lc.run_scene(PUNCH, progress=steps.append)
    assert len(steps) == len(curve) == len(curve.depth)
    assert steps[0]["phase"] == "loading" and curve.phase[-1] == "unloading"
    exact = lc.scene_reference(PUNCH)["stiffness"]
    film = lc.Substrate.layer_on_rigid_base(lc.Material(0.324e6, 0.48), 5e-3)
    assert exact == pytest.approx(lc.analytic.flat_punch_stiffness(film, 2.5e-3), rel=1e-12)
    # 32 cells across the punch: the equal-area staircase is softer by a
    # clean c / N (c = 0.37 at this a/h = 0.5, doc::accuracy): measured
    # -1.116 %; twice as fine halves it.
    assert curve.stiffness / exact - 1 == pytest.approx(-0.37 / 32, abs=1e-3)
    rows, columns, _ = curve.grid
    assert curve.peak.pressure.shape == (rows, columns)



def test_adhesive_cone_against_the_jkr_cone():
    # The JKR cone on a half-space (Maugis & Barquins 1981): pull-off
    # -54 dgamma^2 tan^3(theta) / (pi E*); the reference is the exact
    # axisymmetric cone's, found by minimisation to 1e-10.
    cone = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.48},
        "indenter": {"kind": "cone", "half_angle": 1.3, "base_radius": 1e-3},
        "adhesion": {"kind": "constant", "work_of_adhesion": 0.05},
        "protocol": {"kind": "force_cycle", "max_force": 1e-7, "steps": 3},
        "resolution": {"cells_across": 16},
    }
    modulus = 1e6 / (1 - 0.48**2)
    jkr = -54 * 0.05**2 * math.tan(1.3) ** 3 / (math.pi * modulus)
    exact = lc.scene_reference(cone)["pull_off_force"]
    assert exact == pytest.approx(jkr, rel=1e-9)
    # At 16 cells across the pull-off contact: -0.12 % (measured).
    assert lc.run_scene(cone).pull_off["force"] == pytest.approx(exact, rel=1e-2)

def test_scene_file_and_check(tmp_path):
    path = tmp_path / "punch.toml"
    path.write_text(
        '[substrate]\nkind = "half_space"\nyoungs_modulus = 1e6\npoisson_ratio = 0.5\n'
        '[indenter]\nkind = "flat_punch"\nradius = 1e-3\n'
        '[protocol]\nkind = "depth"\ndepth = 1e-5\n'
    )
    grid = lc.check_scene(path)
    assert grid["rows"] == grid["columns"] > 64 and grid["memory_bytes"] > 0
    curve = lc.run_scene(str(path))
    assert curve.force[0] == pytest.approx(2 * 1e6 / 0.75 * 1e-3 * 1e-5, rel=0.01)


def test_custom_indenter_in_a_scene():
    scene = dict(PUNCH, protocol={"kind": "depth", "depth": 1e-4}, outputs={})
    tilted = lc.Indenter.flat_punch(2.5e-3).tilted(0.0, 0.0)
    curve = lc.run_scene(scene, indenter=tilted)
    reference = lc.run_scene(scene)
    assert curve.force[0] == pytest.approx(reference.force[0], rel=0.02)


def test_file_errors_name_line_and_key(tmp_path):
    path = tmp_path / "typo.toml"
    path.write_text('[substrate]\nkind = "half_space"\nyoungs_modulus = 1e6\npoisson_ratio = 0.5\n'
                    '[indenter]\nkind = "sphere"\nradus = 0.01\n[protocol]\nkind = "depth"\ndepth = 1e-5\n')
    with pytest.raises(lc.InvalidInputError, match=r"typo.toml: line 7, key `radus`: unknown field `radus`"):
        lc.run_scene(path)
    with pytest.raises(lc.InvalidInputError, match="No such file"):
        lc.check_scene(tmp_path / "missing.toml")


def test_errors():
    typo = dict(PUNCH, indenter={"kind": "flat_punch", "radus": 1e-3})
    with pytest.raises(lc.InvalidInputError, match="unknown field `radus`, expected `radius`"):
        lc.run_scene(typo)
    with pytest.raises(lc.InvalidInputError, match="cells_across must be between 8 and 8192"):
        lc.check_scene(dict(PUNCH, resolution={"cells_across": 2}))

    def fail(step):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        lc.run_scene(PUNCH, progress=fail)


SPHERE = {
    "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.48},
    "indenter": {"kind": "paraboloid", "radius": 0.01},
    "adhesion": {"kind": "constant", "work_of_adhesion": 0.05},
    "protocol": {"kind": "cycle", "max_depth": 2e-5, "steps": 4},
    "resolution": {"cells_across": 16},
}


def test_caveats_say_when_adhesion_is_edge_averaged():
    # Axisymmetric: exact JKR balance, no caveat; the pull-off within 0.5 %
    # of JKR's -3/2 pi dgamma R at 16 cells across (0.25 % measured).
    curve = lc.run_scene(SPHERE)
    assert curve.caveats == []
    assert curve.pull_off["force"] == pytest.approx(-1.5 * 3.141592653589793 * 0.05 * 0.01, rel=5e-3)
    # A tilted paraboloid is a paraboloid moved off the axis: its sets are
    # discs about its apex, the energy balance stays exact (no caveat).
    tilt = {"angle_y": 0.05, "angle_x": 0.0}
    tilted = lc.run_scene(dict(SPHERE, tilt=tilt))
    assert tilted.caveats == []
    assert tilted.pull_off["force"] == pytest.approx(curve.pull_off["force"], rel=2e-3)
    # The energy balance on a tilted sphere (cap) averages over its edge.
    cap = dict(SPHERE, tilt=tilt, indenter={"kind": "sphere", "radius": 0.01},
               solver={"adhesion_method": "energy_balance"})
    averaged = lc.run_scene(cap)
    assert len(averaged.caveats) == 1 and "edge-averaged" in averaged.caveats[0]
    # Automatically the tilted cap takes the cohesive zone: no caveat, and a
    # pull-off within its second-order error of JKR (-1.95 % centred at 16
    # cells across, tests/cohesive.rs; this cap -2.89 %, as the same scene in
    # tests/scene_cohesive.rs; the cap is the paraboloid to 0.1 %).
    zone = lc.run_scene(dict(cap, solver={}))
    assert zone.caveats == [] and zone.adhesion_method == "cohesive_zone"
    assert curve.adhesion_method == "energy_balance"
    assert lc.run_scene(PUNCH).adhesion_method is None
    assert zone.pull_off["force"] / curve.pull_off["force"] - 1 == pytest.approx(-0.029, abs=0.005)
    # The mesh-dependent criterion says what it is.
    mesh = lc.run_scene(dict(SPHERE, solver={"adhesion_method": "mesh_criterion"}))
    assert len(mesh.caveats) == 1 and "mesh-dependent" in mesh.caveats[0]


def test_every_example_scene_meets_the_schema():
    # The schema is generated from the scene types; each example scene file
    # (TOML through tomllib, JSON) validates, and a misspelt key does not.
    jsonschema = pytest.importorskip("jsonschema")
    import json
    import pathlib
    import sys

    if sys.version_info < (3, 11):
        pytest.skip("tomllib needs Python 3.11")
    import tomllib

    schema = lc.scene_schema()
    folder = pathlib.Path(__file__).resolve().parents[2] / "examples" / "scenes"
    files = sorted(folder.glob("**/*.toml")) + sorted(folder.glob("**/*.json"))
    assert len(files) >= 5
    for path in files:
        text = path.read_text()
        scene = json.loads(text) if path.suffix == ".json" else tomllib.loads(text)
        jsonschema.validate(scene, schema)
    misspelt = dict(PUNCH, indenter={"kind": "flat_punch", "radus": 2.5e-3})
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(misspelt, schema)
    jsonschema.validate(PUNCH, schema)


def test_a_mistake_in_a_dict_names_its_key_path():
    with pytest.raises(lc.InvalidInputError, match=r"key `indenter\.radius`: invalid type"):
        lc.run_scene(dict(PUNCH, indenter={"kind": "flat_punch", "radius": "big"}))
    with pytest.raises(lc.InvalidInputError, match=r"key `indenter\.radus`: unknown field"):
        lc.check_scene(dict(PUNCH, indenter={"kind": "flat_punch", "radus": 2.5e-3}))
    layers = [
        {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "thickness": 1e-3},
        {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "thickness": None},
    ]
    with pytest.raises(lc.InvalidInputError, match=r"key `substrate\.layers\[1\]\.thickness`"):
        lc.check_scene(dict(PUNCH, substrate={"kind": "stack", "layers": layers}))


def test_plot_curve_draws_both_phases_and_the_pull_off():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import numpy as np

    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "paraboloid", "radius": 0.01},
        "adhesion": {"kind": "constant", "work_of_adhesion": 0.05},
        "protocol": {"kind": "cycle", "max_depth": 2e-6, "steps": 5},
        "resolution": {"cells_across": 16},
    }
    curve = lc.run_scene(scene)
    ax = lc.plot_curve(curve)
    lines = {line.get_label(): line for line in ax.get_lines()}
    phase = np.asarray(curve.phase)
    for name in ("loading", "unloading"):
        x, y = lines[name].get_data()
        np.testing.assert_array_equal(x, np.asarray(curve.depth)[phase == name] / 1e-6)
        np.testing.assert_array_equal(y, np.asarray(curve.force)[phase == name])
    marker = next(line for label, line in lines.items() if label.startswith("pull-off"))
    assert marker.get_ydata()[0] == curve.pull_off["force"] < 0


def test_iteration_reports_come_before_the_steps_of_an_adhesive_run():
    # The energy balance reports each contact set of its family as it is
    # solved, all before the first step;
    # a step-by-step run reports every CG iteration, those of the coarser
    # grids of its cold starts included (so at least the steps' own).
    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "paraboloid", "radius": 0.01},
        "protocol": {"kind": "cycle", "max_depth": 2e-6, "steps": 3},
        "resolution": {"cells_across": 32},
    }
    events = []
    curve = lc.run_scene(scene, progress=lambda s: events.append(("step", s)),
                         iteration=lambda i: events.append(("set", i)))
    assert sum(1 for kind, _ in events if kind == "set") >= sum(curve.iterations) > 0
    events = []
    adhesive = dict(scene, adhesion={"kind": "constant", "work_of_adhesion": 0.05})
    curve = lc.run_scene(adhesive, progress=lambda s: events.append(("step", s)),
                         iteration=lambda i: events.append(("set", i)))
    sets = [info for kind, info in events if kind == "set"]
    assert len(sets) >= 10 and len(events) == len(sets) + len(curve)
    assert all(kind == "set" for kind, _ in events[: len(sets)])
    # Counted from 1 in each family built (a family widened to reach the
    # load is built again), each from its largest set down.
    for a, b in zip(sets, sets[1:]):
        if b["iteration"] != 1:
            assert b["iteration"] == a["iteration"] + 1
            assert b["contact_cells"] < a["contact_cells"]
    assert sets[0]["iteration"] == 1
    assert max(s["residual"] for s in sets) < 1e-7

    def stop(info):
        raise RuntimeError("stop at the first set")

    with pytest.raises(RuntimeError, match="first set"):
        lc.run_scene(adhesive, iteration=stop)


def test_plot_field_draws_the_peak_pressure():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import numpy as np

    scene = dict(PUNCH, outputs={"fields": {"pressure": True, "gap": True}})
    curve = lc.run_scene(scene)
    ax = lc.plot_field(curve.peak)
    mesh = ax.collections[0]
    np.testing.assert_array_equal(np.asarray(mesh.get_array()).ravel(), curve.peak.pressure.ravel())
    assert ax.figure.axes[-1].get_ylabel() == "pressure [Pa]"
    gap = lc.plot_field(curve.peak, "gap")
    assert gap.figure.axes[-1].get_ylabel() == "gap [m]"
    with pytest.raises(ValueError, match="no displacement"):
        lc.plot_field(curve.peak, "displacement")
    with pytest.raises(ValueError, match="expected one of"):
        lc.plot_field(curve.peak, "stress")


def test_force_control_of_a_tilted_cap_runs_through_the_cohesive_zone():
    # Force control of a shape whose contact sets are not discs takes the
    # cohesive zone (it took the edge-averaged energy balance): every force
    # as asked (to 1e-6 of the largest, or the nearer side of a snap of the
    # path as a cell joins the zone: at most one step, within 1e-3), the
    # pull-off at the zone's own error at 16 cells across (-2.52 %; -2.89 %
    # under displacement control), then a step without contact.
    jkr = -1.5 * 3.141592653589793 * 0.05 * 0.01
    cap = dict(SPHERE, tilt={"angle_y": 0.05, "angle_x": 0.0},
               indenter={"kind": "sphere", "radius": 0.01},
               protocol={"kind": "force_cycle", "max_force": -2 * jkr, "steps": 4})
    curve = lc.run_scene(cap)
    assert curve.adhesion_method == "cohesive_zone" and curve.caveats == []
    asked = [k * -2 * jkr / 4 for k in range(5)]
    off = [abs(f - a) / (-2 * jkr) for f, a in zip(curve.force[:5], asked)]
    assert max(off) <= 1e-3 and sum(o > 1e-6 for o in off) <= 1, off
    assert curve.pull_off["force"] / jkr - 1 == pytest.approx(-0.025, abs=0.005)
    assert curve.force[-1] == 0.0 and curve.contact_area[-1] == 0.0


def test_a_square_punch_map_unloads_along_its_peeling_path(tmp_path):
    # A square flat punch as a height map (inf beyond its face): the
    # automatic method takes the cohesive zone, whose depth-controlled
    # unloading of the face bonded whole follows the peeling path; the
    # curve's pull-off is the path's (lc.peel_punch on the same grid).
    import numpy as np

    n, side, spacing = 48, 32, 1e-4
    heights = np.full((n, n), np.inf)
    lo = (n - side) // 2
    heights[lo:lo + side, lo:lo + side] = 0.0
    path = tmp_path / "square.npy"
    np.save(path, heights)
    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.48},
        "indenter": {"kind": "height_map", "path": str(path), "spacing": spacing},
        "adhesion": {"kind": "constant", "work_of_adhesion": 0.05},
        "protocol": {"kind": "cycle", "max_depth": 1e-6, "steps": 4},
    }
    curve = lc.run_scene(scene)
    assert curve.adhesion_method == "cohesive_zone"
    solver = lc.ContactSolver(lc.Substrate.half_space(lc.Material(1e6, 0.48)), n, n, spacing)
    peeled = lc.peel_punch(solver, lc.Indenter.height_map(heights, spacing), 0.05)
    assert curve.pull_off["force"] == pytest.approx(peeled["pull_off_force"], rel=1e-6)
    assert not peeled["detaches_at_onset"]
    assert curve.force[-1] == 0.0


def test_a_tilted_punch_comes_off_by_the_local_criterion():
    # A 1 mm disc tilted by a tenth of Kendall's critical depth across its
    # radius: the automatic method loads it through the cohesive zone and
    # unloads it along its peeling path, coming off 1 to 2 % beyond the
    # exact onset of a punch under force and moment (1.0151 at 32 cells
    # across, tests/scene_tilted_punch.rs); the energy balance, the
    # automatic method before, 7.6 % beyond with its caveat.
    import math

    estar = 1e6 / 0.75
    kendall = math.sqrt(8 * math.pi * 1e-9 * estar * 0.3)
    tilt = 0.1 * kendall / (2e-3 * estar) / 1e-3
    onset = -kendall + 4e-6 * estar * tilt
    scene = {
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "flat_punch", "radius": 1e-3},
        "tilt": {"angle_y": tilt},
        "adhesion": {"kind": "constant", "work_of_adhesion": 0.3},
        "protocol": {"kind": "cycle", "max_depth": 2e-5, "steps": 10},
        "resolution": {"cells_across": 32},
    }
    curve = lc.run_scene(scene)
    assert curve.adhesion_method == "cohesive_zone" and curve.caveats == []
    assert 1.0 <= curve.pull_off["force"] / onset <= 1.03
    balance = lc.run_scene(dict(scene, solver={"adhesion_method": "energy_balance"}))
    assert len(balance.caveats) == 1
    assert balance.pull_off["force"] / onset > 1.05


def test_auto_peels_a_punch_whose_stiffness_barely_changes():
    # A 0.1 m punch on 1 kPa over a stiff plate over a 0.19 Pa base (the
    # reference sweep's seed 159): the bonded punch's (A / k) dk/dA is
    # 0.0039 at its face (0.5 on a half-space), so the automatic method
    # peels it by the local criterion (+0.39 % of the exact pull-off at 32
    # cells across, tests/punch_peeling.rs) where the energy balance is
    # -5.95 % off, flagged.
    layers = [
        {"youngs_modulus": 1e3, "poisson_ratio": 0.45, "thickness": 9.624654318820577e-3},
        {"youngs_modulus": 7.238902357342152e5, "poisson_ratio": 0, "thickness": 2.8840133077183354e-2},
    ]
    scene = {
        "substrate": {"kind": "stack", "layers": layers,
                      "base": {"youngs_modulus": 0.19, "poisson_ratio": 0}},
        "indenter": {"kind": "flat_punch", "radius": 0.1},
        "adhesion": {"kind": "constant", "work_of_adhesion": 100.0},
        "protocol": {"kind": "cycle", "max_depth": 5e-6, "steps": 4},
        "resolution": {"cells_across": 32},
    }
    exact = lc.scene_reference(scene)["pull_off_force"]
    curve = lc.run_scene(scene)
    assert curve.adhesion_method == "cohesive_zone" and curve.caveats == []
    assert curve.pull_off["force"] / exact - 1 == pytest.approx(0.0039, abs=0.006)
    balance = lc.run_scene(dict(scene, solver={"adhesion_method": "energy_balance"}))
    assert balance.adhesion_method == "energy_balance"
    assert any("stiffness barely changes" in c for c in balance.caveats)
    assert abs(balance.pull_off["force"] / exact - 1) > 0.02


def test_zone_scales_mark_a_zone_stiffer_than_the_contact():
    """The sweep's seed 74 (a paraboloid on a 57 GPa layer 24.1 um thick
    resting on a base 3850 times softer, 16 cells across): the two-cell zone
    is 2.93 times the layer (two cells of the grid the curve reports, over
    the scene's thickness), the body about 450 times as stiff at the zone's
    length as at the peak contact's (360 at the exact peak radius, more at
    the coarse run's wider one; BENCHMARKS.md, "The zone stiffer than the
    contact"), and the curve carries both caveats: its pull-off is 40 % too
    strong."""
    import pathlib
    import pickle

    path = (pathlib.Path(__file__).resolve().parents[2] / "examples" / "scenes"
            / "long_zone" / "stiff_layer_far_softer_base.toml")
    curve = lc.run_scene(str(path))
    scales = curve.zone_scales
    assert scales["cells"] == 2.0
    assert scales["length"] == pytest.approx(2 * curve.grid[2], rel=1e-12)
    assert scales["length"] / scales["layer_thickness"] == pytest.approx(2.93, abs=0.01)
    assert 300 < scales["modulus_ratio"] < 600
    assert scales["contact_radius"] == pytest.approx(max(curve.contact_radius), rel=1e-12)
    assert len(curve.caveats) == 2 and "far stiffer than the contact" in curve.caveats[1]
    exact = lc.scene_reference(str(path))["pull_off_force"]
    assert 0.35 < curve.pull_off["force"] / exact - 1 < 0.45
    assert pickle.loads(pickle.dumps(curve)).zone_scales == scales
    # Without a layer there are no scales.
    half = lc.run_scene({
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "sphere", "radius": 1e-3},
        "adhesion": {"kind": "constant", "work_of_adhesion": 0.05},
        "protocol": {"kind": "cycle", "max_depth": 2e-6, "steps": 4},
        "resolution": {"cells_across": 16},
        "solver": {"adhesion_method": "cohesive_zone"},
    })
    assert half.zone_scales is None and half.caveats == []
