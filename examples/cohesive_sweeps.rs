//! Sweeps of the cohesive zone over coarse and awkward inputs, for
//! `BENCHMARKS.md` ("The cohesive zone on contacts it spans") and the
//! CHANGELOG: every case must end in a finite curve or a typed error.
//!
//! * `sinusoid`: Johnson's (1995) sinusoid along the grid and its diagonal
//!   on 32 / 64 / 128 cells a side, `alpha` 0.02 to 0.3, unloaded by
//!   [`ContactSolver::cohesive_pull_off`]: the pull-off's error, the widest
//!   patch of the contact at the least force and whether the zone spans it.
//! * `force`: force cycles of the rough film of
//!   `examples/scenes/rough_adhesive_film.toml` on 16^2 cells, seeds 1 to
//!   5, peaks 0.1 uN to 1 mN in 1 or 3 steps, with and without hysteresis.
//! * `depth`: displacement cycles of the same film, depths 1 nm to 3 um in
//!   1, 2 or 10 steps.
//!
//! `cargo run --release --example cohesive_sweeps -- sinusoid force depth`

use std::f64::consts::PI;

use layered_contact::analytic::JkrSinusoid;
use layered_contact::indenter::HeightMap;
use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Scene, SubstrateSpec};
use layered_contact::solver::{CohesiveZone, ContactSolver, SolverParams};
use layered_contact::topography::Amplitude;
use layered_contact::{Boundary, Error, Grid, Material, Substrate};

const WORK: f64 = 0.05;

/// Johnson's sinusoid along `(k, l)` on `n x n` cells, `alpha`: the
/// pull-off's relative error, the exact pull-off contact's width in lines
/// of cells, the zone's contact across at its least force, whether the
/// zone spans it.
fn sinusoid(k: usize, l: usize, n: usize, alpha: f64) -> Result<(f64, f64, f64, bool), Error> {
    let side = 64e-5;
    let rubber = Material::new(1e6, 0.48)?;
    let wavelength = side / ((k * k + l * l) as f64).sqrt();
    let amplitude = (2.0 * wavelength * WORK / (PI * PI * rubber.contact_modulus())).sqrt() / alpha;
    let exact = JkrSinusoid::new(&rubber, wavelength, amplitude, WORK)?;
    let grid = Grid::square_of_side(n, side)?;
    let columns = grid.columns();
    let values = (0..grid.len())
        .map(|c| {
            let (x, y) = grid.cell_centre(c / columns, c % columns);
            amplitude * (1.0 - (2.0 * PI * (k as f64 * x + l as f64 * y) / side).cos())
        })
        .collect();
    let map = HeightMap::new(grid, values)?;
    let substrate = Substrate::half_space(rubber);
    let params = SolverParams::default();
    let mut solver = ContactSolver::new(&substrate, &grid, Boundary::Periodic, params)?;
    let target = exact.mean_pressure(0.6 * wavelength / PI) * side * side;
    let (start, _) = solver.solve_force(&map, target, None, &mut ())?;
    let zone = CohesiveZone::new(WORK, WORK)?;
    let pull_off =
        solver.cohesive_pull_off(&map, &zone, start.depth, amplitude / 100.0, None, &mut ())?;
    let (pressure, half_width) = exact.pull_off()?;
    let error = pull_off.force / (side * side) / pressure - 1.0;
    let lines = 2.0 * half_width / wavelength * n as f64;
    Ok((
        error,
        lines,
        pull_off.cells_across,
        pull_off.zone_spans_contact(),
    ))
}

/// The rough adhesive film on 16 cells a side of `seed`, with hysteresis
/// (0.01 / 0.05 J/m^2) or without (0.05), under `protocol`.
fn rough_film(seed: u64, hysteresis: bool, protocol: Protocol) -> Scene {
    let (cells, spacing) = (16, 2e-5);
    Scene {
        boundary: Boundary::Periodic,
        substrate: SubstrateSpec::LayerOnRigidBase {
            youngs_modulus: 1e6,
            poisson_ratio: 0.48,
            thickness: 2e-4,
        },
        indenter: IndenterSpec::RoughSurface {
            hurst: 0.8,
            amplitude: Amplitude::RmsHeight(1e-6),
            long_cutoff: 2.5e-4,
            short_cutoff: 4.0 * spacing,
            seed,
            cells,
            spacing,
        },
        adhesion: if hysteresis {
            Adhesion::Hysteresis {
                loading: 0.01,
                unloading: WORK,
            }
        } else {
            Adhesion::Constant {
                work_of_adhesion: WORK,
            }
        },
        protocol,
        ..Scene::default()
    }
}

/// Runs the film's scenes of `protocols`, printing each outcome and the
/// tally.
fn films(protocols: &[Protocol]) {
    let (mut ran, mut refused) = (0, 0);
    for seed in 1..=5 {
        for protocol in protocols {
            for hysteresis in [false, true] {
                match rough_film(seed, hysteresis, *protocol).run(&mut |_| {}) {
                    Ok(curve) => {
                        ran += 1;
                        let pull_off = curve.pull_off().map(|p| p.force);
                        println!("seed {seed} {protocol:?} hysteresis {hysteresis}: {pull_off:?}");
                    }
                    Err(e) => {
                        refused += 1;
                        println!("seed {seed} {protocol:?} hysteresis {hysteresis}: {e}");
                    }
                }
            }
        }
    }
    println!("{ran} ran, {refused} ended with an error\n");
}

fn main() -> Result<(), Error> {
    for sweep in std::env::args().skip(1) {
        match sweep.as_str() {
            "sinusoid" => {
                println!(
                    "| direction | N | alpha | exact lines | contact across | zone spans | error |"
                );
                println!("|---|---|---|---|---|---|---|");
                for (k, l) in [(1, 0), (1, 1)] {
                    for n in [32, 64, 128] {
                        for alpha in [0.02, 0.05, 0.1, 0.2, 0.3] {
                            let (error, lines, across, spans) = sinusoid(k, l, n, alpha)?;
                            println!(
                                "| ({k}, {l}) | {n} | {alpha} | {lines:.2} | {across} | {spans} | {:+.3} % |",
                                100.0 * error
                            );
                        }
                    }
                }
            }
            "force" => {
                let mut protocols = Vec::new();
                for max_force in [1e-7, 1e-6, 1e-5, 1e-4, 1e-3] {
                    for steps in [1, 3] {
                        protocols.push(Protocol::ForceCycle { max_force, steps });
                    }
                }
                films(&protocols);
            }
            "depth" => {
                let mut protocols = Vec::new();
                for max_depth in [1e-9, 1e-8, 1e-7, 3e-7, 1e-6, 3e-6] {
                    for steps in [1, 2, 10] {
                        protocols.push(Protocol::Cycle { max_depth, steps });
                    }
                }
                films(&protocols);
            }
            other => eprintln!("unknown sweep {other:?}: sinusoid, force or depth"),
        }
    }
    Ok(())
}
