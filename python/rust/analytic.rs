//! Bindings of the closed forms and the exact axisymmetric solutions,
//! vectorised over NumPy arrays (`layered_contact.analytic`).

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

use layered_contact as lc;

use super::{checked_len, map, Material, OrPy, Substrate};

/// Hertz: force (N) of a paraboloid of tip radius `radius` pressed `depth`
/// (m) into a half-space of `material`.
#[pyfunction]
pub(crate) fn hertz_force<'py>(
    py: Python<'py>,
    material: &Material,
    radius: f64,
    depth: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let hertz = lc::analytic::Hertz::new(&material.inner, radius).py_err()?;
    map(py, depth, |d| {
        Ok(hertz.force(lc::error::finite("depth", d)?))
    })
}

/// Hertz: contact radius (m) at `depth` (m).
#[pyfunction]
pub(crate) fn hertz_contact_radius<'py>(
    py: Python<'py>,
    material: &Material,
    radius: f64,
    depth: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let hertz = lc::analytic::Hertz::new(&material.inner, radius).py_err()?;
    map(py, depth, |d| {
        Ok(hertz.contact_radius(lc::error::finite("depth", d)?))
    })
}

/// A NumPy array of any shape.
pub(crate) type Array<'py> = Bound<'py, PyArrayDyn<f64>>;

/// JKR: `(force, depth)` (N, m) of a paraboloid of tip radius `radius` on a
/// half-space with work of adhesion `work_of_adhesion` (J/m^2), at contact
/// radius `contact_radius` (m).
#[pyfunction]
pub(crate) fn jkr_state<'py>(
    py: Python<'py>,
    material: &Material,
    radius: f64,
    work_of_adhesion: f64,
    contact_radius: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<(Array<'py>, Array<'py>)> {
    let jkr = lc::analytic::JkrSphere::new(&material.inner, radius, work_of_adhesion).py_err()?;
    let check = |a: f64| lc::error::non_negative_finite("contact_radius", a);
    let force = map(py, contact_radius.clone(), |a| Ok(jkr.force(check(a)?)))?;
    let depth = map(py, contact_radius, |a| Ok(jkr.depth(check(a)?)))?;
    Ok((force, depth))
}

/// JKR pull-off force under load control, `-3/2 pi R w` (N).
#[pyfunction]
pub(crate) fn jkr_pull_off_force(
    material: &Material,
    radius: f64,
    work_of_adhesion: f64,
) -> PyResult<f64> {
    Ok(
        lc::analytic::JkrSphere::new(&material.inner, radius, work_of_adhesion)
            .py_err()?
            .pull_off_force(),
    )
}

/// Exact stiffness (N/m) of a flat punch of radius `radius` (m) on
/// `substrate`, from the axisymmetric solution (any layer thickness).
#[pyfunction]
pub(crate) fn flat_punch_stiffness<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    radius: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    checked_len("radius", radius.shape())?;
    // Each radius is checked here, before the table is sized by the
    // largest, so that the error names the radius.
    if let Some(&bad) = radius
        .as_array()
        .iter()
        .find(|r| !(r.is_finite() && **r > 0.0))
    {
        return Err(lc::Error::InvalidParameter {
            name: "radius (m)",
            value: bad,
            expected: "positive and finite",
        })
        .py_err();
    }
    let largest =
        radius
            .as_array()
            .iter()
            .copied()
            .fold(0.0f64, |m, r| if r.is_finite() { m.max(r) } else { m });
    let substrate = substrate.inner.clone();
    let radii: Vec<f64> = radius.as_array().iter().copied().collect();
    let stiffness = py
        .detach(|| -> lc::Result<Vec<f64>> {
            let exact = lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, largest)?;
            radii
                .iter()
                .map(|&a| Ok(exact.flat_punch(a)?.stiffness()))
                .collect()
        })
        .py_err()?;
    PyArray1::from_vec(py, stiffness).reshape(radius.shape().to_vec())
}

/// Exact load-controlled pull-off force (N) of a paraboloid of tip radius
/// `radius` (m) on `substrate` with work of adhesion `work_of_adhesion`.
#[pyfunction]
pub(crate) fn paraboloid_pull_off_force(
    py: Python<'_>,
    substrate: &Substrate,
    radius: f64,
    work_of_adhesion: f64,
) -> PyResult<f64> {
    let substrate = substrate.inner.clone();
    py.detach(|| -> lc::Result<f64> {
        let jkr =
            lc::analytic::JkrSphere::new(substrate.surface_material(), radius, work_of_adhesion)?
                .pull_off_contact_radius();
        let exact = lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, 3.0 * jkr)?;
        let pull_off = exact.paraboloid(radius, work_of_adhesion)?.pull_off()?;
        Ok(pull_off.load_control.force)
    })
    .py_err()
}

/// Exact `(force, depth)` (N, m) of a paraboloid of tip radius `radius` (m)
/// on `substrate` with work of adhesion `work_of_adhesion` (J/m^2, 0 for
/// none) at contact radius `contact_radius` (m): the JKR equilibrium on the
/// coated body.
#[pyfunction]
pub(crate) fn paraboloid_state<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    radius: f64,
    work_of_adhesion: f64,
    contact_radius: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<(Array<'py>, Array<'py>)> {
    checked_len("contact_radius", contact_radius.shape())?;
    let radii: Vec<f64> = contact_radius.as_array().iter().copied().collect();
    let largest = radii.iter().copied().fold(0.0f64, f64::max);
    let substrate = substrate.inner.clone();
    let states = py
        .detach(|| -> lc::Result<Vec<(f64, f64)>> {
            let exact = lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, largest)?;
            let ball = exact.paraboloid(radius, work_of_adhesion)?;
            radii
                .iter()
                .map(|&a| ball.at_contact_radius(a).map(|s| (s.force, s.depth)))
                .collect()
        })
        .py_err()?;
    let shape = contact_radius.shape().to_vec();
    let force = PyArray1::from_vec(py, states.iter().map(|s| s.0).collect());
    let depth = PyArray1::from_vec(py, states.iter().map(|s| s.1).collect());
    Ok((force.reshape(shape.clone())?, depth.reshape(shape)?))
}

/// Exact pull-off force (N) of a bonded flat punch of radius `radius` (m) on
/// `substrate` with work of adhesion `work_of_adhesion` (J/m^2): Kendall's on
/// a half-space.
#[pyfunction]
pub(crate) fn flat_punch_pull_off_force(
    py: Python<'_>,
    substrate: &Substrate,
    radius: f64,
    work_of_adhesion: f64,
) -> PyResult<f64> {
    let substrate = substrate.inner.clone();
    py.detach(|| {
        let punch = lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, radius)?
            .flat_punch(radius)?;
        lc::error::non_negative_finite("work_of_adhesion", work_of_adhesion)?;
        Ok(punch.pull_off_force(work_of_adhesion))
    })
    .py_err()
}

/// The exact bottom-effect series of a paraboloid on a layer of Poisson
/// ratio `poisson_ratio` bonded to a rigid base: the coefficients of
/// `chi`, `chi^2`, `chi^3`, `chi^4` in `F / F_Hertz`, `chi = sqrt(R d)/h`
/// (`analytic::ParaboloidForceSeries`).
#[pyfunction]
pub(crate) fn paraboloid_series(poisson_ratio: f64) -> PyResult<[f64; 4]> {
    Ok(lc::analytic::ParaboloidForceSeries::new(poisson_ratio)
        .py_err()?
        .coefficients())
}
