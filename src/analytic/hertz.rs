//! Hertz contact of a rigid sphere (paraboloid) with a half-space.

use super::non_negative;
use std::f64::consts::PI;

use crate::error::{positive_finite, Result};
use crate::material::Material;

/// A rigid sphere of radius `R`, in the paraboloidal approximation
/// `f(r) = r^2 / (2R)`, pressed into a half-space without adhesion (Hertz
/// 1882; Johnson, *Contact Mechanics*, 1985, Eqs. 4.22-4.23):
///
/// ```text
/// a = sqrt(R d),   F = (4/3) E* R^(1/2) d^(3/2),   p0 = 2 E* a / (pi R),
/// p(r) = p0 sqrt(1 - r^2/a^2),   dF/dd = 2 a E*.
/// ```
///
/// Valid for `a << R`; the exact spherical cap departs from it at order
/// `d / R`.
///
/// ```
/// use layered_contact::{analytic::Hertz, Material};
///
/// let hertz = Hertz::new(&Material::new(1e6, 0.5)?, 0.05)?;
/// let d = 1e-4;
/// let f = hertz.force(d);
/// assert!((hertz.depth_at_force(f) - d).abs() < 1e-18);
/// assert!((hertz.contact_radius(d) - (0.05f64 * d).sqrt()).abs() < 1e-18);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    contact_modulus: f64,
    radius: f64,
}

impl Hertz {
    /// A sphere of `radius` (m) on a half-space of `material`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `radius`
    /// is not positive and finite.
    pub fn new(material: &Material, radius: f64) -> Result<Self> {
        Ok(Hertz {
            contact_modulus: material.contact_modulus(),
            radius: positive_finite("radius", radius)?,
        })
    }

    /// The contact radius `a = sqrt(R d)` at `depth` (0 for `d <= 0`), m.
    pub fn contact_radius(&self, depth: f64) -> f64 {
        (self.radius * non_negative(depth)).sqrt()
    }

    /// The force `(4/3) E* sqrt(R) d^(3/2)` at `depth` (0 for `d <= 0`), N.
    pub fn force(&self, depth: f64) -> f64 {
        let d = non_negative(depth);
        4.0 / 3.0 * self.contact_modulus * self.radius.sqrt() * d * d.sqrt()
    }

    /// The depth at which the force is `force` (0 for `F <= 0`), m.
    pub fn depth_at_force(&self, force: f64) -> f64 {
        (0.75 * non_negative(force) / (self.contact_modulus * self.radius.sqrt())).powf(2.0 / 3.0)
    }

    /// The contact stiffness `dF/dd = 2 a E*` at `depth`, N/m.
    pub fn stiffness(&self, depth: f64) -> f64 {
        2.0 * self.contact_radius(depth) * self.contact_modulus
    }

    /// The pressure at the centre, `p0 = 2 E* a / (pi R)`, Pa.
    pub fn central_pressure(&self, depth: f64) -> f64 {
        2.0 * self.contact_modulus * self.contact_radius(depth) / (PI * self.radius)
    }

    /// The pressure `p0 sqrt(1 - r^2/a^2)` at radius `r` (0 outside), Pa.
    pub fn pressure(&self, depth: f64, r: f64) -> f64 {
        let a = self.contact_radius(depth);
        if r.abs() < a {
            self.central_pressure(depth) * ((a - r) * (a + r)).sqrt() / a
        } else {
            0.0
        }
    }
}
