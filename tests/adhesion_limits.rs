//! Where the energy-balance adhesion method is exact, and what it says
//! where it is not: the edge-averaged flag on non-axisymmetric contacts, and
//! the refusal of contacts that would meet their periodic images (a wavy
//! surface used to return pull-off forces of 1e25 N there).

use std::f64::consts::PI;

use layered_contact::analytic::{JkrSinusoid, JkrSphere};
use layered_contact::indenter::{HeightMap, Paraboloid};
use layered_contact::scene::{AdhesionMethod, Caveat, IndenterSpec, Resolution, Scene, Tilt};
use layered_contact::solver::{ContactSolver, Reach, EDGE_SHIFT};
use layered_contact::{Boundary, Error, Grid};

mod common;

use common::rubber_sphere::{paraboloid_cycle, rubber, rubber_solver, RADIUS, WORK};

/// `heights(x, y)` sampled at the cell centres of `grid`, and a solver for
/// the rubber half-space on that grid.
fn sampled(
    grid: Grid,
    boundary: Boundary,
    heights: impl Fn(f64, f64) -> f64,
) -> (HeightMap, ContactSolver) {
    let columns = grid.columns();
    let values = (0..grid.len())
        .map(|c| {
            let (x, y) = grid.cell_centre(c / columns, c % columns);
            heights(x, y)
        })
        .collect();
    let solver = rubber_solver(&grid, boundary);
    (HeightMap::new(grid, values).unwrap(), solver)
}

/// The energy-balance branches of `heights(x, y)` sampled at the cell
/// centres of a 64 x 64 isolated grid 4 JKR pull-off radii wide (16 cells
/// across the pull-off contact), pressed to 1.5 pull-off radii.
fn map_branches(heights: impl Fn(f64, f64) -> f64) -> (f64, f64, bool) {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let grid = Grid::square_of_side(64, 8.0 * a).unwrap();
    let (map, mut solver) = sampled(grid, Boundary::Isolated, heights);
    let depth = (1.5 * a).powi(2) / RADIUS;
    let branches = solver
        .adhesive_branches(&map, Reach::Depth(depth), WORK, WORK, &mut ())
        .unwrap();
    let peak = branches.at_depth(depth, 0.0).unwrap();
    let pull_off = branches.pull_off(peak.contact_area).unwrap();
    (
        pull_off.force,
        jkr.pull_off_force(),
        branches.edge_averaged(),
    )
}

#[test]
fn axisymmetry_is_read_from_the_profile_not_the_type() {
    // A height map of the paraboloid: digital discs, so exact JKR (the
    // energy balance is 0.25 % off at 16 cells across, doc::accuracy;
    // 0.5 % allowed).
    let (force, exact, averaged) = map_branches(|x, y| (x * x + y * y) / (2.0 * RADIUS));
    assert!(!averaged);
    assert!((force / exact - 1.0).abs() < 5e-3, "{force} vs {exact}");
    // The same map built from the library's own paraboloid agrees to
    // rounding: the map is only a container.
    let ball = Paraboloid::new(RADIUS).unwrap();
    let (same, _, _) = map_branches(|x, y| {
        use layered_contact::indenter::Indenter;
        ball.height(x, y)
    });
    assert!((same / force - 1.0).abs() < 1e-12);
    // The paraboloid moved off the axis by (0.37, -0.21) cells: discs about
    // its apex, found from the profile (the solver reads the apex from the
    // lowest cell's neighbours), and the same pull-off (JKR's for any apex;
    // 0.5 % allowed as above).
    let cell = 8.0
        * JkrSphere::new(&rubber(), RADIUS, WORK)
            .unwrap()
            .pull_off_contact_radius()
        / 64.0;
    let (x0, y0) = (0.37 * cell, -0.21 * cell);
    let (moved, exact, averaged) =
        map_branches(|x, y| ((x - x0).powi(2) + (y - y0).powi(2)) / (2.0 * RADIUS));
    assert!(!averaged);
    assert!((moved / exact - 1.0).abs() < 5e-3, "{moved} vs {exact}");
    // An elliptic paraboloid (Ry = 2 Rx): its contacts are not discs, and
    // the result says so. Its pull-off is the sphere's of radius
    // sqrt(Rx Ry) to within a few per cent (Johnson & Greenwood 1997), so
    // the number is still of the right size.
    let (force, _, averaged) = map_branches(|x, y| x * x / (2.0 * RADIUS) + y * y / (4.0 * RADIUS));
    assert!(averaged);
    let equivalent = -1.5 * PI * WORK * RADIUS * 2f64.sqrt();
    assert!(
        (force / equivalent - 1.0).abs() < 0.1,
        "{force} vs {equivalent}"
    );
}

fn sphere_scene(tilt: Option<Tilt>) -> Scene {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let resolution = Resolution {
        cells_across: 16,
        margin: 0.05,
    };
    paraboloid_cycle(tilt, (1.5 * a).powi(2) / RADIUS, 6, resolution)
}

#[test]
fn scenes_report_edge_averaged_adhesion() {
    let exact = JkrSphere::new(&rubber(), RADIUS, WORK)
        .unwrap()
        .pull_off_force();
    let straight = sphere_scene(None).run(&mut |_| {}).unwrap();
    assert!(straight.caveats.is_empty());
    let pull_off = straight.pull_off().unwrap().force;
    assert!(
        (pull_off / exact - 1.0).abs() < 5e-3,
        "{pull_off} vs {exact}"
    );
    // A paraboloid tilted by 0.05 rad is a paraboloid whose apex moved
    // sideways by R tan(0.05): the same JKR pull-off, and its contact sets
    // are discs about the moved apex, so the energy balance (the automatic
    // method) is as exact as for the straight one (-0.081 % against
    // -0.032 % at 16 cells) and carries no caveat.
    let tilt = Some(Tilt {
        angle_y: 0.05,
        angle_x: 0.0,
    });
    let tilted = sphere_scene(tilt).run(&mut |_| {}).unwrap();
    assert!(tilted.caveats.is_empty(), "{:?}", tilted.caveats);
    let pull_off = tilted.pull_off().unwrap().force;
    assert!(
        (pull_off / exact - 1.0).abs() < 2e-3,
        "{pull_off} vs {exact}"
    );
    // A tilted sphere's sets are not discs (the linearised tilt of its
    // cap): the energy balance flags them.
    let mut sphere = sphere_scene(tilt);
    sphere.indenter = IndenterSpec::Sphere { radius: RADIUS };
    sphere.solver.adhesion_method = AdhesionMethod::EnergyBalance;
    let tilted = sphere.run(&mut |_| {}).unwrap();
    assert_eq!(tilted.caveats, vec![Caveat::EdgeAveragedAdhesion]);
    assert!(tilted.caveats[0].to_string().contains("several per cent"));
}

#[test]
fn wavy_surfaces_that_used_to_fail_now_match_johnson() {
    // A wavy surface h0 (1 - cos 2 pi x / L) on one period: its contacts are
    // strips across the whole period. Five grids and amplitudes that used
    // to give pull-off forces from -2e25 N to +0.02 N (then refused with a
    // typed error) now give Johnson's (1995) pull-off or a typed error.
    let period = 1e-3;
    let mut accepted = 0;
    for (n, h0) in [(32, 2e-5), (64, 2e-5), (32, 5e-6), (64, 5e-6), (128, 2e-5)] {
        let grid = Grid::square_of_side(n, period).unwrap();
        let (map, mut solver) = sampled(grid, Boundary::Periodic, |x, _| {
            h0 * (1.0 - (2.0 * PI * x / period).cos())
        });
        let exact = JkrSinusoid::new(&rubber(), period, h0, WORK).unwrap();
        let result = solver.adhesive_branches(&map, Reach::Depth(0.5 * h0), WORK, WORK, &mut ());
        match (n, h0, result) {
            // A contact 8.8 cells across at the pull-off: measured -0.48 %
            // (Johnson's sinusoid on finer grids: `tests/adhesion_shapes.rs`).
            (128, 2e-5, Ok(branches)) => {
                let peak = branches.at_depth(0.5 * h0, 0.0).unwrap();
                let force = branches.pull_off(peak.contact_area).unwrap().force;
                let (pressure, _) = exact.pull_off().unwrap();
                let error = force / (period * period) / pressure - 1.0;
                assert!(error.abs() < 0.01, "{n}: {error}");
                assert!(!branches.edge_averaged());
                accepted += 1;
            }
            // 4.4 cells across: the family's narrowest strip (two lines)
            // holds a lower force than the branch's first minimum (the
            // staircase's), so the pull-off is refused; it was accepted at
            // -5.1 % before the least force below the peak was taken.
            (64, 2e-5, Ok(branches)) => {
                let peak = branches.at_depth(0.5 * h0, 0.0).unwrap();
                let pull_off = branches.pull_off(peak.contact_area);
                assert!(
                    matches!(pull_off, Err(Error::Unsupported { .. })),
                    "{pull_off:?}"
                );
                accepted += 1;
            }
            // The loading to half the amplitude needs contacts wider than
            // half the period (the mean displacement is zero on a periodic
            // grid, so the depth is not the approach from first touch).
            (_, _, Err(Error::Unsupported { .. })) => {}
            (_, _, other) => panic!("{n} cells, h0 = {h0}: {other:?}"),
        }
    }
    assert_eq!(accepted, 2);
}

#[test]
fn a_flat_punch_that_is_not_round_is_flagged() {
    // The family of a flat punch is the digital discs clipped by its face:
    // discs for a round punch (exact Kendall), not for a square one, whose
    // energy balance averages the release over an edge where it is not
    // uniform (it used to be reported as exact).
    let grid = Grid::square_of_side(64, 6.4e-3).unwrap();
    let half = 1.6e-3;
    let round = |x: f64, y: f64| {
        if x * x + y * y < half * half {
            0.0
        } else {
            f64::INFINITY
        }
    };
    let square = |x: f64, y: f64| {
        if x.abs() < half && y.abs() < half {
            0.0
        } else {
            f64::INFINITY
        }
    };
    let pull_off = |heights: &dyn Fn(f64, f64) -> f64| {
        let (map, mut solver) = sampled(grid, Boundary::Isolated, heights);
        let branches = solver
            .adhesive_branches(&map, Reach::Depth(1e-7), WORK, WORK, &mut ())
            .unwrap();
        let peak = branches.at_depth(1e-7, 0.0).unwrap();
        let force = branches.pull_off(peak.contact_area).unwrap().force;
        (force, branches.edge_averaged())
    };
    let (force, averaged) = pull_off(&round);
    assert!(!averaged);
    // Kendall (1971): F = -sqrt(8 pi a^3 E* dgamma), a the equal-area
    // radius of the punch's cells less the staircase's 0.117 cells.
    let estar = rubber().contact_modulus();
    let columns = grid.columns();
    let cells = (0..grid.len())
        .filter(|&c| {
            let (x, y) = grid.cell_centre(c / columns, c % columns);
            round(x, y) == 0.0
        })
        .count();
    let a = (cells as f64 * grid.cell_area() / PI).sqrt() - EDGE_SHIFT * grid.spacing();
    let kendall = -(8.0 * PI * a.powi(3) * estar * WORK).sqrt();
    assert!((force / kendall - 1.0).abs() < 5e-3, "{force} vs {kendall}");
    let (_, averaged) = pull_off(&square);
    assert!(averaged);
}

#[test]
fn a_wavy_surface_with_two_troughs_is_refused_not_truncated() {
    // Two crests per period, one a hundredth deeper: the family's sets are
    // first one strip, then two, then one again. The balance cannot take
    // two strips (each would need its own edge), so the branch is refused
    // with a typed error, whichever way the crests run. A single trough
    // (the control) is accepted and exact (`tests/adhesion_shapes.rs`).
    let period = 1e-3;
    let h0 = 2e-5;
    for (k, l) in [(1usize, 0usize), (1, 2)] {
        let n = 128;
        let grid = Grid::square_of_side(n, period).unwrap();
        let heights = |phase: f64, troughs: f64| {
            h0 * (1.0 - (troughs * 2.0 * PI * phase).cos())
                + 0.01 * h0 * (1.0 - (2.0 * PI * phase).cos())
        };
        let map = |troughs: f64| {
            let values = (0..grid.len())
                .map(|c| {
                    let (i, j) = (c / n, c % n);
                    heights(((k * i + l * j) % n) as f64 / n as f64, troughs)
                })
                .collect();
            HeightMap::new(grid, values).unwrap()
        };
        let mut solver = rubber_solver(&grid, Boundary::Periodic);
        let two = solver.adhesive_branches(&map(2.0), Reach::Depth(0.5 * h0), WORK, WORK, &mut ());
        assert!(
            matches!(two, Err(Error::Unsupported { .. })),
            "({k}, {l}): {two:?}"
        );
        // The control, loaded to strips 0.38 of the period wide.
        let wavelength = period / ((k * k + l * l) as f64).sqrt();
        let exact = JkrSinusoid::new(&rubber(), wavelength, 1.01 * h0, WORK).unwrap();
        let target = exact.mean_pressure(0.6 * wavelength / PI) * period * period;
        let one = solver
            .adhesive_branches(&map(1.0), Reach::Force(target), WORK, WORK, &mut ())
            .unwrap();
        assert!(!one.edge_averaged());
        let peak = one.at_force(target, 0.0).unwrap();
        let pull_off = one.pull_off(peak.contact_area);
        let (exact_pull_off, _) = exact.pull_off().unwrap();
        // About 8 lines of cells across the pull-off contact (alpha = 0.14
        // and 0.09): measured -0.47 % along the grid, -0.24 % along two
        // cells by one.
        let error = pull_off.unwrap().force / (period * period) / exact_pull_off - 1.0;
        assert!(error.abs() < 0.01, "({k}, {l}): {error}");
    }
}

#[test]
fn a_pull_off_contact_the_grid_does_not_resolve_is_refused() {
    // Johnson's sinusoid on 64 lines of cells per wavelength with small
    // adhesion parameters: pull-off contacts 1.2, 2.2 and 3.5 lines wide.
    // The branch came out -32 % (2.2 lines) and -4.6 % (3.5) without a
    // word; now each pull-off is refused, while 4.4 lines (the wavy test
    // above) are accepted at -5.1 %.
    let (n, side) = (64, 64e-5);
    for alpha in [0.02, 0.05, 0.1] {
        let estar = rubber().contact_modulus();
        let amplitude = (2.0 * side * WORK / (PI * PI * estar)).sqrt() / alpha;
        let exact = JkrSinusoid::new(&rubber(), side, amplitude, WORK).unwrap();
        let (_, half_width) = exact.pull_off().unwrap();
        assert!(2.0 * half_width / side * n as f64 <= 3.6);
        let grid = Grid::square_of_side(n, side).unwrap();
        let (map, mut solver) = sampled(grid, Boundary::Periodic, |x, _| {
            amplitude * (1.0 - (2.0 * PI * x / side).cos())
        });
        let target = exact.mean_pressure(0.6 * side / PI) * side * side;
        let branches = solver
            .adhesive_branches(&map, Reach::Force(target), WORK, WORK, &mut ())
            .unwrap();
        let peak = branches.at_force(target, 0.0).unwrap();
        let pull_off = branches.pull_off(peak.contact_area);
        assert!(
            matches!(pull_off, Err(Error::Unsupported { .. })),
            "{alpha}: {pull_off:?}"
        );
    }
}

/// Johnson's sinusoid on a periodic square of side `L` on 64 x 64 cells,
/// `h0 (1 - cos 2 pi (x + y) / L)` if `diagonal` (wavelength `L / sqrt 2`,
/// crests along the grid's diagonal), else `h0 (1 - cos 2 pi x / L)`;
/// `alpha` its adhesion parameter, heights sampled at the cell centres plus
/// `noise` times a fixed pseudo-random rounding in `[-h0 / 2, h0 / 2]`.
/// Returns the pull-off's relative error, or the error.
fn sinusoid_pull_off(alpha: f64, diagonal: bool, noise: f64) -> Result<f64, Error> {
    let (n, side) = (64, 64e-5);
    let estar = rubber().contact_modulus();
    let wavelength = if diagonal { side / 2f64.sqrt() } else { side };
    let amplitude = (2.0 * wavelength * WORK / (PI * PI * estar)).sqrt() / alpha;
    let exact = JkrSinusoid::new(&rubber(), wavelength, amplitude, WORK).unwrap();
    let grid = Grid::square_of_side(n, side).unwrap();
    let (map, mut solver) = sampled(grid, Boundary::Periodic, |x, y| {
        // A fixed hash of the position as the rounding.
        let hash =
            ((x * 1e7) as u64 ^ ((y * 1e7) as u64) << 20).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let unit = (hash >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
        let phase = if diagonal { x + y } else { x };
        amplitude * (1.0 - (2.0 * PI * phase / side).cos() + noise * unit)
    });
    let target = exact.mean_pressure(0.6 * wavelength / PI) * side * side;
    let branches = solver.adhesive_branches(&map, Reach::Force(target), WORK, WORK, &mut ())?;
    let peak = branches.at_force(target, 0.0)?;
    let force = branches.pull_off(peak.contact_area)?.force;
    Ok(force / (side * side) / exact.pull_off().unwrap().0 - 1.0)
}

#[test]
fn a_wave_along_the_diagonal_is_refused_where_the_grid_does_not_resolve_it() {
    // Pull-off contacts 1.2 and 3.5 lines of cells wide: refused, as along
    // the grid (`a_pull_off_contact_the_grid_does_not_resolve_is_refused`).
    // The first came out as a compressive "pull-off" 2.3 times the exact
    // force from a ripple of the staircase five lines wide, the second -6.5
    // %. At 5.6 lines: measured -0.76 %.
    for alpha in [0.02, 0.1] {
        let result = sinusoid_pull_off(alpha, true, 0.0);
        assert!(
            matches!(result, Err(Error::Unsupported { .. })),
            "{alpha}: {result:?}"
        );
    }
    let error = sinusoid_pull_off(0.2, true, 0.0).unwrap();
    assert!(error.abs() < 0.01, "{error}");
}

#[test]
fn rounding_in_a_strips_heights_does_not_move_its_pull_off() {
    // Heights carrying rounding (1e-16 of the amplitude) used to split a
    // strip's lines into cells of different heights, and the family read
    // that rounding as heights: along the grid at alpha = 0.2 the pull-off
    // came out +0.78 % instead of -1.60 %, at alpha = 0.1 (3.5 lines) -10 %
    // where it is refused, along the diagonal at 0.1 -7.0 %. The lines are
    // now snapped to one height: the same answers to rounding.
    for diagonal in [false, true] {
        let clean = sinusoid_pull_off(0.2, diagonal, 0.0).unwrap();
        let rounded = sinusoid_pull_off(0.2, diagonal, 1e-16).unwrap();
        assert!((rounded - clean).abs() < 1e-9, "{clean} vs {rounded}");
        let result = sinusoid_pull_off(0.1, diagonal, 1e-16);
        assert!(
            matches!(result, Err(Error::Unsupported { .. })),
            "{result:?}"
        );
    }
}
