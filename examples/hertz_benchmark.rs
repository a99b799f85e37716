//! The peers' Hertz benchmark: a rigid paraboloid `R = 1` on a non-periodic
//! half-space `E* = 1`, domain 2 x 2 on N x N cells, depth 0.25 (contact
//! radius a = 0.5 = L/4), tolerance 1e-8; solved under depth and under force
//! control (the Hertz force at that depth).
//!
//! `cargo run --release --example hertz_benchmark -- 256 512 1024`
//! prints one line per grid and control: N, control, build time (kernel and
//! plans), solve time, iterations, the relative error of the force (depth
//! control) or depth (force control) against Hertz, and the process's peak
//! resident memory so far. `RAYON_NUM_THREADS` sets the threads.
//! `benches/peers/run.sh` runs it beside tamaas and ContactMechanics.

use std::time::Instant;

use layered_contact::indenter::Paraboloid;
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::{Boundary, Grid, Material, Substrate};

#[path = "support/memory.rs"]
mod memory;

fn main() -> Result<(), layered_contact::Error> {
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if sizes.is_empty() {
        vec![256, 512]
    } else {
        sizes
    };
    let (radius, depth, side): (f64, f64, f64) = (1.0, 0.25, 2.0);
    let hertz_force = 4.0 / 3.0 * radius.sqrt() * depth * depth.sqrt();
    let params = SolverParams {
        tolerance: 1e-8,
        ..SolverParams::default()
    };
    println!("N,control,build_s,solve_s,iterations,relative_error,peak_mb");
    for n in sizes {
        let start = Instant::now();
        let grid = Grid::square_of_side(n, side)?;
        let substrate = Substrate::half_space(Material::new(1.0, 0.0)?);
        let mut solver = ContactSolver::new(&substrate, &grid, Boundary::Isolated, params)?;
        let build = start.elapsed().as_secs_f64();
        let indenter = Paraboloid::new(radius)?;
        let start = Instant::now();
        let (s, _) = solver.solve_depth(&indenter, depth, None, &mut ())?;
        let t = start.elapsed().as_secs_f64();
        println!(
            "{n},depth,{build:.3},{t:.3},{},{:.3e},{:.0}",
            s.iterations,
            s.force / hertz_force - 1.0,
            memory::peak_resident_bytes() / 1048576.0
        );
        let start = Instant::now();
        let (s, _) = solver.solve_force(&indenter, hertz_force, None, &mut ())?;
        let t = start.elapsed().as_secs_f64();
        println!(
            "{n},force,{build:.3},{t:.3},{},{:.3e},{:.0}",
            s.iterations,
            s.depth / depth - 1.0,
            memory::peak_resident_bytes() / 1048576.0
        );
    }
    Ok(())
}
