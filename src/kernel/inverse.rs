//! An approximate inverse of the compliance on a box of cells, the
//! preconditioner of the constrained conjugate gradients.
//!
//! On a periodic box of `m0 x m1` cells the compliance is diagonal in
//! Fourier space, `u_z(q) sinc(q_x Delta/2) sinc(q_y Delta/2)`; its inverse
//! is applied to a residual restricted to the cells in contact, and the
//! result restricted again. Vollebregt (2014, J. Comput. Phys. 257, 333-351)
//! introduced this FFT-based preconditioner for conjugate gradients on the
//! contact area; it makes the iteration count of a Hertzian contact nearly
//! independent of the grid. The box only needs to hold the contact with a
//! small margin (the inverse kernel, a stiffness, decays like `1/r^3`), so
//! an application costs a periodic FFT round trip on the contact's bounding
//! box, not on the padded grid. On an isolated grid a contact that spreads
//! over the whole grid (a rough surface) still gets its margin: the box is
//! then the grid zero-padded (its data rows and columns the grid's, the
//! padding never transformed by the row passes). A box cut to the grid
//! itself, as before 2026-11-29, coupled cells on opposite edges as if
//! neighbours: 31, 41 and 58 fine iterations at 1024^2, 2048^2 and 4096^2
//! on the rough film of `BENCHMARKS.md` against 27, 36 and 48 padded.
//!
//! Contact solves carry the residual one cell past the set's edges before
//! the transform and gather the result back after it (`extension`: the
//! zero extension's jump at every edge removed, a quarter fewer iterations
//! on rough contacts).

use crate::error::Result;
use crate::slab::{agree, even_starts, lengths, Slab};

use super::convolution::{
    multiplier, power_of_two_above, wavenumber, Convolution, Precision, Scaled,
};
use super::fourier::FourierCompliance;
use super::operator::{cell_filter, ShareBuffer};

mod extension;

use extension::Band;

/// What a [`BoxInverse`] is applied to: a residual on a row-major grid of
/// `columns` columns and `values.len() / columns` rows, restricted to the
/// cells where `member` holds and shifted by `-shift` there (the force
/// projection), with the box's first cell at grid cell `origin`;
/// `magnitude` bounds `|values - shift|` on the members (it scales them
/// into single precision's range). With `extend` the residual is carried
/// one cell past the members' edges first and the result gathered back
/// (`extension`): the box's non-members then hold its raw output.
#[derive(Clone, Copy)]
pub(crate) struct Residual<'a> {
    pub(crate) columns: usize,
    pub(crate) origin: (isize, isize),
    pub(crate) member: &'a [bool],
    pub(crate) values: &'a [f64],
    pub(crate) shift: f64,
    pub(crate) magnitude: f64,
    pub(crate) extend: bool,
}

/// The approximate inverse on a box of a fixed size (plans, multiplier and
/// box buffers), placed anywhere on a grid at each application.
///
/// Its FFTs run in `T`. In single precision (`f32`) a round trip moves
/// half the bytes, and as the preconditioner only shapes the search
/// direction (the gaps and the step come from the double-precision
/// operator), its rounding of about `1e-7` leaves the iterations and the
/// solution of a contact as they are. The residual and the multiplier are
/// scaled by powers of two into `T`'s range (exactly: no rounding) and the
/// result scaled back in `f64`.
///
/// The box's data (the cells a residual can occupy) may be smaller than its
/// FFT grid: a box wider than an isolated grid holds the grid's cells and
/// zero-pads them, so that its periodic images stay apart by the margin
/// without transforming rows of zeros.
pub(crate) struct BoxInverse<T: Precision> {
    size: (usize, usize),
    /// Rows and columns of data (at most `size`).
    data: (usize, usize),
    /// The multiplier over `multiplier_scale`, in `T`.
    multiplier: Vec<T>,
    /// A power of two about the multiplier's largest value.
    multiplier_scale: f64,
    convolution: Convolution<T>,
    /// Distributed: the split of the grid's rows across the ranks.
    slab: Option<Slab>,
}

impl<T: Precision> BoxInverse<T> {
    /// The inverse of `compliance` on a periodic box of `size` cells of side
    /// `delta`, whose first `data` rows and columns carry the residual (the
    /// rest is zero padding). The mean mode, whose compliance is infinite on a half-space,
    /// gets the stiffness of the smallest nonzero wavevector; a stiffness
    /// that is not finite and positive (an extreme layer) falls back to the
    /// half-space's, `E* |q| / 2`.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn new(
        compliance: &FourierCompliance,
        surface_modulus: f64,
        delta: f64,
        size: (usize, usize),
        data: (usize, usize),
        slab: Option<&Slab>,
    ) -> Result<Self> {
        let (m0, m1) = size;
        let data = (data.0.min(m0), data.1.min(m1));
        let smallest = wavenumber(1, m0.max(m1).max(2), delta).abs();
        let stiffness = |qx: f64, qy: f64| {
            let q = qx.hypot(qy);
            let (qx, q) = if q == 0.0 {
                (smallest, smallest)
            } else {
                (qx, q)
            };
            let value = 1.0 / (compliance.eval(q) * cell_filter(qx, qy, delta));
            if value.is_finite() && value > 0.0 {
                value
            } else {
                0.5 * surface_modulus * q
            }
        };
        let convolution = match slab {
            None => Convolution::new(data.0, data.1, size)?,
            Some(slab) => {
                // Until the box is placed its rows are split evenly (its
                // buffers then grow to what the placements need).
                let counts = lengths(&even_starts(data.0, slab.exchange.ranks()));
                Convolution::distributed(data.0, data.1, size, slab, counts)?
            }
        };
        // Scaled by the multiplier at the largest wavevector (about its
        // largest value: the stiffness grows with `q`), the same on every
        // rank whatever columns it holds, so that split runs round as
        // serial ones do.
        let corner = stiffness(wavenumber(m0 / 2, m0, delta), wavenumber(m1 / 2, m1, delta));
        let multiplier_scale = power_of_two_above(corner / (m0 * m1) as f64);
        let values = multiplier(size, delta, convolution.own_columns(), stiffness)?;
        // A value below `T`'s normal range is raised to it: a mode without
        // stiffness would leave the search direction without that mode.
        let multiplier = values
            .iter()
            .map(|v| T::narrow((v / multiplier_scale).max(T::smallest().into())))
            .collect();
        Ok(BoxInverse {
            size,
            data,
            multiplier,
            multiplier_scale,
            convolution,
            slab: slab.cloned(),
        })
    }

    /// As [`BoxInverse::apply_with`], the FFT working in `buffer` (the
    /// compliance operator's, lent: one buffer of the grid's half-spectra
    /// serves both): the box then holds no per-cell buffer of its own.
    pub(crate) fn apply_in(
        &mut self,
        buffer: &mut ShareBuffer,
        residual: &Residual<'_>,
        result: &mut [f64],
    ) -> Result<(f64, f64)> {
        // The box allocates its buffer only on first use and gives it back
        // below, so it holds none of its own here.
        self.convolution.give_tiles(std::mem::take(&mut buffer.0));
        let sums = self.apply_with(residual, result);
        // The lent buffer, or the box's own if that was too small.
        buffer.0 = self.convolution.take_tiles();
        sums
    }

    /// The box's FFT size (rows, columns).
    pub(crate) fn size(&self) -> (usize, usize) {
        self.size
    }

    /// The box's data rows and columns (at most [`BoxInverse::size`]).
    pub(crate) fn data(&self) -> (usize, usize) {
        self.data
    }

    /// `result = P M^-1 P (r - shift)` for the [`Residual`] `r` on its grid,
    /// `P` the restriction to its members, with the box's first cell at grid
    /// cell `origin` (rows and columns, possibly negative: box cells off the
    /// grid are zero); extended, `P E^T M^-1 E P (r - shift)`
    /// (`extension`). Only cells in the box are written (without the
    /// extension only its members): the box must hold every member.
    /// Returns `(sum result, sum result * (r - shift))` over the members,
    /// added row by row in order (the same whatever the threads).
    ///
    /// The result goes to the box's cells from the transform's last pass
    /// (no buffer of the box's values); extended, the members are then
    /// gathered in place.
    ///
    /// # Errors
    /// As the FFT ([`Error::Internal`](crate::Error::Internal), a bug).
    fn apply_with(&mut self, residual: &Residual<'_>, result: &mut [f64]) -> Result<(f64, f64)> {
        let Residual {
            columns,
            origin,
            member,
            values: residual,
            shift,
            magnitude,
            extend,
        } = *residual;
        // The residual into single precision's range, the result back.
        let scale = 1.0 / power_of_two_above(magnitude);
        let unscale = self.multiplier_scale / scale;
        // The data's extent: where the box meets the grid.
        let (m0, m1) = self.data;
        // This rank's grid rows `grid.start..` and box rows `boxed`
        // (serial: all of either); distributed, a rank whose buffers could
        // not grow stops every rank.
        let local = residual.len() / columns.max(1);
        let placed = self.place(origin.0, local);
        let (grid, boxed) = agree(self.slab.as_ref(), placed)?;
        // The box columns on the grid, `first..last`, and the grid column
        // of the first.
        let first = usize::try_from(-origin.1).unwrap_or(0).min(m1);
        let last = usize::try_from(columns as isize - origin.1)
            .unwrap_or(0)
            .clamp(first, m1);
        let column = |bj: usize| (origin.1 + bj as isize) as usize;
        let cells = column(first)..column(last);
        // The local grid row of (local) box row `b`, if on this rank.
        let grid_row = |b: usize| {
            usize::try_from(origin.0 + (boxed.start + b) as isize)
                .ok()
                .filter(|i| grid.contains(i))
                .map(|i| i - grid.start)
        };
        // Extended, the box's rows on this rank's band, and distributed the
        // members' residual on the rows past it.
        let slab = self.slab.as_ref();
        let band = extend.then(|| {
            let grid_rows = slab.map_or(local, |s| s.starts[s.starts.len() - 1]);
            let box_rows = usize::try_from(origin.0).unwrap_or(0)
                ..usize::try_from(origin.0 + m0 as isize)
                    .unwrap_or(0)
                    .min(grid_rows);
            Band::new(
                member,
                columns,
                cells.clone(),
                (grid.start, local),
                box_rows,
            )
        });
        let edges = match &band {
            Some(band) => band.edges(slab, residual),
            None => (None, None),
        };
        // The box rows are gathered as the convolution reads them.
        let load = |b: usize, line: &mut [T]| {
            line.fill(T::zero());
            if let Some(i) = grid_row(b) {
                if let Some(band) = &band {
                    band.spread(&mut line[first..last], i, residual, &edges, (shift, scale));
                    return;
                }
                let row = i * columns..(i + 1) * columns;
                for ((value, &m), &r) in line[first..last]
                    .iter_mut()
                    .zip(&member[row.clone()][cells.clone()])
                    .zip(&residual[row][cells.clone()])
                {
                    if m {
                        *value = T::narrow((r - shift) * scale);
                    }
                }
            }
        };
        // Each box row's grid row of `result` (rows off this rank's grid:
        // none), ...
        let mut rows: Vec<Option<&mut [f64]>> = result
            .chunks_exact_mut(columns.max(1))
            .map(|row| Some(&mut row[cells.clone()]))
            .collect();
        let targets = (0..boxed.len())
            .map(|b| grid_row(b).and_then(|i| rows.get_mut(i).and_then(Option::take)))
            .collect();
        // ... written on the members as the inverse transform makes it,
        // with the sums over them (extended: on every cell of the box,
        // gathered below).
        let sink = |b: usize, row: Option<&mut [f64]>, values: &[T]| {
            let mut sums = (0.0, 0.0);
            if let (Some(row), Some(i)) = (row, grid_row(b)) {
                for (((out, &m), &r), &z) in row
                    .iter_mut()
                    .zip(&member[i * columns..][cells.clone()])
                    .zip(&residual[i * columns..][cells.clone()])
                    .zip(&values[first..last])
                {
                    if extend {
                        *out = z.into() * unscale;
                    } else if m {
                        let z = z.into() * unscale;
                        *out = z;
                        sums.0 += z;
                        sums.1 += z * (r - shift);
                    }
                }
            }
            sums
        };
        let sums =
            self.convolution
                .apply_into(load, Scaled::exact(&self.multiplier), targets, sink)?;
        drop(rows);
        let Some(band) = band else {
            return Ok(sums
                .into_iter()
                .fold((0.0, 0.0), |(s, d), (a, b)| (s + a, d + b)));
        };
        // The transpose of the extension, with the box inverse's output off
        // the members on the rows past the band.
        let edges = band.edges(slab, result);
        Ok(band.gather(result, residual, &edges, shift))
    }

    /// This rank's grid rows and the box rows it holds, the box's first row
    /// being grid row `origin` of a grid whose rank holds `local` rows.
    /// Distributed, box rows above the grid go to the first rank, rows
    /// below it to the last, the others to the rank of their grid row; the
    /// convolution learns the new split.
    fn place(
        &mut self,
        origin: isize,
        local: usize,
    ) -> Result<(std::ops::Range<usize>, std::ops::Range<usize>)> {
        let m0 = self.data.0;
        let Some(slab) = self.slab.as_ref() else {
            return Ok((0..local, 0..m0));
        };
        let ranks = slab.exchange.ranks();
        // The box rows before rank k's band: those whose grid row lies
        // before its first row.
        let before = |k: usize| -> usize {
            if k == 0 {
                return 0;
            }
            if k == ranks {
                return m0;
            }
            usize::try_from(slab.starts[k] as isize - origin)
                .unwrap_or(0)
                .min(m0)
        };
        let counts: Vec<usize> = (0..ranks).map(|k| before(k + 1) - before(k)).collect();
        let rank = slab.exchange.rank();
        let boxed = before(rank)..before(rank + 1);
        let grid = slab.rows();
        self.convolution.set_row_counts(counts)?;
        Ok((grid, boxed))
    }
}

#[cfg(test)]
mod tests {
    use rand_chacha::rand_core::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use rand_distr::{Distribution, StandardNormal};

    use super::*;
    use crate::material::Material;
    use crate::substrate::Substrate;

    /// `P M^-1 P (r - shift)` and its two sums on a periodic 64^2 box of a
    /// film on glass, in precision `T`, the residual times `factor`.
    fn apply<T: Precision>(member: &[bool], values: &[f64], factor: f64) -> (Vec<f64>, (f64, f64)) {
        let film = Substrate::layer_on_elastic_base(
            Material::new(1e6, 0.49).unwrap(),
            2e-4,
            Material::new(7e10, 0.2).unwrap(),
        )
        .unwrap();
        let compliance = FourierCompliance::new(&film);
        let (n, delta) = (64, 1e-5);
        let mut inverse =
            BoxInverse::<T>::new(&compliance, 1e6, delta, (n, n), (n, n), None).unwrap();
        let scaled: Vec<f64> = values.iter().map(|v| v * factor).collect();
        let shift = 0.25 * factor;
        let residual = Residual {
            columns: n,
            origin: (0, 0),
            member,
            values: &scaled,
            shift,
            magnitude: scaled.iter().fold(0.0_f64, |m, v| m.max(v.abs())) + shift.abs(),
            extend: false,
        };
        let mut result = vec![0.0; n * n];
        let sums = inverse.apply_with(&residual, &mut result).unwrap();
        (result, sums)
    }

    #[test]
    fn single_precision_is_double_to_its_rounding_at_any_scale() {
        // A seeded residual on a random half of the cells.
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let values: Vec<f64> = (0..64 * 64)
            .map(|_| StandardNormal.sample(&mut rng))
            .collect();
        let member: Vec<bool> = values.iter().map(|v: &f64| v.fract().abs() < 0.5).collect();
        let (exact, exact_sums) = apply::<f64>(&member, &values, 1.0);
        let largest = exact.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(largest > 0.0);
        // Scales far outside f32's range (1e-38 to 3e38) without the
        // powers of two that move them into it.
        for factor in [1.0, 1e-45, 1e45] {
            let (single, sums) = apply::<f32>(&member, &values, factor);
            let error = single
                .iter()
                .zip(&exact)
                .fold(0.0_f64, |m, (s, e)| m.max((s / factor - e).abs()));
            // f32's unit rounding 6e-8, grown through the two transforms
            // of 64 points each way: measured 1.7e-7 of the largest value
            // at every factor, and 1.1e-7 on the sums (without the
            // scaling the factors 1e-45 and 1e45 fail).
            assert!(error < 2e-6 * largest, "{factor}: {error} of {largest}");
            assert!(
                (sums.0 / factor / exact_sums.0 - 1.0).abs() < 2e-6,
                "{sums:?}"
            );
            assert!((sums.1 / (factor * factor) / exact_sums.1 - 1.0).abs() < 2e-6);
        }
        // Off the members nothing is written.
        assert!(exact.iter().zip(&member).all(|(z, m)| *m || *z == 0.0));
    }
}
