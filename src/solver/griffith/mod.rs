//! Adhesive contact in the JKR limit by an energy (Griffith) balance over the
//! contact edge, along a nested family of contact sets: for each set two
//! clamped solves give the stiffness `k` and the shape terms `f1`, `f2` of
//! the stored energy `U(d) = (k d^2 - 2 f1 d + f2) / 2`, and
//! `G = dU/dA = dgamma` fixes the depth of each contact area (Johnson,
//! Kendall & Roberts 1971; in this compliance form Shull 2002, Mater. Sci.
//! Eng. R 36, 1). The derivation, the fits and the edge shift are in
//! [`doc::adhesion`](crate::doc::adhesion); the evaluation of the branches is
//! in `branches.rs`.

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::{check_finite, ContactSolver, IterationInfo, Observer};

mod branches;
mod discs;
mod ellipse_fit;
mod ellipse_modes;
mod face;
mod material;
mod peel;
mod periodic;
mod release;
mod window;

use branches::Raw;
pub use branches::{AdhesiveBranches, BranchPoint};
pub use peel::{PeelPoint, PeelingPath, PEEL_FRACTION};
use periodic::{connected, half_period_error};
pub use release::{EdgeFit, EdgePoint, EdgeRelease, EDGE_WINDOW};

/// The smallest contact set of the family, in cells: below about this size
/// the staircase is too coarse for a contact edge to mean anything.
const MIN_CELLS: usize = 9;
/// Area-radius spacing of the family's sets: one cell, or a tenth of the
/// radius if that is more (for discs and other self-similar sets the fits
/// follow power laws exactly, so wide spacing costs little accuracy:
/// measured before the edge shift, 0.33 % against 0.36 % error at 64 cells
/// across a sphere's pull-off contact, for 31 sets instead of 79). Strips
/// keep one cell: their terms follow no power law, and the relative spacing
/// and windows left an error that does not fall with the cell size
/// (Johnson's sinusoid: -1.07 % at 64, 128 and 256 cells per wavelength;
/// with one cell, -1.16, -0.46, -0.19 %). Other shapes keep the relative
/// spacing: their balance is an average over the edge, whose error the
/// finer spacing would not remove, at up to five times the solves.
const NODE_SPACING: f64 = 1.0;
const NODE_RELATIVE_SPACING: f64 = 0.1;
/// Half-width of the window of the local quadratic fits: four cells of
/// radius, or, except for strips, 35 % of the radius if that is more (about
/// seven sets).
const FIT_WINDOW: f64 = 4.0;
const FIT_RELATIVE_WINDOW: f64 = 0.35;
/// On a layered body the relative spacing and window are 2.5 % and 10 % of
/// the radius (`ContactSolver::family_fractions`): a layer's terms follow
/// no power law, and the wider fits left a bias near `1e-3` (the sphere on
/// a film as thick as its pull-off contact's radius: 0.067, 0.086, 0.091 %
/// at 64, 128, 256 cells across; with these 0.0026, 0.017, 0.0014 %, at
/// about 2.5 times the solves).
const LAYER_NODE_RELATIVE_SPACING: f64 = 0.025;
const LAYER_FIT_RELATIVE_WINDOW: f64 = 0.10;
/// How many times the family may be widened (its height level multiplied by
/// four) when the loading branch does not fit in it. A JKR contact jumps in
/// at first touch to a radius set by adhesion, not by the depth: a cycle a
/// nanometre deep may need a level thousands of times its depth. The loop
/// also ends once the level spans the whole profile (the family is capped),
/// so this bound only guards against levels that never grow.
const MAX_WIDENINGS: usize = 64;
/// The staircase edge in cells: a set of `m` cells behaves, to first order in
/// the cell size, like a disc of radius `sqrt(m / pi) - EDGE_SHIFT` cells.
/// The piecewise-constant pressures miss part of the square-root edge
/// singularity, which a slightly smaller contact reproduces: the BEM
/// stiffness of a digital disc on a half-space is `2 E* (r - 0.117 Delta)`
/// to about 1e-3 from 10 to 40 cells of radius (tested), and since the missing
/// energy is a property of the edge alone, the same shift corrects the
/// stiffness, the shape terms and their area derivatives together.
pub const EDGE_SHIFT: f64 = 0.117;
/// Cells of radius the family must reach beyond the loading peak, so that
/// the fits there are two-sided.
const HEADROOM: f64 = 2.0;

/// What the family's sets look like.
#[derive(Debug, Clone, Copy)]
struct Shape {
    /// Strips of a profile invariant along a direction of a periodic grid,
    /// with the height tolerance of a line: each set ends where a line
    /// ends, and the sets are one cell of radius apart (other families, a
    /// tenth of the radius where that is more).
    strip: Option<f64>,
    /// The sets' spacing as a fraction of the radius (at least one cell):
    /// zero for strips, else the first of `family_fractions`.
    relative_spacing: f64,
}

/// The fewest sets a strip family must keep when its narrowest strips fall
/// apart into lines of cells (enough for the fits' windows).
const MIN_STRIP_SETS: usize = 8;
/// The most lines of cells (distinct heights) of a strip that may fall
/// apart because its lines run two cells by one; a wider set that is not
/// one patch is two strips.
const NARROW_STRIP_LINES: usize = 6;

/// The fewest lines of cells across a strip family's pull-off or jump-off
/// contact: Johnson's sinusoid came out -5.1 % at 4.4 lines, -4.6 % at 3.5,
/// -32 % at 2.2.
const MIN_STRIP_LINES: usize = 4;

/// How far a family of contact sets must reach.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reach {
    /// The loading branch up to this depth, m.
    Depth(f64),
    /// The loading branch up to this force, N.
    Force(f64),
}

impl ContactSolver {
    /// The adhesive loading and unloading branches of `indenter` up to
    /// `reach` (a depth or a force on the loading branch), with advancing and
    /// receding works of adhesion `advancing <= receding` (J/m^2), by the
    /// energy balance over the contact edge (see [`AdhesiveBranches`]).
    /// Solves two clamped problems per set of a family of contact sets from
    /// nine cells to beyond the loading peak, each warm-started from the
    /// last.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite reach, a negative or
    /// non-finite work of adhesion, `advancing > receding`, or a depth that
    /// does not reach the indenter; [`Error::IndenterOutsideGrid`] if the
    /// indenter reaches no cell; [`Error::ContactReachesEdge`] if the loading
    /// branch does not fit on the grid; [`Error::Unsupported`] if a set of
    /// the family splits into separate patches (use the mesh-dependent
    /// criterion, [`ContactSolver::solve_depth_hysteretic`]);
    /// [`Error::NoConvergence`] from the inner solves.
    pub fn adhesive_branches<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        reach: Reach,
        advancing: f64,
        receding: f64,
        observer: &mut dyn Observer,
    ) -> Result<AdhesiveBranches> {
        self.serial_only("adhesive branches")?;
        let target = match reach {
            Reach::Depth(d) => check_finite("depth", d)?,
            Reach::Force(f) => check_finite("force", f)?,
        };
        let (advancing, receding) = crate::error::works_of_adhesion(advancing, receding)?;
        let (lowest, strip) = self.sample_family_profile(indenter)?;
        let order = self.family_order(lowest);
        let smallest_level = order
            .get(4 * MIN_CELLS.min(order.len().saturating_sub(1)))
            .map_or(0.0, |&(c, _)| self.workspace.profile[c] - lowest);
        let mut level = match reach {
            Reach::Depth(d) => {
                if d <= lowest {
                    return Err(Error::InvalidParameter {
                        name: "depth",
                        value: d,
                        expected: "deeper than the indenter's lowest point on the grid",
                    });
                }
                2.0 * (d - lowest)
            }
            Reach::Force(f) => {
                let depth = if f > 0.0 {
                    let depth = self.solve_force(indenter, f, None, &mut ())?.0.depth;
                    // The solve sampled the profile afresh.
                    self.sample_family_profile(indenter)?;
                    depth
                } else {
                    lowest
                };
                2.0 * (depth - lowest)
            }
        }
        .max(smallest_level);
        let delta = self.grid().spacing();
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        // The sets' relative spacing and the fits' relative window, for
        // every widening (the profile does not change).
        let (relative_spacing, window) = if strip.is_none() {
            self.family_fractions(lowest)
        } else {
            (0.0, 0.0)
        };
        let shape = Shape {
            strip,
            relative_spacing,
        };
        for _ in 0..=MAX_WIDENINGS {
            let top = order.partition_point(|&(c, _)| self.workspace.profile[c] - lowest <= level);
            let (usable, kept) = self.usable_prefix(&order, top, strip);
            if usable < MIN_CELLS + 4 && periodic && !kept {
                return Err(half_period_error());
            }
            if usable < MIN_CELLS + 4 {
                return Err(Error::ContactReachesEdge {
                    cells: usable,
                    detail: "the grid holds too few cells around the indenter's tip",
                });
            }
            let capped = kept && usable == order.len();
            let (raw, iterations, residual) =
                self.solve_family(&order, usable, lowest, shape, observer)?;
            let mut branches = match AdhesiveBranches::new(
                &raw, delta, window, capped, lowest, advancing, receding,
            ) {
                Err(Error::ContactReachesEdge { .. }) if periodic && !kept => {
                    return Err(half_period_error())
                }
                // Too few sets below a level the grid can still widen:
                // a shallow load whose contact jumps in far beyond it.
                Err(Error::ContactReachesEdge { .. }) if kept && !capped => {
                    level *= 4.0;
                    continue;
                }
                other => other?,
            };
            branches.iterations = iterations;
            branches.residual = residual;
            // The loading branch must reach its target HEADROOM cells of
            // radius below the largest set, where the fits are two-sided.
            let top = branches.max_contact_area();
            let below_top = (top.sqrt() - HEADROOM * delta * std::f64::consts::PI.sqrt()).powi(2);
            let fits = capped
                || below_top > 0.0
                    && match reach {
                        Reach::Depth(_) => {
                            branches.advancing_balance(below_top, false) >= target - lowest
                        }
                        Reach::Force(_) => branches.advancing_balance(below_top, true) >= target,
                    };
            if fits {
                branches.order = order[..usable].iter().map(|&(c, _)| c).collect();
                // Discs and strips release evenly along their edges.
                let discs = !periodic && self.family_is_discs(&order[..usable]);
                branches.edge_averaged = !discs && strip.is_none();
                if strip.is_some() {
                    branches.least_area = MIN_STRIP_LINES as f64 * self.line_area();
                }
                return Ok(branches);
            }
            if !kept && periodic {
                return Err(half_period_error());
            }
            if !kept {
                return Err(Error::ContactReachesEdge {
                    cells: usable,
                    detail: "the adhesive contact at the deepest point reaches the grid's edge",
                });
            }
            level *= 4.0;
        }
        Err(Error::ContactReachesEdge {
            cells: order.len(),
            detail: "the adhesive loading branch did not fit in the family of contact sets",
        })
    }

    /// The family's relative set spacing and fit half-window, as fractions
    /// of the radius: the finer ones for a curved profile (no flat face:
    /// more than four cells at `lowest`, the profile's least height) on a layered body, else
    /// the wider ones, for a half-space's power laws and a punch's sets
    /// pinned at the rim (whose pull-off on a layer they move by -0.5 %).
    /// Until 2026-11-29 a layer thinner than 8 cells, or a profile with
    /// any infinite height (a sphere whose grid reaches past its equator),
    /// took the wider ones: a sphere pressed to 0.85 of its radius into a
    /// stack (a soft layer under two stiff ones, each about a cell thick)
    /// came out 3.2 % under the exact contact radius and 12 % under the
    /// exact peak force (a small difference of compression and adhesion)
    /// at 16 and at 32 cells across alike; with the finer ones 0.18 % and
    /// 1.0 %. Over 400 random axisymmetric scenes (`tests/reference_sweep.rs`,
    /// seeds 7 and 11) one other moved by more than 0.5 % (a pull-off
    /// from 1.6 to 3.1 %), the paper example not at all.
    fn family_fractions(&self, lowest: f64) -> (f64, f64) {
        let flat_face = self
            .workspace
            .profile
            .iter()
            .filter(|&&h| h == lowest)
            .count()
            > 4;
        if self.substrate.top_thickness().is_some() && !flat_face {
            (LAYER_NODE_RELATIVE_SPACING, LAYER_FIT_RELATIVE_WINDOW)
        } else {
            (NODE_RELATIVE_SPACING, FIT_RELATIVE_WINDOW)
        }
    }

    /// The height of `indenter`'s lowest point on the grid (m): depths at or
    /// above it make no contact.
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth`] for the indenter's heights.
    pub fn lowest_height<I: Indenter + ?Sized>(&mut self, indenter: &I) -> Result<f64> {
        self.serial_only("lowest height")?;
        self.sample_profile(indenter)
    }

    /// The pressures, contact and fields of the family's set nearest to
    /// `point` (a point of `branches`, built by this solver for `indenter`),
    /// from one clamped solve at `point.depth`: the cell-level picture of a
    /// branch point, whose force differs from `point.force` by the
    /// staircase (the branch interpolates between whole cells).
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth`].
    pub fn branch_solution<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        branches: &AdhesiveBranches,
        point: &BranchPoint,
    ) -> Result<super::Solution> {
        self.serial_only("branch solution")?;
        let n = self.grid().len();
        let cells = (point.contact_area / self.grid().cell_area()).round() as usize;
        let mut attached = vec![false; n];
        for &c in branches.order.iter().take(cells) {
            if c < n {
                attached[c] = true;
            }
        }
        self.clamped_solution(indenter, point.depth, &attached)
    }

    /// Samples `indenter`'s profile (returning its lowest point) and, on a
    /// strip ([`strip_tolerance`](Self::strip_tolerance), also returned),
    /// makes the heights of each line equal.
    fn sample_family_profile<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
    ) -> Result<(f64, Option<f64>)> {
        let lowest = self.sample_profile(indenter)?;
        let strip = self.strip_tolerance();
        if let Some(tolerance) = strip {
            self.snap_strip_lines(tolerance);
        }
        Ok((lowest, strip))
    }

    /// The reachable cells in the order the family adds them: by height
    /// above the lowest point, then by distance from the axis.
    fn family_order(&self, lowest: f64) -> Vec<(usize, f64)> {
        let grid = *self.grid();
        let (lx, ly) = grid.extent();
        let (columns, delta) = (grid.columns(), grid.spacing());
        let mut order: Vec<(usize, f64)> = self
            .workspace
            .profile
            .iter()
            .enumerate()
            .filter(|(_, f)| f.is_finite())
            .map(|(c, _)| {
                let x = ((c / columns) as f64 + 0.5) * delta - 0.5 * lx;
                let y = ((c % columns) as f64 + 0.5) * delta - 0.5 * ly;
                (c, x * x + y * y)
            })
            .collect();
        let profile = &self.workspace.profile;
        order.sort_by(|a, b| {
            (profile[a.0] - lowest)
                .total_cmp(&(profile[b.0] - lowest))
                .then(a.1.total_cmp(&b.1))
        });
        order
    }

    /// Solves the clamped flat-punch and shape problems on the sets of the
    /// family (the first `m` cells of `order`, for growing `m` up to
    /// `usable`), from the largest down, each warm-started from the last;
    /// also returns the iterations and the largest final residual.
    /// See [`Shape`] for how the kind of family sets the spacing and the
    /// ends of the sets.
    fn solve_family(
        &mut self,
        order: &[(usize, f64)],
        usable: usize,
        lowest: f64,
        shape: Shape,
        observer: &mut dyn Observer,
    ) -> Result<(Vec<Raw>, usize, f64)> {
        let (mut iterations, mut residual) = (0, 0.0f64);
        let grid = *self.grid();
        let Shape {
            strip,
            relative_spacing,
        } = shape;
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        let (n, area) = (grid.len(), grid.cell_area());
        let columns = grid.columns();
        // Set sizes: equal-area radii NODE_SPACING cells apart (or ten per
        // cent, whichever is more), each grown to
        // the end of its tie (so that symmetric cells enter together).
        let mut sizes = Vec::new();
        let mut radius = 0.0f64;
        loop {
            radius += NODE_SPACING.max(relative_spacing * radius);
            let mut m = (std::f64::consts::PI * radius * radius).round() as usize;
            if m >= usable {
                break;
            }
            let profile = &self.workspace.profile;
            let tie = |i: usize| {
                let ((a, ra), (b, rb)) = (order[i], order[i - 1]);
                match strip {
                    // A strip's line: heights equal to the tolerance.
                    Some(tolerance) => (profile[a] - profile[b]).abs() <= tolerance,
                    None => profile[a] == profile[b] && ra == rb,
                }
            };
            while m < usable && m > 0 && tie(m) {
                m += 1;
            }
            if m >= MIN_CELLS && sizes.last().is_none_or(|&last| m > last) && m < usable {
                sizes.push(m);
            }
        }
        sizes.push(usable);
        let mut attached = vec![false; n];
        for &(c, _) in &order[..usable] {
            attached[c] = true;
        }
        let mut target = vec![0.0; n];
        let mut punch = vec![0.0; n];
        let mut shape = vec![0.0; n];
        let mut raw = Vec::with_capacity(sizes.len());
        let mut current = usable;
        // Smaller sets move to a window of the grid around them.
        let mut window: Option<window::Window> = None;
        for (index, &m) in sizes.iter().rev().enumerate() {
            for &(c, _) in &order[m..current] {
                attached[c] = false;
                match window.as_mut() {
                    Some(w) => w.detach(c),
                    None => {
                        punch[c] = 0.0;
                        shape[c] = 0.0;
                    }
                }
            }
            current = m;
            if !connected(&attached, columns, periodic, strip.is_some(), order[0].0, m) {
                // The narrowest strips along a steep lattice direction are
                // lines of cells that touch nowhere: the family starts at
                // the last (widest) set that is one patch. A set of more
                // lines than that is two strips (a profile with two
                // troughs), which the balance cannot take.
                if let Some(tolerance) = strip {
                    let profile = &self.workspace.profile;
                    let lines = 1 + order[..m]
                        .windows(2)
                        .filter(|w| (profile[w[1].0] - profile[w[0].0]).abs() > tolerance)
                        .count();
                    if lines <= NARROW_STRIP_LINES && raw.len() >= MIN_STRIP_SETS {
                        break;
                    }
                }
                return Err(Error::Unsupported {
                    feature: "the energy-balance adhesion method on this indenter",
                    reason: "a contact set splits into separate patches; use the \
                             mesh-dependent criterion",
                });
            }
            let set = order[..m].iter().map(|&(c, _)| c);
            if let Some(bounds) = super::passes::bounds_of(set.clone(), columns) {
                let moved =
                    self.window_for(bounds, set, window.as_ref(), (&punch[..], &shape[..]))?;
                if moved.is_some() {
                    window = moved;
                }
            }
            let (solved, worst) = match window.as_mut() {
                Some(w) => w.solve(lowest)?,
                None => {
                    self.solve_clamped_pair(&attached, lowest, &mut target, &mut punch, &mut shape)?
                }
            };
            let (mut k, mut f1, mut f2) = (0.0, 0.0, 0.0);
            for &(c, _) in &order[..m] {
                let [p1, pf, t] = match window.as_ref() {
                    Some(w) => w.values(c),
                    None => [punch[c], shape[c], target[c]],
                };
                k += p1;
                f1 += pf;
                f2 += pf * t;
            }
            let values = Raw {
                cells: m,
                radius: (m as f64 * area / std::f64::consts::PI).sqrt() - EDGE_SHIFT * area.sqrt(),
                stiffness: k * area,
                shape_force: f1 * area,
                shape_energy: f2 * area,
            };
            super::all_finite(
                "adhesive energy balance",
                &[values.stiffness, values.shape_force, values.shape_energy],
            )?;
            iterations += solved;
            residual = residual.max(worst);
            observer.observe(&IterationInfo {
                iteration: index + 1,
                residual: worst,
                contact_cells: m,
            });
            raw.push(values);
        }
        if window.is_some() {
            // The scratch vectors the first window freed.
            self.workspace.fit(self.local_cells())?;
        }
        raw.reverse();
        Ok((raw, iterations, residual))
    }
}
