//! Stresses below the surface: the full tensor at any depth inside a
//! half-space, a layer or a stack, from a surface pressure on the grid of
//! a solve (periodic or isolated).
//!
//! Each Fourier mode of the pressure is carried through the layers exactly
//! (an Airy stress function per layer written in functions that decay
//! away from one of its faces, so no exponential grows; see
//! [`doc::subsurface`](crate::doc::subsurface)), and a depth plane is six
//! inverse FFTs of the modes' stresses.
//! The pressure is taken as the trigonometric interpolant of the cell
//! values (the band-limited field the grid represents, as in tamaas'
//! volume operators); on planes shallower than a few cells its difference
//! from a pressure uniform in each cell is visible (it decays like
//! `e^(-pi z / Delta)`).
//!
//! On a periodic grid the result is exact for the interpolated pressure
//! (the mean pressure puts every layer in uniaxial strain: a periodic body
//! cannot strain on average in its plane). An isolated contact is computed
//! on a grid zero-padded [`DEFAULT_PADDING`] times along each axis, with
//! the mean mode set to the limit of long waves, whose direction average
//! is the integral of the stress of an unbounded body over a plane. The
//! field the padding leaves, that of the periodic images, is computed on a
//! coarse grid and taken out (a particle-mesh correction, see
//! [`doc::subsurface`](crate::doc::subsurface)): on the axis of a Hertz
//! contact 16 cells in radius on a grid 4 radii wide, padded twice, the
//! images' 1.4e-2 `p0` fall to 2e-5, below the cell size's 2.5e-4. Choose
//! the padding with [`SubsurfaceStress::with_padding`] (or a scene's
//! `outputs.stresses.padding`), and check a result by doubling it.
//!
//! ```
//! use layered_contact::stress::{Side, SubsurfaceStress};
//! use layered_contact::{Boundary, Grid, Material, Substrate};
//!
//! // A cosine pressure p0 cos(q x) on a periodic half-space: at depth z,
//! // sigma_zz = -p0 (1 + q z) e^(-q z) cos(q x) (Johnson 1985, sec. 2.6).
//! let body = Substrate::half_space(Material::new(1e9, 0.3)?);
//! let grid = Grid::new(64, 8, 1e-6)?; // x along the 64 rows
//! let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic)?;
//! let q = 2.0 * std::f64::consts::PI / 64e-6;
//! let x = |i: usize| (i as f64 + 0.5) * 1e-6;
//! let pressure: Vec<f64> = (0..grid.len()).map(|k| 1e6 * (q * x(k / 8)).cos()).collect();
//! let z = 5e-6;
//! let plane = stress.plane(&pressure, z, Side::Below)?;
//! let expected = -1e6 * (1.0 + q * z) * (-q * z).exp() * (q * x(3)).cos();
//! assert!((plane.zz[3 * 8] - expected).abs() < 1e-6);
//! # Ok::<(), layered_contact::Error>(())
//! ```

mod fft;
mod field;
mod images;
mod mode;
mod tensor;

pub use field::SubsurfaceStress;
pub use tensor::Stress;

use crate::error::{Error, Result};
use crate::grid::Boundary;
use crate::substrate::{Base, Substrate};

/// How many times an isolated grid is padded along each axis by
/// [`SubsurfaceStress::new`].
pub const DEFAULT_PADDING: usize = 2;

/// The padding [`SubsurfaceStress::new`] uses: [`DEFAULT_PADDING`] on an
/// isolated grid, none (1) on a periodic one.
pub fn default_padding(boundary: Boundary) -> usize {
    match boundary {
        Boundary::Isolated => DEFAULT_PADDING,
        Boundary::Periodic => 1,
    }
}

/// Whether a plane at `depth` (m) on `side` of an interface lies in the
/// body: finite, at least 0, and not in or below a rigid base whose face is
/// at `rigid_floor` (m; that face belongs to the layer above).
///
/// # Errors
/// [`Error::InvalidParameter`] naming the depth and the range.
pub(crate) fn check_depth(depth: f64, side: Side, rigid_floor: Option<f64>) -> Result<()> {
    let below_floor =
        rigid_floor.is_some_and(|floor| depth > floor || (depth == floor && side == Side::Below));
    if depth >= 0.0 && depth.is_finite() && !below_floor {
        return Ok(());
    }
    Err(Error::InvalidParameter {
        name: "depth of a stress plane (m)",
        value: depth,
        expected: "finite, at least 0, and above a rigid base",
    })
}

/// The depth (m) of a rigid base's face under `substrate`; `None` on an
/// elastic base or a half-space.
pub(crate) fn rigid_floor(substrate: &Substrate) -> Option<f64> {
    match substrate.base() {
        Some(Base::Rigid) => substrate.total_thickness(),
        _ => None,
    }
}

/// The most cells a padded stress grid may have (2^28: 4 GiB per complex
/// spectrum).
pub const MAX_PADDED_CELLS: usize = 1 << 28;

/// Which side of an interface a plane at exactly its depth lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Side {
    /// In the layer above (or the top layer at `z = 0`).
    Above,
    /// In the layer (or base) below; inside a layer both are the same.
    #[default]
    Below,
}

/// The six stress components on one plane `z = depth`, Pa, each a
/// row-major field of the grid's cells (the cell centres).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StressPlane {
    /// Depth below the surface, m.
    pub depth: f64,
    /// `sigma_xx` (`x` along the row index `i`, `y` along the column
    /// index `j`, as [`Grid::cell_centre`](crate::Grid::cell_centre)).
    pub xx: Vec<f64>,
    /// `sigma_yy`.
    pub yy: Vec<f64>,
    /// `sigma_zz`.
    pub zz: Vec<f64>,
    /// `sigma_xy`.
    pub xy: Vec<f64>,
    /// `sigma_xz`.
    pub xz: Vec<f64>,
    /// `sigma_yz`.
    pub yz: Vec<f64>,
}

impl StressPlane {
    /// The six fields in the order `xx, yy, zz, xy, xz, yz`.
    pub fn components(&self) -> [&[f64]; 6] {
        [&self.xx, &self.yy, &self.zz, &self.xy, &self.xz, &self.yz]
    }

    /// The six fields, mutable, in the order of
    /// [`StressPlane::components`].
    pub fn components_mut(&mut self) -> [&mut [f64]; 6] {
        [
            &mut self.xx,
            &mut self.yy,
            &mut self.zz,
            &mut self.xy,
            &mut self.xz,
            &mut self.yz,
        ]
    }

    /// The tensor at cell `k`.
    pub fn at(&self, k: usize) -> Stress {
        Stress {
            xx: self.xx[k],
            yy: self.yy[k],
            zz: self.zz[k],
            xy: self.xy[k],
            xz: self.xz[k],
            yz: self.yz[k],
        }
    }

    /// A derived field, `measure` applied at every cell (for example
    /// `Stress::von_mises`).
    pub fn map(&self, measure: impl Fn(&Stress) -> f64) -> Vec<f64> {
        (0..self.zz.len()).map(|k| measure(&self.at(k))).collect()
    }

    /// The largest value of `measure` on the plane and the cell holding it.
    pub fn max_of(&self, measure: impl Fn(&Stress) -> f64) -> (f64, usize) {
        (0..self.zz.len()).map(|k| (measure(&self.at(k)), k)).fold(
            (f64::NEG_INFINITY, 0),
            |best, v| if v.0 > best.0 { v } else { best },
        )
    }
}

/// The largest value of a measure over a set of planes and where it lies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VolumeMaximum {
    /// The value, Pa.
    pub value: f64,
    /// Depth of its plane, m.
    pub depth: f64,
    /// The cell holding it (row-major index on the grid).
    pub cell: usize,
}

impl VolumeMaximum {
    /// The largest value of `measure` over `planes` (`None` for no planes).
    pub fn over(planes: &[StressPlane], measure: impl Fn(&Stress) -> f64) -> Option<Self> {
        planes
            .iter()
            .map(|plane| {
                let (value, cell) = plane.max_of(&measure);
                VolumeMaximum {
                    value,
                    depth: plane.depth,
                    cell,
                }
            })
            .reduce(|best, next| if next.value > best.value { next } else { best })
    }
}

/// The tractions an interface carries, Pa, on the grid's cells: the
/// normal `sigma_zz` and the shears `sigma_xz`, `sigma_yz`, continuous
/// across it.
#[derive(Debug, Clone, PartialEq)]
pub struct InterfaceTractions {
    /// Depth of the interface, m.
    pub depth: f64,
    /// `sigma_zz` (negative in compression).
    pub normal: Vec<f64>,
    /// `sigma_xz`.
    pub shear_x: Vec<f64>,
    /// `sigma_yz`.
    pub shear_y: Vec<f64>,
}

impl InterfaceTractions {
    /// The largest resultant shear traction `sqrt(sigma_xz^2 + sigma_yz^2)`
    /// (Pa) on the interface and the cell holding it.
    pub fn largest_shear(&self) -> (f64, usize) {
        self.shear_x
            .iter()
            .zip(&self.shear_y)
            .map(|(a, b)| a.hypot(*b))
            .enumerate()
            .fold(
                (0.0, 0),
                |best, (k, v)| if v > best.0 { (v, k) } else { best },
            )
    }
}
