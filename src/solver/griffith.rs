//! Adhesive contact in the JKR limit by an energy (Griffith) balance over the
//! contact edge.
//!
//! For a fixed contact set `S` the clamped problem is linear in the depth:
//! the pressure is `p = d p1 - pf`, with `p1` the flat-punch solution of `S`
//! (unit displacement) and `pf` the one that gives the indenter's profile
//! `f`. The stored elastic energy at depth `d` is therefore a quadratic,
//!
//! ```text
//! U(d, S) = (k d^2 - 2 f1 d + f2) / 2,   k = sum p1 Delta^2,
//!           f1 = sum pf Delta^2,  f2 = sum pf f Delta^2,
//! ```
//!
//! and the force `F = k d - f1`. Along a nested family of contact sets of
//! growing area `A`, the energy release rate of the edge under displacement
//! control is `G = dU/dA = (k' d^2 - 2 f1' d + f2') / 2` (primes: `d/dA`),
//! and the Griffith balance `G = dgamma` is a quadratic in `d` whose root
//! with a tensile edge is the adhesive equilibrium (Johnson, Kendall &
//! Roberts 1971; in this compliance form Shull 2002, Mater. Sci. Eng. R 36,
//! 1, eq. 31; Maugis 2000, Contact, Adhesion and Rupture of Elastic Solids,
//! ch. 5). For a paraboloid it gives the JKR curve exactly in the limit of
//! fine grids, on any substrate, because `k`, `f1` and `f2` are integral
//! quantities that converge with the grid, and the contact area is a
//! continuous parameter rather than a staircase of whole cells.
//!
//! The family is the sequence of level sets of the indenter's profile (ties,
//! such as a flat punch's face, broken by the distance from the axis), so the
//! balance is the edge-averaged one: exact for axisymmetric contacts, whose
//! energy release rate is the same all along the edge, and an average for
//! others. A family whose sets split into separate patches is refused.

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::{check_finite, ContactSolver, IterationInfo, Observer};

/// The smallest contact set of the family, in cells: below about this size
/// the staircase is too coarse for a contact edge to mean anything.
const MIN_CELLS: usize = 9;
/// Area-radius spacing of the family's sets: one cell, or a tenth of the
/// radius if that is more (the fits follow power laws exactly, so wide
/// spacing costs little accuracy: 0.33 % against 0.36 % at 64 cells across a
/// sphere's pull-off contact, for 31 sets instead of 79).
const NODE_SPACING: f64 = 1.0;
const NODE_RELATIVE_SPACING: f64 = 0.1;
/// Half-width of the window of the local quadratic fits: four cells of
/// radius, or 35 % of the radius if that is more (about seven sets).
const FIT_WINDOW: f64 = 4.0;
const FIT_RELATIVE_WINDOW: f64 = 0.35;
/// How many times the family may be widened when the loading branch does
/// not fit in it.
const MAX_WIDENINGS: usize = 4;
/// The staircase edge in cells: a set of `m` cells behaves, to first order in
/// the cell size, like a disc of radius `sqrt(m / pi) - EDGE_SHIFT` cells.
/// The piecewise-constant pressures miss part of the square-root edge
/// singularity, which a slightly smaller contact reproduces: the BEM
/// stiffness of a digital disc on a half-space is `2 E* (r - 0.117 Delta)`
/// to 1e-3 from 10 to 40 cells of radius (tested), and since the missing
/// energy is a property of the edge alone, the same shift corrects the
/// stiffness, the shape terms and their area derivatives together.
pub const EDGE_SHIFT: f64 = 0.117;
/// Cells of radius the family must reach beyond the loading peak, so that
/// the fits there are two-sided.
const HEADROOM: f64 = 2.0;

/// One set of the family, as solved.
#[derive(Debug, Clone, Copy)]
struct Raw {
    cells: usize,
    radius: f64,
    stiffness: f64,
    shape_force: f64,
    shape_energy: f64,
}

/// One set of the family with smoothed values and area derivatives.
#[derive(Debug, Clone, Copy)]
struct Node {
    cells: usize,
    area: f64,
    stiffness: f64,
    shape_force: f64,
    /// Depth (relative to the indenter's lowest point) and force of the
    /// equilibria with the advancing and the receding work of adhesion.
    depth_advancing: f64,
    force_advancing: f64,
    depth_receding: f64,
    force_receding: f64,
}

/// A state on the adhesive branches: depth, force and contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchPoint {
    /// Depth, m.
    pub depth: f64,
    /// Force, N (negative when adhesion pulls).
    pub force: f64,
    /// Contact area, m^2 (a continuous quantity: the area of the family's
    /// set interpolated between whole cells). Zero without contact. Pass it
    /// to the next call as the history.
    pub contact_area: f64,
    /// Radius of the circle of equal area, m.
    pub contact_radius: f64,
}

/// The loading and unloading branches of one indenter on one grid, with
/// adhesion hysteresis, from the energy balance over the contact edge. Built
/// by [`ContactSolver::adhesive_branches`]; every depth or force after that
/// costs no solve.
///
/// The history is the contact area: pass the previous point's
/// [`BranchPoint::contact_area`] (0 before first contact). The edge advances
/// while the energy release rate is below the advancing work of adhesion
/// `dgamma0`, recedes where it exceeds the receding one `dgamma1`, and stays
/// in between.
///
/// ```
/// use layered_contact::analytic::JkrSphere;
/// use layered_contact::indenter::Paraboloid;
/// use layered_contact::solver::{ContactSolver, Reach, SolverParams};
/// use layered_contact::{Boundary, Grid, Material, Substrate};
///
/// let rubber = Material::new(1e6, 0.5)?;
/// let (radius, dgamma) = (0.01, 0.05);
/// let jkr = JkrSphere::new(&rubber, radius, dgamma)?;
/// let a = jkr.pull_off_contact_radius();
/// // 32 cells across the pull-off contact, room for the peak's.
/// let grid = Grid::square(96, 6.0 * a)?;
/// let mut solver = ContactSolver::new(
///     &Substrate::half_space(rubber), &grid, Boundary::Isolated, SolverParams::default())?;
/// let ball = Paraboloid::new(radius)?;
/// let depth = (1.2 * a).powi(2) / radius;
/// let branches = solver.adhesive_branches(&ball, Reach::Depth(depth), dgamma, dgamma, &mut ())?;
/// // Press in from no contact (history 0), then pull off from the peak.
/// let peak = branches.at_depth(depth, 0.0)?;
/// let pull_off = branches.pull_off(peak.contact_area)?;
/// // 32 cells across: within 0.5 % of JKR (0.2 % measured).
/// assert!((pull_off.force / jkr.pull_off_force() - 1.0).abs() < 0.005);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct AdhesiveBranches {
    nodes: Vec<Node>,
    /// Whether the largest set holds every cell the indenter can reach (a
    /// flat punch's face): the contact cannot grow beyond it.
    capped: bool,
    lowest: f64,
    /// The family's cells in the order they join the contact.
    order: Vec<usize>,
    iterations: usize,
    residual: f64,
}

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
        let target = match reach {
            Reach::Depth(d) => check_finite("depth", d)?,
            Reach::Force(f) => check_finite("force", f)?,
        };
        let advancing =
            crate::error::non_negative_finite("work_of_adhesion (advancing)", advancing)?;
        let receding = crate::error::non_negative_finite("work_of_adhesion (receding)", receding)?;
        if advancing > receding {
            return Err(Error::InvalidParameter {
                name: "work_of_adhesion (advancing)",
                value: advancing,
                expected: "at most the receding work of adhesion",
            });
        }
        let lowest = self.sample_profile(indenter)?;
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
                    self.solve_force(indenter, f, None, &mut ())?.0.depth
                } else {
                    lowest
                };
                2.0 * (depth - lowest)
            }
        }
        .max(smallest_level);
        let delta = self.grid().spacing();
        for _ in 0..=MAX_WIDENINGS {
            let top = order.partition_point(|&(c, _)| self.workspace.profile[c] - lowest <= level);
            let (usable, kept) = self.usable_prefix(&order, top);
            if usable < MIN_CELLS + 4 {
                return Err(Error::ContactReachesEdge {
                    cells: usable,
                    detail: "the grid holds too few cells around the indenter's tip",
                });
            }
            let capped = kept && usable == order.len();
            let (mut iterations, mut residual) = (0, 0.0);
            let raw = self.solve_family(
                &order,
                usable,
                lowest,
                observer,
                &mut iterations,
                &mut residual,
            )?;
            let mut branches =
                AdhesiveBranches::new(&raw, delta, capped, lowest, advancing, receding)?;
            branches.iterations = iterations;
            branches.residual = residual;
            // The loading branch must reach its target HEADROOM cells of
            // radius below the largest set, where the fits are two-sided.
            let nodes = &branches.nodes;
            let top = nodes.last().map_or(0.0, |n| n.area);
            let below_top = (top.sqrt() - HEADROOM * delta * std::f64::consts::PI.sqrt()).powi(2);
            let fits = capped
                || nodes
                    .iter()
                    .rev()
                    .find(|n| n.area <= below_top)
                    .is_some_and(|n| match reach {
                        Reach::Depth(_) => n.depth_advancing >= target - lowest,
                        Reach::Force(_) => n.force_advancing >= target,
                    });
            if fits {
                branches.order = order[..usable].iter().map(|&(c, _)| c).collect();
                return Ok(branches);
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

    /// The height of `indenter`'s lowest point on the grid (m): depths at or
    /// above it make no contact.
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth`] for the indenter's heights.
    pub fn lowest_height<I: Indenter + ?Sized>(&mut self, indenter: &I) -> Result<f64> {
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
        check_finite("depth", point.depth)?;
        self.sample_profile(indenter)?;
        let n = self.grid().len();
        let cells = (point.contact_area / self.grid().cell_area()).round() as usize;
        let mut attached = vec![false; n];
        for &c in branches.order.iter().take(cells) {
            if c < n {
                attached[c] = true;
            }
        }
        let mut pressure = vec![0.0; n];
        let (iterations, residual) = if cells > 0 {
            self.clamped_solve(point.depth, &attached, &mut pressure)?
        } else {
            self.workspace.displacement.fill(0.0);
            (0, 0.0)
        };
        let solution = self.solution(
            &pressure,
            point.depth,
            iterations,
            residual,
            Some(&attached),
        );
        super::check_solution(&solution)?;
        Ok(solution)
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

    /// How many of the first `top` cells of `order` the family may use: it
    /// stops before the first cell on the grid's outer ring (an isolated
    /// contact must stay off the edge). Also says whether `top` was kept.
    fn usable_prefix(&self, order: &[(usize, f64)], top: usize) -> (usize, bool) {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let on_edge = |c: usize| {
            let (i, j) = (c / columns, c % columns);
            i == 0 || j == 0 || i + 1 == rows || j + 1 == columns
        };
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        match order[..top]
            .iter()
            .position(|&(c, _)| !periodic && on_edge(c))
        {
            Some(first) => (first, false),
            None => (top, true),
        }
    }

    /// Solves the clamped flat-punch and shape problems on the sets of the
    /// family (the first `m` cells of `order`, for growing `m` up to
    /// `usable`), from the largest down, each warm-started from the last.
    fn solve_family(
        &mut self,
        order: &[(usize, f64)],
        usable: usize,
        lowest: f64,
        observer: &mut dyn Observer,
        iterations: &mut usize,
        residual: &mut f64,
    ) -> Result<Vec<Raw>> {
        let grid = *self.grid();
        let (n, area) = (grid.len(), grid.cell_area());
        let columns = grid.columns();
        // Set sizes: equal-area radii NODE_SPACING cells apart (or ten per
        // cent, whichever is more), each grown to
        // the end of its tie (so that symmetric cells enter together).
        let mut sizes = Vec::new();
        let mut radius = 0.0f64;
        loop {
            radius += NODE_SPACING.max(NODE_RELATIVE_SPACING * radius);
            let mut m = (std::f64::consts::PI * radius * radius).round() as usize;
            if m >= usable {
                break;
            }
            let key = |i: usize| {
                let (c, r2) = order[i];
                (self.workspace.profile[c], r2)
            };
            while m < usable && m > 0 && key(m) == key(m - 1) {
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
        for (index, &m) in sizes.iter().rev().enumerate() {
            for &(c, _) in &order[m..current] {
                attached[c] = false;
                punch[c] = 0.0;
                shape[c] = 0.0;
            }
            current = m;
            if !connected(&attached, columns, order[0].0, m) {
                return Err(Error::Unsupported {
                    feature: "the energy-balance adhesion method on this indenter",
                    reason: "a contact set splits into separate patches; use the \
                             mesh-dependent criterion",
                });
            }
            for &(c, _) in &order[..m] {
                target[c] = 1.0;
            }
            let (i1, r1) = self.clamped_cg(&attached, &target, &mut punch)?;
            for &(c, _) in &order[..m] {
                target[c] = self.workspace.profile[c] - lowest;
            }
            let (i2, r2) = self.clamped_cg(&attached, &target, &mut shape)?;
            let (mut k, mut f1, mut f2) = (0.0, 0.0, 0.0);
            for &(c, _) in &order[..m] {
                k += punch[c];
                f1 += shape[c];
                f2 += shape[c] * target[c];
            }
            let values = Raw {
                cells: m,
                radius: (m as f64 * area / std::f64::consts::PI).sqrt() - EDGE_SHIFT * area.sqrt(),
                stiffness: k * area,
                shape_force: f1 * area,
                shape_energy: f2 * area,
            };
            for v in [values.stiffness, values.shape_force, values.shape_energy] {
                if !v.is_finite() {
                    return Err(Error::NonFinite {
                        what: "adhesive energy balance",
                        value: v,
                    });
                }
            }
            *iterations += i1 + i2;
            *residual = residual.max(r1).max(r2);
            observer.observe(&IterationInfo {
                iteration: index + 1,
                residual: r1.max(r2),
                contact_cells: m,
            });
            raw.push(values);
        }
        raw.reverse();
        Ok(raw)
    }
}

/// Whether the first `m` cells of the family (marked in `attached`) form
/// one 4-connected patch containing `start`.
fn connected(attached: &[bool], columns: usize, start: usize, m: usize) -> bool {
    let n = attached.len();
    let rows = n / columns;
    let mut seen = vec![false; n];
    let mut stack = vec![start];
    seen[start] = true;
    let mut count = 0usize;
    while let Some(c) = stack.pop() {
        count += 1;
        let (i, j) = (c / columns, c % columns);
        let neighbours = [
            (i > 0).then(|| c - columns),
            (i + 1 < rows).then(|| c + columns),
            (j > 0).then(|| c - 1),
            (j + 1 < columns).then(|| c + 1),
        ];
        for m in neighbours.into_iter().flatten() {
            if attached[m] && !seen[m] {
                seen[m] = true;
                stack.push(m);
            }
        }
    }
    count == m
}

/// Least-squares quadratic through `(x, y)` points: returns the value and
/// the slope at `x = 0`.
fn quadratic_fit(points: &[(f64, f64)]) -> (f64, f64) {
    let mut s = [0.0f64; 5];
    let mut t = [0.0f64; 3];
    for &(x, y) in points {
        let mut xp = 1.0;
        for (k, sk) in s.iter_mut().enumerate() {
            *sk += xp;
            if k < 3 {
                t[k] += xp * y;
            }
            xp *= x;
        }
    }
    // Normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = t, by Cramer.
    let m = [[s[0], s[1], s[2]], [s[1], s[2], s[3]], [s[2], s[3], s[4]]];
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(m);
    let column = |k: usize| {
        let mut mk = m;
        for (row, tk) in mk.iter_mut().zip(t) {
            row[k] = tk;
        }
        det(mk) / d
    };
    (column(0), column(1))
}

impl AdhesiveBranches {
    fn new(
        raw: &[Raw],
        delta: f64,
        capped: bool,
        lowest: f64,
        advancing: f64,
        receding: f64,
    ) -> Result<Self> {
        let mut nodes = Vec::with_capacity(raw.len());
        for r in raw {
            let window: Vec<&Raw> = raw
                .iter()
                .filter(|o| {
                    (o.radius - r.radius).abs()
                        <= (FIT_WINDOW * delta).max(FIT_RELATIVE_WINDOW * r.radius)
                })
                .collect();
            if window.len() < 4 {
                continue;
            }
            // Fit in log-log coordinates where the values are positive (they
            // grow like powers of the radius, which a quadratic in log r
            // follows exactly), else in linear ones.
            let fit = |value: fn(&Raw) -> f64| {
                let positive = window.iter().all(|o| value(o) > 0.0);
                let points: Vec<(f64, f64)> = window
                    .iter()
                    .map(|o| {
                        if positive {
                            ((o.radius / r.radius).ln(), value(o).ln())
                        } else {
                            ((o.radius - r.radius) / delta, value(o))
                        }
                    })
                    .collect();
                let (v, slope) = quadratic_fit(&points);
                // d/dA = d/dr / (2 pi r)
                let (v, dr) = if positive {
                    let v = v.exp();
                    (v, v * slope / r.radius)
                } else {
                    (v, slope / delta)
                };
                (v, dr / (2.0 * std::f64::consts::PI * r.radius))
            };
            let (stiffness, dk) = fit(|o| o.stiffness);
            let (shape_force, df1) = fit(|o| o.shape_force);
            let (_, df2) = fit(|o| o.shape_energy);
            if !(dk > 0.0) {
                continue;
            }
            let equilibrium = |work: f64| {
                // k' d^2 - 2 f1' d + f2' - 2 w = 0, the root with a tensile edge.
                let centre = df1 / dk;
                let spread = ((df1 * df1 - dk * df2 + 2.0 * work * dk).max(0.0)).sqrt() / dk;
                let depth = centre - spread;
                (depth, depth * stiffness - shape_force)
            };
            let (depth_advancing, force_advancing) = equilibrium(advancing);
            let (depth_receding, force_receding) = equilibrium(receding);
            nodes.push(Node {
                cells: r.cells,
                area: std::f64::consts::PI * r.radius * r.radius,
                stiffness,
                shape_force,
                depth_advancing,
                force_advancing,
                depth_receding,
                force_receding,
            });
        }
        if nodes.len() < 3 {
            return Err(Error::ContactReachesEdge {
                cells: raw.last().map_or(0, |r| r.cells),
                detail: "too few contact sets on the grid for the energy balance",
            });
        }
        Ok(AdhesiveBranches {
            nodes,
            capped,
            lowest,
            order: Vec::new(),
            iterations: 0,
            residual: 0.0,
        })
    }
}

/// Linear interpolation of `value` at `area` between nodes `i` and `i + 1`.
fn lerp(nodes: &[Node], i: usize, area: f64, value: fn(&Node) -> f64) -> f64 {
    let (a, b) = (&nodes[i], &nodes[i + 1]);
    let t = ((area - a.area) / (b.area - a.area)).clamp(0.0, 1.0);
    value(a) + t * (value(b) - value(a))
}

/// The area in `[nodes[i].area, nodes[i+1].area]` where the linear
/// interpolant of `value` equals `target`.
fn crossing(nodes: &[Node], i: usize, target: f64, value: fn(&Node) -> f64) -> f64 {
    let (a, b) = (&nodes[i], &nodes[i + 1]);
    let (va, vb) = (value(a), value(b));
    let t = if vb == va {
        0.0
    } else {
        ((target - va) / (vb - va)).clamp(0.0, 1.0)
    };
    a.area + t * (b.area - a.area)
}

/// Which way a prescribed quantity is given.
#[derive(Clone, Copy)]
enum Load {
    Depth(f64),
    Force(f64),
}

impl AdhesiveBranches {
    /// Total inner conjugate-gradient iterations spent building the branches.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The largest relative residual of the inner solves.
    pub fn residual(&self) -> f64 {
        self.residual
    }

    /// The number of contact sets of the family.
    pub fn sets(&self) -> usize {
        self.nodes.len()
    }

    /// The largest contact area the branches hold, m^2.
    pub fn max_contact_area(&self) -> f64 {
        self.nodes.last().map_or(0.0, |n| n.area)
    }

    /// The segment `i` with `nodes[i].area <= area < nodes[i+1].area`
    /// (clamped to the ends).
    fn segment(&self, area: f64) -> usize {
        let last = self.nodes.len() - 2;
        self.nodes
            .partition_point(|n| n.area <= area)
            .saturating_sub(1)
            .min(last)
    }

    fn point(&self, area: f64, load: Load) -> BranchPoint {
        if area <= 0.0 {
            let depth = match load {
                Load::Depth(d) => d,
                Load::Force(_) => self.lowest,
            };
            return BranchPoint {
                depth,
                force: 0.0,
                contact_area: 0.0,
                contact_radius: 0.0,
            };
        }
        let i = self.segment(area);
        let k = lerp(&self.nodes, i, area, |n| n.stiffness);
        let f1 = lerp(&self.nodes, i, area, |n| n.shape_force);
        let (depth, force) = match load {
            Load::Depth(d) => (d, (d - self.lowest) * k - f1),
            Load::Force(f) => (self.lowest + (f + f1) / k, f),
        };
        BranchPoint {
            depth,
            force,
            contact_area: area,
            contact_radius: (area / std::f64::consts::PI).sqrt(),
        }
    }

    /// The equilibrium at `depth` (m) reached from a contact of area
    /// `history` (m^2; 0 for none): the edge advances or recedes only as far
    /// as the balance requires.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth or a negative
    /// history; [`Error::ContactReachesEdge`] if the contact would grow
    /// beyond the sets computed (well beyond the reach the branches were
    /// built for).
    pub fn at_depth(&self, depth: f64, history: f64) -> Result<BranchPoint> {
        check_finite("depth", depth)?;
        let history = crate::error::non_negative_finite("contact area (history)", history)?;
        let area = self.evolve(Load::Depth(depth - self.lowest), history)?;
        self.checked(self.point(area, Load::Depth(depth)))
    }

    /// The equilibrium under force `force` (N, negative pulls) reached from a
    /// contact of area `history` (m^2; 0 for none): load-controlled JKR, with
    /// the jump into contact at first touch and the jump out at the pull-off
    /// force.
    ///
    /// # Errors
    /// [`Error::NoEquilibrium`] for a pull beyond the least force the
    /// contact can hold (or any pull without contact); otherwise as
    /// [`at_depth`](Self::at_depth).
    pub fn at_force(&self, force: f64, history: f64) -> Result<BranchPoint> {
        check_finite("force", force)?;
        let history = crate::error::non_negative_finite("contact area (history)", history)?;
        let area = self.evolve(Load::Force(force), history)?;
        if area == 0.0 {
            let least = if history > 0.0 {
                self.pull_off(history)?.force
            } else {
                0.0
            };
            return Err(Error::NoEquilibrium { force, least });
        }
        self.checked(self.point(area, Load::Force(force)))
    }

    /// The contact area after the edge has moved under `load` from `area`.
    fn evolve(&self, load: Load, area: f64) -> Result<f64> {
        let nodes = &self.nodes;
        let first = nodes[0].area;
        // The prescribed value and the advancing and receding balances.
        let (target, advancing, receding): (f64, fn(&Node) -> f64, fn(&Node) -> f64) = match load {
            Load::Depth(d) => (d, |n| n.depth_advancing, |n| n.depth_receding),
            Load::Force(f) => (f, |n| n.force_advancing, |n| n.force_receding),
        };
        // At a fixed contact, depth and force rise together; the edge
        // advances while the prescribed value lies above the advancing
        // balance, recedes while it lies below the receding one.
        let start = if area < first {
            if match load {
                Load::Depth(d) => d <= 0.0,
                Load::Force(f) => f < 0.0,
            } {
                return Ok(0.0);
            }
            first
        } else {
            area
        };
        let mut i = self.segment(start);
        if area < first || target > lerp(nodes, i, start, advancing) {
            // Advance: the first area above `start` where the balance holds.
            loop {
                if advancing(&nodes[i + 1]) >= target {
                    let crossing = crossing(nodes, i, target, advancing);
                    return Ok(crossing.max(start));
                }
                if i + 2 == nodes.len() {
                    if self.capped {
                        return Ok(nodes[i + 1].area);
                    }
                    return Err(Error::ContactReachesEdge {
                        cells: nodes[i + 1].cells,
                        detail: "the adhesive contact grows beyond the sets computed \
                                 (build the branches for a deeper maximum depth)",
                    });
                }
                i += 1;
            }
        }
        if target < lerp(nodes, i, start, receding) {
            // Recede: the first area below `start` where the balance holds.
            loop {
                if receding(&nodes[i]) <= target {
                    return Ok(crossing(nodes, i, target, receding).min(start));
                }
                if i == 0 {
                    return Ok(0.0);
                }
                i -= 1;
            }
        }
        Ok(start)
    }

    /// The load-controlled pull-off reached from a contact of area `history`
    /// (m^2, typically the loading peak's): the first minimum of the force
    /// on the receding branch below that area, refined by a parabola through
    /// the three sets around it. A pull beyond its force finds no
    /// equilibrium.
    ///
    /// # Errors
    /// [`Error::NonFinite`] if the branch holds no finite force there.
    pub fn pull_off(&self, history: f64) -> Result<BranchPoint> {
        self.first_minimum(history, |n| n.force_receding)
    }

    /// The displacement-controlled jump-off reached from a contact of area
    /// `history` (m^2): the first minimum of the depth on the receding
    /// branch below that area, where the contact comes off under fixed
    /// grips.
    ///
    /// # Errors
    /// As [`pull_off`](Self::pull_off).
    pub fn jump_off(&self, history: f64) -> Result<BranchPoint> {
        self.first_minimum(history, |n| n.depth_receding)
    }

    /// The first local minimum of `key` walking down the receding branch
    /// from `history`, refined by the vertex of a parabola.
    fn first_minimum(&self, history: f64, key: fn(&Node) -> f64) -> Result<BranchPoint> {
        let nodes = &self.nodes;
        let mut i = (self.segment(history) + 1).min(nodes.len() - 1);
        while i > 0 && key(&nodes[i - 1]) <= key(&nodes[i]) {
            i -= 1;
        }
        let mut area = nodes[i].area;
        if i > 0 && i + 1 < nodes.len() && nodes[i + 1].area <= history.max(nodes[i].area) {
            let (x0, x1, x2) = (nodes[i - 1].area, nodes[i].area, nodes[i + 1].area);
            let (y0, y1, y2) = (key(&nodes[i - 1]), key(&nodes[i]), key(&nodes[i + 1]));
            let num = (x1 - x0).powi(2) * (y1 - y2) - (x1 - x2).powi(2) * (y1 - y0);
            let den = (x1 - x0) * (y1 - y2) - (x1 - x2) * (y1 - y0);
            if den != 0.0 {
                area = (x1 - 0.5 * num / den).clamp(x0, x2);
            }
        }
        let area = area.min(history.max(nodes[0].area));
        let j = self.segment(area);
        let depth = self.lowest + lerp(nodes, j, area, |n| n.depth_receding);
        self.checked(self.point(area, Load::Depth(depth)))
    }

    /// `point` if all its values are finite.
    fn checked(&self, point: BranchPoint) -> Result<BranchPoint> {
        for value in [point.depth, point.force, point.contact_area] {
            if !value.is_finite() {
                return Err(Error::NonFinite {
                    what: "adhesive energy balance",
                    value,
                });
            }
        }
        Ok(point)
    }
}
