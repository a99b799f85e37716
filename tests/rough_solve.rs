//! Rough contacts, whose steps clamp pressures in most iterations: the
//! constrained conjugate gradients then take the step length from the
//! direction's energy and move the displacement by one convolution of the
//! whole change of the pressure. The solution they return must still be
//! the contact of the displacement `K p` applied afresh.

use layered_contact::indenter::Indenter;
use layered_contact::kernel::ComplianceOperator;
use layered_contact::solver::{ContactSolver, Fields, SolverParams};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Boundary, Grid, Material, Substrate};

mod common;

/// A seeded self-affine surface on `n x n` cells of a 1 mm square pressed
/// into a rubber half-space and a film on a rigid base, periodic and
/// isolated, under depth and force control (about a fifth of the area in
/// contact). Checked against the operator applied afresh to the returned
/// pressures: the reported displacement equals it within 1e-10 of its
/// largest value (measured: 1e-15), and the gap it makes is closed on the
/// contact to 1e-6 of the surface's height range (measured: 5e-9; the
/// solver's tolerance is 1e-8 on the pressure) and open elsewhere. A
/// displacement update off by a thousandth of the change of the pressure
/// (a mutation tried) put the displacement 1e-4 of its largest value off.
#[test]
fn rough_contacts_close_the_gaps_of_their_fresh_displacement() {
    let n = 96;
    let side = 1e-3;
    let grid = Grid::square_of_side(n, side).unwrap();
    let rubber = Material::new(1e6, 0.49).unwrap();
    let bodies = [
        Substrate::half_space(rubber),
        Substrate::layer_on_rigid_base(rubber, 1e-4).unwrap(),
    ];
    let surface = SelfAffine {
        hurst: 0.8,
        amplitude: Amplitude::RmsSlope(0.1),
        long_cutoff: 0.25 * side,
        short_cutoff: 4.0 * side / n as f64,
        seed: 7,
    };
    let indenter = surface.indenter(&grid).unwrap();
    let heights = surface.heights(&grid).unwrap();
    let range = heights.iter().fold(f64::MIN, |m, h| m.max(*h))
        - heights.iter().fold(f64::MAX, |m, h| m.min(*h));
    let params = SolverParams {
        fields: Fields::all(),
        tolerance: 1e-8,
        ..SolverParams::default()
    };
    let mut checked = 0;
    for body in &bodies {
        for boundary in [Boundary::Periodic, Boundary::Isolated] {
            let mut solver = ContactSolver::new(body, &grid, boundary, params).unwrap();
            let mut operator = ComplianceOperator::new(body, &grid, boundary).unwrap();
            let force = 0.05 * rubber.contact_modulus() * side * side * 0.1;
            let (by_force, _) = solver.solve_force(&indenter, force, None, &mut ()).unwrap();
            let mut solutions = vec![by_force];
            // Depth control too where the uniform mode is bounded (not on a
            // periodic half-space).
            if operator.uniform_mode_bounded() {
                let depth = solutions[0].depth;
                solutions.push(
                    solver
                        .solve_depth(&indenter, depth, None, &mut ())
                        .unwrap()
                        .0,
                );
            }
            for solution in solutions {
                let (fresh, worst, largest) = common::fresh_displacement(&mut operator, &solution);
                let pressure: Vec<f64> = solution.pressure.unwrap().iter().copied().collect();
                assert!(
                    worst <= 1e-10 * largest,
                    "{boundary:?}: {worst} of {largest}"
                );
                let fraction = solution.contact_area / (side * side);
                assert!((0.05..0.6).contains(&fraction), "{fraction}");
                // Gaps of the fresh displacement (heights measured down
                // from the indenter's lowest point: its profile).
                let profile: Vec<f64> = (0..grid.len())
                    .map(|c| {
                        let (x, y) = grid.cell_centre(c / n, c % n);
                        indenter.height(x, y)
                    })
                    .collect();
                let mut closed = 0.0f64;
                let mut open = 0.0f64;
                for ((h, u), p) in profile.iter().zip(&fresh).zip(&pressure) {
                    let gap = h - solution.depth + u;
                    if *p > 0.0 {
                        closed = closed.max(gap.abs());
                    } else {
                        open = open.min(gap);
                    }
                }
                assert!(
                    closed <= 1e-6 * range,
                    "{boundary:?}: closed {closed} of {range}"
                );
                assert!(
                    open >= -1e-6 * range,
                    "{boundary:?}: open {open} of {range}"
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 7);
}
