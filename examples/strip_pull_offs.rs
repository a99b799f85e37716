//! The energy balance's pull-off of Johnson's (1995) adhesive sinusoid on
//! coarse periodic grids, for `BENCHMARKS.md` ("Pull-offs of coarse
//! strips"): every direction, grid and adhesion parameter of the sweep
//! either within a few per cent of the exact pull-off
//! ([`JkrSinusoid`]) or refused with a typed error.
//!
//! A rubber half-space (E = 1 MPa, nu = 0.48, dgamma = 0.05 J/m^2) under
//! `h0 (1 - cos 2 pi (k x + l y) / L)` on an `N x N` periodic square of side
//! `L` (wavelength `L / sqrt(k^2 + l^2)`), loaded under force control to
//! strips 0.38 of the wavelength wide, `alpha` Johnson's adhesion
//! parameter. Prints one line per accepted case (its error and the exact
//! pull-off contact's width in lines of cells), then the counts of
//! accepted and refused cases and the worst accepted error.
//!
//! `cargo run --release --example strip_pull_offs`

use std::f64::consts::PI;

use layered_contact::analytic::JkrSinusoid;
use layered_contact::indenter::HeightMap;
use layered_contact::solver::{ContactSolver, Reach, SolverParams};
use layered_contact::{Boundary, Error, Grid, Material, Substrate};

const WORK: f64 = 0.05;
const SIDE: f64 = 64e-5;

/// The pull-off's relative error of the sinusoid along `(k, l)` on `n x n`
/// cells at adhesion parameter `alpha`, and the exact pull-off contact's
/// width in lines of cells.
fn pull_off(k: usize, l: usize, n: usize, alpha: f64) -> Result<(f64, f64), Error> {
    let rubber = Material::new(1e6, 0.48)?;
    let wavelength = SIDE / ((k * k + l * l) as f64).sqrt();
    let amplitude = (2.0 * wavelength * WORK / (PI * PI * rubber.contact_modulus())).sqrt() / alpha;
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
    let mut solver = ContactSolver::new(&substrate, &grid, Boundary::Periodic, params)?;
    let target = exact.mean_pressure(0.6 * wavelength / PI) * SIDE * SIDE;
    let branches = solver.adhesive_branches(&map, Reach::Force(target), WORK, WORK, &mut ())?;
    let peak = branches.at_force(target, 0.0)?;
    let force = branches.pull_off(peak.contact_area)?.force;
    let (pressure, half_width) = exact.pull_off()?;
    // Lines of cells along the wave's normal: N per wavelength.
    let lines = 2.0 * half_width / wavelength * n as f64;
    Ok((force / (SIDE * SIDE) / pressure - 1.0, lines))
}

fn main() -> Result<(), Error> {
    let (mut accepted, mut refused, mut worst) = (0, 0, 0.0f64);
    println!("| direction | N | alpha | lines across the pull-off | error |");
    println!("|---|---|---|---|---|");
    for (k, l) in [(1, 0), (1, 1), (2, 1)] {
        for n in [32, 64, 128] {
            for alpha in [0.02, 0.05, 0.08, 0.1, 0.12, 0.14, 0.17, 0.2, 0.25, 0.3] {
                match pull_off(k, l, n, alpha) {
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
        "\n{accepted} accepted, {refused} refused; worst accepted error {:.2} %",
        100.0 * worst
    );
    Ok(())
}
