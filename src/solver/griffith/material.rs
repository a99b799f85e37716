//! The local energy release rate along the edge of a clamped contact set,
//! from its configurational (material) forces.
//!
//! Move the cells of a clamped set by a smooth field `eps V(x)` (the
//! indenter stays put). The stored energy `U = max_q [sum q g - q C q / 2]`
//! of the forces `q_i = p_i Delta^2` changes, by the envelope theorem, at
//!
//! `dU/deps = sum_i q_i V_i . (grad g_i - sum_j grad C(x_i - x_j) q_j)`,
//!
//! the discrete form of the shape derivative `int G V.n ds` over the edge
//! (Eshelby 1951; Rice 1968, J. Appl. Mech. 35, 379; as material forces in
//! Mueller & Maugin 2002, Comput. Mech. 29, 52). The bracket vanishes on
//! cells inside the set (there `u = g`), so the whole release sits on the
//! edge cells: `F_i = q_i (grad g - grad u)_i`, with `u` the surface
//! displacement of the solution and the gradients taken by central
//! differences. A translation `V` weighs every force by the indenter's slope
//! and is as exact as the pressures; a `V` varying over a length `l` is off
//! only through the pairs of edge cells a cell apart, by `O(Delta / l)`
//! whatever the edge's direction on the grid, where the pressures of single
//! edge cells (and so every criterion built on them) carry errors of order
//! one that depend on it.

use super::release::EdgeFit;

/// The material forces of the edge cells of a clamped set, as quadratics in
/// the depth: with the pressures `d p1 - pf` and displacements `d u1 - uf`
/// of the punch and shape solutions, `F(d) = d^2 a - d b + c` (N/m per
/// cell, pointing out of the set where the edge is tensile).
#[derive(Debug, Clone, Default)]
pub(super) struct EdgeForces {
    /// The edge cells: attached cells with a detached 4-neighbour.
    pub(super) cells: Vec<usize>,
    /// `[a, b, c]` per edge cell, each `[x, y]`.
    pub(super) coefficients: Vec<[[f64; 2]; 3]>,
    /// The sum of the unit vectors from each edge cell towards its detached
    /// 4-neighbours: summed over a stretch of edge, its length is the
    /// stretch's length in cells and its direction the outward normal.
    pub(super) facets: Vec<[f64; 2]>,
    /// `[p1, pf]` per edge cell: its pressure is `d p1 - pf`.
    pub(super) pressures: Vec<[f64; 2]>,
    /// The degree of the polynomial that the indenter's face over the set
    /// is, to rounding: 1 (a plane), 2 (a quadratic), `None` (neither).
    pub(super) face_degree: Option<usize>,
    /// Whether the body is a homogeneous half-space (where an elliptical
    /// contact's release rate has the form of `ellipse_modes.rs`).
    pub(super) half_space: bool,
    pub(super) rows: usize,
    pub(super) columns: usize,
    pub(super) periodic: bool,
}

impl crate::solver::ContactSolver {
    /// The two clamped solutions of the energy identity on `attached`
    /// (row-major cells the indenter reaches): the pressures `punch` of a
    /// unit depth and `shape` of the face's heights above `lowest`, each
    /// warm-started from what it holds (zero it off the set first).
    /// `target` is scratch of the grid's length. Returns the CG
    /// iterations and the larger residual.
    pub(super) fn solve_clamped_pair(
        &mut self,
        attached: &[bool],
        lowest: f64,
        target: &mut [f64],
        punch: &mut [f64],
        shape: &mut [f64],
    ) -> crate::error::Result<(usize, f64)> {
        target.fill(1.0);
        let (i1, r1) = self.clamped_cg(attached, target, punch)?;
        for ((t, h), &on) in target.iter_mut().zip(&self.workspace.profile).zip(attached) {
            *t = if on { h - lowest } else { 0.0 };
        }
        // A set all at the lowest height (a strip's lowest lines) has no
        // shape pressures: zero exactly, not the warm start iterated down to
        // rounding, whose sign decided a pull-off's refusal
        // (`tests/adhesion_limits.rs`, Johnson's sinusoid at alpha = 0.1).
        if target.iter().all(|&t| t == 0.0) {
            for (p, &on) in shape.iter_mut().zip(attached) {
                if on {
                    *p = 0.0;
                }
            }
            return Ok((i1, r1));
        }
        let (i2, r2) = self.clamped_cg(attached, target, shape)?;
        Ok((i1 + i2, r1.max(r2)))
    }
}

/// The fields of the two clamped solutions on one set.
pub(super) struct ClampedPair<'a> {
    pub(super) attached: &'a [bool],
    /// Heights above the lowest point (`+inf` where the indenter is absent).
    pub(super) profile: &'a [f64],
    pub(super) lowest: f64,
    pub(super) punch: &'a [f64],
    pub(super) punch_displacement: &'a [f64],
    pub(super) shape: &'a [f64],
    pub(super) shape_displacement: &'a [f64],
}

impl EdgeForces {
    /// The edge cells' material forces of `pair` on a `rows x columns` grid
    /// of spacing `delta`, wrapping round if `periodic`, on a half-space if
    /// `half_space`.
    pub(super) fn new(
        pair: &ClampedPair,
        rows: usize,
        columns: usize,
        delta: f64,
        periodic: bool,
        half_space: bool,
    ) -> Self {
        let n = pair.attached.len();
        let area = delta * delta;
        let height = |c: usize| pair.profile[c] - pair.lowest;
        let mut forces = EdgeForces {
            rows,
            columns,
            periodic,
            face_degree: super::face::degree(pair, rows, columns, delta, periodic),
            half_space,
            ..EdgeForces::default()
        };
        for c in 0..n {
            if !pair.attached[c] {
                continue;
            }
            // Back and front along the rows, then along the columns.
            let [up, down, left, right] = super::periodic::neighbours(c, rows, columns, periodic);
            let around = [[up, down], [left, right]];
            let edge = around
                .iter()
                .flatten()
                .any(|m| m.is_none_or(|m| !pair.attached[m]));
            if !edge {
                continue;
            }
            let mut coefficients = [[0.0; 2]; 3];
            let mut facet = [0.0; 2];
            for (axis, sides) in around.iter().enumerate() {
                for (side, m) in sides.iter().enumerate() {
                    if m.is_none_or(|m| !pair.attached[m]) {
                        facet[axis] += if side == 0 { -1.0 } else { 1.0 };
                    }
                }
            }
            for (axis, &[back, front]) in around.iter().enumerate() {
                // The slope of the indenter: central where both neighbours
                // carry it, else one-sided from the side that does.
                let finite = |m: Option<usize>| m.filter(|&m| height(m).is_finite());
                let slope = match (finite(back), finite(front)) {
                    (Some(b), Some(f)) => (height(f) - height(b)) / (2.0 * delta),
                    (Some(b), None) => (height(c) - height(b)) / delta,
                    (None, Some(f)) => (height(f) - height(c)) / delta,
                    (None, None) => 0.0,
                };
                let gradient = |field: &[f64]| match (back, front) {
                    (Some(b), Some(f)) => (field[f] - field[b]) / (2.0 * delta),
                    (Some(b), None) => (field[c] - field[b]) / delta,
                    (None, Some(f)) => (field[f] - field[c]) / delta,
                    (None, None) => 0.0,
                };
                // r(d) = grad g - grad u = d r1 - rf with g = d - h.
                let r1 = -gradient(pair.punch_displacement);
                let rf = slope - gradient(pair.shape_displacement);
                let (q1, qf) = (pair.punch[c] * area, pair.shape[c] * area);
                coefficients[0][axis] = q1 * r1;
                coefficients[1][axis] = q1 * rf + qf * r1;
                coefficients[2][axis] = qf * rf;
            }
            forces.cells.push(c);
            forces.coefficients.push(coefficients);
            forces.facets.push(facet);
            forces.pressures.push([pair.punch[c], pair.shape[c]]);
        }
        forces
    }

    /// The forces smoothed along the edge by a Gaussian of `window` cells,
    /// `exp(-r^2 / window^2)` over the edge cells within `3 window`: per
    /// edge cell the outward normal (of the smoothed facets) and the release
    /// rate's quadratic `G(d) = d^2 a - d b + c` (J/m^2), by a local
    /// quadratic fit along the edge (the forces' weighted moments of order 0
    /// to 2 in the tangential offset `s` matched by those of
    /// `G(s) (e.n) Delta`, with `e` the facets; a local Savitzky-Golay
    /// filter), so that a rate varying smoothly along the edge is followed
    /// without the window's `O(window^2)` bias. Exact for a straight edge of
    /// uniform release, whatever its direction.
    ///
    /// The edge of a digital ellipse on a half-space (or disc on any
    /// body) under a planar or quadratic face is fitted instead by the
    /// five or nine functions in which its release rate lies
    /// ([`EdgeForces::ellipse_modes`]); the second value says which.
    pub(super) fn smoothed(&self, delta: f64, window: f64) -> (Vec<EdgeRate>, EdgeFit) {
        let mut rates = self.smoothed_locally(delta, window);
        match self.ellipse_modes(delta) {
            Some((modes, functions)) => {
                for (rate, quadratic) in rates.iter_mut().zip(modes) {
                    rate.quadratic = quadratic;
                }
                (rates, EdgeFit::Modes { functions })
            }
            None => (rates, EdgeFit::Window { cells: window }),
        }
    }

    /// The local fit of [`EdgeForces::smoothed`].
    fn smoothed_locally(&self, delta: f64, window: f64) -> Vec<EdgeRate> {
        let mut index = vec![u32::MAX; self.rows * self.columns];
        for (k, &c) in self.cells.iter().enumerate() {
            index[c] = k as u32;
        }
        let mut rates = Vec::with_capacity(self.cells.len());
        for &c in &self.cells {
            let (mut facet, mut pressure) = ([0.0; 2], [0.0; 2]);
            self.visit(&index, c, window, |k, _, w| {
                for axis in 0..2 {
                    facet[axis] += w * self.facets[k][axis];
                    pressure[axis] += w * self.pressures[k][axis];
                }
            });
            let length = facet[0].hypot(facet[1]);
            if length <= 0.0 {
                rates.push(EdgeRate {
                    normal: [0.0; 2],
                    quadratic: [0.0; 3],
                    pressure,
                });
                continue;
            }
            let normal = [facet[0] / length, facet[1] / length];
            let tangent = [-normal[1], normal[0]];
            // Moments: lengths sum w (e.n) s^k, k = 0..4; forces
            // sum w (F.n) s^k, k = 0..2, for each coefficient.
            let (mut lengths, mut forces) = ([0.0; 5], [[0.0; 3]; 3]);
            self.visit(&index, c, window, |k, offset, w| {
                let s = offset[0] * tangent[0] + offset[1] * tangent[1];
                let e = self.facets[k][0] * normal[0] + self.facets[k][1] * normal[1];
                let mut power = w;
                for (order, total) in lengths.iter_mut().enumerate() {
                    *total += power * e;
                    if order < 3 {
                        for (sums, term) in forces.iter_mut().zip(&self.coefficients[k]) {
                            sums[order] += power * (term[0] * normal[0] + term[1] * normal[1]);
                        }
                    }
                    power *= s;
                }
            });
            let quadratic = forces.map(|f| centre_value(&lengths, &f) / delta);
            rates.push(EdgeRate {
                normal,
                quadratic,
                pressure,
            });
        }
        rates
    }

    /// Calls `visit(k, [di, dj], w)` for every edge cell `k` within `3
    /// window` cells of cell `c` (offset in cells, Gaussian weight), wrapping
    /// round a periodic grid.
    fn visit(
        &self,
        index: &[u32],
        c: usize,
        window: f64,
        mut visit: impl FnMut(usize, [f64; 2], f64),
    ) {
        let (rows, columns) = (self.rows as isize, self.columns as isize);
        let (i, j) = (c as isize / columns, c as isize % columns);
        let reach = (3.0 * window).ceil() as isize;
        // A box no wider than the grid, so that a periodic wrap visits no
        // cell twice.
        let (ri, rj) = (reach.min((rows - 1) / 2), reach.min((columns - 1) / 2));
        let wrap = |value: isize, period: isize| {
            if (0..period).contains(&value) {
                Some(value)
            } else if self.periodic {
                Some(value.rem_euclid(period))
            } else {
                None
            }
        };
        for di in -ri..=ri {
            let Some(row) = wrap(i + di, rows) else {
                continue;
            };
            for dj in -rj..=rj {
                let Some(column) = wrap(j + dj, columns) else {
                    continue;
                };
                let k = index[(row * columns + column) as usize];
                if k != u32::MAX {
                    let r2 = (di * di + dj * dj) as f64;
                    visit(
                        k as usize,
                        [di as f64, dj as f64],
                        (-r2 / (window * window)).exp(),
                    );
                }
            }
        }
    }
}

/// The value at `s = 0` of the quadratic `G(s)` whose moments against the
/// lengths (`m_k = lengths[k]`) match `forces`: the system
/// `sum_l m_(k+l) g_l = f_k`, `k = 0..2`, by Cramer's rule; the plain
/// weighted mean `f_0 / m_0` where it is singular (too few cells along the
/// edge to fit a curve).
fn centre_value(lengths: &[f64; 5], forces: &[f64; 3]) -> f64 {
    let m = lengths;
    let det3 = |c0: [f64; 3], c1: [f64; 3], c2: [f64; 3]| {
        c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) - c1[0] * (c0[1] * c2[2] - c0[2] * c2[1])
            + c2[0] * (c0[1] * c1[2] - c0[2] * c1[1])
    };
    let columns = [[m[0], m[1], m[2]], [m[1], m[2], m[3]], [m[2], m[3], m[4]]];
    let det = det3(columns[0], columns[1], columns[2]);
    let scale = m[0] * m[2] * m[4];
    if det.abs() > 1e-9 * scale.abs() && scale != 0.0 {
        det3(*forces, columns[1], columns[2]) / det
    } else if m[0] > 0.0 {
        forces[0] / m[0]
    } else {
        0.0
    }
}

/// The smoothed release rate at one edge cell.
#[derive(Debug, Clone, Copy)]
pub(super) struct EdgeRate {
    /// Outward unit normal `[x, y]` (zero where the edge's facets cancel).
    pub(super) normal: [f64; 2],
    /// `[a, b, c]` of `G(d) = d^2 a - d b + c`, J/m^2.
    pub(super) quadratic: [f64; 3],
    /// `[p1, pf]` of the smoothed edge pressure `d p1 - pf` (Pa; its sign
    /// tells a pulling edge from a pushing one).
    pressure: [f64; 2],
}

impl EdgeRate {
    /// The release rate at depth `depth`, J/m^2.
    pub(super) fn at(&self, depth: f64) -> f64 {
        let [a, b, c] = self.quadratic;
        depth * depth * a - depth * b + c
    }

    /// The smoothed pressure of the edge cells at depth `depth`, Pa (a
    /// weighted sum, not an average: only its sign is meant).
    pub(super) fn edge_pressure(&self, depth: f64) -> f64 {
        depth * self.pressure[0] - self.pressure[1]
    }

    /// The depth at which this edge, pulled (the depth falling), releases
    /// `work` J/m^2: the lower root of `G(d) = work`, if the edge pulls
    /// there. `None` where the rate never reaches it.
    pub(super) fn critical_depth(&self, work: f64) -> Option<f64> {
        let [a, b, c] = self.quadratic;
        if a <= 0.0 {
            return None;
        }
        let discriminant = b * b - 4.0 * a * (c - work);
        if discriminant < 0.0 {
            return None;
        }
        let depth = (b - discriminant.sqrt()) / (2.0 * a);
        (depth.is_finite() && self.edge_pressure(depth) < 0.0).then_some(depth)
    }
}
