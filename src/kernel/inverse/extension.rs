//! The residual carried one cell past the working set's edges before the
//! box inverse, and the transpose of that after it.
//!
//! The exact preconditioner of the constrained conjugate gradients is the
//! inverse of the compliance restricted to the working set `C`. It is the
//! Schur complement of the stiffness `K^-1`: `E^T K^-1 E`, where `E`
//! extends a displacement given on `C` by the one that costs the least
//! elastic energy (the surface's displacement where no pressure acts
//! outside `C`). Vollebregt's box inverse (2014, J. Comput. Phys. 257,
//! 333) extends by zero, which leaves a jump at every edge of the set,
//! and a rough contact is mostly edges. Here `E` also sets each cell
//! outside the set to a quarter of the sum of its set neighbours' values
//! (one sweep of the four-neighbour mean, the set's cells held): for any
//! such `E`, `E^T K^-1 E` is symmetric and positive definite. The sweep
//! stays within the grid and the box's data; on a periodic grid it does
//! not wrap round (any linear `E` will do). On the rough film of
//! `BENCHMARKS.md` it took 22, 26 and 34 fine iterations at 512^2, 1024^2
//! and 2048^2 to 17, 20 and 25 ("The box inverse past the contact's
//! edges"; `benches/rough/edge_extension.py` measures wider extensions).
//!
//! Both directions work on one row at a time with the rows above and
//! below: rows of this rank, or those of the neighbouring ranks exchanged
//! beforehand ([`edge_rows`]), so that split runs apply the same operator.

use std::ops::Range;

use num_complex::Complex;

use crate::slab::Slab;

use super::super::convolution::Precision;

/// The weight of a set neighbour's value in a cell outside the set: the
/// four-neighbour mean.
const WEIGHT: f64 = 0.25;

/// Rows of a piece of work of [`Band::gather`], which runs in place.
const GATHER_ROWS: usize = 32;

/// A row over the box's columns: which cells are members, and the values
/// (the residual before the box inverse, its output after). A row that is
/// not the box's is a blank one (no members, zeros), so that every row has
/// two neighbours and the passes run without a branch per cell.
#[derive(Clone, Copy)]
pub(super) struct Row<'a> {
    member: &'a [bool],
    values: &'a [f64],
}

/// A row of another rank, or a copy of one of this rank's.
pub(super) struct OwnedRow {
    member: Vec<bool>,
    values: Vec<f64>,
}

impl OwnedRow {
    fn row(&self) -> Row<'_> {
        Row {
            member: &self.member,
            values: &self.values,
        }
    }
}

/// `value` where `keep`, else zero: a select the compiler makes without a
/// branch per cell (members lie at random in a rough contact), and never
/// `0 * value` (a gap off the indenter is infinite).
#[inline(always)]
fn masked(keep: bool, value: f64) -> f64 {
    if keep {
        value
    } else {
        0.0
    }
}

/// `row` cut to `n` cells.
fn cut(row: Row<'_>, n: usize) -> (&[bool], &[f64]) {
    (&row.member[..n], &row.values[..n])
}

/// `line = E (r - shift) scale` on one row: the members' residual less
/// `shift`, and next to them (the row's other cells, with `above` and
/// `below`) the extension; all scaled by `scale` into `T`.
fn spread<T: Precision>(
    line: &mut [T],
    this: Row<'_>,
    [a, b]: [Row<'_>; 2],
    shift: f64,
    scale: f64,
) {
    let n = line.len();
    // Every row cut to the line's length: the loop then checks no index.
    let ((m, r), (ma, ra), (mb, rb)) = (cut(this, n), cut(a, n), cut(b, n));
    let value = |m: bool, r: f64| masked(m, r - shift);
    // The row's own neighbours, a window sliding along it.
    let (mut left, mut here) = (0.0, if n > 0 { value(m[0], r[0]) } else { 0.0 });
    for j in 0..n {
        let right = if j + 1 < n {
            value(m[j + 1], r[j + 1])
        } else {
            0.0
        };
        let sum = left + right + value(ma[j], ra[j]) + value(mb[j], rb[j]);
        line[j] = T::narrow(if m[j] { here } else { WEIGHT * sum } * scale);
        (left, here) = (here, right);
    }
}

/// `E^T` on one row in place (`row`, its members `member`): each member's
/// output plus a quarter of its non-member neighbours' (in the row, and in
/// `a` and `b`); the other cells keep theirs. Returns `(sum z, sum z (r -
/// shift))` over the members, in four lanes (cell `j` in lane `j % 4`)
/// added in a fixed order: four chains of additions instead of one.
fn gather(
    row: &mut [f64],
    member: &[bool],
    residual: &[f64],
    [a, b]: [Row<'_>; 2],
    shift: f64,
) -> (f64, f64) {
    let n = row.len();
    // Every row cut to this one's length: the loop then checks no index.
    let (member, residual) = (&member[..n], &residual[..n]);
    let ((ma, ya), (mb, yb)) = (cut(a, n), cut(b, n));
    let mut lanes = [[0.0; 2]; 4];
    // A member's neighbour in the row is read before it is written only
    // where it is not a member, and those keep their values.
    for j in 0..n {
        let left = if j > 0 {
            masked(!member[j - 1], row[j - 1])
        } else {
            0.0
        };
        let right = if j + 1 < n {
            masked(!member[j + 1], row[j + 1])
        } else {
            0.0
        };
        let m = member[j];
        let z = row[j]
            + masked(
                m,
                WEIGHT * (left + right + masked(!ma[j], ya[j]) + masked(!mb[j], yb[j])),
            );
        row[j] = z;
        let lane = &mut lanes[j % 4];
        lane[0] += masked(m, z);
        lane[1] += masked(m, z * (residual[j] - shift));
    }
    let total = |k: usize| (lanes[0][k] + lanes[1][k]) + (lanes[2][k] + lanes[3][k]);
    (total(0), total(1))
}

/// This rank's rows of a grid and where a box lies on them.
pub(super) struct Band<'a> {
    /// Which of this rank's cells are members.
    pub(super) member: &'a [bool],
    pub(super) columns: usize,
    /// The box's columns on the grid.
    pub(super) cells: Range<usize>,
    /// The (global) grid row of this rank's first row, and its rows.
    pub(super) start: usize,
    pub(super) local: usize,
    /// The (global) grid rows of the box.
    pub(super) box_rows: Range<usize>,
    /// A row of no members and zeros, the box's width.
    pub(super) blank: OwnedRow,
}

/// The rows just above and below a band, from its neighbouring ranks.
pub(super) type Edges = (Option<OwnedRow>, Option<OwnedRow>);

impl<'a> Band<'a> {
    /// The band of `member` (this rank's rows, `columns` wide) whose box
    /// covers `cells` and the (global) grid rows `box_rows`.
    pub(super) fn new(
        member: &'a [bool],
        columns: usize,
        cells: Range<usize>,
        (start, local): (usize, usize),
        box_rows: Range<usize>,
    ) -> Self {
        let blank = OwnedRow {
            member: vec![false; cells.len()],
            values: vec![0.0; cells.len()],
        };
        Band {
            member,
            columns,
            cells,
            start,
            local,
            box_rows,
            blank,
        }
    }

    /// Local row `i` of `values`.
    fn row<'b>(&self, values: &'b [f64], i: usize) -> Row<'b>
    where
        'a: 'b,
    {
        Row {
            member: self.members(i),
            values: &values[i * self.columns..][self.cells.clone()],
        }
    }

    /// Local row `i`'s members.
    fn members(&self, i: usize) -> &'a [bool] {
        &self.member[i * self.columns..][self.cells.clone()]
    }

    /// Whether local row `i` (or the one past either end of the band) is
    /// one of the box's.
    fn boxed(&self, i: isize) -> bool {
        let g = self.start as isize + i;
        g >= 0 && self.box_rows.contains(&(g as usize))
    }

    /// Distributed, the rows next to this band from the neighbouring ranks:
    /// each rank sends its first and last rows of `values` (members and
    /// values; blank off the box); serial, none. Every rank must call it.
    pub(super) fn edges(&self, slab: Option<&Slab>, values: &[f64]) -> Edges {
        let Some(slab) = slab else {
            return (None, None);
        };
        let end = |i: usize| {
            if self.local > 0 && self.boxed(i as isize) {
                self.row(values, i)
            } else {
                self.blank.row()
            }
        };
        edge_rows(slab, end(0), end(self.local.saturating_sub(1)))
    }

    /// The box's rows next to local row `i`: rows of `values` on this rank
    /// or, past the band, the `edges` from its neighbours; blank if not
    /// the box's.
    fn neighbours<'b>(&'b self, i: usize, values: &'b [f64], edges: &'b Edges) -> [Row<'b>; 2] {
        let past =
            |edge: &'b Option<OwnedRow>| edge.as_ref().map_or(self.blank.row(), OwnedRow::row);
        let up = if !self.boxed(i as isize - 1) {
            self.blank.row()
        } else if i > 0 {
            self.row(values, i - 1)
        } else {
            past(&edges.0)
        };
        let down = if !self.boxed(i as isize + 1) {
            self.blank.row()
        } else if i + 1 < self.local {
            self.row(values, i + 1)
        } else {
            past(&edges.1)
        };
        [up, down]
    }

    /// `E (r - shift) scale` on local row `i` into `line` (the box's
    /// columns), `edges` the residual's rows past the band.
    pub(super) fn spread<T: Precision>(
        &self,
        line: &mut [T],
        i: usize,
        residual: &[f64],
        edges: &Edges,
        (shift, scale): (f64, f64),
    ) {
        let next = self.neighbours(i, residual, edges);
        spread(line, self.row(residual, i), next, shift, scale);
    }

    /// `E^T` on the band's rows of the box, in place in `output` (the box
    /// inverse's output on every box cell), `edges` its rows past the
    /// band. Runs in pieces of [`GATHER_ROWS`] rows on all threads: a
    /// piece changes only its members and reads only non-members of the
    /// rows next to it, copied first. Returns `(sum z, sum z (r - shift))`
    /// over the members, added row by row in order.
    pub(super) fn gather(
        &self,
        output: &mut [f64],
        residual: &[f64],
        edges: &Edges,
        shift: f64,
    ) -> (f64, f64) {
        let boxed = |&i: &usize| self.boxed(i as isize);
        let (Some(first), Some(last)) = ((0..self.local).find(boxed), (0..self.local).rfind(boxed))
        else {
            return (0.0, 0.0);
        };
        let end = last + 1;
        let columns = self.columns;
        let copy = |row: Row<'_>| OwnedRow {
            member: row.member.to_vec(),
            values: row.values.to_vec(),
        };
        // Each piece's rows above and below it.
        let copies: Vec<[OwnedRow; 2]> = (first..end)
            .step_by(GATHER_ROWS)
            .map(|s| {
                let e = (s + GATHER_ROWS).min(end);
                [
                    copy(self.neighbours(s, output, edges)[0]),
                    copy(self.neighbours(e - 1, output, edges)[1]),
                ]
            })
            .collect();
        let sums = crate::parallel::map_rows(
            &mut output[first * columns..end * columns],
            GATHER_ROWS * columns,
            |piece, values| {
                let start = first + piece * GATHER_ROWS;
                let [above, below] = &copies[piece];
                let count = values.len() / columns;
                (0..count)
                    .map(|r| {
                        let i = start + r;
                        let (head, rest) = values.split_at_mut(r * columns);
                        let (current, tail) = rest.split_at_mut(columns);
                        // The piece's own rows, `head` above and `tail`
                        // below (indexed from the piece's start).
                        let up = if r > 0 {
                            Row {
                                member: self.members(i - 1),
                                values: &head[(r - 1) * columns..][self.cells.clone()],
                            }
                        } else {
                            above.row()
                        };
                        let down = if r + 1 < count {
                            Row {
                                member: self.members(i + 1),
                                values: &tail[..columns][self.cells.clone()],
                            }
                        } else {
                            below.row()
                        };
                        let this = self.row(residual, i);
                        gather(
                            &mut current[self.cells.clone()],
                            this.member,
                            this.values,
                            [up, down],
                            shift,
                        )
                    })
                    .collect::<Vec<_>>()
            },
        );
        sums.into_iter()
            .flatten()
            .fold((0.0, 0.0), |(s, d), (a, b)| (s + a, d + b))
    }
}

/// The row just above this rank's band and the one just below it, from the
/// ranks before and after: each rank sends `first` (its band's first row)
/// to the rank before and `last` to the rank after, its members as ones
/// and zeros beside the values. Every rank must call it, with rows of the
/// same length.
fn edge_rows(slab: &Slab, first: Row<'_>, last: Row<'_>) -> Edges {
    let (rank, ranks) = (slab.exchange.rank(), slab.exchange.ranks());
    let n = first.values.len();
    let pack = |row: Row<'_>| -> Vec<Complex<f64>> {
        row.values
            .iter()
            .zip(row.member)
            .map(|(&v, &m)| Complex::new(v, f64::from(u8::from(m))))
            .collect()
    };
    let mut send = Vec::with_capacity(2 * n);
    let mut send_counts = vec![0; ranks];
    let mut receive_counts = vec![0; ranks];
    if rank > 0 {
        send.extend(pack(first));
        send_counts[rank - 1] = n;
        receive_counts[rank - 1] = n;
    }
    if rank + 1 < ranks {
        send.extend(pack(last));
        send_counts[rank + 1] = n;
        receive_counts[rank + 1] = n;
    }
    let mut receive = vec![Complex::new(0.0, 0.0); receive_counts.iter().sum()];
    slab.exchange
        .all_to_all(&send, &send_counts, &mut receive, &receive_counts);
    let unpack = |values: &[Complex<f64>]| OwnedRow {
        member: values.iter().map(|c| c.im != 0.0).collect(),
        values: values.iter().map(|c| c.re).collect(),
    };
    let above = (rank > 0).then(|| unpack(&receive[..n]));
    let below = (rank + 1 < ranks).then(|| unpack(&receive[receive.len() - n..]));
    (above, below)
}

#[cfg(test)]
mod tests;
