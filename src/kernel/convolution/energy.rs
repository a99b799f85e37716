//! The energy `x . (K x)` of a convolution from the forward transform
//! alone (Parseval's theorem), half a round trip: the constrained conjugate
//! gradients take their step length from it where the step will clamp
//! pressures and the whole change of the pressure is convolved anyway.

use num_complex::Complex;

use crate::error::Result;

use super::{Convolution, Precision};

/// Which part of the column pass runs.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Stage {
    /// Forward, multiply, inverse.
    Filter,
    /// Forward only, the energy `multiplier |X|^2` summed.
    Energy,
}

/// `weight sum_i k_i |X_i|^2` over one transformed column line, `low` its
/// row wavenumbers `0..=n0/2` (multipliers `k`), `high` the rest (those of
/// `n0 - i`, read from `k[1..]` backwards): one column's share of
/// Parseval's sum, `weight` 2 for a half-spectrum column that stands for
/// its mirror too.
pub(super) fn line_energy<T: Precision, K: Copy + Into<f64>>(
    low: &[Complex<T>],
    high: &[Complex<T>],
    k: &[K],
    weight: f64,
) -> f64 {
    // `|X|^2` in `f64` whatever `T` (an `f32` square could overflow).
    let term = |c: &Complex<T>, k: &K| {
        let (re, im): (f64, f64) = (c.re.into(), c.im.into());
        (*k).into() * (re * re + im * im)
    };
    let low_sum: f64 = low.iter().zip(k).map(|(c, k)| term(c, k)).sum();
    let high_k = k[1..=high.len()].iter().rev();
    let high_sum: f64 = high.iter().zip(high_k).map(|(c, k)| term(c, k)).sum();
    weight * (low_sum + high_sum)
}

impl<T: Precision> Convolution<T> {
    /// `input . IFFT2(multiplier * FFT2(input))` over the data cells, from
    /// the spectrum of the zero-padded input (Parseval's theorem on the
    /// half-spectrum: a padded grid's circular convolution equals the
    /// linear one where the input is nonzero), the input times `scale`
    /// transformed in `T` (a power of two that moves it into `T`'s range:
    /// the result is divided by its square, exactly) and the sum taken in
    /// `f64`. Distributed, this process's share (its spectrum columns), to
    /// be summed over the ranks; `input` is then this rank's data rows.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory) if the tiles
    /// cannot be allocated again; an exchange's error when distributed.
    pub(crate) fn forward_energy(
        &mut self,
        input: &[f64],
        multiplier: &[f64],
        scale: f64,
    ) -> Result<f64> {
        self.ensure_tiles()?;
        let columns = self.columns;
        self.forward_rows(|i, line: &mut [T]| {
            for (value, x) in line.iter_mut().zip(&input[i * columns..(i + 1) * columns]) {
                *value = T::narrow(x * scale);
            }
        })?;
        self.exchange_to_columns()?;
        Ok(self.filter_columns(super::Scaled::exact(multiplier), Stage::Energy)? / (scale * scale))
    }
}
