//! The release rate round the edge of a bonded disc under a planar face, by
//! its three lowest angular modes instead of a window along the edge.
//!
//! A flat face (tilted or not) bonded over a circular contact on a body
//! that is axisymmetric about the contact's axis (a half-space, a layer, a
//! stack) carries a force and two moments only, and the stress intensity
//! round the edge is `K(theta) = A + B cos theta + C sin theta` (a force
//! excites the zeroth angular mode, a moment the first; the modes do not
//! couple on an axisymmetric body; on a half-space the punch of Kendall
//! 1971, J. Phys. D 4, 1186, tilted as in Johnson 1985, Contact Mechanics,
//! ch. 5), so `G = K^2 / (2 E*)` lies in the span
//! of `1, cos theta, sin theta, cos 2 theta, sin 2 theta`. The edge cells'
//! material forces are projected on these five smooth virtual motions
//! (radial, `V = phi_k(theta) r_hat`: the sums converge to `int G phi_k (r_hat
//! . n) ds` at first order in the cell, whatever the edge's direction) and
//! the release rate is the Galerkin fit in their span, weighted like the
//! local fit by the facets' lengths along `r_hat`. The fit averages over the
//! whole edge, so the staircase's pattern of steps, which a window of a
//! few cells does not average out (a disc tilted by a quarter of Kendall's
//! critical depth: its onset -1.7 to +2.2 % off at 64 cells across over five
//! sub-cell positions), leaves -0.27 to +0.25 % (`BENCHMARKS.md`, "Local
//! release rates along an edge").

use super::material::EdgeForces;

/// The number of angular harmonics fitted (modes 0 to 2).
const HARMONICS: usize = 2;
/// Functions of the fit: the constant and a cosine and a sine per harmonic.
const FUNCTIONS: usize = 2 * HARMONICS + 1;
/// The fewest edge cells of a disc fitted by modes (a disc about five cells
/// in radius); smaller ones keep the local fit.
const MIN_EDGE_CELLS: usize = 24;
/// The widest spread of the edge cells' distances from their centroid, in
/// cells, of a contact taken for a digital disc: at most 1.33 on 72
/// digital discs of 4.5 to 256 cells' radius at random sub-cell positions;
/// 2 keeps the first contacts of a peeling path (a disc less a few edge
/// cells) on the modes (with 1.5 they fall back to the window sooner, and
/// a disc tilted by a tenth of Kendall's depth came off 1.2 and 2.0 %
/// beyond its onset at 32 and 64 cells instead of 0 and 0.9 %). Squares of
/// up to 10 cells spread less: see [`EDGES_PER_RADIUS`].
const MAX_SPREAD: f64 = 2.0;
/// The edge cells of a digital disc per cell of its mean edge radius:
/// 5.63 to 5.89 on those discs (5.49 and 6.11 at 4 and 5 cells centred on
/// a corner); a square has 6.9 (along the grid) or 4.95 (at 45 degrees).
const EDGES_PER_RADIUS: std::ops::RangeInclusive<f64> = 5.4..=6.3;

impl EdgeForces {
    /// The quadratics `[a, b, c]` of `G(d)` (J/m^2) at every edge cell from
    /// the modal fit, where the edge is that of one digital disc under a
    /// planar face on an isolated grid; `None` otherwise (the caller keeps
    /// the local fit).
    pub(super) fn disc_modes(&self, delta: f64) -> Option<Vec<[f64; 3]>> {
        let count = self.cells.len();
        if self.periodic || !self.planar || count < MIN_EDGE_CELLS {
            return None;
        }
        let offsets = self.disc_offsets()?;
        // The normal equations: M g = f, M_kl = sum (e . r_hat) phi_k phi_l,
        // f_k = sum (F . r_hat) phi_k, for each of the three coefficients.
        let mut matrix = [[0.0; FUNCTIONS]; FUNCTIONS];
        let mut rhs = [[0.0; 3]; FUNCTIONS];
        let mut functions = Vec::with_capacity(count);
        for (k, &(di, dj)) in offsets.iter().enumerate() {
            let r = di.hypot(dj);
            let radial = [di / r, dj / r];
            let phi = harmonics(di.atan2(dj));
            let along = |v: [f64; 2]| v[0] * radial[0] + v[1] * radial[1];
            let length = along(self.facets[k]);
            let forces = self.coefficients[k].map(along);
            for (row, &pk) in phi.iter().enumerate() {
                for (entry, &pl) in matrix[row].iter_mut().zip(&phi) {
                    *entry += length * pk * pl;
                }
                for (total, force) in rhs[row].iter_mut().zip(&forces) {
                    *total += force * pk;
                }
            }
            functions.push(phi);
        }
        let fitted = solve(matrix, rhs)?;
        Some(
            functions
                .iter()
                .map(|phi| {
                    let mut quadratic = [0.0; 3];
                    for (p, coefficients) in phi.iter().zip(&fitted) {
                        for (q, g) in quadratic.iter_mut().zip(coefficients) {
                            *q += p * g / delta;
                        }
                    }
                    quadratic
                })
                .collect(),
        )
    }

    /// The edge cells' offsets (rows, columns) from their centroid, if they
    /// are the edge of one digital disc.
    fn disc_offsets(&self) -> Option<Vec<(f64, f64)>> {
        let count = self.cells.len();
        let position = |c: usize| ((c / self.columns) as f64, (c % self.columns) as f64);
        let (mut ci, mut cj) = (0.0, 0.0);
        for &c in &self.cells {
            let (i, j) = position(c);
            ci += i / count as f64;
            cj += j / count as f64;
        }
        let offsets: Vec<(f64, f64)> = self
            .cells
            .iter()
            .map(|&c| {
                let (i, j) = position(c);
                (i - ci, j - cj)
            })
            .collect();
        let (near, far, mean) = offsets
            .iter()
            .map(|(di, dj)| di.hypot(*dj))
            .fold((f64::INFINITY, 0.0f64, 0.0), |(lo, hi, mean), r| {
                (lo.min(r), hi.max(r), mean + r / count as f64)
            });
        let disc = far - near <= MAX_SPREAD
            && near > 0.0
            && EDGES_PER_RADIUS.contains(&(count as f64 / mean));
        disc.then_some(offsets)
    }
}

/// `1, cos t, sin t, cos 2t, sin 2t`.
fn harmonics(t: f64) -> [f64; FUNCTIONS] {
    let mut phi = [1.0; FUNCTIONS];
    for h in 1..=HARMONICS {
        let (s, c) = (h as f64 * t).sin_cos();
        phi[2 * h - 1] = c;
        phi[2 * h] = s;
    }
    phi
}

/// `M^-1 f` for the three columns of `f`, by Gaussian elimination with
/// partial pivoting; `None` if `M` is singular (or not finite) to working
/// precision.
fn solve(
    mut matrix: [[f64; FUNCTIONS]; FUNCTIONS],
    mut rhs: [[f64; 3]; FUNCTIONS],
) -> Option<[[f64; 3]; FUNCTIONS]> {
    let scale = matrix.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    for col in 0..FUNCTIONS {
        let pivot = (col..FUNCTIONS)
            .max_by(|&a, &b| matrix[a][col].abs().total_cmp(&matrix[b][col].abs()))
            .unwrap_or(col);
        matrix.swap(col, pivot);
        rhs.swap(col, pivot);
        let diagonal = matrix[col][col];
        if diagonal.abs() <= 1e-12 * scale {
            return None;
        }
        for row in 0..FUNCTIONS {
            if row == col {
                continue;
            }
            let factor = matrix[row][col] / diagonal;
            let source = matrix[col];
            for (entry, s) in matrix[row].iter_mut().zip(source) {
                *entry -= factor * s;
            }
            let source = rhs[col];
            for (entry, s) in rhs[row].iter_mut().zip(source) {
                *entry -= factor * s;
            }
        }
    }
    let mut solution = [[0.0; 3]; FUNCTIONS];
    for (row, out) in solution.iter_mut().enumerate() {
        for (value, r) in out.iter_mut().zip(rhs[row]) {
            *value = r / matrix[row][row];
        }
    }
    solution
        .iter()
        .flatten()
        .all(|v| v.is_finite())
        .then_some(solution)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edge forces of the set `inside(i, j)` on an `n x n` grid (facets
    /// as `EdgeForces::new` counts them), each cell's force `g(theta)`
    /// times its facet in the constant coefficient.
    fn edge(n: usize, inside: impl Fn(f64, f64) -> bool, g: impl Fn(f64) -> f64) -> EdgeForces {
        let member = |i: isize, j: isize| {
            (0..n as isize).contains(&i)
                && (0..n as isize).contains(&j)
                && inside(i as f64, j as f64)
        };
        let mut forces = EdgeForces {
            rows: n,
            columns: n,
            planar: true,
            ..EdgeForces::default()
        };
        let centre = 0.5 * (n as f64 - 1.0);
        for i in 0..n as isize {
            for j in 0..n as isize {
                if !member(i, j) {
                    continue;
                }
                let facet = [
                    f64::from(!member(i + 1, j)) - f64::from(!member(i - 1, j)),
                    f64::from(!member(i, j + 1)) - f64::from(!member(i, j - 1)),
                ];
                let open = [(i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)]
                    .iter()
                    .any(|&(a, b)| !member(a, b));
                if !open {
                    continue;
                }
                let theta = (i as f64 - centre).atan2(j as f64 - centre);
                let value = g(theta);
                forces.cells.push(i as usize * n + j as usize);
                forces.coefficients.push([
                    [0.0; 2],
                    [0.0; 2],
                    [value * facet[0], value * facet[1]],
                ]);
                forces.facets.push(facet);
                forces.pressures.push([0.0; 2]);
            }
        }
        forces
    }

    #[test]
    fn a_field_in_the_modes_is_fitted_exactly_on_a_digital_disc() {
        // G(theta) = 1 + 0.5 cos theta - 0.3 sin theta + 0.2 cos 2 theta:
        // in the span, so the fit returns it at every edge cell to
        // rounding (the facets' own weights cancel). The offset disc's
        // centroid is not its centre: the angles differ from the centroid's
        // by up to a hundredth of a radian, so there to 1e-2.
        let g = |t: f64| 1.0 + 0.5 * t.cos() - 0.3 * t.sin() + 0.2 * (2.0 * t).cos();
        for (offset, tolerance) in [(0.0, 1e-12), (0.37, 2e-2)] {
            let n = 70;
            let c = 0.5 * (n as f64 - 1.0);
            let forces = edge(n, |i, j| (i - c - offset).hypot(j - c - offset) < 30.0, g);
            let fitted = forces.disc_modes(1.0).expect("a digital disc");
            let offsets = forces.disc_offsets().unwrap();
            for (q, (di, dj)) in fitted.iter().zip(offsets) {
                let exact = g(di.atan2(dj));
                assert!((q[2] - exact).abs() < tolerance, "{} {exact}", q[2]);
                assert_eq!(q[0], 0.0);
            }
        }
    }

    #[test]
    fn only_digital_discs_under_planar_faces_are_fitted_by_modes() {
        let n = 40;
        let c = 0.5 * (n as f64 - 1.0);
        let one = |_: f64| 1.0;
        let disc = edge(n, |i, j| (i - c).hypot(j - c) < 12.0, one);
        assert!(disc.disc_modes(1.0).is_some());
        // Squares along the grid and at 45 degrees, small and large.
        for side in [7.0, 8.0, 10.0, 12.0, 20.0] {
            let square = edge(
                n,
                |i, j| (i - c).abs() < side / 2.0 && (j - c).abs() < side / 2.0,
                one,
            );
            assert!(square.disc_modes(1.0).is_none(), "{side}");
            let diamond = edge(n, |i, j| (i - c).abs() + (j - c).abs() < side / 2.0, one);
            assert!(diamond.disc_modes(1.0).is_none(), "{side}");
        }
        // A 2:1 ellipse, a disc too small, a face that is not a plane.
        let ellipse = edge(n, |i, j| ((i - c) / 16.0).hypot((j - c) / 8.0) < 1.0, one);
        assert!(ellipse.disc_modes(1.0).is_none());
        let small = edge(n, |i, j| (i - c).hypot(j - c) < 3.5, one);
        assert!(small.disc_modes(1.0).is_none());
        let curved = EdgeForces {
            planar: false,
            ..disc
        };
        assert!(curved.disc_modes(1.0).is_none());
    }
}
