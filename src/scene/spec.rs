//! Plain-number descriptions of bodies, indenters and effects: what a scene
//! file holds. Each is validated when built into the library's types.

use crate::error::Result;
use crate::indenter::{Cone, FlatPunch, Indenter, Paraboloid, Sphere, Tilted};
use crate::material::Material;
use crate::substrate::Substrate;

/// The body, by its material constants (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
}

impl SubstrateSpec {
    /// The validated substrate.
    ///
    /// # Errors
    /// The errors of [`Material::new`] and the [`Substrate`] constructors.
    pub fn build(&self) -> Result<Substrate> {
        match *self {
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
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
}

/// A small tilt of the indenter, radians (see [`Tilted`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// # Errors
    /// The errors of the indenters' constructors.
    pub fn build(&self, tilt: Option<Tilt>) -> Result<Box<dyn Indenter + Send + Sync>> {
        let shape: Box<dyn Indenter + Send + Sync> = match *self {
            IndenterSpec::FlatPunch { radius } => Box::new(FlatPunch::new(radius)?),
            IndenterSpec::Sphere { radius } => Box::new(Sphere::new(radius)?),
            IndenterSpec::Paraboloid { radius } => Box::new(Paraboloid::new(radius)?),
            IndenterSpec::Cone {
                half_angle,
                base_radius,
            } => Box::new(Cone::new(half_angle, base_radius)?),
        };
        Ok(match tilt {
            Some(t) => Box::new(Tilted::new(shape, t.angle_y, t.angle_x)?),
            None => shape,
        })
    }
}

/// Which adhesion a scene calls for.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
