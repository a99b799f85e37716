//! The compliance operator: pressure -> surface displacement by FFT
//! convolution, with its plans and scratch buffers.

use crate::error::{Error, Result};
use crate::grid::{fft_fast_even, Boundary, Grid};
use crate::slab::Slab;
use crate::substrate::Substrate;

use super::convolution::{multiplier, wavenumber, Convolution};
use super::fourier::FourierCompliance;
use super::influence::InfluenceCoefficients;

mod energy;
mod halved;
mod single;

/// Applies the compliance of a substrate on a grid: given the cell pressures
/// `p` (Pa, row-major), the displacements `u` (m) at the cell centres,
/// `u_i = sum_j K(i - j) p_j`.
///
/// Built once per (substrate, grid, boundary) and applied any number of
/// times: it owns its FFT plans, the kernel's spectrum and every scratch
/// buffer, so no application allocates but the first (the FFT's buffer of
/// half-spectra, allocated on first use, which a solver also lends to its
/// preconditioner).
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
    /// The kernel's spectrum over the half-spectrum columns (`columns/2 + 1`
    /// columns of `rows/2 + 1` values of non-negative row wavenumbers, the
    /// spectrum being even, column-major on the FFT grid), divided by the
    /// FFT normalisation `rows * columns`.
    spectrum: Vec<f64>,
    /// The spectrum of an approximate inverse, `E* |q| / 2` on the same
    /// grid (built on first use by [`ComplianceOperator::precondition`]).
    inverse_spectrum: Vec<f64>,
    /// `E*` of the surface material, for the approximate inverse.
    surface_modulus: f64,
    convolution: Convolution,
    /// The same transform in single precision, for the energy and the
    /// early iterations' applications (`single.rs`; built on first use).
    single: Option<Convolution<f32>>,
    /// The power of two the spectrum is multiplied by as the
    /// single-precision transform narrows it (set when that is built).
    single_scale: f64,
    /// The split across the ranks of a distributed run, `None` when serial.
    slab: Option<Slab>,
}

impl std::fmt::Debug for ComplianceOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ComplianceOperator")
            .field("grid", &self.grid)
            .field("boundary", &self.boundary)
            .field("fft_size", &self.convolution.size())
            .finish_non_exhaustive()
    }
}

/// A compliance operator's FFT buffer, lent to another convolution
/// ([`ComplianceOperator::lend_buffer`]).
pub(crate) struct ShareBuffer(pub(super) Vec<num_complex::Complex<f64>>);

/// Bytes of the compliance operator's buffers and a solver's per-cell
/// vectors on `grid`: the complex half-spectra of the grid's rows, the
/// kernel's spectrum (and the preconditioner's, built on first use: in
/// single precision for contact solves, in double in the cohesive zone's
/// rounds, counted at the larger), the influence coefficients (while the
/// spectrum is built; kept up to [`KEEP_INFLUENCE_CELLS`]), a few FFT lines
/// per thread (and as many for the energy's transform in single
/// precision, which works in the operator's buffers), and ten per-cell
/// solver vectors.
pub fn memory_estimate(grid: &Grid, boundary: Boundary) -> usize {
    let size = fft_size(grid, boundary);
    let half = size.1 / 2 + 1;
    let cells = grid.len();
    Convolution::<f64>::memory(grid.rows(), size)
        + Convolution::<f32>::scratch_memory(size)
        + 2 * 8 * (size.0 / 2 + 1) * half
        + 8 * cells
        + 10 * 8 * cells
}

/// Bytes per rank of the compliance operator's buffers and a solver's
/// per-cell vectors on `grid` split across `ranks` ranks: each rank's share
/// of [`memory_estimate`], its rows' half-spectra and the two exchange
/// buffers,
/// and on an isolated grid the whole kernel spectrum that every rank
/// builds once (and the influence coefficients it is built from).
pub fn distributed_memory_estimate(grid: &Grid, boundary: Boundary, ranks: usize) -> usize {
    let size = fft_size(grid, boundary);
    let half = size.1 / 2 + 1;
    let ranks = ranks.max(1);
    let whole_spectrum = 8 * (size.0 / 2 + 1) * half;
    // On an isolated grid every rank builds the whole spectrum from the
    // influence coefficients, through the half-spectra of its rows; a
    // periodic grid's multipliers are built column by column.
    let building = match boundary {
        Boundary::Isolated => 8 * grid.len() + 3 * whole_spectrum,
        Boundary::Periodic => 0,
    };
    memory_estimate(grid, boundary).div_ceil(ranks)
        + building
        + 3 * 16 * grid.rows().div_ceil(ranks) * half
}

/// Checks that the cell compliance `Delta / E*` of `grid` lies where
/// coefficients and pressures stay normal `f64` numbers.
fn check_cell_compliance(grid: &Grid, modulus: f64) -> Result<()> {
    crate::error::within(
        "cell compliance Delta / E* (m/Pa)",
        grid.spacing() / modulus,
        (MIN_CELL_COMPLIANCE, MAX_CELL_COMPLIANCE),
        "within [1e-280, 1e280]: rescale lengths or moduli",
    )
    .map(|_| ())
}

/// Reserves the big buffers' `estimate` (bytes) all at once first, so that
/// a grid too large for this machine is a typed error carrying the
/// estimate instead of an abort.
fn reserve(estimate: usize) -> Result<()> {
    Vec::<u8>::new()
        .try_reserve_exact(estimate)
        .map_err(|_| Error::OutOfMemory {
            bytes: estimate,
            what: "the compliance operator and solver buffers",
        })
}

/// The FFT grid: when isolated, zero padding to at least `2n - 1` cells
/// each way (the offsets `-(n-1) ..= n-1` of a linear convolution), of a
/// fast length ([`fft_fast_even`]: `2n` for a power of two, 384 rather
/// than 378 for `n = 189`); the grid itself when periodic.
fn fft_size(grid: &Grid, boundary: Boundary) -> (usize, usize) {
    match boundary {
        Boundary::Isolated => (
            fft_fast_even((2 * grid.rows()).saturating_sub(1)),
            fft_fast_even((2 * grid.columns()).saturating_sub(1)),
        ),
        Boundary::Periodic => (grid.rows(), grid.columns()),
    }
}

/// The largest isolated grid (cells) whose operator keeps its influence
/// coefficients after building its spectrum (for direct sums of a few
/// loads, [`ComplianceOperator::direct_sum_is_cheaper`]): `2^22`, a 2048 x
/// 2048 grid. Larger grids drop the table, 8 bytes per cell (and so do the
/// coarse levels of their multi-resolution start): on a rough contact at
/// 4096^2 the direct sums' share of the time is within the run-to-run
/// noise (the same iterations; BENCHMARKS.md, "Speed: rough contacts on
/// large grids").
pub const KEEP_INFLUENCE_CELLS: usize = 1 << 22;

/// Loaded cells per binary digit of the padded grid's cell count up to which
/// a direct summation of their displacements beats an FFT convolution
/// (measured on 512 x 512 to 2048 x 2048 grids, one and two threads).
pub const DIRECT_LOADS_PER_LOG2: f64 = 3.0;

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

/// Checks that the top layer is thick enough, relative to the cells, for
/// the influence coefficients to mean something. From half a cell up (`h /
/// Delta >= 0.5`) they are verified for every `nu`. A thinner top layer is
/// in series with its support (a rigid base, an elastic base, or the rest
/// of a stack), whose compliance at the cell's wavelength the kernel
/// resolves, and its own compliance settles by uniaxial strain, `u = p h /
/// M` (`M` the uniaxial-strain modulus). That is right only where the two
/// together are resolvable (at least `1e-4` of the cell's half-space
/// compliance `Delta / E*` of the layer) and where the squeeze-film flow of
/// a nearly incompressible layer, whose compliance is `(h/Delta)^2 M / mu`
/// times the uniaxial one, is negligible against them (below 1 %). So a
/// nearly incompressible layer thinner than half a cell is refused on every
/// support that acts as rigid: a rigid base, an elastic base far stiffer
/// than the layer, or a stiff layer under it in a stack. Its coefficients
/// would be rounding noise, not positive definite. Use a finer grid there.
/// A layer on a rigid base thinner than `1e-3` cells, and a stack on a
/// rigid base thinner than half a cell, are refused whatever they are made
/// of.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `h / Delta` and the range.
pub fn check_film(substrate: &Substrate, grid: &Grid) -> Result<()> {
    let (Some(base), Some(total), Some(top), Some(support)) = (
        substrate.base(),
        substrate.total_thickness(),
        substrate.top_thickness(),
        substrate.support(),
    ) else {
        return Ok(());
    };
    // The limits hold to rounding: h = 1e-7 on Delta = 1e-4 is 1e-3.
    let cells = |thickness: f64| thickness / grid.spacing() * (1.0 + 1e-12);
    if matches!(base, crate::substrate::Base::Rigid) {
        let ratio = cells(total);
        if ratio.is_nan() || ratio < MIN_THICKNESS_OVER_SPACING {
            return Err(Error::InvalidParameter {
                name: "h / Delta (layer thickness over cell size)",
                value: ratio,
                expected: "at least 1e-3 on a rigid base",
            });
        }
        if ratio < VERIFIED_THICKNESS_OVER_SPACING && matches!(substrate, Substrate::Stack(_)) {
            return Err(Error::InvalidParameter {
                name: "h / Delta (stack thickness over cell size)",
                value: ratio,
                expected: "at least 0.5 for a stack on a rigid base (refine the grid)",
            });
        }
    }
    let ratio = cells(top);
    if ratio >= VERIFIED_THICKNESS_OVER_SPACING {
        return Ok(());
    }
    // Compliances relative to the layer's half-space at the cell's
    // wavenumber q = pi / Delta, `u_z q E1* / 2`.
    let layer = substrate.surface_material();
    let q = std::f64::consts::PI / grid.spacing();
    let beneath = support.map_or(0.0, |body| {
        FourierCompliance::new(&body).eval(q) * layer.contact_modulus() * q / 2.0
    });
    let film = ratio * layer.contact_modulus() / layer.uniaxial_strain_modulus();
    // (h/Delta)^2 M / mu times the uniaxial compliance, finite at nu = 0.5.
    let squeeze = ratio * ratio * ratio * layer.contact_modulus() / layer.shear_modulus();
    let resolved = film + beneath;
    if !(resolved >= MIN_FILM_COMPLIANCE && squeeze <= MAX_SQUEEZE_SHARE * resolved) {
        return Err(Error::InvalidParameter {
            name: "h / Delta (top layer thickness over cell size)",
            value: ratio,
            expected: "at least 0.5 for this layer on a support that acts as rigid, or thin \
                       enough to compress by uniaxial strain alone (its squeeze-film \
                       compliance, (h/Delta)^2 M/mu times the uniaxial one, below 1 % of the \
                       film's and the support's: on a rigid base below 0.053 cells at nu = \
                       0.3, never for a nearly incompressible layer); refine the grid",
        });
    }
    Ok(())
}

/// Refuses influence coefficients whose remainder is not resolved out to
/// the grid's reach (a coating much stiffer than its base on a grid that
/// spans thousands of its thicknesses), see
/// [`InfluenceCoefficients::tail_error_estimate`].
fn check_tail(influence: &InfluenceCoefficients, substrate: &Substrate) -> Result<()> {
    let tail = influence.tail_error_estimate();
    if tail <= super::influence::MAX_TAIL_ERROR {
        return Ok(());
    }
    let grid = influence.grid();
    let thinnest = substrate
        .terms()
        .iter()
        .map(|term| term.length)
        .fold(f64::INFINITY, f64::min);
    let reach = (grid.rows() as f64 + 0.5).hypot(grid.columns() as f64 + 0.5) * grid.spacing();
    Err(Error::InvalidParameter {
        name: "grid diagonal over coating thickness (isolated grid)",
        value: reach / thinnest,
        expected: "at most 8192 for a coating this much stiffer than its base: its Green's \
                   function is not yet asymptotic further out, and the influence \
                   coefficients would be wrong by orders of magnitude; use fewer or smaller \
                   cells, a thicker coating, or a periodic grid",
    })
}

impl ComplianceOperator {
    /// The operator of `substrate` on `grid` with `boundary`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a top layer thinner than the grid can
    /// resolve on its support (see [`check_film`]), for isolated coefficients
    /// whose tail error estimate exceeds `1e-6` (a coating much stiffer than
    /// its base on a grid whose diagonal spans more than 8192 of its
    /// thicknesses, see
    /// [`InfluenceCoefficients::tail_error_estimate`]), or a cell whose compliance
    /// `Delta / E*` is not a normal `f64` number (cell size and modulus out of
    /// range together).
    pub fn new(substrate: &Substrate, grid: &Grid, boundary: Boundary) -> Result<Self> {
        Self::build(substrate, grid, boundary, None)
    }

    /// The operator split across the ranks of `slab`: it applies to this
    /// rank's rows of pressures and displacements, and keeps its share of
    /// the kernel's spectrum (every rank builds the whole spectrum once and
    /// keeps its columns). No influence coefficients are kept.
    pub(crate) fn distributed(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        slab: &Slab,
    ) -> Result<Self> {
        let operator = Self::build(substrate, grid, boundary, Some(slab));
        slab.agree(operator)
    }

    fn build(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        slab: Option<&Slab>,
    ) -> Result<Self> {
        check_film(substrate, grid)?;
        check_cell_compliance(grid, substrate.surface_material().contact_modulus())?;
        let size = fft_size(grid, boundary);
        reserve(match slab {
            None => memory_estimate(grid, boundary),
            Some(slab) => distributed_memory_estimate(grid, boundary, slab.exchange.ranks()),
        })?;
        let convolution = match slab {
            None => Convolution::new(grid.rows(), grid.columns(), size)?,
            Some(slab) => {
                Convolution::distributed(grid.rows(), grid.columns(), size, slab, slab.counts())?
            }
        };
        let mut operator = ComplianceOperator {
            grid: *grid,
            boundary,
            influence: None,
            layered: substrate.base().is_some(),
            rigid_base: matches!(substrate.base(), Some(crate::substrate::Base::Rigid)),
            spectrum: Vec::new(),
            inverse_spectrum: Vec::new(),
            surface_modulus: substrate.surface_material().contact_modulus(),
            convolution,
            single: None,
            single_scale: 1.0,
            slab: slab.cloned(),
        };
        operator.spectrum = match boundary {
            Boundary::Isolated => {
                let influence = InfluenceCoefficients::isolated(substrate, grid);
                check_tail(&influence, substrate)?;
                let mut spectrum = operator.isolated_spectrum(&influence)?;
                match slab {
                    None if grid.len() <= KEEP_INFLUENCE_CELLS => {
                        operator.influence = Some(influence)
                    }
                    None => {}
                    // Keep this rank's spectrum columns.
                    Some(_) => {
                        let distinct = size.0 / 2 + 1;
                        let columns = operator.convolution.own_columns();
                        spectrum.truncate(columns.end * distinct);
                        spectrum.drain(..columns.start * distinct);
                        spectrum.shrink_to_fit();
                    }
                }
                spectrum
            }
            Boundary::Periodic => operator.periodic_spectrum(&FourierCompliance::new(substrate))?,
        };
        Ok(operator)
    }

    /// This rank's rows of the grid (all of them when serial).
    pub(crate) fn local_rows(&self) -> std::ops::Range<usize> {
        self.slab.as_ref().map_or(0..self.grid.rows(), Slab::rows)
    }

    /// The number of cells in this rank's rows (the grid's when serial).
    pub(crate) fn local_cells(&self) -> usize {
        self.local_rows().len() * self.grid.columns()
    }

    /// The split across ranks, if distributed.
    pub(crate) fn slab(&self) -> Option<&Slab> {
        self.slab.as_ref()
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

    /// The influence coefficients: on isolated operators of at most
    /// [`KEEP_INFLUENCE_CELLS`] cells, not split across ranks (`None`
    /// otherwise).
    pub fn influence(&self) -> Option<&InfluenceCoefficients> {
        self.influence.as_ref()
    }

    /// Drops the influence coefficients (a coarse level of a
    /// multi-resolution start under a fine grid that keeps none): the
    /// operator then corrects by convolution only.
    pub(crate) fn drop_influence(&mut self) {
        self.influence = None;
    }

    /// The spectrum of the coefficients placed on the padded grid in
    /// wrap-around order (offset `-d` at index `n - d`; zero between the
    /// largest offsets of either sign).
    fn isolated_spectrum(&mut self, influence: &InfluenceCoefficients) -> Result<Vec<f64>> {
        let (n0, n1) = self.convolution.size();
        let (rows, columns) = (self.grid.rows(), self.grid.columns());
        let offset = |index: usize, n: usize, cells: usize| -> Option<isize> {
            match index {
                i if i < cells => Some(i as isize),
                i if i + cells > n => Some(i as isize - n as isize),
                _ => None,
            }
        };
        self.convolution.even_kernel_spectrum(|i, values| {
            for (j, value) in values.iter_mut().enumerate() {
                *value = match (offset(i, n0, rows), offset(j, n1, columns)) {
                    (Some(di), Some(dj)) => influence.get(di, dj),
                    _ => 0.0,
                };
            }
        })
    }

    /// `u_z(|q|) sinc(q_x Delta/2) sinc(q_y Delta/2)` at the periodic
    /// wavevectors (the mean mode: `u_z(0)` where finite, else 0).
    fn periodic_spectrum(&self, compliance: &FourierCompliance) -> Result<Vec<f64>> {
        let zero_mode = compliance.at_zero();
        let zero_mode = if zero_mode.is_finite() {
            zero_mode
        } else {
            0.0
        };
        let delta = self.grid.spacing();
        let columns = self.convolution.own_columns();
        multiplier(self.convolution.size(), delta, columns, |qx, qy| {
            if qx == 0.0 && qy == 0.0 {
                zero_mode
            } else {
                compliance.eval(qx.hypot(qy)) * cell_filter(qx, qy, delta)
            }
        })
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

    /// Frees the largest buffer (the half-spectra of the FFT) until the
    /// next application, which allocates it again: for a solver kept idle,
    /// such as the coarse levels of a multi-resolution start while the
    /// finer solve runs.
    pub(crate) fn release_buffer(&mut self) {
        drop(self.convolution.take_tiles());
    }

    /// Lends the largest buffer to `f` (the preconditioner's FFT, which
    /// is never applied at the same time), and takes it back.
    pub(crate) fn lend_buffer<T>(&mut self, f: impl FnOnce(&mut ShareBuffer) -> T) -> T {
        let mut shared = ShareBuffer(self.convolution.take_tiles());
        let result = f(&mut shared);
        self.convolution.give_tiles(shared.0);
        result
    }

    /// Whether adding the displacements of `loads` loaded cells by direct
    /// summation ([`InfluenceCoefficients::add_loads`]) costs less than one
    /// [`apply`](Self::apply): on an isolated grid (which keeps the
    /// influence coefficients), for at most [`DIRECT_LOADS_PER_LOG2`] loads
    /// per binary digit of the padded grid's cell count.
    pub fn direct_sum_is_cheaper(&self, loads: usize) -> bool {
        let (n0, n1) = self.convolution.size();
        self.influence.is_some()
            && (loads as f64) <= DIRECT_LOADS_PER_LOG2 * ((n0 * n1) as f64).log2()
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
            self.inverse_spectrum = self.stiffness_spectrum()?;
        }
        let spectrum = std::mem::take(&mut self.inverse_spectrum);
        let outcome = self.convolve(residual, result, &spectrum);
        self.inverse_spectrum = spectrum;
        outcome
    }

    /// `E* |q| / 2` at the wavevectors of the (padded) grid, with the `q = 0`
    /// mode given the value of the smallest nonzero `|q|`.
    fn stiffness_spectrum(&self) -> Result<Vec<f64>> {
        let (n0, n1) = self.convolution.size();
        let delta = self.grid.spacing();
        let smallest = wavenumber(1, n0.max(n1).max(2), delta).abs();
        let modulus = self.surface_modulus;
        multiplier((n0, n1), delta, self.convolution.own_columns(), |qx, qy| {
            0.5 * modulus * qx.hypot(qy).max(smallest)
        })
    }

    /// `output = IFFT(spectrum * FFT(input))` on the (padded) grid.
    fn convolve(
        &mut self,
        pressure: &[f64],
        displacement: &mut [f64],
        spectrum: &[f64],
    ) -> Result<()> {
        self.check_lengths(&[
            ("pressure", pressure.len()),
            ("displacement", displacement.len()),
        ])?;
        self.convolution.apply(pressure, displacement, spectrum)
    }

    /// [`Error::ShapeMismatch`] for the first `(field, length)` that is not
    /// this rank's cell count.
    fn check_lengths(&self, fields: &[(&'static str, usize)]) -> Result<()> {
        let cells = self.local_cells();
        match fields.iter().find(|(_, found)| *found != cells) {
            Some(&(field, found)) => Err(Error::ShapeMismatch {
                field,
                expected: cells,
                found,
            }),
            None => Ok(()),
        }
    }
}

/// The cell's shape factor `sinc(q_x Delta / 2) sinc(q_y Delta / 2)`: the
/// Fourier transform of uniform pressure on one cell, over its area.
pub(super) fn cell_filter(qx: f64, qy: f64, delta: f64) -> f64 {
    let sinc = |x: f64| if x == 0.0 { 1.0 } else { x.sin() / x };
    sinc(0.5 * qx * delta) * sinc(0.5 * qy * delta)
}
