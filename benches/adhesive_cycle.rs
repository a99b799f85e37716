//! One whole adhesive cycle of a non-axisymmetric indenter through a scene:
//! a 10 mm sphere tilted so that its contact centre moves by (0.3, 0.17)
//! pull-off contact radii, on a rubber half-space (E = 1 MPa, nu = 0.48,
//! dgamma = 0.05 J/m^2), loaded in 6 steps to the JKR depth of 1.6
//! pull-off contact radii and unloaded to contact loss, with 64 and 128
//! cells across the pull-off contact. The automatic adhesion method takes
//! the cohesive zone (its sets are not discs). `BENCHMARKS.md`, "Adhesive
//! scene cycles: error and cost".

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use layered_contact::scene::{AdhesionMethod, IndenterSpec};

#[path = "../examples/support/tilted_cycle.rs"]
#[allow(dead_code)] // the bench uses only the scene
mod tilted_cycle;

fn bench_cycle(c: &mut Criterion) {
    let mut group = c.benchmark_group("adhesive scene cycle (tilted sphere, cohesive zone)");
    group.sample_size(10);
    for n in [64usize, 128] {
        let radius = tilted_cycle::RADIUS;
        let scene =
            tilted_cycle::scene(IndenterSpec::Sphere { radius }, n, AdhesionMethod::Auto).unwrap();
        assert_eq!(
            scene.resolved_adhesion_method(),
            AdhesionMethod::CohesiveZone
        );
        let mut solver = scene.solver().unwrap();
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                scene
                    .run_on(&mut solver, &mut |_| {})
                    .unwrap()
                    .pull_off()
                    .map(|s| s.force)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_cycle);
criterion_main!(benches);
