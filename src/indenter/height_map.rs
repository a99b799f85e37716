//! An arbitrary indenter given by heights on a grid.

use std::io::{Read, Seek, SeekFrom};
use std::ops::Range;
use std::path::Path;

use crate::error::{Error, Result};
use crate::grid::Grid;

use super::Indenter;

mod refine;
mod wavy;

/// An indenter given by its heights at the cell centres of a grid, centred on
/// the axis: the value of cell `(i, j)` is the height at
/// `x = (i + 1/2 - rows/2) Delta`, `y = (j + 1/2 - columns/2) Delta`, and
/// applies to every point of that cell. Outside the map the indenter cannot
/// touch. Use a grid matching the solver's to sample it exactly.
///
/// ```
/// use layered_contact::indenter::{HeightMap, Indenter};
/// use layered_contact::Grid;
///
/// let grid = Grid::new(4, 4, 1e-4)?;
/// let heights: Vec<f64> = (0..16).map(|c| f64::from(c) * 0.5e-6).collect();
/// let map = HeightMap::new(grid, heights)?;
/// assert_eq!(map.height(-1.5e-4, -1.5e-4), 0.0); // cell (0, 0)
/// assert!((map.height(1.5e-4, 1.5e-4) - 7.5e-6).abs() < 1e-20); // cell (3, 3)
/// assert_eq!(map.height(3e-4, 0.0), f64::INFINITY);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct HeightMap {
    grid: Grid,
    /// The first row held: 0, except for a distributed run's band of rows
    /// ([`HeightMap::band`]).
    first_row: usize,
    heights: Vec<f64>,
}

impl HeightMap {
    /// A map of `heights` (m, row-major over `grid`; `+inf` allowed for
    /// points that cannot touch).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] if `heights` does not have `grid.len()`
    /// values; [`Error::InvalidParameter`] if one is NaN or `-inf`.
    pub fn new(grid: Grid, heights: Vec<f64>) -> Result<Self> {
        if heights.len() != grid.len() {
            return Err(Error::ShapeMismatch {
                field: "heights",
                expected: grid.len(),
                found: heights.len(),
            });
        }
        check_heights(&heights)?;
        Ok(HeightMap {
            grid,
            first_row: 0,
            heights,
        })
    }

    /// The rows `first_row..` of a map over `grid` (`heights` row-major, a
    /// whole number of rows): a distributed run's share, which its rank
    /// alone samples. The rows it does not hold read as `+inf`, like the
    /// points outside the map.
    pub(crate) fn band(grid: Grid, first_row: usize, heights: Vec<f64>) -> Result<Self> {
        let columns = grid.columns();
        let rows = heights.len() / columns.max(1);
        if rows * columns != heights.len() || first_row + rows > grid.rows() {
            return Err(Error::ShapeMismatch {
                field: "heights (a band of rows)",
                expected: (grid.rows() - first_row.min(grid.rows())) * columns,
                found: heights.len(),
            });
        }
        check_heights(&heights)?;
        Ok(HeightMap {
            grid,
            first_row,
            heights,
        })
    }
}

impl HeightMap {
    /// A height map from a NumPy `.npy` file of a 2D `float64` array (rows
    /// by columns, heights in m), on square cells of side `spacing` (m).
    ///
    /// # Errors
    /// [`Error::HeightMapFile`] if the file cannot be read or is not a 2D
    /// `float64` array; the errors of [`Grid::new`] and [`HeightMap::new`].
    pub fn from_npy(path: impl AsRef<Path>, spacing: f64) -> Result<Self> {
        let path = path.as_ref();
        let file_error = |detail: String| Error::HeightMapFile {
            path: path.display().to_string(),
            detail,
        };
        let bytes =
            crate::files::read_bounded(path, crate::files::MAX_NPY_BYTES).map_err(file_error)?;
        // The header's shape must fit in the bytes that follow it before
        // anything is allocated for it (a 160-byte file claiming 1e10
        // values aborted the process).
        let mut rest = bytes.as_slice();
        let header = ndarray_npy::npy::header::Header::from_reader(&mut rest)
            .map_err(|e| file_error(e.to_string()))?;
        let claimed = header
            .shape
            .iter()
            .try_fold(8usize, |total, &n| total.checked_mul(n));
        if claimed.is_none_or(|claimed| claimed > rest.len()) {
            return Err(file_error(format!(
                "its header claims shape {:?} of 8-byte values, but {} bytes follow it",
                header.shape,
                rest.len()
            )));
        }
        let array: ndarray::Array2<f64> = ndarray_npy::ReadNpyExt::read_npy(bytes.as_slice())
            .map_err(|e| file_error(e.to_string()))?;
        let (rows, columns) = array.dim();
        let grid = Grid::new(rows, columns, spacing)?;
        HeightMap::new(grid, array.iter().copied().collect())
    }

    /// The grid of the `.npy` height map at `path` on cells of side
    /// `spacing`, from its header alone.
    ///
    /// # Errors
    /// As [`HeightMap::from_npy`], for the header.
    pub(crate) fn npy_grid(path: &Path, spacing: f64) -> Result<Grid> {
        let layout = NpyLayout::of(path)?;
        Grid::new(layout.rows, layout.columns, spacing)
    }

    /// The rows `rows` of the `.npy` height map at `path` on cells of side
    /// `spacing` ([`HeightMap::band`]): a distributed run's share, read
    /// without the rest when the file holds little-endian `float64` in C
    /// order (else read whole and cut).
    ///
    /// # Errors
    /// As [`HeightMap::from_npy`].
    pub(crate) fn npy_band(path: &Path, spacing: f64, rows: Range<usize>) -> Result<Self> {
        let layout = NpyLayout::of(path)?;
        let grid = Grid::new(layout.rows, layout.columns, spacing)?;
        let columns = layout.columns;
        let rows = rows.start.min(layout.rows)..rows.end.min(layout.rows);
        if !layout.plain {
            let whole = HeightMap::from_npy(path, spacing)?;
            let heights = whole.heights[rows.start * columns..rows.end * columns].to_vec();
            return HeightMap::band(grid, rows.start, heights);
        }
        let file_error = |detail: String| Error::HeightMapFile {
            path: path.display().to_string(),
            detail,
        };
        let (mut file, _) =
            crate::files::open_bounded(path, crate::files::MAX_NPY_BYTES).map_err(file_error)?;
        let length = rows.len() * columns * 8;
        let mut bytes = Vec::new();
        bytes
            .try_reserve_exact(length)
            .map_err(|_| file_error(format!("{length} bytes could not be allocated")))?;
        bytes.resize(length, 0);
        file.seek(SeekFrom::Start(
            layout.data_start + (rows.start * columns * 8) as u64,
        ))
        .and_then(|_| file.read_exact(&mut bytes))
        .map_err(|e| file_error(format!("its rows {rows:?}: {e}")))?;
        let heights = bytes
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]))
            .collect();
        HeightMap::band(grid, rows.start, heights)
    }

    /// A height map from a text file with one row of the map per line,
    /// values separated by spaces, tabs or commas (heights in m; empty
    /// lines and lines starting with `#` are skipped), on square cells of
    /// side `spacing` (m).
    ///
    /// # Errors
    /// [`Error::HeightMapFile`] if the file cannot be read, a value is not a
    /// number (naming its line and column) or the rows differ in length; the
    /// errors of [`Grid::new`] and [`HeightMap::new`].
    pub fn from_text(path: impl AsRef<Path>, spacing: f64) -> Result<Self> {
        let path = path.as_ref();
        let file_error = |detail: String| Error::HeightMapFile {
            path: path.display().to_string(),
            detail,
        };
        let text = crate::files::read_text_bounded(path, crate::files::MAX_TEXT_MAP_BYTES)
            .map_err(file_error)?;
        let (mut heights, mut columns, mut rows) = (Vec::new(), None, 0usize);
        for (number, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let before = heights.len();
            for (column, word) in line
                .split(|c: char| c.is_whitespace() || c == ',')
                .filter(|w| !w.is_empty())
                .enumerate()
            {
                let value: f64 = word.parse().map_err(|_| {
                    file_error(format!(
                        "line {}, value {}: `{word}` is not a number",
                        number + 1,
                        column + 1
                    ))
                })?;
                heights.push(value);
            }
            let found = heights.len() - before;
            match columns {
                None => columns = Some(found),
                Some(c) if c != found => {
                    return Err(file_error(format!(
                        "line {} has {found} values, the first row {c}",
                        number + 1
                    )))
                }
                Some(_) => {}
            }
            rows += 1;
        }
        let grid = Grid::new(rows, columns.unwrap_or(0), spacing)?;
        HeightMap::new(grid, heights)
    }

    /// The grid of the map.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The heights (m, row-major): of every row of the grid, except in a
    /// rank's share of a distributed run (the scene of a rough surface split
    /// across MPI ranks), which holds its own rows only.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }
}

impl Indenter for HeightMap {
    fn height(&self, x: f64, y: f64) -> f64 {
        let (lx, ly) = self.grid.extent();
        let delta = self.grid.spacing();
        let i = ((x + 0.5 * lx) / delta).floor();
        let j = ((y + 0.5 * ly) / delta).floor();
        let columns = self.grid.columns();
        let held = self.first_row..self.first_row + self.heights.len() / columns.max(1);
        if i >= 0.0 && j >= 0.0 && held.contains(&(i as usize)) && (j as usize) < columns {
            self.heights[(i as usize - self.first_row) * columns + j as usize]
        } else {
            f64::INFINITY
        }
    }

    fn bounding_radius(&self) -> f64 {
        let (lx, ly) = self.grid.extent();
        0.5 * lx.hypot(ly)
    }
}

/// Every height finite or `+inf`.
fn check_heights(heights: &[f64]) -> Result<()> {
    match heights
        .iter()
        .find(|h| h.is_nan() || **h == f64::NEG_INFINITY)
    {
        Some(&bad) => Err(Error::InvalidParameter {
            name: "heights",
            value: bad,
            expected: "finite or +inf",
        }),
        None => Ok(()),
    }
}

/// Where a `.npy` file's values lie, from its header.
struct NpyLayout {
    rows: usize,
    columns: usize,
    /// The offset of the first value, bytes.
    data_start: u64,
    /// Whether the values are little-endian `float64` in C (row-major)
    /// order, so that a band of rows is a range of bytes.
    plain: bool,
}

impl NpyLayout {
    fn of(path: &Path) -> Result<Self> {
        let file_error = |detail: String| Error::HeightMapFile {
            path: path.display().to_string(),
            detail,
        };
        let (file, metadata) =
            crate::files::open_bounded(path, crate::files::MAX_NPY_BYTES).map_err(file_error)?;
        let mut counted = Counted {
            inner: file,
            bytes: 0,
        };
        let header = ndarray_npy::npy::header::Header::from_reader(&mut counted)
            .map_err(|e| file_error(e.to_string()))?;
        let (rows, columns) = match header.shape[..] {
            [rows, columns] => (rows, columns),
            _ => {
                return Err(file_error(format!(
                    "a height map is a 2D array, its header gives shape {:?}",
                    header.shape
                )))
            }
        };
        let data_start = counted.bytes;
        let holds = metadata.len().saturating_sub(data_start);
        let claimed = (rows as u64)
            .checked_mul(columns as u64)
            .and_then(|n| n.checked_mul(8));
        if claimed.is_none_or(|claimed| claimed > holds) {
            return Err(file_error(format!(
                "its header claims shape {:?} of 8-byte values, but {holds} bytes follow it",
                header.shape
            )));
        }
        let plain = !header.layout.is_fortran()
            && header.type_descriptor == <f64 as ndarray_npy::WritableElement>::type_descriptor();
        Ok(NpyLayout {
            rows,
            columns,
            data_start,
            plain,
        })
    }
}

/// A reader that counts the bytes read through it.
struct Counted<R> {
    inner: R,
    bytes: u64,
}

impl<R: Read> Read for Counted<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.bytes += n as u64;
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use ndarray::ShapeBuilder;

    use super::*;

    /// A band of rows read from a `.npy` file equals those rows of the
    /// whole map, whether read directly (C order) or through the whole
    /// file (Fortran order); the grid comes from the header alone.
    #[test]
    fn a_band_of_an_npy_map_equals_its_rows_of_the_whole() {
        let dir = std::env::temp_dir().join(format!("lc-npy-band-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let values: Vec<f64> = (0..35).map(|k| 1e-6 * f64::from(k * k % 11)).collect();
        for (name, array) in [
            (
                "c.npy",
                ndarray::Array2::from_shape_vec((7, 5), values.clone()),
            ),
            (
                "f.npy",
                ndarray::Array2::from_shape_vec((7, 5).f(), values.clone()),
            ),
        ] {
            let path = dir.join(name);
            ndarray_npy::write_npy(&path, &array.unwrap()).unwrap();
            let whole = HeightMap::from_npy(&path, 1e-4).unwrap();
            // C order is read in bands; Fortran order through the whole.
            assert_eq!(NpyLayout::of(&path).unwrap().plain, name == "c.npy");
            assert_eq!(HeightMap::npy_grid(&path, 1e-4).unwrap(), *whole.grid());
            for rows in [0..7, 2..5, 6..7, 3..3] {
                let band = HeightMap::npy_band(&path, 1e-4, rows.clone()).unwrap();
                assert_eq!(
                    band.heights(),
                    &whole.heights()[rows.start * 5..rows.end * 5]
                );
                for i in 0..7 {
                    let (x, y) = whole.grid().cell_centre(i, 4);
                    let expected = if rows.contains(&i) {
                        whole.height(x, y)
                    } else {
                        f64::INFINITY
                    };
                    assert_eq!(
                        band.height(x, y),
                        expected,
                        "{name}, rows {rows:?}, row {i}"
                    );
                }
            }
        }
        // A header that claims more values than follow is refused.
        let short = dir.join("short.npy");
        let mut bytes = std::fs::read(dir.join("c.npy")).unwrap();
        bytes.truncate(bytes.len() - 8);
        std::fs::write(&short, bytes).unwrap();
        assert!(matches!(
            HeightMap::npy_band(&short, 1e-4, 0..1),
            Err(Error::HeightMapFile { .. })
        ));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
