//! Isotropic linear-elastic materials.

use crate::error::{poisson_ratio, Error, Result};

/// The smallest Young's modulus accepted, Pa.
pub const MIN_MODULUS: f64 = 1e-150;
/// The largest Young's modulus accepted, Pa.
pub const MAX_MODULUS: f64 = 1e150;

/// An isotropic linear-elastic material, given by Young's modulus `E` (Pa)
/// and Poisson's ratio `nu`.
///
/// Both are validated at construction: `E` in `[1e-150, 1e150]` Pa, `nu` in
/// `[0, 0.5]` (`nu = 0.5`, an incompressible rubber, is an ordinary case).
/// The plane-strain contact modulus `E* = E / (1 - nu^2)` is derived, never
/// passed in, so the two cannot be confused.
///
/// ```
/// use layered_contact::{Error, Material};
///
/// let rubber = Material::new(0.324e6, 0.48)?;
/// assert!((rubber.contact_modulus() - 0.324e6 / (1.0 - 0.48 * 0.48)).abs() < 1e-9);
/// assert!(Material::new(1e6, 0.7).is_err());
/// Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    youngs_modulus: f64,
    poisson_ratio: f64,
}

impl Material {
    /// A material with Young's modulus `youngs_modulus` (Pa) and Poisson's
    /// ratio `poisson_ratio`.
    ///
    /// # Errors
    /// [`Error::InvalidYoungsModulus`] if `E` is NaN or outside
    /// `[1e-150, 1e150]` Pa (far beyond any material, and the range in which
    /// compliances `1/(pi E*)` and modulus ratios stay normal `f64` numbers:
    /// `E = 1.2e308` would make every influence coefficient underflow to 0);
    /// [`Error::InvalidPoissonRatio`] if `nu` is outside `[0, 0.5]` or NaN.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        let nu = self::poisson_ratio(poisson_ratio)?;
        let material = Material {
            youngs_modulus,
            poisson_ratio: nu,
        };
        if (MIN_MODULUS..=MAX_MODULUS).contains(&youngs_modulus) {
            Ok(material)
        } else {
            Err(Error::InvalidYoungsModulus {
                value: youngs_modulus,
            })
        }
    }

    /// Young's modulus `E`, Pa.
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson's ratio `nu`.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// The contact (plane-strain) modulus `E* = E / (1 - nu^2)`, Pa.
    pub fn contact_modulus(&self) -> f64 {
        let nu = self.poisson_ratio;
        self.youngs_modulus / ((1.0 - nu) * (1.0 + nu))
    }

    /// The shear modulus `mu = E / (2 (1 + nu))`, Pa.
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Kolosov's constant for plane strain, `kappa = 3 - 4 nu`, in `[1, 3]`.
    pub fn kolosov_constant(&self) -> f64 {
        3.0 - 4.0 * self.poisson_ratio
    }

    /// The uniaxial-strain (oedometric, P-wave) modulus
    /// `M = E (1 - nu) / ((1 + nu)(1 - 2 nu))`, Pa; infinite for `nu = 0.5`.
    pub fn uniaxial_strain_modulus(&self) -> f64 {
        let nu = self.poisson_ratio;
        self.youngs_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))
    }
}
