//! How many cells across the widest patch of a contact is: the measure of
//! whether a cohesive zone ([`CohesiveZone`](super::CohesiveZone)) of a
//! few cells resolves a pull-off contact.

use std::collections::VecDeque;

/// The widest patch of `set` (row-major on `rows x columns` cells,
/// wrapping round if `periodic`) in cells across: `2 d - 1`, `d` the most
/// 4-neighbour steps from a cell of the set to the nearest cell outside it
/// (off an isolated grid counts as outside). A disc `n` cells across gives
/// about `n`, a strip `w` lines of cells wide (along the grid or a
/// diagonal) `w` (`w - 1` for even `w`). Zero for an empty set; the
/// grid's shorter side for a set that fills a periodic grid.
pub(crate) fn widest_patch_cells(set: &[bool], rows: usize, columns: usize, periodic: bool) -> f64 {
    let n = (rows * columns).min(set.len());
    let mut steps = vec![0usize; n];
    let mut queue = VecDeque::new();
    // The set's cells next to a cell outside it (or the grid's edge).
    for c in 0..n {
        if !set[c] {
            continue;
        }
        let around = super::wrapped_neighbours(c, rows, columns, periodic);
        if around.iter().any(|m| m.is_none_or(|m| m >= n || !set[m])) {
            steps[c] = 1;
            queue.push_back(c);
        }
    }
    if queue.is_empty() {
        return if set[..n].iter().any(|&s| s) {
            rows.min(columns) as f64
        } else {
            0.0
        };
    }
    // Breadth first inwards: each cell is queued once.
    let mut deepest = 1;
    while let Some(c) = queue.pop_front() {
        deepest = deepest.max(steps[c]);
        for m in super::wrapped_neighbours(c, rows, columns, periodic)
            .into_iter()
            .flatten()
        {
            if m < n && set[m] && steps[m] == 0 {
                steps[m] = steps[c] + 1;
                queue.push_back(m);
            }
        }
    }
    (2 * deepest - 1) as f64
}

#[cfg(test)]
mod tests {
    use super::widest_patch_cells;

    /// The cells of an `n x n` grid where `inside(i, j)` holds.
    fn cells(n: usize, inside: impl Fn(isize, isize) -> bool) -> Vec<bool> {
        (0..n * n)
            .map(|c| inside((c / n) as isize, (c % n) as isize))
            .collect()
    }

    #[test]
    fn strips_and_discs_measure_their_width() {
        let n = 32;
        // Strips of 1 to 7 lines along the grid and along its diagonal, on
        // a periodic grid: odd widths exactly, even ones one less.
        for w in 1..8isize {
            let along = cells(n, |_, j| j < w);
            let diagonal = cells(n, |i, j| (i + j).rem_euclid(n as isize) < w);
            let expected = (w - 1 + w % 2) as f64;
            assert_eq!(widest_patch_cells(&along, n, n, true), expected);
            assert_eq!(widest_patch_cells(&diagonal, n, n, true), expected);
        }
        // A digital disc of radius 6.5 cells (13 across) on an isolated
        // grid: its centre row's 13 cells, 7 steps from the centre to
        // outside along the axes.
        let disc = cells(n, |i, j| (i - 16).pow(2) + (j - 16).pow(2) <= 42);
        assert_eq!(widest_patch_cells(&disc, n, n, false), 13.0);
        // Nothing, and everything on a periodic grid.
        assert_eq!(widest_patch_cells(&vec![false; n * n], n, n, true), 0.0);
        assert_eq!(widest_patch_cells(&vec![true; n * n], n, n, true), 32.0);
        // Everything on an isolated grid: the edge is outside.
        assert_eq!(widest_patch_cells(&[true; 25], 5, 5, false), 5.0);
    }
}
