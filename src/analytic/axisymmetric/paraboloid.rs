//! The paraboloid on a coated half-space (JKR when adhesive), by contact
//! radius, and the pull-off search every tip shares.

use std::f64::consts::PI;

use super::{pressure_profile, Axisymmetric, Nystrom};
use crate::error::{Error, Result};

/// A paraboloid on the coated half-space, as functions of the contact radius.
/// It holds its own handle on the body's tabulated kernel (shared, not
/// copied), so it may outlive the [`Axisymmetric`] it came from:
/// `Axisymmetric::new(..)?.paraboloid(..)?` is a value.
#[derive(Debug, Clone)]
pub struct LayeredParaboloid {
    pub(in crate::analytic) body: Axisymmetric,
    pub(in crate::analytic) sphere_radius: f64,
    pub(in crate::analytic) work_of_adhesion: f64,
}

/// One equilibrium state of a paraboloid contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// Contact radius `a`, m.
    pub contact_radius: f64,
    /// Depth `d`, m.
    pub depth: f64,
    /// Force `F`, N.
    pub force: f64,
    /// `eps = a/h`.
    pub eps: f64,
}

/// The pull-off point of an adhesive contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PullOff {
    /// Under load control: the state of minimum force.
    pub load_control: ContactState,
    /// Under displacement control: the state of minimum depth, where the
    /// contact jumps off.
    pub displacement_control: ContactState,
}

impl LayeredParaboloid {
    fn solved(&self, contact_radius: f64) -> Result<(f64, Nystrom)> {
        self.body.nystrom(contact_radius)
    }

    fn state(&self, a: f64, solution: &Nystrom) -> ContactState {
        let e = self.body.contact_modulus;
        let curvature = a * a / self.sphere_radius;
        let adhesive = (2.0 * PI * a * self.work_of_adhesion / e).sqrt();
        let depth = (curvature * solution.edge(true) - adhesive) / solution.edge(false);
        self.state_at_depth(a, depth, solution)
    }

    /// The state with contact radius `a` held fixed at `depth` (a contact
    /// pinned by adhesion hysteresis): the force is linear in the depth.
    fn state_at_depth(&self, a: f64, depth: f64, solution: &Nystrom) -> ContactState {
        let e = self.body.contact_modulus;
        let curvature = a * a / self.sphere_radius;
        let force =
            2.0 * e * a * (depth * solution.integral(false) - curvature * solution.integral(true));
        ContactState {
            contact_radius: a,
            depth,
            force,
            eps: solution.eps,
        }
    }

    /// The equilibrium at contact radius `a` (m): JKR if the work of adhesion
    /// is positive (`G = dgamma` at the edge), else non-adhesive (`phi(a) = 0`).
    ///
    /// # Errors
    /// As [`Axisymmetric::flat_punch`].
    pub fn at_contact_radius(&self, contact_radius: f64) -> Result<ContactState> {
        let (a, solution) = self.solved(contact_radius)?;
        Ok(self.state(a, &solution))
    }

    /// The state of a contact of radius `a` (m) held fixed at `depth` (m),
    /// as when adhesion hysteresis pins the edge: not an equilibrium of the
    /// edge unless `depth` is [`at_contact_radius`](Self::at_contact_radius)'s.
    ///
    /// # Errors
    /// As [`LayeredParaboloid::at_contact_radius`].
    pub fn pinned(&self, contact_radius: f64, depth: f64) -> Result<ContactState> {
        let (a, solution) = self.solved(contact_radius)?;
        Ok(self.state_at_depth(a, depth, &solution))
    }

    /// The pressure at radius `r` in the equilibrium of contact radius `a`, Pa.
    ///
    /// # Errors
    /// As [`LayeredParaboloid::at_contact_radius`].
    pub fn pressure(&self, contact_radius: f64, r: f64) -> Result<f64> {
        let (a, solution) = self.solved(contact_radius)?;
        let state = self.state(a, &solution);
        let curvature = a * a / self.sphere_radius;
        Ok(pressure_profile(
            self.body.contact_modulus,
            &solution,
            a,
            state.depth,
            curvature,
            r,
        ))
    }

    /// Equilibria at each of `contact_radii`.
    ///
    /// # Errors
    /// As [`LayeredParaboloid::at_contact_radius`].
    pub fn curve(&self, contact_radii: &[f64]) -> Result<Vec<ContactState>> {
        contact_radii
            .iter()
            .map(|&a| self.at_contact_radius(a))
            .collect()
    }

    /// The pull-off points under load and displacement control, by a
    /// logarithmic scan of the contact radius over
    /// `[a_JKR / 100, min(10 a_JKR, max radius)]` (`a_JKR` the half-space
    /// pull-off radius) refined by golden-section search.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] without adhesion (no pull-off); others as
    /// [`LayeredParaboloid::at_contact_radius`].
    pub fn pull_off(&self) -> Result<PullOff> {
        crate::error::work_for_pull_off(self.work_of_adhesion)?;
        let (lo, hi) = self.pull_off_range();
        let load = self.minimise(lo, hi, |s| s.force)?;
        let displacement = self.minimise(lo, hi, |s| s.depth)?;
        Ok(PullOff {
            load_control: load,
            displacement_control: displacement,
        })
    }

    /// The load-controlled half of [`pull_off`](Self::pull_off), at half
    /// the cost.
    pub(crate) fn load_controlled_pull_off(&self) -> Result<ContactState> {
        let (lo, hi) = self.pull_off_range();
        self.minimise(lo, hi, |s| s.force)
    }

    /// The contact radii scanned for a pull-off: `[a_JKR / 100,
    /// min(10 a_JKR, max radius)]`.
    pub(in crate::analytic) fn pull_off_range(&self) -> (f64, f64) {
        let e = self.body.contact_modulus;
        let scale =
            (9.0 * PI * self.work_of_adhesion * self.sphere_radius.powi(2) / (8.0 * e)).cbrt();
        (
            scale / 100.0,
            (10.0 * scale).min(self.body.max_contact_radius()),
        )
    }

    fn minimise(
        &self,
        lo: f64,
        hi: f64,
        key: impl Fn(&ContactState) -> f64,
    ) -> Result<ContactState> {
        minimise(lo, hi, |a| self.at_contact_radius(a), key)
    }
}

/// The radii [`minimise`] scans, in equal ratios.
pub(in crate::analytic) const MINIMISE_SCAN: usize = 48;

/// The state of least `key` over contact radii in `[lo, hi]` (m): a
/// logarithmic scan of [`MINIMISE_SCAN`] radii refined by golden-section
/// search.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `contact_radius` where the scan's
/// least value is at `hi`: the force or depth still falls there, and the
/// minimum lies beyond the radii searched (the table's largest contact, or
/// a layered body whose softer base spreads the pull-off far beyond the
/// surface modulus's scale: a cone on a film over a base 300 times softer
/// returned the table's edge, a "pull-off" at the peak's own force). The
/// failures of `state`.
pub(in crate::analytic) fn minimise(
    lo: f64,
    hi: f64,
    state: impl Fn(f64) -> Result<ContactState>,
    key: impl Fn(&ContactState) -> f64,
) -> Result<ContactState> {
    let ratio = (hi / lo).powf(1.0 / (MINIMISE_SCAN - 1) as f64);
    let states: Vec<ContactState> = (0..MINIMISE_SCAN)
        .map(|k| state((lo * ratio.powi(k as i32)).min(hi)))
        .collect::<Result<_>>()?;
    let best = (0..MINIMISE_SCAN)
        .min_by(|&i, &j| key(&states[i]).total_cmp(&key(&states[j])))
        .unwrap_or(0);
    if best == MINIMISE_SCAN - 1 {
        return Err(Error::InvalidParameter {
            name: "contact_radius",
            value: hi,
            expected: "a least force or depth within the contact radii searched (it still \
                       falls at this, the largest; build the solution up to a wider \
                       contact: Axisymmetric::up_to_contact_radius)",
        });
    }
    golden_minimum(
        (
            states[best.saturating_sub(1)].contact_radius,
            states[(best + 1).min(MINIMISE_SCAN - 1)].contact_radius,
        ),
        state,
        key,
    )
}

/// The state of least `key` over contact radii in `[a, b]` (m) where one
/// minimum lies inside: golden-section search to `0.618^40 = 4e-9` of the
/// bracket.
///
/// # Errors
/// The failures of `state`.
pub(in crate::analytic) fn golden_minimum(
    (mut a, mut b): (f64, f64),
    state: impl Fn(f64) -> Result<ContactState>,
    key: impl Fn(&ContactState) -> f64,
) -> Result<ContactState> {
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = b - golden * (b - a);
    let mut x2 = a + golden * (b - a);
    let mut f1 = key(&state(x1)?);
    let mut f2 = key(&state(x2)?);
    // 0.618^40 = 4e-9 of the bracket: the value at the minimum, flat to
    // second order, is exact to rounding.
    for _ in 0..40 {
        if f1 < f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - golden * (b - a);
            f1 = key(&state(x1)?);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + golden * (b - a);
            f2 = key(&state(x2)?);
        }
    }
    state(0.5 * (a + b))
}
