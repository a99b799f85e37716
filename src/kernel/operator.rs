//! The compliance operator: pressure -> surface displacement by FFT
//! convolution, with its plans and scratch buffers.

use std::f64::consts::PI;
use std::sync::Arc;

use num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use crate::error::{Error, Result};
use crate::grid::{Boundary, Grid};
use crate::substrate::Substrate;

use super::fourier::FourierCompliance;
use super::influence::InfluenceCoefficients;

/// Applies the compliance of a substrate on a grid: given the cell pressures
/// `p` (Pa, row-major), the displacements `u` (m) at the cell centres,
/// `u_i = sum_j K(i - j) p_j`.
///
/// Built once per (substrate, grid, boundary) and applied any number of
/// times: it owns its FFT plans, the kernel's spectrum and every scratch
/// buffer, so an application allocates nothing.
///
/// * [`Boundary::Isolated`]: the influence coefficients
///   ([`InfluenceCoefficients`]) are convolved on a zero-padded
///   `2 rows x 2 columns` grid, so nothing wraps around; the result equals the
///   dense sum to rounding.
/// * [`Boundary::Periodic`]: the grid is one period; the multiplier is
///   `u_z(q) sinc(q_x Delta / 2) sinc(q_y Delta / 2)` at the periodic
///   wavevectors. The mean (`q = 0`) mode carries the uniaxial-strain
///   compliance on a rigid base and is set to 0 otherwise (the mean
///   displacement of a periodic half-space is undetermined; it is fixed by
///   the indenter's approach instead).
///
/// One application costs one real-to-complex and one complex-to-real 2D FFT
/// of the (padded) grid; half the padded rows are known to be zero and are
/// skipped.
///
/// ```
/// use layered_contact::kernel::ComplianceOperator;
/// use layered_contact::{Boundary, Grid, Material, Substrate};
///
/// let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.45)?, 1e-3)?;
/// let grid = Grid::new(16, 16, 1e-4)?;
/// let mut operator = ComplianceOperator::new(&film, &grid, Boundary::Isolated)?;
/// let mut pressure = vec![0.0; grid.len()];
/// pressure[8 * 16 + 8] = 1e3; // 1 kPa on one cell
/// let mut displacement = vec![0.0; grid.len()];
/// operator.apply(&pressure, &mut displacement)?;
/// let k = operator.influence().unwrap();
/// assert!((displacement[8 * 16 + 8] - 1e3 * k.get(0, 0)).abs() < 1e-12 * displacement[8 * 16 + 8]);
/// Ok::<(), layered_contact::Error>(())
/// ```
pub struct ComplianceOperator {
    grid: Grid,
    boundary: Boundary,
    influence: Option<InfluenceCoefficients>,
    /// Whether the kernel is that of a coated body (else a half-space's).
    layered: bool,
    /// Whether the body is a layer on a rigid base.
    rigid_base: bool,
    /// FFT sizes: rows and columns of the (padded) grid.
    size: (usize, usize),
    /// The kernel's spectrum, transposed (`columns/2 + 1` rows of `rows`
    /// values) and divided by the FFT normalisation `rows * columns`.
    spectrum: Vec<f64>,
    /// The spectrum of an approximate inverse, `E* |q| / 2` on the same
    /// grid (built on first use by [`ComplianceOperator::precondition`]).
    inverse_spectrum: Vec<f64>,
    /// `E*` of the surface material, for the approximate inverse.
    surface_modulus: f64,
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
    workspace: Workspace,
}

/// Scratch buffers owned by the operator.
struct Workspace {
    real: Vec<f64>,
    rows: Vec<Complex<f64>>,
    columns: Vec<Complex<f64>>,
    /// One scratch buffer per task of the row and column passes.
    scratch: Vec<Vec<Complex<f64>>>,
    /// Rows (of the padded grid) per task of the row passes.
    rows_per_task: usize,
    /// Columns (of the half spectrum) per task of the column passes.
    columns_per_task: usize,
}

/// Tasks the row and column passes are split into: one per thread (with the
/// `parallel` feature, and for grids of at least 2^16 padded cells, below
/// which the fork costs more than it saves), else one. Each row or column is
/// transformed by the same code whatever the split, so results do not depend
/// on it.
fn task_count(padded_cells: usize) -> usize {
    #[cfg(feature = "parallel")]
    {
        if padded_cells >= 1 << 16 {
            return rayon::current_num_threads().max(1);
        }
    }
    let _ = padded_cells;
    1
}

/// One task of the column pass: its columns, their multipliers, a scratch buffer.
type ColumnTask<'a> = (
    &'a mut [Complex<f64>],
    (&'a [f64], &'a mut Vec<Complex<f64>>),
);

/// Runs `f` on matching chunks of `a` and `b` with one scratch buffer each,
/// in parallel with the `parallel` feature.
fn for_each_chunk<A: Send, B: Send>(
    a: &mut [A],
    a_chunk: usize,
    b: &mut [B],
    b_chunk: usize,
    scratch: &mut [Vec<Complex<f64>>],
    f: impl Fn(&mut [A], &mut [B], &mut [Complex<f64>]) -> Result<()> + Sync + Send,
) -> Result<()> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        a.par_chunks_mut(a_chunk)
            .zip(b.par_chunks_mut(b_chunk))
            .zip(scratch.par_iter_mut())
            .try_for_each(|((x, y), s)| f(x, y, s))
    }
    #[cfg(not(feature = "parallel"))]
    {
        a.chunks_mut(a_chunk)
            .zip(b.chunks_mut(b_chunk))
            .zip(scratch.iter_mut())
            .try_for_each(|((x, y), s)| f(x, y, s))
    }
}

impl std::fmt::Debug for ComplianceOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ComplianceOperator")
            .field("grid", &self.grid)
            .field("boundary", &self.boundary)
            .field("fft_size", &self.size)
            .finish_non_exhaustive()
    }
}

/// Bytes of the compliance operator's buffers and a solver's per-cell
/// vectors on `grid`: the padded real array, two complex half-spectra, the
/// kernel's spectrum (and the preconditioner's, built on first use), the
/// influence coefficients and eight per-cell solver vectors.
pub fn memory_estimate(grid: &Grid, boundary: Boundary) -> usize {
    let (n0, n1) = match boundary {
        Boundary::Isolated => (2 * grid.rows(), 2 * grid.columns()),
        Boundary::Periodic => (grid.rows(), grid.columns()),
    };
    let half = n1 / 2 + 1;
    let cells = grid.len();
    8 * n0 * n1 + 2 * 16 * n0 * half + 2 * 8 * n0 * half + 8 * cells + 8 * 8 * cells
}

/// A zeroed vector of `len` values, or [`Error::OutOfMemory`].
fn zeroed<T: Clone + Default>(len: usize) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| Error::OutOfMemory {
        bytes: len.saturating_mul(std::mem::size_of::<T>()),
        what: "an FFT buffer",
    })?;
    v.resize(len, T::default());
    Ok(v)
}

/// Cell compliances `Delta / E*` outside this range make influence
/// coefficients or pressures leave the normal `f64` range.
const MIN_CELL_COMPLIANCE: f64 = 1e-280;
const MAX_CELL_COMPLIANCE: f64 = 1e280;
/// The thinnest layer on a rigid base, in cells (`h / Delta`).
pub const MIN_THICKNESS_OVER_SPACING: f64 = 1e-3;
/// Layers on a rigid base at least this many cells thick have coefficients
/// verified against an independent quadrature for every `nu`.
const VERIFIED_THICKNESS_OVER_SPACING: f64 = 0.5;
/// The smallest uniaxial-strain compliance of a thinner film, relative to
/// the cell's half-space compliance, that the coefficients resolve.
const MIN_FILM_COMPLIANCE: f64 = 1e-4;
/// The largest relative share of the squeeze-film (lubrication) compliance
/// `~ (h/Delta)^2 M / mu` of the uniaxial one that a thinner film may have:
/// below half a cell the coefficients settle by uniaxial strain alone.
const MAX_SQUEEZE_SHARE: f64 = 0.01;

/// Checks that a layer on a rigid base is thick enough, relative to the
/// cells, for its influence coefficients to mean something. From half a
/// cell up (`h / Delta >= 0.5`) they are verified for every `nu`. Thinner
/// films, down to `h / Delta = 1e-3`, settle by uniaxial strain, `u = p h /
/// M` (`M` the uniaxial-strain modulus), which is right only where that
/// compliance is resolvable (at least `1e-4` of the cell's half-space
/// compliance `Delta / E*`) and where the squeeze-film flow of a nearly
/// incompressible film, whose compliance is `(h/Delta)^2 M / mu` times the
/// uniaxial one, is negligible (below 1 %). A nearly incompressible film
/// thinner than half a cell (`nu -> 0.5`, `M -> inf`) is refused: its
/// coefficients would be rounding noise, not positive definite. Use a finer
/// grid there.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `h / Delta` and the range.
pub fn check_film(substrate: &Substrate, grid: &Grid) -> Result<()> {
    let Substrate::Coated(coating) = substrate else {
        return Ok(());
    };
    if !matches!(coating.base(), crate::substrate::Base::Rigid) {
        return Ok(());
    }
    // The limits hold to rounding: h = 1e-7 on Delta = 1e-4 is 1e-3.
    let ratio = coating.thickness() / grid.spacing() * (1.0 + 1e-12);
    if ratio.is_nan() || ratio < MIN_THICKNESS_OVER_SPACING {
        return Err(Error::InvalidParameter {
            name: "h / Delta (layer thickness over cell size)",
            value: ratio,
            expected: "at least 1e-3 on a rigid base",
        });
    }
    if ratio >= VERIFIED_THICKNESS_OVER_SPACING {
        return Ok(());
    }
    let layer = coating.layer();
    let uniaxial = layer.uniaxial_strain_modulus();
    let film = ratio * layer.contact_modulus() / uniaxial;
    let squeeze = ratio * ratio * uniaxial / layer.shear_modulus();
    if !(film >= MIN_FILM_COMPLIANCE && squeeze <= MAX_SQUEEZE_SHARE) {
        return Err(Error::InvalidParameter {
            name: "h / Delta (layer thickness over cell size)",
            value: ratio,
            expected: "at least 0.5 for this nearly incompressible film on a rigid base \
                       (below, its squeeze-film compliance is not resolved; refine the grid)",
        });
    }
    Ok(())
}

impl ComplianceOperator {
    /// The operator of `substrate` on `grid` with `boundary`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a layer on a rigid base thinner than
    /// the grid can resolve (see [`check_film`]), or a cell whose compliance
    /// `Delta / E*` is not a normal `f64` number (cell size and modulus out of
    /// range together).
    pub fn new(substrate: &Substrate, grid: &Grid, boundary: Boundary) -> Result<Self> {
        check_film(substrate, grid)?;
        let cell_compliance = grid.spacing() / substrate.surface_material().contact_modulus();
        if !(MIN_CELL_COMPLIANCE..=MAX_CELL_COMPLIANCE).contains(&cell_compliance) {
            return Err(Error::InvalidParameter {
                name: "cell compliance Delta / E* (m/Pa)",
                value: cell_compliance,
                expected: "within [1e-280, 1e280]: rescale lengths or moduli",
            });
        }
        let (rows, columns) = (grid.rows(), grid.columns());
        let size = match boundary {
            Boundary::Isolated => (2 * rows, 2 * columns),
            Boundary::Periodic => (rows, columns),
        };
        // The big buffers (padded real array, two complex half-spectra, the
        // kernel's spectrum, the solver's per-cell vectors): reserve all at
        // once first, so that a grid too large for this machine is a typed
        // error carrying the estimate instead of an abort.
        let estimate = memory_estimate(grid, boundary);
        Vec::<u8>::new()
            .try_reserve_exact(estimate)
            .map_err(|_| Error::OutOfMemory {
                bytes: estimate,
                what: "the compliance operator and solver buffers",
            })?;
        let mut real_planner = RealFftPlanner::<f64>::new();
        let row_forward = real_planner.plan_fft_forward(size.1);
        let row_inverse = real_planner.plan_fft_inverse(size.1);
        let mut planner = FftPlanner::<f64>::new();
        let column_forward = planner.plan_fft_forward(size.0);
        let column_inverse = planner.plan_fft_inverse(size.0);
        let half = size.1 / 2 + 1;
        let scratch_len = [
            row_forward.get_scratch_len(),
            row_inverse.get_scratch_len(),
            column_forward.get_inplace_scratch_len(),
            column_inverse.get_inplace_scratch_len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        let tasks = task_count(size.0 * size.1);
        let workspace = Workspace {
            real: zeroed(size.0 * size.1)?,
            rows: zeroed(size.0 * half)?,
            columns: zeroed(size.0 * half)?,
            scratch: vec![vec![Complex::default(); scratch_len]; tasks],
            rows_per_task: size.0.div_ceil(tasks),
            columns_per_task: half.div_ceil(tasks),
        };
        let mut operator = ComplianceOperator {
            grid: *grid,
            boundary,
            influence: None,
            layered: matches!(substrate, Substrate::Coated(_)),
            rigid_base: matches!(substrate, Substrate::Coated(c) if matches!(c.base(), crate::substrate::Base::Rigid)),
            size,
            spectrum: Vec::new(),
            inverse_spectrum: Vec::new(),
            surface_modulus: substrate.surface_material().contact_modulus(),
            row_forward,
            row_inverse,
            column_forward,
            column_inverse,
            workspace,
        };
        operator.spectrum = match boundary {
            Boundary::Isolated => {
                let influence = InfluenceCoefficients::isolated(substrate, grid);
                let spectrum = operator.isolated_spectrum(&influence)?;
                operator.influence = Some(influence);
                spectrum
            }
            Boundary::Periodic => operator.periodic_spectrum(&FourierCompliance::new(substrate)),
        };
        Ok(operator)
    }

    /// Whether the uniform pressure mode has a finite compliance: on an
    /// isolated grid always; on a periodic grid only for a layer on a rigid
    /// base (elsewhere a uniform pressure on an infinite body sinks without
    /// bound, and the mean displacement is undetermined).
    pub fn uniform_mode_bounded(&self) -> bool {
        self.boundary == Boundary::Isolated || self.rigid_base
    }

    /// The grid the operator acts on.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The boundary condition it was built for.
    pub fn boundary(&self) -> Boundary {
        self.boundary
    }

    /// Whether a layered kernel was built (`false` for a homogeneous
    /// half-space, which needs only Love's closed form or `2/(E* q)`).
    pub fn is_layered(&self) -> bool {
        self.layered
    }

    /// The influence coefficients (isolated operators only).
    pub fn influence(&self) -> Option<&InfluenceCoefficients> {
        self.influence.as_ref()
    }

    /// The spectrum of the coefficients placed on the padded grid in
    /// wrap-around order (offset `-d` at index `n - d`).
    fn isolated_spectrum(&mut self, influence: &InfluenceCoefficients) -> Result<Vec<f64>> {
        let (n0, n1) = self.size;
        let (rows, columns) = (self.grid.rows(), self.grid.columns());
        let offset = |index: usize, n: usize, cells: usize| -> Option<isize> {
            match index {
                i if i < cells => Some(i as isize),
                i if i == cells => None,
                i => Some(i as isize - n as isize),
            }
        };
        for i in 0..n0 {
            for j in 0..n1 {
                self.workspace.real[i * n1 + j] =
                    match (offset(i, n0, rows), offset(j, n1, columns)) {
                        (Some(di), Some(dj)) => influence.get(di, dj),
                        _ => 0.0,
                    };
            }
        }
        self.forward_all_rows()?;
        let normalisation = 1.0 / (n0 * n1) as f64;
        Ok(self
            .workspace
            .columns
            .iter()
            .map(|c| c.re * normalisation)
            .collect())
    }

    /// `u_z(|q|) sinc(q_x Delta/2) sinc(q_y Delta/2)` at the periodic
    /// wavevectors, transposed like the column buffer.
    fn periodic_spectrum(&self, compliance: &FourierCompliance) -> Vec<f64> {
        let (n0, n1) = self.size;
        let delta = self.grid.spacing();
        let half = n1 / 2 + 1;
        let wavenumber = |index: usize, n: usize| wavenumber(index, n, delta);
        let sinc = |x: f64| if x == 0.0 { 1.0 } else { x.sin() / x };
        let zero_mode = compliance.at_zero();
        let zero_mode = if zero_mode.is_finite() {
            zero_mode
        } else {
            0.0
        };
        let normalisation = 1.0 / (n0 * n1) as f64;
        let mut spectrum = vec![0.0; half * n0];
        for ky in 0..half {
            let qy = wavenumber(ky, n1);
            for kx in 0..n0 {
                let qx = wavenumber(kx, n0);
                let value = if kx == 0 && ky == 0 {
                    zero_mode
                } else {
                    compliance.eval(qx.hypot(qy)) * sinc(0.5 * qx * delta) * sinc(0.5 * qy * delta)
                };
                spectrum[ky * n0 + kx] = value * normalisation;
            }
        }
        spectrum
    }

    /// Real-to-complex transform of every row of `workspace.real`, then the
    /// complex transform of every column; result transposed in
    /// `workspace.columns`.
    fn forward_all_rows(&mut self) -> Result<()> {
        let (n0, n1) = self.size;
        self.forward_rows(n0)?;
        let half = n1 / 2 + 1;
        let ws = &mut self.workspace;
        transpose::transpose(&ws.rows, &mut ws.columns, half, n0);
        let scratch = &mut ws.scratch[0];
        self.column_forward
            .process_with_scratch(&mut ws.columns, scratch);
        Ok(())
    }

    /// Complex-to-real transforms of the first `count` rows of
    /// `workspace.rows` into `workspace.real`.
    fn inverse_rows(&mut self, count: usize) -> Result<()> {
        let (_, n1) = self.size;
        let half = n1 / 2 + 1;
        let ws = &mut self.workspace;
        let per_task = ws.rows_per_task;
        let fft = &self.row_inverse;
        for_each_chunk(
            &mut ws.rows[..count * half],
            per_task * half,
            &mut ws.real[..count * n1],
            per_task * n1,
            &mut ws.scratch,
            |spectrum, real, scratch| {
                for (spectrum_row, row) in spectrum
                    .chunks_exact_mut(half)
                    .zip(real.chunks_exact_mut(n1))
                {
                    // A real signal has real DC and Nyquist terms; clear the rounding.
                    spectrum_row[0].im = 0.0;
                    if n1 % 2 == 0 {
                        spectrum_row[half - 1].im = 0.0;
                    }
                    fft.process_with_scratch(spectrum_row, row, scratch)
                        .map_err(fft_error)?;
                }
                Ok(())
            },
        )
    }

    /// Real-to-complex transforms of the first `count` rows of
    /// `workspace.real` into `workspace.rows`.
    fn forward_rows(&mut self, count: usize) -> Result<()> {
        let (_, n1) = self.size;
        let half = n1 / 2 + 1;
        let ws = &mut self.workspace;
        let per_task = ws.rows_per_task;
        let fft = &self.row_forward;
        for_each_chunk(
            &mut ws.real[..count * n1],
            per_task * n1,
            &mut ws.rows[..count * half],
            per_task * half,
            &mut ws.scratch,
            |real, spectrum, scratch| {
                for (row, out) in real
                    .chunks_exact_mut(n1)
                    .zip(spectrum.chunks_exact_mut(half))
                {
                    fft.process_with_scratch(row, out, scratch)
                        .map_err(fft_error)?;
                }
                Ok(())
            },
        )
    }

    /// Forward transform of every column, multiplication by `spectrum`, and
    /// inverse transform, one chunk of columns per task.
    fn filter_columns(&mut self, spectrum: &[f64]) {
        let (n0, _) = self.size;
        let ws = &mut self.workspace;
        let per_task = ws.columns_per_task * n0;
        let (forward, inverse) = (&self.column_forward, &self.column_inverse);
        let filter = |(columns, (k, scratch)): ColumnTask<'_>| {
            forward.process_with_scratch(columns, scratch);
            for (c, k) in columns.iter_mut().zip(k) {
                *c *= *k;
            }
            inverse.process_with_scratch(columns, scratch);
        };
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            ws.columns
                .par_chunks_mut(per_task)
                .zip(spectrum.par_chunks(per_task).zip(ws.scratch.par_iter_mut()))
                .for_each(filter);
        }
        #[cfg(not(feature = "parallel"))]
        {
            ws.columns
                .chunks_mut(per_task)
                .zip(spectrum.chunks(per_task).zip(ws.scratch.iter_mut()))
                .for_each(filter);
        }
    }

    /// Displacements `u = K p` for cell pressures `pressure` (both row-major
    /// over the grid).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] if a slice does not have `grid.len()` values.
    pub fn apply(&mut self, pressure: &[f64], displacement: &mut [f64]) -> Result<()> {
        let spectrum = std::mem::take(&mut self.spectrum);
        let result = self.convolve(pressure, displacement, &spectrum);
        self.spectrum = spectrum;
        result
    }

    /// Applies an approximate inverse of the operator, the half-space
    /// stiffness `E* |q| / 2` of the surface material on the same (padded)
    /// grid: a spectrally equivalent, symmetric positive-definite
    /// preconditioner for conjugate gradients on subsets of the grid.
    ///
    /// # Errors
    /// As [`ComplianceOperator::apply`].
    pub fn precondition(&mut self, residual: &[f64], result: &mut [f64]) -> Result<()> {
        if self.inverse_spectrum.is_empty() {
            self.inverse_spectrum = self.stiffness_spectrum();
        }
        let spectrum = std::mem::take(&mut self.inverse_spectrum);
        let outcome = self.convolve(residual, result, &spectrum);
        self.inverse_spectrum = spectrum;
        outcome
    }

    /// `E* |q| / 2` at the wavevectors of the (padded) grid, with the `q = 0`
    /// mode given the value of the smallest nonzero `|q|`, normalised and
    /// laid out like `spectrum`.
    fn stiffness_spectrum(&self) -> Vec<f64> {
        let (n0, n1) = self.size;
        let delta = self.grid.spacing();
        let half = n1 / 2 + 1;
        let wavenumber = |index: usize, n: usize| wavenumber(index, n, delta);
        let smallest = wavenumber(1, n0.max(n1).max(2)).abs();
        let normalisation = 1.0 / (n0 * n1) as f64;
        let mut spectrum = vec![0.0; half * n0];
        for ky in 0..half {
            let qy = wavenumber(ky, n1);
            for kx in 0..n0 {
                let q = wavenumber(kx, n0).hypot(qy).max(smallest);
                spectrum[ky * n0 + kx] = 0.5 * self.surface_modulus * q * normalisation;
            }
        }
        spectrum
    }

    /// `output = IFFT(spectrum * FFT(input))` on the (padded) grid.
    fn convolve(
        &mut self,
        pressure: &[f64],
        displacement: &mut [f64],
        spectrum: &[f64],
    ) -> Result<()> {
        let cells = self.grid.len();
        for (field, found) in [
            ("pressure", pressure.len()),
            ("displacement", displacement.len()),
        ] {
            if found != cells {
                return Err(Error::ShapeMismatch {
                    field,
                    expected: cells,
                    found,
                });
            }
        }
        let (n0, n1) = self.size;
        let (rows, columns) = (self.grid.rows(), self.grid.columns());
        let half = n1 / 2 + 1;
        // Rows of the pressure, zero-padded; the padding rows transform to zero.
        for (i, row) in self
            .workspace
            .real
            .chunks_exact_mut(n1)
            .take(rows)
            .enumerate()
        {
            row[..columns].copy_from_slice(&pressure[i * columns..(i + 1) * columns]);
            row[columns..].fill(0.0);
        }
        self.workspace.rows[rows * half..].fill(Complex::default());
        self.forward_rows(rows)?;
        let ws = &mut self.workspace;
        transpose::transpose(&ws.rows, &mut ws.columns, half, n0);
        self.filter_columns(spectrum);
        let ws = &mut self.workspace;
        transpose::transpose(&ws.columns, &mut ws.rows, n0, half);
        self.inverse_rows(rows)?;
        let ws = &self.workspace;
        for (i, row) in ws.real.chunks_exact(n1).take(rows).enumerate() {
            displacement[i * columns..(i + 1) * columns].copy_from_slice(&row[..columns]);
        }
        Ok(())
    }
}

/// Buffer sizes are fixed at construction, so an FFT error is a bug of this
/// module; it is reported rather than unwrapped.
fn fft_error(error: realfft::FftError) -> Error {
    Error::Internal {
        what: "FFT",
        detail: error.to_string(),
    }
}

/// The wavenumber (rad/m) of FFT index `index` on `n` cells of side `delta`,
/// indices above `n/2` standing for negative frequencies.
fn wavenumber(index: usize, n: usize, delta: f64) -> f64 {
    let k = if index <= n / 2 {
        index as f64
    } else {
        index as f64 - n as f64
    };
    2.0 * PI * k / (n as f64 * delta)
}
