//! Adhesion through a cohesive zone resolved on the grid
//! (`ContactSolver::solve_depth_cohesive`) against exact JKR references: the
//! sphere (Johnson, Kendall & Roberts 1971) and Johnson's (1995) sinusoid
//! with its crests along the grid and at 45 degrees. Numbers measured by
//! `examples/cohesive_convergence.rs` (BENCHMARKS.md).

use std::f64::consts::PI;

use layered_contact::analytic::{JkrSinusoid, JkrSphere};
use layered_contact::indenter::{HeightMap, Sphere};
use layered_contact::solver::{CohesiveZone, ContactSolver, SolverParams};
use layered_contact::{Boundary, Grid, Substrate};

mod common;

use common::rubber_sphere::{rubber, rubber_solver, RADIUS, WORK};

/// The relative error of the sphere's pull-off with `n` cells across the
/// exact pull-off contact and a zone of `k` cells.
fn sphere_pull_off(n: usize, k: f64) -> f64 {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let delta = 2.0 * a / n as f64;
    let cells = 2 * (4.0 * a / delta).ceil() as usize;
    let grid = Grid::square_of_side(cells, cells as f64 * delta).unwrap();
    let mut solver = rubber_solver(&grid, Boundary::Isolated);
    let zone = CohesiveZone::new(WORK, WORK)
        .unwrap()
        .with_zone_cells(k)
        .unwrap();
    let step = jkr.critical_depth().abs() / 10.0;
    let sphere = Sphere::new(RADIUS).unwrap();
    let p = solver
        .cohesive_pull_off(&sphere, &zone, jkr.depth(1.6 * a), step, None, &mut ())
        .unwrap();
    p.force / jkr.pull_off_force() - 1.0
}

#[test]
fn sphere_pull_off_tends_to_jkr_from_the_dmt_side() {
    // A finite zone pulls harder than the JKR limit (Maugis 1992: the
    // pull-off moves from 1.5 towards 2 pi dgamma R as the zone widens).
    // Measured: +9.83 % and +6.60 % at 16 and 32 cells across with a zone
    // of 8 cells, +6.99 % and +4.15 % with 4. The error is a function of
    // the zone's width over the contact's (k / N) to 0.4 %.
    let coarse = sphere_pull_off(16, 8.0);
    let fine = sphere_pull_off(32, 8.0);
    let narrow = sphere_pull_off(32, 4.0);
    println!("{coarse} {fine} {narrow}");
    assert!((coarse - 0.0983).abs() < 2e-3, "{coarse}");
    assert!((fine - 0.0660).abs() < 2e-3, "{fine}");
    assert!((narrow - 0.0415).abs() < 2e-3, "{narrow}");
    assert!(fine > 0.0 && coarse / fine > 1.4);
}

#[test]
fn zero_work_of_adhesion_is_the_non_adhesive_contact() {
    // No law: one round, the constrained conjugate gradients of the
    // non-adhesive solve (without its multi-resolution start).
    let jkr = JkrSphere::new(&rubber(), RADIUS, 0.0).unwrap();
    let a = 1e-4;
    let grid = Grid::square_of_side(64, 8.0 * a).unwrap();
    let mut solver = rubber_solver(&grid, Boundary::Isolated);
    let sphere = Sphere::new(RADIUS).unwrap();
    let depth = jkr.depth(a);
    let zone = CohesiveZone::new(0.0, 0.0).unwrap();
    let (dry, _) = solver.solve_depth(&sphere, depth, None, &mut ()).unwrap();
    let (cohesive, warm) = solver
        .solve_depth_cohesive(&sphere, depth, &zone, None, &mut ())
        .unwrap();
    assert!((cohesive.force / dry.force - 1.0).abs() < 1e-8);
    assert_eq!(cohesive.contact_cells, dry.contact_cells);
    assert_eq!(warm.attached_cells(), dry.contact_cells);
    // Hertz within the staircase's first-order error (16 cells across).
    assert!((dry.force / jkr.force(a) - 1.0).abs() < 0.05);
}

/// The pull-off error of Johnson's sinusoid (alpha = 0.3) with the wave
/// vector `wave` on `cells x cells` periodic cells, zone of 8 cells.
fn sinusoid_pull_off(cells: usize, wave: (usize, usize)) -> f64 {
    let delta = 1e-5;
    let side = cells as f64 * delta;
    let wavelength = side / ((wave.0 * wave.0 + wave.1 * wave.1) as f64).sqrt();
    let estar = rubber().contact_modulus();
    let amplitude = (2.0 * wavelength * WORK / (PI * PI * estar)).sqrt() / 0.3;
    let exact = JkrSinusoid::new(&rubber(), wavelength, amplitude, WORK).unwrap();
    let grid = Grid::square_of_side(cells, side).unwrap();
    let values = (0..grid.len())
        .map(|c| {
            let (i, j) = (c / cells, c % cells);
            let phase = ((wave.0 * i + wave.1 * j) % cells) as f64 / cells as f64;
            amplitude * (1.0 - (2.0 * PI * phase).cos())
        })
        .collect();
    let map = HeightMap::new(grid, values).unwrap();
    let mut solver = ContactSolver::new(
        &Substrate::half_space(rubber()),
        &grid,
        Boundary::Periodic,
        SolverParams::default(),
    )
    .unwrap();
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let p = solver
        .cohesive_pull_off(
            &map,
            &zone,
            0.6 * amplitude,
            amplitude / 40.0,
            None,
            &mut (),
        )
        .unwrap();
    let (pressure, _) = exact.pull_off().unwrap();
    p.force / (side * side) / pressure - 1.0
}

#[test]
fn johnson_sinusoid_the_same_along_the_grid_and_at_45_degrees() {
    // 128 cells per wavelength: along the grid on 128^2 cells, at 45
    // degrees on 181^2 (wavelength 127.99 cells). Measured -1.643 % and
    // -1.571 %; at 256 cells per wavelength -0.43 % along the grid (order
    // 1.9), and at 181 / 362 cells -0.871 / -0.243 % along, -0.930 /
    // -0.328 % at 45 degrees: the orientations within 0.09 %.
    let along = sinusoid_pull_off(128, (1, 0));
    let diagonal = sinusoid_pull_off(181, (1, 1));
    println!("{along} {diagonal}");
    assert!((along + 0.01643).abs() < 5e-4, "{along}");
    assert!((along - diagonal).abs() < 2e-3, "{along} {diagonal}");
    let finer = sinusoid_pull_off(256, (1, 0));
    assert!(along / finer > 3.0, "{along} {finer}");
}
