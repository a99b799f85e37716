//! The patches of a contact: how many cells across the widest is (the
//! measure of whether a cohesive zone
//! ([`CohesiveZone`](super::CohesiveZone)) of a few cells resolves a
//! pull-off contact), and how many there are (whether the active-set loops
//! may help, [`active_set`](super::active_set)).

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

/// The patches of a set of cells (joined through their four neighbours),
/// found into buffers kept between searches: their cells one after the
/// other in `order`, each patch ending at the next of `ends`.
#[derive(Debug, Default)]
pub(crate) struct Patches {
    pub(crate) order: Vec<usize>,
    pub(crate) ends: Vec<usize>,
    /// The cells the search has reached.
    seen: Vec<bool>,
}

impl Patches {
    /// The patches of `set` (row-major on `rows x columns` cells, wrapping
    /// round if `periodic`), each from its first cell in row-major order,
    /// breadth first; the search stops after `most` patches.
    pub(crate) fn find(
        &mut self,
        set: &[bool],
        (rows, columns): (usize, usize),
        periodic: bool,
        most: usize,
    ) {
        let n = (rows * columns).min(set.len());
        self.order.clear();
        self.ends.clear();
        self.seen.clear();
        self.seen.resize(n, false);
        for first in 0..n {
            if self.ends.len() >= most {
                break;
            }
            if !set[first] || self.seen[first] {
                continue;
            }
            self.seen[first] = true;
            let mut next = self.order.len();
            self.order.push(first);
            while next < self.order.len() {
                let c = self.order[next];
                next += 1;
                for m in super::wrapped_neighbours(c, rows, columns, periodic)
                    .into_iter()
                    .flatten()
                {
                    if m < n && set[m] && !self.seen[m] {
                        self.seen[m] = true;
                        self.order.push(m);
                    }
                }
            }
            self.ends.push(self.order.len());
        }
    }
}

/// How many patches `set` (row-major on `rows x columns` cells, wrapping
/// round if `periodic`) has, cells joined through their four neighbours;
/// the count stops once it passes `most` (it returns `most + 1` then).
pub(crate) fn patch_count_past(
    set: &[bool],
    rows: usize,
    columns: usize,
    periodic: bool,
    most: usize,
) -> usize {
    let mut patches = Patches::default();
    patches.find(set, (rows, columns), periodic, most.saturating_add(1));
    patches.ends.len()
}

#[cfg(test)]
mod tests {
    use super::{patch_count_past, widest_patch_cells};

    /// Counted by hand: a disc is one patch, a ring one, a chessboard's
    /// black cells `n^2 / 2` (no two share a side), four corner cells four
    /// on an isolated grid and one where the grid wraps round; the count
    /// stops one past `most`.
    #[test]
    fn patches_are_counted_through_their_four_neighbours() {
        let n = 16;
        let disc = cells(n, |i, j| (i - 8).pow(2) + (j - 8).pow(2) <= 20);
        assert_eq!(patch_count_past(&disc, n, n, false, 10), 1);
        let ring = cells(n, |i, j| {
            (12..=30).contains(&((i - 8).pow(2) + (j - 8).pow(2)))
        });
        assert_eq!(patch_count_past(&ring, n, n, false, 10), 1);
        let board = cells(n, |i, j| (i + j) % 2 == 0);
        assert_eq!(patch_count_past(&board, n, n, false, 1000), 128);
        assert_eq!(patch_count_past(&board, n, n, false, 10), 11);
        let last = n as isize - 1;
        let corners = cells(n, |i, j| (i == 0 || i == last) && (j == 0 || j == last));
        assert_eq!(patch_count_past(&corners, n, n, false, 10), 4);
        assert_eq!(patch_count_past(&corners, n, n, true, 10), 1);
        assert_eq!(patch_count_past(&vec![false; n * n], n, n, true, 10), 0);
    }

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
