//! Adhesive contact in the JKR limit through a cohesive zone resolved on the
//! grid: a short-range adhesive law whose range shrinks with the cell, so
//! that its zone spans a fixed number of cells and the solution tends to
//! the JKR limit as the grid is refined, for any contact shape.
//!
//! The law (energy per unit area of a gap `g`, `w(g) = -dgamma (1 -
//! g/rho)^2` for `g < rho`, zero beyond) pulls with the tension `sigma(g) =
//! -(2 dgamma / rho)(1 - g/rho)`; its zone, where the gap is open but below
//! `rho`, is `E* rho^2 / (4 dgamma)` long (Maugis 1992, J. Colloid
//! Interface Sci. 150, 243, for Dugdale's law; the same scale for this
//! one). With the range `rho = 2 sqrt(dgamma k Delta / E*)` it spans `k`
//! cells. The JKR limit is the zone's vanishing width: `G = dgamma` holds
//! at every point of every edge without the edge being located.
//!
//! Each equilibrium is a fixed point: for given tensions `t` (one per cell,
//! from the gaps) the contact is the non-adhesive one of the profile
//! shifted by their displacement, `f + K t`, solved by the constrained
//! conjugate gradients for the compressive part `p' = p - t >= 0`; the
//! gaps of that solution give new tensions. The map's rate is the law's
//! negative stiffness `2 dgamma / rho^2` times the zone's compliance with
//! the contact held: plain rounds contract by 0.53, 0.74 and 0.85 at 16,
//! 32 and 64 cells across a pull-off contact (a zone of four cells), the
//! slowest modes the edge's low angular harmonics (a change of one sign all
//! round, largest at the zone's outer side). A model of the map puts the
//! rise on the zone's width in cells against the law's (0.52, 0.72, 0.90
//! for zones of 3, 4, 5 cells, whatever the contact's size): the lattice
//! traps the zone less on finer grids. The Anderson mixing reaches about
//! 0.3 and 0.45 a round at 32 and 64 cells, the rate of a Krylov method on
//! a spectrum that wide (19 and 28 rounds a solve; `BENCHMARKS.md`,
//! "Adhesive scene cycles: error and cost"). Each round's residual is
//! therefore smoothed along the zone and amplified before it is mixed
//! (`cohesive_smoothing.rs`), which narrows the
//! spectrum: 13 and 19 rounds a solve, 57 and 79 CG iterations, against
//! 19 and 28 rounds, 81 and 115 iterations, without. Near a pull-off (a fold of the equilibrium
//! branch) it slows down, and beyond it the iteration walks the contact
//! off, as the quasi-static jump does. A round costs the
//! inner solve's iterations and one operator application (the response to
//! the change of the total pressure, which moves the profile while the
//! inner solve keeps its displacement; both computed afresh every
//! `FRESH_ROUNDS` rounds).

use std::borrow::Cow;

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::cohesive_area::open_zone_cells;
#[cfg(doc)]
use super::cohesive_area::EQUIVALENT_TIP;
use super::cohesive_bonding::{bonded_from, recedes};
use super::cohesive_closest::{Round, CLOSE_ENOUGH};
#[cfg(doc)]
use super::cohesive_law::ZONE_LAYER_FRACTION;
use super::cohesive_law::{zone_modulus, CohesiveZone, Law};
use super::cohesive_smoothing::ZoneSmoothing;
use super::cohesive_steps::Stepper;
use super::overlap_joining::Origin;
use super::polonsky_keer::{Control, StartDisplacement};
use super::{check_finite, ContactSolver, Observer, Solution, WarmStart};

/// The largest change of the cells' curvature factors (as their square
/// roots, weighted by the tensions they scale) between the contact a solve
/// started from and the one it converged to that is left unread
/// ([`ContactSolver::solve_depth_cohesive`]).
const ROOT_TOLERANCE: f64 = 2e-3;

/// The change of the tensions (over the law's peak) below which the
/// contact counts as settled and its curvature is read again, before the
/// fixed point converges to its tolerance: the rounds that converge the
/// last digits then run once, with the law of that contact. Measured on
/// the tilted paraboloid's cycle (`examples/adhesive_cycle_cost`,
/// `BENCHMARKS.md`, "Adhesive scene cycles: error and cost"): 1679 / 2263
/// / 3223 CG iterations at 16 / 32 / 64 cells across, against 1934 / 2787
/// / 4162 reading only the converged contact; 1767 / 2334 / 3627 at 1e-2.
const SETTLED_CHANGE: f64 = 1e-3;

/// Times one solve reads its curvature again (from a settled or a
/// converged contact) and finds it changed. Reads stop sooner once one
/// changes the law by no less than the read before it: on the reference
/// sweep's seed 208 (a sphere on a 58 um incompressible layer over a base
/// 1400 times stiffer, `BENCHMARKS.md`, "A law that jumped at the zone's
/// far side") the receding contact's successive reads changed the law by
/// 2.3, 6.5, 9.0, 9.6 and 10.5 % (tension-weighted), each costing some
/// fifty rounds.
const MAX_REREADS: usize = 8;

/// Rounds that move the profile by the response to the change of the
/// total pressure (one operator application) between those that compute
/// the tensions' displacement and the inner solve's afresh (two), against
/// the drift of the increments.
const FRESH_ROUNDS: usize = 8;

/// How many of the law's ranges the compressive pressures' displacement
/// may reach before the inner solves are tightened below a hundredth of
/// the last change ([`gap_amplification`]). The hundredth leaves that
/// margin: on the tilted paraboloid's cycle (a half-space, where the
/// displacement is a few ranges: about half the cells across the contact
/// over the zone's cells) tightening by the whole displacement cost 13 /
/// 23 / 39 % more CG iterations at 16 / 32 / 64 cells across and changed
/// the pull-offs by under 5e-4 of themselves. On a stiff film over a far
/// softer base (1.6e4 ranges) tightening by a sixteenth of it instead of
/// the whole took 4 to 5 times the iterations a loading step
/// (`BENCHMARKS.md`, "A stiff film over a far softer base"): the factor is
/// the displacement less this margin.
const GAP_MARGIN: f64 = 16.0;

/// The tightest relative change an inner solve is asked for (as the fixed
/// point's own tolerance is at least this).
const INNER_FLOOR: f64 = 1e-13;

/// The factor by which an inner solve's relative change must fall below
/// the one its gaps need on a body where the contact's held tensions move
/// the surface by many of the law's ranges: `max |K t| / rho` less
/// [`GAP_MARGIN`] - 1, at least 1.
///
/// Inside the contact every cell carries the law's peak tension, which the
/// compressive part `p'` cancels. An inner solve to a relative change `r`
/// leaves its gaps wrong by about `r` times the displacement of `p'`, which
/// is about the tensions' own, `max |K t|`; a round's tensions need them
/// right to a part of the law's range `rho`. On a half-space `max |K t|` is
/// a few ranges. On a stiff film over a far softer base it is thousands (a
/// 4.3 GPa film 3.2 um thick over a 0.92 MPa base, a sphere at depth 0:
/// `max |K t|` 1.6e4 ranges): inner solves to a hundredth of the change
/// left the gaps wrong by many ranges, so the rounds never settled, and
/// the fixed point ran to its round limit with the change at the law's
/// peak (`BENCHMARKS.md`, "A stiff film over a far softer base").
fn gap_amplification(kt: &[f64], range: f64) -> f64 {
    let reach = kt.iter().fold(0.0f64, |m, k| m.max(k.abs()));
    (reach / range - (GAP_MARGIN - 1.0)).max(1.0)
}

/// Fixed-point rounds of one cohesive solve before it gives up.
pub(super) const MAX_ROUNDS: usize = 2000;

impl ContactSolver {
    /// Each cell's curvature factor of `zone`'s law, as its square root,
    /// from the cells in `contact`.
    fn curvature_roots(&self, contact: &[bool], zone: &CohesiveZone) -> Vec<f64> {
        let grid = self.grid();
        let bend = super::curvature::edge_curvature(
            contact,
            grid.rows(),
            grid.columns(),
            self.operator.boundary() == crate::grid::Boundary::Periodic,
            zone.zone_cells,
        );
        bend.iter()
            .map(|kappa| {
                let bias = zone.curvature_correction * kappa * zone.zone_cells;
                (1.0 / (1.0 + bias.clamp(-0.5, 0.5))).sqrt()
            })
            .collect()
    }

    /// Adhesive contact at `depth` (m) in the JKR limit by a cohesive zone
    /// resolved on the grid ([`CohesiveZone`]; the method is described in
    /// [`doc::adhesion`](crate::doc::adhesion)). Any contact shape, on
    /// isolated and periodic grids: edges advance and recede where their
    /// local energy release rate asks, contacts split and merge. `warm`
    /// carries the history (the last pressures and which cells are bonded).
    /// With hysteresis (receding work above the advancing one) a solve that
    /// withdraws the indenter from a `warm` that was not itself withdrawn
    /// (a smaller depth here, a smaller force in
    /// [`solve_force_cohesive`](Self::solve_force_cohesive)) also bonds the
    /// advancing zone's cells within 0.6 of its range, so that the edge
    /// stays pinned where loading left it (`BENCHMARKS.md`, "A pinned edge
    /// under hysteresis"); a cell that closes during a solve that is not
    /// withdrawn carries at most the advancing law's peak until an
    /// equilibrium bonds it, so that loading follows the advancing work.
    ///
    /// The solution's pressure includes the tension of the open zone
    /// (cells out of contact within the law's range); its contact cells
    /// are those whose gap is closed, and its contact area adds
    /// [`EQUIVALENT_TIP`] of the open zone's cells around them (the
    /// equivalent crack's). On a layered body the zone is at
    /// most [`ZONE_LAYER_FRACTION`] of the top layer's thickness
    /// ([`CohesiveZone::cells_on`]); where that is under two cells
    /// ([`CohesiveZone::resolves_layer`] false) the pull-off is biased by
    /// per cents and scenes report it.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth;
    /// [`Error::ShapeMismatch`] for a warm start from another grid;
    /// [`Error::NoConvergence`] if an inner solve does not converge, or the
    /// fixed point does not and its rounds never came within 1e-6 of the
    /// law's peak (where they did and left again, the solution is the
    /// closest round's, its `residual` saying how close; under force
    /// control, [`solve_force_cohesive`](Self::solve_force_cohesive),
    /// never); [`Error::ContactReachesEdge`] where the fixed point (under
    /// depth control) does not converge with its last round's zone or
    /// contact on the outer ring of an isolated grid (the zone may want to
    /// spread beyond it: a scene widens its grid); as
    /// [`ContactSolver::solve_depth`] otherwise.
    pub fn solve_depth_cohesive<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        zone: &CohesiveZone,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        check_finite("depth", depth)?;
        let control = Control::Depth(depth);
        let limits = (MAX_ROUNDS, &mut 0);
        self.cohesive_fixed_point(indenter, control, depth, zone, warm, limits, observer)
    }

    /// The fixed point of the cohesive zone under `control`, its gaps first
    /// read at `depth` (m; under force control the depth of `warm`, then
    /// each inner solve's), in at most `max_rounds` rounds, adding the CG
    /// iterations to `spent`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn cohesive_fixed_point<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        control: Control,
        depth: f64,
        zone: &CohesiveZone,
        warm: Option<&WarmStart>,
        (max_rounds, spent): (usize, &mut usize),
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        self.serial_only(match control {
            Control::Depth(_) => "solve depth cohesive",
            Control::Force(_) => "solve force cohesive",
        })?;
        self.check_warm_start(warm)?;
        self.sample_profile(indenter)?;
        let mut depth = depth;
        let spacing = self.grid().spacing();
        let area = self.grid().cell_area();
        // The zone within a quarter of the top layer.
        let zone = &CohesiveZone {
            zone_cells: zone.cells_on(spacing, self.substrate.top_thickness()),
            ..*zone
        };
        // The body's modulus at the zone's length, so that the zone spans
        // its cells on any body.
        let modulus = zone_modulus(
            &self.compliance,
            self.surface_contact_modulus,
            zone.zone_cells * spacing,
            self.substrate.top_thickness(),
        )?;
        let grid_area = self.grid().len() as f64 * area;
        let advancing = Law::new(zone, zone.advancing, spacing, modulus, grid_area)?;
        let receding = Law::new(zone, zone.receding, spacing, modulus, grid_area)?;
        let n = self.local_cells();
        let base = self.workspace.profile.clone();
        // The tensions from the gaps of the last pressures at this depth.
        let total = match warm {
            Some(w) => w.pressure.clone(),
            None => vec![0.0; n],
        };
        let mut kt = super::cell_vector(n)?;
        self.operator.apply(&total, &mut kt)?;
        let grid = *self.grid();
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        let (mut bonded, withdrawn) = match warm {
            // With hysteresis a reversal bonds the advancing zone too.
            Some(w) if zone.receding > zone.advancing => bonded_from(
                w,
                control,
                depth,
                (&base, &kt),
                area,
                ((grid.rows(), grid.columns()), periodic),
                advancing.range,
            ),
            Some(w) => (w.attached.clone(), false),
            None => (vec![false; n], false),
        };
        let prior = bonded.clone();
        let mut tension = vec![0.0; n];
        let held = warm.and_then(|w| w.contact.as_deref());
        for c in 0..n {
            // The warm start's contact is held at first (its cells at the
            // law's peak, as every round holds the round's contact), not
            // opened by the step of depth: on a body whose contact moves
            // as a whole (a stiff coating on a far softer base) the drop of
            // their tensions moved the whole surface away and the first
            // round lost the contact.
            let touching = held.is_some_and(|h| h.get(c) == Some(&true));
            let g = if touching {
                0.0
            } else {
                (base[c] - depth + kt[c]).max(0.0)
            };
            let law = if recedes(bonded[c], prior[c], withdrawn) {
                &receding
            } else {
                &advancing
            };
            tension[c] = law.tension(g);
        }
        let mut compressive: Vec<f64> = (0..n).map(|c| (total[c] - tension[c]).max(0.0)).collect();
        // The inner solves' control: under force control the load the
        // compressive part carries, set with each round's tensions.
        let mut inner_control =
            super::cohesive_force::carry(control, area, &tension, (&mut compressive, 0))?;
        let scale = receding.peak.max(f64::MIN_POSITIVE);
        let outer = self.params.tolerance;
        let tolerance = outer.max(1e-13);
        let mut iterations = 0usize;
        let mut change = f64::INFINITY;
        let mut stepper = Stepper::new();
        let mut smoothing = ZoneSmoothing::new(
            grid.rows(),
            grid.columns(),
            self.operator.boundary() == crate::grid::Boundary::Periodic,
        );
        let mut zone_cells = vec![false; n];
        let mut target = vec![0.0; n];
        let mut mapped = vec![0.0; n];
        // Each cell's law as the square root of its curvature factor (the
        // peak and the range scale with it), set at the first round and
        // read again from settled and converged contacts.
        let mut roots: Vec<f64> = Vec::new();
        // Each cell's largest tension, Pa (its law's peak).
        let mut caps = vec![0.0; n];
        // Curvatures read again and found changed.
        let mut rereads = 0usize;
        // The last accepted read's change (weighted, over the pull).
        let mut last_moved = f64::INFINITY;
        // The round closest to the equilibrium within `CLOSE_ENOUGH` since
        // the law last changed, handed back if the rounds then leave it.
        let mut closest: Option<Round> = None;
        // Whether the curvature was read since the tensions settled (or
        // the law last changed).
        let mut checked = false;
        // The round's contact: the cells carrying compressive pressure.
        let mut contact = vec![false; n];
        // The change of the tensions plus that of the compressive
        // pressures since the last inner solve ended, whether it is
        // pending (not before the first round), and the rounds since `kt`
        // and the displacement were computed afresh.
        let mut change_of_total = vec![0.0; n];
        let mut pending = false;
        let mut since_fresh = 0usize;
        for round in 0..max_rounds {
            self.check_interrupt("the cohesive zone's fixed point")?;
            // Between fresh rounds one application of the operator, to the
            // change of the total pressure, moves the profile: the inner
            // solve keeps the displacement of its last pressures, so that
            // `profile + u` is `base + K (tensions + pressures)` while `kt`
            // and `u` each carry the response to the pressures' change.
            let keep = std::mem::take(&mut pending)
                && since_fresh < FRESH_ROUNDS
                && compressive.iter().any(|p| *p > 0.0);
            let mode = if keep {
                if change_of_total.iter().any(|d| *d != 0.0) {
                    self.operator.apply(&change_of_total, &mut mapped)?;
                    for (k, d) in kt.iter_mut().zip(&mapped) {
                        *k += d;
                    }
                }
                since_fresh += 1;
                StartDisplacement::Given
            } else {
                self.operator.apply(&tension, &mut kt)?;
                since_fresh = 0;
                StartDisplacement::Compute
            };
            for ((f, b), k) in self.workspace.profile.iter_mut().zip(&base).zip(&kt) {
                *f = b + k;
            }
            let start = WarmStart {
                pressure: std::mem::take(&mut compressive),
                attached: Vec::new(),
                contact: None,
                withdrawn: false,
            };
            // Inner solves only as tight as the fixed point has come: a
            // hundredth of the last change of the tensions, tighter where
            // the compressive pressures' displacement dwarfs the law's
            // range (`gap_amplification`).
            let loose = tolerance.max(1e-2 * change.min(scale) / scale);
            let inner = (loose / gap_amplification(&kt, receding.range)).max(INNER_FLOOR);
            self.params.tolerance = inner;
            // The fixed point follows the inner solves' last digits: a
            // double-precision preconditioner (`Preconditioner`) and
            // operator.
            let before = std::mem::replace(&mut self.double_preconditioner, true);
            let solved = self.constrained_cg(
                inner_control,
                Some(Cow::Owned(start)),
                mode,
                false,
                Origin::Warm,
                observer,
            );
            self.double_preconditioner = before;
            self.params.tolerance = outer;
            let (solution, end) = match solved {
                Ok(pair) => pair,
                Err(e) => {
                    self.workspace.profile.copy_from_slice(&base);
                    return Err(e);
                }
            };
            iterations += solution.iterations;
            *spent += solution.iterations;
            depth = solution.depth;
            compressive = end.pressure;
            // The tensions the law gives at the gaps of this solution.
            let previous = change;
            change = 0.0;
            for (k, p) in contact.iter_mut().zip(&compressive) {
                *k = *p > 0.0;
            }
            // The edge's curvature from the first round's contact, then
            // held while the fixed point converges (the law does not change
            // with the contact within those rounds); read again below once
            // the tensions settle and from the converged contact.
            if zone.curvature_correction > 0.0 && roots.is_empty() {
                roots = self.curvature_roots(&contact, zone);
            }
            let ws = &self.workspace;
            let mut contact_cells = 0usize;
            for c in 0..n {
                let touching = contact[c];
                contact_cells += usize::from(touching);
                let g = if touching {
                    0.0
                } else {
                    (ws.profile[c] - depth + ws.displacement[c]).max(0.0)
                };
                let root = roots.get(c).copied().unwrap_or(1.0);
                // Bonded: in contact now, or bonded at the equilibrium the
                // solve started from and not opened past the range since.
                // A round's contact is not the path's: a cell that one
                // round closed and the next opened again was never bonded
                // at an equilibrium (with hysteresis, a fixed point whose
                // contact overshot kept the overshoot at the receding work).
                bonded[c] = touching || (prior[c] && g < receding.range * root);
                let law = if recedes(bonded[c], prior[c], withdrawn) {
                    &receding
                } else {
                    &advancing
                };
                let law = law.scaled(root);
                mapped[c] = law.tension(g);
                caps[c] = law.peak;
                change = f64::max(change, (mapped[c] - tension[c]).abs());
            }
            let converged = change <= tolerance * scale && loose <= tolerance;
            let settled = change <= SETTLED_CHANGE.max(tolerance) * scale;
            let mut law_changed = false;
            if (converged || (settled && !checked))
                && zone.curvature_correction > 0.0
                && rereads < MAX_REREADS
            {
                // A step that moved the contact far (a coarse protocol
                // step) read its curvature from a contact unlike the
                // converged one: read it again, and go on while it moves.
                // Read first once the tensions have settled (the contact
                // no longer moves), so that the rounds that converge the
                // last digits run once, with the law of that contact.
                checked = true;
                let fresh = self.curvature_roots(&contact, zone);
                // The change weighted by the tensions it scales.
                let (mut moved, mut pull) = (0.0, 0.0);
                for ((a, b), t) in fresh.iter().zip(&roots).zip(&mapped) {
                    moved += (a - b).abs() * t.abs();
                    pull += t.abs();
                }
                let ratio = moved / pull.max(f64::MIN_POSITIVE);
                let changed = moved > ROOT_TOLERANCE * pull;
                if changed && ratio >= last_moved {
                    // A read that changes the law by no less than the last
                    // one does not converge it: a contact ragged at the
                    // cell's scale (specks and holes whose curvatures sit
                    // at the clamps) reads another law each time it moves
                    // a cell. Keep the last law and read no more.
                    rereads = MAX_REREADS;
                } else if changed {
                    last_moved = ratio;
                    roots = fresh;
                    rereads += 1;
                    // Rounds of the old law are not this one's.
                    closest = None;
                    law_changed = true;
                    stepper.law_changed();
                    checked = false;
                    if converged {
                        // Nothing moved: the next round starts where
                        // this one ended.
                        change_of_total.fill(0.0);
                        pending = true;
                        continue;
                    }
                }
            }
            // Under force control a fixed point that does not converge is
            // how a force past the least one shows (no equilibrium): only
            // depth control keeps its closest round.
            let closer = closest.as_ref().is_none_or(|r| change < r.residual * scale)
                && matches!(control, Control::Depth(_));
            if converged || (change <= CLOSE_ENOUGH * scale && closer && !law_changed) {
                // The round of the tensions just solved for (the law's
                // tensions at its gaps differ by at most `change`), with
                // the displacement of its total pressure.
                let round = Round {
                    total: (0..n).map(|c| compressive[c] + tension[c]).collect(),
                    displacement: (self.workspace.displacement.iter().zip(&kt))
                        .map(|(u, k)| u + k)
                        .collect(),
                    contact: contact.clone(),
                    bonded: bonded.clone(),
                    open: open_zone_cells(
                        &contact,
                        &tension,
                        (grid.rows(), grid.columns()),
                        periodic,
                    ),
                    depth,
                    residual: change / scale,
                    withdrawn,
                };
                if converged {
                    self.workspace.profile.copy_from_slice(&base);
                    return self.cohesive_round_solution(round, iterations);
                }
                closest = Some(round);
            }
            for ((d, t), p) in change_of_total.iter_mut().zip(&tension).zip(&compressive) {
                *d = -(t + p);
            }
            for (z, (&m, &k)) in zone_cells.iter_mut().zip(mapped.iter().zip(&contact)) {
                *z = !k && m != 0.0;
            }
            smoothing.precondition(&zone_cells, &mapped, &tension, &mut target);
            stepper.next(
                change,
                previous,
                contact_cells,
                &mut tension,
                &target,
                &caps,
            );
            // The compressive part keeps the total pressure of the cells
            // (under force control scaled to carry the force the tensions
            // leave).
            for c in 0..n {
                if compressive[c] > 0.0 {
                    compressive[c] = (compressive[c] + mapped[c] - tension[c]).max(0.0);
                }
            }
            let rounds = round + 1;
            match super::cohesive_force::carry(control, area, &tension, (&mut compressive, rounds))
            {
                Ok(carried) => inner_control = carried,
                Err(e) => {
                    self.workspace.profile.copy_from_slice(&base);
                    return Err(e);
                }
            }
            for c in 0..n {
                change_of_total[c] += tension[c] + compressive[c];
            }
            pending = true;
        }
        self.workspace.profile.copy_from_slice(&base);
        if let Some(round) = closest {
            // The rounds came within `CLOSE_ENOUGH` and left again.
            return self.cohesive_round_solution(round, iterations);
        }
        // A zone that reached the outer ring of an isolated grid may have
        // wanted to spread beyond it: the grid, not the fixed point, is
        // what to change (a scene widens it).
        let (rows, columns) = (grid.rows(), grid.columns());
        // Under force control a fixed point that does not converge is how a
        // force past the least one shows, whatever its zone.
        let at_edge = !periodic
            && matches!(control, Control::Depth(_))
            && (0..n).any(|c| {
                (contact[c] || mapped[c] != 0.0) && super::on_outer_ring(c, rows, columns)
            });
        if at_edge {
            return Err(Error::ContactReachesEdge {
                cells: contact.iter().filter(|k| **k).count(),
                detail: "the cohesive zone's fixed point did not settle with its zone on the \
                         grid's outer ring: use a wider grid",
            });
        }
        Err(Error::NoConvergence {
            method: "cohesive zone fixed point",
            iterations: max_rounds,
            residual: change / scale,
        })
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::analytic::JkrSphere;
    use crate::indenter::Sphere;
    use crate::{Boundary, Grid, Material, Substrate};

    /// The JKR sphere (`R` = 1 cm, `dgamma` = 0.05 J/m^2 on a 1 MPa rubber
    /// half-space) on a grid of 48 cells across four pull-off contact
    /// radii, its solver, the zone (four cells) and the equilibrium at 1.5
    /// pull-off radii.
    pub(in crate::solver) fn jkr_sphere_at_one_and_a_half_radii(
    ) -> (JkrSphere, ContactSolver, Sphere, CohesiveZone, WarmStart) {
        let rubber = Material::new(1e6, 0.48).unwrap();
        let (radius, work) = (1e-2, 0.05);
        let jkr = JkrSphere::new(&rubber, radius, work).unwrap();
        let a = jkr.pull_off_contact_radius();
        let grid = Grid::square_of_side(48, 4.0 * a).unwrap();
        let body = Substrate::half_space(rubber);
        let params = crate::solver::SolverParams::default();
        let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
        let sphere = Sphere::new(radius).unwrap();
        let zone = CohesiveZone::new(work, work).unwrap();
        let (_, warm) = solver
            .solve_depth_cohesive(&sphere, jkr.depth(1.5 * a), &zone, None, &mut ())
            .unwrap();
        (jkr, solver, sphere, zone, warm)
    }

    /// A work of adhesion whose law overflows on the grid (`1e308` J/m^2:
    /// its range is infinite and its peak NaN) is refused by name, not
    /// solved into NaN tensions (a panic in the stepping's clamp, found
    /// by `tests/fuzz_scenes.rs` with `LAYERED_CONTACT_FUZZ_SEED=2026`);
    /// `1e30` builds a finite law on the same grid.
    #[test]
    fn a_work_of_adhesion_whose_law_overflows_is_refused() {
        let rubber = Material::new(1e6, 0.48).unwrap();
        let grid = Grid::square_of_side(16, 1e-3).unwrap();
        let body = Substrate::half_space(rubber);
        let params = crate::solver::SolverParams::default();
        let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
        let sphere = Sphere::new(1e-2).unwrap();
        let zone = CohesiveZone::new(1e308, 1e308).unwrap();
        let error = solver
            .solve_depth_cohesive(&sphere, 1e-6, &zone, None, &mut ())
            .unwrap_err();
        assert!(
            matches!(error, Error::InvalidParameter { name: "work of adhesion", value, .. } if value == 1e308),
            "{error}"
        );
        let area = grid.len() as f64 * grid.cell_area();
        let finite = CohesiveZone::new(1e30, 1e30).unwrap();
        let law = Law::new(&finite, 1e30, grid.spacing(), 1e6, area).unwrap();
        // peak = 2 dgamma / rho, rho = 2 sqrt(dgamma k Delta / E*).
        let range = 2.0 * (1e30 * 4.0 * grid.spacing() / 1e6).sqrt();
        assert!((law.range / range - 1.0).abs() < 1e-15);
        assert!((law.peak * range / 2e30 - 1.0).abs() < 1e-15);
    }

    /// The JKR sphere pressed to a contact of 1.5 pull-off radii on a grid
    /// only 1.5 of them wide, its fixed point stopped after three rounds:
    /// the zone lies on the grid's outer ring, so the error asks for a
    /// wider grid (`ContactReachesEdge`, which a scene answers by widening
    /// it) rather than more rounds; on the grid of four radii the same
    /// three rounds end in `NoConvergence`. Before 2026-12-04 (thirty-second
    /// session) both were `NoConvergence`, and the reference sweep's seed
    /// 162 (a stack whose contact the exact sizing put inside 7 mm, its
    /// zone spreading to the grid's edge at 7.9 mm) failed on a grid a
    /// scene would have widened.
    #[test]
    fn a_zone_that_does_not_settle_on_the_outer_ring_asks_for_a_wider_grid() {
        let rubber = Material::new(1e6, 0.48).unwrap();
        let (radius, work) = (1e-2, 0.05);
        let jkr = JkrSphere::new(&rubber, radius, work).unwrap();
        let a = jkr.pull_off_contact_radius();
        let body = Substrate::half_space(rubber);
        let sphere = Sphere::new(radius).unwrap();
        let zone = CohesiveZone::new(work, work).unwrap();
        let depth = jkr.depth(1.5 * a);
        for (width, at_edge) in [(1.5, true), (4.0, false)] {
            let grid = Grid::square_of_side(24, width * a).unwrap();
            let params = crate::solver::SolverParams::default();
            let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
            let (control, limits) = (Control::Depth(depth), (3, &mut 0));
            let error = solver
                .cohesive_fixed_point(&sphere, control, depth, &zone, None, limits, &mut ())
                .unwrap_err();
            let reaches = matches!(error, Error::ContactReachesEdge { .. });
            let stopped = matches!(error, Error::NoConvergence { iterations: 3, .. });
            assert_eq!((reaches, stopped), (at_edge, !at_edge), "{width}: {error}");
        }
    }

    /// The JKR sphere at its pull-off contact radius, loaded and unloaded
    /// a step, with the displacement refreshed every three iterations
    /// (`REFRESH` in unit tests): the rounds that keep the inner solve's
    /// displacement refresh it with their offset. A refresh that lost the
    /// offset did not converge; the force within the staircase's error
    /// of JKR's (12 cells across the contact radius).
    #[test]
    fn the_kept_displacement_survives_its_refreshes() {
        let (jkr, mut solver, sphere, zone, warm) = jkr_sphere_at_one_and_a_half_radii();
        let a = jkr.pull_off_contact_radius();
        let (solution, _) = solver
            .solve_depth_cohesive(&sphere, jkr.depth(a), &zone, Some(&warm), &mut ())
            .unwrap();
        let error = solution.force / jkr.force(a) - 1.0;
        assert!(error.abs() < 0.05, "{error}");
    }
}
