//! The exact axisymmetric solver: one flat-punch stiffness and a 200-point
//! JKR paraboloid curve on a rubber film on glass (h = 5 mm); the fitting
//! model: a 300-point force curve from one table (a film on glass) and
//! from a 12-node modulus family (a film over a softer gel), approach and
//! retract.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use layered_contact::analytic::{Axisymmetric, ForceCurve, ModulusFamily, Tip};
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

fn bench_force_curves(c: &mut Criterion) {
    let cell = Material::new(10e3, 0.5).unwrap();
    let gel = Material::new(2.5e3, 0.5).unwrap();
    let tip = Tip::Paraboloid { radius: 5e-6 };
    let depths: Vec<f64> = (0..300)
        .map(|k| -0.5e-6 + 2.5e-6 * k as f64 / 299.0)
        .collect();
    let on_glass = Substrate::layer_on_rigid_base(cell, 4e-6).unwrap();
    let table = ForceCurve::on(&on_glass, tip, 2e-6).unwrap();
    c.bench_function("force curve: 300 points, one table, approach", |b| {
        b.iter(|| table.forces(black_box(&depths), 0.8, 0.0))
    });
    c.bench_function("force curve: 300 points, one table, retract", |b| {
        b.iter(|| table.forces(black_box(&depths), 0.8, 1e-3))
    });
    let over_gel = Substrate::layer_on_elastic_base(cell, 4e-6, gel).unwrap();
    let family = ModulusFamily::new(&over_gel, Some(tip), f64::NAN, 2e-6, (3e3, 30e3), 12).unwrap();
    c.bench_function("force curve: 300 points, 12-node family, approach", |b| {
        b.iter(|| family.forces(black_box(&depths), 8e3))
    });
    c.bench_function("force curve: 300 points, 12-node family, retract", |b| {
        b.iter(|| family.adhesive_forces(black_box(&depths), 8e3, 1e-3))
    });
}

criterion_group!(benches, bench_axisymmetric, bench_force_curves);
criterion_main!(benches);
