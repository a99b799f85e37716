//! Adhesion through a cohesive zone resolved on the grid
//! (`ContactSolver::solve_depth_cohesive`) against exact JKR references: the
//! sphere (Johnson, Kendall & Roberts 1971) on a half-space and on a film
//! (the exact layered JKR solution), and Johnson's (1995) sinusoid with its
//! crests along the grid and at 45 degrees; a flat punch is refused.
//! Numbers measured by `examples/cohesive_convergence.rs` (BENCHMARKS.md).

use std::f64::consts::PI;

use layered_contact::analytic::{Axisymmetric, JkrSinusoid, JkrSphere};
use layered_contact::indenter::{FlatPunch, HeightMap, Sphere};
use layered_contact::kernel::ComplianceOperator;
use layered_contact::solver::{CohesiveZone, ContactSolver, Fields, SolverParams};
use layered_contact::{Base, Boundary, Error, Grid, Material, Substrate};

mod common;

use common::rubber_sphere::{rubber, rubber_solver, RADIUS, WORK};

/// The relative error of the sphere's pull-off with `n` cells across the
/// half-space's exact pull-off contact, with `zone`, on a half-space
/// (`film` None) or on a film on a rigid base `1 / film` times as thick as
/// that contact's radius (a negative `film`: that film on a layer ten times
/// stiffer and twice as thick, on the rigid base).
fn sphere_pull_off(n: usize, zone: &CohesiveZone, film: Option<f64>) -> f64 {
    sphere_pull_off_from(n, zone, film, 1.6)
}

/// As [`sphere_pull_off`], unloaded from the JKR depth of `start` pull-off
/// contact radii.
fn sphere_pull_off_from(n: usize, zone: &CohesiveZone, film: Option<f64>, start: f64) -> f64 {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let (substrate, exact) = match film {
        Some(ratio) => {
            // A negative ratio: the film `a / |ratio|` thick on a layer ten
            // times stiffer and twice as thick, on a rigid base.
            let top = a / ratio.abs();
            let film = if ratio > 0.0 {
                Substrate::layer_on_rigid_base(rubber(), top).unwrap()
            } else {
                let stiffer = Material::new(1e7, 0.3).unwrap();
                Substrate::stack(&[(rubber(), top), (stiffer, 2.0 * top)], Base::Rigid).unwrap()
            };
            let body = Axisymmetric::up_to_contact_radius(&film, 4.0 * a).unwrap();
            let exact = body.paraboloid(RADIUS, WORK).unwrap().pull_off().unwrap();
            (film, exact.load_control.force)
        }
        None => (Substrate::half_space(rubber()), jkr.pull_off_force()),
    };
    let (_, grid) = sphere_grid(a, n);
    let mut solver = ContactSolver::new(
        &substrate,
        &grid,
        Boundary::Isolated,
        SolverParams::default(),
    )
    .unwrap();
    let step = jkr.critical_depth().abs() / 10.0;
    let sphere = Sphere::new(RADIUS).unwrap();
    let p = solver
        .cohesive_pull_off(&sphere, zone, jkr.depth(start * a), step, None, &mut ())
        .unwrap();
    p.force / exact - 1.0
}

/// The cell size and the square isolated grid with `n` cells across a
/// contact of radius `a`, four radii each way from its centre.
fn sphere_grid(a: f64, n: usize) -> (f64, Grid) {
    let delta = 2.0 * a / n as f64;
    let cells = 2 * (4.0 * a / delta).ceil() as usize;
    (
        delta,
        Grid::square_of_side(cells, cells as f64 * delta).unwrap(),
    )
}

#[test]
fn sphere_pull_off_converges_at_second_order_with_the_curvature_correction() {
    // Without the correction a finite zone pulls harder than the JKR limit
    // (Maugis 1992: towards 2 pi dgamma R as the zone widens), by 0.20 l/a
    // as l/a falls: +9.83 % and +6.49 % at 16 and 32 cells across (zone of
    // 8 cells, l/a = 1 and 1/2), +4.16 % at 32 with a zone of 4 (l/a =
    // 1/4, as 8 cells at 64: +4.06 %). With it and the default zone of 4
    // cells: -1.95, -0.61, -0.13 % at 16, 32, 64 cells (ratios 3.2, 4.7;
    // the zone of 8 cells gave -6.39, -2.42, -0.66 %).
    let plain = CohesiveZone::new(WORK, WORK)
        .unwrap()
        .with_curvature_correction(0.0)
        .unwrap();
    let wide = plain.with_zone_cells(8.0).unwrap();
    let coarse = sphere_pull_off(16, &wide, None);
    let fine = sphere_pull_off(32, &wide, None);
    let narrow = sphere_pull_off(32, &plain, None);
    println!("plain {coarse} {fine} {narrow}");
    assert_eq!(plain.zone_cells(), 4.0);
    assert!((coarse - 0.0983).abs() < 2e-3, "{coarse}");
    assert!((fine - 0.0649).abs() < 2e-3, "{fine}");
    assert!((narrow - 0.0416).abs() < 2e-3, "{narrow}");
    let corrected = CohesiveZone::new(WORK, WORK).unwrap();
    let coarse = sphere_pull_off(16, &corrected, None);
    let fine = sphere_pull_off(32, &corrected, None);
    println!("corrected {coarse} {fine}");
    assert!((coarse + 0.0195).abs() < 1e-3, "{coarse}");
    assert!((fine + 0.0061).abs() < 1e-3, "{fine}");
    // Second order: the error falls at least 2.5 times per halving.
    assert!(coarse / fine > 2.5, "{coarse} {fine}");
}

#[test]
fn the_layered_sphere_converges_like_the_half_space() {
    // The film as thick as the pull-off contact's radius: the exact layered
    // JKR pull-off. The zone is at most a quarter of the film (2, 4 and 8
    // cells at 16, 32, 64 cells across, the same l/a = 1/4 each time):
    // -1.08, -1.09, -0.99 % (the half-space at l/a = 1/4: -0.66 %). A zone
    // of 8 cells at every size was -8.70, -3.29, -0.99 %.
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let coarse = sphere_pull_off(16, &zone, Some(1.0));
    let fine = sphere_pull_off(32, &zone, Some(1.0));
    println!("{coarse} {fine}");
    assert!((coarse + 0.0108).abs() < 2e-3, "{coarse}");
    assert!((fine + 0.0109).abs() < 2e-3, "{fine}");
}

#[test]
fn the_sphere_on_a_stack_converges_like_the_film() {
    // The film of the test above on a layer ten times stiffer and twice as
    // thick, against the exact stacked JKR pull-off: measured -1.01 % and
    // -0.244 % at 32 and 64 cells across (the zone four cells in both;
    // -0.0025 % at 128, BENCHMARKS.md), as the film alone (-1.09, -0.24 %).
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let coarse = sphere_pull_off(32, &zone, Some(-1.0));
    let fine = sphere_pull_off(64, &zone, Some(-1.0));
    println!("{coarse} {fine}");
    assert!((coarse + 0.0101).abs() < 1e-3, "{coarse}");
    assert!((fine + 0.00244).abs() < 5e-4, "{fine}");
    assert!(coarse / fine > 3.0, "{coarse} {fine}");
}

#[test]
fn the_zone_stays_within_a_quarter_of_a_thin_film() {
    // A film a quarter of the half-space's pull-off radius thick (the exact
    // layered pull-off contact about 2.9 thicknesses wide): 32 cells across
    // put 4 cells through it, and the zone of 8 cells, twice the film,
    // pulled off -10.4 % away. At most a quarter of the film (here two
    // cells, the fewest, still half the film): -0.82 %; at 64 cells +0.060 %
    // (examples/cohesive_convergence with FILM_RATIO=4).
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let delta = 2.0
        * JkrSphere::new(&rubber(), RADIUS, WORK)
            .unwrap()
            .pull_off_contact_radius()
        / 32.0;
    let thickness = Some(delta * 4.0);
    assert_eq!(zone.cells_on(delta, thickness), 2.0);
    assert!(!zone.resolves_layer(delta, thickness));
    assert!(zone.resolves_layer(delta / 2.0, thickness));
    let error = sphere_pull_off(32, &zone, Some(4.0));
    println!("{error}");
    assert!((error + 0.0082).abs() < 1e-3, "{error}");
}

#[test]
fn a_punch_pinned_at_its_rim_is_refused() {
    // The zone cannot form beyond the rim: Kendall's punch came out -23 %
    // at 64 cells across; the pull-off says so instead.
    let a = 1e-3;
    let grid = Grid::square_of_side(36, 36.0 * a / 16.0).unwrap();
    let mut solver = rubber_solver(&grid, Boundary::Isolated);
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let punch = FlatPunch::new(a).unwrap();
    let result = solver.cohesive_pull_off(&punch, &zone, 1e-6, 1e-6, None, &mut ());
    assert!(
        matches!(result, Err(Error::Unsupported { .. })),
        "{result:?}"
    );
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
/// vector `wave` on `cells x cells` periodic cells, a zone of `zone` cells.
fn sinusoid_pull_off(cells: usize, wave: (usize, usize), zone: f64) -> f64 {
    sinusoid_pull_off_on((cells, cells), wave, zone)
}

/// The same on `rows x columns` cells, `wave` waves along the rows and
/// the columns.
fn sinusoid_pull_off_on((rows, columns): (usize, usize), wave: (usize, usize), zone: f64) -> f64 {
    let delta = 1e-5;
    let grid = Grid::new(rows, columns, delta).unwrap();
    let wavelength = HeightMap::wavy_wavelength(&grid, wave).unwrap();
    let estar = rubber().contact_modulus();
    let amplitude = (2.0 * wavelength * WORK / (PI * PI * estar)).sqrt() / 0.3;
    let exact = JkrSinusoid::new(&rubber(), wavelength, amplitude, WORK).unwrap();
    let map = HeightMap::wavy(grid, wave, amplitude).unwrap();
    let mut solver = ContactSolver::new(
        &Substrate::half_space(rubber()),
        &grid,
        Boundary::Periodic,
        SolverParams::default(),
    )
    .unwrap();
    let zone = CohesiveZone::new(WORK, WORK)
        .unwrap()
        .with_zone_cells(zone)
        .unwrap();
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
    p.force / (grid.len() as f64 * grid.cell_area()) / pressure - 1.0
}

/// A straight edge along the grid, on a strip of eight cells across the
/// crests: the lattice traps the whole edge at once, so the force ripples
/// as it steps from cell to cell.
#[test]
fn a_straight_edge_along_the_grid_converges_with_a_wider_zone() {
    // 2048 cells per wavelength (about 240 across the pull-off contact).
    // With a zone of 16 cells the ripple is gone and the zone's length
    // against the contact remains: measured -0.0326 % (-0.1425 % at 1024
    // cells, +0.0067 % at 4096; BENCHMARKS.md, "The cohesive zone grown
    // with the resolution"), where the default zone of four cells is
    // +0.26 to +0.49 % off at 512 to 2048 cells.
    let wide = sinusoid_pull_off_on((2048, 8), (1, 0), 16.0);
    assert!((wide + 0.000326).abs() < 2e-4, "{wide}");
    // 4096 cells per wavelength, the zone of four cells: the walk that
    // stopped at the first rise of the force took a ripple for the
    // pull-off, 32.8 % short of it; walking on until the force has risen
    // three steps in a row, +0.371 % (the ripple's bias at this zone; it
    // was -0.674 % until each solve's first round held the contact it
    // starts from, 2026-12-02: which trapped edge the path keeps is the
    // lattice's).
    let narrow = sinusoid_pull_off_on((4096, 8), (1, 0), 4.0);
    assert!((narrow - 0.00371).abs() < 1e-3, "{narrow}");
}

#[test]
fn johnson_sinusoid_the_same_along_the_grid_and_at_45_degrees() {
    // 128 cells per wavelength: along the grid on 128^2 cells, at 45
    // degrees on 181^2 (wavelength 127.99 cells). With a zone of 8 cells:
    // measured -1.662 % and -1.752 %; at 256 cells per wavelength -0.489 %
    // along the grid (order 1.8), and at 181 / 362 cells -0.910 / -0.229 %
    // along, -0.893 / -0.321 % at 45 degrees: the orientations within 0.09
    // % (BENCHMARKS.md, "Adhesion through a resolved cohesive zone").
    let along = sinusoid_pull_off(128, (1, 0), 8.0);
    let diagonal = sinusoid_pull_off(181, (1, 1), 8.0);
    println!("{along} {diagonal}");
    assert!((along + 0.01662).abs() < 5e-4, "{along}");
    assert!((along - diagonal).abs() < 2e-3, "{along} {diagonal}");
    let finer = sinusoid_pull_off(256, (1, 0), 8.0);
    assert!(along / finer > 3.0, "{along} {finer}");
    // The default zone of 4 cells, a quarter of the pull-off contact's 15
    // cells here: closer to the limit, +0.343 % and -0.613 %, less smooth
    // (the zone's few cells are trapped by the lattice as it moves; at 256
    // cells per wavelength -0.020 % and +0.119 %).
    let along = sinusoid_pull_off(128, (1, 0), 4.0);
    let diagonal = sinusoid_pull_off(181, (1, 1), 4.0);
    println!("{along} {diagonal}");
    assert!((along - 0.00343).abs() < 5e-4, "{along}");
    assert!((diagonal + 0.00613).abs() < 5e-4, "{diagonal}");
}

#[test]
fn a_sphere_off_the_cell_centres_pulls_off_as_on_them() {
    // The JKR sphere moved by (0.3, 0.45) cells from the grid's centre (a
    // height map of the exact sphere at the cell centres), 32 cells across
    // the pull-off contact: the same error as on the centre, -0.61 %
    // (measured -0.670 % moved; with the zone of 8 cells -2.411 % moved
    // against -2.42 %: the staircase changes, the edge's release does not).
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let (delta, grid) = sphere_grid(a, 32);
    let (x0, y0) = (0.3 * delta, 0.45 * delta);
    let values = (0..grid.len())
        .map(|c| {
            let (x, y) = grid.cell_centre(c / grid.columns(), c % grid.columns());
            let r2 = (x - x0).powi(2) + (y - y0).powi(2);
            RADIUS - (RADIUS * RADIUS - r2).max(0.0).sqrt()
        })
        .collect();
    let map = HeightMap::new(grid, values).unwrap();
    let mut solver = rubber_solver(&grid, Boundary::Isolated);
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let step = jkr.critical_depth().abs() / 10.0;
    let p = solver
        .cohesive_pull_off(&map, &zone, jkr.depth(1.6 * a), step, None, &mut ())
        .unwrap();
    let moved = p.force / jkr.pull_off_force() - 1.0;
    println!("{moved}");
    // Within the staircase noise of the edge at 32 cells (about 1e-3).
    assert!((moved + 0.0061).abs() < 1e-3, "{moved}");
}

#[test]
fn with_hysteresis_the_pull_off_is_the_receding_work_s() {
    // Loaded with a fifth of the work of adhesion and unloaded with all of
    // it: the contact pressed past the pull-off contact holds (bonded
    // cells pull with dgamma1) until the edge's release reaches dgamma1,
    // then recedes along the JKR branch of dgamma1: the pull-off does not
    // remember the loading. Pressed to the JKR depth of 2.4 pull-off radii
    // (the loaded contact then holds the whole zone at the pull-off, which
    // spans half the radius at 32 cells across; from 1.6 radii its outer
    // part lay on cells never bonded, pulling with dgamma0: -3.58 % with
    // the zone of 8 cells). Measured -0.620 %, as without hysteresis
    // (-0.615 %; with the zone of 8 cells -2.423 % and -2.42 %).
    let zone = CohesiveZone::new(WORK / 5.0, WORK).unwrap();
    let error = sphere_pull_off_from(32, &zone, None, 2.4);
    println!("{error}");
    assert!((error + 0.0061).abs() < 1e-3, "{error}");
}

#[test]
fn bad_input_is_a_typed_error_never_a_nan() {
    let grid = Grid::square_of_side(32, 1e-3).unwrap();
    let mut solver = rubber_solver(&grid, Boundary::Isolated);
    let sphere = Sphere::new(RADIUS).unwrap();
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    for work in [f64::NAN, -1.0, f64::INFINITY] {
        assert!(CohesiveZone::new(work, WORK).is_err());
    }
    assert!(CohesiveZone::new(2.0 * WORK, WORK).is_err()); // dgamma0 > dgamma1
    for cells in [f64::NAN, 1.0, 300.0] {
        assert!(zone.with_zone_cells(cells).is_err());
    }
    for c in [f64::NAN, -0.1, 2.0] {
        assert!(zone.with_curvature_correction(c).is_err());
    }
    for n in [f64::NAN, 0.5, -64.0, f64::INFINITY, 3e5] {
        assert!(matches!(
            zone.with_resolution(n),
            Err(Error::InvalidParameter { .. })
        ));
    }
    // The largest resolution's zone is the widest allowed, 256 cells.
    let widest = zone.with_resolution(262_144.0).unwrap().zone_cells();
    assert!((widest - 256.0).abs() < 1e-12, "{widest}");
    for depth in [f64::NAN, f64::INFINITY] {
        let r = solver.solve_depth_cohesive(&sphere, depth, &zone, None, &mut ());
        assert!(matches!(r, Err(Error::InvalidParameter { .. })));
    }
    // A warm start from another grid.
    let other = Grid::square_of_side(16, 1e-3).unwrap();
    let (_, warm) = rubber_solver(&other, Boundary::Isolated)
        .solve_depth_cohesive(&sphere, 1e-6, &zone, None, &mut ())
        .unwrap();
    let r = solver.solve_depth_cohesive(&sphere, 1e-6, &zone, Some(&warm), &mut ());
    assert!(matches!(r, Err(Error::ShapeMismatch { .. })));
    // Huge and tiny depths: an Ok is finite, else a typed error.
    for depth in [1e300, 1e-300, -1e300, 0.0, 1e-3] {
        if let Ok((s, _)) = solver.solve_depth_cohesive(&sphere, depth, &zone, None, &mut ()) {
            assert!(s.force.is_finite() && s.depth.is_finite(), "{depth}: {s:?}");
        }
    }
    // An unloading that starts without contact has no pull-off.
    let r = solver.cohesive_pull_off(&sphere, &zone, -1e-3, 1e-7, None, &mut ());
    assert!(matches!(r, Err(Error::InvalidParameter { .. })), "{r:?}");
    // Unloading steps that cannot move the indenter.
    for step in [0.0, -1e-6, f64::NAN, 1e-30] {
        let r = solver.cohesive_pull_off(&sphere, &zone, 1e-6, step, None, &mut ());
        assert!(
            matches!(r, Err(Error::InvalidParameter { .. })),
            "{step}: {r:?}"
        );
    }
}

#[test]
fn a_cold_start_at_first_touch_zips_in_to_the_jkr_contact() {
    // At the depth of first touch the JKR contact is finite (Johnson,
    // Kendall & Roberts 1971: d = a^2/R - sqrt(2 pi dgamma a / E*) = 0 at
    // a0 = (2 pi dgamma R^2 / E*)^(1/3), 1.21 pull-off radii). From a cold
    // start the first round has no contact: the law pulls the cells within
    // its range in, and the edge zips out over some 38 cells, a few a
    // round, while the largest change of the tensions stays at the front's.
    // Measured at 64 cells across the pull-off contact: the force -0.23 %
    // off JKR's at this depth. The closed contact's radius lies 1.4, 1.5,
    // 1.9 and 2.1 cells (14.4, 7.8, 4.9, 2.7 %) inside JKR's at 16, 32, 64
    // and 128 cells (the zone, 4 cells, outside it); the equivalent
    // crack's (the closed cells and 0.43 of the zone's, `EQUIVALENT_TIP`)
    // 0.21, 0.31, 0.18 and 0.13 cells outside (+2.2, +1.6, +0.46,
    // +0.17 %): within a fraction of a cell, so first order.
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let estar = rubber().contact_modulus();
    let radius = jkr.contact_radius_at_depth(0.0).unwrap();
    let expected = (2.0 * PI * WORK * RADIUS * RADIUS / estar).cbrt();
    assert!((radius / expected - 1.0).abs() < 1e-12);
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let sphere = Sphere::new(RADIUS).unwrap();
    for cells in [32, 64] {
        let (delta, grid) = sphere_grid(a, cells);
        let mut solver = rubber_solver(&grid, Boundary::Isolated);
        let (solution, _) = solver
            .solve_depth_cohesive(&sphere, 0.0, &zone, None, &mut ())
            .unwrap();
        if cells == 64 {
            let error = solution.force / jkr.force(radius) - 1.0;
            assert!(error.abs() < 5e-3, "{error}");
        }
        let outside = (solution.contact_radius - radius) / delta;
        assert!(
            outside.abs() < 0.5,
            "{cells}: {outside} cells: {solution:?}"
        );
    }
}

#[test]
fn the_displacement_is_the_response_to_the_total_pressure() {
    // Between fresh rounds the fixed point moves the profile by one
    // operator application to the change of the total pressure and keeps
    // the inner solve's displacement: the displacement it reports must
    // still be K (tensions + pressures). A load step and an unloading step
    // (warm, the bonded cells holding with the receding work), checked
    // against the operator applied afresh (a wrong offset is off by the
    // response to a round's change, a few per cent of the peak).
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let grid = Grid::square_of_side(48, 4.0 * a).unwrap();
    let params = SolverParams {
        fields: Fields::all(),
        ..SolverParams::default()
    };
    let body = Substrate::half_space(rubber());
    let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
    let mut operator = ComplianceOperator::new(&body, &grid, Boundary::Isolated).unwrap();
    let sphere = Sphere::new(RADIUS).unwrap();
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let mut warm = None;
    for depth in [jkr.depth(1.5 * a), jkr.depth(a)] {
        let (solution, next) = solver
            .solve_depth_cohesive(&sphere, depth, &zone, warm.as_ref(), &mut ())
            .unwrap();
        let (_, worst, largest) = common::fresh_displacement(&mut operator, &solution);
        assert!(worst <= 1e-10 * largest, "{depth}: {worst} of {largest}");
        // The pull-off contact's force within the staircase's error.
        if depth == jkr.depth(a) {
            let error = solution.force / jkr.force(a) - 1.0;
            assert!(error.abs() < 0.05, "{error}");
        }
        warm = Some(next);
    }
}
