//! Rough surfaces: seeded self-affine topographies by Fourier synthesis
//! (height maps from files: [`HeightMap::from_npy`], [`HeightMap::from_text`]).
//!
//! A self-affine (fractal) surface has the isotropic power spectral density
//! (Persson et al. 2005, J. Phys.: Condens. Matter 17, R1; Jacobs, Junge &
//! Pastewka 2017, Surf. Topogr.: Metrol. Prop. 5, 013001)
//!
//! ```text
//! C(q) = C0                          q < q_r (roll-off)
//! C(q) = C0 (q / q_r)^(-2 (1 + H))   q_r <= q <= q_s
//! C(q) = 0                           q > q_s
//! ```
//!
//! with Hurst exponent `H`, roll-off wavevector `q_r = 2 pi / lambda_r` and
//! short-wavelength cut-off `q_s = 2 pi / lambda_s`. Each Fourier
//! coefficient of a realisation is `sqrt(C(q))` times a complex Gaussian
//! number drawn from a ChaCha8 generator seeded by the caller (the same seed
//! gives the same surface on every machine); the mean height is zero, and
//! `C0` is chosen so that the realisation has exactly the requested rms
//! height or rms slope (the slope from the spectrum, `sqrt(sum q^2
//! |h_q|^2)`). The surface is periodic on its grid.
//!
//! The random numbers are drawn per wavevector of the grid, so a new grid
//! draws a new surface. For a convergence study in the grid, synthesise
//! once on the coarsest grid (its short cut-off at least two cells) and
//! interpolate onto the finer ones with
//! [`HeightMap::refined`](crate::indenter::HeightMap::refined): the
//! surface is band-limited, and the finer grids then carry the same
//! continuous surface.
//!
//! ```
//! use layered_contact::topography::{Amplitude, SelfAffine};
//! use layered_contact::Grid;
//!
//! let grid = Grid::square_of_side(256, 1e-3)?; // 1 mm, 256 x 256
//! let surface = SelfAffine {
//!     hurst: 0.8,
//!     amplitude: Amplitude::RmsHeight(1e-6),
//!     long_cutoff: 0.5e-3,
//!     short_cutoff: 8.0 * grid.spacing(),
//!     seed: 42,
//! };
//! let heights = surface.heights(&grid)?;
//! let mean = heights.iter().sum::<f64>() / heights.len() as f64;
//! let rms = (heights.iter().map(|h| h * h).sum::<f64>() / heights.len() as f64).sqrt();
//! assert!(mean.abs() < 1e-18 && (rms / 1e-6 - 1.0).abs() < 1e-12);
//! Ok::<(), layered_contact::Error>(())
//! ```

use std::f64::consts::PI;

use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use realfft::RealFftPlanner;

use num_complex::Complex;

use crate::error::{Error, Result};
use crate::grid::Grid;
use crate::indenter::HeightMap;
use crate::kernel::wavenumber;
use crate::slab::{agree, even_starts, lengths, Slab};

/// How large a synthesised surface is.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Amplitude {
    /// Root-mean-square height, m.
    RmsHeight(f64),
    /// Root-mean-square slope (dimensionless).
    RmsSlope(f64),
}

/// A self-affine random surface (see the [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct SelfAffine {
    /// Hurst exponent `H`, in `(0, 1)`.
    pub hurst: f64,
    /// The rms height or slope of the realisation.
    pub amplitude: Amplitude,
    /// Roll-off wavelength `lambda_r`, m: the spectrum is flat at longer
    /// wavelengths (use the grid's side for none).
    pub long_cutoff: f64,
    /// Short-wavelength cut-off `lambda_s`, m: no shorter wavelengths (at
    /// least two cells; a few cells more resolve the asperities).
    pub short_cutoff: f64,
    /// Seed of the random numbers.
    pub seed: u64,
}

impl SelfAffine {
    /// The heights of a realisation on `grid` (m, row-major, zero mean,
    /// periodic on the grid).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for `H` outside `(0, 1)`, a non-positive
    /// or non-finite amplitude, a short cut-off below two cells or above the
    /// long one, or a surface without any mode between them on this grid.
    pub fn heights(&self, grid: &Grid) -> Result<Vec<f64>> {
        self.synthesise(grid, None)
    }

    /// The heights of the rows of `grid` that `slab` gives this rank (all
    /// of them when `slab` is `None`), equal bit for bit to those rows of
    /// [`heights`](Self::heights): a distributed run synthesises its share
    /// of a surface, not the whole of it on every rank.
    ///
    /// Every rank draws the whole sequence of random numbers (cheap beside
    /// the transforms) and keeps the coefficients of its band of columns of
    /// the half-spectrum. It transforms those columns, exchanges the blocks
    /// once (a transpose, as the split convolution does) and transforms its
    /// rows. The sums that normalise the surface are taken in the serial
    /// order: the spectrum's as the coefficients are drawn, the heights' row
    /// by row, each row's sum added over the ranks (where the other ranks
    /// add zeros) and the rows then summed in order. A rank that fails (to
    /// allocate, say) says so to the others before the next exchange, so
    /// that every rank returns the error and none waits.
    pub(crate) fn synthesise(&self, grid: &Grid, slab: Option<&Slab>) -> Result<Vec<f64>> {
        self.check(grid)?;
        let (n0, n1) = (grid.rows(), grid.columns());
        let delta = grid.spacing();
        let half = n1 / 2 + 1;
        let (q_r, q_s) = (2.0 * PI / self.long_cutoff, 2.0 * PI / self.short_cutoff);
        let exponent = -(1.0 + self.hurst); // of the amplitude, sqrt(C)
        let rows = slab.map_or(0..n0, Slab::rows);
        let (rank, ranks) = slab.map_or((0, 1), |s| (s.exchange.rank(), s.exchange.ranks()));
        let column_starts = even_starts(half, ranks);
        let own = column_starts[rank]..column_starts[rank + 1];
        let width = own.len();
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        // This rank's columns of the half-spectrum, row-major (kx, ky).
        let mut spectrum: Vec<Complex<f64>> = agree(
            slab,
            crate::error::zeroed(n0 * width, "rough-surface spectrum"),
        )?;
        // The columns ky = 0 (and ky = n1/2) hold their own conjugates:
        // they are made Hermitian in kx, so that their transforms are real,
        // from the partners kept here.
        let self_conjugate = |ky: usize| ky == 0 || (n1 % 2 == 0 && ky == n1 / 2);
        let mut partners = [vec![Complex::default(); n0], vec![Complex::default(); n0]];
        let (mut height_sum, mut slope_sum) = (0.0, 0.0);
        for kx in 0..n0 {
            let qx = wavenumber(kx, n0, delta);
            let partner = (n0 - kx) % n0;
            for ky in 0..half {
                let q = qx.hypot(wavenumber(ky, n1, delta));
                let re: f64 = StandardNormal.sample(&mut rng);
                let im: f64 = StandardNormal.sample(&mut rng);
                let mut c = if q == 0.0 || q > q_s {
                    Complex::default()
                } else {
                    Complex::new(re, im) * (q.max(q_r) / q_r).powf(exponent)
                };
                // Bins with a conjugate partner in the other half count twice.
                let weight = if self_conjugate(ky) {
                    let column = &mut partners[usize::from(ky != 0)];
                    if partner == kx {
                        c.im = 0.0;
                    } else if partner < kx {
                        c = column[partner].conj();
                    }
                    column[kx] = c;
                    1.0
                } else {
                    2.0
                };
                let power = weight * c.norm_sqr();
                height_sum += power;
                slope_sum += q * q * power;
                if own.contains(&ky) {
                    spectrum[kx * width + ky - own.start] = c;
                }
            }
        }
        if height_sum == 0.0 {
            return Err(Error::InvalidParameter {
                name: "short_cutoff (m)",
                value: self.short_cutoff,
                expected:
                    "a band with at least one wavevector of the grid below 2 pi / short_cutoff",
            });
        }
        // Parseval: the rms of the inverse transform (unnormalised) is
        // sqrt(sum |c|^2) / N over the full spectrum.
        let cells = (n0 * n1) as f64;
        let scale = match self.amplitude {
            Amplitude::RmsHeight(h) => h * cells / height_sum.sqrt(),
            Amplitude::RmsSlope(s) => s * cells / slope_sum.sqrt(),
        } / cells;
        // Inverse 2D transform: complex columns, then complex-to-real rows.
        let columns = rustfft::FftPlanner::<f64>::new().plan_fft_inverse(n0);
        let mut line = vec![Complex::default(); n0];
        for j in 0..width {
            for (kx, value) in line.iter_mut().enumerate() {
                *value = spectrum[kx * width + j] * scale;
            }
            columns.process(&mut line);
            for (kx, value) in line.iter().enumerate() {
                spectrum[kx * width + j] = *value;
            }
        }
        let mut spectrum = match slab {
            Some(slab) => transpose(slab, spectrum, &column_starts, half)?,
            None => spectrum,
        };
        let plan = RealFftPlanner::<f64>::new().plan_fft_inverse(n1);
        let heights = crate::error::zeroed(rows.len() * n1, "rough-surface heights").and_then(
            |mut heights: Vec<f64>| {
                for (row, out) in spectrum
                    .chunks_exact_mut(half)
                    .zip(heights.chunks_exact_mut(n1))
                {
                    row[0].im = 0.0;
                    if n1 % 2 == 0 {
                        row[half - 1].im = 0.0;
                    }
                    plan.process(row, out).map_err(|e| Error::Internal {
                        what: "rough-surface synthesis",
                        detail: e.to_string(),
                    })?;
                }
                Ok(heights)
            },
        );
        drop(spectrum);
        let mut heights = agree(slab, heights)?;
        // Cancel the mean's rounding and the rms height's.
        let mean = grid_sum(slab, n0, rows.start, &heights, n1, |h| h) / cells;
        heights.iter_mut().for_each(|h| *h -= mean);
        if let Amplitude::RmsHeight(target) = self.amplitude {
            let rms = (grid_sum(slab, n0, rows.start, &heights, n1, |h| h * h) / cells).sqrt();
            heights.iter_mut().for_each(|h| *h *= target / rms);
        }
        agree(
            slab,
            crate::solver::all_finite("rough-surface synthesis", &heights),
        )?;
        Ok(heights)
    }

    /// The realisation as a rigid indenter on `grid`: the surface turned
    /// upside down, `f = max(h) - h`, so that its highest summit touches
    /// first, at depth 0.
    ///
    /// # Errors
    /// As [`SelfAffine::heights`].
    pub fn indenter(&self, grid: &Grid) -> Result<HeightMap> {
        self.indenter_on(grid, None)
    }

    /// The realisation as a rigid indenter, holding only the rows of `grid`
    /// that `slab` gives this rank (all of them when `slab` is `None`):
    /// what a distributed run's rank samples. Its top is the whole
    /// surface's.
    ///
    /// # Errors
    /// As [`SelfAffine::heights`].
    pub(crate) fn indenter_on(&self, grid: &Grid, slab: Option<&Slab>) -> Result<HeightMap> {
        let heights = self.synthesise(grid, slab)?;
        let mut top = [-heights.iter().copied().fold(f64::NEG_INFINITY, f64::max)];
        if let Some(slab) = slab {
            slab.exchange.min(&mut top);
        }
        let top = -top[0];
        let first_row = slab.map_or(0, |s| s.rows().start);
        HeightMap::band(*grid, first_row, heights.iter().map(|h| top - h).collect())
    }

    pub(crate) fn check(&self, grid: &Grid) -> Result<()> {
        if !(self.hurst > 0.0 && self.hurst < 1.0) {
            return Err(Error::InvalidParameter {
                name: "hurst",
                value: self.hurst,
                expected: "in (0, 1)",
            });
        }
        let (name, amplitude) = match self.amplitude {
            Amplitude::RmsHeight(h) => ("rms height (m)", h),
            Amplitude::RmsSlope(s) => ("rms slope", s),
        };
        crate::error::positive_finite(name, amplitude)?;
        crate::error::positive_finite("long_cutoff (m)", self.long_cutoff)?;
        let shortest = 2.0 * grid.spacing();
        if !(self.short_cutoff >= shortest * (1.0 - 1e-12) && self.short_cutoff <= self.long_cutoff)
        {
            return Err(Error::InvalidParameter {
                name: "short_cutoff (m)",
                value: self.short_cutoff,
                expected: "at least two cells and at most long_cutoff",
            });
        }
        // The longest wavelength of the grid, 2 pi / (n Delta), must lie in
        // the band for the surface to have a mode.
        let longest = grid.rows().max(grid.columns()) as f64 * grid.spacing();
        if self.short_cutoff > longest * (1.0 + 1e-12) {
            return Err(Error::InvalidParameter {
                name: "short_cutoff (m)",
                value: self.short_cutoff,
                expected:
                    "a band with at least one wavevector of the grid below 2 pi / short_cutoff",
            });
        }
        Ok(())
    }
}

/// This rank's columns of the half-spectrum, all rows (row-major, `width`
/// columns), turned into this rank's rows, all `half` columns: one
/// exchange of blocks between every pair of ranks.
fn transpose(
    slab: &Slab,
    spectrum: Vec<Complex<f64>>,
    column_starts: &[usize],
    half: usize,
) -> Result<Vec<Complex<f64>>> {
    let rank = slab.exchange.rank();
    let width = column_starts[rank + 1] - column_starts[rank];
    let rows = slab.rows().len();
    let widths = lengths(column_starts);
    let send_counts: Vec<usize> = slab.counts().iter().map(|r| r * width).collect();
    let receive_counts: Vec<usize> = widths.iter().map(|w| w * rows).collect();
    let mut receive: Vec<Complex<f64>> = agree(
        Some(slab),
        crate::error::zeroed(rows * half, "rough-surface spectrum (exchanged)"),
    )?;
    slab.exchange
        .all_to_all(&spectrum, &send_counts, &mut receive, &receive_counts);
    drop(spectrum);
    let mut assembled: Vec<Complex<f64>> = agree(
        Some(slab),
        crate::error::zeroed(rows * half, "rough-surface spectrum (rows)"),
    )?;
    let mut blocks = receive.as_slice();
    for (&start, &w) in column_starts.iter().zip(&widths) {
        let (block, rest) = blocks.split_at(w * rows);
        for (i, part) in block.chunks_exact(w.max(1)).take(rows).enumerate() {
            assembled[i * half + start..i * half + start + w].copy_from_slice(&part[..w]);
        }
        blocks = rest;
    }
    Ok(assembled)
}

/// The sum of `f` over the whole grid's heights, of which this rank holds
/// rows `first_row..` (`heights`, `columns` a row), in the serial order:
/// each row summed, the rows' sums added over the ranks (each row's sum is
/// nonzero on one rank only, so that adds nothing to its rounding), then
/// summed in row order.
fn grid_sum(
    slab: Option<&Slab>,
    grid_rows: usize,
    first_row: usize,
    heights: &[f64],
    columns: usize,
    f: impl Fn(f64) -> f64,
) -> f64 {
    let mut sums = vec![0.0; grid_rows];
    for (i, row) in heights.chunks_exact(columns).enumerate() {
        sums[first_row + i] = row.iter().map(|&h| f(h)).sum();
    }
    if let Some(slab) = slab {
        slab.sum(&mut sums);
    }
    sums.iter().sum()
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::indenter::Indenter;

    /// Split across 1 to 5 ranks (threads), each rank's rows of the
    /// surface and of its indenter equal the serial ones bit for bit: even
    /// and odd column counts, rows that do not divide evenly, and more
    /// ranks than some bands of columns hold.
    #[test]
    fn a_split_synthesis_equals_the_serial_one() {
        for (rows, columns, amplitude) in [
            (64, 48, Amplitude::RmsHeight(1e-6)),
            (30, 45, Amplitude::RmsSlope(0.1)),
            (20, 6, Amplitude::RmsHeight(2e-6)),
        ] {
            let grid = Grid::new(rows, columns, 1e-6).unwrap();
            let surface = SelfAffine {
                hurst: 0.7,
                amplitude,
                long_cutoff: 16e-6,
                short_cutoff: 2e-6,
                seed: 11,
            };
            let serial = surface.heights(&grid).unwrap();
            let map = surface.indenter(&grid).unwrap();
            for ranks in 1..=5 {
                let shares = crate::slab::threads::run(ranks, |exchange| {
                    let slab = Slab::new(Arc::clone(&exchange), rows, 1).unwrap();
                    let heights = surface.synthesise(&grid, Some(&slab)).unwrap();
                    let band = surface.indenter_on(&grid, Some(&slab)).unwrap();
                    (slab.rows(), heights, band)
                });
                for (rows, heights, band) in shares {
                    let own = &serial[rows.start * columns..rows.end * columns];
                    assert_eq!(heights, own, "{ranks} ranks, rows {rows:?}");
                    assert_eq!(
                        band.heights(),
                        &map.heights()[rows.start * columns..rows.end * columns]
                    );
                    // The band reads its own rows as the whole map does.
                    for i in [rows.start, rows.end - 1] {
                        let (x, y) = grid.cell_centre(i, columns - 1);
                        assert_eq!(band.height(x, y), map.height(x, y));
                    }
                }
            }
        }
    }
}
