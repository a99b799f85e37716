//! Exact axisymmetric contact on a coated half-space: a Fredholm integral
//! equation of the second kind, solved by Nystrom's method.
//!
//! The derivation is in [`doc::axisymmetric`](crate::doc::axisymmetric). In
//! short: writing the pressure under a contact of radius `a` through an
//! auxiliary function `phi` on `[0, a]`,
//!
//! ```text
//! p(r) = (E1*/pi) [ phi(a) / sqrt(a^2 - r^2) - Integral_r^a phi'(t) / sqrt(t^2 - r^2) dt ],
//! ```
//!
//! the condition `u_z(r) = d - f(r)` inside the contact becomes, with
//! `x = a xi`, `eps = a/h` and the cosine transform
//! `k(y) = Integral_0^inf Lambda_g(u) cos(u y) du`,
//!
//! ```text
//! phi(xi) - (eps/pi) Integral_0^1 [k(eps (xi - s)) + k(eps (xi + s))] phi(s) ds = d - g(a xi),
//! g(x) = x Integral_0^x f'(r) / sqrt(x^2 - r^2) dr          (g = x^2/R for a paraboloid),
//! F = 2 E1* a Integral_0^1 phi(xi) d xi,
//! K_I = -E1* phi(1) / sqrt(pi a),   G = E1* phi(1)^2 / (2 pi a).
//! ```
//!
//! On a half-space `Lambda_g = 0` and `phi = d - g`: Boussinesq, Hertz and
//! JKR exactly. The kernel is smooth, so Gauss-Legendre Nystrom converges
//! exponentially; the order is doubled until the stiffness and the edge value
//! `phi(1)` change by less than `1e-11`.

use std::f64::consts::PI;
use std::sync::Arc;

use nalgebra::{DMatrix, DVector};

use crate::error::{positive_finite, Error, Result};
use crate::numerics::{gauss, oscillatory_integral, OctaveTable};
use crate::substrate::Substrate;

mod curve;
mod family;
mod paraboloid;
mod punch;
mod tip;
mod tip_pressure;

pub use curve::{before_jump_off, ForceCurve};
pub use family::{ModulusFamily, MODULUS_NODES};

pub(in crate::analytic) use paraboloid::{golden_minimum, minimise, MINIMISE_SCAN};
pub use paraboloid::{ContactState, LayeredParaboloid, PullOff};
pub use punch::LayeredFlatPunch;
pub use tip::{LayeredTip, Tip};

/// Smallest and largest Nystrom orders tried.
const MIN_ORDER: usize = 16;
const MAX_ORDER: usize = 4096;
/// Relative change between two orders that counts as converged.
const CONVERGED: f64 = 1e-11;
/// Also accepted as converged: a change that stalls (rounding floor) below
/// this.
const ROUNDING_FLOOR: f64 = 1e-8;

/// The cosine transform `k(y)` of `Lambda_g`, and its derivative, tabulated
/// as a sum of pieces, one per length scale of the body (one for a layer,
/// one per interface of a stack): `k(y) = sum_k s_k k_k(s_k y)` with
/// `s_k = h/z_k`, `z_k` the piece's length and `k_k` the cosine transform
/// of its part of `Lambda_g` in units of `z_k`.
#[derive(Debug)]
struct CosineKernel {
    pieces: Vec<CosinePiece>,
}

#[derive(Debug)]
struct CosinePiece {
    /// `h / z_k`.
    scale: f64,
    value: OctaveTable,
    slope: OctaveTable,
}

impl CosineKernel {
    fn value(&self, y: f64) -> f64 {
        self.pieces
            .iter()
            .map(|piece| piece.scale * piece.value.eval(piece.scale * y))
            .sum()
    }

    fn slope(&self, y: f64) -> f64 {
        self.pieces
            .iter()
            .map(|piece| piece.scale * piece.scale * piece.slope.eval(piece.scale * y))
            .sum()
    }
}

/// Exact axisymmetric contact solutions on one substrate: flat punches and
/// paraboloids, with and without adhesion (JKR).
///
/// Build once per substrate (this tabulates the kernel, a few ms to
/// tens of ms); each solution then costs one small dense solve.
///
/// ```
/// use layered_contact::analytic::{Axisymmetric, PunchStiffnessSeries};
/// use layered_contact::{Material, Substrate};
///
/// let rubber = Material::new(0.324e6, 0.48)?;
/// let film = Substrate::layer_on_rigid_base(rubber, 5e-3)?;
/// let exact = Axisymmetric::new(&film, 4.0)?;
/// let punch = exact.flat_punch(2.5e-3)?; // D = h = 5 mm
/// let series = PunchStiffnessSeries::new(rubber, 5e-3)?.evaluate(2.5e-3)?;
/// // The series is good to ~eps^5 at a/h = 0.5:
/// assert!((punch.ratio() / series.ratio - 1.0).abs() < 0.01);
/// // On a half-space the solution is Boussinesq's, exactly.
/// let half = Axisymmetric::new(&Substrate::half_space(rubber), 4.0)?;
/// assert_eq!(half.flat_punch(1e-3)?.ratio(), 1.0);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Axisymmetric {
    pub(in crate::analytic) contact_modulus: f64,
    /// Layer thickness; `None` for a half-space.
    thickness: Option<f64>,
    kernel: Option<Arc<CosineKernel>>,
    max_eps: f64,
}

/// A third right-hand side of the Nystrom equation, `(kernel, eps, xi) ->
/// r(xi)`.
type ExtraRhs<'a> = dyn Fn(&CosineKernel, f64, f64) -> f64 + 'a;

/// A converged Nystrom solution on `[0, 1]` for a given `eps`.
#[derive(Debug, Clone)]
struct Nystrom {
    eps: f64,
    nodes: Vec<f64>,
    weights: Vec<f64>,
    /// Solutions for the right-hand sides `1` and `xi^2`.
    unit: Vec<f64>,
    quadratic: Vec<f64>,
    /// `Integral_0^1 chi` and `chi(1)` for a third right-hand side `r`
    /// (`chi = r + K chi`), if one was asked for: a tip's profile
    /// ([`super::LayeredTip`]) solved with the same factorisation and
    /// converged with the others.
    extra: Option<[f64; 2]>,
    /// That third solution `chi` at the nodes (empty without one).
    extra_values: Vec<f64>,
    kernel: Option<Arc<CosineKernel>>,
    /// Relative change at the last doubling.
    change: f64,
}

impl Nystrom {
    fn trivial() -> Self {
        Nystrom {
            eps: 0.0,
            nodes: Vec::new(),
            weights: Vec::new(),
            unit: Vec::new(),
            quadratic: Vec::new(),
            extra: None,
            extra_values: Vec::new(),
            kernel: None,
            change: 0.0,
        }
    }

    /// `(eps/pi) [k(eps (xi - s)) + k(eps (xi + s))]`.
    fn kernel_at(kernel: &CosineKernel, eps: f64, xi: f64, s: f64) -> f64 {
        eps / PI * (kernel.value(eps * (xi - s).abs()) + kernel.value(eps * (xi + s)))
    }

    /// `d/dxi` of [`Nystrom::kernel_at`].
    fn kernel_slope(kernel: &CosineKernel, eps: f64, xi: f64, s: f64) -> f64 {
        let sign = if xi >= s { 1.0 } else { -1.0 };
        eps * eps / PI * (sign * kernel.slope(eps * (xi - s).abs()) + kernel.slope(eps * (xi + s)))
    }

    /// Solves at `order` points, for the right-hand sides `1`, `xi^2` and
    /// `extra` if given.
    fn solve(
        kernel: &Arc<CosineKernel>,
        eps: f64,
        order: usize,
        extra: Option<&dyn Fn(f64) -> f64>,
    ) -> Result<Self> {
        let rule = gauss(order);
        let (nodes, weights): (Vec<f64>, Vec<f64>) =
            rule.iter().map(|(x, w)| (0.5 * (x + 1.0), 0.5 * w)).unzip();
        let n = nodes.len();
        let matrix = DMatrix::from_fn(n, n, |i, j| {
            let delta = if i == j { 1.0 } else { 0.0 };
            delta - weights[j] * Self::kernel_at(kernel, eps, nodes[i], nodes[j])
        });
        let lu = matrix.lu();
        let solve = |rhs: DVector<f64>| {
            lu.solve(&rhs).ok_or(Error::Internal {
                what: "Nystrom solve",
                detail: "singular matrix".to_string(),
            })
        };
        let unit = solve(DVector::from_element(n, 1.0))?;
        let quadratic = solve(DVector::from_iterator(n, nodes.iter().map(|x| x * x)))?;
        let mut extra_values = Vec::new();
        let extra = match extra {
            None => None,
            Some(rhs) => {
                let chi = solve(DVector::from_iterator(n, nodes.iter().map(|&x| rhs(x))))?;
                let integral = weights.iter().zip(chi.iter()).map(|(w, v)| w * v).sum();
                let edge = rhs(1.0)
                    + nodes
                        .iter()
                        .zip(&weights)
                        .zip(chi.iter())
                        .map(|((s, w), v)| w * Self::kernel_at(kernel, eps, 1.0, *s) * v)
                        .sum::<f64>();
                extra_values = chi.as_slice().to_vec();
                Some([integral, edge])
            }
        };
        Ok(Nystrom {
            eps,
            nodes,
            weights,
            unit: unit.as_slice().to_vec(),
            quadratic: quadratic.as_slice().to_vec(),
            extra,
            extra_values,
            kernel: Some(Arc::clone(kernel)),
            change: f64::INFINITY,
        })
    }

    /// Doubles the order until integral and edge value of every solution
    /// have converged; `extra` is a third right-hand side and the scale its
    /// solution's change is measured on.
    fn converged(
        kernel: &Arc<CosineKernel>,
        eps: f64,
        extra: Option<(&dyn Fn(f64) -> f64, f64)>,
    ) -> Result<Self> {
        let rhs = extra.map(|(f, _)| f);
        let mut order = MIN_ORDER.max((4.0 * eps).ceil() as usize);
        let mut previous = Self::solve(kernel, eps, order, rhs)?;
        let mut last_change = f64::INFINITY;
        loop {
            order *= 2;
            if order > MAX_ORDER {
                // Still falling at the largest order, but already below
                // the rounding floor (an incompressible film at a/h = 200
                // ends at 7.5e-10): as accurate as a stall would be.
                if previous.change < ROUNDING_FLOOR {
                    return Ok(previous);
                }
                return Err(Error::NoConvergence {
                    method: "Nystrom discretisation",
                    iterations: order / 2,
                    residual: previous.change,
                });
            }
            let mut next = Self::solve(kernel, eps, order, rhs)?;
            let pairs = [
                (next.integral(false), previous.integral(false)),
                (next.edge(false), previous.edge(false)),
                (next.integral(true), previous.integral(true)),
                (next.edge(true), previous.edge(true)),
            ];
            let mut change = pairs
                .iter()
                .map(|(a, b)| ((a - b) / a.abs().max(f64::MIN_POSITIVE)).abs())
                .fold(0.0, f64::max);
            // The extra solution's change on the scale its caller gives (a
            // tip's `chi` beside its profile's own terms, which it corrects:
            // `chi` itself may be a small difference).
            if let (Some(a), Some(b), Some((_, scale))) = (next.extra, previous.extra, extra) {
                let size = scale.max(a[0].abs() + a[1].abs()).max(f64::MIN_POSITIVE);
                change = change.max(((a[0] - b[0]).abs() + (a[1] - b[1]).abs()) / size);
            }
            next.change = change;
            // Converged, or at the rounding floor: the change no longer
            // falls (the Nystrom error falls exponentially with the order
            // until rounding, which grows with `a/h` for incompressible
            // layers, takes over) and is already small.
            if change < CONVERGED || (change < ROUNDING_FLOOR && change > 0.25 * last_change) {
                return Ok(next);
            }
            last_change = change;
            previous = next;
        }
    }

    fn values(&self, quadratic: bool) -> &[f64] {
        if quadratic {
            &self.quadratic
        } else {
            &self.unit
        }
    }

    /// `Integral_0^1 psi`.
    fn integral(&self, quadratic: bool) -> f64 {
        match &self.kernel {
            None => {
                if quadratic {
                    1.0 / 3.0
                } else {
                    1.0
                }
            }
            Some(_) => self
                .weights
                .iter()
                .zip(self.values(quadratic))
                .map(|(w, v)| w * v)
                .sum(),
        }
    }

    /// `rhs + Integral_0^1 kernel(xi, s) psi(s) ds` by the Nystrom rule, for
    /// `kernel` = [`Nystrom::kernel_at`] (values) or
    /// [`Nystrom::kernel_slope`] (slopes).
    fn interpolate(
        &self,
        quadratic: bool,
        xi: f64,
        rhs: f64,
        kernel_fn: fn(&CosineKernel, f64, f64, f64) -> f64,
    ) -> f64 {
        self.interpolate_values(self.values(quadratic), xi, rhs, kernel_fn)
    }

    /// [`Nystrom::interpolate`] of the solution whose node values are
    /// `values`.
    fn interpolate_values(
        &self,
        values: &[f64],
        xi: f64,
        rhs: f64,
        kernel_fn: fn(&CosineKernel, f64, f64, f64) -> f64,
    ) -> f64 {
        match &self.kernel {
            None => rhs,
            Some(kernel) => {
                rhs + self
                    .nodes
                    .iter()
                    .zip(&self.weights)
                    .zip(values)
                    .map(|((s, w), v)| w * kernel_fn(kernel, self.eps, xi, *s) * v)
                    .sum::<f64>()
            }
        }
    }

    /// `psi(xi)` by Nystrom interpolation.
    fn value(&self, quadratic: bool, xi: f64) -> f64 {
        let rhs = if quadratic { xi * xi } else { 1.0 };
        self.interpolate(quadratic, xi, rhs, Self::kernel_at)
    }

    fn edge(&self, quadratic: bool) -> f64 {
        self.value(quadratic, 1.0)
    }

    /// `psi'(xi)`.
    fn slope(&self, quadratic: bool, xi: f64) -> f64 {
        let rhs = if quadratic { 2.0 * xi } else { 0.0 };
        self.interpolate(quadratic, xi, rhs, Self::kernel_slope)
    }
}

impl Axisymmetric {
    /// The largest `a/h` offered: the Nystrom order grows like `8 a/h`
    /// (1600 nodes, about a second, at 200).
    pub const MAX_RADIUS_OVER_THICKNESS: f64 = 200.0;

    /// Solutions on `substrate` for contact radii up to
    /// `max_radius_over_thickness` times the top layer's thickness (the
    /// largest `a/h` covered; ignored for a half-space). The kernel is
    /// tabulated up to that range once, at a cost that grows with it, so ask
    /// for what you need: `2.0` covers contacts up to twice the thickness.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `max_radius_over_thickness` is not
    /// positive and finite or exceeds [`Axisymmetric::MAX_RADIUS_OVER_THICKNESS`].
    pub fn new(substrate: &Substrate, max_radius_over_thickness: f64) -> Result<Self> {
        let max_eps = positive_finite("max_radius_over_thickness", max_radius_over_thickness)?;
        if max_eps > Self::MAX_RADIUS_OVER_THICKNESS {
            return Err(Error::InvalidParameter {
                name: "max_radius_over_thickness",
                value: max_eps,
                expected: "at most 200 (the Nystrom order grows like 8 a/h)",
            });
        }
        let contact_modulus = substrate.surface_material().contact_modulus();
        let Some(h) = substrate.top_thickness() else {
            return Ok(Axisymmetric {
                contact_modulus,
                thickness: None,
                kernel: None,
                max_eps,
            });
        };
        let rule = gauss(20);
        let pieces = substrate
            .terms()
            .into_iter()
            .map(|term| {
                let functions = &term.functions;
                let scale = h / term.length;
                let u_max = 40.0 + (1.0 + functions.lambda(0.0).abs()).ln();
                let y_max = 2.0 * max_eps * scale;
                let value = OctaveTable::build(
                    0,
                    true,
                    |y| {
                        oscillatory_integral(
                            |u| functions.lambda(u) * (u * y).cos(),
                            y,
                            u_max,
                            &rule,
                        )
                    },
                    |end| end >= y_max,
                );
                let slope = value.derivative();
                CosinePiece {
                    scale,
                    value,
                    slope,
                }
            })
            .collect();
        Ok(Axisymmetric {
            contact_modulus,
            thickness: Some(h),
            kernel: Some(Arc::new(CosineKernel { pieces })),
            max_eps,
        })
    }

    /// `eps = a/h` of a contact radius, checked against the tabulated range.
    fn nystrom(&self, radius: f64) -> Result<(f64, Nystrom)> {
        self.nystrom_with(radius, None)
    }

    /// [`Axisymmetric::nystrom`] with a third right-hand side, given the
    /// kernel and `eps` (see [`Nystrom::extra`]), and the scale its
    /// solution converges on.
    fn nystrom_with(&self, radius: f64, extra: Option<(&ExtraRhs, f64)>) -> Result<(f64, Nystrom)> {
        let radius = positive_finite("radius", radius)?;
        match (&self.kernel, self.thickness) {
            (Some(kernel), Some(h)) => {
                let eps = radius / h;
                if eps > self.max_eps {
                    return Err(Error::InvalidParameter {
                        name: "radius / thickness",
                        value: eps,
                        expected: "within the range given to Axisymmetric::new",
                    });
                }
                let rhs = extra.map(|(f, scale)| (move |xi: f64| f(kernel, eps, xi), scale));
                let rhs = rhs
                    .as_ref()
                    .map(|(f, scale)| (f as &dyn Fn(f64) -> f64, *scale));
                Ok((radius, Nystrom::converged(kernel, eps, rhs)?))
            }
            _ => Ok((radius, Nystrom::trivial())),
        }
    }

    /// Solutions on `substrate` for contact radii up to `max_contact_radius`
    /// (m): [`Axisymmetric::new`] with `max_contact_radius / h` (any range on
    /// a half-space).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `max_contact_radius` is not positive and
    /// finite, and as [`Axisymmetric::new`].
    pub fn up_to_contact_radius(substrate: &Substrate, max_contact_radius: f64) -> Result<Self> {
        let radius = positive_finite("max_contact_radius", max_contact_radius)?;
        let eps = substrate
            .top_thickness()
            .map_or(1.0, |thickness| radius / thickness);
        Self::new(substrate, eps)
    }

    /// [`Axisymmetric::up_to_contact_radius`] with `max_contact_radius`
    /// reduced to the most the solutions offer
    /// ([`MAX_RADIUS_OVER_THICKNESS`](Self::MAX_RADIUS_OVER_THICKNESS)
    /// layer thicknesses), for callers that search within whatever range
    /// there is (a force curve's table, a pull-off's scan).
    ///
    /// # Errors
    /// As [`Axisymmetric::up_to_contact_radius`].
    pub fn up_to_contact_radius_in_range(
        substrate: &Substrate,
        max_contact_radius: f64,
    ) -> Result<Self> {
        let most = substrate
            .top_thickness()
            .map_or(f64::INFINITY, |h| h * Self::MAX_RADIUS_OVER_THICKNESS);
        Self::up_to_contact_radius(substrate, max_contact_radius.min(most))
    }

    /// The flat cylindrical punch of `radius` (m), bonded or not.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a radius that is not positive or
    /// beyond the tabulated range; [`Error::NoConvergence`] if the Nystrom
    /// order would exceed 4096.
    pub fn flat_punch(&self, radius: f64) -> Result<LayeredFlatPunch> {
        let (radius, solution) = self.nystrom(radius)?;
        Ok(LayeredFlatPunch {
            contact_modulus: self.contact_modulus,
            radius,
            solution,
        })
    }

    /// A paraboloid `f = r^2 / (2R)` of tip radius `sphere_radius` (m) with
    /// work of adhesion `work_of_adhesion` (J/m^2; 0 for non-adhesive).
    /// The result shares the body's tables, so it can be built in one
    /// expression:
    ///
    /// ```
    /// use layered_contact::analytic::Axisymmetric;
    /// use layered_contact::{Material, Substrate};
    ///
    /// let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.5)?, 1e-3)?;
    /// // Contact radii up to twice the film's thickness (a/h <= 2).
    /// let sphere = Axisymmetric::new(&film, 2.0)?.paraboloid(0.1, 0.0)?;
    /// // a = h/100: Hertz, F = 4 E* a^3 / (3 R); the bonded incompressible
    /// // film stiffens it by 8e-7.
    /// let state = sphere.at_contact_radius(1e-5)?;
    /// let hertz = 4.0 * (1e6 / 0.75) * 1e-15 / (3.0 * 0.1);
    /// assert!((state.force / hertz - 1.0).abs() < 1e-5);
    /// # Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a radius that is not positive and
    /// finite or a negative work of adhesion.
    pub fn paraboloid(
        &self,
        sphere_radius: f64,
        work_of_adhesion: f64,
    ) -> Result<LayeredParaboloid> {
        Ok(LayeredParaboloid {
            body: self.clone(),
            sphere_radius: positive_finite("sphere_radius", sphere_radius)?,
            work_of_adhesion: crate::error::non_negative_finite(
                "work_of_adhesion",
                work_of_adhesion,
            )?,
        })
    }

    /// The largest contact radius (m) the tabulated kernel covers
    /// (`+inf` on a half-space).
    pub fn max_contact_radius(&self) -> f64 {
        self.thickness.map_or(f64::INFINITY, |h| self.max_eps * h)
    }
}

/// `p(r) = (E1*/pi) [phi(a)/sqrt(a^2 - r^2) - Integral_r^a phi'(t)/sqrt(t^2 - r^2) dt]`
/// for `phi(x) = depth psi1(x/a) - (a^2/R) psi2(x/a)`, with the tail integral
/// taken over `v = sqrt(t^2 - r^2)`, which removes its singularity.
fn pressure_profile(
    contact_modulus: f64,
    solution: &Nystrom,
    radius: f64,
    depth: f64,
    curvature: f64,
    r: f64,
) -> f64 {
    let a = radius;
    let r = r.abs();
    // NaN in, NaN out (the depth too: outside the contact the pressure is
    // 0 whatever it is, but a NaN depth is no depth).
    if r.is_nan() || depth.is_nan() {
        return f64::NAN;
    }
    if r >= a {
        return 0.0;
    }
    let phi = |xi: f64| depth * solution.value(false, xi) - curvature * solution.value(true, xi);
    let phi_slope =
        |xi: f64| (depth * solution.slope(false, xi) - curvature * solution.slope(true, xi)) / a;
    let chord = ((a - r) * (a + r)).sqrt();
    let tail = gauss(32).integrate(0.0, chord, |v| {
        let t = r.hypot(v);
        phi_slope(t / a) / t
    });
    contact_modulus / PI * (phi(1.0) / chord - tail)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Material;

    /// The tabulated kernel slope (derivative of the Chebyshev series) and
    /// the Nystrom interpolant's slope against central differences (step
    /// 1e-6, error ~1e-10 of the values).
    #[test]
    fn slopes_match_finite_differences() {
        let m = Material::new(0.324e6, 0.48).unwrap();
        let exact =
            Axisymmetric::new(&Substrate::layer_on_rigid_base(m, 5e-3).unwrap(), 2.0).unwrap();
        let (_, s) = exact.nystrom(4e-3).unwrap();
        let kernel = s.kernel.as_ref().unwrap();
        let h = 1e-6;
        for y in [0.1, 0.7, 1.3, 2.5] {
            let fd = (kernel.value(y + h) - kernel.value(y - h)) / (2.0 * h);
            assert!((kernel.slope(y) - fd).abs() < 1e-9, "k'({y})");
        }
        for xi in [0.1, 0.5, 0.9] {
            for quadratic in [false, true] {
                let fd = (s.value(quadratic, xi + h) - s.value(quadratic, xi - h)) / (2.0 * h);
                assert!((s.slope(quadratic, xi) - fd).abs() < 1e-9, "psi'({xi})");
            }
        }
    }
}
