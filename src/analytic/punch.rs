//! Flat cylindrical punch on a homogeneous half-space, with and without
//! adhesion.

use super::non_negative;
use std::f64::consts::PI;

use crate::error::{non_negative_finite, positive_finite, Result};
use crate::material::Material;

/// A rigid flat cylindrical punch of radius `a` on an elastic half-space
/// (Boussinesq 1885; Johnson, *Contact Mechanics*, 1985, Sec. 3.8):
///
/// ```text
/// F = 2 a E* d,     K = dF/dd = 2 a E*,     p(r) = F / (2 pi a sqrt(a^2 - r^2)),  r < a.
/// ```
///
/// ```
/// use layered_contact::{analytic::BoussinesqPunch, Material};
///
/// let punch = BoussinesqPunch::new(&Material::new(1e6, 0.5)?, 1e-3)?;
/// assert!((punch.stiffness() - 2.0 * 1e-3 * 1e6 / 0.75).abs() < 1e-9);
/// assert_eq!(punch.force(-1e-4), 0.0); // not in contact
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoussinesqPunch {
    contact_modulus: f64,
    radius: f64,
}

impl BoussinesqPunch {
    /// A punch of `radius` (m) on a half-space of `material`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `radius`
    /// is not positive and finite.
    pub fn new(material: &Material, radius: f64) -> Result<Self> {
        Ok(BoussinesqPunch {
            contact_modulus: material.contact_modulus(),
            radius: positive_finite("radius", radius)?,
        })
    }

    /// The stiffness `K = 2 a E*`, N/m.
    pub fn stiffness(&self) -> f64 {
        2.0 * self.radius * self.contact_modulus
    }

    /// The force at `depth` without adhesion: `2 a E* d` for `d > 0`, else 0.
    pub fn force(&self, depth: f64) -> f64 {
        self.stiffness() * non_negative(depth)
    }

    /// The contact pressure at radius `r` under total force `force`:
    /// `F / (2 pi a sqrt(a^2 - r^2))` inside the punch (`|r| < a`), 0 outside
    /// and on the rim, where the integrable edge singularity sits.
    pub fn pressure(&self, force: f64, r: f64) -> f64 {
        let a = self.radius;
        if force.is_nan() || r.is_nan() {
            return f64::NAN;
        }
        if r.abs() < a {
            force / (2.0 * PI * a * ((a - r) * (a + r)).sqrt())
        } else {
            0.0
        }
    }
}

/// A flat cylindrical punch stuck to a half-space with work of adhesion
/// `dgamma` (J/m^2): the JKR limit of Kendall (1971, J. Phys. D 4, 1186).
///
/// The contact radius stays `a` while the punch is attached, so
/// `F = 2 a E* d` for every depth down to detachment. The stress intensity
/// factor at the rim and the energy release rate are (Maugis, *Contact,
/// Adhesion and Rupture of Elastic Solids*, 2000, Ch. 5)
///
/// ```text
/// K_I = -F / (2 a sqrt(pi a)),      G = K_I^2 / (2 E*) = E* d^2 / (2 pi a),
/// ```
///
/// and the punch detaches where `G = dgamma`, in tension:
///
/// ```text
/// F_pull-off = -sqrt(8 pi a^3 E* dgamma),    d_c = -sqrt(2 pi a dgamma / E*).
/// ```
///
/// ```
/// use layered_contact::{analytic::JkrFlatPunch, Material};
///
/// let rubber = Material::new(0.324e6, 0.48)?;
/// let punch = JkrFlatPunch::new(&rubber, 2.5e-3, 0.326)?;
/// let f = punch.pull_off_force();
/// assert!(f < 0.0);
/// assert!((punch.energy_release_rate(punch.critical_depth()) - 0.326).abs() < 1e-12);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrFlatPunch {
    punch: BoussinesqPunch,
    work_of_adhesion: f64,
}

impl JkrFlatPunch {
    /// A punch of `radius` (m) on a half-space of `material`, with work of
    /// adhesion `work_of_adhesion` (J/m^2; 0 gives the non-adhesive punch).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `radius`
    /// is not positive and finite or `work_of_adhesion` is negative or not
    /// finite.
    pub fn new(material: &Material, radius: f64, work_of_adhesion: f64) -> Result<Self> {
        Ok(JkrFlatPunch {
            punch: BoussinesqPunch::new(material, radius)?,
            work_of_adhesion: non_negative_finite("work_of_adhesion", work_of_adhesion)?,
        })
    }

    /// The stiffness `K = 2 a E*` of the attached punch, N/m.
    pub fn stiffness(&self) -> f64 {
        self.punch.stiffness()
    }

    /// The force at `depth`: `2 a E* d` while attached (`d >= d_c`), 0 once
    /// detached.
    pub fn force(&self, depth: f64) -> f64 {
        if depth.is_nan() || depth >= self.critical_depth() {
            // NaN in, NaN out.
            self.stiffness() * depth
        } else {
            0.0
        }
    }

    /// The mode-I stress intensity factor at the rim, `K_I = -F/(2 a sqrt(pi a))`
    /// (Pa m^(1/2)), positive in tension.
    pub fn stress_intensity_factor(&self, depth: f64) -> f64 {
        let a = self.punch.radius;
        -self.stiffness() * depth / (2.0 * a * (PI * a).sqrt())
    }

    /// The energy release rate `G = K_I^2 / (2 E*)` at `depth`, J/m^2.
    pub fn energy_release_rate(&self, depth: f64) -> f64 {
        self.stress_intensity_factor(depth).powi(2) / (2.0 * self.punch.contact_modulus)
    }

    /// The pull-off force `-sqrt(8 pi a^3 E* dgamma)`, N (Kendall 1971).
    pub fn pull_off_force(&self) -> f64 {
        let a = self.punch.radius;
        -(8.0 * PI * a.powi(3) * self.punch.contact_modulus * self.work_of_adhesion).sqrt()
    }

    /// The depth at pull-off, `-sqrt(2 pi a dgamma / E*)`, m.
    pub fn critical_depth(&self) -> f64 {
        -(2.0 * PI * self.punch.radius * self.work_of_adhesion / self.punch.contact_modulus).sqrt()
    }
}
