//! A preconditioner of the cohesive zone's fixed point: the change a round
//! asks of the zone's tensions, amplified along the edge.
//!
//! The fixed point `t = sigma(g(t))` contracts slowest on the zone's long
//! modes along the edge (a change of one sign over many cells of the edge,
//! across the zone's width): the Jacobian `J = sigma' S_Z` (`S_Z` the
//! zone's compliance with the contact held) is largest there, and the
//! spectrum of `I - J` spans `[1 - mu, 1]` with `mu` 0.7 to 0.9
//! (`benches/adhesion/zone_schur.py`). The round's residual
//! `r = sigma(g) - t` is taken as `(I + alpha W) r` instead, `W = D^-1/2 G D^-1/2` a
//! Gaussian smoothing of radius `rho` over the zone's cells (`G` the
//! Gaussian's weights between them, `D` its row sums; `W` is symmetric,
//! its largest eigenvalue 1, on the smooth modes), which lifts the long
//! modes by up to `1 + alpha` and leaves the short ones. The mixing, a
//! Krylov method, contracts by about `(sqrt(kappa) - 1) / (sqrt(kappa) +
//! 1)` a round on a spectrum of condition number `kappa`: in the model of
//! the map (`benches/adhesion/zone_smoothing.py`: discs of 16 and 32 cells'
//! radius, rings of 4 and 5 cells, the law of 4 cells) `alpha = 2`, `rho =
//! 4` cells bring `kappa` from 3.05-3.31 to 1.87-1.92 (rings of 4) and from
//! 7.85-9.66 to 3.86-4.61 (rings of 5). Measured on the tilted
//! paraboloid's cycle (`examples/adhesive_cycle_cost`, `BENCHMARKS.md`,
//! "Adhesive scene cycles: error and cost"): 20 to 31 % fewer CG
//! iterations at 16 to 64 cells across.
//!
//! Applied per 4-connected component of the zone of at least
//! [`MIN_COMPONENT_CELLS`] cells (a rough contact's small patches have no
//! long modes along their edges, and smoothing across neighbouring patches
//! cost iterations there), by a scatter along the rows and a gather along
//! the columns over the component's cells (wrapped round a periodic grid).

use super::patch_width::Patches;

/// The amplification `alpha` of the smoothed residual (1, 2 and 4 measured
/// in the model above; 1.5, 2 and 3 on the cycle: 2 the best or within 1 %
/// of it).
pub(super) const SMOOTHING_GAIN: f64 = 2.0;

/// The Gaussian's radius `rho`, cells (`exp(-d^2 / rho^2)`, cut at `3
/// rho` along each axis).
pub(super) const SMOOTHING_RADIUS: f64 = 4.0;

/// The fewest cells of a zone's component that is preconditioned: about
/// the zone round a contact 8 cells across. On the rough film's cycle at
/// 64^2 (`examples/rough_cohesive_cycle`) every component preconditioned
/// took 17109 CG iterations against 13693 without the preconditioner; from
/// 50, 100, 200 and 400 cells, 12865, 12660, 13447 and 13508.
pub(super) const MIN_COMPONENT_CELLS: usize = 100;

/// The zone's grid and the smoothing's weights.
pub(super) struct ZoneSmoothing {
    rows: usize,
    columns: usize,
    periodic: bool,
    /// The Gaussian's taps `exp(-k^2 / rho^2)`, `k = -reach..=reach`, along
    /// the rows and along the columns (a periodic axis narrower than the
    /// kernel cuts it at half its period, so that no cell is visited twice).
    along_taps: Vec<f64>,
    down_taps: Vec<f64>,
    /// The zone's cells.
    cells: Vec<usize>,
    /// Per zone cell, `D^-1/2`, the scaled residual `D^-1/2 r` and its
    /// smoothing `G D^-1/2 r`.
    scale: Vec<f64>,
    residual: Vec<f64>,
    smoothed: Vec<f64>,
    /// The pass along the rows, of the grid's size, zero between uses.
    along: Vec<f64>,
    /// The zone's 4-connected components.
    components: Patches,
}

impl ZoneSmoothing {
    pub(super) fn new(rows: usize, columns: usize, periodic: bool) -> Self {
        let reach = (3.0 * SMOOTHING_RADIUS).ceil() as usize;
        let taps = |cells: usize| -> Vec<f64> {
            let r = if periodic {
                reach.min(cells.saturating_sub(1) / 2)
            } else {
                reach
            };
            (0..=2 * r)
                .map(|k| {
                    let d = k.abs_diff(r) as f64;
                    (-d * d / (SMOOTHING_RADIUS * SMOOTHING_RADIUS)).exp()
                })
                .collect()
        };
        ZoneSmoothing {
            rows,
            columns,
            periodic,
            along_taps: taps(columns),
            down_taps: taps(rows),
            cells: Vec::new(),
            scale: Vec::new(),
            residual: Vec::new(),
            smoothed: Vec::new(),
            along: Vec::new(),
            components: Patches::default(),
        }
    }

    /// `target = mapped + alpha W (mapped - tension)` on the zone (`zone`
    /// true: open cells the law pulls), `mapped` elsewhere.
    pub(super) fn precondition(
        &mut self,
        zone: &[bool],
        mapped: &[f64],
        tension: &[f64],
        target: &mut [f64],
    ) {
        target.copy_from_slice(mapped);
        self.along.resize(zone.len(), 0.0);
        self.components
            .find(zone, (self.rows, self.columns), self.periodic, usize::MAX);
        let mut start = 0;
        for k in 0..self.components.ends.len() {
            let end = self.components.ends[k];
            if end - start >= MIN_COMPONENT_CELLS {
                self.cells.clear();
                self.cells
                    .extend_from_slice(&self.components.order[start..end]);
                self.precondition_cells(mapped, tension, target);
            }
            start = end;
        }
    }

    /// The preconditioner on the component in `cells`.
    fn precondition_cells(&mut self, mapped: &[f64], tension: &[f64], target: &mut [f64]) {
        // D: the Gaussian's sums over the zone, on the zone.
        let mut values = std::mem::take(&mut self.scale);
        values.clear();
        values.resize(self.cells.len(), 1.0);
        let mut sums = std::mem::take(&mut self.residual);
        sums.clear();
        sums.resize(self.cells.len(), 0.0);
        self.gaussian(&values, &mut sums);
        // D^-1/2 r on the zone.
        for ((v, s), &c) in values.iter_mut().zip(&mut sums).zip(&self.cells) {
            *s = if *s > 0.0 { 1.0 / s.sqrt() } else { 0.0 };
            *v = *s * (mapped[c] - tension[c]);
        }
        let mut smoothed = std::mem::take(&mut self.smoothed);
        smoothed.clear();
        smoothed.resize(self.cells.len(), 0.0);
        self.gaussian(&values, &mut smoothed);
        for ((w, s), &c) in smoothed.iter().zip(&sums).zip(&self.cells) {
            target[c] += SMOOTHING_GAIN * s * w;
        }
        (self.scale, self.residual, self.smoothed) = (values, sums, smoothed);
    }

    /// Neighbour `k` cells along an axis of `period` cells from `i`, if on
    /// the grid (wrapping round when periodic).
    fn shift(&self, i: usize, k: isize, period: usize) -> Option<usize> {
        let m = i as isize + k;
        if self.periodic {
            Some(m.rem_euclid(period as isize) as usize)
        } else {
            (0..period as isize).contains(&m).then_some(m as usize)
        }
    }

    /// `out = G x` on the zone's cells (`x` one value per zone cell): `x`
    /// scattered along the rows, then gathered along the columns, the
    /// rows' pass cleared after it.
    fn gaussian(&mut self, x: &[f64], out: &mut [f64]) {
        let (rows, columns) = (self.rows, self.columns);
        let (along_taps, down_taps) = (&self.along_taps, &self.down_taps);
        let (rc, rr) = (along_taps.len() / 2, down_taps.len() / 2);
        let mut along = std::mem::take(&mut self.along);
        for (&c, &v) in self.cells.iter().zip(x) {
            let (i, j) = (c / columns, c % columns);
            let row = &mut along[i * columns..(i + 1) * columns];
            if j >= rc && j + rc < columns {
                for (a, w) in row[j - rc..=j + rc].iter_mut().zip(along_taps) {
                    *a += w * v;
                }
            } else {
                for (k, w) in along_taps.iter().enumerate() {
                    if let Some(m) = self.shift(j, k as isize - rc as isize, columns) {
                        row[m] += w * v;
                    }
                }
            }
        }
        for (&c, o) in self.cells.iter().zip(out.iter_mut()) {
            let (i, j) = (c / columns, c % columns);
            *o = if i >= rr && i + rr < rows {
                along[(i - rr) * columns + j..]
                    .iter()
                    .step_by(columns)
                    .zip(down_taps)
                    .map(|(a, w)| a * w)
                    .sum()
            } else {
                down_taps
                    .iter()
                    .enumerate()
                    .filter_map(|(k, w)| {
                        let m = self.shift(i, k as isize - rr as isize, rows)?;
                        Some(w * along[m * columns + j])
                    })
                    .sum()
            };
        }
        for &c in &self.cells {
            let (i, j) = (c / columns, c % columns);
            let row = &mut along[i * columns..(i + 1) * columns];
            if j >= rc && j + rc < columns {
                row[j - rc..=j + rc].fill(0.0);
            } else {
                row.fill(0.0);
            }
        }
        self.along = along;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `mapped + alpha D^-1/2 G D^-1/2 (mapped - tension)` by direct sums
    /// over the pairs of `cells` (one component), `G` the Gaussian cut at
    /// `reach` cells along each axis (nearest images when periodic).
    fn dense(
        grid: (usize, usize, bool),
        cells: &[usize],
        mapped: &[f64],
        tension: &[f64],
    ) -> Vec<f64> {
        let (rows, columns, periodic) = grid;
        let reach = (3.0 * SMOOTHING_RADIUS).ceil() as isize;
        let offset = |a: usize, b: usize, period: usize| -> isize {
            let d = b as isize - a as isize;
            if periodic {
                let p = period as isize;
                let d = d.rem_euclid(p);
                if d > p / 2 {
                    d - p
                } else {
                    d
                }
            } else {
                d
            }
        };
        let limit = |period: usize| {
            if periodic {
                reach.min((period as isize - 1) / 2)
            } else {
                reach
            }
        };
        let weight = |a: usize, b: usize| {
            let di = offset(a / columns, b / columns, rows);
            let dj = offset(a % columns, b % columns, columns);
            if di.abs() > limit(rows) || dj.abs() > limit(columns) {
                0.0
            } else {
                (-((di * di + dj * dj) as f64) / (SMOOTHING_RADIUS * SMOOTHING_RADIUS)).exp()
            }
        };
        let sums: Vec<f64> = cells
            .iter()
            .map(|&a| cells.iter().map(|&b| weight(a, b)).sum())
            .collect();
        let mut target = mapped.to_vec();
        for (&a, &da) in cells.iter().zip(&sums) {
            let s: f64 = cells
                .iter()
                .zip(&sums)
                .map(|(&b, &db)| weight(a, b) * (mapped[b] - tension[b]) / db.sqrt())
                .sum();
            target[a] += SMOOTHING_GAIN * s / da.sqrt();
        }
        target
    }

    /// A ring of zone cells (radii 9 to 13 cells about a point off the
    /// cell centres, about 600 cells) and a blob of 3 x 3 cells apart from
    /// it, on isolated and periodic grids (the periodic one narrower than
    /// the Gaussian's reach, so that it wraps): the ring's preconditioned
    /// values equal the direct sums to rounding, the blob (a component
    /// under `MIN_COMPONENT_CELLS`) and the cells off the zone keep
    /// `mapped`.
    #[test]
    fn the_preconditioner_is_the_direct_sum_on_each_large_component() {
        for (rows, columns, periodic) in [(40, 36, false), (30, 29, true)] {
            let n = rows * columns;
            let centre = (14.3, 14.6);
            let mut zone = vec![false; n];
            for (c, z) in zone.iter_mut().enumerate() {
                let (i, j) = ((c / columns) as f64, (c % columns) as f64);
                let r = (i - centre.0).hypot(j - centre.1);
                *z = (9.0..13.0).contains(&r);
            }
            let ring: Vec<usize> = (0..n).filter(|&c| zone[c]).collect();
            assert!(ring.len() >= MIN_COMPONENT_CELLS, "{}", ring.len());
            // The blob, in a corner away from the ring.
            let blob: Vec<usize> = (0..3)
                .flat_map(|i| (0..3).map(move |j| (rows - 3 + i) * columns + columns - 4 + j))
                .collect();
            for &c in &blob {
                assert!(!zone[c]);
                zone[c] = true;
            }
            // Seeded values: a smooth part and a rough one.
            let mapped: Vec<f64> = (0..n)
                .map(|c| -1.0 - 0.3 * (c as f64 * 0.37).sin())
                .collect();
            let tension: Vec<f64> = (0..n)
                .map(|c| {
                    mapped[c] + 0.1 * (c as f64 * 0.11).cos() + 0.05 * ((c * 7919) % 13) as f64
                })
                .collect();
            let mut target = vec![0.0; n];
            let mut smoothing = ZoneSmoothing::new(rows, columns, periodic);
            smoothing.precondition(&zone, &mapped, &tension, &mut target);
            let expected = dense((rows, columns, periodic), &ring, &mapped, &tension);
            for c in 0..n {
                let scale = (expected[c] - mapped[c]).abs().max(1e-3);
                assert!(
                    (target[c] - expected[c]).abs() <= 1e-12 * scale,
                    "cell {c}: {} against {}",
                    target[c],
                    expected[c]
                );
            }
            for &c in &blob {
                assert_eq!(target[c], mapped[c]);
            }
            // The ring's values did move (the test can fail).
            assert!(ring.iter().any(|&c| (target[c] - mapped[c]).abs() > 1e-3));
        }
    }
}
