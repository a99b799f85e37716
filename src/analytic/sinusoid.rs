//! JKR adhesion of a wavy (sinusoidal) surface in plane strain.

use std::f64::consts::PI;

use crate::error::{non_negative_finite, positive_finite, Error, Result};
use crate::material::Material;

/// Bisection steps for the pull-off's contact width (the bracket shrinks by
/// `2^-60`).
const BISECTIONS: usize = 60;
/// Points of the scan that brackets the pull-off.
const SCAN: usize = 4096;

/// A rigid surface `z = g (1 - cos(2 pi x / lambda))` (or a body with that
/// profile against a rigid flat) pressed on a half-space with work of
/// adhesion `dgamma`, in the JKR limit and plane strain (K. L. Johnson 1995,
/// Int. J. Solids Struct. 32, 423). With the contact half-width `a` per
/// period and `psi = pi a / lambda`, the mean pressure is
///
/// ```text
/// pbar / p* = sin^2 psi - alpha sqrt(tan psi),
/// p* = pi E* g / lambda,     alpha = sqrt(2 lambda dgamma / (pi^2 g^2 E*)),
/// ```
///
/// Westergaard's non-adhesive solution (1939) plus the periodic flat punch
/// whose edge stress-intensity factor `K = pbar_F sqrt(lambda / tan psi)`
/// meets Griffith's `K = sqrt(2 E* dgamma)`. Under load control the contact
/// breaks at the minimum of `pbar`, which exists while `alpha` is below
/// about 1.065; above, `pbar` falls all the way to full contact, which the
/// JKR limit never breaks (Johnson's contact also snaps to full contact at
/// zero load from `alpha` of about 0.57 up).
///
/// ```
/// use layered_contact::{analytic::JkrSinusoid, Material};
///
/// let rubber = Material::new(1e6, 0.48)?;
/// // No adhesion: Westergaard, pbar = p* sin^2(pi a / lambda).
/// let dry = JkrSinusoid::new(&rubber, 1e-3, 1e-5, 0.0)?;
/// let p = dry.mean_pressure(0.25e-3);
/// assert!((p - 0.5 * dry.full_contact_pressure()).abs() < 1e-12 * p);
/// let sticky = JkrSinusoid::new(&rubber, 1e-3, 1e-5, 0.01)?;
/// let (pull_off, half_width) = sticky.pull_off()?;
/// assert!(pull_off < 0.0 && half_width < 0.25e-3);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrSinusoid {
    contact_modulus: f64,
    wavelength: f64,
    amplitude: f64,
    work_of_adhesion: f64,
}

impl JkrSinusoid {
    /// A surface of `wavelength` and `amplitude` `g` (m; peak to trough
    /// `2 g`) on a half-space of `material`, work of adhesion
    /// `work_of_adhesion` (J/m^2).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a wavelength or amplitude that is not
    /// positive and finite, or a negative or non-finite work of adhesion.
    pub fn new(
        material: &Material,
        wavelength: f64,
        amplitude: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        Ok(JkrSinusoid {
            contact_modulus: material.contact_modulus(),
            wavelength: positive_finite("wavelength", wavelength)?,
            amplitude: positive_finite("amplitude", amplitude)?,
            work_of_adhesion: non_negative_finite("work_of_adhesion", work_of_adhesion)?,
        })
    }

    /// The mean pressure of full contact without adhesion, `p* = pi E* g /
    /// lambda`, Pa.
    pub fn full_contact_pressure(&self) -> f64 {
        PI * self.contact_modulus * self.amplitude / self.wavelength
    }

    /// Johnson's adhesion parameter `alpha = sqrt(2 lambda dgamma / (pi^2
    /// g^2 E*))`.
    pub fn adhesion_parameter(&self) -> f64 {
        (2.0 * self.wavelength * self.work_of_adhesion
            / (PI * PI * self.amplitude * self.amplitude * self.contact_modulus))
            .sqrt()
    }

    /// The mean pressure (Pa, negative when the surfaces pull) with contact
    /// strips of half-width `half_width` per period: NaN outside `[0,
    /// lambda / 2)`, where no strip of that width exists.
    pub fn mean_pressure(&self, half_width: f64) -> f64 {
        if (0.0..0.5 * self.wavelength).contains(&half_width) {
            self.pressure_at(PI * half_width / self.wavelength)
        } else {
            f64::NAN
        }
    }

    /// The pull-off under load control: the most tensile mean pressure of
    /// the adhesive branch (Pa) and the contact half-width there (m).
    ///
    /// # Errors
    /// [`Error::Unsupported`] if `alpha` is so large that the mean
    /// pressure falls all the way to full contact (no pull-off in the JKR
    /// limit).
    pub fn pull_off(&self) -> Result<(f64, f64)> {
        let alpha = self.adhesion_parameter();
        if alpha == 0.0 {
            return Ok((0.0, 0.0));
        }
        // d pbar / d psi / p* = 2 sin cos - alpha / (2 cos^2 sqrt(tan)):
        // negative near 0 and near pi/2; the pull-off is where it first
        // turns positive.
        let slope = |psi: f64| {
            let (s, c) = psi.sin_cos();
            2.0 * s * c - alpha / (2.0 * c * c * psi.tan().sqrt())
        };
        let top = 0.5 * PI;
        let first = (1..SCAN)
            .map(|k| top * k as f64 / SCAN as f64)
            .find(|&psi| slope(psi) > 0.0)
            .ok_or(Error::Unsupported {
                feature: "a pull-off of this JKR sinusoid",
                reason: "its adhesion parameter is large enough for the surfaces to \
                         snap into full contact, which the JKR limit never breaks",
            })?;
        let (mut low, mut high) = (first - top / SCAN as f64, first);
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (low + high);
            if slope(mid) > 0.0 {
                high = mid;
            } else {
                low = mid;
            }
        }
        let psi = 0.5 * (low + high);
        Ok((self.pressure_at(psi), psi * self.wavelength / PI))
    }

    fn pressure_at(&self, psi: f64) -> f64 {
        self.full_contact_pressure()
            * (psi.sin().powi(2) - self.adhesion_parameter() * psi.tan().sqrt())
    }
}
