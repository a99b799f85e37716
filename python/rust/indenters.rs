//! Rigid indenters: the built-in shapes, height maps and tilts.

use std::sync::Arc;

use numpy::{
    PyArray1, PyArray2, PyArrayDyn, PyArrayMethods, PyReadonlyArray2, PyReadonlyArrayDyn,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use layered_contact as lc;

use super::*;

/// A rigid indenter; built by the static methods.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
pub(crate) struct Indenter {
    pub(crate) inner: Arc<dyn lc::indenter::Indenter + Send + Sync>,
    /// How it was built: its repr and its pickling.
    recipe: Recipe,
}

/// The constructor call that rebuilds an indenter.
#[derive(Clone)]
enum Recipe {
    FlatPunch(f64),
    Sphere(f64),
    Paraboloid(f64),
    Cone(f64, f64),
    /// A height map, read back from the map itself.
    HeightMap(Arc<lc::indenter::HeightMap>),
    /// A rough surface, synthesised again from its seed.
    Rough(RoughSurface),
    /// `inner.tilted(angle_y, angle_x)`.
    Tilted(Box<Indenter>, f64, f64),
}

impl Recipe {
    /// The call as `repr` shows it (after `Indenter.`).
    fn describe(&self) -> String {
        match self {
            Recipe::FlatPunch(r) => format!("flat_punch(radius={r:e})"),
            Recipe::Sphere(r) => format!("sphere(radius={r:e})"),
            Recipe::Paraboloid(r) => format!("paraboloid(radius={r:e})"),
            Recipe::Cone(half_angle, base_radius) => {
                format!("cone(half_angle={half_angle}, base_radius={base_radius:e})")
            }
            Recipe::HeightMap(map) => {
                let grid = map.grid();
                format!(
                    "height_map({} x {}, spacing={:e})",
                    grid.rows(),
                    grid.columns(),
                    grid.spacing()
                )
            }
            Recipe::Rough(r) => format!(
                "rough_surface(hurst={}, seed={}, {} x {})",
                r.hurst, r.seed, r.cells, r.cells
            ),
            Recipe::Tilted(inner, angle_y, angle_x) => {
                format!("{}.tilted({angle_y}, {angle_x})", inner.recipe.describe())
            }
        }
    }
}

/// The parameters of `Indenter.rough_surface` and `rough_surface_heights`.
#[derive(Clone, Copy)]
struct RoughSurface {
    hurst: f64,
    long_cutoff: f64,
    short_cutoff: f64,
    seed: u64,
    cells: usize,
    spacing: f64,
    rms_height: Option<f64>,
    rms_slope: Option<f64>,
}

/// The most cells along a side of a synthesised surface (as in scenes).
const MAX_ROUGH_CELLS: usize = 8192;

impl RoughSurface {
    /// The surface and its grid, checked.
    fn build(&self) -> PyResult<(lc::topography::SelfAffine, lc::Grid)> {
        use lc::topography::Amplitude;
        let amplitude = match (self.rms_height, self.rms_slope) {
            (Some(h), None) => Amplitude::RmsHeight(h),
            (None, Some(s)) => Amplitude::RmsSlope(s),
            _ => {
                return Err(InvalidInputError::new_err(
                    "give exactly one of rms_height (m) and rms_slope",
                ))
            }
        };
        if !(2..=MAX_ROUGH_CELLS).contains(&self.cells) {
            return Err(InvalidInputError::new_err(format!(
                "cells must be between 2 and {MAX_ROUGH_CELLS} along a side, got {}",
                self.cells
            )));
        }
        let grid = lc::Grid::new(self.cells, self.cells, self.spacing).py_err()?;
        let surface = lc::topography::SelfAffine {
            hurst: self.hurst,
            amplitude,
            long_cutoff: self.long_cutoff,
            short_cutoff: self.short_cutoff,
            seed: self.seed,
        };
        Ok((surface, grid))
    }

    /// The arguments of the Python call, in order.
    fn arguments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        (
            self.hurst,
            self.long_cutoff,
            self.short_cutoff,
            self.seed,
            self.cells,
            self.spacing,
            self.rms_height,
            self.rms_slope,
        )
            .into_pyobject(py)
    }
}

/// The heights (m, `cells x cells`, zero mean, periodic) of the seeded
/// self-affine surface that `Indenter.rough_surface` and a scene's
/// `rough_surface` indenter use: Hurst exponent `hurst`, spectrum flat
/// beyond `long_cutoff` (m) and cut at `short_cutoff` (m, at least two
/// cells), scaled to `rms_height` (m) or `rms_slope` (give one).
#[pyfunction]
#[allow(clippy::too_many_arguments)] // Python keyword arguments
#[pyo3(signature = (hurst, long_cutoff, short_cutoff, seed, cells, spacing, rms_height=None, rms_slope=None))]
pub(crate) fn rough_surface_heights(
    py: Python<'_>,
    hurst: f64,
    long_cutoff: f64,
    short_cutoff: f64,
    seed: u64,
    cells: usize,
    spacing: f64,
    rms_height: Option<f64>,
    rms_slope: Option<f64>,
) -> PyResult<Py<PyArray2<f64>>> {
    let (surface, grid) = RoughSurface {
        hurst,
        long_cutoff,
        short_cutoff,
        seed,
        cells,
        spacing,
        rms_height,
        rms_slope,
    }
    .build()?;
    let heights = py.detach(|| surface.heights(&grid)).py_err()?;
    let array = ndarray::Array2::from_shape_vec((cells, cells), heights)
        .map_err(|e| InvalidInputError::new_err(e.to_string()))?;
    Ok(PyArray2::from_owned_array(py, array).unbind())
}

/// `heights` (a periodic map, rows x columns) on a grid `factor` times finer
/// each way over the same extent, by trigonometric interpolation through
/// the cell centres (the crate's `HeightMap::refined`): a surface whose
/// shortest wavelength is at least two cells is the same continuous
/// surface on the finer grid, for convergence studies. The finer cells are
/// `spacing / factor`.
#[pyfunction]
pub(crate) fn refine_heights(
    py: Python<'_>,
    heights: PyReadonlyArray2<'_, f64>,
    factor: usize,
) -> PyResult<Py<PyArray2<f64>>> {
    let shape = heights.shape();
    let (rows, columns) = (shape[0], shape[1]);
    // The spacing does not enter the interpolation.
    let grid = lc::Grid::new(rows, columns, 1.0).py_err()?;
    let values: Vec<f64> = heights.as_array().iter().copied().collect();
    let map = lc::indenter::HeightMap::new(grid, values).py_err()?;
    let fine = py.detach(|| map.refined(factor)).py_err()?;
    let (m0, m1) = (fine.grid().rows(), fine.grid().columns());
    let array = ndarray::Array2::from_shape_vec((m0, m1), fine.heights().to_vec())
        .map_err(|e| InvalidInputError::new_err(e.to_string()))?;
    Ok(PyArray2::from_owned_array(py, array).unbind())
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
    fn new(shape: impl lc::indenter::Indenter + Send + Sync + 'static, recipe: Recipe) -> Self {
        Indenter {
            inner: Arc::new(shape),
            recipe,
        }
    }
}

#[pymethods]
impl Indenter {
    /// A flat cylindrical punch of radius `radius` (m).
    #[staticmethod]
    fn flat_punch(radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::FlatPunch::new(radius).py_err()?;
        Ok(Indenter::new(shape, Recipe::FlatPunch(radius)))
    }

    /// A sphere of radius `radius` (m), the exact spherical cap.
    #[staticmethod]
    fn sphere(radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::Sphere::new(radius).py_err()?;
        Ok(Indenter::new(shape, Recipe::Sphere(radius)))
    }

    /// A paraboloid of tip radius `radius` (m): f = r^2 / (2 R).
    #[staticmethod]
    fn paraboloid(radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::Paraboloid::new(radius).py_err()?;
        Ok(Indenter::new(shape, Recipe::Paraboloid(radius)))
    }

    /// A cone of half-angle `half_angle` (rad, axis to face) and base radius
    /// `base_radius` (m).
    #[staticmethod]
    fn cone(half_angle: f64, base_radius: f64) -> PyResult<Self> {
        let shape = lc::indenter::Cone::new(half_angle, base_radius).py_err()?;
        Ok(Indenter::new(shape, Recipe::Cone(half_angle, base_radius)))
    }

    /// Johnson's wavy surface on a periodic `rows x columns` grid of cells
    /// `spacing` (m) wide: `amplitude (1 - cos(2 pi phase))`, `phase = w0 i /
    /// rows + w1 j / columns` exactly, `waves = (w0, w1)` whole waves along
    /// the rows and columns (crests along the grid for `(w, 0)`, at 45
    /// degrees on a square grid for `(w, w)`); its wavelength is `spacing /
    /// hypot(w0 / rows, w1 / columns)` (the crate's `HeightMap::wavy`).
    #[staticmethod]
    fn wavy(
        rows: usize,
        columns: usize,
        spacing: f64,
        waves: (usize, usize),
        amplitude: f64,
    ) -> PyResult<Self> {
        let grid = lc::Grid::new(rows, columns, spacing).py_err()?;
        let map = Arc::new(lc::indenter::HeightMap::wavy(grid, waves, amplitude).py_err()?);
        Ok(Indenter {
            inner: map.clone(),
            recipe: Recipe::HeightMap(map),
        })
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
        let map = Arc::new(lc::indenter::HeightMap::new(grid, values).py_err()?);
        Ok(Indenter {
            inner: map.clone(),
            recipe: Recipe::HeightMap(map),
        })
    }

    /// The seeded self-affine surface of `rough_surface_heights` (same
    /// arguments) as a rigid indenter, turned upside down (`f = max(h) -
    /// h`: its highest summit touches first, at depth 0), on its own
    /// `cells x cells` grid: the indenter of a scene's `rough_surface`.
    #[staticmethod]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    #[pyo3(signature = (hurst, long_cutoff, short_cutoff, seed, cells, spacing, rms_height=None, rms_slope=None))]
    fn rough_surface(
        py: Python<'_>,
        hurst: f64,
        long_cutoff: f64,
        short_cutoff: f64,
        seed: u64,
        cells: usize,
        spacing: f64,
        rms_height: Option<f64>,
        rms_slope: Option<f64>,
    ) -> PyResult<Self> {
        let recipe = RoughSurface {
            hurst,
            long_cutoff,
            short_cutoff,
            seed,
            cells,
            spacing,
            rms_height,
            rms_slope,
        };
        let (surface, grid) = recipe.build()?;
        let map = py.detach(|| surface.indenter(&grid)).py_err()?;
        Ok(Indenter::new(map, Recipe::Rough(recipe)))
    }

    /// The tilted indenter: rotated by `angle_y` about the y axis (the face
    /// rises with x) and `angle_x` about the x axis (rad, small).
    fn tilted(&self, angle_y: f64, angle_x: f64) -> PyResult<Self> {
        let shape =
            lc::indenter::Tilted::new(Shared(self.inner.clone()), angle_y, angle_x).py_err()?;
        Ok(Indenter::new(
            shape,
            Recipe::Tilted(Box::new(self.clone()), angle_y, angle_x),
        ))
    }

    /// Pickling (multiprocessing, Dask): the constructor and its arguments;
    /// a height map carries its heights, a rough surface its seed.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let class = slf.get_type();
        Ok(match &slf.get().recipe {
            Recipe::FlatPunch(r) => (class.getattr("flat_punch")?, (*r,).into_pyobject(py)?),
            Recipe::Sphere(r) => (class.getattr("sphere")?, (*r,).into_pyobject(py)?),
            Recipe::Paraboloid(r) => (class.getattr("paraboloid")?, (*r,).into_pyobject(py)?),
            Recipe::Cone(half_angle, base_radius) => (
                class.getattr("cone")?,
                (*half_angle, *base_radius).into_pyobject(py)?,
            ),
            Recipe::HeightMap(map) => {
                let grid = map.grid();
                let heights = ndarray::Array2::from_shape_vec(
                    (grid.rows(), grid.columns()),
                    map.heights().to_vec(),
                )
                .map_err(|e| InvalidInputError::new_err(e.to_string()))?;
                let heights = PyArray2::from_owned_array(py, heights);
                (
                    class.getattr("height_map")?,
                    (heights, grid.spacing()).into_pyobject(py)?,
                )
            }
            Recipe::Rough(recipe) => (class.getattr("rough_surface")?, recipe.arguments(py)?),
            Recipe::Tilted(inner, angle_y, angle_x) => {
                let inner = Bound::new(py, (**inner).clone())?;
                (
                    inner.getattr("tilted")?,
                    (*angle_y, *angle_x).into_pyobject(py)?,
                )
            }
        })
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
        format!("Indenter.{}", self.recipe.describe())
    }
}
