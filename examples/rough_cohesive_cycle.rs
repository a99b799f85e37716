//! A seeded rough surface pressed into a rubber film on glass and pulled
//! off with adhesion hysteresis, through the cohesive zone
//! ([`ContactSolver::solve_depth_cohesive`]): the contact splits into
//! patches, which the energy balance cannot follow. Prints the force,
//! contact area and bonded cells per step, the pull-off force and the
//! energy the cycle dissipates (the area of the force-depth loop), beside
//! the mesh-dependent criterion (Pohrt & Popov 2015) on the same grid.
//! Numbers in `BENCHMARKS.md` ("Adhesion through a resolved cohesive
//! zone").
//!
//! `cargo run --release --example rough_cohesive_cycle -- [cells]` (default 128)
use std::time::Instant;

use layered_contact::solver::{CohesiveZone, ContactSolver, SolverParams, WarmStart};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Boundary, Grid, Material, Substrate};

fn main() -> Result<(), layered_contact::Error> {
    let cells: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(128);
    let side = 3.2e-4;
    let grid = Grid::square_of_side(cells, side)?;
    let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.48)?, 2e-4)?;
    let surface = SelfAffine {
        hurst: 0.8,
        amplitude: Amplitude::RmsHeight(1e-6),
        long_cutoff: 2.5e-4,
        short_cutoff: 2e-5,
        seed: 3,
    }
    .indenter(&grid)?;
    let (advancing, receding) = (0.01, 0.05);
    let zone = CohesiveZone::new(advancing, receding)?;
    let mut solver = ContactSolver::new(&film, &grid, Boundary::Periodic, SolverParams::default())?;
    let lowest = solver.lowest_height(&surface)?;
    let (max_depth, steps) = (3e-6, 20);
    let step = max_depth / steps as f64;
    for method in ["cohesive zone", "mesh criterion"] {
        let clock = Instant::now();
        let mut warm: Option<WarmStart> = None;
        let mut curve = Vec::new();
        let mut iterations = 0;
        // Loading to the peak, then unloading until the contact is lost
        // (at most as far below first contact as the peak is above it).
        let depths = (0..=steps)
            .chain((0..steps).rev())
            .map(|k| lowest + k as f64 * step)
            .chain((1..=steps).map(|k| lowest - k as f64 * step));
        for (k, depth) in depths.enumerate() {
            let (solution, end) = match method {
                "cohesive zone" => {
                    solver.solve_depth_cohesive(&surface, depth, &zone, warm.as_ref(), &mut ())?
                }
                _ => solver.solve_depth_hysteretic(
                    &surface,
                    depth,
                    advancing,
                    receding,
                    warm.as_ref(),
                    &mut (),
                )?,
            };
            iterations += solution.iterations;
            let lost = k > steps && solution.contact_cells == 0 && solution.force.abs() == 0.0;
            curve.push((depth, solution.force, solution.contact_area));
            warm = Some(end);
            if lost {
                break;
            }
        }
        let pull_off = curve.iter().map(|c| c.1).fold(f64::INFINITY, f64::min);
        // The loop's area: the work done on the way in less the work given
        // back on the way out (trapezoids along the path).
        let dissipated: f64 = curve
            .windows(2)
            .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
            .sum();
        println!(
            "{method} on {cells}^2: pull-off {pull_off:.4e} N, dissipated {dissipated:.4e} J, \
             {} steps, {iterations} iterations, {:.1} s",
            curve.len(),
            clock.elapsed().as_secs_f64()
        );
        for (depth, force, area) in &curve {
            println!(
                "  depth {:+.3e} m  force {:+.4e} N  contact {:.3} %",
                depth - lowest,
                force,
                100.0 * area / (side * side)
            );
        }
    }
    Ok(())
}
