//! When a fine solve takes the two-level preconditioner
//! ([`balancing`](super::balancing)): as [`ContactSolver::set_coarse_blocks`]
//! set it, or by itself ([`ContactSolver::set_automatic_coarse_blocks`],
//! the default) on a large grid, once the contact count has settled, if
//! the box converges slowly there and the contact has many patches: a
//! rough contact (`BENCHMARKS.md`, "The solver's own choice of
//! preconditioner").

use crate::error::Result;
use crate::grid::Boundary;

use super::balancing::QUIET_ITERATIONS;
#[cfg(doc)]
use super::multiresolution::{count_settled, SETTLED_COUNT_FRACTION};
use super::ContactSolver;

/// The automatic choice ([`ContactSolver::set_automatic_coarse_blocks`])
/// takes the two-level preconditioner on grids of at least this many cells
/// (1024^2), asking more of the box's rate below
/// [`AUTOMATIC_BLOCKS_LARGE_CELLS`]
/// ([`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`]). At 512^2, four seeds of
/// each rough problem of `examples/rough_benchmark.rs` on one thread, the
/// blocks took 0.66 to 0.95 times the box's time on the coated stacks but
/// 0.92 to 1.10 on the tamaas problem, within the runs' spread, and 0.93
/// to 1.43 on the films: not taken (BENCHMARKS.md, "The blocks on smaller
/// grids").
pub const AUTOMATIC_BLOCKS_CELLS: usize = 1024 * 1024;

/// From this many cells (2048^2) the automatic choice takes the blocks
/// once the box's rate reaches [`AUTOMATIC_BLOCKS_BOX_RATE`]; on smaller
/// grids (from [`AUTOMATIC_BLOCKS_CELLS`]) it asks for
/// [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`]. Before the two-level
/// preconditioner's applications went through the coarse level and in
/// single precision, the blocks cost more than they saved below this size:
/// 0.80 to 1.36 times the box's time at 512^2 and 1024^2 on the five rough
/// problems of `examples/rough_benchmark.rs`, against 0.66 to 1.09 at
/// 2048^2 and 0.66 to 0.88 at 4096^2 (BENCHMARKS.md, "The coarse
/// correction once the contact settles").
pub const AUTOMATIC_BLOCKS_LARGE_CELLS: usize = 2048 * 2048;

/// The box's least mean factor an iteration for which the automatic choice
/// takes the blocks on grids from [`AUTOMATIC_BLOCKS_CELLS`] to below
/// [`AUTOMATIC_BLOCKS_LARGE_CELLS`]. At 1024^2 (four seeds of each rough
/// problem of `examples/rough_benchmark.rs`, one thread) the films' boxes
/// decided on 0.40 to 0.46 and the blocks took 0.83 to 1.34 times their
/// time; the tamaas problem and the coated stacks decided on 0.54 to 1.25
/// and the blocks took 0.67 to 0.90 times the box's, in 9 to 25 fewer
/// fine iterations. No factor separates them all: the tamaas problem's
/// seed 7 decides on 0.448 and keeps the box (33 fine iterations, the
/// blocks' 24); a rule that errs that way costs what the box did before
/// (BENCHMARKS.md, "The blocks on smaller grids").
pub const AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE: f64 = 0.5;

/// On grids of at least [`AUTOMATIC_BLOCKS_LARGE_CELLS`] the automatic
/// choice keeps the box if the box's mean factor an iteration (the
/// residual over the one before) over the iterations in which the contact
/// count settled lies below this: the blocks' own factor,
/// once a rough contact's count has settled, was 0.19 to 0.36 in every
/// run of `BENCHMARKS.md`'s two-level sections, so a box that converges
/// faster leaves them nothing to gain. On the rough problems of
/// `examples/rough_benchmark.rs` at 2048^2 the box's factor there was 0.53
/// to 0.88; on a periodic two-way sinusoid of 32 waves a side on 2048^2
/// cells (1024 equal patches) 0.12, where the blocks took 11 fine
/// iterations against the box's 10 and 1.1 to 1.3 times its time
/// (BENCHMARKS.md, "The solver's own choice of preconditioner"). No
/// threshold serves without the patch test: a flat punch on a coated stack
/// decides on 0.8 and the blocks take 1.4 times the box's time, and a
/// threshold of 0.57, which would keep the box for the isolated film at
/// 2048^2 (0.54, then the one loss; 0.99 of the box's time since the
/// applications go through the coarse level, "The blocks on smaller
/// grids"), would also keep it for the tamaas problem at 4096^2 (0.47,
/// where the blocks take 0.8 of its time): BENCHMARKS.md, "The choice on
/// fixed roughness and on one patch".
pub const AUTOMATIC_BLOCKS_BOX_RATE: f64 = 0.3;

/// The block side the automatic choice takes (cells a side), the side of
/// every measurement of `BENCHMARKS.md`'s two-level sections.
pub const AUTOMATIC_BLOCK_SIDE: usize = 16;

/// How a solve's constrained conjugate gradients were preconditioned
/// ([`ContactSolver::last_preconditioning`]): when the contact count had
/// settled enough for the choice between the box and the two-level
/// preconditioner ([`ContactSolver::set_automatic_coarse_blocks`]), the
/// box's rate it judged by, and what served.
///
/// ```
/// use layered_contact::indenter::Sphere;
/// use layered_contact::solver::{ContactSolver, SolverParams};
/// use layered_contact::{Boundary, Grid, Material, Substrate};
///
/// let body = Substrate::half_space(Material::new(1e6, 0.5)?);
/// let grid = Grid::new(64, 64, 1e-5)?;
/// let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default())?;
/// assert!(solver.last_preconditioning().is_none());
/// let (solution, _) = solver.solve_depth(&Sphere::new(1e-2)?, 1e-6, None, &mut ())?;
/// let used = solver.last_preconditioning().unwrap();
/// // A Hertzian contact on a small grid: the box throughout.
/// assert_eq!((used.blocks, used.two_level_iterations), (None, 0));
/// assert!(used.decided_after.is_some_and(|k| k < solution.iterations));
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub struct Preconditioning {
    /// The iterations done when the choice was made: the contact count had
    /// then moved by at most a thousandth of itself in each of the last
    /// three. The choice serves from the next iteration on. `None`: the
    /// solve ended before.
    pub decided_after: Option<usize>,
    /// The mean factor by which the residual fell an iteration over those
    /// three, under the box (the automatic choice keeps the box below
    /// [`AUTOMATIC_BLOCKS_BOX_RATE`], on grids smaller than
    /// [`AUTOMATIC_BLOCKS_LARGE_CELLS`] below
    /// [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`]); `None` with
    /// `decided_after`.
    pub box_factor: Option<f64>,
    /// The side of the two-level preconditioner's blocks (cells) if the
    /// choice took it, `None` for the box alone.
    pub blocks: Option<usize>,
    /// The iterations that applied the two-level preconditioner: from the
    /// choice on, except those after an iteration that moved the contact
    /// count again (the box serves them, [`ContactSolver::set_coarse_blocks`]).
    pub two_level_iterations: usize,
}

/// One solve's part of the choice: how many iterations in a row have left
/// the contact count settled ([`count_settled`]), the residual after the
/// last one that moved it (the box's rate since tells whether the blocks
/// can gain), the decision once taken, and what the solve reports of it.
pub(super) struct CoarseChoice {
    quiet: usize,
    moved_residual: f64,
    wanted: Option<bool>,
    pub(super) report: Preconditioning,
}

impl Default for CoarseChoice {
    fn default() -> Self {
        CoarseChoice {
            quiet: 0,
            moved_residual: f64::INFINITY,
            wanted: None,
            report: Preconditioning::default(),
        }
    }
}

impl CoarseChoice {
    /// An iteration ended at `residual`, its contact count `settled` or not.
    pub(super) fn record(&mut self, settled: bool, residual: f64) {
        if settled {
            self.quiet += 1;
        } else {
            self.quiet = 0;
            self.moved_residual = residual;
        }
    }
}

impl ContactSolver {
    /// Let each fine solve choose its preconditioner (the default): the
    /// two-level one over blocks of [`AUTOMATIC_BLOCK_SIDE`] cells on a grid
    /// of at least [`AUTOMATIC_BLOCKS_CELLS`] cells (built on first use and
    /// kept), once three iterations in a row have changed the contact count
    /// by at most a thousandth, and then only if over those three the box's
    /// residual shrank by a mean factor of at least
    /// [`AUTOMATIC_BLOCKS_BOX_RATE`] an iteration (a box that converges
    /// faster leaves the blocks nothing to gain: a periodic sinusoid's many
    /// equal patches; [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`] on grids
    /// smaller than [`AUTOMATIC_BLOCKS_LARGE_CELLS`], where the blocks'
    /// own costs weigh more: the rough films' boxes) and the contact has more
    /// than 256 patches (a rough contact: a Hertzian or flat punch's
    /// contact, one patch, gains nothing from the blocks); the box
    /// otherwise, on a periodic grid whose sides the block side does not
    /// divide, on a solver split across MPI ranks whose rows are not whole
    /// rows of blocks on every rank, in adhesive solves and
    /// on the coarse levels of the multi-resolution start. Undoes
    /// [`ContactSolver::set_coarse_blocks`].
    ///
    /// ```
    /// use layered_contact::solver::{ContactSolver, SolverParams};
    /// use layered_contact::{Boundary, Grid, Material, Substrate};
    ///
    /// let body = Substrate::half_space(Material::new(1.0, 0.0)?);
    /// let grid = Grid::square_of_side(64, 1.0)?;
    /// let mut solver = ContactSolver::new(&body, &grid, Boundary::Periodic, SolverParams::default())?;
    /// assert!(solver.coarse_blocks_automatic());
    /// solver.set_coarse_blocks(Some(16))?;
    /// assert!(!solver.coarse_blocks_automatic());
    /// solver.set_automatic_coarse_blocks();
    /// assert!(solver.coarse_blocks_automatic() && solver.coarse_blocks().is_none());
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn set_automatic_coarse_blocks(&mut self) {
        self.balancing = None;
        self.coarse_automatic = true;
    }

    /// Whether the solves choose their preconditioner themselves
    /// ([`ContactSolver::set_automatic_coarse_blocks`], the default).
    pub fn coarse_blocks_automatic(&self) -> bool {
        self.coarse_automatic
    }

    /// Whether the constrained conjugate gradients' next iteration takes
    /// the two-level preconditioner: each of the last [`QUIET_ITERATIONS`]
    /// iterations changed the contact count by at most
    /// [`SETTLED_COUNT_FRACTION`] of it ([`count_settled`]), and the
    /// preconditioner is on or, chosen automatically, the solve wants it
    /// (decided on the first such iteration from the contact where
    /// `pressure` is positive and the box's mean factor over the quiet
    /// iterations, down to `residual`:
    /// [`ContactSolver::set_automatic_coarse_blocks`]); while the set still
    /// moves, the box alone. `done`: the solve's iterations so far, for
    /// its report ([`Preconditioning`]).
    pub(super) fn coarse_correction_now(
        &mut self,
        choice: &mut CoarseChoice,
        residual: f64,
        pressure: &[f64],
        done: usize,
    ) -> Result<bool> {
        if choice.quiet < QUIET_ITERATIONS {
            return Ok(false);
        }
        let decided = match choice.wanted {
            Some(wanted) => wanted,
            None => {
                let box_rate = (residual / choice.moved_residual).powf(1.0 / choice.quiet as f64);
                let decided = if self.coarse_automatic {
                    // A rate that is not a number (no residual yet) keeps
                    // the box.
                    self.automatic_blocks(pressure, box_rate)?
                } else {
                    self.balancing.is_some()
                };
                choice.wanted = Some(decided);
                choice.report.decided_after = Some(done);
                choice.report.box_factor = Some(box_rate).filter(|r| r.is_finite());
                choice.report.blocks = self.coarse_blocks().filter(|_| decided);
                decided
            }
        };
        choice.report.two_level_iterations += usize::from(decided);
        Ok(decided)
    }

    /// How the last solve that ran the constrained conjugate gradients
    /// preconditioned them: a non-adhesive solve under depth or force
    /// control (not one that ended before, without contact), or a round of
    /// the cohesive zone's. `None` before the first. The coarse levels of
    /// the multi-resolution start are not counted; their iterations take
    /// the box.
    pub fn last_preconditioning(&self) -> Option<Preconditioning> {
        self.preconditioning
    }

    /// The automatic choice for a fine, non-adhesive solve whose contact is
    /// where `pressure` is positive and whose box's mean factor over the
    /// quiet iterations was `box_rate`: the blocks (built if they are not)
    /// on a large enough grid, a box slow enough for its size (a rate that
    /// is not a number keeps the box) and a contact of many patches.
    fn automatic_blocks(&mut self, pressure: &[f64], box_rate: f64) -> Result<bool> {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let side = AUTOMATIC_BLOCK_SIDE;
        let periodic = self.operator.boundary() == Boundary::Periodic;
        let cells = rows * columns;
        let least_rate = if cells >= AUTOMATIC_BLOCKS_LARGE_CELLS {
            AUTOMATIC_BLOCKS_BOX_RATE
        } else {
            AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE
        };
        let fits = cells >= AUTOMATIC_BLOCKS_CELLS
            && box_rate >= least_rate
            && rows.min(columns) >= 4 * side
            && !(periodic && (rows % side != 0 || columns % side != 0));
        // Collective on a split solver: every rank takes the same branch.
        let split_fits = self.ranks_hold_whole_blocks(side);
        let eligible = fits
            && split_fits
            && !self.start_level
            && !self.double_preconditioner
            && self.params.precondition;
        if !eligible || self.few_patches(pressure) {
            return Ok(false);
        }
        if self.balancing.is_none() {
            self.build_blocks(side)?;
        }
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    use super::{
        CoarseChoice, Preconditioning, AUTOMATIC_BLOCKS_BOX_RATE, AUTOMATIC_BLOCKS_CELLS,
        AUTOMATIC_BLOCKS_LARGE_CELLS, AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE, AUTOMATIC_BLOCK_SIDE,
        QUIET_ITERATIONS,
    };
    use crate::solver::{ContactSolver, SolverParams};
    use crate::{Boundary, Grid, Material, Substrate};

    /// The automatic choice's patch test, on its own (the solves of
    /// `tests/coarse_blocks_automatic.rs` whose box converges fast never
    /// reach it): on a periodic 2048 x 2048 grid, with the box's rate at
    /// 0.5 and the count settled, a contact of one square patch (a quarter
    /// of the side across) keeps the box and builds nothing; one of 4096
    /// single-cell specks (every 32nd cell each way, more than 256
    /// patches) takes blocks of 16, built then; before the count settles,
    /// neither is decided. Each decision's report: the iterations done as
    /// given (7), the rate 0.5 to rounding, the blocks taken, and one
    /// iteration with them (the one about to run) or none.
    #[test]
    fn the_automatic_choice_counts_the_patches() {
        let n = 2048;
        let grid = Grid::square_of_side(n, 1.0).unwrap();
        let body = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
        let mut solver =
            ContactSolver::new(&body, &grid, Boundary::Periodic, SolverParams::default()).unwrap();
        let rate = 0.5;
        assert!(rate > AUTOMATIC_BLOCKS_BOX_RATE);
        let quarter = n / 4;
        let one: Vec<f64> = (0..n * n)
            .map(|c| f64::from(u8::from(c / n < quarter && c % n < quarter)))
            .collect();
        let specks: Vec<f64> = (0..n * n)
            .map(|c| f64::from(u8::from((c / n) % 32 == 0 && (c % n) % 32 == 0)))
            .collect();
        // The residual fell by `rate` an iteration over the quiet ones.
        let quiet = |quiet| CoarseChoice {
            quiet,
            moved_residual: 1.0,
            wanted: None,
            report: Preconditioning::default(),
        };
        let reported = |choice: &CoarseChoice, blocks, two_level| {
            let r = choice.report;
            assert_eq!(r.decided_after, Some(7));
            assert!((r.box_factor.unwrap() - rate).abs() < 1e-15);
            assert_eq!((r.blocks, r.two_level_iterations), (blocks, two_level));
        };
        let residual = rate.powi(QUIET_ITERATIONS as i32);
        let mut choice = quiet(QUIET_ITERATIONS - 1);
        let early = solver.coarse_correction_now(&mut choice, residual, &specks, 7);
        assert!(!early.unwrap() && choice.wanted.is_none());
        assert_eq!(choice.report, Preconditioning::default());
        let mut choice = quiet(QUIET_ITERATIONS);
        let patch = solver.coarse_correction_now(&mut choice, residual, &one, 7);
        assert!(!patch.unwrap());
        assert_eq!((choice.wanted, solver.coarse_blocks()), (Some(false), None));
        reported(&choice, None, 0);
        let mut choice = quiet(QUIET_ITERATIONS);
        let rough = solver.coarse_correction_now(&mut choice, residual, &specks, 7);
        assert!(rough.unwrap());
        assert_eq!(
            (choice.wanted, solver.coarse_blocks()),
            (Some(true), Some(AUTOMATIC_BLOCK_SIDE))
        );
        reported(&choice, Some(AUTOMATIC_BLOCK_SIDE), 1);
    }

    /// The rate a smaller grid asks of the box, on its own: on a periodic
    /// 1024 x 1024 grid of single-cell specks every 32nd cell each way
    /// (1024 patches), the count settled, a box's factor of 0.45 (above
    /// [`AUTOMATIC_BLOCKS_BOX_RATE`], below
    /// [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`]: a rough film's, 0.40 to
    /// 0.46 at 1024^2) keeps the box and builds nothing, 0.55 (the tamaas
    /// problem's 0.63 to 0.66) takes blocks of 16; on 512 x 512 cells,
    /// specks every 16th cell (1024 patches again), a factor of 0.9 keeps
    /// the box: the grid lies below [`AUTOMATIC_BLOCKS_CELLS`].
    #[test]
    fn a_smaller_grid_asks_more_of_the_box() {
        assert_eq!(AUTOMATIC_BLOCKS_CELLS, 1024 * 1024);
        const { assert!(AUTOMATIC_BLOCKS_LARGE_CELLS > AUTOMATIC_BLOCKS_CELLS) };
        let body = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
        let decide = |n: usize, every: usize, rate: f64| {
            let grid = Grid::square_of_side(n, 1.0).unwrap();
            let mut solver =
                ContactSolver::new(&body, &grid, Boundary::Periodic, SolverParams::default())
                    .unwrap();
            let specks: Vec<f64> = (0..n * n)
                .map(|c| {
                    f64::from(u8::from(
                        (c / n).is_multiple_of(every) && (c % n).is_multiple_of(every),
                    ))
                })
                .collect();
            let mut choice = CoarseChoice {
                quiet: QUIET_ITERATIONS,
                moved_residual: 1.0,
                wanted: None,
                report: Preconditioning::default(),
            };
            let residual = rate.powi(QUIET_ITERATIONS as i32);
            let decided = solver
                .coarse_correction_now(&mut choice, residual, &specks, 5)
                .unwrap();
            assert!((choice.report.box_factor.unwrap() - rate).abs() < 1e-15);
            (decided, solver.coarse_blocks())
        };
        let (low, high) = (0.45, 0.55);
        assert!(AUTOMATIC_BLOCKS_BOX_RATE < low && low < AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE);
        assert!(high > AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE);
        assert_eq!(decide(1024, 32, low), (false, None));
        assert_eq!(decide(1024, 32, high), (true, Some(AUTOMATIC_BLOCK_SIDE)));
        assert_eq!(decide(512, 16, 0.9), (false, None));
    }
}
