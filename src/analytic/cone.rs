//! Rigid conical punch on a half-space.

use super::{non_negative, rising_root};
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

/// A rigid cone of half-angle `theta` (profile `f(r) = s r`, `s =
/// cot(theta)`) stuck to a half-space with work of adhesion `dgamma`, in
/// the JKR limit (Maugis & Barquins 1981, J. Physique Lett. 42, L95; Maugis
/// 2000, *Contact, Adhesion and Rupture of Elastic Solids*, ch. 5): Sneddon's
/// cone less the flat punch's adhesive term, with the contact radius `a`
/// as the free variable,
///
/// ```text
/// F(a) = (pi/2) E* s a^2 - sqrt(8 pi dgamma E* a^3)
/// d(a) = (pi/2) s a - sqrt(2 pi dgamma a / E*)
/// ```
///
/// Under load control the contact breaks at the minimum of `F(a)`, `a_p =
/// 18 dgamma / (pi E* s^2)`, `F_p = -54 dgamma^2 / (pi E* s^3)`; under
/// displacement control at the minimum of `d(a)`, `a_c = 2 dgamma / (pi E*
/// s^2)`, `d_c = -dgamma / (E* s)`. Unlike the sphere's, the cone's pull-off
/// force depends on the modulus.
///
/// ```
/// use layered_contact::{analytic::JkrCone, Material};
///
/// let rubber = Material::new(1e6, 0.5)?;
/// let cone = JkrCone::new(&rubber, 70f64.to_radians(), 0.05)?;
/// let f = cone.pull_off_force();
/// assert!((cone.force(cone.pull_off_contact_radius()) - f).abs() < 1e-12 * f.abs());
/// let a = cone.contact_radius_at_force(1e-6).unwrap();
/// assert!((cone.force(a) - 1e-6).abs() < 1e-12 * 1e-6);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrCone {
    contact_modulus: f64,
    /// `cot(theta)`.
    slope: f64,
    work_of_adhesion: f64,
}

impl JkrCone {
    /// A cone of `half_angle` (radians, in `(0, pi/2)`) on a half-space of
    /// `material` with `work_of_adhesion` (J/m^2; 0 gives Sneddon's cone).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a half-angle outside `(0, pi/2)` or a
    /// negative or non-finite work of adhesion.
    pub fn new(material: &Material, half_angle: f64, work_of_adhesion: f64) -> Result<Self> {
        let sneddon = SneddonCone::new(material, half_angle)?;
        Ok(JkrCone {
            contact_modulus: sneddon.contact_modulus,
            slope: sneddon.slope,
            work_of_adhesion: crate::error::non_negative_finite(
                "work_of_adhesion",
                work_of_adhesion,
            )?,
        })
    }

    /// The force `F(a)` at contact radius `a` (m), N.
    pub fn force(&self, contact_radius: f64) -> f64 {
        let a = non_negative(contact_radius);
        let e = self.contact_modulus;
        FRAC_PI_2 * e * self.slope * a * a
            - (8.0 * PI * self.work_of_adhesion * e * a.powi(3)).sqrt()
    }

    /// The depth `d(a)` at contact radius `a` (m), m.
    pub fn depth(&self, contact_radius: f64) -> f64 {
        let a = non_negative(contact_radius);
        FRAC_PI_2 * self.slope * a
            - (2.0 * PI * self.work_of_adhesion * a / self.contact_modulus).sqrt()
    }

    /// `dgamma / (E* s^2)`, the length that sets the adhesive contact.
    fn length(&self) -> f64 {
        self.work_of_adhesion / (self.contact_modulus * self.slope * self.slope)
    }

    /// The pull-off force under load control, `-54 dgamma^2 / (pi E* s^3)`, N.
    pub fn pull_off_force(&self) -> f64 {
        -54.0 * self.work_of_adhesion * self.length() / (PI * self.slope)
    }

    /// The contact radius at load-controlled pull-off, `18 dgamma / (pi E*
    /// s^2)`, m.
    pub fn pull_off_contact_radius(&self) -> f64 {
        18.0 * self.length() / PI
    }

    /// The contact radius at which the contact jumps off under displacement
    /// control, `2 dgamma / (pi E* s^2)`, m.
    pub fn critical_contact_radius(&self) -> f64 {
        2.0 * self.length() / PI
    }

    /// The depth at which the contact jumps off under displacement control,
    /// `-dgamma / (E* s)`, m.
    pub fn critical_depth(&self) -> f64 {
        -self.work_of_adhesion / (self.contact_modulus * self.slope)
    }

    /// The contact radius at `force` on the branch stable under load
    /// control (`a >= a_p`), or `None` below the pull-off force or for a
    /// force that is not finite. By bisection to full precision.
    pub fn contact_radius_at_force(&self, force: f64) -> Option<f64> {
        if !force.is_finite() || force < self.pull_off_force() {
            return None;
        }
        // Above a_p, F rises; F(a) >= (pi/2) E* s a^2 / 2 once the
        // adhesive term is at most half the elastic one (from 64 a_p / 9;
        // at 16 a_p a third).
        let lo = self.pull_off_contact_radius();
        let elastic =
            (2.0 * force.max(0.0) / (FRAC_PI_2 * self.contact_modulus * self.slope)).sqrt();
        Some(rising_root(
            |a| self.force(a),
            force,
            lo,
            (16.0 * lo).max(elastic),
        ))
    }

    /// The contact radius at `depth` on the branch stable under
    /// displacement control (`a >= a_c`), or `None` once the contact has
    /// jumped off (`d < d_c`) or for a depth that is not finite.
    pub fn contact_radius_at_depth(&self, depth: f64) -> Option<f64> {
        if !depth.is_finite() || depth < self.critical_depth() {
            return None;
        }
        // Above a_c, d rises; d(a) >= (pi/4) s a once a >= 16 a_c.
        let lo = self.critical_contact_radius();
        let elastic = 2.0 * depth.max(0.0) / (FRAC_PI_2 * self.slope);
        Some(rising_root(
            |a| self.depth(a),
            depth,
            lo,
            (16.0 * lo).max(elastic),
        ))
    }
}
