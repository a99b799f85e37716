//! Primal-dual active-set loops, for a contact whose constrained conjugate
//! gradients ([`polonsky_keer`](super::polonsky_keer)) find their contact
//! set slowly.
//!
//! On a stiff layer over a far softer base the layer bends like a plate on
//! a foundation, and a contact changes the pressures far from where a cell
//! joins or leaves it. The constrained conjugate gradients change their
//! working set a few cells an iteration: a sphere on a layer 8000 times
//! stiffer than its base took 2019 iterations to find a ring of contact
//! (`examples/disc_or_ring.rs`), where the linear system on the converged
//! set takes 5 to 29 (`benches/rough/plate_active_set.py`). A solve
//! under depth or force control (the cohesive zone's inner solves among
//! them) still running at [`ACTIVE_SET_AFTER`] iterations, on a contact
//! of few patches ([`LOOP_PATCHES`]), therefore tries, once, the loops of
//! Hintermueller, Ito & Kunisch (2002, SIAM J. Optim. 13, 865):
//! solve the linear system on the current set (the clamped solve of the
//! energy balance, preconditioned by the same box inverse), take out every
//! cell whose pressure came out tensile and add every cell the indenter
//! overlaps, until the set no longer changes. If it settles, the
//! constrained iteration goes on from its pressures, which hold the
//! conditions of the bound-constrained minimum to the clamped solve's
//! tolerance, until its own change meets the tolerance (7 and 21 more
//! iterations on `tests/plate_contact.rs`'s ring at a/h = 6 and 8 at the
//! default `1e-8`; at `1e-14`, near its rounding floor, up to hundreds:
//! `BENCHMARKS.md`, "A folding branch; the loops split across ranks"); if it does not
//! within [`MAX_LOOPS`] loops or the budget, the iteration goes on from
//! where it was. A solver split across MPI ranks runs the same loops, its
//! sums, bounds and decisions taken over every rank.

use crate::error::{Error, Result};

use super::polonsky_keer::Control;
use super::ContactSolver;

/// The iteration of the constrained conjugate gradients at which a solve
/// that has not converged tries the active-set loops: above what smooth
/// and rough contacts on a film or a half-space take (12 to 15 for a
/// Hertzian contact, 17 to 58 fine iterations for rough ones up to
/// 8192^2, `BENCHMARKS.md`), so that only the slow class is touched. A
/// rough contact on a coated stack over a soft base takes 55 to 140 (512^2
/// to 8192^2), and is kept from the loops by its patches
/// ([`LOOP_PATCHES`]).
pub(super) const ACTIVE_SET_AFTER: usize = 100;

/// The loops are not tried on a contact of more patches than this (cells
/// joined through their four neighbours; on a split run each rank counts
/// its own rows' and the counts add up). They are for a plate's disc or
/// ring, whose set the constrained iteration finds a few cells an
/// iteration (its iterate at the 100th iteration in 1 to 96 patches on
/// `tests/plate_contact.rs`). A rough contact has many small patches (the
/// converged sets of `rough_benchmark`'s coated stack in 154 / 327 / 681 /
/// 1796 patches at 256^2 / 512^2 / 1024^2 / 2048^2, its film in 315 / 1050
/// and the tamaas problem in 692 / 2142 at 512^2 / 1024^2; 237 at 256^2
/// at its 100th iteration, where the loops are still tried, cheaply) and
/// takes a linear solve a loop and many loops: `rough_benchmark isolated
/// 512 1024` with the loops from the 8th or 12th iteration took 56 / 70
/// and 42 / 68 fine iterations against 17 / 20; its coated stack at
/// 2048^2 from the 20th or 30th (the loops' solves to `1e-3` or `1e-4`)
/// 970 to 1204 against 82; from the 100th, 115 iterations at 2048^2 that gave back
/// the set it had, and at 8192^2 more than seventeen minutes (stopped)
/// where the whole solve takes five without them (2026-12-05,
/// BENCHMARKS.md, "A start level stops once its contact settles").
pub(super) const LOOP_PATCHES: usize = 256;

/// The most loops tried.
const MAX_LOOPS: usize = 30;

impl ContactSolver {
    /// Whether the contact where `pressure` is positive has at most
    /// [`LOOP_PATCHES`] patches, summed over the ranks.
    pub(super) fn few_patches(&self, pressure: &[f64]) -> bool {
        let columns = self.grid().columns();
        let rows = pressure.len() / columns.max(1);
        // A rank's rows do not wrap round onto themselves.
        let periodic =
            self.operator.boundary() == crate::Boundary::Periodic && self.operator.slab().is_none();
        let set: Vec<bool> = pressure.iter().map(|p| *p > 0.0).collect();
        let local =
            super::patch_width::patch_count_past(&set, rows, columns, periodic, LOOP_PATCHES);
        let mut count = [local as f64];
        self.sum_over_ranks(&mut count);
        count[0] <= LOOP_PATCHES as f64
    }

    /// The loops from the cells where `pressure` is positive, under
    /// `control`, over `reachable` cells, within `budget` conjugate-gradient
    /// iterations in all; `offset` the part of the displacement that the
    /// pressures do not make (an inner solve of the cohesive zone keeps
    /// the tensions' response in it). The settled pressures (`None` if the
    /// set did not settle) and the iterations spent either way, a solve
    /// that ran out of the budget counting all of it; the workspace's
    /// vectors hold no state of the caller's. Under force
    /// control each loop solves twice on the set, for a unit depth and for
    /// the profile, and takes the depth that carries the force.
    pub(super) fn active_set_loops(
        &mut self,
        control: Control,
        pressure: &[f64],
        reachable: &[bool],
        budget: usize,
        offset: Option<&[f64]>,
    ) -> Result<(Option<Vec<f64>>, usize)> {
        let n = pressure.len();
        let offset_at = |c: usize| offset.map_or(0.0, |o| o[c]);
        // The displacement the pressures must make where they act, less the
        // depth.
        let profile: Vec<f64> = (0..n)
            .map(|c| -self.workspace.profile[c] - offset_at(c))
            .collect();
        // What each loop's first solve is for: the displacement at the
        // depth, or under force control a unit depth.
        let first: Vec<f64> = match control {
            Control::Depth(d) => profile.iter().map(|f| d + f).collect(),
            Control::Force(_) => vec![1.0; n],
        };
        let mut member: Vec<bool> = pressure.iter().map(|p| *p > 0.0).collect();
        let mut p: Vec<f64> = pressure.iter().map(|p| p.max(0.0)).collect();
        // Under force control, the solutions for a unit depth and for the
        // profile, and the first one's displacement.
        let (mut unit, mut shape) = (vec![0.0; n], vec![0.0; n]);
        let mut unit_response = Vec::new();
        let mut spent = 0;
        for _ in 0..MAX_LOOPS {
            if !self.on_any_rank(member.iter().any(|m| *m)) {
                return Ok((None, spent));
            }
            let depth = match control {
                Control::Depth(d) => {
                    if !self.solve_on(&member, &first, &mut p, budget, &mut spent)? {
                        return Ok((None, spent));
                    }
                    d
                }
                Control::Force(w) => {
                    if !self.solve_on(&member, &first, &mut unit, budget, &mut spent)? {
                        return Ok((None, spent));
                    }
                    unit_response.clone_from(&self.workspace.displacement);
                    if !self.solve_on(&member, &profile, &mut shape, budget, &mut spent)? {
                        return Ok((None, spent));
                    }
                    let mut sums = [unit.iter().sum(), shape.iter().sum()];
                    self.sum_over_ranks(&mut sums);
                    let [a, b] = sums;
                    if !a.is_finite() || a <= 0.0 || !b.is_finite() {
                        return Ok((None, spent));
                    }
                    let d = (w / self.grid().cell_area() - b) / a;
                    for c in 0..n {
                        p[c] = d * unit[c] + shape[c];
                        self.workspace.displacement[c] += d * unit_response[c];
                    }
                    d
                }
            };
            if let Some(offset) = offset {
                for (u, o) in self.workspace.displacement.iter_mut().zip(offset) {
                    *u += o;
                }
            }
            // Overlap counts beyond the solve's own tolerance on the scale
            // of the prescribed displacements.
            let scale = profile
                .iter()
                .zip(&member)
                .filter(|(_, m)| **m)
                .fold(0.0f64, |s, (f, _)| s.max((depth + f).abs()));
            let scale = self.max_over_ranks(scale);
            let overlap = -self.params.tolerance * scale;
            let ws = &self.workspace;
            let mut changed = false;
            for c in 0..n {
                if member[c] {
                    if p[c] < 0.0 {
                        member[c] = false;
                        p[c] = 0.0;
                        unit[c] = 0.0;
                        shape[c] = 0.0;
                        changed = true;
                    }
                } else if reachable[c] && ws.profile[c] - depth + ws.displacement[c] < overlap {
                    member[c] = true;
                    changed = true;
                }
            }
            if !self.on_any_rank(changed) {
                return Ok((Some(p), spent));
            }
        }
        Ok((None, spent))
    }

    /// The clamped solve of `x` on `member` for `target`, within what is
    /// left of `budget` after `spent` (which it adds to, all that was left
    /// if it did not converge): whether it ran to its tolerance. The
    /// solver's own iteration limit is restored.
    fn solve_on(
        &mut self,
        member: &[bool],
        target: &[f64],
        x: &mut [f64],
        budget: usize,
        spent: &mut usize,
    ) -> Result<bool> {
        if *spent >= budget {
            return Ok(false);
        }
        let left = budget - *spent;
        let saved = std::mem::replace(&mut self.params.max_iterations, left);
        // The two-level preconditioner if it was set; not the automatic
        // choice's (the loops run on contacts of few patches).
        let two_level = !self.coarse_automatic;
        let solved = self.clamped_cg_with(member, target, x, two_level);
        self.params.max_iterations = saved;
        match solved {
            Ok((iterations, _)) => {
                *spent += iterations;
                Ok(true)
            }
            Err(Error::NoConvergence { .. }) => {
                *spent = budget;
                Ok(false)
            }
            Err(e) => Err(e),
        }
    }
}
