//! An approximate inverse of the compliance on a box of cells, the
//! preconditioner of the constrained conjugate gradients.
//!
//! On a periodic box of `m0 x m1` cells the compliance is diagonal in
//! Fourier space, `u_z(q) sinc(q_x Delta/2) sinc(q_y Delta/2)`; its inverse
//! is applied to a residual restricted to the cells in contact, and the
//! result restricted again. Vollebregt (2014, J. Comput. Phys. 257, 333-351)
//! introduced this FFT-based preconditioner for conjugate gradients on the
//! contact area; it makes the iteration count of a Hertzian contact nearly
//! independent of the grid. The box only needs to hold the contact with a
//! small margin (the inverse kernel, a stiffness, decays like `1/r^3`), so
//! an application costs a periodic FFT round trip on the contact's bounding
//! box, not on the padded grid.

use crate::error::Result;

use super::convolution::{multiplier, wavenumber, zeroed, Convolution};
use super::fourier::FourierCompliance;
use super::operator::cell_filter;

/// The approximate inverse on a box of a fixed size (plans, multiplier and
/// box buffers), placed anywhere on a grid at each application.
pub(crate) struct BoxInverse {
    size: (usize, usize),
    multiplier: Vec<f64>,
    convolution: Convolution,
    input: Vec<f64>,
    output: Vec<f64>,
}

impl BoxInverse {
    /// The inverse of `compliance` on a periodic box of `size` cells of side
    /// `delta`. The mean mode, whose compliance is infinite on a half-space,
    /// gets the stiffness of the smallest nonzero wavevector; a stiffness
    /// that is not finite and positive (an extreme layer) falls back to the
    /// half-space's, `E* |q| / 2`.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`](crate::Error::OutOfMemory).
    pub(crate) fn new(
        compliance: &FourierCompliance,
        surface_modulus: f64,
        delta: f64,
        size: (usize, usize),
    ) -> Result<Self> {
        let (m0, m1) = size;
        let smallest = wavenumber(1, m0.max(m1).max(2), delta).abs();
        let stiffness = |qx: f64, qy: f64| {
            let q = qx.hypot(qy);
            let (qx, q) = if q == 0.0 {
                (smallest, smallest)
            } else {
                (qx, q)
            };
            let value = 1.0 / (compliance.eval(q) * cell_filter(qx, qy, delta));
            if value.is_finite() && value > 0.0 {
                value
            } else {
                0.5 * surface_modulus * q
            }
        };
        Ok(BoxInverse {
            size,
            multiplier: multiplier(size, delta, stiffness)?,
            convolution: Convolution::new(m0, m1, size)?,
            input: zeroed(m0 * m1)?,
            output: zeroed(m0 * m1)?,
        })
    }

    /// The box size (rows, columns).
    pub(crate) fn size(&self) -> (usize, usize) {
        self.size
    }

    /// `result = P M^-1 P residual` on a row-major grid of `columns` columns
    /// and `residual.len() / columns` rows, `P` the restriction to the cells
    /// where `member` holds, with the box's first cell at grid cell
    /// `origin` (rows and columns, possibly negative: box cells off the grid
    /// are zero). Only members in the box are written: the box must hold
    /// every member.
    ///
    /// # Errors
    /// As the FFT ([`Error::Internal`](crate::Error::Internal), a bug).
    pub(crate) fn apply(
        &mut self,
        columns: usize,
        origin: (isize, isize),
        member: &[bool],
        residual: &[f64],
        result: &mut [f64],
    ) -> Result<()> {
        let rows = residual.len() / columns.max(1);
        let (m0, m1) = self.size;
        let cell = |bi: usize, bj: usize| -> Option<usize> {
            let i = usize::try_from(origin.0 + bi as isize).ok()?;
            let j = usize::try_from(origin.1 + bj as isize).ok()?;
            (i < rows && j < columns).then_some(i * columns + j)
        };
        for bi in 0..m0 {
            for bj in 0..m1 {
                self.input[bi * m1 + bj] = match cell(bi, bj) {
                    Some(c) if member[c] => residual[c],
                    _ => 0.0,
                };
            }
        }
        self.convolution
            .apply(&self.input, &mut self.output, &self.multiplier)?;
        for bi in 0..m0 {
            for bj in 0..m1 {
                if let Some(c) = cell(bi, bj) {
                    if member[c] {
                        result[c] = self.output[bi * m1 + bj];
                    }
                }
            }
        }
        Ok(())
    }
}
