//! A seeded rough surface pressed into a rubber film on glass and pulled
//! off with adhesion hysteresis, through the cohesive zone
//! ([`ContactSolver::solve_depth_cohesive`]): the contact splits into
//! patches, which the energy balance cannot follow. Prints the force,
//! contact area and bonded cells per step, the pull-off force (the least
//! force of the steps, then searched between its neighbours by
//! [`ContactSolver::cohesive_pull_off`]) and the energy the cycle
//! dissipates (the area of the force-depth loop), beside the
//! mesh-dependent criterion (Pohrt & Popov 2015) on the same grid. Numbers
//! in `BENCHMARKS.md` ("Adhesion through a resolved cohesive zone").
//!
//! ```text
//! cargo run --release --example rough_cohesive_cycle -- [cells] [--refine-from BASE] [--zone-length L] [--zone-only]
//! ```
//!
//! `cells` defaults to 128. With `--refine-from BASE` the surface is
//! synthesised on `BASE x BASE` cells and interpolated onto `cells x
//! cells` ([`HeightMap::refined`]): the same surface on every grid, for a
//! convergence study (a synthesis on each grid draws a new surface).
//! `--zone-length L` makes the cohesive zone `L` metres long on every grid
//! (`L / Delta` cells, [`CohesiveZone::with_zone_cells`]; by default it is
//! four cells, shorter on finer grids): refined at a fixed zone, the cycle
//! converges to the cohesive law's own solution; with four cells the zone
//! shortens with the cell too, towards the JKR limit, which this surface
//! does not reach on these grids (`BENCHMARKS.md`). `--zone-only` leaves
//! out the mesh criterion.
use std::time::Instant;

use layered_contact::indenter::HeightMap;
use layered_contact::solver::{CohesiveZone, ContactSolver, SolverParams, WarmStart};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Boundary, Error, Grid, Material, Substrate};

fn main() -> Result<(), Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let option = |name: &str| args.iter().position(|a| a == name);
    let cells: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(128);
    let base: usize = option("--refine-from")
        .and_then(|k| args.get(k + 1))
        .and_then(|a| a.parse().ok())
        .unwrap_or(cells);
    let zone_only = option("--zone-only").is_some();
    let zone_length: Option<f64> = option("--zone-length")
        .and_then(|k| args.get(k + 1))
        .and_then(|a| a.parse().ok());
    if base == 0 || !cells.is_multiple_of(base) {
        return Err(Error::InvalidParameter {
            name: "cells over --refine-from",
            value: cells as f64 / base as f64,
            expected: "a whole number",
        });
    }
    let side = 3.2e-4;
    let grid = Grid::square_of_side(cells, side)?;
    let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.48)?, 2e-4)?;
    let synthesised: HeightMap = SelfAffine {
        hurst: 0.8,
        amplitude: Amplitude::RmsHeight(1e-6),
        long_cutoff: 2.5e-4,
        short_cutoff: 2e-5,
        seed: 3,
    }
    .indenter(&Grid::square_of_side(base, side)?)?;
    let surface = synthesised.refined(cells / base)?;
    let (advancing, receding) = (0.01, 0.05);
    let zone = match zone_length {
        Some(length) => {
            CohesiveZone::new(advancing, receding)?.with_zone_cells(length / grid.spacing())?
        }
        None => CohesiveZone::new(advancing, receding)?,
    };
    let mut solver = ContactSolver::new(&film, &grid, Boundary::Periodic, SolverParams::default())?;
    let lowest = solver.lowest_height(&surface)?;
    let (max_depth, steps) = (3e-6, 20);
    let step = max_depth / steps as f64;
    let methods: &[&str] = if zone_only {
        &["cohesive zone"]
    } else {
        &["cohesive zone", "mesh criterion"]
    };
    for &method in methods {
        let clock = Instant::now();
        let mut warm: Option<WarmStart> = None;
        let mut curve = Vec::new();
        // The states after the unloading steps, to search the pull-off from.
        let mut unloading: Vec<WarmStart> = Vec::new();
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
            if k >= steps {
                unloading.push(end.clone());
            }
            warm = Some(end);
            if lost {
                break;
            }
        }
        // The least force of the unloading steps (`curve[steps..]`), then
        // searched between its neighbours from the step before it.
        let least = (steps..curve.len())
            .min_by(|&a, &b| curve[a].1.total_cmp(&curve[b].1))
            .unwrap_or(steps);
        let stepped = curve[least].1;
        let pull_off = if method == "cohesive zone" && least > steps {
            let from = least - 1;
            let searched = solver.cohesive_pull_off(
                &surface,
                &zone,
                curve[from].0,
                step,
                Some(&unloading[from - steps]),
                &mut (),
            )?;
            iterations += searched.iterations;
            searched.force.min(stepped)
        } else {
            stepped
        };
        // The loop's area: the work done on the way in less the work given
        // back on the way out (trapezoids along the path).
        let dissipated: f64 = curve
            .windows(2)
            .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
            .sum();
        println!(
            "{method} on {cells}^2 (surface of {base}^2): pull-off {pull_off:.5e} N (least step \
             {stepped:.5e}), dissipated {dissipated:.5e} J, {} steps, {iterations} iterations, \
             {:.1} s",
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
