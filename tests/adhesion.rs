//! Adhesive contact by the energy balance over the contact edge, against the
//! exact JKR solutions (closed form on a half-space, Fredholm on layers).
//!
//! Tolerances are set from the measured errors (quoted at each test, and in
//! `BENCHMARKS.md` from the `accuracy` example), with a factor of two to
//! five of room: the staircase makes the error fluctuate by about 0.1 %
//! from one grid to the next rather than fall monotonically.

use layered_contact::analytic::{Axisymmetric, JkrSphere, LayeredJkrCycle};
use layered_contact::indenter::{FlatPunch, HeightMap, Paraboloid};
use layered_contact::scene::{
    Adhesion, AdhesionMethod, Curve, IndenterSpec, Phase, Protocol, Resolution, Scene,
    SubstrateSpec,
};
use layered_contact::solver::{ContactSolver, Reach, SolverParams, EDGE_SHIFT};
use layered_contact::{Boundary, Error, Grid, Substrate};

mod common;

use common::rubber_sphere::{rubber, E, NU, RADIUS, WORK};

/// The exact JKR pull-off radius on a half-space of the rubber.
fn half_space_pull_off_radius() -> f64 {
    JkrSphere::new(&rubber(), RADIUS, WORK)
        .unwrap()
        .pull_off_contact_radius()
}

/// An adhesive sphere cycle on `substrate`, pressed until the contact is
/// 1.5 pull-off radii wide, `cells` across the pull-off contact.
fn sphere_cycle(substrate: SubstrateSpec, exact: &Axisymmetric, cells: usize) -> (Scene, f64) {
    let ball = exact.paraboloid(RADIUS, WORK).unwrap();
    let pull_off = ball.pull_off().unwrap().load_control;
    let depth = ball
        .at_contact_radius(1.5 * pull_off.contact_radius)
        .unwrap()
        .depth;
    let scene = Scene {
        substrate,
        indenter: IndenterSpec::Paraboloid { radius: RADIUS },
        adhesion: Adhesion::Constant {
            work_of_adhesion: WORK,
        },
        protocol: Protocol::Cycle {
            max_depth: depth,
            steps: 10,
        },
        resolution: Resolution {
            cells_across: cells,
            margin: 0.05,
        },
        ..Scene::default()
    };
    (scene, pull_off.force)
}

/// A solver on the rubber half-space with default parameters.
fn half_space_solver(grid: &Grid) -> ContactSolver {
    ContactSolver::new(
        &Substrate::half_space(rubber()),
        grid,
        Boundary::Isolated,
        SolverParams::default(),
    )
    .unwrap()
}

fn pull_off(curve: &Curve) -> f64 {
    curve.pull_off().unwrap().force
}

/// A digital disc of `m` cells on a half-space has the stiffness of a disc of
/// radius `sqrt(m / pi) - EDGE_SHIFT` cells: the calibration of the shift,
/// within 2e-3 from 10 to 40 cells of radius (measured -3e-5, -1.4e-4,
/// -9e-4 at 10.3, 19.7 and 40.2 cells: the digital disc's own roughness).
#[test]
fn edge_shift_is_the_stiffness_of_a_digital_disc() {
    let m = rubber();
    for radius_cells in [10.3, 19.7, 40.2] {
        let cells = (2.0 * radius_cells) as usize + 4;
        let delta = 1e-5;
        let grid = Grid::new(cells, cells, delta).unwrap();
        let mut solver = ContactSolver::new(
            &Substrate::half_space(m),
            &grid,
            Boundary::Isolated,
            SolverParams::default(),
        )
        .unwrap();
        let punch = FlatPunch::new(radius_cells * delta).unwrap();
        let (s, _) = solver.solve_depth(&punch, 1e-7, None, &mut ()).unwrap();
        let equal_area = (s.contact_cells as f64 / std::f64::consts::PI).sqrt();
        let shifted = 2.0 * m.contact_modulus() * (equal_area - EDGE_SHIFT) * delta;
        let ratio = s.force / 1e-7 / shifted;
        assert!((ratio - 1.0).abs() < 2e-3, "r = {radius_cells}: {ratio}");
    }
}

/// JKR pull-off of a sphere on a half-space: within 0.5 % at 16, 32 and 64
/// cells across the pull-off contact (measured -0.005 %, -0.05 %, +0.08 %);
/// the mesh-dependent criterion at 32 cells is 5.9 % too strong (it
/// converges like 3/N), bounded here by 9 %.
#[test]
fn sphere_pull_off_on_a_half_space() {
    let substrate = SubstrateSpec::HalfSpace {
        youngs_modulus: E,
        poisson_ratio: NU,
    };
    let exact = Axisymmetric::new(&substrate.build().unwrap(), 1.0).unwrap();
    let closed_form = JkrSphere::new(&rubber(), RADIUS, WORK)
        .unwrap()
        .pull_off_force();
    for cells in [16, 32, 64] {
        let (scene, reference) = sphere_cycle(substrate.clone(), &exact, cells);
        assert!((reference / closed_form - 1.0).abs() < 1e-9);
        let curve = scene.run(&mut |_| {}).unwrap();
        let error = pull_off(&curve) / closed_form - 1.0;
        assert!(error.abs() < 0.005, "{cells} cells: {error}");
    }
    // The reference method, mesh-dependent: about 3/N too strong.
    let (mut scene, _) = sphere_cycle(substrate, &exact, 32);
    scene.solver.adhesion_method = AdhesionMethod::MeshCriterion;
    let error = pull_off(&scene.run(&mut |_| {}).unwrap()) / closed_form - 1.0;
    assert!(error > 0.0 && error < 0.09, "mesh criterion: {error}");
}

/// Layers: rigid base with the pull-off contact about one thickness wide,
/// elastic base ten times stiffer with it about three thicknesses wide;
/// within 0.5 % of the exact layered JKR pull-off at 64 cells (measured
/// -0.10 % and +0.03 %).
#[test]
fn sphere_pull_off_on_layers() {
    let a = half_space_pull_off_radius();
    let cases = [
        SubstrateSpec::LayerOnRigidBase {
            youngs_modulus: E,
            poisson_ratio: NU,
            thickness: a,
        },
        SubstrateSpec::LayerOnElasticBase {
            youngs_modulus: E,
            poisson_ratio: NU,
            thickness: a / 3.0,
            base_youngs_modulus: 10.0 * E,
            base_poisson_ratio: 0.3,
        },
    ];
    for substrate in cases {
        let exact = Axisymmetric::new(&substrate.build().unwrap(), 20.0).unwrap();
        let (scene, reference) = sphere_cycle(substrate.clone(), &exact, 64);
        let curve = scene.run(&mut |_| {}).unwrap();
        let error = pull_off(&curve) / reference - 1.0;
        // Measured 2.6e-5 and 1.1e-4; within the staircase noise (about
        // 1e-4). The family of the half-space's spacing and fits gave
        // 6.7e-4 on the film on the rigid base: its bias on a layer.
        println!("{error:e}");
        assert!(error.abs() < 3e-4, "{substrate:?}: {error}");
    }
}

/// Along the whole unloading branch, not only at its minimum, the force is
/// within 1 % (of the pull-off force) of the exact layered JKR curve at 64
/// cells: compared at the same depth while the edge is pinned, and at the
/// same contact radius once it recedes (where the curve turns vertical and
/// a comparison at equal depth would measure the slope, not the error).
/// Measured: at most 0.18 % along the unloading branch, 0.10 % (of the peak
/// force) along the loading branch.
#[test]
fn whole_unloading_branch_follows_the_exact_curve() {
    let a = half_space_pull_off_radius();
    let substrate = SubstrateSpec::LayerOnRigidBase {
        youngs_modulus: E,
        poisson_ratio: NU,
        thickness: a,
    };
    let body = substrate.build().unwrap();
    let exact = Axisymmetric::new(&body, 20.0).unwrap();
    let (mut scene, reference) = sphere_cycle(substrate, &exact, 64);
    // Hysteresis: advancing work a third of the receding one.
    scene.adhesion = Adhesion::Hysteresis {
        loading: WORK / 3.0,
        unloading: WORK,
    };
    let Protocol::Cycle { max_depth, .. } = scene.protocol else {
        unreachable!()
    };
    let curve = scene.run(&mut |_| {}).unwrap();
    let cycle = LayeredJkrCycle::new(&exact, RADIUS, WORK / 3.0, WORK, max_depth).unwrap();
    let receding = exact.paraboloid(RADIUS, WORK).unwrap();
    let peak = cycle.peak();
    let mut compared = 0;
    for step in curve.phase(Phase::Unloading) {
        if step.contact_area == 0.0 {
            continue;
        }
        let expected = if step.contact_radius >= 0.999 * peak.contact_radius {
            cycle.unloading(step.depth).unwrap().unwrap().force
        } else {
            receding
                .at_contact_radius(step.contact_radius)
                .unwrap()
                .force
        };
        let error = (step.force - expected) / reference.abs();
        assert!(error.abs() < 0.01, "d = {}: {error}", step.depth);
        compared += 1;
    }
    assert!(compared > 15, "{compared} unloading steps compared");
    // The loading branch, at equal depth: within 0.5 % of the peak force.
    for step in curve.phase(Phase::Loading).filter(|s| s.depth > 0.0) {
        let expected = cycle.loading(step.depth).unwrap().unwrap().force;
        let error = (step.force - expected) / peak.force;
        assert!(error.abs() < 0.005, "loading d = {}: {error}", step.depth);
    }
}

/// Load control: the contact jumps in at zero force, and the pull-off under
/// force control is within 0.5 % of the exact value (closed form on a
/// half-space; measured -0.007 % at 48 cells); a pull beyond it is a typed
/// error, not a state.
#[test]
fn force_controlled_pull_off() {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let scene = Scene {
        substrate: SubstrateSpec::HalfSpace {
            youngs_modulus: E,
            poisson_ratio: NU,
        },
        indenter: IndenterSpec::Paraboloid { radius: RADIUS },
        adhesion: Adhesion::Constant {
            work_of_adhesion: WORK,
        },
        protocol: Protocol::ForceCycle {
            max_force: -jkr.pull_off_force(),
            steps: 8,
        },
        resolution: Resolution {
            cells_across: 48,
            margin: 0.05,
        },
        ..Scene::default()
    };
    let curve = scene.run(&mut |_| {}).unwrap();
    // Jump-in: contact at zero force, of the JKR radius there.
    let first = curve.steps[0];
    let a0 = jkr.contact_radius_at_force(0.0).unwrap();
    assert_eq!(first.force, 0.0);
    assert!((first.contact_radius / a0 - 1.0).abs() < 0.01);
    let error = pull_off(&curve) / jkr.pull_off_force() - 1.0;
    assert!(error.abs() < 0.005, "{error}");
    // The curve ends without contact, just after the pull-off.
    let last = curve.steps.last().unwrap();
    assert_eq!((last.force, last.contact_area), (0.0, 0.0));

    // The same branches answer force and depth requests; beyond the pull-off
    // force there is no equilibrium.
    let grid = scene.grid().unwrap();
    let mut solver = half_space_solver(&grid);
    let ball = Paraboloid::new(RADIUS).unwrap();
    let push = -0.5 * jkr.pull_off_force();
    let branches = solver
        .adhesive_branches(&ball, Reach::Force(push), WORK, WORK, &mut ())
        .unwrap();
    let loaded = branches.at_force(push, 0.0).unwrap();
    assert!((loaded.force - push).abs() < 1e-15);
    let exact_a = jkr.contact_radius_at_force(push).unwrap();
    assert!((loaded.contact_radius / exact_a - 1.0).abs() < 0.01);
    let beyond = 1.01 * jkr.pull_off_force();
    match branches.at_force(beyond, loaded.contact_area) {
        Err(Error::NoEquilibrium { force, least }) => {
            assert_eq!(force, beyond);
            assert!((least / jkr.pull_off_force() - 1.0).abs() < 0.005);
        }
        other => panic!("expected NoEquilibrium, got {other:?}"),
    }
    // A pull without contact has no equilibrium either.
    assert!(matches!(
        branches.at_force(-1e-6, 0.0),
        Err(Error::NoEquilibrium { .. })
    ));
}

/// Flat punch on a layer (rigid base, a/h = 0.35): the energy balance's
/// pull-off within 0.3 % of the exact layered value at 32 and 64 cells
/// (measured +0.09 % and +0.19 %).
#[test]
fn flat_punch_pull_off_on_a_layer() {
    let (a, h) = (3.5e-3, 10e-3);
    let substrate = SubstrateSpec::LayerOnRigidBase {
        youngs_modulus: 0.324e6,
        poisson_ratio: NU,
        thickness: h,
    };
    let exact = Axisymmetric::new(&substrate.build().unwrap(), 0.5)
        .unwrap()
        .flat_punch(a)
        .unwrap()
        .pull_off_force(0.326);
    for cells in [32, 64] {
        let scene = Scene {
            substrate: substrate.clone(),
            indenter: IndenterSpec::FlatPunch { radius: a },
            adhesion: Adhesion::Hysteresis {
                loading: 0.0175,
                unloading: 0.326,
            },
            protocol: Protocol::Cycle {
                max_depth: 2e-4,
                steps: 10,
            },
            resolution: Resolution {
                cells_across: cells,
                margin: 0.0,
            },
            ..Scene::default()
        };
        let curve = scene.run(&mut |_| {}).unwrap();
        let error = pull_off(&curve) / exact - 1.0;
        assert!(error.abs() < 0.003, "{cells} cells: {error}");
    }
}

/// The exact references: by depth and by force they return the states of
/// the contact-radius parametrisation, and on a half-space they are the
/// closed-form JKR curve.
#[test]
fn exact_layered_jkr_by_depth_and_force() {
    let body = Substrate::half_space(rubber());
    let exact = Axisymmetric::new(&body, 1.0).unwrap();
    let ball = exact.paraboloid(RADIUS, WORK).unwrap();
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    for depth in [-1e-6, 0.0, 2e-6, 1e-5] {
        let state = ball.at_depth(depth).unwrap().unwrap();
        let a = jkr.contact_radius_at_depth(depth).unwrap();
        assert!((state.contact_radius / a - 1.0).abs() < 1e-9, "{depth}");
        assert!((state.force - jkr.force(a)).abs() < 1e-9 * jkr.pull_off_force().abs());
    }
    for force in [0.5 * jkr.pull_off_force(), 0.0, 0.01] {
        let state = ball.at_force(force).unwrap().unwrap();
        let a = jkr.contact_radius_at_force(force).unwrap();
        assert!((state.contact_radius / a - 1.0).abs() < 1e-9, "{force}");
    }
    // Beyond the pull-off (load control) and the jump-off (displacement):
    // no equilibrium.
    assert!(ball
        .at_force(1.001 * jkr.pull_off_force())
        .unwrap()
        .is_none());
    assert!(ball
        .at_depth(1.001 * jkr.critical_depth())
        .unwrap()
        .is_none());
    // The cycle with hysteresis: pinned, then receding at dgamma1.
    let cycle = LayeredJkrCycle::new(&exact, RADIUS, 0.01, WORK, 1e-5).unwrap();
    let peak = cycle.peak();
    let loading = JkrSphere::new(&rubber(), RADIUS, 0.01).unwrap();
    assert!(
        (peak.contact_radius / loading.contact_radius_at_depth(1e-5).unwrap() - 1.0).abs() < 1e-9
    );
    let pinned = cycle.unloading(0.9e-5).unwrap().unwrap();
    assert_eq!(pinned.contact_radius, peak.contact_radius);
    // Pinned: the force falls with the punch stiffness 2 a E*.
    let slope = (peak.force - pinned.force) / 0.1e-5;
    assert!((slope / (2.0 * peak.contact_radius * rubber().contact_modulus()) - 1.0).abs() < 1e-9);
    let least = cycle.unloading_pull_off().unwrap();
    assert!((least.force / jkr.pull_off_force() - 1.0).abs() < 1e-9);
    assert!(cycle.loading(-1e-7).unwrap().is_none());
    assert!(matches!(
        LayeredJkrCycle::new(&exact, RADIUS, 0.1, 0.05, 1e-5),
        Err(Error::InvalidParameter { .. })
    ));
}

/// With hysteresis the energy-balance branches load above and unload below,
/// and an advancing work above the receding one is refused.
#[test]
fn hysteresis_and_invalid_works() {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let grid = Grid::square_of_side(96, 6.0 * a).unwrap();
    let mut solver = half_space_solver(&grid);
    let ball = Paraboloid::new(RADIUS).unwrap();
    let depth = (1.2 * a).powi(2) / RADIUS;
    assert!(matches!(
        solver.adhesive_branches(&ball, Reach::Depth(depth), 0.1, 0.05, &mut ()),
        Err(Error::InvalidParameter { .. })
    ));
    let branches = solver
        .adhesive_branches(&ball, Reach::Depth(depth), 0.2 * WORK, WORK, &mut ())
        .unwrap();
    let peak = branches.at_depth(depth, 0.0).unwrap();
    let loaded = branches.at_depth(0.5 * depth, 0.0).unwrap();
    let unloaded = branches.at_depth(0.5 * depth, peak.contact_area).unwrap();
    assert!(unloaded.force < loaded.force);
    assert!(unloaded.contact_area > loaded.contact_area);
    // The edge stays pinned just after the peak: same area, force linear.
    let just_after = branches.at_depth(0.99 * depth, peak.contact_area).unwrap();
    assert_eq!(just_after.contact_area, peak.contact_area);
}

/// A family whose contact splits into two patches is refused with a typed
/// error naming the way out.
#[test]
fn split_contact_is_refused() {
    let grid = Grid::square_of_side(48, 4.8e-3).unwrap();
    let heights: Vec<f64> = (0..grid.len())
        .map(|c| {
            let (i, j) = ((c / 48) as f64 - 23.5, (c % 48) as f64 - 23.5);
            let d1 = (i - 10.0).hypot(j);
            let d2 = (i + 10.0).hypot(j);
            1e-6 * d1.min(d2).powi(2)
        })
        .collect();
    let bumps = HeightMap::new(grid, heights).unwrap();
    let mut solver = half_space_solver(&grid);
    match solver.adhesive_branches(&bumps, Reach::Depth(2e-5), WORK, WORK, &mut ()) {
        Err(Error::Unsupported { reason, .. }) => assert!(reason.contains("mesh-dependent")),
        other => panic!("expected Unsupported, got {other:?}"),
    }
}
