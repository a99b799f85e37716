//! The exact loading and unloading of a paraboloid with adhesion
//! hysteresis on a coated body.

use crate::error::{Error, Result};

use super::axisymmetric::{ContactState, LayeredParaboloid};
use super::layered_jkr_unloading::{least_below, unloading_root};

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
    /// The deepest depth asked for (m).
    max_depth: f64,
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
        let peak = advancing
            .loading_at_depth(max_depth)?
            .ok_or(Error::Internal {
                what: "layered JKR cycle",
                detail: "no loading equilibrium at a positive depth".into(),
            })?;
        Ok(LayeredJkrCycle {
            advancing,
            receding,
            peak,
            max_depth,
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
        self.advancing.loading_at_depth(depth)
    }

    /// The unloading branch at `depth <= max_depth` (m): pinned at the
    /// peak's contact radius until the energy release rate reaches the
    /// receding work of adhesion, then receding, the edge at the widest
    /// receding equilibrium inside the peak's radius (where the receding
    /// branch folds, the edge jumps inward at each fold; the branch's widest
    /// equilibrium at that depth may lie beyond the peak, where an unloading
    /// never goes); `None` once the contact has jumped off.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a depth beyond `max_depth` (the
    /// unloading starts there; a pinned contact pressed deeper is no state
    /// of the cycle: its edge would advance); others as
    /// [`LayeredParaboloid::at_depth`].
    pub fn unloading(&self, depth: f64) -> Result<Option<ContactState>> {
        crate::solver::check_finite("depth", depth)?;
        if depth > self.max_depth.max(self.peak.depth) {
            return Err(Error::InvalidParameter {
                name: "depth",
                value: depth,
                expected: "an unloading depth at most the cycle's max_depth",
            });
        }
        let a = self.peak.contact_radius;
        let release = self.receding.at_contact_radius(a)?;
        if depth >= release.depth {
            return self.receding.pinned(a, depth).map(Some);
        }
        unloading_root(&self.receding, a, depth, false)
    }

    /// The least force of the unloading branch (displacement control): the
    /// least force of the receding branch over the contact radii up to the
    /// peak's, or the pinned contact at its release where the least lies
    /// there (a second, deeper least beyond the peak, on a film over a far
    /// softer base, is never reached).
    ///
    /// # Errors
    /// As [`LayeredParaboloid::pull_off`]; [`Error::Unsupported`] where the
    /// receding branch folds inside the peak and its least force lies on
    /// radii that the unloading jumps over.
    pub fn unloading_pull_off(&self) -> Result<ContactState> {
        least_below(&self.receding, self.peak.contact_radius, false, true)
    }
}
