//! Bindings of the local Griffith criterion (`ContactSolver.edge_release`,
//! `ContactSolver.peel_punch`) and of the adhesive sinusoid's exact
//! pull-off.

use numpy::{PyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use layered_contact as lc;

use super::{ContactSolver, Indenter, Material, OrPy, Shared};

/// The energy release rate along the edge of `contact` (a boolean
/// `rows x columns` mask of cells held bonded to `indenter` at `depth`, m),
/// smoothed over `window` cells: a dict of arrays over the edge cells
/// (`row`, `column`, `x`, `y`, `normal_x`, `normal_y`, `release_rate` in
/// J/m^2, `stress_intensity` in Pa m^1/2, positive where the edge pulls),
/// the floats `force` (N) and `depth` (m), and `fit` and `fit_functions`:
/// `"modes"` and 5 or 9 where the rates were fitted over the whole edge
/// (`EdgeFit::Modes`), `"window"` and 0 where smoothed by the window.
#[pyfunction]
#[pyo3(signature = (solver, indenter, depth, contact, window=lc::solver::EDGE_WINDOW))]
pub(crate) fn edge_release<'py>(
    py: Python<'py>,
    mut solver: PyRefMut<'_, ContactSolver>,
    indenter: &Indenter,
    depth: f64,
    contact: PyReadonlyArray2<'py, bool>,
    window: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let mask = contact.as_array().to_owned();
    let shape = Shared(indenter.inner.clone());
    let inner = &mut solver.inner;
    let edge = py
        .detach(|| inner.edge_release(&shape, depth, &mask, window))
        .py_err()?;
    let column = |f: &dyn Fn(&lc::solver::EdgePoint) -> f64| -> Vec<f64> {
        edge.points.iter().map(f).collect()
    };
    let d = PyDict::new(py);
    let cells = |f: &dyn Fn(&lc::solver::EdgePoint) -> usize| -> Vec<usize> {
        edge.points.iter().map(f).collect()
    };
    d.set_item("row", PyArray1::from_vec(py, cells(&|p| p.cell.0)))?;
    d.set_item("column", PyArray1::from_vec(py, cells(&|p| p.cell.1)))?;
    d.set_item("x", PyArray1::from_vec(py, column(&|p| p.position.0)))?;
    d.set_item("y", PyArray1::from_vec(py, column(&|p| p.position.1)))?;
    d.set_item("normal_x", PyArray1::from_vec(py, column(&|p| p.normal.0)))?;
    d.set_item("normal_y", PyArray1::from_vec(py, column(&|p| p.normal.1)))?;
    d.set_item(
        "release_rate",
        PyArray1::from_vec(py, column(&|p| p.release_rate)),
    )?;
    d.set_item(
        "stress_intensity",
        PyArray1::from_vec(py, column(&|p| p.stress_intensity)),
    )?;
    d.set_item("force", edge.force)?;
    d.set_item("depth", edge.depth)?;
    let (fit, functions) = fit_name(&edge.fit);
    d.set_item("fit", fit)?;
    d.set_item("fit_functions", functions)?;
    Ok(d)
}

/// `("modes", functions)`, `("window", 0)`, or `("other", 0)` for a way
/// added since.
fn fit_name(fit: &lc::solver::EdgeFit) -> (&'static str, usize) {
    match fit {
        lc::solver::EdgeFit::Modes { functions } => ("modes", *functions),
        lc::solver::EdgeFit::Window { .. } => ("window", 0),
        _ => ("other", 0),
    }
}

/// The pull-off of a flat punch (tilted or not) bonded over its whole face,
/// or over `bonded` (a boolean `rows x columns` mask of face cells:
/// `ContactSolver::peel_punch_from`), along its peeling path
/// (`ContactSolver::peel_punch`): a dict of arrays over the
/// path's contacts (`depth` m, `force` N, each the critical one of that
/// contact; `stiffness` N/m, its bonded `dF/dd`; `contact_cells`; `contact_area` m^2; `peels_x`, `peels_y` m,
/// where it peels next; `fitted_by_modes`, whether that contact's rates
/// were fitted over its whole edge) and `pull_off_force`, `pull_off_depth`,
/// `jump_off_depth`, `jump_off_force`, `detaches_at_onset`, `iterations`.
#[pyfunction]
#[pyo3(signature = (solver, indenter, work_of_adhesion, bonded=None))]
pub(crate) fn peel_punch<'py>(
    py: Python<'py>,
    mut solver: PyRefMut<'_, ContactSolver>,
    indenter: &Indenter,
    work_of_adhesion: f64,
    bonded: Option<PyReadonlyArray2<'py, bool>>,
) -> PyResult<Bound<'py, PyDict>> {
    let shape = Shared(indenter.inner.clone());
    let bonded: Option<Vec<bool>> = bonded.map(|b| b.as_array().iter().copied().collect());
    let inner = &mut solver.inner;
    let path = py
        .detach(|| match &bonded {
            Some(cells) => inner.peel_punch_from(&shape, work_of_adhesion, cells),
            None => inner.peel_punch(&shape, work_of_adhesion),
        })
        .py_err()?;
    let points = path.points();
    let column =
        |f: &dyn Fn(&lc::solver::PeelPoint) -> f64| -> Vec<f64> { points.iter().map(f).collect() };
    let d = PyDict::new(py);
    d.set_item("depth", PyArray1::from_vec(py, column(&|p| p.depth)))?;
    d.set_item("force", PyArray1::from_vec(py, column(&|p| p.force)))?;
    d.set_item(
        "stiffness",
        PyArray1::from_vec(py, column(&|p| p.stiffness)),
    )?;
    d.set_item(
        "contact_cells",
        PyArray1::from_vec(py, points.iter().map(|p| p.contact_cells).collect()),
    )?;
    d.set_item(
        "contact_area",
        PyArray1::from_vec(py, column(&|p| p.contact_area)),
    )?;
    d.set_item("peels_x", PyArray1::from_vec(py, column(&|p| p.peels_at.0)))?;
    d.set_item("peels_y", PyArray1::from_vec(py, column(&|p| p.peels_at.1)))?;
    let modes: Vec<bool> = points
        .iter()
        .map(|p| matches!(p.fit, lc::solver::EdgeFit::Modes { .. }))
        .collect();
    d.set_item("fitted_by_modes", PyArray1::from_vec(py, modes))?;
    d.set_item("pull_off_force", path.pull_off().force)?;
    d.set_item("pull_off_depth", path.pull_off().depth)?;
    d.set_item("jump_off_depth", path.jump_off().depth)?;
    d.set_item("jump_off_force", path.jump_off().force)?;
    d.set_item("detaches_at_onset", path.detaches_at_onset())?;
    d.set_item("iterations", path.iterations())?;
    Ok(d)
}

/// Johnson's (1995) adhesive sinusoid in plane strain: the pull-off mean
/// pressure (Pa, negative) and contact half-width (m) of a surface of
/// `wavelength` and `amplitude` (m) on a half-space of `material` with
/// `work_of_adhesion` (J/m^2).
#[pyfunction]
pub(crate) fn jkr_sinusoid_pull_off(
    material: &Material,
    wavelength: f64,
    amplitude: f64,
    work_of_adhesion: f64,
) -> PyResult<(f64, f64)> {
    lc::analytic::JkrSinusoid::new(&material.inner, wavelength, amplitude, work_of_adhesion)
        .and_then(|s| s.pull_off())
        .py_err()
}

/// The pull-off of an unloading through the cohesive zone
/// (`ContactSolver.cohesive_pull_off`; the crate's
/// `solver::CohesivePullOff`).
#[pyclass(module = "layered_contact._native", frozen, get_all)]
pub(crate) struct CohesivePullOff {
    /// The most tensile force along the unloading, N (negative).
    force: f64,
    /// The depth where it is reached, m.
    depth: f64,
    /// Cohesive solves taken.
    solves: usize,
    /// Conjugate-gradient iterations over all of them.
    iterations: usize,
    /// The widest patch of the contact at the pull-off, cells across.
    cells_across: f64,
    /// The zone's width on this grid, cells.
    zone_cells: f64,
}

/// The fields of a [`CohesivePullOff`] in the order of its declaration:
/// the pickled state.
type PullOffState = (f64, f64, usize, usize, f64, f64);

impl From<&lc::solver::CohesivePullOff> for CohesivePullOff {
    fn from(p: &lc::solver::CohesivePullOff) -> Self {
        Self::_rebuild((
            p.force,
            p.depth,
            p.solves,
            p.iterations,
            p.cells_across,
            p.zone_cells,
        ))
    }
}

#[pymethods]
impl CohesivePullOff {
    /// Whether the zone is wider than the contact at the pull-off: the
    /// zones of its two sides then meet and the force is a cohesive law's,
    /// not the JKR limit's (`CohesivePullOff::zone_spans_contact`).
    #[getter]
    fn zone_spans_contact(&self) -> bool {
        self.cells_across < self.zone_cells
    }

    /// Pickling (multiprocessing, Dask): the fields, read back by
    /// `_rebuild`.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (PullOffState,))> {
        let p = slf.get();
        let state = (
            p.force,
            p.depth,
            p.solves,
            p.iterations,
            p.cells_across,
            p.zone_cells,
        );
        Ok((slf.get_type().getattr("_rebuild")?, (state,)))
    }

    /// The pull-off whose `__reduce__` gave `state`.
    #[staticmethod]
    fn _rebuild(state: PullOffState) -> Self {
        let (force, depth, solves, iterations, cells_across, zone_cells) = state;
        CohesivePullOff {
            force,
            depth,
            solves,
            iterations,
            cells_across,
            zone_cells,
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "CohesivePullOff(force={:e}, depth={:e}, solves={}, iterations={}, \
             cells_across={}, zone_cells={})",
            self.force,
            self.depth,
            self.solves,
            self.iterations,
            self.cells_across,
            self.zone_cells
        )
    }
}
