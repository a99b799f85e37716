//! [`SubsurfaceStress`]: the modes of a body solved once per grid, then
//! depth planes of any pressure by inverse FFTs.

use std::collections::HashMap;

use num_complex::Complex;

use crate::error::{Error, Result};
use crate::grid::{Boundary, Grid};
use crate::substrate::{Base, Substrate};

use super::fft::Fft2;
use super::images::{padded_size, Images};
use super::mode::{Column, Ply};
use super::{
    check_depth, default_padding, rigid_floor, InterfaceTractions, Side, StressPlane,
    MAX_PADDED_CELLS,
};

/// Plans the stresses below a grid on one body: the exact solution of
/// every distinct wavenumber once, then any number of planes for any
/// pressure.
pub struct SubsurfaceStress {
    column: Column,
    grid: Grid,
    boundary: Boundary,
    /// The depth of a rigid base's face, m (`None` on an elastic base).
    floor: Option<f64>,
    fft: Fft2,
    /// Per spectrum bin (column by column, `half x rows`), the index of its
    /// wavenumber in `wavenumbers` (`u32::MAX` for the mean).
    bins: Vec<u32>,
    /// Per distinct wavenumber: `q` and the basis coefficients.
    wavenumbers: Vec<f64>,
    coefficients: Vec<f64>,
    /// Direction cosines of each bin's wavevector.
    cosines: Vec<(f64, f64)>,
    /// On an isolated grid, the periodic images' field to take out.
    images: Option<Box<Images>>,
    /// Wavenumber (rad/m) of a low-pass filter `exp(-(q/cutoff)^4)` on
    /// every mode (infinite: none); see [`SubsurfaceStress::filtered`].
    cutoff: f64,
}

/// Which of `xx, yy, zz, xy, xz, yz` have imaginary multipliers (the
/// shears across the plane, odd in the wavevector).
const IMAGINARY: [bool; 6] = [false, false, false, false, true, true];

/// Distinct wavenumbers solved per parallel task while planning.
const SOLVES_PER_TASK: usize = 256;

impl SubsurfaceStress {
    /// Plans the stresses in `substrate` under `grid`; an isolated grid is
    /// padded [`DEFAULT_PADDING`](super::DEFAULT_PADDING) times.
    ///
    /// # Errors
    /// As [`SubsurfaceStress::with_padding`].
    pub fn new(substrate: &Substrate, grid: &Grid, boundary: Boundary) -> Result<Self> {
        Self::with_padding(substrate, grid, boundary, default_padding(boundary))
    }

    /// Plans the stresses with an isolated grid zero-padded `padding` times
    /// along each axis (rounded up to a length whose FFT is fast and that
    /// the images' coarse grid divides); the images' field is taken out
    /// (see the [module docs](super)), so more padding is rarely needed.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a padding below 2 on an isolated
    /// grid, other than 1 on a periodic one, or a padded grid beyond
    /// [`MAX_PADDED_CELLS`]; [`Error::Internal`] if a wavenumber's system
    /// is singular (not seen on any body the constructors accept).
    pub fn with_padding(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        padding: usize,
    ) -> Result<Self> {
        let valid = match boundary {
            Boundary::Isolated => padding >= 2,
            Boundary::Periodic => padding == 1,
        };
        let factor = Images::factor(grid);
        let padded = match boundary {
            Boundary::Isolated => (
                padded_size(grid.rows(), padding, factor),
                padded_size(grid.columns(), padding, factor),
            ),
            Boundary::Periodic => (grid.rows(), grid.columns()),
        };
        if !valid || padded.0.saturating_mul(padded.1) > MAX_PADDED_CELLS {
            return Err(Error::InvalidParameter {
                name: "padding of the subsurface stress grid",
                value: padding as f64,
                expected: "1 on a periodic grid; at least 2 on an isolated one, with at most \
                           2^28 padded cells",
            });
        }
        let mut plan = Self::planned(substrate, grid, boundary, padded)?;
        if boundary == Boundary::Isolated {
            plan.images = Some(Box::new(Images::new(substrate, grid, padded, factor)?));
        }
        Ok(plan)
    }

    /// The plan on an FFT grid of `(rows, columns)` (the grid's own on a
    /// periodic grid), without the images' correction.
    pub(super) fn planned(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        (rows, columns): (usize, usize),
    ) -> Result<Self> {
        if let Substrate::Stack(stack) = substrate {
            if stack.top_rests() {
                return Err(Error::Unsupported {
                    feature: "stresses below a layer resting on layers without friction",
                    reason: "the stress modes carry a frictionless interface only at the base; \
                             the sliding interface under a stack's top layer is not propagated",
                });
            }
        }
        let column = column_of(substrate);
        let half = columns / 2 + 1;
        let dx = grid.spacing();
        let mut bins = vec![u32::MAX; rows * half];
        let mut cosines = vec![(0.0, 0.0); rows * half];
        let mut index: HashMap<u64, u32> = HashMap::new();
        let mut wavenumbers = Vec::new();
        // Column by column, as the spectrum is stored: a wavenumber's first
        // bin comes in storage order, and the modes are read nearly in turn.
        for j in 0..half {
            let ky = 2.0 * std::f64::consts::PI * j as f64 / (columns as f64 * dx);
            for i in 0..rows {
                let ki = if 2 * i <= rows {
                    i as f64
                } else {
                    i as f64 - rows as f64
                };
                // x along the rows' index, y along the columns' (as Grid::cell_centre).
                let kx = 2.0 * std::f64::consts::PI * ki / (rows as f64 * dx);
                let q = kx.hypot(ky);
                if q == 0.0 {
                    continue;
                }
                let next = wavenumbers.len() as u32;
                let id = *index.entry(q.to_bits()).or_insert_with(|| {
                    wavenumbers.push(q);
                    next
                });
                bins[j * rows + i] = id;
                cosines[j * rows + i] = (kx / q, ky / q);
            }
        }
        let n = column.unknowns();
        let mut coefficients = vec![0.0; n * wavenumbers.len()];
        let failures =
            crate::parallel::map_rows(&mut coefficients, n * SOLVES_PER_TASK, |t, chunk| {
                let mut matrix = Vec::new();
                for (k, out) in chunk.chunks_mut(n).enumerate() {
                    column.solve(wavenumbers[t * SOLVES_PER_TASK + k], &mut matrix, out)?;
                }
                Ok(())
            });
        failures.into_iter().collect::<Result<Vec<()>>>()?;
        Ok(SubsurfaceStress {
            column,
            grid: *grid,
            boundary,
            floor: rigid_floor(substrate),
            fft: Fft2::new(rows, columns, grid.rows(), grid.columns()),
            bins,
            wavenumbers,
            coefficients,
            cosines,
            images: None,
            cutoff: f64::INFINITY,
        })
    }

    /// This plan with every mode multiplied by `exp(-(q/cutoff)^4)`: one
    /// to third order at long waves, so the field far from a load keeps
    /// its leading multipoles (it changes by about `(cutoff R)^-4` at a
    /// distance `R`), negligible at the grid's Nyquist wavenumber, so the
    /// field is smooth between cells, and a kernel that decays fast, so a
    /// local field stays local.
    pub(super) fn filtered(mut self, cutoff: f64) -> Self {
        self.cutoff = cutoff;
        self
    }

    /// The grid the stresses are computed on.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The depths of the interfaces (m), top down, and of the base's top
    /// (the last entry; for a layer on a rigid base, the base).
    pub fn interface_depths(&self) -> Vec<f64> {
        let mut depth = 0.0;
        self.column
            .plies
            .iter()
            .map(|ply| {
                depth += ply.thickness;
                depth
            })
            .collect()
    }

    /// The six components on the plane `z = depth` (m) under `pressure`
    /// (Pa, one value per cell, compressive positive), in the layer on the
    /// given `side` of an interface at that depth.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] if `pressure` does not fit the grid;
    /// [`Error::InvalidParameter`] for a negative or non-finite depth, or
    /// a depth in or below a rigid base; [`Error::NonFinite`] for a
    /// non-finite pressure.
    pub fn plane(&mut self, pressure: &[f64], depth: f64, side: Side) -> Result<StressPlane> {
        let mut planes = self.planes(pressure, &[depth], side)?;
        planes.pop().ok_or(Error::Internal {
            what: "subsurface stress",
            detail: "no plane for one depth".into(),
        })
    }

    /// The planes at `depths` (m) under one `pressure`, transformed once:
    /// each plane then costs six inverse FFTs.
    ///
    /// # Errors
    /// As [`SubsurfaceStress::plane`].
    pub fn planes(
        &mut self,
        pressure: &[f64],
        depths: &[f64],
        side: Side,
    ) -> Result<Vec<StressPlane>> {
        let mut planes = Vec::new();
        self.planes_into(pressure, depths, side, &mut planes)?;
        Ok(planes)
    }

    /// As [`SubsurfaceStress::planes`], into `planes`, whose fields are
    /// reused (resized to the depths and the grid): writing six fresh
    /// fields is a good part of a plane's cost (see `BENCHMARKS.md`).
    ///
    /// # Errors
    /// As [`SubsurfaceStress::plane`]; `planes` is then left partly
    /// written.
    pub fn planes_into(
        &mut self,
        pressure: &[f64],
        depths: &[f64],
        side: Side,
        planes: &mut Vec<StressPlane>,
    ) -> Result<()> {
        self.check(pressure)?;
        for &depth in depths {
            check_depth(depth, side, self.floor)?;
        }
        let bins = self.fft.rows() * self.fft.half();
        let mut spectrum = vec![Complex::default(); bins];
        self.fft.forward(pressure, &mut spectrum);
        let cells = self.grid.len();
        planes.truncate(depths.len());
        planes.resize_with(depths.len(), StressPlane::default);
        for (plane, &depth) in planes.iter_mut().zip(depths) {
            plane.depth = depth;
            let StressPlane {
                xx,
                yy,
                zz,
                xy,
                xz,
                yz,
                ..
            } = plane;
            for field in [xx, yy, zz, xy, xz, yz] {
                field.resize(cells, 0.0);
            }
            self.one_plane(&spectrum, side, plane)?;
        }
        if let Some(images) = &mut self.images {
            images.remove(pressure, depths, side, planes)?;
        }
        Ok(())
    }

    /// Fills `out` (at its depth, its fields of the grid's size) from the
    /// pressure's `spectrum`.
    fn one_plane(
        &mut self,
        spectrum: &[Complex<f64>],
        side: Side,
        out: &mut StressPlane,
    ) -> Result<()> {
        let depth = out.depth;
        let (layer, top) = self.column.locate(depth, side == Side::Above);
        let n = self.column.unknowns();
        // Per distinct wavenumber, the mode's stresses (zz, xi xi, eta eta,
        // xi z) per unit pressure.
        let mut modes = vec![[0.0; 4]; self.wavenumbers.len()];
        let (column, wavenumbers, coefficients, cutoff) = (
            &self.column,
            &self.wavenumbers,
            &self.coefficients,
            self.cutoff,
        );
        crate::parallel::for_each_row(&mut modes, SOLVES_PER_TASK, |t, chunk| {
            for (k, mode) in chunk.iter_mut().enumerate() {
                let id = t * SOLVES_PER_TASK + k;
                let q = wavenumbers[id];
                *mode = column.stress_at(
                    layer,
                    q * (depth - top),
                    q,
                    &coefficients[id * n..(id + 1) * n],
                );
                if cutoff.is_finite() {
                    let filter = (-(q / cutoff).powi(4)).exp();
                    mode.iter_mut().for_each(|m| *m *= filter);
                }
            }
        });
        // The mean mode's in-plane stress per unit pressure: uniaxial strain
        // on a periodic grid (no mean strain in the plane), the direction
        // average of the long-wave limit for an isolated contact.
        let lateral = match self.boundary {
            Boundary::Periodic => {
                let nu = self.column.ply(layer).map_or(0.0, |p| p.nu);
                -nu / (1.0 - nu)
            }
            Boundary::Isolated => {
                let [_, xi, eta] = self.column.long_wave(layer);
                0.5 * (xi + eta)
            }
        };
        let (bins, cosines) = (&self.bins, &self.cosines);
        let rows = self.fft.rows();
        let columns = self.fft.columns();
        let nyquist_row = if rows.is_multiple_of(2) {
            rows / 2
        } else {
            usize::MAX
        };
        let nyquist_column = if columns.is_multiple_of(2) {
            self.fft.half() - 1
        } else {
            usize::MAX
        };
        // xx, yy, zz, xy, xz, yz per unit pressure, in column j and row i;
        // the shears' multipliers are imaginary.
        let multipliers = |j: usize, i: usize| match bins[j * rows + i] {
            u32::MAX => [lateral, lateral, -1.0, 0.0, 0.0, 0.0],
            id => {
                let m = &modes[id as usize];
                let (c, s) = cosines[j * rows + i];
                // A Nyquist row (column) stands for both signs of its
                // wavenumber: what is odd in it averages to zero there (the
                // trapezoidal rule at the band's edge), what is even stays.
                let odd_x = if i == nyquist_row { 0.0 } else { c };
                let odd_y = if j == nyquist_column { 0.0 } else { s };
                [
                    c * c * m[1] + s * s * m[2],
                    s * s * m[1] + c * c * m[2],
                    m[0],
                    odd_x * odd_y * (m[1] - m[2]),
                    -odd_x * m[3],
                    -odd_y * m[3],
                ]
            }
        };
        self.fft
            .inverse_filtered(spectrum, multipliers, IMAGINARY, out.components_mut());
        for field in out.components() {
            if let Some(v) = field.iter().find(|v| !v.is_finite()) {
                return Err(Error::NonFinite {
                    what: "a subsurface stress",
                    value: *v,
                });
            }
        }
        Ok(())
    }

    /// The tractions on every interface (the planes at the layers'
    /// bottoms; the last is the base's top).
    ///
    /// # Errors
    /// As [`SubsurfaceStress::plane`].
    pub fn interfaces(&mut self, pressure: &[f64]) -> Result<Vec<InterfaceTractions>> {
        let depths = self.interface_depths();
        Ok(self
            .planes(pressure, &depths, Side::Above)?
            .into_iter()
            .map(|plane| InterfaceTractions {
                depth: plane.depth,
                normal: plane.zz,
                shear_x: plane.xz,
                shear_y: plane.yz,
            })
            .collect())
    }

    fn check(&self, pressure: &[f64]) -> Result<()> {
        if pressure.len() != self.grid.len() {
            return Err(Error::ShapeMismatch {
                field: "pressure",
                found: pressure.len(),
                expected: self.grid.len(),
            });
        }
        if let Some(v) = pressure.iter().find(|v| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: "the pressure given for the subsurface stresses",
                value: *v,
            });
        }
        Ok(())
    }
}

/// The body as the mode solution sees it, in units of the top layer's
/// shear modulus.
fn column_of(substrate: &Substrate) -> Column {
    let top = substrate.surface_material().shear_modulus();
    let ply = |m: &crate::Material, thickness: f64| Ply {
        mu: m.shear_modulus() / top,
        nu: m.poisson_ratio(),
        thickness,
    };
    let base = |b: &Base| match b {
        Base::Rigid => None,
        Base::Elastic(m) => Some(ply(m, 0.0)),
    };
    match substrate {
        Substrate::HalfSpace(m) => Column {
            plies: vec![],
            base: Some(ply(m, 0.0)),
            frictionless: false,
        },
        Substrate::Coated(c) => Column {
            plies: vec![ply(c.layer(), c.thickness())],
            base: base(c.base()),
            frictionless: c.is_frictionless(),
        },
        Substrate::Stack(s) => Column {
            plies: s
                .layers()
                .iter()
                .map(|l| ply(l.material(), l.thickness()))
                .collect(),
            base: base(s.base()),
            frictionless: false,
        },
    }
}
