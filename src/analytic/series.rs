//! Small-indentation ("bottom-effect") series on a layer bonded to a rigid
//! base: the flat punch's stiffness and the paraboloid's force.
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
//! For a paraboloid of tip radius `R` at depth `d`, with `chi = sqrt(R d)/h`
//! and `c = 2 a0 / pi`, the exact expansion of the same integral equation
//! ([`ParaboloidForceSeries`]) is
//!
//! ```text
//! F / F_Hertz = 1 + c chi + (7/6) c^2 chi^2 + [(40/27) c^3 + 32 a1/(15 pi)] chi^3
//!                 + [(143/72) c^4 + 32 c a1/(5 pi)] chi^4 + O(chi^5).
//! ```
//!
//! Dimitriadis et al. (2002, Biophys. J. 82, 2798), whose series AFM users
//! fit, wrote the same expansion with the punch's factors (1 in place of
//! 7/6, 40/27 and 143/72; 24/(5 pi) in place of 32/(5 pi)) and with `a0`,
//! `a1` from polynomial fits in `nu`: their bonded coefficients at
//! `nu = 0.5`, [`DIMITRIADIS_BONDED`], are 1.133, 1.283, 0.769, 0.0975
//! where the exact ones are 1.1270, 1.4817, 1.4700, 1.0047
//! ([`doc::bottom_effect`](crate::doc::bottom_effect) has where each series
//! leaves the exact curve).
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

/// The bonded-layer coefficients of Dimitriadis et al. (2002, Biophys. J.
/// 82, 2798, Eq. 12 at `nu = 0.5`): `F / F_Hertz = 1 + 1.133 chi + 1.283
/// chi^2 + 0.769 chi^3 + 0.0975 chi^4`, `chi = sqrt(R d)/h`, as AFM software
/// fits them. Kept to compare with; the exact coefficients are those of
/// [`ParaboloidForceSeries`].
pub const DIMITRIADIS_BONDED: [f64; 4] = [1.133, 1.283, 0.769, 0.0975];

/// The unbonded-layer coefficients of Dimitriadis et al. (2002, Eq. 13 at
/// `nu = 0.5`): 0.884, 0.781, 0.386, 0.0048. The exact ones
/// ([`ParaboloidForceSeries::frictionless`]) do not depend on `nu`: 0.7433,
/// 0.6446, 0.3399, 0.0076.
pub const DIMITRIADIS_UNBONDED: [f64; 4] = [0.884, 0.781, 0.386, 0.0048];

/// The force of a paraboloid pressed into a layer bonded to a rigid base,
/// expanded in `chi = sqrt(R d)/h` to fourth order: the exact small-
/// indentation series (see the [module docs](self)).
///
/// ```
/// use layered_contact::analytic::ParaboloidForceSeries;
///
/// // An incompressible layer (cells, gels): 1 + 1.1270 chi + 1.4817 chi^2 + ...
/// let c = ParaboloidForceSeries::new(0.5)?.coefficients();
/// assert!((c[0] - 1.1269549993).abs() < 1e-9);
/// assert!((c[1] / (c[0] * c[0]) - 7.0 / 6.0).abs() < 1e-14);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParaboloidForceSeries {
    coefficients: [f64; 4],
}

impl ParaboloidForceSeries {
    /// The series for a layer of Poisson ratio `poisson_ratio` on a rigid
    /// base.
    ///
    /// # Errors
    /// [`Error::InvalidPoissonRatio`](crate::Error::InvalidPoissonRatio) if
    /// `poisson_ratio` is outside `[0, 0.5]`.
    pub fn new(poisson_ratio: f64) -> Result<Self> {
        let (a0, a1) = bonded_moments(poisson_ratio)?;
        Ok(Self::from_moments(a0, a1))
    }

    /// The series for a layer resting on a rigid base without friction
    /// (Dimitriadis et al. 2002's unbonded layer), the same for every
    /// Poisson ratio: `1 + 0.7433 chi + 0.6446 chi^2 + 0.3399 chi^3 +
    /// 0.0076 chi^4`; against least-squares fits of exact forces to the
    /// fits' precision, as for bonded layers (`tests/unbonded.rs`).
    ///
    /// # Errors
    /// As [`a_m_of`](super::a_m_of).
    pub fn frictionless() -> Result<Self> {
        let (a0, a1) = resting_moments()?;
        Ok(Self::from_moments(a0, a1))
    }

    /// The series from the moments `a0`, `a1` of the layer's `Lambda_g`.
    fn from_moments(a0: f64, a1: f64) -> Self {
        use std::f64::consts::PI;
        let c = 2.0 * a0 / PI;
        ParaboloidForceSeries {
            coefficients: [
                c,
                7.0 / 6.0 * c * c,
                40.0 / 27.0 * c.powi(3) + 32.0 * a1 / (15.0 * PI),
                143.0 / 72.0 * c.powi(4) + 32.0 * c * a1 / (5.0 * PI),
            ],
        }
    }

    /// The coefficients of `chi`, `chi^2`, `chi^3`, `chi^4`.
    pub fn coefficients(&self) -> [f64; 4] {
        self.coefficients
    }

    /// `F / F_Hertz` at `chi = sqrt(R d)/h` by the truncated series (for any
    /// `chi`: it is an expansion, and leaves the exact force by 5 % near
    /// `chi = 0.5`, see [`doc::bottom_effect`](crate::doc::bottom_effect)).
    pub fn ratio_at(&self, chi: f64) -> f64 {
        truncated_series(&self.coefficients, chi)
    }
}

/// The bonded-layer coefficients of Garcia & Garcia (2018, Biophys. J.
/// 114, 2923) at `nu = 0.5` for a paraboloid, in `chi = sqrt(R d)/h`: 1.133,
/// 1.497, 1.469, 0.755. Their first two are the exact series' form, `c` and
/// `(7/6) c^2`, with Dimitriadis' `c = 1.133` (and `c^2` = 1.283) where the
/// exact `c` is 1.12695; the exact coefficients are those of
/// [`ParaboloidForceSeries`] ([`doc::bottom_effect`](crate::doc::bottom_effect)
/// compares them).
pub const GARCIA_PARABOLOID: [f64; 4] = [1.133, 1.497, 1.469, 0.755];

/// Garcia & Garcia (2018) for a cone, in `chi = d tan(theta)/h`
/// (`theta` the half-angle): 0.721, 0.650, 0.491, 0.225. The first two are
/// the exact form `2 c/pi`, `5 c^2/pi^2` with Dimitriadis' `c`; the exact
/// coefficients are those of [`ConeForceSeries`].
pub const GARCIA_CONE: [f64; 4] = [0.721, 0.650, 0.491, 0.225];

/// Garcia & Garcia (2018) for a flat punch, in `chi = a/h`: 1.133, 1.283,
/// 0.598, -0.291, against the exact [`PunchStiffnessSeries`] (Lyashenko,
/// Popov & Borysiuk 2023): `c`, `c^2` with Dimitriadis' `c`.
pub const GARCIA_PUNCH: [f64; 4] = [1.133, 1.283, 0.598, -0.291];

/// The force of a cone of half-angle `theta` pressed into a layer bonded
/// to a rigid base over Sneddon's, `F_S = (2/pi) E* tan(theta) d^2`,
/// expanded in `chi = d tan(theta)/h` to fourth order, with `c = 2 a0/pi`:
///
/// ```text
/// F / F_S = 1 + (2c/pi) chi + (5 c^2/pi^2) chi^2 + [14 c^3/pi^3 + 16 a1/pi^4] chi^3
///             + [42 c^4/pi^4 + 112 c a1/pi^5] chi^4 + O(chi^5).
/// ```
///
/// The first two orders follow from the constant shift of the paraboloid's
/// derivation ([`doc::bottom_effect`](crate::doc::bottom_effect)): with
/// Sneddon's `d_0 = (pi/2) a cot(theta)` and `F = (pi/2) E* a^2 cot(theta)`,
/// `y = a/h` solves `y - (c/2) y^2 = (2/pi) chi` and `F/F_S = (pi y / (2
/// chi))^2`. In `u = 2 chi/pi` the series is `1 + c u + (5/4) c^2 u^2 +
/// (7/4) c^3 u^3 + (21/8) c^4 u^4` plus `(2 a1/pi) u^3 + (7 c a1/pi) u^4`;
/// the rational factors of the third and fourth orders were identified from
/// exact solutions at Poisson ratios 0 and 0.5 and then checked at 0.3 and
/// 0.45 (`tests/bottom_effect.rs`, to the least-squares fits' precision, as
/// for the paraboloid).
///
/// ```
/// use layered_contact::analytic::{ConeForceSeries, GARCIA_CONE};
///
/// let c = ConeForceSeries::new(0.5)?.coefficients();
/// // 0.7174, 0.6434, 0.4889, 0.3004 against Garcia & Garcia's 0.721, 0.650,
/// // 0.491, 0.225:
/// assert!((c[0] - 0.71744).abs() < 1e-5 && (GARCIA_CONE[0] / c[0] - 1.0) < 0.006);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConeForceSeries {
    coefficients: [f64; 4],
}

impl ConeForceSeries {
    /// The series for a layer of Poisson ratio `poisson_ratio` bonded to a
    /// rigid base.
    ///
    /// # Errors
    /// [`Error::InvalidPoissonRatio`](crate::Error::InvalidPoissonRatio) if
    /// `poisson_ratio` is outside `[0, 0.5]`.
    pub fn new(poisson_ratio: f64) -> Result<Self> {
        let (a0, a1) = bonded_moments(poisson_ratio)?;
        Ok(Self::from_moments(a0, a1))
    }

    /// The series for a layer resting on a rigid base without friction,
    /// the same for every Poisson ratio.
    ///
    /// # Errors
    /// As [`a_m_of`](super::a_m_of).
    pub fn frictionless() -> Result<Self> {
        let (a0, a1) = resting_moments()?;
        Ok(Self::from_moments(a0, a1))
    }

    fn from_moments(a0: f64, a1: f64) -> Self {
        use std::f64::consts::PI;
        let c = 2.0 * a0 / PI;
        let (p2, p3, p4) = (PI * PI, PI.powi(3), PI.powi(4));
        ConeForceSeries {
            coefficients: [
                2.0 * c / PI,
                5.0 * c * c / p2,
                14.0 * c.powi(3) / p3 + 16.0 * a1 / p4,
                42.0 * c.powi(4) / p4 + 112.0 * c * a1 / (p4 * PI),
            ],
        }
    }

    /// The coefficients of `chi`, `chi^2`, `chi^3`, `chi^4`.
    pub fn coefficients(&self) -> [f64; 4] {
        self.coefficients
    }

    /// `F / F_S` at `chi = d tan(theta)/h` by the truncated series.
    pub fn ratio_at(&self, chi: f64) -> f64 {
        truncated_series(&self.coefficients, chi)
    }
}

/// The moments `a0`, `a1` of a layer of Poisson ratio `nu` bonded to a
/// rigid base.
fn bonded_moments(nu: f64) -> Result<(f64, f64)> {
    Ok((a_m(0, nu)?, a_m(1, nu)?))
}

/// The moments `a0`, `a1` of a layer resting on a rigid base without
/// friction (the same for every Poisson ratio).
fn resting_moments() -> Result<(f64, f64)> {
    let resting = crate::substrate::CoatingFunctions::frictionless_rigid_base();
    Ok((super::a_m_of(0, &resting)?, super::a_m_of(1, &resting)?))
}

/// `1 + c[0] x + c[1] x^2 + c[2] x^3 + c[3] x^4`: a bottom-effect series
/// such as [`DIMITRIADIS_BONDED`] at `x`.
pub fn truncated_series(coefficients: &[f64; 4], x: f64) -> f64 {
    1.0 + x
        * (coefficients[0] + x * (coefficients[1] + x * (coefficients[2] + x * coefficients[3])))
}
