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

use crate::parallel::{for_each_row, for_each_row_with};

/// Spectrum columns transformed per call (and per parallel task), at most.
const COLUMN_BLOCK: usize = 16;

/// Rows of a field transformed back per task.
const ROW_GROUP: usize = 16;

/// Bytes of the lines of one field a block of columns fills at once.
const BLOCK_BYTES: usize = 1 << 18;

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
    /// The filtered fields' data rows, per block of columns (see
    /// [`Fft2::inverse_filtered`]).
    tiles: Vec<Complex<f64>>,
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
            tiles: Vec::new(),
        }
    }

    /// FFT rows (padded): the length of a spectrum column.
    pub(super) fn rows(&self) -> usize {
        self.rows
    }

    /// FFT columns (padded).
    pub(super) fn columns(&self) -> usize {
        self.columns
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

    /// The data rows and columns of `K` fields whose spectra are
    /// `spectrum` (column by column) times per-bin multipliers, normalised,
    /// into `fields`. `multipliers(j, i)` gives the `K` multipliers of the
    /// bin in spectrum column `j` and row `i` (read once per bin for all
    /// fields), real or, where `imaginary` says, times the imaginary unit;
    /// blocks of columns are filtered
    /// and transformed back together, and only their data rows kept. The
    /// imaginary parts a real row transform ignores (its mean and, for an
    /// even width, its Nyquist bin) are set to zero.
    pub(super) fn inverse_filtered<const K: usize>(
        &mut self,
        spectrum: &[Complex<f64>],
        multipliers: impl Fn(usize, usize) -> [f64; K] + Sync,
        imaginary: [bool; K],
        fields: [&mut [f64]; K],
    ) {
        let (rows, half, data_rows) = (self.rows, self.half(), self.data_rows);
        let tile_len = K * data_rows;
        self.tiles.resize(tile_len * half, Complex::default());
        let plan = &self.column_inverse;
        // Per block of columns, `K` row-major tiles of `data_rows x width`.
        // Columns per block: one field's lines fit in the second-level
        // cache; the block's multipliers of all fields are found first, then
        // each field is filtered and transformed back in turn.
        let block = (BLOCK_BYTES / (16 * rows)).clamp(1, COLUMN_BLOCK);
        let scratch_len = plan.get_inplace_scratch_len();
        let init = || {
            (
                vec![[0.0; K]; block * rows],
                vec![Complex::default(); block * rows],
                vec![Complex::default(); scratch_len],
            )
        };
        for_each_row_with(
            &mut self.tiles,
            tile_len * block,
            init,
            |(factors, lines, scratch), b, tiles| {
                let width = tiles.len() / tile_len;
                let j0 = b * block;
                let (factors, lines) = (&mut factors[..width * rows], &mut lines[..width * rows]);
                for (w, column) in factors.chunks_exact_mut(rows).enumerate() {
                    for (i, m) in column.iter_mut().enumerate() {
                        *m = multipliers(j0 + w, i);
                    }
                }
                let spectrum = &spectrum[j0 * rows..(j0 + width) * rows];
                for (c, tile) in tiles.chunks_exact_mut(data_rows * width).enumerate() {
                    for ((line, v), m) in lines.iter_mut().zip(spectrum).zip(&*factors) {
                        let m = m[c];
                        *line = if imaginary[c] {
                            Complex::new(-v.im * m, v.re * m)
                        } else {
                            v * m
                        };
                    }
                    plan.process_with_scratch(lines, scratch);
                    // The data rows, transposed into the tile row by row
                    // (its writes in order, the reads in `width` streams).
                    for (i, out) in tile.chunks_exact_mut(width).enumerate() {
                        for (w, value) in out.iter_mut().enumerate() {
                            *value = lines[w * rows + i];
                        }
                    }
                }
            },
        );
        let (columns, data_columns) = (self.columns, self.data_columns);
        let even = columns % 2 == 0;
        let scale = 1.0 / (self.rows * self.columns) as f64;
        let tiles = &self.tiles;
        let plan = &self.row_inverse;
        let init = || {
            (
                vec![Complex::default(); ROW_GROUP * half],
                vec![0.0; columns],
                vec![Complex::default(); plan.get_scratch_len()],
            )
        };
        // Rows in groups: a group's values in a tile are contiguous.
        for (c, field) in fields.into_iter().enumerate() {
            for_each_row_with(
                field,
                ROW_GROUP * data_columns,
                init,
                |(lines, real, scratch), g, out| {
                    let first = g * ROW_GROUP;
                    let count = out.len() / data_columns;
                    for (b, tile) in tiles.chunks(tile_len * block).enumerate() {
                        let width = tile.len() / tile_len;
                        let group = &tile[(c * data_rows + first) * width..][..count * width];
                        for (line, row) in
                            lines.chunks_exact_mut(half).zip(group.chunks_exact(width))
                        {
                            line[b * block..][..width].copy_from_slice(row);
                        }
                    }
                    for (line, out) in lines
                        .chunks_exact_mut(half)
                        .zip(out.chunks_exact_mut(data_columns))
                    {
                        line[0].im = 0.0;
                        if even {
                            line[half - 1].im = 0.0;
                        }
                        // Lengths match the plan, so the transform cannot fail.
                        let _ = plan.process_with_scratch(line, real, scratch);
                        for (o, v) in out.iter_mut().zip(real.iter()) {
                            *o = v * scale;
                        }
                    }
                },
            );
        }
    }
}
