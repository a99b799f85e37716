//! What rough-contact studies read off a periodic contact: the contact
//! fraction, the mean gap and the interfacial stiffness along a force
//! protocol, against Westergaard's wavy surface (plane strain, periodic,
//! exact): `p_bar = p* sin^2(pi a / lambda)`, `p* = pi E* D / lambda`, and
//! the mean gap `u_bar / D = 1 - s + s ln s`, `s = p_bar / p*` (from the
//! exact pressure and the periodic Green's function, whose value at the
//! contact's centre is `(2 p_bar lambda / (pi E*)) (1/2 - ln sin(pi a /
//! lambda))`), so that `-dp_bar/du_bar = p* / (D ln(1/s))`.

use std::f64::consts::PI;

use layered_contact::indenter::Indenter;
use layered_contact::solver::{ContactSolver, Fields, SolverParams};
use layered_contact::{Boundary, Grid, Material, Substrate};

const WAVELENGTH: f64 = 1e-3;
const AMPLITUDE: f64 = 1e-6;

/// `D (1 - cos(2 pi x / lambda))`, invariant along `y`.
struct Wavy;

impl Indenter for Wavy {
    fn height(&self, x: f64, _y: f64) -> f64 {
        AMPLITUDE * (1.0 - (2.0 * PI * x / WAVELENGTH).cos())
    }
    fn bounding_radius(&self) -> f64 {
        f64::INFINITY
    }
}

/// Contact fraction and mean gap of the wavy surface at `s = p_bar / p*`
/// on `n` cells per wavelength (8 along the crests).
fn wavy(n: usize, s: f64) -> (f64, f64) {
    let material = Material::new(1e6, 0.5).unwrap();
    let estar = material.contact_modulus();
    let p_star = PI * estar * AMPLITUDE / WAVELENGTH;
    let grid = Grid::new(n, 8, WAVELENGTH / n as f64).unwrap();
    let params = SolverParams {
        fields: Fields {
            gap: true,
            ..Fields::default()
        },
        ..SolverParams::default()
    };
    let mut solver = ContactSolver::new(
        &Substrate::half_space(material),
        &grid,
        Boundary::Periodic,
        params,
    )
    .unwrap();
    let (lx, ly) = grid.extent();
    let (solution, _) = solver
        .solve_force(&Wavy, s * p_star * lx * ly, None, &mut ())
        .unwrap();
    let fraction = solution.contact_area / (lx * ly);
    (fraction, solution.mean_gap().unwrap())
}

#[test]
fn mean_gap_and_contact_of_the_wavy_surface_converge_to_westergaard() {
    // The contact fraction is a count of cells, within a cell per edge of
    // the exact `2 a / lambda`. The mean gap is an average over the whole
    // period: measured relative errors, largest over s = 0.1, 0.4, 0.7,
    // 8.1e-4, 2.0e-4 and 9.2e-6 at 128, 256 and 512 cells per wavelength
    // (not a clean power of the cell size: the edge cells' share changes
    // with where the edge falls); the bounds are twice those.
    let bounds = [1.6e-3, 4e-4, 2e-5];
    for s in [0.1f64, 0.4, 0.7] {
        let exact_fraction = 2.0 / PI * s.sqrt().asin();
        let exact_gap = AMPLITUDE * (1.0 - s + s * s.ln());
        let runs: Vec<(f64, f64)> = [128, 256, 512].iter().map(|&n| wavy(n, s)).collect();
        let errors: Vec<f64> = runs.iter().map(|r| r.1 / exact_gap - 1.0).collect();
        println!("s {s}: mean gap errors {errors:?}");
        for ((&(fraction, _), n), (error, bound)) in runs
            .iter()
            .zip([128.0, 256.0, 512.0])
            .zip(errors.iter().zip(bounds))
        {
            assert!(
                (fraction - exact_fraction).abs() <= 2.0 / n,
                "s {s}: {fraction} vs {exact_fraction}"
            );
            assert!(error.abs() < bound, "s {s}: {errors:?}");
        }
    }
}

#[test]
fn interfacial_stiffness_of_the_wavy_surface() {
    // -dp_bar/du_bar by central differences of two loads 1 % apart, against
    // p* / (D ln(1/s)) at 512 cells per wavelength: measured +0.065 % at
    // s = 0.2 and +0.049 % at 0.5.
    let estar = Material::new(1e6, 0.5).unwrap().contact_modulus();
    let p_star = PI * estar * AMPLITUDE / WAVELENGTH;
    for s in [0.2f64, 0.5] {
        let (ds, n) = (0.01 * s, 512);
        let (_, below) = wavy(n, s - ds);
        let (_, above) = wavy(n, s + ds);
        let stiffness = -2.0 * ds * p_star / (above - below);
        let exact = p_star / (AMPLITUDE * (1.0 / s).ln());
        println!("s {s}: stiffness {stiffness:e} vs {exact:e}");
        assert!((stiffness / exact - 1.0).abs() < 0.01, "s {s}");
    }
}

#[test]
fn mean_gap_needs_the_gap_field_and_a_covered_grid() {
    let material = Material::new(1e6, 0.5).unwrap();
    let grid = Grid::new(32, 8, WAVELENGTH / 32.0).unwrap();
    let mut solver = ContactSolver::new(
        &Substrate::half_space(material),
        &grid,
        Boundary::Periodic,
        SolverParams::default(),
    )
    .unwrap();
    let (solution, _) = solver.solve_force(&Wavy, 1e-3, None, &mut ()).unwrap();
    assert_eq!(solution.mean_gap(), None);
}
