//! The exact layered JKR paraboloid as a function of depth and of force, and
//! its loading and unloading curve with adhesion hysteresis.

use super::axisymmetric::{ContactState, LayeredParaboloid};
use crate::error::{Error, Result};

/// Bisection steps on the contact radius: the bracket shrinks by `2^-50`.
const BISECTIONS: usize = 50;
/// Doublings of the upper bracket before giving up (a contact `2^40` times
/// the pull-off radius lies far outside any tabulated range).
const MAX_DOUBLINGS: usize = 40;

impl LayeredParaboloid {
    /// The stable equilibrium at `target` depth or force: the root of
    /// `key(a) = target` of largest radius, on the branch where `key` grows
    /// with `a`; `None` below the branch's least value (no adhesive
    /// equilibrium: the contact has come off). Walks down from a radius
    /// where `key >= target` in steps of 10 % until `key < target`, then
    /// bisects; if the walk passes the branch's minimum first, the minimum
    /// (golden section) decides.
    fn stable_root(&self, target: f64, by_force: bool) -> Result<Option<ContactState>> {
        let key = |a: f64| -> Result<f64> {
            let s = self.at_contact_radius(a)?;
            Ok(if by_force { s.force } else { s.depth })
        };
        let limit = self.body.max_contact_radius();
        let scale = (self.sphere_radius * target.abs().max(f64::MIN_POSITIVE))
            .sqrt()
            .min(limit);
        let (lo_range, _) = self.pull_off_range();
        // An upper bracket: key(hi) >= target.
        let mut hi = scale.max(lo_range);
        let mut doublings = 0;
        while key(hi)? < target {
            if hi >= limit || doublings == MAX_DOUBLINGS {
                return Err(Error::InvalidParameter {
                    name: if by_force { "force" } else { "depth" },
                    value: target,
                    expected: "reached within the tabulated contact radii \
                               (build Axisymmetric with a larger max_radius_over_thickness)",
                });
            }
            hi = (2.0 * hi).min(limit);
            doublings += 1;
        }
        // Walk down to a lower bracket.
        let floor = lo_range.min(hi) * 1e-3;
        let (mut previous, mut lo) = (key(hi)?, hi);
        loop {
            let next = 0.9 * lo;
            let value = key(next)?;
            if value < target {
                hi = lo;
                lo = next;
                break;
            }
            if value > previous || next < floor {
                // Passed the minimum (or ran out of branch) above the target.
                if self.work_of_adhesion == 0.0 {
                    return Ok(None);
                }
                let least = if by_force {
                    self.load_controlled_pull_off()?.force
                } else {
                    self.pull_off()?.displacement_control.depth
                };
                if target < least {
                    return Ok(None);
                }
                // The minimum dips below the target between samples: bracket
                // between it and the last sample above.
                let pull_off = self.pull_off()?;
                let at = if by_force {
                    pull_off.load_control
                } else {
                    pull_off.displacement_control
                };
                hi = lo;
                lo = at.contact_radius;
                break;
            }
            previous = value;
            lo = next;
        }
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if key(mid)? < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        self.at_contact_radius(hi).map(Some)
    }

    /// The stable equilibrium at `depth` (m) under displacement control: the
    /// largest-radius JKR state, `None` below the depth at which the contact
    /// jumps off.
    ///
    /// ```
    /// use layered_contact::analytic::Axisymmetric;
    /// use layered_contact::{Material, Substrate};
    ///
    /// let film = Substrate::layer_on_rigid_base(Material::new(0.324e6, 0.48)?, 5e-3)?;
    /// let exact = Axisymmetric::new(&film, 2.0)?;
    /// let ball = exact.paraboloid(0.05, 0.326)?;
    /// let state = ball.at_depth(1e-4)?.unwrap();
    /// assert!((state.depth - 1e-4).abs() < 1e-15);
    /// assert!((ball.at_contact_radius(state.contact_radius)?.force - state.force).abs() < 1e-12);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth or one whose
    /// contact lies beyond the tabulated range; others as
    /// [`at_contact_radius`](Self::at_contact_radius).
    pub fn at_depth(&self, depth: f64) -> Result<Option<ContactState>> {
        crate::solver::check_finite("depth", depth)?;
        self.stable_root(depth, false)
    }

    /// The stable equilibrium under force `force` (N, negative pulls) under
    /// load control: the largest-radius JKR state, `None` below the pull-off
    /// force.
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn at_force(&self, force: f64) -> Result<Option<ContactState>> {
        crate::solver::check_finite("force", force)?;
        self.stable_root(force, true)
    }
}

/// The exact displacement-controlled loading and unloading of a paraboloid
/// on a coated half-space with adhesion hysteresis: the contact edge advances
/// against the advancing work of adhesion `dgamma0` while the indenter goes
/// in, stays pinned when it starts to retract, and recedes against the
/// receding work `dgamma1 >= dgamma0` once the energy release rate reaches
/// it (Johnson, Kendall & Roberts 1971; hysteresis as in Maugis 2000, ch. 5).
///
/// ```
/// use layered_contact::analytic::{Axisymmetric, LayeredJkrCycle};
/// use layered_contact::{Material, Substrate};
///
/// let film = Substrate::layer_on_rigid_base(Material::new(0.324e6, 0.48)?, 5e-3)?;
/// let exact = Axisymmetric::new(&film, 2.0)?;
/// let cycle = LayeredJkrCycle::new(&exact, 0.05, 0.0175, 0.326, 2e-4)?;
/// let peak = cycle.loading(2e-4)?.unwrap();
/// // Unloading starts pinned at the peak's contact radius...
/// let pinned = cycle.unloading(1.9e-4)?.unwrap();
/// assert_eq!(pinned.contact_radius, peak.contact_radius);
/// // ...and the least force on the way out is the receding pull-off force.
/// let least = cycle.unloading_pull_off()?;
/// assert!(least.force < 0.0);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct LayeredJkrCycle {
    advancing: LayeredParaboloid,
    receding: LayeredParaboloid,
    peak: ContactState,
}

impl LayeredJkrCycle {
    /// The cycle of a paraboloid of tip radius `sphere_radius` (m) pressed
    /// to `max_depth` (m) and pulled off, with advancing and receding works
    /// of adhesion (J/m^2).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for invalid radii or works, an advancing
    /// work above the receding one, a non-positive maximum depth, or a peak
    /// contact beyond the tabulated range.
    pub fn new(
        body: &super::Axisymmetric,
        sphere_radius: f64,
        advancing: f64,
        receding: f64,
        max_depth: f64,
    ) -> Result<Self> {
        let max_depth = crate::error::positive_finite("max_depth", max_depth)?;
        let (advancing, receding) = crate::error::works_of_adhesion(advancing, receding)?;
        let advancing = body.paraboloid(sphere_radius, advancing)?;
        let receding = body.paraboloid(sphere_radius, receding)?;
        let peak = advancing.at_depth(max_depth)?.ok_or(Error::Internal {
            what: "layered JKR cycle",
            detail: "no loading equilibrium at a positive depth".into(),
        })?;
        Ok(LayeredJkrCycle {
            advancing,
            receding,
            peak,
        })
    }

    /// The state at the deepest point.
    pub fn peak(&self) -> ContactState {
        self.peak
    }

    /// The loading branch at `depth` (m): `None` before first contact
    /// (`depth < 0`); at `depth >= 0` the contact has jumped in and grows
    /// against the advancing work of adhesion.
    ///
    /// # Errors
    /// As [`LayeredParaboloid::at_depth`].
    pub fn loading(&self, depth: f64) -> Result<Option<ContactState>> {
        crate::solver::check_finite("depth", depth)?;
        if depth < 0.0 {
            return Ok(None);
        }
        self.advancing.at_depth(depth)
    }

    /// The unloading branch at `depth <= max_depth` (m): pinned at the
    /// peak's contact radius until the energy release rate reaches the
    /// receding work of adhesion, then receding; `None` once the contact has
    /// jumped off.
    ///
    /// # Errors
    /// As [`LayeredParaboloid::at_depth`].
    pub fn unloading(&self, depth: f64) -> Result<Option<ContactState>> {
        crate::solver::check_finite("depth", depth)?;
        let a = self.peak.contact_radius;
        let release = self.receding.at_contact_radius(a)?;
        if depth >= release.depth {
            return self.receding.pinned(a, depth).map(Some);
        }
        self.receding.at_depth(depth)
    }

    /// The least force of the unloading branch (displacement control): the
    /// load-controlled pull-off of the receding work if its contact is
    /// smaller than the peak's, else the pinned contact at its release.
    ///
    /// # Errors
    /// As [`LayeredParaboloid::pull_off`].
    pub fn unloading_pull_off(&self) -> Result<ContactState> {
        let pull_off = self.receding.pull_off()?.load_control;
        if pull_off.contact_radius <= self.peak.contact_radius {
            Ok(pull_off)
        } else {
            self.receding.at_contact_radius(self.peak.contact_radius)
        }
    }
}
