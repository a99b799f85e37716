//! The surface grid of the boundary-element method.

use crate::error::{positive_finite, Error, Result};

/// The largest number of cells along one axis.
pub const MAX_CELLS_PER_AXIS: usize = 1 << 15;
/// The largest number of cells in a grid, `2^30` (32768 x 32768: the
/// isolated operator works on four times as many). One process has the
/// memory for about `2^26` on 24 GiB ([`crate::kernel::memory_estimate`]);
/// larger grids run split across MPI ranks (the `mpi` feature).
pub const MAX_CELLS: usize = 1 << 30;

/// A rectangular grid of `rows x columns` square cells of side `spacing`
/// (`Delta`, m), carrying a pressure uniform in each cell.
///
/// Fields on the grid are row-major slices: cell `(i, j)` (row `i`, column
/// `j`) is element `i * columns + j`; its centre is at
/// `((i + 1/2) Delta, (j + 1/2) Delta)` from the grid's corner.
///
/// ```
/// use layered_contact::Grid;
///
/// let grid = Grid::new(64, 48, 1e-4)?;
/// assert_eq!(grid.len(), 64 * 48);
/// assert!((grid.extent().0 - 6.4e-3).abs() < 1e-15);
/// assert!(Grid::new(0, 8, 1e-4).is_err());
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    rows: usize,
    columns: usize,
    spacing: f64,
}

impl Grid {
    /// A grid of `rows x columns` cells of side `spacing` (m).
    ///
    /// # Errors
    /// [`Error::InvalidGrid`] if a dimension is 0 or the grid exceeds
    /// [`MAX_CELLS_PER_AXIS`] or [`MAX_CELLS`];
    /// [`Error::InvalidParameter`] if `spacing` is not positive and finite.
    pub fn new(rows: usize, columns: usize, spacing: f64) -> Result<Self> {
        if rows == 0 || columns == 0 {
            return Err(Error::InvalidGrid {
                rows,
                columns,
                expected: "at least one cell along each axis",
            });
        }
        if rows > MAX_CELLS_PER_AXIS
            || columns > MAX_CELLS_PER_AXIS
            || rows.saturating_mul(columns) > MAX_CELLS
        {
            return Err(Error::InvalidGrid {
                rows,
                columns,
                expected: "at most 2^15 cells per axis and 2^30 cells in all",
            });
        }
        Ok(Grid {
            rows,
            columns,
            spacing: positive_finite("spacing", spacing)?,
        })
    }

    /// A square grid of `n x n` cells covering a square of side `side` (m):
    /// cells of side `side / n` (where [`Grid::new`] takes the cell's side).
    ///
    /// ```
    /// let grid = layered_contact::Grid::square_of_side(64, 1e-3)?;
    /// assert_eq!(grid.spacing(), 1e-3 / 64.0);
    /// # Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Grid::new`].
    pub fn square_of_side(n: usize, side: f64) -> Result<Self> {
        Self::new(n, n, positive_finite("side", side)? / n.max(1) as f64)
    }

    /// The former name of [`Grid::square_of_side`], whose second argument
    /// (the side of the square, not of a cell as in [`Grid::new`]) its name
    /// did not say.
    ///
    /// # Errors
    /// As [`Grid::new`].
    #[deprecated(
        since = "0.1.0",
        note = "use Grid::square_of_side (the same arguments)"
    )]
    pub fn square(n: usize, side: f64) -> Result<Self> {
        Self::square_of_side(n, side)
    }

    /// Cells along the first axis.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Cells along the second axis.
    pub fn columns(&self) -> usize {
        self.columns
    }

    /// The side `Delta` of a cell, m.
    pub fn spacing(&self) -> f64 {
        self.spacing
    }

    /// The number of cells.
    pub fn len(&self) -> usize {
        self.rows * self.columns
    }

    /// Always `false`: a grid has at least one cell.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The area of one cell, `Delta^2`, m^2.
    pub fn cell_area(&self) -> f64 {
        self.spacing * self.spacing
    }

    /// The centre `(x, y)` (m) of cell `(i, j)`, the axis at the grid's
    /// centre: `x = (i + 1/2) Delta - rows Delta / 2`,
    /// `y = (j + 1/2) Delta - columns Delta / 2`. Field arrays hold the
    /// value of cell `(i, j)` at `[i, j]`.
    ///
    /// ```
    /// let grid = layered_contact::Grid::new(4, 2, 1e-3)?;
    /// assert_eq!(grid.cell_centre(0, 1), (-1.5e-3, 0.5e-3));
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn cell_centre(&self, i: usize, j: usize) -> (f64, f64) {
        let (lx, ly) = self.extent();
        (
            (i as f64 + 0.5) * self.spacing - 0.5 * lx,
            (j as f64 + 0.5) * self.spacing - 0.5 * ly,
        )
    }

    /// The size of the gridded region `(rows Delta, columns Delta)`, m.
    pub fn extent(&self) -> (f64, f64) {
        (
            self.rows as f64 * self.spacing,
            self.columns as f64 * self.spacing,
        )
    }
}

/// How the gridded region relates to the rest of the surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Boundary {
    /// A single contact on an unbounded body (the default): the pressure
    /// vanishes outside the grid, and the convolution is done on a
    /// zero-padded grid of twice the size so that it does not wrap around.
    #[default]
    Isolated,
    /// The grid is one period of a doubly periodic surface.
    Periodic,
}

/// The smallest number of cells `>= n` whose prime factors are 2, 3, 5 and 7
/// only: FFTs of such (padded) lengths are several times faster than of
/// lengths with a large prime factor.
pub(crate) fn fft_friendly(n: usize) -> usize {
    // A power of two lies in [n, 2n]: the search is bounded.
    let n = n.max(1);
    (n..=2 * n)
        .find(|&m| seven_smooth_part(m) == 1)
        .unwrap_or(n)
}

/// `m` divided by its factors 2, 3, 5 and 7 (1 when it has no other).
fn seven_smooth_part(m: usize) -> usize {
    let mut rest = m;
    for p in [2, 3, 5, 7] {
        while rest.is_multiple_of(p) {
            rest /= p;
        }
    }
    rest
}

/// The largest odd part of the sizes [`fft_fast_even`] admits.
const FAST_ODD_PART: usize = 45;

/// The smallest even number of cells `>= n` whose half has no prime factor
/// above 7 and an odd part of at most 45 (a power of two times 1, 3, 5, 7,
/// 9, 15, 21, 25, 27, 35 or 45): a real-to-complex FFT of an even length is
/// a complex FFT of half the length, of an odd one a complex FFT of the
/// whole (at 1024 cells' spacing, a periodic convolution on 625 x 625 cells
/// took 2.2 times as long as on 640 x 640), and rustfft's complex
/// transforms of lengths with few factors of two run at up to 1.6 times
/// the time per point of those with many (this machine, 2026-11-29: 20.8
/// us for 4116 = 4 x 3 x 7^3 points against 14.4 us for 4608 = 2^9 x 9
/// and 11.8 us for 4096; 3.85 us for 1050 = 2 x 525 against 3.1 us for
/// 1152 and 1120). A power of two lies in `[n, 2n]`: the search is bounded.
pub(crate) fn fft_fast_even(n: usize) -> usize {
    let half = n.div_ceil(2).max(1);
    let admissible =
        |m: usize| m >> m.trailing_zeros() <= FAST_ODD_PART && seven_smooth_part(m) == 1;
    2 * (half..=2 * half).find(|&m| admissible(m)).unwrap_or(half)
}

#[cfg(test)]
mod tests {
    use super::{fft_fast_even, fft_friendly};

    /// Whether `m` has no prime factor above 7, by trial division.
    fn smooth(m: usize) -> bool {
        (2..=m).all(|p| !m.is_multiple_of(p) || p <= 7 || (2..p).any(|d| p % d == 0))
    }

    /// The odd part of `m`, by division.
    fn odd_part(mut m: usize) -> usize {
        while m.is_multiple_of(2) {
            m /= 2;
        }
        m
    }

    /// Against a brute-force search: the least admissible size at or above
    /// `n`, for every `n` up to 5000.
    #[test]
    fn fft_sizes_are_the_least_admissible() {
        for n in 1..=5000 {
            let plain = (n..).find(|&m| smooth(m)).unwrap();
            assert_eq!(fft_friendly(n), plain, "{n}");
            let even = (n..)
                .find(|&m| m.is_multiple_of(2) && smooth(m / 2) && odd_part(m / 2) <= 45)
                .unwrap();
            assert_eq!(fft_fast_even(n), even, "{n}");
        }
        // The sizes that motivated the odd part's bound.
        assert_eq!(fft_fast_even(4104), 4480);
        assert_eq!(fft_fast_even(1032), 1120);
    }
}
