//! The family's smaller sets solved on a window of the grid around them.
//!
//! On an isolated grid the compliance between two cells depends only on
//! their offset, so the clamped problems of a set (whose pressures vanish
//! off it and whose displacements are prescribed only on it) are the same
//! equations on any grid that holds the set. A family runs from a set
//! nearly as wide as the grid down to nine cells; solved on the whole grid,
//! each iteration of a small set's conjugate gradients costs a convolution
//! of the whole grid. Once a set's bounding box holds at most half the
//! grid's cells, the family moves to a solver on that box (the smaller
//! sets of the family lie inside it: the sets are nested), and again each
//! time the box halves: the same values to the solver's tolerance, for a
//! fraction of the convolutions' cost (`BENCHMARKS.md`, "The family on
//! windows of the grid").

use crate::error::Result;
use crate::grid::{Boundary, Grid};
use crate::solver::passes::Bounds;
use crate::solver::ContactSolver;

/// A window is taken once the set's bounding box holds at most one part in
/// this many of the current grid's cells (a new operator costs about one
/// kernel build of the window; its convolutions are then about this much
/// cheaper). 2 and 4 were measured (`BENCHMARKS.md`, "The family on
/// windows of the grid"): the same on the accuracy harness's spheres, 2
/// faster on the slow scenes.
const WINDOW_FRACTION: usize = 2;

/// Grids of fewer cells than this are not windowed further: their
/// convolutions cost less than a window's kernel build repays.
const MIN_WINDOWED_CELLS: usize = 64 * 64;

/// The clamped pair's fields on a window of the full grid, and its solver.
pub(super) struct Window {
    solver: Box<ContactSolver>,
    /// The window's first row and column on the full grid.
    origin: (usize, usize),
    /// Its columns, and the full grid's.
    columns: usize,
    full_columns: usize,
    attached: Vec<bool>,
    target: Vec<f64>,
    punch: Vec<f64>,
    shape: Vec<f64>,
}

impl Window {
    /// The index on the window of full-grid cell `c` (inside it).
    pub(super) fn index(&self, c: usize) -> usize {
        let (i, j) = (c / self.full_columns, c % self.full_columns);
        (i - self.origin.0) * self.columns + (j - self.origin.1)
    }

    /// Cells of the window's grid.
    fn cells(&self) -> usize {
        self.attached.len()
    }

    /// The clamped pair on the window (see
    /// [`ContactSolver::solve_clamped_pair`]).
    pub(super) fn solve(&mut self, lowest: f64) -> Result<(usize, f64)> {
        self.solver.solve_clamped_pair(
            &self.attached,
            lowest,
            &mut self.target,
            &mut self.punch,
            &mut self.shape,
        )
    }

    /// Detaches full-grid cell `c` (inside the window).
    pub(super) fn detach(&mut self, c: usize) {
        let k = self.index(c);
        self.attached[k] = false;
        self.punch[k] = 0.0;
        self.shape[k] = 0.0;
    }

    /// `[punch, shape, target]` at full-grid cell `c` (inside the window).
    pub(super) fn values(&self, c: usize) -> [f64; 3] {
        let k = self.index(c);
        [self.punch[k], self.shape[k], self.target[k]]
    }
}

impl ContactSolver {
    /// A window around `bounds` (the next set's bounding box on this
    /// solver's isolated grid) if that set holds at most a
    /// [`WINDOW_FRACTION`] of the cells of the grid it is solved on now
    /// (`current`, or this solver's), `None` to stay. The window takes the
    /// set's cells `set` (full-grid indices), their profile and their
    /// pressures (`current`'s, or `punch` and `shape` on the full grid).
    /// The first window frees this solver's FFT buffer, preconditioner and
    /// scratch vectors (but the profile) before it is built: they idle
    /// while windows solve, and the family's peak memory stays near the
    /// grid's own. The caller sizes the scratch vectors again after the
    /// family ([`Workspace::fit`](crate::solver::workspace::Workspace::fit)).
    pub(super) fn window_for(
        &mut self,
        bounds: Bounds,
        set: impl Iterator<Item = usize>,
        current: Option<&Window>,
        (punch, shape): (&[f64], &[f64]),
    ) -> Result<Option<Window>> {
        if self.operator.boundary() != Boundary::Isolated {
            return Ok(None);
        }
        // The set's bounding box and a cell more each way (within the
        // grid), where the preconditioner's extension past the set's edges
        // reaches on the whole grid: the window's solves then take the
        // whole grid's steps.
        let ((r0, r1), (c0, c1)) = bounds;
        let (full_rows, full_columns) = (self.grid().rows(), self.grid().columns());
        let (r0, r1) = (r0.saturating_sub(1), (r1 + 1).min(full_rows - 1));
        let (c0, c1) = (c0.saturating_sub(1), (c1 + 1).min(full_columns - 1));
        let (rows, columns) = (r1 - r0 + 1, c1 - c0 + 1);
        let now = current.map_or(self.grid().len(), Window::cells);
        if now < MIN_WINDOWED_CELLS || WINDOW_FRACTION * rows * columns > now {
            return Ok(None);
        }
        let grid = Grid::new(rows, columns, self.grid().spacing())?;
        if current.is_none() {
            self.preconditioner = None;
            self.operator.release_buffer();
            drop(self.workspace.lend());
        }
        let mut solver =
            ContactSolver::new(&self.substrate, &grid, Boundary::Isolated, self.params)?;
        solver.interrupt.clone_from(&self.interrupt);
        solver.double_preconditioner = self.double_preconditioner;
        let n = grid.len();
        let mut window = Window {
            solver: Box::new(solver),
            origin: (r0, c0),
            columns,
            full_columns: self.grid().columns(),
            attached: vec![false; n],
            target: vec![0.0; n],
            punch: vec![0.0; n],
            shape: vec![0.0; n],
        };
        for c in set {
            let k = window.index(c);
            let [p, s] = match current {
                Some(old) => {
                    let [p, s, _] = old.values(c);
                    [p, s]
                }
                None => [punch[c], shape[c]],
            };
            window.attached[k] = true;
            window.punch[k] = p;
            window.shape[k] = s;
            window.solver.workspace.profile[k] = self.workspace.profile[c];
        }
        Ok(Some(window))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::indenter::Paraboloid;
    use crate::solver::SolverParams;
    use crate::{Material, Substrate};

    /// A disc of 12 cells' radius, off the centre of a 96 x 96 grid of a
    /// soft film on a base 500 times stiffer (the slow scenes' kind of
    /// body): its clamped pair solved on the whole grid and on the window
    /// around it. The compliance between two cells depends only on their
    /// offset, so the pressures agree (measured within 8e-14 and 2.3e-13 of
    /// the largest, the solves' tolerance 1e-10: the two solves take the
    /// same steps but for the convolutions' rounding); a window one row
    /// off the disc's cells fails this.
    #[test]
    fn a_set_solved_on_its_window_has_the_whole_grid_s_pressures() {
        let n = 96;
        let film = Material::new(1e6, 0.45).unwrap();
        let base = Material::new(5e8, 0.3).unwrap();
        let body = Substrate::layer_on_elastic_base(film, 2e-5, base).unwrap();
        let grid = Grid::new(n, n, 5e-6).unwrap();
        let params = SolverParams {
            tolerance: 1e-10,
            ..SolverParams::default()
        };
        let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
        let lowest = solver
            .sample_profile(&Paraboloid::new(1e-3).unwrap())
            .unwrap();
        let inside = |c: usize| {
            let (i, j) = ((c / n) as f64, (c % n) as f64);
            (i - 40.3).hypot(j - 55.6) < 12.0
        };
        let set: Vec<usize> = (0..n * n).filter(|&c| inside(c)).collect();
        let attached: Vec<bool> = (0..n * n).map(inside).collect();
        let (mut target, mut punch, mut shape) =
            (vec![0.0; n * n], vec![0.0; n * n], vec![0.0; n * n]);
        solver
            .solve_clamped_pair(&attached, lowest, &mut target, &mut punch, &mut shape)
            .unwrap();
        let bounds = crate::solver::passes::bounds_of(set.iter().copied(), n).unwrap();
        let zero = vec![0.0; n * n];
        let mut window = solver
            .window_for(bounds, set.iter().copied(), None, (&zero, &zero))
            .unwrap()
            .expect("a disc of 24 cells across on 96 is windowed, with a cell more each way");
        assert_eq!(window.cells(), 26 * 26);
        window.solve(lowest).unwrap();
        for (whole, k) in [(&punch, 0), (&shape, 1)] {
            let largest = set.iter().map(|&c| whole[c].abs()).fold(0.0, f64::max);
            for &c in &set {
                let windowed = window.values(c)[k];
                assert!(
                    (windowed - whole[c]).abs() < 1e-11 * largest,
                    "{k} {c}: {windowed} {}",
                    whole[c]
                );
            }
        }
    }
}
