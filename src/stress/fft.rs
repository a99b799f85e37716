//! A planned two-dimensional real FFT of a (padded) grid: rows by
//! `realfft`, columns by `rustfft`, both planned once (RustFFT's habit),
//! on all threads with the `parallel` feature. The half-spectrum is kept
//! column by column (`(columns/2 + 1) x rows`, each column contiguous), and
//! only the data rows of a padded grid are ever transformed along the rows:
//! the padding rows are zero going in, and not wanted coming out.

use std::sync::Arc;

use num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use crate::parallel::for_each_row;

/// Spectrum columns transformed per call (and per parallel task).
const COLUMN_BLOCK: usize = 16;

pub(super) struct Fft2 {
    /// FFT rows and columns (padded).
    rows: usize,
    columns: usize,
    /// Data rows and columns (the grid).
    data_rows: usize,
    data_columns: usize,
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
    /// The data rows' half-spectra, row-major `data_rows x half`.
    rows_spectra: Vec<Complex<f64>>,
}

impl Fft2 {
    /// Transforms of a `rows x columns` FFT grid whose first `data_rows x
    /// data_columns` values are the data.
    pub(super) fn new(rows: usize, columns: usize, data_rows: usize, data_columns: usize) -> Self {
        let mut real = RealFftPlanner::<f64>::new();
        let mut complex = FftPlanner::<f64>::new();
        Fft2 {
            rows,
            columns,
            data_rows,
            data_columns,
            row_forward: real.plan_fft_forward(columns),
            row_inverse: real.plan_fft_inverse(columns),
            column_forward: complex.plan_fft_forward(rows),
            column_inverse: complex.plan_fft_inverse(rows),
            rows_spectra: vec![Complex::default(); data_rows * (columns / 2 + 1)],
        }
    }

    /// FFT rows (padded): the length of a spectrum column.
    pub(super) fn rows(&self) -> usize {
        self.rows
    }

    /// Spectrum columns.
    pub(super) fn half(&self) -> usize {
        self.columns / 2 + 1
    }

    /// The half-spectrum (column by column) of `field`, the data
    /// (`data_rows x data_columns`, row-major) zero-padded.
    pub(super) fn forward(&mut self, field: &[f64], spectrum: &mut [Complex<f64>]) {
        let (columns, width, half) = (self.columns, self.data_columns, self.half());
        let plan = &self.row_forward;
        for_each_row(&mut self.rows_spectra, half, |i, out| {
            let mut real = vec![0.0; columns];
            real[..width].copy_from_slice(&field[i * width..(i + 1) * width]);
            // Lengths match the plan, so the transform cannot fail.
            let _ = plan.process(&mut real, out);
        });
        let (rows, data_rows) = (self.rows, self.data_rows);
        let spectra = &self.rows_spectra;
        let plan = &self.column_forward;
        for_each_row(spectrum, rows * COLUMN_BLOCK, |b, block| {
            for (c, column) in block.chunks_mut(rows).enumerate() {
                let j = b * COLUMN_BLOCK + c;
                for (i, value) in column.iter_mut().enumerate() {
                    *value = if i < data_rows {
                        spectra[i * half + j]
                    } else {
                        Complex::default()
                    };
                }
            }
            // The columns of a block in one call: one scratch for all.
            plan.process(block);
        });
    }

    /// The data rows and columns of the field of `spectrum` (column by
    /// column; overwritten), normalised, into `field`. The imaginary parts
    /// a real row transform ignores (its mean and, for an even width, its
    /// Nyquist bin) are set to zero.
    pub(super) fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        let (rows, half) = (self.rows, self.half());
        let plan = &self.column_inverse;
        for_each_row(spectrum, rows * COLUMN_BLOCK, |_, block| {
            plan.process(block)
        });
        let spectrum = &*spectrum;
        for_each_row(&mut self.rows_spectra, half, |i, row| {
            for (j, value) in row.iter_mut().enumerate() {
                *value = spectrum[j * rows + i];
            }
        });
        let (columns, width) = (self.columns, self.data_columns);
        let even = columns % 2 == 0;
        let scale = 1.0 / (self.rows * self.columns) as f64;
        let spectra = &self.rows_spectra;
        let plan = &self.row_inverse;
        for_each_row(field, width, |i, out| {
            let mut line = spectra[i * half..(i + 1) * half].to_vec();
            line[0].im = 0.0;
            if even {
                line[half - 1].im = 0.0;
            }
            let mut real = vec![0.0; columns];
            let _ = plan.process(&mut line, &mut real);
            for (o, v) in out.iter_mut().zip(&real) {
                *o = v * scale;
            }
        });
    }
}
