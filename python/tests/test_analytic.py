"""The analytic functions against closed forms written out here."""

import math

import numpy as np
import pytest

import layered_contact as lc

RUBBER = lc.Material(1e6, 0.5)
E_STAR = 1e6 / 0.75


def test_contact_modulus():
    assert RUBBER.contact_modulus == pytest.approx(E_STAR, rel=1e-15)


def test_hertz_vectorised():
    depth = np.array([[1e-6, 4e-6, 9e-6], [0.0, 1e-5, 2e-5]])
    force = lc.analytic.hertz_force(RUBBER, 0.01, depth)
    assert force.shape == (2, 3)
    np.testing.assert_allclose(force, 4 / 3 * E_STAR * math.sqrt(0.01) * depth**1.5, rtol=1e-14)
    radius = lc.analytic.hertz_contact_radius(RUBBER, 0.01, 4e-6)
    assert isinstance(radius, float)
    assert radius == pytest.approx(math.sqrt(0.01 * 4e-6), rel=1e-14)


def test_jkr():
    w, r = 0.05, 0.01
    assert lc.analytic.jkr_pull_off_force(RUBBER, r, w) == pytest.approx(-1.5 * math.pi * r * w, rel=1e-12)
    a = np.linspace(1e-4, 1e-3, 7)
    force, depth = lc.analytic.jkr_state(RUBBER, r, w, a)
    # JKR (1971): F = 4 E* a^3 / (3 R) - sqrt(8 pi w E* a^3), d = a^2/R - sqrt(2 pi w a / E*).
    np.testing.assert_allclose(force, 4 * E_STAR * a**3 / (3 * r) - np.sqrt(8 * math.pi * w * E_STAR * a**3), rtol=1e-12)
    np.testing.assert_allclose(depth, a**2 / r - np.sqrt(2 * math.pi * w * a / E_STAR), rtol=1e-12)


def test_flat_punch_stiffness():
    a = np.array([1e-3, 2e-3])
    half_space = lc.Substrate.half_space(RUBBER)
    np.testing.assert_allclose(lc.analytic.flat_punch_stiffness(half_space, a), 2 * E_STAR * a, rtol=1e-12)
    # A film on glass (nu = 0.48) at a = h: K / (2 E* a) = 3.36659, the exact
    # axisymmetric value the Rust crate's tests pin to its published digits.
    film_material = lc.Material(0.324e6, 0.48)
    film = lc.Substrate.layer_on_rigid_base(film_material, 5e-3)
    k = lc.analytic.flat_punch_stiffness(film, 5e-3)
    assert k / (2 * film_material.contact_modulus * 5e-3) == pytest.approx(3.36659, abs=1e-5)
    # A bad radius is named with its value (it once read "max_contact_radius
    # ... got 0", the table's size derived from it).
    for bad in (-1e-3, 0.0, np.nan):
        with pytest.raises(lc.InvalidInputError, match=r"radius \(m\) must be positive and finite, got"):
            lc.analytic.flat_punch_stiffness(film, np.array([1e-3, bad]))


def test_layered_pull_off_tends_to_jkr_on_a_thick_layer():
    thick = lc.Substrate.layer_on_rigid_base(RUBBER, 1.0)
    force = lc.analytic.paraboloid_pull_off_force(thick, 0.01, 0.05)
    assert force == pytest.approx(-1.5 * math.pi * 0.01 * 0.05, rel=1e-3)


def test_errors_carry_the_library_message():
    with pytest.raises(lc.InvalidInputError, match=r"Poisson ratio must lie in \[0, 0.5\], got 0.7"):
        lc.Material(1e6, 0.7)
    with pytest.raises(lc.InvalidInputError, match="depth must be finite, got NaN"):
        lc.analytic.hertz_force(RUBBER, 0.01, [1e-6, float("nan")])
    assert issubclass(lc.InvalidInputError, lc.LayeredContactError)


def test_exact_paraboloid_and_punch_on_a_half_space_are_jkr_and_kendall():
    half_space = lc.Substrate.half_space(RUBBER)
    a = np.array([1e-4, 3e-4, 1e-3])
    force, depth = lc.analytic.paraboloid_state(half_space, 0.01, 0.05, a)
    jkr_force, jkr_depth = lc.analytic.jkr_state(RUBBER, 0.01, 0.05, a)
    np.testing.assert_allclose(force, jkr_force, rtol=1e-9)
    np.testing.assert_allclose(depth, jkr_depth, rtol=1e-9)
    kendall = -math.sqrt(8 * math.pi * 1e-3**3 * E_STAR * 0.05)
    assert lc.analytic.flat_punch_pull_off_force(half_space, 1e-3, 0.05) == pytest.approx(kendall, rel=1e-9)
    with pytest.raises(lc.InvalidInputError, match="work_of_adhesion"):
        lc.analytic.flat_punch_pull_off_force(half_space, 1e-3, float("nan"))


def test_exact_paraboloid_on_a_film_is_stiffer_than_hertz():
    film = lc.Substrate.layer_on_rigid_base(lc.Material(0.324e6, 0.48), 5e-3)
    a = np.array([1e-4, 3e-3])
    force, depth = lc.analytic.paraboloid_state(film, 0.05, 0.0, a)
    # Without adhesion the depth is Hertz's a^2/R for a << h: the film's
    # correction is first order in a/h (14 % at a/h = 0.2, 1.4 % at 0.02).
    assert depth[0] == pytest.approx(1e-8 / 0.05, rel=0.03)
    hertz = lc.analytic.hertz_force(lc.Material(0.324e6, 0.48), 0.05, depth)
    assert np.all(force > hertz)


def test_bottom_effect_series_matches_the_exact_forces():
    # Least squares through exact forces at chi <= 0.1 (paraboloid_state,
    # the Nystrom solution) against the series from the kernel's moments:
    # the first coefficient to 1e-8, the second to 1e-6 (the fit's own
    # precision at this number of points).
    c = lc.analytic.bottom_effect_series(0.5)
    assert abs(c[1] / c[0] ** 2 - 7.0 / 6.0) < 1e-14
    h = 1e-5
    film = lc.Substrate.layer_on_rigid_base(lc.Material(1e6, 0.5), h)
    radii = np.linspace(1e-3, 0.1, 60) * h
    force, depth = lc.analytic.paraboloid_state(film, h, 0.0, radii)
    chi = np.sqrt(h * depth) / h
    ratio = force / lc.analytic.hertz_force(lc.Material(1e6, 0.5), h, depth)
    fitted = np.linalg.lstsq(np.vander(chi, 10, increasing=True)[:, 1:], ratio - 1, rcond=None)[0]
    assert abs(fitted[0] - c[0]) < 1e-8
    assert abs(fitted[1] - c[1]) < 1e-6
    # Dimitriadis' first coefficient, from a fit in nu, is 0.54 % high.
    assert abs(lc.analytic.DIMITRIADIS_BONDED[0] / c[0] - 1.00537) < 1e-4


def test_tip_pressure_is_sneddons_cone_and_finds_a_disc_that_pulls():
    # Sneddon (1948): a cone on a half-space presses with
    # p = (E* cot(theta) / 2) acosh(a / r).
    theta, a = math.radians(70), 1e-6
    r = np.array([0.1e-6, 0.5e-6, 0.9e-6, 1.2e-6])
    half = lc.Substrate.half_space(RUBBER)
    p, least = lc.analytic.tip_pressure(half, "cone", a, r, half_angle=theta)
    exact = 0.5 * E_STAR / math.tan(theta) * np.arccosh(np.maximum(a / r, 1.0))
    np.testing.assert_allclose(p, exact, rtol=1e-9)
    assert least > 0
    # A sphere on a 95 MPa layer over a base 8000 times softer: the disc of
    # 9.74 um pulls at its middle (18 % of its mean; the BEM's contact is a
    # ring there, tests/promise.rs), the disc of 3 um presses everywhere.
    layer, base = lc.Material(9.52688603947193e7, 0.45), lc.Material(1.1906824045483834e4, 0.45)
    plate = lc.Substrate.layer_resting_on_elastic_base(layer, 1.3643821587963536e-6, base)
    p, least = lc.analytic.tip_pressure(plate, "sphere", 9.74e-6, [0.0], radius=2.340057717547073e-5)
    assert -0.2 < least < -0.15
    assert p[0] < 0
    _, least = lc.analytic.tip_pressure(plate, "sphere", 3e-6, 0.0, radius=2.340057717547073e-5)
    assert least > 0.1
