//! The cohesive-zone adhesion ([`ContactSolver::solve_depth_cohesive`])
//! against exact JKR references, for `BENCHMARKS.md` ("Adhesion through a
//! resolved cohesive zone"): pull-off errors against the resolution for
//!
//! * `sphere`: the JKR sphere on a half-space (Johnson, Kendall & Roberts
//!   1971), `N` cells across the pull-off contact;
//! * `layer`: the same sphere on a rubber film on a rigid base as thick as
//!   the half-space's pull-off contact radius, against the exact layered
//!   JKR pull-off ([`Axisymmetric`](layered_contact::analytic::Axisymmetric));
//!   `FILM_RATIO=r` in the environment makes the film `r` times thinner;
//! * `stack`: the same sphere on a stack, the rubber film of `layer` on a
//!   layer ten times stiffer and twice as thick on a rigid base, against the
//!   exact stacked JKR pull-off (the same `Axisymmetric` reference);
//! * `punch`: Kendall's flat punch (1971), `N` cells across, against the
//!   punch of the staircase's area;
//! * `ellipse`: an elliptic paraboloid (radii 10 and 20 mm) on the
//!   half-space, `N` cells across the short axis of a 0.46 mm pull-off
//!   contact, beside the energy balance on the same grid (no exact
//!   reference: the two methods' difference);
//! * `sinusoid`: Johnson's (1995) sinusoid, `alpha = 0.3`, `N` cells per
//!   wavelength with the crests along the grid (`N^2` cells) and at 45
//!   degrees (`(N sqrt 2)^2` cells);
//! * `strip`: the same sinusoid along the grid on `N x 8` cells (a straight
//!   edge along the grid, cheap enough for thousands of cells per
//!   wavelength).
//!
//! `cargo run --release --example cohesive_convergence -- [zone cells | auto] [case N...]...`,
//! for example `-- 8 sphere 16 32 64 punch 16 32 sinusoid 128 181`; `auto`
//! grows the zone with the cells across the pull-off contact
//! ([`CohesiveZone::with_resolution`]; the sinusoid's contact from its exact
//! pull-off half-width).
use std::f64::consts::PI;
use std::time::Instant;

use layered_contact::analytic::{Axisymmetric, JkrFlatPunch, JkrSinusoid, JkrSphere};
use layered_contact::indenter::{FlatPunch, HeightMap, Sphere};
use layered_contact::solver::{CohesiveZone, ContactSolver, Reach, SolverParams};
use layered_contact::{Base, Boundary, Grid, Material, Result, Substrate};

const WORK: f64 = 0.05;
const RADIUS: f64 = 0.01;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    // `auto`: the zone grown with the resolution (`CohesiveZone::with_resolution`).
    let auto = args.first().is_some_and(|a| a == "auto");
    let k: f64 = args
        .first()
        .and_then(|a| a.parse().ok())
        .unwrap_or(if auto { 4.0 } else { 8.0 });
    // CURVATURE_CORRECTION=c overrides the default (0 turns it off).
    let correction: f64 = std::env::var("CURVATURE_CORRECTION")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(layered_contact::solver::CURVATURE_CORRECTION);
    let base = CohesiveZone::new(WORK, WORK)?
        .with_zone_cells(k)?
        .with_curvature_correction(correction)?;
    let rubber = Material::new(1e6, 0.48)?;
    let mut case = String::new();
    for arg in args.iter().skip(1) {
        let Ok(n) = arg.parse::<usize>() else {
            case = arg.clone();
            continue;
        };
        let clock = Instant::now();
        // The zone for `n` cells across the pull-off contact.
        let zone = if auto {
            base.with_resolution(n as f64)?
        } else {
            base
        };
        let k = zone.zone_cells();
        match case.as_str() {
            "sphere" | "layer" | "stack" => {
                let jkr = JkrSphere::new(&rubber, RADIUS, WORK)?;
                let a = jkr.pull_off_contact_radius();
                let (substrate, exact) = if case == "sphere" {
                    (Substrate::half_space(rubber), jkr.pull_off_force())
                } else if case == "stack" {
                    let stiffer = Material::new(1e7, 0.3)?;
                    let stack = Substrate::stack(&[(rubber, a), (stiffer, 2.0 * a)], Base::Rigid)?;
                    let body = Axisymmetric::up_to_contact_radius(&stack, 4.0 * a)?;
                    let exact = body.paraboloid(RADIUS, WORK)?.pull_off()?.load_control;
                    (stack, exact.force)
                } else {
                    // FILM_RATIO=r makes the film a / r thick (default 1).
                    let ratio: f64 = std::env::var("FILM_RATIO")
                        .ok()
                        .and_then(|r| r.parse().ok())
                        .unwrap_or(1.0);
                    let film = Substrate::layer_on_rigid_base(rubber, a / ratio)?;
                    let body = Axisymmetric::up_to_contact_radius(&film, 4.0 * a)?;
                    let exact = body.paraboloid(RADIUS, WORK)?.pull_off()?.load_control;
                    (film, exact.force)
                };
                let delta = 2.0 * a / n as f64;
                let cells = 2 * (4.0 * a / delta).ceil() as usize;
                let grid = Grid::square_of_side(cells, cells as f64 * delta)?;
                let mut solver = ContactSolver::new(
                    &substrate,
                    &grid,
                    Boundary::Isolated,
                    SolverParams::default(),
                )?;
                let step = jkr.critical_depth().abs() / 10.0;
                let start = jkr.depth(1.6 * a);
                let p = solver.cohesive_pull_off(
                    &Sphere::new(RADIUS)?,
                    &zone,
                    start,
                    step,
                    None,
                    &mut (),
                )?;
                report(
                    &case,
                    k,
                    n,
                    &format!("{cells}^2"),
                    p.force / exact - 1.0,
                    p.solves,
                    p.iterations,
                    clock,
                );
            }
            "punch" => {
                let a = 1e-3;
                let delta = 2.0 * a / n as f64;
                let cells = n + 4;
                let grid = Grid::square_of_side(cells, cells as f64 * delta)?;
                let face = (0..grid.len())
                    .filter(|&c| {
                        let (x, y) = grid.cell_centre(c / cells, c % cells);
                        x * x + y * y <= a * a
                    })
                    .count();
                let equal_area = (face as f64 * delta * delta / PI).sqrt();
                let exact = JkrFlatPunch::new(&rubber, equal_area, WORK)?;
                let mut solver = half_space(&rubber, &grid, Boundary::Isolated)?;
                let dc = exact.critical_depth().abs();
                // `cohesive_pull_off` refuses it (pinned at the rim); the
                // bias it would carry, from an unloading in steps of
                // dc / 160 to the first rise of the force.
                let punch = FlatPunch::new(a)?;
                if let Err(e) =
                    solver.cohesive_pull_off(&punch, &zone, 0.3 * dc, dc / 20.0, None, &mut ())
                {
                    println!("{case:16} zone {k:>4} cells  N {n:>4}: {e}");
                }
                let (mut lowest, mut warm, mut solves, mut iterations) =
                    (f64::INFINITY, None, 0, 0);
                for step in 0..10_000 {
                    let depth = 0.3 * dc - step as f64 * dc / 160.0;
                    let (s, end) = solver.solve_depth_cohesive(
                        &punch,
                        depth,
                        &zone,
                        warm.as_ref(),
                        &mut (),
                    )?;
                    (solves, iterations) = (solves + 1, iterations + s.iterations);
                    warm = Some(end);
                    if s.force > lowest || s.contact_cells == 0 {
                        break;
                    }
                    lowest = s.force;
                }
                let error = lowest / exact.pull_off_force() - 1.0;
                report(
                    "punch (walked)",
                    k,
                    n,
                    &format!("{cells}^2"),
                    error,
                    solves,
                    iterations,
                    clock,
                );
            }
            "ellipse" => {
                let (rx, ry) = (0.01, 0.02);
                let delta = 0.46e-3 / n as f64;
                let cells = 4 * n;
                let grid = Grid::square_of_side(cells, cells as f64 * delta)?;
                let values = (0..grid.len())
                    .map(|c| {
                        let (x, y) = grid.cell_centre(c / cells, c % cells);
                        x * x / (2.0 * rx) + y * y / (2.0 * ry)
                    })
                    .collect();
                let map = HeightMap::new(grid, values)?;
                let mut solver = half_space(&rubber, &grid, Boundary::Isolated)?;
                // The sphere of the same mean curvature for the depths.
                let jkr = JkrSphere::new(&rubber, (rx * ry).sqrt(), WORK)?;
                let start = jkr.depth(1.5 * jkr.pull_off_contact_radius());
                let step = jkr.critical_depth().abs() / 10.0;
                let p = solver.cohesive_pull_off(&map, &zone, start, step, None, &mut ())?;
                let branches =
                    solver.adhesive_branches(&map, Reach::Depth(start), WORK, WORK, &mut ())?;
                let peak = branches.at_depth(start, 0.0)?;
                let balance = branches.pull_off(peak.contact_area)?.force;
                println!(
                    "ellipse          zone {k:>4} cells  N {n:>4} ({cells}^2)  cohesive {:.6e} N, energy balance {:.6e} N, difference {:+.4} %  {} solves  {:.1} s",
                    p.force,
                    balance,
                    100.0 * (p.force / balance - 1.0),
                    p.solves,
                    clock.elapsed().as_secs_f64()
                );
            }
            "sinusoid" => {
                for (wave, cells) in [
                    ((1, 0), n),
                    ((1, 1), (n as f64 * 2f64.sqrt()).round() as usize),
                ] {
                    let clock = Instant::now();
                    let (error, solves, iterations, k) =
                        sinusoid(&rubber, &base, auto, wave, (cells, cells))?;
                    let name = if wave == (1, 0) {
                        "sinusoid along"
                    } else {
                        "sinusoid 45 deg"
                    };
                    let grid = format!("{cells}^2");
                    report(name, k, n, &grid, error, solves, iterations, clock);
                }
            }
            "strip" => {
                // Crests along the grid on a strip eight cells wide.
                let (error, solves, iterations, k) =
                    sinusoid(&rubber, &base, auto, (1, 0), (n, 8))?;
                let grid = format!("{n} x 8");
                report("strip along", k, n, &grid, error, solves, iterations, clock);
            }
            other => println!("unknown case {other:?}"),
        }
    }
    Ok(())
}

/// A solver for the rubber half-space on `grid`.
fn half_space(rubber: &Material, grid: &Grid, boundary: Boundary) -> Result<ContactSolver> {
    ContactSolver::new(
        &Substrate::half_space(*rubber),
        grid,
        boundary,
        SolverParams::default(),
    )
}

#[allow(clippy::too_many_arguments)]
fn report(
    case: &str,
    k: f64,
    n: usize,
    grid: &str,
    error: f64,
    solves: usize,
    iterations: usize,
    clock: Instant,
) {
    println!(
        "{case:16} zone {k:>5.2} cells  N {n:>4} ({grid})  error {:+.4} %  {solves} solves  {iterations} iterations  {:.1} s",
        100.0 * error,
        clock.elapsed().as_secs_f64()
    );
}

/// The pull-off error of Johnson's sinusoid with wave vector `wave` (in
/// waves along the rows and the columns) on `rows x columns` periodic
/// cells, its solves, iterations and zone's cells (with `auto`, grown
/// with the cells across the pull-off contact's width).
fn sinusoid(
    rubber: &Material,
    base: &CohesiveZone,
    auto: bool,
    wave: (usize, usize),
    (rows, columns): (usize, usize),
) -> Result<(f64, usize, usize, f64)> {
    let delta = 1e-5;
    let grid = Grid::new(rows, columns, delta)?;
    let wavelength = HeightMap::wavy_wavelength(&grid, wave)?;
    let amplitude = (2.0 * wavelength * WORK / (PI * PI * rubber.contact_modulus())).sqrt() / 0.3;
    let exact = JkrSinusoid::new(rubber, wavelength, amplitude, WORK)?;
    let map = HeightMap::wavy(grid, wave, amplitude)?;
    let mut solver = half_space(rubber, &grid, Boundary::Periodic)?;
    let (pull_off, half_width) = exact.pull_off()?;
    let zone = if auto {
        base.with_resolution(2.0 * half_width / delta)?
    } else {
        *base
    };
    let p = solver.cohesive_pull_off(
        &map,
        &zone,
        0.6 * amplitude,
        amplitude / 40.0,
        None,
        &mut (),
    )?;
    let area = grid.len() as f64 * grid.cell_area();
    Ok((
        p.force / area / pull_off - 1.0,
        p.solves,
        p.iterations,
        zone.zone_cells(),
    ))
}
