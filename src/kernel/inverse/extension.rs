//! The residual carried one cell past the working set's edges before the
//! box inverse, and the transpose of that after it.
//!
//! The exact preconditioner of the constrained conjugate gradients is the
//! inverse of the compliance restricted to the working set `C`. It is the
//! Schur complement of the stiffness `K^-1`: `E^T K^-1 E`, where `E`
//! extends a displacement given on `C` by the one that costs the least
//! elastic energy (the surface's displacement where no pressure acts
//! outside `C`). Vollebregt's box inverse (2014, J. Comput. Phys. 257,
//! 333) extends by zero, which leaves a jump at every edge of the set; a
//! rough contact is mostly edges, and the jump's cost grows with the
//! number of scales the surface resolves. Here `E` also sets each cell
//! outside the set to a quarter of the sum of its set neighbours' values
//! (one sweep of the four-neighbour mean, the set's cells held): for any
//! such `E`, `E^T K^-1 E` is symmetric and positive definite, and closer to
//! the exact inverse than the zero extension. On the rough film of
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

/// Copies of the rows above and below a piece of [`Band::gather`], where
/// they are the box's.
type Beside = (Option<Vec<f64>>, Option<Vec<f64>>);

/// A row next to the one worked on, over the box's columns.
#[derive(Clone, Copy)]
pub(super) enum Row<'a> {
    /// A row of this rank: its members and values (the residual before the
    /// box inverse, its output after).
    Local {
        member: &'a [bool],
        values: &'a [f64],
    },
    /// A row of another rank, already reduced to what the other side
    /// reads: the members' residual less the shift (zero elsewhere) before
    /// the box inverse, the other cells' output (zero at members) after.
    Edge(&'a [f64]),
}

impl Row<'_> {
    /// The box inverse's output at column `j` if not a member, else zero.
    fn outside_value(&self, j: usize) -> f64 {
        match *self {
            Row::Local { member, values } if !member[j] => values[j],
            Row::Local { .. } => 0.0,
            Row::Edge(values) => values[j],
        }
    }
}

/// `line = E (r - shift) scale` on one row: the members' residual less
/// `shift`, and next to them (the row's other cells, with `above` and
/// `below`) the extension; all scaled by `scale` into `T`.
fn spread<T: Precision>(
    line: &mut [T],
    member: &[bool],
    residual: &[f64],
    (above, below): (Option<Row<'_>>, Option<Row<'_>>),
    shift: f64,
    scale: f64,
) {
    let n = line.len();
    // The members' values of the rows above and below, summed column by
    // column (a loop per kind of row, not a match per cell).
    let mut vertical = vec![0.0; n];
    for row in [above, below].into_iter().flatten() {
        match row {
            Row::Local { member, values } => {
                for ((v, &m), &r) in vertical.iter_mut().zip(member).zip(values) {
                    if m {
                        *v += r - shift;
                    }
                }
            }
            Row::Edge(values) => {
                for (v, &r) in vertical.iter_mut().zip(values) {
                    *v += r;
                }
            }
        }
    }
    let value = |j: usize| if member[j] { residual[j] - shift } else { 0.0 };
    // The row's own neighbours, a window sliding along it.
    let (mut left, mut here) = (0.0, if n > 0 { value(0) } else { 0.0 });
    for (j, out) in line.iter_mut().enumerate() {
        let right = if j + 1 < n { value(j + 1) } else { 0.0 };
        let sum = left + right + vertical[j];
        *out = if member[j] {
            T::narrow(here * scale)
        } else if sum == 0.0 {
            T::zero()
        } else {
            T::narrow(WEIGHT * sum * scale)
        };
        (left, here) = (here, right);
    }
}

/// `E^T` on one row in place: each member's output plus a quarter of its
/// non-member neighbours' (in the row, and in `above` and `below`). Returns
/// `(sum z, sum z (r - shift))` over the members.
fn gather(
    row: &mut [f64],
    member: &[bool],
    residual: &[f64],
    (above, below): (Option<Row<'_>>, Option<Row<'_>>),
    shift: f64,
) -> (f64, f64) {
    let n = row.len();
    let mut sums = (0.0, 0.0);
    for j in 0..n {
        if !member[j] {
            continue;
        }
        // The row's own neighbours are read before being written only at
        // members, which are never read here.
        let mut sum = 0.0;
        if j > 0 && !member[j - 1] {
            sum += row[j - 1];
        }
        if j + 1 < n && !member[j + 1] {
            sum += row[j + 1];
        }
        for r in [above, below].iter().flatten() {
            sum += r.outside_value(j);
        }
        let z = row[j] + WEIGHT * sum;
        row[j] = z;
        sums.0 += z;
        sums.1 += z * (residual[j] - shift);
    }
    sums
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
}

impl<'a> Band<'a> {
    /// Local row `i` of `values` over the box's columns.
    fn row<'b>(&self, values: &'b [f64], i: usize) -> &'b [f64] {
        &values[i * self.columns..][self.cells.clone()]
    }

    /// Local row `i`'s members over the box's columns.
    fn members(&self, i: usize) -> &'a [bool] {
        &self.member[i * self.columns..][self.cells.clone()]
    }

    /// Whether local row `i` (or the one past either end of the band) is
    /// one of the box's.
    fn boxed(&self, i: isize) -> bool {
        let g = self.start as isize + i;
        g >= 0 && self.box_rows.contains(&(g as usize))
    }

    /// Distributed, the rows next to this band from the neighbouring ranks
    /// (`send(i)` of local row `i` is what this rank sends of its first
    /// and last rows, zeros if off the box); serial, none. Every rank must
    /// call it.
    pub(super) fn edges(
        &self,
        slab: Option<&Slab>,
        send: impl Fn(usize) -> Vec<f64>,
    ) -> (Vec<f64>, Vec<f64>) {
        let Some(slab) = slab else {
            return (Vec::new(), Vec::new());
        };
        let end = |i: usize| {
            if self.local > 0 && self.boxed(i as isize) {
                send(i)
            } else {
                vec![0.0; self.cells.len()]
            }
        };
        edge_rows(slab, &end(0), &end(self.local.saturating_sub(1)))
    }

    /// The box's rows next to local row `i`: rows of `values` on this rank
    /// or, past the band, the `edges` from its neighbours.
    pub(super) fn neighbours<'b>(
        &'b self,
        i: usize,
        values: &'b [f64],
        edges: &'b (Vec<f64>, Vec<f64>),
    ) -> (Option<Row<'b>>, Option<Row<'b>>) {
        let local = |j: usize| Row::Local {
            member: self.members(j),
            values: self.row(values, j),
        };
        let edge = |row: &'b Vec<f64>| (!row.is_empty()).then_some(Row::Edge(row));
        let up = if !self.boxed(i as isize - 1) {
            None
        } else if i > 0 {
            Some(local(i - 1))
        } else {
            edge(&edges.0)
        };
        let down = if !self.boxed(i as isize + 1) {
            None
        } else if i + 1 < self.local {
            Some(local(i + 1))
        } else {
            edge(&edges.1)
        };
        (up, down)
    }

    /// `E (r - shift) scale` on local row `i` into `line` (the box's
    /// columns), `edges` the members' residual of the rows past the band.
    pub(super) fn spread<T: Precision>(
        &self,
        line: &mut [T],
        i: usize,
        residual: &[f64],
        edges: &(Vec<f64>, Vec<f64>),
        (shift, scale): (f64, f64),
    ) {
        let next = self.neighbours(i, residual, edges);
        spread(
            line,
            self.members(i),
            self.row(residual, i),
            next,
            shift,
            scale,
        );
    }

    /// The members' residual less `shift` on local row `i`: what this rank
    /// sends its neighbours before the box inverse.
    pub(super) fn members_of(&self, residual: &[f64], i: usize, shift: f64) -> Vec<f64> {
        self.members(i)
            .iter()
            .zip(self.row(residual, i))
            .map(|(&m, &r)| if m { r - shift } else { 0.0 })
            .collect()
    }

    /// The box inverse's output off the members on local row `i`: what this
    /// rank sends its neighbours after it.
    pub(super) fn outside_of(&self, output: &[f64], i: usize) -> Vec<f64> {
        self.members(i)
            .iter()
            .zip(self.row(output, i))
            .map(|(&m, &y)| if m { 0.0 } else { y })
            .collect()
    }

    /// `E^T` on the band's rows of the box, in place in `output` (the box
    /// inverse's output on every box cell), `edges` the other cells'
    /// output on the rows past the band. Runs in pieces of [`GATHER_ROWS`]
    /// rows on all threads: a piece writes only its members and reads only
    /// non-members of the rows next to it, copied first. Returns `(sum z,
    /// sum z (r - shift))` over the members, added row by row in order.
    pub(super) fn gather(
        &self,
        output: &mut [f64],
        residual: &[f64],
        edges: &(Vec<f64>, Vec<f64>),
        shift: f64,
    ) -> (f64, f64) {
        let boxed: Vec<usize> = (0..self.local)
            .filter(|&i| self.boxed(i as isize))
            .collect();
        let (Some(&first), Some(&last)) = (boxed.first(), boxed.last()) else {
            return (0.0, 0.0);
        };
        let end = last + 1;
        let columns = self.columns;
        // Each piece's rows above and below it, if the box's.
        let copies: Vec<Beside> = (first..end)
            .step_by(GATHER_ROWS)
            .map(|s| {
                let e = (s + GATHER_ROWS).min(end);
                let past = |row: &Vec<f64>| (!row.is_empty()).then(|| row.clone());
                let up = if !self.boxed(s as isize - 1) {
                    None
                } else if s > 0 {
                    Some(self.outside_of(output, s - 1))
                } else {
                    past(&edges.0)
                };
                let down = if !self.boxed(e as isize) {
                    None
                } else if e < self.local {
                    Some(self.outside_of(output, e))
                } else {
                    past(&edges.1)
                };
                (up, down)
            })
            .collect();
        let sums = crate::parallel::map_rows(
            &mut output[first * columns..end * columns],
            GATHER_ROWS * columns,
            |piece, values| {
                let start = first + piece * GATHER_ROWS;
                let (above, below) = &copies[piece];
                let count = values.len() / columns;
                (0..count)
                    .map(|r| {
                        let i = start + r;
                        let (head, rest) = values.split_at_mut(r * columns);
                        let (current, tail) = rest.split_at_mut(columns);
                        let up = if r > 0 {
                            Some(Row::Local {
                                member: self.members(i - 1),
                                values: &head[(r - 1) * columns..][self.cells.clone()],
                            })
                        } else {
                            above.as_deref().map(Row::Edge)
                        };
                        let down = if r + 1 < count {
                            Some(Row::Local {
                                member: self.members(i + 1),
                                values: &tail[..columns][self.cells.clone()],
                            })
                        } else {
                            below.as_deref().map(Row::Edge)
                        };
                        gather(
                            &mut current[self.cells.clone()],
                            self.members(i),
                            self.row(residual, i),
                            (up, down),
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
/// to the rank before and `last` to the rank after. Every rank must call
/// it, with rows of the same length.
fn edge_rows(slab: &Slab, first: &[f64], last: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let (rank, ranks) = (slab.exchange.rank(), slab.exchange.ranks());
    let n = first.len();
    let packed = n.div_ceil(2);
    let pack = |row: &[f64]| -> Vec<Complex<f64>> {
        row.chunks(2)
            .map(|p| Complex::new(p[0], p.get(1).copied().unwrap_or(0.0)))
            .collect()
    };
    let mut send = Vec::with_capacity(2 * packed);
    let mut send_counts = vec![0; ranks];
    let mut receive_counts = vec![0; ranks];
    if rank > 0 {
        send.extend(pack(first));
        send_counts[rank - 1] = packed;
        receive_counts[rank - 1] = packed;
    }
    if rank + 1 < ranks {
        send.extend(pack(last));
        send_counts[rank + 1] = packed;
        receive_counts[rank + 1] = packed;
    }
    let mut receive = vec![Complex::new(0.0, 0.0); receive_counts.iter().sum()];
    slab.exchange
        .all_to_all(&send, &send_counts, &mut receive, &receive_counts);
    let unpack = |values: &[Complex<f64>]| -> Vec<f64> {
        values.iter().flat_map(|c| [c.re, c.im]).take(n).collect()
    };
    let above = if rank > 0 {
        unpack(&receive[..packed])
    } else {
        Vec::new()
    };
    let below = if rank + 1 < ranks {
        unpack(&receive[receive.len() - packed..])
    } else {
        Vec::new()
    };
    (above, below)
}

#[cfg(test)]
mod tests;
