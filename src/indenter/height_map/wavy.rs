//! The wavy surface of Johnson's adhesive sinusoid on a periodic grid, at
//! any orientation that tiles the period.

use std::f64::consts::PI;

use crate::error::{positive_finite, Error, Result};
use crate::grid::Grid;

use super::HeightMap;

impl HeightMap {
    /// The wavy surface `h = A (1 - cos(2 pi phase))`, `phase = w0 i / rows
    /// + w1 j / columns` (its fractional part, exact) at cell `(i, j)`:
    /// `waves = (w0, w1)` whole waves along the grid's rows and columns, so
    /// that it is periodic on the grid's period, its crests straight, along the grid for `(w, 0)` or
    /// `(0, w)` and at 45 degrees on a square grid for `(w, w)`; its
    /// wavelength is [`HeightMap::wavy_wavelength`]. Its troughs (height 0)
    /// touch first. The surface of Johnson's adhesive sinusoid (K. L.
    /// Johnson 1995, Int. J. Solids Struct. 32, 423-430;
    /// [`JkrSinusoid`](crate::analytic::JkrSinusoid)) in plane strain.
    ///
    /// ```
    /// use layered_contact::indenter::HeightMap;
    /// use layered_contact::Grid;
    ///
    /// let grid = Grid::new(64, 8, 1e-5)?;
    /// let map = HeightMap::wavy(grid, (1, 0), 2e-6)?;
    /// assert_eq!(HeightMap::wavy_wavelength(&grid, (1, 0))?, 64.0 * 1e-5);
    /// // A crest half a wavelength from the trough, along every column.
    /// assert!((map.heights()[32 * 8 + 5] - 4e-6).abs() < 1e-20);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`HeightMap::wavy_wavelength`]; [`Error::InvalidParameter`] for
    /// an amplitude that is not positive and finite.
    pub fn wavy(grid: Grid, waves: (usize, usize), amplitude: f64) -> Result<Self> {
        Self::wavy_wavelength(&grid, waves)?;
        let amplitude = positive_finite("amplitude of the wavy surface (m)", amplitude)?;
        let (rows, columns) = (grid.rows() as u128, grid.columns() as u128);
        let period = rows * columns;
        // The phase as a whole fraction of the period, so that the cells
        // of one crest take exactly one height.
        let heights = (0..grid.len() as u128)
            .map(|c| {
                let (i, j) = (c / columns, c % columns);
                let turns = (waves.0 as u128 * i * columns + waves.1 as u128 * j * rows) % period;
                let phase = turns as f64 / period as f64;
                amplitude * (1.0 - (2.0 * PI * phase).cos())
            })
            .collect();
        HeightMap::new(grid, heights)
    }

    /// The wavelength (m) of [`HeightMap::wavy`]'s surface with `waves`
    /// whole waves along the rows and columns of `grid`: `Delta /
    /// sqrt((w0 / rows)^2 + (w1 / columns)^2)`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for no wave (`(0, 0)`) or a wavelength
    /// under two cells (the grid cannot carry it).
    pub fn wavy_wavelength(grid: &Grid, waves: (usize, usize)) -> Result<f64> {
        let (kx, ky) = (
            waves.0 as f64 / grid.rows() as f64,
            waves.1 as f64 / grid.columns() as f64,
        );
        let per_cell = kx.hypot(ky);
        if !(per_cell > 0.0 && per_cell <= 0.5) {
            return Err(Error::InvalidParameter {
                name: "waves per cell of the wavy surface",
                value: per_cell,
                expected: "above 0 and at most 1/2 (a wavelength of at least two cells)",
            });
        }
        Ok(grid.spacing() / per_cell)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wavelength_and_the_crests_are_exact_and_bad_waves_are_refused() {
        let grid = Grid::new(100, 100, 1e-5).unwrap();
        // (3, 4) waves: 0.05 a cell, 20 cells.
        let wavelength = HeightMap::wavy_wavelength(&grid, (3, 4)).unwrap();
        assert!((wavelength / 2e-4 - 1.0).abs() < 1e-15);
        // At 45 degrees every cell of a diagonal takes one height.
        let map = HeightMap::wavy(grid, (7, 7), 1e-6).unwrap();
        let h = map.heights();
        for i in 1..100 {
            assert_eq!(h[i * 100 + (99 - i)], h[99], "{i}");
        }
        assert!(h[99] > 0.0);
        // Half a wave from the trough: twice the amplitude.
        let strip = HeightMap::wavy(Grid::new(64, 8, 1e-5).unwrap(), (1, 0), 1e-6).unwrap();
        assert!((strip.heights()[32 * 8] - 2e-6).abs() < 1e-21);
        for waves in [(0, 0), (51, 0), (40, 40)] {
            assert!(matches!(
                HeightMap::wavy(grid, waves, 1e-6),
                Err(Error::InvalidParameter { .. })
            ));
        }
        for amplitude in [0.0, -1e-6, f64::NAN, f64::INFINITY] {
            assert!(HeightMap::wavy(grid, (1, 0), amplitude).is_err());
        }
    }
}
