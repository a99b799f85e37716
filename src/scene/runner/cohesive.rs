//! The unloading of a cycle through the cohesive zone: steps of the
//! protocol until the contact is lost, and the pull-off searched between
//! the last two where the force turns (golden sections to a sixteenth of
//! a step, then the parabola's vertex: `solver::least_force`).

use crate::error::{Error, Result};
use crate::solver::least_force::{least_force, Probe, STEP_FRACTION};
use crate::solver::{substeps, ContactSolver, Solution, WarmStart};

use super::super::{Phase, Step};
use super::{next_increment, still_attached, unloading_steps, Control, Runner};

/// What a probe of the search keeps: its state, and its solution unless it
/// is already recorded.
type Kept = (Option<WarmStart>, Option<Solution>);

impl Runner<'_> {
    /// One solve (as [`Runner::solve`]) from the scene's last state, which
    /// is the equilibrium at depth `above` (m) when given: where the
    /// cohesive zone's fixed point does not reach `control`'s depth from
    /// it, the step is taken again in 2, 4, 8 or 16 substeps (as
    /// [`ContactSolver::cohesive_pull_off`] does); the solution then counts
    /// the iterations of every substep.
    pub(super) fn solve_after(&mut self, above: Option<f64>, control: Control) -> Result<Solution> {
        let failed = match self.solve(control) {
            Err(failed @ Error::NoConvergence { .. }) => failed,
            other => return other,
        };
        let (Some(above), Control::Depth(depth), Some(zone), Some(from)) =
            (above, control, self.cohesive, self.warm.take())
        else {
            return Err(failed);
        };
        let (indenter, observer) = (self.indenter, &mut *self.observer);
        let mut iterations = 0;
        let mut solve = |solver: &mut ContactSolver, d: f64, w: Option<&WarmStart>| {
            let (solution, end) = solver.solve_depth_cohesive(indenter, d, &zone, w, observer)?;
            iterations += solution.iterations;
            Ok((solution, end))
        };
        let reached = substeps(self.solver, &mut solve, (above, depth), &from, failed);
        match reached {
            Ok((mut solution, state)) => {
                solution.iterations = iterations;
                self.note_cohesive(&solution, &state);
                self.warm = Some(state);
                Ok(solution)
            }
            Err(e) => {
                self.warm = Some(from);
                Err(e)
            }
        }
    }

    /// Retracts from `max_depth` by `increment` (doubled at each step
    /// beyond `-max_depth`, as [`Runner::unload`]) until the contact is
    /// lost. Each step is recorded one step late: where the force rises
    /// after a new least value, the least force of the last two steps is
    /// searched from the last recorded state (each equilibrium reached from
    /// the nearest one above it) and solved at the parabola's vertex, so
    /// that [`Curve::pull_off`] is the minimum of the curve, not of the
    /// protocol's steps. Every equilibrium is recorded, by falling depth.
    /// A step after that search whose equilibrium the fixed point does not
    /// reach ends the curve at the last one, with
    /// [`Caveat::CohesiveUnloadingCutShort`](super::super::Caveat::CohesiveUnloadingCutShort).
    ///
    /// [`Curve::pull_off`]: super::super::Curve::pull_off
    pub(in crate::scene) fn unload_cohesive(
        &mut self,
        max_depth: f64,
        increment: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        if self.bonded_at_rim() {
            // A punch's face bonded at its rim: the zone cannot form
            // beyond it; the local criterion's peeling path instead.
            return self.unload_peeled(max_depth, increment, progress);
        }
        let mut increment = increment;
        let mut depth = max_depth;
        let mut recorded = Probe {
            depth,
            force: self.steps.last().map_or(0.0, |s| s.force),
            kept: (self.warm.clone(), None),
        };
        let mut lowest = recorded.force;
        let mut pending: Option<Probe<Kept>> = None;
        // Whether the least force was searched between two steps.
        let mut searched = false;
        let reach = self.pull_reach(max_depth);
        let limit = unloading_steps(max_depth, increment, reach);
        for _ in 0..limit {
            let Some(next) = next_increment(depth, increment, max_depth, reach) else {
                break;
            };
            increment = next;
            let above = depth;
            depth -= increment;
            let solution = match self.solve_after(Some(above), Control::Depth(depth)) {
                // Past the least force, a step whose equilibrium the fixed
                // point does not reach ends the curve at the last one, with
                // `Caveat::CohesiveUnloadingCutShort`.
                Err(Error::NoConvergence { .. }) if searched => {
                    self.cut_short = true;
                    let Some(last) = pending.take() else {
                        return Ok(true);
                    };
                    let (_, solution) = last.kept;
                    return Ok(solution.is_none_or(|s| self.record(s, Phase::Unloading, progress)));
                }
                other => other?,
            };
            let lost = solution.contact_cells == 0;
            let current = Probe {
                depth,
                force: solution.force,
                kept: (self.warm.clone(), Some(solution)),
            };
            match pending.take() {
                Some(turn) if turn.force < lowest && current.force > turn.force => {
                    // The force turned within the last two steps.
                    let (state, lost, least) =
                        match self.search([recorded, turn, current], progress)? {
                            Some(end) => end,
                            None => return Ok(false),
                        };
                    if lost {
                        return Ok(true);
                    }
                    lowest = lowest.min(least);
                    searched = true;
                    self.warm = state.clone();
                    recorded = Probe {
                        depth,
                        force: self.steps.last().map_or(0.0, |s| s.force),
                        kept: (state, None),
                    };
                    continue;
                }
                Some(previous) => {
                    lowest = lowest.min(previous.force);
                    let (state, solution) = previous.kept;
                    recorded = Probe {
                        depth: previous.depth,
                        force: previous.force,
                        kept: (state, None),
                    };
                    if let Some(solution) = solution {
                        if !self.record(solution, Phase::Unloading, progress) {
                            return Ok(false);
                        }
                    }
                }
                None => {}
            }
            if lost {
                let (_, solution) = current.kept;
                return Ok(solution.is_some_and(|s| self.record(s, Phase::Unloading, progress)));
            }
            pending = Some(current);
        }
        Err(still_attached(limit, depth))
    }

    /// Searches the least force of `bracket` (the last recorded step, the
    /// turn and the step after it) and records every equilibrium after the
    /// first, by falling depth. Returns the last one's state, whether it
    /// lost contact and the least force, or `None` if a contact reached the
    /// grid's edge.
    fn search(
        &mut self,
        bracket: [Probe<Kept>; 3],
        progress: &mut dyn FnMut(&Step),
    ) -> Result<Option<(Option<WarmStart>, bool, f64)>> {
        // The bracket spans two steps.
        let width = STEP_FRACTION * 0.5 * (bracket[0].depth - bracket[2].depth);
        let probes = least_force(bracket, width, |depth, from: &Probe<Kept>| {
            self.warm = from.kept.0.clone();
            let solution = self.solve_after(Some(from.depth), Control::Depth(depth))?;
            Ok::<_, crate::Error>(Probe {
                depth,
                force: solution.force,
                kept: (self.warm.clone(), Some(solution)),
            })
        })?;
        let lowest = probes.iter().min_by(|a, b| a.force.total_cmp(&b.force));
        let least = lowest.map_or(f64::INFINITY, |p| p.force);
        if lowest
            .and_then(|p| p.kept.0.as_ref())
            .is_some_and(|state| self.solver.bonded_at_rim(state))
        {
            return Err(crate::solver::pinned_at_rim());
        }
        let mut end = (None, false);
        for probe in probes.into_iter().skip(1) {
            let (state, solution) = probe.kept;
            let Some(solution) = solution else { continue };
            end = (state, solution.contact_cells == 0);
            if !self.record(solution, Phase::Unloading, progress) {
                return Ok(None);
            }
        }
        Ok(Some((end.0, end.1, least)))
    }
}
