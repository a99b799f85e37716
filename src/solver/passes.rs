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
    /// Whether a member carries no pressure (new overlap).
    pub(super) overlap: bool,
    /// The rows `(first, last)` and columns `(first, last)` of the members,
    /// `None` if there are none.
    pub(super) bounds: Option<Bounds>,
}

/// Rows `(first, last)` and columns `(first, last)` of a set of cells.
pub(super) type Bounds = ((usize, usize), (usize, usize));

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
        r.filter(|&c| pressure[c] > 0.0)
            .fold((0.0, 0), |(s, k), c| {
                (s + profile[c] + displacement[c], k + 1)
            })
    })
    .into_iter()
    .fold((0.0, 0), |(s, k), (a, b)| (s + a, k + b))
}

/// Gaps `profile - reference + u` on reachable cells (0 elsewhere) and the
/// working set: reachable cells in contact or overlapping, on a row-major
/// grid of `columns` columns.
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
) -> WorkingSet {
    let pass = |(k, (gap, working)): (usize, (&mut [f64], &mut [bool]))| {
        let mut set = WorkingSet::default();
        let first = k * CHUNK;
        // The row and column of cell `c`, kept by counting.
        let (mut row, mut column) = (first / columns, first % columns);
        let (mut rows, mut cols) = ((usize::MAX, 0), (usize::MAX, 0));
        for (i, (g, w)) in gap.iter_mut().zip(working.iter_mut()).enumerate() {
            let c = first + i;
            *g = if reachable[c] {
                profile[c] - reference + displacement[c]
            } else {
                0.0
            };
            let open = pressure[c] == 0.0;
            *w = reachable[c] && (!open || *g < 0.0);
            if *w {
                set.members += 1;
                set.gap_sum += *g;
                set.overlap |= open;
                rows = (rows.0.min(row), row);
                cols = (cols.0.min(column), cols.1.max(column));
            }
            column += 1;
            if column == columns {
                column = 0;
                row += 1;
            }
        }
        set.bounds = (set.members > 0).then_some((rows, cols));
        set
    };
    let parts: Vec<WorkingSet> = chunks_mut!(gap)
        .zip(chunks_mut!(working))
        .enumerate()
        .map(pass)
        .collect();
    parts
        .into_iter()
        .fold(WorkingSet::default(), |a, b| WorkingSet {
            members: a.members + b.members,
            gap_sum: a.gap_sum + b.gap_sum,
            overlap: a.overlap | b.overlap,
            bounds: union(a.bounds, b.bounds),
        })
}

/// `(sum a, sum a b)` over the working set.
pub(super) fn sum_and_dot(working: &[bool], a: &[f64], b: &[f64]) -> (f64, f64) {
    map_chunks(a.len(), |r| {
        r.filter(|&c| working[c])
            .fold((0.0, 0.0), |(s, d), c| (s + a[c], d + a[c] * b[c]))
    })
    .into_iter()
    .fold((0.0, 0.0), |(s, d), (x, y)| (s + x, d + y))
}

/// `[sum a t, sum b t, sum t]` over the working set.
pub(super) fn two_dots(working: &[bool], a: &[f64], b: &[f64], t: &[f64]) -> [f64; 3] {
    map_chunks(t.len(), |r| {
        r.filter(|&c| working[c]).fold([0.0; 3], |[x, y, z], c| {
            [x + a[c] * t[c], y + b[c] * t[c], z + t[c]]
        })
    })
    .into_iter()
    .fold([0.0; 3], |[x, y, z], [a, b, c]| [x + a, y + b, z + c])
}

/// `direction = z - shift + beta direction` on the working set, 0 elsewhere.
pub(super) fn update_direction(
    working: &[bool],
    z: &[f64],
    shift: f64,
    beta: f64,
    direction: &mut [f64],
) {
    let pass = |(k, direction): (usize, &mut [f64])| {
        for (i, t) in direction.iter_mut().enumerate() {
            let c = k * CHUNK + i;
            *t = if working[c] {
                z[c] - shift + beta * *t
            } else {
                0.0
            };
        }
    };
    chunks_mut!(direction).enumerate().for_each(pass);
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
}

/// The step `p -= step t` on the working set, clamped at zero; `u -= step
/// K t`; `correction` gets what the clamping added (to apply `K` to);
/// `previous` the old pressures. Pressures, `previous` and the statistics
/// only on `cells`, which must hold the working set and every pressure;
/// `correction` is 0 outside them.
#[allow(clippy::too_many_arguments)]
pub(super) fn step(
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
        axpy(
            &mut displacement[outside.clone()],
            -step,
            &response[outside.clone()],
        );
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
        for i in 0..p.len() {
            let c = k * CHUNK + i;
            let old = p[i];
            prev[i] = old;
            let stepped = if working[c] {
                old - step * direction[c]
            } else {
                old
            };
            let new = stepped.max(0.0);
            p[i] = new;
            u[i] -= step * response[c];
            corr[i] = new - stepped;
            s.corrected += usize::from(corr[i] != 0.0);
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
        for (i, v) in values.iter_mut().enumerate() {
            *v += factor * add[k * CHUNK + i];
        }
    };
    chunks_mut!(values).enumerate().for_each(pass);
}

/// `values *= factor`.
pub(super) fn scale(values: &mut [f64], factor: f64) {
    chunks_mut!(values).for_each(|chunk| chunk.iter_mut().for_each(|v| *v *= factor));
}

/// What [`rescale`] found: the pressure's change and size, and the sum of
/// `profile + u` over the cells with pressure (the depth under force
/// control is its mean), with their count; as `f64` to be summed over the
/// ranks in one exchange.
pub(super) type Rescaled = [f64; 4];

/// `u = factor (u + add)` (`add` 0 if `None`: the response to a clamping
/// correction not yet added) and `p *= factor`; returns `[sum |p -
/// previous|, sum p, sum over p > 0 of profile + u, count of p > 0]` of the
/// result. The pressures only on `cells`, which must hold every pressure.
/// One pass instead of three (the correction's `axpy`, the scaling, and the
/// next iteration's contact sum).
pub(super) fn rescale(
    cells: Range<usize>,
    pressure: &mut [f64],
    displacement: &mut [f64],
    add: Option<&[f64]>,
    previous: &[f64],
    profile: &[f64],
    factor: f64,
) -> Rescaled {
    let (lo, hi) = (cells.start, cells.end);
    for outside in [0..lo, hi..displacement.len()] {
        match add {
            Some(add) => {
                let add = &add[outside.clone()];
                let pass = |(k, values): (usize, &mut [f64])| {
                    for (i, v) in values.iter_mut().enumerate() {
                        *v = factor * (*v + add[k * CHUNK + i]);
                    }
                };
                chunks_mut!(displacement[outside])
                    .enumerate()
                    .for_each(pass);
            }
            None => scale(&mut displacement[outside], factor),
        }
    }
    // From here on, indices count from the first cell of `cells`.
    let (pressure, previous) = (&mut pressure[cells.clone()], &previous[cells.clone()]);
    let (profile, add) = (&profile[cells.clone()], add.map(|a| &a[cells.clone()]));
    let displacement = &mut displacement[cells];
    let pass = |(k, (p, u)): (usize, (&mut [f64], &mut [f64]))| {
        let mut sums = [0.0; 4];
        for i in 0..p.len() {
            let c = k * CHUNK + i;
            p[i] *= factor;
            u[i] = factor * (u[i] + add.map_or(0.0, |a| a[c]));
            sums[0] += (p[i] - previous[c]).abs();
            sums[1] += p[i];
            if p[i] > 0.0 {
                // In the order of `contact_sum`.
                sums[2] = sums[2] + profile[c] + u[i];
                sums[3] += 1.0;
            }
        }
        sums
    };
    let parts: Vec<Rescaled> = chunks_mut!(pressure)
        .zip(chunks_mut!(displacement))
        .enumerate()
        .map(pass)
        .collect();
    parts.into_iter().fold([0.0; 4], |a, b| {
        [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]
    })
}
