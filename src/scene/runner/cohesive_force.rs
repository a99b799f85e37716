//! Force control through the cohesive zone. Each prescribed force is
//! reached first by one fixed point under force control from the path's
//! last equilibrium (`ContactSolver::solve_force_cohesive`, at most
//! [`FORCE_ROUNDS`] rounds; the tilted paraboloid's force cycle in 2.2 to
//! 2.7 times fewer CG iterations than by the search alone, `BENCHMARKS.md`,
//! "Force steps by one fixed point under force control"). Where that does
//! not converge, loses the contact or moves the wrong way, the depth is
//! searched along the displacement-controlled path: steps that double
//! until the force is passed, then regula falsi with the Illinois
//! modification (Dowell & Jarratt 1971, BIT 11, 168). Every trial
//! equilibrium is reached from the last one on the side the step started
//! from, as a quasi-static path reaches it, so that the history (which
//! cells are bonded) is the path's. The contact jumps in at zero force
//! (the protocol starts where the indenter touches); along the unloading a
//! force below the least the contact can hold is the jump-off: the least
//! force is searched as the displacement-controlled unloading's
//! (`solver::least_force`), recorded as the pull-off, and followed by a
//! step without contact, as the energy balance's force cycle does.
//!
//! The force along the path is not continuous at every depth: a cell
//! joining or leaving the zone snaps the force by a little (up to 4e-4 of
//! the largest force measured on a tilted paraboloid at 32 cells across
//! with the zone of 4 cells, one `f64` step of depth apart). A prescribed
//! force inside such a snap has no equilibrium; the search then narrows
//! the bracket to the resolution of `f64` and the step is the equilibrium
//! on the side of the snap nearer in force, recorded with its own force.

use crate::error::{Error, Result};
use crate::solver::least_force::{least_force, Probe, STEP_FRACTION};
use crate::solver::{Solution, WarmStart};

use super::super::{Phase, Step, MAX_PROTOCOL_STEPS};
use super::{Control, Runner};

/// Trial equilibria of one force step at most.
const MAX_TRIALS: usize = 100;

/// The fraction of the cohesive law's range below which a bracket of the
/// depth search that still straddles the force asked is a jump of the force
/// (a patch of a rough contact snapping in or off), not a slope: its end
/// nearer in force is taken. Regula falsi closes on a jump by halvings, and
/// 100 trials left brackets 1e-17 m wide across jumps of 1 to 10 % of a
/// step's force on the rough film of `examples/scenes/rough_adhesive_film.toml`
/// (a range of 3.8 um), where the search stopped with `NoConvergence`.
const SNAP_RANGE_FRACTION: f64 = 1e-9;

/// How close a step's force comes to the prescribed one, relative to the
/// protocol's largest force (or, at zero force, the pull at first touch),
/// unless the force lies inside a snap of the path (module docs).
const FORCE_TOLERANCE: f64 = 1e-6;

/// Halvings of the first unloading trial towards the peak where it lost
/// the contact ([`Runner::kept_between`]).
const HALVINGS: usize = 8;

/// Fixed-point rounds of one force step taken under force control before
/// the depth search takes it instead: a step takes 20 to 40 at 64 cells
/// across on the tilted paraboloid (30 let one of its unloading steps fall
/// back; 40 cost 31 % more iterations at 128 cells, more steps falling
/// back), and the jump-off spends them all.
const FORCE_ROUNDS: usize = 60;

/// An equilibrium of the path: its state and its solution.
type Kept = (Option<WarmStart>, Solution);

/// Where a search for a force ended (moved once a step: its size is no
/// cost).
#[allow(clippy::large_enum_variant)]
enum Reached {
    /// The equilibrium at the force (within the tolerance).
    At(Probe<Kept>),
    /// Along an unloading, the contact was lost before the force came
    /// down to the one asked: the least force walked between its
    /// neighbours, by falling depth.
    Beyond([Probe<Kept>; 3]),
}

/// What one force step looks for: `force` (N), deeper (`down` false) or
/// shallower along the path, to within `tolerance` (N).
#[derive(Clone, Copy)]
struct Aim {
    force: f64,
    down: bool,
    tolerance: f64,
    /// The bracket's width in depth (m) at which the force counts as
    /// snapping across the one asked ([`SNAP_RANGE_FRACTION`] of the law's
    /// range).
    snap: f64,
}

/// The last two equilibria of the path, and the iterations spent since the
/// last recorded step.
struct Path {
    before: Option<Probe<Kept>>,
    current: Probe<Kept>,
    iterations: usize,
}

/// Consecutive unloading steps of a force cycle that may land on one and the
/// same equilibrium before the cycle stops with a typed error.
const STILL_STEPS: usize = 32;

impl Runner<'_> {
    /// The scene's force protocol through the cohesive zone: from the
    /// touch up to `max_force`, in `steps` increments if `cycle` (from zero
    /// force) and then back down by the same decrement into tension until
    /// the jump-off, or else in one step. False if a contact reached the
    /// grid's edge.
    pub(in crate::scene) fn force_cohesive(
        &mut self,
        max_force: f64,
        steps: usize,
        cycle: bool,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let increment = max_force / steps.max(1) as f64;
        // The indenter touches at its lowest point; a depth scale from the
        // non-adhesive contact at the largest force.
        let touch = self.solver.lowest_height(self.indenter)?;
        let mut path = self.touch(touch)?;
        let free = if max_force > 0.0 {
            let (dry, _) =
                self.solver
                    .solve_force(self.indenter, max_force, None, self.observer)?;
            path.iterations += dry.iterations;
            (dry.depth - touch).max(0.0)
        } else {
            0.0
        };
        let zone = self.cohesive.ok_or(Error::Internal {
            what: "force control through the cohesive zone",
            detail: "no cohesive zone".into(),
        })?;
        let spacing = self.solver.grid().spacing();
        let range = zone.range(
            zone.receding(),
            spacing,
            self.solver.substrate().surface_material().contact_modulus(),
        );
        // The first trial of a step when no secant is known.
        let fallback = (free / steps.max(1) as f64)
            .max(range)
            .max(f64::MIN_POSITIVE);
        let scale = if max_force > 0.0 {
            max_force
        } else {
            path.current.force.abs()
        };
        let tolerance = FORCE_TOLERANCE * scale;
        let snap = SNAP_RANGE_FRACTION * range;
        let loading: Vec<f64> = if cycle {
            (0..=steps).map(|k| k as f64 * increment).collect()
        } else {
            vec![max_force]
        };
        let last = loading.len() - 1;
        for (k, &force) in loading.iter().enumerate() {
            let peak = k == last;
            let step = secant_step(&path, force).unwrap_or(fallback);
            let aim = Aim {
                force,
                down: false,
                tolerance,
                snap,
            };
            let reached = self.seek_kept(&mut path, aim, step, peak)?;
            let Reached::At(at) = reached else {
                return Err(Error::Internal {
                    what: "force control through the cohesive zone",
                    detail: "a loading step found no equilibrium".into(),
                });
            };
            if !self.accept(&mut path, at, Phase::Loading, progress) {
                return Ok(false);
            }
        }
        if !cycle {
            return Ok(true);
        }
        if self.bonded_at_rim() {
            // A punch's face bonded at its rim: its peeling path.
            return self.unload_peeled_force(max_force, increment, progress);
        }
        let mut still = 0;
        for k in 1..=MAX_PROTOCOL_STEPS {
            let force = max_force - k as f64 * increment;
            let step = secant_step(&path, force).unwrap_or(fallback);
            let aim = Aim {
                force,
                down: true,
                tolerance,
                snap,
            };
            match self.seek_kept(&mut path, aim, step, false)? {
                Reached::At(at) => {
                    if !self.accept(&mut path, at, Phase::Unloading, progress) {
                        return Ok(false);
                    }
                }
                Reached::Beyond(bracket) => match self.least(&mut path, bracket, aim)? {
                    Reached::At(at) => {
                        if !self.accept(&mut path, at, Phase::Unloading, progress) {
                            return Ok(false);
                        }
                    }
                    Reached::Beyond(bracket) => {
                        let [_, least, _] = bracket;
                        return self.jump_off(&mut path, least, progress);
                    }
                },
            }
            // A step that lands on the last one's equilibrium again: the
            // decrement is below the force the path resolves (a work of
            // adhesion whose forces dwarf the protocol's), and stepping
            // on would only repeat it up to the protocol's bound.
            let same = path.before.as_ref().is_some_and(|before| {
                before.depth == path.current.depth && before.force == path.current.force
            });
            still = if same { still + 1 } else { 0 };
            if still == STILL_STEPS {
                return Err(Error::InvalidParameter {
                    name: "protocol.max_force / steps (N)",
                    value: increment,
                    expected: "a force step the cohesive path resolves: the unloading stood \
                               at one equilibrium for 32 steps (forces of adhesion that dwarf \
                               the protocol's; raise max_force or lower the work of adhesion)",
                });
            }
        }
        Err(super::super::pull_off_beyond_steps(increment))
    }

    /// The equilibrium where the indenter touches (the start of the path).
    fn touch(&mut self, depth: f64) -> Result<Path> {
        self.warm = None;
        let solution = self.solve(Control::Depth(depth))?;
        Ok(Path {
            before: None,
            iterations: solution.iterations,
            current: Probe {
                depth,
                force: solution.force,
                kept: (self.warm.clone(), solution),
            },
        })
    }

    /// [`Runner::seek`], keeping the requested fields of every trial at the
    /// most loaded step (the one accepted becomes the curve's peak).
    fn seek_kept(&mut self, path: &mut Path, aim: Aim, step: f64, peak: bool) -> Result<Reached> {
        if !peak {
            return self.seek(path, aim, step);
        }
        let (reached, kept) = self.with_kept_fields(|runner| runner.seek(path, aim, step))?;
        if let (true, Reached::At(at)) = (kept, &reached) {
            self.peak = Some(at.kept.1.clone());
        }
        Ok(reached)
    }

    /// The equilibrium at `force` along the path from its current one,
    /// deeper (`down` false) or shallower: trial depths `step`, `2 step`,
    /// `4 step`... away until the force is passed, then regula falsi.
    fn seek(&mut self, path: &mut Path, aim: Aim, step: f64) -> Result<Reached> {
        let near = clone_probe(&path.current);
        if (near.force - aim.force).abs() <= aim.tolerance {
            return Ok(Reached::At(near));
        }
        if let Some(at) = self.under_force(path, aim, &near)? {
            return Ok(Reached::At(at));
        }
        let before = path
            .before
            .as_ref()
            .filter(|b| b.depth > near.depth)
            .map(clone_probe);
        self.falsi(path, aim, step, near, None, before)
    }

    /// The equilibrium at `aim`'s force reached from `near` by the cohesive
    /// zone's fixed point under force control, in at most
    /// [`FORCE_ROUNDS`] rounds: `None` (and the scene's state left at
    /// `near`) where it does not converge, loses the contact or moves the
    /// wrong way, so that the depth search takes the step.
    fn under_force(
        &mut self,
        path: &mut Path,
        aim: Aim,
        near: &Probe<Kept>,
    ) -> Result<Option<Probe<Kept>>> {
        let (Some(zone), Some(state)) = (self.cohesive, near.kept.0.as_ref()) else {
            return Ok(None);
        };
        let solved = self.solver.solve_force_cohesive_within(
            self.indenter,
            aim.force,
            &zone,
            (state, near.depth),
            (FORCE_ROUNDS, &mut path.iterations),
            self.observer,
        );
        let (solution, end) = match solved {
            Ok(pair) => pair,
            Err(Error::NoConvergence { .. }) => return Ok(None),
            Err(e) => return Err(e),
        };
        let onward = if aim.down {
            solution.depth < near.depth
        } else {
            solution.depth > near.depth
        };
        let held = (solution.force - aim.force).abs() <= aim.tolerance;
        if !(onward && held && solution.contact_cells > 0) {
            return Ok(None);
        }
        self.note_cohesive(&solution, &end);
        self.warm = Some(end.clone());
        Ok(Some(Probe {
            depth: solution.depth,
            force: solution.force,
            kept: (Some(end), solution),
        }))
    }

    /// [`Runner::seek`] from `near` (on the path's side of `force`), with
    /// `far` past it if known; `before` is the equilibrium above `near`
    /// along an unloading.
    fn falsi(
        &mut self,
        path: &mut Path,
        aim: Aim,
        step: f64,
        mut near: Probe<Kept>,
        mut far: Option<Probe<Kept>>,
        before: Option<Probe<Kept>>,
    ) -> Result<Reached> {
        let Aim {
            force,
            down,
            tolerance,
            snap,
        } = aim;
        let sign = if down { -1.0 } else { 1.0 };
        let mut step = step;
        // The least force walked so far along an unloading, with the
        // equilibria on either side of it (a bracket if the contact is lost).
        let mut least: [Option<Probe<Kept>>; 3] = [before, Some(clone_probe(&near)), None];
        // Illinois: the residual of an end kept twice in a row is halved.
        let mut r_near = near.force - force;
        let mut r_far = far.as_ref().map_or(0.0, |f| f.force - force);
        let mut far_replaced: Option<bool> = None;
        for _ in 0..MAX_TRIALS {
            let depth = match &far {
                None => near.depth + sign * step,
                Some(far) => {
                    let d = (near.depth * r_far - far.depth * r_near) / (r_far - r_near);
                    let (lo, hi) = (near.depth.min(far.depth), near.depth.max(far.depth));
                    if d > lo && d < hi {
                        d
                    } else {
                        0.5 * (near.depth + far.depth)
                    }
                }
            };
            let jump = far
                .as_ref()
                .is_some_and(|f| depth == f.depth || (f.depth - near.depth).abs() <= snap);
            if depth == near.depth || jump {
                // The bracket is at the resolution of f64 or a fraction of
                // the law's range (the force snaps across the one asked):
                // its end nearer in force.
                return Ok(Reached::At(nearer(near, far, force)));
            }
            self.warm = near.kept.0.clone();
            let solution = self.solve_after(Some(near.depth), Control::Depth(depth))?;
            path.iterations += solution.iterations;
            let lost = solution.contact_cells == 0;
            let probe = Probe {
                depth,
                force: solution.force,
                kept: (self.warm.clone(), solution),
            };
            let residual = probe.force - force;
            if residual.abs() <= tolerance && !lost {
                return Ok(Reached::At(probe));
            }
            let crossed = if down { residual < 0.0 } else { residual > 0.0 };
            if down && !crossed && lost {
                // Lost before the force came down to the one asked: the
                // least force walked, between its neighbours.
                let [above, lowest, below] = least;
                let Some(lowest) = lowest else {
                    return Err(Error::Internal {
                        what: "force control through the cohesive zone",
                        detail: "no equilibrium walked along the unloading".into(),
                    });
                };
                let Some(above) = above else {
                    // Lost at the trials from the top of the path (the
                    // unloading's first step from the peak, where forces
                    // of adhesion dwarf the protocol's): an equilibrium
                    // between, by halving towards the top.
                    let mid = self.kept_between(path, &lowest, &probe)?;
                    return Ok(Reached::Beyond([lowest, mid, probe]));
                };
                return Ok(Reached::Beyond([above, lowest, below.unwrap_or(probe)]));
            }
            if crossed {
                if far_replaced == Some(true) {
                    r_near *= 0.5;
                }
                r_far = residual;
                far = Some(probe);
                far_replaced = Some(true);
            } else {
                if far.is_some() && far_replaced == Some(false) {
                    r_far *= 0.5;
                }
                if down {
                    let lower = least[1].as_ref().is_some_and(|l| probe.force < l.force);
                    if lower {
                        least = [Some(clone_probe(&near)), Some(clone_probe(&probe)), None];
                    } else if least[2].is_none() {
                        least[2] = Some(clone_probe(&probe));
                    }
                }
                r_near = residual;
                near = probe;
                if far.is_none() {
                    step *= 2.0;
                }
                far_replaced = Some(false);
            }
        }
        Err(Error::NoConvergence {
            method: "force control through the cohesive zone (depth of one force step)",
            iterations: MAX_TRIALS,
            residual: near.force - force,
        })
    }

    /// An equilibrium in contact between `top` and `lost` (which lost the
    /// contact), at `1/2, 1/4, ... 1/256` of the way from `top`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if every one lost the contact (the
    /// peak force is where the contact comes off).
    fn kept_between(
        &mut self,
        path: &mut Path,
        top: &Probe<Kept>,
        lost: &Probe<Kept>,
    ) -> Result<Probe<Kept>> {
        let mut fraction = 1.0;
        for _ in 0..HALVINGS {
            fraction *= 0.5;
            let depth = top.depth + (lost.depth - top.depth) * fraction;
            self.warm = top.kept.0.clone();
            let solution = self.solve_after(Some(top.depth), Control::Depth(depth))?;
            path.iterations += solution.iterations;
            if solution.contact_cells > 0 {
                return Ok(Probe {
                    depth,
                    force: solution.force,
                    kept: (self.warm.clone(), solution),
                });
            }
        }
        Err(Error::InvalidParameter {
            name: "protocol.max_force (N)",
            value: top.force,
            expected: "a peak from which the unloading holds the contact: it came off \
                       within 1/256 of the first unloading step (raise max_force)",
        })
    }

    /// Records `at` as the path's new current equilibrium, with the
    /// iterations spent reaching it.
    fn accept(
        &mut self,
        path: &mut Path,
        at: Probe<Kept>,
        phase: Phase,
        progress: &mut dyn FnMut(&Step),
    ) -> bool {
        let mut solution = at.kept.1.clone();
        solution.iterations = std::mem::take(&mut path.iterations);
        self.warm = at.kept.0.clone();
        let previous = std::mem::replace(&mut path.current, at);
        path.before = Some(previous);
        self.record(solution, phase, progress)
    }

    /// The least force of `bracket` (the unloading's, each equilibrium
    /// reached from the last one above it): `Beyond` with it in the middle
    /// if it is above `force` (the jump-off), else the equilibrium at
    /// `force` between the searched ones.
    fn least(&mut self, path: &mut Path, bracket: [Probe<Kept>; 3], aim: Aim) -> Result<Reached> {
        let Aim {
            force, tolerance, ..
        } = aim;
        let width = STEP_FRACTION * 0.5 * (bracket[0].depth - bracket[2].depth);
        let mut probes = least_force(bracket, width, |depth, from: &Probe<Kept>| {
            self.warm = from.kept.0.clone();
            let solution = self.solve_after(Some(from.depth), Control::Depth(depth))?;
            path.iterations += solution.iterations;
            Ok::<_, Error>(Probe {
                depth,
                force: solution.force,
                kept: (self.warm.clone(), solution),
            })
        })?;
        // The first equilibrium down the unloading at or below `force`.
        let reachable = probes
            .iter()
            .position(|p| p.kept.1.contact_cells > 0 && p.force <= force + tolerance);
        if let Some(i) = reachable.filter(|&i| i > 0) {
            let far = probes.swap_remove(i);
            let near = probes.swap_remove(i - 1);
            if (far.force - force).abs() <= tolerance {
                return Ok(Reached::At(far));
            }
            return self.falsi(path, aim, 0.0, near, Some(far), None);
        }
        let m = (1..probes.len() - 1)
            .min_by(|&a, &b| probes[a].force.total_cmp(&probes[b].force))
            .ok_or(Error::Internal {
                what: "force control through the cohesive zone",
                detail: "no equilibrium at the pull-off".into(),
            })?;
        let below = probes.swap_remove(m + 1);
        let lowest = probes.swap_remove(m);
        let above = probes.swap_remove(m - 1);
        Ok(Reached::Beyond([above, lowest, below]))
    }

    /// The jump-off: `least`, the least force of the unloading, recorded as
    /// the pull-off, then a step without contact at its depth.
    fn jump_off(
        &mut self,
        path: &mut Path,
        least: Probe<Kept>,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let depth = least.depth;
        if !self.accept(path, least, Phase::Unloading, progress) {
            return Ok(false);
        }
        self.record_jump_off(depth, progress);
        Ok(true)
    }
}

/// The first trial's distance from the path's current equilibrium towards
/// `force`: a quarter more than the secant of its last two equilibria asks,
/// so that it passes the force and brackets it; `None` without a rising
/// secant.
fn secant_step(path: &Path, force: f64) -> Option<f64> {
    let before = path.before.as_ref()?;
    let (d, f) = (path.current.depth, path.current.force);
    let slope = (f - before.force) / (d - before.depth);
    let step = 1.25 * (force - f).abs() / slope;
    (slope.is_finite() && slope > 0.0 && step.is_finite() && step > 0.0).then_some(step)
}

/// A copy of a probe.
fn clone_probe(p: &Probe<Kept>) -> Probe<Kept> {
    Probe {
        depth: p.depth,
        force: p.force,
        kept: p.kept.clone(),
    }
}

/// Of `near` and `far`, the equilibrium whose force is nearer `force`.
fn nearer(near: Probe<Kept>, far: Option<Probe<Kept>>, force: f64) -> Probe<Kept> {
    match far {
        Some(far) if (far.force - force).abs() < (near.force - force).abs() => far,
        _ => near,
    }
}
