//! The indenter's face over a bonded set: a plane, a quadratic, or
//! neither. A bonded face whose heights over an elliptical set are a
//! polynomial of degree `n` is pressed by a polynomial of that degree over
//! `sqrt(1 - f)` (Galin 1953), so its release rate round the edge lies in a
//! span of `4 n + 1` functions (`ellipse_modes.rs`).

use super::ellipse_fit::{centroid, least_squares};
use super::material::ClampedPair;

/// The tolerance of the fits, relative to the largest height or slope.
const ROUNDING: f64 = 1e-9;

/// The degree of the polynomial that the indenter's heights over the set
/// `pair.attached` form, to rounding: 1 (a plane), 2 (a quadratic, on an
/// isolated grid), `None` otherwise.
pub(super) fn degree(
    pair: &ClampedPair,
    rows: usize,
    columns: usize,
    delta: f64,
    periodic: bool,
) -> Option<usize> {
    if planar(pair, rows, columns, delta, periodic) {
        Some(1)
    } else if !periodic && quadratic(pair, columns) {
        Some(2)
    } else {
        None
    }
}

/// Whether the indenter's heights over the set `pair.attached` form a plane:
/// their central differences (where both neighbours are in the set) the
/// same at every cell along each axis, to [`ROUNDING`] of the largest slope
/// or of the heights over a cell.
fn planar(pair: &ClampedPair, rows: usize, columns: usize, delta: f64, periodic: bool) -> bool {
    let mut ranges = [[f64::INFINITY, f64::NEG_INFINITY]; 2];
    let mut largest = 0.0f64;
    for (c, _) in pair.attached.iter().enumerate().filter(|(_, on)| **on) {
        let height = pair.profile[c] - pair.lowest;
        if !height.is_finite() {
            return false;
        }
        largest = largest.max(height.abs());
        let [up, down, left, right] = super::periodic::neighbours(c, rows, columns, periodic);
        for (axis, pair_of) in [[up, down], [left, right]].iter().enumerate() {
            if let [Some(b), Some(f)] = *pair_of {
                if pair.attached[b] && pair.attached[f] {
                    let slope = (pair.profile[f] - pair.profile[b]) / (2.0 * delta);
                    ranges[axis][0] = ranges[axis][0].min(slope);
                    ranges[axis][1] = ranges[axis][1].max(slope);
                }
            }
        }
    }
    let steepest = ranges
        .iter()
        .flatten()
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let tolerance = ROUNDING * steepest.max(largest / delta);
    ranges
        .iter()
        .all(|[lo, hi]| !lo.is_finite() || hi - lo <= tolerance)
}

/// Whether the indenter's heights over the set `pair.attached` (on a grid
/// of `columns` columns, not wrapping round) are a quadratic in position:
/// the least-squares quadratic through them off by at most [`ROUNDING`] of
/// the largest height at every cell.
fn quadratic(pair: &ClampedPair, columns: usize) -> bool {
    let cells: Vec<usize> = (0..pair.attached.len())
        .filter(|&c| pair.attached[c])
        .collect();
    let heights: Vec<f64> = cells
        .iter()
        .map(|&c| pair.profile[c] - pair.lowest)
        .collect();
    if cells.len() < 6 || heights.iter().any(|h| !h.is_finite()) {
        return false;
    }
    let points: Vec<[f64; 2]> = cells
        .iter()
        .map(|&c| [(c / columns) as f64, (c % columns) as f64])
        .collect();
    let Some((mean, spread)) = centroid(&points) else {
        return false;
    };
    let basis = |p: &[f64; 2]| {
        let (u, v) = ((p[0] - mean[0]) / spread, (p[1] - mean[1]) / spread);
        [1.0, u, v, u * u, u * v, v * v]
    };
    let Some(fitted) = least_squares(points.iter().zip(&heights).map(|(p, &h)| (basis(p), h)))
    else {
        return false;
    };
    let largest = heights.iter().fold(0.0f64, |m, h| m.max(h.abs()));
    points.iter().zip(&heights).all(|(p, &h)| {
        let value: f64 = basis(p).iter().zip(&fitted).map(|(b, g)| b * g).sum();
        (value - h).abs() <= ROUNDING * largest
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The degree of the face `height(i, j)` over the disc of radius 12
    /// cells on a 40 x 40 grid.
    fn degree_of(height: impl Fn(f64, f64) -> f64) -> Option<usize> {
        let n = 40;
        let c = 19.3;
        let attached: Vec<bool> = (0..n * n)
            .map(|k| ((k / n) as f64 - c).hypot((k % n) as f64 - c) < 12.0)
            .collect();
        let profile: Vec<f64> = (0..n * n)
            .map(|k| height((k / n) as f64, (k % n) as f64))
            .collect();
        let zero = vec![0.0; n * n];
        let pair = ClampedPair {
            attached: &attached,
            profile: &profile,
            lowest: profile.iter().copied().fold(f64::INFINITY, f64::min),
            punch: &zero,
            punch_displacement: &zero,
            shape: &zero,
            shape_displacement: &zero,
        };
        degree(&pair, n, n, 1e-5, false)
    }

    #[test]
    fn planes_and_quadratics_are_told_from_other_faces() {
        // Heights in metres on cells of 10 um: a tilted plane, a
        // paraboloid of radius 10 mm moved off the grid's centre and tilted,
        // an exact spherical cap of that radius (off a paraboloid by r^4 /
        // 8 R^3, 5e-5 of the heights 15 cells from its apex), a cone.
        let d = 1e-5;
        assert_eq!(degree_of(|i, j| 3e-3 * i * d - 1e-3 * j * d), Some(1));
        let paraboloid = |i: f64, j: f64| {
            let (x, y) = ((i - 17.2) * d, (j - 21.9) * d);
            (x * x + y * y) / 2e-2 + 1e-3 * x
        };
        assert_eq!(degree_of(paraboloid), Some(2));
        let cap = |i: f64, j: f64| {
            let (x, y) = ((i - 17.2) * d, (j - 21.9) * d);
            1e-2 - (1e-4 - x * x - y * y).sqrt()
        };
        assert_eq!(degree_of(cap), None);
        assert_eq!(degree_of(|i, j| 0.1 * d * (i - 19.0).hypot(j - 19.0)), None);
        assert_eq!(degree_of(|_, _| f64::INFINITY), None);
    }
}
