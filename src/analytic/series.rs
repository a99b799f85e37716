//! The stiffness series of a flat cylindrical punch on a layer bonded to a
//! rigid base.
//!
//! With `eps = a/h` (punch radius over layer thickness), Eq. 5 of Lyashenko,
//! Popov & Borysiuk (2023, Lubricants 11, 84):
//!
//! ```text
//! K / (2 a E*) = 1 + (2 eps a0/pi)(1 + 2 eps a0/pi) + (8 eps^3/pi)(a0^3/pi^2 + a1/3)
//!                  + (16 eps^4 a0/pi^2)(a0^3/pi^2 + 2 a1/3)
//! ```
//!
//! with the moments `a0`, `a1` of [`a_m`](super::a_m()).
//!
//! # Range of validity
//!
//! The series is an expansion in powers of `eps`, derived for `eps < 1`. At
//! `eps = 1` it is about 4 % off the exact stiffness, and beyond `eps = 2` it
//! is useless (it is a quartic in `eps`, while the exact stiffness of a thin
//! layer grows like `eps^2`, or `eps^3` for an incompressible one). Every
//! result therefore carries `eps`, and
//! [`SeriesStiffness::is_within_validity`] says whether `eps <= 1`
//! ([`PunchStiffnessSeries::VALID_UP_TO_EPS`]). Nothing is clamped or
//! extrapolated silently.

use crate::error::{positive_finite, Result};
use crate::material::Material;

use super::lambda::a_m;

/// The flat-punch stiffness series for one layer on a rigid base.
///
/// ```
/// use layered_contact::{analytic::PunchStiffnessSeries, Material};
///
/// let rubber = Material::new(0.324e6, 0.48)?;
/// let series = PunchStiffnessSeries::new(rubber, 5e-3)?;
/// let k = series.evaluate(2.5e-3)?; // D = 2a = 5 mm = h
/// assert_eq!(k.eps, 0.5);
/// assert!((k.ratio - 1.885659780820121).abs() < 1e-12);
/// assert!(k.is_within_validity());
/// assert!((k.stiffness - k.ratio * 2.0 * 2.5e-3 * rubber.contact_modulus()).abs() < 1e-9);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PunchStiffnessSeries {
    contact_modulus: f64,
    thickness: f64,
    a0: f64,
    a1: f64,
}

/// One evaluation of the series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesStiffness {
    /// `eps = a / h`, the expansion parameter.
    pub eps: f64,
    /// `K / (2 a E*)`, the stiffness relative to the half-space punch.
    pub ratio: f64,
    /// The stiffness `K = dF/dd`, N/m.
    pub stiffness: f64,
}

impl SeriesStiffness {
    /// Whether `eps <= 1`, the range the series was derived for.
    pub fn is_within_validity(&self) -> bool {
        self.eps <= PunchStiffnessSeries::VALID_UP_TO_EPS
    }
}

impl PunchStiffnessSeries {
    /// The largest `eps = a/h` the series was derived for.
    pub const VALID_UP_TO_EPS: f64 = 1.0;

    /// The series for a `layer` of `thickness` (m) on a rigid base.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if
    /// `thickness` is not positive and finite.
    pub fn new(layer: Material, thickness: f64) -> Result<Self> {
        let thickness = positive_finite("thickness", thickness)?;
        let nu = layer.poisson_ratio();
        Ok(PunchStiffnessSeries {
            contact_modulus: layer.contact_modulus(),
            thickness,
            a0: a_m(0, nu)?,
            a1: a_m(1, nu)?,
        })
    }

    /// The moments `(a0, a1)` the series uses.
    pub fn moments(&self) -> (f64, f64) {
        (self.a0, self.a1)
    }

    /// `K / (2 a E*)` as a function of `eps = a/h` alone (the series'
    /// polynomial, evaluated for any `eps`; see the module docs on validity).
    pub fn ratio_at(&self, eps: f64) -> f64 {
        use std::f64::consts::PI;
        let (a0, a1) = (self.a0, self.a1);
        let x = 2.0 * eps * a0 / PI;
        let c = a0.powi(3) / (PI * PI);
        1.0 + x * (1.0 + x)
            + 8.0 * eps.powi(3) / PI * (c + a1 / 3.0)
            + 16.0 * eps.powi(4) * a0 / (PI * PI) * (c + 2.0 * a1 / 3.0)
    }

    /// The stiffness of a punch of `radius` (m).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `radius`
    /// is not positive and finite, or so large against the thickness that
    /// the truncated series has lost its meaning (a ratio below 1: a layer on
    /// a rigid base is always stiffer than its half-space; use
    /// [`Axisymmetric`](crate::analytic::Axisymmetric) there).
    pub fn evaluate(&self, radius: f64) -> Result<SeriesStiffness> {
        let radius = positive_finite("radius", radius)?;
        let eps = radius / self.thickness;
        let ratio = self.ratio_at(eps);
        if !(ratio >= 1.0 && ratio.is_finite()) {
            return Err(crate::Error::InvalidParameter {
                name: "radius / thickness (eps)",
                value: eps,
                expected: "small enough for the series to hold (it gives a stiffness ratio \
                           below 1 here); use the exact Axisymmetric solution",
            });
        }
        Ok(SeriesStiffness {
            eps,
            ratio,
            stiffness: ratio * 2.0 * radius * self.contact_modulus,
        })
    }
}
