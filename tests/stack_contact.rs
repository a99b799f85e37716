//! Contact on stacks of layers: influence coefficients against a direct
//! quadrature of the whole stack's Green's function, and the boundary-element
//! solver against the exact axisymmetric solutions on three-layer stacks.

mod common;

use std::f64::consts::PI;

use layered_contact::analytic::Axisymmetric;
use layered_contact::indenter::{FlatPunch, Paraboloid};
use layered_contact::kernel::InfluenceCoefficients;
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::substrate::StackFunctions;
use layered_contact::{Base, Boundary, Grid, Material, Substrate};

fn hard() -> Material {
    Material::new(20e6, 0.3).unwrap()
}

fn soft() -> Material {
    Material::new(1e6, 0.49).unwrap()
}

/// The two three-layer stacks (top first): soft/hard/soft on a rigid base
/// and hard/soft/hard on an elastic base, thicknesses 1, 0.5 and 2 mm.
fn stacks() -> Vec<(&'static str, Substrate)> {
    let h = [1e-3, 0.5e-3, 2e-3];
    vec![
        (
            "soft/hard/soft on rigid",
            Substrate::stack(
                &[(soft(), h[0]), (hard(), h[1]), (soft(), h[2])],
                Base::Rigid,
            )
            .unwrap(),
        ),
        (
            "hard/soft/hard on elastic",
            Substrate::stack(
                &[(hard(), h[0]), (soft(), h[1]), (hard(), h[2])],
                Base::Elastic(Material::new(5e6, 0.3).unwrap()),
            )
            .unwrap(),
        ),
    ]
}

/// `g(rho) = Integral_0^inf Lambda_g(u) J0(u rho) du` of the whole stack by
/// direct quadrature (no split into interfaces, J0 instead of the disc
/// integrals of J1).
fn g_direct(f: &StackFunctions, rho: f64) -> f64 {
    common::hankel_j0(|u| f.lambda(u), rho, 0.25)
}

/// Influence coefficients of both stacks against the top material's Love
/// coefficient minus the stack's remainder `g(r/h1)/(pi E1* h1)` integrated
/// over the cell by 12 x 12 Gauss points per quarter, at h1/Delta = 1 and
/// 4. Measured: within 6.9e-15 of the self-coefficient; asserted 1e-12.
#[test]
fn stack_coefficients_match_direct_quadrature() {
    for (name, substrate) in stacks() {
        let Substrate::Stack(stack) = &substrate else {
            panic!("a stack")
        };
        let f = stack.functions();
        let h1 = stack.top().thickness();
        let layer = *stack.top().material();
        for h_over_delta in [1.0, 4.0] {
            let delta = h1 / h_over_delta;
            let grid = Grid::new(6, 6, delta).unwrap();
            let half_space = InfluenceCoefficients::isolated(&Substrate::half_space(layer), &grid);
            let k = InfluenceCoefficients::isolated(&substrate, &grid);
            let mut worst = 0.0f64;
            for (di, dj) in [(0, 0), (1, 0), (2, 5)] {
                let (x, y) = (di as f64 * delta, dj as f64 * delta);
                let remainder = common::cell_integral(|rho| g_direct(&f, rho), x, y, delta, h1, 12);
                let reference =
                    half_space.get(di, dj) - remainder / (PI * layer.contact_modulus() * h1);
                worst = worst.max((k.get(di, dj) - reference).abs() / half_space.get(0, 0));
            }
            println!("{name}, h1/Delta = {h_over_delta}: {worst:.1e}");
            assert!(
                worst < 1e-12,
                "{name}, h1/Delta = {h_over_delta}: {worst:e}"
            );
        }
    }
}

fn solver(substrate: &Substrate, grid: &Grid) -> ContactSolver {
    ContactSolver::new(substrate, grid, Boundary::Isolated, SolverParams::default()).unwrap()
}

/// A flat punch of radius 1.5 mm (128 cells across) on both stacks: the
/// stiffness against the exact axisymmetric stiffness at the equal-area
/// radius. Measured: -0.31 % and -0.14 %; asserted 0.5 %.
#[test]
fn flat_punch_on_stacks_matches_the_exact_solution() {
    let (a, across) = (1.5e-3, 128);
    for (name, substrate) in stacks() {
        let grid = Grid::new(across + 2, across + 2, 2.0 * a / across as f64).unwrap();
        let d = 1e-6;
        let (s, _) = solver(&substrate, &grid)
            .solve_depth(&FlatPunch::new(a).unwrap(), d, None, &mut ())
            .unwrap();
        let exact = Axisymmetric::up_to_contact_radius(&substrate, 2.0 * a)
            .unwrap()
            .flat_punch(s.contact_radius)
            .unwrap();
        assert!(exact.holds_without_adhesion(), "{name}");
        let error = s.force / d / exact.stiffness() - 1.0;
        println!("{name}: punch stiffness {error:+.2e}");
        assert!(error.abs() < 0.005, "{name}: {error}");
    }
}

/// A paraboloid of tip radius 20 mm pressed to a contact radius of 1.5 mm
/// on both stacks, 128 cells across the exact contact: force and contact
/// radius against the exact axisymmetric solution at the same depth.
/// Measured: force +3.8e-5 and +1.4e-5, radius +0.12 % for both; asserted
/// 0.5 % and 1 % (one cell is 1.6 % of the radius).
#[test]
fn paraboloid_on_stacks_matches_the_exact_solution() {
    let (radius, a, across) = (20e-3, 1.5e-3, 128);
    for (name, substrate) in stacks() {
        let exact = Axisymmetric::up_to_contact_radius(&substrate, 2.0 * a)
            .unwrap()
            .paraboloid(radius, 0.0)
            .unwrap()
            .at_contact_radius(a)
            .unwrap();
        let n = across * 5 / 4;
        let grid = Grid::new(n, n, 2.0 * a / across as f64).unwrap();
        let (s, _) = solver(&substrate, &grid)
            .solve_depth(
                &Paraboloid::new(radius).unwrap(),
                exact.depth,
                None,
                &mut (),
            )
            .unwrap();
        let force = s.force / exact.force - 1.0;
        let contact = s.contact_radius / exact.contact_radius - 1.0;
        println!("{name}: force {force:+.2e}, radius {contact:+.2e}");
        assert!(
            force.abs() < 0.005 && contact.abs() < 0.01,
            "{name}: {force} {contact}"
        );
    }
}

/// The example scene `examples/scenes/sphere_on_stack.toml` (a sphere with
/// hysteretic adhesion on a three-layer skin-like stack on a rigid base,
/// 64 cells across), read from its file and run: every quantity the scene
/// reports against the exact stack solution. Measured: peak force
/// +0.059 %, peak contact radius -0.81 %, pull-off -0.22 %; asserted 0.5 %,
/// 1.5 % (one cell is 1.0 % of the peak radius) and 1 %.
#[cfg(feature = "serde")]
#[test]
fn stack_scene_file_matches_the_exact_solution() {
    use layered_contact::scene::{Quantity, Scene};
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/scenes/sphere_on_stack.toml"
    );
    let scene = Scene::read(path).unwrap();
    let curve = scene.run(&mut |_| {}).unwrap();
    let references = scene.reference().unwrap();
    for (quantity, tolerance) in [
        (Quantity::PeakForce, 0.005),
        (Quantity::PeakContactRadius, 0.015),
        (Quantity::PullOffForce, 0.01),
    ] {
        let exact = references
            .iter()
            .find(|r| r.quantity == quantity)
            .unwrap()
            .value;
        let error = quantity.of(&curve).unwrap() / exact - 1.0;
        println!("{}: {error:+.2e}", quantity.name());
        assert!(error.abs() < tolerance, "{}: {error}", quantity.name());
    }
}
