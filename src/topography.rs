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

use crate::error::{Error, Result};
use crate::grid::Grid;
use crate::indenter::HeightMap;
use crate::kernel::wavenumber;

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
        self.check(grid)?;
        let (n0, n1) = (grid.rows(), grid.columns());
        let delta = grid.spacing();
        let half = n1 / 2 + 1;
        let (q_r, q_s) = (2.0 * PI / self.long_cutoff, 2.0 * PI / self.short_cutoff);
        let exponent = -(1.0 + self.hurst); // of the amplitude, sqrt(C)
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let mut spectrum: Vec<num_complex::Complex<f64>> =
            crate::error::zeroed(n0 * half, "rough-surface spectrum")?;
        for kx in 0..n0 {
            let qx = wavenumber(kx, n0, delta);
            for ky in 0..half {
                let qy = wavenumber(ky, n1, delta);
                let q = qx.hypot(qy);
                let re: f64 = StandardNormal.sample(&mut rng);
                let im: f64 = StandardNormal.sample(&mut rng);
                if q == 0.0 || q > q_s {
                    continue;
                }
                let amplitude = (q.max(q_r) / q_r).powf(exponent);
                spectrum[kx * half + ky] = num_complex::Complex::new(re, im) * amplitude;
            }
        }
        // The columns ky = 0 (and ky = n1/2) hold their own conjugates:
        // make them Hermitian in kx so that their transforms are real.
        for ky in std::iter::once(0).chain((n1 % 2 == 0).then_some(n1 / 2)) {
            for kx in 0..n0 {
                let partner = (n0 - kx) % n0;
                let index = kx * half + ky;
                if partner == kx {
                    spectrum[index].im = 0.0;
                } else if partner < kx {
                    spectrum[index] = spectrum[partner * half + ky].conj();
                }
            }
        }
        let (mut height_sum, mut slope_sum) = (0.0, 0.0);
        for kx in 0..n0 {
            let qx = wavenumber(kx, n0, delta);
            for ky in 0..half {
                let q = qx.hypot(wavenumber(ky, n1, delta));
                // Bins with a conjugate partner in the other half count twice.
                let weight = if ky == 0 || (n1 % 2 == 0 && ky == n1 / 2) {
                    1.0
                } else {
                    2.0
                };
                let power = weight * spectrum[kx * half + ky].norm_sqr();
                height_sum += power;
                slope_sum += q * q * power;
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
        let mut planner = rustfft::FftPlanner::<f64>::new();
        let columns = planner.plan_fft_inverse(n0);
        let mut line = vec![num_complex::Complex::default(); n0];
        for ky in 0..half {
            for (kx, value) in line.iter_mut().enumerate() {
                *value = spectrum[kx * half + ky] * scale;
            }
            columns.process(&mut line);
            for (kx, value) in line.iter().enumerate() {
                spectrum[kx * half + ky] = *value;
            }
        }
        let rows = RealFftPlanner::<f64>::new().plan_fft_inverse(n1);
        let mut heights: Vec<f64> = crate::error::zeroed(n0 * n1, "rough-surface heights")?;
        for (row, out) in spectrum
            .chunks_exact_mut(half)
            .zip(heights.chunks_exact_mut(n1))
        {
            row[0].im = 0.0;
            if n1 % 2 == 0 {
                row[half - 1].im = 0.0;
            }
            rows.process(row, out).map_err(|e| Error::Internal {
                what: "rough-surface synthesis",
                detail: e.to_string(),
            })?;
        }
        // Cancel the mean's rounding and the rms height's.
        let mean = heights.iter().sum::<f64>() / cells;
        heights.iter_mut().for_each(|h| *h -= mean);
        if let Amplitude::RmsHeight(target) = self.amplitude {
            let rms = (heights.iter().map(|h| h * h).sum::<f64>() / cells).sqrt();
            heights.iter_mut().for_each(|h| *h *= target / rms);
        }
        crate::solver::all_finite("rough-surface synthesis", &heights)?;
        Ok(heights)
    }

    /// The realisation as a rigid indenter on `grid`: the surface turned
    /// upside down, `f = max(h) - h`, so that its highest summit touches
    /// first, at depth 0.
    ///
    /// # Errors
    /// As [`SelfAffine::heights`].
    pub fn indenter(&self, grid: &Grid) -> Result<HeightMap> {
        let heights = self.heights(grid)?;
        let top = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        HeightMap::new(*grid, heights.iter().map(|h| top - h).collect())
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
