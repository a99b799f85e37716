//! The per-cell passes of the constrained conjugate gradients, on all
//! threads with the `parallel` feature.
//!
//! Cells are split into chunks of a fixed size and sums are added chunk by
//! chunk in order, so results do not depend on the number of threads.

use std::ops::Range;

/// Cells per chunk (fixed: the summation order depends on it alone).
const CHUNK: usize = 1 << 14;

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Chunks of a mutable slice, in parallel with the `parallel` feature.
macro_rules! chunks_mut {
    ($v:expr) => {{
        #[cfg(feature = "parallel")]
        let chunks = $v.par_chunks_mut(CHUNK);
        #[cfg(not(feature = "parallel"))]
        let chunks = $v.chunks_mut(CHUNK);
        chunks
    }};
}

/// `f` on every chunk's range of cells, in parallel, results in order.
fn map_chunks<T: Send>(n: usize, f: impl Fn(Range<usize>) -> T + Sync + Send) -> Vec<T> {
    let range = |k: usize| k * CHUNK..((k + 1) * CHUNK).min(n);
    #[cfg(feature = "parallel")]
    {
        (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(range)
            .map(f)
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        (0..n.div_ceil(CHUNK)).map(range).map(f).collect()
    }
}

/// What the gap pass found about the working set.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct WorkingSet {
    /// Cells in the set.
    pub(super) members: usize,
    /// Sum of their gaps.
    pub(super) gap_sum: f64,
    /// The largest absolute gap among them (0 if none).
    pub(super) gap_max: f64,
    /// Whether a member carries no pressure (new overlap).
    pub(super) overlap: bool,
    /// Reachable cells without pressure that overlap the indenter (gap
    /// below zero), members or not.
    pub(super) overlap_cells: usize,
    /// The sum of their gaps (at most zero).
    pub(super) overlap_sum: f64,
    /// The least of their gaps (0 if there are none).
    pub(super) deepest: f64,
    /// How many of them lie apart from the contact: no neighbour in its
    /// row carries pressure.
    pub(super) apart_cells: usize,
    /// The rows `(first, last)` and columns `(first, last)` of the members,
    /// `None` if there are none.
    pub(super) bounds: Option<Bounds>,
}

/// Rows `(first, last)` and columns `(first, last)` of a set of cells.
pub(super) type Bounds = ((usize, usize), (usize, usize));

/// The bounds of `cells` on a grid `columns` wide, `None` if there are
/// none.
pub(super) fn bounds_of(cells: impl Iterator<Item = usize>, columns: usize) -> Option<Bounds> {
    cells
        .map(|c| Some(((c / columns, c / columns), (c % columns, c % columns))))
        .fold(None, union)
}

/// The bounds of two sets' union.
fn union(a: Option<Bounds>, b: Option<Bounds>) -> Option<Bounds> {
    match (a, b) {
        (Some(((r0, r1), (c0, c1))), Some(((s0, s1), (d0, d1)))) => {
            Some(((r0.min(s0), r1.max(s1)), (c0.min(d0), c1.max(d1))))
        }
        (a, None) => a,
        (None, b) => b,
    }
}

/// `(sum of profile + u, count)` over the cells that carry pressure.
pub(super) fn contact_sum(profile: &[f64], displacement: &[f64], pressure: &[f64]) -> (f64, usize) {
    map_chunks(pressure.len(), |r| {
        let cells = profile[r.clone()].iter().zip(&displacement[r.clone()]);
        cells
            .zip(&pressure[r])
            .fold((0.0, 0), |(s, k), ((h, u), p)| {
                // A select, not a branch: contacts are patchy.
                let inside = *p > 0.0;
                (if inside { s + h + u } else { s }, k + usize::from(inside))
            })
    })
    .into_iter()
    .fold((0.0, 0), |(s, k), (a, b)| (s + a, k + b))
}

/// The gap pass's findings chunk by chunk: each chunk's part of the
/// working set and its new overlap (offsets in the chunk, [`BESIDE`] set
/// for a cell beside the contact), which [`GapPass::leave_out`]
/// may still take out of the set.
#[derive(Debug)]
pub(super) struct GapPass {
    parts: Vec<Part>,
}

/// A chunk's part of the working set and its listed new overlap.
type Part = (WorkingSet, Vec<u32>);

/// The flag of a listed overlapping cell with a neighbour in contact in
/// its row (a chunk's offsets are below `CHUNK`, 2^14).
const BESIDE: u32 = 1 << 31;

impl GapPass {
    /// The working set of the whole pass (the chunks' sums added in order).
    pub(super) fn set(&self) -> WorkingSet {
        self.parts
            .iter()
            .fold(WorkingSet::default(), |a, (b, _)| WorkingSet {
                members: a.members + b.members,
                gap_sum: a.gap_sum + b.gap_sum,
                gap_max: a.gap_max.max(b.gap_max),
                overlap: a.overlap | b.overlap,
                overlap_cells: a.overlap_cells + b.overlap_cells,
                overlap_sum: a.overlap_sum + b.overlap_sum,
                deepest: a.deepest.min(b.deepest),
                apart_cells: a.apart_cells + b.apart_cells,
                bounds: union(a.bounds, b.bounds),
            })
    }

    /// Takes the listed overlapping cells for which `stays_out(cell,
    /// beside)` holds (`beside`: a neighbour in contact in its row) out of
    /// the working set and returns the set: its members and gap sum less
    /// theirs (chunk by chunk, in the same order, so the result does not
    /// depend on the threads); the largest absolute gap as it was (the
    /// deepest overlap, a member, stays); the bounds as they were (they
    /// still hold every member). Visits only the listed cells, on all
    /// threads with the `parallel` feature.
    pub(super) fn leave_out(
        mut self,
        gap: &[f64],
        working: &mut [bool],
        stays_out: impl Fn(usize, bool) -> bool + Sync,
    ) -> WorkingSet {
        let visit = |(k, ((part, listed), working)): (usize, (&mut Part, &mut [bool]))| {
            for &entry in listed.iter() {
                let offset = (entry & !BESIDE) as usize;
                let c = k * CHUNK + offset;
                if stays_out(c, entry & BESIDE != 0) {
                    working[offset] = false;
                    part.members -= 1;
                    part.gap_sum -= gap[c];
                }
            }
        };
        #[cfg(feature = "parallel")]
        let parts = self.parts.par_iter_mut();
        #[cfg(not(feature = "parallel"))]
        let parts = self.parts.iter_mut();
        parts.zip(chunks_mut!(working)).enumerate().for_each(visit);
        self.set()
    }
}

/// Gaps `profile - reference + u` on reachable cells (0 elsewhere) and the
/// working set: reachable cells in contact or overlapping, on a row-major
/// grid of `columns` columns; the overlapping cells without pressure are
/// listed, those with no neighbour in contact in their row counted apart.
#[allow(clippy::too_many_arguments)]
pub(super) fn gaps_and_working_set(
    profile: &[f64],
    displacement: &[f64],
    pressure: &[f64],
    reachable: &[bool],
    reference: f64,
    columns: usize,
    gap: &mut [f64],
    working: &mut [bool],
) -> GapPass {
    let pass = |(k, (gap, working)): (usize, (&mut [f64], &mut [bool]))| {
        let mut set = WorkingSet::default();
        let mut listed = Vec::new();
        let first = k * CHUNK;
        let (mut rows, mut cols) = ((usize::MAX, 0), (usize::MAX, 0));
        // Row by row (a chunk holds whole rows unless a row is longer than
        // it: then pieces of rows, each with its grid row and first column).
        let mut at = 0;
        while at < gap.len() {
            let cell = first + at;
            let (row, column) = (cell / columns, cell % columns);
            let end = (at + columns - column).min(gap.len());
            let cells = cell..first + end;
            let inputs = profile[cells.clone()]
                .iter()
                .zip(&displacement[cells.clone()])
                .zip(pressure[cells.clone()].iter().zip(&reachable[cells]));
            let (gap, working) = (&mut gap[at..end], &mut working[at..end]);
            let before = set.members;
            // Selects, not branches, where the set decides: rough contacts
            // are patchy.
            for (i, ((g, w), ((h, u), (p, &reach)))) in gap
                .iter_mut()
                .zip(working.iter_mut())
                .zip(inputs)
                .enumerate()
            {
                *g = if reach { h - reference + u } else { 0.0 };
                let open = *p == 0.0;
                let overlaps = reach && open && *g < 0.0;
                *w = reach && (!open || *g < 0.0);
                let member = *w;
                set.members += usize::from(member);
                // Adding +0.0 leaves the sum as it was (it starts at +0.0).
                set.gap_sum += if member { *g } else { 0.0 };
                set.gap_max = if member {
                    set.gap_max.max(g.abs())
                } else {
                    set.gap_max
                };
                // New overlap: rare once the contact settles, a branch.
                if overlaps {
                    set.overlap = true;
                    set.overlap_cells += 1;
                    set.overlap_sum += *g;
                    set.deepest = set.deepest.min(*g);
                    // No neighbour in its row in contact.
                    let (c, j) = (cell + i, column + i);
                    let beside = (j > 0 && pressure[c - 1] > 0.0)
                        || (j + 1 < columns && pressure[c + 1] > 0.0);
                    set.apart_cells += usize::from(!beside);
                    // A chunk's offsets are below `CHUNK` (2^14).
                    let offset = (at + i) as u32;
                    listed.push(if beside { offset | BESIDE } else { offset });
                }
            }
            if set.members > before {
                // The row's first and last members, found from its ends.
                let lo = working.iter().position(|w| *w).unwrap_or(0);
                let hi = working.iter().rposition(|w| *w).unwrap_or(0);
                rows = (rows.0.min(row), row);
                cols = (cols.0.min(column + lo), cols.1.max(column + hi));
            }
            at = end;
        }
        set.bounds = (set.members > 0).then_some((rows, cols));
        (set, listed)
    };
    GapPass {
        parts: chunks_mut!(gap)
            .zip(chunks_mut!(working))
            .enumerate()
            .map(pass)
            .collect(),
    }
}

/// `(sum a, sum a b)` over the working set.
pub(super) fn sum_and_dot(working: &[bool], a: &[f64], b: &[f64]) -> (f64, f64) {
    map_chunks(a.len(), |r| {
        let cells = working[r.clone()].iter().zip(&a[r.clone()]).zip(&b[r]);
        cells.fold(
            (0.0, 0.0),
            |(s, d), ((w, a), b)| {
                if *w {
                    (s + a, d + a * b)
                } else {
                    (s, d)
                }
            },
        )
    })
    .into_iter()
    .fold((0.0, 0.0), |(s, d), (x, y)| (s + x, d + y))
}

/// `sum a b`.
pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    map_chunks(a.len(), |r| {
        a[r.clone()]
            .iter()
            .zip(&b[r])
            .map(|(x, y)| x * y)
            .sum::<f64>()
    })
    .into_iter()
    .sum()
}

/// What [`update_direction`] summed: `(sum t, sum t gap)` of the new
/// direction `t` (the gradient's part along it), the same of the old
/// direction on the working set (whether the conjugation descends), and
/// the largest `|t|` (the scale of its energy in single precision).
pub(super) type DirectionSums = [f64; 5];

/// `direction = z - shift + beta direction` on the working set, 0
/// elsewhere; returns the [`DirectionSums`] of the new and the old
/// direction, read in the same pass.
pub(super) fn update_direction(
    working: &[bool],
    z: &[f64],
    gap: &[f64],
    shift: f64,
    beta: f64,
    direction: &mut [f64],
) -> DirectionSums {
    let pass = |(k, direction): (usize, &mut [f64])| {
        let cells = k * CHUNK..k * CHUNK + direction.len();
        let inputs = working[cells.clone()]
            .iter()
            .zip(&z[cells.clone()])
            .zip(&gap[cells]);
        let mut sums = [0.0; 5];
        for (t, ((w, z), g)) in direction.iter_mut().zip(inputs) {
            // Selects, not branches: rough contacts are patchy.
            let old = if *w { *t } else { 0.0 };
            sums[2] += old;
            sums[3] += old * g;
            *t = if *w { z - shift + beta * *t } else { 0.0 };
            sums[0] += *t;
            sums[1] += *t * g;
            sums[4] = sums[4].max(t.abs());
        }
        sums
    };
    let parts: Vec<DirectionSums> = chunks_mut!(direction).enumerate().map(pass).collect();
    parts.into_iter().fold([0.0; 5], |a, b| {
        [
            a[0] + b[0],
            a[1] + b[1],
            a[2] + b[2],
            a[3] + b[3],
            a[4].max(b[4]),
        ]
    })
}

/// What a step did.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Step {
    /// Cells where clamping changed a pressure off the search direction.
    pub(super) corrected: usize,
    /// Sum of the absolute pressure changes.
    pub(super) change: f64,
    /// Sum of the new pressures.
    pub(super) size: f64,
    /// Cells with pressure.
    pub(super) contact: usize,
    /// The largest absolute value written to `correction` (the scale of a
    /// single-precision application to it).
    pub(super) largest: f64,
}

/// The step `p -= step t` on the working set, clamped at zero. With
/// `DEFERRED` false, `u -= step K t` (`response` holds `K t`), `correction`
/// gets what the clamping added (to apply `K` to) and `previous` the old
/// pressures; with `DEFERRED` true, `u`, `response` and `previous` are left
/// alone and `correction` gets the whole change of the pressure (the
/// caller applies `K` to it, or to `t`, once it knows whether the step
/// clamped; the old pressures are the new less it, [`Before::Changes`]).
/// Pressures, `previous` and the statistics only on `cells`,
/// which must hold the working set and every pressure; `correction` is 0
/// outside them.
#[allow(clippy::too_many_arguments)]
pub(super) fn step<const DEFERRED: bool>(
    cells: Range<usize>,
    working: &[bool],
    direction: &[f64],
    response: &[f64],
    step: f64,
    pressure: &mut [f64],
    displacement: &mut [f64],
    correction: &mut [f64],
    previous: &mut [f64],
) -> Step {
    let (lo, hi) = (cells.start, cells.end);
    for outside in [0..lo, hi..displacement.len()] {
        if !DEFERRED {
            axpy(
                &mut displacement[outside.clone()],
                -step,
                &response[outside.clone()],
            );
        }
        correction[outside].fill(0.0);
    }
    // From here on, indices count from the first cell of `cells`.
    let (working, direction) = (&working[cells.clone()], &direction[cells.clone()]);
    let response = &response[cells.clone()];
    let (pressure, displacement) = (
        &mut pressure[cells.clone()],
        &mut displacement[cells.clone()],
    );
    let (correction, previous) = (&mut correction[cells.clone()], &mut previous[cells]);
    type Chunk<'a> = (
        usize,
        (
            ((&'a mut [f64], &'a mut [f64]), &'a mut [f64]),
            &'a mut [f64],
        ),
    );
    let pass = |(k, (((p, u), corr), prev)): Chunk<'_>| {
        let mut s = Step::default();
        let cells = k * CHUNK..k * CHUNK + p.len();
        let inputs = working[cells.clone()]
            .iter()
            .zip(&direction[cells.clone()])
            .zip(&response[cells]);
        let outputs = p
            .iter_mut()
            .zip(u.iter_mut())
            .zip(corr.iter_mut())
            .zip(prev);
        for ((((p, u), corr), prev), ((w, t), kt)) in outputs.zip(inputs) {
            let old = *p;
            if !DEFERRED {
                *prev = old;
            }
            let stepped = if *w { old - step * t } else { old };
            let new = stepped.max(0.0);
            *p = new;
            if DEFERRED {
                *corr = new - old;
            } else {
                *u -= step * kt;
                *corr = new - stepped;
            }
            s.largest = s.largest.max(corr.abs());
            s.corrected += usize::from(new != stepped);
            s.change += (new - old).abs();
            s.size += new;
            s.contact += usize::from(new > 0.0);
        }
        s
    };
    let parts: Vec<Step> = chunks_mut!(pressure)
        .zip(chunks_mut!(displacement))
        .zip(chunks_mut!(correction))
        .zip(chunks_mut!(previous))
        .enumerate()
        .map(pass)
        .collect();
    parts.into_iter().fold(Step::default(), |a, b| Step {
        corrected: a.corrected + b.corrected,
        change: a.change + b.change,
        size: a.size + b.size,
        contact: a.contact + b.contact,
        largest: a.largest.max(b.largest),
    })
}

/// The nonzero values and their cells (`first` + index), in cell order.
pub(super) fn nonzeros(values: &[f64], first: usize) -> Vec<(usize, f64)> {
    map_chunks(values.len(), |r| {
        r.filter(|&c| values[c] != 0.0)
            .map(|c| (first + c, values[c]))
            .collect::<Vec<_>>()
    })
    .concat()
}

/// `values += factor * add`.
pub(super) fn axpy(values: &mut [f64], factor: f64, add: &[f64]) {
    let pass = |(k, values): (usize, &mut [f64])| {
        let add = &add[k * CHUNK..k * CHUNK + values.len()];
        for (v, a) in values.iter_mut().zip(add) {
            *v += factor * a;
        }
    };
    chunks_mut!(values).enumerate().for_each(pass);
}

/// `values *= factor`.
pub(super) fn scale(values: &mut [f64], factor: f64) {
    chunks_mut!(values).for_each(|chunk| chunk.iter_mut().for_each(|v| *v *= factor));
}

mod rescale;
pub(super) use rescale::{add_rescaled, rescale, rescale_row, rescale_targets, Before, Rescaled};

#[cfg(test)]
pub(super) mod tests;
