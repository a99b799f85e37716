//! Trigonometric interpolation of a periodic height map onto a finer grid:
//! the same band-limited surface with more cells under each wavelength,
//! for convergence studies of rough contacts.

use std::f64::consts::PI;

use num_complex::Complex;
use rustfft::{Fft, FftPlanner};

use crate::error::{zeroed, Error, Result};
use crate::grid::Grid;

use super::HeightMap;

impl HeightMap {
    /// The map on a grid `factor` times finer each way over the same
    /// extent, by trigonometric interpolation: the map is read as one
    /// period of the band-limited surface
    /// `h(x, y) = (1 / (n0 n1)) sum_k H_k exp(2 pi i (kx x / Lx + ky y / Ly))`
    /// through its cell centres (`H` its discrete Fourier transform, `kx` in
    /// `-n0/2..n0/2`, a Nyquist coefficient split evenly between `+n/2` and
    /// `-n/2`), and that surface is sampled at the centres of the finer
    /// cells (Briggs & Henson 1995, *The DFT*, SIAM, section 6.5). A
    /// surface synthesised with its shortest wavelength at least two cells
    /// of the coarse grid ([`SelfAffine`](crate::topography::SelfAffine))
    /// is band-limited, and then this is the same continuous surface on a
    /// finer grid: a convergence study in the grid that keeps the surface
    /// (a new synthesis on each grid draws a new one). An odd `factor`
    /// keeps the coarse heights at the centres of the middle fine cells
    /// (to rounding); `factor = 1` returns the map itself.
    ///
    /// Meant for periodic grids: on an isolated grid the map is still
    /// treated as periodic, and a map whose edges do not meet overshoots
    /// near them (Gibbs). Memory: 16 bytes per fine cell (its spectrum)
    /// besides the result's 8.
    ///
    /// ```
    /// use layered_contact::indenter::HeightMap;
    /// use layered_contact::Grid;
    /// use std::f64::consts::PI;
    ///
    /// // cos(2 pi x / L) on 8 x 8 cells of a 1 mm square, refined 4 times.
    /// let grid = Grid::square_of_side(8, 1e-3)?;
    /// let centre = |i: usize, n: usize| (i as f64 + 0.5) / n as f64; // x / L
    /// let heights = (0..64).map(|c| (2.0 * PI * centre(c / 8, 8)).cos() * 1e-6).collect();
    /// let fine = HeightMap::new(grid, heights)?.refined(4)?;
    /// assert_eq!(fine.grid().rows(), 32);
    /// for (c, h) in fine.heights().iter().enumerate() {
    ///     let exact = (2.0 * PI * centre(c / 32, 32)).cos() * 1e-6;
    ///     assert!((h - exact).abs() < 1e-20);
    /// }
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a `factor` of 0 or a map with a
    /// `+inf` height (a point that cannot touch has no interpolant);
    /// [`Error::InvalidGrid`] if the finer grid exceeds [`Grid::new`]'s
    /// limits; [`Error::Unsupported`] for a distributed run's band of rows;
    /// [`Error::NonFinite`] where heights near `f64`'s limit overflow in
    /// the transforms; [`Error::OutOfMemory`] if its buffers cannot be
    /// allocated.
    pub fn refined(&self, factor: usize) -> Result<HeightMap> {
        if factor == 0 {
            return Err(Error::InvalidParameter {
                name: "refinement factor",
                value: 0.0,
                expected: "at least 1",
            });
        }
        if let Some(&bad) = self.heights.iter().find(|h| !h.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "height of a map to refine (m)",
                value: bad,
                expected: "finite everywhere (a point that cannot touch has no interpolant)",
            });
        }
        let (n0, n1) = (self.grid.rows(), self.grid.columns());
        if self.first_row != 0 || self.heights.len() != n0 * n1 {
            return Err(Error::Unsupported {
                feature: "refining a distributed run's band of rows",
                reason: "the interpolant needs every row: refine the whole map",
            });
        }
        let (m0, m1) = (n0.saturating_mul(factor), n1.saturating_mul(factor));
        let fine = Grid::new(m0, m1, self.grid.spacing() / factor as f64)?;
        if factor == 1 {
            return Ok(self.clone());
        }
        let mut planner = FftPlanner::<f64>::new();
        let mut spectrum: Vec<Complex<f64>> = zeroed(n0 * n1, "a height map's spectrum")?;
        for (s, h) in spectrum.iter_mut().zip(&self.heights) {
            *s = Complex::new(*h, 0.0);
        }
        transform_2d(&mut spectrum, (n0, n1), &mut planner, false);
        let mut values: Vec<Complex<f64>> = zeroed(m0 * m1, "a refined height map's spectrum")?;
        let (targets0, targets1) = (targets(n0, factor), targets(n1, factor));
        for (kx, row) in spectrum.chunks_exact(n1).enumerate() {
            for &(i, wx) in &targets0[kx] {
                let line = &mut values[i * m1..(i + 1) * m1];
                for (h, targets) in row.iter().zip(&targets1) {
                    for &(j, wy) in targets {
                        line[j] += h * wx * wy;
                    }
                }
            }
        }
        drop(spectrum);
        transform_2d(&mut values, (m0, m1), &mut planner, true);
        let scale = 1.0 / (n0 * n1) as f64;
        let mut heights: Vec<f64> = zeroed(m0 * m1, "a refined height map")?;
        for (h, v) in heights.iter_mut().zip(&values) {
            *h = v.re * scale;
        }
        // Heights near f64's limit overflow in the transforms.
        crate::solver::all_finite("refining a height map (heights near f64's limit)", &heights)?;
        HeightMap::new(fine, heights)
    }
}

/// Where coefficient `k` of `n` lands on a grid `factor` times finer, with
/// its weight: the signed wavenumber `s` (`-n/2 < s < n/2`, the Nyquist one
/// split half to `+n/2`, half to `-n/2`) times the phase that moves the
/// samples from the coarse cell centres to the fine ones, `exp(-2 pi i s
/// (factor - 1) / (2 factor n))` (the first fine centre lies `(factor - 1)
/// / 2` fine cells before the first coarse one).
fn targets(n: usize, factor: usize) -> Vec<Vec<(usize, Complex<f64>)>> {
    let m = n * factor;
    let shift = -((factor - 1) as f64) / (2.0 * (factor * n) as f64);
    let land = |s: isize, weight: f64| {
        let index = s.rem_euclid(m as isize) as usize;
        (
            index,
            Complex::from_polar(weight, 2.0 * PI * s as f64 * shift),
        )
    };
    (0..n)
        .map(|k| {
            let s = k as isize;
            if 2 * k < n {
                vec![land(s, 1.0)]
            } else if 2 * k > n {
                vec![land(s - n as isize, 1.0)]
            } else {
                vec![land(s, 0.5), land(-s, 0.5)]
            }
        })
        .collect()
}

/// The unnormalised 2D FFT of a row-major `rows x columns` array, in place
/// (inverse: `exp(+i ...)`).
fn transform_2d(
    values: &mut [Complex<f64>],
    (rows, columns): (usize, usize),
    planner: &mut FftPlanner<f64>,
    inverse: bool,
) {
    let plan = |n: usize, planner: &mut FftPlanner<f64>| -> std::sync::Arc<dyn Fft<f64>> {
        if inverse {
            planner.plan_fft_inverse(n)
        } else {
            planner.plan_fft_forward(n)
        }
    };
    let along_rows = plan(columns, planner);
    along_rows.process(values);
    let along_columns = plan(rows, planner);
    let mut line = vec![Complex::default(); rows];
    for j in 0..columns {
        for (value, source) in line.iter_mut().zip(values[j..].iter().step_by(columns)) {
            *value = *source;
        }
        along_columns.process(&mut line);
        for (value, target) in line.iter().zip(values[j..].iter_mut().step_by(columns)) {
            *target = *value;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A band-limited surface sampled on `grid`, defined on `coarse` (the
    /// same extent): modes `(p, q, amplitude, phase)` with `|p| < n0/2`,
    /// `|q| < n1/2` of the coarse grid, plus `cos(pi (y - y0) / Delta)`,
    /// the coarse columns' Nyquist mode, in phase with the first coarse
    /// cell centre `y0`.
    fn surface(grid: &Grid, coarse: &Grid) -> Vec<f64> {
        let (lx, ly) = coarse.extent();
        let modes = [
            (0, 1, 0.7, 0.3),
            (1, -2, 0.4, -1.1),
            (2, 3, 0.2, 2.0),
            (-2, 1, 0.1, 0.5),
        ];
        let y0 = coarse.cell_centre(0, 0).1;
        let n1 = grid.columns();
        (0..grid.len())
            .map(|c| {
                let (x, y) = grid.cell_centre(c / n1, c % n1);
                let waves: f64 = modes
                    .iter()
                    .map(|&(p, q, a, phase)| {
                        a * (2.0 * PI * (f64::from(p) * x / lx + f64::from(q) * y / ly) + phase)
                            .cos()
                    })
                    .sum();
                let nyquist = 0.3 * (PI * (y - y0) / coarse.spacing()).cos();
                1e-6 * (waves + nyquist)
            })
            .collect()
    }

    /// Refined by 2, 3 and 4, the map equals the same surface sampled at
    /// the finer cell centres, to the FFTs' rounding (about `1e-16 log2 N`
    /// of the amplitude; the bound is 1e-13 of it).
    #[test]
    fn a_band_limited_surface_is_sampled_exactly_on_finer_grids() {
        let coarse = Grid::new(8, 8, 1.25e-4).unwrap();
        // A square domain of 8 x 8 cells, and a rectangle of 6 x 10.
        let rectangle = Grid::new(6, 10, 1e-4).unwrap();
        for grid in [coarse, rectangle] {
            let map = HeightMap::new(grid, surface(&grid, &grid)).unwrap();
            for factor in [1, 2, 3, 4] {
                let fine = map.refined(factor).unwrap();
                let expected = surface(fine.grid(), &grid);
                assert_eq!(fine.grid().extent(), grid.extent());
                let worst = fine
                    .heights()
                    .iter()
                    .zip(&expected)
                    .map(|(h, e)| (h - e).abs())
                    .fold(0.0, f64::max);
                assert!(worst < 1e-13 * 1e-6, "{grid:?} by {factor}: {worst:e}");
            }
        }
    }

    /// An odd factor puts a fine cell centre on every coarse one: the
    /// coarse heights come back there, whatever the map (here not
    /// band-limited: a ramp with a jump at the period's edge).
    #[test]
    fn an_odd_factor_keeps_the_coarse_heights() {
        let grid = Grid::new(5, 7, 1e-4).unwrap();
        let heights: Vec<f64> = (0..35)
            .map(|c| 1e-6 * f64::from(c % 7 + c / 7 * 3))
            .collect();
        let map = HeightMap::new(grid, heights.clone()).unwrap();
        let fine = map.refined(3).unwrap();
        for (c, h) in heights.iter().enumerate() {
            let (i, j) = (c / 7, c % 7);
            let value = fine.heights()[(3 * i + 1) * 21 + 3 * j + 1];
            assert!(
                (value - h).abs() < 1e-13 * 1e-5,
                "cell {c}: {value:e} against {h:e}"
            );
        }
    }

    #[test]
    fn bad_refinements_are_refused() {
        let grid = Grid::new(4, 4, 1e-4).unwrap();
        let map = HeightMap::new(grid, vec![0.0; 16]).unwrap();
        assert!(matches!(
            map.refined(0),
            Err(Error::InvalidParameter { .. })
        ));
        assert!(matches!(
            map.refined(1 << 14),
            Err(Error::InvalidGrid { rows: 65536, .. })
        ));
        let huge = HeightMap::new(grid, [1e308, -1e308, 1e308, -1e308].repeat(4)).unwrap();
        assert!(huge.refined(2).is_err());
        let mut heights = vec![0.0; 16];
        heights[5] = f64::INFINITY;
        let map = HeightMap::new(grid, heights).unwrap();
        assert!(matches!(
            map.refined(2),
            Err(Error::InvalidParameter { .. })
        ));
    }
}
