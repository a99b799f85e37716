//! Full solves: a non-adhesive sphere on a film (N = 128 .. 1024 cells
//! across the grid) and an adhesive load-unload curve of a sphere
//! (N = 64 .. 256; finer curves are timed by the `accuracy` example).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

use layered_contact::indenter::Sphere;
use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Resolution, Scene, SubstrateSpec};
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::{Boundary, Grid, Material, Substrate};

fn bench_solver(c: &mut Criterion) {
    let film = Substrate::layer_on_rigid_base(Material::new(0.324e6, 0.48).unwrap(), 5e-3).unwrap();
    let mut group = c.benchmark_group("non-adhesive solve (sphere R = 30 mm, d = 0.1 mm)");
    group.sample_size(10);
    for n in [128usize, 256, 512, 1024] {
        // The contact (radius ~1.7 mm) spans about 80 % of the grid.
        let grid = Grid::new(n, n, 4.2e-3 / n as f64).unwrap();
        let mut solver =
            ContactSolver::new(&film, &grid, Boundary::Isolated, SolverParams::default()).unwrap();
        let ball = Sphere::new(0.03).unwrap();
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                solver
                    .solve_depth(&ball, black_box(1e-4), None, &mut ())
                    .unwrap()
                    .0
                    .force
            })
        });
    }
    group.finish();

    let mut group = c.benchmark_group("adhesive curve (sphere, 10 + unloading steps)");
    group.sample_size(10);
    for n in [64usize, 128, 256] {
        let scene = Scene {
            substrate: SubstrateSpec::LayerOnRigidBase {
                youngs_modulus: 0.324e6,
                poisson_ratio: 0.48,
                thickness: 5e-3,
            },
            indenter: IndenterSpec::Sphere { radius: 0.03 },
            adhesion: Adhesion::Hysteresis {
                loading: 0.0175,
                unloading: 0.326,
            },
            protocol: Protocol::Cycle {
                max_depth: 1e-4,
                steps: 10,
            },
            resolution: Resolution {
                cells_across: n,
                margin: 0.15,
            },
            ..Scene::default()
        };
        let mut solver = scene.solver().unwrap();
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| scene.run_on(&mut solver, &mut |_| {}).unwrap().steps.len())
        });
    }
    group.finish();
}

criterion_group!(benches, bench_solver);
criterion_main!(benches);
