//! The exact axisymmetric solver: one flat-punch stiffness and a 200-point
//! JKR paraboloid curve on a rubber film on glass (h = 5 mm).

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use layered_contact::analytic::Axisymmetric;
use layered_contact::{Material, Substrate};

fn bench_axisymmetric(c: &mut Criterion) {
    let rubber = Material::new(0.324e6, 0.48).unwrap();
    let film = Substrate::layer_on_rigid_base(rubber, 5e-3).unwrap();
    c.bench_function("axisymmetric: kernel table (eps <= 4)", |b| {
        b.iter(|| Axisymmetric::new(black_box(&film), 4.0).unwrap())
    });
    let exact = Axisymmetric::new(&film, 4.0).unwrap();
    c.bench_function("axisymmetric: flat punch stiffness, D = h", |b| {
        b.iter(|| exact.flat_punch(black_box(2.5e-3)).unwrap().stiffness())
    });
    let ball = exact.paraboloid(0.05, 0.326).unwrap();
    let radii: Vec<f64> = (1..=200).map(|k| k as f64 * 5e-5).collect();
    c.bench_function("axisymmetric: JKR paraboloid curve, 200 points", |b| {
        b.iter(|| ball.curve(black_box(&radii)).unwrap())
    });
}

criterion_group!(benches, bench_axisymmetric);
criterion_main!(benches);
