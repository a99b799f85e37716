"""The solver from Python: arrays, shapes, Hertz, height maps, warm starts."""

import math

import numpy as np
import pytest

import layered_contact as lc

RUBBER = lc.Material(1e6, 0.5)
HALF_SPACE = lc.Substrate.half_space(RUBBER)


def test_hertz_and_fields():
    n, spacing, r, d = 64, 2e-5, 0.01, 1e-5
    solver = lc.ContactSolver(HALF_SPACE, n, n + 8, spacing)
    s = solver.solve_depth(lc.Indenter.paraboloid(r), d)
    # 32 cells across the Hertz contact: force within 0.1 %.
    assert s.force == pytest.approx(lc.analytic.hertz_force(RUBBER, r, d), rel=1e-3)
    assert s.pressure.shape == (n, n + 8)
    assert s.gap.shape == s.displacement.shape == (n, n + 8)
    assert s.x.shape == (n,) and s.y.shape == (n + 8,)
    assert s.x[0] == pytest.approx(-(n - 1) / 2 * spacing)
    assert s.pressure.sum() * spacing**2 == pytest.approx(s.force, rel=1e-12)
    # The gap is closed under pressure, to the solver tolerance (1e-8).
    assert np.all(np.abs(s.gap[s.pressure > 0]) < 1e-8 * d)
    assert np.all(s.gap[s.pressure == 0] >= -1e-8 * d)
    assert s.contact_cells == int((s.pressure > 0).sum())


def test_height_map_equals_its_shape():
    n, spacing = 48, 2e-5
    shape = lc.Indenter.paraboloid(0.01)
    x = (np.arange(n) + 0.5 - n / 2) * spacing
    xx, yy = np.meshgrid(x, x, indexing="ij")
    heights = shape.height(xx, yy)
    assert heights.shape == (n, n)
    solver = lc.ContactSolver(HALF_SPACE, n, n, spacing)
    direct = solver.solve_depth(shape, 8e-6)
    mapped = solver.solve_depth(lc.Indenter.height_map(heights, spacing), 8e-6)
    assert mapped.force == pytest.approx(direct.force, rel=1e-12)


def test_force_control_and_warm_start():
    solver = lc.ContactSolver(HALF_SPACE, 64, 64, 2e-5)
    ball = lc.Indenter.sphere(0.01)
    first = solver.solve_force(ball, 2e-3)
    again = solver.solve_force(ball, 2e-3, warm_start=True)
    assert first.force == pytest.approx(2e-3, rel=1e-9)
    assert again.depth == pytest.approx(first.depth, rel=1e-7)
    assert again.iterations < first.iterations


def test_bad_inputs_raise():
    with pytest.raises(lc.InvalidInputError, match="force"):
        lc.ContactSolver(HALF_SPACE, 16, 16, 1e-5).solve_force(lc.Indenter.sphere(0.01), -1.0)
    with pytest.raises(lc.InvalidInputError, match="heights"):
        lc.Indenter.height_map(np.full((4, 4), np.nan), 1e-5)
    with pytest.raises(lc.InvalidInputError):
        lc.ContactSolver(HALF_SPACE, 0, 16, 1e-5)
    with pytest.raises(TypeError):
        lc.Indenter.height_map(np.zeros(5), 1e-5)


def test_solves_release_the_gil():
    import threading

    solver = lc.ContactSolver(HALF_SPACE, 512, 512, 2e-6)
    ball = lc.Indenter.paraboloid(0.01)
    counter, stop = [0], [False]

    def spin():
        while not stop[0]:
            counter[0] += 1

    thread = threading.Thread(target=spin)
    thread.start()
    try:
        before = counter[0]
        solver.solve_depth(ball, 1e-6)  # about 0.3 s
        during = counter[0] - before
    finally:
        stop[0] = True
        thread.join()
    # Holding the GIL would freeze the other thread for the whole solve
    # (a count of a few at most); released, it counts millions.
    assert during > 10_000


def test_rough_contact_outputs_along_a_force_protocol():
    # A seeded rough surface on a periodic half-space under three loads:
    # the mean gap is the gap field's mean (the indenter covers the grid),
    # falls as the load grows while the contact fraction grows, survives
    # pickling, and the multi-resolution start's iterations are reported.
    import pickle

    n, spacing = 64, 1e-6
    heights = lc.rough_surface_heights(hurst=0.8, long_cutoff=16e-6, short_cutoff=4e-6, seed=3,
                                       cells=n, spacing=spacing, rms_slope=0.1)
    indenter = lc.Indenter.height_map(heights.max() - heights, spacing)
    solver = lc.ContactSolver(lc.Substrate.half_space(lc.Material(1e6, 0.5)), n, n, spacing,
                              periodic=True)
    area = (n * spacing) ** 2
    gaps, fractions = [], []
    for pressure in (2e3, 5e3, 1e4):
        s = solver.solve_force(indenter, pressure * area)
        assert s.mean_gap == pytest.approx(float(np.mean(s.gap)), rel=1e-12)
        gaps.append(s.mean_gap)
        fractions.append(s.contact_area / area)
    assert gaps[0] > gaps[1] > gaps[2] > 0.0
    assert fractions[0] < fractions[1] < fractions[2] < 1.0
    assert s.coarse_iterations > 0
    copy = pickle.loads(pickle.dumps(s))
    assert copy.mean_gap == s.mean_gap and copy.coarse_iterations == s.coarse_iterations
    # A punch narrower than its isolated grid leaves the gap infinite
    # beyond its rim: no mean gap.
    punch = lc.ContactSolver(lc.Substrate.half_space(lc.Material(1e6, 0.5)), 32, 32, 1e-5)
    assert punch.solve_depth(lc.Indenter.flat_punch(1e-4), 1e-6).mean_gap is None


def test_interface_curve_follows_westergaard():
    # Westergaard's wavy surface (plane strain, periodic): contact fraction
    # (2/pi) asin(sqrt(s)), mean gap u/D = 1 - s + s ln s and interfacial
    # stiffness p*/(D ln(1/s)), s = p/p*, p* = pi E* D / lambda. On 256
    # cells per wavelength the BEM's mean gap is within 2e-4 of it (Rust's
    # tests/interface.rs), so the central difference at s = 0.3 between
    # loads 2 % apart is within its truncation error: measured 7e-5 (mean
    # gap) and 4.6e-4 (stiffness), asserted 4e-4 and 1 %.
    wavelength, amplitude, n = 1e-3, 1e-6, 256
    material = lc.Material(1e6, 0.5)
    estar = 1e6 / (1 - 0.25)
    p_star = math.pi * estar * amplitude / wavelength
    spacing = wavelength / n
    x = (np.arange(n) + 0.5 - n / 2) * spacing
    heights = np.repeat((amplitude * (1 - np.cos(2 * math.pi * x / wavelength)))[:, None], 8, axis=1)
    solver = lc.ContactSolver(lc.Substrate.half_space(material), n, 8, spacing, periodic=True)
    s = np.array([0.294, 0.3, 0.306])
    curve = lc.interface_curve(solver, lc.Indenter.height_map(heights, spacing), s * p_star)
    exact_gap = amplitude * (1 - s + s * np.log(s))
    np.testing.assert_allclose(curve["mean_gap"], exact_gap, rtol=4e-4)
    np.testing.assert_allclose(curve["contact_fraction"], 2 / math.pi * np.arcsin(np.sqrt(s)),
                               atol=2.0 / n)
    exact_stiffness = p_star / (amplitude * math.log(1 / 0.3))
    assert abs(curve["stiffness"][1] / exact_stiffness - 1) < 0.01, curve["stiffness"]
    assert len(curve["gaps"]) == 3 and curve["gaps"][0].shape == (n, 8)
    with pytest.raises(lc.InvalidInputError, match="increasing"):
        lc.interface_curve(solver, lc.Indenter.height_map(heights, spacing), [2e3, 1e3])


def test_two_level_preconditioner_on_a_rough_contact():
    """`coarse_blocks` (the crate's `ContactSolver::set_coarse_blocks`): the
    problem of `benches/peers/rough.py` at 512^2 (a seeded rough surface on a
    periodic half-space of E* = 1, mean pressure 0.01, about a fifth in
    contact) solves to the box's pressures (within 1e-6 of the largest at
    the default tolerance 1e-8) in fewer fine iterations (measured 27 with
    the box, 19 with blocks of 16, which join once the contact count has
    settled; at 256^2 21 and 18); the solver's own choice (`None`, the
    default) keeps the box below 1024^2 cells: the box's iterations exactly,
    and no blocks (the `coarse_blocks` property: 16 where they were set).
    `last_preconditioning` reports it: no solve yet, then the choice made
    after the same iterations in both (the box's run alike up to there),
    the box's factor (measured 0.555) above the 0.5 the automatic choice
    asks of a grid from 1024^2 to below 2048^2 (this one is too small for
    blocks), and the blocks' iterations counted: all those after
    the choice but the ones after a move of the contact count. Blocks that
    do not divide a periodic grid are refused, naming them, and so is a
    name other than "box"."""
    n = 512
    heights = lc.rough_surface_heights(
        hurst=0.8, long_cutoff=0.25, short_cutoff=4.0 / n, seed=1, cells=n,
        spacing=1.0 / n, rms_slope=0.1)
    surface = lc.Indenter.height_map(heights.max() - heights, 1.0 / n)
    body = lc.Substrate.half_space(lc.Material(1.0, 0.0))
    boxed = lc.ContactSolver(body, n, n, 1.0 / n, periodic=True, coarse_blocks="box").solve_force(
        surface, 0.01)
    choosing = lc.ContactSolver(body, n, n, 1.0 / n, periodic=True)
    assert choosing.last_preconditioning is None
    chosen = choosing.solve_force(surface, 0.01)
    assert choosing.coarse_blocks is None
    kept = choosing.last_preconditioning
    assert kept["blocks"] is None and kept["two_level_iterations"] == 0
    assert kept["box_factor"] > 0.5 and kept["decided_after"] < chosen.iterations
    solver = lc.ContactSolver(body, n, n, 1.0 / n, periodic=True, coarse_blocks=16)
    assert solver.coarse_blocks == 16
    two = solver.solve_force(surface, 0.01)
    taken = solver.last_preconditioning
    assert taken["decided_after"] == kept["decided_after"]
    assert taken["box_factor"] == kept["box_factor"]
    assert taken["blocks"] == 16
    assert 1 <= taken["two_level_iterations"] <= two.iterations - taken["decided_after"]
    assert np.max(np.abs(two.pressure - boxed.pressure)) <= 1e-6 * boxed.pressure.max()
    assert two.iterations + 5 <= boxed.iterations
    assert chosen.iterations == boxed.iterations
    with pytest.raises(lc.InvalidInputError, match="coarse blocks"):
        lc.ContactSolver(body, n, n, 1.0 / n, periodic=True, coarse_blocks=12)
    with pytest.raises(lc.InvalidInputError, match="coarse_blocks"):
        lc.ContactSolver(body, n, n, 1.0 / n, periodic=True, coarse_blocks="boxes")
