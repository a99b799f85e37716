//! The floating-point types a [`Convolution`](super::Convolution) runs in:
//! `f64` for the compliance operator, whose displacements are the answer,
//! and `f32` for the preconditioner, which only shapes the search direction
//! (half the bytes through the memory-bound passes of its round trip).
//!
//! Whatever the type, the half-spectra are kept in a buffer of
//! `Complex<f64>` values, seen as this type's values: one buffer serves the
//! operator and the preconditioner in turn
//! ([`ComplianceOperator::lend_buffer`](crate::kernel::ComplianceOperator)).

use num_complex::Complex;
use realfft::FftNum;

/// The power of two nearest above `magnitude` (1 for zero or a value that
/// is not finite), its exponent kept where the power and its inverse are
/// finite: a scale that moves values into single precision's range without
/// rounding them.
pub(crate) fn power_of_two_above(magnitude: f64) -> f64 {
    if magnitude > 0.0 && magnitude.is_finite() {
        2.0_f64.powi(magnitude.log2().ceil().clamp(-1000.0, 1000.0) as i32)
    } else {
        1.0
    }
}

/// A floating-point type of a [`Convolution`](super::Convolution).
pub(crate) trait Precision: FftNum + Default + Into<f64> {
    /// The value of this type nearest to `x`.
    fn narrow(x: f64) -> Self;

    /// The smallest positive normal value.
    fn smallest() -> Self;

    /// The values of `buffer` seen as this type's complex values.
    fn view(buffer: &[Complex<f64>]) -> &[Complex<Self>];

    /// As [`Precision::view`], mutable.
    fn view_mut(buffer: &mut [Complex<f64>]) -> &mut [Complex<Self>];

    /// How many `Complex<f64>` values hold `len` of this type's.
    fn stored(len: usize) -> usize;
}

impl Precision for f64 {
    fn narrow(x: f64) -> Self {
        x
    }

    fn smallest() -> Self {
        f64::MIN_POSITIVE
    }

    fn view(buffer: &[Complex<f64>]) -> &[Complex<Self>] {
        buffer
    }

    fn view_mut(buffer: &mut [Complex<f64>]) -> &mut [Complex<Self>] {
        buffer
    }

    fn stored(len: usize) -> usize {
        len
    }
}

impl Precision for f32 {
    fn narrow(x: f64) -> Self {
        x as f32
    }

    fn smallest() -> Self {
        f32::MIN_POSITIVE
    }

    // A `Complex<f64>` is 16 bytes aligned to 8 and a `Complex<f32>` 8
    // bytes aligned to 4: every such cast is valid, and `cast_slice`, which
    // checks size and alignment, cannot fail.
    fn view(buffer: &[Complex<f64>]) -> &[Complex<Self>] {
        bytemuck::cast_slice(buffer)
    }

    fn view_mut(buffer: &mut [Complex<f64>]) -> &mut [Complex<Self>] {
        bytemuck::cast_slice_mut(buffer)
    }

    fn stored(len: usize) -> usize {
        len.div_ceil(2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_buffer_seen_in_single_precision_holds_twice_the_values() {
        let mut buffer = vec![Complex::new(0.0_f64, 0.0); f32::stored(5)];
        assert_eq!(buffer.len(), 3);
        let view = f32::view_mut(&mut buffer);
        assert_eq!(view.len(), 6);
        view[4] = Complex::new(1.5, -2.25);
        // The values written are read back through the view.
        assert_eq!(f32::view(&buffer)[4], Complex::new(1.5, -2.25));
        assert_eq!(f32::narrow(0.1), 0.1_f32);
        assert_eq!(f64::stored(5), 5);
    }
}
