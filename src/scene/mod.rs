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
//! TOML or JSON; see the `run_scene` example.
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
mod curve;
mod spec;

pub use accuracy::{richardson, Converged, Quantity};
pub use curve::{Curve, Phase, Step};
pub use spec::{Adhesion, IndenterSpec, SubstrateSpec, Tilt};

use crate::error::{positive_finite, Error, Result};
use crate::grid::{Boundary, Grid};
use crate::indenter::Indenter;
use crate::solver::{ContactSolver, Fields, Solution, SolverParams, WarmStart};

/// How the indenter is driven.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// One non-adhesive solve at total force `force` (N).
    Force {
        /// Force, N.
        force: f64,
    },
    /// Displacement control: from depth 0 to `max_depth` in `steps` equal
    /// increments, then back out with the same increment until the contact
    /// is lost; the pull-off depth is located by bisection. A contact still
    /// attached at `-20 max_depth` ends the run with
    /// [`Error::NoConvergence`].
    Cycle {
        /// Maximum depth, m.
        max_depth: f64,
        /// Increments of the loading branch.
        steps: usize,
    },
    /// Force control (non-adhesive): up to `max_force` in `steps`
    /// increments and back down to zero.
    ForceCycle {
        /// Maximum force, N.
        max_force: f64,
        /// Increments of the loading branch.
        steps: usize,
    },
}

/// How fine the grid is.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct Resolution {
    /// Cells across the largest contact diameter the protocol reaches (the
    /// punch diameter, or the Hertz estimate for curved indenters).
    pub cells_across: usize,
    /// Extra width around that contact, as a fraction of its diameter
    /// (curved indenters only; the grid grows if the contact reaches its edge).
    pub margin: f64,
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
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct Outputs {
    /// Fields of the most loaded step to keep in [`Curve::peak`].
    pub fields: Fields,
}

/// Solver settings of a scene.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct SolverSettings {
    /// See [`SolverParams::tolerance`].
    pub tolerance: f64,
    /// See [`SolverParams::max_iterations`].
    pub max_iterations: usize,
    /// Bisection steps that locate the pull-off depth of a cycle.
    pub pull_off_bisections: usize,
}

impl Default for SolverSettings {
    fn default() -> Self {
        SolverSettings {
            tolerance: 1e-8,
            max_iterations: 10_000,
            pull_off_bisections: 10,
        }
    }
}

/// A contact experiment. See the [module docs](self).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
const MAX_PROTOCOL_STEPS: usize = 100_000;
/// Unloading past zero depth stops after this many times the loading depth
/// (a contact so sticky that it holds beyond is reported, not followed forever).
const MAX_PULL_DEPTHS: f64 = 20.0;
const MAX_GRID_GROWTH: usize = 4;

impl Scene {
    /// Checks the scene without solving it.
    ///
    /// # Errors
    /// The first invalid value, as a typed error.
    pub fn validate(&self) -> Result<()> {
        self.substrate.build()?;
        self.indenter.build(self.tilt)?;
        if let Some((loading, unloading)) = self.adhesion.works() {
            crate::error::non_negative_finite("work_of_adhesion (loading)", loading)?;
            crate::error::non_negative_finite("work_of_adhesion (unloading)", unloading)?;
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
            }
        }
        if self.adhesion != Adhesion::None
            && matches!(
                self.protocol,
                Protocol::Force { .. } | Protocol::ForceCycle { .. }
            )
        {
            return Err(Error::Unsupported {
                feature: "force control with adhesion",
                reason: "adhesive scenes are displacement-controlled (depth or cycle protocols)",
            });
        }
        if !(self.resolution.cells_across >= 2 && self.resolution.cells_across <= 8192) {
            return Err(Error::InvalidParameter {
                name: "cells_across",
                value: self.resolution.cells_across as f64,
                expected: "between 2 and 8192",
            });
        }
        crate::error::non_negative_finite("margin", self.resolution.margin)?;
        positive_finite("tolerance", self.solver.tolerance)?;
        Ok(())
    }

    /// The radius (m) of the largest contact the protocol should reach, for
    /// sizing the grid.
    fn contact_radius_estimate(&self) -> Result<f64> {
        let substrate = self.substrate.build()?;
        let softest = match &substrate {
            crate::substrate::Substrate::HalfSpace(m) => m.contact_modulus(),
            crate::substrate::Substrate::Coated(c) => match c.base() {
                crate::substrate::Base::Elastic(b) => {
                    b.contact_modulus().min(c.layer().contact_modulus())
                }
                crate::substrate::Base::Rigid => c.layer().contact_modulus(),
            },
        };
        Ok(match (self.indenter, self.protocol) {
            (IndenterSpec::FlatPunch { radius }, _) => radius,
            (IndenterSpec::Sphere { radius } | IndenterSpec::Paraboloid { radius }, protocol) => {
                let (target, by_force) = match protocol {
                    Protocol::Depth { depth } => (depth.abs(), false),
                    Protocol::Cycle { max_depth, .. } => (max_depth, false),
                    Protocol::Force { force } => (force, true),
                    Protocol::ForceCycle { max_force, .. } => (max_force, true),
                };
                let hertz = if by_force {
                    (0.75 * target * radius / softest).cbrt()
                } else {
                    (radius * target).sqrt()
                };
                let estimate = match &substrate {
                    crate::substrate::Substrate::Coated(coating) => exact_contact_radius(
                        &substrate,
                        coating.thickness(),
                        radius,
                        target,
                        by_force,
                        hertz,
                    )
                    .unwrap_or(1.5 * hertz),
                    crate::substrate::Substrate::HalfSpace(_) => hertz,
                };
                estimate.min(radius).max(f64::MIN_POSITIVE)
            }
            (
                IndenterSpec::Cone {
                    half_angle,
                    base_radius,
                },
                protocol,
            ) => {
                let depth = match protocol {
                    Protocol::Depth { depth } => depth.abs(),
                    Protocol::Cycle { max_depth, .. } => max_depth,
                    Protocol::Force { force }
                    | Protocol::ForceCycle {
                        max_force: force, ..
                    } => (0.5 * std::f64::consts::PI * force / (softest * half_angle.tan())).sqrt(),
                };
                (2.0 * depth * half_angle.tan() / std::f64::consts::PI).min(base_radius)
            }
        })
    }

    /// The grid the scene is solved on (before any growth).
    ///
    /// # Errors
    /// As [`Scene::validate`].
    ///
    /// Grid sizes are rounded up to products of 2, 3, 5 and 7 (fast FFTs).
    /// For a flat punch (untilted or not) the spacing is adjusted within 2 %
    /// of `2a / cells_across` so that the cells whose centres lie on the
    /// punch have the punch's area: the staircase punch then has the right
    /// radius on average, and the stiffness converges smoothly like `1/N`
    /// instead of oscillating with the staircase.
    pub fn grid(&self) -> Result<Grid> {
        self.validate()?;
        let radius = self.contact_radius_estimate()?;
        let n = self.resolution.cells_across;
        match self.indenter {
            IndenterSpec::FlatPunch { radius } => {
                let cells = fft_friendly(n + 2);
                Grid::new(cells, cells, equal_area_spacing(radius, n, cells))
            }
            _ => {
                let cells = (n as f64 * (1.0 + 2.0 * self.resolution.margin)).ceil() as usize;
                let cells = fft_friendly(cells);
                Grid::new(cells, cells, 2.0 * radius / n as f64)
            }
        }
    }

    /// A solver for this scene's substrate on `grid`.
    fn solver_on(&self, grid: &Grid) -> Result<ContactSolver> {
        let params = SolverParams {
            tolerance: self.solver.tolerance,
            max_iterations: self.solver.max_iterations,
            fields: Fields::default(),
        };
        ContactSolver::new(&self.substrate.build()?, grid, self.boundary, params)
    }

    /// Builds the kernel and FFT plans for this scene (the expensive part),
    /// to pass to [`Scene::run_on`] once or many times.
    ///
    /// # Errors
    /// As [`Scene::validate`].
    pub fn solver(&self) -> Result<ContactSolver> {
        self.solver_on(&self.grid()?)
    }

    /// Runs the scene, reporting each step to `progress`.
    ///
    /// # Errors
    /// Invalid scenes, and solver failures (typed, with residuals).
    pub fn run(&self, progress: &mut dyn FnMut(&Step)) -> Result<Curve> {
        let mut solver = self.solver()?;
        self.run_on(&mut solver, progress)
    }

    /// Runs the scene on a solver built by [`Scene::solver`] (or shared with
    /// another scene on the same substrate and grid). A curved indenter whose
    /// contact reaches the edge of the grid restarts on a grid 1.5 times as
    /// wide with the same spacing (at most four times).
    ///
    /// # Errors
    /// As [`Scene::run`].
    pub fn run_on(
        &self,
        solver: &mut ContactSolver,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<Curve> {
        self.validate()?;
        let indenter = self.indenter.build(self.tilt)?;
        let mut grown: Option<ContactSolver> = None;
        for _ in 0..=MAX_GRID_GROWTH {
            let active = grown.as_mut().unwrap_or(&mut *solver);
            match Runner::new(self, active, &indenter).run(progress)? {
                Outcome::Done(curve) => return Ok(*curve),
                Outcome::ReachedEdge => {
                    let grid = *active.grid();
                    let cells = fft_friendly((grid.rows() * 3).div_ceil(2));
                    grown = Some(self.solver_on(&Grid::new(cells, cells, grid.spacing())?)?);
                }
            }
        }
        Err(Error::InvalidParameter {
            name: "resolution.margin",
            value: self.resolution.margin,
            expected: "a grid that holds the contact (it still reached the edge after growing)",
        })
    }
}

/// The smallest number of cells `>= n` whose prime factors are 2, 3, 5 and 7
/// only: FFTs of such (padded) lengths are several times faster than of
/// lengths with a large prime factor.
fn fft_friendly(n: usize) -> usize {
    (n.max(1)..)
        .find(|&m| {
            let mut rest = m;
            for p in [2, 3, 5, 7] {
                while rest % p == 0 {
                    rest /= p;
                }
            }
            rest == 1
        })
        .unwrap_or(n)
}

/// A spacing within 2 % of `2 radius / n` for which the cells of a
/// `cells`-square grid whose centres lie within `radius` of its centre cover
/// the disc's area most closely.
fn equal_area_spacing(radius: f64, n: usize, cells: usize) -> f64 {
    let half = 0.5 * cells as f64;
    let area_error = |spacing: f64| {
        let inside = (0..cells * cells)
            .filter(|c| {
                let x = ((c / cells) as f64 + 0.5 - half) * spacing;
                let y = ((c % cells) as f64 + 0.5 - half) * spacing;
                x.hypot(y) <= radius
            })
            .count() as f64;
        (inside * spacing * spacing / (std::f64::consts::PI * radius * radius) - 1.0).abs()
    };
    let nominal = 2.0 * radius / n as f64;
    (0..=80)
        .map(|k| nominal * (0.98 + 0.0005 * k as f64))
        .min_by(|a, b| area_error(*a).total_cmp(&area_error(*b)))
        .unwrap_or(nominal)
}

/// The contact radius of a paraboloid of tip radius `radius` at depth (or
/// force) `target` on a coated substrate, from the exact axisymmetric
/// solution (bisection on the contact radius); `None` if it cannot be found
/// (then the caller falls back to Hertz).
fn exact_contact_radius(
    substrate: &crate::substrate::Substrate,
    thickness: f64,
    radius: f64,
    target: f64,
    by_force: bool,
    hertz: f64,
) -> Option<f64> {
    let upper = (2.0 * hertz).min(radius);
    let exact = crate::analytic::Axisymmetric::new(
        substrate,
        (upper / thickness).min(crate::analytic::Axisymmetric::MAX_RADIUS_OVER_THICKNESS),
    )
    .ok()?;
    let ball = exact.paraboloid(radius, 0.0).ok()?;
    let value = |a: f64| {
        ball.at_contact_radius(a)
            .ok()
            .map(|s| if by_force { s.force } else { s.depth })
    };
    if value(upper)? < target {
        return Some(upper);
    }
    let (mut lo, mut hi) = (0.0, upper);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if value(mid)? < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(hi)
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

enum Outcome {
    Done(Box<Curve>),
    ReachedEdge,
}

/// The state of one run of a scene.
struct Runner<'a> {
    scene: &'a Scene,
    solver: &'a mut ContactSolver,
    indenter: &'a dyn Indenter,
    steps: Vec<Step>,
    peak: Option<Solution>,
    warm: Option<WarmStart>,
    /// Whether curved-indenter contacts must stay off the grid's edge.
    watch_edge: bool,
}

impl<'a> Runner<'a> {
    fn new(
        scene: &'a Scene,
        solver: &'a mut ContactSolver,
        indenter: &'a (dyn Indenter + Send + Sync),
    ) -> Self {
        Runner {
            scene,
            solver,
            indenter,
            steps: Vec::new(),
            peak: None,
            warm: None,
            watch_edge: !matches!(scene.indenter, IndenterSpec::FlatPunch { .. })
                && scene.boundary == Boundary::Isolated,
        }
    }

    /// One solve at `depth` (or force), warm-started from the last. With
    /// adhesion the contact edge advances against the loading and recedes
    /// against the unloading work of adhesion, in either phase.
    fn solve(&mut self, control: Control) -> Result<Solution> {
        let warm = self.warm.as_ref();
        let (solution, warm) =
            match (control, self.scene.adhesion.works()) {
                (Control::Depth(d), None) => {
                    self.solver.solve_depth(self.indenter, d, warm, &mut ())?
                }
                (Control::Force(f), None) => {
                    self.solver.solve_force(self.indenter, f, warm, &mut ())?
                }
                (Control::Depth(d), Some((loading, unloading))) => self
                    .solver
                    .solve_depth_hysteretic(self.indenter, d, loading, unloading, warm, &mut ())?,
                (Control::Force(_), Some(_)) => {
                    unreachable!("validated: adhesion needs displacement control")
                }
            };
        self.warm = Some(warm);
        Ok(solution)
    }

    fn touches_edge(&self) -> bool {
        let Some(warm) = &self.warm else { return false };
        let grid = self.solver.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        (0..rows * columns).any(|c| {
            let (i, j) = (c / columns, c % columns);
            (i == 0 || j == 0 || i + 1 == rows || j + 1 == columns) && warm.is_attached(c)
        })
    }

    /// Records a step; false if the contact reached the grid's edge.
    fn record(
        &mut self,
        solution: Solution,
        phase: Phase,
        progress: &mut dyn FnMut(&Step),
    ) -> bool {
        if self.watch_edge && self.touches_edge() {
            return false;
        }
        let step = Step::new(phase, &solution);
        progress(&step);
        self.steps.push(step);
        true
    }

    /// [`Runner::solve`] at the most loaded point: keeps the requested fields
    /// of this very solve as the curve's peak.
    fn solve_peak(&mut self, control: Control) -> Result<Solution> {
        let fields = self.scene.outputs.fields;
        if fields == Fields::default() {
            return self.solve(control);
        }
        let params = *self.solver.params();
        self.solver.set_params(SolverParams { fields, ..params });
        let result = self.solve(control);
        self.solver.set_params(params);
        let solution = result?;
        self.peak = Some(solution.clone());
        Ok(solution)
    }

    fn run(mut self, progress: &mut dyn FnMut(&Step)) -> Result<Outcome> {
        match self.scene.protocol {
            Protocol::Depth { depth } => {
                let s = self.solve_peak(Control::Depth(depth))?;
                if !self.record(s, Phase::Loading, progress) {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::Force { force } => {
                let s = self.solve_peak(Control::Force(force))?;
                if !self.record(s, Phase::Loading, progress) {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::Cycle { max_depth, steps } => {
                let increment = max_depth / steps as f64;
                for k in 0..=steps {
                    let control = Control::Depth(k as f64 * increment);
                    let s = if k == steps {
                        self.solve_peak(control)?
                    } else {
                        self.solve(control)?
                    };
                    if !self.record(s, Phase::Loading, progress) {
                        return Ok(Outcome::ReachedEdge);
                    }
                }
                if !self.unload(max_depth, increment, progress)? {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::ForceCycle { max_force, steps } => {
                let increment = max_force / steps as f64;
                let forces = (0..=steps).chain((0..steps).rev());
                for (n, k) in forces.enumerate() {
                    let phase = if n <= steps {
                        Phase::Loading
                    } else {
                        Phase::Unloading
                    };
                    let control = Control::Force(k as f64 * increment);
                    let s = if n == steps {
                        self.solve_peak(control)?
                    } else {
                        self.solve(control)?
                    };
                    if !self.record(s, phase, progress) {
                        return Ok(Outcome::ReachedEdge);
                    }
                }
            }
        }
        Ok(Outcome::Done(Box::new(Curve {
            steps: self.steps,
            grid: *self.solver.grid(),
            peak: self.peak,
        })))
    }

    /// Retracts from `max_depth` by `increment` until the contact is lost.
    /// The step in which the contact first shrinks and the step in which it
    /// is lost are each refined by bisection, so that the pull-off force is
    /// found even when the curve turns within one increment.
    fn unload(
        &mut self,
        max_depth: f64,
        increment: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let mut depth = max_depth;
        let mut cells = self.last_contact_cells();
        let mut shrinking_refined = false;
        let limit = (MAX_PULL_DEPTHS * max_depth / increment).ceil() as usize + 1;
        for _ in 0..limit {
            let before = self.warm.clone();
            let solution = self.solve(Control::Depth(depth - increment))?;
            let lost = solution.contact_cells == 0;
            let shrinks = solution.contact_cells < cells;
            if lost || (shrinks && !shrinking_refined) {
                // Bisect between `depth` (state `before`) and `depth - increment`.
                let after = self.warm.take();
                self.warm = before;
                if !self.bisect(depth, depth - increment, cells, lost, progress)? {
                    return Ok(false);
                }
                shrinking_refined = true;
                if lost {
                    let s = self.solve(Control::Depth(depth - increment))?;
                    self.record(s, Phase::Unloading, progress);
                    return Ok(true);
                }
                self.warm = after;
            }
            depth -= increment;
            cells = solution.contact_cells;
            if !self.record(solution, Phase::Unloading, progress) {
                return Ok(false);
            }
        }
        Err(Error::NoConvergence {
            method:
                "unloading to contact loss (still attached 20 loading depths above the surface)",
            iterations: limit,
            residual: depth,
        })
    }

    fn last_contact_cells(&self) -> usize {
        self.warm.as_ref().map_or(0, WarmStart::attached_cells)
    }

    /// Bisects `(lower, upper)` for the depth where the contact first holds
    /// fewer than `cells` cells (or none, if `to_loss`), recording the states
    /// on the near side. Leaves the warm start at the last such state.
    fn bisect(
        &mut self,
        upper: f64,
        lower: f64,
        cells: usize,
        to_loss: bool,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let (mut near, mut far) = (upper, lower);
        let mut near_state = self.warm.clone();
        for _ in 0..self.scene.solver.pull_off_bisections {
            let middle = 0.5 * (near + far);
            self.warm = near_state.clone();
            let s = self.solve(Control::Depth(middle))?;
            let crossed = if to_loss {
                s.contact_cells == 0
            } else {
                s.contact_cells < cells
            };
            if crossed {
                far = middle;
            } else {
                near = middle;
                near_state = self.warm.clone();
                if !self.record(s, Phase::Unloading, progress) {
                    return Ok(false);
                }
            }
        }
        self.warm = near_state;
        Ok(true)
    }
}

/// The prescribed quantity of one solve.
#[derive(Clone, Copy)]
enum Control {
    Depth(f64),
    Force(f64),
}
