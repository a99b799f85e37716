//! The split of a [`Convolution`] across the ranks of a distributed run:
//! each rank transforms its own data rows (passes 1 and 3) and its own
//! spectrum columns (pass 2), and two all-to-all exchanges carry the
//! half-spectra between the two, the transposes of a slab-decomposed 2D FFT.

use num_complex::Complex;

use super::{widen, zeroed, Convolution, Precision};
use crate::error::{Error, Result};
use crate::slab::{even_starts, Slab};

/// How a distributed convolution splits its work: each rank transforms its
/// own data rows (passes 1 and 3) and its own spectrum columns (pass 2);
/// two all-to-all exchanges carry the half-spectra between the two.
pub(super) struct Split {
    pub(super) slab: Slab,
    /// Data rows of each rank (in rank order; they add up to `rows`).
    pub(super) row_counts: Vec<usize>,
    /// Spectrum columns: rank `k` filters `columns[k]..columns[k + 1]`.
    pub(super) columns: Vec<usize>,
    /// The exchanges' buffers, `f64` whatever the convolution's type (an
    /// `f32` value is carried exactly).
    pub(super) send: Vec<Complex<f64>>,
    pub(super) receive: Vec<Complex<f64>>,
}

impl Split {
    pub(super) fn rank(&self) -> usize {
        self.slab.exchange.rank()
    }

    /// The spectrum columns rank `k` filters.
    pub(super) fn columns_of(&self, k: usize) -> std::ops::Range<usize> {
        self.columns[k]..self.columns[k + 1]
    }

    /// This rank's spectrum columns.
    pub(super) fn own_columns(&self) -> std::ops::Range<usize> {
        self.columns_of(self.rank())
    }

    /// How many spectrum columns rank `k` filters.
    pub(super) fn width(&self, k: usize) -> usize {
        self.columns_of(k).len()
    }
}

impl<T: Precision> Convolution<T> {
    /// As [`Convolution::new`], split across the ranks of `slab`: this rank
    /// holds `row_counts[rank]` of the `rows` data rows (rank `k` the band
    /// after those of ranks `0..k`) and filters an even share of the
    /// spectrum columns. Every rank must apply it together.
    pub(in crate::kernel) fn distributed(
        rows: usize,
        columns: usize,
        size: (usize, usize),
        slab: &Slab,
        row_counts: Vec<usize>,
    ) -> Result<Self> {
        let mut convolution = Self::distributed_unallocated(rows, columns, size, slab, row_counts)?;
        convolution.ensure_split_buffers()?;
        Ok(convolution)
    }

    /// As [`Convolution::distributed`], without the rows' half-spectra and
    /// the exchanges' buffers: for a convolution that works in another's,
    /// lent to it ([`Convolution::give_buffers`]; any missing are allocated
    /// at the first application).
    pub(in crate::kernel) fn distributed_unallocated(
        rows: usize,
        columns: usize,
        size: (usize, usize),
        slab: &Slab,
        row_counts: Vec<usize>,
    ) -> Result<Self> {
        let half = size.1 / 2 + 1;
        let split = Split {
            slab: slab.clone(),
            columns: even_starts(half, slab.exchange.ranks()),
            row_counts: Vec::new(),
            send: Vec::new(),
            receive: Vec::new(),
        };
        let mut convolution = Self::build(rows, columns, size, Some(split))?;
        convolution.store_row_counts(row_counts)?;
        Ok(convolution)
    }

    /// Sets how many data rows each rank holds (a distributed convolution
    /// only; a box placed anew on the grid changes them), growing the
    /// buffers if needed.
    pub(in crate::kernel) fn set_row_counts(&mut self, row_counts: Vec<usize>) -> Result<()> {
        self.store_row_counts(row_counts)?;
        self.ensure_split_buffers()
    }

    /// [`Convolution::set_row_counts`] without growing the buffers.
    fn store_row_counts(&mut self, row_counts: Vec<usize>) -> Result<()> {
        let Some(split) = self.split.as_mut() else {
            return Ok(());
        };
        if row_counts.len() != split.slab.exchange.ranks()
            || row_counts.iter().sum::<usize>() != self.rows
        {
            return Err(Error::Internal {
                what: "distributed FFT",
                detail: format!("row counts {row_counts:?} do not split {} rows", self.rows),
            });
        }
        split.row_counts = row_counts;
        let local = self.local_rows();
        self.rows_per_task = local.div_ceil(self.tasks.len()).max(1);
        Ok(())
    }

    /// Distributed: grows the rows' half-spectra and the exchanges' buffers
    /// to what the row counts need (they may have been lent away:
    /// [`Convolution::take_buffers`]).
    pub(super) fn ensure_split_buffers(&mut self) -> Result<()> {
        let Some(split) = self.split.as_mut() else {
            return Ok(());
        };
        let half = self.size.1 / 2 + 1;
        let local = split.row_counts[split.rank()];
        let width = split.width(split.rank());
        let exchanged = (local * half).max(self.rows * width);
        // MPI counts are 32-bit.
        if exchanged > i32::MAX as usize {
            return Err(Error::InvalidParameter {
                name: "half-spectrum values one rank exchanges",
                value: exchanged as f64,
                expected: "below 2^31 (MPI counts): use more ranks",
            });
        }
        fn grow(buffer: &mut Vec<Complex<f64>>, len: usize) -> Result<()> {
            if buffer.len() < len {
                *buffer = Vec::new();
                *buffer = zeroed(len)?;
            }
            Ok(())
        }
        grow(&mut self.row_spectra, T::stored(local * half))?;
        grow(&mut split.send, exchanged)?;
        grow(&mut split.receive, exchanged)
    }

    /// Distributed: sends each rank the spectrum columns it filters of this
    /// rank's rows, and receives this rank's columns of every row, as a
    /// row-major `rows x width` matrix in `receive`.
    pub(super) fn exchange_to_columns(&mut self) -> Result<()> {
        let Some(split) = self.split.as_mut() else {
            return Ok(());
        };
        let (rank, ranks) = (split.rank(), split.slab.exchange.ranks());
        let half = self.size.1 / 2 + 1;
        let local = split.row_counts[rank];
        let mut at = 0;
        for k in 0..ranks {
            let columns = split.columns_of(k);
            for row in T::view(&self.row_spectra)[..local * half].chunks_exact(half) {
                let values = &row[columns.clone()];
                for (sent, value) in split.send[at..at + values.len()].iter_mut().zip(values) {
                    *sent = widen(*value);
                }
                at += values.len();
            }
        }
        let send_counts: Vec<usize> = (0..ranks).map(|k| local * split.width(k)).collect();
        let width = split.width(rank);
        let receive_counts: Vec<usize> = split.row_counts.iter().map(|r| r * width).collect();
        split.slab.exchange.all_to_all(
            &split.send[..at],
            &send_counts,
            &mut split.receive[..self.rows * width],
            &receive_counts,
        );
        Ok(())
    }

    /// Distributed: sends each rank its rows of the columns filtered here,
    /// and receives this rank's rows of every rank's columns (per rank `k`
    /// a row-major `local rows x width(k)` matrix, in rank order, in
    /// `receive`).
    pub(super) fn exchange_to_rows(&mut self) -> Result<()> {
        let Some(split) = self.split.as_mut() else {
            return Ok(());
        };
        let (rank, ranks) = (split.rank(), split.slab.exchange.ranks());
        let (rows, block) = (self.rows, self.block);
        let width = split.width(rank);
        let mut at = 0;
        for i in 0..rows {
            let buffer = &T::view(&self.tiles)[..self.tiles_len];
            for tile in super::tiles(buffer, rows, block, width) {
                let w = tile.len() / rows;
                let values = &tile[i * w..(i + 1) * w];
                for (sent, value) in split.send[at..at + w].iter_mut().zip(values) {
                    *sent = widen(*value);
                }
                at += w;
            }
        }
        let send_counts: Vec<usize> = split.row_counts.iter().map(|r| r * width).collect();
        let local = split.row_counts[rank];
        let receive_counts: Vec<usize> = (0..ranks).map(|k| local * split.width(k)).collect();
        split.slab.exchange.all_to_all(
            &split.send[..at],
            &send_counts,
            &mut split.receive[..local * (self.size.1 / 2 + 1)],
            &receive_counts,
        );
        Ok(())
    }
}
