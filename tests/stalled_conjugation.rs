//! A solve whose kept conjugation cycles goes back to Polonsky and Keer's
//! restarts (`src/solver/stall.rs`) and converges to the exact values.

#![cfg(feature = "serde")]

use layered_contact::scene::{Quantity, Scene};

/// A flat punch on a layer 2800 times stiffer than its base, through the
/// cohesive zone with hysteresis, 16 cells across: the cohesive zone's
/// first solve (zero depth, the whole face touching) cycled for 10000
/// iterations with one rim cell flickering in and out of the working set
/// and ended in `NoConvergence` (the cohesive reference sweep, seed 65);
/// 12, 20, 24 and 32 cells across converged. The scene as the sweep drew
/// it.
const SCENE: &str = r#"
[substrate]
kind = "layer_on_elastic_base"
youngs_modulus = 4.198204960616409e7
poisson_ratio = 0.3
thickness = 1.3344859375499145e-4
base_youngs_modulus = 1.4986186196828174e4
base_poisson_ratio = 0.5
[indenter]
kind = "flat_punch"
radius = 1.8743031511507004e-3
[adhesion]
kind = "hysteresis"
loading = 1.2916193544746537e2
unloading = 4.789703001115365e2
[protocol]
kind = "cycle"
max_depth = 9.393768113040992e-8
steps = 4
[resolution]
cells_across = 16
[solver]
adhesion_method = "cohesive_zone"
"#;

#[test]
fn a_cycling_conjugation_restarts_and_the_punch_meets_its_exact_values() {
    let scene = Scene::from_toml(SCENE).unwrap();
    let curve = scene.run(&mut |_| {}).unwrap();
    let references = scene.reference().unwrap();
    let mut checked = 0;
    for reference in &references {
        let value = reference.quantity.of(&curve).unwrap();
        let error = value / reference.value - 1.0;
        // Measured: stiffness and peak force -1.05 %, pull-off -0.071 %.
        // The bounds are the 16-cell punch's discretisation error: the same
        // scene through the energy balance comes out -0.94 % and -1.47 %,
        // and its pull-off at 12 to 32 cells through the cohesive zone
        // within 0.43 %.
        let bound = match reference.quantity {
            Quantity::PullOffForce => 5e-3,
            _ => 1.5e-2,
        };
        assert!(
            error.abs() < bound,
            "{}: {value:e} against {:e}",
            reference.quantity.name(),
            reference.value
        );
        checked += 1;
    }
    assert_eq!(checked, 3);
}
