//! Full solves: a non-adhesive sphere on a film (N = 128 .. 1024 cells
//! across the grid) and one adhesive loading and unloading cycle of a sphere
//! on a film with hysteresis, 64 and 128 cells across the pull-off contact,
//! by the energy balance (and, at 64, the mesh-dependent criterion for
//! comparison; finer curves are timed by the `accuracy` example); the
//! adhesive branches of an elliptic paraboloid (radii 10 and 20 mm, a
//! non-axisymmetric family of contact sets) at 64 and 128 cells across its
//! pull-off contact; the cohesive-zone pull-off of Johnson's sinusoid with
//! its crests at 45 degrees to the grid (64 and 128 cells per wavelength);
//! a rough periodic contact (the surface of
//! `benches/peers/rough.py`, N = 256, 512 and 1024, with the box and with
//! the two-level preconditioner over blocks of 16); the cost of one CG iteration
//! against a padded FFT round trip.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

use std::time::{Duration, Instant};

use num_complex::Complex;
use rayon::prelude::*;

use layered_contact::indenter::{HeightMap, Paraboloid, Sphere};
use layered_contact::kernel::ComplianceOperator;
use layered_contact::scene::{
    Adhesion, AdhesionMethod, IndenterSpec, Protocol, Resolution, Scene, SolverSettings,
    SubstrateSpec,
};
use layered_contact::solver::{CohesiveZone, ContactSolver, IterationInfo, Reach, SolverParams};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Boundary, Grid, Material, Substrate};

/// The rough periodic contact of `benches/peers/rough.py`: a seeded
/// self-affine surface (Hurst 0.8, rms slope 0.1, roll-off at L/4, cut-off
/// at four cells) on a periodic half-space (`E* = 1`, `L = 1`) at a mean
/// pressure of `0.01 E*` (about 20 % contact), tolerance 1e-8.
fn bench_rough(c: &mut Criterion) {
    let half = Substrate::half_space(Material::new(0.75, 0.5).unwrap());
    let mut group = c.benchmark_group("rough periodic solve (half-space, 0.01 E*)");
    group.sample_size(10);
    for n in [256usize, 512, 1024] {
        let grid = Grid::new(n, n, 1.0 / n as f64).unwrap();
        let surface = SelfAffine {
            hurst: 0.8,
            amplitude: Amplitude::RmsSlope(0.1),
            long_cutoff: 0.25,
            short_cutoff: 4.0 / n as f64,
            seed: 1,
        }
        .indenter(&grid)
        .unwrap();
        let params = SolverParams {
            tolerance: 1e-8,
            ..SolverParams::default()
        };
        // The box (the default), then the two-level preconditioner over
        // blocks of 16 cells (`ContactSolver::set_coarse_blocks`).
        for blocks in [None, Some(16)] {
            let mut solver = ContactSolver::new(&half, &grid, Boundary::Periodic, params).unwrap();
            solver.set_coarse_blocks(blocks).unwrap();
            let id = match blocks {
                None => BenchmarkId::from_parameter(n),
                Some(b) => BenchmarkId::new(format!("blocks of {b}"), n),
            };
            group.bench_function(id, |b| {
                b.iter(|| {
                    solver
                        .solve_force(&surface, black_box(0.01), None, &mut ())
                        .unwrap()
                        .0
                        .iterations
                })
            });
        }
    }
    group.finish();
}

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

    // The elliptic paraboloid: a JKR pull-off contact of about 0.23 mm
    // radius along the short axis on the rubber half-space of the adhesion
    // tests (E = 1 MPa, nu = 0.48, dgamma = 0.05 J/m^2).
    let mut group = c.benchmark_group(
        "adhesive branches, elliptic paraboloid (Rx = 10 mm, Ry = 20 mm, half-space)",
    );
    group.sample_size(10);
    let rubber = Substrate::half_space(Material::new(1e6, 0.48).unwrap());
    let short = 0.23e-3;
    for n in [64usize, 128] {
        // 64 or 128 cells across the short axis, the grid four times as wide.
        let delta = 2.0 * short / n as f64;
        let grid = Grid::square_of_side(4 * n, (4 * n) as f64 * delta).unwrap();
        let columns = grid.columns();
        let heights = (0..grid.len())
            .map(|c| {
                let (x, y) = grid.cell_centre(c / columns, c % columns);
                x * x / (2.0 * 0.01) + y * y / (2.0 * 0.02)
            })
            .collect();
        let map = HeightMap::new(grid, heights).unwrap();
        let mut solver =
            ContactSolver::new(&rubber, &grid, Boundary::Isolated, SolverParams::default())
                .unwrap();
        let depth = (1.5 * short).powi(2) / 0.01;
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                let branches = solver
                    .adhesive_branches(&map, Reach::Depth(depth), 0.05, 0.05, &mut ())
                    .unwrap();
                let peak = branches.at_depth(depth, 0.0).unwrap();
                branches.pull_off(peak.contact_area).unwrap().force
            })
        });
    }
    group.finish();
}

/// The unit the peers' iterations are counted in: a plain FFT round trip of
/// the zero-padded `2N x 2N` grid, as FFT-based solvers do one per operator
/// application (the padded input written, real-to-complex row transforms,
/// a transpose, complex column transforms forward, a multiplication and
/// back, a transpose, complex-to-real row transforms; rows and columns on
/// all threads, transposes on one).
struct PaddedRoundTrip {
    size: usize,
    forward: std::sync::Arc<dyn realfft::RealToComplex<f64>>,
    inverse: std::sync::Arc<dyn realfft::ComplexToReal<f64>>,
    column_forward: std::sync::Arc<dyn rustfft::Fft<f64>>,
    column_inverse: std::sync::Arc<dyn rustfft::Fft<f64>>,
    real: Vec<f64>,
    spectrum: Vec<Complex<f64>>,
    transposed: Vec<Complex<f64>>,
}

impl PaddedRoundTrip {
    fn new(n: usize) -> Self {
        let size = 2 * n;
        let mut real = realfft::RealFftPlanner::<f64>::new();
        let mut complex = rustfft::FftPlanner::<f64>::new();
        let half = size / 2 + 1;
        PaddedRoundTrip {
            size,
            forward: real.plan_fft_forward(size),
            inverse: real.plan_fft_inverse(size),
            column_forward: complex.plan_fft_forward(size),
            column_inverse: complex.plan_fft_inverse(size),
            real: vec![0.0; size * size],
            spectrum: vec![Complex::default(); size * half],
            transposed: vec![Complex::default(); size * half],
        }
    }

    fn run(&mut self) {
        let (size, half) = (self.size, self.size / 2 + 1);
        let scale = 1.0 / (size * size) as f64;
        self.real.par_chunks_mut(size).for_each(|row| row.fill(1.0));
        let forward = &self.forward;
        self.real
            .par_chunks_mut(size)
            .zip(self.spectrum.par_chunks_mut(half))
            .for_each(|(r, s)| forward.process(r, s).expect("sizes match"));
        transpose::transpose(&self.spectrum, &mut self.transposed, half, size);
        let (f, i) = (&self.column_forward, &self.column_inverse);
        self.transposed.par_chunks_mut(size).for_each(|line| {
            f.process(line);
            line.iter_mut().for_each(|v| *v *= scale);
            i.process(line);
        });
        transpose::transpose(&self.transposed, &mut self.spectrum, size, half);
        let inverse = &self.inverse;
        self.spectrum
            .par_chunks_mut(half)
            .zip(self.real.par_chunks_mut(size))
            .for_each(|(s, r)| {
                s[0].im = 0.0;
                s[half - 1].im = 0.0;
                inverse.process(s, r).expect("sizes match");
            });
    }
}

/// One constrained-CG iteration on the peers' Hertz problem (paraboloid
/// R = 1 on a half-space, 2 x 2 domain, depth 0.25, tolerance 1e-8) against
/// a padded FFT round trip ([`PaddedRoundTrip`]) and one operator
/// application of this crate. An iteration is timed between the observer's
/// calls of the first and the last iteration of the solve on the grid (the
/// coarse grids of the multi-resolution start, solved before, are not
/// counted): a cold solve as the benchmark runs it, one warm-started from
/// the solution at a 4 % smaller depth, and a cold one without the
/// multi-resolution start (the contact grows from the first touch, clamping
/// in most iterations).
fn bench_iteration(c: &mut Criterion) {
    let mut group = c.benchmark_group("CG iteration vs padded FFT round trip");
    group.sample_size(10);
    for n in [512usize, 1024] {
        let grid = Grid::square_of_side(n, 2.0).unwrap();
        let substrate = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
        let ball = Paraboloid::new(1.0).unwrap();
        let params = SolverParams {
            tolerance: 1e-8,
            ..SolverParams::default()
        };
        let mut round_trip = PaddedRoundTrip::new(n);
        group.bench_function(BenchmarkId::new("padded FFT round trip", n), |b| {
            b.iter(|| round_trip.run())
        });
        drop(round_trip);
        let mut operator = ComplianceOperator::new(&substrate, &grid, Boundary::Isolated).unwrap();
        let pressure: Vec<f64> = (0..grid.len()).map(|i| (i % 17) as f64).collect();
        let mut displacement = vec![0.0; grid.len()];
        group.bench_function(BenchmarkId::new("operator application", n), |b| {
            b.iter(|| {
                operator
                    .apply(black_box(&pressure), &mut displacement)
                    .unwrap()
            })
        });
        drop(operator);
        let mut per_iteration = |name: &str, params: SolverParams, warm: bool| {
            let mut solver =
                ContactSolver::new(&substrate, &grid, Boundary::Isolated, params).unwrap();
            let (_, start) = solver.solve_depth(&ball, 0.24, None, &mut ()).unwrap();
            let start = warm.then_some(&start);
            group.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter_custom(|repeats| {
                    let mut total = Duration::ZERO;
                    for _ in 0..repeats {
                        let mut calls: Vec<Instant> = Vec::new();
                        let mut observer = |_: &IterationInfo| calls.push(Instant::now());
                        solver
                            .solve_depth(&ball, black_box(0.25), start, &mut observer)
                            .unwrap();
                        let (first, last) = (calls[0], calls[calls.len() - 1]);
                        total += (last - first) / (calls.len() - 1) as u32;
                    }
                    total
                })
            });
        };
        per_iteration("CG iteration, multi-resolution start", params, false);
        per_iteration("CG iteration, warm start", params, true);
        let plain_start = SolverParams {
            multiresolution: false,
            ..params
        };
        per_iteration(
            "CG iteration, no multi-resolution start",
            plain_start,
            false,
        );
    }
    group.finish();
}

/// One unloading to the pull-off through the cohesive zone (8 cells) of
/// Johnson's sinusoid (`alpha = 0.3`, rubber half-space, periodic) with its
/// crests at 45 degrees to the grid, `n` cells per wavelength on `n sqrt 2`
/// cells each way (the case of `tests/cohesive.rs`).
fn bench_cohesive(c: &mut Criterion) {
    let rubber = Material::new(1e6, 0.48).unwrap();
    let work = 0.05;
    let mut group = c.benchmark_group("cohesive pull-off (sinusoid at 45 degrees, alpha = 0.3)");
    group.sample_size(10);
    for n in [64usize, 128] {
        let cells = (n as f64 * 2f64.sqrt()).round() as usize;
        let spacing = 1e-5;
        let wavelength = cells as f64 * spacing / 2f64.sqrt();
        let amplitude = (2.0 * wavelength * work
            / (std::f64::consts::PI.powi(2) * rubber.contact_modulus()))
        .sqrt()
            / 0.3;
        let grid = Grid::square_of_side(cells, cells as f64 * spacing).unwrap();
        let values = (0..grid.len())
            .map(|c| {
                let phase = ((c / cells + c % cells) % cells) as f64 / cells as f64;
                amplitude * (1.0 - (2.0 * std::f64::consts::PI * phase).cos())
            })
            .collect();
        let surface = HeightMap::new(grid, values).unwrap();
        let zone = CohesiveZone::new(work, work).unwrap();
        let mut solver = ContactSolver::new(
            &Substrate::half_space(rubber),
            &grid,
            Boundary::Periodic,
            SolverParams::default(),
        )
        .unwrap();
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                solver
                    .cohesive_pull_off(
                        &surface,
                        &zone,
                        0.6 * amplitude,
                        black_box(amplitude / 40.0),
                        None,
                        &mut (),
                    )
                    .unwrap()
                    .force
            })
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    bench_solver,
    bench_rough,
    bench_cohesive,
    bench_iteration
);
criterion_main!(benches);
