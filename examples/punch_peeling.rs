//! An adhesive flat punch on a stiff plate over a softer base, for
//! `BENCHMARKS.md` ("Seeds 156, 159 and 162 settled" and "`auto` peels a
//! punch whose stiffness barely changes"): a 0.1 m punch on a 1 kPa layer
//! 9.6 mm thick over a 724 kPa plate 28.8 mm thick over a base of 0.19 Pa
//! to 190 kPa (the `auto` reference sweep's seed 159 and its family),
//! 100 J/m^2, a depth cycle. For each base it prints the exact body's `r =
//! (A / k) dk/dA` at the rim (0.5 on a half-space: how much the stiffness
//! changes with the contact), where the edge stops peeling
//! (`Axisymmetric::punch_pull_off`, `c / a`) and the pull-off over the
//! rim's, the method `auto` takes, then the pull-off errors of the scene's
//! energy balance and of its peeling path by the local criterion (the
//! cohesive zone's unloading of a punch) against the exact pull-off, at
//! the cells across the punch given (default 32).
//!
//! `cargo run --release --example punch_peeling -- 16 32 64`
use layered_contact::analytic::Axisymmetric;
use layered_contact::scene::Quantity;
use layered_contact::Result;

#[path = "support/punch_plate.rs"]
mod punch_plate;
use punch_plate::{body, scene, RADIUS, SEED_159_BASE, TOP, WORK};

fn main() -> Result<()> {
    let cells: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let cells = if cells.is_empty() { vec![32] } else { cells };
    println!("base Pa   r       c/a    F/rim   auto           N    energy balance  peeling path");
    for base in [SEED_159_BASE, 1.9, 1.9e1, 1.9e2, 1.9e3, 1.9e4, 1.9e5] {
        let body = body(base)?;
        let exact = Axisymmetric::new(&body, 1.05 * RADIUS / TOP)?;
        let rim = exact.flat_punch(RADIUS)?;
        let inner = exact.flat_punch(0.99 * RADIUS)?;
        let slope = (rim.stiffness() - inner.stiffness()) / (0.01 * RADIUS);
        let r = slope * RADIUS / (2.0 * rim.stiffness());
        let peeled = exact.punch_pull_off(RADIUS, WORK)?.load_control;
        for &n in &cells {
            let mut errors = Vec::new();
            for method in ["energy_balance", "cohesive_zone"] {
                let scene = scene(base, n, method)?;
                let reference = scene.reference()?.into_iter();
                let mut exact = reference.filter(|r| r.quantity == Quantity::PullOffForce);
                // A typed refusal is printed as such.
                let error = match (exact.next(), scene.run(&mut |_| {})) {
                    (Some(e), Ok(curve)) => curve.pull_off().map_or("-".into(), |p| {
                        format!("{:+.3} %", 100.0 * (p.force / e.value - 1.0))
                    }),
                    (_, Err(refused)) => format!("refused: {refused:?}").chars().take(40).collect(),
                    _ => "-".into(),
                };
                errors.push(error);
            }
            let auto = scene(base, n, "auto")?.resolved_adhesion_method();
            println!(
                "{base:<9.2e} {r:<7.4} {:<6.3} {:<7.4} {:<14} {n:<4} {:<15} {}",
                peeled.contact_radius / RADIUS,
                peeled.force / rim.pull_off_force(WORK),
                format!("{auto:?}"),
                errors[0],
                errors[1]
            );
        }
    }
    Ok(())
}
