//! Which sets a family may hold on a periodic grid, and the connectivity
//! of a set: a set must not meet its periodic images across its edge, where
//! the energy balance is undefined, but the contact of a surface that is
//! invariant along a direction of the grid (a wavy surface, crests along
//! the grid, at 45 degrees or two cells by one) is a strip that meets its
//! own images along that direction by nature.

use crate::error::Error;
use crate::solver::ContactSolver;

/// The lattice translations (rows, columns) along which a periodic profile
/// may be invariant: along the grid, its diagonals, and the directions two
/// cells by one.
const STRIP_DIRECTIONS: [(usize, isize); 8] = [
    (0, 1),
    (1, 0),
    (1, 1),
    (1, -1),
    (1, 2),
    (2, 1),
    (1, -2),
    (2, -1),
];

impl ContactSolver {
    /// How many of the first `top` cells of `order` the family may use: on
    /// an isolated grid it stops before the first cell on the grid's outer
    /// ring (an isolated contact must stay off the edge); on a periodic grid
    /// before the first cell that would make a set span more than half the
    /// period along a row or a column (measured from the family's first
    /// cell across the periodic boundary), so that no set meets its images;
    /// for strips (`strip`, the tolerance of
    /// [`strip_tolerance`](Self::strip_tolerance)), at half the period's
    /// area, at the end of a line. Also says whether `top` was
    /// kept.
    pub(super) fn usable_prefix(
        &self,
        order: &[(usize, f64)],
        top: usize,
        strip: Option<f64>,
    ) -> (usize, bool) {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let first = match (self.operator.boundary(), strip) {
            (crate::grid::Boundary::Isolated, _) => order[..top]
                .iter()
                .position(|&(c, _)| crate::solver::on_outer_ring(c, rows, columns)),
            (crate::grid::Boundary::Periodic, Some(tolerance)) => {
                // Strips: at most half the period's area, ending where a
                // height ends (a whole strip).
                let half = grid.len() / 2;
                (top > half).then(|| {
                    let profile = &self.workspace.profile;
                    let mut end = half;
                    while end > 0
                        && (profile[order[end].0] - profile[order[end - 1].0]).abs() <= tolerance
                    {
                        end -= 1;
                    }
                    end
                })
            }
            (crate::grid::Boundary::Periodic, None) => {
                let start = order.first().map_or(0, |&(c, _)| c);
                let mut span = Span::new(start, rows, columns);
                order[..top].iter().position(|&(c, _)| !span.include(c))
            }
        };
        match first {
            Some(first) => (first, false),
            None => (top, true),
        }
    }

    /// Whether the sampled profile on a periodic grid is invariant along a
    /// direction of [`STRIP_DIRECTIONS`] (to `1e-9` of its range, the
    /// tolerance returned: heights closer than it are one line): its
    /// contact sets are then strips across the period.
    pub(super) fn strip_tolerance(&self) -> Option<f64> {
        if self.operator.boundary() != crate::grid::Boundary::Periodic {
            return None;
        }
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let profile = &self.workspace.profile;
        let (low, high) = profile
            .iter()
            .filter(|f| f.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &f| {
                (l.min(f), h.max(f))
            });
        if high < low {
            return None;
        }
        let tolerance = 1e-9 * (high - low).max(f64::MIN_POSITIVE);
        let invariant = STRIP_DIRECTIONS.iter().any(|&(di, dj)| {
            (0..profile.len()).all(|c| {
                let (i, j) = (c / columns, c % columns);
                let m = ((i + di) % rows) * columns
                    + (j as isize + dj).rem_euclid(columns as isize) as usize;
                let (a, b) = (profile[c], profile[m]);
                a == b || (a - b).abs() <= tolerance
            })
        });
        invariant.then_some(tolerance)
    }

    /// Heights of the sampled profile closer than `tolerance` (a strip's,
    /// [`strip_tolerance`](Self::strip_tolerance)) made equal: each to the
    /// lowest of its group, walking up from the lowest point. A strip
    /// sampled at cell centres that do not lie on its lines exactly (a
    /// wave along a diagonal, or a map carrying rounding) has lines whose
    /// cells differ by rounding; the family's sets, ties and shape
    /// problems would read that rounding as heights (on Johnson's sinusoid
    /// along the diagonal at `alpha = 0.02`, a pull-off 4.3 times the
    /// exact one, where the same wave along the grid is refused).
    pub(super) fn snap_strip_lines(&mut self, tolerance: f64) {
        let profile = &mut self.workspace.profile;
        let mut finite: Vec<usize> = (0..profile.len())
            .filter(|&c| profile[c].is_finite())
            .collect();
        finite.sort_by(|&a, &b| profile[a].total_cmp(&profile[b]));
        let mut anchor = f64::NEG_INFINITY;
        for c in finite {
            if profile[c] - anchor <= tolerance {
                profile[c] = anchor;
            } else {
                anchor = profile[c];
            }
        }
    }

    /// The area of one line of cells of a strip family (m^2): a row or a
    /// column of the grid, the longer (exact for lines along the grid and,
    /// on square grids, along its diagonals and two cells by one).
    pub(super) fn line_area(&self) -> f64 {
        let grid = *self.grid();
        grid.rows().max(grid.columns()) as f64 * grid.cell_area()
    }
}

/// The 4-neighbours of cell `c`, wrapping round a periodic grid.
pub(super) use crate::solver::wrapped_neighbours as neighbours;

/// The error of a periodic family whose sets would span more than half the
/// period.
pub(super) fn half_period_error() -> Error {
    Error::Unsupported {
        feature: "the energy-balance adhesion method for a contact wider than half the period",
        reason: "its contact sets would meet their periodic images, where the balance \
                 is undefined; use the mesh-dependent criterion or a wider period",
    }
}

/// The rows and columns a growing set spans on a periodic grid, as offsets
/// from its first cell taken the short way round.
struct Span {
    start: (usize, usize),
    shape: (usize, usize),
    rows: (isize, isize),
    columns: (isize, isize),
}

impl Span {
    fn new(start: usize, rows: usize, columns: usize) -> Self {
        Span {
            start: (start / columns, start % columns),
            shape: (rows, columns),
            rows: (0, 0),
            columns: (0, 0),
        }
    }

    /// Adds cell `c`; false if the set would then span more than half the
    /// period in either direction.
    fn include(&mut self, c: usize) -> bool {
        let offset = |index: usize, start: usize, period: usize| {
            let forward = (index + period - start) % period;
            if 2 * forward > period {
                forward as isize - period as isize
            } else {
                forward as isize
            }
        };
        let (rows, columns) = self.shape;
        let di = offset(c / columns, self.start.0, rows);
        let dj = offset(c % columns, self.start.1, columns);
        self.rows = (self.rows.0.min(di), self.rows.1.max(di));
        self.columns = (self.columns.0.min(dj), self.columns.1.max(dj));
        let within = |(lo, hi): (isize, isize), period: usize| 2 * (hi - lo + 1) as usize <= period;
        within(self.rows, rows) && within(self.columns, columns)
    }
}

/// Whether the first `m` cells of the family (marked in `attached`) form
/// one patch containing `start`: 4-connected, or 8-connected for the
/// strips of a surface invariant along a diagonal (a line of cells at 45
/// degrees touches only at corners); across the edges of a periodic grid if
/// `periodic`.
pub(super) fn connected(
    attached: &[bool],
    columns: usize,
    periodic: bool,
    corners: bool,
    start: usize,
    m: usize,
) -> bool {
    let n = attached.len();
    let rows = n / columns;
    let mut seen = vec![false; n];
    let mut stack = vec![start];
    seen[start] = true;
    let mut count = 0usize;
    while let Some(c) = stack.pop() {
        count += 1;
        let sides = neighbours(c, rows, columns, periodic);
        let diagonals = if corners {
            let [up, down, _, _] = sides;
            let beside = |row: Option<usize>| {
                row.map_or([None, None], |r| {
                    let [_, _, left, right] = neighbours(r, rows, columns, periodic);
                    [left, right]
                })
            };
            let ([a, b], [d, e]) = (beside(up), beside(down));
            [a, b, d, e]
        } else {
            [None; 4]
        };
        for m in sides.into_iter().chain(diagonals).flatten() {
            if attached[m] && !seen[m] {
                seen[m] = true;
                stack.push(m);
            }
        }
    }
    count == m
}
