//! The unloading of a flat punch bonded over its whole face, where the
//! cohesive zone cannot go (its contact is pinned at the rim): the local
//! Griffith criterion's peeling path
//! ([`ContactSolver::peel_punch`](crate::solver::ContactSolver::peel_punch))
//! walked at the protocol's depths.

use crate::error::{Error, Result};
use crate::solver::{pinned_at_rim, WarmStart};

use super::super::{Phase, Step};
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
    /// minimum. Refuses (as the cohesive zone does) a contact that is not
    /// the whole face.
    ///
    /// [`Curve::pull_off`]: super::super::Curve::pull_off
    pub(in crate::scene) fn unload_peeled(
        &mut self,
        max_depth: f64,
        increment: f64,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<bool> {
        let (_, receding) = self.scene.adhesion.works().unwrap_or((0.0, 0.0));
        // An indenter that is not a punch bonded at a rim keeps the
        // cohesive zone's refusal; other errors (no convergence, an
        // interrupt) are the solve's own.
        let path = match self.solver.peel_punch(self.indenter, receding) {
            Err(Error::Unsupported { .. } | Error::InvalidParameter { .. }) => {
                return Err(pinned_at_rim())
            }
            other => other?,
        };
        let points = path.points();
        let bonded = self.warm.as_ref().map_or(0, WarmStart::attached_cells);
        if bonded != points[0].contact_cells {
            return Err(pinned_at_rim());
        }
        let visited = path.visited();
        let least = visited
            .iter()
            .copied()
            .min_by(|&a, &b| points[a].force.total_cmp(&points[b].force))
            .unwrap_or(0);
        let mut least_recorded = false;
        let mut held = 0usize;
        let (mut depth, mut increment) = (max_depth, increment);
        let limit = unloading_steps(max_depth, increment);
        for _ in 0..limit {
            let Some(next) = next_increment(depth, increment, max_depth) else {
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
}
