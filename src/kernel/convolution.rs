//! Two-dimensional FFT convolution of a grid of cells with a real
//! multiplier, zero-padded or periodic, in three cache-blocked passes that
//! run on all threads.
//!
//! 1. Rows: each data row, zero-padded to the FFT width, goes through a
//!    real-to-complex FFT, and its half-spectrum is cut into the tiles of
//!    `tiles`: per block of a few adjacent spectrum columns, a row-major
//!    tile of `rows x block` values.
//! 2. Columns: the columns of each tile are gathered into contiguous lines
//!    (a blocked transpose), padded with zeros to the FFT height,
//!    transformed, multiplied, transformed back, and their data rows
//!    written back into the tile, in place.
//! 3. Rows again: each row is gathered from the tiles (the blocked
//!    transpose back), goes through the complex-to-real FFT, and its data
//!    columns are the output.
//!
//! Nothing of the padded grid is ever stored whole: the buffers hold the
//! `rows x (width/2 + 1)` half-spectra of the data rows once (16 bytes per
//! cell of an unpadded grid with an even number of columns, twice that
//! split across ranks, whose exchanges need their own) and a few lines per
//! thread. Each row and column is transformed by the same code whatever
//! the number of threads, so results do not depend on it.

use std::sync::Arc;

use num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use crate::error::{Error, Result};

mod energy;
mod exchange;
mod multiplier;
mod precision;
mod rows_out;
mod tiling;

use energy::{line_energy, Stage};
use exchange::Split;
pub(super) use multiplier::multiplier;
pub(crate) use multiplier::wavenumber;
pub(crate) use precision::{power_of_two_above, Precision};
use tiling::{tiles, tiles_mut, TILE_PAD};

/// Bytes of the column lines a thread transforms at once (a block fits in
/// the second-level cache).
const BLOCK_BYTES: usize = 1 << 18;

/// The fewest spectrum columns in a block (see [`BLOCK_BYTES`]): on a
/// periodic 8192^2 grid, whose blocks would otherwise hold 2 columns, the
/// rough film of `BENCHMARKS.md` took 182 s with 2 and 144 s with 16.
const MIN_BLOCK: usize = 16;

/// Plans and scratch of one convolution geometry, in `f64` or `f32`
/// ([`Precision`]).
pub(super) struct Convolution<T: Precision = f64> {
    /// Data rows and columns (the grid).
    rows: usize,
    columns: usize,
    /// FFT height and width (padded or not).
    size: (usize, usize),
    row_forward: Arc<dyn RealToComplex<T>>,
    row_inverse: Arc<dyn ComplexToReal<T>>,
    column_forward: Arc<dyn Fft<T>>,
    column_inverse: Arc<dyn Fft<T>>,
    /// Distributed only: half-spectra of this rank's data rows, `local x
    /// half`, row-major (serial runs cut them into `tiles` directly); kept
    /// as `Complex<f64>` values whatever `T`, as `tiles`.
    row_spectra: Vec<Complex<f64>>,
    /// The half-spectra of the data rows (serial) or this rank's filtered
    /// columns of every row (distributed): per block of `block` columns a
    /// row-major tile of `rows x block`; kept as `Complex<f64>` values
    /// whatever `T` ([`Precision::view`]), so that one buffer can be lent
    /// between convolutions of either type.
    tiles: Vec<Complex<f64>>,
    /// The values of `T` the tiles take (they may be released or lent
    /// between applications, and are allocated again when needed).
    tiles_len: usize,
    tasks: Vec<Scratch<T>>,
    rows_per_task: usize,
    /// Spectrum columns per block and blocks per task.
    block: usize,
    blocks_per_task: usize,
    /// The split across the ranks of a distributed run, `None` when serial.
    split: Option<Split>,
}

/// A convolution's large buffers, lent between convolutions
/// ([`Convolution::take_buffers`]).
pub(super) struct Buffers {
    tiles: Vec<Complex<f64>>,
    row_spectra: Vec<Complex<f64>>,
    send: Vec<Complex<f64>>,
    receive: Vec<Complex<f64>>,
}

/// One thread's scratch.
struct Scratch<T> {
    /// One padded real row.
    real: Vec<T>,
    /// A block of column lines, or a group of row spectra.
    lines: Vec<Complex<T>>,
    fft: Vec<Complex<T>>,
}

/// Tasks the passes are split into: one per thread (with the `parallel`
/// feature, and for grids of at least 2^16 FFT cells, below which the fork
/// costs more than it saves), else one.
fn task_count(fft_cells: usize) -> usize {
    #[cfg(feature = "parallel")]
    {
        if fft_cells >= 1 << 16 {
            return rayon::current_num_threads().max(1);
        }
    }
    let _ = fft_cells;
    1
}

/// Runs `f` on every task, in parallel with the `parallel` feature.
fn run_tasks<T: Send>(tasks: Vec<T>, f: impl Fn(T) -> Result<()> + Sync + Send) -> Result<()> {
    #[cfg(feature = "parallel")]
    if tasks.len() > 1 {
        use rayon::prelude::*;
        return tasks.into_par_iter().try_for_each(f);
    }
    tasks.into_iter().try_for_each(f)
}

/// A zeroed FFT buffer of `len` values, or [`Error::OutOfMemory`].
pub(super) fn zeroed<T: Clone + Default>(len: usize) -> Result<Vec<T>> {
    crate::error::zeroed(len, "an FFT buffer")
}

/// The loader of a grid's data rows (`columns` values each) for the
/// forward pass.
fn data_rows(input: &[f64], columns: usize) -> impl Fn(usize, &mut [f64]) + Sync + '_ {
    move |i, line| line.copy_from_slice(&input[i * columns..(i + 1) * columns])
}

/// The nearest complex value of type `T` (the distributed exchanges carry
/// `f64` whatever the convolution's type: exact both ways for `f32`).
fn narrow<T: Precision>(value: Complex<f64>) -> Complex<T> {
    Complex::new(T::narrow(value.re), T::narrow(value.im))
}

/// The `f64` value of a complex value of type `T` (exact).
fn widen<T: Precision>(value: Complex<T>) -> Complex<f64> {
    Complex::new(value.re.into(), value.im.into())
}

/// A multiplier and the factor its values are multiplied by as they are
/// narrowed to the convolution's type (a power of two that brings an `f64`
/// multiplier into `f32`'s range without rounding it; 1 where the types
/// match).
#[derive(Clone, Copy)]
pub(crate) struct Scaled<'a, M> {
    pub(crate) values: &'a [M],
    pub(crate) scale: f64,
}

impl<'a, M> Scaled<'a, M> {
    /// The multiplier as it is.
    pub(crate) fn exact(values: &'a [M]) -> Self {
        Scaled { values, scale: 1.0 }
    }
}

/// Buffer sizes are fixed at construction, so an FFT error is a bug of this
/// module; it is reported rather than unwrapped.
fn fft_error(error: realfft::FftError) -> Error {
    Error::Internal {
        what: "FFT",
        detail: error.to_string(),
    }
}

impl<T: Precision> Convolution<T> {
    /// Bytes of the buffers of a serial convolution of data of `rows` rows
    /// on an FFT grid of `size`, besides the multipliers.
    pub(super) fn memory(rows: usize, size: (usize, usize)) -> usize {
        let half = size.1 / 2 + 1;
        size_of::<Complex<T>>() * rows * half + Self::scratch_memory(size)
    }

    /// Bytes of the per-thread scratch alone (a convolution that works in
    /// another's buffers, [`Convolution::take_buffers`]).
    pub(super) fn scratch_memory(size: (usize, usize)) -> usize {
        let tasks = task_count(size.0 * size.1);
        let (real, complex) = (size_of::<T>(), size_of::<Complex<T>>());
        tasks * (real * size.1 + BLOCK_BYTES + complex * size.0)
    }

    /// Plans and buffers for `rows x columns` data on an FFT grid of `size`
    /// (`size.0 >= rows`, `size.1 >= columns`; larger means zero-padded).
    pub(super) fn new(rows: usize, columns: usize, size: (usize, usize)) -> Result<Self> {
        Self::build(rows, columns, size, None)
    }

    fn build(
        rows: usize,
        columns: usize,
        size: (usize, usize),
        split: Option<Split>,
    ) -> Result<Self> {
        let (n0, n1) = size;
        let mut real_planner = RealFftPlanner::<T>::new();
        let row_forward = real_planner.plan_fft_forward(n1);
        let row_inverse = real_planner.plan_fft_inverse(n1);
        let mut planner = FftPlanner::<T>::new();
        let column_forward = planner.plan_fft_forward(n0);
        let column_inverse = planner.plan_fft_inverse(n0);
        let half = n1 / 2 + 1;
        let fft_scratch = [
            row_forward.get_scratch_len(),
            row_inverse.get_scratch_len(),
            column_forward.get_inplace_scratch_len(),
            column_inverse.get_inplace_scratch_len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        let tasks = task_count(n0 * n1);
        // The spectrum columns this process filters.
        let width = split.as_ref().map_or(half, |s| s.width(s.rank()));
        // At least MIN_BLOCK columns: the row passes copy a block's piece
        // of each row, and pieces of one or two values cost more in calls
        // than a block that spills to the next cache level (tall grids).
        let line_bytes = size_of::<Complex<T>>() * n0;
        let block = (BLOCK_BYTES / line_bytes).clamp(MIN_BLOCK.min(width.max(1)), width.max(1));
        let blocks = width.div_ceil(block);
        let lines = (block * n0).max(half);
        let scratch = (0..tasks)
            .map(|_| {
                Ok(Scratch {
                    real: zeroed(n1)?,
                    lines: zeroed(lines)?,
                    fft: zeroed(fft_scratch)?,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let local_rows = if split.is_some() { 0 } else { rows };
        Ok(Convolution {
            rows,
            columns,
            size,
            row_forward,
            row_inverse,
            column_forward,
            column_inverse,
            row_spectra: Vec::new(),
            // Allocated by the first application.
            tiles: Vec::new(),
            tiles_len: rows * width + blocks * TILE_PAD,
            tasks: scratch,
            rows_per_task: local_rows.div_ceil(tasks),
            block,
            blocks_per_task: blocks.div_ceil(tasks),
            split,
        })
    }

    /// Takes the largest buffer (the tiles of the half-spectra) out, to
    /// free it or lend it to another convolution that is not applied at
    /// the same time ([`Convolution::give_tiles`]); the next application
    /// without it allocates one.
    pub(super) fn take_tiles(&mut self) -> Vec<Complex<f64>> {
        std::mem::take(&mut self.tiles)
    }

    /// Gives this convolution `tiles` as its buffer (taken from another
    /// with [`Convolution::take_tiles`]; used if large enough), in place of
    /// its own.
    pub(super) fn give_tiles(&mut self, tiles: Vec<Complex<f64>>) {
        self.tiles = tiles;
    }

    /// This process's data rows.
    fn local_rows(&self) -> usize {
        self.split
            .as_ref()
            .map_or(self.rows, |s| s.row_counts[s.rank()])
    }

    /// The spectrum columns this process filters, as a range of the
    /// `size.1 / 2 + 1` columns of the half-spectrum.
    pub(super) fn own_columns(&self) -> std::ops::Range<usize> {
        self.split
            .as_ref()
            .map_or(0..self.size.1 / 2 + 1, Split::own_columns)
    }

    /// The FFT grid (height, width).
    pub(super) fn size(&self) -> (usize, usize) {
        self.size
    }

    /// The tiles, allocated again if they were released or lent away
    /// (every value is written before it is read, so the new buffer needs
    /// no particular content).
    fn ensure_tiles(&mut self) -> Result<()> {
        let stored = T::stored(self.tiles_len);
        if self.tiles.len() < stored {
            self.tiles = Vec::new();
            self.tiles = zeroed(stored)?;
        }
        self.ensure_split_buffers()
    }

    /// Takes every large buffer out (the tiles, and when distributed the
    /// rows' half-spectra and the exchanges' buffers), to lend them to
    /// another convolution of the same split that is not applied at the
    /// same time ([`Convolution::give_buffers`]).
    pub(super) fn take_buffers(&mut self) -> Buffers {
        let (send, receive) = match self.split.as_mut() {
            Some(split) => (
                std::mem::take(&mut split.send),
                std::mem::take(&mut split.receive),
            ),
            None => (Vec::new(), Vec::new()),
        };
        Buffers {
            tiles: self.take_tiles(),
            row_spectra: std::mem::take(&mut self.row_spectra),
            send,
            receive,
        }
    }

    /// Gives this convolution the buffers taken from another
    /// ([`Convolution::take_buffers`]); any too small for it is allocated
    /// again at the next application.
    pub(super) fn give_buffers(&mut self, buffers: Buffers) {
        self.give_tiles(buffers.tiles);
        self.row_spectra = buffers.row_spectra;
        if let Some(split) = self.split.as_mut() {
            split.send = buffers.send;
            split.receive = buffers.receive;
        }
    }

    /// As [`Convolution::apply`], the input's data row `i` (of this rank)
    /// written into `line` by `load(i, line)` instead of read from a grid:
    /// a gather from elsewhere needs no buffer of its own.
    pub(super) fn apply_loaded<M: Copy + Into<f64> + Sync>(
        &mut self,
        load: impl Fn(usize, &mut [T]) + Sync,
        output: &mut [f64],
        multiplier: Scaled<'_, M>,
        combine: impl Fn(f64, T) -> f64 + Sync,
    ) -> Result<()> {
        let columns = self.columns;
        let rows = output[..self.local_rows() * columns].chunks_exact_mut(columns);
        self.apply_into(load, multiplier, rows.collect(), |_, row, values| {
            for (out, value) in row.iter_mut().zip(values) {
                *out = combine(*out, *value);
            }
        })?;
        Ok(())
    }

    /// As [`Convolution::apply_loaded`], each output data row `i` (of this
    /// rank) handed to `sink(i, target, values)` with `targets[i]` instead
    /// of combined into an output grid: a pass that reads the result once
    /// (a masked copy, sums over it) runs inside the transform's last pass.
    /// Returns the sinks' results in row order (to be added in that order:
    /// the same whatever the threads).
    pub(super) fn apply_into<M: Copy + Into<f64> + Sync, O: Send, S: Send>(
        &mut self,
        load: impl Fn(usize, &mut [T]) + Sync,
        multiplier: Scaled<'_, M>,
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[T]) -> S + Sync,
    ) -> Result<Vec<S>> {
        if targets.len() != self.local_rows() {
            return Err(Error::Internal {
                what: "convolution",
                detail: format!(
                    "{} output rows for {} data rows",
                    targets.len(),
                    self.local_rows()
                ),
            });
        }
        self.ensure_tiles()?;
        self.forward_rows(load)?;
        self.exchange_to_columns()?;
        self.filter_columns(multiplier, Stage::Filter)?;
        self.exchange_to_rows()?;
        self.inverse_rows(targets, sink)
    }

    /// Pass 1: real-to-complex transforms of the zero-padded data rows,
    /// into the tiles (serial) or `row_spectra` (distributed).
    fn forward_rows(&mut self, load: impl Fn(usize, &mut [T]) + Sync) -> Result<()> {
        let (rows, columns, half) = (self.rows, self.columns, self.size.1 / 2 + 1);
        let per_task = self.rows_per_task;
        let fft = &self.row_forward;
        let local = self.local_rows();
        // The data rows of each task.
        let bands = (0..local)
            .step_by(per_task.max(1))
            .map(|i| i..(i + per_task).min(local));
        if self.split.is_some() {
            let tasks: Vec<_> = bands
                .zip(T::view_mut(&mut self.row_spectra)[..local * half].chunks_mut(per_task * half))
                .zip(self.tasks.iter_mut())
                .collect();
            return run_tasks(tasks, |((band, spectra), scratch)| {
                for (i, spectrum) in band.zip(spectra.chunks_exact_mut(half)) {
                    load(i, &mut scratch.real[..columns]);
                    scratch.real[columns..].fill(T::zero());
                    fft.process_with_scratch(&mut scratch.real, spectrum, &mut scratch.fft)
                        .map_err(fft_error)?;
                }
                Ok(())
            });
        }
        // Each task's rows of every tile.
        let mut pieces: Vec<Vec<&mut [Complex<T>]>> =
            (0..self.tasks.len()).map(|_| Vec::new()).collect();
        let buffer = &mut T::view_mut(&mut self.tiles)[..self.tiles_len];
        for tile in tiles_mut(buffer, rows, self.block, half) {
            let width = tile.len() / rows;
            for (piece, task) in tile.chunks_mut(per_task * width).zip(pieces.iter_mut()) {
                task.push(piece);
            }
        }
        let block = self.block;
        let tasks: Vec<_> = bands.zip(pieces).zip(self.tasks.iter_mut()).collect();
        run_tasks(tasks, |((band, mut pieces), scratch)| {
            let spectrum = &mut scratch.lines[..half];
            for (r, i) in band.enumerate() {
                load(i, &mut scratch.real[..columns]);
                scratch.real[columns..].fill(T::zero());
                fft.process_with_scratch(&mut scratch.real, spectrum, &mut scratch.fft)
                    .map_err(fft_error)?;
                for (values, piece) in spectrum.chunks(block).zip(pieces.iter_mut()) {
                    let width = values.len();
                    piece[r * width..(r + 1) * width].copy_from_slice(values);
                }
            }
            Ok(())
        })
    }

    /// Pass 2: column transforms, multiplication, inverse column transforms
    /// ([`Stage::Filter`]), or the forward transforms only
    /// ([`Stage::Energy`]). Returns the sum over this process's columns of
    /// the spectrum of `multiplier |X|^2` for [`Stage::Energy`] (0
    /// otherwise), added block by block in order whatever the number of
    /// threads.
    fn filter_columns<M: Copy + Into<f64> + Sync>(
        &mut self,
        multiplier: Scaled<'_, M>,
        stage: Stage,
    ) -> Result<f64> {
        let Scaled {
            values: multiplier,
            scale,
        } = multiplier;
        let (rows, n0) = (self.rows, self.size.0);
        let even = self.size.1.is_multiple_of(2);
        let half = self.size.1 / 2 + 1;
        // The first of this process's spectrum columns.
        let own = self.own_columns().start;
        let (block, per_task) = (self.block, self.blocks_per_task * self.block);
        let (forward, inverse) = (&self.column_forward, &self.column_inverse);
        // Distributed, the rows' spectra of the columns filtered here arrive
        // row-major, of `stride` values per row; serial, they are in the
        // tiles, filtered in place.
        let (received, stride): (Option<&[Complex<f64>]>, usize) = match &self.split {
            Some(split) => (Some(&split.receive), split.width(split.rank())),
            None => (None, self.size.1 / 2 + 1),
        };
        // Each task's tiles.
        let mut groups = Vec::with_capacity(self.tasks.len());
        let buffer = &mut T::view_mut(&mut self.tiles)[..self.tiles_len];
        let mut rest: Vec<_> = tiles_mut(buffer, rows, block, stride).collect();
        while !rest.is_empty() {
            let tail = rest.split_off(self.blocks_per_task.min(rest.len()));
            groups.push(std::mem::replace(&mut rest, tail));
        }
        // One energy per block, added in block order below.
        let mut energies = vec![0.0; groups.iter().map(Vec::len).sum()];
        let tasks: Vec<_> = groups
            .into_iter()
            .zip(energies.chunks_mut(self.blocks_per_task.max(1)))
            .zip(self.tasks.iter_mut())
            .enumerate()
            .collect();
        run_tasks(tasks, |(task, ((group, energies), scratch))| {
            let first = task * per_task;
            for (b, (tile, energy)) in group.into_iter().zip(energies).enumerate() {
                let j0 = first + b * block;
                let width = tile.len() / rows;
                let lines = &mut scratch.lines[..width * n0];
                // Gather the block's columns (a blocked transpose).
                for (w, line) in lines.chunks_exact_mut(n0).enumerate() {
                    match received {
                        Some(source) => {
                            let column = source[j0 + w..].iter().step_by(stride);
                            for (value, spectrum) in line[..rows].iter_mut().zip(column) {
                                *value = narrow(*spectrum);
                            }
                        }
                        None => {
                            let column = tile[w..].iter().step_by(width);
                            for (value, spectrum) in line[..rows].iter_mut().zip(column) {
                                *value = *spectrum;
                            }
                        }
                    }
                    line[rows..].fill(Complex::default());
                }
                forward.process_with_scratch(lines, &mut scratch.fft);
                // Row wavenumber index i > n0/2 has the multiplier of n0 - i.
                let distinct = n0 / 2 + 1;
                for (w, (line, k)) in lines
                    .chunks_exact_mut(n0)
                    .zip(multiplier[j0 * distinct..].chunks_exact(distinct))
                    .enumerate()
                {
                    let (low, high) = line.split_at_mut(distinct);
                    let high_k = k[1..=n0 - distinct].iter().rev();
                    if stage == Stage::Energy {
                        // The columns other than 0 and n1/2 stand for
                        // their mirror too.
                        let j = own + j0 + w;
                        let single = j == 0 || (even && j == half - 1);
                        *energy += line_energy(low, high, k, if single { 1.0 } else { 2.0 });
                        continue;
                    }
                    // (Exact where `M` is `T` and the scale 1.)
                    for (c, k) in low.iter_mut().zip(k) {
                        *c = *c * T::narrow((*k).into() * scale);
                    }
                    for (c, k) in high.iter_mut().zip(high_k) {
                        *c = *c * T::narrow((*k).into() * scale);
                    }
                }
                if stage == Stage::Energy {
                    continue;
                }
                inverse.process_with_scratch(lines, &mut scratch.fft);
                // Store the data rows as a row-major tile of `rows x width`.
                for (w, line) in lines.chunks_exact(n0).enumerate() {
                    for (value, out) in line[..rows].iter().zip(tile[w..].iter_mut().step_by(width))
                    {
                        *out = *value;
                    }
                }
            }
            Ok(())
        })?;
        Ok(energies.into_iter().sum())
    }
}

/// The compliance operator's applications, in double precision.
impl Convolution {
    /// `output = IFFT2(multiplier * FFT2(input))` restricted to the data
    /// cells, `input` zero-padded to the FFT grid; the multiplier is even in
    /// the row wavenumber (every multiplier here is: a function of `|q|`
    /// times the cell's even filter) and given by its `height / 2 + 1` rows
    /// of non-negative row wavenumbers for each of the spectrum columns
    /// [`Convolution::own_columns`] (column-major), the FFT normalisation
    /// included. Distributed, `input` and `output` are this rank's data rows.
    pub(super) fn apply(
        &mut self,
        input: &[f64],
        output: &mut [f64],
        multiplier: &[f64],
    ) -> Result<()> {
        self.apply_combined(input, output, multiplier, |_, value| value)
    }

    /// As [`Convolution::apply`], each output value `v` made
    /// `combine(output, v)` (an addition needs no buffer for the response).
    pub(crate) fn apply_combined(
        &mut self,
        input: &[f64],
        output: &mut [f64],
        multiplier: &[f64],
        combine: impl Fn(f64, f64) -> f64 + Sync,
    ) -> Result<()> {
        let load = data_rows(input, self.columns);
        self.apply_loaded(load, output, Scaled::exact(multiplier), combine)
    }

    /// As [`Convolution::apply_into`], the input read from the grid `input`.
    pub(crate) fn apply_input_into<O: Send, S: Send>(
        &mut self,
        input: &[f64],
        multiplier: &[f64],
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[f64]) -> S + Sync,
    ) -> Result<Vec<S>> {
        let load = data_rows(input, self.columns);
        self.apply_into(load, Scaled::exact(multiplier), targets, sink)
    }
}
