//! Rough contacts on large grids: a self-affine surface (Hurst 0.8, rms
//! slope 0.1, roll-off at a quarter of the domain, cut-off at four cells),
//! turned into a rigid indenter and pressed under force control onto a
//! rubber film (E = 1 MPa, nu = 0.49, 0.1 mm thick) on a rigid base, over a
//! 1 mm square; nominal pressure 5 kPa (a few per cent of the area in
//! contact).
//!
//! ```text
//! cargo run --release --example rough_benchmark -- [isolated|periodic|peers|stack|periodic-stack] [--refine] [--box | --blocks B] N [N ...]
//! ```
//!
//! `stack` presses the same surface, isolated, into a stack instead: a
//! 20 um coating (E = 5 MPa, nu = 0.3) on the same rubber film over a
//! softer elastic base (E = 0.2 MPa, nu = 0.45); `periodic-stack` the
//! same on a periodic grid. Isolated, the soft base carries the square
//! window of the surface like a flat punch: most of the force lies next
//! to the window's edges (`BANDS=1`, below).
//!
//! `peers` solves the problem of `benches/peers/rough.py` instead (the
//! same surface on a periodic half-space of `E* = 1` over a unit square,
//! mean pressure `0.01 E*`), the one timed against tamaas.
//!
//! With `--refine` the cut-off stays at 31.25 um (16 cells of a 512 grid)
//! whatever N: the same roughness on finer and finer grids, which shows
//! whether the solver's iterations depend on the grid or on the surface.
//! The solver chooses its preconditioner itself
//! (`ContactSolver::set_automatic_coarse_blocks`: the two-level one on
//! rough contacts of grids of 2048^2 cells and more, and from 1024^2 where
//! the box converges slowly); `--box` keeps it to
//! the box, `--blocks B` to the two-level preconditioner over blocks of `B
//! x B` cells (`ContactSolver::set_coarse_blocks`). A line `# blocks`
//! after each grid's CSV line says which blocks the solver had.
//!
//! Prints one CSV line per grid: N, boundary, seconds to build the solver,
//! to synthesise the surface and to solve, iterations (and those of the
//! multi-resolution start), the contact fraction, and the process's peak
//! resident memory and bytes per cell. `RAYON_NUM_THREADS` sets the threads.
//! `TRACE=1` adds a line per grid on how the fine iterations converge: the
//! last iteration whose contact count changed and the mean factor by which
//! the residual falls per iteration before and after it (the linear
//! phase's rate, set by the preconditioner), and when the first fine
//! iteration ended (the multi-resolution start before it) and the mean time
//! of a fine iteration after it; `TRACE=all` also a line per fine
//! iteration (`# k residual contact_cells`, `k` from 0). Both add the
//! iterations done when the solver's choice of preconditioner was made,
//! the box's factor it judged by and the iterations that took the
//! two-level preconditioner (`ContactSolver::last_preconditioning`).
//! `SEED=k` synthesises the surface from seed `k` (1 unless set), for the
//! spread of iteration counts over surfaces of the same statistics.
//! `COLD=1` solves without the multi-resolution start. `BANDS=1` keeps the pressures and
//! prints the solution's edge flag and the share of the force on the cells
//! within 5, 10 and 20 % of the side from the grid's edges.

use std::time::Instant;

use layered_contact::solver::{ContactSolver, Fields, IterationInfo, SolverParams};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Base, Boundary, Grid, Material, Substrate};

#[path = "support/memory.rs"]
mod memory;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1).peekable();
    // The peers' problem of `benches/peers/rough.py`: the same surface on a
    // periodic half-space of E* = 1 over a unit square, mean pressure 0.01.
    let peers = args.peek().map(String::as_str) == Some("peers");
    let stack = matches!(
        args.peek().map(String::as_str),
        Some("stack" | "periodic-stack")
    );
    let boundary = match args.peek().map(String::as_str) {
        Some("periodic" | "peers" | "periodic-stack") => {
            args.next();
            Boundary::Periodic
        }
        Some("isolated" | "stack") => {
            args.next();
            Boundary::Isolated
        }
        _ => Boundary::Isolated,
    };
    let refine = args.peek().map(String::as_str) == Some("--refine");
    if refine {
        args.next();
    }
    // `--box`: the box alone; `--blocks B`: the two-level preconditioner
    // over blocks of B cells; neither: the solver's own choice.
    let blocks = match args.peek().map(String::as_str) {
        Some("--box") => {
            args.next();
            Some(None)
        }
        Some("--blocks") => {
            args.next();
            let side = args.next().unwrap_or_default();
            let side = side
                .parse::<usize>()
                .map_err(|e| format!("--blocks needs a block side in cells, got {side:?}: {e}"))?;
            Some(Some(side))
        }
        _ => None,
    };
    let sizes = args
        .map(|a| {
            a.parse::<usize>()
                .map_err(|e| format!("a grid side in cells, got {a:?}: {e}"))
        })
        .collect::<Result<Vec<usize>, String>>()?;
    // Side (m), body and nominal pressure (Pa).
    let (side, film, pressure) = if peers {
        (1.0, Substrate::half_space(Material::new(1.0, 0.0)?), 0.01)
    } else if stack {
        let (coat, rubber) = (Material::new(5e6, 0.3)?, Material::new(1e6, 0.49)?);
        let base = Base::Elastic(Material::new(2e5, 0.45)?);
        let body = Substrate::stack(&[(coat, 2e-5), (rubber, 1e-4)], base)?;
        (1e-3, body, 5e3)
    } else {
        let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.49)?, 1e-4)?;
        (1e-3, film, 5e3)
    };
    let force = pressure * side * side;
    let bands = std::env::var("BANDS").is_ok();
    let seed = match std::env::var("SEED") {
        Ok(k) => k
            .parse::<u64>()
            .map_err(|e| format!("SEED must be a non-negative integer, got {k:?}: {e}"))?,
        Err(_) => 1,
    };
    println!("N,boundary,build_s,surface_s,solve_s,iterations,coarse_iterations,contact_fraction,peak_mb,bytes_per_cell");
    for n in sizes {
        let grid = Grid::square_of_side(n, side)?;
        let start = Instant::now();
        let surface = SelfAffine {
            hurst: 0.8,
            amplitude: Amplitude::RmsSlope(0.1),
            long_cutoff: 0.25 * side,
            short_cutoff: if refine {
                16.0 * side / 512.0
            } else {
                4.0 * grid.spacing()
            },
            seed,
        }
        .indenter(&grid)?;
        let synthesis = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let params = SolverParams {
            tolerance: 1e-8,
            multiresolution: std::env::var("COLD").is_err(),
            fields: Fields {
                pressure: bands,
                ..Fields::default()
            },
            ..SolverParams::default()
        };
        let mut solver = ContactSolver::new(&film, &grid, boundary, params)?;
        if let Some(blocks) = blocks {
            solver.set_coarse_blocks(blocks)?;
        }
        let build = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let mut trace: Vec<(f64, usize)> = Vec::new();
        // When the first fine iteration ends: the multi-resolution start's
        // share of the solve is the time before it, less one iteration.
        let mut first: Option<f64> = None;
        let mut observe = |i: &IterationInfo| {
            first.get_or_insert_with(|| start.elapsed().as_secs_f64());
            trace.push((i.residual, i.contact_cells));
        };
        let (solution, _) = solver.solve_force(&surface, force, None, &mut observe)?;
        let solve = start.elapsed().as_secs_f64();
        let peak = memory::peak_resident_bytes();
        println!(
            "{n},{boundary:?},{build:.2},{synthesis:.2},{solve:.2},{},{},{:.4},{:.0},{:.0}",
            solution.iterations,
            solution.coarse_iterations,
            solution.contact_cells as f64 / grid.len() as f64,
            peak / 1048576.0,
            peak / grid.len() as f64
        );
        println!(
            "# blocks {:?}{}",
            solver.coarse_blocks(),
            if solver.coarse_blocks_automatic() {
                " (automatic)"
            } else {
                ""
            }
        );
        if let (true, Some(p)) = (bands, &solution.pressure) {
            print_bands(p, solution.edge_contact);
        }
        if std::env::var("TRACE").is_ok() {
            if std::env::var("TRACE").as_deref() == Ok("all") {
                for (k, (r, c)) in trace.iter().enumerate() {
                    println!("# {k} {r:.3e} {c}");
                }
            }
            print_rates(&trace);
            if let Some(p) = solver.last_preconditioning() {
                if let (Some(k), Some(rate)) = (p.decided_after, p.box_factor) {
                    println!(
                        "# the choice decides at iteration {k} on a factor of {rate:.3}; \
                         {} iterations with the blocks",
                        p.two_level_iterations
                    );
                }
            }
            let first = first.unwrap_or(f64::NAN);
            let per = (solve - first) / (trace.len().max(2) - 1) as f64;
            println!(
                "# first fine iteration done at {first:.2} s; then {per:.3} s a fine iteration"
            );
        }
    }
    Ok(())
}

/// The last iteration whose contact count changed, and the mean factor by
/// which the residual fell per iteration up to it and after it.
fn print_rates(trace: &[(f64, usize)]) {
    let settled = (1..trace.len())
        .rev()
        .find(|&k| trace[k].1 != trace[k - 1].1)
        .unwrap_or(0);
    // "-" where there is no iteration to measure (the contact settled at
    // the last one).
    let rate = |from: usize, to: usize| {
        if to > from {
            format!(
                "{:.3}",
                (trace[to].0 / trace[from].0).powf(1.0 / (to - from) as f64)
            )
        } else {
            "-".to_string()
        }
    };
    let last = trace.len().saturating_sub(1);
    println!(
        "# contact settled at iteration {} of {}; residual factor per iteration {} before, {} after",
        settled + 1,
        trace.len(),
        rate(0, settled),
        rate(settled, last)
    );
}

/// The solution's edge flag and the share of the force on the cells within
/// 5, 10 and 20 % of the side from the grid's edges.
fn print_bands(pressure: &ndarray::Array2<f64>, edge_contact: bool) {
    let (rows, cols) = pressure.dim();
    let total: f64 = pressure.sum();
    let shares: Vec<String> = [0.05, 0.1, 0.2]
        .iter()
        .map(|band| {
            let (m, k) = ((band * rows as f64) as usize, (band * cols as f64) as usize);
            let near: f64 = pressure
                .indexed_iter()
                .filter(|((i, j), _)| *i < m || *j < k || *i >= rows - m || *j >= cols - k)
                .map(|(_, p)| p)
                .sum();
            format!(
                "{:.0} % ({:.0} % of the area)",
                100.0 * near / total,
                100.0 * (1.0 - (1.0 - 2.0 * band).powi(2))
            )
        })
        .collect();
    println!(
        "# edge contact {edge_contact}; force within 5 / 10 / 20 % of the side of the edges: {}",
        shares.join(" / ")
    );
}
