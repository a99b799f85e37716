//! Pass 3 of a convolution: the complex-to-real transforms of the filtered
//! rows, each data row handed to a sink with its target (an output grid's
//! row, or what a fused pass needs).

use super::tiling::tiles;
use super::{fft_error, narrow, run_tasks, Convolution, Precision};
use crate::error::Result;

impl<T: Precision> Convolution<T> {
    /// Pass 3: complex-to-real transforms of the filtered rows; the data
    /// columns of row `i` go to `sink(i, targets[i], values)`, whose results
    /// come back in row order.
    pub(super) fn inverse_rows<O: Send, S: Send>(
        &mut self,
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[T]) -> S + Sync,
    ) -> Result<Vec<S>> {
        let (rows, columns, half) = (self.rows, self.columns, self.size.1 / 2 + 1);
        let even = self.size.1.is_multiple_of(2);
        let per_task = self.rows_per_task.max(1);
        let block = self.block;
        let fft = &self.row_inverse;
        let filtered = &T::view(&self.tiles)[..self.tiles_len];
        let split = self.split.as_ref();
        let local = self.local_rows();
        let mut results: Vec<Option<S>> = (0..targets.len()).map(|_| None).collect();
        let mut targets = targets.into_iter();
        let groups: Vec<Vec<O>> = (0..local.div_ceil(per_task))
            .map(|_| targets.by_ref().take(per_task).collect())
            .collect();
        let tasks: Vec<_> = groups
            .into_iter()
            .zip(results.chunks_mut(per_task))
            .zip(self.tasks.iter_mut())
            .enumerate()
            .collect();
        run_tasks(tasks, |(task, ((group, results), scratch))| {
            for (r, (target, result)) in group.into_iter().zip(results).enumerate() {
                let i = task * per_task + r;
                let spectrum = &mut scratch.lines[..half];
                match split {
                    // Gather the row from every rank's block of columns.
                    Some(split) => {
                        let mut at = 0;
                        for k in 0..split.slab.exchange.ranks() {
                            let columns = split.columns_of(k);
                            let w = columns.len();
                            let received = &split.receive[at + i * w..at + (i + 1) * w];
                            for (value, r) in spectrum[columns].iter_mut().zip(received) {
                                *value = narrow(*r);
                            }
                            at += local * w;
                        }
                    }
                    // Gather the row from the tiles of pass 2.
                    None => {
                        for (j0, tile) in (0..half)
                            .step_by(block)
                            .zip(tiles(filtered, rows, block, half))
                        {
                            let width = tile.len() / rows;
                            spectrum[j0..j0 + width]
                                .copy_from_slice(&tile[i * width..(i + 1) * width]);
                        }
                    }
                }
                // A real signal has real DC and Nyquist terms; clear the rounding.
                spectrum[0].im = T::zero();
                if even {
                    spectrum[half - 1].im = T::zero();
                }
                fft.process_with_scratch(spectrum, &mut scratch.real, &mut scratch.fft)
                    .map_err(fft_error)?;
                *result = Some(sink(i, target, &scratch.real[..columns]));
            }
            Ok(())
        })?;
        Ok(results.into_iter().flatten().collect())
    }
}
