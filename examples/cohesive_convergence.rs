//! The cohesive-zone adhesion ([`ContactSolver::solve_depth_cohesive`])
//! against exact JKR references, for `BENCHMARKS.md` ("Adhesion through a
//! resolved cohesive zone"): the pull-off of the JKR sphere on a half-space
//! (Johnson, Kendall & Roberts 1971) at `N` cells across its pull-off
//! contact, and of Johnson's (1995) sinusoid with its crests along the grid
//! and at 45 degrees at the same wavelength in cells.
//!
//! `cargo run --release --example cohesive_convergence -- [zone cells] [sphere N...] [-- sinusoid n...]`
//! Defaults: zone of 8 cells, sphere at 16 32 64, sinusoid at 181 362.
use std::f64::consts::PI;
use std::time::Instant;

use layered_contact::analytic::{JkrSinusoid, JkrSphere};
use layered_contact::indenter::{HeightMap, Sphere};
use layered_contact::solver::{CohesiveZone, ContactSolver, SolverParams};
use layered_contact::{Boundary, Grid, Material, Substrate};

fn main() -> Result<(), layered_contact::Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let split = args.iter().position(|a| a == "--").unwrap_or(args.len());
    let k: f64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(8.0);
    let mut spheres: Vec<usize> = args[1.min(split)..split]
        .iter()
        .filter_map(|a| a.parse().ok())
        .collect();
    let mut waves: Vec<usize> = args[(split + 1).min(args.len())..]
        .iter()
        .filter_map(|a| a.parse().ok())
        .collect();
    if split == args.len() && spheres.is_empty() {
        spheres = vec![16, 32, 64];
        waves = vec![181, 362];
    }
    let rubber = Material::new(1e6, 0.48)?;
    let work = 0.05;
    let zone = CohesiveZone::new(work, work)?.with_zone_cells(k)?;
    let jkr = JkrSphere::new(&rubber, 0.01, work)?;
    let a_po = jkr.pull_off_contact_radius();
    for n in spheres {
        let delta = 2.0 * a_po / n as f64;
        let cells = 2 * (4.0 * a_po / delta).ceil() as usize;
        let grid = Grid::square_of_side(cells, cells as f64 * delta)?;
        let mut solver = ContactSolver::new(
            &Substrate::half_space(rubber),
            &grid,
            Boundary::Isolated,
            SolverParams::default(),
        )?;
        let sphere = Sphere::new(0.01)?;
        let start = jkr.depth(1.6 * a_po);
        let step = jkr.critical_depth().abs() / 10.0;
        let clock = Instant::now();
        let p = solver.cohesive_pull_off(&sphere, &zone, start, step, None, &mut ())?;
        println!(
            "sphere, zone {k} cells, N = {n} ({cells}^2): error {:+.4} %, {} solves, {} iterations, {:.1} s",
            100.0 * (p.force / jkr.pull_off_force() - 1.0),
            p.solves,
            p.iterations,
            clock.elapsed().as_secs_f64()
        );
    }
    for n in waves {
        // Crests along the grid on n x n cells, and at 45 degrees on the
        // grid whose wavelength has the same length in cells (n sqrt 2).
        for (wave, cells) in [
            ((1usize, 0usize), n),
            ((1, 1), (n as f64 * 2f64.sqrt()).round() as usize),
        ] {
            let delta = 1e-5;
            let side = cells as f64 * delta;
            let wavelength = side / ((wave.0 * wave.0 + wave.1 * wave.1) as f64).sqrt();
            let estar = rubber.contact_modulus();
            let amplitude = (2.0 * wavelength * work / (PI * PI * estar)).sqrt() / 0.3;
            let exact = JkrSinusoid::new(&rubber, wavelength, amplitude, work)?;
            let grid = Grid::square_of_side(cells, side)?;
            let values = (0..grid.len())
                .map(|c| {
                    let (i, j) = (c / cells, c % cells);
                    let phase = ((wave.0 * i + wave.1 * j) % cells) as f64 / cells as f64;
                    amplitude * (1.0 - (2.0 * PI * phase).cos())
                })
                .collect();
            let map = HeightMap::new(grid, values)?;
            let mut solver = ContactSolver::new(
                &Substrate::half_space(rubber),
                &grid,
                Boundary::Periodic,
                SolverParams::default(),
            )?;
            let (exact_pull_off, _) = exact.pull_off()?;
            let clock = Instant::now();
            let p = solver.cohesive_pull_off(
                &map,
                &zone,
                0.6 * amplitude,
                amplitude / 40.0,
                None,
                &mut (),
            )?;
            println!(
                "sinusoid {wave:?}, zone {k} cells, {:.1} cells per wavelength ({cells}^2): error {:+.4} %, {} solves, {} iterations, {:.1} s",
                wavelength / delta,
                100.0 * (p.force / (side * side) / exact_pull_off - 1.0),
                p.solves,
                p.iterations,
                clock.elapsed().as_secs_f64()
            );
        }
    }
    Ok(())
}
