//! Full solves: a non-adhesive sphere on a film (N = 128 .. 1024 cells
//! across the grid) and one adhesive loading and unloading cycle of a sphere
//! on a film with hysteresis, 64 and 128 cells across the pull-off contact,
//! by the energy balance (and, at 64, the mesh-dependent criterion for
//! comparison; finer curves are timed by the `accuracy` example).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

use std::time::{Duration, Instant};

use layered_contact::indenter::{Paraboloid, Sphere};
use layered_contact::kernel::ComplianceOperator;
use layered_contact::scene::{
    Adhesion, AdhesionMethod, IndenterSpec, Protocol, Resolution, Scene, SolverSettings,
    SubstrateSpec,
};
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

    let mut group =
        c.benchmark_group("adhesive cycle (sphere R = 30 mm on a 5 mm film, d = 0.1 mm)");
    group.sample_size(10);
    for (n, method) in [
        (64usize, AdhesionMethod::EnergyBalance),
        (128, AdhesionMethod::EnergyBalance),
        (64, AdhesionMethod::MeshCriterion),
    ] {
        let scene = Scene {
            substrate: SubstrateSpec::LayerOnRigidBase {
                youngs_modulus: 0.324e6,
                poisson_ratio: 0.48,
                thickness: 5e-3,
            },
            indenter: IndenterSpec::Paraboloid { radius: 0.03 },
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
                margin: 0.05,
            },
            solver: SolverSettings {
                adhesion_method: method,
                ..SolverSettings::default()
            },
            ..Scene::default()
        };
        let mut solver = scene.solver().unwrap();
        let name = match method {
            AdhesionMethod::EnergyBalance => "energy balance",
            _ => "mesh criterion",
        };
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter(|| scene.run_on(&mut solver, &mut |_| {}).unwrap().steps.len())
        });
    }
    group.finish();
}

/// One constrained-CG iteration on the peers' Hertz problem (paraboloid
/// R = 1 on a half-space, 2 x 2 domain, depth 0.25), timed as a solve's time
/// divided by its iterations, beside one operator application (one padded
/// FFT round trip of this crate) on the same grid. Two solves whose contact
/// set changes while they iterate: a cold one without the multi-resolution
/// start, and one warm-started from the solution at a 4 % smaller depth.
fn bench_iteration(c: &mut Criterion) {
    let mut group = c.benchmark_group("CG iteration vs padded FFT round trip");
    group.sample_size(10);
    for n in [512usize, 1024] {
        let grid = Grid::square(n, 2.0).unwrap();
        let substrate = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
        let params = SolverParams {
            tolerance: 1e-8,
            ..SolverParams::default()
        };
        let mut solver = ContactSolver::new(&substrate, &grid, Boundary::Isolated, params).unwrap();
        let ball = Paraboloid::new(1.0).unwrap();
        let (_, warm) = solver.solve_depth(&ball, 0.24, None, &mut ()).unwrap();
        let mut per_iteration = |name: &str, solver: &mut ContactSolver, warm| {
            group.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter_custom(|repeats| {
                    let mut total = Duration::ZERO;
                    for _ in 0..repeats {
                        let start = Instant::now();
                        let (s, _) = solver
                            .solve_depth(&ball, black_box(0.25), warm, &mut ())
                            .unwrap();
                        total += start.elapsed() / s.iterations as u32;
                    }
                    total
                })
            });
        };
        per_iteration("CG iteration, warm start", &mut solver, Some(&warm));
        let mut cold = ContactSolver::new(
            &substrate,
            &grid,
            Boundary::Isolated,
            SolverParams {
                multiresolution: false,
                ..params
            },
        )
        .unwrap();
        per_iteration("CG iteration, cold", &mut cold, None);
        let mut operator = ComplianceOperator::new(&substrate, &grid, Boundary::Isolated).unwrap();
        let pressure: Vec<f64> = (0..grid.len()).map(|i| (i % 17) as f64).collect();
        let mut displacement = vec![0.0; grid.len()];
        group.bench_function(BenchmarkId::new("padded FFT round trip", n), |b| {
            b.iter(|| {
                operator
                    .apply(black_box(&pressure), &mut displacement)
                    .unwrap()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_solver, bench_iteration);
criterion_main!(benches);
