//! The adhesive branches built from a family of contact sets: smooth fits of
//! the sets' stiffness and shape terms against the contact radius, the
//! Griffith balance at any contact area, and the walk of the contact edge
//! under a prescribed depth or force.

use std::f64::consts::PI;

use crate::error::{Error, Result};
use crate::solver::check_finite;

use super::FIT_WINDOW;

/// Bisection steps locating the contact area between two sets (the
/// bracket shrinks by `2^-50`).
const BISECTIONS: usize = 50;

/// One set of the family, as solved.
#[derive(Debug, Clone, Copy)]
pub(super) struct Raw {
    pub(super) cells: usize,
    /// Effective radius of the set (equal-area radius less the edge shift), m.
    pub(super) radius: f64,
    /// `k = sum p1 Delta^2`, N/m.
    pub(super) stiffness: f64,
    /// `f1 = sum pf Delta^2`, N.
    pub(super) shape_force: f64,
    /// `f2 = sum pf f Delta^2`, N m.
    pub(super) shape_energy: f64,
}

/// A local least-squares quadratic of a set quantity against the contact
/// radius: in `(ln r, ln y)` where the quantity is positive over the window
/// (the terms grow like powers of the radius, which such a fit follows
/// exactly), else in `(r, y)`.
#[derive(Debug, Clone, Copy)]
struct Fit {
    logarithmic: bool,
    /// The radius the fit is centred on, m.
    centre: f64,
    /// The unit of `r - centre` in the linear case, m.
    unit: f64,
    coefficients: [f64; 3],
}

impl Fit {
    fn new(window: &[&Raw], centre: f64, unit: f64, value: fn(&Raw) -> f64) -> Self {
        let logarithmic = window.iter().all(|o| value(o) > 0.0);
        let points: Vec<(f64, f64)> = window
            .iter()
            .map(|o| {
                if logarithmic {
                    ((o.radius / centre).ln(), value(o).ln())
                } else {
                    ((o.radius - centre) / unit, value(o))
                }
            })
            .collect();
        Fit {
            logarithmic,
            centre,
            unit,
            coefficients: quadratic_fit(&points),
        }
    }

    /// The value and its derivative with respect to the contact area at
    /// contact radius `r`.
    fn eval(&self, r: f64) -> (f64, f64) {
        let [c0, c1, c2] = self.coefficients;
        let (value, per_radius) = if self.logarithmic {
            let x = (r / self.centre).ln();
            let value = (c0 + x * (c1 + x * c2)).exp();
            (value, value * (c1 + 2.0 * c2 * x) / r)
        } else {
            let x = (r - self.centre) / self.unit;
            (c0 + x * (c1 + x * c2), (c1 + 2.0 * c2 * x) / self.unit)
        };
        (value, per_radius / (2.0 * PI * r))
    }
}

/// One set of the family: its area and the fits centred on it.
#[derive(Debug, Clone, Copy)]
struct Node {
    cells: usize,
    area: f64,
    stiffness: Fit,
    shape_force: Fit,
    shape_energy: Fit,
}

/// The fewest cells of a set a receding contact may snap onto past a
/// minimum of its balance (four times the family's smallest, a disc of
/// about 3.4 cells' radius); a smaller one comes off instead.
const RESOLVED_CELLS: usize = 4 * super::MIN_CELLS;

/// The set terms at one contact area.
#[derive(Debug, Clone, Copy)]
struct Local {
    stiffness: f64,
    shape_force: f64,
    /// Area derivatives of `k`, `f1`, `f2`.
    slopes: [f64; 3],
}

impl Local {
    /// The depth (relative to the lowest point) and force at which the
    /// energy release rate `(k' d^2 - 2 f1' d + f2') / 2` equals `work`,
    /// on the root with a tensile edge; NaN where `k' <= 0` (no balance).
    fn balance(&self, work: f64) -> (f64, f64) {
        let [dk, df1, df2] = self.slopes;
        if dk.is_nan() || dk <= 0.0 {
            return (f64::NAN, f64::NAN);
        }
        let spread = (df1 * df1 - dk * df2 + 2.0 * work * dk).max(0.0).sqrt() / dk;
        let depth = df1 / dk - spread;
        (depth, depth * self.stiffness - self.shape_force)
    }
}

/// A state on the adhesive branches: depth, force and contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchPoint {
    /// Depth, m.
    pub depth: f64,
    /// Force, N (negative when adhesion pulls).
    pub force: f64,
    /// Contact area, m^2: a continuous quantity (the effective area of the
    /// family's sets, interpolated between whole cells). Zero without
    /// contact. Pass it to the next call as the history.
    pub contact_area: f64,
    /// Radius of the circle of equal area, m.
    pub contact_radius: f64,
}

/// The loading and unloading branches of one indenter on one grid, with
/// adhesion hysteresis, from the energy balance over the contact edge. Built
/// by [`ContactSolver::adhesive_branches`](crate::solver::ContactSolver::adhesive_branches);
/// every depth or force after that costs no solve.
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
/// let grid = Grid::square_of_side(96, 6.0 * a)?;
/// let mut solver = ContactSolver::new(
///     &Substrate::half_space(rubber), &grid, Boundary::Isolated, SolverParams::default())?;
/// let ball = Paraboloid::new(radius)?;
/// let depth = (1.2 * a).powi(2) / radius;
/// let branches = solver.adhesive_branches(&ball, Reach::Depth(depth), dgamma, dgamma, &mut ())?;
/// // Press in from no contact (history 0), then pull off from the peak.
/// let peak = branches.at_depth(depth, 0.0)?;
/// let pull_off = branches.pull_off(peak.contact_area)?;
/// // 32 cells across: within 0.5 % of JKR.
/// assert!((pull_off.force / jkr.pull_off_force() - 1.0).abs() < 0.005);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct AdhesiveBranches {
    nodes: Vec<Node>,
    /// The least contact area a pull-off or jump-off may have (m^2): the
    /// area of a strip family's narrowest resolved strip, else 0.
    pub(super) least_area: f64,
    /// Whether the largest set holds every cell the indenter can reach (a
    /// flat punch's face): the contact cannot grow beyond it.
    capped: bool,
    lowest: f64,
    advancing: f64,
    receding: f64,
    /// The family's cells in the order they join the contact.
    pub(super) order: Vec<usize>,
    pub(super) iterations: usize,
    pub(super) residual: f64,
    /// Whether the balance is only edge-averaged (see
    /// [`AdhesiveBranches::edge_averaged`]).
    pub(super) edge_averaged: bool,
}

/// Which way a prescribed quantity is given.
#[derive(Clone, Copy)]
enum Load {
    Depth(f64),
    Force(f64),
}

/// Which balance.
#[derive(Clone, Copy, PartialEq)]
enum Edge {
    Advancing,
    Receding,
}

impl AdhesiveBranches {
    /// Fits every set against its neighbours within the fit window.
    pub(super) fn new(
        raw: &[Raw],
        delta: f64,
        relative_window: f64,
        capped: bool,
        lowest: f64,
        advancing: f64,
        receding: f64,
    ) -> Result<Self> {
        let mut nodes = Vec::with_capacity(raw.len());
        for r in raw {
            let mut half_width = (FIT_WINDOW * delta).max(relative_window * r.radius);
            if relative_window == 0.0 {
                // Strips: their narrowest sets lie further apart in
                // equal-area radius than the window; each fit takes at
                // least its four nearest sets.
                let mut distances: Vec<f64> =
                    raw.iter().map(|o| (o.radius - r.radius).abs()).collect();
                distances.sort_by(f64::total_cmp);
                if let Some(&fourth) = distances.get(3) {
                    half_width = half_width.max(fourth);
                }
            }
            let window: Vec<&Raw> = raw
                .iter()
                .filter(|o| (o.radius - r.radius).abs() <= half_width)
                .collect();
            if window.len() < 4 || r.radius.is_nan() || r.radius <= 0.0 {
                continue;
            }
            nodes.push(Node {
                cells: r.cells,
                area: PI * r.radius * r.radius,
                stiffness: Fit::new(&window, r.radius, delta, |o| o.stiffness),
                shape_force: Fit::new(&window, r.radius, delta, |o| o.shape_force),
                shape_energy: Fit::new(&window, r.radius, delta, |o| o.shape_energy),
            });
        }
        let branches = AdhesiveBranches {
            nodes,
            least_area: 0.0,
            capped,
            lowest,
            advancing,
            receding,
            order: Vec::new(),
            iterations: 0,
            residual: 0.0,
            edge_averaged: true,
        };
        if branches.nodes.len() < 3 {
            return Err(Error::ContactReachesEdge {
                cells: raw.last().map_or(0, |r| r.cells),
                detail: "too few contact sets on the grid for the energy balance",
            });
        }
        Ok(branches)
    }

    /// Total inner conjugate-gradient iterations spent building the branches.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The largest relative residual of the inner solves.
    pub fn residual(&self) -> f64 {
        self.residual
    }

    /// Whether the balance is only the edge-averaged one, and so not the
    /// JKR-limit solution: true unless every set of the family is a digital
    /// disc on an isolated grid, about the axis or about a paraboloid's apex
    /// anywhere on the grid (an axisymmetric profile about its own axis), or
    /// a strip across a periodic grid (a profile invariant along the grid's
    /// rows, columns or diagonals), the cases where the energy release rate
    /// is the same all along the edge and the balance is exact. Elsewhere (a
    /// tilted, elliptic or rectangular indenter, a height map, a flat punch
    /// that is not round) the real contact is not a level set of the profile
    /// and the forces may be off by several per cent (measured in
    /// [`doc::adhesion`](crate::doc::adhesion));
    /// scenes report it as [`Caveat::EdgeAveragedAdhesion`](crate::scene::Caveat::EdgeAveragedAdhesion).
    pub fn edge_averaged(&self) -> bool {
        self.edge_averaged
    }

    /// The number of contact sets of the family.
    pub fn sets(&self) -> usize {
        self.nodes.len()
    }

    /// The largest contact area the branches hold, m^2.
    pub fn max_contact_area(&self) -> f64 {
        self.nodes.last().map_or(0.0, |n| n.area)
    }

    /// How much the stiffness changes with the contact at `area` (m^2):
    /// `(A / k) dk/dA` from the fits of its sets (0.5 on a half-space,
    /// where `k = 2 E* a`; near 0 on a stiff plate over a far softer base,
    /// whose stiffness the base sets). NaN without two sets.
    pub(crate) fn stiffness_area_slope(&self, area: f64) -> f64 {
        if self.nodes.len() < 2 {
            return f64::NAN;
        }
        let local = self.local(area);
        area * local.slopes[0] / local.stiffness
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

    /// The set terms at `area`: the fits of the two sets around it, blended
    /// linearly in area.
    fn local(&self, area: f64) -> Local {
        let i = self.segment(area);
        let (a, b) = (&self.nodes[i], &self.nodes[i + 1]);
        let t = ((area - a.area) / (b.area - a.area)).clamp(0.0, 1.0);
        let r = (area / PI).sqrt();
        let blend = |fa: &Fit, fb: &Fit| {
            let (va, sa) = fa.eval(r);
            let (vb, sb) = fb.eval(r);
            (va + t * (vb - va), sa + t * (sb - sa))
        };
        let (stiffness, dk) = blend(&a.stiffness, &b.stiffness);
        let (shape_force, df1) = blend(&a.shape_force, &b.shape_force);
        let (_, df2) = blend(&a.shape_energy, &b.shape_energy);
        Local {
            stiffness,
            shape_force,
            slopes: [dk, df1, df2],
        }
    }

    /// The balance's depth (relative to the lowest point) or force at `area`.
    fn balance(&self, area: f64, edge: Edge, load: Load) -> f64 {
        let work = match edge {
            Edge::Advancing => self.advancing,
            Edge::Receding => self.receding,
        };
        let (depth, force) = self.local(area).balance(work);
        match load {
            Load::Depth(_) => depth,
            Load::Force(_) => force,
        }
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
        let local = self.local(area);
        let (depth, force) = match load {
            Load::Depth(d) => (d, (d - self.lowest) * local.stiffness - local.shape_force),
            Load::Force(f) => (self.lowest + (f + local.shape_force) / local.stiffness, f),
        };
        BranchPoint {
            depth,
            force,
            contact_area: area,
            contact_radius: (area / PI).sqrt(),
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
    /// built for); [`Error::NonFinite`] if the balance breaks down there.
    pub fn at_depth(&self, depth: f64, history: f64) -> Result<BranchPoint> {
        check_finite("depth", depth)?;
        let history = crate::error::non_negative_finite("contact area (history)", history)?;
        let area = self.evolve(Load::Depth(depth - self.lowest), history)?;
        self.checked(self.point(area, Load::Depth(depth)))
    }

    /// The equilibrium under force `force` (N, negative pulls) reached from a
    /// contact of area `history` (m^2; 0 for none): load-controlled JKR, with
    /// the jump into contact at first touch (at zero force the contact
    /// jumps in) and the jump out at the pull-off force.
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

    /// The area in `[lo, hi]` where `balance(area) = target`, by bisection
    /// (`balance(lo) - target` and `balance(hi) - target` of opposite signs).
    fn crossing(&self, lo: f64, hi: f64, target: f64, edge: Edge, load: Load) -> f64 {
        let below = self.balance(lo, edge, load) < target;
        let (mut lo, mut hi) = (lo, hi);
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if (self.balance(mid, edge, load) < target) == below {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// The contact area after the edge has moved under `load` from `area`.
    fn evolve(&self, load: Load, area: f64) -> Result<f64> {
        let nodes = &self.nodes;
        let first = nodes[0].area;
        let target = match load {
            Load::Depth(d) => d,
            Load::Force(f) => f,
        };
        // At a fixed contact, depth and force rise together; the edge
        // advances while the prescribed value lies above the advancing
        // balance, recedes while it lies below the receding one.
        let fresh = area < first;
        if fresh
            && match load {
                Load::Depth(d) => d <= 0.0,
                Load::Force(f) => f < 0.0,
            }
        {
            return Ok(0.0);
        }
        let start = area.max(first);
        let advancing = |a: f64| self.balance(a, Edge::Advancing, load);
        let receding = |a: f64| self.balance(a, Edge::Receding, load);
        if fresh || target > advancing(start) {
            // Advance: the first area above `start` where the balance holds.
            let mut lo = start;
            for node in nodes.iter().filter(|n| n.area > start) {
                if advancing(node.area) >= target {
                    return Ok(self.crossing(lo, node.area, target, Edge::Advancing, load));
                }
                lo = node.area;
            }
            if self.capped {
                return Ok(lo);
            }
            return Err(Error::ContactReachesEdge {
                cells: nodes.last().map_or(0, |n| n.cells),
                detail: "the adhesive contact grows beyond the sets computed \
                         (build the branches for a deeper reach)",
            });
        }
        if target < receding(start) {
            // Recede: the first area below `start` where the balance holds.
            // A landing past a minimum of the balance is a snap to a smaller
            // contact; onto a set the grid hardly resolves it is the
            // staircase's, not the body's (a punch on a layer over a base
            // 1800 times softer, 16 cells across: a 12-cell disc held at
            // twice the depth the exact solution comes off at, with 1.8
            // times its pull-off force), and the contact comes off.
            let (mut hi, mut previous, mut snapped) = (start, receding(start), false);
            for node in nodes.iter().rev().filter(|n| n.area < start) {
                let value = receding(node.area);
                if value <= target {
                    if snapped && node.cells < RESOLVED_CELLS {
                        return Ok(0.0);
                    }
                    return Ok(self.crossing(node.area, hi, target, Edge::Receding, load));
                }
                snapped |= value > previous;
                (hi, previous) = (node.area, value);
            }
            return Ok(0.0);
        }
        Ok(start)
    }

    /// The load-controlled pull-off reached from a contact of area `history`
    /// (m^2, typically the loading peak's): the least force on the
    /// receding branch below that area (its first minimum, unless the
    /// branch falls lower further down, where the contact snaps to). A
    /// pull beyond its force finds no equilibrium.
    ///
    /// # Errors
    /// [`Error::NonFinite`] if the branch holds no finite force there;
    /// [`Error::Unsupported`] if the force is least at the family's smallest
    /// set, on strips fewer than four lines of cells wide, where a set the
    /// grid does not resolve, just below the least of those it does, holds
    /// a lower force, or where the least force is compressive (the pull-off
    /// contact is narrower than the grid resolves).
    pub fn pull_off(&self, history: f64) -> Result<BranchPoint> {
        self.least_below(history, Load::Force(0.0))
    }

    /// The displacement-controlled jump-off reached from a contact of area
    /// `history` (m^2): the least depth on the receding branch below that
    /// area (as [`pull_off`](Self::pull_off)), where the contact comes off
    /// under fixed grips.
    ///
    /// # Errors
    /// As [`pull_off`](Self::pull_off).
    pub fn jump_off(&self, history: f64) -> Result<BranchPoint> {
        self.least_below(history, Load::Depth(0.0))
    }

    /// The least value of the receding balance (depth or force) below
    /// `history`, located on the sets and refined by golden-section search
    /// between the sets around it. Where the balance has one minimum below
    /// `history` (the JKR sphere, punch and sinusoid) it is that minimum;
    /// past a first minimum with a lower one below it on a set a receding
    /// contact can snap onto (as `evolve`'s), the contact snaps to the
    /// branch below under either control and comes off at the lower
    /// (Maugis 2000, Contact, Adhesion and Rupture of Elastic Solids,
    /// ch. 5).
    fn least_below(&self, history: f64, load: Load) -> Result<BranchPoint> {
        let nodes = &self.nodes;
        let key = |a: f64| self.balance(a, Edge::Receding, load);
        let top = history.clamp(nodes[0].area, self.max_contact_area());
        // The sets below `top` (and `top`), each with whether it has as
        // many cells as `evolve` lets a receding contact snap onto, and the
        // balance on each.
        let (mut areas, mut resolved): (Vec<f64>, Vec<bool>) = nodes
            .iter()
            .filter(|n| n.area < top)
            .map(|n| (n.area, n.cells >= RESOLVED_CELLS))
            .unzip();
        areas.push(top);
        resolved.push(true);
        let values: Vec<f64> = areas.iter().map(|&a| key(a)).collect();
        // The first minimum walking down.
        let mut i = areas.len() - 1;
        while i > 0 && values[i - 1] <= values[i] {
            i -= 1;
        }
        // Past it the edge snaps to the branch below, where the balance
        // holds again at the same load, and recedes on from there: the
        // contact comes off at the least value of the sets it can snap
        // onto (onto a smaller one the snap is the staircase's and the
        // contact comes off, as in `evolve`). A strip's sets are all such:
        // on a strip along the grid's diagonal 1.2 lines of cells wide at
        // the pull-off, the first minimum, a ripple of the staircase five
        // lines wide, had been returned as a compressive "pull-off" 2.3
        // times the exact force; the least is on the narrowest strip, and
        // refused below.
        for j in (0..i).rev() {
            if resolved[j] && values[j] < values[i] {
                i = j;
            }
        }
        // A least value with a lower one just below it on a set too small
        // to snap onto: the minimum may lie among the sets the grid does
        // not resolve.
        let unresolved_below = i == 0 || !resolved[i - 1];
        if unresolved_below && values[..i].iter().any(|&v| v < values[i]) {
            return Err(unresolved_minimum());
        }
        // An adhesive contact comes off under tension: a least force above
        // zero is a staircase's (the unloaded, vanishing contact lies below).
        if matches!(load, Load::Force(_)) && values[i] > 0.0 {
            return Err(unresolved_minimum());
        }
        let (mut lo, mut hi) = (
            areas[i.saturating_sub(1)],
            areas[(i + 1).min(areas.len() - 1)],
        );
        let golden = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..BISECTIONS {
            let (x1, x2) = (hi - golden * (hi - lo), lo + golden * (hi - lo));
            if key(x1) < key(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let area = 0.5 * (lo + hi);
        // Pinned at the family's smallest set (the minimum lies below it,
        // where the family holds no set), or on a strip narrower than the
        // grid resolves (a wavy surface's pull-off contact 2.2 lines of
        // cells wide came out 32 % off before this check).
        if i == 0 && area - areas[0] <= 1e-6 * areas[0] || area < self.least_area {
            return Err(unresolved_minimum());
        }
        let depth = self.lowest + self.balance(area, Edge::Receding, Load::Depth(0.0));
        self.checked(self.point(area, Load::Depth(depth)))
    }

    /// `point` if all its values are finite.
    fn checked(&self, point: BranchPoint) -> Result<BranchPoint> {
        crate::solver::all_finite(
            "adhesive energy balance",
            &[point.depth, point.force, point.contact_area],
        )?;
        Ok(point)
    }
}

/// The refusal of a pull-off or jump-off the family's sets do not resolve.
fn unresolved_minimum() -> Error {
    Error::Unsupported {
        feature: "a pull-off or jump-off at the family's smallest contact sets",
        reason: "the force (or depth) is least where the grid hardly resolves the contact; \
                 refine the grid",
    }
}

/// Least-squares quadratic through `(x, y)` points: the coefficients
/// `[c0, c1, c2]` of `c0 + c1 x + c2 x^2`.
fn quadratic_fit(points: &[(f64, f64)]) -> [f64; 3] {
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
    // Normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = t, by Cramer's rule.
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
    [column(0), column(1), column(2)]
}

impl AdhesiveBranches {
    /// The advancing balance's depth (relative to the lowest point) or
    /// force at `area`: the loading branch reaches a target up to the area
    /// where this attains it.
    pub(super) fn advancing_balance(&self, area: f64, by_force: bool) -> f64 {
        let load = if by_force {
            Load::Force(0.0)
        } else {
            Load::Depth(0.0)
        };
        self.balance(area, Edge::Advancing, load)
    }
}
