//! The unloading of an exact tip from a peak contact on a coated body: the
//! state at a depth or force once the contact's edge recedes, and the
//! least force or depth on the way out. Where the receding branch folds (a
//! film on a far softer base) the edge jumps inward at each fold, and the
//! branch's widest equilibrium at a depth may lie beyond the peak, where an
//! unloading never goes.

use super::axisymmetric::{golden_minimum, minimise, ContactState, LayeredTip, MINIMISE_SCAN};
use super::layered_jkr::{controlled, crossing, Branch, LOADING_STEP};
use crate::error::{Error, Result};

/// The most samples [`unloading_root`] takes going inward (`1.15^400 =
/// 2e24` times inside the peak).
const MOST_SAMPLES: usize = 400;

/// The relative distance within which a least state is taken to be the
/// unloading's own state at its depth.
const ON_PATH: f64 = 1e-6;

/// The state of `tip` at `target` depth or force (`by_force`) that an
/// unloading from a contact of `peak_radius` (m) reaches once its edge
/// recedes: the root of `key(a) = target` of largest radius at or inside
/// the peak, the key rising through the target there. As the target falls
/// the edge reaches exactly the radii whose key lies below that of every
/// radius between them and the peak, jumping inward at each fold. `None`
/// where the branch inside the peak stays above the target: the contact
/// has come off. The caller has checked `key(peak) > target` (the pinned
/// contact has let go); at or below it, the peak's state.
///
/// Scans inward from the peak in steps of [`LOADING_STEP`]; where the
/// samples turn up, the minimum between the last three (golden sections)
/// decides whether the branch dipped below the target in between; then
/// bisects. The scan ends at the pull-off span's smallest radius once the
/// samples rise inward (the branch's unstable part, climbing to 0), or
/// without adhesion at a target `<= 0` at once (the contact comes off at
/// depth and force 0).
///
/// # Errors
/// [`Error::Internal`] if no end is found in [`MOST_SAMPLES`] samples; the
/// failures of `tip.state`.
pub(super) fn unloading_root(
    tip: &impl Branch,
    peak_radius: f64,
    target: f64,
    by_force: bool,
) -> Result<Option<ContactState>> {
    let key = |a: f64| tip.state(a).map(|s| controlled(&s, by_force));
    if tip.work() == 0.0 && target <= 0.0 {
        return Ok(None);
    }
    let floor = tip.pull_off_low();
    let (mut hi, mut last) = (peak_radius, key(peak_radius)?);
    if last <= target {
        return tip.state(peak_radius).map(Some);
    }
    // The sample outside `hi`: the peak itself at first.
    let mut outer = (peak_radius, f64::INFINITY);
    for _ in 0..MOST_SAMPLES {
        let lo = hi / LOADING_STEP;
        let value = key(lo)?;
        if value < target {
            return crossing(tip, (lo, hi), &key, target).map(Some);
        }
        if value > last {
            if last < outer.1 {
                let dip =
                    golden_minimum((lo, outer.0), |a| tip.state(a), |s| controlled(s, by_force))?;
                if controlled(&dip, by_force) < target {
                    let above = if dip.contact_radius < hi { hi } else { outer.0 };
                    return crossing(tip, (dip.contact_radius, above), &key, target).map(Some);
                }
            }
            if lo < floor {
                return Ok(None);
            }
        }
        outer = (hi, last);
        (hi, last) = (lo, value);
    }
    Err(Error::Internal {
        what: "exact unloading branch",
        detail: format!(
            "no end of the branch within {MOST_SAMPLES} samples inside {peak_radius:e} m \
             (the target {target:e})"
        ),
    })
}

/// The least force (`depth` false) or depth (`depth` true) of an unloading
/// from a contact of `peak_radius` (m): over the contact radii up to it,
/// the state at `peak_radius` itself where the least lies there (a contact
/// pinned at the peak lets go as it starts to recede). A layered body may
/// have a second, deeper minimum far beyond the peak (a film on a much
/// softer base: the base's own JKR scale), which an unloading from the
/// peak never reaches. With `displacement_control`, a least force must lie
/// on the radii a depth-controlled unloading reaches ([`unloading_root`]):
/// where the receding branch folds, the edge jumps over some.
///
/// # Errors
/// [`Error::Unsupported`] for a least force that a depth-controlled
/// unloading jumps over; [`Error::InvalidParameter`] without adhesion, or
/// where the least lies beyond the tabulated radii; the failures of
/// `tip.state`.
pub(super) fn least_below(
    tip: &impl Branch,
    peak_radius: f64,
    depth: bool,
    displacement_control: bool,
) -> Result<ContactState> {
    let (lo, hi) = tip.span()?;
    let top = hi.min(peak_radius);
    if top <= lo {
        return tip.state(top);
    }
    let key = |s: &ContactState| controlled(s, !depth);
    let least = match minimise(lo, top, |a| tip.state(a), key) {
        Err(Error::InvalidParameter {
            name: "contact_radius",
            ..
        }) if top == peak_radius => {
            // The scan's least sample is the peak's: the least lies there
            // or within the scan's last step (a paraboloid's least force 4 %
            // inside the peak, 0.18 % below the peak's, was missed).
            let at_peak = tip.state(top)?;
            let step = (top / lo).powf(1.0 / (MINIMISE_SCAN - 1) as f64);
            let inside = golden_minimum((top / step, top), |a| tip.state(a), key)?;
            if key(&inside) >= key(&at_peak) {
                return Ok(at_peak);
            }
            inside
        }
        other => other?,
    };
    if depth || !displacement_control {
        // The least of the key that the unloading follows lies below every
        // radius outside it: the unloading reaches it.
        return Ok(least);
    }
    let reached = unloading_root(tip, peak_radius, least.depth, false)?;
    match reached {
        Some(s) if (s.contact_radius / least.contact_radius - 1.0).abs() <= ON_PATH => Ok(least),
        _ => Err(Error::Unsupported {
            feature: "the exact least force of this depth-controlled unloading",
            reason: "the receding branch folds inside the peak, and its least force lies on \
                     radii that the unloading jumps over; the least depth and the states \
                     along the unloading are exact",
        }),
    }
}

impl LayeredTip {
    /// As [`least_below`].
    pub(crate) fn least_below(
        &self,
        peak_radius: f64,
        depth: bool,
        displacement_control: bool,
    ) -> Result<ContactState> {
        least_below(self, peak_radius, depth, displacement_control)
    }
}
