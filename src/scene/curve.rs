//! The result of a scene: a curve of quasi-static steps.

use super::Caveat;
use crate::grid::Grid;
use crate::solver::Solution;

/// Which branch a step belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Phase {
    /// The indenter advances.
    Loading,
    /// The indenter retracts.
    Unloading,
}

impl Phase {
    /// `"loading"` or `"unloading"`.
    pub fn name(&self) -> &'static str {
        match self {
            Phase::Loading => "loading",
            Phase::Unloading => "unloading",
        }
    }
}

/// One equilibrium of a quasi-static protocol.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct Step {
    /// Loading or unloading.
    pub phase: Phase,
    /// Depth, m.
    pub depth: f64,
    /// Force, N.
    pub force: f64,
    /// Contact area, m^2.
    pub contact_area: f64,
    /// Radius of the circle of equal area, m.
    pub contact_radius: f64,
    /// Solver iterations of this step. With the energy-balance adhesion
    /// method the whole cost (building the branches) is counted on the
    /// first step and the others cost none.
    pub iterations: usize,
}

impl Step {
    pub(crate) fn new(phase: Phase, solution: &Solution) -> Self {
        Step {
            phase,
            depth: solution.depth,
            force: solution.force,
            contact_area: solution.contact_area,
            contact_radius: solution.contact_radius,
            iterations: solution.iterations,
        }
    }
}

/// The steps of a scene, in the order they were computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The steps.
    pub steps: Vec<Step>,
    /// The grid the scene was solved on.
    pub grid: Grid,
    /// The solution at the deepest (most loaded) step, with the fields the
    /// scene asked for; `None` if it asked for none.
    pub peak: Option<Solution>,
    /// Where the numbers are known to be less than the method's accuracy
    /// (empty when they are not): the tool prints them, Python returns
    /// them as `Curve.caveats`.
    pub caveats: Vec<Caveat>,
    /// The stresses below the surface at the most loaded step, when the
    /// scene's outputs ask for them.
    pub stresses: Option<super::SubsurfaceResult>,
}

impl Curve {
    /// Steps of one phase.
    pub fn phase(&self, phase: Phase) -> impl Iterator<Item = &Step> {
        self.steps.iter().filter(move |s| s.phase == phase)
    }

    /// The contact stiffness `K = dF/dd` at the end of the loading branch,
    /// from its last two steps (N/m); `None` with fewer than two loading steps
    /// in contact.
    pub fn stiffness(&self) -> Option<f64> {
        let loading: Vec<&Step> = self
            .phase(Phase::Loading)
            .filter(|s| s.contact_area > 0.0)
            .collect();
        match loading.as_slice() {
            [.., a, b] if b.depth != a.depth => Some((b.force - a.force) / (b.depth - a.depth)),
            _ => None,
        }
    }

    /// The pull-off point: the step of least (most tensile) force on the
    /// unloading branch, if that force is negative.
    pub fn pull_off(&self) -> Option<&Step> {
        self.phase(Phase::Unloading)
            .filter(|s| s.force < 0.0)
            .min_by(|a, b| a.force.total_cmp(&b.force))
    }
}
