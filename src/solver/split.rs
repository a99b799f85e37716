//! What a solver split across MPI ranks (the `mpi` feature, module
//! `distributed`) adds to the serial one: sums and agreements over
//! the ranks, and the refusal of what does not run split. On a serial
//! solver each of these is the identity.

use crate::error::{Error, Result};
use crate::grid::{Boundary, Grid};
use crate::kernel::ComplianceOperator;
use crate::slab::Slab;
use crate::substrate::Substrate;

use super::{passes, ContactSolver, SolverParams};

impl ContactSolver {
    /// `result` on a serial solver; on a split one, an error on every rank
    /// if any rank's `result` is one ([`Slab::agree`](crate::slab::Slab)),
    /// so that no rank waits in a collective for one that has returned.
    pub(crate) fn agreed<T>(&self, result: Result<T>) -> Result<T> {
        crate::slab::agree(self.operator.slab(), result)
    }

    /// Whether `flag` holds on any rank (on this one when serial).
    pub(crate) fn on_any_rank(&self, flag: bool) -> bool {
        let mut count = [f64::from(u8::from(flag))];
        self.sum_over_ranks(&mut count);
        count[0] > 0.0
    }

    /// Sums `values` over the ranks of a distributed solver (nothing when
    /// serial).
    pub(super) fn sum_over_ranks(&self, values: &mut [f64]) {
        over_ranks(&self.operator, values);
    }

    /// `value` summed over the ranks (itself when serial).
    pub(super) fn summed(&self, value: f64) -> f64 {
        summed_over_ranks(&self.operator, value)
    }

    /// [`Error::Unsupported`] for `what` on a distributed solver: only the
    /// non-adhesive solves run on a grid split across ranks.
    pub(crate) fn serial_only(&self, what: &'static str) -> Result<()> {
        match self.operator.slab() {
            Some(_) => Err(Error::Unsupported {
                feature: what,
                reason: "a solver split across MPI ranks runs only the non-adhesive \
                         solves (solve_depth and solve_force)",
            }),
            None => Ok(()),
        }
    }

    /// A solver like this one (split across the same ranks if it is) for
    /// `substrate` on another grid.
    pub(crate) fn like_on(
        &self,
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        params: SolverParams,
    ) -> Result<ContactSolver> {
        match self.operator.slab() {
            None => ContactSolver::new(substrate, grid, boundary, params),
            Some(slab) => {
                let slab = Slab::for_grid(slab.exchange.clone(), grid)?;
                ContactSolver::on_slab(substrate, grid, boundary, params, &slab)
            }
        }
    }

    /// A solver for `substrate` on `grid` split as `slab` says (an error on
    /// every rank if on any).
    pub(crate) fn on_slab(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        params: SolverParams,
        slab: &Slab,
    ) -> Result<ContactSolver> {
        let operator = ComplianceOperator::distributed(substrate, grid, boundary, slab)?;
        slab.agree(ContactSolver::with_operator(operator, substrate, params))
    }

    /// Whether this solver is split across more than one rank (its fields
    /// hold only this rank's rows).
    pub(crate) fn is_split(&self) -> bool {
        self.operator
            .slab()
            .is_some_and(|slab| slab.exchange.ranks() > 1)
    }

    /// The number of cells of this rank's rows (the grid's when serial).
    pub(super) fn local_cells(&self) -> usize {
        self.operator.local_cells()
    }

    /// The working set over every rank, its bounds in rows of the whole
    /// grid (a serial solver's set as it is).
    pub(super) fn whole_working_set(&self, mut set: passes::WorkingSet) -> passes::WorkingSet {
        if self.operator.slab().is_none() {
            return set;
        }
        let mut sums = [
            set.members as f64,
            set.gap_sum,
            f64::from(u8::from(set.overlap)),
            set.overlap_cells as f64,
            set.overlap_sum,
            set.apart_cells as f64,
        ];
        self.sum_over_ranks(&mut sums);
        (set.bounds, set.gap_max) = self.whole_bounds(set.bounds, set.gap_max);
        set.members = sums[0] as usize;
        set.gap_sum = sums[1];
        set.overlap = sums[2] > 0.0;
        set.overlap_cells = sums[3] as usize;
        set.overlap_sum = sums[4];
        set.apart_cells = sums[5] as usize;
        // Not `deepest`: one collective more, taken only where it is read
        // (`ContactSolver::holding`).
        set
    }

    /// `bounds` of cells in this rank's rows as bounds in rows of the whole
    /// grid over every rank (`None` if no rank has any), and the largest of
    /// the ranks' `largest` (a magnitude, at least zero); as they are on a
    /// serial solver. One collective.
    pub(super) fn whole_bounds(
        &self,
        bounds: Option<passes::Bounds>,
        largest: f64,
    ) -> (Option<passes::Bounds>, f64) {
        let Some(slab) = self.operator.slab() else {
            return (bounds, largest);
        };
        let first = slab.rows().start;
        // Bounds as minima: first row and column, and minus the last ones.
        let mut minima = match bounds {
            Some(((r0, r1), (c0, c1))) => [
                (first + r0) as f64,
                -((first + r1) as f64),
                c0 as f64,
                -(c1 as f64),
                -largest,
            ],
            None => [
                f64::INFINITY,
                f64::INFINITY,
                f64::INFINITY,
                f64::INFINITY,
                -largest,
            ],
        };
        slab.exchange.min(&mut minima);
        let bounds = minima[0].is_finite().then(|| {
            (
                (minima[0] as usize, -minima[1] as usize),
                (minima[2] as usize, -minima[3] as usize),
            )
        });
        (bounds, -minima[4])
    }

    /// The largest of the ranks' `value`s (this one's when serial).
    pub(super) fn max_over_ranks(&self, value: f64) -> f64 {
        let mut minimum = [-value];
        if let Some(slab) = self.operator.slab() {
            slab.exchange.min(&mut minimum);
        }
        -minimum[0]
    }

    /// A step's statistics over every rank.
    pub(super) fn whole_step(&self, mut stats: passes::Step) -> passes::Step {
        if self.operator.slab().is_some() {
            let mut sums = [
                stats.corrected as f64,
                stats.change,
                stats.size,
                stats.contact as f64,
                // A scale the same on every rank: the sum of the largest.
                stats.largest,
            ];
            self.sum_over_ranks(&mut sums);
            stats.corrected = sums[0] as usize;
            (stats.change, stats.size) = (sums[1], sums[2]);
            stats.contact = sums[3] as usize;
            stats.largest = sums[4];
        }
        stats
    }
}

/// `values` summed over the ranks of a split `operator` (nothing when
/// serial): [`ContactSolver::sum_over_ranks`] where the solver's workspace
/// is borrowed (the two-level preconditioner's passes).
pub(super) fn over_ranks(operator: &ComplianceOperator, values: &mut [f64]) {
    if let Some(slab) = operator.slab() {
        slab.sum(values);
    }
}

/// `value` summed over the ranks of a split `operator` (itself when
/// serial): [`ContactSolver::summed`] where the solver's workspace is
/// borrowed.
pub(super) fn summed_over_ranks(operator: &ComplianceOperator, value: f64) -> f64 {
    let mut sum = [value];
    over_ranks(operator, &mut sum);
    sum[0]
}
