"""Stresses below the surface from Python: the cosine closed form on a
periodic half-space, the Hertz field on the axis of an isolated contact,
a scene's stresses, and the section figure."""

import numpy as np
import pytest

import layered_contact as lc

NU = 0.3


def test_a_cosine_on_a_periodic_half_space_is_exact():
    # p0 cos(q x), x along the rows: sigma_zz = -p0 (1 + qz) e^(-qz) cos,
    # sigma_xx = -p0 (1 - qz) e^(-qz) cos, sigma_yy = -2 nu p0 e^(-qz) cos,
    # sigma_xz = -p0 qz e^(-qz) sin (Johnson 1985, sec. 2.6); to rounding.
    rows, columns, spacing, p0 = 64, 4, 1e-6, 1e6
    q = 2 * np.pi / (rows * spacing)
    x = (np.arange(rows) + 0.5) * spacing
    pressure = np.repeat((p0 * np.cos(q * x))[:, None], columns, axis=1)
    body = lc.Substrate.half_space(lc.Material(1e9, NU))
    depths = [0.0, 3e-6, 20e-6]
    s = lc.subsurface_stress(body, pressure, spacing, depths, periodic=True)
    assert s["zz"].shape == (3, rows, columns)
    for k, z in enumerate(depths):
        t = q * z
        e = np.exp(-t)
        c, sn = np.cos(q * x), np.sin(q * x)
        np.testing.assert_allclose(s["zz"][k, :, 0], -p0 * (1 + t) * e * c, atol=1e-9 * p0)
        np.testing.assert_allclose(s["xx"][k, :, 0], -p0 * (1 - t) * e * c, atol=1e-9 * p0)
        np.testing.assert_allclose(s["yy"][k, :, 0], -2 * NU * p0 * e * c, atol=1e-9 * p0)
        np.testing.assert_allclose(s["xz"][k, :, 0], -p0 * t * e * sn, atol=1e-9 * p0)
        np.testing.assert_allclose(s["yz"][k], 0.0, atol=1e-9 * p0)


def _hertz(n=64, cells=16):
    a = 1e-3
    spacing = a / cells
    centre = (np.arange(n) + 0.5 - n / 2) * spacing
    r2 = (centre[:, None] ** 2 + centre[None, :] ** 2) / a**2
    return np.where(r2 < 1, np.sqrt(np.clip(1 - r2, 0, None)), 0.0), spacing, a


def test_hertz_on_the_axis_of_an_isolated_contact():
    # Johnson 1985, eq. 3.64, at the four cells around the axis (their mean;
    # the half-cell offset changes the axis values by less than 1e-3 p0).
    # At the default padding (2, the images taken out) the axis is 2.5e-4 p0
    # off, the cells' own share (tests/stress.rs).
    pressure, spacing, a = _hertz()
    body = lc.Substrate.half_space(lc.Material(1e9, NU))
    zr = np.array([0.25, 0.48, 1.0, 2.0])
    s = lc.subsurface_stress(body, pressure, spacing, list(zr * a))
    axis = (slice(None), slice(31, 33), slice(31, 33))
    zz = s["zz"][axis].mean(axis=(1, 2))
    xx = s["xx"][axis].mean(axis=(1, 2))
    np.testing.assert_allclose(zz, -1 / (1 + zr**2), atol=3e-3)
    exact_r = -(1 + NU) * (1 - zr * np.arctan(1 / zr)) + 0.5 / (1 + zr**2)
    np.testing.assert_allclose(xx, exact_r, atol=3e-3)
    best = s["max_shear_stress"]
    assert abs(best["value"] - 0.310) < 3e-3 and best["depth"] == pytest.approx(0.48 * a)
    with pytest.raises(lc.InvalidInputError, match="padding"):
        lc.subsurface_stress(body, pressure, spacing, [0.0], padding=1)
    with pytest.raises(lc.InvalidInputError, match="side"):
        lc.subsurface_stress(body, pressure, spacing, [0.0], side="left")


def test_scenes_return_their_stresses_and_a_section():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    scene = {
        "substrate": {
            "kind": "stack",
            "layers": [
                {"youngs_modulus": 400e9, "poisson_ratio": 0.25, "thickness": 2e-6},
                {"youngs_modulus": 279e9, "poisson_ratio": 0.21, "thickness": 1e-6},
            ],
            "base": {"youngs_modulus": 210e9, "poisson_ratio": 0.3},
        },
        "indenter": {"kind": "sphere", "radius": 100e-6},
        "protocol": {"kind": "depth", "depth": 0.25e-6},
        "resolution": {"cells_across": 32},
        "outputs": {
            "fields": {"pressure": True},
            "stresses": {"depth_grid": {"to": 6e-6, "planes": 7}, "interfaces": True},
        },
    }
    curve = lc.run_scene(scene)
    s = curve.stresses
    np.testing.assert_allclose(s["depth"], np.linspace(0, 6e-6, 7), rtol=0, atol=1e-18)
    # On the surface sigma_zz is minus the pressure, cell by cell (to 3e-11
    # of the peak on this isolated grid: the tail of the images' coarse
    # filter, wrapped round the period; tests/stress.rs).
    p = curve.peak.pressure
    np.testing.assert_allclose(s["zz"][0], -p, atol=1e-9 * p.max())
    assert s["boundaries"] == [2e-6, 3e-6]
    np.testing.assert_array_equal(s["interfaces"]["depth"], [2e-6, 3e-6])
    vm = s["max_von_mises"]
    k = int(np.argmin(abs(s["depth"] - vm["depth"])))
    assert s["von_mises"][k, vm["row"], vm["column"]] == vm["value"]
    # The principal stresses are ordered and keep the trace (3 x hydrostatic).
    assert np.all(s["principal_max"] >= s["principal_mid"])
    assert np.all(s["principal_mid"] >= s["principal_min"])
    trace = s["principal_max"] + s["principal_mid"] + s["principal_min"]
    np.testing.assert_allclose(trace, s["xx"] + s["yy"] + s["zz"], rtol=0, atol=1e-9 * p.max())
    np.testing.assert_allclose(s["max_shear"], 0.5 * (s["principal_max"] - s["principal_min"]))
    ax = lc.plot_section(s)
    assert ax.get_ylabel() == "depth z [m]"
    assert len(ax.lines) == 2  # the two boundaries above 6 um
