//! The coarse space of the two-level preconditioner
//! ([`balancing`](super::balancing)): the working set's cells of each `b x
//! b` block of the grid, one coarse unknown a block, and its coarse matrix
//! `E~ ~ Z^T A Z` (`Z` the blocks' indicators on the set, `A` the
//! compliance) built from a coarse grid:
//!
//! ```text
//! E~_IJ = n_I n_J Kb(I - J) / b^4      (I != J)
//! E~_II = sum_{i, j in I} K_ij          (each block's own pairs, exact)
//! ```
//!
//! with `n_I` the set's cells in block `I` and `Kb` the compliance between
//! two whole blocks (the response to one block's uniform load summed over
//! each block: one convolution once per solver). Far blocks see each other
//! through a smooth kernel, so their entries need only the counts; a
//! block's own pairs do not (its cells may be one patch or scattered
//! specks). Measured in the numpy model (`benches/rough/coarse_balancing.py`,
//! `BENCHMARKS.md`, "A coarse matrix from a coarse grid"): entries within
//! 10 % of the exact matrix's largest, the linear phase's iterations flat in
//! N. `E~ v` is one convolution on the grid of blocks (zero-padded to twice
//! its size on an isolated grid) and a diagonal; `E~ c = f` is solved by
//! Jacobi-preconditioned conjugate gradients.

use std::ops::Range;

use crate::error::{Error, Result};
use crate::kernel::EvenConvolution;

/// The relative residual to which the coarse systems are solved. The
/// outer conjugate gradients assume a fixed linear preconditioner, but a
/// loose coarse solve barely moves it: the rough film and the tamaas
/// problem of `examples/rough_benchmark.rs` at 2048^2 took the same outer
/// iterations (20 and 24) with the coarse solves to `1e-6`, `1e-3`, `1e-2`
/// and `1e-1`, and 23 and 89 to `0.3` (2026-12-04, thirty-sixth session);
/// `1e-3` stays a factor of a hundred below the loosest that kept them,
/// and took 0.9 times the outer iteration's time of `1e-6` at 2048^2.
const COARSE_TOLERANCE: f64 = 1e-3;

/// The most inner iterations of a coarse solve (it stops there, inexact):
/// Jacobi-preconditioned conjugate gradients on the blocks took 9 and 16
/// on average (to `1e-3`) on the rough film and the tamaas problem of
/// `examples/rough_benchmark.rs` at 1024^2, and 20 at 1024^2 and 63 to 80
/// at 2048^2 on its coated stack over a soft base, whose coarse matrix is
/// ill-conditioned (2026-12-04, thirty-sixth session; more than 100 to
/// `1e-6` there).
const COARSE_ITERATIONS: usize = 200;

/// `out = E~ v`: `n_I (Kb * (n v))_I / b^4` plus each block's own pairs
/// less what that term gave them; `pair` is `Kb(0) / b^4` and `b`.
fn product(
    convolution: &mut EvenConvolution,
    states: &[BlockState],
    (mean_pair, side): (f64, usize),
    v: &[f64],
    out: &mut [f64],
    weighted: &mut [f64],
) -> Result<()> {
    for ((w, v), state) in weighted.iter_mut().zip(v).zip(states) {
        *w = v * state.count;
    }
    convolution.apply(weighted, out)?;
    let far = 1.0 / (side as f64).powi(4);
    for ((out, v), state) in out.iter_mut().zip(v).zip(states) {
        let n = state.count;
        let own = state.own - n * n * mean_pair;
        *out = n * *out * far + own * v;
    }
    Ok(())
}

/// `sum_{a, c} k(c - a)` over a block's member cells (offsets within the
/// block), `near` the kernel on `(2 side - 1)^2` offsets: each pair once
/// (`k` is even), in four independent sums.
fn own_pairs(near: &[f64], side: usize, members: &[(usize, usize)]) -> f64 {
    let width = 2 * side - 1;
    let centre = (side - 1) * (width + 1);
    let mut sum = 0.5 * near[centre] * members.len() as f64;
    for (a, &(ai, aj)) in members.iter().enumerate() {
        let row = &near[centre - ai * width - aj..];
        let mut lanes = [0.0; 4];
        let mut chunks = members[a + 1..].chunks_exact(4);
        for chunk in &mut chunks {
            for (lane, &(ci, cj)) in lanes.iter_mut().zip(chunk) {
                *lane += row[ci * width + cj];
            }
        }
        for &(ci, cj) in chunks.remainder() {
            lanes[0] += row[ci * width + cj];
        }
        sum += (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
    }
    2.0 * sum
}

/// `k(di, dj)`, the compliance between cells `(di, dj)` apart for `|di|,
/// |dj| < side`, on `(2 side - 1)^2` offsets, from the response `point` to
/// a unit load on cell `(0, 0)` of a grid of `(rows, columns)` cells (on an
/// isolated grid read at non-negative offsets and mirrored). `point` holds
/// the grid rows `local` (all of them when serial); the offsets whose row
/// lies elsewhere are left zero (on a split solver the ranks' parts add
/// up to the whole).
pub(super) fn near_kernel(
    point: &[f64],
    side: usize,
    (rows, columns): (usize, usize),
    local: &Range<usize>,
    periodic: bool,
) -> Vec<f64> {
    let width = 2 * side - 1;
    let reach = side as isize - 1;
    let mut near = vec![0.0; width * width];
    for di in -reach..=reach {
        for dj in -reach..=reach {
            let (i, j) = if periodic {
                (
                    di.rem_euclid(rows as isize) as usize,
                    dj.rem_euclid(columns as isize) as usize,
                )
            } else {
                (di.unsigned_abs(), dj.unsigned_abs())
            };
            if local.contains(&i) {
                near[(di + reach) as usize * width + (dj + reach) as usize] =
                    point[(i - local.start) * columns + j];
            }
        }
    }
    near
}

/// A block's part of the working set: a signature of its member cells
/// (count, sum and sum of squares of their indices; its pairs are summed
/// again only when it changes), their count and their own pairs' sum.
#[derive(Clone, Copy, Default)]
struct BlockState {
    signature: (u64, u64, u64),
    count: f64,
    own: f64,
}

/// The coarse space of one grid and its coarse matrix for the current
/// working set.
pub(super) struct CoarseSpace {
    /// The block's side `b`, cells.
    side: usize,
    /// The grid's rows and columns.
    rows: usize,
    columns: usize,
    /// The grid rows this process holds (all of them when serial; on a
    /// split solver whole rows of blocks,
    /// [`ContactSolver::ranks_hold_whole_blocks`](super::ContactSolver::ranks_hold_whole_blocks)).
    local: Range<usize>,
    /// Blocks each way (the last ones partial on an isolated grid whose
    /// sides `b` does not divide).
    blocks: (usize, usize),
    /// `k(di, dj) = K` between cells `(di, dj)` apart, `|di|, |dj| < b`.
    near: Vec<f64>,
    /// `Kb(0) / b^4`: the far formula's own-block entry per pair of cells.
    mean_pair: f64,
    convolution: EvenConvolution,
    /// Each block's part of the working set (`n_I` and `E~_II`).
    states: Vec<BlockState>,
    /// The coarse solve's vectors (one value a block).
    scratch: [Vec<f64>; 6],
}

impl CoarseSpace {
    /// The coarse space of blocks of `side` cells on a grid of `cells`
    /// (rows, columns), of which this process holds the rows `local`, from
    /// the kernel `near` between cells less than a block apart
    /// ([`near_kernel`], whole) and the compliance's response `block` to a
    /// unit load on each cell of the block at the origin (its rows
    /// `local`); `sum` adds a vector over the ranks of a split solver (the
    /// identity when serial).
    ///
    /// # Errors
    /// [`Error::Internal`] if the kernel or the response is not finite.
    pub(super) fn new(
        side: usize,
        cells: (usize, usize),
        local: Range<usize>,
        periodic: bool,
        near: Vec<f64>,
        block: &[f64],
        sum: &dyn Fn(&mut [f64]),
    ) -> Result<Self> {
        let (rows, columns) = cells;
        // Any rank's values not finite stops every rank's build.
        let mut not_finite = [f64::from(u8::from(
            !near.iter().chain(block).all(|v| v.is_finite()),
        ))];
        sum(&mut not_finite);
        if not_finite[0] > 0.0 {
            return Err(Error::Internal {
                what: "two-level preconditioner",
                detail: "the compliance's response to a block is not finite".into(),
            });
        }
        let blocks = (rows.div_ceil(side), columns.div_ceil(side));
        let m = blocks.0 * blocks.1;
        let (mut kb, mut cells_in) = (vec![0.0; m], vec![0.0; m]);
        for i in 0..rows {
            for j in 0..columns {
                let k = (i / side) * blocks.1 + j / side;
                if local.contains(&i) {
                    kb[k] += block[(i - local.start) * columns + j];
                }
                cells_in[k] += 1.0;
            }
        }
        sum(&mut kb);
        // A partial block's sum scaled to a whole block's.
        let whole = (side * side) as f64;
        for (k, n) in kb.iter_mut().zip(&cells_in) {
            *k *= whole / n;
        }
        Ok(CoarseSpace {
            side,
            rows,
            columns,
            local,
            blocks,
            near,
            mean_pair: kb[0] / (whole * whole),
            convolution: EvenConvolution::new(&kb, blocks.0, blocks.1, periodic)?,
            states: vec![BlockState::default(); m],
            scratch: std::array::from_fn(|_| vec![0.0; m]),
        })
    }

    /// The block's side, cells.
    pub(super) fn side(&self) -> usize {
        self.side
    }

    /// The number of blocks.
    pub(super) fn len(&self) -> usize {
        self.states.len()
    }

    /// Row `i`'s runs of cells in one block: `(block, columns)`, `columns`
    /// a range of the row's columns (`i` counted from this process's first
    /// row).
    pub(super) fn row_runs(&self, i: usize) -> impl Iterator<Item = (usize, Range<usize>)> {
        let (side, columns) = (self.side, self.columns);
        let row = ((self.local.start + i) / side) * self.blocks.1;
        (0..columns)
            .step_by(side)
            .enumerate()
            .map(move |(b, j)| (row + b, j..(j + side).min(columns)))
    }

    /// Row `i`'s part of each block's sum of `value(j)` over the row's
    /// columns `j` in `member` (the row's cells of the working set), in the
    /// order of [`Self::row_runs`].
    pub(super) fn row_sums(
        &self,
        i: usize,
        member: &[bool],
        value: impl Fn(usize) -> f64,
    ) -> Vec<f64> {
        self.row_runs(i)
            .map(|(_, range)| range.filter(|j| member[*j]).map(&value).sum())
            .collect()
    }

    /// `sums[block] = sum` of each row's part of each block's sum
    /// (`parts[i]`: row `i`'s values in the order of [`Self::row_runs`]).
    pub(super) fn gather(&self, parts: &[Vec<f64>], sums: &mut [f64]) {
        sums.fill(0.0);
        for (i, part) in parts.iter().enumerate() {
            for ((block, _), sum) in self.row_runs(i).zip(part) {
                sums[block] += sum;
            }
        }
    }

    /// `out = E~ v` (with scratch of its own).
    #[cfg(test)]
    fn product(&mut self, v: &[f64], out: &mut [f64]) -> Result<()> {
        let mut weighted = vec![0.0; v.len()];
        let pair = (self.mean_pair, self.side);
        product(
            &mut self.convolution,
            &self.states,
            pair,
            v,
            out,
            &mut weighted,
        )
    }

    /// Counts and own pairs for the working set `working` (this process's
    /// rows; the pairs of the blocks whose set changed); on a split solver
    /// the other ranks' blocks from them (`sum` adds a vector over the
    /// ranks: two values a block).
    pub(super) fn update(&mut self, working: &[bool], sum: &dyn Fn(&mut [f64])) {
        let (side, columns, rows) = (self.side, self.columns, self.rows);
        let (near, per_row) = (&self.near, self.blocks.1);
        let first = self.local.start;
        // This process's block rows (whole: `ContactSolver::ranks_hold_whole_blocks`).
        let own_blocks = first / side * per_row..self.local.end.div_ceil(side) * per_row;
        // Block rows on every thread; each block's own cells and sums.
        crate::parallel::for_each_row_with(
            &mut self.states[own_blocks.clone()],
            per_row,
            || Vec::with_capacity(side * side),
            |members: &mut Vec<(usize, usize)>, block_row, states| {
                for (block_column, state) in states.iter_mut().enumerate() {
                    let (bi, bj) = (first + block_row * side, block_column * side);
                    members.clear();
                    let mut signature = (0u64, 0u64);
                    for i in bi..(bi + side).min(rows) {
                        for j in bj..(bj + side).min(columns) {
                            if working[(i - first) * columns + j] {
                                members.push((i - bi, j - bj));
                                let c = (i * columns + j) as u64;
                                signature = (
                                    signature.0.wrapping_add(c),
                                    signature.1.wrapping_add(c.wrapping_mul(c)),
                                );
                            }
                        }
                    }
                    let signature = (members.len() as u64, signature.0, signature.1);
                    if signature != state.signature {
                        *state = BlockState {
                            signature,
                            count: members.len() as f64,
                            own: own_pairs(near, side, members),
                        };
                    }
                }
            },
        );
        if self.local.len() < rows {
            // Every rank's blocks: this rank's counts and pairs, zero
            // elsewhere, added up.
            let m = self.states.len();
            let mut shared = vec![0.0; 2 * m];
            for k in own_blocks.clone() {
                (shared[k], shared[m + k]) = (self.states[k].count, self.states[k].own);
            }
            sum(&mut shared);
            for (k, state) in self.states.iter_mut().enumerate() {
                if !own_blocks.contains(&k) {
                    (state.count, state.own) = (shared[k], shared[m + k]);
                }
            }
        }
    }

    /// `E~^-1 f` into `f`, by Jacobi-preconditioned conjugate gradients to
    /// [`COARSE_TOLERANCE`] (at most [`COARSE_ITERATIONS`]; blocks without
    /// members keep zero).
    ///
    /// # Errors
    /// [`Error::Internal`] if an FFT fails.
    pub(super) fn solve(&mut self, f: &mut [f64]) -> Result<()> {
        let CoarseSpace {
            mean_pair,
            convolution,
            states,
            scratch,
            side,
            ..
        } = self;
        let [x, r, z, d, ad, weighted] = scratch;
        let mut apply = |v: &[f64], out: &mut [f64]| {
            product(convolution, states, (*mean_pair, *side), v, out, weighted)
        };
        let jacobi = |r: &[f64], z: &mut [f64]| {
            for ((z, r), state) in z.iter_mut().zip(r).zip(states.iter()) {
                *z = if state.own > 0.0 { r / state.own } else { 0.0 };
            }
        };
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(a, b)| a * b).sum::<f64>();
        r.copy_from_slice(f);
        x.fill(0.0);
        let norm = dot(r, r).sqrt();
        if norm > 0.0 && norm.is_finite() {
            jacobi(r, z);
            d.copy_from_slice(z);
            let mut rz = dot(r, z);
            for _ in 0..COARSE_ITERATIONS {
                apply(d, ad)?;
                let dad = dot(d, ad);
                if !(dad > 0.0 && dad.is_finite() && rz > 0.0) {
                    break;
                }
                let alpha = rz / dad;
                for k in 0..x.len() {
                    x[k] += alpha * d[k];
                    r[k] -= alpha * ad[k];
                }
                if dot(r, r).sqrt() <= COARSE_TOLERANCE * norm {
                    break;
                }
                jacobi(r, z);
                let rz_new = dot(r, z);
                let beta = rz_new / rz;
                rz = rz_new;
                for k in 0..d.len() {
                    d[k] = z[k] + beta * d[k];
                }
            }
        }
        f.copy_from_slice(x);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use rand_chacha::rand_core::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    use super::{near_kernel, CoarseSpace};
    use crate::kernel::ComplianceOperator;
    use crate::{Boundary, Grid, Material, Substrate};

    /// `E~ v` (a convolution on the padded grid of blocks and a diagonal
    /// from four-lane pair sums) against the same matrix summed densely:
    /// every far entry from the compliance's response to that block's
    /// uniform load (no mirror, no padding), every block's own pairs from
    /// the response to each member cell. On a film, isolated (32 x 28
    /// cells) and periodic (32 x 24), blocks of 4, over a seeded set of
    /// about 40 % of the cells. Agreement within 1e-12 of the largest
    /// entry (the FFTs' rounding; the grid of blocks padded by one block
    /// instead of doubled puts them 6.1e-3 of it apart).
    #[test]
    fn coarse_matrix_matches_dense_sums() {
        let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.45).unwrap(), 2e-5).unwrap();
        for (rows, columns, boundary) in
            [(32, 28, Boundary::Isolated), (32, 24, Boundary::Periodic)]
        {
            let grid = Grid::new(rows, columns, 1e-5).unwrap();
            let mut operator = ComplianceOperator::new(&film, &grid, boundary).unwrap();
            let (side, n) = (4, rows * columns);
            let (nb0, nb1) = (rows / side, columns / side);
            let m = nb0 * nb1;
            let mut response = |cells: &[usize]| {
                let mut field = vec![0.0; n];
                for c in cells {
                    field[*c] = 1.0;
                }
                let mut out = vec![0.0; n];
                operator.apply(&field, &mut out).unwrap();
                out
            };
            let cells_of = |k: usize| -> Vec<usize> {
                let (bi, bj) = (k / nb1 * side, k % nb1 * side);
                (bi..bi + side)
                    .flat_map(|i| (bj..bj + side).map(move |j| i * columns + j))
                    .collect()
            };
            let periodic = boundary == Boundary::Periodic;
            let near = near_kernel(&response(&[0]), side, (rows, columns), &(0..rows), periodic);
            let block = response(&cells_of(0));
            let mut space = CoarseSpace::new(
                side,
                (rows, columns),
                0..rows,
                periodic,
                near,
                &block,
                &|_| {},
            )
            .unwrap();
            // A seeded set (the generator of `topography`).
            let mut random = ChaCha8Rng::seed_from_u64(12345);
            let working: Vec<bool> = (0..n).map(|_| random.next_u64() % 10 < 4).collect();
            space.update(&working, &|_| {});
            let members = |k: usize| -> Vec<usize> {
                cells_of(k).into_iter().filter(|c| working[*c]).collect()
            };
            let v: Vec<f64> = (0..m).map(|k| ((k * 7 % 11) as f64 - 5.0) / 3.0).collect();
            let b4 = (side as f64).powi(4);
            let mut expected = vec![0.0; m];
            for j in 0..m {
                let u = response(&cells_of(j));
                let own = members(j);
                for i in (0..m).filter(|i| *i != j) {
                    let kb: f64 = cells_of(i).iter().map(|c| u[*c]).sum();
                    let pairs = (members(i).len() * own.len()) as f64;
                    expected[i] += pairs * kb / b4 * v[j];
                }
                for a in &own {
                    let u = response(&[*a]);
                    expected[j] += own.iter().map(|c| u[*c]).sum::<f64>() * v[j];
                }
            }
            let mut product = vec![0.0; m];
            space.product(&v, &mut product).unwrap();
            let largest = expected.iter().fold(0.0_f64, |a, e| a.max(e.abs()));
            let error = expected
                .iter()
                .zip(&product)
                .fold(0.0_f64, |a, (e, p)| a.max((e - p).abs()));
            assert!(
                error <= 1e-12 * largest,
                "{boundary:?}: {error:e} of {largest:e}"
            );
        }
    }
}
