//! Rigid indenters: the built-in shapes, height maps and tilts.

use std::sync::Arc;

use numpy::{
    PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArray2, PyReadonlyArrayDyn,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;

use layered_contact as lc;

use super::*;

/// A rigid indenter; built by the static methods.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
pub(crate) struct Indenter {
    pub(crate) inner: Arc<dyn lc::indenter::Indenter + Send + Sync>,
    pub(crate) name: String,
}

/// A shared indenter as a library indenter.
pub(crate) struct Shared(pub(crate) Arc<dyn lc::indenter::Indenter + Send + Sync>);

impl lc::indenter::Indenter for Shared {
    fn height(&self, x: f64, y: f64) -> f64 {
        self.0.height(x, y)
    }

    fn bounding_radius(&self) -> f64 {
        self.0.bounding_radius()
    }
}

impl Indenter {
    fn new(shape: impl lc::indenter::Indenter + Send + Sync + 'static, name: String) -> Self {
        Indenter {
            inner: Arc::new(shape),
            name,
        }
    }
}

#[pymethods]
impl Indenter {
    /// A flat cylindrical punch of radius `radius` (m).
    #[staticmethod]
    fn flat_punch(radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::FlatPunch::new(radius).py_err()?;
        Ok(Indenter::new(
            shape,
            format!("flat_punch(radius={radius:e})"),
        ))
    }

    /// A sphere of radius `radius` (m), the exact spherical cap.
    #[staticmethod]
    fn sphere(radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::Sphere::new(radius).py_err()?;
        Ok(Indenter::new(shape, format!("sphere(radius={radius:e})")))
    }

    /// A paraboloid of tip radius `radius` (m): f = r^2 / (2 R).
    #[staticmethod]
    fn paraboloid(radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::Paraboloid::new(radius).py_err()?;
        Ok(Indenter::new(
            shape,
            format!("paraboloid(radius={radius:e})"),
        ))
    }

    /// A cone of half-angle `half_angle` (rad, axis to face) and base radius
    /// `base_radius` (m).
    #[staticmethod]
    fn cone(half_angle: f64, base_radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::Cone::new(half_angle, base_radius).py_err()?;
        Ok(Indenter::new(
            shape,
            format!("cone(half_angle={half_angle}, base_radius={base_radius:e})"),
        ))
    }

    /// Any shape as a 2D array of heights (m, `rows x columns`, `+inf` where
    /// it cannot touch) on square cells of side `spacing` (m), centred on
    /// the axis: `heights[i, j]` is the height at
    /// `x = (i + 1/2 - rows/2) spacing`, `y = (j + 1/2 - columns/2) spacing`.
    #[staticmethod]
    fn height_map(heights: PyReadonlyArray2<'_, f64>, spacing: f64) -> PyResult<Self> {
        let shape = heights.shape();
        let (rows, columns) = (shape[0], shape[1]);
        // The grid's limits first: a broadcast array of 2^31 values copied
        // 16 GB before they were checked.
        let grid = lc::Grid::new(rows, columns, spacing).py_err()?;
        let values: Vec<f64> = heights.as_array().iter().copied().collect();
        let map = lc::indenter::HeightMap::new(grid, values).py_err()?;
        Ok(Indenter::new(
            map,
            format!("height_map({rows} x {columns}, spacing={spacing:e})"),
        ))
    }

    /// The tilted indenter: rotated by `angle_y` about the y axis (the face
    /// rises with x) and `angle_x` about the x axis (rad, small).
    fn tilted(&self, angle_y: f64, angle_x: f64) -> PyResult<Self> {
        let shape =
            lc::indenter::Tilted::new(Shared(self.inner.clone()), angle_y, angle_x).py_err()?;
        Ok(Indenter::new(
            shape,
            format!("{}.tilted({angle_y}, {angle_x})", self.name),
        ))
    }

    /// The height f(x, y) (m) above the lowest point; `inf` where it cannot
    /// touch. Vectorised over NumPy arrays of equal shape.
    fn height<'py>(
        &self,
        py: Python<'py>,
        x: PyReadonlyArrayDyn<'py, f64>,
        y: PyReadonlyArrayDyn<'py, f64>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        if x.shape() != y.shape() {
            return Err(InvalidInputError::new_err(format!(
                "x and y must have the same shape, got {:?} and {:?}",
                x.shape(),
                y.shape()
            )));
        }
        checked_len("x", x.shape())?;
        let values: Vec<f64> = x
            .as_array()
            .iter()
            .zip(y.as_array().iter())
            .map(|(x, y)| self.inner.height(*x, *y))
            .collect();
        PyArray1::from_vec(py, values).reshape(x.shape().to_vec())
    }

    /// Radius (m) of the disc outside which the indenter cannot touch.
    #[getter]
    fn bounding_radius(&self) -> f64 {
        self.inner.bounding_radius()
    }

    fn __repr__(&self) -> String {
        format!("Indenter.{}", self.name)
    }
}
