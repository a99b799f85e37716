//! JKR adhesive contact of a rigid sphere (paraboloid) with a half-space.

use super::{non_negative, rising_root};
use std::f64::consts::PI;

use crate::error::{non_negative_finite, positive_finite, Result};
use crate::material::Material;

/// A rigid sphere of radius `R` (paraboloid, `a << R`) stuck to a half-space
/// with work of adhesion `dgamma`, in the JKR limit (Johnson, Kendall &
/// Roberts 1971, Proc. R. Soc. A 324, 301; Maugis 2000, Ch. 5). With the
/// contact radius `a` as the free variable:
///
/// ```text
/// F(a) = 4 E* a^3 / (3 R) - sqrt(8 pi dgamma E* a^3)
/// d(a) = a^2 / R - sqrt(2 pi dgamma a / E*)
/// ```
///
/// Under load control the contact breaks at the minimum of `F(a)`:
/// `F = -(3/2) pi dgamma R` at `a = (9 pi dgamma R^2 / (8 E*))^(1/3)`. Under
/// displacement control it breaks at the minimum of `d(a)`:
/// `a_c = (pi dgamma R^2 / (8 E*))^(1/3)`, `d_c = -3 a_c^2 / R`.
///
/// ```
/// use layered_contact::{analytic::JkrSphere, Material};
///
/// let rubber = Material::new(0.324e6, 0.48)?;
/// let jkr = JkrSphere::new(&rubber, 0.05, 0.326)?;
/// let f = jkr.pull_off_force();
/// assert!((f + 1.5 * std::f64::consts::PI * 0.326 * 0.05).abs() < 1e-15);
/// // The force at the pull-off radius is the pull-off force:
/// assert!((jkr.force(jkr.pull_off_contact_radius()) - f).abs() < 1e-12 * f.abs());
/// // Back and forth between force and contact radius:
/// let a = jkr.contact_radius_at_force(0.1).unwrap();
/// assert!((jkr.force(a) - 0.1).abs() < 1e-12);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrSphere {
    contact_modulus: f64,
    radius: f64,
    work_of_adhesion: f64,
}

impl JkrSphere {
    /// A sphere of `radius` (m) on a half-space of `material` with
    /// `work_of_adhesion` (J/m^2; 0 gives Hertz).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `radius`
    /// is not positive and finite or `work_of_adhesion` is negative or not
    /// finite.
    pub fn new(material: &Material, radius: f64, work_of_adhesion: f64) -> Result<Self> {
        Ok(JkrSphere {
            contact_modulus: material.contact_modulus(),
            radius: positive_finite("radius", radius)?,
            work_of_adhesion: non_negative_finite("work_of_adhesion", work_of_adhesion)?,
        })
    }

    /// `pi dgamma / E*`, the length that sets the adhesive terms.
    fn adhesion_length(&self) -> f64 {
        PI * self.work_of_adhesion / self.contact_modulus
    }

    /// The force `F(a)` at contact radius `a` (m), N.
    pub fn force(&self, contact_radius: f64) -> f64 {
        let a = non_negative(contact_radius);
        let e = self.contact_modulus;
        4.0 * e * a.powi(3) / (3.0 * self.radius)
            - (8.0 * PI * self.work_of_adhesion * e * a.powi(3)).sqrt()
    }

    /// The depth `d(a)` at contact radius `a` (m), m.
    pub fn depth(&self, contact_radius: f64) -> f64 {
        let a = non_negative(contact_radius);
        a * a / self.radius - (2.0 * self.adhesion_length() * a).sqrt()
    }

    /// The pull-off force under load control, `-(3/2) pi dgamma R`, N.
    pub fn pull_off_force(&self) -> f64 {
        -1.5 * PI * self.work_of_adhesion * self.radius
    }

    /// The contact radius at load-controlled pull-off,
    /// `(9 pi dgamma R^2 / (8 E*))^(1/3)`, m.
    pub fn pull_off_contact_radius(&self) -> f64 {
        (9.0 * self.adhesion_length() * self.radius.powi(2) / 8.0).cbrt()
    }

    /// The contact radius at which the contact jumps off under displacement
    /// control, `a_c = (pi dgamma R^2 / (8 E*))^(1/3)`, m.
    pub fn critical_contact_radius(&self) -> f64 {
        (self.adhesion_length() * self.radius.powi(2) / 8.0).cbrt()
    }

    /// The depth at which the contact jumps off under displacement control,
    /// `d_c = -3 a_c^2 / R` (the minimum of `d(a)`), m.
    pub fn critical_depth(&self) -> f64 {
        -3.0 * self.critical_contact_radius().powi(2) / self.radius
    }

    /// The contact radius at `force` on the stable branch, or `None` below the
    /// pull-off force (JKR 1971, Eq. 7):
    /// `a^3 = (3R / (4E*)) (F + 3 pi dgamma R + sqrt(6 pi dgamma R F + (3 pi dgamma R)^2))`.
    pub fn contact_radius_at_force(&self, force: f64) -> Option<f64> {
        let p = 3.0 * PI * self.work_of_adhesion * self.radius;
        let discriminant = 2.0 * p * force + p * p;
        if discriminant.is_nan() || discriminant < 0.0 {
            return None;
        }
        let a3 = 0.75 * self.radius / self.contact_modulus * (force + p + discriminant.sqrt());
        Some(a3.max(0.0).cbrt())
    }

    /// The contact radius at `depth` on the branch that is stable under
    /// displacement control (`a >= a_c`), or `None` once the contact has
    /// jumped off (`d < d_c`) or for a depth that is not finite. Found by
    /// bisection to full precision.
    pub fn contact_radius_at_depth(&self, depth: f64) -> Option<f64> {
        if !depth.is_finite() || depth < self.critical_depth() {
            return None;
        }
        let mut lo = self.critical_contact_radius();
        // d(a) <= a^2/R and d(a) -> a^2/R: grow the bracket until d(hi) >= depth.
        let mut hi = (2.0 * lo).max((self.radius * depth.abs()).sqrt());
        while self.depth(hi) < depth {
            lo = hi;
            hi *= 2.0;
        }
        Some(rising_root(|a| self.depth(a), depth, lo, hi))
    }
}
