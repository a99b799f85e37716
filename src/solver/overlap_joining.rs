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
//! ed., section 16.5). On a solve from the multi-resolution start, while
//! the contact shrinks (its count fell in the iteration before: the
//! overshoot being shed), the cells beside it are held to the same
//! threshold: its edge, retreating, would otherwise take back shallow
//! overlap the next steps shed again. Not on a solve from a uniform
//! pressure: a plate on a stiff layer over a far softer base (the ring
//! contact of `tests/mpi.rs`), whose contact shrinks from the whole plate
//! to a ring, took 1857 split iterations with the edge held, over its
//! bound of 1600. No parameter. Neighbours along the row only: a
//! row lies whole on one rank of a split solver, so the rule needs no
//! exchange and a split solve takes the serial one's steps. Start levels
//! let every overlapping cell in, as before (they stop at a loosened
//! tolerance with overlap left), and so do solves from a warm start (the
//! cohesive zone's rounds move an edge a cell at a time; on a straight
//! edge along the grid the rule held its fixed point back).
//!
//! The gap pass lets every overlapping cell in and lists them, marking
//! those beside the contact (a neighbour in contact in their row); once
//! the mean is known,
//! [`GapPass::leave_out_shallower`](super::passes::GapPass::leave_out_shallower)
//! takes the listed ones above it out again, visiting those cells only
//! (with a second pass over the grid the isolated film at 4096^2 took 1.04
//! times as long).
//!
//! Without the edge's cells in every iteration (the mean alone) a
//! Hertzian contact, whose overlap is a thin ring at its edge, took up to
//! twice its iterations under force control and a two-way sinusoid of
//! 1024 equal patches 3.5 times; held only while the contact shrinks, the
//! Hertzian contacts keep their counts and the rough ones from the start
//! need fewer (the tamaas problem at 8192^2 40.6 fine iterations over
//! seven seeds against 44.1, a coated stack 67 against 73). Measured in
//! BENCHMARKS.md, "Only the deeper overlap joins", "Only the deeper
//! overlap joins, at no extra pass" and "The edge held while the contact
//! shrinks, after the multi-resolution start".

use super::passes::WorkingSet;
use super::ContactSolver;

/// Where a constrained solve's start came from, which decides the rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Origin {
    /// A warm start of the caller's (or a cohesive zone's round): every
    /// overlapping cell joins.
    Warm,
    /// A uniform pressure: overlap apart from the contact joins if deep.
    Cold,
    /// The multi-resolution start's prolonged pressure: the same, and
    /// while the contact shrinks, the overlap beside it too.
    Coarse,
}

impl Origin {
    /// Whether the overlap beside the contact is held to the threshold,
    /// given whether the contact count fell in the last iteration.
    pub(super) fn holds_edge(self, shrinking: bool) -> bool {
        shrinking && self == Origin::Coarse
    }
}

impl ContactSolver {
    /// The gap at or below which overlap away from the contact's edge (or,
    /// if `edge_held`, any overlap) joins the working set, if not every
    /// overlapping cell does: on a fine solve (not a start level) from no
    /// warm start of the caller's, with at least two overlapping cells,
    /// some of them apart from the contact unless `edge_held`, their mean
    /// gap, or their deepest if rounding put the mean below it (the
    /// deepest always joins, so a solve with overlap left never stops). The
    /// same on every rank (`set` is the whole grid's, `edge_held` decided
    /// on the whole contact count; one collective for the deepest).
    pub(super) fn deeper_overlap(
        &self,
        set: &WorkingSet,
        origin: Origin,
        edge_held: bool,
    ) -> Option<f64> {
        if origin == Origin::Warm
            || self.start_level
            || !set.overlap
            || set.overlap_cells < 2
            || (set.apart_cells == 0 && !edge_held)
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
    /// cells or none apart from the contact unless its edge is held (on a
    /// shrinking contact from the multi-resolution start).
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
        let (cold, coarse, warm) = (Origin::Cold, Origin::Coarse, Origin::Warm);
        // Gaps -1, -2 and -6: the mean -3.
        let three = set(3, -9.0, -6.0);
        assert_eq!(solver.deeper_overlap(&three, cold, false), Some(-3.0));
        assert_eq!(solver.deeper_overlap(&three, coarse, false), Some(-3.0));
        // Three equal gaps whose sum rounded down: the deepest.
        let g = -0.1;
        let sum = 3.0 * g - 1e-17;
        assert!(sum / 3.0 < g);
        assert_eq!(solver.deeper_overlap(&set(3, sum, g), cold, false), Some(g));
        assert_eq!(
            solver.deeper_overlap(&set(1, -2.0, -2.0), cold, false),
            None
        );
        let closed = WorkingSet {
            overlap: false,
            ..three
        };
        assert_eq!(solver.deeper_overlap(&closed, cold, false), None);
        // Every overlapping cell beside the contact: all join ...
        let beside = WorkingSet {
            apart_cells: 0,
            ..three
        };
        assert_eq!(solver.deeper_overlap(&beside, cold, false), None);
        // ... unless the edge is held: then those beside it too.
        assert_eq!(solver.deeper_overlap(&beside, coarse, true), Some(-3.0));
        assert_eq!(solver.deeper_overlap(&three, warm, false), None);
        solver.start_level = true;
        assert_eq!(solver.deeper_overlap(&three, cold, false), None);
        // The edge held only on a shrinking contact from the coarse start.
        let held: Vec<bool> = [(warm, true), (cold, true), (coarse, false), (coarse, true)]
            .iter()
            .map(|&(origin, shrinking)| origin.holds_edge(shrinking))
            .collect();
        assert_eq!(held, [false, false, false, true]);
    }
}
