//! The pressure under any axisymmetric tip on the coated half-space, and
//! whether its disc of contact holds without adhesion.
//!
//! The exact solution assumes that the contact is the disc `r < a`. A stiff
//! layer on a far softer base bends like a plate on a foundation, and
//! pressed far enough its middle lifts off the tip: the contact becomes a
//! ring (as for a plate on a foundation under a rigid sphere). The disc's
//! solution then pulls on the tip inside, which a non-adhesive contact
//! cannot do, and it is not the contact's solution (a sphere of 23 um on a
//! 95 MPa layer 1.4 um thick over a base 8000 times softer: the disc's
//! radius 9.7 um against a ring of 8.5 to 10 um in the BEM).

use std::f64::consts::PI;

use super::tip::{piece_rule, Solved, TipFunctions};
use super::{gauss, LayeredTip, Nystrom, Tip};
use crate::error::{Error, Result};

/// Radii at which [`LayeredTip::minimum_pressure_ratio`] samples the
/// pressure, evenly over `[0, 0.999 a]`.
const PRESSURE_SAMPLES: usize = 100;

/// Gauss-Legendre points of the pressure's tail integral (per piece between
/// kinks of the profile).
const TAIL_ORDER: usize = 32;

/// The least pressure over the mean above which the disc counts as holding
/// without adhesion: zero to the rounding of the pressure's terms.
const HOLDS_ROUNDING: f64 = 1e-9;

impl Tip {
    /// `g'(x)`, the slope of [`Tip::equivalent_profile`]: `d/dx [x
    /// Integral_0^(pi/2) f'(x sin t) dt] = Integral_0^(pi/2) [f'(x sin t) + x
    /// sin t f''(x sin t)] dt`, in closed form but for the rounded cone
    /// beyond its kink (Gauss-Legendre over the sphere's part).
    fn equivalent_slope(&self, x: f64) -> f64 {
        let x = x.abs();
        // d/dx [x atanh(x/R)].
        let sphere = |radius: f64| {
            let u = x / radius;
            u.atanh() + u / ((1.0 - u) * (1.0 + u))
        };
        match *self {
            Tip::Paraboloid { radius } => 2.0 * x / radius,
            Tip::Sphere { radius } => sphere(radius),
            Tip::Cone { half_angle } => 0.5 * PI / half_angle.tan(),
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => {
                let b = tip_radius * half_angle.cos();
                if x <= b {
                    return sphere(tip_radius);
                }
                let edge = (b / x).asin();
                let r2 = tip_radius * tip_radius;
                // f' + r f'' of the sphere at r = x sin t.
                let sphere_part = piece_rule().integrate(0.0, edge, |t| {
                    let r = x * t.sin();
                    let rest = (r2 - r * r).sqrt();
                    r / rest + r * r2 / (rest * rest * rest)
                });
                sphere_part + (0.5 * PI - edge) / half_angle.tan()
            }
        }
    }
}

impl LayeredTip {
    /// The pressure (Pa, positive in compression) at radius `r` (m) of the
    /// equilibrium with contact radius `contact_radius` (m), that of
    /// [`LayeredTip::at_contact_radius`]; zero outside the contact:
    ///
    /// ```text
    /// p(r) = (E1*/pi) [phi(a) / sqrt(a^2 - r^2) - Integral_r^a phi'(t) / sqrt(t^2 - r^2) dt],
    /// phi = d psi_1 - psi_g
    /// ```
    ///
    /// (Sneddon 1965, Int. J. Eng. Sci. 3, 47, on a half-space; the
    /// Fredholm solution of [`doc::axisymmetric`](crate::doc::axisymmetric)
    /// on a coated body).
    ///
    /// ```
    /// use layered_contact::analytic::{Axisymmetric, Tip};
    /// use layered_contact::{Material, Substrate};
    ///
    /// // Sneddon's cone on a half-space: p = (E* cot(theta) / 2) acosh(a/r).
    /// let rubber = Material::new(1e6, 0.5)?;
    /// let theta = 70f64.to_radians();
    /// let half = Axisymmetric::new(&Substrate::half_space(rubber), 1.0)?;
    /// let cone = half.tip(Tip::Cone { half_angle: theta }, 0.0)?;
    /// let (a, r): (f64, f64) = (1e-6, 0.3e-6);
    /// let sneddon = 0.5 * rubber.contact_modulus() / theta.tan() * (a / r).acosh();
    /// assert!((cone.pressure(a, r)? / sneddon - 1.0).abs() < 1e-9);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`LayeredTip::at_contact_radius`].
    pub fn pressure(&self, contact_radius: f64, r: f64) -> Result<f64> {
        let (solved, functions) = self.solved_with_functions(contact_radius)?;
        let depth = self.equilibrium_depth(contact_radius, &solved);
        let profile = Profile {
            tip: self,
            solved: &solved,
            functions: &functions,
            radius: contact_radius,
            depth,
        };
        Ok(profile.pressure(&gauss(TAIL_ORDER), r))
    }

    /// The least pressure over the disc of radius `contact_radius` (m),
    /// sampled at 100 radii over `[0, 0.999 a]` (the pressure of a
    /// non-adhesive contact falls to zero at the edge like `sqrt(a - r)`),
    /// divided by the mean pressure `F / (pi a^2)` of that equilibrium:
    /// negative where the disc's solution pulls on the tip, as a stiff layer
    /// on a far softer base does at its middle once it bends. As
    /// [`LayeredFlatPunch::minimum_pressure_ratio`](super::LayeredFlatPunch::minimum_pressure_ratio)
    /// for the punch.
    ///
    /// # Errors
    /// As [`LayeredTip::at_contact_radius`], and
    /// [`Error::InvalidParameter`] where the equilibrium's force is zero (no
    /// mean pressure to measure by).
    pub fn minimum_pressure_ratio(&self, contact_radius: f64) -> Result<f64> {
        let (solved, functions) = self.solved_with_functions(contact_radius)?;
        let a = contact_radius;
        let depth = self.equilibrium_depth(a, &solved);
        let force = self.state_at_depth(a, depth, &solved).force;
        let mean = force / (PI * a * a);
        if mean.is_nan() || mean == 0.0 {
            return Err(Error::InvalidParameter {
                name: "force at the contact radius",
                value: force,
                expected: "non-zero (the least pressure is measured by the mean)",
            });
        }
        let profile = Profile {
            tip: self,
            solved: &solved,
            functions: &functions,
            radius: a,
            depth,
        };
        let rule = gauss(TAIL_ORDER);
        let least = (0..PRESSURE_SAMPLES)
            .map(|k| profile.pressure(&rule, 0.999 * a * k as f64 / (PRESSURE_SAMPLES - 1) as f64))
            .fold(f64::INFINITY, f64::min);
        Ok(least / mean.abs())
    }

    /// Whether the disc of radius `contact_radius` (m) presses on the tip
    /// everywhere ([`LayeredTip::minimum_pressure_ratio`] at least zero, to
    /// `1e-9` of the mean), so that without adhesion it is the contact.
    ///
    /// # Errors
    /// As [`LayeredTip::minimum_pressure_ratio`].
    pub fn holds_without_adhesion(&self, contact_radius: f64) -> Result<bool> {
        Ok(self.minimum_pressure_ratio(contact_radius)? >= -HOLDS_ROUNDING)
    }
}

/// One equilibrium's auxiliary function `phi`, for its pressure.
struct Profile<'a> {
    tip: &'a LayeredTip,
    solved: &'a Solved,
    functions: &'a TipFunctions,
    radius: f64,
    depth: f64,
}

impl Profile<'_> {
    /// `d phi / d xi` at `xi = x / a`: `d psi_1' - psi_g'`, with `psi_g'
    /// = a g'(a xi) + (K g)' + (K chi)'` (or `(a^2/R) psi_2'` for a
    /// paraboloid).
    fn slope(&self, xi: f64) -> f64 {
        let solution = &self.functions.solution;
        let a = self.radius;
        let profile = match self.tip.tip {
            Tip::Paraboloid { radius } => a * a / radius * solution.slope(true, xi),
            tip => {
                let kg = match &solution.kernel {
                    None => 0.0,
                    Some(kernel) => self
                        .functions
                        .weighted
                        .iter()
                        .map(|&(s, wg)| wg * Nystrom::kernel_slope(kernel, solution.eps, xi, s))
                        .sum(),
                };
                a * tip.equivalent_slope(a * xi)
                    + solution.interpolate_values(
                        &solution.extra_values,
                        xi,
                        kg,
                        Nystrom::kernel_slope,
                    )
            }
        };
        self.depth * solution.slope(false, xi) - profile
    }

    /// The pressure at `r`, the tail integral by `rule` on each piece
    /// between the profile's kinks (the piece past a kink over `w^2`), over `u` with `t = r cosh u` (`dt /
    /// sqrt(t^2 - r^2) = du`: smooth, and exact for a cone's constant
    /// `phi'`, whose pressure grows like `ln(a/r)` at the centre); at the
    /// centre itself over `t` (`phi'(0) = 0` but for the cone, whose
    /// pressure is infinite there and comes out large).
    fn pressure(&self, rule: &gauss_quad::legendre::GaussLegendre, r: f64) -> f64 {
        let a = self.radius;
        let r = r.abs();
        if r.is_nan() {
            return f64::NAN;
        }
        if r >= a {
            return 0.0;
        }
        let edge = self.depth * self.solved.unit[1] - self.solved.profile[1];
        let chord = ((a - r) * (a + r)).sqrt();
        let kink = self.tip.tip.kink().filter(|&b| b > r && b < a);
        // The piece from a kink out: `g''` grows like `1 / sqrt(x - b)`
        // past a rounded cone's (its `asin(b/x)`), so `phi'` starts like a
        // square root there, which `w^2` removes.
        let integrate = |lo: f64, hi: f64, f: &dyn Fn(f64) -> f64, from_kink: bool| {
            if from_kink {
                let span = hi - lo;
                rule.integrate(0.0, 1.0, |w| 2.0 * span * w * f(lo + span * w * w))
            } else {
                rule.integrate(lo, hi, f)
            }
        };
        let pieces = |end: f64, at: &dyn Fn(f64) -> f64, f: &dyn Fn(f64) -> f64| match kink {
            Some(b) => integrate(0.0, at(b), f, false) + integrate(at(b), end, f, true),
            None => integrate(0.0, end, f, false),
        };
        let tail = if r > 0.0 {
            pieces((a / r).acosh(), &|b| (b / r).acosh(), &|u| {
                self.slope(r * u.cosh() / a) / a
            })
        } else {
            pieces(a, &|b| b, &|t| self.slope(t / a) / (a * t))
        };
        self.tip.body.contact_modulus / PI * (edge / chord - tail)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `g'` against central differences of `g` (step `1e-6 x`), on both
    /// sides of the rounded cone's kink.
    #[test]
    fn equivalent_slopes_match_finite_differences() {
        let tips = [
            Tip::Paraboloid { radius: 2e-3 },
            Tip::Sphere { radius: 2e-3 },
            Tip::Cone { half_angle: 1.2 },
            Tip::RoundedCone {
                half_angle: 1.2,
                tip_radius: 1e-3,
            },
        ];
        for tip in tips {
            for x in [1e-4, 3e-4, 5e-4, 9e-4, 1.5e-3] {
                let h = 1e-6 * x;
                let fd =
                    (tip.equivalent_profile(x + h) - tip.equivalent_profile(x - h)) / (2.0 * h);
                let slope = tip.equivalent_slope(x);
                assert!(
                    (slope / fd - 1.0).abs() < 1e-7,
                    "{tip:?} at {x}: {slope} vs {fd}"
                );
            }
        }
    }
}
