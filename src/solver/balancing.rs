//! The two-level balancing preconditioner of the constrained conjugate
//! gradients (chosen by each fine solve of a rough contact on a large grid,
//! [`coarse_choice`](super::coarse_choice), or set by
//! [`ContactSolver::set_coarse_blocks`]): the box
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
//! iteration (in single precision, as the box's; on an isolated grid
//! through the coarse level of the multi-resolution start, at a quarter of
//! the cost: [`applications`]) and two coarse solves, and no memory a cell
//! beyond the box's: `BENCHMARKS.md`, "A two-level preconditioner for
//! rough contacts", "The two-level preconditioner's applications in single
//! precision" and "The two-level preconditioner through the coarse
//! level".

use crate::error::{Error, Result};
use crate::grid::Boundary;

use super::coarse_space::{near_kernel, CoarseSpace};
use super::passes::Bounds;
use super::split::{over_ranks, summed_over_ranks};
use super::ContactSolver;

mod applications;

/// The two-level preconditioner's state: its coarse space and the two
/// coarse solutions of an application (one value a block). It holds no
/// vector of a value a cell: the compliance's two applications load their
/// fields row by row and hand back what is needed of the responses, and
/// the box's residual lives in the workspace's `previous` (free until the
/// step writes the old pressures).
pub(super) struct Balancing {
    space: CoarseSpace,
    first: Vec<f64>,
    second: Vec<f64>,
}

/// The two-level preconditioner joins the constrained conjugate gradients
/// once this many iterations in a row have left the contact count settled
/// ([`coarse_choice`](super::coarse_choice)). It is a metric for the linear
/// problem on a fixed set; while the set still moves, the projected steps
/// in it clamp more than a third of the contact, and the contact grows
/// instead of settling (a projected step in a metric that couples the cells
/// at their bound to the free ones need not descend: Bertsekas 1982, SIAM
/// J. Control Optim. 20, 221-246; measured in BENCHMARKS.md, "The blocks
/// while the contact still moves"). On the tamaas problem at 1024^2 that
/// runaway needs the multi-resolution start's sampled coarse heights
/// (from a cold start, or with the coarse heights averaged, blocks taken
/// from the third iteration converge in 26 and 23 iterations), but from
/// 2048^2 blocks taken early cost iterations from either start (38 and 42
/// at 2048^2 and 4096^2, against 28 and 35 after three quiet ones), and
/// the stack runs away from either (BENCHMARKS.md, "What the blocks'
/// runaway depends on"). On the coated stack of
/// `examples/rough_benchmark.rs` (a stiff coating over a soft base, whose
/// contact sheds cells for dozens of iterations) the blocks taken in every
/// iteration settled its set at the 47th and 83rd fine iteration at 1024^2
/// and 2048^2, against the box's 61st and 67th; taken after one quiet
/// iteration, at 4096^2 they joined during a pause in the early shedding,
/// tripled the contact in three iterations and took 226 iterations (the box
/// 105). After three: 55 / 50 / 62 fine iterations at 1024^2 / 2048^2 /
/// 4096^2 against the box's 85 / 82 / 105, the rough films within a few
/// iterations of the blocks taken throughout, the tamaas problem 35
/// against 26 at 4096^2 (BENCHMARKS.md, "The coarse correction once the
/// contact settles").
pub(super) const QUIET_ITERATIONS: usize = 3;

impl ContactSolver {
    /// Precondition the non-adhesive solves' constrained conjugate
    /// gradients (and their active-set loops) with a two-level balancing
    /// preconditioner over blocks of `blocks x blocks` cells (`None`: the
    /// box inverse alone), which joins once three iterations in a row have
    /// changed the contact count by at most a thousandth (the box alone
    /// before). Either way the solver no longer chooses for itself (the
    /// default, [`ContactSolver::set_automatic_coarse_blocks`]). On rough
    /// contacts the iterations then grow like `log N` instead of by a
    /// quarter to a third each doubling of the grid, but each costs 1.5 to
    /// 2 times as much (two more applications of the compliance and two
    /// solves on the grid of blocks; no more memory a cell; on an isolated
    /// grid the applications go through the multi-resolution start's coarse
    /// level since 2026-12-06, which took the rough film's iteration with
    /// the blocks at 4096^2 from about 0.85 to 0.6 s): in one sweep
    /// of `BENCHMARKS.md` ("The coarse correction once the contact
    /// settles", blocks of 16 from 512^2 to 4096^2) the solves took 0.66 to
    /// 0.99 times the box's time at 2048^2 and 4096^2 on the rough films,
    /// a periodic half-space and a coating over a soft base (the isolated
    /// film at 2048^2 1.09), and 0.80 to 1.36 times on the smaller grids.
    /// Adhesive solves and the coarse levels of the multi-resolution start
    /// keep the box.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for blocks smaller than 2 cells or
    /// larger than a quarter of the grid's smaller side, or that do not
    /// divide the sides of a periodic grid, or on a solver split across MPI
    /// ranks, that do not divide the first row of every rank (each rank
    /// holds whole rows of blocks; [`doc::distributed`](crate::doc::distributed)).
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
            self.coarse_automatic = false;
            return Ok(());
        };
        self.build_blocks(side)?;
        self.coarse_automatic = false;
        Ok(())
    }

    /// The two-level preconditioner over blocks of `side` cells, built.
    pub(super) fn build_blocks(&mut self, side: usize) -> Result<()> {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let local = self.operator.local_rows();
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
        if !self.ranks_hold_whole_blocks(side) {
            return Err(Error::InvalidParameter {
                name: "coarse blocks (cells a side) on a solver split across MPI ranks",
                value: side as f64,
                expected: "a divisor of every rank's first row (each rank holds whole \
                           rows of blocks; the grid's rows split evenly over the ranks \
                           in multiples of the block side)",
            });
        }
        // The responses to a unit load on cell (0, 0) and on the block at
        // the origin, in the workspace's scratch vectors; in single
        // precision, as the preconditioner's other applications (about
        // `1e-7` of the largest value: the far blocks' entries of the
        // coarse matrix to about `1e-3` of themselves at 8192^2).
        let n = self.local_cells();
        let ws = &mut self.workspace;
        let (mut field, mut response) = (
            std::mem::take(&mut ws.previous),
            std::mem::take(&mut ws.response),
        );
        // Sized on every rank before the collective applications (a rank
        // that could not allocate stops them all).
        let fitted = super::workspace::fit(&mut field, n)
            .and_then(|()| super::workspace::fit(&mut response, n));
        let fitted = self.agreed(fitted);
        let responses = fitted.and_then(|()| {
            // On a split solver each rank loads and reads its own rows.
            field.fill(0.0);
            if local.start == 0 {
                field[0] = 1.0;
            }
            self.operator
                .apply_single(&field, &mut response, 1.0, |_, v| v)?;
            let mut near = near_kernel(&response, side, (rows, columns), &local, periodic);
            self.sum_over_ranks(&mut near);
            field.fill(0.0);
            for i in local.start..side.min(local.end) {
                let row = (i - local.start) * columns;
                field[row..row + side].fill(1.0);
            }
            self.operator
                .apply_single(&field, &mut response, 1.0, |_, v| v)?;
            let sum = |v: &mut [f64]| self.sum_over_ranks(v);
            CoarseSpace::new(
                side,
                (rows, columns),
                local.clone(),
                periodic,
                near,
                &response,
                &sum,
            )
        });
        let space = self.agreed(responses);
        let ws = &mut self.workspace;
        (ws.previous, ws.response) = (field, response);
        let space = space?;
        let blocks = space.len();
        self.balancing = Some(Box::new(Balancing {
            space,
            first: vec![0.0; blocks],
            second: vec![0.0; blocks],
        }));
        Ok(())
    }

    /// Whether every rank holds whole rows of blocks of `side` cells (a
    /// serial solver does): its rows begin on a block's edge and end on one
    /// or at the grid's end. A split solver takes the two-level
    /// preconditioner only then (each block's own pairs are summed by the
    /// rank that holds it). Collective on a split solver.
    pub(super) fn ranks_hold_whole_blocks(&self, side: usize) -> bool {
        let (local, rows) = (self.operator.local_rows(), self.grid().rows());
        let fits = local.start.is_multiple_of(side)
            && (local.end.is_multiple_of(side) || local.end == rows);
        !self.on_any_rank(!fits)
    }

    /// The block side of the two-level preconditioner, if it is on
    /// ([`ContactSolver::set_coarse_blocks`]) or the automatic choice has
    /// built it ([`ContactSolver::set_automatic_coarse_blocks`]).
    pub fn coarse_blocks(&self) -> Option<usize> {
        self.balancing.as_ref().map(|b| b.space.side())
    }

    /// The constrained conjugate gradients' preconditioned residual: the
    /// two-level preconditioner if it is on, `coarse` asks for it
    /// ([`coarse_correction_now`](Self::coarse_correction_now)) and the
    /// solve is a fine, non-adhesive one, else the box alone
    /// ([`ContactSolver::precondition_working_set`]).
    pub(super) fn precondition_step(
        &mut self,
        bounds: Option<Bounds>,
        shift: f64,
        gap_max: f64,
        coarse: bool,
    ) -> Result<(f64, f64)> {
        let balanced =
            coarse && self.params.precondition && !self.double_preconditioner && bounds.is_some();
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
    /// r)` over the working set as the box does. The two applications of
    /// the compliance in single precision, as the box's: they only shape
    /// the search direction.
    fn balanced(
        &mut self,
        balancing: &mut Balancing,
        bounds: Option<Bounds>,
        shift: f64,
    ) -> Result<(f64, f64)> {
        let Balancing {
            space,
            first,
            second,
        } = balancing;
        // This rank's rows (all of them when serial).
        let (rows, columns) = (self.operator.local_rows().len(), self.grid().columns());
        let sum = |v: &mut [f64]| self.sum_over_ranks(v);
        space.update(&self.workspace.working, &sum);
        let ws = &mut self.workspace;
        // c1 = E~^-1 Z^T r.
        let (gap, working, space_at) = (&ws.gap, &ws.working, &*space);
        let parts = crate::parallel::map_row_indices(rows, columns, |i| {
            let cells = i * columns..(i + 1) * columns;
            let (gap, member) = (&gap[cells.clone()], &working[cells]);
            space_at.row_sums(i, member, |j| gap[j] - shift)
        });
        space.gather(&parts, first);
        over_ranks(&self.operator, first);
        space.solve(first)?;
        // The scale of the load `Z c1` the same on every rank (each solved
        // the coarse system itself; ranks whose FFTs round otherwise may
        // differ in the last digits): the sum of their largest values.
        let largest = first.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        let largest = summed_over_ranks(&self.operator, largest);
        // s = r - A Z c1 on the set, into `previous`.
        let maxima = self.coarse_load_residual(space, first, largest, shift)?;
        // Scales the same on every rank: the sums of their largest.
        let s_max = summed_over_ranks(&self.operator, maxima.into_iter().fold(0.0, f64::max));
        // y = B s in `response`, zero off the set.
        let ws = &mut self.workspace;
        std::mem::swap(&mut ws.gap, &mut ws.previous);
        let boxed = self.precondition_working_set(bounds, 0.0, s_max);
        let ws = &mut self.workspace;
        std::mem::swap(&mut ws.gap, &mut ws.previous);
        boxed?;
        let working = &ws.working;
        let maxima = crate::parallel::map_rows(&mut ws.response, columns, |i, y| {
            let member = &working[i * columns..(i + 1) * columns];
            let mut largest = 0.0_f64;
            for (y, w) in y.iter_mut().zip(member) {
                if !*w {
                    *y = 0.0;
                }
                largest = largest.max(y.abs());
            }
            largest
        });
        let y_max = summed_over_ranks(&self.operator, maxima.into_iter().fold(0.0, f64::max));
        // Z^T A y, each row's part of each block's sum.
        let parts = self.block_sums_of_response(space, y_max)?;
        // c2 = E~^-1 Z^T A y; z = Z c1 + y - Z c2.
        space.gather(&parts, second);
        over_ranks(&self.operator, second);
        space.solve(second)?;
        let ws = &mut self.workspace;
        let (gap, working, space_at) = (&ws.gap, &ws.working, &*space);
        let (first, second) = (&*first, &*second);
        let sums = crate::parallel::map_rows(&mut ws.response, columns, |i, row| {
            let cells = i * columns..(i + 1) * columns;
            let (gap, member) = (&gap[cells.clone()], &working[cells]);
            let (mut z_sum, mut rz) = (0.0, 0.0);
            for (block, range) in space_at.row_runs(i) {
                let correction = first[block] - second[block];
                for j in range.filter(|j| member[*j]) {
                    let z = correction + row[j];
                    row[j] = z;
                    z_sum += z;
                    rz += z * (gap[j] - shift);
                }
            }
            (z_sum, rz)
        });
        let (z_sum, rz) = sums
            .into_iter()
            .fold((0.0, 0.0), |(a, b), (c, d)| (a + c, b + d));
        Ok((z_sum, rz))
    }
}
