//! The cohesive zone with adhesion hysteresis against the exact cycle of a
//! paraboloid on a half-space ([`LayeredJkrCycle`]): the contact edge pinned
//! from the loading peak until the energy release rate reaches the receding
//! work, then receding. The zone's bonded cells decide where it is pinned
//! (`src/solver/cohesive_bonding.rs`).

#![cfg(feature = "serde")]

use layered_contact::analytic::{Axisymmetric, LayeredJkrCycle};
use layered_contact::scene::{
    Adhesion, AdhesionMethod, Caveat, IndenterSpec, Phase, Protocol, Quantity, Resolution, Scene,
    SolverSettings, SubstrateSpec,
};
use layered_contact::{Material, Substrate};

mod common;
use common::pull_off_error;

const RADIUS: f64 = 0.1;
const MODULUS: f64 = 1e3;
const ADVANCING: f64 = 0.146;
const RECEDING: f64 = 1.122;
const MAX_DEPTH: f64 = 5e-3;

/// The paraboloid of the cohesive reference sweep's seed 29 (there a
/// sphere): 0.1 m on a 1 kPa half-space (`nu` = 0), works 0.146 and 1.122
/// J/m^2, pressed 5 mm in four steps and pulled off, through the cohesive
/// zone on `cells` cells across the pull-off contact.
fn pinned_cycle(cells: usize) -> Scene {
    Scene {
        substrate: SubstrateSpec::HalfSpace {
            youngs_modulus: MODULUS,
            poisson_ratio: 0.0,
        },
        indenter: IndenterSpec::Paraboloid { radius: RADIUS },
        adhesion: Adhesion::Hysteresis {
            loading: ADVANCING,
            unloading: RECEDING,
        },
        protocol: Protocol::Cycle {
            max_depth: MAX_DEPTH,
            steps: 4,
        },
        resolution: Resolution {
            cells_across: cells,
            ..Resolution::default()
        },
        solver: SolverSettings {
            adhesion_method: AdhesionMethod::CohesiveZone,
            ..SolverSettings::default()
        },
        ..Scene::default()
    }
}

/// The exact cycle of [`pinned_cycle`]'s paraboloid on its half-space.
fn exact_cycle() -> LayeredJkrCycle {
    let half_space = Substrate::half_space(Material::new(MODULUS, 0.0).unwrap());
    let exact = Axisymmetric::new(&half_space, 1.0).unwrap();
    LayeredJkrCycle::new(&exact, RADIUS, ADVANCING, RECEDING, MAX_DEPTH).unwrap()
}

/// Errors of [`pinned_cycle`] on `cells` against [`exact_cycle`]: the
/// pull-off's relative error, the largest error of the pinned unloading
/// branch (every unloading step before the least force, against the exact
/// force at its depth) and of the loading branch (every loading step), both
/// over the exact pull-off force.
fn errors(cells: usize) -> (f64, f64, f64) {
    let cycle = exact_cycle();
    let least = cycle.unloading_pull_off().unwrap();
    let scale = least.force.abs();
    let curve = pinned_cycle(cells).run(&mut |_| {}).unwrap();
    let pull_off = curve.pull_off().unwrap();
    let mut branch: f64 = 0.0;
    for step in curve.phase(Phase::Unloading) {
        if step.depth <= pull_off.depth {
            continue;
        }
        let state = cycle.unloading(step.depth).unwrap().unwrap();
        branch = branch.max((step.force - state.force).abs() / scale);
    }
    let mut loading: f64 = 0.0;
    for step in curve.phase(Phase::Loading) {
        let state = cycle.loading(step.depth).unwrap().unwrap();
        loading = loading.max((step.force - state.force).abs() / scale);
    }
    (pull_off.force / least.force - 1.0, branch, loading)
}

#[test]
fn a_pinned_edge_unloads_and_comes_off_near_the_exact_cycle() {
    // Measured (pull-off, largest branch error) at 16, 32 and 64 cells:
    // -9.17 %, 10.8 %; -4.16 %, 5.42 %; -1.88 %, 4.83 % (-1.85 %, 4.68 % at
    // 64 while the loading's closed cells held with the receding work,
    // before 2026-12-03). With the closed
    // cells alone bonded (before 2026-12-03): -24.7 %, 29.7 %; -12.6 %,
    // 19.6 %; -5.37 %, 11.9 %.
    for (cells, pull_off_bound, branch_bound) in [(32, 0.05, 0.065), (64, 0.025, 0.055)] {
        let (pull_off, branch, _) = errors(cells);
        assert!(
            pull_off.abs() < pull_off_bound,
            "{cells}: pull-off {pull_off}"
        );
        assert!(branch < branch_bound, "{cells}: branch {branch}");
    }
}

/// A sphere of 0.1 m on a 1 kPa layer 0.14 m thick over a base 2000 times
/// softer, works 0.177 and 1.122 J/m^2, through the cohesive zone on 32
/// cells across (the cohesive reference sweep's seed 56).
const SOFT_BELOW: &str = r#"
[substrate]
kind = "layer_on_elastic_base"
youngs_modulus = 1e3
poisson_ratio = 0
thickness = 1.39587327302203e-1
base_youngs_modulus = 5.459748547489498e-1
base_poisson_ratio = 0
[indenter]
kind = "sphere"
radius = 1e-1
[adhesion]
kind = "hysteresis"
loading = 1.766800595480793e-1
unloading = 1.1220184543019633e0
[protocol]
kind = "cycle"
max_depth = 5.011872336272722e-3
steps = 4
[resolution]
cells_across = 32
[solver]
adhesion_method = "cohesive_zone"
"#;

#[test]
fn the_loading_follows_the_advancing_work() {
    // The half-space: measured 0.29 % and 0.066 % of the pull-off force at
    // 32 and 64 cells; 0.29 % and 0.51 % while the loading's closed cells
    // held with the receding work (before 2026-12-03).
    let (_, _, error) = errors(64);
    assert!(error < 2e-3, "{error}");
    // Over the far softer base the receding work on the closed cells
    // pulled the contact on: the peak's radius +8.5 % and its force -13.1 %
    // at 32 cells (+10.2 % and -23.0 % at 64); now +1.56 % and +1.08 %
    // (+0.61 % and +0.35 % at 64). The bounds are the 32-cell
    // discretisation's: the same scene at its advancing work alone comes
    // out +0.71 % and +0.60 %.
    let scene = Scene::from_toml(SOFT_BELOW).unwrap();
    let curve = scene.run(&mut |_| {}).unwrap();
    let mut compared = 0;
    for reference in scene.reference().unwrap() {
        if matches!(
            reference.quantity,
            Quantity::PeakForce | Quantity::PeakContactRadius
        ) {
            let value = reference.quantity.of(&curve).unwrap();
            let error = value / reference.value - 1.0;
            assert!(error.abs() < 0.03, "{:?} {error:e}", reference.quantity);
            compared += 1;
        }
    }
    assert_eq!(compared, 2);
}

/// A sphere of 10 mm on a 0.2 mm rubber film (1 MPa, `nu` 0.48) on glass,
/// works 0.05 and 0.1 J/m^2, through the cohesive zone on 32 cells across:
/// its edge recedes before the pull-off.
const RECEDING_EDGE: &str = r#"
[substrate]
kind = "layer_on_rigid_base"
youngs_modulus = 1e6
poisson_ratio = 0.48
thickness = 2e-4
[indenter]
kind = "sphere"
radius = 0.01
[adhesion]
kind = "hysteresis"
loading = 0.05
unloading = 0.1
[protocol]
kind = "cycle"
max_depth = 5e-6
steps = 4
[resolution]
cells_across = 32
[solver]
adhesion_method = "cohesive_zone"
"#;

#[test]
fn a_pinned_pull_off_is_flagged_and_a_receding_one_is_not() {
    // The paraboloid comes off with 0.83 of its peak's contact area, its
    // pull-off -4.16 % off the exact one (above): flagged.
    let curve = pinned_cycle(32).run(&mut |_| {}).unwrap();
    assert!(curve.caveats.contains(&Caveat::CohesivePinnedPullOff));
    // The film's sphere comes off with 0.52 of it, within 0.24 % of the
    // exact pull-off (measured -0.236 %): not flagged.
    let scene = Scene::from_toml(RECEDING_EDGE).unwrap();
    let curve = scene.run(&mut |_| {}).unwrap();
    assert!(!curve.caveats.contains(&Caveat::CohesivePinnedPullOff));
    let error = pull_off_error(&scene, &curve);
    assert!(error.abs() < 5e-3, "{error}");
    // Over the base 2000 times softer the caveat holds whatever the
    // pull-off's contact (measured -9.55 % at 32 cells).
    let curve = Scene::from_toml(SOFT_BELOW)
        .unwrap()
        .run(&mut |_| {})
        .unwrap();
    assert!(curve.caveats.contains(&Caveat::CohesivePinnedPullOff));
}

/// The reference sweep's seed 156 at 16 cells across (its scene as the
/// sweep shrank it): a sphere on a nearly incompressible 1 kPa film over a
/// base 34 times stiffer, works 2.6e-4 and 1.8e-3 J/m^2.
const TAIL_UNRESOLVED: &str = r#"
[substrate]
kind = "layer_on_elastic_base"
youngs_modulus = 1e3
poisson_ratio = 0.4999
thickness = 3.8028840232949023e-3
base_youngs_modulus = 3.3779141073700375e4
base_poisson_ratio = 0
[indenter]
kind = "sphere"
radius = 1e-1
[adhesion]
kind = "hysteresis"
loading = 2.636743457951125e-4
unloading = 1.8065579553231054e-3
[protocol]
kind = "cycle"
max_depth = 7.707206228212584e-5
steps = 4
[resolution]
cells_across = 16
[solver]
adhesion_method = "cohesive_zone"
"#;

/// Past its least force the unloading of [`TAIL_UNRESOLVED`] steps to
/// -57.8 um, 3 % above where the exact contact lets go under displacement
/// control, and there the zone's fixed point reaches no equilibrium, in
/// 16 substeps either (the contact flips between four cells and none).
/// Before 2026-12-04 (thirty-second session) the whole scene failed with
/// `NoConvergence`; now the curve ends at the last equilibrium (-38.5 um,
/// still in contact) with `Caveat::CohesiveUnloadingCutShort`, and its
/// pull-off, found before, is the exact one's to the staircase of 16 cells
/// (measured -1.03 %; the sweep allows 5 % at 16 cells). Should the fixed
/// point one day reach that step, this test needs another scene.
#[test]
fn an_unloading_whose_tail_does_not_converge_ends_with_its_caveat() {
    let scene = Scene::from_toml(TAIL_UNRESOLVED).unwrap();
    let curve = scene.run(&mut |_| {}).unwrap();
    assert!(curve.caveats.contains(&Caveat::CohesiveUnloadingCutShort));
    let last = curve.steps.last().unwrap();
    assert_eq!(last.phase, Phase::Unloading);
    assert!(last.contact_area > 0.0 && last.depth < -3e-5, "{last:?}");
    let error = pull_off_error(&scene, &curve);
    assert!(error.abs() < 0.02, "{error}");
    // A cycle whose unloading reaches contact loss carries no such caveat.
    let curve = pinned_cycle(16).run(&mut |_| {}).unwrap();
    assert!(!curve.caveats.contains(&Caveat::CohesiveUnloadingCutShort));
    assert_eq!(curve.steps.last().unwrap().contact_area, 0.0);
}
