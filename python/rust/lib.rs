//! Python bindings of `layered-contact`: a thin layer over the Rust crate's
//! public API. Library errors become the exceptions below with the library's
//! own messages; solves release the GIL. One module per thing bound:
//! `bodies` (materials, substrates), `indenters`, `solver`, `scenes`,
//! `analytic`, `curves` (fitting models), `stresses`, `adhesion` (local
//! release rates); this file holds the errors, array helpers and the
//! module's registration.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

use layered_contact as lc;

mod adhesion;
mod analytic;
mod bodies;
mod curves;
mod indenters;
mod scenes;
mod solver;
mod stresses;

use bodies::{Material, Substrate};
use indenters::{Indenter, Shared};
use scenes::{array, check_scene, run_scene, scene_reference, scene_schema, Curve};
use solver::{centres, ContactSolver, Solution};

create_exception!(
    layered_contact,
    LayeredContactError,
    PyException,
    "An error of the layered-contact library."
);
create_exception!(
    layered_contact,
    InvalidInputError,
    LayeredContactError,
    "A value outside its valid range (the message names it and the range)."
);
create_exception!(
    layered_contact,
    ConvergenceError,
    LayeredContactError,
    "A solver that did not converge (the message gives the residual)."
);
create_exception!(
    layered_contact,
    EdgeContactWarning,
    pyo3::exceptions::PyUserWarning,
    "A contact that reaches the edge of an isolated grid: the grid is too \
     small, and the force is that of a contact cut off at its edge. Make it \
     an error with `warnings.simplefilter(\"error\", EdgeContactWarning)`."
);

create_exception!(
    layered_contact,
    CohesiveZoneWarning,
    pyo3::exceptions::PyUserWarning,
    "A cohesive zone wider than the contact at the pull-off: the zones of \
     the contact's two sides meet, and the force is a cohesive law's, not \
     the JKR limit's (a finer grid resolves it). Make it an error with \
     `warnings.simplefilter(\"error\", CohesiveZoneWarning)`."
);

/// The library's error as the matching Python exception, same message.
fn to_py(error: lc::Error) -> PyErr {
    let message = error.to_string();
    match error {
        lc::Error::NoConvergence { .. } | lc::Error::NoEquilibrium { .. } => {
            ConvergenceError::new_err(message)
        }
        lc::Error::InvalidYoungsModulus { .. }
        | lc::Error::InvalidPoissonRatio { .. }
        | lc::Error::InvalidThickness { .. }
        | lc::Error::InvalidParameter { .. }
        | lc::Error::InvalidGrid { .. }
        | lc::Error::ShapeMismatch { .. }
        | lc::Error::IndenterOutsideGrid { .. }
        | lc::Error::HeightMapFile { .. }
        | lc::Error::SceneFile { .. } => InvalidInputError::new_err(message),
        _ => LayeredContactError::new_err(message),
    }
}

trait OrPy<T> {
    fn py_err(self) -> PyResult<T>;
}

impl<T> OrPy<T> for lc::Result<T> {
    fn py_err(self) -> PyResult<T> {
        self.map_err(to_py)
    }
}

/// The most values an array argument may hold (1 GiB of `f64`): the result
/// has as many, and a broadcast view of one value can claim billions.
const MAX_ARRAY_VALUES: usize = 1 << 27;

/// The number of values of an array of `shape`, checked before anything is
/// copied or allocated for it.
fn checked_len(name: &str, shape: &[usize]) -> PyResult<usize> {
    match shape.iter().try_fold(1usize, |n, &k| n.checked_mul(k)) {
        Some(n) if n <= MAX_ARRAY_VALUES => Ok(n),
        _ => Err(InvalidInputError::new_err(format!(
            "{name} has shape {shape:?}: at most 2^27 values per call (split it)"
        ))),
    }
}

/// `f` applied to every element of `values`, same shape.
fn map<'py>(
    py: Python<'py>,
    values: PyReadonlyArrayDyn<'py, f64>,
    f: impl Fn(f64) -> lc::Result<f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    checked_len("the array", values.shape())?;
    let out: Vec<f64> = values
        .as_array()
        .iter()
        .map(|v| f(*v))
        .collect::<lc::Result<_>>()
        .py_err()?;
    PyArray1::from_vec(py, out).reshape(values.shape().to_vec())
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("LayeredContactError", py.get_type::<LayeredContactError>())?;
    m.add("InvalidInputError", py.get_type::<InvalidInputError>())?;
    m.add("ConvergenceError", py.get_type::<ConvergenceError>())?;
    m.add("EdgeContactWarning", py.get_type::<EdgeContactWarning>())?;
    m.add("CohesiveZoneWarning", py.get_type::<CohesiveZoneWarning>())?;
    m.add_class::<Material>()?;
    m.add_class::<Substrate>()?;
    m.add_class::<Indenter>()?;
    m.add_class::<Solution>()?;
    m.add_class::<ContactSolver>()?;
    m.add_class::<Curve>()?;
    m.add_class::<adhesion::CohesivePullOff>()?;
    m.add_function(wrap_pyfunction!(run_scene, m)?)?;
    m.add_function(wrap_pyfunction!(indenters::rough_surface_heights, m)?)?;
    m.add_function(wrap_pyfunction!(indenters::refine_heights, m)?)?;
    m.add_function(wrap_pyfunction!(stresses::subsurface_stress, m)?)?;
    m.add_function(wrap_pyfunction!(check_scene, m)?)?;
    m.add_function(wrap_pyfunction!(scene_reference, m)?)?;
    m.add_function(wrap_pyfunction!(scene_schema, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::hertz_force, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::hertz_contact_radius, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::jkr_state, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::jkr_pull_off_force, m)?)?;
    m.add_function(wrap_pyfunction!(adhesion::jkr_sinusoid_pull_off, m)?)?;
    m.add_function(wrap_pyfunction!(adhesion::edge_release, m)?)?;
    m.add_function(wrap_pyfunction!(adhesion::peel_punch, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::flat_punch_stiffness, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::paraboloid_pull_off_force, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::paraboloid_state, m)?)?;
    m.add_class::<curves::ForceCurve>()?;
    m.add_class::<curves::ModulusFamily>()?;
    m.add_function(wrap_pyfunction!(curves::before_jump_off, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::paraboloid_series, m)?)?;
    m.add_function(wrap_pyfunction!(curves::tip_pull_off, m)?)?;
    m.add_function(wrap_pyfunction!(curves::tip_pressure, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::flat_punch_pull_off_force, m)?)?;
    Ok(())
}
