//! The two-level preconditioner's two applications of the compliance
//! ([`balancing`](super)): `A Z c1` and `Z^T A y`, in single precision,
//! through the multi-resolution start's coarse level on an isolated grid
//! (the grid of half the cells each way), else on the grid itself.
//!
//! Through the coarse level, `A` is replaced in both by
//!
//! ```text
//! A~ = P A_c P^T / 4
//! ```
//!
//! with `P` the injection of a coarse cell's value into its (up to) four
//! fine cells and `A_c` the coarse level's compliance (serially Galerkin's
//! `P^T A P / 4`, `ComplianceOperator::halved`, so that `A~` is `A` seen
//! through the means over 2 x 2 cells; split across ranks the substrate's
//! own on the coarse grid). For any symmetric `A~` the preconditioner `M =
//! Q + (I - Q A~) B (I - A~ Q)` stays symmetric and positive definite:
//! `x^T M x = x^T Q x + (P~ x)^T B (P~ x)`, `P~ = I - A~ Q`, where `x^T Q
//! x > 0` unless `Q x = 0`, and then `P~ x = x`. The conjugate gradients
//! keep their preconditioner's one requirement; the coarse correction
//! needs what varies from block to block, which the means keep.
//!
//! An isolated grid's applications run on the padded grid of four times
//! the cells, a coarse level's on a quarter of that: on the rough film of
//! `examples/rough_benchmark.rs` at 4096^2 (two threads) an iteration with
//! the blocks fell from about 0.85 to 0.6 s, the fine iterations stayed
//! at 23 and the solve took 17.2 to 19.1 s against 19.3 to 22.7 s. On a
//! periodic grid the applications are a quarter as dear to begin with:
//! through the coarse level an iteration cost the same and the periodic
//! film and the tamaas problem took two more (24 and 35 at 4096^2, 4 to
//! 8 % longer), so periodic grids keep their own. Measured in `BENCHMARKS.md`,
//! "The two-level preconditioner through the coarse level" (2026-12-06,
//! forty-sixth session).

use crate::error::Result;
use crate::grid::Boundary;
use crate::kernel::ComplianceOperator;

use super::super::coarse_space::CoarseSpace;
use super::super::ContactSolver;

/// The fine rows of coarse row `ci`, of `rows` fine rows (the last coarse
/// row of an odd count has one).
fn pair(ci: usize, rows: usize) -> std::ops::Range<usize> {
    2 * ci..(2 * ci + 2).min(rows)
}

/// `s = gap - shift - kx(j)` on the row's cells of the working set
/// (`member`), 0 elsewhere; returns the largest `|s|`.
fn residual_row(
    s: &mut [f64],
    gap: &[f64],
    member: &[bool],
    shift: f64,
    kx: impl Fn(usize) -> f64,
) -> f64 {
    let mut largest = 0.0_f64;
    for (j, (s, (g, w))) in s.iter_mut().zip(gap.iter().zip(member)).enumerate() {
        *s = if *w { g - shift - kx(j) } else { 0.0 };
        largest = largest.max(s.abs());
    }
    largest
}

impl ContactSolver {
    /// Runs `f` with the coarse level's operator if the two applications
    /// go through it (`None` if not): on an isolated grid (a periodic
    /// grid's own applications cost no more, see the module's doc), where
    /// the multi-resolution start has built it, on the grid of half the
    /// cells each way (rounded up), and on a split solver every rank's
    /// first row is even and its coarse rows are the halves of its rows.
    /// Collective on a split solver with an isolated grid.
    fn with_halved<R>(
        &mut self,
        f: impl FnOnce(&mut Self, Option<&mut ComplianceOperator>) -> R,
    ) -> R {
        // Every rank has the same boundary: no collective for a periodic
        // grid.
        if self.operator.boundary() != Boundary::Isolated {
            return f(self, None);
        }
        let mut levels = self.coarse.take();
        let (grid, local) = (*self.grid(), self.operator.local_rows());
        let fits = match &levels {
            Some(Some(coarse)) => {
                let coarse_grid = coarse.grid();
                coarse_grid.rows() == grid.rows().div_ceil(2)
                    && coarse_grid.columns() == grid.columns().div_ceil(2)
                    && local.start.is_multiple_of(2)
                    && coarse.operator.local_rows() == (local.start / 2..local.end.div_ceil(2))
            }
            _ => false,
        };
        let fits = !self.on_any_rank(!fits);
        let operator = levels
            .as_mut()
            .and_then(|c| c.as_mut())
            .filter(|_| fits)
            .map(|c| &mut c.operator);
        let result = f(self, operator);
        self.coarse = levels;
        result
    }

    /// `s = r - A Z c1` on the working set (`r = gap - shift`, `Z c1` the
    /// values `coarse` of the blocks on the set's cells, `largest` about
    /// their largest absolute value), into the workspace's `previous`;
    /// returns the largest `|s|` of each row (or pair of rows).
    pub(super) fn coarse_load_residual(
        &mut self,
        space: &CoarseSpace,
        coarse: &[f64],
        largest: f64,
        shift: f64,
    ) -> Result<Vec<f64>> {
        self.with_halved(|solver, halved| {
            let (rows, columns) = (solver.operator.local_rows().len(), solver.grid().columns());
            let ws = &mut solver.workspace;
            let (gap, working) = (&ws.gap, &ws.working);
            // The residual less the response `kx(j)` on row `i`.
            let residual = |i: usize, s: &mut [f64], kx: &[f32], unscale: f64, halved: bool| {
                let cells = i * columns..(i + 1) * columns;
                if halved {
                    residual_row(s, &gap[cells.clone()], &working[cells], shift, |j| {
                        f64::from(kx[j / 2]) * unscale
                    })
                } else {
                    residual_row(s, &gap[cells.clone()], &working[cells], shift, |j| {
                        f64::from(kx[j]) * unscale
                    })
                }
            };
            let Some(coarse_operator) = halved else {
                return solver.operator.apply_rows_single(
                    largest,
                    |i, line, scale| {
                        let member = &working[i * columns..(i + 1) * columns];
                        for (block, range) in space.row_runs(i) {
                            let value = (coarse[block] * scale) as f32;
                            for (x, w) in line[range.clone()].iter_mut().zip(&member[range]) {
                                *x = if *w { value } else { 0.0 };
                            }
                        }
                    },
                    ws.previous.chunks_exact_mut(columns).collect(),
                    |i, s, kx, unscale| residual(i, s, kx, unscale, false),
                );
            };
            solver.operator.apply_rows_single_lent(
                coarse_operator,
                largest,
                // P^T (Z c1) / 4: the means over 2 x 2 cells.
                |ci, line, scale| {
                    line.fill(0.0);
                    for i in pair(ci, rows) {
                        let member = &working[i * columns..(i + 1) * columns];
                        for (block, range) in space.row_runs(i) {
                            let value = (0.25 * coarse[block] * scale) as f32;
                            for j in range.filter(|j| member[*j]) {
                                line[j / 2] += value;
                            }
                        }
                    }
                },
                ws.previous[..rows * columns]
                    .chunks_mut(2 * columns)
                    .collect(),
                // P: each coarse value on its fine cells.
                |ci, two_rows: &mut [f64], kx, unscale| {
                    two_rows
                        .chunks_exact_mut(columns)
                        .enumerate()
                        .map(|(k, s)| residual(2 * ci + k, s, kx, unscale, true))
                        .fold(0.0, f64::max)
                },
            )
        })
    }

    /// `Z^T A y` (`y` the workspace's `response`, zero off the working
    /// set, `y_max` about its largest absolute value): each row's part of
    /// each block's sum over the set, in the order of
    /// [`CoarseSpace::row_runs`].
    pub(super) fn block_sums_of_response(
        &mut self,
        space: &CoarseSpace,
        y_max: f64,
    ) -> Result<Vec<Vec<f64>>> {
        self.with_halved(|solver, halved| {
            let (rows, columns) = (solver.operator.local_rows().len(), solver.grid().columns());
            let ws = &solver.workspace;
            let (y, working) = (&ws.response, &ws.working);
            let Some(coarse_operator) = halved else {
                return solver.operator.apply_rows_single(
                    y_max,
                    |i, line, scale| {
                        for (x, y) in line.iter_mut().zip(&y[i * columns..(i + 1) * columns]) {
                            *x = (y * scale) as f32;
                        }
                    },
                    vec![(); rows],
                    |i, (), ky, unscale| {
                        let member = &working[i * columns..(i + 1) * columns];
                        space.row_sums(i, member, |j| f64::from(ky[j]) * unscale)
                    },
                );
            };
            let pairs = solver.operator.apply_rows_single_lent(
                coarse_operator,
                y_max,
                |ci, line, scale| {
                    line.fill(0.0);
                    for i in pair(ci, rows) {
                        let row = &y[i * columns..(i + 1) * columns];
                        for (x, y) in line.iter_mut().zip(row.chunks(2)) {
                            *x += (0.25 * y.iter().sum::<f64>() * scale) as f32;
                        }
                    }
                },
                vec![(); rows.div_ceil(2)],
                |ci, (), ky, unscale| {
                    (pair(ci, rows))
                        .map(|i| {
                            let member = &working[i * columns..(i + 1) * columns];
                            space.row_sums(i, member, |j| f64::from(ky[j / 2]) * unscale)
                        })
                        .collect::<Vec<_>>()
                },
            )?;
            Ok(pairs.into_iter().flatten().collect())
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::indenter::Paraboloid;
    use crate::solver::{ContactSolver, SolverParams};
    use crate::{Boundary, Grid, Material, Substrate};

    /// `u = A_c (P^T x / 4)` in double precision through the coarse
    /// level's operator, `x` on the `rows x columns` grid.
    fn through_coarse(solver: &mut ContactSolver, x: &[f64], columns: usize) -> Vec<f64> {
        let coarse = solver.coarse.as_mut().unwrap().as_mut().unwrap();
        let half = coarse.grid().columns();
        let mut restricted = vec![0.0; coarse.grid().len()];
        for (c, v) in x.iter().enumerate() {
            restricted[(c / columns / 2) * half + (c % columns) / 2] += 0.25 * v;
        }
        let mut u = vec![0.0; restricted.len()];
        coarse.operator.apply(&restricted, &mut u).unwrap();
        u
    }

    /// Both applications go through the coarse level, as `A~ = P A_c P^T
    /// / 4` with the level's operator applied in double precision: on an
    /// isolated 70 x 65 grid (a coarse level of 35 x 33, a last fine row
    /// and column alone in their coarse cells) with blocks of 5 cells (odd:
    /// a coarse cell straddles two blocks), a patterned working set and
    /// seeded values, `r - A~ Z c` and `Z^T A~ y` within 1e-5 of the
    /// largest response (measured 1.7e-7: single precision's rounding
    /// through the transforms; the grid's own `A` gives responses up to
    /// 3.5e-2 of the largest away, so the test fails if either
    /// application takes the grid's own: checked). And
    /// `y . A~ Z c = c . Z^T A~ y` to single precision: the two use the
    /// same `A~`, as the preconditioner's symmetry needs.
    #[test]
    fn the_applications_go_through_the_coarse_level() {
        let (rows, columns) = (70, 65);
        let grid = Grid::new(rows, columns, 1e-5).unwrap();
        let body = Substrate::half_space(Material::new(1e6, 0.3).unwrap());
        let mut solver =
            ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default()).unwrap();
        // A solve builds the coarse level.
        let sphere = Paraboloid::new(1e-3).unwrap();
        solver.solve_depth(&sphere, 1e-7, None, &mut ()).unwrap();
        solver.set_coarse_blocks(Some(5)).unwrap();
        let balancing = solver.balancing.take().unwrap();
        let space = &balancing.space;
        let n = grid.len();
        let seeded = |c: usize, k: usize| ((c * 7919 + k * 104729) % 1013) as f64 / 1013.0 - 0.4;
        let ws = &mut solver.workspace;
        for c in 0..n {
            ws.working[c] = (c / columns * 3 + c % columns * 7) % 5 != 0;
            ws.gap[c] = 1e-5 * seeded(c, 1);
            ws.response[c] = if ws.working[c] {
                1e6 * seeded(c, 2)
            } else {
                0.0
            };
        }
        let (working, gap, y) = (ws.working.clone(), ws.gap.clone(), ws.response.clone());
        let coarse: Vec<f64> = (0..space.len())
            .map(|b| 1e6 * (seeded(b, 3) + 1.0))
            .collect();
        let shift = 3e-6;
        let block_of = |c: usize| {
            space
                .row_runs(c / columns)
                .find(|(_, range)| range.contains(&(c % columns)))
                .unwrap()
                .0
        };
        // r - A~ Z c against the reference.
        let largest = coarse.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        solver
            .coarse_load_residual(space, &coarse, largest, shift)
            .unwrap();
        let z_c: Vec<f64> = (0..n)
            .map(|c| if working[c] { coarse[block_of(c)] } else { 0.0 })
            .collect();
        let u = through_coarse(&mut solver, &z_c, columns);
        let half = columns.div_ceil(2);
        let at = |c: usize| (c / columns / 2) * half + (c % columns) / 2;
        let u_max = u.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for c in 0..n {
            let expected = if working[c] {
                gap[c] - shift - u[at(c)]
            } else {
                0.0
            };
            let got = solver.workspace.previous[c];
            assert!(
                (got - expected).abs() <= 1e-5 * u_max,
                "cell {c}: {got} against {expected}"
            );
        }
        let y_dot_azc: f64 = (0..n).map(|c| y[c] * u[at(c)]).sum();
        // Z^T A~ y against the reference.
        let y_max = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let parts = solver.block_sums_of_response(space, y_max).unwrap();
        let mut sums = vec![0.0; space.len()];
        space.gather(&parts, &mut sums);
        let v = through_coarse(&mut solver, &y, columns);
        let mut expected = vec![0.0; space.len()];
        for c in (0..n).filter(|c| working[*c]) {
            expected[block_of(c)] += v[at(c)];
        }
        let s_max = expected.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for (b, (got, want)) in sums.iter().zip(&expected).enumerate() {
            assert!(
                (got - want).abs() <= 1e-5 * s_max,
                "block {b}: {got} against {want}"
            );
        }
        let c_dot_ztay: f64 = coarse.iter().zip(&sums).map(|(a, b)| a * b).sum();
        assert!(
            (y_dot_azc / c_dot_ztay - 1.0).abs() < 1e-5,
            "{y_dot_azc} against {c_dot_ztay}"
        );
    }
}
