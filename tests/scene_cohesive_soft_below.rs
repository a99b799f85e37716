//! The cohesive zone on bodies softer below their surface than at it: a
//! stiff top layer over a far softer one. The zone's law is built with the
//! body's least modulus at wavelengths no longer than the zone
//! (`doc::adhesion`); before 2026-12-02 it took the surface material's,
//! the zone shrank to a fraction of a cell on these bodies, the lattice
//! trapped the contact's edge and the cycles came out tens of per cent
//! off their exact values with no more than a caveat of per cents (the
//! cohesive reference sweep's seed 13, `tests/reference_sweep.rs`). The
//! mesh-dependent criterion, whose critical stress takes the surface's
//! `E*` at the cell's scale, refuses such bodies.
//! A stiff layer on a half-space thousands of times softer is still off
//! by tens of per cents at 16 cells, as its caveat says (the last test).

#![cfg(feature = "serde")]

use layered_contact::scene::{Caveat, Curve, Quantity, Scene, ZONE_CONTACT_MODULUS_RATIO};

/// The scene of `substrate` and `indenter` (TOML tables' bodies), cycled
/// through the cohesive zone in four steps to `max_depth` with `work`
/// J/m^2, 16 cells across the pull-off contact.
fn cycle(substrate: &str, indenter: &str, work: f64, max_depth: f64) -> Scene {
    Scene::from_toml(&format!(
        "[substrate]\n{substrate}\n[indenter]\n{indenter}\n[adhesion]\nkind = \"constant\"\n\
         work_of_adhesion = {work:e}\n[protocol]\nkind = \"cycle\"\nmax_depth = {max_depth:e}\n\
         steps = 4\n[resolution]\ncells_across = 16\n[solver]\n\
         adhesion_method = \"cohesive_zone\"\n"
    ))
    .unwrap()
}

/// At 16 cells across: the peak force and pull-off within 2.5 % of the
/// exact axisymmetric values and the peak contact radius within 4 %: the
/// zone of two cells is longer than a quarter of the top layer (the
/// caveat's bias of per cents), and a cell is about a tenth of the radius.
const AT_16_CELLS: [(Quantity, f64); 3] = [
    (Quantity::PeakForce, 0.025),
    (Quantity::PeakContactRadius, 0.04),
    (Quantity::PullOffForce, 0.025),
];

/// Asserts that `scene` reports the caveat of a zone long against the
/// layer and comes within `bounds` (relative) of its exact values; returns
/// its curve.
fn assert_within_the_caveat(scene: &Scene, bounds: &[(Quantity, f64)]) -> Curve {
    assert_within(scene, &[Caveat::CohesiveZoneLongAgainstLayer], bounds)
}

/// Asserts that `scene` reports `caveats` and comes within `bounds`
/// (relative) of its exact values; returns its curve.
fn assert_within(scene: &Scene, caveats: &[Caveat], bounds: &[(Quantity, f64)]) -> Curve {
    let curve = scene.run(&mut |_| {}).unwrap();
    assert_eq!(curve.caveats, caveats);
    let references = scene.reference().unwrap();
    for &(quantity, bound) in bounds {
        let exact = references.iter().find(|r| r.quantity == quantity).unwrap();
        let error = quantity.of(&curve).unwrap() / exact.value - 1.0;
        assert!(error.abs() < bound, "{quantity:?} {error:e}");
    }
    curve
}

/// The paraboloid on the plate over a far softer layer of the first test
/// below, through the cohesive zone.
fn plate() -> Scene {
    cycle(
        "kind = \"stack\"\nlayers = [ { youngs_modulus = 4.851901410873788e9, poisson_ratio = \
         0.45, thickness = 3.759473894676288e-5 }, { youngs_modulus = 1.3204302992092755e7, \
         poisson_ratio = 0, thickness = 1.4047347491749039e-5 } ]\nbase = { youngs_modulus = \
         7.872956920080994e9, poisson_ratio = 0 }",
        "kind = \"paraboloid\"\nradius = 6.257314239145287e-3",
        4.865233519891493e3,
        2.1951840646478546e-5,
    )
}

/// A paraboloid (R 6.3 mm, 4865 J/m^2) on a 4.85 GPa layer 37.6 um thick
/// over a 13.2 MPa layer 14 um thick on a 7.9 GPa base, 131 um cells: at
/// the zone's 263 um the body is 8.6 times softer than its surface. Before:
/// peak force -69.2 %, its contact radius -17.9 %, pull-off +113.8 %. Now
/// +0.38, -3.0 and +1.57 % (2026-12-02). The bounds: 2.5 % on the peak
/// force and the pull-off (the zone longer than a quarter of the
/// top layer, the caveat's bias of per cents; -2.4 and +2.9 % at 64 cells,
/// the zone still 1.75 times the layer), 4 % on the radius (a cell is 11 %
/// of it).
#[test]
fn a_stiff_plate_over_a_far_softer_layer_cycles_to_its_exact_values() {
    assert_within_the_caveat(&plate(), &AT_16_CELLS);
}

/// The plate at 32 cells across: an unloading step's rounds came to
/// 4.0e-8 of the law's peak, then a mode of the rounds grew back by about
/// 1.5 % a round, and the scene ended in `NoConvergence` after 2000 rounds
/// (2026-12-02). The fixed point now hands back its closest round within
/// 1e-6 of the peak: peak force -7.30 %, its contact radius -0.77 %,
/// pull-off +5.08 % (2026-12-03; +0.38 / +1.57 % at 16 cells and -2.38 /
/// +2.91 % at 64: the zone is two cells, longer than the 37.6 um plate up
/// to 64 cells, and the caveat, which the scene reports, quotes this
/// bias). Bounded by 8 %, the caveat's.
#[test]
fn the_plate_at_32_cells_comes_back_from_its_closest_round() {
    let mut scene = plate();
    scene.resolution.cells_across = 32;
    let bounds = [(Quantity::PeakForce, 0.08), (Quantity::PullOffForce, 0.08)];
    assert_within_the_caveat(&scene, &bounds);
}

/// A sphere (R 0.1 m, 0.87 J/m^2) on a 1 kPa layer 2.3 mm thick over a
/// layer 370 times softer (2.7 Pa, 0.85 mm) on a 1.6 kPa base. Before:
/// peak force -56.3 %, contact radius -11.5 %, pull-off +96.9 %. Now
/// -0.04, -3.7 and +1.8 % (2026-12-02); the bounds as above.
#[test]
fn a_layer_over_a_far_softer_one_cycles_to_its_exact_values() {
    let scene = cycle(
        "kind = \"stack\"\nlayers = [ { youngs_modulus = 1e3, poisson_ratio = 0, thickness = \
         2.270897959111936e-3 }, { youngs_modulus = 2.7214697649255752e0, poisson_ratio = 0, \
         thickness = 8.485254491359048e-4 } ]\nbase = { youngs_modulus = 1.6226539357202516e3, \
         poisson_ratio = 0 }",
        "kind = \"sphere\"\nradius = 1e-1",
        8.653250843321382e-1,
        5.011872336272722e-3,
    );
    assert_within_the_caveat(&scene, &AT_16_CELLS);
}

/// The plate through the mesh-dependent criterion: at wavelengths of four
/// 131 um cells the body's `E*` is 0.041 of its surface's, and the
/// criterion's pull-off came out 13.3 times the exact one (+1234 %, its
/// caveat promising at most about 40 %). Refused, naming the ratio.
#[test]
fn the_mesh_criterion_refuses_a_body_far_softer_at_the_cells_scale() {
    let mut scene = plate();
    scene.solver.adhesion_method = layered_contact::scene::AdhesionMethod::MeshCriterion;
    match scene.run(&mut |_| {}) {
        Err(layered_contact::Error::InvalidParameter { value, .. }) => {
            assert!((value - 0.0409).abs() < 5e-4, "{value}");
        }
        other => panic!("{:?}", other.map(|c| c.pull_off().map(|p| p.force))),
    }
}

/// A paraboloid (R 3.4 mm, 68.6 J/m^2) on a 57 GPa layer 24 um thick
/// resting on a 14.8 MPa base (3850 times softer; the cohesive reference
/// sweep's seed 74), 35 um cells: the zone of two cells is 2.9 times the
/// layer's thickness, the body 448 times as stiff at that length as at
/// the peak contact's radius, and the caveats of a zone long against the
/// layer and stiffer than the contact quote what that costs: the pull-off
/// +39.9 % (+22, +14, +5.1, +0.20 % at 20, 24, 32, 64 cells, measured with
/// the tool on 2026-12-03; the energy balance's peak force +0.04 % at 16). Asserted within 35 to 45 %
/// and flagged, so that the caveat's quote follows the method: a change
/// that moves it must move the caveat's numbers too.
#[test]
fn a_stiff_layer_on_a_far_softer_half_space_is_as_far_off_as_its_caveat_says() {
    let scene = cycle(
        "kind = \"layer_resting_on_elastic_base\"\nyoungs_modulus = 5.699309133317363e10\n\
         poisson_ratio = 0.3\nthickness = 2.412818170441917e-5\n\
         base_youngs_modulus = 1.47934312668344e7\nbase_poisson_ratio = 0.5",
        "kind = \"paraboloid\"\nradius = 3.408462164269162e-3",
        6.857232844176532e1,
        5.385678181901121e-6,
    );
    let curve = scene.run(&mut |_| {}).unwrap();
    assert_eq!(
        curve.caveats,
        [
            Caveat::CohesiveZoneLongAgainstLayer,
            Caveat::CohesiveZoneStifferThanContact
        ]
    );
    let exact = scene.reference().unwrap();
    let pull_off = exact
        .iter()
        .find(|r| r.quantity == Quantity::PullOffForce)
        .unwrap();
    let error = Quantity::PullOffForce.of(&curve).unwrap() / pull_off.value - 1.0;
    assert!((0.35..0.45).contains(&error), "{error:e}");
}

/// A flat punch (0.66 mm) on a 1.93 GPa layer 41.8 um thick over a base
/// 194 times softer (the cohesive reference sweep's seed 89), 16 cells
/// across: the zone of two cells is 3.9 times the layer and the body 65
/// times as stiff at its length as at the punch's radius, past
/// [`ZONE_CONTACT_MODULUS_RATIO`], yet the punch's face holds the edge and
/// its stiffness, peak force and pull-off come within 2 % of the exact
/// values (measured -1.31, -1.36 and -0.45 %; the sweep's five punches
/// above the ratio within 1.4 %): it carries no caveat, neither the one of
/// a zone stiffer than the contact nor (since 2026-12-04, thirty-third
/// session) the long-zone one: an untilted punch's contact is its face
/// from the first step, and no zone forms on it.
#[test]
fn a_flat_punch_past_the_ratio_is_not_flagged_stiffer_than_its_contact() {
    let scene = cycle(
        "kind = \"layer_on_elastic_base\"\nyoungs_modulus = 1.9342804801992502e9\n\
         poisson_ratio = 0.4999\nthickness = 4.182135283386953e-5\n\
         base_youngs_modulus = 9.94860956521798e6\nbase_poisson_ratio = 0.3",
        "kind = \"flat_punch\"\nradius = 6.603943603198456e-4",
        3.644432772560535e5,
        8.744245932003516e-11,
    );
    let curve = assert_within(
        &scene,
        &[],
        &[
            (Quantity::Stiffness, 0.02),
            (Quantity::PeakForce, 0.02),
            (Quantity::PullOffForce, 0.02),
        ],
    );
    let scales = scene.zone_scales(&curve).unwrap().unwrap();
    assert!(
        scales.modulus_ratio > ZONE_CONTACT_MODULUS_RATIO,
        "{scales:?}"
    );
}
