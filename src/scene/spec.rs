//! Plain-number descriptions of bodies, indenters and effects: what a scene
//! file holds. Each is validated when built into the library's types.

use std::path::PathBuf;
use std::sync::Arc;

use crate::error::{Error, Result};
use crate::grid::Grid;
use crate::indenter::{Cone, FlatPunch, HeightMap, Indenter, Paraboloid, Sphere, Tilted};
use crate::material::Material;
use crate::substrate::Substrate;
use crate::topography::{Amplitude, SelfAffine};

/// The body, by its material constants (SI units).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum SubstrateSpec {
    /// A homogeneous half-space.
    HalfSpace {
        /// `E`, Pa.
        youngs_modulus: f64,
        /// `nu`.
        poisson_ratio: f64,
    },
    /// A layer on a rigid base.
    LayerOnRigidBase {
        /// `E1`, Pa.
        youngs_modulus: f64,
        /// `nu1`.
        poisson_ratio: f64,
        /// `h`, m.
        thickness: f64,
    },
    /// A layer resting on a rigid base without friction (see
    /// [`Substrate::layer_resting_on_rigid_base`]).
    LayerRestingOnRigidBase {
        /// `E1`, Pa.
        youngs_modulus: f64,
        /// `nu1`.
        poisson_ratio: f64,
        /// `h`, m.
        thickness: f64,
    },
    /// A layer resting on an elastic half-space without friction (see
    /// [`Substrate::layer_resting_on_elastic_base`]).
    LayerRestingOnElasticBase {
        /// `E1`, Pa.
        youngs_modulus: f64,
        /// `nu1`.
        poisson_ratio: f64,
        /// `h`, m.
        thickness: f64,
        /// `E2`, Pa.
        base_youngs_modulus: f64,
        /// `nu2`.
        base_poisson_ratio: f64,
    },
    /// A layer on an elastic half-space.
    LayerOnElasticBase {
        /// `E1`, Pa.
        youngs_modulus: f64,
        /// `nu1`.
        poisson_ratio: f64,
        /// `h`, m.
        thickness: f64,
        /// `E2`, Pa.
        base_youngs_modulus: f64,
        /// `nu2`.
        base_poisson_ratio: f64,
    },
    /// Bonded layers, top first, on a rigid base (`base` omitted) or an
    /// elastic half-space; see [`Substrate::stack`].
    ///
    /// ```toml
    /// [substrate]
    /// kind = "stack"
    /// layers = [
    ///     { youngs_modulus = 300e9, poisson_ratio = 0.2, thickness = 2e-6 },
    ///     { youngs_modulus = 140e9, poisson_ratio = 0.21, thickness = 0.3e-6 },
    /// ]
    /// base = { youngs_modulus = 210e9, poisson_ratio = 0.3 }
    /// ```
    Stack {
        /// The layers, top first.
        layers: Vec<LayerSpec>,
        /// The elastic base; `None` (omitted) for a rigid base.
        #[cfg_attr(feature = "serde", serde(default))]
        base: Option<MaterialSpec>,
    },
}

/// A material by its constants.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct MaterialSpec {
    /// `E`, Pa.
    pub youngs_modulus: f64,
    /// `nu`.
    pub poisson_ratio: f64,
}

/// One layer of a stack.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct LayerSpec {
    /// `E`, Pa.
    pub youngs_modulus: f64,
    /// `nu`.
    pub poisson_ratio: f64,
    /// Thickness, m.
    pub thickness: f64,
}

impl SubstrateSpec {
    /// The validated substrate.
    ///
    /// # Errors
    /// The errors of [`Material::new`] and the [`Substrate`] constructors.
    pub fn build(&self) -> Result<Substrate> {
        match *self {
            SubstrateSpec::Stack {
                ref layers,
                ref base,
            } => {
                let layers = layers
                    .iter()
                    .map(|l| {
                        Ok((
                            Material::new(l.youngs_modulus, l.poisson_ratio)?,
                            l.thickness,
                        ))
                    })
                    .collect::<Result<Vec<_>>>()?;
                let base = match base {
                    None => crate::substrate::Base::Rigid,
                    Some(m) => crate::substrate::Base::Elastic(Material::new(
                        m.youngs_modulus,
                        m.poisson_ratio,
                    )?),
                };
                Substrate::stack(&layers, base)
            }
            SubstrateSpec::HalfSpace {
                youngs_modulus,
                poisson_ratio,
            } => Ok(Substrate::half_space(Material::new(
                youngs_modulus,
                poisson_ratio,
            )?)),
            SubstrateSpec::LayerOnRigidBase {
                youngs_modulus,
                poisson_ratio,
                thickness,
            } => Substrate::layer_on_rigid_base(
                Material::new(youngs_modulus, poisson_ratio)?,
                thickness,
            ),
            SubstrateSpec::LayerRestingOnRigidBase {
                youngs_modulus,
                poisson_ratio,
                thickness,
            } => Substrate::layer_resting_on_rigid_base(
                Material::new(youngs_modulus, poisson_ratio)?,
                thickness,
            ),
            SubstrateSpec::LayerRestingOnElasticBase {
                youngs_modulus,
                poisson_ratio,
                thickness,
                base_youngs_modulus,
                base_poisson_ratio,
            } => Substrate::layer_resting_on_elastic_base(
                Material::new(youngs_modulus, poisson_ratio)?,
                thickness,
                Material::new(base_youngs_modulus, base_poisson_ratio)?,
            ),
            SubstrateSpec::LayerOnElasticBase {
                youngs_modulus,
                poisson_ratio,
                thickness,
                base_youngs_modulus,
                base_poisson_ratio,
            } => Substrate::layer_on_elastic_base(
                Material::new(youngs_modulus, poisson_ratio)?,
                thickness,
                Material::new(base_youngs_modulus, base_poisson_ratio)?,
            ),
        }
    }
}

/// The indenter's shape.
///
/// The four solids are sized by the scene from their contact (see
/// [`Scene::grid`](super::Scene::grid)). The two height-map kinds are solved
/// on the map's own grid, whatever the scene's resolution says: the map is
/// sampled exactly, cell by cell, and a contact that reaches the map's edge
/// ends there (the map is all there is of the indenter). [`Custom`]
/// takes any [`Indenter`] of the caller's; it cannot be written to or read
/// from a scene file.
///
/// [`Custom`]: IndenterSpec::Custom
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum IndenterSpec {
    /// A flat cylindrical punch.
    FlatPunch {
        /// Radius, m.
        radius: f64,
    },
    /// A sphere (exact cap).
    Sphere {
        /// Radius, m.
        radius: f64,
    },
    /// A paraboloid of tip radius `radius`.
    Paraboloid {
        /// Tip radius, m.
        radius: f64,
    },
    /// A cone.
    Cone {
        /// Half-angle between axis and face, radians.
        half_angle: f64,
        /// Base radius, m.
        base_radius: f64,
    },
    /// Heights (m) read from a file ([`HeightMap::from_npy`] for a `.npy`
    /// file, [`HeightMap::from_text`] for any other), on square cells of
    /// side `spacing`, centred on the axis. The indenter's lowest point
    /// should be at height 0 (it then touches first at depth 0). Split
    /// across MPI ranks, each rank reads its own rows of a `.npy` map (a
    /// text map is read whole on every rank).
    HeightMap {
        /// The file; relative paths are relative to the working directory.
        path: PathBuf,
        /// Cell side, m.
        spacing: f64,
    },
    /// A seeded self-affine rough surface ([`SelfAffine`]) synthesised on
    /// `cells` x `cells` square cells of side `spacing`, turned upside down
    /// into a rigid indenter ([`SelfAffine::indenter`]) whose highest summit
    /// touches first, at depth 0.
    RoughSurface {
        /// Hurst exponent, in `(0, 1)`.
        hurst: f64,
        /// The rms height (m) or rms slope.
        amplitude: Amplitude,
        /// Roll-off wavelength, m.
        long_cutoff: f64,
        /// Short-wavelength cut-off, m (at least two cells).
        short_cutoff: f64,
        /// Seed of the random numbers.
        seed: u64,
        /// Cells along each side, 2 to 32768 (beyond 8192 the solve needs more
        /// memory than one 24 GiB machine has: split it across MPI ranks).
        cells: usize,
        /// Cell side, m.
        spacing: f64,
    },
    /// Any indenter of the caller's: the grid spans its
    /// [`bounding_radius`](Indenter::bounding_radius) with `cells_across`
    /// cells across the bounding diameter (so give a bounding radius close to
    /// the largest contact) and the scene's margin around it, and grows if
    /// the contact reaches its edge.
    #[cfg_attr(feature = "serde", serde(skip))]
    Custom(CustomIndenter),
}

/// An indenter of the caller's for [`IndenterSpec::Custom`], shared by the
/// scenes that hold it. Two are equal if they are the same indenter.
///
/// ```
/// use layered_contact::indenter::Paraboloid;
/// use layered_contact::scene::{CustomIndenter, IndenterSpec, Protocol, Scene};
///
/// let shape = CustomIndenter::new(Paraboloid::new(0.01)?);
/// let scene = Scene {
///     indenter: IndenterSpec::Custom(shape),
///     protocol: Protocol::Depth { depth: 1e-5 },
///     ..Scene::default()
/// };
/// // 64 cells (the default) across the bounding diameter, 0.25 of it on each side.
/// assert_eq!(scene.grid()?.rows(), 96);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Clone)]
pub struct CustomIndenter(Arc<dyn Indenter + Send + Sync>);

impl CustomIndenter {
    /// Wraps `indenter`.
    pub fn new(indenter: impl Indenter + Send + Sync + 'static) -> Self {
        CustomIndenter(Arc::new(indenter))
    }
}

impl std::fmt::Debug for CustomIndenter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CustomIndenter")
            .field("bounding_radius", &self.0.bounding_radius())
            .finish_non_exhaustive()
    }
}

impl PartialEq for CustomIndenter {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Indenter for CustomIndenter {
    fn height(&self, x: f64, y: f64) -> f64 {
        self.0.height(x, y)
    }

    fn bounding_radius(&self) -> f64 {
        self.0.bounding_radius()
    }
}

/// The widest synthesised rough surface, in cells along a side (the widest
/// grid a scene builds).
const MAX_ROUGH_CELLS: usize = crate::grid::MAX_CELLS_PER_AXIS;

/// A small tilt of the indenter, radians (see [`Tilted`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct Tilt {
    /// Rotation about the `y` axis (the face rises with `x`).
    pub angle_y: f64,
    /// Rotation about the `x` axis (the face rises with `y`).
    pub angle_x: f64,
}

impl IndenterSpec {
    /// The validated indenter, tilted if `tilt` is given.
    ///
    /// Height maps are read or synthesised here, once per call.
    ///
    /// # Errors
    /// The errors of the indenters' constructors, of reading a height map
    /// ([`Error::HeightMapFile`]) and of the synthesis
    /// ([`SelfAffine::heights`]).
    pub fn build(&self, tilt: Option<Tilt>) -> Result<Box<dyn Indenter + Send + Sync>> {
        self.build_on(tilt, None)
    }

    /// [`build`](Self::build) for a solver on `grid` split by `slab` (a
    /// distributed run's rank): a rough surface on that same grid is
    /// synthesised in shares, and this rank keeps its own rows only.
    pub(crate) fn build_on(
        &self,
        tilt: Option<Tilt>,
        split: Option<(&crate::slab::Slab, &crate::grid::Grid)>,
    ) -> Result<Box<dyn Indenter + Send + Sync>> {
        let shape: Box<dyn Indenter + Send + Sync> = match self {
            IndenterSpec::FlatPunch { radius } => Box::new(FlatPunch::new(*radius)?),
            IndenterSpec::Sphere { radius } => Box::new(Sphere::new(*radius)?),
            IndenterSpec::Paraboloid { radius } => Box::new(Paraboloid::new(*radius)?),
            IndenterSpec::Cone {
                half_angle,
                base_radius,
            } => Box::new(Cone::new(*half_angle, *base_radius)?),
            IndenterSpec::HeightMap { path, spacing } => match split {
                // A rank of a split run on the map's own grid reads its rows
                // of a `.npy` map only.
                Some((slab, on)) if is_npy(path) && HeightMap::npy_grid(path, *spacing)? == *on => {
                    Box::new(HeightMap::npy_band(path, *spacing, slab.rows())?)
                }
                _ => Box::new(read_height_map(path, *spacing)?),
            },
            IndenterSpec::RoughSurface { .. } => {
                let (surface, grid) = self.rough_surface()?.ok_or(Error::Internal {
                    what: "scene indenter",
                    detail: "a rough surface without its parameters".into(),
                })?;
                // A solver on another grid samples the whole surface.
                let slab = split.and_then(|(slab, on)| (*on == grid).then_some(slab));
                Box::new(surface.indenter_on(&grid, slab)?)
            }
            IndenterSpec::Custom(custom) => {
                crate::error::positive_finite("bounding_radius", custom.bounding_radius())?;
                Box::new(custom.clone())
            }
        };
        Ok(match tilt {
            Some(t) => Box::new(Tilted::new(shape, t.angle_y, t.angle_x)?),
            None => shape,
        })
    }

    /// The grid a height-map kind is defined on (reading a map file's
    /// heights); `None` for the other kinds.
    ///
    /// # Errors
    /// As [`IndenterSpec::build`].
    pub fn map_grid(&self) -> Result<Option<Grid>> {
        Ok(match self {
            IndenterSpec::HeightMap { path, spacing } if is_npy(path) => {
                Some(HeightMap::npy_grid(path, *spacing)?)
            }
            IndenterSpec::HeightMap { path, spacing } => {
                Some(*read_height_map(path, *spacing)?.grid())
            }
            IndenterSpec::RoughSurface { .. } => self.rough_surface()?.map(|(_, grid)| grid),
            _ => None,
        })
    }

    /// Whether the indenter ends at the edge of its own grid (the height-map
    /// kinds), so that a contact reaching it is not truncated by the grid and
    /// `resolution.cells_across` does not set the cell.
    pub fn is_map(&self) -> bool {
        matches!(
            self,
            IndenterSpec::HeightMap { .. } | IndenterSpec::RoughSurface { .. }
        )
    }

    /// The surface and grid of a rough-surface kind, validated without
    /// synthesising it.
    fn rough_surface(&self) -> Result<Option<(SelfAffine, Grid)>> {
        let IndenterSpec::RoughSurface {
            hurst,
            amplitude,
            long_cutoff,
            short_cutoff,
            seed,
            cells,
            spacing,
        } = *self
        else {
            return Ok(None);
        };
        crate::error::within(
            "cells",
            cells as f64,
            (2.0, MAX_ROUGH_CELLS as f64),
            "between 2 and 32768 cells along a side",
        )?;
        let grid = Grid::new(cells, cells, spacing)?;
        let surface = SelfAffine {
            hurst,
            amplitude,
            long_cutoff,
            short_cutoff,
            seed,
        };
        surface.check(&grid)?;
        Ok(Some((surface, grid)))
    }
}

/// A height map from `path`: `.npy` by its extension, plain text otherwise.
fn read_height_map(path: &std::path::Path, spacing: f64) -> Result<HeightMap> {
    if is_npy(path) {
        HeightMap::from_npy(path, spacing)
    } else {
        HeightMap::from_text(path, spacing)
    }
}

/// Whether `path` names a `.npy` file (by its extension).
fn is_npy(path: &std::path::Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"))
}

/// Which adhesion a scene calls for.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum Adhesion {
    /// No adhesion: the non-adhesive solver, `p >= 0`.
    #[default]
    None,
    /// One work of adhesion for both phases, J/m^2.
    Constant {
        /// `dgamma`, J/m^2.
        work_of_adhesion: f64,
    },
    /// Adhesion hysteresis: `dgamma0` while the indenter advances, `dgamma1`
    /// while it retracts, J/m^2.
    Hysteresis {
        /// `dgamma0`, J/m^2.
        loading: f64,
        /// `dgamma1`, J/m^2.
        unloading: f64,
    },
}

impl Adhesion {
    /// The work of adhesion in each phase, `None` without adhesion.
    pub fn works(&self) -> Option<(f64, f64)> {
        match *self {
            Adhesion::None => None,
            Adhesion::Constant { work_of_adhesion } => Some((work_of_adhesion, work_of_adhesion)),
            Adhesion::Hysteresis { loading, unloading } => Some((loading, unloading)),
        }
    }
}
