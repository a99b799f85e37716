//! A tip held by a cantilever on a stack whose branch folds (a soft film
//! over a stiffer layer over a far softer base): the spring's base `Z = d +
//! F/k` has several local minima along the branch. The pull-off is the
//! least of them (as `pull_off`'s least force and depth are the least over
//! the radii), the jump-in the first radius going out where `F + k d`
//! rises through zero; both against a dense scan of the exact states.

use layered_contact::analytic::{Axisymmetric, ContactState, LayeredJkrCycle, Tip};
use layered_contact::{Base, Error, Material, Substrate};

/// Each scan's step between radii: 1 %.
const SCAN_STEP: f64 = 1.01;

/// The spring's stiffness, N/m: stiff enough that the least `Z` lies near
/// the least depth.
const STIFFNESS: f64 = 1e3;

/// A film of 1 kPa (1 mm thick) over a layer `10^0.816` times stiffer and
/// 1.31 film thicknesses thick, over a base `10^3.545` times softer than
/// that layer (a draw of the search that found the fault).
fn stack() -> Axisymmetric {
    let h = 1e-3;
    let film = Material::new(1e3, 0.3).unwrap();
    let layer = Material::new(1e3 * 10f64.powf(0.816299103910258), 0.3).unwrap();
    let base = Material::new(layer.youngs_modulus() * 10f64.powf(-3.545022830291984), 0.3).unwrap();
    let body = Substrate::stack(
        &[(film, h), (layer, 1.3131347248513139 * h)],
        Base::Elastic(base),
    )
    .unwrap();
    Axisymmetric::up_to_contact_radius(&body, 60.0 * h).unwrap()
}

/// The states at radii from 1 to 40 mm in steps of [`SCAN_STEP`].
fn scan(tip: &layered_contact::analytic::LayeredTip) -> Vec<ContactState> {
    let mut a = 1e-3;
    let mut out = Vec::new();
    while a < 4e-2 {
        out.push(tip.at_contact_radius(a).unwrap());
        a *= SCAN_STEP;
    }
    out
}

/// A paraboloid of 2.2 m with a work of 1.2e-5 J/m^2: `Z` has local minima
/// at about 1.95 mm and 12.5 mm, the inner one the lower by 0.27 % (a
/// bisection between the load- and displacement-controlled pull-offs'
/// radii, 1.96 and 29.3 mm, returned the outer one before: 12.40 mm).
#[test]
fn the_spring_pull_off_is_the_least_base_position() {
    let exact = stack();
    let tip = exact
        .tip(
            Tip::Paraboloid {
                radius: 2.2039673420238564,
            },
            1.222680383736522e-5,
        )
        .unwrap();
    let z = |s: &ContactState| s.depth + s.force / STIFFNESS;
    let states = scan(&tip);
    let least = states.iter().min_by(|a, b| z(a).total_cmp(&z(b))).unwrap();
    let pull = tip.spring_pull_off(STIFFNESS).unwrap();
    // At or below every scanned state's base position, and within a scan
    // step of the least one's radius.
    assert!(z(&pull) <= z(least), "{} {}", z(&pull), z(least));
    assert!(
        (pull.contact_radius / least.contact_radius).ln().abs() < SCAN_STEP.ln(),
        "{} {}",
        pull.contact_radius,
        least.contact_radius
    );
    assert!(
        (pull.contact_radius / 1.9557e-3 - 1.0).abs() < 1e-3,
        "{}",
        pull.contact_radius
    );
    // The jump-in: the first scanned radius going out where F + k d >= 0
    // lies within a step outside the returned one.
    let jump = tip.spring_jump_in(STIFFNESS).unwrap();
    let first = states
        .iter()
        .find(|s| s.force + STIFFNESS * s.depth >= 0.0)
        .unwrap();
    assert!(
        jump.contact_radius <= first.contact_radius
            && jump.contact_radius * SCAN_STEP >= first.contact_radius,
        "{} {}",
        jump.contact_radius,
        first.contact_radius
    );
    assert!((jump.force + STIFFNESS * jump.depth).abs() < 1e-9 * jump.force.abs());
}

/// An unloading deeper than the cycle's peak is refused: the pinned
/// contact pressed deeper is no state of the cycle (it returned the peak's
/// radius at 3e-4 m on a cycle to 2e-4 m, 1.92 N, where the loading there
/// has 5.26 mm and 2.12 N).
#[test]
fn an_unloading_below_the_peak_is_refused() {
    let film = Substrate::layer_on_rigid_base(Material::new(0.324e6, 0.48).unwrap(), 5e-3).unwrap();
    let exact = Axisymmetric::new(&film, 2.0).unwrap();
    let cycle = LayeredJkrCycle::new(&exact, 0.05, 0.0175, 0.326, 2e-4).unwrap();
    assert!(matches!(
        cycle.unloading(3e-4),
        Err(Error::InvalidParameter { name: "depth", .. })
    ));
    // At the peak's own depth, the peak.
    let at_peak = cycle.unloading(2e-4).unwrap().unwrap();
    assert_eq!(at_peak.contact_radius, cycle.peak().contact_radius);
    assert!((at_peak.force / cycle.peak().force - 1.0).abs() < 1e-12);
}
