//! Whether a non-adhesive sphere's contact on a stiff layer over a softer
//! base is the disc the exact solution assumes, for `BENCHMARKS.md` ("A
//! disc or a ring"): a sphere (R = 23.4 um) on a 95 MPa layer (nu = 0.45,
//! 1.36 um thick) resting on a base 30 to 8000 times softer, at contact
//! radii of 1 to 8 layer thicknesses. For each it prints the exact disc's
//! least pressure over its mean (`LayeredTip::minimum_pressure_ratio`:
//! negative where the disc would pull on the tip) beside the BEM at the
//! disc's depth (96 cells across 2.6 contact radii, isolated): its pressure
//! at the centre, its contact cells (the disc holds about 4312), its force
//! against the disc's, and the cold solve's iterations (fine and coarse):
//! a contact whose middle lifts off took hundreds to thousands (up to 2019)
//! before a slow solve tried active-set loops, now up to 356
//! (`src/solver/active_set.rs`).
//!
//! `cargo run --release --example disc_or_ring`
use layered_contact::analytic::{Axisymmetric, Tip};
use layered_contact::indenter::Sphere;
use layered_contact::solver::{ContactSolver, Fields, SolverParams};
use layered_contact::{Boundary, Grid, Material, Result, Substrate};

fn main() -> Result<()> {
    let h = 1.36e-6;
    let radius = 23.4e-6;
    let layer = Material::new(9.5e7, 0.45)?;
    let n = 96;
    println!(
        "E1/E2  a/h  depth m    least/mean  BEM centre Pa  BEM cells  BEM F / disc F - 1  iterations"
    );
    for ratio in [30.0, 300.0, 3000.0, 8000.0] {
        let base = Material::new(9.5e7 / ratio, 0.45)?;
        let body = Substrate::layer_resting_on_elastic_base(layer, h, base)?;
        let tip = Axisymmetric::new(&body, 10.0)?.tip(Tip::Sphere { radius }, 0.0)?;
        for eps in [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0] {
            let a = eps * h;
            let state = tip.at_contact_radius(a)?;
            let least = tip.minimum_pressure_ratio(a)?;
            let grid = Grid::new(n, n, 2.6 * a / n as f64)?;
            let params = SolverParams {
                fields: Fields::all(),
                tolerance: 1e-8,
                ..SolverParams::default()
            };
            let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params)?;
            let (solution, _) =
                solver.solve_depth(&Sphere::new(radius)?, state.depth, None, &mut ())?;
            let Some(p) = solution.pressure.as_ref() else {
                continue;
            };
            // The mean of the four cells about the grid's centre.
            let m = n / 2;
            let centre = 0.25 * (p[[m, m]] + p[[m - 1, m]] + p[[m, m - 1]] + p[[m - 1, m - 1]]);
            let cells = p.iter().filter(|v| **v > 0.0).count();
            println!(
                "{ratio:5} {eps:4} {:.3e} {least:+.4e}  {centre:.4e}  {cells:9}  {:+.3e}  {} ({})",
                state.depth,
                solution.force / state.force - 1.0,
                solution.iterations,
                solution.coarse_iterations
            );
        }
    }
    Ok(())
}
