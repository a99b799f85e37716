//! Adhesive scenes through the cohesive zone, the automatic method for
//! scenes whose contact sets are not discs, and the automatic choice. A
//! tilted paraboloid is a paraboloid moved off the axis (`r^2 / 2R + x
//! tan(t)` is the paraboloid about `x = -R tan(t)`, lowered by `R tan(t)^2
//! / 2`), so its JKR pull-off force is exactly `-3 pi R dgamma / 2`
//! (Johnson, Kendall & Roberts 1971) while its contact lies off the grid's
//! cell centres: both methods are measured against it.

use std::f64::consts::PI;

use layered_contact::analytic::JkrSphere;
use layered_contact::grid::Boundary;
use layered_contact::scene::{
    Adhesion, AdhesionMethod, IndenterSpec, Phase, Protocol, Quantity, Resolution, Scene,
    SolverSettings, SubstrateSpec, Tilt,
};
use layered_contact::Error;

mod common;

use common::rubber_sphere::{paraboloid_cycle, rubber, RADIUS, WORK};

/// A rubber half-space under a paraboloid tilted so that its contact
/// centre moves by `(0.3, 0.17)` pull-off contact radii, cycled with the
/// pull-off contact `cells` cells across.
fn tilted_cycle(cells: usize) -> Scene {
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let a = jkr.pull_off_contact_radius();
    let tilt = Tilt {
        angle_y: (0.3 * a / RADIUS).atan(),
        angle_x: (0.17 * a / RADIUS).atan(),
    };
    let resolution = Resolution {
        cells_across: cells,
        margin: 0.6,
    };
    paraboloid_cycle(Some(tilt), jkr.depth(1.6 * a), 6, resolution)
}

#[test]
fn a_tilted_sphere_cycle_through_the_cohesive_zone_has_its_jkr_pull_off() {
    let mut scene = tilted_cycle(32);
    scene.solver.adhesion_method = AdhesionMethod::CohesiveZone;
    let curve = scene.run(&mut |_| {}).unwrap();
    assert!(curve.caveats.is_empty(), "{:?}", curve.caveats);
    let exact = -1.5 * PI * RADIUS * WORK;
    let pull_off = curve.pull_off().unwrap();
    let error = pull_off.force / exact - 1.0;
    // The sphere centred on the grid at 32 cells across: -0.61 % (the
    // cohesive zone's second-order error, tests/cohesive.rs); moved off
    // the cell centres by a fraction of a cell, -0.67 %; this scene's
    // paraboloid, -0.688 % (with the zone of 8 cells -2.42, -2.41 and
    // -2.40 %).
    assert!((error + 0.0069).abs() < 0.002, "{error}");
    // The pull-off is the parabola's vertex, a minimum of the recorded
    // steps, in the unloading, and the contact is lost at its end.
    assert_eq!(pull_off.phase, Phase::Unloading);
    let last = curve.steps.last().unwrap();
    assert!(last.contact_area == 0.0 && last.depth < pull_off.depth);
    // Depths fall monotonically along the unloading.
    let unloading: Vec<f64> = curve.phase(Phase::Unloading).map(|s| s.depth).collect();
    assert!(unloading.windows(2).all(|w| w[1] <= w[0]), "{unloading:?}");
}

#[test]
fn a_tilted_paraboloid_takes_the_exact_energy_balance_and_a_tilted_cone_the_zone() {
    let scene = tilted_cycle(32);
    assert_eq!(
        scene.resolved_adhesion_method(),
        AdhesionMethod::EnergyBalance
    );
    let curve = scene.run(&mut |_| {}).unwrap();
    // Its sets are discs about the moved axis: no caveat, and the pull-off
    // as exact as the centred sphere's (doc::accuracy: 0.1 % at 32 cells).
    assert!(curve.caveats.is_empty(), "{:?}", curve.caveats);
    let error = curve.pull_off().unwrap().force / (-1.5 * PI * RADIUS * WORK) - 1.0;
    assert!(error.abs() < 1e-3, "{error}");
    // The sets of a tilted cone or sphere, or of any indenter on a periodic
    // grid, are not discs: the cohesive zone.
    let cone = Scene {
        indenter: IndenterSpec::Cone {
            half_angle: 1.2,
            base_radius: 1e-3,
        },
        ..scene.clone()
    };
    let sphere = Scene {
        indenter: IndenterSpec::Sphere { radius: RADIUS },
        ..scene.clone()
    };
    let periodic = Scene {
        boundary: layered_contact::Boundary::Periodic,
        tilt: None,
        ..scene.clone()
    };
    for other in [cone, sphere, periodic] {
        assert_eq!(
            other.resolved_adhesion_method(),
            AdhesionMethod::CohesiveZone,
            "{other:?}"
        );
    }
}

#[test]
fn the_automatic_method_for_punches_and_force_control() {
    let mut punch = tilted_cycle(32);
    punch.indenter = IndenterSpec::FlatPunch { radius: 1e-3 };
    // Automatic: a tilted punch takes the cohesive zone (and its peeling
    // path, tests/scene_tilted_punch.rs), an untilted one the exact
    // energy balance.
    assert_eq!(
        punch.resolved_adhesion_method(),
        AdhesionMethod::CohesiveZone
    );
    punch.validate().unwrap();
    punch.tilt = None;
    assert_eq!(
        punch.resolved_adhesion_method(),
        AdhesionMethod::EnergyBalance
    );
    let mut forced = tilted_cycle(32);
    forced.protocol = Protocol::ForceCycle {
        max_force: 1e-3,
        steps: 4,
    };
    // A tilted paraboloid's sets are discs under force control too; a
    // tilted cone's are not, and force control takes the cohesive zone
    // (a_force_cycle_through_the_cohesive_zone_follows_jkr_and_jumps_off_at_the_pull_off).
    assert_eq!(
        forced.resolved_adhesion_method(),
        AdhesionMethod::EnergyBalance
    );
    forced.indenter = IndenterSpec::Cone {
        half_angle: 1.2,
        base_radius: 1e-3,
    };
    assert_eq!(
        forced.resolved_adhesion_method(),
        AdhesionMethod::CohesiveZone
    );
    forced.validate().unwrap();
    forced.solver.adhesion_method = AdhesionMethod::MeshCriterion;
    assert!(matches!(forced.validate(), Err(Error::Unsupported { .. })));
}

/// Protocol steps twice as long as the JKR sphere's critical depth move
/// the contact by many cells in one solve: each solve reads the edge's
/// curvature again from the contact it converges to, so the pull-off is
/// the zone's own (a tilted sphere at 16 cells across: -2.88 %, against
/// -1.95 % centred, `tests/cohesive.rs`; with the zone of 8 cells -6.74
/// and -6.39 %). Read only once, from the first round's contact, the
/// correction took the wrong curvature on such steps and the pull-off
/// came out +9.3 % with the zone of 8 cells (the uncorrected zone's bias).
#[test]
fn coarse_protocol_steps_keep_the_zone_s_pull_off() {
    let tilt = Tilt {
        angle_y: 0.05,
        angle_x: 0.0,
    };
    let resolution = Resolution {
        cells_across: 16,
        ..Resolution::default()
    };
    let scene = Scene {
        indenter: IndenterSpec::Sphere { radius: RADIUS },
        ..paraboloid_cycle(Some(tilt), 2e-5, 4, resolution)
    };
    assert_eq!(
        scene.resolved_adhesion_method(),
        AdhesionMethod::CohesiveZone
    );
    let curve = scene.run(&mut |_| {}).unwrap();
    let error = curve.pull_off().unwrap().force / (-1.5 * PI * RADIUS * WORK) - 1.0;
    assert!((error + 0.0288).abs() < 0.005, "{error}");
}

#[test]
fn a_film_thinner_than_eight_cells_is_reported_and_a_thicker_one_converges() {
    // The cohesive zone is at most a quarter of the film: a film as thick
    // as the pull-off contact's radius, 8 cells at 16 cells across, takes
    // a zone of two cells (the sphere centred on the grid: -1.08 %,
    // tests/cohesive.rs; this scene -0.53 %; a zone of 8 cells there gave
    // -8.70 %) and no caveat; a film a quarter of that, 2 cells
    // thick, is too thin for any zone and the curve says so.
    use layered_contact::analytic::Axisymmetric;
    use layered_contact::scene::{Caveat, SubstrateSpec};
    use layered_contact::Substrate;
    let a = JkrSphere::new(&rubber(), RADIUS, WORK)
        .unwrap()
        .pull_off_contact_radius();
    for (thickness, reported) in [(a, false), (a / 4.0, true)] {
        let mut scene = tilted_cycle(16);
        scene.substrate = SubstrateSpec::LayerOnRigidBase {
            youngs_modulus: rubber().youngs_modulus(),
            poisson_ratio: rubber().poisson_ratio(),
            thickness,
        };
        scene.solver.adhesion_method = AdhesionMethod::CohesiveZone;
        let curve = scene.run(&mut |_| {}).unwrap();
        assert_eq!(
            curve
                .caveats
                .contains(&Caveat::CohesiveZoneLongAgainstLayer),
            reported,
            "{:?}",
            curve.caveats
        );
        if !reported {
            let film = Substrate::layer_on_rigid_base(rubber(), thickness).unwrap();
            let body = Axisymmetric::up_to_contact_radius(&film, 4.0 * a).unwrap();
            let exact = body.paraboloid(RADIUS, WORK).unwrap().pull_off().unwrap();
            let error = curve.pull_off().unwrap().force / exact.load_control.force - 1.0;
            println!("{error}");
            assert!(error.abs() < 0.015, "{error}");
        }
    }
}

#[test]
fn a_force_cycle_through_the_cohesive_zone_follows_jkr_and_jumps_off_at_the_pull_off() {
    // Force control: each step is one fixed point under force control
    // (or, where it fails, a depth search along the displacement-controlled
    // path), so each force is the one asked (to rounding), the
    // depth at each force is JKR's (Johnson,
    // Kendall & Roberts 1971) to the zone's error, and the unloading ends
    // at the load-controlled pull-off, -3 pi R dgamma / 2, then a step
    // without contact.
    let jkr = JkrSphere::new(&rubber(), RADIUS, WORK).unwrap();
    let max_force = -2.0 * jkr.pull_off_force();
    let mut scene = tilted_cycle(32);
    scene.protocol = Protocol::ForceCycle {
        max_force,
        steps: 4,
    };
    assert_eq!(
        scene.resolved_adhesion_method(),
        AdhesionMethod::EnergyBalance
    );
    scene.solver.adhesion_method = AdhesionMethod::CohesiveZone;
    let curve = scene.run(&mut |_| {}).unwrap();
    // The tilted paraboloid's depths are its apex's, lowered by R tan(t)^2 / 2.
    let tilt = scene.tilt.unwrap();
    let (tx, ty) = (tilt.angle_x.tan(), tilt.angle_y.tan());
    let lowered = 0.5 * RADIUS * (tx * tx + ty * ty);
    let loading: Vec<_> = curve.phase(Phase::Loading).collect();
    assert_eq!(loading.len(), 5);
    for (k, step) in loading.iter().enumerate() {
        let force = k as f64 * max_force / 4.0;
        // Each force as asked to rounding: the fixed point under force
        // control carries it (measured at most 9.4e-14 of the largest; the
        // depth search, where it takes a step, comes to 1e-6 of it or to
        // the nearer side of a snap, 2.4e-5 here before).
        let off = (step.force - force).abs() / max_force;
        assert!(off <= 1e-12, "{force} {step:?}");
        let radius = jkr.contact_radius_at_force(force).unwrap();
        let depth = jkr.depth(radius);
        let error = (step.depth + lowered - depth) / jkr.critical_depth().abs();
        // Measured -0.52 % at zero force to -0.30 % at the peak: the
        // zone's error at 32 cells across (-1.56 % to -0.89 % with the
        // zone of 8 cells).
        println!("{k} {error}");
        assert!(error.abs() < 0.025, "{k} {error}");
    }
    let pull_off = curve.pull_off().unwrap();
    let error = pull_off.force / (-1.5 * PI * RADIUS * WORK) - 1.0;
    println!("pull-off {error}");
    // The displacement-controlled cycle of this scene: -0.688 %; measured
    // -0.694 % (with the zone of 8 cells -2.40 % both ways).
    assert!((error + 0.0069).abs() < 0.002, "{error}");
    let last = curve.steps.last().unwrap();
    assert!(last.contact_area == 0.0 && last.force == 0.0 && last.depth == pull_off.depth);
    // One step of force control: the peak's force (or the nearer side of
    // a snap, as above), at JKR's depth (the cycle's peak: -0.30 % of the
    // critical depth).
    scene.protocol = Protocol::Force { force: max_force };
    let curve = scene.run(&mut |_| {}).unwrap();
    assert_eq!(curve.steps.len(), 1);
    let step = curve.steps[0];
    assert!(
        (step.force - max_force).abs() <= 1e-3 * max_force,
        "{step:?}"
    );
    let depth = jkr.depth(jkr.contact_radius_at_force(max_force).unwrap());
    let error = (step.depth + lowered - depth) / jkr.critical_depth().abs();
    println!("force {error}");
    assert!(error.abs() < 0.025, "{error}");
}

/// A scene's unloading step that the cohesive zone's fixed point cannot
/// reach (the cycle loaded and unloaded in one whole step of twice its
/// peak depth, the inner solves held to ten iterations: the first
/// unloading step, from the peak back to the depth of first touch,
/// returns `NoConvergence`) is taken in substeps: the same pull-off as the
/// unrestricted scene's. (At the peak of 1.6 pull-off radii the same
/// step came within ten iterations once a warm start far from the new
/// depth's scale was scaled to it, 2026-11-29.)
#[test]
fn a_scene_step_out_of_reach_is_taken_in_substeps() {
    let pull_off = |max_iterations: usize| {
        let mut scene = tilted_cycle(24);
        if let Protocol::Cycle { steps, max_depth } = &mut scene.protocol {
            *steps = 1;
            *max_depth *= 2.0;
        }
        scene.solver.adhesion_method = AdhesionMethod::CohesiveZone;
        scene.solver.max_iterations = max_iterations;
        let curve = scene.run(&mut |_| {}).unwrap();
        let iterations: usize = curve.steps.iter().map(|s| s.iterations).sum();
        (curve.pull_off().unwrap().force, iterations)
    };
    let free = pull_off(1000);
    let held = pull_off(10);
    // The substeps' solves are counted (measured: 752 iterations against
    // 653); equal counts would mean no step needed them.
    assert!(held.1 > free.1, "{held:?} {free:?}");
    // Measured 5e-14 apart: the same equilibria, to the search's rounding.
    assert!((held.0 / free.0 - 1.0).abs() < 1e-9, "{held:?} {free:?}");
}

/// A force cycle whose steps the cohesive path cannot resolve: a work of
/// adhesion of 1e30 J/m^2 under a paraboloid of 10 mm (the grid sized to a
/// pull-off contact some 1e7 m across, JKR's pull-off force about 5e28 N)
/// cycled to 1 mN in steps of 0.25 mN. Every step landed on one and the
/// same equilibrium (6.3e12 N), and the unloading into tension would have
/// repeated it up to the protocol's bound of 100000 steps (hours). It now
/// stops with a typed error naming the step after 32 such steps (4 s). On
/// an isolated grid such a scene is now refused before any solve (the next
/// test); on a periodic one, where no closed form bounds the pull-off, the
/// steps that stand still stop it (1.8 s).
#[test]
fn a_force_cycle_whose_steps_the_path_cannot_resolve_is_a_typed_error() {
    let scene = Scene {
        substrate: SubstrateSpec::HalfSpace {
            youngs_modulus: 1e6,
            poisson_ratio: 0.48,
        },
        indenter: IndenterSpec::Paraboloid { radius: 10e-3 },
        boundary: Boundary::Periodic,
        adhesion: Adhesion::Constant {
            work_of_adhesion: 1e30,
        },
        protocol: Protocol::ForceCycle {
            max_force: 1e-3,
            steps: 4,
        },
        resolution: Resolution {
            cells_across: 16,
            ..Resolution::default()
        },
        ..Scene::default()
    };
    scene.validate().unwrap();
    let outcome = common::bounded(move || scene.run(&mut |_| {}));
    match outcome {
        Err(Error::InvalidParameter { name, value, .. }) => {
            assert_eq!(name, "protocol.max_force / steps (N)");
            assert_eq!(value, 2.5e-4);
        }
        other => panic!("{other:?}"),
    }
}

/// A force cycle whose pull-off lies beyond the protocol's bound of steps
/// is refused before any solve, where a closed form bounds the pull-off:
/// a 10 mm paraboloid at 1e10 J/m^2 cycled to 1 mN in steps of 0.25 mN
/// needs some 2e12 unloading steps to JKR's pull-off of 4.7e8 N (the
/// cohesive path stepped on at 25 steps a second, 67 minutes to the
/// protocol's bound). Both methods, and `validate`, refuse it at once. The
/// bound itself: a flat punch, whose bound is a tenth of Kendall's
/// pull-off, is refused with one step fewer than the bound needs and
/// accepted at the bound.
#[test]
fn a_force_cycle_whose_pull_off_is_out_of_reach_is_refused_before_solving() {
    let scene = |indenter, work, max_force, steps, method| Scene {
        substrate: SubstrateSpec::HalfSpace {
            youngs_modulus: 1e6,
            poisson_ratio: 0.48,
        },
        indenter,
        adhesion: Adhesion::Constant {
            work_of_adhesion: work,
        },
        protocol: Protocol::ForceCycle { max_force, steps },
        resolution: Resolution {
            cells_across: 16,
            ..Resolution::default()
        },
        solver: SolverSettings {
            adhesion_method: method,
            ..SolverSettings::default()
        },
        ..Scene::default()
    };
    let refused = |scene: Scene| {
        for outcome in [
            scene.validate(),
            common::bounded(move || scene.run(&mut |_| {}).map(|_| ())),
        ] {
            match outcome {
                Err(Error::InvalidParameter { name, .. }) => {
                    assert_eq!(name, "protocol.max_force / steps (N)")
                }
                other => panic!("{other:?}"),
            }
        }
    };
    let paraboloid = IndenterSpec::Paraboloid { radius: 10e-3 };
    for method in [AdhesionMethod::Auto, AdhesionMethod::CohesiveZone] {
        refused(scene(paraboloid.clone(), 1e10, 1e-3, 4, method));
    }
    // Kendall's pull-off of a 1 mm punch at 0.05 J/m^2 on E* = E / (1 -
    // nu^2): the unloading from max_force to a tenth of it, in steps of
    // max_force / steps, must take at most 100000 steps.
    let (radius, work) = (1e-3f64, 0.05);
    let modulus = 1e6 / (1.0 - 0.48f64.powi(2));
    let kendall = (8.0 * PI * radius.powi(3) * modulus * work).sqrt();
    let max_force = 1e-6;
    let fits = (100_000.0 * max_force / (max_force + kendall / 10.0)).floor() as usize;
    let punch = IndenterSpec::FlatPunch { radius };
    refused(scene(
        punch.clone(),
        work,
        max_force,
        fits + 1,
        AdhesionMethod::Auto,
    ));
    scene(punch, work, max_force, fits, AdhesionMethod::Auto)
        .validate()
        .unwrap();
}

/// A sphere of `radius` on `substrate` through the cohesive zone, with
/// `cells` cells across its pull-off contact (the reference sweep's scenes
/// of the two tests below).
fn sphere_through_the_zone(
    substrate: SubstrateSpec,
    radius: f64,
    adhesion: Adhesion,
    protocol: Protocol,
    cells: usize,
) -> Scene {
    Scene {
        substrate,
        indenter: IndenterSpec::Sphere { radius },
        adhesion,
        protocol,
        resolution: Resolution {
            cells_across: cells,
            ..Default::default()
        },
        solver: SolverSettings {
            adhesion_method: AdhesionMethod::CohesiveZone,
            ..Default::default()
        },
        ..Scene::default()
    }
}

/// A sphere (R 53 um) on a 4.3 GPa film 3.2 um thick over a base 4700
/// times softer (0.92 MPa), `dgamma` 11.6 J/m^2, solved once at depth 0
/// from no contact through the cohesive zone (8 cells across the pull-off
/// contact): the contact's held tensions move the surface by 1.6e4 of the
/// law's ranges, and inner solves to a hundredth of the change left the
/// gaps wrong by many ranges, so the fixed point never settled (2000
/// rounds, about 50 s, `NoConvergence` with the change at the law's
/// peak; a case of the reference sweep with the cohesive zone forced).
/// With the inner solves tightened by that displacement the force at
/// depth 0 is +1.69 % off the exact axisymmetric solution, +0.48 % at 12
/// cells across (27 s). The 2.5 % bound: at 8 cells the zone spans more
/// than a quarter of the film, which the scene reports as a bias of per
/// cents.
#[test]
fn a_cold_solve_on_a_stiff_film_over_a_far_softer_base_settles() {
    let scene = sphere_through_the_zone(
        SubstrateSpec::LayerOnElasticBase {
            youngs_modulus: 4.325619078675405e9,
            poisson_ratio: 0.2,
            thickness: 3.157992190517384e-6,
            base_youngs_modulus: 9.194112283532594e5,
            base_poisson_ratio: 0.0,
        },
        5.3311857979683405e-5,
        Adhesion::Constant {
            work_of_adhesion: 1.1608904617690778e1,
        },
        Protocol::Depth { depth: 0.0 },
        8,
    );
    let references = scene.reference().unwrap();
    let exact = references
        .iter()
        .find(|r| r.quantity == Quantity::PeakForce)
        .unwrap();
    let curve = scene.run(&mut |_| {}).unwrap();
    let force = curve.steps.last().unwrap().force;
    let error = force / exact.value - 1.0;
    assert!(error.abs() < 0.025, "force at depth 0 {error:e}");
    assert!(!curve.caveats.is_empty());
}

/// A sphere with hysteresis (2.2e-5 / 3.4e-5 J/m^2) on a 3 kPa layer
/// (`nu` 0.49, 0.16 mm, under two cells thick at 16 cells across the
/// pull-off contact) resting on a base 124 times softer, cycled through
/// the cohesive zone: before 2026-12-02 the first solve's rounds fell into
/// a cycle of eight (the contact had grown for six rounds and then stayed,
/// which the stepping kept reading as an edge zipping in, at full steps),
/// and the scene ended in `NoConvergence` after 2000 rounds (a case of the
/// reference sweep, seed 11). Now the peak force is -6.1 % of itself off
/// the exact axisymmetric value, 2.9 % of the cycle's force scale (the
/// exact pull-off, twice the net peak force: compression and adhesion
/// nearly cancel at the peak), and the pull-off +3.9 %; the 5 % bound on
/// the force scale is the bias of a zone longer than a quarter of the
/// layer, which the scene reports (-4.6 % with the zone the whole
/// thickness, on a rigid base). The peak's contact radius is -1.4 %
/// (+1.8, +0.19, +0.11 % at 32, 64, 128 cells, with the peak force +2.1,
/// -0.29, -0.36 % of itself), bounded by the reference sweep's 6 % for a
/// radius at 16 cells. Until 2026-12-03 the loading's closed cells held
/// with the receding work: +3.8 % at 16 cells, and +4.2, +5.0, +1.9 % at
/// 32, 64, 128 (`BENCHMARKS.md`, "The loading branch under hysteresis").
#[test]
fn a_layer_under_two_cells_thick_on_a_far_softer_base_is_cycled() {
    let scene = sphere_through_the_zone(
        SubstrateSpec::LayerRestingOnElasticBase {
            youngs_modulus: 2.9833060309763073e3,
            poisson_ratio: 0.49,
            thickness: 1.638695504925234e-4,
            base_youngs_modulus: 2.4079031600936393e1,
            base_poisson_ratio: 0.2,
        },
        2.1597276153468518e-2,
        Adhesion::Hysteresis {
            loading: 2.1611897749672226e-5,
            unloading: 3.353249567759468e-5,
        },
        Protocol::Cycle {
            max_depth: 4.658156645694662e-6,
            steps: 4,
        },
        16,
    );
    let curve = scene.run(&mut |_| {}).unwrap();
    assert!(!curve.caveats.is_empty());
    let references = scene.reference().unwrap();
    let scale = references
        .iter()
        .find(|r| r.quantity == Quantity::PullOffForce)
        .unwrap()
        .value
        .abs();
    let mut compared = 0;
    for reference in references {
        if let Some(value) = reference.quantity.of(&curve) {
            let error = if reference.quantity == Quantity::PeakForce {
                (value - reference.value) / scale
            } else {
                value / reference.value - 1.0
            };
            let radius = reference.quantity == Quantity::PeakContactRadius;
            let bound = if radius { 0.06 } else { 0.05 };
            assert!(error.abs() < bound, "{:?} {error:e}", reference.quantity);
            compared += 1;
        }
    }
    // The peak force, its contact radius and the pull-off.
    assert_eq!(compared, 3);
}
