//! The release rate round the edge of a bonded elliptical (or circular)
//! contact under a planar or quadratic face, by the few smooth functions
//! it lies in, instead of a window along the edge.
//!
//! A flat face (tilted or not) bonded over an elliptical contact on a
//! frictionless half-space presses with `p = L(x, y) / sqrt(1 - f(x, y))`,
//! `L` linear and `f = 1` the ellipse (Galin 1953, *Contact Problems in the
//! Theory of Elasticity*, ch. 2: a polynomial displacement of degree `n`
//! over an ellipse is made by a pressure of the same degree over the root;
//! the circular punch of Kendall 1971, J. Phys. D 4, 1186, tilted as in
//! Johnson 1985, *Contact Mechanics*, ch. 5). Near the edge `1 - f = 2 s /
//! h`, with `s` the distance in and `h = x . n` the support distance (the
//! position's projection on the outward normal), so `K = L sqrt(pi h)` and
//! `G = K^2 / (2 E*) = h Q(x, y)` with `Q = pi L^2 / (2 E*)` a quadratic.
//! On the ellipse one quadratic is tied by `f = 1`, so `G / h` lies in the
//! span of `1, x, y, x^2 - y^2, 2 x y` (about the ellipse's centre). On a
//! circle these are the angular modes 0 to 2, and there the span is exact
//! on any body that is axisymmetric about the contact's axis (a layer, a
//! stack): a force excites the zeroth mode of `K`, a moment the first, and
//! the modes do not couple. A quadratic face (a paraboloid, tilted or
//! moved) is pressed by a quadratic over the root, so `G / h` is a
//! polynomial of degree 4 on the ellipse, in the span of the nine harmonic
//! polynomials of degree up to 4 (`face.rs` tells the faces apart).
//!
//! A circle (on any body) or, where none fits, an ellipse (on a
//! half-space) is fitted to the edge cells by least squares (the conic
//! through their centres; `ellipse_fit.rs`). Where every edge cell lies
//! within a band of [`MAX_SPREAD`] cells of it and the cells are as many
//! as a digital ellipse of that size has, the edge cells' material forces
//! are projected on the five (or nine) virtual motions `V = phi_k(x') x'`
//! (`x'` the cell's position scaled onto the fitted ellipse, so `V . n =
//! phi_k h`: the sums converge to `int G phi_k h ds` at first order in the
//! cell, whatever the edge's direction) and the release rate is the
//! Galerkin fit `G = h sum g_l phi_l` in their span. The fit averages over
//! the whole edge, so the staircase's pattern of steps, which a window of a
//! few cells does not average out, leaves a first-order error
//! (`BENCHMARKS.md`, "A disc's edge fitted by its angular modes" and "An
//! ellipse's edge fitted by its modes").

use super::ellipse_fit::{solve, Ellipse};
use super::material::EdgeForces;

/// The fewest edge cells of a contact fitted by modes (a disc about five
/// cells in radius); smaller ones keep the local fit.
const MIN_EDGE_CELLS: usize = 24;
/// The widest band of the edge cells' distances from the fitted conic, in
/// cells, of a contact taken for a digital ellipse: at most 1.11, 1.13,
/// 1.20, 1.28 on 60 digital ellipses each of aspect ratios 1, 1.5, 2, 3
/// (minor semi-axes 4.5 to 64.5 cells, random orientations and sub-cell
/// positions);
/// 2 keeps the first contacts of a peeling path (a disc less a few edge
/// cells) on the modes (with 1.5 they fall back to the window sooner, and
/// a disc tilted by a tenth of Kendall's depth came off 1.2 and 2.0 %
/// beyond its onset at 32 and 64 cells instead of 0 and 0.9 %; with 3,
/// tried on 2026-11-28, the ten such discs at 64 cells all came off at
/// their onsets and at 128 cells 0.5 to 0.9 % beyond: the band decides
/// where a barely stable path switches estimator, not how exact the fit
/// is, so it stays at 2). Squares of up to 10 cells fit a circle closer:
/// see [`EDGE_COUNT`].
const MAX_SPREAD: f64 = 2.0;
/// The edge cells of a digital ellipse over the number expected of the
/// fitted one (the integral of `max(|n_x|, |n_y|)` along it: a straight
/// edge at an angle `t` to the grid has `max(|cos t|, |sin t|)` edge cells
/// per cell of length): 0.987 to 1.036 on the ellipses of [`MAX_SPREAD`];
/// squares of 7 to 40 cells have 1.17 to 1.19 along the grid and 0.85 to
/// 0.87 at 45 degrees (and fit circles within 2 cells up to 10 and 20
/// cells).
const EDGE_COUNT: std::ops::RangeInclusive<f64> = 0.93..=1.10;

impl EdgeForces {
    /// The quadratics `[a, b, c]` of `G(d)` (J/m^2) at every edge cell from
    /// the fit in the functions of an ellipse, where the edge is that of
    /// one digital ellipse (on a half-space) or disc (on any body) under a
    /// planar or quadratic face on an isolated grid, and the number of
    /// functions fitted; `None` otherwise (the caller keeps the local fit).
    pub(super) fn ellipse_modes(&self, delta: f64) -> Option<(Vec<[f64; 3]>, usize)> {
        if self.periodic || self.cells.len() < MIN_EDGE_CELLS {
            return None;
        }
        let degree = self.face_degree?;
        let ellipse = self.edge_ellipse()?;
        match degree {
            1 => self
                .galerkin(&ellipse, delta, harmonics::<5>)
                .map(|rates| (rates, 5)),
            2 => self
                .galerkin(&ellipse, delta, harmonics::<9>)
                .map(|rates| (rates, 9)),
            _ => None,
        }
    }

    /// The Galerkin fit `G = h sum g_l phi_l(x' / r)` of the edge cells'
    /// material forces against the virtual motions `phi_k(x' / r) x'`, `x'`
    /// each cell's position scaled onto `ellipse`, `h` the support distance
    /// there and `r` the ellipse's mean radius.
    fn galerkin<const N: usize>(
        &self,
        ellipse: &Ellipse,
        delta: f64,
        basis: fn([f64; 2]) -> [f64; N],
    ) -> Option<Vec<[f64; 3]>> {
        let scale = ellipse.mean_radius();
        // The normal equations: M g = f, M_kl = sum (e . x') h phi_k phi_l,
        // f_k = sum (F . x') phi_k, for each of the three coefficients.
        let mut matrix = [[0.0; N]; N];
        let mut rhs = [[0.0; 3]; N];
        let mut functions = Vec::with_capacity(self.cells.len());
        for (k, &c) in self.cells.iter().enumerate() {
            let (on, support) = ellipse.project(self.position(c));
            let phi = basis([on[0] / scale, on[1] / scale]);
            let along = |v: [f64; 2]| (v[0] * on[0] + v[1] * on[1]) / scale;
            let length = along(self.facets[k]) * support / scale;
            let forces = self.coefficients[k].map(along);
            for (row, &pk) in phi.iter().enumerate() {
                for (entry, &pl) in matrix[row].iter_mut().zip(&phi) {
                    *entry += length * pk * pl;
                }
                for (total, force) in rhs[row].iter_mut().zip(&forces) {
                    *total += force * pk;
                }
            }
            functions.push((phi, support / scale));
        }
        let fitted = solve(matrix, rhs)?;
        Some(
            functions
                .iter()
                .map(|(phi, support)| {
                    let mut quadratic = [0.0; 3];
                    for (p, coefficients) in phi.iter().zip(&fitted) {
                        for (q, g) in quadratic.iter_mut().zip(coefficients) {
                            *q += support * p * g / delta;
                        }
                    }
                    quadratic
                })
                .collect(),
        )
    }

    /// Cell `c`'s centre `[row, column]`, in cells.
    fn position(&self, c: usize) -> [f64; 2] {
        [(c / self.columns) as f64, (c % self.columns) as f64]
    }

    /// The circle fitted to the edge cells or, on a half-space where none
    /// fits, the ellipse, if the cells are the edge of one such digital
    /// curve: within a band of [`MAX_SPREAD`] cells of it, and as many as
    /// it should have ([`EDGE_COUNT`]). The circle comes first so that a
    /// peeling path's first contacts (a disc less a few edge cells) keep
    /// the disc's modes as on a layer (with the ellipse first, the disc
    /// tilted by a tenth of Kendall's depth came off 1.37 % beyond its
    /// onset at 64 cells instead of 0.15 %).
    fn edge_ellipse(&self) -> Option<Ellipse> {
        let points: Vec<[f64; 2]> = self.cells.iter().map(|&c| self.position(c)).collect();
        let fits = |ellipse: &Ellipse| {
            // A cell at the centre has no distance (0 / 0): no ellipse.
            let (near, far) = points.iter().map(|&x| ellipse.distance(x)).fold(
                (f64::INFINITY, f64::NEG_INFINITY),
                |(lo, hi), d| {
                    if d.is_finite() {
                        (lo.min(d), hi.max(d))
                    } else {
                        (f64::NEG_INFINITY, f64::INFINITY)
                    }
                },
            );
            let ratio = points.len() as f64 / ellipse.edge_cells();
            far - near <= MAX_SPREAD && EDGE_COUNT.contains(&ratio)
        };
        let circle = Ellipse::fit(&points, true).filter(fits);
        if circle.is_some() || !self.half_space {
            return circle;
        }
        Ellipse::fit(&points, false).filter(fits)
    }
}

/// The harmonic polynomials of degree up to `(N - 1) / 2`: `1` and the
/// real and imaginary parts of `(u + i v)^k` (`u, v, u^2 - v^2, 2 u v,
/// ...`), which span the polynomials of that degree on any ellipse (one
/// that vanished on it would vanish inside, by the maximum principle).
fn harmonics<const N: usize>([u, v]: [f64; 2]) -> [f64; N] {
    let mut phi = [1.0; N];
    let (mut re, mut im) = (1.0, 0.0);
    for k in 1..=(N - 1) / 2 {
        (re, im) = (re * u - im * v, re * v + im * u);
        phi[2 * k - 1] = re;
        phi[2 * k] = im;
    }
    phi
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edge forces of the set `inside(i, j)` on an `n x n` grid (facets
    /// as `EdgeForces::new` counts them), each cell's force `g(i, j)`
    /// times its facet in the constant coefficient.
    fn edge(
        n: usize,
        half_space: bool,
        inside: impl Fn(f64, f64) -> bool,
        g: impl Fn(f64, f64) -> f64,
    ) -> EdgeForces {
        let member = |i: isize, j: isize| {
            (0..n as isize).contains(&i)
                && (0..n as isize).contains(&j)
                && inside(i as f64, j as f64)
        };
        let mut forces = EdgeForces {
            rows: n,
            columns: n,
            face_degree: Some(1),
            half_space,
            ..EdgeForces::default()
        };
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
                let value = g(i as f64, j as f64);
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
        // rounding (the facets' own weights cancel), on a half-space or a
        // layer (a circle either way). The offset disc's fitted centre is
        // off its own by a fraction of a cell, so there the fit is off by
        // 3.0e-4 at the worst cell (measured; asserted to 1e-3: about the
        // edge cells' centroid, the centre before, it needed 2e-2).
        let n = 70;
        let c = 0.5 * (n as f64 - 1.0);
        for half_space in [false, true] {
            for (offset, tolerance) in [(0.0, 1e-12), (0.37, 1e-3)] {
                let (ci, cj) = (c + offset, c + offset);
                let g = |i: f64, j: f64| {
                    let t = (i - ci).atan2(j - cj);
                    1.0 + 0.5 * t.cos() - 0.3 * t.sin() + 0.2 * (2.0 * t).cos()
                };
                let forces = edge(n, half_space, |i, j| (i - ci).hypot(j - cj) < 30.0, g);
                let (fitted, functions) = forces.ellipse_modes(1.0).expect("a digital disc");
                assert_eq!(functions, 5);
                let worst = fitted
                    .iter()
                    .zip(&forces.cells)
                    .map(|(q, &cell)| {
                        let [i, j] = forces.position(cell);
                        assert_eq!(q[0], 0.0);
                        (q[2] - g(i, j)).abs()
                    })
                    .fold(0.0, f64::max);
                assert!(worst < tolerance, "{half_space} {offset}: {worst:e}");
            }
        }
    }

    #[test]
    fn a_field_in_the_modes_of_a_quadratic_face_is_fitted_exactly() {
        // Under a quadratic face K has the angular modes 0 to 2, so G those
        // to 4: G(theta) = 1 + 0.3 cos 3 theta - 0.2 sin 4 theta is
        // returned to rounding on a centred digital disc, and the five
        // functions of a planar face miss it by the amplitudes.
        let n = 70;
        let c = 0.5 * (n as f64 - 1.0);
        let g = |i: f64, j: f64| {
            let t = (i - c).atan2(j - c);
            1.0 + 0.3 * (3.0 * t).cos() - 0.2 * (4.0 * t).sin()
        };
        let disc = edge(n, false, |i, j| (i - c).hypot(j - c) < 30.0, g);
        let worst = |forces: &EdgeForces| {
            let (fitted, _) = forces.ellipse_modes(1.0).expect("a digital disc");
            fitted
                .iter()
                .zip(&forces.cells)
                .map(|(q, &cell)| {
                    let [i, j] = forces.position(cell);
                    (q[2] - g(i, j)).abs()
                })
                .fold(0.0, f64::max)
        };
        let quadratic = EdgeForces {
            face_degree: Some(2),
            ..disc.clone()
        };
        assert!(worst(&quadratic) < 1e-12, "{}", worst(&quadratic));
        assert!(worst(&disc) > 0.3, "{}", worst(&disc));
    }

    /// A 2:1 ellipse of semi-axes `2 b`, `b` about `centre`, its major
    /// axis at `angle` to the rows: `f(i, j)` and the support distance.
    fn ellipse(b: f64, angle: f64, centre: [f64; 2]) -> impl Fn(f64, f64) -> (f64, f64) {
        let (s, c) = angle.sin_cos();
        move |i, j| {
            let (y, x) = (i - centre[0], j - centre[1]);
            let (u, v) = (c * x + s * y, -s * x + c * y);
            let (a2, b2) = (4.0 * b * b, b * b);
            let f = u * u / a2 + v * v / b2;
            // At the point scaled onto the ellipse, h = 1 / |grad f / 2|.
            let root = f.sqrt();
            let h = root / ((u / a2).hypot(v / b2));
            (f, h)
        }
    }

    #[test]
    fn a_field_of_an_elliptical_punch_is_fitted_on_a_digital_ellipse() {
        // G = h (1 + 0.4 x - 0.2 y + 0.1 x^2 + 0.05 x y) on the edge of a
        // 2:1 ellipse, at three orientations and off the cell centres: the
        // fitted ellipse is the digital one's, a fraction of a cell off
        // the exact curve, so the fit returns G to within 2.4 % (minor
        // semi-axis 10 cells) and 1.1 % (20 cells) at the worst cell,
        // falling at first order.
        let n = 90;
        for (b, expected) in [(10.0, 0.03), (20.0, 0.015)] {
            for angle in [0.0, 0.5, 0.8] {
                let centre = [44.3, 44.6];
                let shape = ellipse(b, angle, centre);
                let g = |i: f64, j: f64| {
                    let (f, h) = shape(i, j);
                    let (x, y) = (
                        (j - centre[1]) / f.sqrt() / b,
                        (i - centre[0]) / f.sqrt() / b,
                    );
                    h / b * (1.0 + 0.4 * x - 0.2 * y + 0.1 * x * x + 0.05 * x * y)
                };
                let forces = edge(n, true, |i, j| shape(i, j).0 < 1.0, g);
                let (fitted, _) = forces.ellipse_modes(1.0).expect("a digital ellipse");
                let worst = fitted
                    .iter()
                    .zip(&forces.cells)
                    .map(|(q, &cell)| {
                        let [i, j] = forces.position(cell);
                        (q[2] / g(i, j) - 1.0).abs()
                    })
                    .fold(0.0, f64::max);
                println!("b {b} angle {angle}: worst {worst:.4}");
                assert!(worst < expected, "{b} {angle}: {worst}");
                // On a layer only a circle is fitted: not this one.
                let layered = EdgeForces {
                    half_space: false,
                    ..forces
                };
                assert!(layered.ellipse_modes(1.0).is_none());
            }
        }
    }

    #[test]
    fn only_digital_ellipses_under_planar_faces_are_fitted_by_modes() {
        let n = 40;
        let c = 0.5 * (n as f64 - 1.0);
        let one = |_: f64, _: f64| 1.0;
        let disc = edge(n, false, |i, j| (i - c).hypot(j - c) < 12.0, one);
        assert!(disc.ellipse_modes(1.0).is_some());
        // Squares along the grid and at 45 degrees, small and large.
        for side in [7.0, 8.0, 10.0, 12.0, 20.0] {
            for half_space in [false, true] {
                let square = edge(
                    n,
                    half_space,
                    |i, j| (i - c).abs() < side / 2.0 && (j - c).abs() < side / 2.0,
                    one,
                );
                assert!(square.ellipse_modes(1.0).is_none(), "{side}");
                let diamond = edge(
                    n,
                    half_space,
                    |i, j| (i - c).abs() + (j - c).abs() < side / 2.0,
                    one,
                );
                assert!(diamond.ellipse_modes(1.0).is_none(), "{side}");
            }
        }
        // A 2:1 rectangle, a disc too small, a face that is not a plane.
        let rectangle = edge(
            n,
            true,
            |i, j| (i - c).abs() < 16.0 && (j - c).abs() < 8.0,
            one,
        );
        assert!(rectangle.ellipse_modes(1.0).is_none());
        let small = edge(n, true, |i, j| (i - c).hypot(j - c) < 3.5, one);
        assert!(small.ellipse_modes(1.0).is_none());
        let curved = EdgeForces {
            face_degree: None,
            ..disc
        };
        assert!(curved.ellipse_modes(1.0).is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: 300,
            rng_seed: proptest::test_runner::RngSeed::Fixed(20261128),
            ..proptest::prelude::ProptestConfig::default()
        })]
        /// Any super-ellipse (from diamonds to near-squares), any size,
        /// orientation and position, any field and face: no fit, or a
        /// finite one.
        #[test]
        fn never_a_nan(exponent in 0.5f64..8.0, aspect in 1.0f64..4.0, size in 1.0f64..30.0,
                       angle in 0.0f64..3.2, ci in 25.0f64..26.0, cj in 25.0f64..26.0,
                       scale in -300.0f64..300.0, quadratic in proptest::bool::ANY,
                       half_space in proptest::bool::ANY) {
            let (s, c) = angle.sin_cos();
            let inside = |i: f64, j: f64| {
                let (y, x) = (i - ci, j - cj);
                let (u, v) = ((c * x + s * y) / (aspect * size), (-s * x + c * y) / size);
                u.abs().powf(exponent) + v.abs().powf(exponent) < 1.0
            };
            let magnitude = 10f64.powf(scale);
            let g = |i: f64, j: f64| magnitude * (1.0 + 0.5 * ((i - ci) * 0.3).sin() * j.cos());
            let forces = EdgeForces {
                face_degree: Some(if quadratic { 2 } else { 1 }),
                ..edge(52, half_space, inside, g)
            };
            if let Some((fitted, functions)) = forces.ellipse_modes(1.0) {
                proptest::prop_assert_eq!(functions, if quadratic { 9 } else { 5 });
                proptest::prop_assert_eq!(fitted.len(), forces.cells.len());
                proptest::prop_assert!(fitted.iter().flatten().all(|v| v.is_finite()));
            }
        }
    }
}
