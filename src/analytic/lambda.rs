//! The kernel function `Lambda` of a layer and its moments `a_m`.
//!
//! For a layer (Poisson ratio `nu`, thickness `h`) on a rigid base
//! (Lyashenko, Popov & Borysiuk 2023, Lubricants 11, 84, section 2):
//!
//! ```text
//! Lambda(u) = [2 L e^(-4u) - (L^2 + 1 + 4u + 4u^2) e^(-2u)]
//!           / [L e^(-4u) - (L^2 + 1 + 4u^2) e^(-2u) + L],      L = 4 nu - 3,
//! a_m = (-1)^m / (2^(2m) (m!)^2) * Integral_0^inf Lambda(u) u^(2m) du.
//! ```
//!
//! `Lambda` is the rigid-base case of `Lambda_g = 1 - R` of the coated
//! half-space ([`CoatingFunctions`]), which is what is evaluated here.

use std::num::NonZeroUsize;

use gauss_quad::legendre::GaussLegendre;

use crate::error::{Error, Result};
use crate::material::Material;
use crate::substrate::{Base, CoatingFunctions};

/// `Lambda(u)` for a layer with Poisson ratio `nu` on a rigid base
/// (Lyashenko, Popov & Borysiuk 2023). `Lambda(0) = 1`; it decays like `u^2 e^(-2u)` and is exactly 0
/// beyond `u = 400`. For many evaluations build a [`CoatingFunctions`] once.
///
/// ```
/// use layered_contact::analytic::lambda;
///
/// assert!((lambda(0.0, 0.3)? - 1.0).abs() < 1e-15);
/// assert!(lambda(5.0, 0.5)? > 0.0 && lambda(5.0, 0.5)? < 1e-2);
/// assert_eq!(lambda(1e6, 0.5)?, 0.0);
/// Ok::<(), layered_contact::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidPoissonRatio`] if `nu` is outside `[0, 0.5]`.
pub fn lambda(u: f64, nu: f64) -> Result<f64> {
    Ok(CoatingFunctions::rigid_base(nu)?.lambda(u))
}

/// `Lambda_g(t) = 1 - R(t)` for a `layer` bonded to `base`, with `t = q h`.
///
/// ```
/// use layered_contact::{analytic::lambda_g, Base, Material};
///
/// let layer = Material::new(1e6, 0.45)?;
/// // On a rigid base it is the Lambda of a layer on a rigid base:
/// let rigid = lambda_g(0.7, &layer, &Base::Rigid);
/// assert!((rigid - layered_contact::analytic::lambda(0.7, 0.45)?).abs() < 1e-16);
/// // On a base of the same material it vanishes:
/// assert_eq!(lambda_g(0.7, &layer, &Base::Elastic(layer)), 0.0);
/// Ok::<(), layered_contact::Error>(())
/// ```
pub fn lambda_g(t: f64, layer: &Material, base: &Base) -> f64 {
    CoatingFunctions::new(layer, base).lambda(t)
}

/// Beyond this order `|a_m|` (about `m^2 4^-m`) underflows `f64`.
const UNDERFLOW_ORDER: u32 = 560;

/// Panel width and order of the composite Gauss-Legendre rule for `a_m`.
const PANEL_WIDTH: f64 = 1.0;
const PANEL_ORDER: usize = 24;

/// The moment `a_m = (-1)^m / (2^(2m) (m!)^2) * Integral_0^inf Lambda(u) u^(2m) du`
/// of Lyashenko, Popov & Borysiuk (2023), for a layer with Poisson ratio `nu`
/// on a rigid base.
///
/// Computed by composite 24-point Gauss-Legendre quadrature on unit panels,
/// continued past the peak of the integrand until a panel adds less than
/// `1e-17` of the sum. The weight `(u/2)^(2m) e^(-2u) / (m!)^2` is formed in
/// logarithms and multiplied by `e^(2u) Lambda(u)`, so nothing overflows for
/// any `m`. Relative accuracy: `2e-15` for `m <= 2` against 80-digit
/// references (tests), degrading like `1e-16 m ln m` for large `m` through
/// the logarithms. Since `|a_m|` falls like `m^2 4^-m`, it is 0 in `f64`
/// beyond `m = 560` (returned at once).
///
/// ```
/// use layered_contact::analytic::a_m;
///
/// // nu = 0.48: a0 = 1.70675517670361, a1 = -0.904416001990345
/// assert!((a_m(0, 0.48)? - 1.7067551767036142).abs() < 1e-13);
/// assert!((a_m(1, 0.48)? + 0.9044160019903449).abs() < 1e-13);
/// Ok::<(), layered_contact::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidPoissonRatio`] if `nu` is outside `[0, 0.5]`;
/// [`Error::NoConvergence`] if the tail has not decayed after `m + 2000`
/// panels (not observed).
pub fn a_m(m: u32, nu: f64) -> Result<f64> {
    a_m_of(m, &CoatingFunctions::rigid_base(nu)?)
}

/// The moment `a_m` of [`a_m`] for any single coating's `Lambda_g`: a
/// layer on an elastic base, or one resting on a rigid base without
/// friction ([`CoatingFunctions::frictionless_rigid_base`]: `a_0 =
/// 1.16757683740435`, `a_1 = -0.395381386454349`).
///
/// ```
/// use layered_contact::analytic::a_m_of;
/// use layered_contact::substrate::CoatingFunctions;
///
/// let resting = CoatingFunctions::frictionless_rigid_base();
/// assert!((a_m_of(0, &resting)? - 1.1675768374043457).abs() < 1e-14);
/// Ok::<(), layered_contact::Error>(())
/// ```
///
/// # Errors
/// As [`a_m`].
pub fn a_m_of(m: u32, functions: &CoatingFunctions) -> Result<f64> {
    if m > UNDERFLOW_ORDER {
        // |a_m| ~ m^2 / 4^m is below the smallest subnormal f64.
        return Ok(0.0);
    }
    let order = NonZeroUsize::new(PANEL_ORDER).expect("order is positive");
    let rule = GaussLegendre::new(order);
    let mf = f64::from(m);
    let ln_factorial: f64 = (2..=m).map(|k| f64::from(k).ln()).sum();
    let integrand = |u: f64| {
        let ln_power = if m == 0 { 0.0 } else { mf * (0.5 * u).ln() };
        functions.lambda_scaled(u) * (2.0 * (ln_power - ln_factorial - u)).exp()
    };
    let peak = mf + 1.0;
    let max_panels = m as usize + 2000;
    let mut sum = 0.0;
    let mut part = 0.0;
    for panel in 0..max_panels {
        let start = panel as f64 * PANEL_WIDTH;
        part = rule.integrate(start, start + PANEL_WIDTH, integrand);
        sum += part;
        if start > peak && part.abs() <= 1e-17 * sum.abs() {
            let sign = if m.is_multiple_of(2) { 1.0 } else { -1.0 };
            return Ok(sign * sum);
        }
    }
    Err(Error::NoConvergence {
        method: "a_m quadrature",
        iterations: max_panels,
        residual: (part / sum).abs(),
    })
}
