//! A convolution with a real kernel even in both offsets on a small grid:
//! the two-level preconditioner's coarse matrix on the grid of blocks
//! (`solver::coarse_space`), through the same real FFTs as the compliance
//! operator.

use super::convolution::Convolution;
use crate::error::Result;

/// `output = k * input` on a grid of `rows x columns`, periodic or
/// zero-padded to twice each side.
pub(crate) struct EvenConvolution {
    convolution: Convolution,
    multiplier: Vec<f64>,
}

impl EvenConvolution {
    /// The kernel `k(i, j) = kernel[i * columns + j]` at offsets `0 <= i <
    /// rows`, `0 <= j < columns`, even in each (`k(-i, j) = k(i, j)`; on a
    /// periodic grid also `k(rows - i, j) = k(i, j)`).
    ///
    /// # Errors
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) for the buffers.
    pub(crate) fn new(kernel: &[f64], rows: usize, columns: usize, periodic: bool) -> Result<Self> {
        let size = if periodic {
            (rows, columns)
        } else {
            (2 * rows, 2 * columns)
        };
        let mut convolution = Convolution::new(rows, columns, size)?;
        let offset = |k: usize, n: usize| if periodic || k <= n / 2 { k } else { n - k };
        let multiplier = convolution.even_kernel_spectrum(|i, row| {
            for (j, value) in row.iter_mut().enumerate() {
                let j = offset(j, size.1);
                *value = if i < rows && j < columns {
                    kernel[i * columns + j]
                } else {
                    0.0
                };
            }
        })?;
        Ok(EvenConvolution {
            convolution,
            multiplier,
        })
    }

    /// `output = k * input` over the grid's `rows x columns` values.
    ///
    /// # Errors
    /// [`Error::Internal`](crate::Error::Internal) if an FFT fails.
    pub(crate) fn apply(&mut self, input: &[f64], output: &mut [f64]) -> Result<()> {
        self.convolution.apply(input, output, &self.multiplier)
    }
}
