//! The cohesive zone's length against the top layer and the body's contact
//! modulus at the zone's scale against the contact's, for scene files: the
//! two numbers that tell a long zone's bias
//! ([`Caveat::CohesiveZoneLongAgainstLayer`]) on a body far softer below
//! from one that costs a few per cent (`BENCHMARKS.md`, "Seeds 74 to 85").
//!
//! For each scene (its resolution, its body, its zone as
//! [`Scene::cohesive_zone`] and [`CohesiveZone::cells_on`] set it) it
//! prints the zone's length over the top layer's thickness, and `E*(q) = 2
//! / (q u_z(q))` (the body's surface compliance, Perriot & Barthel 2004,
//! [`FourierCompliance`]) at the zone's wavelength `q = 2 pi / l` and at the
//! peak contact's, `q = pi / a` (`a` the exact peak contact radius of
//! [`Scene::reference`]), over the surface material's `E*`, and their
//! ratio ([`ZoneScales`]; the run itself measures it at its own peak
//! contact for [`Caveat::CohesiveZoneStifferThanContact`]).
//!
//! `cargo run --release --example zone_scales -- examples/scenes/long_zone/*.toml`
//!
//! [`CohesiveZone::cells_on`]: layered_contact::solver::CohesiveZone::cells_on

use layered_contact::kernel::FourierCompliance;
#[cfg(doc)]
use layered_contact::scene::Caveat;
use layered_contact::scene::{Quantity, Scene, ZoneScales};

fn main() {
    println!("| scene | zone / h | E*(zone) / E*s | E*(contact) / E*s | E*(zone) / E*(contact) |");
    println!("|---|---|---|---|---|");
    for path in std::env::args().skip(1) {
        match row(&path) {
            Ok(cells) => println!("| {path} | {cells} |"),
            Err(e) => println!("| {path} | {e} | | | |"),
        }
    }
}

/// The table's cells for the scene file at `path`.
fn row(path: &str) -> Result<String, Box<dyn std::error::Error>> {
    let scene = Scene::from_toml(&std::fs::read_to_string(path)?)?;
    let body = scene.substrate.build()?;
    let Some(zone) = scene.cohesive_zone()? else {
        return Err("no cohesive zone".into());
    };
    let Some(a) = scene
        .reference()?
        .iter()
        .find(|r| r.quantity == Quantity::PeakContactRadius)
        .map(|r| r.value)
    else {
        return Err("no exact peak contact".into());
    };
    let Some(scales) = ZoneScales::new(&zone, &body, scene.grid()?.spacing(), a) else {
        return Err("no layer".into());
    };
    let compliance = FourierCompliance::new(&body);
    let surface = body.surface_material().contact_modulus();
    let pi = std::f64::consts::PI;
    let modulus = |q: f64| compliance.contact_modulus_at(q) / surface;
    Ok(format!(
        "{:.2} | {:.3} | {:.3e} | {:.1}",
        scales.length / scales.layer_thickness,
        modulus(2.0 * pi / scales.length),
        modulus(pi / a),
        scales.modulus_ratio
    ))
}
