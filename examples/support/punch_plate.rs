//! The adhesive flat punch on a stiff plate over a softer base of
//! `BENCHMARKS.md` ("Seeds 156, 159 and 162 settled"), shared by
//! `examples/punch_peeling.rs` and `tests/punch_peeling.rs`: a 0.1 m punch
//! on a 1 kPa layer 9.6 mm thick over a 724 kPa plate 28.8 mm thick over an
//! elastic base (the `auto` reference sweep's seed 159 with a base of 0.19
//! Pa, as the sweep shrank it), 100 J/m^2, a depth cycle of 4 steps to 5
//! um.

use layered_contact::substrate::Base;
use layered_contact::{Material, Result, Substrate};

/// The punch's radius, m.
pub const RADIUS: f64 = 0.1;
/// The work of adhesion, J/m^2.
pub const WORK: f64 = 100.0;
/// The top layer's thickness, m.
pub const TOP: f64 = 9.624654318820577e-3;
/// The plate's thickness, m.
const PLATE: f64 = 2.8840133077183354e-2;
/// The plate's Young's modulus, Pa.
const PLATE_MODULUS: f64 = 7.238902357342152e5;
/// Seed 159's base, Pa.
pub const SEED_159_BASE: f64 = 1.8913878403638912e-1;

/// The body with a base of Young's modulus `base` (Pa, Poisson ratio 0).
pub fn body(base: f64) -> Result<Substrate> {
    let top = Material::new(1e3, 0.45)?;
    let plate = Material::new(PLATE_MODULUS, 0.0)?;
    Substrate::stack(
        &[(top, TOP), (plate, PLATE)],
        Base::Elastic(Material::new(base, 0.0)?),
    )
}

/// The scene on the body over `base` (Pa), `cells` across the punch, by
/// `method` (a scene file's `adhesion_method`).
#[cfg(feature = "serde")]
pub fn scene(base: f64, cells: usize, method: &str) -> Result<layered_contact::scene::Scene> {
    layered_contact::scene::Scene::from_toml(&format!(
        r#"
[substrate]
kind = "stack"
layers = [ {{ youngs_modulus = 1e3, poisson_ratio = 0.45, thickness = {TOP:e} }}, {{ youngs_modulus = {PLATE_MODULUS:e}, poisson_ratio = 0, thickness = {PLATE:e} }} ]
base = {{ youngs_modulus = {base:e}, poisson_ratio = 0 }}
[indenter]
kind = "flat_punch"
radius = {RADIUS:e}
[adhesion]
kind = "constant"
work_of_adhesion = {WORK:e}
[protocol]
kind = "cycle"
max_depth = 5.011872336272726e-6
steps = 4
[resolution]
cells_across = {cells}
[solver]
adhesion_method = "{method}"
"#
    ))
}
