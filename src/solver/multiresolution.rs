//! The multi-resolution start of the non-adhesive solver: the same problem
//! solved on the grid of half the cells each way, recursively, and
//! prolonged to start (or, from a warm start, correct) the fine solve
//! (Brandt 1977, Math. Comp. 31, 333-390).

use crate::grid::Grid;
use crate::indenter::Indenter;
#[cfg(doc)]
use crate::kernel::ComplianceOperator;

use super::polonsky_keer::Control;
use super::{ContactSolver, Fields, SolverParams, WarmStart};

/// Grids at least this many cells each way start from the solution on the
/// grid of half the cells each way (rounded up).
pub const MULTIRESOLUTION_CELLS: usize = 64;

/// The tolerance of the coarse solves of a multi-resolution start (or the
/// solve's own, if looser): a start needs the contact set, not the last
/// digits of the pressure. Measured against `1e-5` (2026-11-25): the same
/// fine iterations on the rough contacts of `rough_benchmark` and
/// `benches/peers/rough.py` (1024^2 and 2048^2) and on the Hertzian ones of
/// `hertz_benchmark`, a fifth fewer coarse ones. A coarse solve stops there
/// even while cells still overlap the indenter (a fine solve also waits for
/// them to join): on rough contacts a further fifth of the coarse
/// iterations, the fine ones and the Hertzian ones unchanged (2026-11-29,
/// BENCHMARKS.md "Speed: rough contacts on large grids"); a looser
/// tolerance then (3e-3, 1e-2) costs the Hertzian contact under depth
/// control up to twice its fine iterations.
const COARSE_TOLERANCE: f64 = 1e-3;

/// A start level that was itself started from its coarser level stops at
/// this fraction of its first iteration's residual, if that is looser than
/// its tolerance ([`loosened`]).
const START_RESIDUAL_FRACTION: f64 = 0.03;

/// The loosest tolerance [`loosened`] gives.
const LOOSEST_START_TOLERANCE: f64 = 1e-2;

/// The tolerance of a start level prolonged from its own coarser level,
/// whose first iteration changed the pressure by `first_residual` (relative
/// L1): `tolerance`, or [`START_RESIDUAL_FRACTION`] of `first_residual` if
/// that is looser (at most [`LOOSEST_START_TOLERANCE`]).
///
/// The first iteration after a prolongation measures how far apart two
/// successive grids' solutions lie; the finer level's own start will be as
/// far from this level's solution, so converging this level much beyond
/// that buys its finer level nothing. A rough surface gains a scale of
/// patches with each level and starts far (a first residual of 0.2 to 0.4),
/// a smooth contact near (1e-3 to 2e-2, so its levels keep
/// [`COARSE_TOLERANCE`]). Measured (2026-11-29, BENCHMARKS.md "Speed: rough
/// contacts on large grids"): the rough problems' coarse iterations fall by
/// a fifth to a third, their fine ones move by at most two; the Hertzian
/// contacts of `hertz_benchmark` (256^2 to 2048^2, depth and force) keep
/// every count. A fraction of 0.1 saves a few more coarse iterations but
/// costs the Hertzian contact at 256^2 six more fine ones; 0.01 saves half
/// as many.
///
/// The start level right under the solve asked for keeps its tolerance
/// (`ContactSolver::loosens`): the solve starts from its solution, and how
/// far that start lies is not the only thing it pays for. On the tamaas
/// problem at 8192^2 (`rough_benchmark peers`, seed 2) a loosened start set
/// the fine solve off on a zig-zag, its contact from 14.0 to 22.1 million
/// cells and back to 12.6 million over 40 iterations, 64 in all; with the
/// level under it kept to its tolerance, 44. Over seeds 1 to 7 at 8192^2:
/// 44 to 49 fine iterations against 46 to 64, for -3 to +13 coarse ones;
/// the films' fine counts unchanged from 512^2 to 8192^2 but the periodic
/// film's at 8192^2 (28 against 27); the coated stack's, chaotic in the
/// start, -3 to +7 on seed 1 and lower on average over five seeds from
/// 512^2 to 4096^2, two outliers of 118 gone (BENCHMARKS.md, "The start
/// level under the solve").
pub(super) fn loosened(tolerance: f64, first_residual: f64) -> f64 {
    tolerance.max((START_RESIDUAL_FRACTION * first_residual).min(LOOSEST_START_TOLERANCE))
}

/// A start level stops at its [`loosened`] tolerance only in an iteration
/// that changed its contact count by at most this fraction of the count
/// before it ([`start_count_settled`]); while its contact set still moves
/// it keeps its own tolerance. On a stiff coating over a soft base (the
/// coated stack of `examples/rough_benchmark.rs`) the constrained
/// iteration sheds the cells a start gave too many a few hundred a step
/// for dozens of steps: a level that stopped at a change of about 1e-2
/// handed its finer level a contact 37 % too large at 2048^2, and the fine
/// solve spent 227 iterations shedding it where it spent 82 with a
/// thousandth (BENCHMARKS.md, "A start level stops once its contact
/// settles"). A thousandth still let the stack's 512^2 level stop while it
/// shed: 85 fine iterations at 1024^2 against 55 at 512^2 and 50 at
/// 2048^2; with 3e-4, 62 at 1024^2, and 59 / 76 against 62 / 80 at
/// 4096^2 / 8192^2; the other rough problems' fine counts moved by -1 to
/// +3 from 512^2 to 8192^2 for 0 to 14 more coarse iterations (the stack
/// at 8192^2 29; BENCHMARKS.md, "A start level's settled count").
pub(super) const START_SETTLED_FRACTION: f64 = 3e-4;

/// The two-level preconditioner joins once its contact count has moved by
/// at most this fraction of itself in each of three iterations in a row
/// ([`count_settled`], `balancing::QUIET_ITERATIONS`). The rough film and
/// the tamaas problem of `examples/rough_benchmark.rs` change their counts
/// by less than this once the box's settling is over; 3e-4 or 1e-4 join
/// later and cost the tamaas problem and the stack 3 to 16 more fine
/// iterations at 2048^2 and 4096^2, a looser 1e-2 more still
/// (BENCHMARKS.md, "A start level's settled count", "The blocks while the
/// contact still moves").
pub(super) const SETTLED_COUNT_FRACTION: f64 = 1e-3;

/// Whether an iteration that took a contact count from `before` (`None`
/// for the first iteration) to `now` moved it by at most `fraction` of
/// `before`.
fn count_within(before: Option<usize>, now: usize, fraction: f64) -> bool {
    before.is_some_and(|b| b.abs_diff(now) as f64 <= fraction * b as f64)
}

/// Whether an iteration that took a contact count from `before` to `now`
/// leaves it settled for the two-level preconditioner (three in a row:
/// [`SETTLED_COUNT_FRACTION`]).
pub(super) fn count_settled(before: Option<usize>, now: usize) -> bool {
    count_within(before, now, SETTLED_COUNT_FRACTION)
}

/// Whether an iteration that took a contact count from `before` to `now`
/// lets a start level stop at its loosened tolerance
/// ([`START_SETTLED_FRACTION`]).
pub(super) fn start_count_settled(before: Option<usize>, now: usize) -> bool {
    count_within(before, now, START_SETTLED_FRACTION)
}

/// The parameters of a coarse solver under a solver with `params`.
pub(super) fn coarse_params(params: &SolverParams) -> SolverParams {
    SolverParams {
        tolerance: params.tolerance.max(COARSE_TOLERANCE),
        fields: Fields::default(),
        ..*params
    }
}

impl ContactSolver {
    /// The multi-resolution start: the same problem solved on the grid of
    /// half the cells each way (twice their size; an odd count rounded up,
    /// the last coarse row or column then half off the grid), itself
    /// started from the next coarser grid, its pressures spread over the
    /// four cells each coarse cell covers. The coarse grid sees the
    /// indenter shifted so that its cell centres fall on the centres of the
    /// fine cells they cover (half a fine cell along an odd side), sampled
    /// there: on a height map, whose lookup is the nearest cell's, one of
    /// the four fine cells around that point, not their mean. The mean
    /// (each coarse level the mean of the finest cells it covers), measured
    /// on the rough problems of `examples/rough_benchmark.rs` at 1024^2 to
    /// 4096^2, moved the fine counts by -15 to +3 and is not taken
    /// (BENCHMARKS.md, "What the blocks' runaway depends on"). Where
    /// the fine grid is even each way (and the solver serial), the coarse
    /// operator is Galerkin's `R K P` of the fine one, taken from its
    /// spectrum ([`ComplianceOperator::halved`]; nothing evaluated on the
    /// coarse grid: 1.5 s less of an isolated 4096^2 film's start, 4 s of a
    /// periodic 8192^2 one's, BENCHMARKS.md "Speed: rough contacts on large
    /// grids"); elsewhere the substrate's own kernel on the coarse grid.
    /// `None`
    /// for grids smaller than [`MULTIRESOLUTION_CELLS`], or if the coarse
    /// grid cannot resolve the substrate (a film too thin
    /// for its cells) or its solve fails: the fine solve then starts from
    /// `warm` or cold, and reports its own errors. Also the iterations
    /// spent and the factor by which the coarse levels scaled `warm`
    /// (`ContactSolver::scale_warm_start`; 1 for none).
    ///
    /// With a `warm` start the coarse solve starts from its pressures
    /// averaged over each coarse cell, and the fine start is `warm` plus
    /// the change the coarse solve made, clamped at zero: the coarse-grid
    /// correction of Brandt's full approximation scheme (1977, Math. Comp.
    /// 31, 333-390). The fine start keeps the detail of `warm` and gets the
    /// contact's new extent from the coarse grid, where the iterations that
    /// move the contact edge are cheap; started from `warm` itself, the
    /// fine solve spends its first iterations clamping the overlap ring of
    /// the new load (thousands of cells, a convolution each).
    pub(super) fn coarse_start<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        control: Control,
        warm: Option<&WarmStart>,
    ) -> Option<(WarmStart, usize, f64)> {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        if !self.params.multiresolution || rows.min(columns) < MULTIRESOLUTION_CELLS {
            return None;
        }
        let (coarse_rows, half) = (rows.div_ceil(2), columns.div_ceil(2));
        if self.coarse.is_none() {
            let params = coarse_params(&self.params);
            let boundary = self.operator.boundary();
            let built = Grid::new(coarse_rows, half, 2.0 * grid.spacing()).and_then(|g| match self
                .operator
                .slab()
            {
                // Galerkin's coarse operator from this one's spectrum where
                // the grid halves (`ComplianceOperator::halved`), else the
                // substrate's own on the coarse grid.
                None => {
                    crate::kernel::check_film(&self.substrate, &g)?;
                    match self.operator.halved(&g) {
                        Some(operator) => {
                            ContactSolver::with_operator(operator?, &self.substrate, params)
                        }
                        None => ContactSolver::new(&self.substrate, &g, boundary, params),
                    }
                }
                Some(slab) => ContactSolver::on_slab(
                    &self.substrate,
                    &g,
                    boundary,
                    params,
                    &slab.halved(rows),
                ),
            });
            // Under a fine grid too large to keep its influence
            // coefficients the coarse levels keep none either (8 bytes a
            // coarse cell). Below, they keep them: a Hertzian contact's
            // coarse solves clamp few cells, and their direct sums saved
            // about a tenth of the solve at 2048^2 (BENCHMARKS.md).
            let lean = self.operator.influence().is_none();
            let built = built.map(|mut coarse| {
                if lean {
                    coarse.operator.drop_influence();
                }
                coarse.start_level = true;
                // The level under the solve asked for keeps its
                // tolerance; those under it loosen theirs.
                coarse.loosens = self.start_level;
                coarse
            });
            // Distributed, every rank has the coarse solver or none has.
            self.coarse = Some(self.agreed(built).ok().map(Box::new));
        }
        let coarse = self.coarse.as_mut()?.as_mut()?;
        coarse.single_precision = self.single_precision;
        // The coarse cell of fine cell `c`.
        let block = |c: usize| (c / columns / 2) * half + (c % columns) / 2;
        let restricted = warm.map(|w| {
            let mut pressure = vec![0.0; coarse.local_cells()];
            for (c, p) in w.pressure.iter().enumerate() {
                pressure[block(c)] += 0.25 * p;
            }
            let attached = pressure.iter().map(|p| *p > 0.0).collect();
            WarmStart {
                pressure,
                attached,
                contact: None,
                withdrawn: false,
            }
        });
        let start = restricted.as_ref();
        // A coarse cell centre lies (rounded-up half count - half count)
        // fine cells before the centre of the fine cells it covers.
        let shift = |cells: usize| (cells.div_ceil(2) as f64 - 0.5 * cells as f64) * grid.spacing();
        let shifted = Shifted {
            inner: indenter,
            by: (shift(rows), shift(columns)),
        };
        // As a trait object: every coarser level solves with the same type.
        let indenter: &dyn Indenter = &shifted;
        // The coarse solve works in this solver's scratch vectors (idle
        // until it is done), given back after it with the values of the
        // coarse grid: the caller sizes them again
        // ([`Workspace::fit`](super::workspace::Workspace::fit)).
        coarse.workspace.restore(&mut self.workspace.lend());
        let solved = match control {
            Control::Depth(d) => coarse.solve_depth(indenter, d, start, &mut ()),
            Control::Force(w) => coarse.solve_force(indenter, w, start, &mut ()),
        };
        self.workspace.restore(&mut coarse.workspace);
        // The coarse solver keeps its kernel and plans, not its scratch,
        // while the finer solve runs.
        coarse.release_scratch();
        // The coarse solve scaled its start (the restricted warm start) to
        // the new depth's scale; the warm start's detail is scaled alike.
        let scale = coarse.warm_scale;
        let (solution, solved) = self.agreed(solved).ok()?;
        // Row by row on every thread (cell by cell, with a division for
        // each cell's coarse cell, the prolongation to a periodic 8192^2
        // grid took 1.5 s).
        let mut pressure = vec![0.0; self.local_cells()];
        crate::parallel::for_each_row(&mut pressure, columns, |i, row| {
            let coarse_row = &solved.pressure[(i / 2) * half..][..half];
            match (warm, start) {
                (Some(w), Some(r)) => {
                    let warm_row = &w.pressure[i * columns..][..columns];
                    let restricted_row = &r.pressure[(i / 2) * half..][..half];
                    for (j, (p, w)) in row.iter_mut().zip(warm_row).enumerate() {
                        let detail = w - restricted_row[j / 2];
                        *p = (scale * detail + coarse_row[j / 2]).max(0.0);
                    }
                }
                _ => {
                    for (j, p) in row.iter_mut().enumerate() {
                        *p = coarse_row[j / 2];
                    }
                }
            }
        });
        let attached = pressure.iter().map(|p| *p > 0.0).collect();
        Some((
            WarmStart {
                pressure,
                attached,
                contact: None,
                withdrawn: false,
            },
            solution.iterations + solution.coarse_iterations,
            scale,
        ))
    }
}

/// An indenter moved by `-by` (heights at `(x, y)` are the inner
/// indenter's at `(x, y) + by`).
struct Shifted<'a, I: ?Sized> {
    inner: &'a I,
    by: (f64, f64),
}

impl<I: Indenter + ?Sized> Indenter for Shifted<'_, I> {
    fn height(&self, x: f64, y: f64) -> f64 {
        self.inner.height(x + self.by.0, y + self.by.1)
    }

    fn bounding_radius(&self) -> f64 {
        self.inner.bounding_radius() + self.by.0.hypot(self.by.1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rule's three regimes, against the numbers worked by hand: a
    /// smooth contact's first change (1e-2) keeps the level's tolerance, a
    /// rough one's (0.2) gives 3 % of it, a start as far as a cold one (1)
    /// the loosest; a solve's own looser tolerance is kept.
    #[test]
    fn a_start_level_stops_at_a_fraction_of_its_first_change() {
        assert_eq!(loosened(1e-3, 1e-2), 1e-3);
        assert!((loosened(1e-3, 0.2) - 6e-3).abs() < 1e-15);
        assert_eq!(loosened(1e-3, 1.0), 1e-2);
        assert_eq!(loosened(1e-3, f64::INFINITY), 1e-2);
        assert_eq!(loosened(5e-2, 0.2), 5e-2);
    }

    /// The start level right under the solve asked for keeps its
    /// tolerance ([`COARSE_TOLERANCE`]); the levels under it loosen
    /// theirs. The tamaas problem of `benches/peers/rough.py` (seed 1),
    /// each level solved again after the solve (on the surface itself, not
    /// moved to the level's cell centres), its residual at the end: at
    /// 256^2 the 128^2 level stops at 7.3e-4 (at 1.3e-3 when it loosened
    /// its tolerance too, before 2026-12-06); at 512^2 the 128^2 level, two
    /// under the solve, at its loosened 1.6e-3.
    #[test]
    fn the_start_level_under_the_solve_keeps_its_tolerance() {
        use crate::topography::{Amplitude, SelfAffine};
        use crate::{Boundary, Material, Substrate};
        let body = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
        let params = SolverParams {
            tolerance: 1e-8,
            ..SolverParams::default()
        };
        // The residual at the end of each start level's solve, from the
        // one under the solve down.
        let levels = |n: usize| {
            let grid = Grid::square_of_side(n, 1.0).unwrap();
            let surface = SelfAffine {
                hurst: 0.8,
                amplitude: Amplitude::RmsSlope(0.1),
                long_cutoff: 0.25,
                short_cutoff: 4.0 * grid.spacing(),
                seed: 1,
            }
            .indenter(&grid)
            .unwrap();
            let mut solver = ContactSolver::new(&body, &grid, Boundary::Periodic, params).unwrap();
            solver.solve_force(&surface, 0.01, None, &mut ()).unwrap();
            let mut residuals = Vec::new();
            let mut level = solver.coarse.as_mut().and_then(|c| c.as_mut());
            while let Some(coarse) = level {
                let (solution, _) = coarse.solve_force(&surface, 0.01, None, &mut ()).unwrap();
                residuals.push(solution.residual);
                level = coarse.coarse.as_mut().and_then(|c| c.as_mut());
            }
            residuals
        };
        let small = levels(256);
        assert!(small[0] <= COARSE_TOLERANCE, "{small:?}");
        let large = levels(512);
        assert!(large[0] <= COARSE_TOLERANCE, "{large:?}");
        assert!(large[1] > COARSE_TOLERANCE, "{large:?}");
    }

    /// A count is settled when it moved by at most a thousandth of itself
    /// (counted by hand: 1 of 1000 is, 2 of 1000 is not), never in the
    /// first iteration, and an empty contact only if it stays empty; for a
    /// start level's stop by at most 3e-4 (2 of 10000 is, 4 is not).
    #[test]
    fn a_count_settles_within_a_thousandth() {
        assert!(count_settled(Some(1000), 1001));
        assert!(count_settled(Some(1000), 999));
        assert!(!count_settled(Some(1000), 1002));
        assert!(!count_settled(Some(1000), 998));
        assert!(!count_settled(None, 1000));
        assert!(count_settled(Some(0), 0));
        assert!(!count_settled(Some(0), 1));
        assert!(start_count_settled(Some(10000), 10002));
        assert!(start_count_settled(Some(10000), 9998));
        assert!(!start_count_settled(Some(10000), 10004));
        assert!(!start_count_settled(Some(1000), 1001));
        assert!(!start_count_settled(None, 0));
    }
}
