//! Contacts of one patch under the box and under the two-level
//! preconditioner: a sphere (R = 2 mm, 8 um deep), a flat punch (radius a
//! quarter of the side, 1 um deep) and a cone (half-angle 1.3 rad, 30 um
//! deep) pressed under depth control into a half-space (E = 1 MPa, nu =
//! 0.5), the rubber film of `rough_benchmark` (0.1 mm on a rigid base) or
//! its coated stack, isolated, over a 1 mm square of N x N cells, tolerance
//! 1e-8. Shows why the solver's automatic choice
//! (`ContactSolver::set_automatic_coarse_blocks`) keeps the box for a
//! contact of few patches whatever the box's rate: BENCHMARKS.md, "The
//! choice on fixed roughness and on one patch".
//!
//! ```text
//! cargo run --release --example one_patch_blocks -- [N]
//! ```
//!
//! Prints a line per contact and preconditioner: the fine iterations, the
//! solve's time, the force, the contact cells, and the iterations done
//! when the choice was made and the box's factor it judged by
//! (`ContactSolver::last_preconditioning`). N defaults to 2048 (the
//! automatic choice's smallest grid), also for an argument that is not a
//! count.
//! `RAYON_NUM_THREADS` sets the threads.

use std::time::Instant;

use layered_contact::indenter::{Cone, FlatPunch, Indenter, Sphere};
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::{Base, Boundary, Grid, Material, Substrate};

fn main() -> Result<(), layered_contact::Error> {
    let n = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(2048);
    let side = 1e-3;
    let grid = Grid::square_of_side(n, side)?;
    let half_space = Substrate::half_space(Material::new(1e6, 0.5)?);
    let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.49)?, 1e-4)?;
    let (coat, rubber) = (Material::new(5e6, 0.3)?, Material::new(1e6, 0.49)?);
    let base = Base::Elastic(Material::new(2e5, 0.45)?);
    let stack = Substrate::stack(&[(coat, 2e-5), (rubber, 1e-4)], base)?;
    let sphere = Sphere::new(2e-3)?;
    let punch = FlatPunch::new(0.25 * side)?;
    let cone = Cone::new(1.3, 0.5 * side)?;
    let contacts: [(&str, &Substrate, &dyn Indenter, f64); 7] = [
        ("sphere, half-space", &half_space, &sphere, 8e-6),
        ("sphere, film", &film, &sphere, 8e-6),
        ("sphere, stack", &stack, &sphere, 8e-6),
        ("punch, half-space", &half_space, &punch, 1e-6),
        ("punch, film", &film, &punch, 1e-6),
        ("punch, stack", &stack, &punch, 1e-6),
        ("cone, film", &film, &cone, 3e-5),
    ];
    let params = SolverParams {
        tolerance: 1e-8,
        ..SolverParams::default()
    };
    for (name, body, indenter, depth) in contacts {
        for blocks in [None, Some(16)] {
            let mut solver = ContactSolver::new(body, &grid, Boundary::Isolated, params)?;
            solver.set_coarse_blocks(blocks)?;
            let start = Instant::now();
            let (solution, _) = solver.solve_depth(indenter, depth, None, &mut ())?;
            let seconds = start.elapsed().as_secs_f64();
            let decides = solver
                .last_preconditioning()
                .and_then(|p| Some((p.decided_after?, p.box_factor?)))
                .map_or("never".to_string(), |(k, r)| format!("at {k} on {r:.3}"));
            let preconditioner = blocks.map_or("box".to_string(), |b| format!("blocks of {b}"));
            println!(
                "{name:18} {preconditioner:12} {:3} iterations {seconds:6.2} s, force {:.6e} N, {} cells; the choice decides {decides}",
                solution.iterations, solution.force, solution.contact_cells
            );
        }
    }
    Ok(())
}
