//! The step-by-step runner: non-adhesive protocols and adhesive ones with
//! the mesh-dependent criterion or the cohesive zone, one warm-started
//! solve per step.

use crate::error::{Error, Result};
use crate::grid::Boundary;
use crate::indenter::Indenter;
use crate::solver::{
    CohesiveZone, ContactSolver, Fields, Observer, Solution, SolverParams, WarmStart,
};

mod cohesive;
mod cohesive_force;
mod peeled;

use super::{Curve, IndenterSpec, Phase, Protocol, Scene, Step, MAX_PULL_DEPTHS};

pub(super) enum Outcome {
    Done(Box<Curve>),
    ReachedEdge,
    /// The indenter touches at the scene's depth but no cell centre does:
    /// its lowest point (on its axis) lies between cell centres.
    MissesTip,
}

/// The state of one run of a scene.
pub(super) struct Runner<'a> {
    scene: &'a Scene,
    solver: &'a mut ContactSolver,
    indenter: &'a dyn Indenter,
    /// Sees every iteration of the solves.
    observer: &'a mut dyn Observer,
    steps: Vec<Step>,
    peak: Option<Solution>,
    warm: Option<WarmStart>,
    /// Whether curved-indenter contacts must stay off the grid's edge.
    watch_edge: bool,
    /// The cohesive zone's law, when the scene's adhesion takes it.
    cohesive: Option<CohesiveZone>,
    /// The least force of the cohesive solves and the widest patch of its
    /// contact in cells across.
    least_cohesive: Option<(f64, f64)>,
    /// Whether the cohesive unloading ended before the contact was lost
    /// ([`Caveat::CohesiveUnloadingCutShort`](super::Caveat::CohesiveUnloadingCutShort)).
    cut_short: bool,
}

impl<'a> Runner<'a> {
    pub(super) fn new(
        scene: &'a Scene,
        solver: &'a mut ContactSolver,
        indenter: &'a (dyn Indenter + Send + Sync),
        observer: &'a mut dyn Observer,
    ) -> Result<Self> {
        let cohesive = scene.cohesive_zone()?;
        Ok(Runner {
            scene,
            solver,
            indenter,
            observer,
            steps: Vec::new(),
            peak: None,
            warm: None,
            watch_edge: !matches!(scene.indenter, IndenterSpec::FlatPunch { .. })
                && !scene.indenter.is_map()
                && scene.boundary == Boundary::Isolated,
            cohesive,
            least_cohesive: None,
            cut_short: false,
        })
    }

    /// One solve at `depth` (or force), warm-started from the last. With
    /// adhesion the contact edge advances against the loading and recedes
    /// against the unloading work of adhesion, in either phase.
    fn solve(&mut self, control: Control) -> Result<Solution> {
        let warm = self.warm.as_ref();
        let (solution, warm) = match (control, self.scene.adhesion.works(), self.cohesive) {
            (Control::Depth(d), Some(_), Some(zone)) => {
                let (solution, warm) = self.solver.solve_depth_cohesive(
                    self.indenter,
                    d,
                    &zone,
                    warm,
                    self.observer,
                )?;
                self.note_cohesive(&solution, &warm);
                (solution, warm)
            }
            (Control::Depth(d), None, _) => {
                self.solver
                    .solve_depth(self.indenter, d, warm, self.observer)?
            }
            (Control::Force(f), None, _) => {
                self.solver
                    .solve_force(self.indenter, f, warm, self.observer)?
            }
            (Control::Depth(d), Some((loading, unloading)), None) => {
                self.solver.solve_depth_hysteretic(
                    self.indenter,
                    d,
                    loading,
                    unloading,
                    warm,
                    self.observer,
                )?
            }
            // `Scene::validate_settings` refuses the mesh criterion before
            // any solve; the cohesive zone's force steps are depth searches
            // (`force_cohesive`).
            (Control::Force(_), Some(_), cohesive) => {
                return Err(Error::Unsupported {
                    feature: if cohesive.is_some() {
                        "one force-controlled solve through the cohesive zone"
                    } else {
                        "force control with the mesh-dependent adhesion criterion"
                    },
                    reason: "use the energy-balance method or the cohesive zone's force protocols",
                })
            }
        };
        self.warm = Some(warm);
        Ok(solution)
    }

    /// Keeps the widest patch of a cohesive equilibrium's contact if its
    /// force is the least so far (and tensile): the caveat that the zone
    /// spans the contact at the pull-off reads it.
    fn note_cohesive(&mut self, solution: &Solution, state: &WarmStart) {
        if solution.force < self.least_cohesive.map_or(0.0, |(force, _)| force) {
            let across = self.solver.widest_contact_patch(state);
            self.least_cohesive = Some((solution.force, across));
        }
    }

    /// Records a step; false if the contact reached the grid's edge.
    fn record(
        &mut self,
        solution: Solution,
        phase: Phase,
        progress: &mut dyn FnMut(&Step),
    ) -> bool {
        if self.watch_edge && solution.edge_contact {
            return false;
        }
        let step = Step::new(phase, &solution);
        progress(&step);
        self.steps.push(step);
        true
    }

    /// Whether the state the loading left bonds a face at its rim (a punch,
    /// where the cohesive zone cannot form beyond it): its unloading is the
    /// peeling path's.
    fn bonded_at_rim(&self) -> bool {
        self.warm
            .as_ref()
            .is_some_and(|state| self.solver.bonded_at_rim(state))
    }

    /// Records the unloading's step without contact at `depth`, after a
    /// jump-off under force control, and forgets the history.
    fn record_jump_off(&mut self, depth: f64, progress: &mut dyn FnMut(&Step)) {
        let free = Step {
            phase: Phase::Unloading,
            depth,
            force: 0.0,
            contact_area: 0.0,
            contact_radius: 0.0,
            iterations: 0,
        };
        progress(&free);
        self.steps.push(free);
        self.warm = None;
    }

    /// [`Runner::solve`] at the most loaded point: keeps the requested fields
    /// of this very solve as the curve's peak.
    fn solve_peak(&mut self, control: Control, above: Option<f64>) -> Result<Solution> {
        let (solution, kept) =
            self.with_kept_fields(|runner| runner.solve_after(above, control))?;
        if kept {
            self.peak = Some(solution.clone());
        }
        Ok(solution)
    }

    /// `work` with the solver keeping the fields the scene's outputs ask
    /// for (its parameters restored after), and whether it asks for any.
    fn with_kept_fields<T>(
        &mut self,
        work: impl FnOnce(&mut Self) -> Result<T>,
    ) -> Result<(T, bool)> {
        let fields = self.scene.outputs.kept_fields();
        if fields == Fields::default() {
            return Ok((work(self)?, false));
        }
        let params = *self.solver.params();
        self.solver.set_params(SolverParams { fields, ..params });
        let result = work(self);
        self.solver.set_params(params);
        Ok((result?, true))
    }

    pub(super) fn run(mut self, progress: &mut dyn FnMut(&Step)) -> Result<Outcome> {
        match self.scene.protocol {
            Protocol::Depth { depth } => {
                let s = self.solve_peak(Control::Depth(depth), None)?;
                if !self.record(s, Phase::Loading, progress) {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::Force { force } if self.cohesive.is_some() => {
                if !self.force_cohesive(force, 1, false, progress)? {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::ForceCycle { max_force, steps } if self.cohesive.is_some() => {
                if !self.force_cohesive(max_force, steps, true, progress)? {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::Force { force } => {
                let s = self.solve_peak(Control::Force(force), None)?;
                if !self.record(s, Phase::Loading, progress) {
                    return Ok(Outcome::ReachedEdge);
                }
            }
            Protocol::Cycle { max_depth, steps } => {
                let increment = max_depth / steps as f64;
                for k in 0..=steps {
                    let control = Control::Depth(k as f64 * increment);
                    // The step before's depth, for the cohesive zone's substeps.
                    let above = k.checked_sub(1).map(|j| j as f64 * increment);
                    let s = if k == steps {
                        self.solve_peak(control, above)?
                    } else {
                        self.solve_after(above, control)?
                    };
                    if !self.record(s, Phase::Loading, progress) {
                        return Ok(Outcome::ReachedEdge);
                    }
                }
                // Unloading starts at the peak itself, so that the loop closes.
                if let Some(peak) = self.steps.last().copied() {
                    let step = Step {
                        phase: Phase::Unloading,
                        iterations: 0,
                        ..peak
                    };
                    progress(&step);
                    self.steps.push(step);
                }
                let unloaded = if self.cohesive.is_some() {
                    self.unload_cohesive(max_depth, increment, progress)?
                } else {
                    self.unload(max_depth, increment, progress)?
                };
                if !unloaded {
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
                        self.solve_peak(control, None)?
                    } else {
                        self.solve(control)?
                    };
                    if !self.record(s, phase, progress) {
                        return Ok(Outcome::ReachedEdge);
                    }
                }
            }
        }
        // A pinned pull-off through the zone (`Caveat::CohesivePinnedPullOff`):
        // with hysteresis, of an indenter that is neither a flat punch (its
        // face pins the contact; within 0.9 % at 16 cells) nor a rough
        // surface (`Caveat::CohesiveZoneOnRoughSurface` says more).
        let pinned = self.cohesive.is_some()
            && self.scene.adhesion.works().is_some_and(|(a, r)| r > a)
            && !matches!(
                self.scene.indenter,
                IndenterSpec::FlatPunch { .. } | IndenterSpec::RoughSurface { .. }
            );
        let substrate = self.solver.substrate();
        let soft_below = substrate.surface_material().contact_modulus()
            >= super::SOFT_BELOW_CONTRAST * substrate.softest_contact_modulus();
        let peak_radius = super::caveat::peak_radius(&self.steps);
        let mut curve = Curve {
            steps: self.steps,
            grid: *self.solver.grid(),
            peak: self.peak,
            // The step-by-step runner's adhesion is the mesh-dependent
            // criterion's or the cohesive zone's.
            caveats: match (self.scene.adhesion.works(), self.cohesive) {
                (Some(_), None) => vec![super::Caveat::MeshDependentAdhesion],
                (Some(_), Some(zone)) => super::caveat::cohesive(
                    &zone,
                    substrate,
                    (self.solver.grid().spacing(), peak_radius),
                    (&self.scene.indenter, self.scene.untilted()),
                    self.least_cohesive.map(|(_, across)| across),
                ),
                _ => Vec::new(),
            },
            stresses: None,
        };
        if pinned && (soft_below || curve.came_off_pinned()) {
            curve.caveats.push(super::Caveat::CohesivePinnedPullOff);
        }
        if self.cut_short {
            curve.caveats.push(super::Caveat::CohesiveUnloadingCutShort);
        }
        Ok(Outcome::Done(Box::new(curve)))
    }

    /// Retracts from `max_depth` by `increment` until the contact is lost.
    /// The step in which the contact first shrinks and the step in which it
    /// is lost are each refined by bisection, so that the pull-off force is
    /// found even when the curve turns within one increment. Beyond
    /// `-max_depth` the increment doubles at each step, so that a contact
    /// that holds far above the surface costs a few dozen solves, not thousands
    /// (to [`Runner::pull_reach`]).
    fn unload(
        &mut self,
        max_depth: f64,
        increment: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let mut depth = max_depth;
        let mut cells = self.last_contact_cells();
        let mut shrinking_refined = false;
        let mut increment = increment;
        let reach = self.pull_reach(max_depth);
        let limit = unloading_steps(max_depth, increment, reach);
        for _ in 0..limit {
            let Some(next) = next_increment(depth, increment, max_depth, reach) else {
                break;
            };
            increment = next;
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
        Err(still_attached(limit, depth))
    }

    /// How far above the surface (m, positive) an unloading from
    /// `max_depth` follows a contact that still holds: `MAX_PULL_DEPTHS`
    /// loading depths, or four times the pull-off depth of Kendall's flat
    /// punch (1971, J. Phys. D 4, 1186: `sqrt(2 pi dgamma a / E*)`) as wide
    /// as the grid's diagonal on a half-space of the body's softest
    /// material, with the receding work and the cohesive law's range,
    /// whichever is farther. Why the punch bounds the others in the JKR
    /// limit (an argument, not a proof): a bonded cell's surface is pulled
    /// up by at least the depth (its gap is closed over an indenter whose
    /// lowest point is at the depth), the punch pulls its whole face by
    /// exactly that, and no bonded patch on the grid is wider; the factor
    /// four covers the rest (layers no softer than their softest material,
    /// the mesh criterion's stronger pull on coarse grids). A sticky flat
    /// punch pressed a few micrometres
    /// comes off tens of thousands of loading depths above the surface (in
    /// the reference sweep's cohesive cases: a 0.2 m punch on a 1 kPa
    /// half-space, 5 um deep, at -0.25 m); it had ended in `NoConvergence`
    /// at 4096.
    fn pull_reach(&self, max_depth: f64) -> f64 {
        let grid = self.solver.grid();
        let half_diagonal =
            0.5 * grid.spacing() * (grid.rows() as f64).hypot(grid.columns() as f64);
        let modulus = self.solver.substrate().softest_contact_modulus();
        let work = self
            .scene
            .adhesion
            .works()
            .map_or(0.0, |(_, receding)| receding);
        let range = self
            .cohesive
            .map_or(0.0, |zone| zone.range(work, grid.spacing(), modulus));
        let kendall = (2.0 * std::f64::consts::PI * work * half_diagonal / modulus).sqrt();
        (MAX_PULL_DEPTHS * max_depth).max(4.0 * (kendall + range))
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

/// The most unloading steps from `max_depth` by `increment`: to `-max_depth`
/// in steps of `increment`, then doubling them to `-reach`.
fn unloading_steps(max_depth: f64, increment: f64, reach: f64) -> usize {
    (2.0 * max_depth / increment).ceil() as usize
        + (reach / increment).log2().ceil().max(0.0) as usize
        + 2
}

/// The increment of the next unloading step from `depth`: doubled beyond
/// `-max_depth`, none beyond `-reach`.
fn next_increment(depth: f64, increment: f64, max_depth: f64, reach: f64) -> Option<f64> {
    if depth < -reach {
        None
    } else if depth < -max_depth {
        Some(2.0 * increment)
    } else {
        Some(increment)
    }
}

// The message of `still_attached` spells the reach out (its `method` is
// a `&'static str`): it must follow the constant.
const _: () = assert!(MAX_PULL_DEPTHS == 4096.0);

/// The error of an unloading that still holds past its reach
/// ([`Runner::pull_reach`]).
fn still_attached(steps: usize, depth: f64) -> Error {
    Error::NoConvergence {
        method: "unloading to contact loss (still attached past the larger of 4096 loading \
                 depths and four times Kendall's pull-off depth of a punch as wide as the grid \
                 on the body's softest material)",
        iterations: steps,
        residual: depth,
    }
}

/// The prescribed quantity of one solve.
#[derive(Clone, Copy)]
enum Control {
    Depth(f64),
    Force(f64),
}
