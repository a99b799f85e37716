//! The unloading of a cycle through the cohesive zone: steps of the
//! protocol until the contact is lost, and the pull-off walked again on
//! steps eight times finer, its minimum solved at the vertex of the
//! parabola through the three lowest forces.

use crate::error::Result;
use crate::solver::{Solution, WarmStart};

use super::super::{Phase, Step, MAX_PULL_DEPTHS};
use super::{still_attached, unloading_steps, Control, Runner};

/// Finer steps per protocol step where the force turns.
const REFINEMENT: usize = 8;

/// A vertex closer than this (in fine steps) to a solved step is not
/// solved again.
const VERTEX_MARGIN: f64 = 0.01;

/// The last recorded equilibrium of the walk.
struct Recorded {
    depth: f64,
    force: f64,
    state: Option<WarmStart>,
}

impl Runner<'_> {
    /// Retracts from `max_depth` by `increment` (doubled at each step
    /// beyond `-max_depth`, as [`Runner::unload`]) until the contact is
    /// lost. Each step is recorded one step late: where the force rises
    /// after a new lowest value, the last two steps are walked again in
    /// steps eight times finer from the last recorded state, and the
    /// pull-off is solved at the vertex of the parabola through the lowest
    /// fine force and its neighbours (exact to third order in the step
    /// where the force is smooth), so that [`Curve::pull_off`] is the
    /// minimum of the curve, not of the protocol's steps.
    ///
    /// [`Curve::pull_off`]: super::super::Curve::pull_off
    pub(in crate::scene) fn unload_cohesive(
        &mut self,
        max_depth: f64,
        increment: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let mut increment = increment;
        let mut depth = max_depth;
        let mut recorded = Recorded {
            depth,
            force: self.steps.last().map_or(0.0, |s| s.force),
            state: self.warm.clone(),
        };
        let mut lowest = recorded.force;
        let mut pending: Option<(Solution, Option<WarmStart>)> = None;
        let limit = unloading_steps(max_depth, increment);
        for _ in 0..limit {
            if depth < -max_depth {
                increment *= 2.0;
            }
            if depth < -MAX_PULL_DEPTHS * max_depth {
                break;
            }
            depth -= increment;
            let solution = self.solve(Control::Depth(depth))?;
            let lost = solution.contact_cells == 0;
            match pending.take() {
                Some((turn, _)) if turn.force < lowest && solution.force > turn.force => {
                    // The force turned within the last two steps: walk them
                    // again, finer, from the last recorded state.
                    let Some(walked) = self.refine(&recorded, depth, progress)? else {
                        return Ok(false);
                    };
                    lowest = lowest.min(walked.0);
                    recorded = Recorded {
                        depth: walked.1,
                        force: walked.2,
                        state: self.warm.clone(),
                    };
                    if walked.3 {
                        return Ok(true);
                    }
                    depth = walked.1;
                    continue;
                }
                Some((previous, state)) => {
                    lowest = lowest.min(previous.force);
                    recorded = Recorded {
                        depth: previous.depth,
                        force: previous.force,
                        state,
                    };
                    if !self.record(previous, Phase::Unloading, progress) {
                        return Ok(false);
                    }
                }
                None => {}
            }
            if lost {
                return Ok(self.record(solution, Phase::Unloading, progress));
            }
            pending = Some((solution, self.warm.clone()));
        }
        Err(still_attached(limit, depth))
    }

    /// Walks from `from` (recorded) to `to` in `2 REFINEMENT` steps,
    /// solves the vertex of the lowest force, and records them in order.
    /// Returns the lowest force, the depth, force and loss of contact of
    /// the walk's last step (the runner's state is its), or `None` if a
    /// contact reached the grid's edge.
    fn refine(
        &mut self,
        from: &Recorded,
        to: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<Option<(f64, f64, f64, bool)>> {
        let fine = (from.depth - to) / (2 * REFINEMENT) as f64;
        self.warm = from.state.clone();
        // The forces from `from` on, the solutions after it.
        let mut forces = vec![from.force];
        let mut walk: Vec<Solution> = Vec::with_capacity(2 * REFINEMENT + 1);
        // The states before and at the lowest force of the walk.
        let (mut before, mut at) = (None, None);
        for k in 1..=2 * REFINEMENT {
            let d = if k == 2 * REFINEMENT {
                to
            } else {
                from.depth - k as f64 * fine
            };
            let previous = self.warm.clone();
            let solution = self.solve(Control::Depth(d))?;
            let lost = solution.contact_cells == 0;
            if solution.force < forces.iter().copied().fold(f64::INFINITY, f64::min) {
                (before, at) = (previous, self.warm.clone());
            }
            forces.push(solution.force);
            walk.push(solution);
            if lost {
                break;
            }
        }
        let last = self.warm.take();
        let j = (0..forces.len())
            .min_by(|&a, &b| forces[a].total_cmp(&forces[b]))
            .unwrap_or(0);
        if let Some(state) = at.as_ref() {
            if j > 0 && self.solver.bonded_at_rim(state) {
                return Err(crate::solver::pinned_at_rim());
            }
        }
        let mut lowest = forces[j];
        if j > 0 && j + 1 < forces.len() {
            let curvature = forces[j - 1] - 2.0 * forces[j] + forces[j + 1];
            let shift = if curvature > 0.0 {
                0.5 * (forces[j - 1] - forces[j + 1]) / curvature
            } else {
                0.0
            };
            if shift.abs() > VERTEX_MARGIN {
                // From the solved step above the vertex.
                self.warm = if shift > 0.0 { at } else { before };
                let vertex = walk[j - 1].depth - shift * fine;
                let solution = self.solve(Control::Depth(vertex))?;
                lowest = lowest.min(solution.force);
                let place = if shift > 0.0 { j } else { j - 1 };
                walk.insert(place, solution);
            }
        }
        let (depth, force, lost) = walk.last().map_or((from.depth, from.force, false), |s| {
            (s.depth, s.force, s.contact_cells == 0)
        });
        for solution in walk {
            if !self.record(solution, Phase::Unloading, progress) {
                return Ok(None);
            }
        }
        self.warm = last;
        Ok(Some((lowest, depth, force, lost)))
    }
}
