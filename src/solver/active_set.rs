//! Primal-dual active-set loops, for a depth-driven contact whose
//! constrained conjugate gradients ([`polonsky_keer`](super::polonsky_keer))
//! find their contact set slowly.
//!
//! On a stiff layer over a far softer base the layer bends like a plate on
//! a foundation, and a contact changes the pressures far from where a cell
//! joins or leaves it. The constrained conjugate gradients change their
//! working set a few cells an iteration: a sphere on a layer 8000 times
//! stiffer than its base took 2019 iterations to find a ring of contact
//! (`examples/disc_or_ring.rs`), where the linear system on the converged
//! set takes 5 to 29 (`benches/rough/plate_active_set.py`). A depth-driven
//! serial solve (the cohesive zone's inner solves among them) still
//! running at [`ACTIVE_SET_AFTER`] iterations therefore tries, once, the
//! loops of Hintermueller, Ito & Kunisch (2002, SIAM J. Optim. 13, 865):
//! solve the linear system on the current set (the clamped solve of the
//! energy balance, preconditioned by the same box inverse), take out every
//! cell whose pressure came out tensile and add every cell the indenter
//! overlaps, until the set no longer changes. If it settles, the
//! constrained iteration goes on from its pressures (and ends at once, the
//! conditions of the bound-constrained minimum holding); if it does not
//! within [`MAX_LOOPS`] loops or the budget, the iteration goes on from
//! where it was.

use crate::error::{Error, Result};

use super::ContactSolver;

/// The iteration of the constrained conjugate gradients at which a
/// depth-driven solve that has not converged tries the active-set loops:
/// above what smooth and rough contacts take (12 to 15 for a Hertzian
/// contact, 17 to 58 fine iterations for rough ones up to 8192^2,
/// `BENCHMARKS.md`), so that only the slow class is touched.
pub(super) const ACTIVE_SET_AFTER: usize = 100;

/// The most loops tried.
const MAX_LOOPS: usize = 30;

impl ContactSolver {
    /// The loops from the cells where `pressure` is positive, at `depth`,
    /// over `reachable` cells, within `budget` conjugate-gradient
    /// iterations in all; `offset` the part of the displacement that the
    /// pressures do not make (an inner solve of the cohesive zone keeps
    /// the tensions' response in it). The settled pressures (the
    /// workspace's displacement theirs, with `offset`) and the iterations
    /// spent, or `None` if the set did not settle (the workspace's vectors
    /// then hold no state of the caller's).
    pub(super) fn active_set_loops(
        &mut self,
        depth: f64,
        pressure: &[f64],
        reachable: &[bool],
        budget: usize,
        offset: Option<&[f64]>,
    ) -> Result<Option<(Vec<f64>, usize)>> {
        let saved = self.params.max_iterations;
        let result = self.loops(depth, pressure, reachable, budget, offset);
        self.params.max_iterations = saved;
        result
    }

    fn loops(
        &mut self,
        depth: f64,
        pressure: &[f64],
        reachable: &[bool],
        budget: usize,
        offset: Option<&[f64]>,
    ) -> Result<Option<(Vec<f64>, usize)>> {
        let offset_at = |c: usize| offset.map_or(0.0, |o| o[c]);
        // The displacement the pressures must make where they act.
        let target: Vec<f64> = (0..pressure.len())
            .map(|c| depth - self.workspace.profile[c] - offset_at(c))
            .collect();
        let mut member: Vec<bool> = pressure.iter().map(|p| *p > 0.0).collect();
        let mut p: Vec<f64> = pressure.iter().map(|p| p.max(0.0)).collect();
        let mut spent = 0;
        for _ in 0..MAX_LOOPS {
            if spent >= budget || !member.iter().any(|m| *m) {
                return Ok(None);
            }
            self.params.max_iterations = budget - spent;
            match self.clamped_cg(&member, &target, &mut p) {
                Ok((iterations, _)) => spent += iterations,
                Err(Error::NoConvergence { .. }) => return Ok(None),
                Err(e) => return Err(e),
            }
            if let Some(offset) = offset {
                for (u, o) in self.workspace.displacement.iter_mut().zip(offset) {
                    *u += o;
                }
            }
            // Overlap counts beyond the solve's own tolerance on the scale
            // of the prescribed displacements.
            let scale = target
                .iter()
                .zip(&member)
                .filter(|(_, m)| **m)
                .fold(0.0f64, |s, (t, _)| s.max(t.abs()));
            let overlap = -self.params.tolerance * scale;
            let ws = &self.workspace;
            let mut changed = false;
            for c in 0..p.len() {
                if member[c] {
                    if p[c] < 0.0 {
                        member[c] = false;
                        p[c] = 0.0;
                        changed = true;
                    }
                } else if reachable[c] && ws.profile[c] - depth + ws.displacement[c] < overlap {
                    member[c] = true;
                    changed = true;
                }
            }
            if !changed {
                return Ok(Some((p, spent)));
            }
        }
        Ok(None)
    }
}
