//! The tabulated force curve (`analytic::ForceCurve`) against the exact
//! states it interpolates, computed directly at contact radii between the
//! table's: every tip, a layer on glass, on a softer base and a stack,
//! with and without adhesion, and rescaled to another modulus.

use layered_contact::analytic::{Axisymmetric, ForceCurve, Tip};
use layered_contact::substrate::Base;
use layered_contact::{Error, Material, Substrate};

fn film(e: f64) -> Material {
    Material::new(e, 0.45).unwrap()
}

fn bodies(e: f64) -> Vec<(&'static str, Substrate)> {
    vec![
        (
            "film on glass",
            Substrate::layer_on_rigid_base(film(e), 4e-6).unwrap(),
        ),
        (
            "film on a softer base",
            Substrate::layer_on_elastic_base(film(e), 4e-6, Material::new(0.3 * e, 0.3).unwrap())
                .unwrap(),
        ),
        (
            "stack",
            Substrate::stack(
                &[
                    (film(e), 3e-6),
                    (Material::new(10.0 * e, 0.3).unwrap(), 1e-6),
                ],
                Base::Rigid,
            )
            .unwrap(),
        ),
    ]
}

const TIPS: [Tip; 4] = [
    Tip::Paraboloid { radius: 5e-6 },
    Tip::Sphere { radius: 5e-6 },
    Tip::Cone { half_angle: 1.2 },
    Tip::RoundedCone {
        half_angle: 1.2,
        tip_radius: 0.5e-6,
    },
];

#[test]
fn the_table_reproduces_the_exact_states() {
    // Radii off the table's nodes; the fixed-grips branch only (beyond the
    // least depth). Measured worst, relative to the largest force: 1e-10 to
    // 4e-10 without adhesion, up to 6e-8 with it (next to the branch's
    // start, where the depth turns); bound 1e-7.
    for (i, (name, body)) in bodies(10e3).into_iter().enumerate() {
        let exact = Axisymmetric::up_to_contact_radius(&body, 20e-6).unwrap();
        // Every tip on glass, the paraboloid and the cone on the others.
        let tips = if i == 0 {
            &TIPS[..]
        } else {
            &[TIPS[0], TIPS[2]]
        };
        for &tip in tips {
            let curve = ForceCurve::new(&exact, tip, 2e-6).unwrap();
            for work in [0.0, 1e-3] {
                let states = exact.tip(tip, work).unwrap();
                let least = if work > 0.0 {
                    states
                        .pull_off()
                        .unwrap()
                        .displacement_control
                        .contact_radius
                } else {
                    0.0
                };
                // Errors relative to the largest force of the samples (a
                // force crossing zero has no relative error of its own).
                let samples: Vec<_> = (0..25)
                    .map(|k| 0.05e-6 * 1.17f64.powi(k))
                    .filter(|&a| a > 1.05 * least)
                    .map(|a| states.at_contact_radius(a).unwrap())
                    .take_while(|s| s.depth <= curve.max_depth())
                    .collect();
                let scale = samples.iter().map(|s| s.force.abs()).fold(0.0, f64::max);
                let worst = samples
                    .iter()
                    .map(|s| ((curve.force(s.depth, 1.0, work) - s.force) / scale).abs())
                    .fold(0.0, f64::max);
                println!("{name} {tip:?} w {work}: worst {worst:.1e}");
                assert!(worst < 1e-7, "{name} {tip:?} w {work}: {worst}");
            }
        }
    }
}

#[test]
fn on_glass_the_table_serves_every_modulus() {
    // A single layer on a rigid base: F scales with E* at fixed w / E*.
    let (e1, e2) = (10e3, 37e3);
    let table = Substrate::layer_on_rigid_base(film(e1), 4e-6).unwrap();
    let other = Substrate::layer_on_rigid_base(film(e2), 4e-6).unwrap();
    let curve = ForceCurve::new(
        &Axisymmetric::up_to_contact_radius(&table, 20e-6).unwrap(),
        TIPS[2],
        2e-6,
    )
    .unwrap();
    let exact = Axisymmetric::up_to_contact_radius(&other, 20e-6).unwrap();
    let states = exact.tip(TIPS[2], 2e-3).unwrap();
    for a in [0.4e-6, 1e-6, 2e-6] {
        let s = states.at_contact_radius(a).unwrap();
        let f = curve.force(s.depth, e2 / e1, 2e-3);
        assert!(((f - s.force) / s.force).abs() < 1e-7, "{f} {}", s.force);
    }
}

#[test]
fn flat_punch_is_linear_until_it_detaches() {
    let body = Substrate::layer_on_rigid_base(film(10e3), 4e-6).unwrap();
    let exact = Axisymmetric::up_to_contact_radius(&body, 2e-6).unwrap();
    let punch = exact.flat_punch(2e-6).unwrap();
    let curve = ForceCurve::flat_punch(&exact, 2e-6).unwrap();
    let (k, dc) = (punch.stiffness(), punch.critical_depth(1e-3));
    assert!((curve.force(1e-7, 1.0, 0.0) / (k * 1e-7) - 1.0).abs() < 1e-15);
    assert_eq!(curve.force(-1e-9, 1.0, 0.0), 0.0);
    assert!((curve.force(0.99 * dc, 1.0, 1e-3) / (k * 0.99 * dc) - 1.0).abs() < 1e-15);
    assert_eq!(curve.force(1.01 * dc, 1.0, 1e-3), 0.0);
}

#[test]
fn bad_requests_give_nan_or_errors() {
    let body = Substrate::layer_on_rigid_base(film(10e3), 4e-6).unwrap();
    let exact = Axisymmetric::up_to_contact_radius(&body, 20e-6).unwrap();
    let curve = ForceCurve::new(&exact, TIPS[0], 2e-6).unwrap();
    for (depth, ratio, work) in [
        (f64::NAN, 1.0, 0.0),
        (3e-6, 1.0, 0.0),
        (1e-6, 0.0, 0.0),
        (1e-6, f64::INFINITY, 0.0),
        (1e-6, 1.0, -1.0),
    ] {
        assert!(curve.force(depth, ratio, work).is_nan());
    }
    for depth in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            ForceCurve::new(&exact, TIPS[0], depth),
            Err(Error::InvalidParameter { .. })
        ));
    }
    // A cap cannot reach 6 um: its contact stays below 0.95 R.
    assert!(matches!(
        ForceCurve::new(&exact, Tip::Sphere { radius: 2e-6 }, 6e-6),
        Err(Error::InvalidParameter { .. })
    ));
}

/// A 4 um film of 10 kPa bonded to a gel of 1.25 kPa (`nu = 0.5`), and a
/// paraboloid of 5 um: a body whose force does not scale with the film's
/// modulus.
fn film_over_a_gel() -> (Substrate, Tip) {
    let gel = Material::new(1.25e3, 0.5).unwrap();
    let film =
        Substrate::layer_on_elastic_base(Material::new(1e4, 0.5).unwrap(), 4e-6, gel).unwrap();
    (film, Tip::Paraboloid { radius: 5e-6 })
}

#[test]
fn a_modulus_family_converges_geometrically_in_its_nodes() {
    // A film over a gel four times softer than its lower end, moduli over a
    // decade (5 to 50 kPa), against exact tables at five moduli off the
    // nodes, 40 depths to half the thickness. Measured: 2.6e-5 and 8.2e-9
    // relative with 6 and 10 nodes (a factor of about 7 per node; with a
    // gel twice as stiff 7.2e-5, 2.8e-8, and 7.2e-10 at 12 nodes, the
    // tables' own precision; 0.3 ms for 40 depths at 12 nodes). Asserted:
    // 1e-6 at 10 nodes and a fall of at least 100 from 6.
    use layered_contact::analytic::ModulusFamily;
    let (film, tip) = film_over_a_gel();
    let depths: Vec<f64> = (1..=40).map(|k| 2e-6 * k as f64 / 40.0).collect();
    let moduli = [5.3e3, 9.1e3, 17.7e3, 33e3, 47e3];
    let exact: Vec<Vec<f64>> = moduli
        .iter()
        .map(|&e| {
            let body = film.with_surface_youngs_modulus(e).unwrap();
            ForceCurve::on(&body, tip, 2e-6)
                .unwrap()
                .forces(&depths, 1.0, 0.0)
        })
        .collect();
    let worst = |nodes: usize| {
        let family =
            ModulusFamily::new(&film, Some(tip), f64::NAN, 2e-6, (5e3, 50e3), nodes).unwrap();
        let mut worst: f64 = 0.0;
        for (e, reference) in moduli.iter().zip(&exact) {
            for (f, g) in family.forces(&depths, *e).iter().zip(reference) {
                worst = worst.max((f / g - 1.0).abs());
            }
        }
        // Outside the range: NaN, not an extrapolation.
        assert!(family.forces(&[1e-6], 60e3)[0].is_nan());
        worst
    };
    let (six, ten) = (worst(6), worst(10));
    println!("modulus family: 6 nodes {six:.2e}, 10 nodes {ten:.2e}");
    assert!(ten < 1e-6 && six / ten > 100.0, "{six:e} {ten:e}");
}

#[test]
fn a_modulus_family_serves_retract_curves() {
    // The same film over a softer gel, with adhesion: the family's table at
    // a modulus off the nodes (interpolated at each contact radius) against
    // the exact table built at that modulus, along the whole fixed-grips
    // branch from detachment to half the thickness, relative to the
    // curve's largest force (forces cross zero). Measured: see the
    // assertion's message.
    use layered_contact::analytic::ModulusFamily;
    let (film, tip) = film_over_a_gel();
    let work = 2e-3;
    let depths: Vec<f64> = (0..=60)
        .map(|k| -0.6e-6 + 2.6e-6 * k as f64 / 60.0)
        .collect();
    let moduli = [5.3e3, 17.7e3, 47e3];
    let exact: Vec<Vec<f64>> = moduli
        .iter()
        .map(|&e| {
            let body = film.with_surface_youngs_modulus(e).unwrap();
            ForceCurve::on(&body, tip, 2e-6)
                .unwrap()
                .forces(&depths, 1.0, work)
        })
        .collect();
    let worst = |nodes: usize| {
        let family =
            ModulusFamily::new(&film, Some(tip), f64::NAN, 2e-6, (5e3, 50e3), nodes).unwrap();
        let mut worst: f64 = 0.0;
        for (e, reference) in moduli.iter().zip(&exact) {
            let scale = reference.iter().fold(0.0f64, |m, f| m.max(f.abs()));
            let forces = family.adhesive_forces(&depths, *e, work);
            let mut pulled = 0;
            for (f, g) in forces.iter().zip(reference) {
                if *g < 0.0 {
                    pulled += 1;
                }
                // Both detached (0) or both on the branch.
                assert_eq!(*f == 0.0, *g == 0.0, "{e}: {f} {g}");
                worst = worst.max((f - g).abs() / scale);
            }
            assert!(pulled > 5, "{e}: the range holds the tensile branch");
        }
        assert!(family.adhesive_forces(&[1e-6], 60e3, work)[0].is_nan());
        assert!(family.curve(60e3).is_err());
        worst
    };
    let (six, twelve) = (worst(6), worst(12));
    println!("modulus family, retract: 6 nodes {six:.2e}, 12 nodes {twelve:.2e}");
    assert!(twelve < 1e-6 && six / twelve > 100.0, "{six:e} {twelve:e}");
}

#[test]
fn an_adhesive_curve_ends_where_its_table_does() {
    // Adhesion lifts the indenter at a given contact radius, so a table
    // built to `max_depth` reaches less deep with a work of adhesion. On a
    // half-space (JKR's closed form) the table of a paraboloid reaches
    // `d0(2 a) - lift(2 a)` with `a` Hertz's radius at `max_depth`:
    // `4 max_depth - sqrt(4 pi a w / E*)`. Beyond, the force is NaN (it was
    // the clamped last state before, 4.75e-9 N for 3.56e-8 N on a film);
    // within, it is the curve of a deeper table.
    let material = Material::new(1e4, 0.5).unwrap();
    let body = Substrate::half_space(material);
    let (r, max_depth) = (5e-6, 1e-6);
    let tip = Tip::Paraboloid { radius: r };
    let table = ForceCurve::on(&body, tip, max_depth).unwrap();
    let deeper = ForceCurve::on(&body, tip, 4.0 * max_depth).unwrap();
    let estar = material.contact_modulus();
    let a = (r * max_depth).sqrt();
    // A work whose lift at 2a is 3.5 max_depth: the table reaches 0.5.
    let work = (3.5 * max_depth).powi(2) * estar / (4.0 * std::f64::consts::PI * a);
    let reach = table.reach(1.0, work);
    println!("reach {reach:e}");
    assert!((reach / (0.5 * max_depth) - 1.0).abs() < 1e-9, "{reach:e}");
    assert_eq!(table.reach(1.0, 0.0), max_depth);
    assert!(table.force(0.9 * max_depth, 1.0, work).is_nan());
    assert!(!deeper.force(0.9 * max_depth, 1.0, work).is_nan());
    let inside = 0.45 * max_depth;
    let (f, g) = (
        table.force(inside, 1.0, work),
        deeper.force(inside, 1.0, work),
    );
    // The tables are within 1e-6 of the exact curve (measured 1.3e-7 here,
    // at the shallower table's last radii).
    assert!((f / g - 1.0).abs() < 1e-6, "{f:e} {g:e}");
    assert!(table.reach(-1.0, work).is_nan());
}
