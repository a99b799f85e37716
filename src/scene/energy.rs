//! Adhesive scenes by the energy balance over the contact edge: the
//! branches are built once per scene ([`ContactSolver::adhesive_branches`]),
//! and every step of the protocol is then an evaluation on them.

use crate::error::{Error, Result};
use crate::indenter::Indenter;
use crate::solver::{AdhesiveBranches, BranchPoint, ContactSolver, Observer, Reach, SolverParams};

use super::method::PUNCH_STIFFNESS_SLOPE;
use super::runner::Outcome;
use super::{
    Caveat, Curve, IndenterSpec, Phase, Protocol, Scene, Step, MAX_PROTOCOL_STEPS, MAX_PULL_DEPTHS,
};

/// Runs an adhesive `scene` with works `(advancing, receding)` on `solver`.
pub(super) fn run(
    scene: &Scene,
    solver: &mut ContactSolver,
    indenter: &(dyn Indenter + Send + Sync),
    (advancing, receding): (f64, f64),
    progress: &mut dyn FnMut(&Step),
    observer: &mut dyn Observer,
) -> Result<Outcome> {
    let reach = scene.protocol.peak();
    let mut recorder = Recorder {
        steps: Vec::new(),
        progress,
        iterations: 0,
        interrupt: solver.interrupt().cloned(),
    };
    if let Reach::Depth(depth) = reach {
        let lowest = solver.lowest_height(indenter)?;
        // An indenter's lowest point is on its axis at height 0: past it, it
        // touches (and a JKR contact jumps in), whether or not a cell centre
        // does. A depth-driven step in between would miss that contact (a
        // paraboloid of 0.73 mm at 16 cells across a 1.2 mm contact: its
        // apex between four centres 6 um below them, a cycle's first step at
        // 4.8 um reported no contact where 32 cells find -1.3 uN): the
        // scene's grid is rebuilt with a centre on the axis. A height map is
        // its own samples.
        let first = match scene.protocol {
            Protocol::Cycle { max_depth, steps } if scene.untilted() => {
                max_depth / steps.max(1) as f64
            }
            _ => depth,
        };
        if first > 0.0 && first <= lowest && !scene.indenter.is_map() {
            return Ok(Outcome::MissesTip);
        }
        if depth <= lowest {
            // The indenter never touches: every step is free.
            recorder.free(Phase::Loading, depth)?;
            return Ok(done(solver, recorder.steps, None, false));
        }
    }
    let branches = match solver.adhesive_branches(indenter, reach, advancing, receding, observer) {
        Err(Error::ContactReachesEdge { .. }) => return Ok(Outcome::ReachedEdge),
        other => other?,
    };
    recorder.iterations = branches.iterations();
    let peak = match scene.protocol {
        Protocol::Depth { depth } => {
            recorder.record(Phase::Loading, branches.at_depth(depth, 0.0)?)?
        }
        Protocol::Force { force } => {
            recorder.record(Phase::Loading, branches.at_force(force, 0.0)?)?
        }
        Protocol::Cycle { max_depth, steps } => cycle(&branches, &mut recorder, max_depth, steps)?,
        Protocol::ForceCycle { max_force, steps } => {
            force_cycle(&branches, &mut recorder, max_force, steps)?
        }
    };
    let fields = scene.outputs.kept_fields();
    let peak_solution = if fields == crate::solver::Fields::default() {
        None
    } else {
        let params = *solver.params();
        solver.set_params(SolverParams { fields, ..params });
        let solution = solver.branch_solution(indenter, &branches, &peak);
        solver.set_params(params);
        Some(solution?)
    };
    // A punch whose stiffness barely changes with its contact
    // (`Caveat::EnergyBalanceFlatStiffness`).
    let flat = matches!(scene.indenter, IndenterSpec::FlatPunch { .. })
        && branches.stiffness_area_slope(branches.max_contact_area()) < PUNCH_STIFFNESS_SLOPE;
    let mut outcome = done(
        solver,
        recorder.steps,
        peak_solution,
        // A tilted paraboloid's sets are discs about its apex (the solver
        // finds them too; the scene knows it without reading the profile).
        branches.edge_averaged() && !scene.contact_sets_are_discs(),
    );
    if let (true, Outcome::Done(curve)) = (flat, &mut outcome) {
        curve.caveats.push(Caveat::EnergyBalanceFlatStiffness);
    }
    Ok(outcome)
}

fn done(
    solver: &ContactSolver,
    steps: Vec<Step>,
    peak: Option<crate::solver::Solution>,
    edge_averaged: bool,
) -> Outcome {
    Outcome::Done(Box::new(Curve {
        steps,
        grid: *solver.grid(),
        peak,
        caveats: if edge_averaged {
            vec![Caveat::EdgeAveragedAdhesion]
        } else {
            Vec::new()
        },
        stresses: None,
    }))
}

/// Collects steps and reports each.
struct Recorder<'p> {
    steps: Vec<Step>,
    progress: &'p mut dyn FnMut(&Step),
    /// Iterations not yet attributed to a step (the branches' cost goes to
    /// the first step).
    iterations: usize,
    /// The solver's interrupt check, asked after every step.
    interrupt: Option<crate::solver::Interrupt>,
}

impl Recorder<'_> {
    fn record(&mut self, phase: Phase, point: BranchPoint) -> Result<BranchPoint> {
        let step = Step {
            phase,
            depth: point.depth,
            force: point.force,
            contact_area: point.contact_area,
            contact_radius: point.contact_radius,
            iterations: std::mem::take(&mut self.iterations),
        };
        (self.progress)(&step);
        self.steps.push(step);
        crate::solver::interrupted(&self.interrupt, "the adhesive scene")?;
        Ok(point)
    }

    fn free(&mut self, phase: Phase, depth: f64) -> Result<BranchPoint> {
        self.record(
            phase,
            BranchPoint {
                depth,
                force: 0.0,
                contact_area: 0.0,
                contact_radius: 0.0,
            },
        )
    }
}

/// The loading branch, steps `0..=steps` of `at(k, history)`, and the peak
/// recorded again as the first unloading step (so that the loop closes).
fn load(
    recorder: &mut Recorder,
    steps: usize,
    at: impl Fn(usize, f64) -> Result<BranchPoint>,
) -> Result<BranchPoint> {
    let mut peak = at(0, 0.0)?;
    recorder.record(Phase::Loading, peak)?;
    for k in 1..=steps {
        peak = recorder.record(Phase::Loading, at(k, peak.contact_area)?)?;
    }
    recorder.record(Phase::Unloading, peak)?;
    Ok(peak)
}

/// Displacement-controlled loading and unloading; returns the peak.
fn cycle(
    branches: &AdhesiveBranches,
    recorder: &mut Recorder,
    max_depth: f64,
    steps: usize,
) -> Result<BranchPoint> {
    let increment = max_depth / steps as f64;
    let peak = load(recorder, steps, |k, area| {
        branches.at_depth(k as f64 * increment, area)
    })?;
    let mut area = peak.contact_area;
    // Exact points of the receding branch: the least force if it lies on the
    // path (above the jump-off), and the jump-off.
    let mut exact = Vec::new();
    // The contact is lost past the jump-off, which for a shallow cycle lies
    // many loading depths above the surface (adhesion sets its scale).
    let mut last_depth = -MAX_PULL_DEPTHS * max_depth;
    if area > 0.0 {
        let jump = branches.jump_off(area)?;
        let pull = branches.pull_off(area)?;
        if pull.contact_area > jump.contact_area && pull.depth > jump.depth {
            exact.push(pull);
        }
        exact.push(jump);
        last_depth = last_depth.min(2.0 * jump.depth);
    }
    let mut exact = exact.into_iter().peekable();
    let mut depth = max_depth;
    let mut step = increment;
    // 2 * steps increments reach -max_depth; doubling the increment from
    // there crosses any finite jump-off depth within the exponent range.
    for _ in 0..2 * steps + 2100 {
        if depth < -max_depth {
            step *= 2.0;
        }
        depth -= step;
        let point = branches.at_depth(depth, area)?;
        while let Some(e) = exact.next_if(|e| e.depth > point.depth && e.contact_area <= area) {
            recorder.record(Phase::Unloading, e)?;
        }
        area = point.contact_area;
        recorder.record(Phase::Unloading, point)?;
        if area == 0.0 {
            return Ok(peak);
        }
        if depth < last_depth {
            break;
        }
    }
    Err(Error::Internal {
        what: "the energy-balance unloading",
        detail: format!(
            "still attached at depth {depth:e} m, where the contact must be lost by \
             {last_depth:e} m (twice the exact jump-off depth, or {MAX_PULL_DEPTHS} loading \
             depths above the surface)"
        ),
    })
}

/// Load-controlled loading and unloading to the pull-off; returns the peak.
fn force_cycle(
    branches: &AdhesiveBranches,
    recorder: &mut Recorder,
    max_force: f64,
    steps: usize,
) -> Result<BranchPoint> {
    let increment = max_force / steps as f64;
    // At zero force the contact jumps in.
    let peak = load(recorder, steps, |k, area| {
        branches.at_force(k as f64 * increment, area)
    })?;
    let mut area = peak.contact_area;
    for k in 1..=MAX_PROTOCOL_STEPS {
        let force = max_force - k as f64 * increment;
        match branches.at_force(force, area) {
            Ok(point) => {
                area = point.contact_area;
                recorder.record(Phase::Unloading, point)?;
            }
            Err(Error::NoEquilibrium { .. }) => {
                let pull = recorder.record(Phase::Unloading, branches.pull_off(area)?)?;
                recorder.free(Phase::Unloading, pull.depth)?;
                return Ok(peak);
            }
            Err(e) => return Err(e),
        }
    }
    Err(super::pull_off_beyond_steps(increment))
}
