//! What a whole adhesive cycle costs, for `BENCHMARKS.md` ("Adhesive scene
//! cycles: error and cost"): a paraboloid (R = 10 mm) tilted so that its
//! contact centre moves by (0.3, 0.17) pull-off contact radii, on a rubber
//! half-space (E = 1 MPa, nu = 0.48, dgamma = 0.05 J/m^2), loaded in 6
//! steps to the JKR depth of 1.6 pull-off contact radii and unloaded to
//! contact loss, with `N` cells across the pull-off contact. A tilted
//! paraboloid is a paraboloid moved off the axis, so its pull-off is
//! JKR's `-3 pi R dgamma / 2` exactly, while its contact lies off the
//! cell centres.
//!
//! For each method (`cohesive`, `energy`, `mesh`) and `N` it prints the
//! pull-off error, the steps, the conjugate-gradient iterations of the
//! whole cycle, its time, and the cost in non-adhesive solves: the
//! iterations of one cold non-adhesive solve at the peak depth on the same
//! grid to the scene's tolerance (its coarse-grid iterations counted at a
//! quarter each, an upper bound of their cost). Until 2026-11-28 20:55 UTC
//! that solve ran to the solver's default tolerance, `1e-10`, against the
//! scene's `1e-8`: `BENCHMARKS.md` tables before then count in solves about
//! a fifth dearer (95.5 of them for the 64-cell cycle, 115.3 now).
//!
//! `cargo run --release --example adhesive_cycle_cost -- [method N...]...`,
//! for example `-- cohesive 16 32 64 mesh 16 32`; `STEPS=1` prints every
//! step (phase, depth, force, iterations, contact area); `FORCE=1` runs a
//! force cycle instead, to twice the pull-off force in 6 steps and back by
//! the same decrement to the jump-off (a grid sized for that peak);
//! `PLAIN=1` adds the cost of the cycle's depths (those that press in)
//! solved without adhesion, each from the last (with `STEPS=1` each
//! solve's fine and coarse iterations). `TOL=1e-6` sets the scene's solver
//! tolerance (default `1e-8`), to see what a looser one saves and costs in
//! accuracy.
use std::f64::consts::PI;
use std::time::Instant;

use layered_contact::indenter::{Indenter, Paraboloid, Tilted};
use layered_contact::scene::{AdhesionMethod, IndenterSpec};
use layered_contact::Result;

#[path = "support/tilted_cycle.rs"]
mod tilted_cycle;
use tilted_cycle::{jkr, RADIUS, WORK};

fn main() -> Result<()> {
    let jkr = jkr()?;
    let a = jkr.pull_off_contact_radius();
    let tilt = tilted_cycle::tilt()?;
    let exact = -1.5 * PI * RADIUS * WORK;
    println!("method    N   error %   steps  iterations  time s  non-adhesive solves");
    let mut method = AdhesionMethod::CohesiveZone;
    for arg in std::env::args().skip(1) {
        let Ok(n) = arg.parse::<usize>() else {
            method = match arg.as_str() {
                "energy" => AdhesionMethod::EnergyBalance,
                "mesh" => AdhesionMethod::MeshCriterion,
                _ => AdhesionMethod::CohesiveZone,
            };
            continue;
        };
        let mut scene =
            tilted_cycle::scene(IndenterSpec::Paraboloid { radius: RADIUS }, n, method)?;
        if let Some(tolerance) = std::env::var("TOL").ok().and_then(|t| t.parse().ok()) {
            scene.solver.tolerance = tolerance;
        }
        if std::env::var("FORCE").is_ok() {
            scene.protocol = layered_contact::scene::Protocol::ForceCycle {
                max_force: -2.0 * jkr.pull_off_force(),
                steps: 6,
            };
        }
        let clock = Instant::now();
        let mut solver = scene.solver()?;
        let curve = scene.run_on(&mut solver, &mut |_| {})?;
        let time = clock.elapsed().as_secs_f64();
        if std::env::var("STEPS").is_ok() {
            for s in &curve.steps {
                println!(
                    "  {:?} {:+.4e} {:+.5e} {:6} {}",
                    s.phase, s.depth, s.force, s.iterations, s.contact_area
                );
            }
        }
        let iterations: usize = curve.steps.iter().map(|s| s.iterations).sum();
        // One cold non-adhesive solve at the peak on the cycle's grid.
        let mut plain = layered_contact::solver::ContactSolver::new(
            &scene.substrate.build()?,
            &curve.grid,
            scene.boundary,
            layered_contact::solver::SolverParams {
                tolerance: scene.solver.tolerance,
                ..Default::default()
            },
        )?;
        let indenter = Tilted::new(Paraboloid::new(RADIUS)?, tilt.angle_y, tilt.angle_x)?;
        let peak = jkr.depth(1.6 * a);
        let one = plain
            .solve_depth(&indenter as &dyn Indenter, peak, None, &mut ())?
            .0;
        // A solve's cost in fine iterations, a coarse one counted a quarter.
        let weighted = |s: &layered_contact::solver::Solution| {
            s.iterations as f64 + s.coarse_iterations as f64 / 4.0
        };
        let cost = weighted(&one);
        println!(
            "{:<8} {n:4} {:+9.4} {:7} {:11} {:7.2} {:8.1} (one solve to {:e}: {} + {} coarse)",
            format!("{method:?}"),
            100.0 * (curve.pull_off().map_or(f64::NAN, |s| s.force) / exact - 1.0),
            curve.steps.len(),
            iterations,
            time,
            iterations as f64 / cost,
            scene.solver.tolerance,
            one.iterations,
            one.coarse_iterations,
        );
        if std::env::var("PLAIN").is_ok() {
            // The same depths without adhesion, each solve warm-started from
            // the one before, as a non-adhesive cycle would be run.
            let (mut warm, mut spent) = (None, 0.0);
            for s in curve.steps.iter().filter(|s| s.depth > 0.0) {
                let (solution, state) = plain.solve_depth(
                    &indenter as &dyn Indenter,
                    s.depth,
                    warm.as_ref(),
                    &mut (),
                )?;
                spent += weighted(&solution);
                if std::env::var("STEPS").is_ok() {
                    println!(
                        "    {:+.4e} {} + {}",
                        s.depth, solution.iterations, solution.coarse_iterations
                    );
                }
                warm = Some(state);
            }
            println!(
                "  the same depths without adhesion, warm: {:.1} non-adhesive solves",
                spent / cost
            );
        }
    }
    Ok(())
}
