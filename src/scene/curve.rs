//! The result of a scene: a curve of quasi-static steps.

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

/// A known limit of the method that computed a [`Curve`], reported with it
/// instead of being left for the reader to discover.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Caveat {
    /// The energy-balance adhesion method balanced the energy release rate
    /// averaged over the contact edge, along contact sets that are level
    /// sets of the profile but neither discs (about the axis or a
    /// paraboloid's apex) on an isolated grid nor strips across a periodic one: the JKR-limit solution only
    /// where the release is even along the edge. For a tilted, elliptic or
    /// rectangular indenter or a height map the forces may be off by several
    /// per cent ([`doc::adhesion`](crate::doc::adhesion));
    /// [`ContactSolver::edge_release`](crate::solver::ContactSolver::edge_release)
    /// shows how uneven the release is on a contact, and the mesh-dependent
    /// criterion is the cell-by-cell alternative. For a flat punch (tilted,
    /// or with a face that is not round) the balance is too strong (a
    /// square by 7 to 9 %):
    /// [`ContactSolver::peel_punch`](crate::solver::ContactSolver::peel_punch)
    /// gives its pull-off by the local criterion, and a scene of a flat
    /// punch through the cohesive zone (the automatic method for a tilted
    /// one) unloads along that path. See
    /// [`AdhesiveBranches::edge_averaged`](crate::solver::AdhesiveBranches::edge_averaged).
    EdgeAveragedAdhesion,
    /// The mesh-dependent adhesion criterion (Pohrt & Popov 2015, the
    /// method of the reference experiment's simulations) computed the
    /// adhesive steps cell by cell: its pull-off depends on the cell size
    /// (too strong by about `3/N` on a curved edge `N` cells across) and on
    /// how the contact edge lies on the grid (a straight edge along the grid
    /// acts as if the work of adhesion were about 1.66 times larger): a
    /// reference method, not a converged JKR-limit answer
    /// ([`doc::adhesion`](crate::doc::adhesion)).
    MeshDependentAdhesion,
    /// The cohesive zone ([`CohesiveZone`](crate::solver::CohesiveZone))
    /// spans two cells, its fewest, and is still longer than a quarter of
    /// the top layer's thickness (the layer is thinner than eight cells):
    /// it then acts as a softer law than the JKR limit and the forces are
    /// biased by per cents: a sphere's pull-off on a film on a rigid base
    /// -0.8 % with the zone half the thickness, -4.6 % with the whole (see
    /// [`ZONE_LAYER_FRACTION`](crate::solver::ZONE_LAYER_FRACTION)); on a
    /// layer over a far softer one, where the zone's modulus is the
    /// body's at its length, a paraboloid's peak force and pull-off -2.4
    /// and +2.9 % at 64 cells across, -7.3 and +5.1 % at 32
    /// (`tests/scene_cohesive_soft_below.rs`), a sphere's peak force +5.0 %
    /// at 64 and +1.9 % at 128
    /// (`BENCHMARKS.md`, "The cohesive contact's area"); a nearly
    /// incompressible layer (`nu` 0.49) on a base 290 times stiffer, a
    /// sphere's pull-off -9.9, -6.9, -2.0 % at 16, 32, 64 cells (the
    /// cohesive reference sweep's seed 71; `BENCHMARKS.md`, "The loading
    /// branch under hysteresis"). A stiff layer on a half-space thousands
    /// of times softer is the worst measured: a paraboloid on a 57 GPa
    /// layer 24 um thick over a base 3850 times softer (the sweep's seed
    /// 74), pull-off +40, +22, +14, +5.1, +0.20 % at 16, 20, 24, 32, 64
    /// cells across, where the zone of two cells is 2.9, 2.4, 2.0, 1.5,
    /// 0.73 times the layer's thickness (the energy balance: peak force
    /// +0.04 % at 16; `BENCHMARKS.md`, "Seeds 74 to 85"). Over a base ten
    /// times softer a zone 2.4 and 6.4 times the thickness gave +3.1 and
    /// +1.9 %. A finer grid resolves it.
    CohesiveZoneLongAgainstLayer,
    /// A synthesised rough surface went through the cohesive zone: its
    /// forces depend on the zone's length, and their JKR limit is not
    /// established. Measured on the same surface refined from 64^2 to
    /// 512^2 cells (`BENCHMARKS.md`, "Adhesion through a resolved cohesive
    /// zone"): at a fixed zone the cycle converges in the grid (0.036 %
    /// between the two finest), but the converged pull-off moved by +8,
    /// +25 and -16 % as the zone halved from the surface's shortest
    /// wavelength to an eighth of it. Read the forces as those of a cohesive
    /// (Maugis-Dugdale) law of the zone's length
    /// ([`CohesiveZone::with_zone_cells`](crate::solver::CohesiveZone::with_zone_cells));
    /// `doc::adhesion`.
    CohesiveZoneOnRoughSurface,
    /// The cohesive zone was wider than the contact at the pull-off (the
    /// contact's widest patch fewer cells across than the zone): the zones
    /// of its two sides meet, and the force is a cohesive law's, not the
    /// JKR limit's. Johnson's sinusoid so resolved came out 0.9 to 25 %
    /// weak (`BENCHMARKS.md`, "The cohesive zone on contacts it spans");
    /// see [`CohesivePullOff::zone_spans_contact`](crate::solver::CohesivePullOff::zone_spans_contact).
    /// A finer grid resolves it.
    CohesiveZoneSpansContact,
    /// With adhesion hysteresis through the cohesive zone, the contact of
    /// an indenter that is neither a flat punch nor a rough surface came
    /// off near where the loading left it (at the pull-off it still covered
    /// [`PINNED_AREA_FRACTION`] of the peak's contact area or more: the edge
    /// was pinned), or the body is far softer below its surface (its
    /// softest contact modulus at least [`SOFT_BELOW_CONTRAST`] times below
    /// the surface's), where the contact jumps off as soon as a pinned edge
    /// moves. Such a pull-off
    /// comes where the pinned edge begins to recede, and through the zone
    /// it converges slowly in the grid, mostly too weak: -8.4, -3.7, -1.4 %
    /// at 16, 32, 64 cells across on a half-space (works 0.146 and 1.122
    /// J/m^2), -19, -9.6, -6.3 % on a layer over a base 2000 times softer.
    /// Of the cohesive reference sweep's scenes with hysteresis (seeds 11,
    /// 37 and 50 to 69), the 33 flagged at 32 cells came out -17.5 to
    /// +3.3 % (the last under the long-zone caveat too), the 48 not flagged
    /// within 1.5 % (`BENCHMARKS.md`, "The loading branch under
    /// hysteresis"). A finer grid narrows it; for an axisymmetric contact
    /// the energy balance is exact.
    CohesivePinnedPullOff,
}

/// The least part of the peak's contact area that a contact still covers
/// at its pull-off for [`Caveat::CohesivePinnedPullOff`]. Measured ratios
/// (through the cohesive zone, 32 and 64 cells across): edges pinned to the
/// pull-off 0.73 to 0.93 (a sphere on a half-space 0.83; over bases 2000 to
/// 10000 times softer 0.73, 0.93, 0.83; a cone 0.81), edges that recede
/// before it, whose pull-offs are within 0.6 %, 0.52 and 0.58 (a sphere on
/// a rubber film on glass, works 0.05 and 0.1 J/m^2; on a stack over a
/// base 32 times softer).
pub const PINNED_AREA_FRACTION: f64 = 0.7;

/// The ratio of the surface's contact modulus to the body's softest from
/// which [`Caveat::CohesivePinnedPullOff`] applies with hysteresis whatever
/// the pull-off's contact: over bases 2600 and 9700 times softer than the
/// layer the cohesive zone's edge receded early and came off with 0.61 to
/// 0.69 of the peak's area in six of the sweep's runs (-6.6 to -20.2 % at
/// 16 or 32 cells), where unflagged bodies 10 and 18 times softer below
/// came within 0.9 % at 32 cells.
pub const SOFT_BELOW_CONTRAST: f64 = 100.0;

impl std::fmt::Display for Caveat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Caveat::EdgeAveragedAdhesion => f.write_str(
                "edge-averaged adhesion: the contact sets are neither discs (about the grid's \
                 axis or a paraboloid's apex) nor strips across a periodic grid, so the energy balance averages the \
                 energy release rate over the edge and its forces may be off by several per \
                 cent (the JKR-limit solution only where the release is even along the edge; \
                 a flat punch's pull-off by the local criterion: ContactSolver::peel_punch, \
                 Python layered_contact.peel_punch)",
            ),
            Caveat::MeshDependentAdhesion => f.write_str(
                "mesh-dependent adhesion: the criterion of Pohrt & Popov (2015) decides each \
                 cell, so the pull-off depends on the cell size (about 3/N too strong on a \
                 curved edge N cells across) and on how the contact edge lies on the grid (up \
                 to about 40 % too strong along a straight edge on the grid): a reference \
                 method, not a converged answer",
            ),
            Caveat::CohesiveZoneLongAgainstLayer => f.write_str(
                "cohesive zone long against the layer: the top layer is thinner than eight \
                 cells, so the two-cell zone is longer than a quarter of its thickness and \
                 the forces may be off by per cents (on a rigid base -0.8 % with the zone \
                 half the thickness, -4.6 % with the whole; over a far softer layer up to \
                 8 % measured; a nearly incompressible layer on a far stiffer base -6.9 % at \
                 32 cells across), and by tens of per cents where a stiff layer lies on a \
                 body thousands of times softer (+40 % with the zone three times the \
                 layer's thickness, +5 % at one and a half times): refine the grid",
            ),
            Caveat::CohesiveZoneOnRoughSurface => f.write_str(
                "cohesive zone on a rough surface: the forces depend on the zone's length and \
                 their JKR limit is not established (measured on a rough film, converged in \
                 the grid at a fixed zone, the pull-off moved by +8, +25 and -16 % as the zone \
                 halved from the shortest wavelength to an eighth of it): read them as a \
                 cohesive law's of the zone's length",
            ),
            Caveat::CohesiveZoneSpansContact => f.write_str(
                "cohesive zone wider than the contact at the pull-off: the zones of the \
                 contact's two sides meet, so the force is a cohesive law's, not the JKR \
                 limit's (Johnson's sinusoid so resolved came out 0.9 to 25 % weak): refine \
                 the grid",
            ),
            Caveat::CohesivePinnedPullOff => f.write_str(
                "pinned pull-off through the cohesive zone: with adhesion hysteresis the \
                 contact came off near where the loading left it, or the body is far softer \
                 below its surface, and such a pull-off converges slowly in the grid, \
                 mostly too weak (-8.4, -3.7, -1.4 % at 16, 32, 64 cells across on a \
                 half-space; -19, -9.6, -6.3 % over a base 2000 times softer): refine the \
                 grid, or for an axisymmetric contact use the energy balance (exact)",
            ),
        }
    }
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

    /// Whether the contact at the pull-off still covers
    /// [`PINNED_AREA_FRACTION`] of the peak's (the last loading step's)
    /// contact area or more.
    pub(super) fn came_off_pinned(&self) -> bool {
        let peak = self.phase(Phase::Loading).last().map(|s| s.contact_area);
        match (peak, self.pull_off()) {
            (Some(peak), Some(pull_off)) if peak > 0.0 => {
                pull_off.contact_area >= PINNED_AREA_FRACTION * peak
            }
            _ => false,
        }
    }
}
