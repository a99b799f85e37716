//! The operator's energy `x . (K x)` in half a round trip
//! (`Convolution::forward_energy`) and `output += factor K x` without a
//! buffer for `K x`: the constrained conjugate gradients' step on a
//! clamping iteration (a step length from the direction's energy, one
//! convolution of the whole change of the pressure) instead of two
//! convolutions; `K x` row by row into a pass of the caller's
//! ([`ComplianceOperator::apply_into`]).

use crate::error::Result;

use super::ComplianceOperator;

impl ComplianceOperator {
    /// `x . (K x)` over this rank's spectrum columns (summed over the ranks
    /// by the caller when distributed; the whole energy when serial).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) for a slice of
    /// another length than this rank's cells.
    pub(crate) fn energy(&mut self, x: &[f64]) -> Result<f64> {
        self.check_lengths(&[("direction", x.len())])?;
        self.convolution.forward_energy(x, &self.spectrum, 1.0)
    }

    /// `output += factor K x` in one round trip.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) for a slice of
    /// another length than this rank's cells.
    pub(crate) fn apply_add(&mut self, x: &[f64], output: &mut [f64], factor: f64) -> Result<()> {
        self.check_lengths(&[("pressure", x.len()), ("displacement", output.len())])?;
        self.convolution
            .apply_combined(x, output, &self.spectrum, |u, k| u + factor * k)
    }

    /// `K x` row by row: this rank's data row `i` of the response goes to
    /// `sink(i, targets[i], row)`, and the sinks' results come back in row
    /// order (a pass over the response, such as the constrained conjugate
    /// gradients' rescale under force control, runs inside the
    /// transform's last pass instead of over a buffer).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) for a slice of
    /// another length than this rank's cells;
    /// [`Error::Internal`](crate::Error::Internal) for another number of
    /// targets than this rank's rows.
    pub(crate) fn apply_into<O: Send, S: Send>(
        &mut self,
        x: &[f64],
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[f64]) -> S + Sync,
    ) -> Result<Vec<S>> {
        self.check_lengths(&[("pressure", x.len())])?;
        self.convolution
            .apply_input_into(x, &self.spectrum, targets, sink)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::{Boundary, Grid, Material, Substrate};

    /// A seeded pseudo-random field of `n` values in `[-1, 1)` (a linear
    /// congruential generator: no dependency for a test).
    pub(in crate::kernel::operator) fn field(n: usize, seed: u64) -> Vec<f64> {
        let mut state = seed;
        (0..n)
            .map(|_| {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
            })
            .collect()
    }

    pub(in crate::kernel::operator) fn bodies() -> Vec<Substrate> {
        let rubber = Material::new(1e6, 0.45).unwrap();
        vec![
            Substrate::half_space(rubber),
            Substrate::layer_on_rigid_base(rubber, 3e-6).unwrap(),
        ]
    }

    /// The energy from the spectrum against the dot product of the field
    /// with its response in space, on periodic and isolated grids of even
    /// and odd sides (the half-spectrum's Nyquist column counted once where
    /// there is one), on a half-space and a layer: equal to rounding
    /// (1e-12 of `|x| |K x|`; a weight of 2 on the Nyquist column, or 1 on
    /// the others, is off by per cents).
    #[test]
    fn the_energy_is_the_field_dotted_with_its_response() {
        for body in bodies() {
            for (rows, columns, boundary) in [
                (12, 10, Boundary::Periodic),
                (9, 7, Boundary::Periodic),
                (8, 11, Boundary::Isolated),
                (13, 6, Boundary::Isolated),
            ] {
                let grid = Grid::new(rows, columns, 1e-6).unwrap();
                let mut operator = ComplianceOperator::new(&body, &grid, boundary).unwrap();
                let x = field(grid.len(), (rows * columns) as u64);
                let mut kx = vec![0.0; grid.len()];
                operator.apply(&x, &mut kx).unwrap();
                let dot: f64 = x.iter().zip(&kx).map(|(a, b)| a * b).sum();
                let norms = x.iter().map(|a| a * a).sum::<f64>().sqrt()
                    * kx.iter().map(|a| a * a).sum::<f64>().sqrt();
                let energy = operator.energy(&x).unwrap();
                assert!(
                    (energy - dot).abs() <= 1e-12 * norms,
                    "{rows}x{columns} {boundary:?}: {energy} against {dot}"
                );
            }
        }
    }

    /// `apply_add` against `apply` and an addition in space.
    #[test]
    fn apply_add_adds_the_scaled_response() {
        let body = &bodies()[1];
        let grid = Grid::new(10, 9, 1e-6).unwrap();
        for boundary in [Boundary::Periodic, Boundary::Isolated] {
            let mut operator = ComplianceOperator::new(body, &grid, boundary).unwrap();
            let x = field(grid.len(), 1);
            let mut kx = vec![0.0; grid.len()];
            operator.apply(&x, &mut kx).unwrap();
            let largest = kx.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            // A start of the response's size, so that an error shows.
            let start: Vec<f64> = field(grid.len(), 2).iter().map(|v| v * largest).collect();
            let mut output = start.clone();
            operator.apply_add(&x, &mut output, -0.75).unwrap();
            for ((o, s), k) in output.iter().zip(&start).zip(&kx) {
                assert!((o - (s - 0.75 * k)).abs() <= 1e-13 * largest);
            }
        }
    }
}
