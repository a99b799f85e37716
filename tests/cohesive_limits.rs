//! Where the cohesive zone cannot give the JKR limit, and what it says:
//! a zone wider than the contact at the pull-off (the zones of its two
//! sides meet), flagged on the pull-off and reported by scenes.

use std::f64::consts::PI;

use layered_contact::analytic::JkrSinusoid;
use layered_contact::indenter::HeightMap;
use layered_contact::scene::{Adhesion, Caveat, IndenterSpec, Protocol, Scene, SubstrateSpec};
use layered_contact::solver::{CohesivePullOff, CohesiveZone};
use layered_contact::topography::Amplitude;
use layered_contact::{Boundary, Grid};

mod common;

use common::rubber_sphere::{rubber, rubber_solver, WORK};

/// Johnson's sinusoid along the grid, one wavelength on `n x n` periodic
/// cells, adhesion parameter `alpha`, unloaded through the cohesive zone
/// (four cells) from the non-adhesive contact 0.38 of the wavelength wide:
/// the pull-off and its relative error.
fn sinusoid_pull_off(n: usize, alpha: f64) -> (CohesivePullOff, f64) {
    let side = 64e-5;
    let estar = rubber().contact_modulus();
    let amplitude = (2.0 * side * WORK / (PI * PI * estar)).sqrt() / alpha;
    let exact = JkrSinusoid::new(&rubber(), side, amplitude, WORK).unwrap();
    let grid = Grid::square_of_side(n, side).unwrap();
    let columns = grid.columns();
    let values = (0..grid.len())
        .map(|c| {
            let (x, _) = grid.cell_centre(c / columns, c % columns);
            amplitude * (1.0 - (2.0 * PI * x / side).cos())
        })
        .collect();
    let map = HeightMap::new(grid, values).unwrap();
    let mut solver = rubber_solver(&grid, Boundary::Periodic);
    let target = exact.mean_pressure(0.6 * side / PI) * side * side;
    let (start, _) = solver.solve_force(&map, target, None, &mut ()).unwrap();
    let zone = CohesiveZone::new(WORK, WORK).unwrap();
    let pull_off = solver
        .cohesive_pull_off(&map, &zone, start.depth, amplitude / 100.0, None, &mut ())
        .unwrap();
    let (pressure, _) = exact.pull_off().unwrap();
    let error = pull_off.force / (side * side) / pressure - 1.0;
    (pull_off, error)
}

#[test]
fn a_zone_wider_than_the_pull_off_contact_is_flagged() {
    // 64 cells a wavelength at alpha = 0.05: the exact pull-off contact 2.2
    // lines wide, the zone's one line at its least force; measured -5.13 %.
    let (coarse, error) = sinusoid_pull_off(64, 0.05);
    assert_eq!((coarse.cells_across, coarse.zone_cells), (1.0, 4.0));
    assert!(coarse.zone_spans_contact());
    assert!(error < -0.03, "{error}");
    // 128 cells at alpha = 0.3: 15 lines exact, 11 at the zone's least
    // force; measured +0.298 %.
    let (fine, error) = sinusoid_pull_off(128, 0.3);
    assert_eq!(fine.cells_across, 11.0);
    assert!(!fine.zone_spans_contact());
    assert!(error.abs() < 0.005, "{error}");
}

/// The rough adhesive film of `examples/scenes/rough_adhesive_film.toml`
/// (0.32 mm square, rms height 1 um, a 0.2 mm rubber film on glass,
/// hysteresis 0.01 / 0.05 J/m^2) on `cells` a side, its short cut-off four
/// cells, pressed to 1 um and pulled off.
fn rough_film(cells: usize) -> Scene {
    rough_film_seeded(cells, 3)
}

/// [`rough_film`] of another seed.
fn rough_film_seeded(cells: usize, seed: u64) -> Scene {
    let spacing = 3.2e-4 / cells as f64;
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
        adhesion: Adhesion::Hysteresis {
            loading: 0.01,
            unloading: 0.05,
        },
        protocol: Protocol::Cycle {
            max_depth: 1e-6,
            steps: 10,
        },
        ..Scene::default()
    }
}

/// The pull-off force (N) of `scene` run as a force cycle to `max_force`
/// (N) in `steps`.
fn force_cycle_pull_off(mut scene: Scene, max_force: f64, steps: usize) -> f64 {
    scene.protocol = Protocol::ForceCycle { max_force, steps };
    let curve = scene.run(&mut |_| {}).unwrap();
    curve.pull_off().unwrap().force
}

#[test]
fn scenes_report_a_zone_wider_than_the_pull_off_contact() {
    // The film at its advancing work alone (0.01 J/m^2; with its
    // hysteresis the pinned contact is wider than the zone on 32 cells
    // since 2026-12-03). On 32 cells a side the zone (four cells, 40 um)
    // is wider than every patch at the pull-off; on 64 (20 um) it is not,
    // and the force is nearly three times weaker: measured -0.3078 mN and
    // -0.1068 mN (-0.3407 and -0.1132 mN until 2026-12-04, when the zone's
    // cells at the far side of the band where the edge's curvature is read
    // took a spurious one, and each solve read it up to eight times).
    let film = |cells| {
        let mut scene = rough_film(cells);
        scene.adhesion = Adhesion::Constant {
            work_of_adhesion: 0.01,
        };
        scene
    };
    let expected = [
        Caveat::CohesiveZoneOnRoughSurface,
        Caveat::CohesiveZoneSpansContact,
    ];
    let coarse = film(32).run(&mut |_| {}).unwrap();
    assert_eq!(coarse.caveats, expected);
    assert!(coarse.caveats[1].to_string().contains("refine the grid"));
    let fine = film(64).run(&mut |_| {}).unwrap();
    assert_eq!(fine.caveats, expected[..1]);
    let (f32, f64) = (
        coarse.pull_off().unwrap().force,
        fine.pull_off().unwrap().force,
    );
    assert!((f32 / f64 - 2.88).abs() < 0.05, "{f32} {f64}");
}

#[test]
fn a_force_cycle_whose_pull_off_dwarfs_its_peak_comes_off() {
    // The rough film on 16 cells a side loaded to 10 uN and 100 uN, about
    // a two-hundredth and a twentieth of its pull-off force: at 10 uN (and
    // 1 uN) the first unloading trial from the peak lost the contact, and
    // the cycle stopped with an internal error. Now the trial is halved
    // towards the peak and the least force searched between.
    let pull_off = |max_force| force_cycle_pull_off(rough_film(16), max_force, 2);
    let (small, large) = (pull_off(1e-5), pull_off(1e-4));
    // The edges are pinned at the peak's contact, which grows with the
    // peak force: measured -1.4050 mN at 10 uN against -1.7318 mN at
    // 100 uN (a ratio of 0.8113; 0.9553 while the closed cells of the
    // loading held with the receding work and the contacts grew past the
    // advancing work's, and 0.09 % apart when only the closed cells bonded
    // and the edges receded at once, both before 2026-12-04).
    assert!(small < 0.0 && small > large, "{small} {large}");
    assert!((small / large - 0.8113).abs() < 5e-3, "{small} {large}");
    // At 1 uN, steps of 0.5 uN against a pull-off of 1.4 mN: the peak's
    // contact is the advancing work's at about no load, as at 10 uN, and
    // the pinned edges come off within 0.4 % of that force (measured
    // -1.4000 mN, 418 steps as the unloading's steps double). Until
    // 2026-12-03 the loading's closed cells held with the receding work:
    // the path stood still for 32 steps and ended in the protocol's error.
    let tiny = pull_off(1e-6);
    assert!((tiny / small - 1.0).abs() < 1e-2, "{tiny} {small}");
}

#[test]
fn a_force_step_across_a_jump_of_the_force_takes_the_nearer_side() {
    // The rough film of seed 4 on 16 cells a side, work of adhesion 0.05
    // J/m^2, loaded to 100 uN in three steps: a patch snapping in or off
    // makes the force jump across a step's force, and the depth search
    // closed on the jump to brackets 1e-17 m wide without reaching the
    // resolution of f64 in its 100 trials (`NoConvergence`). Its pull-off
    // now: -2.0636 mN, against -2.0615 mN loaded to 1 mN.
    let mut scene = rough_film_seeded(16, 4);
    scene.adhesion = Adhesion::Constant {
        work_of_adhesion: 0.05,
    };
    let pull_off = |max_force| force_cycle_pull_off(scene.clone(), max_force, 3);
    let (jumping, reference) = (pull_off(1e-4), pull_off(1e-3));
    assert!(
        (jumping / reference - 1.0).abs() < 0.01,
        "{jumping} {reference}"
    );
}

#[test]
fn a_shallow_adhesive_cycle_comes_off_far_above_the_surface() {
    // The rough film of seed 1 on 16 cells a side (work of adhesion 0.05
    // J/m^2) pressed 1 and 10 nm: the contact jumps in, its force is least
    // a few nanometres above the surface (-1.64680 and -1.64633 mN
    // measured), and it holds, its pull falling off, to 0.82 and 1.03 um
    // above (820 and 103 loading depths); the run stopped with
    // `NoConvergence` at 20.
    let pull_off = |max_depth: f64| {
        let mut scene = rough_film_seeded(16, 1);
        scene.adhesion = Adhesion::Constant {
            work_of_adhesion: 0.05,
        };
        scene.protocol = Protocol::Cycle {
            max_depth,
            steps: 10,
        };
        let curve = scene.run(&mut |_| {}).unwrap();
        assert_eq!(curve.steps.last().unwrap().contact_area, 0.0);
        // Held far beyond the old bound of 20 loading depths.
        let held = curve.steps.iter().filter(|s| s.contact_area > 0.0);
        let highest = held.map(|s| s.depth).fold(0.0, f64::min);
        assert!(highest < -20.0 * max_depth, "{highest}");
        curve.pull_off().unwrap().force
    };
    let (one, ten) = (pull_off(1e-9), pull_off(1e-8));
    assert!((one / ten - 1.0).abs() < 5e-3, "{one} {ten}");
}
