//! Scenes: a substrate, an indenter, the effects it calls for, a loading
//! protocol and the outputs wanted, run as one quasi-static experiment.
//!
//! A scene simulates only what it asks for: without adhesion it runs the
//! non-adhesive solver (bit-for-bit what [`ContactSolver::solve_depth`]
//! gives); a homogeneous half-space (including a layer of infinite thickness
//! or of the base's own material) builds only Love's closed-form kernel; no
//! pressure, displacement or gap field is kept unless
//! [`Outputs::fields`] asks for it. Kernel and FFT plans are built once per
//! scene by [`Scene::solver`], and can be shared by scenes on the same
//! substrate and grid through [`Scene::run_on`].
//!
//! With the `serde` feature (on by default) scenes read from and write to
//! TOML or JSON; the `layered-contact` command-line tool runs such files.
//!
//! ```
//! use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Scene, SubstrateSpec};
//!
//! let scene = Scene {
//!     substrate: SubstrateSpec::LayerOnRigidBase {
//!         youngs_modulus: 0.324e6,
//!         poisson_ratio: 0.48,
//!         thickness: 5e-3,
//!     },
//!     indenter: IndenterSpec::FlatPunch { radius: 2.5e-3 },
//!     adhesion: Adhesion::Constant { work_of_adhesion: 0.326 },
//!     protocol: Protocol::Cycle { max_depth: 2e-4, steps: 10 },
//!     ..Scene::default()
//! };
//! let curve = scene.run(&mut |_| {})?;
//! let stiffness = curve.stiffness().unwrap();
//! let pull_off = curve.pull_off().unwrap();
//! assert!(stiffness > 0.0 && pull_off.force < 0.0 && pull_off.depth < 0.0);
//! Ok::<(), layered_contact::Error>(())
//! ```

mod accuracy;
mod caveat;
mod curve;
mod energy;
#[cfg(feature = "serde")]
mod file;
mod method;
mod reference;
mod run;
mod runner;
#[cfg(feature = "serde")]
mod schema;
mod sizing;
mod spec;
mod stresses;

pub use accuracy::{richardson, Converged, Quantity};
pub use caveat::{
    Caveat, ZoneScales, PINNED_AREA_FRACTION, SOFT_BELOW_CONTRAST, ZONE_CONTACT_MODULUS_RATIO,
};
pub use curve::{Curve, Phase, Step};
pub use reference::Reference;
pub use spec::{
    Adhesion, CustomIndenter, IndenterSpec, LayerSpec, MaterialSpec, SubstrateSpec, Tilt,
};
pub use stresses::{DepthGrid, StressOutputs, SubsurfaceResult, MAX_STRESS_PLANES};

use crate::error::{positive_finite, Error, Result};
use crate::grid::{Boundary, Grid};
use crate::solver::{ContactSolver, Fields, Observer, SolverParams};

use crate::grid::fft_friendly;
use runner::{Outcome, Runner};

/// How the indenter is driven.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum Protocol {
    /// One solve at `depth` (m).
    Depth {
        /// Depth, m.
        depth: f64,
    },
    /// One solve at total force `force` (N, `>= 0`); with adhesion (energy
    /// balance) the load-controlled JKR state reached by pressing in from
    /// no contact, which at zero force is the state the contact jumps into.
    Force {
        /// Force, N.
        force: f64,
    },
    /// Displacement control: from depth 0 to `max_depth` in `steps` equal
    /// increments, then back out from the peak with the same increment
    /// until the contact is lost (doubling the increment beyond
    /// `-max_depth`). With the energy-balance adhesion method the pull-off
    /// (least force) and the jump-off (least depth) are added as exact
    /// steps of the unloading branch; with the mesh-dependent criterion the
    /// depths where the contact first shrinks and where it is lost are
    /// located by bisection. The increments double beyond `-max_depth`; a
    /// contact still attached past the larger of `-4096 max_depth` and four
    /// times Kendall's pull-off depth of a punch as wide as the grid on
    /// the body's softest material (`sqrt(2 pi dgamma a / E*)`, Kendall
    /// 1971) ends the run with [`Error::NoConvergence`].
    Cycle {
        /// Maximum depth, m.
        max_depth: f64,
        /// Increments of the loading branch.
        steps: usize,
    },
    /// Force control: up to `max_force` in `steps` increments and back down
    /// to zero. With adhesion (energy balance or cohesive zone) the contact
    /// jumps in at zero force, follows the advancing branch up, stays pinned and then
    /// recedes on the way down, and the unloading goes on into tension with
    /// the same increment until the pull-off force, which is added as an
    /// exact step (the jump-off under load control), followed by a step
    /// without contact. A cycle whose unloading would need more than 100000
    /// steps to reach a tenth of the closed form's pull-off (JKR's for a
    /// paraboloid, Kendall's for an untilted flat punch, the smaller of the
    /// two for a sphere, the exact solution's for a cone; isolated grids)
    /// is refused by `Scene::validate` before any solve.
    ForceCycle {
        /// Maximum force, N.
        max_force: f64,
        /// Increments of the loading branch.
        steps: usize,
    },
}

/// How fine the grid is.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct Resolution {
    /// Cells across the smallest contact diameter the protocol must
    /// resolve, 8 to 8192: the punch's diameter; for curved indenters the
    /// largest contact the protocol reaches (Hertz or exact layered
    /// estimate) or, in an adhesive scene with a sphere, paraboloid or
    /// cone, the pull-off contact (exact layered JKR) if that is smaller.
    pub cells_across: usize,
    /// Extra width around the largest contact, as a fraction of its
    /// diameter on each side, at most 10: for curved indenters (the grid
    /// grows if the contact reaches its edge), and for a flat punch on a
    /// periodic grid, whose period is then the diameter times `1 + 2
    /// margin` (an array of punches; an isolated punch's grid holds its
    /// face and a ring of cells, whatever the margin).
    pub margin: f64,
}

impl Protocol {
    /// The depth or force of the protocol's peak (its deepest depth or
    /// largest force).
    pub(crate) fn peak(&self) -> crate::solver::Reach {
        use crate::solver::Reach;
        match *self {
            Protocol::Depth { depth } => Reach::Depth(depth),
            Protocol::Cycle { max_depth, .. } => Reach::Depth(max_depth),
            Protocol::Force { force } => Reach::Force(force),
            Protocol::ForceCycle { max_force, .. } => Reach::Force(max_force),
        }
    }

    /// The name and value of what the protocol reaches for (a depth or a
    /// force, as in the scene file), for error messages.
    pub(crate) fn reach(&self) -> (&'static str, f64) {
        match *self {
            Protocol::Depth { depth } => ("depth", depth),
            Protocol::Cycle { max_depth, .. } => ("max_depth", max_depth),
            Protocol::Force { force } => ("force", force),
            Protocol::ForceCycle { max_force, .. } => ("max_force", max_force),
        }
    }
}

impl Default for Resolution {
    fn default() -> Self {
        Resolution {
            cells_across: 64,
            margin: 0.25,
        }
    }
}

/// What a scene keeps.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct Outputs {
    /// Fields of the most loaded step to keep in [`Curve::peak`].
    pub fields: Fields,
    /// Stresses below the surface at the most loaded step, in
    /// [`Curve::stresses`].
    pub stresses: StressOutputs,
}

impl Outputs {
    /// The fields the most loaded solve keeps: those asked for, and the
    /// pressure when stresses are asked for.
    pub(crate) fn kept_fields(&self) -> Fields {
        Fields {
            pressure: self.fields.pressure || self.stresses.any(),
            ..self.fields
        }
    }
}

/// Solver settings of a scene.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct SolverSettings {
    /// See [`SolverParams::tolerance`].
    pub tolerance: f64,
    /// See [`SolverParams::max_iterations`].
    pub max_iterations: usize,
    /// Bisection steps that locate the pull-off depth of a cycle (mesh-dependent
    /// criterion), at most 60.
    pub pull_off_bisections: usize,
    /// How adhesion is solved.
    pub adhesion_method: AdhesionMethod,
}

/// How an adhesive scene decides where the contact edge stands.
///
/// [`Auto`](AdhesionMethod::Auto), the default, takes the method that is
/// exact for the scene ([`Scene::resolved_adhesion_method`]): the energy
/// balance where the contact sets are discs (but for a punch whose
/// stiffness barely changes with its contact), the cohesive zone for every
/// other shape. `#[non_exhaustive]`: methods may be added
/// in minor releases.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
#[non_exhaustive]
pub enum AdhesionMethod {
    /// The method that converges to the JKR limit for the scene: the energy
    /// balance for an untilted flat punch, sphere or cone and any paraboloid
    /// on an isolated grid (their contact sets are discs: exact, and a whole
    /// cycle for the price of one family of contact sets), except a punch
    /// on a layered body whose stiffness barely changes with its contact
    /// ([`Scene::resolved_adhesion_method`]); the cohesive zone for every
    /// other scene (tilted indenters, punches included, height maps, rough
    /// surfaces, custom indenters, periodic grids), under displacement or
    /// force control, a punch's unloading along its peeling path by the
    /// local criterion.
    #[default]
    Auto,
    /// The energy (Griffith) balance over the contact edge along a family of
    /// contact sets ([`ContactSolver::adhesive_branches`]): a sphere's
    /// pull-off against exact JKR at each resolution is tabulated in
    /// [`doc::accuracy`](crate::doc::accuracy) (half-space and layers),
    /// displacement or force control, a whole cycle for the price of one
    /// family. The edge-averaged balance: exact for axisymmetric contacts
    /// and for wavy surfaces on periodic grids (strips, at first order in
    /// the cell size), flagged as [`Caveat::EdgeAveragedAdhesion`] on the
    /// curve for every other (forces may be off by several per cent);
    /// refuses contacts that split into patches or span more than half a
    /// period.
    EnergyBalance,
    /// The mesh-dependent critical stress of Pohrt & Popov (2015), cell by
    /// cell ([`ContactSolver::solve_depth_hysteretic`]): the method of the
    /// reference experiments' simulations, for any contact shape, but
    /// converging slowly (about `3/N` relative error in a sphere's pull-off
    /// force) and biased by how the contact edge lies on the grid; its
    /// curves carry [`Caveat::MeshDependentAdhesion`]. Displacement control
    /// only.
    MeshCriterion,
    /// A cohesive zone resolved on the grid
    /// ([`ContactSolver::solve_depth_cohesive`] with the law of
    /// [`Scene::cohesive_zone`]: four cells up to 64 across the contact,
    /// growing like the square root of `cells_across` beyond): the JKR
    /// limit for any contact shape, orientation and number of patches, on
    /// isolated and periodic grids (a sphere's pull-off -0.13 % at 64 cells
    /// across, [`doc::accuracy`](crate::doc::accuracy); a tilted
    /// paraboloid's cycle -0.099, -0.041, +0.0052 % at 64, 128, 256).
    /// A step whose equilibrium the zone's fixed point does not reach is
    /// taken again in 2, 4, 8 or 16 substeps.
    /// The pull-off of a cycle is searched between the two steps around the
    /// least force (golden sections to a sixteenth of a step, then the
    /// parabola's vertex: about nine more solves). Under force control
    /// each step is a search of the depth along the displacement-controlled
    /// path (regula falsi, to 1e-6 of the largest force, or to the nearer
    /// side where the path's force snaps across the one asked as a cell joins
    /// or leaves the zone), the contact jumps in at zero force and off at the
    /// least force the unloading holds. A cycle of a flat punch (the
    /// [`FlatPunch`](IndenterSpec::FlatPunch) spec, tilted or not, a height
    /// map or a custom indenter: its contact pinned at the rim, where the
    /// zone cannot form) unloads along the punch's peeling path by the
    /// local criterion from the contact bonded at the peak, the whole face
    /// or a part of it that reaches the rim
    /// ([`ContactSolver::peel_punch_from`](crate::solver::ContactSolver::peel_punch_from)),
    /// under displacement or force control.
    CohesiveZone,
}

impl AdhesionMethod {
    /// Its name in scene files: `"auto"`, `"energy_balance"`,
    /// `"mesh_criterion"` or `"cohesive_zone"`.
    ///
    /// ```
    /// use layered_contact::scene::AdhesionMethod;
    ///
    /// assert_eq!(AdhesionMethod::CohesiveZone.name(), "cohesive_zone");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            AdhesionMethod::Auto => "auto",
            AdhesionMethod::EnergyBalance => "energy_balance",
            AdhesionMethod::MeshCriterion => "mesh_criterion",
            AdhesionMethod::CohesiveZone => "cohesive_zone",
        }
    }
}

impl Default for SolverSettings {
    fn default() -> Self {
        SolverSettings {
            tolerance: 1e-8,
            max_iterations: 10_000,
            pull_off_bisections: 10,
            adhesion_method: AdhesionMethod::default(),
        }
    }
}

/// A contact experiment. See the [module docs](self).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Scene {
    /// The body.
    pub substrate: SubstrateSpec,
    /// The indenter.
    pub indenter: IndenterSpec,
    /// An optional small tilt of the indenter.
    #[cfg_attr(feature = "serde", serde(default))]
    pub tilt: Option<Tilt>,
    /// Adhesion (none by default).
    #[cfg_attr(feature = "serde", serde(default))]
    pub adhesion: Adhesion,
    /// Isolated (default) or periodic.
    #[cfg_attr(feature = "serde", serde(default))]
    pub boundary: Boundary,
    /// How the indenter is driven.
    pub protocol: Protocol,
    /// Grid resolution.
    #[cfg_attr(feature = "serde", serde(default))]
    pub resolution: Resolution,
    /// What to keep.
    #[cfg_attr(feature = "serde", serde(default))]
    pub outputs: Outputs,
    /// Solver settings.
    #[cfg_attr(feature = "serde", serde(default))]
    pub solver: SolverSettings,
}

impl Default for Scene {
    /// A 1 mm flat punch pressed 10 um into a rubber half-space (E = 1 MPa,
    /// nu = 0.5): a starting point for struct-update syntax.
    fn default() -> Self {
        Scene {
            substrate: SubstrateSpec::HalfSpace {
                youngs_modulus: 1e6,
                poisson_ratio: 0.5,
            },
            indenter: IndenterSpec::FlatPunch { radius: 1e-3 },
            tilt: None,
            adhesion: Adhesion::None,
            boundary: Boundary::Isolated,
            protocol: Protocol::Depth { depth: 1e-5 },
            resolution: Resolution::default(),
            outputs: Outputs::default(),
            solver: SolverSettings::default(),
        }
    }
}

/// Bounds on a scene's work, so that no input can run forever.
pub(super) const MAX_PROTOCOL_STEPS: usize = 100_000;

/// The error of a force cycle whose unloading is still attached after
/// [`MAX_PROTOCOL_STEPS`] decrements of `decrement` (N): the protocol's
/// step is too small for the pull-off, a limit of the input rather than a
/// failed iteration (a punch tilted by 1 mrad, cycled to 1 pN in 3 steps,
/// walked its peeling path for 70 s before it said so, as `NoConvergence`
/// until 2026-12-02). [`Scene::validate`] refuses such cycles at once
/// where a closed form or exact solution bounds the pull-off.
pub(super) fn pull_off_beyond_steps(decrement: f64) -> Error {
    Error::InvalidParameter {
        name: "protocol.max_force / steps (N)",
        value: decrement,
        expected: "a force step that reaches the pull-off within 100000 unloading steps (the \
                   unloading was still attached after them: raise max_force or lower steps)",
    }
}
/// Unloading past zero depth stops after this many times the loading depth
/// (a contact so sticky that it holds beyond is reported, not followed
/// forever). The increments double beyond one loading depth, so the bound
/// costs about a dozen steps; at 20 loading depths, as before, a rough
/// film pressed 1 or 10 nm into contact (a jump-in under adhesion, the
/// contact held to 0.8 to 1 um above the surface) was refused.
pub(super) const MAX_PULL_DEPTHS: f64 = 4096.0;
const MAX_GRID_GROWTH: usize = 4;
const MIN_CELLS_ACROSS: usize = 8;
const MAX_MARGIN: f64 = 10.0;
const MAX_BISECTIONS: usize = 60;

impl Scene {
    /// Checks the scene without solving it.
    ///
    /// # Errors
    /// The first invalid value, as a typed error.
    pub fn validate(&self) -> Result<()> {
        if matches!(self.indenter, IndenterSpec::RoughSurface { .. }) {
            // Its parameters, without synthesising it: a surface of 32768
            // cells a side takes minutes and 25 GB, and `check` runs on a
            // cluster's login node.
            self.indenter.map_grid()?;
            if let Some(tilt) = self.tilt {
                crate::indenter::tilt::check_angles(tilt.angle_y, tilt.angle_x)?;
            }
        } else {
            self.indenter.build(self.tilt)?;
        }
        self.validate_settings()
    }

    /// Checks everything but the indenter (whose map may be costly to read).
    fn validate_settings(&self) -> Result<()> {
        let substrate = self.substrate.build()?;
        self.outputs.stresses.plane_depths(&substrate)?;
        if let Some((loading, unloading)) = self.adhesion.works() {
            crate::error::works_of_adhesion(loading, unloading)?;
        }
        match self.protocol {
            Protocol::Depth { depth } => {
                crate::solver::check_finite("depth", depth)?;
            }
            Protocol::Force { force } => {
                crate::error::non_negative_finite("force", force)?;
            }
            Protocol::Cycle { max_depth, steps } => {
                positive_finite("max_depth", max_depth)?;
                check_steps(steps)?;
            }
            Protocol::ForceCycle { max_force, steps } => {
                positive_finite("max_force", max_force)?;
                check_steps(steps)?;
                // The unloading walks down by the same decrement to the
                // pull-off: where that lies beyond the protocol's bound
                // of steps, say so now rather than after hours of solves.
                let increment = max_force / steps as f64;
                if let Some(bound) = self.pull_off_bound(&substrate) {
                    if (max_force + bound) / increment > MAX_PROTOCOL_STEPS as f64 {
                        return Err(Error::InvalidParameter {
                            name: "protocol.max_force / steps (N)",
                            value: increment,
                            expected: "a force step that reaches the pull-off within 100000 \
                                       unloading steps (a tenth of the pull-off of the closed \
                                       form or exact solution already lies beyond them: raise \
                                       max_force or lower steps)",
                        });
                    }
                }
            }
        }
        let method = self.resolved_adhesion_method();
        let forced = matches!(
            self.protocol,
            Protocol::Force { .. } | Protocol::ForceCycle { .. }
        );
        if self.adhesion != Adhesion::None && forced && method == AdhesionMethod::MeshCriterion {
            return Err(Error::Unsupported {
                feature: "force control with the mesh-dependent adhesion criterion",
                reason: "use the energy balance or the cohesive zone for adhesive force control",
            });
        }
        crate::error::within(
            "cells_across",
            self.resolution.cells_across as f64,
            (MIN_CELLS_ACROSS as f64, 8192.0),
            "between 8 and 8192 (fewer cells cannot describe a contact)",
        )?;
        let margin = crate::error::non_negative_finite("margin", self.resolution.margin)?;
        if margin > MAX_MARGIN {
            return Err(Error::InvalidParameter {
                name: "margin",
                value: margin,
                expected: "at most 10 contact diameters",
            });
        }
        positive_finite("tolerance", self.solver.tolerance)?;
        if self.solver.pull_off_bisections > MAX_BISECTIONS {
            return Err(Error::InvalidParameter {
                name: "pull_off_bisections",
                value: self.solver.pull_off_bisections as f64,
                expected: "at most 60 (2^-60 of an increment is below f64 resolution)",
            });
        }
        Ok(())
    }

    /// Makes a relative height-map path relative to `folder` (the folder of
    /// the scene file it was read from), as front-ends do.
    pub fn resolve_paths(&mut self, folder: &std::path::Path) {
        if let IndenterSpec::HeightMap { path, .. } = &mut self.indenter {
            if path.is_relative() {
                *path = folder.join(&*path);
            }
        }
    }
}

fn check_steps(steps: usize) -> Result<()> {
    if (1..=MAX_PROTOCOL_STEPS).contains(&steps) {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name: "steps",
            value: steps as f64,
            expected: "between 1 and 100000",
        })
    }
}
