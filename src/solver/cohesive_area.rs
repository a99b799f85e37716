//! The contact area a cohesive zone's solution reports: the closed cells
//! and the open zone's cells up to the tip of the equivalent crack
//! ([`EQUIVALENT_TIP`]).

/// Where the equivalent crack's tip lies in an open cohesive zone, as a
/// fraction of the zone's length from its closed end: a cohesive solution's
/// contact area ([`Solution::contact_area`](super::Solution::contact_area))
/// counts the closed cells and this fraction of the open cells of the zone
/// around them.
///
/// The zone's tractions `sigma(xi)` over `0 < xi < l` behind the closed
/// edge of a semi-infinite crack load the body, far from the zone, as a
/// traction-free crack whose tip is
/// `Delta = 2 int sigma sqrt(xi) dxi / int sigma / sqrt(xi) dxi` into the
/// zone: the first two terms of the field ahead of a crack whose faces
/// carry tractions (Rice 1968, "Mathematical analysis in the mechanics of
/// fracture", in Liebowitz (ed.), *Fracture* II, 191), with the zone's
/// condition that the stress at the closed edge is finite. That crack is
/// the JKR contact with the zone's force and approach. Dugdale's uniform
/// tension gives `Delta = 2 l / 3`, which Maugis's (1992, J. Colloid
/// Interface Sci. 150, 243) solution approaches as its `lambda` grows
/// (0.650 of `c - a` at `lambda` = 300 and `a_bar` = 3, at equal load);
/// the linear softening of [`CohesiveZone`](super::CohesiveZone)'s law,
/// whose tensions the zone's own opening sets, gives `0.4264 l` (the test
/// below solves the zone's integral equation to five digits).
///
/// Counting the closed cells alone put a sphere's contact radius most of
/// a zone inside JKR's: -4.9 % at the depth of first touch at 64 cells
/// across the pull-off contact, +0.46 % counting the zone so
/// (`tests/cohesive.rs`); `BENCHMARKS.md`, "The cohesive contact's area",
/// has the convergence.
pub const EQUIVALENT_TIP: f64 = 0.4264;

/// The open cells of the zone (out of `contact`, with a tension) joined to
/// a closed cell through open cells of the zone, side by side (across the
/// grid's edges on a periodic grid): cells within the law's range of the
/// indenter but around no contact border no crack and count none.
pub(super) fn open_zone_cells(
    contact: &[bool],
    tension: &[f64],
    cells: (usize, usize),
    periodic: bool,
) -> usize {
    open_zone(contact, tension, cells, periodic)
        .iter()
        .filter(|&&open| open)
        .count()
}

/// Which cells [`open_zone_cells`] counts, as a mask.
pub(super) fn open_zone(
    contact: &[bool],
    tension: &[f64],
    (rows, columns): (usize, usize),
    periodic: bool,
) -> Vec<bool> {
    let n = contact.len();
    debug_assert!(n == rows * columns && tension.len() == n);
    let open = |c: usize| !contact[c] && tension[c] != 0.0;
    let mut seen = vec![false; n];
    // Start from the open cells beside a closed cell; each cell enters the
    // stack at most once, so the walk ends within `n` steps.
    let mut stack: Vec<usize> = Vec::new();
    let visit = |c: usize, seen: &mut Vec<bool>, stack: &mut Vec<usize>| {
        if open(c) && !seen[c] {
            seen[c] = true;
            stack.push(c);
        }
    };
    for c in (0..n).filter(|&c| contact[c]) {
        for m in super::wrapped_neighbours(c, rows, columns, periodic)
            .into_iter()
            .flatten()
        {
            visit(m, &mut seen, &mut stack);
        }
    }
    while let Some(c) = stack.pop() {
        for m in super::wrapped_neighbours(c, rows, columns, periodic)
            .into_iter()
            .flatten()
        {
            visit(m, &mut seen, &mut stack);
        }
    }
    seen
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The tip of the equivalent crack of a zone `0 < t < 1` behind a
    /// semi-infinite crack's closed edge (`E' = 1`, peak tension 1), whose
    /// tension at opening `delta` is `law(delta / delta_c)` with `delta_c`
    /// the opening at the zone's end: the zone's tensions piecewise
    /// constant on `cells` intervals uniform in `s = sqrt(t)`, collocated
    /// at their midpoints. The opening of a crack whose faces carry `p(t)`
    /// is `(4 / pi) int p(t) ln|(sqrt x + sqrt t)/(sqrt x - sqrt t)| dt`
    /// (Tada, Paris & Irwin, *The Stress Analysis of Cracks Handbook*,
    /// 3rd ed., 2000, semi-infinite crack, point loads on its faces), and
    /// `8 K sqrt(x / 2 pi)` under the stress intensity `K`, which the
    /// finite stress at the edge sets to `sqrt(2 / pi) int p / sqrt(t) dt`.
    fn equivalent_tip(cells: usize, law: impl Fn(f64) -> f64) -> f64 {
        // int_{s0}^{s1} 2 s ln|(a + s)/(a - s)| ds.
        let primitive = |s: f64, a: f64| {
            let log = if s == a {
                0.0
            } else {
                ((a + s) / (a - s)).abs().ln()
            };
            (s * s - a * a) * log + 2.0 * a * s
        };
        let edges: Vec<f64> = (0..=cells).map(|k| k as f64 / cells as f64).collect();
        // sqrt(2 / pi) int 1 / sqrt(t) dt over each interval.
        let k_of: Vec<f64> = edges
            .windows(2)
            .map(|e| (2.0 / PI).sqrt() * 2.0 * (e[1] - e[0]))
            .collect();
        // The opening at `x = a^2` per unit tension of each interval.
        let row = |a: f64| -> Vec<f64> {
            edges
                .windows(2)
                .zip(&k_of)
                .map(|(e, k)| {
                    8.0 * k * a / (2.0 * PI).sqrt()
                        - 4.0 / PI * (primitive(e[1], a) - primitive(e[0], a))
                })
                .collect()
        };
        let rows: Vec<Vec<f64>> = edges.windows(2).map(|e| row(0.5 * (e[0] + e[1]))).collect();
        let end = row(1.0);
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let mut sigma = vec![1.0; cells];
        for _ in 0..10_000 {
            let critical = dot(&end, &sigma);
            let next: Vec<f64> = rows
                .iter()
                .map(|r| law((dot(r, &sigma) / critical).clamp(0.0, 1.0)))
                .collect();
            let change = next
                .iter()
                .zip(&sigma)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            for (s, n) in sigma.iter_mut().zip(&next) {
                *s = 0.5 * (*s + n);
            }
            if change < 1e-13 {
                break;
            }
        }
        // 2 int sigma sqrt(t) dt / int sigma / sqrt(t) dt.
        let (mut above, mut below) = (0.0, 0.0);
        for (e, s) in edges.windows(2).zip(&sigma) {
            above += s * 2.0 / 3.0 * (e[1].powi(3) - e[0].powi(3));
            below += s * 2.0 * (e[1] - e[0]);
        }
        2.0 * above / below
    }

    /// Dugdale's zone (uniform tension) has its equivalent tip at exactly
    /// two thirds (the formula's integrals in closed form); the linear
    /// softening law's, converged in the intervals, is the constant to its
    /// four digits.
    #[test]
    fn the_equivalent_tip_of_the_linear_law_is_the_constant() {
        let dugdale = equivalent_tip(50, |_| 1.0);
        assert!((dugdale - 2.0 / 3.0).abs() < 1e-12, "{dugdale}");
        let coarse = equivalent_tip(200, |r| 1.0 - r);
        let fine = equivalent_tip(400, |r| 1.0 - r);
        // 0.426352 at 200 and 400 intervals (0.426352 at 1600 too).
        assert!((coarse - fine).abs() < 1e-6, "{coarse} {fine}");
        assert!((fine - EQUIVALENT_TIP).abs() < 5e-5, "{fine}");
    }

    /// A ring of open cells around a closed one counts; an open patch
    /// apart from any contact does not, and a ring wrapping a periodic
    /// grid's edge counts only when the grid wraps.
    #[test]
    fn only_open_cells_joined_to_a_contact_count() {
        let (rows, columns) = (6, 6);
        let mut contact = vec![false; 36];
        let mut tension = vec![0.0; 36];
        // Closed at (0, 0); open at (0, 1), (1, 0), and (5, 0) across the
        // edge; an open pair apart at (3, 3), (3, 4).
        contact[0] = true;
        for c in [1, 6, 30, 21, 22] {
            tension[c] = -1.0;
        }
        let cells = (rows, columns);
        assert_eq!(open_zone_cells(&contact, &tension, cells, false), 2);
        assert_eq!(open_zone_cells(&contact, &tension, cells, true), 3);
        // Without a closed cell, none.
        contact[0] = false;
        assert_eq!(open_zone_cells(&contact, &tension, cells, true), 0);
    }
}
