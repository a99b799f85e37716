//! A planned two-dimensional real FFT of one grid: rows by `realfft`,
//! columns by `rustfft`, both planned once (RustFFT's habit).

use std::sync::Arc;

use num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

/// Forward and inverse transforms of a `rows x columns` real field to its
/// `rows x (columns/2 + 1)` half-spectrum (row-major, unnormalised forward,
/// normalised inverse).
pub(super) struct Fft2 {
    rows: usize,
    columns: usize,
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
    real: Vec<f64>,
    line: Vec<Complex<f64>>,
    column: Vec<Complex<f64>>,
}

impl Fft2 {
    pub(super) fn new(rows: usize, columns: usize) -> Self {
        let mut real = RealFftPlanner::<f64>::new();
        let mut complex = FftPlanner::<f64>::new();
        Fft2 {
            rows,
            columns,
            row_forward: real.plan_fft_forward(columns),
            row_inverse: real.plan_fft_inverse(columns),
            column_forward: complex.plan_fft_forward(rows),
            column_inverse: complex.plan_fft_inverse(rows),
            real: vec![0.0; columns],
            line: vec![Complex::default(); columns / 2 + 1],
            column: vec![Complex::default(); rows],
        }
    }

    fn half(&self) -> usize {
        self.columns / 2 + 1
    }

    /// The half-spectrum of `field` into `spectrum`.
    pub(super) fn forward(&mut self, field: &[f64], spectrum: &mut [Complex<f64>]) {
        let half = self.half();
        for i in 0..self.rows {
            self.real
                .copy_from_slice(&field[i * self.columns..(i + 1) * self.columns]);
            // Lengths match the plan, so the transform cannot fail.
            let _ = self.row_forward.process(&mut self.real, &mut self.line);
            spectrum[i * half..(i + 1) * half].copy_from_slice(&self.line);
        }
        for j in 0..half {
            for i in 0..self.rows {
                self.column[i] = spectrum[i * half + j];
            }
            self.column_forward.process(&mut self.column);
            for i in 0..self.rows {
                spectrum[i * half + j] = self.column[i];
            }
        }
    }

    /// The field of the half-spectrum `spectrum` (overwritten) into
    /// `field`, normalised. The imaginary parts a real row transform
    /// ignores (its mean and, for an even width, its Nyquist bin) are set
    /// to zero.
    pub(super) fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        let half = self.half();
        for j in 0..half {
            for i in 0..self.rows {
                self.column[i] = spectrum[i * half + j];
            }
            self.column_inverse.process(&mut self.column);
            for i in 0..self.rows {
                spectrum[i * half + j] = self.column[i];
            }
        }
        let scale = 1.0 / (self.rows * self.columns) as f64;
        for i in 0..self.rows {
            self.line
                .copy_from_slice(&spectrum[i * half..(i + 1) * half]);
            self.line[0].im = 0.0;
            if self.columns % 2 == 0 {
                self.line[half - 1].im = 0.0;
            }
            let _ = self.row_inverse.process(&mut self.line, &mut self.real);
            for (out, v) in field[i * self.columns..(i + 1) * self.columns]
                .iter_mut()
                .zip(&self.real)
            {
                *out = v * scale;
            }
        }
    }
}
