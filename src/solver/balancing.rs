//! The two-level balancing preconditioner of the constrained conjugate
//! gradients (opt-in: [`ContactSolver::set_coarse_blocks`]): the box
//! inverse `B` ([`preconditioning`](super::preconditioning)) inside a
//! coarse correction over the working set's cells of `b x b` blocks
//! (Mandel 1993, Commun. Numer. Meth. Eng. 9, 233-241):
//!
//! ```text
//! M r = Q r + (I - Q A) B (I - A Q) r,    Q = Z E~^-1 Z^T
//! ```
//!
//! `A` the compliance on the working set, `Z` the blocks' indicators on
//! it, `E~ ~ Z^T A Z` the coarse matrix of
//! [`coarse_space`](super::coarse_space). Symmetric and positive definite
//! for any symmetric positive definite `E~` (Tang, Nabben, Vuik & Erlangga
//! 2009, J. Sci. Comput. 39, 340-370). The box serves a contact of one
//! scale of patches well and one of many scales worse (its rate slows with
//! every doubling of a rough surface's grid); the coarse correction
//! handles what varies from block to block, so the count grows like `log
//! N` instead. It costs two more applications of the compliance an
//! iteration and two coarse solves: `BENCHMARKS.md`, "A two-level
//! preconditioner for rough contacts".

use crate::error::{Error, Result};
use crate::grid::Boundary;

use super::coarse_space::CoarseSpace;
use super::passes::Bounds;
use super::ContactSolver;

/// The two-level preconditioner's state: its coarse space and two
/// vectors of a value a cell.
pub(super) struct Balancing {
    space: CoarseSpace,
    field: Vec<f64>,
    response: Vec<f64>,
    coarse: Vec<f64>,
}

impl ContactSolver {
    /// Precondition the non-adhesive solves' constrained conjugate
    /// gradients (and their active-set loops) with a two-level balancing
    /// preconditioner over blocks of `blocks x blocks` cells (`None`: the
    /// box inverse alone, the default). On rough contacts the iterations
    /// then grow like `log N` instead of by a quarter to a third each
    /// doubling of the grid, but each costs 1.6 to 2.8 times as much (two
    /// more applications of the compliance and two solves on the grid of
    /// blocks) and the solver holds two more vectors (16 bytes a cell): on
    /// the rough films and half-spaces of `BENCHMARKS.md` ("A two-level
    /// preconditioner for rough contacts", blocks of 16 from 512^2 to
    /// 8192^2) the solves took 1.08 to 2.2 times the box's time, and on a
    /// coating over a soft base far more. Adhesive solves and the coarse
    /// levels of the multi-resolution start keep the box.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for blocks smaller than 2 cells or
    /// larger than a quarter of the grid's smaller side, or that do not
    /// divide the sides of a periodic grid; [`Error::Unsupported`] on a
    /// solver split across MPI ranks.
    ///
    /// ```
    /// use layered_contact::solver::{ContactSolver, SolverParams};
    /// use layered_contact::topography::{Amplitude, SelfAffine};
    /// use layered_contact::{Boundary, Grid, Material, Substrate};
    ///
    /// let grid = Grid::square_of_side(128, 1.0)?;
    /// let body = Substrate::half_space(Material::new(1.0, 0.0)?);
    /// let surface = SelfAffine {
    ///     hurst: 0.8,
    ///     amplitude: Amplitude::RmsSlope(0.1),
    ///     long_cutoff: 0.25,
    ///     short_cutoff: 4.0 * grid.spacing(),
    ///     seed: 1,
    /// }
    /// .indenter(&grid)?;
    /// let mut solver = ContactSolver::new(&body, &grid, Boundary::Periodic, SolverParams::default())?;
    /// let (boxed, _) = solver.solve_force(&surface, 0.01, None, &mut ())?;
    /// solver.set_coarse_blocks(Some(16))?;
    /// let (two_level, _) = solver.solve_force(&surface, 0.01, None, &mut ())?;
    /// assert!((two_level.depth / boxed.depth - 1.0).abs() < 1e-7);
    /// assert!(two_level.iterations < boxed.iterations);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn set_coarse_blocks(&mut self, blocks: Option<usize>) -> Result<()> {
        let Some(side) = blocks else {
            self.balancing = None;
            return Ok(());
        };
        if self.is_split() {
            return Err(Error::Unsupported {
                feature: "the two-level preconditioner on a solver split across MPI ranks",
                reason: "its coarse space is built on one process; use the box \
                         preconditioner (the default)",
            });
        }
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        if side < 2 || side > rows.min(columns) / 4 {
            return Err(Error::InvalidParameter {
                name: "coarse blocks (cells a side)",
                value: side as f64,
                expected: "at least 2 and at most a quarter of the grid's smaller side",
            });
        }
        let periodic = self.operator.boundary() == Boundary::Periodic;
        if periodic && (rows % side != 0 || columns % side != 0) {
            return Err(Error::InvalidParameter {
                name: "coarse blocks (cells a side)",
                value: side as f64,
                expected: "a divisor of both sides of a periodic grid",
            });
        }
        let n = rows * columns;
        let mut field = crate::error::zeroed(n, "the two-level preconditioner's vectors")?;
        let mut response = crate::error::zeroed(n, "the two-level preconditioner's vectors")?;
        // The responses to a unit load on cell (0, 0) and on the block at
        // the origin (on an isolated grid the kernel is read at
        // non-negative offsets and mirrored).
        field[0] = 1.0;
        self.operator.apply(&field, &mut response)?;
        let point = response.clone();
        field[0] = 0.0;
        for i in 0..side {
            field[i * columns..i * columns + side].fill(1.0);
        }
        self.operator.apply(&field, &mut response)?;
        let space = CoarseSpace::new(side, (rows, columns), periodic, &point, &response)?;
        let coarse = vec![0.0; space.len()];
        self.balancing = Some(Box::new(Balancing {
            space,
            field,
            response,
            coarse,
        }));
        Ok(())
    }

    /// The block side of the two-level preconditioner, if it is on
    /// ([`ContactSolver::set_coarse_blocks`]).
    pub fn coarse_blocks(&self) -> Option<usize> {
        self.balancing.as_ref().map(|b| b.space.side())
    }

    /// The constrained conjugate gradients' preconditioned residual: the
    /// two-level preconditioner if it is on and the solve is a fine,
    /// non-adhesive one, else the box alone
    /// ([`ContactSolver::precondition_working_set`]).
    pub(super) fn precondition_step(
        &mut self,
        bounds: Option<Bounds>,
        shift: f64,
        gap_max: f64,
    ) -> Result<(f64, f64)> {
        let balanced = self.params.precondition && !self.double_preconditioner && bounds.is_some();
        match self.balancing.take() {
            Some(mut balancing) if balanced => {
                let out = self.balanced(&mut balancing, bounds, shift);
                self.balancing = Some(balancing);
                out
            }
            taken => {
                self.balancing = taken;
                self.precondition_working_set(bounds, shift, gap_max)
            }
        }
    }

    /// `z = Q r + y - Q A y`, `y = B (r - A Q r)`, `r = gap - shift` on the
    /// working set, into the workspace's `response`; returns `(sum z, sum z
    /// r)` over the working set as the box does.
    fn balanced(
        &mut self,
        balancing: &mut Balancing,
        bounds: Option<Bounds>,
        shift: f64,
    ) -> Result<(f64, f64)> {
        let Balancing {
            space,
            field,
            response,
            coarse,
        } = balancing;
        let working = &self.workspace.working;
        space.update(working);
        // c1 = E~^-1 Z^T r; field = Z c1.
        let gap = &self.workspace.gap;
        coarse.fill(0.0);
        space.runs(|block, cells| {
            for c in cells.filter(|c| working[*c]) {
                coarse[block] += gap[c] - shift;
            }
        });
        space.solve(coarse)?;
        space.runs(|block, cells| {
            for c in cells {
                field[c] = if working[c] { coarse[block] } else { 0.0 };
            }
        });
        // s = r - A Z c1 on the set, handed to the box as its residual.
        self.operator.apply(field, response)?;
        let mut s_max = 0.0_f64;
        for ((s, g), w) in response.iter_mut().zip(&self.workspace.gap).zip(working) {
            *s = if *w { g - shift - *s } else { 0.0 };
            s_max = s_max.max(s.abs());
        }
        std::mem::swap(&mut self.workspace.gap, response);
        let boxed = self.precondition_working_set(bounds, 0.0, s_max);
        std::mem::swap(&mut self.workspace.gap, response);
        boxed?;
        // y = B s in the workspace's `response` (zero off the set); A y.
        let ws = &mut self.workspace;
        for (y, w) in ws.response.iter_mut().zip(&ws.working) {
            if !*w {
                *y = 0.0;
            }
        }
        self.operator.apply(&self.workspace.response, response)?;
        // c2 = E~^-1 Z^T A y; z = Z c1 + y - Z c2.
        let ws = &mut self.workspace;
        coarse.fill(0.0);
        space.runs(|block, cells| {
            for c in cells.filter(|c| ws.working[*c]) {
                coarse[block] += response[c];
            }
        });
        space.solve(coarse)?;
        let (mut z_sum, mut rz) = (0.0, 0.0);
        space.runs(|block, cells| {
            for c in cells.filter(|c| ws.working[*c]) {
                let z = field[c] + ws.response[c] - coarse[block];
                ws.response[c] = z;
                z_sum += z;
                rz += z * (ws.gap[c] - shift);
            }
        });
        Ok((z_sum, rz))
    }
}
