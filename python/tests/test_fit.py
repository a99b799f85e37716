"""Fitting measured curves (layered_contact.fit) against the exact model:
the fast tables against direct exact solutions, and fits of synthetic
curves with 1 % noise (seeded) recovering the modulus and the work of
adhesion where a Hertz/JKR half-space fit is off by a factor of several."""

import pickle

import numpy as np
import pytest

import layered_contact as lc
from layered_contact import analytic
from layered_contact.fit import CurveModel, Sample, fit_curve

H, R, E, W, NU, Z0 = 4e-6, 5e-6, 10e3, 1e-3, 0.5, 1e-7
LAYER = Sample(thickness=H, poisson_ratio=NU)


def test_model_matches_the_exact_states():
    # The native table (analytic::ForceCurve, Hermite interpolation over
    # 500 contact radii): within 1e-6 of the exact state on the stable
    # branch, relative to the largest force of the samples (a force that
    # crosses zero has no relative error of its own; measured 5e-7 there,
    # 1e-9 elsewhere).
    model = CurveModel("paraboloid", R, LAYER, max_depth=3e-6)
    substrate = LAYER.substrate(E)
    for w in (0.0, W):
        radii = np.linspace(0.9e-6, 3e-6, 9)
        force, depth = analytic.paraboloid_state(substrate, R, w, radii)
        got = model.force(depth, E, w)
        np.testing.assert_allclose(got, force, rtol=1e-6, atol=1e-6 * np.max(np.abs(force)))
    # On a half-space the model is JKR's closed form.
    half = CurveModel("paraboloid", R, Sample(poisson_ratio=NU), max_depth=3e-6)
    material = lc.Material(E, NU)
    force, depth = analytic.jkr_state(material, R, W, np.linspace(1e-6, 3e-6, 5))
    np.testing.assert_allclose(half.force(depth, E, W), force, rtol=1e-6)


def synthetic(segment, seed):
    """A curve of the exact model to half the thickness, contact point Z0,
    plus Gaussian noise of 1 % of the largest force."""
    truth = CurveModel("paraboloid", R, LAYER, max_depth=2.5e-6)
    z = np.linspace(0.5 * H + Z0, -0.8e-6 + Z0, 2000)
    f = truth.force(z - Z0, E, W if segment == "retract" else 0.0)
    rng = np.random.default_rng(seed)
    return z, f + 0.01 * np.max(np.abs(f)) * rng.standard_normal(z.size)


@pytest.mark.parametrize("seed", range(4))
def test_fits_recover_the_modulus_and_the_work_of_adhesion(seed):
    for segment in ("approach", "retract"):
        z, f = synthetic(segment, seed)
        fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=LAYER, segment=segment,
                        youngs_modulus=5e3, work_of_adhesion=0.5e-3)
        assert abs(fit.params["youngs_modulus"] / E - 1) < 0.01, fit.params
        assert abs(fit.params["contact_point"] - Z0) < 0.02 * H, fit.params
        # The standard error is the scatter's size: the truth within 4 of them.
        assert abs(fit.params["youngs_modulus"] - E) < 4 * fit.stderr["youngs_modulus"]
        if segment == "retract":
            assert abs(fit.params["work_of_adhesion"] / W - 1) < 0.03, fit.params
        # Hertz (JKR) on a half-space: the modulus off by more than twice.
        hertz = fit_curve(z, f, tip="paraboloid", radius=R, sample=Sample(poisson_ratio=NU),
                          segment=segment, youngs_modulus=5e3, work_of_adhesion=0.5e-3)
        assert hertz.params["youngs_modulus"] > 2 * E, hertz.params


def test_flat_punch_on_a_stiff_supported_layer():
    # A bonded punch is linear: F = K d, K from the exact stiffness.
    sample = Sample(thickness=H, poisson_ratio=0.3, base_youngs_modulus=1e9)
    stiffness = analytic.flat_punch_stiffness(sample.substrate(E), R)
    z = np.linspace(-0.2e-6, 1e-6, 50)
    model = CurveModel("flat_punch", R, sample, max_depth=2e-6)
    np.testing.assert_allclose(model.force(z, E), np.where(z > 0, stiffness * z, 0.0),
                               rtol=1e-12, atol=0.0)
    rng = np.random.default_rng(7)
    f = model.force(z - 0.05e-6, E) * (1 + 0.01 * rng.standard_normal(z.size))
    fit = fit_curve(z, f, tip="flat_punch", radius=R, sample=sample, youngs_modulus=3e4)
    assert abs(fit.params["youngs_modulus"] / E - 1) < 0.01, fit.params


@pytest.mark.parametrize("kwargs, match", [
    (dict(tip="pyramid"), "tip"),
    (dict(tip="cone"), "half_angle"),
    (dict(segment="sideways"), "segment"),
    (dict(vary=("radius",)), "vary"),
    (dict(segment="retract", work_of_adhesion=0.0), "work_of_adhesion"),
])
def test_bad_requests_are_refused(kwargs, match):
    z, f = synthetic("retract", 0)
    args = dict(tip="paraboloid", radius=R, sample=LAYER, youngs_modulus=5e3)
    args.update(kwargs)
    with pytest.raises(lc.InvalidInputError, match=match):
        fit_curve(z, f, **args)
    with pytest.raises(lc.InvalidInputError, match="finite"):
        fit_curve(z, np.where(z > 0, np.nan, f), tip="paraboloid", radius=R, sample=LAYER,
                  youngs_modulus=5e3)


def test_the_example_goes_from_a_csv_to_the_film_properties(tmp_path, monkeypatch):
    import importlib.util
    import pathlib

    path = pathlib.Path(__file__).parents[1] / "examples" / "fit_curve.py"
    spec = importlib.util.spec_from_file_location("fit_curve_example", path)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    monkeypatch.chdir(tmp_path)
    params = example.main([])  # writes and fits its synthetic curve
    assert abs(params["youngs_modulus"] / E - 1) < 0.01
    assert abs(params["work_of_adhesion"] / W - 1) < 0.03


@pytest.mark.parametrize("tip, size", [
    ("cone", dict(half_angle=np.radians(70.0))),
    ("sphere", dict(radius=5e-6)),
    ("rounded_cone", dict(radius=0.3e-6, half_angle=np.radians(70.0))),
])
def test_other_tips_fit_on_a_film(tip, size):
    # An AFM pyramid (a cone of 70 degrees, or one worn to a 0.3 um apex)
    # and a 5 um colloidal sphere (its cap, not its paraboloid) indented to
    # half of a 4 um film on glass, 2000 points as the paraboloid's.
    truth = CurveModel(tip, size.get("radius"), LAYER, max_depth=2.5e-6,
                       half_angle=size.get("half_angle"))
    z = np.linspace(-0.5e-6, 0.5 * H, 2000)
    f = truth.force(z - Z0, E)
    rng = np.random.default_rng(11)
    f = f + 0.01 * np.max(f) * rng.standard_normal(z.size)
    fit = fit_curve(z, f, tip=tip, sample=LAYER, youngs_modulus=3e4, **size)
    # A cone's force (~ E (z - z0)^2) ties the modulus to the contact
    # point more than a sphere's: at this noise its standard error is 0.68 %
    # (sphere 0.23 %; measured with seed 11). The estimate lies within 3 standard errors of the
    # truth, and those are below 1 %.
    error, stderr = fit.params["youngs_modulus"] - E, fit.stderr["youngs_modulus"]
    assert stderr < 0.01 * E and abs(error) < 3 * stderr, (fit.params, fit.stderr)


def test_cantilever_pull_off_lies_between_the_controls():
    substrate = LAYER.substrate(E)
    out = analytic.tip_pull_off(substrate, "cone", W, half_angle=1.2, spring=0.01)
    load, grips = out["load_control"], out["displacement_control"]
    spring, jump = out["spring_pull_off"], out["spring_jump_in"]
    assert load["force"] < spring["force"] < grips["force"] < 0
    assert grips["depth"] < spring["depth"] < load["depth"]
    assert abs(jump["force"] + 0.01 * jump["depth"]) < 1e-9 * abs(jump["force"])
    with pytest.raises(lc.InvalidInputError, match="half_angle"):
        analytic.tip_pull_off(substrate, "cone", W, half_angle=2.0)


def test_a_film_on_a_coated_support_is_a_stack():
    # A gel film on a 1 um polymer coating of 1 MPa on glass: the model is
    # the stack's exact solution; fitting the film's modulus rebuilds the
    # tables for each modulus tried.
    sample = Sample(thickness=H, poisson_ratio=NU, below=((1e6, 0.4, 1e-6),))
    substrate = sample.substrate(E)
    assert substrate.layer_count == 2
    model = CurveModel("paraboloid", R, sample, max_depth=2.5e-6)
    radii = np.linspace(0.5e-6, 3e-6, 5)
    force, depth = analytic.paraboloid_state(substrate, R, 0.0, radii)
    np.testing.assert_allclose(model.force(depth, E), force, rtol=1e-6)
    z = np.linspace(-0.3e-6, 0.5 * H, 400)
    f = model.force(z, E)
    fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=sample, youngs_modulus=7e3)
    assert abs(fit.params["youngs_modulus"] / E - 1) < 1e-6, fit.params


def test_force_piezo_curves_are_fitted_through_the_cantilever():
    # The piezo moves z = d + F/k; given k the fit recovers the film.
    k = 0.05
    truth = CurveModel("paraboloid", R, LAYER, max_depth=2.5e-6)
    d = np.linspace(-0.5e-6, 0.5 * H, 1000)
    f = truth.force(d - Z0, E)
    piezo = d + f / k
    fit = fit_curve(piezo, f, tip="paraboloid", radius=R, sample=LAYER, youngs_modulus=5e3,
                    spring_constant=k)
    assert abs(fit.params["youngs_modulus"] / E - 1) < 1e-6, fit.params
    assert abs(fit.params["contact_point"] - Z0) < 1e-6 * H, fit.params
    with pytest.raises(lc.InvalidInputError, match="spring_constant"):
        fit_curve(piezo, f, tip="paraboloid", radius=R, sample=LAYER, youngs_modulus=5e3,
                  spring_constant=-1.0)


def test_an_unbonded_film_is_fitted_with_its_own_model():
    # A gel resting on glass without friction: the bonded model, stiffer,
    # reads it softer than it is (by more than 20 %); its own recovers it.
    resting = Sample(thickness=H, poisson_ratio=NU, bonded=False)
    truth = CurveModel("paraboloid", R, resting, max_depth=2.5e-6)
    z = np.linspace(-0.3e-6, 0.5 * H, 600)
    f = truth.force(z - Z0, E)
    fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=resting, youngs_modulus=5e3)
    assert abs(fit.params["youngs_modulus"] / E - 1) < 1e-6, fit.params
    bonded = fit_curve(z, f, tip="paraboloid", radius=R, sample=LAYER, youngs_modulus=5e3)
    assert bonded.params["youngs_modulus"] < 0.8 * E, bonded.params
    # Resting on a coating on glass (Substrate.layer_resting_on): its own
    # model recovers it too, and the substrate pickles by its recipe.
    coated = Sample(thickness=H, poisson_ratio=NU, bonded=False, below=((1e6, 0.4, 1e-6),))
    body = coated.substrate(E)
    assert repr(body).startswith("Substrate.layer_resting_on(")
    assert repr(pickle.loads(pickle.dumps(body))) == repr(body)
    truth = CurveModel("paraboloid", R, coated, max_depth=2.5e-6)
    f = truth.force(z - Z0, E)
    fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=coated, youngs_modulus=5e3)
    assert abs(fit.params["youngs_modulus"] / E - 1) < 1e-6, fit.params


def test_an_unbonded_film_on_a_gel_is_softer_than_bonded_and_stiffer_than_on_nothing():
    # The native resting-on-an-elastic-base body: its punch stiffness lies
    # between the bonded film on the same gel and the gel-free limit of an
    # infinitely soft support, and a base far stiffer than the film tends
    # to the film resting on glass (first order in E1*/E2*: 1e-4 here).
    gel = dict(base_youngs_modulus=2.5e3, base_poisson_ratio=0.5)
    resting = Sample(thickness=H, poisson_ratio=NU, bonded=False, **gel)
    bonded = Sample(thickness=H, poisson_ratio=NU, **gel)
    a = 2e-6

    def stiffness(sample):
        return float(lc.analytic.flat_punch_stiffness(sample.substrate(E), a))

    assert stiffness(resting) < stiffness(bonded)
    stiff = Sample(thickness=H, poisson_ratio=NU, bonded=False,
                   base_youngs_modulus=1e4 * E, base_poisson_ratio=NU)
    glass = Sample(thickness=H, poisson_ratio=NU, bonded=False)
    assert abs(stiffness(stiff) / stiffness(glass) - 1.0) < 1e-3
    # On a coating on glass: softer than bonded to the same coating (0.78
    # of it), and within the coating's compliance (1 um of 1 MPa under 10
    # kPa: measured -7.7e-4) of the film resting on glass itself.
    coating = ((1e6, 0.4, 1e-6),)
    on_coating = Sample(thickness=H, poisson_ratio=NU, bonded=False, below=coating)
    bonded_on_coating = Sample(thickness=H, poisson_ratio=NU, below=coating)
    assert stiffness(on_coating) < stiffness(bonded_on_coating)
    assert stiffness(on_coating) < stiffness(glass)
    assert abs(stiffness(on_coating) / stiffness(glass) - 1.0) < 1e-2


def test_the_thickness_and_the_support_can_be_fitted_too():
    # A film of unknown thickness on glass, and one of known thickness on a
    # support of unknown modulus: each value tried builds its own table.
    z = np.linspace(-0.3e-6, 0.5 * H, 300)
    truth = CurveModel("paraboloid", R, LAYER, max_depth=2.5e-6)
    f = truth.force(z - Z0, E)
    guess = Sample(thickness=1.3 * H, poisson_ratio=NU)
    fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=guess, youngs_modulus=E,
                    vary=("thickness", "contact_point"))
    assert abs(fit.params["thickness"] / H - 1) < 1e-5, fit.params
    soft = Sample(thickness=H, poisson_ratio=NU, base_youngs_modulus=3 * E)
    f = CurveModel("paraboloid", R, soft, max_depth=2.5e-6).force(z - Z0, E)
    start = Sample(thickness=H, poisson_ratio=NU, base_youngs_modulus=6 * E)
    fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=start, youngs_modulus=E,
                    vary=("base_youngs_modulus", "contact_point"))
    assert abs(fit.params["base_youngs_modulus"] / (3 * E) - 1) < 1e-5, fit.params
    with pytest.raises(lc.InvalidInputError, match="rigid support"):
        fit_curve(z, f, tip="paraboloid", radius=R, sample=LAYER, youngs_modulus=E,
                  vary=("base_youngs_modulus",))


def test_a_modulus_family_serves_a_force_map_on_a_gel():
    # A film on a gel four times softer: its force does not scale with the
    # film's modulus, so a plain model builds a table per modulus tried.
    # With modulus_range the tables are built once (12 Chebyshev nodes in
    # ln E over 3 to 30 kPa) and reused across the curves of a map: the
    # estimates agree with the plain fit's to 1e-5 (the family is within
    # 1e-8 of the exact curve) and recover E within 1 % at 1 % noise, and
    # the second curve builds no table.
    gel = Sample(thickness=H, poisson_ratio=NU, base_youngs_modulus=2.5e3,
                 base_poisson_ratio=0.5)
    truth = CurveModel("paraboloid", R, gel, max_depth=2.5e-6)
    # The fit reaches past the deepest point by half the span (3.15 um).
    family = CurveModel("paraboloid", R, gel, max_depth=3.2e-6, modulus_range=(3e3, 30e3))
    z = np.linspace(0.0, 2.1e-6, 300)
    exact = truth.force(z - Z0, E)
    np.testing.assert_allclose(family.force(z - Z0, E), exact, rtol=1e-7,
                               atol=1e-9 * exact.max())
    rng = np.random.default_rng(21)
    estimates = []
    for e in (E, 1.5 * E):
        f = truth.force(z - Z0, e) + 0.01 * exact.max() * rng.standard_normal(z.size)
        fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=gel, youngs_modulus=8e3,
                        vary=("youngs_modulus", "contact_point"), model=family)
        assert abs(fit.params["youngs_modulus"] / e - 1.0) < 0.01, fit.params
        estimates.append(fit.params["youngs_modulus"])
    assert family._tables == {}
    plain = fit_curve(z, truth.force(z - Z0, E) + 0.01 * exact.max()
                      * np.random.default_rng(21).standard_normal(z.size),
                      tip="paraboloid", radius=R, sample=gel, youngs_modulus=8e3,
                      vary=("youngs_modulus", "contact_point"))
    assert abs(plain.params["youngs_modulus"] / estimates[0] - 1.0) < 1e-5
    with pytest.raises(lc.InvalidInputError, match="modulus_range"):
        CurveModel("paraboloid", R, gel, max_depth=2.5e-6, modulus_range=(3e4, 3e3))


def test_a_modulus_family_serves_retract_curves_on_a_gel():
    # Retract curves on a support that does not scale: the family's table
    # at a modulus (interpolated at each contact radius) is within 1e-7 of
    # the exact table's curve with adhesion, and a fit of the modulus and
    # the work of adhesion to a noisy retract curve builds no table per
    # modulus and recovers both (1 % and 3 %).
    gel = Sample(thickness=H, poisson_ratio=NU, base_youngs_modulus=2.5e3,
                 base_poisson_ratio=0.5)
    truth = CurveModel("paraboloid", R, gel, max_depth=2.5e-6)
    # The fit reaches past the deepest point by half the span (3.55 um).
    family = CurveModel("paraboloid", R, gel, max_depth=3.6e-6, modulus_range=(3e3, 30e3))
    z = np.linspace(0.5 * H + Z0, -0.8e-6 + Z0, 2000)
    exact = truth.force(z - Z0, E, W)
    assert exact.min() < 0.0
    scale = np.max(np.abs(exact))
    np.testing.assert_allclose(family.force(z - Z0, E, W), exact, rtol=0.0, atol=1e-7 * scale)
    f = exact + 0.01 * scale * np.random.default_rng(8).standard_normal(z.size)
    fit = fit_curve(z, f, tip="paraboloid", radius=R, sample=gel, segment="retract",
                    youngs_modulus=8e3, work_of_adhesion=0.5e-3, model=family)
    assert abs(fit.params["youngs_modulus"] / E - 1) < 0.01, fit.params
    assert abs(fit.params["work_of_adhesion"] / W - 1) < 0.03, fit.params
    assert family._tables == {}
