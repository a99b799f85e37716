//! Accuracy on demand: Richardson extrapolation over grid refinement, and
//! scenes run until a quantity has converged to a requested accuracy.
//!
//! The BEM converges like `1/N` (`N` cells across the contact: the error of
//! the staircase contact edge, measured in [`doc::accuracy`](crate::doc::accuracy)). Two resolutions `N1 < N2` with values `v1`, `v2` give the
//! extrapolated value `v2 + (v2 - v1) / ((N2/N1)^p - 1)` (order `p = 1`) and
//! the error estimate `|v2 - v1| / ((N2/N1)^p - 1)` for `v2`.

use crate::error::{Error, Result};

use super::{Curve, Resolution, Scene};

/// Richardson extrapolation of `(cells, value)` pairs converging like
/// `cells^(-order)`.
///
/// ```
/// use layered_contact::scene::richardson;
///
/// // v(N) = 2 - 3/N: exact for order 1.
/// let v = |n: f64| 2.0 - 3.0 / n;
/// assert!((richardson((32, v(32.0)), (64, v(64.0)), 1.0) - 2.0).abs() < 1e-14);
/// ```
pub fn richardson(coarse: (usize, f64), fine: (usize, f64), order: f64) -> f64 {
    let ratio = (fine.0 as f64 / coarse.0 as f64).powf(order);
    fine.1 + (fine.1 - coarse.1) / (ratio - 1.0)
}

/// A scalar result of a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Quantity {
    /// [`Curve::stiffness`], N/m.
    Stiffness,
    /// The force at the peak, the last step of the loading phase (the
    /// deepest point of a depth-driven protocol), N. For a non-adhesive
    /// curve it is also the largest force; an adhesive contact a few
    /// nanometres deep pulls at its peak, below the zero force of the free
    /// steps.
    PeakForce,
    /// The pull-off force ([`Curve::pull_off`]), N.
    PullOffForce,
    /// The contact radius (of equal area) at the peak (the last step of
    /// the loading phase), m.
    PeakContactRadius,
}

impl Quantity {
    /// Its name in files and messages: `stiffness`, `peak_force`,
    /// `pull_off_force`, `peak_contact_radius`.
    pub fn name(&self) -> &'static str {
        match self {
            Quantity::Stiffness => "stiffness",
            Quantity::PeakForce => "peak_force",
            Quantity::PullOffForce => "pull_off_force",
            Quantity::PeakContactRadius => "peak_contact_radius",
        }
    }

    /// The quantity of `curve`, if the curve has it.
    pub fn of(&self, curve: &Curve) -> Option<f64> {
        match self {
            Quantity::Stiffness => curve.stiffness(),
            Quantity::PeakForce => peak_step(curve).map(|s| s.force),
            Quantity::PullOffForce => curve.pull_off().map(|s| s.force),
            Quantity::PeakContactRadius => peak_step(curve).map(|s| s.contact_radius),
        }
    }
}

/// The last step of the loading phase.
fn peak_step(curve: &Curve) -> Option<&super::Step> {
    curve
        .steps
        .iter()
        .rev()
        .find(|s| s.phase == super::Phase::Loading)
}

/// The outcome of [`Scene::converge`].
#[derive(Debug, Clone, PartialEq)]
pub struct Converged {
    /// The value at the finest resolution run.
    pub value: f64,
    /// Its Richardson extrapolation from the two finest runs.
    pub extrapolated: f64,
    /// The estimated relative error of `value`.
    pub error_estimate: f64,
    /// Cells across the contact of the finest run.
    pub cells_across: usize,
    /// Every run: `(cells across, value)`.
    pub runs: Vec<(usize, f64)>,
}

/// Finest resolution [`Scene::converge`] tries.
const MAX_CELLS_ACROSS: usize = 1024;

impl Scene {
    /// Runs the scene at its resolution and at successively doubled ones until
    /// the estimated relative error of `quantity` (from the change between the
    /// last two runs, for `1/N` convergence) is below `target`.
    ///
    /// ```
    /// use layered_contact::scene::{Protocol, Quantity, Resolution, Scene};
    ///
    /// // Boussinesq punch: K = 2 a E* = 2 * 1e-3 * 1e6 / 0.75.
    /// let scene = Scene {
    ///     protocol: Protocol::Cycle { max_depth: 1e-5, steps: 2 },
    ///     resolution: Resolution { cells_across: 16, margin: 0.0 },
    ///     ..Scene::default()
    /// };
    /// let k = scene.converge(Quantity::Stiffness, 0.01)?;
    /// assert!(k.error_estimate < 0.01);
    /// assert!((k.extrapolated / (2e-3 * 1e6 / 0.75) - 1.0).abs() < 0.01);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a target that is not positive;
    /// [`Error::Unsupported`] for a quantity the protocol does not produce;
    /// [`Error::NoConvergence`] if
    /// 1024 cells across do not reach the target; any error of the runs.
    pub fn converge(&self, quantity: Quantity, target: f64) -> Result<Converged> {
        crate::error::positive_finite("target", target)?;
        let mut runs: Vec<(usize, f64)> = Vec::new();
        let mut cells = self.resolution.cells_across;
        loop {
            let scene = Scene {
                resolution: Resolution {
                    cells_across: cells,
                    ..self.resolution
                },
                ..self.clone()
            };
            let curve = scene.run(&mut |_| {})?;
            let value = quantity.of(&curve).ok_or(Error::Unsupported {
                feature: "this quantity for this protocol",
                reason: "stiffness needs two loaded steps (a cycle), pull-off an adhesive cycle",
            })?;
            runs.push((cells, value));
            if let [.., coarse, fine] = runs.as_slice() {
                let extrapolated = richardson(*coarse, *fine, 1.0);
                let error_estimate = ((fine.1 - extrapolated) / extrapolated).abs();
                if error_estimate < target || 2 * cells > MAX_CELLS_ACROSS {
                    if error_estimate >= target {
                        return Err(Error::NoConvergence {
                            method: "grid refinement to the target accuracy",
                            iterations: runs.len(),
                            residual: error_estimate,
                        });
                    }
                    return Ok(Converged {
                        value: fine.1,
                        extrapolated,
                        error_estimate,
                        cells_across: fine.0,
                        runs,
                    });
                }
            }
            cells *= 2;
        }
    }
}
