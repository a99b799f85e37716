//! The operator of the grid of half the cells each way, from a finer
//! operator's spectrum alone: Galerkin's coarse operator `R K P`
//! (a coarse cell's pressure spread over its four fine cells, its
//! displacement the mean of theirs; Hackbusch 1985, Multi-Grid Methods and
//! Applications, Springer), for the coarse levels of the
//! solver's multi-resolution start. No influence coefficient of the coarse
//! grid is evaluated and no transform run: on a rough film at 4096^2 the
//! coarse levels' kernels took 1.5 s of the solve's start from the
//! substrate on an isolated grid, and at 8192^2 the periodic 4096^2
//! level's multiplier 3.8 s (BENCHMARKS.md, "Speed: rough contacts on
//! large grids").

use crate::error::Result;
use crate::grid::Grid;

use super::{check_cell_compliance, fft_size, memory_estimate, reserve, ComplianceOperator};
use super::{Convolution, KEEP_INFLUENCE_CELLS};
use crate::kernel::convolution::zeroed;

impl ComplianceOperator {
    /// Galerkin's coarse operator `R K P` of this operator on `coarse`, the
    /// grid of half its cells each way (twice their size), with the same
    /// boundary; on an isolated grid its influence coefficients too where
    /// this operator keeps its own
    /// ([`InfluenceCoefficients::halved`](super::InfluenceCoefficients)).
    ///
    /// The coarse kernel is the fine one filtered by `w = (1, 2, 1)` each
    /// way and taken at even offsets, times `1/4`; on the spectrum, which is
    /// real and even, that is the sum over the four aliases of each coarse
    /// wavevector of `(2 + 2 cos(2 pi k0 / n0)) (2 + 2 cos(2 pi k1 / n1))`
    /// times the fine spectrum, times `1/4` (the FFT grid halves with the
    /// grid: the fine normalisation `1 / (n0 n1)` is a quarter of the
    /// coarse one). On an isolated grid the filtered kernel at the one
    /// coarse offset the padding never reads (`±rows / 2`) differs from
    /// zero; nothing reads it. On a periodic grid the mean mode keeps its
    /// value (zero where the mean displacement is undetermined).
    ///
    /// `None` where the halving does not apply: a distributed operator (each
    /// rank holds only its columns of the spectrum), an odd side, a coarse
    /// grid that is not this one halved, or padded sizes that do not halve
    /// to the coarse grid's own; the coarse operator is then built from the
    /// substrate.
    pub(crate) fn halved(&self, coarse: &Grid) -> Option<Result<Self>> {
        let (rows, columns) = (self.grid.rows(), self.grid.columns());
        let (n0, n1) = self.convolution.size();
        let applies = self.slab.is_none()
            && rows % 2 == 0
            && columns % 2 == 0
            && coarse.rows() * 2 == rows
            && coarse.columns() * 2 == columns
            && coarse.spacing() == 2.0 * self.grid.spacing()
            && n0 % 2 == 0
            && n1 % 2 == 0
            && fft_size(coarse, self.boundary) == (n0 / 2, n1 / 2);
        applies.then(|| self.galerkin(coarse))
    }

    fn galerkin(&self, coarse: &Grid) -> Result<Self> {
        check_cell_compliance(coarse, self.surface_modulus)?;
        reserve(memory_estimate(coarse, self.boundary))?;
        let (n0, n1) = self.convolution.size();
        let (m0, m1) = (n0 / 2, n1 / 2);
        let distinct = n0 / 2 + 1;
        let coarse_distinct = m0 / 2 + 1;
        let coarse_half = m1 / 2 + 1;
        // The filter's factor at each index of n, and where the even
        // spectrum keeps index k.
        let weights = |n: usize| -> Vec<f64> {
            (0..n)
                .map(|k| 2.0 + 2.0 * (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos())
                .collect()
        };
        let (w0, w1) = (weights(n0), weights(n1));
        let fold = |k: usize, n: usize| k.min(n - k);
        let mut spectrum = zeroed(coarse_distinct * coarse_half)?;
        crate::parallel::for_each_row(&mut spectrum, coarse_distinct, |b, column| {
            for (a, value) in column.iter_mut().enumerate() {
                let mut sum = 0.0;
                for k0 in [a, a + m0] {
                    for k1 in [b, b + m1] {
                        let fine = self.spectrum[fold(k1, n1) * distinct + fold(k0, n0)];
                        sum += w0[k0] * w1[k1] * fine;
                    }
                }
                *value = 0.25 * sum;
            }
        });
        let influence = self
            .influence
            .as_ref()
            .filter(|_| coarse.len() <= KEEP_INFLUENCE_CELLS)
            .map(|k| k.halved(coarse));
        Ok(ComplianceOperator {
            grid: *coarse,
            boundary: self.boundary,
            influence,
            layered: self.layered,
            rigid_base: self.rigid_base,
            spectrum,
            inverse_spectrum: Vec::new(),
            surface_modulus: self.surface_modulus,
            convolution: Convolution::new(coarse.rows(), coarse.columns(), (m0, m1))?,
            single: None,
            single_scale: 1.0,
            slab: None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::energy::tests::{bodies, field};
    use super::*;
    use crate::grid::Boundary;

    /// The halved operator against `R K P` through the fine operator
    /// itself (the coarse pressure spread over the four fine cells of each
    /// coarse cell, the fine response averaged over them) on isolated and
    /// periodic grids, and on an isolated grid its coefficients' direct sums
    /// against its convolution, on a half-space and a film, square and
    /// oblong grids: equal to rounding (1e-13 of the largest response). The
    /// coarse operator of the same substrate built on the coarse grid
    /// (collocation at the coarse cell's centre) differs from it by more
    /// than 1e-3 of the largest response, so the test tells the two apart.
    #[test]
    fn the_halved_operator_is_the_fine_one_between_prolongation_and_restriction() {
        for body in bodies() {
            for boundary in [Boundary::Isolated, Boundary::Periodic] {
                for (rows, columns) in [(8, 8), (12, 6), (10, 14)] {
                    let fine = Grid::new(rows, columns, 1e-6).unwrap();
                    let coarse = Grid::new(rows / 2, columns / 2, 2e-6).unwrap();
                    let mut operator = ComplianceOperator::new(&body, &fine, boundary).unwrap();
                    let mut halved = operator.halved(&coarse).unwrap().unwrap();
                    let x = field(coarse.len(), (rows * columns) as u64);
                    let block = |c: usize| (c / columns / 2) * (columns / 2) + (c % columns) / 2;
                    let spread: Vec<f64> = (0..fine.len()).map(|c| x[block(c)]).collect();
                    let mut response = vec![0.0; fine.len()];
                    operator.apply(&spread, &mut response).unwrap();
                    let mut expected = vec![0.0; coarse.len()];
                    for (c, u) in response.iter().enumerate() {
                        expected[block(c)] += 0.25 * u;
                    }
                    let mut convolved = vec![0.0; coarse.len()];
                    halved.apply(&x, &mut convolved).unwrap();
                    let largest = expected.iter().fold(0.0f64, |m, u| m.max(u.abs()));
                    let case = format!("{boundary:?} {rows}x{columns}");
                    for (e, c) in expected.iter().zip(&convolved) {
                        assert!((c - e).abs() <= 1e-13 * largest, "{case}: {c} against {e}");
                    }
                    if let Some(table) = halved.influence() {
                        let mut summed = vec![0.0; coarse.len()];
                        let loads: Vec<(usize, f64)> = x.iter().copied().enumerate().collect();
                        table.add_loads(&loads, &mut summed);
                        for (e, s) in expected.iter().zip(&summed) {
                            assert!((s - e).abs() <= 1e-13 * largest, "{case}: {s} against {e}");
                        }
                    }
                    let mut direct = ComplianceOperator::new(&body, &coarse, boundary).unwrap();
                    let mut collocated = vec![0.0; coarse.len()];
                    direct.apply(&x, &mut collocated).unwrap();
                    let apart = collocated
                        .iter()
                        .zip(&convolved)
                        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
                    assert!(apart > 1e-3 * largest, "{case}: {apart} of {largest}");
                }
            }
        }
    }

    /// Where the halving does not apply it says so: an odd side, a coarse
    /// grid that is not this one halved.
    #[test]
    fn the_halving_applies_only_to_even_grids_halved() {
        let body = &bodies()[0];
        let grid = Grid::new(9, 8, 1e-6).unwrap();
        for boundary in [Boundary::Isolated, Boundary::Periodic] {
            let odd = ComplianceOperator::new(body, &grid, boundary).unwrap();
            assert!(odd.halved(&Grid::new(5, 4, 2e-6).unwrap()).is_none());
        }
        let grid = Grid::new(8, 8, 1e-6).unwrap();
        let isolated = ComplianceOperator::new(body, &grid, Boundary::Isolated).unwrap();
        assert!(isolated.halved(&Grid::new(4, 4, 3e-6).unwrap()).is_none());
        assert!(isolated.halved(&Grid::new(4, 2, 2e-6).unwrap()).is_none());
        assert!(isolated.halved(&Grid::new(4, 4, 2e-6).unwrap()).is_some());
    }
}
