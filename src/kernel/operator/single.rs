//! The compliance operator's transform in single precision: the energy
//! `x . (K x)` and the applications `K x` of the constrained conjugate
//! gradients' early iterations, whose pressures are still far from the
//! answer (`f32`'s rounding, about `1e-7` of the largest value, is far
//! below the iteration's change there). The same transform as in double
//! precision, in the operator's own buffers (lent: no memory added but its
//! plans and a few lines per thread); the kernel's spectrum stays in `f64`
//! and is narrowed as the column pass reads it. Half the bytes through the
//! memory-bound passes and twice the values per vector instruction: the
//! forward half of a round trip on a 4096 x 4096 isolated grid took 0.062 s
//! against 0.10 s in double (BENCHMARKS.md, "Speed: rough contacts on large
//! grids").

use crate::error::Result;

use super::super::convolution::{power_of_two_above, Convolution, Scaled};
use super::ComplianceOperator;

impl ComplianceOperator {
    /// Runs `f` with the single-precision transform (built on first use)
    /// working in this operator's buffers, the spectrum and the power of
    /// two that brings it into `f32`'s range.
    fn with_single<R>(
        &mut self,
        f: impl FnOnce(&mut Convolution<f32>, Scaled<'_, f64>) -> Result<R>,
    ) -> Result<R> {
        let mut single = match self.single.take() {
            Some(single) => single,
            None => {
                let (rows, columns) = (self.grid.rows(), self.grid.columns());
                let size = self.convolution.size();
                let built = match self.slab.as_ref() {
                    None => Convolution::new(rows, columns, size),
                    // It works in the operator's buffers: none of its own.
                    Some(slab) => Convolution::distributed_unallocated(
                        rows,
                        columns,
                        size,
                        slab,
                        slab.counts(),
                    ),
                };
                // Distributed, a rank that could not build it stops every rank.
                let built = crate::slab::agree(self.slab.as_ref(), built)?;
                // The same power of two on every rank: the sum of their
                // largest values.
                let mut largest = [self.spectrum.iter().fold(0.0_f64, |m, k| m.max(k.abs()))];
                if let Some(slab) = self.slab.as_ref() {
                    slab.exchange.sum(&mut largest);
                }
                self.single_scale = 1.0 / power_of_two_above(largest[0]);
                built
            }
        };
        single.give_buffers(self.convolution.take_buffers());
        let spectrum = Scaled {
            values: &self.spectrum,
            scale: self.single_scale,
        };
        let result = f(&mut single, spectrum);
        self.convolution.give_buffers(single.take_buffers());
        self.single = Some(single);
        result
    }

    /// As [`ComplianceOperator::energy`], the transform in single
    /// precision (the multiplier and the sum stay in `f64`), `x` scaled by
    /// a power of two from `magnitude`, about its largest absolute value
    /// (the same on every rank), into `f32`'s range. Its relative rounding
    /// is about `1e-7`; the caller checks that the total is finite and
    /// positive.
    ///
    /// # Errors
    /// As [`ComplianceOperator::energy`].
    pub(crate) fn energy_single(&mut self, x: &[f64], magnitude: f64) -> Result<f64> {
        self.check_lengths(&[("direction", x.len())])?;
        let scale = 1.0 / power_of_two_above(magnitude);
        self.with_single(|single, spectrum| single.forward_energy(x, spectrum.values, scale))
    }

    /// `output = combine(output, K x)` in single precision, `x` scaled by a
    /// power of two from `magnitude` (about its largest absolute value, the
    /// same on every rank) into `f32`'s range: each value within about
    /// `1e-6` of the largest of `K x` of the value in double precision.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) for a slice of
    /// another length than this rank's cells.
    pub(crate) fn apply_single(
        &mut self,
        x: &[f64],
        output: &mut [f64],
        magnitude: f64,
        combine: impl Fn(f64, f64) -> f64 + Sync,
    ) -> Result<()> {
        self.check_lengths(&[("displacement", output.len())])?;
        let columns = self.grid.columns();
        let rows = output.chunks_exact_mut(columns).collect();
        self.apply_into_single(x, magnitude, rows, |_, row, values, unscale| {
            for (out, value) in row.iter_mut().zip(values) {
                *out = combine(*out, f64::from(*value) * unscale);
            }
        })?;
        Ok(())
    }

    /// As [`ComplianceOperator::apply_into`], in single precision (`x`
    /// scaled as in [`ComplianceOperator::apply_single`]): each row reaches
    /// its sink as computed, in `f32`, with the factor that turns its
    /// values into `K x` (`sink(i, targets[i], values, factor)`).
    ///
    /// # Errors
    /// As [`ComplianceOperator::apply_into`].
    pub(crate) fn apply_into_single<O: Send, S: Send>(
        &mut self,
        x: &[f64],
        magnitude: f64,
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[f32], f64) -> S + Sync,
    ) -> Result<Vec<S>> {
        self.check_lengths(&[("pressure", x.len())])?;
        let columns = self.grid.columns();
        let load = |i: usize, line: &mut [f32], scale: f64| {
            for (value, x) in line.iter_mut().zip(&x[i * columns..(i + 1) * columns]) {
                *value = (x * scale) as f32;
            }
        };
        self.apply_rows_single(magnitude, load, targets, sink)
    }

    /// As [`ComplianceOperator::apply_into_single`], each row `i` of `x`
    /// written by `load(i, row, scale)` as its values times `scale` (a
    /// power of two from `magnitude`, about the largest absolute value of
    /// `x`) instead of read from a slice: a load built on the fly (the
    /// two-level preconditioner's piecewise constant fields) needs no
    /// vector of its own.
    ///
    /// # Errors
    /// As [`ComplianceOperator::apply_into`].
    pub(crate) fn apply_rows_single<O: Send, S: Send>(
        &mut self,
        magnitude: f64,
        load: impl Fn(usize, &mut [f32], f64) + Sync,
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[f32], f64) -> S + Sync,
    ) -> Result<Vec<S>> {
        let scale = 1.0 / power_of_two_above(magnitude);
        self.with_single(|single, spectrum| {
            let unscale = 1.0 / (scale * spectrum.scale);
            let load = |i: usize, line: &mut [f32]| load(i, line, scale);
            single.apply_into(load, spectrum, targets, |i, target, values| {
                sink(i, target, values, unscale)
            })
        })
    }

    /// As [`ComplianceOperator::apply_rows_single`] of `other` (an
    /// operator never applied at the same time, such as a coarse level's,
    /// whose buffers are smaller), in this operator's large buffers, lent
    /// to it: no memory added.
    ///
    /// # Errors
    /// As [`ComplianceOperator::apply_into`].
    pub(crate) fn apply_rows_single_lent<O: Send, S: Send>(
        &mut self,
        other: &mut ComplianceOperator,
        magnitude: f64,
        load: impl Fn(usize, &mut [f32], f64) + Sync,
        targets: Vec<O>,
        sink: impl Fn(usize, O, &[f32], f64) -> S + Sync,
    ) -> Result<Vec<S>> {
        other
            .convolution
            .give_buffers(self.convolution.take_buffers());
        let result = other.apply_rows_single(magnitude, load, targets, sink);
        self.convolution
            .give_buffers(other.convolution.take_buffers());
        result
    }
}

#[cfg(test)]
mod tests {
    use super::super::energy::tests::{bodies, field};
    use super::*;
    use crate::{Boundary, Grid, Material, Substrate};

    /// The energy in single precision against the energy in double, on
    /// periodic and isolated grids of a half-space and a layer, for fields
    /// scaled far outside `f32`'s range (1e-38 to 3e38): within 1e-6
    /// (measured 1e-9 to 9e-8, `f32`'s unit rounding 6e-8 grown through
    /// the transforms; without the power-of-two scaling the factor 1e-45 is
    /// 117 % off).
    #[test]
    fn the_energy_in_single_precision_is_double_to_its_rounding() {
        for body in bodies() {
            for (rows, columns, boundary) in
                [(32, 30, Boundary::Periodic), (17, 24, Boundary::Isolated)]
            {
                let grid = Grid::new(rows, columns, 1e-6).unwrap();
                let mut operator = ComplianceOperator::new(&body, &grid, boundary).unwrap();
                for factor in [1.0, 1e-45, 1e45] {
                    let x: Vec<f64> = field(grid.len(), 3).iter().map(|v| v * factor).collect();
                    let largest = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
                    let double = operator.energy(&x).unwrap();
                    let single = operator.energy_single(&x, largest).unwrap();
                    let error = (single / double - 1.0).abs();
                    assert!(
                        error < 1e-6,
                        "{boundary:?} {factor}: {single} against {double}"
                    );
                }
                // The operator's own applications are untouched by the
                // buffers it lent.
                let x = field(grid.len(), 4);
                let mut kx = vec![0.0; grid.len()];
                operator.apply(&x, &mut kx).unwrap();
                let dot: f64 = x.iter().zip(&kx).map(|(a, b)| a * b).sum();
                assert!((operator.energy(&x).unwrap() / dot - 1.0).abs() < 1e-12);
            }
        }
    }

    /// `K x` in single precision against double, overwritten and added
    /// to a start, and row by row into a sink, on periodic and isolated
    /// grids of a half-space and a layer, for fields scaled far outside
    /// `f32`'s range (1e-45 to 1e45): every value within 1e-6 of the
    /// largest response (measured up to 2.3e-7: `f32`'s unit rounding
    /// 6e-8 grown through the transforms). Without the spectrum's scaling
    /// the stiff half-space's error is 2.8e-6 (its spectrum, about 1e-41,
    /// below `f32`'s normal range).
    #[test]
    fn the_response_in_single_precision_is_double_to_its_rounding() {
        // A half-space of E = 1e15 Pa on cells of 1e-22 m: a spectrum of
        // about 1e-41 before its scaling.
        let stiff = Substrate::half_space(Material::new(1e15, 0.2).unwrap());
        let cases = bodies()
            .into_iter()
            .map(|b| (b, 1e-6))
            .chain([(stiff, 1e-22)]);
        for (body, spacing) in cases {
            for (rows, columns, boundary) in
                [(32, 30, Boundary::Periodic), (17, 24, Boundary::Isolated)]
            {
                let grid = Grid::new(rows, columns, spacing).unwrap();
                let mut operator = ComplianceOperator::new(&body, &grid, boundary).unwrap();
                for factor in [1.0, 1e-45, 1e45] {
                    let x: Vec<f64> = field(grid.len(), 5).iter().map(|v| v * factor).collect();
                    let largest = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
                    let mut double = vec![0.0; grid.len()];
                    operator.apply(&x, &mut double).unwrap();
                    let scale = double.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
                    let error = |single: &[f64], offset: &dyn Fn(usize) -> f64| {
                        single
                            .iter()
                            .zip(&double)
                            .enumerate()
                            .map(|(c, (s, d))| (s - offset(c) - d).abs() / scale)
                            .fold(0.0_f64, f64::max)
                    };
                    let mut single = vec![0.0; grid.len()];
                    operator
                        .apply_single(&x, &mut single, largest, |_, k| k)
                        .unwrap();
                    let overwritten = error(&single, &|_| 0.0);
                    // Added to a start of the response's size, halved.
                    let start: Vec<f64> = field(grid.len(), 6).iter().map(|v| v * scale).collect();
                    let mut added = start.clone();
                    operator
                        .apply_single(&x, &mut added, largest, |u, k| u + 0.5 * k)
                        .unwrap();
                    let added: Vec<f64> = added.iter().map(|a| 2.0 * a).collect();
                    let added = error(&added, &|c| 2.0 * start[c]);
                    let targets: Vec<usize> = (0..rows).collect();
                    let rows_out = operator
                        .apply_into_single(&x, largest, targets, |i, r, values, unscale| {
                            assert_eq!(i, r);
                            values
                                .iter()
                                .map(|v| f64::from(*v) * unscale)
                                .collect::<Vec<_>>()
                        })
                        .unwrap()
                        .concat();
                    let into = error(&rows_out, &|_| 0.0);
                    for (what, e) in [("apply", overwritten), ("add", added), ("into", into)] {
                        assert!(e < 1e-6, "{boundary:?} {factor} {what}: {e}");
                    }
                }
            }
        }
    }
}
