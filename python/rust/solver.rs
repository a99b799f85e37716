//! The boundary-element solver and its solutions.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use layered_contact as lc;

use super::*;

/// The cell centres of `grid` along its rows (`x`) and columns (`y`), m.
pub(crate) fn centres(py: Python<'_>, grid: &lc::Grid) -> (Py<PyAny>, Py<PyAny>) {
    let x = (0..grid.rows()).map(|i| grid.cell_centre(i, 0).0).collect();
    let y = (0..grid.columns())
        .map(|j| grid.cell_centre(0, j).1)
        .collect();
    (array(py, x), array(py, y))
}

/// A field as a `rows x columns` array.
pub(crate) fn field(
    py: Python<'_>,
    array: &Option<ndarray::Array2<f64>>,
) -> PyResult<Option<Py<PyAny>>> {
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
pub(crate) struct Solution {
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
    /// Iterations of the multi-resolution start on the coarser grids.
    coarse_iterations: usize,
    /// The mean gap over the grid, m (`u_bar` of rough-contact studies;
    /// `None` without the gap field or where the indenter does not cover
    /// the grid).
    mean_gap: Option<f64>,
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
    pub(crate) fn new(py: Python<'_>, s: &lc::solver::Solution, grid: &lc::Grid) -> PyResult<Self> {
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
            coarse_iterations: s.coarse_iterations,
            mean_gap: s.mean_gap(),
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
    /// Pickling (multiprocessing, Dask): the fields as a dict, read back by
    /// `_rebuild` (without warning again about an edge contact).
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyDict>,))> {
        let py = slf.py();
        let s = slf.get();
        let state = PyDict::new(py);
        state.set_item("depth", s.depth)?;
        state.set_item("force", s.force)?;
        state.set_item("contact_area", s.contact_area)?;
        state.set_item("contact_radius", s.contact_radius)?;
        state.set_item("contact_cells", s.contact_cells)?;
        state.set_item("edge_contact", s.edge_contact)?;
        state.set_item("iterations", s.iterations)?;
        state.set_item("coarse_iterations", s.coarse_iterations)?;
        state.set_item("mean_gap", s.mean_gap)?;
        state.set_item("residual", s.residual)?;
        state.set_item("pressure", &s.pressure)?;
        state.set_item("displacement", &s.displacement)?;
        state.set_item("gap", &s.gap)?;
        state.set_item("x", &s.x)?;
        state.set_item("y", &s.y)?;
        Ok((slf.get_type().getattr("_rebuild")?, (state,)))
    }

    /// The solution whose `__reduce__` gave `state`.
    #[staticmethod]
    fn _rebuild(state: &Bound<'_, PyDict>) -> PyResult<Self> {
        let get = |key: &str| {
            state.get_item(key)?.ok_or_else(|| {
                InvalidInputError::new_err(format!("a pickled Solution without {key}"))
            })
        };
        Ok(Solution {
            depth: get("depth")?.extract()?,
            force: get("force")?.extract()?,
            contact_area: get("contact_area")?.extract()?,
            contact_radius: get("contact_radius")?.extract()?,
            contact_cells: get("contact_cells")?.extract()?,
            edge_contact: get("edge_contact")?.extract()?,
            iterations: get("iterations")?.extract()?,
            coarse_iterations: get("coarse_iterations")?.extract()?,
            mean_gap: get("mean_gap")?.extract()?,
            residual: get("residual")?.extract()?,
            pressure: get("pressure")?.extract()?,
            displacement: get("displacement")?.extract()?,
            gap: get("gap")?.extract()?,
            x: get("x")?.unbind(),
            y: get("y")?.unbind(),
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "Solution(depth={:e}, force={:e}, contact_radius={:e}, iterations={})",
            self.depth, self.force, self.contact_radius, self.iterations
        )
    }
}

/// `coarse_blocks` of `ContactSolver(...)`: a block side or `"box"`.
#[derive(FromPyObject)]
enum CoarseBlocks {
    Side(usize),
    Named(String),
}

/// The boundary-element solver on one substrate and grid: kernel and FFT
/// plans are built once, solves reuse them (and the last solve as a warm
/// start when asked). Solves release the GIL.
#[pyclass(module = "layered_contact._native")]
pub(crate) struct ContactSolver {
    pub(crate) inner: lc::solver::ContactSolver,
    /// The last solve's state and depth (m).
    warm: Option<(lc::solver::WarmStart, f64)>,
}

#[pymethods]
impl ContactSolver {
    /// A solver for `substrate` on `rows x columns` square cells of side
    /// `spacing` (m), isolated (the body is infinite) or periodic;
    /// `coarse_blocks` chooses the preconditioner: `None` lets each solve
    /// choose (the crate's `ContactSolver::set_automatic_coarse_blocks`:
    /// the two-level preconditioner over blocks of 16 cells for rough
    /// contacts on grids of 2048^2 cells and more, and from 1024^2 where
    /// the box converges slowly, else the box); a number
    /// the two-level preconditioner over blocks of that many cells a side
    /// (`ContactSolver::set_coarse_blocks`, which joins once the contact
    /// count has settled: rough contacts in iterations that grow like `log
    /// N`, at 0.66 to 1.09 times the box's time at 2048^2 and 4096^2 and up
    /// to 1.36 times on smaller grids); `"box"` the box alone.
    #[new]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    #[pyo3(signature = (substrate, rows, columns, spacing, periodic=false, tolerance=1e-8, max_iterations=10_000, coarse_blocks=None))]
    fn new(
        py: Python<'_>,
        substrate: &Substrate,
        rows: usize,
        columns: usize,
        spacing: f64,
        periodic: bool,
        tolerance: f64,
        max_iterations: usize,
        coarse_blocks: Option<CoarseBlocks>,
    ) -> PyResult<Self> {
        let coarse_blocks = match coarse_blocks {
            None => None,
            Some(CoarseBlocks::Side(side)) => Some(Some(side)),
            Some(CoarseBlocks::Named(name)) if name == "box" => Some(None),
            Some(CoarseBlocks::Named(name)) => {
                return Err(super::InvalidInputError::new_err(format!(
                    "coarse_blocks {name:?}: expected None (the solver's choice), \"box\" or a block side in cells"
                )))
            }
        };
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
            .detach(|| {
                let mut solver =
                    lc::solver::ContactSolver::new(&substrate, &grid, boundary, params)?;
                if let Some(blocks) = coarse_blocks {
                    solver.set_coarse_blocks(blocks)?;
                }
                Ok::<_, lc::Error>(solver)
            })
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

    /// The adhesive equilibrium at `depth` (m) in the JKR limit through a
    /// cohesive zone resolved on the grid (any contact shape, isolated or
    /// periodic; the crate's `doc::adhesion`): works of adhesion
    /// `advancing` and `receding` (J/m^2, `receding` defaults to
    /// `advancing`), the zone `zone_cells` cells wide (default 4), or
    /// grown with the resolution for `cells_across` cells across the
    /// pull-off contact (`max(4, sqrt(cells_across) / 2)` cells: the crate's
    /// `CohesiveZone::with_resolution`, for convergence studies; not both).
    /// `warm_start` carries the history (which cells are bonded).
    #[pyo3(signature = (indenter, depth, advancing, receding=None, zone_cells=None, warm_start=false, cells_across=None))]
    #[allow(clippy::too_many_arguments)]
    fn solve_depth_cohesive(
        &mut self,
        py: Python<'_>,
        indenter: &Indenter,
        depth: f64,
        advancing: f64,
        receding: Option<f64>,
        zone_cells: Option<f64>,
        warm_start: bool,
        cells_across: Option<f64>,
    ) -> PyResult<Solution> {
        let zone = cohesive_zone(advancing, receding, zone_cells, cells_across)?;
        self.solve(py, indenter, warm_start, move |solver, shape, warm| {
            solver.solve_depth_cohesive(shape, depth, &zone, warm, &mut ())
        })
    }

    /// The adhesive equilibrium carrying `force` (N, negative pulls) through
    /// the cohesive zone (the law as in `solve_depth_cohesive`), from the
    /// last solve's equilibrium (its bonded cells are the history): one
    /// fixed point under force control (the crate's
    /// `ContactSolver::solve_force_cohesive`). Beyond the least force the
    /// contact can hold there is no equilibrium: `ConvergenceError` (the
    /// last state is kept). `InvalidInputError` without a solve before.
    #[pyo3(signature = (indenter, force, advancing, receding=None, zone_cells=None, cells_across=None))]
    #[allow(clippy::too_many_arguments)]
    fn solve_force_cohesive(
        &mut self,
        py: Python<'_>,
        indenter: &Indenter,
        force: f64,
        advancing: f64,
        receding: Option<f64>,
        zone_cells: Option<f64>,
        cells_across: Option<f64>,
    ) -> PyResult<Solution> {
        let zone = cohesive_zone(advancing, receding, zone_cells, cells_across)?;
        let Some((warm, depth)) = self.warm.take() else {
            return Err(InvalidInputError::new_err(
                "solve_force_cohesive starts from the last solve's equilibrium: solve one first \
                 (solve_depth_cohesive)",
            ));
        };
        let shape = Shared(indenter.inner.clone());
        let inner = &mut self.inner;
        let solved =
            py.detach(|| inner.solve_force_cohesive(&shape, force, &zone, (&warm, depth), &mut ()));
        match solved {
            Ok((solution, end)) => {
                self.warm = Some((end, solution.depth));
                Solution::new(py, &solution, self.inner.grid())
            }
            Err(e) => {
                self.warm = Some((warm, depth));
                Err(e).py_err()
            }
        }
    }

    /// The pull-off under displacement control through the cohesive zone
    /// (the law as in `solve_depth_cohesive`): from the equilibrium at
    /// `depth` (m, reached cold), withdrawn in steps of `step` (m) until
    /// the force has stayed above its least value for three steps, the
    /// least force then searched to a sixteenth of a step (the crate's
    /// `ContactSolver::cohesive_pull_off`; a step out of the fixed point's
    /// reach is taken in substeps). Returns a `CohesivePullOff` (its force,
    /// N, and depth, m, the solves and iterations it took, the contact's
    /// and the zone's widths in cells); a `CohesiveZoneWarning` where the
    /// zone is wider than the contact at the pull-off
    /// (`CohesivePullOff.zone_spans_contact`).
    #[pyo3(signature = (indenter, depth, step, advancing, receding=None, zone_cells=None, cells_across=None))]
    #[allow(clippy::too_many_arguments)]
    fn cohesive_pull_off(
        &mut self,
        py: Python<'_>,
        indenter: &Indenter,
        depth: f64,
        step: f64,
        advancing: f64,
        receding: Option<f64>,
        zone_cells: Option<f64>,
        cells_across: Option<f64>,
    ) -> PyResult<adhesion::CohesivePullOff> {
        let zone = cohesive_zone(advancing, receding, zone_cells, cells_across)?;
        let shape = Shared(indenter.inner.clone());
        let inner = &mut self.inner;
        let pull_off = py
            .detach(|| inner.cohesive_pull_off(&shape, &zone, depth, step, None, &mut ()))
            .py_err()?;
        if pull_off.zone_spans_contact() {
            let message = std::ffi::CString::new(format!(
                "the cohesive zone ({} cells) is wider than the contact at the pull-off \
                 (its widest patch {} cells across): the force is a cohesive law's, not \
                 the JKR limit's; refine the grid",
                pull_off.zone_cells, pull_off.cells_across
            ))?;
            PyErr::warn(py, &py.get_type::<CohesiveZoneWarning>(), &message, 1)?;
        }
        Ok(adhesion::CohesivePullOff::from(&pull_off))
    }

    /// `(rows, columns, spacing)`.
    #[getter]
    fn grid(&self) -> (usize, usize, f64) {
        let g = self.inner.grid();
        (g.rows(), g.columns(), g.spacing())
    }

    /// The block side of the two-level preconditioner the solver has: set
    /// by `coarse_blocks`, or built by its own choice in a solve (rough
    /// contacts on grids of 1024^2 cells and more); `None` while it has
    /// only the box.
    #[getter]
    fn coarse_blocks(&self) -> Option<usize> {
        self.inner.coarse_blocks()
    }

    /// How the last solve preconditioned its iterations (the crate's
    /// `ContactSolver::last_preconditioning`), `None` before the first: a
    /// dict of `decided_after` (the iterations done when the choice between
    /// the box and the two-level preconditioner was made, once the contact
    /// count had settled; `None` if the solve ended before), `box_factor`
    /// (the box's mean residual factor an iteration then), `blocks` (the
    /// block side if the two-level preconditioner was taken, else `None`)
    /// and `two_level_iterations`.
    #[getter]
    fn last_preconditioning<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(used) = self.inner.last_preconditioning() else {
            return Ok(None);
        };
        let dict = PyDict::new(py);
        dict.set_item("decided_after", used.decided_after)?;
        dict.set_item("box_factor", used.box_factor)?;
        dict.set_item("blocks", used.blocks)?;
        dict.set_item("two_level_iterations", used.two_level_iterations)?;
        Ok(Some(dict))
    }
}

/// The cohesive law of the given works of adhesion, its zone `zone_cells`
/// wide (default four) or grown for `cells_across` cells across the
/// pull-off contact.
fn cohesive_zone(
    advancing: f64,
    receding: Option<f64>,
    zone_cells: Option<f64>,
    cells_across: Option<f64>,
) -> PyResult<lc::solver::CohesiveZone> {
    let zone = lc::solver::CohesiveZone::new(advancing, receding.unwrap_or(advancing));
    match (zone_cells, cells_across) {
        (Some(_), Some(_)) => Err(InvalidInputError::new_err(
            "give zone_cells (the zone's width) or cells_across (the zone grown with the \
             resolution), not both",
        )),
        (Some(cells), None) => zone.and_then(|z| z.with_zone_cells(cells)).py_err(),
        (None, Some(across)) => zone.and_then(|z| z.with_resolution(across)).py_err(),
        (None, None) => zone.py_err(),
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
        let from = warm.as_ref().map(|(w, _)| w);
        let (solution, warm) = py.detach(|| run(inner, &shape, from)).py_err()?;
        self.warm = Some((warm, solution.depth));
        Solution::new(py, &solution, self.inner.grid())
    }
}
