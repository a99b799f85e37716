//! One whole adhesive cycle of a non-axisymmetric indenter through a scene:
//! a 10 mm sphere tilted so that its contact centre moves by (0.3, 0.17)
//! pull-off contact radii, on a rubber half-space (E = 1 MPa, nu = 0.48,
//! dgamma = 0.05 J/m^2), loaded in 6 steps to the JKR depth of 1.6
//! pull-off contact radii and unloaded to contact loss, with 64 and 128
//! cells across the pull-off contact. The automatic adhesion method takes
//! the cohesive zone (its sets are not discs). `BENCHMARKS.md`, "Adhesive
//! scene cycles: error and cost". Beside it, the peeling path of a square
//! flat punch bonded over its face (`ContactSolver::peel_punch`), 64 and
//! 128 cells across: `BENCHMARKS.md`, "Local release rates along an edge";
//! and a force cycle of the tilted paraboloid at 64 cells.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use layered_contact::indenter::HeightMap;
use layered_contact::scene::{AdhesionMethod, IndenterSpec, Protocol, Scene};
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::{Boundary, Grid, Material, Substrate};

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
        bench_scene(&mut group, n, &scene);
    }
    group.finish();
}

/// One run of `scene` (its pull-off) as the benchmark `n` of `group`.
fn bench_scene(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    n: usize,
    scene: &Scene,
) {
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

/// The same scene with the tilted paraboloid under a force cycle to twice
/// the pull-off force in 6 steps and back to the jump-off (each force step
/// one fixed point under force control), 64 cells across:
/// `BENCHMARKS.md`, "Force steps by one fixed point under force control".
fn bench_force_cycle(c: &mut Criterion) {
    let mut group =
        c.benchmark_group("adhesive scene force cycle (tilted paraboloid, cohesive zone)");
    group.sample_size(10);
    let radius = tilted_cycle::RADIUS;
    let jkr = tilted_cycle::jkr().unwrap();
    let spec = IndenterSpec::Paraboloid { radius };
    let mut scene = tilted_cycle::scene(spec, 64, AdhesionMethod::CohesiveZone).unwrap();
    scene.protocol = Protocol::ForceCycle {
        max_force: -2.0 * jkr.pull_off_force(),
        steps: 6,
    };
    bench_scene(&mut group, 64, &scene);
    group.finish();
}

fn bench_peel(c: &mut Criterion) {
    let mut group = c.benchmark_group("peeling path (square flat punch)");
    group.sample_size(10);
    for n in [64usize, 128] {
        let (cells, delta) = (n + 16, 1e-4);
        let grid = Grid::square_of_side(cells, cells as f64 * delta).unwrap();
        let heights = (0..grid.len())
            .map(|c| {
                let (i, j) = (c / cells, c % cells);
                if (8..8 + n).contains(&i) && (8..8 + n).contains(&j) {
                    0.0
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        let square = HeightMap::new(grid, heights).unwrap();
        let rubber = Substrate::half_space(Material::new(1e6, 0.48).unwrap());
        let mut solver =
            ContactSolver::new(&rubber, &grid, Boundary::Isolated, SolverParams::default())
                .unwrap();
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| solver.peel_punch(&square, 0.05).unwrap().pull_off().force)
        });
    }
    group.finish();
}

criterion_group!(benches, bench_cycle, bench_force_cycle, bench_peel);
criterion_main!(benches);
