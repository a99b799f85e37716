//! The exact layered JKR paraboloid and tips (the sphere) as functions of
//! depth and of force: the stable equilibrium and the loading's state.
//! The paraboloid's cycle with adhesion hysteresis is in
//! [`layered_jkr_cycle`](super::layered_jkr_cycle).

use super::axisymmetric::{golden_minimum, ContactState, LayeredParaboloid, LayeredTip, Tip};
use std::f64::consts::PI;

use crate::error::{Error, Result};

/// Bisection steps on the contact radius: the bracket shrinks by `2^-50`.
const BISECTIONS: usize = 50;
/// Doublings of the upper bracket before giving up (a contact `2^40` times
/// the pull-off radius lies far outside any tabulated range).
const MAX_DOUBLINGS: usize = 40;

/// What the search for a stable equilibrium needs of an exact tip on the
/// coated half-space (the paraboloid, the sphere).
pub(super) trait Branch {
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
    /// The contact radii a pull-off is sought over (m).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] without adhesion.
    fn span(&self) -> Result<(f64, f64)>;
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
    fn span(&self) -> Result<(f64, f64)> {
        crate::error::work_for_pull_off(self.work_of_adhesion)?;
        Ok(self.pull_off_range())
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
    fn span(&self) -> Result<(f64, f64)> {
        self.range()
    }
}

/// The force of `state` (`by_force`) or its depth.
pub(super) fn controlled(state: &ContactState, by_force: bool) -> f64 {
    if by_force {
        state.force
    } else {
        state.depth
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
    let key = |a: f64| tip.state(a).map(|s| controlled(&s, by_force));
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
            if target < controlled(&least, by_force) {
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
    crossing(tip, (lo, hi), &key, target).map(Some)
}

/// The state of `tip` where `key` rises through `target` between radii
/// `lo` (below it) and `hi` (at or above it), by [`BISECTIONS`]
/// bisections.
pub(super) fn crossing(
    tip: &impl Branch,
    (mut lo, mut hi): (f64, f64),
    key: &impl Fn(f64) -> Result<f64>,
    target: f64,
) -> Result<ContactState> {
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if key(mid)? < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    tip.state(hi)
}

/// The factor between the radii at which [`loading_root`] samples its
/// branch.
pub(super) const LOADING_STEP: f64 = 1.15;

/// Where [`loading_root`] starts its scan, as a fraction of the stable
/// root's radius (made smaller, four decades at a time, until the branch
/// there lies below the target).
const LOADING_FLOOR: f64 = 1e-4;

/// The state of `tip` at `target > 0` depth or force that a quasi-static
/// loading from first contact reaches: the first root, going out in `a`,
/// at which `key(a)` rises through `target`. Where `key` falls somewhere
/// with `a` (a stiff layer over a far softer base: the branch has folds)
/// the loading jumps out at each fold and this root may be far smaller
/// than [`stable_root`]'s (a cone on such a stack at 5 mm: 3.0 mm against
/// 25.5 mm). Scans from [`LOADING_FLOOR`] of the stable root's radius in
/// steps of [`LOADING_STEP`], then bisects; where the samples turn down
/// below the target, the maximum between them (golden sections) decides
/// whether the branch rose through it in between (a target within 0.2 %
/// of a fold's depth, whose excursion above it spans 10 % of the radius,
/// was stepped over before). At `target <= 0` the stable root.
fn loading_root(tip: &impl Branch, target: f64, by_force: bool) -> Result<Option<ContactState>> {
    let Some(stable) = stable_root(tip, target, by_force)? else {
        return Ok(None);
    };
    if target <= 0.0 {
        return Ok(Some(stable));
    }
    let key = |a: f64| tip.state(a).map(|s| controlled(&s, by_force));
    let top = stable.contact_radius;
    // A start below the target: the branch goes to 0 with the radius.
    let mut lo = top;
    for _ in 0..4 {
        lo *= LOADING_FLOOR;
        if key(lo)? < target {
            break;
        }
    }
    if key(lo)? >= target {
        return Err(Error::Internal {
            what: "exact loading branch",
            detail: format!("no radius down to {lo:e} m lies below the target {target:e}"),
        });
    }
    first_rise(
        tip,
        |s| controlled(s, by_force),
        target,
        (lo, top),
        Some(stable),
    )
}

/// The first root of `key(state(a)) = target` going out in `a` from
/// `start` (where `key` lies below `target`) to `top`, sampled in steps of
/// [`LOADING_STEP`] (at most `log(top / start) / log(LOADING_STEP)`
/// samples), then bisected. Where no sample below `top` reaches the target,
/// `at_top` if given (the state at `top`, known to lie on the target), else
/// the crossing before `top` if `top` reaches it, else `None`. A local
/// maximum between samples may rise above the target where neither does (a
/// target just below a fold's depth): where the samples turn down, the
/// maximum between the last three is found (golden sections) and, if it
/// reaches the target, the crossing lies below it. No maximum is sought
/// between the start and the first sample (the start lies far below the
/// target; an adhesive branch falls there).
pub(in crate::analytic) fn first_rise(
    tip: &impl Branch,
    key: impl Fn(&ContactState) -> f64,
    target: f64,
    (start, top): (f64, f64),
    at_top: Option<ContactState>,
) -> Result<Option<ContactState>> {
    let at = |a: f64| tip.state(a).map(|s| key(&s));
    let mut lo = start;
    let mut before = (lo, f64::INFINITY);
    let mut last = at(lo)?;
    loop {
        let hi = lo * LOADING_STEP;
        if hi >= top {
            return match at_top {
                Some(state) => Ok(Some(state)),
                None if at(top)? >= target => crossing(tip, (lo, top), &at, target).map(Some),
                None => Ok(None),
            };
        }
        let value = at(hi)?;
        if value >= target {
            return crossing(tip, (lo, hi), &at, target).map(Some);
        }
        if value < last && last > before.1 {
            let peak = golden_minimum((before.0, hi), |a| tip.state(a), |s| -key(s))?;
            if key(&peak) >= target && peak.contact_radius > before.0 {
                return crossing(tip, (before.0, peak.contact_radius), &at, target).map(Some);
            }
        }
        before = (lo, last);
        (lo, last) = (hi, value);
    }
}

impl LayeredParaboloid {
    /// The stable equilibrium at `depth` (m) under displacement control: the
    /// largest-radius JKR state, `None` below the depth at which the contact
    /// jumps off. Where the branch folds, a loading from first contact
    /// stops at a smaller one: [`loading_at_depth`](Self::loading_at_depth).
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

    /// The state that a quasi-static loading from first contact reaches at
    /// `depth > 0` (m): the first equilibrium, going out in contact radius,
    /// at which the depth rises through `depth`. Where the branch folds (a
    /// stiff layer over a far softer base) the loading jumps outward at
    /// each fold and may stop far inside [`at_depth`](Self::at_depth)'s
    /// largest-radius state; elsewhere the two are the same. At
    /// `depth <= 0`, [`at_depth`](Self::at_depth).
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn loading_at_depth(&self, depth: f64) -> Result<Option<ContactState>> {
        loading_root(self, depth, false)
    }

    /// As [`loading_at_depth`](Self::loading_at_depth) under load control
    /// at `force > 0` (N).
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn loading_at_force(&self, force: f64) -> Result<Option<ContactState>> {
        loading_root(self, force, true)
    }
}

impl LayeredTip {
    /// The stable equilibrium at `depth` (m) under displacement control,
    /// as [`LayeredParaboloid::at_depth`]: the largest-radius state, `None`
    /// below the depth at which the contact jumps off (or at `depth <= 0`
    /// without adhesion). Where the branch folds, a loading from first
    /// contact stops at a smaller one:
    /// [`loading_at_depth`](Self::loading_at_depth).
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

    /// The state that a quasi-static loading from first contact reaches at
    /// `depth > 0` (m), as [`LayeredParaboloid::loading_at_depth`]: where
    /// the branch folds (a stiff layer over a far softer base) it may lie
    /// far inside [`at_depth`](Self::at_depth)'s largest-radius state.
    ///
    /// ```
    /// use layered_contact::analytic::{Axisymmetric, Tip};
    /// use layered_contact::{Base, Material, Substrate};
    ///
    /// // A soft film on a stiffer layer over a far softer base.
    /// let body = Substrate::stack(
    ///     &[(Material::new(1e3, 0.0)?, 1.8e-3), (Material::new(8.7e3, 0.0)?, 2.6e-3)],
    ///     Base::Elastic(Material::new(4.15, 0.0)?),
    /// )?;
    /// let exact = Axisymmetric::up_to_contact_radius(&body, 0.1)?;
    /// let cone = exact.tip(Tip::Cone { half_angle: 1.4 }, 2.2e-3)?;
    /// let loading = cone.loading_at_depth(5e-3)?.unwrap();
    /// let widest = cone.at_depth(5e-3)?.unwrap();
    /// // The loading stops at 3 mm; an equilibrium of 25 mm lies beyond a fold.
    /// assert!(loading.contact_radius < 3.1e-3 && widest.contact_radius > 2e-2);
    /// assert!((loading.depth - 5e-3).abs() < 1e-12);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn loading_at_depth(&self, depth: f64) -> Result<Option<ContactState>> {
        loading_root(self, depth, false)
    }

    /// As [`loading_at_depth`](Self::loading_at_depth) under load control
    /// at `force > 0` (N).
    ///
    /// # Errors
    /// As [`at_depth`](Self::at_depth).
    pub fn loading_at_force(&self, force: f64) -> Result<Option<ContactState>> {
        loading_root(self, force, true)
    }
}
