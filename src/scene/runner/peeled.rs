//! The unloading of a flat punch bonded at its rim (over its whole face or
//! a part of it), where the cohesive zone cannot go (its contact is pinned
//! at the rim): the local Griffith criterion's peeling path from the
//! contact the loading left
//! ([`ContactSolver::peel_punch_from`](crate::solver::ContactSolver::peel_punch_from))
//! walked at the protocol's depths or forces.

use crate::error::{Error, Result};
use crate::solver::{pinned_at_rim, PeelingPath};

use super::super::{Phase, Step, MAX_PROTOCOL_STEPS};
use super::{next_increment, still_attached, unloading_steps, Runner};

impl Runner<'_> {
    /// Retracts from `max_depth` by `increment` (doubled beyond
    /// `-max_depth`, as [`Runner::unload`]) along the punch's peeling path:
    /// at each depth the first contact of the path that holds there (each
    /// holds down to its critical depth), solved bonded at that depth,
    /// until none holds. The state of the least force the depth control
    /// reaches (the most tensile critical force among the path's records of
    /// the most tensile critical depth) is recorded where the protocol
    /// passes its depth, so that [`Curve::pull_off`] is the curve's
    /// minimum. Refuses (as the cohesive zone does) a contact of fewer than
    /// 16 cells, and a pull-off the grid hardly resolves.
    ///
    /// [`Curve::pull_off`]: super::super::Curve::pull_off
    pub(in crate::scene) fn unload_peeled(
        &mut self,
        max_depth: f64,
        increment: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let path = self.peeling_path()?;
        let points = path.points();
        let visited = path.visited();
        let least = visited
            .iter()
            .copied()
            .min_by(|&a, &b| points[a].force.total_cmp(&points[b].force))
            .unwrap_or(0);
        let mut least_recorded = false;
        let mut held = 0usize;
        let (mut depth, mut increment) = (max_depth, increment);
        let reach = self.pull_reach(max_depth);
        let limit = unloading_steps(max_depth, increment, reach);
        for _ in 0..limit {
            let Some(next) = next_increment(depth, increment, max_depth, reach) else {
                break;
            };
            increment = next;
            let above = depth;
            depth -= increment;
            let critical = points[least].depth;
            if !least_recorded && critical < above && critical >= depth {
                least_recorded = true;
                let solution =
                    self.solver
                        .clamped_solution(self.indenter, critical, &path.contact(least))?;
                if !self.record(solution, Phase::Unloading, progress) {
                    return Ok(false);
                }
            }
            while held < points.len() && depth < points[held].depth {
                held += 1;
            }
            let attached = if held < points.len() {
                path.contact(held)
            } else {
                vec![false; self.solver.grid().len()]
            };
            let solution = self
                .solver
                .clamped_solution(self.indenter, depth, &attached)?;
            let lost = solution.contact_cells == 0;
            if !self.record(solution, Phase::Unloading, progress) {
                return Ok(false);
            }
            if lost {
                self.warm = None;
                return Ok(true);
            }
        }
        Err(still_attached(limit, depth))
    }

    /// The force-controlled unloading of a punch bonded at its rim, from
    /// `max_force` down by `decrement` into tension: at each force the
    /// first contact of the peeling path that holds it (each holds down to
    /// its critical force), at the depth where its bonded stiffness carries
    /// that force; past the most tensile critical force (the pull-off,
    /// recorded at its critical depth) a step without contact, as the
    /// cohesive zone's own force cycle ends.
    pub(in crate::scene) fn unload_peeled_force(
        &mut self,
        max_force: f64,
        decrement: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let path = self.peeling_path()?;
        let points = path.points();
        let pull = path.pull_off_index();
        let mut held = 0usize;
        for k in 1..=MAX_PROTOCOL_STEPS {
            let force = max_force - k as f64 * decrement;
            while held <= pull && force < points[held].force {
                held += 1;
            }
            if held > pull {
                let at = &points[pull];
                let solution =
                    self.solver
                        .clamped_solution(self.indenter, at.depth, &path.contact(pull))?;
                if !self.record(solution, Phase::Unloading, progress) {
                    return Ok(false);
                }
                self.record_jump_off(at.depth, progress);
                return Ok(true);
            }
            let p = &points[held];
            let depth = p.depth + (force - p.force) / p.stiffness;
            let solution =
                self.solver
                    .clamped_solution(self.indenter, depth, &path.contact(held))?;
            if !self.record(solution, Phase::Unloading, progress) {
                return Ok(false);
            }
        }
        Err(super::super::pull_off_beyond_steps(decrement))
    }

    /// The peeling path of the scene's punch from the cells bonded in the
    /// state the loading left: too few of them keep the cohesive zone's
    /// refusal; other errors (an indenter without a rim, a pull-off the grid
    /// hardly resolves, no convergence, an interrupt) are the path's own.
    fn peeling_path(&mut self) -> Result<PeelingPath> {
        let (_, receding) = self.scene.adhesion.works().unwrap_or((0.0, 0.0));
        let Some(bonded) = self.warm.as_ref().map(|w| w.attached.clone()) else {
            return Err(pinned_at_rim());
        };
        match self
            .solver
            .peel_punch_from(self.indenter, receding, &bonded)
        {
            Err(Error::InvalidParameter { .. }) => Err(pinned_at_rim()),
            other => other,
        }
    }
}
