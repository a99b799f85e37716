//! Whether the contact sets of an energy-balance family are digital discs,
//! about the grid's axis or about the apex of a paraboloid anywhere on the
//! grid: then every set is the contact of an axisymmetric indenter (about
//! its own axis) and the edge-averaged balance is the exact JKR one.

use crate::solver::ContactSolver;

impl ContactSolver {
    /// Whether the family's sets (`order`, sorted by height, then distance
    /// from the grid's axis) are digital discs about the grid's axis, or
    /// about the apex of the profile read from the lowest cell's
    /// neighbours (a paraboloid moved off the axis, as a tilted one is).
    pub(super) fn family_is_discs(&self, order: &[(usize, f64)]) -> bool {
        self.discs_about(order, (0.0, 0.0))
            || self
                .paraboloid_apex(order)
                .is_some_and(|apex| self.discs_about(order, apex))
    }

    /// Along `order` the distance from `centre` never decreases, cells at
    /// the same distance have the same height, and every cell of the grid
    /// as near `centre` as the family's farthest belongs to it (a disc
    /// clipped by the indenter's footprint, a flat punch that is not round,
    /// is not a disc).
    fn discs_about(&self, order: &[(usize, f64)], centre: (f64, f64)) -> bool {
        let grid = *self.grid();
        let columns = grid.columns();
        let delta2 = grid.cell_area();
        let profile = &self.workspace.profile;
        let distance = |c: usize| {
            let (x, y) = grid.cell_centre(c / columns, c % columns);
            (x - centre.0).powi(2) + (y - centre.1).powi(2)
        };
        // The family holds only finite heights, sorted: the first is the
        // lowest and the last the highest.
        let range = match (order.first(), order.last()) {
            (Some(&(low, _)), Some(&(high, _))) => profile[high] - profile[low],
            _ => return true,
        };
        let tolerance = 1e-9 * range.max(f64::MIN_POSITIVE);
        let farthest = order.iter().map(|&(c, _)| distance(c)).fold(0.0, f64::max);
        let within = (0..grid.len()).filter(|&c| distance(c) <= farthest).count();
        if within != order.len() {
            return false;
        }
        order.windows(2).all(|w| {
            let ((a, _), (b, _)) = (w[0], w[1]);
            let (ra, rb) = (distance(a), distance(b));
            if (rb - ra).abs() <= 1e-9 * delta2 {
                (profile[b] - profile[a]).abs() <= tolerance
            } else {
                rb > ra
            }
        })
    }

    /// The apex of a paraboloid `k r^2 + b x + c y + a` through the lowest
    /// cell of `order` and its four neighbours (central differences, exact
    /// for a paraboloid), if the two second differences agree and are
    /// positive; else `None`.
    fn paraboloid_apex(&self, order: &[(usize, f64)]) -> Option<(f64, f64)> {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let delta = grid.spacing();
        let profile = &self.workspace.profile;
        let &(lowest, _) = order.first()?;
        let (i, j) = (lowest / columns, lowest % columns);
        if !(1..rows - 1).contains(&i) || !(1..columns - 1).contains(&j) {
            return None;
        }
        let h = |di: isize, dj: isize| {
            let cell = (i as isize + di) as usize * columns + (j as isize + dj) as usize;
            profile[cell]
        };
        let (centre, up, down, left, right) = (h(0, 0), h(-1, 0), h(1, 0), h(0, -1), h(0, 1));
        if ![centre, up, down, left, right]
            .iter()
            .all(|v| v.is_finite())
        {
            return None;
        }
        // Second differences: 2 k delta^2 along both axes.
        let (along_x, along_y) = (up + down - 2.0 * centre, left + right - 2.0 * centre);
        let curvature = 0.5 * (along_x + along_y);
        // The heights are finite here, so the comparisons are too.
        if curvature <= 0.0 || (along_x - along_y).abs() > 1e-6 * curvature {
            return None;
        }
        let (x, y) = grid.cell_centre(i, j);
        // The slope at the cell, 2 k (x - x0), over 2 k.
        let apex = (
            x - delta * 0.5 * (down - up) / curvature,
            y - delta * 0.5 * (right - left) / curvature,
        );
        (apex.0.is_finite() && apex.1.is_finite()).then_some(apex)
    }
}
