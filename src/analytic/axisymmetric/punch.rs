//! The flat cylindrical punch on a coated half-space, bonded: stiffness,
//! edge stress intensity and Kendall's pull-off.

use std::f64::consts::PI;

use super::paraboloid::golden_minimum;
use super::{pressure_profile, Axisymmetric, ContactState, Nystrom, PullOff};
use crate::error::{non_negative_finite, Result};

/// A flat punch on the coated half-space: stiffness, edge stress intensity,
/// JKR (Kendall) pull-off.
///
/// It solves the *bonded* problem: the whole face is held at the punch's
/// displacement, so the pressure may be tensile inside the face (a stiff
/// layer on a much softer base bends, and its middle pulls on the punch).
/// Such a solution holds without adhesion only if the pressure is
/// compressive everywhere: [`minimum_pressure_ratio`](Self::minimum_pressure_ratio)
/// and [`holds_without_adhesion`](Self::holds_without_adhesion) say whether
/// it does; where it does not, a non-adhesive punch lifts off inside and
/// the BEM (which solves that unilateral problem) is rightly softer.
#[derive(Debug, Clone)]
pub struct LayeredFlatPunch {
    pub(super) contact_modulus: f64,
    pub(super) radius: f64,
    pub(super) solution: Nystrom,
}

impl LayeredFlatPunch {
    /// `eps = a/h` (0 on a half-space).
    pub fn eps(&self) -> f64 {
        self.solution.eps
    }

    /// The least pressure over the face divided by the mean pressure
    /// `F / (pi a^2)` (independent of the depth): negative where the bonded
    /// solution pulls on the punch. Sampled at 400 radii over `[0, 0.999 a]`
    /// (near the edge the pressure grows like `1/sqrt(a - r)`, so the
    /// minimum lies inside).
    pub fn minimum_pressure_ratio(&self) -> f64 {
        let depth = 1.0;
        let mean = self.stiffness() * depth / (PI * self.radius * self.radius);
        (0..400)
            .map(|k| self.pressure(depth, 0.999 * self.radius * k as f64 / 399.0))
            .fold(f64::INFINITY, f64::min)
            / mean
    }

    /// Whether the bonded solution is compressive over the whole face, so
    /// that it is also the solution without adhesion.
    pub fn holds_without_adhesion(&self) -> bool {
        self.minimum_pressure_ratio() >= 0.0
    }

    /// The stiffness `K = 2 a E1* Integral_0^1 psi`, N/m.
    pub fn stiffness(&self) -> f64 {
        2.0 * self.radius * self.contact_modulus * self.ratio()
    }

    /// `K / (2 a E1*)`.
    pub fn ratio(&self) -> f64 {
        self.solution.integral(false)
    }

    /// The edge factor `psi(1)`: the stress intensity relative to the
    /// half-space punch at the same depth.
    pub fn edge_factor(&self) -> f64 {
        self.solution.edge(false)
    }

    /// The Nystrom order used.
    pub fn order(&self) -> usize {
        self.solution.nodes.len()
    }

    /// The relative change of the results at the last doubling of the order.
    pub fn convergence(&self) -> f64 {
        self.solution.change
    }

    /// The stress intensity factor at the rim, `K_I = -E1* d psi(1) / sqrt(pi a)`
    /// (Pa m^(1/2), positive in tension).
    pub fn stress_intensity_factor(&self, depth: f64) -> f64 {
        -self.contact_modulus * depth * self.edge_factor() / (PI * self.radius).sqrt()
    }

    /// The energy release rate `G = K_I^2 / (2 E1*) = E1* d^2 psi(1)^2 / (2 pi a)`, J/m^2.
    pub fn energy_release_rate(&self, depth: f64) -> f64 {
        self.stress_intensity_factor(depth).powi(2) / (2.0 * self.contact_modulus)
    }

    /// How much the bonded stiffness changes with the contact at the face,
    /// `(A / k) dk/dA` (`A = pi a^2`): `dk/dA = 2 G / d^2` (the release rate
    /// of the rim held at depth `d`), so `2 pi a^2 G(1) / k`. 0.5 on a
    /// half-space (`k = 2 a E*`, `G(1) = E* / (2 pi a)`); near 0 on a stiff
    /// plate over a far softer base, whose stiffness the base sets.
    ///
    /// ```
    /// use layered_contact::analytic::Axisymmetric;
    /// use layered_contact::{Material, Substrate};
    ///
    /// let body = Substrate::half_space(Material::new(1e6, 0.5)?);
    /// let punch = Axisymmetric::new(&body, 1.0)?.flat_punch(1e-3)?;
    /// assert!((punch.area_slope() - 0.5).abs() < 1e-12);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn area_slope(&self) -> f64 {
        2.0 * PI * self.radius * self.radius * self.energy_release_rate(1.0) / self.stiffness()
    }

    /// The depth at which a punch stuck with `work_of_adhesion` detaches,
    /// `-sqrt(2 pi a dgamma / E1*) / psi(1)`, m.
    pub fn critical_depth(&self, work_of_adhesion: f64) -> f64 {
        -(2.0 * PI * self.radius * work_of_adhesion.max(0.0) / self.contact_modulus).sqrt()
            / self.edge_factor()
    }

    /// The force `K d_c` at which the rim lets go, N (negative): the
    /// pull-off of a punch whose contact stays the face until then (load
    /// and displacement control agree). Where the edge then peels inward
    /// stably (a stiff plate over a far softer base), the pull-off comes
    /// later, at a larger force: [`Axisymmetric::punch_pull_off`].
    pub fn pull_off_force(&self, work_of_adhesion: f64) -> f64 {
        self.stiffness() * self.critical_depth(work_of_adhesion)
    }

    /// The pressure at radius `r` under the punch at `depth`, Pa.
    pub fn pressure(&self, depth: f64, r: f64) -> f64 {
        pressure_profile(
            self.contact_modulus,
            &self.solution,
            self.radius,
            depth,
            0.0,
            r,
        )
    }
}

/// Steps (as fractions of the punch's radius) of the scan that follows a
/// bonded punch's edge peeling inward ([`Axisymmetric::punch_pull_off`]):
/// its first rise of the force or depth is then refined by golden
/// sections.
const PEEL_STEP: f64 = 0.02;

/// How far inside the rim (as a fraction of the radius) a force or depth
/// that rises over the scan's first step is read again, to tell a rim that
/// lets go at once (Kendall's disc: both rise) from a least within that
/// step.
const NEAR_RIM: f64 = 1e-4;

impl Axisymmetric {
    /// The pull-off of a flat punch of `radius` (m) bonded with
    /// `work_of_adhesion` (J/m^2), following its edge as it peels inward.
    ///
    /// A bonded punch pulled until its rim's energy release rate reaches
    /// the work of adhesion ([`LayeredFlatPunch::pull_off_force`], Kendall
    /// 1971 on a half-space) detaches at once where the release rate at
    /// fixed load grows as the bonded disc shrinks, as on a half-space
    /// (there `F_c ~ c^(3/2)`). On a layered body it may fall instead: a
    /// stiff plate over a far softer base carries the load by bending, and
    /// a disc of contact `c < a` needs a larger force to peel further. The
    /// edge then recedes stably, each bonded disc `c` at the force
    /// `F_c(c)` and depth `d_c(c)` of a punch of radius `c` (the face
    /// beyond it opens). Under load control the contact comes off at the
    /// first least `F_c` as `c` shrinks from `a`, under displacement
    /// control at the first least `d_c`; where either rises at once, at
    /// the rim (both `PullOff` states then the stuck punch's). Scanned in
    /// steps of 2 % of `a`, the first rise refined by golden sections (to
    /// 4e-9 of a step).
    ///
    /// On the reference sweep's seed 159 (a 0.1 m punch on a 1 kPa layer
    /// 9.6 mm thick over a 724 kPa layer 28.8 mm thick over a base of 0.19
    /// Pa, 100 J/m^2) the rim lets go at -48.86 N and the least force is
    /// -56.47 N at `c = 0.71 a` (`tests/punch_peeling.rs`).
    ///
    /// ```
    /// use layered_contact::analytic::{Axisymmetric, JkrFlatPunch};
    /// use layered_contact::{Material, Substrate};
    ///
    /// // On a half-space the rim lets go at once: Kendall's pull-off.
    /// let rubber = Material::new(1e6, 0.5)?;
    /// let half = Axisymmetric::new(&Substrate::half_space(rubber), 1.0)?;
    /// let pull_off = half.punch_pull_off(1e-3, 0.05)?;
    /// let kendall = JkrFlatPunch::new(&rubber, 1e-3, 0.05)?.pull_off_force();
    /// assert!((pull_off.load_control.force / kendall - 1.0).abs() < 1e-12);
    /// assert_eq!(pull_off.load_control.contact_radius, 1e-3);
    /// # Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Axisymmetric::flat_punch`] at `radius` or a smaller one;
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) for a
    /// negative or non-finite work of adhesion.
    pub fn punch_pull_off(&self, radius: f64, work_of_adhesion: f64) -> Result<PullOff> {
        let work = non_negative_finite("work of adhesion", work_of_adhesion)?;
        let state = |c: f64| -> Result<ContactState> {
            let punch = self.flat_punch(c)?;
            Ok(ContactState {
                contact_radius: punch.radius,
                depth: punch.critical_depth(work),
                force: punch.pull_off_force(work),
                eps: punch.eps(),
            })
        };
        let rim = state(radius)?;
        let first_least = |key: fn(&ContactState) -> f64| -> Result<ContactState> {
            let (mut above, mut at) = (rim, rim);
            for k in 1..(1.0 / PEEL_STEP) as usize {
                let next = state(radius * (1.0 - k as f64 * PEEL_STEP))?;
                if key(&next) >= key(&at) {
                    if at.contact_radius == radius {
                        // Rising at once: the rim's state, unless it falls
                        // just inside the rim (then the least lies within
                        // the first step).
                        let near = state(radius * (1.0 - NEAR_RIM))?;
                        if key(&near) >= key(&rim) {
                            return Ok(rim);
                        }
                        return golden_minimum((next.contact_radius, radius), state, key);
                    }
                    return golden_minimum((next.contact_radius, above.contact_radius), state, key);
                }
                (above, at) = (at, next);
            }
            Ok(at)
        };
        Ok(PullOff {
            load_control: first_least(|s| s.force)?,
            displacement_control: first_least(|s| s.depth)?,
        })
    }
}
