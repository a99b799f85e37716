//! Sweeps of the adhesion methods over coarse and awkward inputs, for
//! `BENCHMARKS.md` ("Pull-offs of coarse strips", "The cohesive zone on
//! contacts it spans") and the CHANGELOG: every case must end in a finite
//! answer or a typed error.
//!
//! Johnson's (1995) adhesive sinusoid `h0 (1 - cos 2 pi (k x + l y) / L)`
//! on an `N x N` periodic square of side `L` (wavelength
//! `L / sqrt(k^2 + l^2)`) on a rubber half-space (E = 1 MPa, nu = 0.48,
//! dgamma = 0.05 J/m^2), against [`JkrSinusoid`]:
//!
//! * `strips`: the energy balance, loaded under force control to strips
//!   0.38 of the wavelength wide, along the grid, its diagonal and `(2, 1)`
//!   on 32 / 64 / 128 cells, `alpha` 0.02 to 0.3: each case within a few
//!   per cent of the exact pull-off or refused with a typed error;
//! * `sinusoid`: the cohesive zone ([`ContactSolver::cohesive_pull_off`])
//!   along the grid and its diagonal: the pull-off's error, the widest
//!   patch of the contact at the least force and whether the zone spans it.
//!
//! The rough film of `examples/scenes/rough_adhesive_film.toml` on 16^2
//! cells, seeds 1 to 5, with and without hysteresis, through the cohesive
//! zone:
//!
//! * `force`: force cycles to 0.1 uN to 1 mN in 1 or 3 steps;
//! * `depth`: displacement cycles to 1 nm to 3 um in 1, 2 or 10 steps.
//!
//! `cargo run --release --example adhesion_sweeps -- strips sinusoid force depth`

use std::f64::consts::PI;

use layered_contact::analytic::JkrSinusoid;
use layered_contact::indenter::HeightMap;
use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Scene, SubstrateSpec};
use layered_contact::solver::{CohesiveZone, ContactSolver, Reach, SolverParams};
use layered_contact::topography::Amplitude;
use layered_contact::{Boundary, Error, Grid, Material, Substrate};

const WORK: f64 = 0.05;
const SIDE: f64 = 64e-5;

/// Johnson's sinusoid along `(k, l)` on `n x n` periodic cells at adhesion
/// parameter `alpha`, with a solver on its grid.
struct Sinusoid {
    map: HeightMap,
    solver: ContactSolver,
    exact: JkrSinusoid,
    wavelength: f64,
    amplitude: f64,
    /// The force (N) of strips 0.38 of the wavelength wide.
    target: f64,
    n: usize,
}

impl Sinusoid {
    fn new(k: usize, l: usize, n: usize, alpha: f64) -> Result<Self, Error> {
        let rubber = Material::new(1e6, 0.48)?;
        let wavelength = SIDE / ((k * k + l * l) as f64).sqrt();
        let amplitude =
            (2.0 * wavelength * WORK / (PI * PI * rubber.contact_modulus())).sqrt() / alpha;
        let exact = JkrSinusoid::new(&rubber, wavelength, amplitude, WORK)?;
        let grid = Grid::square_of_side(n, SIDE)?;
        let columns = grid.columns();
        let values = (0..grid.len())
            .map(|c| {
                let (x, y) = grid.cell_centre(c / columns, c % columns);
                amplitude * (1.0 - (2.0 * PI * (k as f64 * x + l as f64 * y) / SIDE).cos())
            })
            .collect();
        let map = HeightMap::new(grid, values)?;
        let substrate = Substrate::half_space(rubber);
        let params = SolverParams::default();
        let solver = ContactSolver::new(&substrate, &grid, Boundary::Periodic, params)?;
        let target = exact.mean_pressure(0.6 * wavelength / PI) * SIDE * SIDE;
        Ok(Sinusoid {
            map,
            solver,
            exact,
            wavelength,
            amplitude,
            target,
            n,
        })
    }

    /// The relative error of a pull-off force (N), and the exact pull-off
    /// contact's width in lines of cells along the wave's normal (`N` a
    /// wavelength).
    fn error(&self, force: f64) -> Result<(f64, f64), Error> {
        let (pressure, half_width) = self.exact.pull_off()?;
        let lines = 2.0 * half_width / self.wavelength * self.n as f64;
        Ok((force / (SIDE * SIDE) / pressure - 1.0, lines))
    }

    /// The energy balance's pull-off: its error and width.
    fn energy_balance(&mut self) -> Result<(f64, f64), Error> {
        let reach = Reach::Force(self.target);
        let branches = self
            .solver
            .adhesive_branches(&self.map, reach, WORK, WORK, &mut ())?;
        let peak = branches.at_force(self.target, 0.0)?;
        self.error(branches.pull_off(peak.contact_area)?.force)
    }

    /// The cohesive zone's pull-off (four cells, unloaded in steps of a
    /// hundredth of the amplitude from the non-adhesive contact at the
    /// target): its error and width, the widest patch of its contact in
    /// cells across and whether the zone spans it.
    fn cohesive(&mut self) -> Result<(f64, f64, f64, bool), Error> {
        let (start, _) = self
            .solver
            .solve_force(&self.map, self.target, None, &mut ())?;
        let zone = CohesiveZone::new(WORK, WORK)?;
        let step = self.amplitude / 100.0;
        let pull_off =
            self.solver
                .cohesive_pull_off(&self.map, &zone, start.depth, step, None, &mut ())?;
        let (error, lines) = self.error(pull_off.force)?;
        Ok((
            error,
            lines,
            pull_off.cells_across,
            pull_off.zone_spans_contact(),
        ))
    }
}

/// The energy balance's table over directions, grids and `alpha`, then the
/// counts of accepted and refused cases and the worst accepted error.
fn strips() -> Result<(), Error> {
    let (mut accepted, mut refused, mut worst) = (0, 0, 0.0f64);
    println!("| direction | N | alpha | lines across the pull-off | error |");
    println!("|---|---|---|---|---|");
    for (k, l) in [(1, 0), (1, 1), (2, 1)] {
        for n in [32, 64, 128] {
            for alpha in [0.02, 0.05, 0.08, 0.1, 0.12, 0.14, 0.17, 0.2, 0.25, 0.3] {
                match Sinusoid::new(k, l, n, alpha)?.energy_balance() {
                    Ok((error, lines)) => {
                        accepted += 1;
                        worst = worst.max(error.abs());
                        println!(
                            "| ({k}, {l}) | {n} | {alpha} | {lines:.2} | {:+.3} % |",
                            100.0 * error
                        );
                    }
                    Err(Error::Unsupported { .. }) => refused += 1,
                    Err(other) => return Err(other),
                }
            }
        }
    }
    println!(
        "\n{accepted} accepted, {refused} refused; worst accepted error {:.2} %\n",
        100.0 * worst
    );
    Ok(())
}

/// The cohesive zone's table over directions, grids and `alpha`.
fn sinusoids() -> Result<(), Error> {
    println!("| direction | N | alpha | exact lines | contact across | zone spans | error |");
    println!("|---|---|---|---|---|---|---|");
    for (k, l) in [(1, 0), (1, 1)] {
        for n in [32, 64, 128] {
            for alpha in [0.02, 0.05, 0.1, 0.2, 0.3] {
                let (error, lines, across, spans) = Sinusoid::new(k, l, n, alpha)?.cohesive()?;
                println!(
                    "| ({k}, {l}) | {n} | {alpha} | {lines:.2} | {across} | {spans} | {:+.3} % |",
                    100.0 * error
                );
            }
        }
    }
    println!();
    Ok(())
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
            "strips" => strips()?,
            "sinusoid" => sinusoids()?,
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
            other => eprintln!("unknown sweep {other:?}: strips, sinusoid, force or depth"),
        }
    }
    Ok(())
}
