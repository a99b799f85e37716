//! The rescale of the pressure to the load under force control, as a pass
//! of its own or inside the step's convolution.

use std::ops::Range;

#[cfg(feature = "parallel")]
use rayon::prelude::*;

use super::{scale, CHUNK};

/// What [`rescale`] found: the pressure's change and size, and the sum of
/// `profile + u` over the cells with pressure (the depth under force
/// control is its mean), with their count; as `f64` to be summed over the
/// ranks in one exchange.
pub(in crate::solver) type Rescaled = [f64; 4];

/// The pressures before a step, as [`rescale`] reads them: kept
/// (`previous` of a step that is not deferred), or as the changes that
/// the new pressures less them are (`correction` of a deferred one).
#[derive(Clone, Copy)]
pub(in crate::solver) enum Before<'a> {
    Pressures(&'a [f64]),
    Changes(&'a [f64]),
}

impl<'a> Before<'a> {
    pub(in crate::solver) fn cells(self, cells: Range<usize>) -> Before<'a> {
        match self {
            Before::Pressures(v) => Before::Pressures(&v[cells]),
            Before::Changes(v) => Before::Changes(&v[cells]),
        }
    }
}

/// `u *= factor` and `p *= factor`; returns `[sum |p - before|, sum p,
/// sum over p > 0 of profile + u, count of p > 0]` of the result. The
/// pressures only on `cells`, which must hold every pressure. One pass
/// instead of two (the scaling, and the next iteration's contact sum);
/// where the step convolved anyway, [`rescale_row`] runs inside that
/// convolution instead.
pub(in crate::solver) fn rescale(
    cells: Range<usize>,
    pressure: &mut [f64],
    displacement: &mut [f64],
    before: Before<'_>,
    profile: &[f64],
    factor: f64,
) -> Rescaled {
    let (lo, hi) = (cells.start, cells.end);
    for outside in [0..lo, hi..displacement.len()] {
        scale(&mut displacement[outside], factor);
    }
    // From here on, indices count from the first cell of `cells`.
    let (pressure, before) = (&mut pressure[cells.clone()], before.cells(cells.clone()));
    let profile = &profile[cells.clone()];
    let displacement = &mut displacement[cells];
    let pass = |(k, (p, u)): (usize, (&mut [f64], &mut [f64]))| {
        let cells = k * CHUNK..k * CHUNK + p.len();
        rescale_cells::<f64>(
            p,
            u,
            None,
            0.0,
            before.cells(cells.clone()),
            &profile[cells],
            factor,
        )
    };
    let parts: Vec<Rescaled> = chunks_mut!(pressure)
        .zip(chunks_mut!(displacement))
        .enumerate()
        .map(pass)
        .collect();
    add_rescaled(parts)
}

/// The [`Rescaled`] sums of parts, added in order.
pub(in crate::solver) fn add_rescaled(parts: Vec<Rescaled>) -> Rescaled {
    parts.into_iter().fold([0.0; 4], |a, b| {
        [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]
    })
}

/// `p *= factor`, `u = factor (u + add_factor add)` (`add` 0 if `None`)
/// on a run of cells, with their [`Rescaled`] sums.
fn rescale_cells<A: Copy + Into<f64>>(
    pressure: &mut [f64],
    displacement: &mut [f64],
    add: Option<&[A]>,
    add_factor: f64,
    before: Before<'_>,
    profile: &[f64],
    factor: f64,
) -> Rescaled {
    match before {
        Before::Pressures(b) => rescale_with(
            pressure,
            displacement,
            add,
            add_factor,
            profile,
            factor,
            |i, _| b[i],
        ),
        Before::Changes(b) => rescale_with(
            pressure,
            displacement,
            add,
            add_factor,
            profile,
            factor,
            |i, p| p - b[i],
        ),
    }
}

/// [`rescale_cells`] with the old pressure of cell `i` `old(i, p)` from its
/// new one before the scaling.
fn rescale_with<A: Copy + Into<f64>>(
    pressure: &mut [f64],
    displacement: &mut [f64],
    add: Option<&[A]>,
    add_factor: f64,
    profile: &[f64],
    factor: f64,
    old: impl Fn(usize, f64) -> f64,
) -> Rescaled {
    let mut sums = [0.0; 4];
    let cells = pressure
        .iter_mut()
        .zip(displacement.iter_mut())
        .zip(profile);
    for (i, ((p, u), h)) in cells.enumerate() {
        let old = old(i, *p);
        *p *= factor;
        *u = factor * (*u + add.map_or(0.0, |a| add_factor * a[i].into()));
        sums[0] += (*p - old).abs();
        sums[1] += *p;
        // In the order of `contact_sum`; a select, not a branch.
        let inside = *p > 0.0;
        sums[2] = if inside { sums[2] + h + *u } else { sums[2] };
        sums[3] += if inside { 1.0 } else { 0.0 };
    }
    sums
}

/// One row's targets of a rescale inside a convolution: the displacement's
/// row, and the pressure's on the rows that may carry pressure.
pub(in crate::solver) type RescaleRow<'a> = (&'a mut [f64], Option<&'a mut [f64]>);

/// The [`RescaleRow`]s of a grid of `columns` columns whose pressures lie
/// on the whole rows `cells`.
pub(in crate::solver) fn rescale_targets<'a>(
    cells: Range<usize>,
    columns: usize,
    pressure: &'a mut [f64],
    displacement: &'a mut [f64],
) -> Vec<RescaleRow<'a>> {
    let columns = columns.max(1);
    let rows = cells.start / columns..cells.end.div_ceil(columns);
    displacement
        .chunks_exact_mut(columns)
        .zip(pressure.chunks_exact_mut(columns))
        .enumerate()
        .map(|(i, (u, p))| (u, rows.contains(&i).then_some(p)))
        .collect()
}

/// [`rescale`] of row `row` (`before` and `profile` its cells) inside
/// the convolution whose response row is `response`: `u = factor (u +
/// add_factor response)` and, on the pressure's rows, `p *= factor` with
/// the [`Rescaled`] sums (zero on the other rows).
pub(in crate::solver) fn rescale_row<A: Copy + Into<f64>>(
    row: RescaleRow<'_>,
    response: &[A],
    add_factor: f64,
    before: Before<'_>,
    profile: &[f64],
    factor: f64,
) -> Rescaled {
    let (u, p) = row;
    match p {
        Some(p) => rescale_cells(p, u, Some(response), add_factor, before, profile, factor),
        None => {
            for (u, v) in u.iter_mut().zip(response) {
                *u = factor * (*u + add_factor * (*v).into());
            }
            [0.0; 4]
        }
    }
}
