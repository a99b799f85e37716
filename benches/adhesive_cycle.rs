//! One whole adhesive cycle of a non-axisymmetric indenter through a scene:
//! a 10 mm sphere tilted so that its contact centre moves by (0.3, 0.17)
//! pull-off contact radii, on a rubber half-space (E = 1 MPa, nu = 0.48,
//! dgamma = 0.05 J/m^2), loaded in 6 steps to the JKR depth of 1.6
//! pull-off contact radii and unloaded to contact loss, with 64 and 128
//! cells across the pull-off contact. The automatic adhesion method takes
//! the cohesive zone (its sets are not discs). `BENCHMARKS.md`, "Adhesive
//! scene cycles: error and cost".

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use layered_contact::analytic::JkrSphere;
use layered_contact::scene::{
    Adhesion, AdhesionMethod, IndenterSpec, Protocol, Resolution, Scene, SubstrateSpec, Tilt,
};
use layered_contact::Material;

fn bench_cycle(c: &mut Criterion) {
    let (radius, work) = (0.01, 0.05);
    let jkr = JkrSphere::new(&Material::new(1e6, 0.48).unwrap(), radius, work).unwrap();
    let a = jkr.pull_off_contact_radius();
    let mut group = c.benchmark_group("adhesive scene cycle (tilted sphere, cohesive zone)");
    group.sample_size(10);
    for n in [64usize, 128] {
        let scene = Scene {
            substrate: SubstrateSpec::HalfSpace {
                youngs_modulus: 1e6,
                poisson_ratio: 0.48,
            },
            indenter: IndenterSpec::Sphere { radius },
            tilt: Some(Tilt {
                angle_y: (0.3 * a / radius).atan(),
                angle_x: (0.17 * a / radius).atan(),
            }),
            adhesion: Adhesion::Constant {
                work_of_adhesion: work,
            },
            protocol: Protocol::Cycle {
                max_depth: jkr.depth(1.6 * a),
                steps: 6,
            },
            resolution: Resolution {
                cells_across: n,
                margin: 0.6,
            },
            ..Scene::default()
        };
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
