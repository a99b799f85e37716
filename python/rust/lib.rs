//! Python bindings of `layered-contact`: a thin layer over the Rust crate's
//! public API. Library errors become the exceptions below with the library's
//! own messages; solves release the GIL.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use numpy::{
    PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArray2, PyReadonlyArrayDyn,
    PyUntypedArrayMethods,
};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use std::time::{Duration, Instant};

use layered_contact as lc;

mod adhesion;
mod analytic;
mod curves;
mod stresses;

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

/// An isotropic linear-elastic material.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
struct Material {
    inner: lc::Material,
}

#[pymethods]
impl Material {
    #[new]
    fn new(youngs_modulus: f64, poisson_ratio: f64) -> PyResult<Self> {
        Ok(Material {
            inner: lc::Material::new(youngs_modulus, poisson_ratio).py_err()?,
        })
    }

    /// Young's modulus E, Pa.
    #[getter]
    fn youngs_modulus(&self) -> f64 {
        self.inner.youngs_modulus()
    }

    /// Poisson ratio nu.
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.inner.poisson_ratio()
    }

    /// Plane-strain modulus E* = E / (1 - nu^2), Pa.
    #[getter]
    fn contact_modulus(&self) -> f64 {
        self.inner.contact_modulus()
    }

    fn __repr__(&self) -> String {
        format!(
            "Material(youngs_modulus={:e}, poisson_ratio={})",
            self.inner.youngs_modulus(),
            self.inner.poisson_ratio()
        )
    }

    /// Pickling (multiprocessing, Dask): the constructor and its arguments.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (f64, f64))> {
        let m = slf.get().inner;
        Ok((
            slf.get_type().into_any(),
            (m.youngs_modulus(), m.poisson_ratio()),
        ))
    }
}

/// The elastic body: a half-space, a layer, or a stack of bonded layers, on a
/// rigid or elastic base.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
struct Substrate {
    inner: lc::Substrate,
}

#[pymethods]
impl Substrate {
    /// A homogeneous half-space.
    #[staticmethod]
    fn half_space(material: &Material) -> Self {
        Substrate {
            inner: lc::Substrate::half_space(material.inner),
        }
    }

    /// A layer of thickness `thickness` (m) resting on a rigid base without
    /// friction (Dimitriadis et al. 2002's unbonded layer).
    #[staticmethod]
    fn layer_resting_on_rigid_base(layer: &Material, thickness: f64) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_resting_on_rigid_base(layer.inner, thickness).py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) resting without friction on an
    /// elastic half-space of `base`.
    #[staticmethod]
    fn layer_resting_on_elastic_base(
        layer: &Material,
        thickness: f64,
        base: &Material,
    ) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_resting_on_elastic_base(layer.inner, thickness, base.inner)
                .py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) bonded to a rigid base.
    #[staticmethod]
    fn layer_on_rigid_base(layer: &Material, thickness: f64) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_on_rigid_base(layer.inner, thickness).py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) bonded to an elastic half-space.
    #[staticmethod]
    fn layer_on_elastic_base(layer: &Material, thickness: f64, base: &Material) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_on_elastic_base(layer.inner, thickness, base.inner)
                .py_err()?,
        })
    }

    /// Bonded `layers`, each `(material, thickness)` (m), top first, on an
    /// elastic half-space of `base`, or on a rigid base when `base` is None.
    /// Adjacent layers of one material merge; one layer left is a coating.
    #[staticmethod]
    #[pyo3(signature = (layers, base=None))]
    fn stack(
        layers: Vec<(PyRef<'_, Material>, f64)>,
        base: Option<PyRef<'_, Material>>,
    ) -> PyResult<Self> {
        let layers: Vec<(lc::Material, f64)> = layers.iter().map(|(m, h)| (m.inner, *h)).collect();
        let base = base.map_or(lc::Base::Rigid, |m| lc::Base::Elastic(m.inner));
        Ok(Substrate {
            inner: lc::Substrate::stack(&layers, base).py_err()?,
        })
    }

    /// The number of layers (0 for a half-space).
    #[getter]
    fn layer_count(&self) -> usize {
        match &self.inner {
            lc::Substrate::HalfSpace(_) => 0,
            lc::Substrate::Stack(stack) => stack.layers().len(),
            _ => 1,
        }
    }

    /// The total thickness of the layers (m); None for a half-space.
    #[getter]
    fn total_thickness(&self) -> Option<f64> {
        self.inner.total_thickness()
    }

    /// `Substrate.half_space(Material(...))` and the like: the constructor
    /// that rebuilds it.
    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let (name, arguments) = slf.get().parts(slf.py())?;
        let arguments = arguments
            .iter()
            .map(|a| Ok(a.bind(slf.py()).repr()?.to_string()))
            .collect::<PyResult<Vec<String>>>()?;
        Ok(format!("Substrate.{name}({})", arguments.join(", ")))
    }

    /// Pickling (multiprocessing, Dask): the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let (name, arguments) = slf.get().parts(py)?;
        Ok((slf.get_type().getattr(name)?, PyTuple::new(py, arguments)?))
    }
}

impl Substrate {
    /// The constructor's name and arguments that rebuild this substrate.
    fn parts(&self, py: Python<'_>) -> PyResult<(&'static str, Vec<Py<PyAny>>)> {
        let material = |m: &lc::Material| -> PyResult<Py<PyAny>> {
            Ok(Py::new(py, Material { inner: *m })?.into_any())
        };
        let number =
            |v: f64| -> PyResult<Py<PyAny>> { Ok(v.into_pyobject(py)?.into_any().unbind()) };
        Ok(match &self.inner {
            lc::Substrate::HalfSpace(m) => ("half_space", vec![material(m)?]),
            lc::Substrate::Coated(c) => {
                let (layer, h) = (material(c.layer())?, number(c.thickness())?);
                match (c.base(), c.is_frictionless()) {
                    (lc::Base::Rigid, false) => ("layer_on_rigid_base", vec![layer, h]),
                    (lc::Base::Rigid, true) => ("layer_resting_on_rigid_base", vec![layer, h]),
                    (lc::Base::Elastic(b), false) => {
                        ("layer_on_elastic_base", vec![layer, h, material(b)?])
                    }
                    (lc::Base::Elastic(b), true) => (
                        "layer_resting_on_elastic_base",
                        vec![layer, h, material(b)?],
                    ),
                }
            }
            lc::Substrate::Stack(stack) => {
                let layers = stack
                    .layers()
                    .iter()
                    .map(|l| {
                        Ok(
                            PyTuple::new(py, [material(l.material())?, number(l.thickness())?])?
                                .into_any()
                                .unbind(),
                        )
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                let base = match stack.base() {
                    lc::Base::Rigid => py.None(),
                    lc::Base::Elastic(b) => material(b)?,
                };
                (
                    "stack",
                    vec![PyList::new(py, layers)?.into_any().unbind(), base],
                )
            }
        })
    }
}

/// A rigid indenter; built by the static methods.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
struct Indenter {
    inner: Arc<dyn lc::indenter::Indenter + Send + Sync>,
    name: String,
}

/// A shared indenter as a library indenter.
struct Shared(Arc<dyn lc::indenter::Indenter + Send + Sync>);

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

/// The cell centres of `grid` along its rows (`x`) and columns (`y`), m.
fn centres(py: Python<'_>, grid: &lc::Grid) -> (Py<PyAny>, Py<PyAny>) {
    let x = (0..grid.rows()).map(|i| grid.cell_centre(i, 0).0).collect();
    let y = (0..grid.columns())
        .map(|j| grid.cell_centre(0, j).1)
        .collect();
    (array(py, x), array(py, y))
}

/// A field as a `rows x columns` array.
fn field(py: Python<'_>, array: &Option<ndarray::Array2<f64>>) -> PyResult<Option<Py<PyAny>>> {
    array
        .as_ref()
        .map(|a| {
            let (rows, columns) = a.dim();
            let values: Vec<f64> = a.iter().copied().collect();
            Ok(PyArray1::from_vec(py, values)
                .reshape([rows, columns])?
                .into_any()
                .unbind())
        })
        .transpose()
}

/// One equilibrium of the boundary-element solver. Arrays are
/// `rows x columns` with `[i, j]` at `(x[i], y[j])`, m from the axis.
#[pyclass(module = "layered_contact._native", frozen, get_all)]
struct Solution {
    /// Depth of the indenter's lowest point below the undeformed surface, m.
    depth: f64,
    /// Total force, N (negative when adhesion pulls).
    force: f64,
    /// Contact area, m^2.
    contact_area: f64,
    /// Radius of the circle of equal area, m.
    contact_radius: f64,
    /// Cells in contact.
    contact_cells: usize,
    /// Whether the contact touches the edge of an isolated grid.
    edge_contact: bool,
    /// Iterations on this grid.
    iterations: usize,
    /// Final residual.
    residual: f64,
    /// Cell pressures, Pa (compression positive).
    pressure: Option<Py<PyAny>>,
    /// Surface displacements into the body, m.
    displacement: Option<Py<PyAny>>,
    /// Gap between indenter and surface, m (`inf` where it cannot reach).
    gap: Option<Py<PyAny>>,
    /// Cell-centre coordinates along the rows, m.
    x: Py<PyAny>,
    /// Cell-centre coordinates along the columns, m.
    y: Py<PyAny>,
}

impl Solution {
    /// The solution as Python sees it; an [`EdgeContactWarning`] if its
    /// contact reaches the edge of an isolated grid (raised instead where
    /// warnings are errors).
    fn new(py: Python<'_>, s: &lc::solver::Solution, grid: &lc::Grid) -> PyResult<Self> {
        if s.edge_contact {
            let message = std::ffi::CString::new(format!(
                "the contact ({} cells, radius {:e} m) reaches the edge of the isolated \
                 {} x {} grid: enlarge the grid",
                s.contact_cells,
                s.contact_radius,
                grid.rows(),
                grid.columns()
            ))?;
            PyErr::warn(py, &py.get_type::<EdgeContactWarning>(), &message, 1)?;
        }
        let (x, y) = centres(py, grid);
        Ok(Solution {
            depth: s.depth,
            force: s.force,
            contact_area: s.contact_area,
            contact_radius: s.contact_radius,
            contact_cells: s.contact_cells,
            edge_contact: s.edge_contact,
            iterations: s.iterations,
            residual: s.residual,
            pressure: field(py, &s.pressure)?,
            displacement: field(py, &s.displacement)?,
            gap: field(py, &s.gap)?,
            x,
            y,
        })
    }
}

#[pymethods]
impl Solution {
    fn __repr__(&self) -> String {
        format!(
            "Solution(depth={:e}, force={:e}, contact_radius={:e}, iterations={})",
            self.depth, self.force, self.contact_radius, self.iterations
        )
    }
}

/// The boundary-element solver on one substrate and grid: kernel and FFT
/// plans are built once, solves reuse them (and the last solve as a warm
/// start when asked). Solves release the GIL.
#[pyclass(module = "layered_contact._native")]
struct ContactSolver {
    inner: lc::solver::ContactSolver,
    warm: Option<lc::solver::WarmStart>,
}

#[pymethods]
impl ContactSolver {
    /// A solver for `substrate` on `rows x columns` square cells of side
    /// `spacing` (m), isolated (the body is infinite) or periodic.
    #[new]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    #[pyo3(signature = (substrate, rows, columns, spacing, periodic=false, tolerance=1e-8, max_iterations=10_000))]
    fn new(
        py: Python<'_>,
        substrate: &Substrate,
        rows: usize,
        columns: usize,
        spacing: f64,
        periodic: bool,
        tolerance: f64,
        max_iterations: usize,
    ) -> PyResult<Self> {
        let grid = lc::Grid::new(rows, columns, spacing).py_err()?;
        let boundary = if periodic {
            lc::Boundary::Periodic
        } else {
            lc::Boundary::Isolated
        };
        let params = lc::solver::SolverParams {
            tolerance,
            max_iterations,
            fields: lc::solver::Fields::all(),
            ..lc::solver::SolverParams::default()
        };
        let substrate = substrate.inner.clone();
        let inner = py
            .detach(|| lc::solver::ContactSolver::new(&substrate, &grid, boundary, params))
            .py_err()?;
        Ok(ContactSolver { inner, warm: None })
    }

    /// The equilibrium at depth `depth` (m); `warm_start` starts from the
    /// previous solve (load stepping).
    #[pyo3(signature = (indenter, depth, warm_start=false))]
    fn solve_depth(
        &mut self,
        py: Python<'_>,
        indenter: &Indenter,
        depth: f64,
        warm_start: bool,
    ) -> PyResult<Solution> {
        self.solve(py, indenter, warm_start, |solver, shape, warm| {
            solver.solve_depth(shape, depth, warm, &mut ())
        })
    }

    /// The equilibrium under total force `force` (N, >= 0).
    #[pyo3(signature = (indenter, force, warm_start=false))]
    fn solve_force(
        &mut self,
        py: Python<'_>,
        indenter: &Indenter,
        force: f64,
        warm_start: bool,
    ) -> PyResult<Solution> {
        self.solve(py, indenter, warm_start, |solver, shape, warm| {
            solver.solve_force(shape, force, warm, &mut ())
        })
    }

    /// `(rows, columns, spacing)`.
    #[getter]
    fn grid(&self) -> (usize, usize, f64) {
        let g = self.inner.grid();
        (g.rows(), g.columns(), g.spacing())
    }
}

type Solved = lc::Result<(lc::solver::Solution, lc::solver::WarmStart)>;

impl ContactSolver {
    fn solve(
        &mut self,
        py: Python<'_>,
        indenter: &Indenter,
        warm_start: bool,
        run: impl FnOnce(
                &mut lc::solver::ContactSolver,
                &Shared,
                Option<&lc::solver::WarmStart>,
            ) -> Solved
            + Send,
    ) -> PyResult<Solution> {
        let shape = Shared(indenter.inner.clone());
        let warm = if warm_start { self.warm.take() } else { None };
        let inner = &mut self.inner;
        let (solution, warm) = py.detach(|| run(inner, &shape, warm.as_ref())).py_err()?;
        self.warm = Some(warm);
        Solution::new(py, &solution, self.inner.grid())
    }
}

/// A scene from a dict (the structure of a scene file) or a TOML/JSON file.
fn read_scene(py: Python<'_>, scene: &Bound<'_, PyAny>) -> PyResult<lc::scene::Scene> {
    if let Ok(dict) = scene.cast::<PyDict>() {
        let json: String = py
            .import("json")?
            .call_method1("dumps", (dict,))?
            .extract()?;
        return lc::scene::Scene::from_json(&json).py_err();
    }
    let path: PathBuf = scene.extract().map_err(|_| {
        InvalidInputError::new_err("a scene is a dict or the path of a TOML or JSON file")
    })?;
    lc::scene::Scene::read(path).py_err()
}

/// A step as a dict.
fn step_dict<'py>(py: Python<'py>, s: &lc::scene::Step) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("phase", s.phase.name())?;
    d.set_item("depth", s.depth)?;
    d.set_item("force", s.force)?;
    d.set_item("contact_area", s.contact_area)?;
    d.set_item("contact_radius", s.contact_radius)?;
    d.set_item("iterations", s.iterations)?;
    Ok(d)
}

/// The result of a scene: its steps as arrays, and the peak's fields.
#[pyclass(module = "layered_contact._native", frozen, get_all)]
struct Curve {
    /// "loading" or "unloading" for each step.
    phase: Vec<String>,
    /// Depths, m.
    depth: Py<PyAny>,
    /// Forces, N.
    force: Py<PyAny>,
    /// Contact areas, m^2.
    contact_area: Py<PyAny>,
    /// Contact radii (equal area), m.
    contact_radius: Py<PyAny>,
    /// Solver iterations per step.
    iterations: Vec<usize>,
    /// Contact stiffness at the end of loading, N/m (None without two
    /// loading steps in contact).
    stiffness: Option<f64>,
    /// The pull-off step as a dict (None without tension on unloading).
    pull_off: Option<Py<PyDict>>,
    /// `(rows, columns, spacing)` of the grid solved on.
    grid: (usize, usize, f64),
    /// The most loaded step with the fields the scene asked for (None if it
    /// asked for none).
    peak: Option<Py<Solution>>,
    /// Known limits of the method behind these numbers, as sentences
    /// (empty when there are none): see `layered_contact::scene::Caveat`.
    caveats: Vec<String>,
    /// The stresses below the surface at the most loaded step, when the
    /// scene's `outputs.stresses` asks for them (see `subsurface_stress`).
    stresses: Option<Py<PyDict>>,
}

#[pymethods]
impl Curve {
    fn __len__(&self) -> usize {
        self.phase.len()
    }

    fn __repr__(&self) -> String {
        let stiffness = self
            .stiffness
            .map_or("None".to_string(), |k| format!("{k:e}"));
        format!(
            "Curve({} steps on a {} x {} grid, stiffness={stiffness})",
            self.phase.len(),
            self.grid.0,
            self.grid.1,
        )
    }
}

fn array(py: Python<'_>, values: Vec<f64>) -> Py<PyAny> {
    PyArray1::from_vec(py, values).into_any().unbind()
}

/// Runs a scene (a dict or a TOML/JSON file path), calling
/// `progress(step_dict)` after each step; `indenter` replaces the scene's
/// indenter by any `Indenter` (sized from its bounding radius). Releases
/// the GIL while solving.
#[pyfunction]
#[pyo3(signature = (scene, progress=None, indenter=None))]
fn run_scene(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    progress: Option<Py<PyAny>>,
    indenter: Option<&Indenter>,
) -> PyResult<Curve> {
    let mut scene = read_scene(py, scene)?;
    if let Some(shape) = indenter {
        scene.indenter = lc::scene::IndenterSpec::Custom(lc::scene::CustomIndenter::new(Shared(
            shape.inner.clone(),
        )));
    }
    // The first error the callback raises, or Ctrl-C (checked every 10 ms
    // inside the solves and after every step), stops the run and is raised.
    let raised: Arc<Mutex<Option<PyErr>>> = Arc::default();
    let interrupt: lc::solver::Interrupt = {
        let raised = Arc::clone(&raised);
        let last = Mutex::new(Instant::now());
        Arc::new(move || {
            let mut raised = raised.lock().unwrap_or_else(|e| e.into_inner());
            if raised.is_some() {
                return true;
            }
            let mut last = last.lock().unwrap_or_else(|e| e.into_inner());
            if last.elapsed() < Duration::from_millis(10) {
                return false;
            }
            *last = Instant::now();
            match Python::attach(|py| py.check_signals()) {
                Ok(()) => false,
                Err(e) => {
                    *raised = Some(e);
                    true
                }
            }
        })
    };
    let curve = py.detach(|| {
        let mut solver = scene.solver()?;
        solver.set_interrupt(Some(interrupt));
        scene.run_on(&mut solver, &mut |step| {
            let mut raised = raised.lock().unwrap_or_else(|e| e.into_inner());
            if raised.is_some() {
                return;
            }
            Python::attach(|py| {
                let outcome = py.check_signals().and_then(|()| match &progress {
                    Some(callback) => step_dict(py, step)
                        .and_then(|d| callback.call1(py, (d,)))
                        .map(|_| ()),
                    None => Ok(()),
                });
                if let Err(e) = outcome {
                    *raised = Some(e);
                }
            });
        })
    });
    if let Some(e) = raised.lock().unwrap_or_else(|e| e.into_inner()).take() {
        return Err(e);
    }
    let curve = curve.py_err()?;
    let steps = &curve.steps;
    let column = |f: fn(&lc::scene::Step) -> f64| array(py, steps.iter().map(f).collect());
    let pull_off = curve
        .pull_off()
        .map(|s| step_dict(py, s).map(Bound::unbind))
        .transpose()?;
    let peak = curve
        .peak
        .as_ref()
        .map(|s| Py::new(py, Solution::new(py, s, &curve.grid)?))
        .transpose()?;
    Ok(Curve {
        phase: steps.iter().map(|s| s.phase.name().to_string()).collect(),
        depth: column(|s| s.depth),
        force: column(|s| s.force),
        contact_area: column(|s| s.contact_area),
        contact_radius: column(|s| s.contact_radius),
        iterations: steps.iter().map(|s| s.iterations).collect(),
        stiffness: curve.stiffness(),
        pull_off,
        grid: (
            curve.grid.rows(),
            curve.grid.columns(),
            curve.grid.spacing(),
        ),
        peak,
        caveats: curve.caveats.iter().map(ToString::to_string).collect(),
        stresses: curve
            .stresses
            .as_ref()
            .map(|r| stresses::stresses_dict(py, &curve.grid, r).map(Bound::unbind))
            .transpose()?,
    })
}

/// Validates a scene; returns `(rows, columns, spacing, memory_bytes)` of
/// the grid it is solved on.
#[pyfunction]
fn check_scene(py: Python<'_>, scene: &Bound<'_, PyAny>) -> PyResult<(usize, usize, f64, usize)> {
    let scene = read_scene(py, scene)?;
    scene.validate().py_err()?;
    let grid = scene.grid().py_err()?;
    let bytes = lc::kernel::memory_estimate(&grid, scene.boundary);
    Ok((grid.rows(), grid.columns(), grid.spacing(), bytes))
}

/// The JSON Schema of a scene (a dict or file), as JSON text: every key
/// with its type, default and description.
#[pyfunction]
fn scene_schema() -> String {
    lc::scene::Scene::json_schema()
}

/// The exact values of a scene's results where they exist, as
/// `{quantity: value}` (see `Scene::reference` of the Rust crate).
#[pyfunction]
fn scene_reference<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let scene = read_scene(py, scene)?;
    let references = py.detach(|| scene.reference()).py_err()?;
    let out = PyDict::new(py);
    for r in references {
        out.set_item(PyString::new(py, r.quantity.name()), r.value)?;
    }
    Ok(out)
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
    m.add_class::<Material>()?;
    m.add_class::<Substrate>()?;
    m.add_class::<Indenter>()?;
    m.add_class::<Solution>()?;
    m.add_class::<ContactSolver>()?;
    m.add_class::<Curve>()?;
    m.add_function(wrap_pyfunction!(run_scene, m)?)?;
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
    m.add_function(wrap_pyfunction!(analytic::flat_punch_stiffness, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::paraboloid_pull_off_force, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::paraboloid_state, m)?)?;
    m.add_class::<curves::ForceCurve>()?;
    m.add_class::<curves::ModulusFamily>()?;
    m.add_function(wrap_pyfunction!(curves::before_jump_off, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::paraboloid_series, m)?)?;
    m.add_function(wrap_pyfunction!(curves::tip_pull_off, m)?)?;
    m.add_function(wrap_pyfunction!(analytic::flat_punch_pull_off_force, m)?)?;
    Ok(())
}
