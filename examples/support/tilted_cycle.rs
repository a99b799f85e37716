//! The tilted adhesive cycle of `BENCHMARKS.md` ("Adhesive scene cycles:
//! error and cost"), shared by `examples/adhesive_cycle_cost.rs` and
//! `benches/adhesive_cycle.rs`: an indenter of radius 10 mm tilted so that
//! its contact centre moves by (0.3, 0.17) pull-off contact radii, on a
//! rubber half-space (E = 1 MPa, nu = 0.48, dgamma = 0.05 J/m^2), loaded
//! in 6 steps to the JKR depth of 1.6 pull-off contact radii and unloaded
//! to contact loss, with `n` cells across the pull-off contact.

use layered_contact::analytic::JkrSphere;
use layered_contact::scene::{
    Adhesion, AdhesionMethod, IndenterSpec, Protocol, Resolution, Scene, SolverSettings,
    SubstrateSpec, Tilt,
};
use layered_contact::{Material, Result};

/// Young's modulus of the rubber, Pa.
pub const E: f64 = 1e6;
/// Its Poisson ratio.
pub const NU: f64 = 0.48;
/// The indenter's radius, m.
pub const RADIUS: f64 = 0.01;
/// The work of adhesion, J/m^2.
pub const WORK: f64 = 0.05;

/// JKR's sphere of the cycle (the reference of its pull-off).
pub fn jkr() -> Result<JkrSphere> {
    JkrSphere::new(&Material::new(E, NU)?, RADIUS, WORK)
}

/// The tilt that moves the contact centre by (0.3, 0.17) pull-off radii.
pub fn tilt() -> Result<Tilt> {
    let a = jkr()?.pull_off_contact_radius();
    Ok(Tilt {
        angle_y: (0.3 * a / RADIUS).atan(),
        angle_x: (0.17 * a / RADIUS).atan(),
    })
}

/// The cycle of `indenter` with `n` cells across the pull-off contact,
/// adhesion by `method`.
pub fn scene(indenter: IndenterSpec, n: usize, method: AdhesionMethod) -> Result<Scene> {
    let jkr = jkr()?;
    let a = jkr.pull_off_contact_radius();
    Ok(Scene {
        substrate: SubstrateSpec::HalfSpace {
            youngs_modulus: E,
            poisson_ratio: NU,
        },
        indenter,
        tilt: Some(tilt()?),
        adhesion: Adhesion::Constant {
            work_of_adhesion: WORK,
        },
        protocol: Protocol::Cycle {
            max_depth: jkr.depth(1.6 * a),
            steps: 6,
        },
        resolution: Resolution {
            cells_across: n,
            margin: 0.6,
        },
        solver: SolverSettings {
            adhesion_method: method,
            ..SolverSettings::default()
        },
        ..Scene::default()
    })
}
