//! Stresses below the surface on a 512 x 512 grid: planning (every distinct
//! wavenumber's layered solution), ten depth planes of one pressure (fresh,
//! and into buffers reused from the previous call), and,
//! for scale, one application of the surface compliance operator on the
//! same grid; on a half-space and a three-layer coating on steel, periodic
//! and isolated (padded 4 times).

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use layered_contact::kernel::ComplianceOperator;
use layered_contact::stress::{Side, SubsurfaceStress};
use layered_contact::{Base, Boundary, Grid, Material, Substrate};

fn coating() -> Substrate {
    Substrate::stack(
        &[
            (Material::new(400e9, 0.25).unwrap(), 2e-6),
            (Material::new(279e9, 0.21).unwrap(), 1e-6),
        ],
        Base::Elastic(Material::new(210e9, 0.3).unwrap()),
    )
    .unwrap()
}

/// A Hertz-like pressure over a disc a quarter of the grid wide.
fn pressure(n: usize) -> Vec<f64> {
    (0..n * n)
        .map(|k| {
            let (x, y) = (
                (k / n) as f64 - n as f64 / 2.0,
                (k % n) as f64 - n as f64 / 2.0,
            );
            let r2 = (x * x + y * y) / (n as f64 / 8.0).powi(2);
            if r2 < 1.0 {
                1e9 * (1.0 - r2).sqrt()
            } else {
                0.0
            }
        })
        .collect()
}

fn bench_stress(c: &mut Criterion) {
    let n = 512;
    let grid = Grid::new(n, n, 0.05e-6).unwrap();
    let p = pressure(n);
    let depths: Vec<f64> = (1..=10).map(|k| 0.4e-6 * k as f64).collect();
    let bodies = [
        (
            "half-space",
            Substrate::half_space(Material::new(210e9, 0.3).unwrap()),
        ),
        ("coating", coating()),
    ];
    let mut group = c.benchmark_group("subsurface stress 512 x 512");
    group.sample_size(10);
    for (name, body) in &bodies {
        for boundary in [Boundary::Periodic, Boundary::Isolated] {
            let label = format!("{name}, {boundary:?}");
            group.bench_function(format!("plan, {label}"), |b| {
                b.iter(|| SubsurfaceStress::new(black_box(body), &grid, boundary).unwrap())
            });
            let mut stress = SubsurfaceStress::new(body, &grid, boundary).unwrap();
            group.bench_function(format!("ten planes, {label}"), |b| {
                b.iter(|| black_box(stress.planes(black_box(&p), &depths, Side::Below).unwrap()))
            });
            let mut planes = Vec::new();
            group.bench_function(format!("ten planes into the same buffers, {label}"), |b| {
                b.iter(|| {
                    stress
                        .planes_into(black_box(&p), &depths, Side::Below, &mut planes)
                        .unwrap()
                })
            });
            let mut operator = ComplianceOperator::new(body, &grid, boundary).unwrap();
            let mut u = vec![0.0; n * n];
            group.bench_function(format!("one operator application, {label}"), |b| {
                b.iter(|| operator.apply(black_box(&p), &mut u).unwrap())
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench_stress);
criterion_main!(benches);
