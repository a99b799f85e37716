//! Which new overlap joins the working set of a fine solve's constrained
//! conjugate gradients ([`polonsky_keer`](super::polonsky_keer)).
//!
//! Polonsky and Keer (1999, Wear 231, 206-219) let every cell the indenter
//! overlaps join the working set at once. After a multi-resolution start
//! on a rough surface that overshoots: the finer grid's asperities overlap
//! all over the prolonged contact, join with zero pressure, take load from
//! their neighbours, and the contact grows well past its final size before
//! the box preconditioner sheds it again, a few per cent an iteration (on
//! the tamaas problem of `examples/rough_benchmark.rs` at 8192^2 from 13.4
//! to 15.1 million cells in two iterations, then 27 more down to 12.7
//! million; BENCHMARKS.md, "What the blocks' runaway depends on").
//!
//! A fine solve lets in an overlapping cell if it lies beside a cell in
//! contact in its row (the contact's edge growing), or if it overlaps at
//! least as deeply as the overlap's mean (its deepest always). Where the
//! compliance reaches far, the deep ones carry the load that lifts the
//! shallow detached ones clear, and the next iteration measures the
//! overlap afresh: the most violated constraints first, as active-set
//! methods add them (Nocedal & Wright 2006, Numerical Optimization, 2nd
//! ed., section 16.5). No parameter. Neighbours along the row only: a
//! row lies whole on one rank of a split solver, so the rule needs no
//! exchange and a split solve takes the serial one's steps. Start levels
//! let every overlapping cell in, as before (they stop at a loosened
//! tolerance with overlap left), and so do solves from a warm start (the
//! cohesive zone's rounds move an edge a cell at a time; on a straight
//! edge along the grid the rule held its fixed point back).
//!
//! The gap pass lets every overlapping cell in and lists those apart from
//! the contact (no neighbour in contact in their row); once the mean is
//! known,
//! [`GapPass::leave_out_shallower`](super::passes::GapPass::leave_out_shallower)
//! takes the listed ones above it out again, visiting those cells only
//! (with a second pass over the grid the isolated film at 4096^2 took 1.04
//! times as long).
//!
//! Without the edge's cells (the mean alone) a Hertzian contact, whose
//! overlap is a thin ring at its edge, took up to twice its iterations
//! under force control and a two-way sinusoid of 1024 equal patches 3.5
//! times. Measured in BENCHMARKS.md, "Only the deeper overlap joins" and
//! "Only the deeper overlap joins, at no extra pass".

use super::passes::WorkingSet;
use super::ContactSolver;

impl ContactSolver {
    /// The gap at or below which overlap away from the contact's edge
    /// joins the working set, if not every overlapping cell does: on a
    /// `cold` fine solve (from no warm start of the caller's; not a start
    /// level) with at least two overlapping cells, some of them apart from
    /// the contact, their mean gap, or their deepest if rounding put the
    /// mean below it (the deepest always joins, so a solve with overlap
    /// left never stops). The same on every rank (`set` is the whole
    /// grid's; one collective for the deepest).
    pub(super) fn deeper_overlap(&self, set: &WorkingSet, cold: bool) -> Option<f64> {
        if !cold
            || self.start_level
            || !set.overlap
            || set.overlap_cells < 2
            || set.apart_cells == 0
        {
            return None;
        }
        let deepest = -self.max_over_ranks(-set.deepest);
        Some((set.overlap_sum / set.overlap_cells as f64).max(deepest))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The mean of the overlapping cells' gaps, not below their deepest;
    /// no limit on a warm solve, a start level, with fewer than two such
    /// cells or none apart from the contact.
    #[test]
    fn the_mean_overlap_and_never_below_the_deepest() {
        use crate::{Boundary, Grid, Material, Substrate};
        let body = Substrate::half_space(Material::new(1e6, 0.5).unwrap());
        let grid = Grid::new(8, 8, 1e-6).unwrap();
        let params = crate::solver::SolverParams::default();
        let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
        let set = |cells: usize, sum: f64, deepest: f64| WorkingSet {
            overlap: true,
            overlap_cells: cells,
            overlap_sum: sum,
            deepest,
            apart_cells: 1,
            ..WorkingSet::default()
        };
        // Gaps -1, -2 and -6: the mean -3.
        assert_eq!(solver.deeper_overlap(&set(3, -9.0, -6.0), true), Some(-3.0));
        // Three equal gaps whose sum rounded down: the deepest.
        let g = -0.1;
        let sum = 3.0 * g - 1e-17;
        assert!(sum / 3.0 < g);
        assert_eq!(solver.deeper_overlap(&set(3, sum, g), true), Some(g));
        assert_eq!(solver.deeper_overlap(&set(1, -2.0, -2.0), true), None);
        let closed = WorkingSet {
            overlap: false,
            ..set(3, -9.0, -6.0)
        };
        assert_eq!(solver.deeper_overlap(&closed, true), None);
        // Every overlapping cell beside the contact: all join.
        let beside = WorkingSet {
            apart_cells: 0,
            ..set(3, -9.0, -6.0)
        };
        assert_eq!(solver.deeper_overlap(&beside, true), None);
        assert_eq!(solver.deeper_overlap(&set(3, -9.0, -6.0), false), None);
        solver.start_level = true;
        assert_eq!(solver.deeper_overlap(&set(3, -9.0, -6.0), true), None);
    }
}
