//! Rigid conical punch on a half-space.

use super::non_negative;
use std::f64::consts::{FRAC_PI_2, PI};

use crate::error::{Error, Result};
use crate::material::Material;

/// A rigid cone of half-angle `theta` (between axis and face; a Berkovich
/// equivalent cone has 70.3 degrees), profile `f(r) = r cot(theta)`, pressed
/// into a half-space without adhesion (Sneddon 1965, Int. J. Eng. Sci. 3, 47):
///
/// ```text
/// d = (pi/2) a cot(theta),   F = (pi/2) E* a^2 cot(theta) = 2 E* d^2 tan(theta) / pi,
/// mean pressure F / (pi a^2) = (E*/2) cot(theta).
/// ```
///
/// ```
/// use layered_contact::{analytic::SneddonCone, Material};
///
/// let cone = SneddonCone::new(&Material::new(1e9, 0.3)?, 70.3f64.to_radians())?;
/// let d = 1e-6;
/// let a = cone.contact_radius(d);
/// let mean = cone.force(d) / (std::f64::consts::PI * a * a);
/// assert!((mean / cone.mean_pressure() - 1.0).abs() < 1e-14);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SneddonCone {
    contact_modulus: f64,
    /// `cot(theta)`, the slope of the face.
    slope: f64,
}

impl SneddonCone {
    /// A cone of `half_angle` (radians, strictly between 0 and pi/2) on a
    /// half-space of `material`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `half_angle` is outside `(0, pi/2)`.
    pub fn new(material: &Material, half_angle: f64) -> Result<Self> {
        if !(half_angle > 0.0 && half_angle < FRAC_PI_2) {
            return Err(Error::InvalidParameter {
                name: "half_angle",
                value: half_angle,
                expected: "in (0, pi/2) radians",
            });
        }
        Ok(SneddonCone {
            contact_modulus: material.contact_modulus(),
            slope: 1.0 / half_angle.tan(),
        })
    }

    /// The contact radius `a = 2 d tan(theta) / pi` at `depth` (0 for `d <= 0`), m.
    pub fn contact_radius(&self, depth: f64) -> f64 {
        2.0 * non_negative(depth) / (PI * self.slope)
    }

    /// The force `2 E* d^2 tan(theta) / pi` at `depth` (0 for `d <= 0`), N.
    pub fn force(&self, depth: f64) -> f64 {
        let d = non_negative(depth);
        2.0 * self.contact_modulus * d * d / (PI * self.slope)
    }

    /// The contact stiffness `dF/dd = 2 a E*` at `depth`, N/m.
    pub fn stiffness(&self, depth: f64) -> f64 {
        2.0 * self.contact_radius(depth) * self.contact_modulus
    }

    /// The mean contact pressure `(E*/2) cot(theta)`, independent of depth, Pa.
    pub fn mean_pressure(&self) -> f64 {
        0.5 * self.contact_modulus * self.slope
    }
}
