//! Scenes: runs, checks, references and the schema.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::time::{Duration, Instant};

use layered_contact as lc;

use super::*;

/// A scene from a dict (the structure of a scene file) or a TOML/JSON file.
pub(crate) fn read_scene(py: Python<'_>, scene: &Bound<'_, PyAny>) -> PyResult<lc::scene::Scene> {
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
pub(crate) fn step_dict<'py>(py: Python<'py>, s: &lc::scene::Step) -> PyResult<Bound<'py, PyDict>> {
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
pub(crate) struct Curve {
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
    /// The adhesion method the scene ran (`"energy_balance"`,
    /// `"cohesive_zone"` or `"mesh_criterion"`: the automatic one
    /// resolved), None without adhesion.
    adhesion_method: Option<String>,
    /// The stresses below the surface at the most loaded step, when the
    /// scene's `outputs.stresses` asks for them (see `subsurface_stress`).
    stresses: Option<Py<PyDict>>,
    /// The cohesive zone's scales on a layered body (`cells`, `length` m,
    /// `layer_thickness` m, `contact_radius` m of the peak, and
    /// `modulus_ratio`, the body's contact modulus at the zone's length
    /// over that at the peak contact's: from 30 with a zone long against
    /// the layer the caveat of a zone stiffer than the contact), None
    /// without a cohesive zone or a layer: see
    /// `layered_contact::scene::ZoneScales`.
    zone_scales: Option<Py<PyDict>>,
}

#[pymethods]
impl Curve {
    fn __len__(&self) -> usize {
        self.phase.len()
    }

    /// Pickling (multiprocessing, Dask): the fields as a dict, read back by
    /// `_rebuild`.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyDict>,))> {
        let py = slf.py();
        let c = slf.get();
        let state = PyDict::new(py);
        state.set_item("phase", &c.phase)?;
        state.set_item("depth", &c.depth)?;
        state.set_item("force", &c.force)?;
        state.set_item("contact_area", &c.contact_area)?;
        state.set_item("contact_radius", &c.contact_radius)?;
        state.set_item("iterations", &c.iterations)?;
        state.set_item("stiffness", c.stiffness)?;
        state.set_item("pull_off", &c.pull_off)?;
        state.set_item("grid", c.grid)?;
        state.set_item("peak", &c.peak)?;
        state.set_item("caveats", &c.caveats)?;
        state.set_item("adhesion_method", &c.adhesion_method)?;
        state.set_item("stresses", &c.stresses)?;
        state.set_item("zone_scales", &c.zone_scales)?;
        Ok((slf.get_type().getattr("_rebuild")?, (state,)))
    }

    /// The curve whose `__reduce__` gave `state`.
    #[staticmethod]
    fn _rebuild(state: &Bound<'_, PyDict>) -> PyResult<Self> {
        let get = |key: &str| {
            state
                .get_item(key)?
                .ok_or_else(|| InvalidInputError::new_err(format!("a pickled Curve without {key}")))
        };
        Ok(Curve {
            phase: get("phase")?.extract()?,
            depth: get("depth")?.unbind(),
            force: get("force")?.unbind(),
            contact_area: get("contact_area")?.unbind(),
            contact_radius: get("contact_radius")?.unbind(),
            iterations: get("iterations")?.extract()?,
            stiffness: get("stiffness")?.extract()?,
            pull_off: get("pull_off")?.extract()?,
            grid: get("grid")?.extract()?,
            peak: get("peak")?.extract()?,
            caveats: get("caveats")?.extract()?,
            adhesion_method: get("adhesion_method")?.extract()?,
            stresses: get("stresses")?.extract()?,
            // Absent from curves pickled before 0.2.0's zone scales.
            zone_scales: match state.get_item("zone_scales")? {
                Some(v) => v.extract()?,
                None => None,
            },
        })
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

pub(crate) fn array(py: Python<'_>, values: Vec<f64>) -> Py<PyAny> {
    PyArray1::from_vec(py, values).into_any().unbind()
}

/// Runs a scene (a dict or a TOML/JSON file path), calling
/// `progress(step_dict)` after each step and `iteration(dict)` (keys
/// `iteration`, `residual`, `contact_cells`) for every iteration of the
/// inner solves, or, with the energy-balance adhesion, once per contact set
/// of its family, before the steps (which then come at once); `indenter`
/// replaces the scene's indenter by any `Indenter` (sized from its bounding
/// radius). Releases the GIL while solving.
#[pyfunction]
#[pyo3(signature = (scene, progress=None, indenter=None, iteration=None))]
pub(crate) fn run_scene(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    progress: Option<Py<PyAny>>,
    indenter: Option<&Indenter>,
    iteration: Option<Py<PyAny>>,
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
        let mut observe = |info: &lc::solver::IterationInfo| {
            let Some(callback) = &iteration else {
                return;
            };
            let mut raised = raised.lock().unwrap_or_else(|e| e.into_inner());
            if raised.is_some() {
                return;
            }
            Python::attach(|py| {
                let d = PyDict::new(py);
                let outcome = d
                    .set_item("iteration", info.iteration)
                    .and_then(|()| d.set_item("residual", info.residual))
                    .and_then(|()| d.set_item("contact_cells", info.contact_cells))
                    .and_then(|()| callback.call1(py, (d,)))
                    .map(|_| ());
                if let Err(e) = outcome {
                    *raised = Some(e);
                }
            });
        };
        scene.run_observed(
            &mut solver,
            &mut |step| {
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
            },
            &mut observe,
        )
    });
    if let Some(e) = raised.lock().unwrap_or_else(|e| e.into_inner()).take() {
        return Err(e);
    }
    let curve = curve.py_err()?;
    let adhesion_method = scene.adhesion_method_run().map(|m| m.name().to_string());
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
        adhesion_method,
        stresses: curve
            .stresses
            .as_ref()
            .map(|r| stresses::stresses_dict(py, &curve.grid, r).map(Bound::unbind))
            .transpose()?,
        zone_scales: scene
            .zone_scales(&curve)
            .py_err()?
            .map(|z| zone_scales_dict(py, &z).map(Bound::unbind))
            .transpose()?,
    })
}

/// `ZoneScales` as a dict.
fn zone_scales_dict<'py>(
    py: Python<'py>,
    z: &lc::scene::ZoneScales,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("cells", z.cells)?;
    d.set_item("length", z.length)?;
    d.set_item("layer_thickness", z.layer_thickness)?;
    d.set_item("contact_radius", z.contact_radius)?;
    d.set_item("modulus_ratio", z.modulus_ratio)?;
    Ok(d)
}

/// Validates a scene; returns `(rows, columns, spacing, memory_bytes)` of
/// the grid it is solved on.
#[pyfunction]
pub(crate) fn check_scene(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
) -> PyResult<(usize, usize, f64, usize)> {
    let scene = read_scene(py, scene)?;
    scene.validate().py_err()?;
    let grid = scene.grid().py_err()?;
    let bytes = lc::kernel::memory_estimate(&grid, scene.boundary);
    Ok((grid.rows(), grid.columns(), grid.spacing(), bytes))
}

/// The JSON Schema of a scene (a dict or file), as JSON text: every key
/// with its type, default and description.
#[pyfunction]
pub(crate) fn scene_schema() -> String {
    lc::scene::Scene::json_schema()
}

/// The exact values of a scene's results where they exist, as
/// `{quantity: value}` (see `Scene::reference` of the Rust crate).
#[pyfunction]
pub(crate) fn scene_reference<'py>(
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
