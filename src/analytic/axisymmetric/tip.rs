//! Any axisymmetric tip on the coated half-space: the sphere (not only its
//! paraboloid), the cone and the cone with a rounded apex, through the
//! equivalent profile `g` of the Fredholm equation (the method of
//! dimensionality reduction's, Popov & Hess 2015).
//!
//! With `psi_1` the flat punch's solution and `psi_g` the solution for the
//! right-hand side `g(a xi)`, the auxiliary function is
//! `phi = d psi_1 - psi_g`; the edge condition `phi(1) = -sqrt(2 pi a
//! dgamma / E1*)` (0 without adhesion) gives the depth and
//! `F = 2 E1* a (d Integral psi_1 - Integral psi_g)` the force. A kink of
//! `g` (where the rounded cone's sphere meets its cone) would slow the
//! Nystrom rule to algebraic convergence, so `psi_g = g + chi` is split and
//! only the smooth `chi = (I - K)^-1 K g` is discretised; `K g` is
//! integrated piecewise between the kinks.

use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::OnceLock;

use gauss_quad::legendre::GaussLegendre;

use super::{gauss, minimise, Axisymmetric, ContactState, CosineKernel, Nystrom, PullOff};
use crate::analytic::layered_jkr::first_rise;
use crate::error::{non_negative_finite, positive_finite, Error, Result};

/// Points of the piecewise Gauss-Legendre rule for `K g` and `Integral g`
/// per piece (the integrands are smooth within a piece).
const PIECE_ORDER: usize = 64;
/// The piecewise rule, built once.
pub(super) fn piece_rule() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| gauss(PIECE_ORDER))
}

/// Relative step of the central differences of the spring criteria.
const SLOPE_STEP: f64 = 1e-5;

/// The bracket about the golden sections' least `Z` (relative) that
/// [`LayeredTip::spring_pull_off`] bisects on the slope's sign: wide
/// against the sections' `4e-9` of their bracket, narrow against the
/// distance between two local minima of a folding branch.
const SPRING_BRACKET: f64 = 1e-3;

/// The boundary in `[lo, hi]` between radii where `below` holds (at `lo`)
/// and where it does not (at `hi`), by 60 bisections (1e-18 of the bracket).
fn bisect(mut lo: f64, mut hi: f64, below: impl Fn(f64) -> Result<bool>) -> Result<f64> {
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if below(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// The largest contact radius of a spherical cap, in radii: the profile's
/// slope grows without bound at the equator.
const MAX_CAP: f64 = 0.95;

/// A rigid axisymmetric tip.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Tip {
    /// `f = r^2 / (2R)`, tip radius `radius` (m).
    Paraboloid {
        /// Tip radius `R`, m.
        radius: f64,
    },
    /// A sphere of radius `radius` (m): `f = R - sqrt(R^2 - r^2)`; its
    /// contact radius stays below `0.95 R`.
    Sphere {
        /// Sphere radius `R`, m.
        radius: f64,
    },
    /// A cone of half-angle `half_angle` (rad, between axis and face, in
    /// `(0, pi/2)`): `f = r cot(theta)`.
    Cone {
        /// Half-angle `theta`, rad.
        half_angle: f64,
    },
    /// A cone of half-angle `half_angle` (rad) whose apex is a sphere of
    /// radius `tip_radius` (m), tangent to it at `b = R cos(theta)`: a
    /// worn pyramidal AFM tip (Briscoe, Sebastian & Adams 1994).
    RoundedCone {
        /// Half-angle `theta`, rad.
        half_angle: f64,
        /// Apex radius `R`, m.
        tip_radius: f64,
    },
}

impl Tip {
    pub(super) fn validated(self) -> Result<Self> {
        let angle = |theta: f64| {
            if theta > 0.0 && theta < FRAC_PI_2 {
                Ok(theta)
            } else {
                Err(Error::InvalidParameter {
                    name: "half_angle",
                    value: theta,
                    expected: "between 0 and pi/2 (rad, between the axis and the face)",
                })
            }
        };
        Ok(match self {
            Tip::Paraboloid { radius } => Tip::Paraboloid {
                radius: positive_finite("radius", radius)?,
            },
            Tip::Sphere { radius } => Tip::Sphere {
                radius: positive_finite("radius", radius)?,
            },
            Tip::Cone { half_angle } => Tip::Cone {
                half_angle: angle(half_angle)?,
            },
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => Tip::RoundedCone {
                half_angle: angle(half_angle)?,
                tip_radius: positive_finite("tip_radius", tip_radius)?,
            },
        })
    }

    /// The height `f(r)` of the tip above its apex at radius `r`, m.
    pub fn height(&self, r: f64) -> f64 {
        let r = r.abs();
        match *self {
            Tip::Paraboloid { radius } => r * r / (2.0 * radius),
            Tip::Sphere { radius } => sphere_height(radius, r),
            Tip::Cone { half_angle } => r / half_angle.tan(),
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => {
                let b = tip_radius * half_angle.cos();
                if r <= b {
                    sphere_height(tip_radius, r)
                } else {
                    sphere_height(tip_radius, b) + (r - b) / half_angle.tan()
                }
            }
        }
    }

    /// The equivalent profile `g(x) = x Integral_0^x f'(r) / sqrt(x^2 - r^2) dr`
    /// (m): `x^2/R` for the paraboloid, `(x/2) ln((R + x)/(R - x))` for the
    /// sphere (Sneddon 1965), `(pi/2) x cot(theta)` for the cone, and for the
    /// rounded cone the sphere's inside `b` and, beyond, the sphere's part
    /// `x Integral_0^asin(b/x) f_s'(x sin t) dt` (Gauss-Legendre) plus the
    /// cone's `x cot(theta) (pi/2 - asin(b/x))`.
    pub fn equivalent_profile(&self, x: f64) -> f64 {
        let x = x.abs();
        match *self {
            Tip::Paraboloid { radius } => x * x / radius,
            Tip::Sphere { radius } => sphere_equivalent(radius, x),
            Tip::Cone { half_angle } => FRAC_PI_2 * x / half_angle.tan(),
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => {
                let b = tip_radius * half_angle.cos();
                if x <= b {
                    return sphere_equivalent(tip_radius, x);
                }
                let edge = (b / x).asin();
                let slope = |r: f64| r / (tip_radius * tip_radius - r * r).sqrt();
                let sphere = piece_rule().integrate(0.0, edge, |t| slope(x * t.sin()));
                x * sphere + x / half_angle.tan() * (FRAC_PI_2 - edge)
            }
        }
    }

    /// The largest contact radius the tip admits, m: `0.95 R` for a
    /// spherical cap (its slope grows without bound at the equator),
    /// unbounded otherwise.
    pub(in crate::analytic) fn max_contact_radius(&self) -> f64 {
        match *self {
            Tip::Sphere { radius } => MAX_CAP * radius,
            _ => f64::INFINITY,
        }
    }

    /// Where `g` has a kink (the rounded cone's `b`), m.
    pub(super) fn kink(&self) -> Option<f64> {
        match *self {
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => Some(tip_radius * half_angle.cos()),
            _ => None,
        }
    }

    /// The contact radii (m) a pull-off with work of adhesion `work`
    /// (J/m^2) on a surface of contact modulus `modulus` (Pa) is sought in:
    /// around the JKR radius of the tip's apex (paraboloid, sphere) or the
    /// cone's length `dgamma / (E* cot^2 theta)`. Build the
    /// [`Axisymmetric`] solutions up to the upper end
    /// ([`Axisymmetric::up_to_contact_radius`]) before asking a
    /// [`LayeredTip`] for its pull-off.
    pub fn pull_off_radii(&self, work: f64, modulus: f64) -> (f64, f64) {
        let ball = |r: f64| (9.0 * PI * work * r * r / (8.0 * modulus)).cbrt();
        let cone = |theta: f64| work * theta.tan().powi(2) / modulus;
        match *self {
            Tip::Paraboloid { radius } => (ball(radius) / 100.0, 10.0 * ball(radius)),
            Tip::Sphere { radius } => (ball(radius) / 100.0, self.max_contact_radius()),
            Tip::Cone { half_angle } => (cone(half_angle) / 100.0, 100.0 * cone(half_angle)),
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => {
                let (s, c) = (ball(tip_radius), cone(half_angle));
                (s.min(c) / 100.0, 100.0 * s.max(c))
            }
        }
    }
}

fn sphere_height(radius: f64, r: f64) -> f64 {
    // R - sqrt(R^2 - r^2) without cancellation.
    r * r / (radius + (radius * radius - r * r).sqrt())
}

fn sphere_equivalent(radius: f64, x: f64) -> f64 {
    // (x/2) ln((R + x)/(R - x)) = x atanh(x/R).
    x * (x / radius).atanh()
}

/// A tip on the coated half-space, as functions of the contact radius.
#[derive(Debug, Clone)]
pub struct LayeredTip {
    pub(in crate::analytic) body: Axisymmetric,
    pub(in crate::analytic) tip: Tip,
    pub(in crate::analytic) work_of_adhesion: f64,
}

/// The four numbers a contact radius needs: `Integral psi_1`, `psi_1(1)`,
/// `Integral psi_g` (m) and `psi_g(1)` (m).
#[derive(Debug, Clone, Copy)]
pub(super) struct Solved {
    pub(super) eps: f64,
    pub(super) unit: [f64; 2],
    pub(super) profile: [f64; 2],
}

/// The solutions behind [`Solved`]: `psi_1` (and for a paraboloid its
/// quadratic `psi_2`, `psi_g = (a^2/R) psi_2`) and for other tips `chi`
/// (`psi_g = g + chi`, `chi = K g + K chi`) with the piecewise rule's nodes
/// and weights times `g`, from which `K g` is summed.
pub(super) struct TipFunctions {
    pub(super) solution: Nystrom,
    pub(super) weighted: Vec<(f64, f64)>,
}

impl Axisymmetric {
    /// The rigid `tip` with work of adhesion `work_of_adhesion` (J/m^2; 0
    /// for non-adhesive): the paraboloid of [`paraboloid`](Self::paraboloid)
    /// and the sphere, cone and rounded cone.
    ///
    /// ```
    /// use layered_contact::analytic::{Axisymmetric, SneddonCone, Tip};
    /// use layered_contact::{Material, Substrate};
    ///
    /// let rubber = Material::new(1e6, 0.5)?;
    /// let theta = 70f64.to_radians();
    /// // On a half-space, Sneddon's cone.
    /// let half = Axisymmetric::new(&Substrate::half_space(rubber), 1.0)?;
    /// let state = half.tip(Tip::Cone { half_angle: theta }, 0.0)?.at_contact_radius(1e-6)?;
    /// let sneddon = SneddonCone::new(&rubber, theta)?;
    /// assert!((state.force / sneddon.force(state.depth) - 1.0).abs() < 1e-12);
    /// // On a film of 2 um on glass, stiffer.
    /// let film = Axisymmetric::new(&Substrate::layer_on_rigid_base(rubber, 2e-6)?, 2.0)?;
    /// let coated = film.tip(Tip::Cone { half_angle: theta }, 0.0)?.at_contact_radius(1e-6)?;
    /// assert!(coated.force / sneddon.force(coated.depth) > 1.3);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-positive or non-finite size, a
    /// half-angle outside `(0, pi/2)` or a negative work of adhesion.
    pub fn tip(&self, tip: Tip, work_of_adhesion: f64) -> Result<LayeredTip> {
        Ok(LayeredTip {
            body: self.clone(),
            tip: tip.validated()?,
            work_of_adhesion: non_negative_finite("work_of_adhesion", work_of_adhesion)?,
        })
    }
}

impl LayeredTip {
    /// The tip.
    pub fn tip(&self) -> Tip {
        self.tip
    }

    fn solved(&self, contact_radius: f64) -> Result<Solved> {
        Ok(self.solved_with_functions(contact_radius)?.0)
    }

    /// [`LayeredTip::solved`] and the solutions themselves
    /// ([`TipFunctions`]), for the pressure profile.
    pub(super) fn solved_with_functions(
        &self,
        contact_radius: f64,
    ) -> Result<(Solved, TipFunctions)> {
        let a = positive_finite("contact_radius", contact_radius)?;
        if let Tip::Sphere { radius } = self.tip {
            if a > self.tip.max_contact_radius() {
                return Err(Error::InvalidParameter {
                    name: "contact_radius / sphere radius",
                    value: a / radius,
                    expected: "at most 0.95 (the cap's slope grows without bound at the equator)",
                });
            }
        }
        if let Tip::Paraboloid { radius } = self.tip {
            // `g(a xi) = (a^2/R) xi^2`: the punch's own quadratic solution,
            // as `LayeredParaboloid` has it (the same values).
            let (_, unit) = self.body.nystrom(a)?;
            let curvature = a * a / radius;
            let solved = Solved {
                eps: unit.eps,
                unit: [unit.integral(false), unit.edge(false)],
                profile: [curvature * unit.integral(true), curvature * unit.edge(true)],
            };
            let functions = TipFunctions {
                solution: unit,
                weighted: Vec::new(),
            };
            return Ok((solved, functions));
        }
        let g = |xi: f64| self.tip.equivalent_profile(a * xi);
        let mut breaks = vec![0.0];
        breaks.extend(self.tip.kink().map(|b| b / a).filter(|&k| k < 1.0));
        breaks.push(1.0);
        // The piecewise rule's nodes and weights times `g`, once: `K g` at
        // every Nystrom node sums over them.
        let rule = piece_rule();
        let weighted: Vec<(f64, f64)> = breaks
            .windows(2)
            .flat_map(|w| {
                let (mid, half) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
                rule.iter()
                    .map(move |(x, weight)| (mid + half * x, half * weight))
                    .collect::<Vec<_>>()
            })
            .map(|(s, weight)| (s, weight * g(s)))
            .collect();
        let integral_g: f64 = weighted.iter().map(|(_, wg)| wg).sum();
        // `chi = K g + K chi` shares the flat punch's factorisations and is
        // converged with its solutions.
        let kg = |kernel: &CosineKernel, eps: f64, xi: f64| -> f64 {
            weighted
                .iter()
                .map(|&(s, wg)| wg * Nystrom::kernel_at(kernel, eps, xi, s))
                .sum()
        };
        // Converged on the scale of the profile's own terms, which `chi`
        // corrects.
        let scale = integral_g.abs() + g(1.0).abs();
        let (_, unit) = self.body.nystrom_with(a, Some((&kg, scale)))?;
        let chi = unit.extra.unwrap_or([0.0, 0.0]);
        let solved = Solved {
            eps: unit.eps,
            unit: [unit.integral(false), unit.edge(false)],
            profile: [integral_g + chi[0], g(1.0) + chi[1]],
        };
        let functions = TipFunctions {
            solution: unit,
            weighted,
        };
        Ok((solved, functions))
    }

    pub(super) fn state_at_depth(&self, a: f64, depth: f64, solved: &Solved) -> ContactState {
        let e = self.body.contact_modulus;
        ContactState {
            contact_radius: a,
            depth,
            force: 2.0 * e * a * (depth * solved.unit[0] - solved.profile[0]),
            eps: solved.eps,
        }
    }

    /// The equilibrium at contact radius `a` (m): JKR if the work of
    /// adhesion is positive, else non-adhesive (`phi(1) = 0`).
    ///
    /// # Errors
    /// As [`Axisymmetric::flat_punch`], and [`Error::InvalidParameter`] for
    /// a spherical cap's contact beyond 0.95 of its radius;
    /// [`Error::NoConvergence`] if the profile's solution does not converge
    /// with the flat punch's (by order 4096).
    pub fn at_contact_radius(&self, contact_radius: f64) -> Result<ContactState> {
        let solved = self.solved(contact_radius)?;
        let depth = self.equilibrium_depth(contact_radius, &solved);
        Ok(self.state_at_depth(contact_radius, depth, &solved))
    }

    /// The depth at which the edge of a contact of radius `a` is in
    /// equilibrium: `phi(1) = -sqrt(2 pi a dgamma / E1*)`.
    pub(super) fn equilibrium_depth(&self, a: f64, solved: &Solved) -> f64 {
        let adhesive = (2.0 * PI * a * self.work_of_adhesion / self.body.contact_modulus).sqrt();
        (solved.profile[1] - adhesive) / solved.unit[1]
    }

    /// The state of a contact of radius `a` (m) held at `depth` (m), as
    /// when adhesion hysteresis pins its edge.
    ///
    /// # Errors
    /// As [`LayeredTip::at_contact_radius`].
    pub fn pinned(&self, contact_radius: f64, depth: f64) -> Result<ContactState> {
        let solved = self.solved(contact_radius)?;
        Ok(self.state_at_depth(contact_radius, depth, &solved))
    }

    /// Equilibria at each of `contact_radii`.
    ///
    /// # Errors
    /// As [`LayeredTip::at_contact_radius`].
    pub fn curve(&self, contact_radii: &[f64]) -> Result<Vec<ContactState>> {
        contact_radii
            .iter()
            .map(|&a| self.at_contact_radius(a))
            .collect()
    }

    /// The pull-off points under load and displacement control (as
    /// [`LayeredParaboloid::pull_off`](super::LayeredParaboloid::pull_off)).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] without adhesion; others as
    /// [`LayeredTip::at_contact_radius`].
    pub fn pull_off(&self) -> Result<PullOff> {
        let (lo, hi) = self.range()?;
        Ok(PullOff {
            load_control: self.load_controlled_pull_off()?,
            displacement_control: minimise(lo, hi, |a| self.at_contact_radius(a), |s| s.depth)?,
        })
    }

    /// The load-controlled half of [`pull_off`](Self::pull_off), at half
    /// the cost (a Nystrom solve for each radius it tries).
    pub(crate) fn load_controlled_pull_off(&self) -> Result<ContactState> {
        let (lo, hi) = self.range()?;
        minimise(lo, hi, |a| self.at_contact_radius(a), |s| s.force)
    }

    /// The pull-off of the tip held by a spring of stiffness `stiffness`
    /// (N/m, an AFM cantilever): with the spring's base at `Z = d + F/k`,
    /// the unloading follows the branch while `Z` falls with the contact
    /// radius (`dF/dd > -k`) and the tip jumps off at the least `Z`, where
    /// `dF/dd = -k`: between the load-controlled pull-off (`k -> 0`) and
    /// the displacement-controlled one (`k -> inf`). The least `Z` over
    /// the radii [`pull_off`](Self::pull_off) searches (a logarithmic scan
    /// and golden sections, as there), its radius then refined by bisection
    /// on central differences of the exact states. Where the branch folds
    /// (a stiff layer over a far softer base) `Z` may have several local
    /// minima, and this is the least of them, as `pull_off`'s are the
    /// least force and depth: a bisection between those two pull-offs'
    /// radii returned, before, a local minimum six times wider whose `Z`
    /// lay 0.27 % above the least (`tests/cantilever_on_folds.rs`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a stiffness that is not positive and
    /// finite, or without adhesion; others as [`LayeredTip::pull_off`].
    pub fn spring_pull_off(&self, stiffness: f64) -> Result<ContactState> {
        let k = positive_finite("stiffness", stiffness)?;
        let (lo, hi) = self.range()?;
        let least = minimise(
            lo,
            hi,
            |a| self.at_contact_radius(a),
            |s| s.depth + s.force / k,
        )?;
        // F'(a) + k d'(a) = k Z'(a): negative inside the least, positive
        // outside it.
        let unstable = |a: f64| -> Result<bool> {
            let h = SLOPE_STEP * a;
            let (minus, plus) = (
                self.at_contact_radius(a - h)?,
                self.at_contact_radius(a + h)?,
            );
            Ok(plus.force - minus.force + k * (plus.depth - minus.depth) < 0.0)
        };
        let a = least.contact_radius;
        let (inside, outside) = (a * (1.0 - SPRING_BRACKET), a * (1.0 + SPRING_BRACKET));
        if outside > hi || !unstable(inside)? || unstable(outside)? {
            // The golden sections' least, where the slope's sign does not
            // bracket it (a minimum flat to the differences' rounding).
            return Ok(least);
        }
        self.at_contact_radius(bisect(inside, outside, unstable)?)
    }

    /// Where the tip lands when a spring of stiffness `stiffness` (N/m)
    /// brings it to touch the surface: the state on the loading branch with
    /// `F + k d = 0` (the cantilever's base at the undeformed surface), the
    /// JKR jump into contact: the first radius, going out from the
    /// smallest a pull-off is sought at, where `F + k d` rises through 0
    /// (as [`LayeredParaboloid::loading_at_depth`](super::LayeredParaboloid::loading_at_depth):
    /// where the branch folds, the loading stops at the first such radius,
    /// not a wider one beyond a fold).
    ///
    /// # Errors
    /// As [`LayeredTip::spring_pull_off`], and [`Error::NoConvergence`] if
    /// no contact radius within the tabulated range balances the spring.
    pub fn spring_jump_in(&self, stiffness: f64) -> Result<ContactState> {
        let k = positive_finite("stiffness", stiffness)?;
        let (start, _) = self.range()?;
        let limit = self
            .body
            .max_contact_radius()
            .min(self.tip.max_contact_radius());
        let spring = |s: &ContactState| s.force + k * s.depth;
        // An adhesive branch starts below the surface with a pull: `F + k
        // d < 0` at the smallest radius a pull-off is sought at.
        if spring(&self.at_contact_radius(start)?) >= 0.0 {
            return Err(Error::Internal {
                what: "spring jump-in",
                detail: format!("the branch balances the spring already at {start:e} m"),
            });
        }
        first_rise(self, spring, 0.0, (start, limit), None)?.ok_or(Error::NoConvergence {
            method: "spring jump-in (no contact radius in range balances the spring)",
            iterations: 0,
            residual: k,
        })
    }

    /// The contact radii a pull-off is sought over (m).
    pub(in crate::analytic) fn range(&self) -> Result<(f64, f64)> {
        crate::error::work_for_pull_off(self.work_of_adhesion)?;
        let (lo, hi) = self
            .tip
            .pull_off_radii(self.work_of_adhesion, self.body.contact_modulus);
        Ok((lo, hi.min(self.body.max_contact_radius())))
    }
}
