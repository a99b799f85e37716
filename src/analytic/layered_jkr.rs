//! The exact layered JKR paraboloid and tips (the sphere) as functions of
//! depth and of force, and the paraboloid's loading and unloading curve
//! with adhesion hysteresis.

use super::axisymmetric::{ContactState, LayeredParaboloid, LayeredTip, Tip};
use std::f64::consts::PI;

use crate::error::{Error, Result};

/// Bisection steps on the contact radius: the bracket shrinks by `2^-50`.
const BISECTIONS: usize = 50;
/// Doublings of the upper bracket before giving up (a contact `2^40` times
/// the pull-off radius lies far outside any tabulated range).
const MAX_DOUBLINGS: usize = 40;

/// What the search for a stable equilibrium needs of an exact tip on the
/// coated half-space (the paraboloid, the sphere).
trait Branch {
    /// The equilibrium at contact radius `a` (m).
    fn state(&self, a: f64) -> Result<ContactState>;
    /// A contact radius of the order of the one at `target` (m): the
    /// search's first bracket, doubled or walked down from.
    fn scale(&self, target: f64, by_force: bool) -> f64;
    /// The work of adhesion, J/m^2.
    fn work(&self) -> f64;
    /// The largest contact radius of the solution (m), and whether the
    /// tip's own shape (a spherical cap) sets it rather than the table.
    fn limit(&self) -> (f64, bool);
    /// The smallest contact radius a pull-off is sought at (m; 0 without
    /// adhesion).
    fn pull_off_low(&self) -> f64;
    /// The pull-off state under load (`by_force`) or displacement control.
    fn least(&self, by_force: bool) -> Result<ContactState>;
}

impl Branch for LayeredParaboloid {
    fn state(&self, a: f64) -> Result<ContactState> {
        self.at_contact_radius(a)
    }
    fn scale(&self, target: f64, _by_force: bool) -> f64 {
        (self.sphere_radius * target.abs()).sqrt()
    }
    fn work(&self) -> f64 {
        self.work_of_adhesion
    }
    fn limit(&self) -> (f64, bool) {
        (self.body.max_contact_radius(), false)
    }
    fn pull_off_low(&self) -> f64 {
        self.pull_off_range().0
    }
    fn least(&self, by_force: bool) -> Result<ContactState> {
        if by_force {
            self.load_controlled_pull_off()
        } else {
            Ok(self.pull_off()?.displacement_control)
        }
    }
}

impl Branch for LayeredTip {
    fn state(&self, a: f64) -> Result<ContactState> {
        self.at_contact_radius(a)
    }
    fn scale(&self, target: f64, by_force: bool) -> f64 {
        let t = target.abs();
        // Sneddon's cone: `a = 2 d tan(theta) / pi`, `F = (pi/2) E* a^2
        // cot(theta)`; the sphere's apex as the paraboloid's.
        let cone = |theta: f64| {
            if by_force {
                (2.0 * t * theta.tan() / (PI * self.body.contact_modulus)).sqrt()
            } else {
                2.0 * t * theta.tan() / PI
            }
        };
        match self.tip {
            Tip::Paraboloid { radius } | Tip::Sphere { radius } => (radius * t).sqrt(),
            Tip::Cone { half_angle } => cone(half_angle),
            Tip::RoundedCone {
                half_angle,
                tip_radius,
            } => (tip_radius * t).sqrt().min(cone(half_angle)),
        }
    }
    fn work(&self) -> f64 {
        self.work_of_adhesion
    }
    fn limit(&self) -> (f64, bool) {
        let (table, cap) = (
            self.body.max_contact_radius(),
            self.tip.max_contact_radius(),
        );
        (table.min(cap), cap < table)
    }
    fn pull_off_low(&self) -> f64 {
        if self.work_of_adhesion > 0.0 {
            self.tip
                .pull_off_radii(self.work_of_adhesion, self.body.contact_modulus)
                .0
        } else {
            0.0
        }
    }
    fn least(&self, by_force: bool) -> Result<ContactState> {
        if by_force {
            self.load_controlled_pull_off()
        } else {
            Ok(self.pull_off()?.displacement_control)
        }
    }
}

/// The stable equilibrium of `tip` at `target` depth or force: the root of
/// `key(a) = target` of largest radius, on the branch where `key` grows
/// with `a`; `None` below the branch's least value (no adhesive
/// equilibrium: the contact has come off). Walks down from a radius where
/// `key >= target` in steps of 10 % until `key < target`, then bisects; if
/// the walk passes the branch's minimum first, the minimum (golden
/// section) decides.
fn stable_root(tip: &impl Branch, target: f64, by_force: bool) -> Result<Option<ContactState>> {
    crate::solver::check_finite(if by_force { "force" } else { "depth" }, target)?;
    let key = |a: f64| -> Result<f64> {
        let s = tip.state(a)?;
        Ok(if by_force { s.force } else { s.depth })
    };
    let (limit, capped) = tip.limit();
    let scale = tip.scale(target, by_force).min(limit);
    let lo_range = tip.pull_off_low();
    // An upper bracket: key(hi) >= target.
    let mut hi = scale.max(lo_range).max(f64::MIN_POSITIVE.sqrt());
    let mut doublings = 0;
    while key(hi)? < target {
        if hi >= limit || doublings == MAX_DOUBLINGS {
            return Err(Error::InvalidParameter {
                name: if by_force { "force" } else { "depth" },
                value: target,
                expected: if capped {
                    "reached by a contact within 0.95 of the sphere's radius \
                     (the cap's slope grows without bound at the equator)"
                } else {
                    "reached within the tabulated contact radii \
                     (build Axisymmetric with a larger max_radius_over_thickness)"
                },
            });
        }
        hi = (2.0 * hi).min(limit);
        doublings += 1;
    }
    // Walk down to a lower bracket; without adhesion the branch falls to
    // 0 with the radius, so a walk past `1e-9` of the start has met no
    // root (a target at or below 0).
    let floor = if lo_range > 0.0 {
        lo_range.min(hi) * 1e-3
    } else {
        hi * 1e-9
    };
    let (mut previous, mut lo) = (key(hi)?, hi);
    // Whether a sample has come out below the one before it (the walk is on
    // a part of the branch that rises with the radius), and the sample at
    // which the walk first met one above the one before it while none had
    // (a part that falls with the radius: beyond a local maximum, as a
    // film's on a far softer base, whose own JKR branch falls far beyond
    // the film's; or past the minimum in the first step).
    let (mut fell, mut rise_start) = (false, None);
    loop {
        let next = 0.9 * lo;
        let value = key(next)?;
        if value < target {
            hi = lo;
            lo = next;
            break;
        }
        if (value > previous && fell) || next < floor {
            // Passed the minimum (or ran out of branch) above the target.
            if tip.work() == 0.0 {
                return Ok(None);
            }
            let least = tip.least(by_force)?;
            if target < if by_force { least.force } else { least.depth } {
                return Ok(None);
            }
            // The minimum dips below the target between samples: bracket
            // between it and the last sample above it on the rising part.
            hi = if fell { lo } else { rise_start.unwrap_or(lo) };
            lo = least.contact_radius;
            break;
        }
        if value > previous && rise_start.is_none() {
            rise_start = Some(lo);
        }
        fell |= value < previous;
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
    tip.state(hi).map(Some)
}

impl LayeredParaboloid {
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
        stable_root(self, depth, false)
    }

    /// The stable equilibrium under force `force` (N, negative pulls) under
    /// load control: the largest-radius JKR state, `None` below the pull-off
    /// force.
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn at_force(&self, force: f64) -> Result<Option<ContactState>> {
        stable_root(self, force, true)
    }
}

impl LayeredTip {
    /// The stable equilibrium at `depth` (m) under displacement control,
    /// as [`LayeredParaboloid::at_depth`]: the largest-radius state, `None`
    /// below the depth at which the contact jumps off (or at `depth <= 0`
    /// without adhesion).
    ///
    /// ```
    /// use layered_contact::analytic::{Axisymmetric, Tip};
    /// use layered_contact::{Material, Substrate};
    ///
    /// let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.45)?, 1e-3)?;
    /// let exact = Axisymmetric::new(&film, 4.0)?;
    /// let ball = exact.tip(Tip::Sphere { radius: 5e-3 }, 0.05)?;
    /// let state = ball.at_depth(2e-4)?.unwrap();
    /// assert!((state.depth - 2e-4).abs() < 1e-15);
    /// // The sphere is blunter than its paraboloid: less force at one depth.
    /// let paraboloid = exact.paraboloid(5e-3, 0.05)?.at_depth(2e-4)?.unwrap();
    /// assert!(state.force < paraboloid.force);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth, one whose
    /// contact lies beyond the tabulated range or beyond 0.95 of a
    /// sphere's radius; others as [`at_contact_radius`](Self::at_contact_radius).
    pub fn at_depth(&self, depth: f64) -> Result<Option<ContactState>> {
        stable_root(self, depth, false)
    }

    /// The stable equilibrium under force `force` (N, negative pulls)
    /// under load control, `None` below the pull-off force.
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn at_force(&self, force: f64) -> Result<Option<ContactState>> {
        stable_root(self, force, true)
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
