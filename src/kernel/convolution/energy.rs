//! The energy `x . (K x)` of a convolution from the forward transform
//! alone (Parseval's theorem), half a round trip: the constrained conjugate
//! gradients take their step length from it where the step will clamp
//! pressures and the whole change of the pressure is convolved anyway.

use crate::error::Result;

use super::{Convolution, Stage};

impl Convolution {
    /// `input . IFFT2(multiplier * FFT2(input))` over the data cells, from
    /// the spectrum of the zero-padded input (Parseval's theorem on the
    /// half-spectrum: a padded grid's circular convolution equals the
    /// linear one where the input is nonzero). Distributed, this process's
    /// share (its spectrum columns), to be summed over the ranks; `input`
    /// is then this rank's data rows.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) if the tiles
    /// cannot be allocated again; an exchange's error when distributed.
    pub(crate) fn forward_energy(&mut self, input: &[f64], multiplier: &[f64]) -> Result<f64> {
        self.ensure_tiles()?;
        let columns = self.columns;
        self.forward_rows(|i, line| line.copy_from_slice(&input[i * columns..(i + 1) * columns]))?;
        self.exchange_to_columns()?;
        self.filter_columns(multiplier, Stage::Energy)
    }
}
