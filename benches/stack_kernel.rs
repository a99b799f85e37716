//! Building a stack's kernels: `R(t)` of a three-layer stack (one
//! evaluation), the isolated influence coefficients on a 128 x 128 grid and
//! the exact axisymmetric kernel, for 1, 3 and 6 alternating hard and soft
//! layers (1 mm, 1.1 mm, ...) on steel, cells of 0.1 mm.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

use layered_contact::analytic::Axisymmetric;
use layered_contact::kernel::InfluenceCoefficients;
use layered_contact::{Base, Grid, Material, Substrate};

fn stack(layers: usize) -> Substrate {
    let hard = Material::new(1e9, 0.3).unwrap();
    let soft = Material::new(1e6, 0.45).unwrap();
    let layers: Vec<(Material, f64)> = (0..layers)
        .map(|k| {
            (
                if k % 2 == 0 { hard } else { soft },
                1e-3 * (1.0 + 0.1 * k as f64),
            )
        })
        .collect();
    Substrate::stack(&layers, Base::Elastic(Material::new(2e11, 0.3).unwrap())).unwrap()
}

fn bench_stack(c: &mut Criterion) {
    let Substrate::Stack(three) = stack(3) else {
        unreachable!("three different layers")
    };
    let functions = three.functions();
    c.bench_function("stack R(t), 3 layers", |b| {
        b.iter(|| functions.r(black_box(0.7)))
    });

    let grid = Grid::new(128, 128, 1e-4).unwrap();
    let mut group = c.benchmark_group("stack influence coefficients (128 x 128)");
    group.sample_size(10);
    for layers in [1, 3, 6] {
        let substrate = stack(layers);
        group.bench_with_input(BenchmarkId::from_parameter(layers), &substrate, |b, s| {
            b.iter(|| InfluenceCoefficients::isolated(black_box(s), &grid))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("stack axisymmetric kernel (a/h1 up to 5)");
    group.sample_size(10);
    for layers in [1, 3, 6] {
        let substrate = stack(layers);
        group.bench_with_input(BenchmarkId::from_parameter(layers), &substrate, |b, s| {
            b.iter(|| Axisymmetric::new(black_box(s), 5.0).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, bench_stack);
criterion_main!(benches);
