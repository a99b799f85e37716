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
//! After the multi-resolution start, overlap the contact's own gap error
//! explains stays out too. That error is smooth in the early fine
//! iterations (on the tamaas problem at 2048^2, 96 % of its rms at
//! wavelengths above 128 cells), so a shallow overlapping cell is as
//! likely the error of the pressures around it as a new asperity, and
//! ever more likely as the grid refines (89 % of the joins of the second
//! and third fine iterations wrong at 8192^2). The gaps of the cells in
//! contact, zero at the solution, estimate the error near a cell: their
//! normalised convolution along its row ([`RowEstimate`]). A cell whose
//! gap less the estimate is at least zero stays out (the deepest always
//! joins). Counted cell by cell, that reading cleared 94 % of the overlap
//! that joined wrongly and kept 78 % of the right. Along rows only, as the
//! edge's rule: a 2D Gaussian of 2 cells saved two more iterations on the
//! stack at 2048^2 and one on the periodic stack, but a split solver
//! would exchange rows for it. With it the tamaas problem at 8192^2 takes
//! 31.1 fine iterations over seven seeds against 40.6, the coated stack at
//! 4096^2 43 against 51, the films from one more to three fewer, the
//! Hertzian contacts as before. Measured in BENCHMARKS.md, "The early gap
//! error is smooth: the contact's own gaps estimate it" and "New overlap
//! the gap error explains stays out".
//!
//! The gap pass lets every overlapping cell in and lists them, marking
//! those beside the contact (a neighbour in contact in their row); once
//! the mean is known,
//! [`GapPass::leave_out`](super::passes::GapPass::leave_out) takes the
//! listed ones that stay out again ([`Holding::stays_out`]), visiting
//! those cells only (with a second pass over the grid the isolated film at
//! 4096^2 took 1.04 times as long).
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
    /// while the contact shrinks, the overlap beside it too; and overlap
    /// the contact's own gap error explains stays out.
    Coarse,
}

impl Origin {
    /// Whether the overlap beside the contact is held to the threshold,
    /// given whether the contact count fell in the last iteration.
    pub(super) fn holds_edge(self, shrinking: bool) -> bool {
        shrinking && self == Origin::Coarse
    }
}

/// How an iteration holds new overlap back: the cells it keeps out of
/// the working set ([`Holding::stays_out`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Holding {
    /// The gap above which overlap apart from the contact (and, if
    /// `beside_too`, beside it) stays out, if any.
    pub(super) join_at: Option<f64>,
    /// Whether `join_at` holds the overlap beside the contact too.
    pub(super) beside_too: bool,
    /// Whether overlap the contact's gap error explains stays out
    /// ([`RowEstimate`]).
    pub(super) explained: bool,
    /// The deepest overlap of the whole grid (every rank's), which always
    /// joins.
    pub(super) deepest: f64,
}

impl Holding {
    /// Whether the overlapping cell `cell`, with gap `gap[cell]` (below
    /// zero) and `beside` the contact (a neighbour in its row carries
    /// pressure) or not, stays out of the working set.
    pub(super) fn stays_out(
        &self,
        cell: usize,
        beside: bool,
        gap: &[f64],
        estimate: &RowEstimate,
    ) -> bool {
        let g = gap[cell];
        let shallow = self
            .join_at
            .is_some_and(|at| (self.beside_too || !beside) && g > at);
        shallow || (self.explained && g > self.deepest && g - estimate.at(cell) >= 0.0)
    }
}

/// The standard deviation, in cells, of the Gaussian along a row that
/// smooths the contact's gaps into [`RowEstimate`] (measured against 4
/// and against a 2D Gaussian of 2 in BENCHMARKS.md, "The early gap error
/// is smooth: the contact's own gaps estimate it").
const SIGMA: f64 = 8.0;

/// How far the Gaussian reaches, in cells: three standard deviations.
const REACH: usize = 24;

/// An estimate of an iteration's gap error near a cell from the gaps of
/// the cells in contact in its row (zero at the solution): their
/// normalised convolution (Knutsson & Westin 1993, CVPR, 515-523) with a
/// Gaussian of [`SIGMA`] cells, `sum w g m / sum w m` with `m` 1 where the
/// pressure is positive, wrapping at the row's ends on a periodic grid; 0
/// where the weights in contact add to less than a thousandth of the
/// Gaussian's (no contact near). A row lies whole on one rank of a split
/// solver, so the estimate needs no exchange.
#[derive(Debug)]
pub(super) struct RowEstimate<'a> {
    gap: &'a [f64],
    pressure: &'a [f64],
    columns: usize,
    periodic: bool,
    weights: [f64; 2 * REACH + 1],
    /// The least weight in contact that gives an estimate: a thousandth
    /// of the Gaussian's sum.
    least: f64,
}

impl<'a> RowEstimate<'a> {
    /// The estimate on rows `columns` long of `gap` and `pressure` (of the
    /// same length, whole rows).
    pub(super) fn new(gap: &'a [f64], pressure: &'a [f64], columns: usize, periodic: bool) -> Self {
        let weights: [f64; 2 * REACH + 1] = std::array::from_fn(|k| {
            let d = (k as f64 - REACH as f64) / SIGMA;
            (-0.5 * d * d).exp()
        });
        let least = 1e-3 * weights.iter().sum::<f64>();
        Self {
            gap,
            pressure,
            columns,
            periodic,
            weights,
            least,
        }
    }

    /// The estimate at `cell`.
    pub(super) fn at(&self, cell: usize) -> f64 {
        let (row, j) = (cell - cell % self.columns, cell % self.columns);
        let (mut sum, mut weight) = (0.0, 0.0);
        for (k, w) in self.weights.iter().enumerate() {
            // The column `j + k - REACH`, wrapped on a periodic grid.
            let column = (j + k) as isize - REACH as isize;
            let column = if self.periodic {
                column.rem_euclid(self.columns as isize)
            } else {
                column
            };
            if !(0..self.columns as isize).contains(&column) {
                continue;
            }
            let c = row + column as usize;
            if self.pressure[c] > 0.0 {
                sum += w * self.gap[c];
                weight += w;
            }
        }
        if weight > self.least {
            sum / weight
        } else {
            0.0
        }
    }
}

impl ContactSolver {
    /// How this iteration holds new overlap back, if it does: on a fine
    /// solve (not a start level) from no warm start of the caller's, with
    /// at least two overlapping cells. Overlap apart from the contact (or,
    /// if `edge_held`, any overlap) joins only at or below the overlapping
    /// cells' mean gap, or their deepest if rounding put the mean below it
    /// (the deepest always joins, so a solve with overlap left never
    /// stops); none is held to the mean if all of it lies beside the
    /// contact and the edge is not held. From the multi-resolution start,
    /// overlap the gap error explains stays out too. The same on every rank
    /// (`set` is the whole grid's, `edge_held` decided on the whole contact
    /// count; one collective for the deepest).
    pub(super) fn holding(
        &self,
        set: &WorkingSet,
        origin: Origin,
        edge_held: bool,
    ) -> Option<Holding> {
        if origin == Origin::Warm || self.start_level || !set.overlap || set.overlap_cells < 2 {
            return None;
        }
        let explained = origin == Origin::Coarse;
        let by_depth = set.apart_cells > 0 || edge_held;
        if !by_depth && !explained {
            return None;
        }
        let deepest = -self.max_over_ranks(-set.deepest);
        let mean = set.overlap_sum / set.overlap_cells as f64;
        Some(Holding {
            join_at: by_depth.then_some(mean.max(deepest)),
            beside_too: edge_held,
            explained,
            deepest,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::passes::tests::next;

    /// Overlap held to the mean of the overlapping cells' gaps, not below
    /// their deepest; from the multi-resolution start, overlap the gap
    /// error explains held too; nothing held on a warm solve, a start
    /// level, with fewer than two overlapping cells, or, from a uniform
    /// pressure, with none apart from the contact unless its edge is held
    /// (on a shrinking contact from the multi-resolution start).
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
        let hold = |join_at: Option<f64>, beside_too, explained, deepest| {
            Some(Holding {
                join_at,
                beside_too,
                explained,
                deepest,
            })
        };
        // Gaps -1, -2 and -6: the mean -3.
        let three = set(3, -9.0, -6.0);
        let at = Some(-3.0);
        assert_eq!(
            solver.holding(&three, cold, false),
            hold(at, false, false, -6.0)
        );
        assert_eq!(
            solver.holding(&three, coarse, false),
            hold(at, false, true, -6.0)
        );
        // Three equal gaps whose sum rounded down: the deepest.
        let g = -0.1;
        let sum = 3.0 * g - 1e-17;
        assert!(sum / 3.0 < g);
        let rounded = solver.holding(&set(3, sum, g), cold, false);
        assert_eq!(rounded, hold(Some(g), false, false, g));
        assert_eq!(solver.holding(&set(1, -2.0, -2.0), coarse, false), None);
        let closed = WorkingSet {
            overlap: false,
            ..three
        };
        assert_eq!(solver.holding(&closed, coarse, false), None);
        // Every overlapping cell beside the contact: none held to the mean
        // (from the multi-resolution start, the explained ones still) ...
        let beside = WorkingSet {
            apart_cells: 0,
            ..three
        };
        assert_eq!(solver.holding(&beside, cold, false), None);
        assert_eq!(
            solver.holding(&beside, coarse, false),
            hold(None, false, true, -6.0)
        );
        // ... unless the edge is held: then those beside it too.
        assert_eq!(
            solver.holding(&beside, coarse, true),
            hold(at, true, true, -6.0)
        );
        assert_eq!(solver.holding(&three, warm, false), None);
        solver.start_level = true;
        assert_eq!(solver.holding(&three, coarse, false), None);
        // The edge held only on a shrinking contact from the coarse start.
        let held: Vec<bool> = [(warm, true), (cold, true), (coarse, false), (coarse, true)]
            .iter()
            .map(|&(origin, shrinking)| origin.holds_edge(shrinking))
            .collect();
        assert_eq!(held, [false, false, false, true]);
    }

    /// The estimate against a direct sum over each cell's row: weights
    /// `exp(-d^2 / 2 sigma^2)` of the distance `d` in columns (on a
    /// periodic grid the shortest way round) up to three standard
    /// deviations, over the cells in contact, normalised by their sum; 0
    /// where that sum is below a thousandth of the Gaussian's (a row
    /// without contact, and the cells far from a row's only contact). Rows
    /// of 100 cells, the middle one without contact, the last with one cell
    /// in contact; within 4 eps of the sum's magnitude (the same terms
    /// added in another order).
    #[test]
    fn the_estimate_is_the_normalised_sum_over_the_row() {
        let (rows, columns) = (4, 100);
        let n = rows * columns;
        let mut state = 7;
        let gap: Vec<f64> = (0..n).map(|_| 0.5 * next(&mut state)).collect();
        let pressure: Vec<f64> = (0..n)
            .map(|c| match c / columns {
                1 => 0.0,
                3 => f64::from(c % columns == 50),
                // About 30 % in contact (`next` lies in [-1, 1)).
                _ => f64::from(next(&mut state) < -0.4),
            })
            .collect();
        let gaussian: f64 = (-24..=24_i32)
            .map(|d| (-f64::from(d * d) / 128.0).exp())
            .sum();
        for periodic in [false, true] {
            let estimate = RowEstimate::new(&gap, &pressure, columns, periodic);
            let (mut zeros, mut wrapped) = (0, 0);
            for c in 0..n {
                let (row, j) = (c / columns, c % columns);
                let (mut sum, mut weight, mut magnitude) = (0.0, 0.0, 0.0);
                for k in 0..columns {
                    let straight = j.abs_diff(k);
                    let d = if periodic {
                        straight.min(columns - straight)
                    } else {
                        straight
                    };
                    let other = row * columns + k;
                    if d <= 24 && pressure[other] > 0.0 {
                        let w = (-((d * d) as f64) / 128.0).exp();
                        (sum, weight) = (sum + w * gap[other], weight + w);
                        magnitude += w * gap[other].abs();
                        wrapped += usize::from(d < straight);
                    }
                }
                let direct = if weight > 1e-3 * gaussian {
                    sum / weight
                } else {
                    0.0
                };
                zeros += usize::from(direct == 0.0);
                let error = (estimate.at(c) - direct).abs();
                assert!(
                    error <= 4.0 * f64::EPSILON * magnitude / weight.max(1e-300),
                    "cell {c}: {error}"
                );
                if direct == 0.0 {
                    assert_eq!(estimate.at(c), 0.0, "cell {c}");
                }
            }
            // The empty row, and the last row's cells more than 22 columns
            // from its one contact (exp(-23^2 / 128) = 0.016 lies below a
            // thousandth of the Gaussian's sum, 0.020; exp(-22^2 / 128)
            // = 0.023 above it).
            assert_eq!(zeros, columns + columns - 45, "{periodic}");
            assert_eq!(wrapped > 0, periodic);
        }
    }

    /// An overlapping cell stays out if apart from the contact (or beside
    /// it, if held too) and shallower than `join_at`, or, where explained
    /// overlap is held, if its gap less the estimate is at least zero,
    /// unless it is the deepest. Gaps of a row of 60 cells: contact at
    /// columns 20 to 39 with gap -0.5 (the estimate -0.5 near them), overlap
    /// at columns 10 (gap -0.4), 19 (-0.6, beside), 41 (-0.2) and 45
    /// (-1.0, the deepest).
    #[test]
    fn overlap_stays_out_by_depth_or_explained() {
        let columns = 60;
        let mut gap = vec![0.1; columns];
        let mut pressure = vec![0.0; columns];
        for c in 20..40 {
            (gap[c], pressure[c]) = (-0.5, 1.0);
        }
        for (c, g) in [(10, -0.4), (19, -0.6), (41, -0.2), (45, -1.0)] {
            gap[c] = g;
        }
        let estimate = RowEstimate::new(&gap, &pressure, columns, false);
        assert!((estimate.at(41) + 0.5).abs() < 1e-15);
        let out = |hold: Holding| -> Vec<usize> {
            [(10, false), (19, true), (41, false), (45, false)]
                .into_iter()
                .filter(|&(c, beside)| hold.stays_out(c, beside, &gap, &estimate))
                .map(|(c, _)| c)
                .collect()
        };
        let by_depth = Holding {
            join_at: Some(-0.55),
            beside_too: false,
            explained: false,
            deepest: -1.0,
        };
        assert_eq!(out(by_depth), [10, 41]);
        assert_eq!(
            out(Holding {
                beside_too: true,
                ..by_depth
            }),
            [10, 41]
        );
        let shallow = Holding {
            join_at: Some(-0.3),
            ..by_depth
        };
        assert_eq!(out(shallow), [41]);
        // Explained: -0.4 and -0.2 at or above the estimate near them
        // (-0.5 at column 41; column 10 lies ten columns from the contact,
        // its estimate -0.5 too); -0.6 below it joins, and the deepest.
        let explained = Holding {
            join_at: None,
            explained: true,
            ..by_depth
        };
        assert!((estimate.at(10) + 0.5).abs() < 1e-15);
        assert_eq!(out(explained), [10, 41]);
        // A cell at the deepest gap joins even where explained.
        let deep = Holding {
            deepest: -0.4,
            ..explained
        };
        assert_eq!(out(deep), [41]);
    }
}
