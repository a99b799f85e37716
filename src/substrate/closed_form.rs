//! The coating factor of one layer on a base, in closed form.
//!
//! The surface normal displacement of the coated body under a unit normal
//! point force has the Fourier (Hankel) transform `u_z(q) = 2 R(q h) / (E1* q)`,
//! with (Perriot & Barthel 2004, J. Mater. Res. 19, 600; Lyashenko, Popov &
//! Borysiuk 2023, Lubricants 11, 84; `G = mu1/mu2`, `G = 0` for a rigid base)
//!
//! ```text
//! R(t) = N(t) / D(t)
//! N(t) = 1 + 4 m t e^(-2t) - lam m e^(-4t)
//! D(t) = 1 - (lam + m + 4 m t^2) e^(-2t) + lam m e^(-4t)
//! lam  = 1 - 4 (1 - nu1) / (1 + G (3 - 4 nu2)),   m = (G - 1) / (G + 3 - 4 nu1)
//! ```
//!
//! and `Lambda_g(t) = 1 - R(t)`; for a rigid base `Lambda_g` is the `Lambda(u)`
//! of Lyashenko, Popov & Borysiuk (2023).
//!
//! Written as above, `N` and `D` lose all digits to cancellation at small `t`
//! (`R ~ 2t^3/3` for an incompressible layer on a rigid base, `D ~ 4t^4/3`
//! on a very soft substrate). This module evaluates them in a rearranged form
//! in which every term has one sign (or the cancellation is bounded by a factor
//! of four), derived with `kappa_i = 3 - 4 nu_i`, `a = 1 - lam`, `b = 1 - m`:
//!
//! ```text
//! a = (1 + kappa1) / (1 + G kappa2),     b = (1 + kappa1) / (G + kappa1),
//! 1 - lam m = G (1 + kappa1)(1 + kappa2) / ((1 + G kappa2)(G + kappa1)),
//! 1 + lam   = 2 (G kappa2 - (1 - 2 nu1)) / (1 + G kappa2),
//! f(s)      = 1 - e^(-2s) - 2 s e^(-s) = 2 e^(-s) (sinh s - s)      (>= 0),
//! D(t) = f(t) (f(t) + 4 t e^(-t)) + (a + b) e^(-2t) (1 - e^(-2t)) + 4 b t^2 e^(-2t) + a b e^(-4t),
//! N(t) = (1 - lam m) + m (1 + lam)(1 - e^(-4t)) - m f(2t),
//! D(t) - N(t) = 2 lam m e^(-4t) - (lam + m + 4 m t + 4 m t^2) e^(-2t)
//!             = e^(-2t) [-2 (1 - e^(-2t)) + (a + b)(1 - 2 e^(-2t)) + 2 a b e^(-2t) - 4 m t (1 + t)].
//! ```
//!
//! `Lambda_g = (D - N) / D` uses the first form of `D - N` when `|lam| + |m| <= a + b`
//! and the second otherwise (on a soft base the first loses a factor `G`).
//!
//! `f` is summed as a power series for `s < 2` and `1 - e^(-x)` is `-expm1(-x)`;
//! only decaying exponentials appear, so nothing overflows for any `t`.
//! Against 80-digit values (`tests/data/analytic.json`) the relative error is
//! below `1e-15` on every reference point; a randomized scan over
//! `t in [1e-6, 300]`, `G in [0, 1e7]`, `nu in [0, 0.5]` found at most `7e-16`.

use super::frictionless::{
    frictionless_lambda_scaled, frictionless_lambda_taylor, frictionless_r, frictionless_r_over_t,
};
use crate::error::Result;
use crate::material::Material;

use super::series::Series;
use super::Base;

/// Sum of `sinh(s) - s` as a power series, for `0 <= s < 2`.
fn sinh_minus_identity_series(s: f64) -> f64 {
    let s2 = s * s;
    let mut term = s * s2 / 6.0;
    let mut sum = term;
    let mut k = 3.0;
    while term > 1e-17 * sum {
        term *= s2 / ((k + 1.0) * (k + 2.0));
        k += 2.0;
        sum += term;
    }
    sum
}

/// `f(s) = 1 - e^(-2s) - 2 s e^(-s) = 2 e^(-s) (sinh s - s)`, to full relative
/// precision for every `s >= 0` (series below `s = 2`, where the direct form
/// would cancel).
pub(super) fn one_minus_exp_terms(s: f64) -> f64 {
    if s < 2.0 {
        2.0 * (-s).exp() * sinh_minus_identity_series(s)
    } else {
        let e = (-s).exp();
        1.0 - e * e - 2.0 * s * e
    }
}

/// Beyond this `t`, `Lambda_g(t) < t^2 e^(-2t)` is below the smallest
/// subnormal `f64`: `R = 1` and `Lambda_g = 0` exactly.
pub(super) const T_NEGLIGIBLE: f64 = 400.0;

/// The functions of `t = q h` that describe a coated half-space: the coating
/// factor `R(t)` and `Lambda_g(t) = 1 - R(t)`, evaluated without cancellation
/// (see the [module docs](self) for the formulas and their rearrangement).
///
/// Build once (it precomputes the material constants), evaluate many times.
/// The argument `t` is `|q| h`: negative `t` is read as `|t|`.
///
/// ```
/// use layered_contact::{Error, Material};
/// use layered_contact::substrate::{Base, CoatingFunctions};
///
/// // Rigid base: R(0) = 0, R -> 1 at large q h, R = 1 - Lambda.
/// let f = CoatingFunctions::rigid_base(0.5)?;
/// assert_eq!(f.r(0.0), 0.0);
/// // Incompressible layer: R ~ 2 t^3 / 3 at small t, no cancellation.
/// assert!((f.r(1e-3) / (2e-9 / 3.0) - 1.0).abs() < 1e-5);
/// assert!((f.r(2.0) + f.lambda(2.0) - 1.0).abs() < 1e-15);
/// // Elastic base: R(0) = E1* / E2*.
/// let layer = Material::new(1e6, 0.3)?;
/// let base = Material::new(1e9, 0.3)?;
/// let g = CoatingFunctions::new(&layer, &Base::Elastic(base));
/// assert!((g.r(0.0) - 1e-3).abs() < 1e-18);
/// Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoatingFunctions {
    /// A layer resting on its base without friction (then only
    /// `support_ratio` is used of the constants below).
    frictionless: bool,
    /// `rho = E1*/E2*` of a frictionless layer (0 on a rigid base).
    support_ratio: f64,
    /// `G = mu1 / mu2` (0 for a rigid base).
    shear_ratio: f64,
    kappa1: f64,
    kappa2: f64,
    lam: f64,
    m: f64,
    a: f64,
    b: f64,
    one_minus_lam_m: f64,
    one_plus_lam: f64,
}

impl CoatingFunctions {
    /// The functions of a `layer` bonded to `base`.
    pub fn new(layer: &Material, base: &Base) -> Self {
        match base {
            Base::Rigid => Self::from_constants(layer.poisson_ratio(), 0.0, 0.5),
            Base::Elastic(substrate) => Self::from_constants(
                layer.poisson_ratio(),
                layer.shear_modulus() / substrate.shear_modulus(),
                substrate.poisson_ratio(),
            ),
        }
    }

    /// The functions of a layer with Poisson ratio `nu` on a rigid base; then
    /// `Lambda_g` is the `Lambda(u)` of Lyashenko, Popov & Borysiuk (2023).
    ///
    /// # Errors
    /// [`Error::InvalidPoissonRatio`](crate::Error::InvalidPoissonRatio) if `nu` is outside `[0, 0.5]`.
    pub fn rigid_base(nu: f64) -> Result<Self> {
        Ok(Self::from_constants(
            crate::error::poisson_ratio(nu)?,
            0.0,
            0.5,
        ))
    }

    /// `nu1`, `G = mu1/mu2 >= 0` and `nu2` (unused when `G = 0`), all valid.
    fn from_constants(nu1: f64, shear_ratio: f64, nu2: f64) -> Self {
        let g = shear_ratio;
        let kappa1 = 3.0 - 4.0 * nu1;
        let kappa2 = 3.0 - 4.0 * nu2;
        let one_plus_g_kappa2 = 1.0 + g * kappa2;
        let g_plus_kappa1 = g + kappa1;
        CoatingFunctions {
            frictionless: false,
            support_ratio: 0.0,
            shear_ratio: g,
            kappa1,
            kappa2,
            lam: (g * kappa2 - kappa1) / one_plus_g_kappa2,
            m: (g - 1.0) / g_plus_kappa1,
            a: (1.0 + kappa1) / one_plus_g_kappa2,
            b: (1.0 + kappa1) / g_plus_kappa1,
            // Written as a product of ratios so that nothing overflows for huge G.
            one_minus_lam_m: (g / one_plus_g_kappa2) * ((1.0 + kappa1) * (1.0 + kappa2))
                / g_plus_kappa1,
            one_plus_lam: 2.0 * (g * kappa2 - 2.0 * (0.5 - nu1)) / one_plus_g_kappa2,
        }
    }

    /// The functions of a layer resting on a rigid base without friction
    /// (shear-free and in contact everywhere: Dimitriadis et al. 2002's
    /// unbonded layer). A layer of thickness `h` then behaves as one half of
    /// a free slab of thickness `2h` loaded on both faces alike, and
    /// (plane strain, Airy stress function; independent of `nu`)
    ///
    /// ```text
    /// R(t) = 2 sinh^2 t / (2t + sinh 2t) = (1 - e^(-2t))^2 / D(t),   D(t) = 1 - e^(-4t) + 4t e^(-2t),
    /// Lambda_g(t) = 2 e^(-2t) (1 + 2t - e^(-2t)) / D(t),
    /// ```
    ///
    /// every term of one sign; `R ~ t/2` at small `t` (a shear-free film
    /// under a long load is in uniaxial stress, `u = p h / E1*`).
    /// [`CoatingFunctions::frictionless`] gives the layer resting on an
    /// elastic base.
    ///
    /// ```
    /// use layered_contact::substrate::CoatingFunctions;
    ///
    /// let f = CoatingFunctions::frictionless_rigid_base();
    /// assert!((f.r(1.0) - 2.0 * 1f64.sinh().powi(2) / (2.0 + 2f64.sinh())).abs() < 1e-15);
    /// assert!((f.r_over_t(0.0) - 0.5).abs() < 1e-15);
    /// ```
    pub fn frictionless_rigid_base() -> Self {
        CoatingFunctions {
            frictionless: true,
            ..Self::from_constants(0.5, 0.0, 0.5)
        }
    }

    /// The functions of a `layer` resting on `base` without friction: the
    /// interface carries no shear, the layer may slide on it, and the
    /// normal displacement and traction are continuous. With `rho =
    /// E1*/E2*` (0 on a rigid base, where this is
    /// [`CoatingFunctions::frictionless_rigid_base`]), the layer split into
    /// the parts symmetric and antisymmetric about its mid-plane (compliances
    /// `R_s = (cosh t - 1)/(t + sinh t)`, `R_a = (cosh t + 1)/(sinh t - t)`)
    /// and its bottom face pressed on by the base's own compliance `2/(E2* q)`
    /// give, with `e = e^(-2t)`,
    ///
    /// ```text
    /// R(t) = (rho (R_s + R_a) + 2 R_s R_a) / (2 rho + R_s + R_a)
    ///      = (rho P(t) + (1 - e)^2) / D(t),
    /// Lambda_g(t) = 2 e [(1 - e + 2t) - rho (1 - e + 2t + 2t^2)] / D(t),
    /// P(t) = 1 - e^2 + 4 t e,   D(t) = P(t) + rho f(t) (1 - e + 2 t e^(-t)),
    /// f(t) = 1 - e - 2 t e^(-t) = 2 e^(-t) (sinh t - t),
    /// ```
    ///
    /// every term of `R` and `D` of one sign (`f` is summed as a series at
    /// small `t`). `R(0) = rho`, as for a bonded layer: long waves see the
    /// base alone. `Lambda_g` changes sign where the two brackets balance,
    /// and only there loses relative (not absolute) precision. The
    /// independent check in `tests/unbonded.rs` integrates the plane-strain
    /// equations through the layer.
    ///
    /// ```
    /// use layered_contact::{Base, Material};
    /// use layered_contact::substrate::CoatingFunctions;
    ///
    /// let gel = Material::new(10e3, 0.5)?;
    /// let soft = Material::new(20e3, 0.5)?;
    /// let f = CoatingFunctions::frictionless(&gel, &Base::Elastic(soft));
    /// assert!((f.r(0.0) - 0.5).abs() < 1e-15);
    /// assert!((f.r(1.3) + f.lambda(1.3) - 1.0).abs() < 1e-15);
    /// let glass = CoatingFunctions::frictionless(&gel, &Base::Rigid);
    /// assert_eq!(glass.r(0.7), CoatingFunctions::frictionless_rigid_base().r(0.7));
    /// # Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn frictionless(layer: &Material, base: &Base) -> Self {
        let support_ratio = match base {
            Base::Rigid => 0.0,
            Base::Elastic(support) => layer.contact_modulus() / support.contact_modulus(),
        };
        CoatingFunctions {
            support_ratio,
            ..Self::frictionless_rigid_base()
        }
    }

    /// Whether the layer rests on its base without friction.
    pub fn is_frictionless(&self) -> bool {
        self.frictionless
    }

    /// `G = mu1 / mu2`, the shear-modulus ratio of layer to base (0 for a
    /// rigid base).
    pub fn shear_ratio(&self) -> f64 {
        self.shear_ratio
    }

    /// `D(t)`, every term non-negative.
    fn denominator(&self, t: f64) -> f64 {
        let f = one_minus_exp_terms(t);
        let e1 = (-t).exp();
        let e2 = e1 * e1;
        f * (f + 4.0 * t * e1)
            + (self.a + self.b) * e2 * (-(-2.0 * t).exp_m1())
            + 4.0 * self.b * t * t * e2
            + self.a * self.b * e2 * e2
    }

    /// `N(t)`, cancellation bounded.
    fn numerator(&self, t: f64) -> f64 {
        self.one_minus_lam_m + self.m * self.one_plus_lam * (-(-4.0 * t).exp_m1())
            - self.m * one_minus_exp_terms(2.0 * t)
    }

    /// `R(0)`: `E1*/E2*`, written `G (1 + kappa2) / (1 + kappa1)`; 0 on a
    /// rigid base.
    pub fn r_at_zero(&self) -> f64 {
        if self.frictionless {
            return self.support_ratio;
        }
        self.shear_ratio * (1.0 + self.kappa2) / (1.0 + self.kappa1)
    }

    /// The coating factor `R(t)`, `t = q h`: `u_z(q) = 2 R(q h) / (E1* q)`.
    /// Relative accuracy a few `1e-16` for every `t >= 0` (see module docs).
    pub fn r(&self, t: f64) -> f64 {
        let t = t.abs();
        if t > T_NEGLIGIBLE {
            return 1.0;
        }
        if self.frictionless {
            return frictionless_r(self.support_ratio, t);
        }
        let d = self.denominator(t);
        if d > 0.0 {
            self.numerator(t) / d
        } else {
            // Only when t underflows D (t = 0, or t < ~1e-300 with G ~ 1e300).
            self.r_at_zero()
        }
    }

    /// `Lambda_g(t) = 1 - R(t)`, evaluated directly so that its exponentially
    /// small tail keeps its relative precision; for a rigid base it is the
    /// `Lambda(u)` of Lyashenko, Popov & Borysiuk (2023), with `Lambda(0) = 1`.
    pub fn lambda(&self, t: f64) -> f64 {
        let t = t.abs();
        if t > T_NEGLIGIBLE {
            return 0.0;
        }
        if self.frictionless {
            return (-2.0 * t).exp() * self.lambda_scaled(t);
        }
        let d = self.denominator(t);
        if d > 0.0 {
            (-2.0 * t).exp() * self.lambda_numerator_scaled(t) / d
        } else {
            1.0 - self.r_at_zero()
        }
    }

    /// `e^(2t) (D(t) - N(t))`, in whichever of two equal forms cancels less:
    ///
    /// ```text
    /// 2 lam m e^(-2t) - (lam + m) - 4 m t (1 + t)                               (|lam| + |m| <= a + b)
    /// -2 (1 - e^(-2t)) + (a + b)(1 - 2 e^(-2t)) + 2 a b e^(-2t) - 4 m t (1 + t)  (otherwise)
    /// ```
    ///
    /// At `t = 0` both equal `-(a + b - 2ab)`; the first keeps its digits when
    /// `lam` and `m` are small (similar materials, stiff base), the second when
    /// `a` and `b` are (soft base, `G >> 1`), where the first would lose a
    /// factor `G` to cancellation.
    fn lambda_numerator_scaled(&self, t: f64) -> f64 {
        let e2 = (-2.0 * t).exp();
        let tail = 4.0 * self.m * t * (1.0 + t);
        if self.lam.abs() + self.m.abs() <= self.a + self.b {
            2.0 * self.lam * self.m * e2 - (self.lam + self.m) - tail
        } else {
            2.0 * (-2.0 * t).exp_m1()
                + (self.a + self.b) * (1.0 - 2.0 * e2)
                + 2.0 * self.a * self.b * e2
                - tail
        }
    }

    /// `e^(2t) Lambda_g(t)`, which grows only polynomially: used where
    /// `Lambda_g` multiplies a large power of `t` (the `a_m` integrals).
    pub(crate) fn lambda_scaled(&self, t: f64) -> f64 {
        let t = t.abs();
        if self.frictionless {
            return frictionless_lambda_scaled(self.support_ratio, t);
        }
        self.lambda_numerator_scaled(t) / self.denominator(t)
    }

    /// `R(t) / t`, finite at `t = 0` on a rigid base, where it is the
    /// uniaxial-strain limit `R'(0) = 4 m (1 + lam) / D(0)` (0 for an
    /// incompressible layer). On an elastic base `R(0) > 0`, so `R(t)/t`
    /// is `+inf` at `t = 0`.
    pub fn r_over_t(&self, t: f64) -> f64 {
        let t = t.abs();
        if self.frictionless {
            let rho = self.support_ratio;
            let rho_over_t = if rho > 0.0 { rho / t } else { 0.0 };
            return frictionless_r_over_t(rho, rho_over_t, t);
        }
        if self.shear_ratio > 0.0 || t > T_NEGLIGIBLE {
            return self.r(t) / t;
        }
        // Rigid base: N(t) = m (1 + lam)(1 - e^(-4t)) - m f(2t), divided by t
        // term by term.
        let growth = if t == 0.0 {
            4.0
        } else {
            -(-4.0 * t).exp_m1() / t
        };
        let cubic = if t == 0.0 {
            0.0
        } else {
            one_minus_exp_terms(2.0 * t) / t
        };
        (self.m * self.one_plus_lam * growth - self.m * cubic) / self.denominator(t)
    }

    /// The first [`TAYLOR_TERMS`](super::series::TAYLOR_TERMS) Taylor coefficients of `Lambda_g(t)` at
    /// `t = 0`, by truncated power-series arithmetic on the cancellation-free
    /// forms of `D` and `D - N` (so `D(0) = a b > 0` is exact).
    pub(crate) fn lambda_taylor(&self) -> Series {
        if self.frictionless {
            return frictionless_lambda_taylor(&Series::constant(self.support_ratio));
        }
        let (a, b, lam, m) = (self.a, self.b, self.lam, self.m);
        let e1 = Series::exp(-1.0);
        let e2 = Series::exp(-2.0);
        let one = Series::constant(1.0);
        let t = Series::monomial(1);
        let t2 = Series::monomial(2);
        let f = e1.scale(2.0).mul(&Series::sinh_minus_identity());
        let one_minus_e2 = one.sub(&e2);
        let d = f
            .mul(&f.add(&t.mul(&e1).scale(4.0)))
            .add(&e2.mul(&one_minus_e2).scale(a + b))
            .add(&t2.mul(&e2).scale(4.0 * b))
            .add(&Series::exp(-4.0).scale(a * b));
        let tail = t.add(&t2).scale(4.0 * m);
        let inner = if lam.abs() + m.abs() <= a + b {
            e2.scale(2.0 * lam * m)
                .sub(&Series::constant(lam + m))
                .sub(&tail)
        } else {
            one_minus_e2
                .scale(-2.0)
                .add(&one.sub(&e2.scale(2.0)).scale(a + b))
                .add(&e2.scale(2.0 * a * b))
                .sub(&tail)
        };
        e2.mul(&inner).div(&d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Taylor coefficients against the function itself at `t = 1e-3`,
    /// for bonded and frictionless layers. The truncation error is `c_9
    /// t^9`; the coefficients grow up to `11^k` (bonded on a base 5.7
    /// times softer: 1.3e-9 at `t = 1e-2`), so at `1e-3` it is below
    /// 1e-17 and the sums agree to rounding (measured at most 9e-16).
    #[test]
    fn taylor_series_meet_the_functions() {
        let layer = Material::new(1e6, 0.45).unwrap();
        let soft = Base::Elastic(Material::new(0.2e6, 0.3).unwrap());
        let stiff = Base::Elastic(Material::new(50e6, 0.25).unwrap());
        let kinds = [
            CoatingFunctions::new(&layer, &Base::Rigid),
            CoatingFunctions::new(&layer, &soft),
            CoatingFunctions::frictionless(&layer, &Base::Rigid),
            CoatingFunctions::frictionless(&layer, &soft),
            CoatingFunctions::frictionless(&layer, &stiff),
        ];
        for f in kinds {
            let series = f.lambda_taylor().0;
            let t = 1e-3;
            let sum: f64 = series.iter().rev().fold(0.0, |acc, c| acc * t + c);
            let error = (sum - f.lambda(t)).abs();
            assert!(error < 3e-15, "{f:?}: {error:e}");
        }
    }
}
