//! The extension past the set's edges against a dense reference, and
//! split across thread ranks against the serial run.

use std::sync::Arc;

use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};

use super::super::{BoxInverse, Residual};
use crate::kernel::fourier::FourierCompliance;
use crate::material::Material;
use crate::slab::Slab;
use crate::substrate::Substrate;

/// A grid of 40 x 36 cells, a box of 32 x 32 (FFT) whose data, 30 x 28
/// cells, starts at grid cell (5, 4), a film on glass.
const GRID: (usize, usize) = (40, 36);
const ORIGIN: (isize, isize) = (5, 4);
const DATA: (usize, usize) = (30, 28);
const DELTA: f64 = 1e-5;

fn compliance() -> FourierCompliance {
    let film = Substrate::layer_on_elastic_base(
        Material::new(1e6, 0.49).unwrap(),
        2e-4,
        Material::new(7e10, 0.2).unwrap(),
    )
    .unwrap();
    FourierCompliance::new(&film)
}

/// The box inverse on `rows` (a band of the grid's rows, all of them
/// when serial) of `member` and `values`.
fn apply(
    inverse: &mut BoxInverse<f64>,
    rows: std::ops::Range<usize>,
    member: &[bool],
    values: &[f64],
    shift: f64,
    extend: bool,
) -> (Vec<f64>, (f64, f64)) {
    let cells = rows.start * GRID.1..rows.end * GRID.1;
    let residual = Residual {
        columns: GRID.1,
        origin: ORIGIN,
        member: &member[cells.clone()],
        values: &values[cells.clone()],
        shift,
        magnitude: values.iter().fold(0.0_f64, |m, v| m.max(v.abs())) + shift.abs(),
        extend,
    };
    let mut result = vec![0.0; cells.len()];
    let sums = inverse.apply_with(&residual, &mut result).unwrap();
    (result, sums)
}

/// Members: a seeded random third of the box's cells away from its
/// sides (the solver keeps a margin), some on the box's first and last
/// data rows' neighbours.
fn members(rng: &mut ChaCha8Rng) -> Vec<bool> {
    let mut member = vec![false; GRID.0 * GRID.1];
    for i in 7..33 {
        for j in 6..30 {
            let x: f64 = StandardNormal.sample(rng);
            member[i * GRID.1 + j] = x > 0.43;
        }
    }
    member
}

fn random(rng: &mut ChaCha8Rng) -> Vec<f64> {
    (0..GRID.0 * GRID.1)
        .map(|_| StandardNormal.sample(rng))
        .collect()
}

/// The extended box inverse equals `W E^T K^-1 E W`, formed densely:
/// `K^-1` column by column from the box inverse on every cell, `E` the
/// extension by the four-neighbour mean written out. So it is
/// symmetric and positive on the members, and it is not the plain
/// box inverse.
#[test]
fn the_extension_is_the_transpose_pair_around_the_box_inverse() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let member = members(&mut rng);
    let compliance = compliance();
    let mut inverse =
        BoxInverse::<f64>::new(&compliance, 1e6, DELTA, (32, 32), DATA, None).unwrap();
    let n = GRID.0 * GRID.1;
    let in_box = |c: usize| {
        let (i, j) = ((c / GRID.1) as isize, (c % GRID.1) as isize);
        (0..DATA.0 as isize).contains(&(i - ORIGIN.0))
            && (0..DATA.1 as isize).contains(&(j - ORIGIN.1))
    };
    // K^-1 restricted to the box's cells, a column per cell.
    let everywhere: Vec<bool> = (0..n).map(in_box).collect();
    let mut stiffness = vec![vec![0.0; n]; n];
    for c in (0..n).filter(|&c| in_box(c)) {
        let mut unit = vec![0.0; n];
        unit[c] = 1.0;
        stiffness[c] = apply(&mut inverse, 0..GRID.0, &everywhere, &unit, 0.0, false).0;
    }
    // E: members keep their value, a box cell outside takes a quarter of
    // its members' among its four neighbours.
    let extend = |r: &[f64]| -> Vec<f64> {
        (0..n)
            .map(|c| {
                if member[c] {
                    return r[c];
                }
                if !in_box(c) {
                    return 0.0;
                }
                let (i, j) = (c / GRID.1, c % GRID.1);
                let mut sum = 0.0;
                for (di, dj) in [(-1isize, 0isize), (1, 0), (0, -1), (0, 1)] {
                    let (a, b) = (i as isize + di, j as isize + dj);
                    if a >= 0 && b >= 0 && (a as usize) < GRID.0 && (b as usize) < GRID.1 {
                        let d = a as usize * GRID.1 + b as usize;
                        if member[d] {
                            sum += r[d];
                        }
                    }
                }
                0.25 * sum
            })
            .collect()
    };
    let dense = |r: &[f64]| -> Vec<f64> {
        let x = extend(r);
        // y = K^-1 x, then z = E^T y on the members.
        let mut y = vec![0.0; n];
        for (c, column) in stiffness.iter().enumerate() {
            if x[c] != 0.0 {
                for (yk, s) in y.iter_mut().zip(column) {
                    *yk += x[c] * s;
                }
            }
        }
        (0..n)
            .map(|c| {
                let unit: Vec<f64> = (0..n).map(|k| f64::from(u8::from(k == c))).collect();
                if member[c] {
                    extend(&unit).iter().zip(&y).map(|(e, y)| e * y).sum()
                } else {
                    0.0
                }
            })
            .collect()
    };
    let (u, v) = (random(&mut rng), random(&mut rng));
    let shift = 0.3;
    let shifted: Vec<f64> = u.iter().map(|x| x - shift).collect();
    let (fast, sums) = apply(&mut inverse, 0..GRID.0, &member, &u, shift, true);
    let exact = dense(&shifted);
    let largest = exact.iter().fold(0.0_f64, |m, z| m.max(z.abs()));
    for c in (0..n).filter(|&c| member[c]) {
        assert!((fast[c] - exact[c]).abs() <= 1e-12 * largest, "{c}");
    }
    let (sum, dot) = (0..n).filter(|&c| member[c]).fold((0.0, 0.0), |(s, d), c| {
        (s + exact[c], d + exact[c] * shifted[c])
    });
    assert!((sums.0 - sum).abs() <= 1e-12 * largest * n as f64);
    assert!(
        (sums.1 / dot - 1.0).abs() <= 1e-12 && dot > 0.0,
        "{sums:?} {dot}"
    );
    // Symmetric: u . M v = v . M u over the members.
    let mv = apply(&mut inverse, 0..GRID.0, &member, &v, 0.0, true).0;
    let mu = apply(&mut inverse, 0..GRID.0, &member, &u, 0.0, true).0;
    let dot =
        |a: &[f64], b: &[f64]| -> f64 { (0..n).filter(|&c| member[c]).map(|c| a[c] * b[c]).sum() };
    assert!((dot(&u, &mv) / dot(&v, &mu) - 1.0).abs() < 1e-12);
    // Not the plain box inverse.
    let plain = apply(&mut inverse, 0..GRID.0, &member, &u, shift, false).0;
    let apart = (0..n)
        .filter(|&c| member[c])
        .fold(0.0_f64, |m, c| m.max((plain[c] - fast[c]).abs()));
    assert!(apart > 1e-2 * largest, "{apart} of {largest}");
}

/// Split across 2 to 5 ranks (threads), the extended box inverse gives
/// each rank the serial result on its rows, and the same sums.
#[test]
fn split_runs_extend_as_the_serial_one() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let member = members(&mut rng);
    let values = random(&mut rng);
    let compliance = compliance();
    let mut serial = BoxInverse::<f64>::new(&compliance, 1e6, DELTA, (32, 32), DATA, None).unwrap();
    let (expected, sums) = apply(&mut serial, 0..GRID.0, &member, &values, 0.1, true);
    let largest = expected.iter().fold(0.0_f64, |m, z| m.max(z.abs()));
    for ranks in 2..=5 {
        let shares = crate::slab::threads::run(ranks, |exchange| {
            let slab = Slab::new(Arc::clone(&exchange), GRID.0, 1).unwrap();
            let mut inverse =
                BoxInverse::<f64>::new(&compliance, 1e6, DELTA, (32, 32), DATA, Some(&slab))
                    .unwrap();
            let (result, part) = apply(&mut inverse, slab.rows(), &member, &values, 0.1, true);
            (slab.rows(), result, part)
        });
        let mut total = (0.0, 0.0);
        for (rows, result, part) in shares {
            total = (total.0 + part.0, total.1 + part.1);
            for (k, z) in result.iter().enumerate() {
                let c = rows.start * GRID.1 + k;
                if member[c] {
                    assert!((z - expected[c]).abs() <= 1e-13 * largest, "{ranks}: {c}");
                }
            }
        }
        assert!(
            (total.0 - sums.0).abs() <= 1e-12 * largest * GRID.0 as f64,
            "{ranks}"
        );
        assert!((total.1 / sums.1 - 1.0).abs() <= 1e-12, "{ranks}");
    }
}
