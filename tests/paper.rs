//! A reduced run of the `paper` example's logic (a few points), checked
//! against the exact axisymmetric solutions: BEM stiffness within 0.1 %,
//! flat-punch and sphere pull-off within 1 % (measured: stiffness within
//! 0.02 %, pull-offs +0.08 % and +0.12 %; the full example's worst pull-off
//! is 0.3 %).

#[path = "../src/bin/layered-contact/paper/experiment.rs"]
mod experiment;

use experiment::Config;

#[test]
fn reduced_paper_run_matches_exact_solutions() {
    let config = Config {
        thicknesses_mm: vec![10.0],
        stiffness_diameters_mm: vec![4.0, 15.0],
        punch_diameters_mm: vec![7.0],
        sphere_radii_mm: vec![30.0],
        ..Config::standard()
    };
    // Stiffness: measured -0.011 % and -0.016 % (Richardson extrapolation of
    // 80 and 160 cells across on equal-area punch grids; from 64 and 128
    // cells the accuracy harness measures up to 0.057 %).
    let rows = experiment::stiffness_rows(&config, &|| {}).unwrap();
    let with_bem: Vec<_> = rows.iter().filter(|r| r.bem.is_some()).collect();
    assert_eq!(with_bem.len(), 2);
    for row in with_bem {
        let error = row.bem.unwrap() / row.exact - 1.0;
        assert!(
            error.abs() < 1e-3,
            "D = {} mm: BEM off by {error}",
            row.d_mm
        );
        // The series and the exact solution agree at a/h <= 0.2 to 1.1e-4.
        if row.eps <= 0.2 {
            assert!((row.series / row.exact - 1.0).abs() < 2e-4);
        }
    }

    // Flat punch D = 7 mm on h = 10 mm: measured +0.08 %.
    let curve = experiment::punch_scene(10.0, 7.0, config.punch_depth, config.steps)
        .run(&mut |_| {})
        .unwrap();
    let exact = experiment::exact_punch_pull_off(10.0, 7.0, experiment::DGAMMA_PUNCH).unwrap();
    let error = experiment::pull_off(&curve) / exact - 1.0;
    assert!(error.abs() < 0.01, "flat punch pull-off off by {error}");
    // Indentation and pull-off branches coincide for d > 0 (paper.json claim).
    let stiffness = curve.stiffness().unwrap();
    for step in curve
        .steps
        .iter()
        .filter(|s| s.depth > 0.0 && s.contact_area > 0.0)
    {
        assert!(
            (step.force - stiffness * step.depth).abs() < 0.01 * stiffness * config.punch_depth
        );
    }

    // Sphere R = 30 mm on h = 15 mm, dgamma0 = 0.0175 / dgamma1 = 0.326,
    // 32 cells across the pull-off contact, energy balance: measured +0.12 %
    // (at most 0.3 % over all 21 runs of the default example).
    let curve = experiment::sphere_scene(
        30.0,
        15.0,
        experiment::DGAMMA_PUNCH,
        config.sphere_depth,
        config.steps,
        config.cells_across_sphere,
    )
    .run(&mut |_| {})
    .unwrap();
    let exact = experiment::exact_sphere_pull_off(30.0, 15.0, experiment::DGAMMA_PUNCH).unwrap();
    let error = experiment::pull_off(&curve) / exact - 1.0;
    assert!(error.abs() < 0.01, "sphere pull-off off by {error}");
    // Hysteresis: at the same depth, unloading carries less force than loading.
    let loading_at = |d: f64| {
        curve
            .steps
            .iter()
            .find(|s| {
                s.phase == layered_contact::scene::Phase::Loading && (s.depth - d).abs() < 1e-12
            })
            .map(|s| s.force)
    };
    let unloading = curve
        .phase(layered_contact::scene::Phase::Unloading)
        .find(|s| s.depth < config.sphere_depth && loading_at(s.depth).is_some())
        .unwrap();
    assert!(unloading.force < loading_at(unloading.depth).unwrap());
}
