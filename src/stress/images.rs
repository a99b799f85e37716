//! The field of an isolated contact's periodic images, computed on a
//! coarse grid and taken out of a padded plane.
//!
//! Zero-padding makes the FFT's convolution periodic: a padded plane holds
//! the field of the pressure plus that of its images, one period `L` away
//! and more (less their mean, which the long-wave mean mode restores).
//! Seen from the grid the images lie at least a grid's width away, so
//! their field is smooth there and depends on the pressure only through
//! its low moments: a coarse grid resolves it. The pressure is deposited
//! on cells `factor` fine cells wide by cloud-in-cell weights (which keep
//! its force and first moments), and the coarse planes are computed twice,
//! with the period `L` and with `LONG_PERIOD L`. Their difference is the
//! images' field at `L` less theirs at `LONG_PERIOD L` (the near field is
//! the same in both and cancels); interpolated back with the same weights
//! and subtracted, it leaves the images at the long period, a thousandth
//! of the short one's on a half-space. This is the particle-mesh idea of
//! Hockney & Eastwood (1988, ch. 5) applied to the images only.

use crate::error::Result;
use crate::grid::{fft_friendly, Boundary, Grid};
use crate::substrate::Substrate;

use super::field::SubsurfaceStress;
use super::{Side, StressPlane};

/// How much longer the coarse reference period is than the padded grid's.
pub(super) const LONG_PERIOD: usize = 8;

/// Coarse cells across the grid's shorter side (about): the images lie a
/// shorter side away.
const COARSE_CELLS: usize = 16;

/// Coarse cells along the longer side, at most (about): on a long strip the
/// coarse grid grows no further, and the images across it are resolved less
/// finely.
const MAX_COARSE_CELLS: usize = 128;

/// The coarse planes' filter cutoff over their Nyquist wavenumber (see
/// [`SubsurfaceStress::filtered`]): the filter is `e^-24` at Nyquist. A
/// sharper filter (`q^8`, `q^16`) keeps more of the far field but its
/// kernel's tail, wrapped round the short period, reaches the grid: on the
/// surface `sigma_zz = -p` then held to 5e-8 `p0` at best, here to 1e-11.
const CUTOFF: f64 = 0.45;

/// The images' field of one padded isolated grid.
pub(super) struct Images {
    /// Fine cells per coarse cell along each axis.
    factor: usize,
    /// Fine data rows and columns.
    rows: usize,
    columns: usize,
    /// The coarse planes with the padded grid's period and the long one.
    short: SubsurfaceStress,
    long: SubsurfaceStress,
}

/// The padded FFT size of `n` fine cells padded `padding` times, a
/// multiple of `factor` whose coarse count holds the deposit.
pub(super) fn padded_size(n: usize, padding: usize, factor: usize) -> usize {
    let coarse = fft_friendly(
        n.saturating_mul(padding)
            .div_ceil(factor)
            .max(coarse_cells(n, factor)),
    );
    coarse.saturating_mul(factor)
}

/// Coarse cells holding the deposit of `n` fine cells: one more on each
/// side.
fn coarse_cells(n: usize, factor: usize) -> usize {
    n.div_ceil(factor) + 2
}

impl Images {
    /// Fine cells per coarse cell on `grid`.
    pub(super) fn factor(grid: &Grid) -> usize {
        let (short, long) = (
            grid.rows().min(grid.columns()),
            grid.rows().max(grid.columns()),
        );
        short
            .div_ceil(COARSE_CELLS)
            .max(long.div_ceil(MAX_COARSE_CELLS))
    }

    /// The coarse plans for `grid` on `substrate`, whose padded grid is
    /// `padded` (each a multiple of `factor`, from [`padded_size`]).
    ///
    /// # Errors
    /// As [`SubsurfaceStress::with_padding`].
    pub(super) fn new(
        substrate: &Substrate,
        grid: &Grid,
        padded: (usize, usize),
        factor: usize,
    ) -> Result<Self> {
        let coarse = Grid::new(
            coarse_cells(grid.rows(), factor),
            coarse_cells(grid.columns(), factor),
            grid.spacing() * factor as f64,
        )?;
        let period = (padded.0 / factor, padded.1 / factor);
        let long = (LONG_PERIOD * period.0, LONG_PERIOD * period.1);
        let cutoff = CUTOFF * std::f64::consts::PI / coarse.spacing();
        let plan = |size| {
            SubsurfaceStress::planned(substrate, &coarse, Boundary::Isolated, size)
                .map(|plan| plan.filtered(cutoff))
        };
        Ok(Images {
            factor,
            rows: grid.rows(),
            columns: grid.columns(),
            short: plan(period)?,
            long: plan(long)?,
        })
    }

    /// Fine index `i`'s coarse neighbours along an axis: the lower one and
    /// the upper one's weight (the fine centre between the coarse centres;
    /// coarse cell 0 starts a coarse cell before the grid).
    fn weight(&self, i: usize) -> (usize, f64) {
        let t = (i as f64 + 0.5) / self.factor as f64 + 0.5;
        let lower = t.floor();
        (lower as usize, t - lower)
    }

    /// Takes the images' field out of `planes` (at `depths` on `side`,
    /// computed from `pressure` on the padded grid).
    ///
    /// # Errors
    /// As [`SubsurfaceStress::planes`].
    pub(super) fn remove(
        &mut self,
        pressure: &[f64],
        depths: &[f64],
        side: Side,
        planes: &mut [StressPlane],
    ) -> Result<()> {
        let width = coarse_cells(self.columns, self.factor);
        let rows: Vec<_> = (0..self.rows).map(|i| self.weight(i)).collect();
        let columns: Vec<_> = (0..self.columns).map(|j| self.weight(j)).collect();
        // The same force on cells factor^2 times larger, by cloud-in-cell.
        let area = 1.0 / (self.factor * self.factor) as f64;
        let mut coarse = vec![0.0; coarse_cells(self.rows, self.factor) * width];
        for (line, &(a, u)) in pressure.chunks_exact(self.columns).zip(&rows) {
            for (p, &(b, v)) in line.iter().zip(&columns) {
                let p = p * area;
                coarse[a * width + b] += (1.0 - u) * (1.0 - v) * p;
                coarse[a * width + b + 1] += (1.0 - u) * v * p;
                coarse[(a + 1) * width + b] += u * (1.0 - v) * p;
                coarse[(a + 1) * width + b + 1] += u * v * p;
            }
        }
        let short = self.short.planes(&coarse, depths, side)?;
        let long = self.long.planes(&coarse, depths, side)?;
        let mut images = vec![0.0; coarse.len()];
        for ((plane, short), long) in planes.iter_mut().zip(&short).zip(&long) {
            for ((fine, a), b) in plane
                .components_mut()
                .into_iter()
                .zip(short.components())
                .zip(long.components())
            {
                for ((image, a), b) in images.iter_mut().zip(a).zip(b) {
                    *image = a - b;
                }
                // Bilinear interpolation, the adjoint of the deposit.
                let images = &images;
                crate::parallel::for_each_row(fine, self.columns, |i, line| {
                    let (a, u) = rows[i];
                    let (upper, lower) = (&images[a * width..], &images[(a + 1) * width..]);
                    for (value, &(b, v)) in line.iter_mut().zip(&columns) {
                        let left = (1.0 - u) * upper[b] + u * lower[b];
                        let right = (1.0 - u) * upper[b + 1] + u * lower[b + 1];
                        *value -= (1.0 - v) * left + v * right;
                    }
                });
            }
        }
        Ok(())
    }
}
