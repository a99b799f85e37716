//! The curvature of a contact's edge, read from its cells: the contact's
//! indicator smoothed by a Gaussian, and the divergence of the unit normal
//! of its level sets (`kappa = div n`, `n = -grad chi / |grad chi|`; the
//! level-set curvature of Osher & Sethian 1988, J. Comput. Phys. 79, 12).
//! Positive where the contact is convex (a disc of radius `a`: `1/a`).
//! Out of contact, at the far side of the band where the level sets follow
//! the edge and up to the smoothing's reach, each cell takes the curvature
//! of the nearest cells within the band, so that a cohesive zone that
//! reaches there reads no spurious curvature.

/// Gradients smaller than this (per cell) leave the level sets without a
/// normal: more than about three widths from any edge the smoothed
/// indicator is flat.
const FLAT: f64 = 1e-3;

/// The least gradient (per cell, times the smoothing width) at which the
/// curvature of the level sets is read as the edge's: about 2.3 widths from
/// it, inside the truncated Gaussian's reach of three. Beyond, up to the
/// reach, cells out of contact take the curvature of the nearest cells
/// within (`extend_into`).
const TRUSTED: f64 = 0.03;

/// The edge curvature (per cell) at every cell of a `rows x columns` grid
/// whose contact cells are `contact`, smoothed over `width` cells (the
/// Gaussian's standard deviation), carried outward from the band it is read
/// in ([`TRUSTED`]) to the smoothing's reach; `periodic` wraps the grid,
/// else the contact is zero beyond it.
pub(super) fn edge_curvature(
    contact: &[bool],
    rows: usize,
    columns: usize,
    periodic: bool,
    width: f64,
) -> Vec<f64> {
    let reach = (3.0 * width).ceil() as isize;
    let weights: Vec<f64> = (-reach..=reach)
        .map(|k| (-0.5 * (k as f64 / width).powi(2)).exp())
        .collect();
    let total: f64 = weights.iter().sum();
    let weights: Vec<f64> = weights.iter().map(|w| w / total).collect();
    let at = |i: isize, n: usize| wrap(i, n, periodic);
    // Separable smoothing: along the rows, then along the columns.
    let mut along = vec![0.0; rows * columns];
    for r in 0..rows {
        for c in 0..columns {
            let mut sum = 0.0;
            for (k, w) in weights.iter().enumerate() {
                if let Some(cc) = at(c as isize + k as isize - reach, columns) {
                    if contact[r * columns + cc] {
                        sum += w;
                    }
                }
            }
            along[r * columns + c] = sum;
        }
    }
    let mut smooth = vec![0.0; rows * columns];
    for r in 0..rows {
        for c in 0..columns {
            let mut sum = 0.0;
            for (k, w) in weights.iter().enumerate() {
                if let Some(rr) = at(r as isize + k as isize - reach, rows) {
                    sum += w * along[rr * columns + c];
                }
            }
            smooth[r * columns + c] = sum;
        }
    }
    // Unit normals by central differences, then their divergence.
    let value = |r: isize, c: isize| -> f64 {
        match (at(r, rows), at(c, columns)) {
            (Some(r), Some(c)) => smooth[r * columns + c],
            _ => 0.0,
        }
    };
    let mut normal = vec![(0.0, 0.0); rows * columns];
    let mut trusted = vec![false; rows * columns];
    for r in 0..rows as isize {
        for c in 0..columns as isize {
            let gx = 0.5 * (value(r + 1, c) - value(r - 1, c));
            let gy = 0.5 * (value(r, c + 1) - value(r, c - 1));
            let size = gx.hypot(gy);
            let cell = r as usize * columns + c as usize;
            if size > FLAT {
                normal[cell] = (-gx / size, -gy / size);
                trusted[cell] = size * width >= TRUSTED;
            }
        }
    }
    let component = |r: isize, c: isize, x: bool| -> Option<f64> {
        match (at(r, rows), at(c, columns)) {
            (Some(r), Some(c)) => {
                let n = normal[r * columns + c];
                if n == (0.0, 0.0) {
                    None
                } else if x {
                    Some(n.0)
                } else {
                    Some(n.1)
                }
            }
            _ => None,
        }
    };
    let mut curvature = vec![0.0; rows * columns];
    for r in 0..rows as isize {
        for c in 0..columns as isize {
            let cell = r as usize * columns + c as usize;
            if normal[cell] == (0.0, 0.0) {
                continue;
            }
            let parts = (
                component(r + 1, c, true),
                component(r - 1, c, true),
                component(r, c + 1, false),
                component(r, c - 1, false),
            );
            // A neighbour beyond the normals' reach (or the grid) counts as
            // zero, and its difference reads the reach, not the edge: such
            // a cell is not trusted.
            if [parts.0, parts.1, parts.2, parts.3].contains(&None) {
                trusted[cell] = false;
            }
            let v = |p: Option<f64>| p.unwrap_or(0.0);
            curvature[cell] = 0.5 * (v(parts.0) - v(parts.1)) + 0.5 * (v(parts.2) - v(parts.3));
        }
    }
    // The fringe: cells out of contact whose level sets have a normal but
    // are not trusted.
    let fringe: Vec<bool> = (0..rows * columns)
        .map(|c| !contact[c] && !trusted[c] && normal[c] != (0.0, 0.0))
        .collect();
    extend_into(&mut curvature, &trusted, &fringe, (rows, columns), periodic);
    curvature
}

/// Index `i` along an axis of `n` cells: wrapped on a periodic grid, else
/// `None` beyond it.
fn wrap(i: isize, n: usize, periodic: bool) -> Option<usize> {
    if periodic {
        Some(i.rem_euclid(n as isize) as usize)
    } else {
        (0..n as isize).contains(&i).then_some(i as usize)
    }
}

/// The `fringe` cells take the curvature of the nearest `trusted` cells
/// (the mean over the neighbours reached a layer before, layer by layer
/// outward through the fringe): there, at the far side of the band, the
/// smoothed indicator is nearly flat and its truncated Gaussian's reach
/// ends, so the level sets carry the staircase and the truncation rather
/// than the edge (a disc of 15 cells smoothed over 2: `kappa R` from -10 to
/// 1.5 five to seven cells out), and a cohesive zone that reached there
/// read a law that jumped between its clamps as the contact moved by a
/// cell. Beyond the Gaussian's reach the curvature stays zero, as before:
/// carrying the edge's value on to every cell moved the pull-offs of cases
/// at the method's limits by per cents (a stiff film over a far softer
/// base from +1.69 / +0.48 % to -2.82 / -1.99 % at 8 / 12 cells across,
/// `tests/scene_cohesive.rs`), and tapering it to zero over three widths
/// left `tests/scene_cohesive_soft_below.rs`' plate at 32 cells without
/// convergence. Contact cells keep their own values (dropping their
/// differences to neighbours without a normal stalled Johnson's sinusoid
/// along the grid with a zone of 16 cells, `tests/cohesive.rs`).
fn extend_into(
    curvature: &mut [f64],
    trusted: &[bool],
    fringe: &[bool],
    (rows, columns): (usize, usize),
    periodic: bool,
) {
    let n = rows * columns;
    let mut known: Vec<bool> = trusted.to_vec();
    let mut queued = vec![false; n];
    let mut layer: Vec<usize> = (0..n).filter(|&c| known[c]).collect();
    for (k, f) in curvature.iter_mut().zip(fringe) {
        if *f {
            *k = 0.0;
        }
    }
    let neighbours = |cell: usize| -> [Option<usize>; 4] {
        let (r, c) = ((cell / columns) as isize, (cell % columns) as isize);
        let at = |r: isize, c: isize| {
            Some(wrap(r, rows, periodic)? * columns + wrap(c, columns, periodic)?)
        };
        [at(r + 1, c), at(r - 1, c), at(r, c + 1), at(r, c - 1)]
    };
    // Each layer is new fringe cells only, so at most `n` layers in all.
    while !layer.is_empty() {
        let mut next: Vec<usize> = Vec::new();
        for &cell in &layer {
            for nb in neighbours(cell).into_iter().flatten() {
                if fringe[nb] && !known[nb] && !queued[nb] {
                    queued[nb] = true;
                    next.push(nb);
                }
            }
        }
        let values: Vec<f64> = next
            .iter()
            .map(|&cell| {
                let (sum, count) = neighbours(cell)
                    .into_iter()
                    .flatten()
                    .filter(|&nb| known[nb])
                    .fold((0.0, 0usize), |(s, k), nb| (s + curvature[nb], k + 1));
                sum / count.max(1) as f64
            })
            .collect();
        for (&cell, v) in next.iter().zip(values) {
            curvature[cell] = v;
            known[cell] = true;
        }
        layer = next;
    }
}

#[cfg(test)]
mod tests {
    use super::edge_curvature;

    #[test]
    fn a_digital_disc_has_the_curvature_of_its_circle() {
        // Discs of radius 15 and 30 cells on 128^2, smoothed over 8 cells:
        // the mean over the ring of cells at the edge is 1/R within 1 %
        // (measured 1.009 and 1.003 R), each cell within 6 % (the
        // staircase's facets; standard deviations 1.9 %).
        let n = 128usize;
        for radius in [15.0f64, 30.0] {
            let at = |c: usize| ((c / n) as f64 + 0.5 - 64.0).hypot((c % n) as f64 + 0.5 - 64.0);
            let contact: Vec<bool> = (0..n * n).map(|c| at(c) <= radius).collect();
            let kappa = edge_curvature(&contact, n, n, false, 8.0);
            let ring: Vec<f64> = (0..n * n)
                .filter(|&c| (at(c) - radius).abs() <= 0.5)
                .map(|c| kappa[c] * at(c))
                .collect();
            let mean = ring.iter().sum::<f64>() / ring.len() as f64;
            assert!((mean - 1.0).abs() < 0.01, "{radius}: {mean}");
            assert!(
                ring.iter().all(|k| (k - 1.0).abs() < 0.06),
                "{radius}: {ring:?}"
            );
        }
        // A straight edge (a half-plane, periodic along it): zero.
        let half: Vec<bool> = (0..n * n).map(|c| c / n < 64).collect();
        let flat = edge_curvature(&half, n, n, true, 8.0);
        assert!(flat[64 * n + 10].abs() < 1e-12);
    }

    /// Out of contact beyond the band where the level sets are read
    /// (about 2.3 widths), up to the smoothing's reach, each cell carries
    /// the curvature of the nearest cells within it: a disc off the cell
    /// centres, smoothed over 2 and 4 cells, has `kappa R` in [0, 1.6] on
    /// every cell out of contact, at least 0.2 within the reach (the band's
    /// own 0.26 to 1.48 over 2 cells, 0.55 to 1.16 over 4) and zero a cell
    /// beyond it. Before 2026-12-04 (thirty-fourth session) the truncated
    /// Gaussian's fringe read -10 (over 2 cells, five to seven cells out;
    /// -14 over 4 cells, eleven out): a cohesive zone that reached there
    /// had its law jump between its clamps as the contact moved.
    #[test]
    fn cells_beyond_the_band_carry_the_edge_curvature() {
        let n = 96usize;
        for (radius, width) in [(15.0f64, 2.0), (20.0, 4.0)] {
            let at = |c: usize| ((c / n) as f64 + 0.37 - 48.0).hypot((c % n) as f64 + 0.71 - 48.0);
            let contact: Vec<bool> = (0..n * n).map(|c| at(c) <= radius).collect();
            let kappa = edge_curvature(&contact, n, n, false, width);
            for c in (0..n * n).filter(|&c| !contact[c]) {
                let (read, out) = (kappa[c] * radius, at(c) - radius);
                assert!(
                    (0.0..=1.6).contains(&read),
                    "{radius} {width} {out}: {read}"
                );
                if out <= 3.0 * width - 1.0 {
                    assert!(read >= 0.2, "{radius} {width} {out}: {read}");
                }
                if out > 3.0 * width + 1.5 {
                    assert_eq!(read, 0.0, "{radius} {width} {out}");
                }
            }
        }
    }
}
