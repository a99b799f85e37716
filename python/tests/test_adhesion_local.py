"""The local Griffith criterion and the adhesive sinusoid from Python,
against the exact values the Rust tests use."""

import math
import pickle
import warnings

import numpy as np
import pytest

import layered_contact as lc

RUBBER = lc.Material(1e6, 0.48)
ESTAR = 1e6 / (1 - 0.48**2)


def test_kendall_punch_release_is_uniform_and_exact():
    # A disc punch 32 cells across held at 1 um: G = E* d^2 / (2 pi a)
    # everywhere on the edge. The disc's edge is fitted by its angular
    # modes: the same rate at every cell (to rounding), within the 0.45 / N
    # of the material forces (1.4 %; measured -0.79 %).
    n, spacing = 64, 1e-4
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), n, n, spacing)
    punch = lc.Indenter.flat_punch(1.6e-3)
    x = (np.arange(n) + 0.5 - n / 2) * spacing
    contact = x[:, None] ** 2 + x[None, :] ** 2 < 1.6e-3**2
    edge = lc.edge_release(solver, punch, 1e-6, contact)
    a = math.sqrt(contact.sum() / math.pi) * spacing - 0.117 * spacing
    exact = ESTAR * 1e-12 / (2 * math.pi * a)
    assert edge["fit"] == "modes" and edge["fit_functions"] == 5
    rates = edge["release_rate"]
    assert np.ptp(rates) < 1e-9 * rates.mean()
    assert np.all(np.abs(rates / exact - 1) < 0.014)
    assert np.all(edge["stress_intensity"] < 0)  # a pushing punch
    assert edge["force"] > 0
    # Outward normals: along the position vector.
    radial = edge["normal_x"] * edge["x"] + edge["normal_y"] * edge["y"]
    assert np.all(radial / np.hypot(edge["x"], edge["y"]) > 0.95)


def test_jkr_sphere_edge_is_fitted_by_nine_modes():
    # The JKR sphere's pull-off contact, 32 cells across, held at the JKR
    # depth of its effective radius: a digital disc under a quadratic face,
    # fitted by nine modes; every edge cell within 1.5 % of dgamma (1.36 %
    # measured at the worst; the Rust doc example of edge_release).
    radius, work = 0.01, 0.05
    a = (9 * math.pi * work * radius**2 / (8 * ESTAR)) ** (1 / 3)
    n, spacing = 48, 2 * a / 32
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), n, n, spacing)
    x = (np.arange(n) + 0.5 - n / 2) * spacing
    contact = x[:, None] ** 2 + x[None, :] ** 2 < a**2
    r = (math.sqrt(contact.sum() / math.pi) - 0.117) * spacing
    depth = r * r / radius - math.sqrt(2 * math.pi * r * work / ESTAR)
    edge = lc.edge_release(solver, lc.Indenter.paraboloid(radius), depth, contact)
    assert edge["fit"] == "modes" and edge["fit_functions"] == 9
    assert np.all(np.abs(edge["release_rate"] / work - 1) < 0.015)


def test_edge_release_refuses_a_wrong_mask():
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), 16, 16, 1e-4)
    punch = lc.Indenter.flat_punch(5e-4)
    with pytest.raises(lc.InvalidInputError):
        lc.edge_release(solver, punch, 1e-6, np.ones((15, 16), dtype=bool))
    with pytest.raises(lc.InvalidInputError):
        lc.edge_release(solver, punch, 1e-6, np.zeros((16, 16), dtype=bool), window=0.5)


def test_johnson_sinusoid_pull_off():
    # Westergaard plus the periodic punch: at the pull-off the slope of
    # pbar(psi) = p* (sin^2 psi - alpha sqrt(tan psi)) vanishes.
    wavelength, amplitude, work = 1e-3, 2e-5, 0.05
    pressure, half_width = lc.analytic.jkr_sinusoid_pull_off(RUBBER, wavelength, amplitude, work)
    p_star = math.pi * ESTAR * amplitude / wavelength
    alpha = math.sqrt(2 * wavelength * work / (math.pi**2 * amplitude**2 * ESTAR))
    psi = math.pi * half_width / wavelength
    exact = p_star * (math.sin(psi) ** 2 - alpha * math.sqrt(math.tan(psi)))
    assert pressure == pytest.approx(exact, rel=1e-12)
    pbar = lambda s: math.sin(s) ** 2 - alpha * math.sqrt(math.tan(s))  # noqa: E731
    assert pbar(psi) <= min(pbar(psi * 0.99), pbar(psi * 1.01))
    with pytest.raises(lc.LayeredContactError):
        lc.analytic.jkr_sinusoid_pull_off(RUBBER, wavelength, 1e-7, work)


def test_cohesive_zone_sinusoid_along_the_grid_and_at_45_degrees():
    # Johnson's sinusoid (alpha = 0.3) through the default cohesive zone of
    # 4 cells, 64 cells per wavelength: along the grid on 64^2 cells, at 45
    # degrees on 91^2 (64.35 cells per wavelength). The Rust example
    # (examples/cohesive_convergence.rs) measures -1.78 % along and -1.77 %
    # at 45 degrees here (+0.34 and -0.61 % at 128 cells, -0.02 and +0.12 %
    # at 256; with a zone of 8 cells -4.40 and -4.12 % here).
    work, spacing = 0.05, 1e-5
    errors = []
    for n, wave in [(64, (1, 0)), (91, (1, 1))]:
        side = n * spacing
        wavelength = side / math.hypot(*wave)
        amplitude = math.sqrt(2 * wavelength * work / (math.pi**2 * ESTAR)) / 0.3
        surface = lc.Indenter.wavy(n, n, spacing, wave, amplitude)
        solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), n, n, spacing, periodic=True)
        force = solver.cohesive_pull_off(surface, 0.6 * amplitude, amplitude / 40, work).force
        exact, _ = lc.analytic.jkr_sinusoid_pull_off(RUBBER, wavelength, amplitude, work)
        errors.append(force / side**2 / exact - 1)
    assert errors[0] == pytest.approx(-0.0178, abs=1e-3)
    assert abs(errors[0] - errors[1]) < 5e-3


def test_cohesive_zone_wider_than_the_pull_off_contact_warns():
    # Johnson's sinusoid along the grid, 64 cells a wavelength: at alpha =
    # 0.05 the contact at the least force is one line wide, under the zone's
    # four cells, and the pull-off 5.1 % weak (the Rust test
    # tests/cohesive_limits.rs); at alpha = 0.3 it is resolved.
    work, spacing, n = 0.05, 1e-5, 64
    side = n * spacing
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), n, n, spacing, periodic=True)

    def pull_off(alpha):
        amplitude = math.sqrt(2 * side * work / (math.pi**2 * ESTAR)) / alpha
        surface = lc.Indenter.wavy(n, n, spacing, (1, 0), amplitude)
        found = solver.cohesive_pull_off(surface, 0.6 * amplitude, amplitude / 40, work)
        exact, _ = lc.analytic.jkr_sinusoid_pull_off(RUBBER, side, amplitude, work)
        return found, found.force / side**2 / exact - 1

    with pytest.warns(lc.CohesiveZoneWarning, match="refine the grid"):
        found, error = pull_off(0.05)
    assert error < -0.03
    # The warning's reason, on the result: the contact at the least force
    # is narrower than the zone (its four cells).
    assert found.zone_spans_contact and found.cells_across < found.zone_cells == 4.0
    # It pickles (Dask returns it from workers) to the same fields.
    again = pickle.loads(pickle.dumps(found))
    assert (again.force, again.depth, again.iterations) == (found.force, found.depth, found.iterations)
    with warnings.catch_warnings():
        warnings.simplefilter("error", lc.CohesiveZoneWarning)
        found, error = pull_off(0.3)
    assert abs(error) < 0.02
    # A resolved contact: wider than the zone, and the solves and their
    # iterations counted (each solve at least one iteration).
    assert not found.zone_spans_contact and found.cells_across > found.zone_cells
    assert 1 <= found.solves <= found.iterations


def test_cohesive_zone_refuses_bad_laws():
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), 16, 16, 1e-4)
    sphere = lc.Indenter.sphere(1e-2)
    with pytest.raises(lc.InvalidInputError):
        solver.solve_depth_cohesive(sphere, 1e-6, 0.05, receding=0.01)
    with pytest.raises(lc.InvalidInputError):
        solver.solve_depth_cohesive(sphere, 1e-6, 0.05, zone_cells=1.0)
    with pytest.raises(lc.InvalidInputError):
        solver.cohesive_pull_off(sphere, 1e-6, 0.0, 0.05)


def test_peel_punch_disc_at_kendall_and_square_later():
    # Kendall's disc comes off at its onset; a square height map (64 cells
    # across on 80^2 cells) after its corners start to detach, at 472.2 uN
    # over 64^1.5 (the Rust test tests/peel_punch.rs and BENCHMARKS.md).
    spacing, work = 1e-4, 0.05
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), 48, 48, spacing)
    disc = lc.peel_punch(solver, lc.Indenter.flat_punch(16 * spacing), work)
    assert disc["detaches_at_onset"]
    radius = math.sqrt(disc["contact_area"][0] / math.pi) - 0.117 * spacing
    kendall = -math.sqrt(8 * math.pi * ESTAR * work * radius**3)
    assert disc["pull_off_force"] == pytest.approx(kendall, rel=0.02)
    assert disc["force"][0] == disc["pull_off_force"]
    # The bonded face's stiffness: 2 E* a.
    assert disc["stiffness"][0] == pytest.approx(2 * ESTAR * radius, rel=0.02)
    assert np.all(np.diff(disc["contact_cells"].astype(np.int64)) < 0)
    # The whole face is a disc: fitted by its modes.
    assert disc["fitted_by_modes"][0]
    n, side = 80, 64
    heights = np.full((n, n), np.inf)
    lo = (n - side) // 2
    heights[lo:lo + side, lo:lo + side] = 0.0
    square = lc.Indenter.height_map(heights, spacing)
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), n, n, spacing)
    path = lc.peel_punch(solver, square, work)
    assert not path["detaches_at_onset"]
    assert -path["pull_off_force"] / side**1.5 * 1e6 == pytest.approx(472.2, rel=3e-3)
    assert path["pull_off_force"] < 1.1 * path["force"][0]
    # A sphere has no rim inside the grid.
    with pytest.raises(lc.LayeredContactError, match="without a rim"):
        lc.peel_punch(solver, lc.Indenter.sphere(1e-2), work)
    # Tilted: a tenth of Kendall's critical depth across the radius; the
    # onset within the staircase's 2 % of the exact force-and-moment one
    # (tests/peel_punch.rs), the pull-off beyond it.
    a = 16 * spacing
    critical = math.sqrt(2 * math.pi * a * work / ESTAR)
    tilt = 0.1 * critical / a
    solver = lc.ContactSolver(lc.Substrate.half_space(RUBBER), 48, 48, spacing)
    tilted = lc.peel_punch(solver, lc.Indenter.flat_punch(a).tilted(0.0, tilt), work)
    radius = math.sqrt(tilted["contact_area"][0] / math.pi) - 0.117 * spacing
    critical = math.sqrt(2 * math.pi * radius * work / ESTAR)
    onset = 2 * ESTAR * radius * (2 * radius * tilt - critical)
    assert tilted["force"][0] == pytest.approx(onset, rel=0.02)
    assert tilted["pull_off_force"] <= tilted["force"][0]
    # From a part of the face (the half at negative x): the path starts
    # where it is bonded and holds less than the whole face.
    centres = (np.arange(48) + 0.5 - 24) * spacing
    x, y = np.meshgrid(centres, centres, indexing="ij")
    half = (x < 0) & (np.hypot(x, y) <= a)
    part = lc.peel_punch(solver, lc.Indenter.flat_punch(a), work, bonded=half)
    assert part["contact_cells"][0] == half.sum()
    assert disc["pull_off_force"] < part["pull_off_force"] < 0.0
    with pytest.raises(lc.LayeredContactError):
        lc.peel_punch(solver, lc.Indenter.flat_punch(a), work, bonded=half[:40])


def test_cohesive_zone_grown_with_the_resolution():
    # cells_across sizes the zone as the crate's CohesiveZone::with_resolution:
    # max(4, sqrt(N) / 2) cells, 8 at 256 across, 4 up to 64.
    substrate = lc.Substrate.half_space(RUBBER)
    sphere = lc.Indenter.sphere(1e-2)
    depth = 1e-6

    def solved(**law):
        solver = lc.ContactSolver(substrate, 32, 32, 4e-5)
        return solver.solve_depth_cohesive(sphere, depth, 0.05, **law).force

    assert solved(cells_across=256.0) == solved(zone_cells=8.0)
    assert solved(cells_across=32.0) == solved()
    assert solved(zone_cells=8.0) != solved()
    with pytest.raises(lc.InvalidInputError):
        solved(zone_cells=8.0, cells_across=256.0)
    with pytest.raises(lc.InvalidInputError):
        solved(cells_across=0.5)


def test_force_controlled_cohesive_solve_follows_jkr():
    # From the equilibrium at 1.5 pull-off radii, JKR's force at 1.2 radii
    # (Johnson, Kendall & Roberts 1971) by one fixed point under force
    # control: the force to rounding, the depth within the zone's error
    # (5 % of the critical depth at 12 cells across the radius), and the
    # depth-controlled solve at that depth, from the state it reached, gives
    # the same force (1e-9; the crate's unit test measures 2e-11). A pull
    # beyond JKR's load-controlled pull-off has no equilibrium.
    radius, work = 1e-2, 0.05
    e_star = RUBBER.contact_modulus
    a0 = (9 * math.pi * work * radius**2 / (8 * e_star)) ** (1 / 3)

    def jkr_force(a):
        return 4 * e_star * a**3 / (3 * radius) - math.sqrt(8 * math.pi * work * e_star * a**3)

    def jkr_depth(a):
        return a * a / radius - math.sqrt(2 * math.pi * work * a / e_star)

    critical = abs(jkr_depth(a0 / 4 ** (1 / 3)))
    substrate = lc.Substrate.half_space(RUBBER)
    sphere = lc.Indenter.sphere(radius)
    solver = lc.ContactSolver(substrate, 48, 48, 4 * a0 / 48)
    with pytest.raises(lc.InvalidInputError):
        solver.solve_force_cohesive(sphere, jkr_force(1.2 * a0), work)
    solver.solve_depth_cohesive(sphere, jkr_depth(1.5 * a0), work)
    force = jkr_force(1.2 * a0)
    pulled = solver.solve_force_cohesive(sphere, force, work)
    assert abs(pulled.force / force - 1) < 1e-12
    assert abs(pulled.depth - jkr_depth(1.2 * a0)) < 0.05 * critical
    again = solver.solve_depth_cohesive(sphere, pulled.depth, work, warm_start=True)
    assert abs(again.force - pulled.force) < 1e-9 * abs(force)
    with pytest.raises(lc.ConvergenceError):
        solver.solve_force_cohesive(sphere, 1.2 * -1.5 * math.pi * radius * work, work)


def test_wavy_surface_heights():
    # Indenter.wavy: amplitude (1 - cos(2 pi phase)), the phase an exact
    # fraction of the period, as numpy's from the cell indices.
    n, spacing, amplitude = 12, 1e-5, 2e-6
    surface = lc.Indenter.wavy(n, n, spacing, (1, 2), amplitude)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    phase = ((i + 2 * j) % n) / n
    centres = (np.arange(n) + 0.5 - n / 2) * spacing
    x, y = np.meshgrid(centres, centres, indexing="ij")
    expected = amplitude * (1 - np.cos(2 * math.pi * phase))
    assert np.abs(surface.height(x, y) - expected).max() <= 1e-21
    with pytest.raises(lc.InvalidInputError):
        lc.Indenter.wavy(n, n, spacing, (0, 0), amplitude)
    with pytest.raises(lc.InvalidInputError):
        lc.Indenter.wavy(n, n, spacing, (1, 0), -1.0)
