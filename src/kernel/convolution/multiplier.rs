//! Multipliers of a [`Convolution`]: the spectrum of
//! a kernel given in real space, and multipliers given as functions of the
//! wavevector, laid out as the column pass reads them.

use num_complex::Complex;

use super::{fft_error, zeroed, Convolution};
use crate::error::Result;

impl Convolution {
    /// The normalised real spectrum of a real kernel on the whole FFT grid
    /// that is even in the row index (row `i` equals row `height - i`),
    /// laid out as [`Convolution::apply`] takes it: `row(i, values)` fills
    /// row `i` (`i <= height / 2`) of width `size.1`. The spectrum of an
    /// even kernel is real and even; its imaginary rounding is dropped.
    pub(in crate::kernel) fn even_kernel_spectrum(
        &mut self,
        row: impl Fn(usize, &mut [f64]),
    ) -> Result<Vec<f64>> {
        let (n0, n1) = self.size;
        let half = n1 / 2 + 1;
        let distinct = n0 / 2 + 1;
        let mut row_spectra: Vec<Complex<f64>> = zeroed(distinct * half)?;
        let scratch = &mut self.tasks[0];
        for (i, spectrum) in row_spectra.chunks_exact_mut(half).enumerate() {
            row(i, &mut scratch.real);
            self.row_forward
                .process_with_scratch(&mut scratch.real, spectrum, &mut scratch.fft)
                .map_err(fft_error)?;
        }
        let normalisation = 1.0 / (n0 * n1) as f64;
        let mut spectrum = zeroed(half * distinct)?;
        let line = &mut scratch.lines[..n0];
        for (j, column) in spectrum.chunks_exact_mut(distinct).enumerate() {
            for (i, value) in line.iter_mut().enumerate() {
                *value = row_spectra[i.min(n0 - i) * half + j];
            }
            self.column_forward
                .process_with_scratch(line, &mut scratch.fft);
            for (k, value) in column.iter_mut().zip(line.iter()) {
                *k = value.re * normalisation;
            }
        }
        Ok(spectrum)
    }
}

/// The wavenumber (rad/m) of FFT index `index` on `n` cells of side `delta`,
/// indices above `n/2` standing for negative frequencies.
pub(crate) fn wavenumber(index: usize, n: usize, delta: f64) -> f64 {
    let k = if index <= n / 2 {
        index as f64
    } else {
        index as f64 - n as f64
    };
    2.0 * std::f64::consts::PI * k / (n as f64 * delta)
}

/// The multiplier `f(q_x, q_y)`, even in `q_x`, at the wavevectors of an FFT
/// grid of `size` with cells of side `delta`, divided by the FFT
/// normalisation and laid out for [`Convolution::apply`] (`q_x >= 0` only),
/// on the spectrum columns `columns` (of `size.1 / 2 + 1`: those a
/// convolution filters, [`Convolution::own_columns`]).
///
/// # Errors
/// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
pub(in crate::kernel) fn multiplier(
    size: (usize, usize),
    delta: f64,
    columns: std::ops::Range<usize>,
    f: impl Fn(f64, f64) -> f64 + Sync + Send,
) -> Result<Vec<f64>> {
    let (n0, n1) = size;
    let normalisation = 1.0 / (n0 * n1) as f64;
    let distinct = n0 / 2 + 1;
    let mut values = zeroed(columns.len() * distinct)?;
    // Columns on every thread: a layer's compliance at the 10.6 million
    // wavevectors of the 4608^2 box of a rough film at 4096^2 took 0.27 s
    // on one.
    crate::parallel::for_each_row(&mut values, distinct, |c, column| {
        let qy = wavenumber(columns.start + c, n1, delta);
        for (kx, value) in column.iter_mut().enumerate() {
            *value = f(wavenumber(kx, n0, delta), qy) * normalisation;
        }
    });
    Ok(values)
}
