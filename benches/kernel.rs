//! Kernel construction (N = 128 .. 1024) and one operator application
//! (isolated, N = 128 .. 2048, padded 4096 x 4096 for the largest; periodic,
//! N = 512 .. 2048), for a 5 mm rubber film on glass with cells of 0.1 mm.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

use layered_contact::kernel::{ComplianceOperator, InfluenceCoefficients};
use layered_contact::{Boundary, Grid, Material, Substrate};

const SIZES: [usize; 4] = [128, 256, 512, 1024];

fn film() -> Substrate {
    Substrate::layer_on_rigid_base(Material::new(0.324e6, 0.48).unwrap(), 5e-3).unwrap()
}

fn bench_kernel(c: &mut Criterion) {
    let substrate = film();
    let mut group = c.benchmark_group("influence coefficients (isolated)");
    group.sample_size(10);
    for n in SIZES {
        let grid = Grid::new(n, n, 1e-4).unwrap();
        group.bench_with_input(BenchmarkId::from_parameter(n), &grid, |b, grid| {
            b.iter(|| InfluenceCoefficients::isolated(black_box(&substrate), grid))
        });
    }
    group.finish();

    let isolated = SIZES.into_iter().chain([2048]);
    bench_operator(
        c,
        "operator application (isolated, padded 2N x 2N)",
        Boundary::Isolated,
        isolated,
    );
    let periodic = [512, 1024, 2048].into_iter();
    bench_operator(
        c,
        "operator application (periodic, N x N)",
        Boundary::Periodic,
        periodic,
    );
}

/// One application of the film's compliance on `n x n` grids.
fn bench_operator(
    c: &mut Criterion,
    name: &str,
    boundary: Boundary,
    sizes: impl Iterator<Item = usize>,
) {
    let substrate = film();
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    for n in sizes {
        let grid = Grid::new(n, n, 1e-4).unwrap();
        let mut operator = ComplianceOperator::new(&substrate, &grid, boundary).unwrap();
        let pressure: Vec<f64> = (0..grid.len()).map(|i| (i % 17) as f64).collect();
        let mut displacement = vec![0.0; grid.len()];
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                operator
                    .apply(black_box(&pressure), &mut displacement)
                    .unwrap()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_kernel);
criterion_main!(benches);
