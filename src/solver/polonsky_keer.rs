//! Non-adhesive contact by constrained conjugate gradients (Polonsky & Keer
//! 1999, Wear 231, 206-219), preconditioned with the compliance's inverse on
//! a box around the contact (Vollebregt 2014, J. Comput. Phys. 257,
//! 333-351), with a multi-resolution start. Unlike Polonsky and Keer, the
//! conjugation survives new overlap joining the working set (a projected
//! Fletcher-Reeves step, Fletcher & Reeves 1964, Comput. J. 7, 149-154),
//! restarted only where the new direction would not descend: rough
//! contacts, whose working set grows in most early iterations, otherwise
//! iterate near steepest descent. A solve whose change has stopped falling
//! goes back to Polonsky and Keer's restarts ([`stall`](super::stall)); one
//! still running at its 100th iteration tries primal-dual
//! active-set loops once ([`active_set`](super::active_set): a plate over a
//! soft base changes its set a few cells an iteration). On a fine solve,
//! new overlap away from the contact's edge (after the multi-resolution
//! start, any new overlap while the contact shrinks) joins the working set
//! only if at least as deep as the overlap's mean, and after that start
//! only if the contact's own gap error, smoothed along the row, does not
//! explain it ([`overlap_joining`](super::overlap_joining)). A
//! cold solve's early iterations, until the
//! change per iteration falls to `1e-5`, apply the operator in single
//! precision; the displacement is then recomputed in double and the solve
//! ends in double ([`EARLY_ABOVE`]), its conjugation restarted there and
//! once before ([`RESTART_BELOW`]). The multi-resolution start
//! is in [`multiresolution`](super::multiresolution), the preconditioner's
//! box in [`preconditioning`](super::preconditioning), the operator's part
//! of a step in [`step_response`](super::step_response).

use std::borrow::Cow;
use std::ops::Range;

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::active_set::ACTIVE_SET_AFTER;
use super::coarse_choice::{CoarseChoice, Preconditioning};
use super::multiresolution::{count_settled, loosened, start_count_settled};
use super::overlap_joining::{Origin, RowEstimate};
use super::stall::Stall;
use super::step_response::Arithmetic;
use super::{check_finite, passes, ContactSolver, IterationInfo, Observer, Solution, WarmStart};

/// The smallest load the solver takes, as a penetration over the cell size
/// or a force over `E* Delta^2`: the constrained conjugate gradients square
/// pressures and gaps, and below about `1e-150` of their natural scale the
/// squares leave the normal `f64` range (depths of `1e-200` m did not
/// converge, forces of `1e-200` N came out 7 % off).
const MIN_LOAD_SCALE: f64 = 1e-100;

/// Iterations between full recomputations of `u = K p` (three in unit
/// tests, so that the refreshes, and the one that keeps a given start
/// displacement's offset, run in short solves too).
const REFRESH: usize = if cfg!(test) { 3 } else { 50 };

/// The relative change of the pressure per iteration that ends a cold
/// solve's early iterations, which apply the operator in single precision
/// ([`Arithmetic`]): `f32`'s rounding moves the displacement by about
/// `1e-7` of its scale a step, and the change stays far above that until
/// here. The displacement is then recomputed in double and the
/// conjugation restarts. Measured in BENCHMARKS.md ("Speed: rough
/// contacts on large grids"): the same iterations with the end at `1e-6`,
/// seven more at `1e-7` on the rough film at 4096^2.
const EARLY_ABOVE: f64 = 1e-5;

/// The relative change of the pressure per iteration at which a cold
/// solve restarts its conjugation once (besides at [`EARLY_ABOVE`]): the
/// conjugation kept while the working set changed (a projected
/// Fletcher-Reeves step) carries the directions of sets the contact has
/// left, and a steepest-descent step clears them. Measured in
/// BENCHMARKS.md ("Speed: rough contacts on large grids").
const RESTART_BELOW: f64 = 1e-3;

/// Which quantity a non-adhesive solve prescribes.
#[derive(Clone, Copy)]
pub(super) enum Control {
    Depth(f64),
    Force(f64),
}

/// Where the constrained conjugate gradients get the displacement of their
/// starting pressure.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum StartDisplacement {
    /// `u = K p` of the start, one operator application.
    Compute,
    /// The workspace's displacement already is the start's, less an offset
    /// that the profile carries (the cohesive zone's fixed point adds the
    /// response to its tensions' and pressures' change to the profile in
    /// one application): kept, and refreshed as `u_start + K (p - p_start)`
    /// so that the offset survives. The warm start must have contact.
    Given,
}

impl ContactSolver {
    /// Non-adhesive contact at `depth` (m): pressures `p >= 0`, zero gap
    /// where `p > 0`, non-negative gap elsewhere.
    ///
    /// A depth at which the indenter does not yet touch gives a solution
    /// without contact (force 0). `warm` starts the iteration from a previous
    /// solution (any depth) on the same grid. On a grid of at least
    /// [`MULTIRESOLUTION_CELLS`](super::MULTIRESOLUTION_CELLS) cells each way the start is corrected on
    /// the grid of half the cells first (the coarse solve starts from the
    /// warm pressures averaged over its cells, the fine one from the warm
    /// pressures plus the coarse solve's change: Brandt 1977, Math. Comp.
    /// 31, 333-390): the fine iterations then start with nearly the final
    /// contact instead of clamping their way back from the overlap of the
    /// new load. A warm start more than four times off the new depth's
    /// scale is first scaled to the least energy along its own pressures
    /// (at each level, the fine one's detail by the coarse one's factor):
    /// a punch unloaded to a hair's breadth of first contact would
    /// otherwise cancel pressures a billion times too large and stall in
    /// their rounding.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth, a penetration
    /// below `1e-100` cells (it would underflow), or an indenter height
    /// that is NaN; [`Error::IndenterOutsideGrid`] if the indenter
    /// reaches no cell; [`Error::ShapeMismatch`] for a warm start from another
    /// grid; [`Error::NoConvergence`] if the tolerance is not reached within
    /// the iteration limit.
    pub fn solve_depth<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        check_finite("depth", depth)?;
        self.check_warm_start(warm)?;
        let lowest = self.sample_profile(indenter)?;
        if depth <= lowest {
            return Ok(self.no_contact(depth));
        }
        let spacing = self.grid().spacing();
        if depth - lowest < MIN_LOAD_SCALE * spacing {
            return Err(Error::InvalidParameter {
                name: "penetration over cell size (depth - lowest height) / Delta",
                value: (depth - lowest) / spacing,
                expected: "at least 1e-100 (smaller loads underflow in the solver's squared \
                           norms): rescale lengths",
            });
        }
        self.solve_from(indenter, Control::Depth(depth), warm, observer)
    }

    /// Non-adhesive contact under total force `force` (N, `>= 0`); the depth
    /// is part of the solution. Zero force gives the first-contact depth and
    /// no contact. `warm` as in [`ContactSolver::solve_depth`].
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth`], and [`Error::InvalidParameter`] for
    /// a negative force (a non-adhesive contact cannot pull) or one below
    /// `1e-100 E* Delta^2` (it would underflow).
    pub fn solve_force<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        force: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        let force = crate::error::non_negative_finite("force", force)?;
        self.check_warm_start(warm)?;
        let lowest = self.sample_profile(indenter)?;
        if force == 0.0 {
            return Ok(self.no_contact(lowest));
        }
        let spacing = self.grid().spacing();
        let scale = self.surface_contact_modulus * spacing * spacing;
        if force < MIN_LOAD_SCALE * scale {
            return Err(Error::InvalidParameter {
                name: "force over cell load F / (E* Delta^2)",
                value: force / scale,
                expected: "0 or at least 1e-100 (smaller loads underflow in the solver's \
                           squared norms): rescale forces",
            });
        }
        self.solve_from(indenter, Control::Force(force), warm, observer)
    }

    /// The constrained conjugate gradients from the multi-resolution start
    /// if the grid allows one (corrected from `warm` if that has contact),
    /// else from `warm`.
    fn solve_from<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        control: Control,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        // Whether the warm start has contact on any rank (a split solver's
        // warm start holds its own rows).
        let warm = warm.filter(|w| self.on_any_rank(w.pressure.iter().any(|p| *p > 0.0)));
        // The coarse start is handed over, not copied: its pressures become
        // the iteration's (a vector per cell less while it runs).
        let coarse = self.coarse_start(indenter, control, warm);
        // The scratch vectors come back from the coarse solve sized for it.
        let fitted = self.workspace.fit(self.local_cells());
        self.agreed(fitted)?;
        // A start level prolonged from its own coarser level may stop at
        // a fraction of how far that start was ([`loosened`]), but the one
        // under the solve asked for (`ContactSolver::loosens`).
        let loosens = self.start_level && self.loosens && coarse.is_some();
        // `coarse_scale`: how much the coarse levels scaled the warm start
        // (the start's detail was scaled alike), so that a finer level
        // scales its own.
        let (start, coarse_iterations, coarse_scale) = match coarse {
            Some((start, iterations, scale)) => (Some(Cow::Owned(start)), iterations, scale),
            None => (warm.map(Cow::Borrowed), 0, 1.0),
        };
        // A cold solve (the coarse levels' start is no warm start of the
        // caller's) iterates long enough for the early iterations in single
        // precision to pay; a warm one may end before the displacement's
        // recomputation in double would.
        let origin = match (warm, coarse_iterations) {
            (Some(_), _) => Origin::Warm,
            (None, 0) => Origin::Cold,
            (None, _) => Origin::Coarse,
        };
        let (mut solution, end) = self.constrained_cg(
            control,
            start,
            StartDisplacement::Compute,
            loosens,
            origin,
            observer,
        )?;
        solution.coarse_iterations = coarse_iterations;
        self.warm_scale *= coarse_scale;
        Ok((solution, end))
    }

    /// The constrained conjugate gradients from `warm` (or a uniform
    /// pressure), to the solver's tolerance; `loosens`: the start came
    /// from this start level's coarser level and the level is not the one
    /// under the solve asked for, so the tolerance loosens to a fraction of
    /// the first iteration's change ([`loosened`]);
    /// `origin`: where the start came from; a solve from no warm start of
    /// the caller's is a cold one, of many iterations, whose early ones
    /// apply the operator in single precision ([`EARLY_ABOVE`]), whose
    /// conjugation restarts twice ([`RESTART_BELOW`]) and whose new overlap
    /// joins by the rule of [`overlap_joining`](super::overlap_joining).
    pub(super) fn constrained_cg(
        &mut self,
        control: Control,
        warm: Option<Cow<'_, WarmStart>>,
        start_displacement: StartDisplacement,
        loosens: bool,
        origin: Origin,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        let n = self.local_cells();
        let columns = self.grid().columns();
        let area = self.grid().cell_area();
        self.preconditioning = Some(Preconditioning::default());
        // This rank's rows (all of them when serial).
        let local = self.operator.local_rows();
        let reachable = self.reachable();
        let warm = warm.filter(|w| {
            let contact = w
                .pressure
                .iter()
                .zip(&reachable)
                .any(|(p, r)| *r && *p > 0.0);
            self.on_any_rank(contact)
        });
        let given = start_displacement == StartDisplacement::Given;
        if given && warm.is_none() {
            return Err(Error::Internal {
                what: "constrained conjugate gradients",
                detail: "a given start displacement without a start that has contact".into(),
            });
        }
        let warmed = warm.is_some();
        let mut pressure = self.initial_pressure(control, warm, &reachable);
        if let Control::Force(w) = control {
            let mut total = [area * pressure.iter().sum::<f64>()];
            self.sum_over_ranks(&mut total);
            passes::scale(&mut pressure, w / total[0]);
        }
        let force_control = matches!(control, Control::Force(_));
        let mut tolerance = self.params.tolerance;
        // A start level's own tolerance, which it keeps while its contact
        // count still moves ([`start_count_settled`]).
        let strict = tolerance;
        // The contact count after the last iteration.
        let mut last_contact: Option<usize> = None;
        // Whether the last iteration's contact count fell below the one
        // before ([`overlap_joining`](super::overlap_joining)).
        let mut shrinking = false;
        // When this solve takes the coarse correction
        // ([`ContactSolver::coarse_correction_now`]), and whether the last
        // iteration took it.
        let mut coarse_choice = CoarseChoice::default();
        let mut coarse_last = false;
        let mut rz_old = 0.0;
        self.workspace.direction.fill(0.0);
        let mut depth = match control {
            Control::Depth(d) => d,
            Control::Force(_) => 0.0,
        };
        let mut residual = f64::INFINITY;
        // Whether the last step's clamping needed a convolution.
        let mut clamped = false;
        // The cells where the pressure and the search direction may be
        // nonzero (whole rows): the passes that only concern the working
        // set run on its rows.
        let mut pressure_cells = 0..n;
        let mut direction_cells: Option<Range<usize>> = None;
        // Under force control, the sum of profile + u over the contact and
        // its cell count, summed over the ranks, as the last rescale found
        // them (`None`: to be summed anew).
        let mut contact_sums: Option<(f64, f64)> = None;
        // u = K p is kept up to date incrementally: one operator application
        // per iteration (K t), plus one only when clamping changed the
        // pressure off the search direction (after such a step, the energy
        // t . K t and one application to the change of p instead), and a
        // full refresh every REFRESH iterations against drift.
        // A given start displacement is kept with its start pressure, to
        // refresh against (allocated only then).
        self.warm_scale = 1.0;
        let start = if given {
            Some((pressure.clone(), self.workspace.displacement.clone()))
        } else {
            self.operator
                .apply(&pressure, &mut self.workspace.displacement)?;
            if let (Control::Depth(d), true) = (control, warmed) {
                self.warm_scale = self.scale_warm_start(d, &mut pressure);
            }
            None
        };
        // A cold solve's early iterations, until the change falls to
        // EARLY_ABOVE (or the tolerance, if looser), apply the operator in
        // single precision; then the displacement is recomputed in double
        // and the conjugation restarts, as it does once before, where the
        // change first falls to RESTART_BELOW. A start level may stop in
        // the early phase (its pressures are only a start), a fine solve
        // only after it. The cohesive zone's rounds (warm, whose fixed
        // point follows the inner solves' last digits) stay in double.
        let cold = origin != Origin::Warm && !self.double_preconditioner;
        let mut early = cold;
        let mut restarted = !cold;
        let mut stall = Stall::new();
        // The conjugate-gradient iterations of the active-set loops, if
        // they ran: counted in the solution's iterations and against the
        // iteration limit, whether or not the set settled.
        let mut loop_iterations = 0;
        for iteration in 1..=self.params.max_iterations {
            if iteration + loop_iterations > self.params.max_iterations {
                break;
            }
            self.check_interrupt("the constrained conjugate gradients")?;
            let leave = early && residual <= EARLY_ABOVE.max(tolerance);
            if leave {
                // The recomputed displacement moves the gaps off the early
                // iterations' own (kept across that move, the conjugation
                // of a 4 x 5 grid of an incompressible film crept at a
                // change of 3e-9 an iteration for ever).
                early = false;
                rz_old = 0.0;
            }
            if !restarted && residual <= RESTART_BELOW {
                restarted = true;
                rz_old = 0.0;
            }
            let single = early && self.single_precision;
            // A solve still running tries the active-set loops once
            // (`src/solver/active_set.rs`), then goes on from the
            // pressures they leave (or its own) with the displacement
            // recomputed below and its conjugation restarted.
            // Not on a contact of many patches (LOOP_PATCHES).
            let tried = iteration == ACTIVE_SET_AFTER && self.few_patches(&pressure);
            if tried {
                // A given start displacement carries a part the pressures
                // do not make: `u0 - K p0`.
                let offset = match &start {
                    Some((p0, u0)) => {
                        let mut offset = vec![0.0; n];
                        self.operator.apply(p0, &mut offset)?;
                        for (o, u) in offset.iter_mut().zip(u0) {
                            *o = u - *o;
                        }
                        Some(offset)
                    }
                    None => None,
                };
                let budget = self.params.max_iterations.saturating_sub(iteration);
                let (settled, spent) = self.active_set_loops(
                    control,
                    &pressure,
                    &reachable,
                    budget,
                    offset.as_deref(),
                )?;
                if let Some(settled) = settled {
                    pressure = settled;
                }
                loop_iterations = spent;
                self.workspace.direction.fill(0.0);
                direction_cells = None;
                pressure_cells = 0..n;
                rz_old = 0.0;
                clamped = false;
                early = false;
            }
            if iteration % REFRESH == 0 || leave || tried {
                let ws = &mut self.workspace;
                match &start {
                    Some((p0, u0)) => {
                        // `gap` and `response` are written again before
                        // they are next read.
                        for ((d, p), q) in ws.gap.iter_mut().zip(&pressure).zip(p0) {
                            *d = p - q;
                        }
                        self.operator.apply(&ws.gap, &mut ws.response)?;
                        for ((u, s), k) in ws.displacement.iter_mut().zip(u0).zip(&ws.response) {
                            *u = s + k;
                        }
                    }
                    None => {
                        self.operator.apply(&pressure, &mut ws.displacement)?;
                    }
                }
                contact_sums = None;
            }
            // The depth under force control: the mean of profile + u over
            // the contact.
            let reference = match control {
                Control::Depth(d) => d,
                Control::Force(_) => {
                    let (sum, contact) = match contact_sums.take() {
                        Some((sum, contact)) => (sum, contact as usize),
                        None => {
                            let ws = &self.workspace;
                            let cells = pressure_cells.clone();
                            let (sum, contact) = passes::contact_sum(
                                &ws.profile[cells.clone()],
                                &ws.displacement[cells.clone()],
                                &pressure[cells],
                            );
                            let mut totals = [sum, contact as f64];
                            self.sum_over_ranks(&mut totals);
                            (totals[0], totals[1] as usize)
                        }
                    };
                    if contact == 0 {
                        return Err(Error::Internal {
                            what: "constrained conjugate gradients",
                            detail: "no cell carries pressure under force control".into(),
                        });
                    }
                    depth = sum / contact as f64;
                    depth
                }
            };
            // Gaps and the working set: cells in contact, and reachable
            // cells the indenter overlaps (the free variables of the
            // bound-constrained minimum; new overlap keeps the
            // conjugation unless the solve has stalled, below). On a fine
            // solve, overlap away from the contact's edge joins only if
            // deep, and after the multi-resolution start only if the gap
            // error near it does not explain it
            // ([`overlap_joining`](super::overlap_joining)).
            let ws = &mut self.workspace;
            let pass = passes::gaps_and_working_set(
                &ws.profile,
                &ws.displacement,
                &pressure,
                &reachable,
                reference,
                columns,
                &mut ws.gap,
                &mut ws.working,
            );
            let mut set = self.whole_working_set(pass.set());
            let edge_held = origin.holds_edge(shrinking);
            if let Some(hold) = self.holding(&set, origin, edge_held) {
                let periodic = self.operator.boundary() == crate::Boundary::Periodic;
                let ws = &mut self.workspace;
                let (gap, working) = (&ws.gap, &mut ws.working);
                let estimate = RowEstimate::new(gap, &pressure, columns, periodic);
                let stays_out = |c, beside| hold.stays_out(c, beside, gap, &estimate);
                let local = pass.leave_out(gap, working, stays_out);
                set = self.whole_working_set(local);
            }
            if set.members == 0 {
                // No pressure and no overlap (depth control only: under
                // force control some cell always carries pressure): zero
                // pressure is the solution. Only rounding gets here, at a
                // depth a hair's breadth past first contact.
                return self.converged(control, pressure, depth, iteration, 0.0);
            }
            // The working set's rows on this rank (it has members, so
            // bounds).
            let working_cells = set.bounds.map_or(0..n, |((first, last), _)| {
                let row = |r: usize| r.clamp(local.start, local.end) - local.start;
                row(first) * columns..row(last + 1) * columns
            });
            // Under force control the gradient is projected on loads of
            // zero net force: the gaps' mean over the set is taken out
            // (where they are read, not in a pass of its own).
            let shift = if force_control {
                set.gap_sum / set.members as f64
            } else {
                0.0
            };
            // z = P M^-1 P r in `response`, r = gap - shift; under force
            // control projected too (its mean taken out of the direction;
            // the product r.z is unchanged as r has zero sum).
            // The coarse correction only while the contact count stands
            // ([`ContactSolver::coarse_correction_now`]); a change of
            // preconditioner restarts the conjugation.
            let done = iteration - 1 + loop_iterations;
            let coarse =
                self.coarse_correction_now(&mut coarse_choice, residual, &pressure, done)?;
            self.preconditioning = Some(coarse_choice.report);
            if coarse != coarse_last {
                rz_old = 0.0;
            }
            coarse_last = coarse;
            let (z_sum, rz) = self.precondition_step(set.bounds, shift, set.gap_max, coarse)?;
            let mut sums = [z_sum, rz];
            self.sum_over_ranks(&mut sums);
            let [z_sum, rz] = sums;
            let z_shift = if force_control {
                z_sum / set.members as f64
            } else {
                0.0
            };
            super::all_finite(
                "constrained conjugate gradients (the depth, heights or force \
                 overflow f64 at these moduli and cell sizes)",
                &[rz, depth],
            )?;
            // Conjugation; a zero previous product (every gap closed
            // exactly) restarts from steepest descent instead of making
            // 0/0 = NaN. New overlap changes the working set; Polonsky and
            // Keer restart there, which on rough contacts (cells join the
            // set in most of the early iterations) keeps the iteration
            // near steepest descent. The conjugation is kept instead (a
            // projected Fletcher-Reeves step), unless the new direction
            // would not descend: `gap . t = rz + beta gap . t_old` on the
            // new set (the old direction is zero off the old one), summed
            // in the pass that writes the new direction, which runs again
            // with `beta = 0` in the rare case it would not. Measured in
            // BENCHMARKS.md ("Rough contacts beside tamaas").
            // A solve that has stalled restarts at new overlap instead
            // ([`Stall`]).
            let restart = rz_old <= 0.0 || (set.overlap && stall.restarts_on_overlap());
            let beta = if restart { 0.0 } else { rz / rz_old };
            rz_old = rz;
            // The direction is zero off the working set: only the rows of
            // the old and the new one are written.
            let cells = direction_cells.map_or(working_cells.clone(), |d| {
                d.start.min(working_cells.start)..d.end.max(working_cells.end)
            });
            let update = |solver: &mut Self, beta: f64| {
                let ws = &mut solver.workspace;
                passes::update_direction(
                    &ws.working[cells.clone()],
                    &ws.response[cells.clone()],
                    &ws.gap[cells.clone()],
                    z_shift,
                    beta,
                    &mut ws.direction[cells.clone()],
                )
            };
            let [mut t_sum, mut gap_dot, old_sum, old_dot, mut t_max] = update(self, beta);
            if set.overlap && beta > 0.0 {
                let mut old = [old_sum, old_dot];
                self.sum_over_ranks(&mut old);
                if rz + beta * (old[1] - shift * old[0]) <= 0.0 {
                    [t_sum, gap_dot, _, _, t_max] = update(self, 0.0);
                }
            }
            direction_cells = Some(working_cells.clone());
            // After a step whose clamping needed a convolution, the next
            // likely clamps too: the energy, not `K t`.
            let deferred = clamped;
            let mut arithmetic = Arithmetic::default();
            if single {
                // A scale the same on every rank: the sum of the largest.
                arithmetic.direction = Some(self.summed(t_max));
            }
            let cells = working_cells.clone();
            let (energy, summed_single) =
                self.direction_energy(deferred, cells, t_max, arithmetic)?;
            let mut dots = [gap_dot, energy, t_sum];
            self.sum_over_ranks(&mut dots);
            let [gap_dot, mut denominator, t_sum] = dots;
            if summed_single && !(denominator.is_finite() && denominator > 0.0) {
                // Out of single precision's reach after all: in double.
                let mut energy = [self.operator.energy(&self.workspace.direction)?];
                self.sum_over_ranks(&mut energy);
                denominator = energy[0];
            }
            let numerator = gap_dot - shift * t_sum;
            let ws = &mut self.workspace;
            let step = if denominator > 0.0 {
                numerator / denominator
            } else if numerator == 0.0 {
                0.0 // A zero direction: the gaps are closed.
            } else {
                // K t . t <= 0 for t != 0: t lies in the operator's null
                // space, the uniform mode of a periodic grid on a body
                // without a rigid base.
                return Err(self.singular_uniform_mode());
            };
            // Step along the direction, clamp at zero, and keep u = K p up
            // to date: u -= step K t now, + K (correction) below, the
            // correction being what clamping added to p - step t (`gap`
            // holds it); deferred, u moves below by K of the whole change
            // of p (`gap` holds that).
            let step_pass = if deferred {
                passes::step::<true>
            } else {
                passes::step::<false>
            };
            let mut stats = step_pass(
                working_cells.clone(),
                &ws.working,
                &ws.direction,
                &ws.response,
                step,
                &mut pressure,
                &mut ws.displacement,
                &mut ws.gap,
                &mut ws.previous,
            );
            stats = self.whole_step(stats);
            if single {
                arithmetic.change = Some(stats.largest);
            }
            // Pressures are now zero off the working set.
            pressure_cells = working_cells.clone();
            // Under force control the pressure is rescaled to the load:
            // inside the step's convolution if it has one (its last pass
            // adds the response), else in a pass below.
            let rescaled = force_control && area * stats.size > 0.0;
            let direct = self.operator.direct_sum_is_cheaper(stats.corrected);
            clamped = stats.corrected > 0 && !direct;
            let factor = match control {
                Control::Force(w) if rescaled => Some(w / (area * stats.size)),
                _ => None,
            };
            let fused = self.respond_to_step(
                deferred,
                stats.corrected,
                direct,
                step,
                working_cells.clone(),
                &mut pressure,
                factor,
                arithmetic,
            )?;
            let ws = &mut self.workspace;
            if let Control::Force(w) = control {
                if let Some(factor) = factor {
                    let mut sums = fused.unwrap_or_else(|| {
                        passes::rescale(
                            working_cells.clone(),
                            &mut pressure,
                            &mut ws.displacement,
                            // A deferred step left the change in `gap`.
                            if deferred {
                                passes::Before::Changes(&ws.gap)
                            } else {
                                passes::Before::Pressures(&ws.previous)
                            },
                            &ws.profile,
                            factor,
                        )
                    });
                    self.sum_over_ranks(&mut sums);
                    [stats.change, stats.size] = [sums[0], sums[1]];
                    contact_sums = Some((sums[2], sums[3]));
                } else {
                    // Every pressure clamped: restart uniform on the
                    // working set.
                    for c in 0..n {
                        pressure[c] = if ws.working[c] { 1.0 } else { 0.0 };
                    }
                    passes::scale(&mut pressure, w / (area * set.members as f64));
                    rz_old = 0.0;
                    self.operator.apply(&pressure, &mut ws.displacement)?;
                    let mut size = [pressure.iter().sum()];
                    self.sum_over_ranks(&mut size);
                    stats.size = size[0];
                }
            }
            residual = if stats.size > 0.0 {
                stats.change / stats.size
            } else {
                f64::INFINITY
            };
            if loosens && iteration == 1 {
                tolerance = loosened(tolerance, residual);
            }
            stall.record(residual);
            observer.observe(&IterationInfo {
                iteration: iteration + loop_iterations,
                residual,
                contact_cells: stats.contact,
            });
            coarse_choice.record(count_settled(last_contact, stats.contact), residual);
            let settled = start_count_settled(last_contact, stats.contact);
            shrinking = last_contact.is_some_and(|c| stats.contact < c);
            last_contact = Some(stats.contact);
            // A fine solve stops only once no cell overlaps; a start level
            // may stop with overlap left (`ContactSolver::start_level`),
            // and at its loosened tolerance only once its count settles.
            if (residual <= strict || (residual <= tolerance && settled))
                && (!set.overlap || self.start_level)
                && (!early || self.start_level)
            {
                return self.converged(
                    control,
                    pressure,
                    depth,
                    iteration + loop_iterations,
                    residual,
                );
            }
        }
        Err(Error::NoConvergence {
            method: "constrained conjugate gradients (Polonsky-Keer)",
            iterations: self.params.max_iterations,
            residual,
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::solver::{ContactSolver, SolverParams};
    use crate::topography::{Amplitude, SelfAffine};
    use crate::{Boundary, Grid, Material, Substrate};

    /// A rough contact (the surface of `examples/rough_benchmark.rs` on a
    /// 128 x 128 grid, about 8 % in contact) on a film, isolated, and on a
    /// periodic half-space, under force and depth control, solved with the
    /// early iterations in single precision and in double throughout: the
    /// same pressures within 1e-13 of the largest (measured 1.5e-15 and
    /// 2.9e-15: the double-precision iterations that follow remove what
    /// `f32`'s rounding, about 2e-7 of a response, moved), forces and
    /// depths within 1e-12, iteration counts within one. A single-precision
    /// response off by 1e-3 of itself moves the pressures by 5e-12, off by
    /// 0.1 adds eight iterations.
    #[test]
    fn single_precision_early_iterations_reach_the_same_pressures() {
        let rubber = Material::new(1e6, 0.49).unwrap();
        let bodies = [
            (
                Substrate::layer_on_rigid_base(rubber, 1e-4).unwrap(),
                Boundary::Isolated,
            ),
            (Substrate::half_space(rubber), Boundary::Periodic),
        ];
        let grid = Grid::square_of_side(128, 1e-3).unwrap();
        let surface = SelfAffine {
            hurst: 0.8,
            amplitude: Amplitude::RmsSlope(0.1),
            long_cutoff: 0.25e-3,
            short_cutoff: 4.0 * grid.spacing(),
            seed: 1,
        }
        .indenter(&grid)
        .unwrap();
        for (body, boundary) in bodies {
            let mut solutions = Vec::new();
            for single in [true, false] {
                let params = SolverParams {
                    tolerance: 1e-10,
                    ..SolverParams::default()
                };
                let mut solver = ContactSolver::new(&body, &grid, boundary, params).unwrap();
                solver.single_precision = single;
                let (by_force, warm) = solver.solve_force(&surface, 5e-3, None, &mut ()).unwrap();
                let (by_depth, _) = solver
                    .solve_depth(&surface, by_force.depth, None, &mut ())
                    .unwrap();
                solutions.push((by_force, by_depth, warm.pressure));
            }
            let (single, double) = (&solutions[0], &solutions[1]);
            let largest = double.2.iter().fold(0.0_f64, |m, p| m.max(*p));
            let difference = single
                .2
                .iter()
                .zip(&double.2)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(difference <= 1e-13 * largest, "{boundary:?}: {difference}");
            for (a, b) in [(&single.0, &double.0), (&single.1, &double.1)] {
                assert!(a.iterations.abs_diff(b.iterations) <= 1, "{boundary:?}");
                assert!((a.force / b.force - 1.0).abs() < 1e-12, "{boundary:?}");
                assert!((a.depth / b.depth - 1.0).abs() < 1e-12, "{boundary:?}");
            }
        }
    }
}
