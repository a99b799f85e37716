//! The pull-off of an unloading through the cohesive zone of
//! [`cohesive`](super::cohesive): the indenter withdrawn in steps, the
//! least force searched between the steps around the least one
//! ([`least_force`]).

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::least_force::{least_force, Probe, STEP_FRACTION};
use super::{check_finite, CohesiveZone, ContactSolver, Observer, WarmStart};

/// The pull-off of an unloading under displacement control
/// ([`ContactSolver::cohesive_pull_off`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct CohesivePullOff {
    /// The most tensile force along the unloading, N (negative).
    pub force: f64,
    /// The depth where it is reached, m.
    pub depth: f64,
    /// Cohesive solves taken.
    pub solves: usize,
    /// Conjugate-gradient iterations over all of them.
    pub iterations: usize,
    /// The widest patch of the contact at the pull-off in cells across
    /// (twice the most steps from a cell in contact to an open one, less
    /// one).
    pub cells_across: f64,
    /// The zone's width in cells on this grid (`CohesiveZone::cells_on`).
    pub zone_cells: f64,
}

impl CohesivePullOff {
    /// Whether the zone is wider than the pull-off contact (its widest
    /// patch fewer cells across than the zone): the zones of its two sides
    /// then meet and the force is a cohesive law's, not the JKR limit's.
    /// Johnson's sinusoid so resolved (the exact pull-off contact 0.6 to
    /// 11 lines of cells wide, the zone's contact at its least force 0 to 3)
    /// came out 0.9 to 25 % weak, where the widest resolved ones were
    /// within 2.6 % (`BENCHMARKS.md`, "The cohesive zone on contacts it
    /// spans"). A finer grid (or a narrower zone) resolves it.
    pub fn zone_spans_contact(&self) -> bool {
        self.cells_across < self.zone_cells
    }
}

/// Steps in a row whose force is above the least one before
/// [`ContactSolver::cohesive_pull_off`] takes the least as the pull-off's
/// neighbourhood.
const RISES: usize = 3;

/// Halvings of an unloading step whose equilibrium the fixed point did not
/// reach from the step before: 2, 4, 8, then 16 substeps.
const SUBSTEP_LEVELS: u32 = 4;

/// Unloading steps before [`ContactSolver::cohesive_pull_off`] gives up.
const MAX_UNLOADING_STEPS: usize = 10_000;

impl ContactSolver {
    /// The pull-off force under displacement control: from the equilibrium
    /// at `depth` (reached from `warm`, or cold), the indenter is withdrawn
    /// in steps of `step` (m) with [`solve_depth_cohesive`](Self::solve_depth_cohesive)
    /// until the force has stayed above its least value for three steps
    /// in a row or the contact is lost (a contact edge trapped by the
    /// lattice makes the force ripple about its trend, so one rise is not
    /// yet the pull-off: a straight edge along the grid with the zone of
    /// four cells stopped a third short of Johnson's sinusoid's pull-off
    /// at 4096 cells per wavelength when the walk ended at the first rise);
    /// the least force between the steps on either side of the least one
    /// is then bracketed by golden sections to a sixteenth of a step, each
    /// equilibrium reached from the nearest one above it, and solved at the
    /// vertex of the parabola through the least three (exact to third order
    /// in the bracket where the force is smooth; about nine more solves).
    /// A step whose equilibrium the fixed point does not reach is taken
    /// again in 2, 4, 8 or 16 substeps.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a step that is not positive and
    /// finite, a start without contact or already past the pull-off (the
    /// force rises at the first step); [`Error::Unsupported`] if the contact at the pull-off
    /// is pinned at the rim of the indenter's face (a cell in contact next
    /// to one it cannot reach: a flat punch), which the zone does not
    /// represent; [`Error::NoConvergence`] after 10000 steps or where 16
    /// substeps do not reach a step's equilibrium; as
    /// [`solve_depth_cohesive`](Self::solve_depth_cohesive) otherwise.
    pub fn cohesive_pull_off<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        zone: &CohesiveZone,
        depth: f64,
        step: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<CohesivePullOff> {
        let step = crate::error::positive_finite("unloading step", step)?;
        check_finite("depth", depth)?;
        if depth - STEP_FRACTION * step / 16.0 == depth {
            return Err(Error::InvalidParameter {
                name: "unloading step (m)",
                value: step,
                expected: "at least 256 units in the last place of the depth (the search \
                           for the least force divides it)",
            });
        }
        let mut tally = CohesivePullOff {
            force: f64::INFINITY,
            depth,
            solves: 0,
            iterations: 0,
            cells_across: 0.0,
            zone_cells: zone.cells_on(self.grid().spacing(), self.substrate.top_thickness()),
        };
        let mut solve = |solver: &mut Self, d: f64, w: Option<&WarmStart>| {
            let (s, end) = solver.solve_depth_cohesive(indenter, d, zone, w, observer)?;
            tally.solves += 1;
            tally.iterations += s.iterations;
            Ok::<_, Error>(((s.force, s.contact_cells), end))
        };
        let ((force, contact), end) = solve(self, depth, warm)?;
        if contact == 0 {
            return Err(Error::InvalidParameter {
                name: "start depth of the unloading (m)",
                value: depth,
                expected: "a depth at which the indenter is in contact",
            });
        }
        // The last three (depth, force, state) of the walk, and those around
        // the least force so far once a step above it has been solved.
        let mut walk = vec![(depth, force, end)];
        let mut around_least = None;
        let (mut least, mut rises) = (force, 0usize);
        for k in 1..=MAX_UNLOADING_STEPS {
            let d = depth - k as f64 * step;
            let from = &walk[walk.len() - 1].2;
            let ((force, contact), end) = match solve(self, d, Some(from)) {
                Err(failed @ Error::NoConvergence { .. }) => {
                    substeps(self, &mut solve, (d + step, d), from, failed)?
                }
                other => other?,
            };
            if force > least && k == 1 {
                return Err(Error::InvalidParameter {
                    name: "start depth of the unloading (m)",
                    value: depth,
                    expected: "before the pull-off (the force rose at the first step)",
                });
            }
            walk.push((d, force, end));
            if walk.len() > 3 {
                walk.remove(0);
            }
            if force < least {
                // A new least: the steps around an earlier one no longer apply.
                (least, rises, around_least) = (force, 0, None);
            } else {
                rises += 1;
                if rises == 1 {
                    around_least = Some(walk.clone());
                }
            }
            // The force rising for RISES steps in a row: a contact edge
            // trapped by the lattice holds a little longer and then steps,
            // so that the force ripples about its trend (a straight edge
            // along the grid with a zone of four cells held one step 9 %
            // beyond it) and one rise is not yet the pull-off.
            if rises >= RISES || contact == 0 {
                break;
            }
            if k == MAX_UNLOADING_STEPS {
                return Err(Error::NoConvergence {
                    method: "cohesive pull-off (unloading steps)",
                    iterations: k,
                    residual: force,
                });
            }
        }
        // The least force between the steps around the least one.
        let walked: Vec<Probe<WarmStart>> = around_least
            .unwrap_or(walk)
            .into_iter()
            .map(|(depth, force, kept)| Probe { depth, force, kept })
            .collect();
        let bracket: [Probe<WarmStart>; 3] = walked.try_into().map_err(|_| Error::Internal {
            what: "cohesive pull-off",
            detail: "the walk ended with fewer than three steps".into(),
        })?;
        let probes = least_force(bracket, STEP_FRACTION * step, |d, from| {
            let ((force, _), kept) = solve(self, d, Some(&from.kept))?;
            Ok::<_, Error>(Probe {
                depth: d,
                force,
                kept,
            })
        })?;
        let lowest = probes
            .iter()
            .min_by(|a, b| a.force.total_cmp(&b.force))
            .ok_or(Error::Internal {
                what: "cohesive pull-off",
                detail: "no equilibrium".into(),
            })?;
        if self.bonded_at_rim(&lowest.kept) {
            return Err(pinned_at_rim());
        }
        (tally.depth, tally.force) = (lowest.depth, lowest.force);
        tally.cells_across = self.widest_contact_patch(&lowest.kept);
        Ok(tally)
    }
}

impl ContactSolver {
    /// Whether a cell bonded in `state` lies next to one the indenter
    /// cannot reach (the rim of a face: a flat punch), whose pull-off the
    /// cohesive zone does not represent ([`pinned_at_rim`]).
    pub(crate) fn bonded_at_rim(&self, state: &WarmStart) -> bool {
        let grid = self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let profile = &self.workspace.profile;
        (0..profile.len().min(state.attached.len())).any(|c| {
            state.attached[c]
                && super::neighbours(c, rows, columns)
                    .iter()
                    .any(|m| m.is_some_and(|m| !profile[m].is_finite()))
        })
    }

    /// The widest patch of the cells in contact in `state` (closed gaps),
    /// in cells across ([`CohesivePullOff::cells_across`]).
    pub(crate) fn widest_contact_patch(&self, state: &WarmStart) -> f64 {
        let grid = self.grid();
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        super::patch_width::widest_patch_cells(
            state.contact.as_ref().unwrap_or(&state.attached),
            grid.rows(),
            grid.columns(),
            periodic,
        )
    }
}

/// The refusal of a cohesive pull-off pinned at the rim of a face.
pub(crate) fn pinned_at_rim() -> Error {
    Error::Unsupported {
        feature: "the cohesive zone's pull-off of a contact pinned at the rim of a face \
                  (a flat punch)",
        reason: "the zone cannot form beyond the rim, so the contact detaches late and \
                 weak (Kendall's punch -23 % at 64 cells across); a punch bonded at its rim \
                 over at least 16 cells comes off along its peeling path \
                 (ContactSolver::peel_punch, peel_punch_from; Python: \
                 layered_contact.peel_punch), a round one also by the energy balance",
    }
}

/// The equilibrium at `to` (m) reached from `from`, the state at `above`,
/// in 2, 4, 8 or 16 equal substeps (the first division that converges):
/// near a fold of a force curve that ripples as a trapped edge steps, the
/// fixed point can creep for thousands of rounds from a whole step away
/// and converge from half of it (Johnson's sinusoid along the grid at
/// 8192 cells per wavelength, `BENCHMARKS.md`, "The cohesive zone grown
/// with the resolution"). Returns what `solve` returns at `to` (its
/// result and the state); the last division's [`Error::NoConvergence`] (`failed`, the
/// whole step's, if none was tried) if none converges.
pub(crate) fn substeps<T, F>(
    solver: &mut ContactSolver,
    solve: &mut F,
    (above, to): (f64, f64),
    from: &WarmStart,
    failed: Error,
) -> Result<(T, WarmStart)>
where
    F: FnMut(&mut ContactSolver, f64, Option<&WarmStart>) -> Result<(T, WarmStart)>,
{
    let mut last = failed;
    for level in 1..=SUBSTEP_LEVELS {
        let parts = 1usize << level;
        let depth = |m: usize| above + (to - above) * m as f64 / parts as f64;
        let mut reached = solve(solver, depth(1), Some(from));
        for m in 2..=parts {
            let Ok((_, state)) = &reached else { break };
            reached = solve(solver, depth(m), Some(state));
        }
        match reached {
            Err(e @ Error::NoConvergence { .. }) => last = e,
            other => return other,
        }
    }
    Err(last)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A solve that reaches depth `d` from the last depth it reached only
    /// within `reach` (m), as a fixed point that creeps from a whole step
    /// away: `substeps` divides the step until it converges (four parts
    /// of a step of 1 within 0.3), and gives up with the last division's
    /// `NoConvergence` after sixteen (within 0.01 none does).
    #[test]
    fn a_step_out_of_reach_is_taken_in_the_first_division_that_converges() {
        let (_, mut solver, _, _, warm) =
            super::super::cohesive::tests::jkr_sphere_at_one_and_a_half_radii();
        for (reach, parts) in [(0.3, Some(4)), (0.6, Some(2)), (0.01, None)] {
            let mut last = 1.0;
            let mut reached = Vec::new();
            let mut solve = |_: &mut ContactSolver, d: f64, from: Option<&WarmStart>| {
                let from = from.ok_or(Error::Internal {
                    what: "test",
                    detail: "no state".into(),
                })?;
                // A division starts again from the state at 1.
                if reached.is_empty() {
                    last = 1.0;
                }
                if last - d > reach {
                    reached.clear();
                    return Err(Error::NoConvergence {
                        method: "test",
                        iterations: 1,
                        residual: last - d,
                    });
                }
                last = d;
                reached.push(d);
                Ok((d, from.clone()))
            };
            let failed = Error::NoConvergence {
                method: "whole step",
                iterations: 0,
                residual: 1.0,
            };
            let outcome = substeps(&mut solver, &mut solve, (1.0, 0.0), &warm, failed);
            match parts {
                Some(parts) => {
                    let (depth, _) = outcome.unwrap();
                    assert_eq!(depth, 0.0);
                    assert_eq!(reached.len(), parts, "{reached:?}");
                }
                None => assert!(
                    matches!(outcome, Err(Error::NoConvergence { method: "test", .. })),
                    "{outcome:?}"
                ),
            }
        }
    }
}
