//! An ellipse fitted to the cells of a contact's edge, by least squares
//! on the algebraic distance of the conic (Fitzgibbon, Pilu & Fisher 1999,
//! IEEE TPAMI 21, 476, without their constraint: here the centroid of the
//! points is inside the curve, and the conic is normalised to 1 there).

/// Vertices of the polygon that stands for the fitted ellipse in
/// [`Ellipse::edge_cells`].
const OUTLINE_POINTS: usize = 720;

/// The ellipse `(x - centre)^T q (x - centre) = 1`, positions `[row,
/// column]` in cells.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ellipse {
    centre: [f64; 2],
    q: [[f64; 2]; 2],
}

impl Ellipse {
    /// The conic `A u^2 + B u v + C v^2 + D u + E v = 1` through `points`
    /// by least squares (in coordinates about their centroid, scaled by
    /// their spread, so that the centroid, inside the curve, is not on
    /// it), with `A = C, B = 0` if `circle`; `None` unless it is a real
    /// ellipse.
    pub(super) fn fit(points: &[[f64; 2]], circle: bool) -> Option<Self> {
        let (mean, spread) = centroid(points)?;
        let scaled = |p: &[f64; 2]| [(p[0] - mean[0]) / spread, (p[1] - mean[1]) / spread];
        let [a, b, c, d, e] = if circle {
            let [a, d, e] = least_squares(points.iter().map(|p| {
                let [u, v] = scaled(p);
                ([u * u + v * v, u, v], 1.0)
            }))?;
            [a, 0.0, a, d, e]
        } else {
            least_squares(points.iter().map(|p| {
                let [u, v] = scaled(p);
                ([u * u, u * v, v * v, u, v], 1.0)
            }))?
        };
        let det = a * c - 0.25 * b * b;
        if !(a > 0.0 && det > 0.0) {
            return None;
        }
        // The centre -Q^-1 [D, E] / 2 and the level 1 + u0^T Q u0 there.
        let u0 = [
            -0.5 * (c * d - 0.5 * b * e) / det,
            -0.5 * (a * e - 0.5 * b * d) / det,
        ];
        let level = 1.0 + a * u0[0] * u0[0] + b * u0[0] * u0[1] + c * u0[1] * u0[1];
        let factor = level * spread * spread;
        if !(factor > 0.0 && factor.is_finite()) {
            return None;
        }
        Some(Ellipse {
            centre: [mean[0] + u0[0] * spread, mean[1] + u0[1] * spread],
            q: [
                [a / factor, 0.5 * b / factor],
                [0.5 * b / factor, c / factor],
            ],
        })
    }

    /// `y = x - centre`, `q y` and `y^T q y` (1 on the ellipse).
    fn level(&self, x: [f64; 2]) -> ([f64; 2], [f64; 2], f64) {
        let y = [x[0] - self.centre[0], x[1] - self.centre[1]];
        let g = [
            self.q[0][0] * y[0] + self.q[0][1] * y[1],
            self.q[1][0] * y[0] + self.q[1][1] * y[1],
        ];
        (y, g, y[0] * g[0] + y[1] * g[1])
    }

    /// `x`'s offset from the centre scaled onto the ellipse along the ray
    /// from it, `x'`, and the support distance `x' . n` there.
    pub(super) fn project(&self, x: [f64; 2]) -> ([f64; 2], f64) {
        let (y, g, f) = self.level(x);
        let root = f.sqrt();
        ([y[0] / root, y[1] / root], root / g[0].hypot(g[1]))
    }

    /// The distance of `x` outside the ellipse along the normal, to first
    /// order in its distance from the curve.
    pub(super) fn distance(&self, x: [f64; 2]) -> f64 {
        let (_, g, f) = self.level(x);
        let root = f.sqrt();
        (root - 1.0) * root / g[0].hypot(g[1])
    }

    /// The geometric mean of the semi-axes, `det(q)^(-1/4)`.
    pub(super) fn mean_radius(&self) -> f64 {
        let det = self.q[0][0] * self.q[1][1] - self.q[0][1] * self.q[1][0];
        det.powf(-0.25)
    }

    /// The edge cells a digital ellipse of this shape has: the sum of
    /// `max(|dx|, |dy|)` over the sides of an inscribed polygon.
    pub(super) fn edge_cells(&self) -> f64 {
        let vertex = |k: usize| {
            let t = std::f64::consts::TAU * k as f64 / OUTLINE_POINTS as f64;
            let v = [t.cos(), t.sin()];
            let f = self.q[0][0] * v[0] * v[0]
                + 2.0 * self.q[0][1] * v[0] * v[1]
                + self.q[1][1] * v[1] * v[1];
            [v[0] / f.sqrt(), v[1] / f.sqrt()]
        };
        (0..OUTLINE_POINTS)
            .map(|k| {
                let (a, b) = (vertex(k), vertex(k + 1));
                (b[0] - a[0]).abs().max((b[1] - a[1]).abs())
            })
            .sum()
    }
}

/// The centroid of `points` and their root-mean-square distance from it;
/// `None` unless that is positive and finite.
pub(super) fn centroid(points: &[[f64; 2]]) -> Option<([f64; 2], f64)> {
    let n = points.len() as f64;
    let mut mean = [0.0; 2];
    for p in points {
        mean[0] += p[0] / n;
        mean[1] += p[1] / n;
    }
    let spread = (points
        .iter()
        .map(|p| (p[0] - mean[0]).powi(2) + (p[1] - mean[1]).powi(2))
        .sum::<f64>()
        / n)
        .sqrt();
    (spread.is_finite() && spread > 0.0).then_some((mean, spread))
}

/// The least-squares solution of `row . theta = target` over the pairs
/// `(row, target)`, by the normal equations.
pub(super) fn least_squares<const N: usize>(
    rows: impl Iterator<Item = ([f64; N], f64)>,
) -> Option<[f64; N]> {
    let mut matrix = [[0.0; N]; N];
    let mut rhs = [[0.0; 1]; N];
    for (row, target) in rows {
        for (k, &rk) in row.iter().enumerate() {
            for (entry, &rl) in matrix[k].iter_mut().zip(&row) {
                *entry += rk * rl;
            }
            rhs[k][0] += rk * target;
        }
    }
    solve(matrix, rhs).map(|x| x.map(|[value]| value))
}

/// `M^-1 f` for the `M` columns of `f`, by Gaussian elimination with
/// partial pivoting; `None` if `M` is singular (or not finite) to working
/// precision.
pub(super) fn solve<const N: usize, const M: usize>(
    mut matrix: [[f64; N]; N],
    mut rhs: [[f64; M]; N],
) -> Option<[[f64; M]; N]> {
    let scale = matrix.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    for col in 0..N {
        let pivot = (col..N)
            .max_by(|&a, &b| matrix[a][col].abs().total_cmp(&matrix[b][col].abs()))
            .unwrap_or(col);
        matrix.swap(col, pivot);
        rhs.swap(col, pivot);
        let diagonal = matrix[col][col];
        if diagonal.abs() <= 1e-12 * scale {
            return None;
        }
        for row in 0..N {
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
    let mut solution = [[0.0; M]; N];
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

    /// The edge cells (inside, with a 4-neighbour outside) of the set
    /// `inside` on an `n x n` grid.
    fn edge_cells(n: usize, inside: impl Fn(f64, f64) -> bool) -> Vec<[f64; 2]> {
        let member = |i: isize, j: isize| inside(i as f64, j as f64);
        let mut cells = Vec::new();
        for i in 0..n as isize {
            for j in 0..n as isize {
                let open = [(i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)]
                    .iter()
                    .any(|&(a, b)| !member(a, b));
                if member(i, j) && open {
                    cells.push([i as f64, j as f64]);
                }
            }
        }
        cells
    }

    #[test]
    fn a_digital_ellipse_is_fitted_about_its_centre_with_its_axes() {
        // A 2:1 ellipse, semi-axes 40 and 20 cells, major axis at 0.5 rad
        // to the columns, centred off the cell centres: the fitted centre
        // within a twentieth of a cell, the axes' ratio within 1 % and the
        // major axis's direction within a hundredth of a radian. (The
        // edge cells' centres lie inside the curve by about half a cell,
        // so the axes themselves are short by that: not tested.)
        let (centre, angle) = ([44.3, 44.6], 0.5f64);
        let (s, c) = angle.sin_cos();
        let cells = edge_cells(90, |i, j| {
            let (y, x) = (i - centre[0], j - centre[1]);
            ((c * x + s * y) / 40.0).hypot((-s * x + c * y) / 20.0) < 1.0
        });
        let fitted = Ellipse::fit(&cells, false).expect("an ellipse");
        let offset = (fitted.centre[0] - centre[0]).hypot(fitted.centre[1] - centre[1]);
        let [[qyy, qyx], [_, qxx]] = fitted.q;
        let (trace, det) = (qxx + qyy, qxx * qyy - qyx * qyx);
        let root = (0.25 * trace * trace - det).sqrt();
        let ratio = ((0.5 * trace + root) / (0.5 * trace - root)).sqrt();
        // The major axis: the eigenvector of the smaller eigenvalue.
        let direction = 0.5 * (-2.0 * qyx).atan2(qyy - qxx);
        println!("centre off by {offset:.4}, ratio {ratio:.4}, direction {direction:.4}");
        assert!(offset < 0.05, "{offset}");
        assert!((ratio / 2.0 - 1.0).abs() < 0.01, "{ratio}");
        assert!((direction - angle).abs() < 0.01, "{direction}");
        // A circle fitted to it is no ellipse of its shape.
        let circle = Ellipse::fit(&cells, true).expect("a circle");
        let (near, far) = cells
            .iter()
            .map(|&x| circle.distance(x))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), d| {
                (l.min(d), h.max(d))
            });
        assert!(far - near > 20.0, "{near} {far}");
    }

    #[test]
    fn collinear_or_single_points_are_no_ellipse() {
        let line: Vec<[f64; 2]> = (0..30).map(|k| [k as f64, 2.0 * k as f64]).collect();
        assert!(Ellipse::fit(&line, false).is_none());
        assert!(Ellipse::fit(&[[3.0, 4.0]; 30], true).is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: 500,
            rng_seed: proptest::test_runner::RngSeed::Fixed(20261128),
            ..proptest::prelude::ProptestConfig::default()
        })]
        /// Any cloud of points, of any finite or non-finite coordinates: no
        /// ellipse, or one whose every derived quantity is finite.
        #[test]
        fn never_a_nan(points in proptest::collection::vec(
            (proptest::num::f64::ANY, proptest::num::f64::ANY), 0..40),
            circle in proptest::bool::ANY) {
            let points: Vec<[f64; 2]> = points.iter().map(|&(a, b)| [a, b]).collect();
            if let Some(ellipse) = Ellipse::fit(&points, circle) {
                proptest::prop_assert!(ellipse.mean_radius().is_finite());
                proptest::prop_assert!(ellipse.edge_cells().is_finite());
                proptest::prop_assert!(ellipse.centre.iter().all(|v| v.is_finite()));
            }
        }
    }
}
