//! Cost of the analytic building blocks: `Lambda_g`, `a_m`, the series.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use layered_contact::analytic::{a_m, PunchStiffnessSeries};
use layered_contact::substrate::{Base, CoatingFunctions};
use layered_contact::Material;

fn bench_analytic(c: &mut Criterion) {
    let layer = Material::new(0.324e6, 0.48).unwrap();
    let base = Material::new(3.0e6, 0.3).unwrap();
    let functions = CoatingFunctions::new(&layer, &Base::Elastic(base));
    c.bench_function("coating R(t), 1000 points in [0, 20]", |b| {
        b.iter(|| {
            (0..1000)
                .map(|i| functions.r(black_box(i as f64 * 0.02)))
                .sum::<f64>()
        })
    });
    c.bench_function("a_m(1, 0.48)", |b| b.iter(|| a_m(black_box(1), 0.48)));
    c.bench_function("series: new + evaluate", |b| {
        b.iter(|| {
            PunchStiffnessSeries::new(layer, black_box(5e-3))
                .and_then(|s| s.evaluate(2.5e-3))
                .map(|k| k.ratio)
        })
    });
}

criterion_group!(benches, bench_analytic);
criterion_main!(benches);
