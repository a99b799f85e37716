//! The solver's own choice of preconditioner
//! (`ContactSolver::set_automatic_coarse_blocks`, the default): the
//! two-level preconditioner over blocks of 16 cells for a rough contact on
//! a grid of at least 2048^2 cells, and from 1024^2 if its box converges
//! slowly enough for the smaller grid; the box for a contact of one patch,
//! for the rough film at 1024^2 and on smaller grids.

use layered_contact::indenter::{HeightMap, Sphere};
use layered_contact::solver::{
    ContactSolver, IterationInfo, Preconditioning, Solution, SolverParams, WarmStart,
    AUTOMATIC_BLOCKS_BOX_RATE, AUTOMATIC_BLOCKS_CELLS, AUTOMATIC_BLOCKS_LARGE_CELLS,
    AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE, AUTOMATIC_BLOCK_SIDE,
};
use layered_contact::{Boundary, Grid, Material, Substrate};

mod common;

/// The problem of `benches/peers/rough.py` on `n x n` cells: the seeded
/// surface (Hurst 0.8, rms slope 0.1, roll-off at a quarter of the side,
/// cut-off at four cells) on a periodic half-space of `E* = 1` over a unit
/// square, solved at a mean pressure of `0.01`, tolerance 1e-8, with the
/// preconditioner `blocks` sets (`None`: the solver's choice). The solution,
/// the blocks the solver had and its report of the preconditioning, checked
/// against the choice's rule read from the iterations' residuals and
/// contact counts ([`decision`]).
fn peers_problem(
    n: usize,
    blocks: Option<Option<usize>>,
) -> (Solution, Option<usize>, Preconditioning) {
    let body = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
    rough_problem(&body, n, 1.0, Boundary::Periodic, 0.01, blocks)
}

/// The seeded rough surface of [`peers_problem`] over a square of `side`
/// (m) on `n x n` cells, pressed into `body` at a mean pressure of
/// `pressure` (Pa), tolerance 1e-8, as [`peers_problem`] solves and checks
/// it.
fn rough_problem(
    body: &Substrate,
    n: usize,
    side: f64,
    boundary: Boundary,
    pressure: f64,
    blocks: Option<Option<usize>>,
) -> (Solution, Option<usize>, Preconditioning) {
    let grid = Grid::square_of_side(n, side).unwrap();
    let indenter = common::rough_surface(side, n, 1).indenter(&grid).unwrap();
    let params = SolverParams {
        tolerance: 1e-8,
        ..SolverParams::default()
    };
    let mut solver = ContactSolver::new(body, &grid, boundary, params).unwrap();
    if let Some(blocks) = blocks {
        solver.set_coarse_blocks(blocks).unwrap();
    }
    let mut trace = Vec::new();
    let mut observe = |i: &IterationInfo| trace.push((i.residual, i.contact_cells));
    let (solution, _) = solver
        .solve_force(&indenter, pressure * side * side, None, &mut observe)
        .unwrap();
    let report = solver.last_preconditioning().unwrap();
    let (k, factor) = decision(&trace).unwrap();
    assert_eq!(report.decided_after, Some(k));
    let reported = report.box_factor.unwrap();
    assert!(
        (reported - factor).abs() <= 1e-12 * factor,
        "{reported} against {factor}"
    );
    (solution, solver.coarse_blocks(), report)
}

/// The choice's rule from a solve's `(residual, contact cells)` after each
/// fine iteration, as `coarse_choice.rs` documents it: the iterations done
/// once three in a row have each changed the contact count by at most a
/// thousandth of it, and the residual's mean factor an iteration over those
/// three (from the residual after the last one that moved it). `None` if
/// the solve ended before.
fn decision(trace: &[(f64, usize)]) -> Option<(usize, f64)> {
    let (mut quiet, mut moved, mut before, mut last) = (0_i32, f64::INFINITY, None::<usize>, 0.0);
    for (k, &(residual, cells)) in trace.iter().enumerate() {
        if quiet >= 3 {
            return Some((k, (last / moved).powf(1.0 / f64::from(quiet))));
        }
        if before.is_some_and(|b| b.abs_diff(cells) as f64 <= 1e-3 * b as f64) {
            quiet += 1;
        } else {
            quiet = 0;
            moved = residual;
        }
        before = Some(cells);
        last = residual;
    }
    None
}

/// The solutions of `solve` on two solvers from `new`: the first choosing
/// its preconditioner itself, the second set to the box; neither may have
/// built blocks.
fn chosen_and_boxed(
    new: impl Fn() -> Result<ContactSolver, layered_contact::Error>,
    solve: impl Fn(&mut ContactSolver) -> Result<(Solution, WarmStart), layered_contact::Error>,
) -> [Solution; 2] {
    [false, true].map(|boxed| {
        let mut solver = new().unwrap();
        if boxed {
            solver.set_coarse_blocks(None).unwrap();
        }
        let (solution, _) = solve(&mut solver).unwrap();
        assert_eq!(solver.coarse_blocks(), None);
        solution
    })
}

/// At 2048^2 (the smallest grid on which the automatic choice asks the
/// box's rate of [`AUTOMATIC_BLOCKS_BOX_RATE`] only) the rough contact
/// (thousands of patches) takes the blocks: measured 29 fine iterations
/// against the box's 45 (`rough_benchmark peers 2048` and `--box`,
/// 2026-12-06; BENCHMARKS.md, "The solver's own choice of preconditioner"
/// and "A start level's settled count"); the bound, 10 fewer, fails if
/// the choice keeps the box. The same solution: the same contact cells and
/// depths within 1e-8 (each solve's tolerance bounds its pressures' last
/// change, not their error; the blocks' solution at 1024^2 and below lies
/// within 1e-10 of the box's in `tests/rough_solve.rs`).
#[test]
fn rough_contact_on_a_large_grid_takes_the_blocks() {
    assert_eq!(AUTOMATIC_BLOCKS_LARGE_CELLS, 2048 * 2048);
    takes_the_blocks(2048, AUTOMATIC_BLOCKS_BOX_RATE, 10);
}

/// At 1024^2 (the smallest grid of the automatic choice) the same rough
/// problem's box decides on a factor above
/// [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`] (measured 0.653) and the
/// solver takes the blocks: measured 23 fine iterations against the box's
/// 33, in 0.71 to 0.90 of its time on one thread over four seeds
/// (`rough_benchmark peers 1024` and `--blocks 16`, 2026-12-06;
/// BENCHMARKS.md, "The blocks on smaller grids"); the bound, 6 fewer,
/// fails if the choice keeps the box. The same contact as the box's.
#[test]
fn rough_contact_with_a_slow_box_on_a_1024_grid_takes_the_blocks() {
    assert_eq!(AUTOMATIC_BLOCKS_CELLS, 1024 * 1024);
    takes_the_blocks(1024, AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE, 6);
}

/// The rough problem on `n x n` cells, chosen and boxed: the choice takes
/// the blocks on a box's factor of at least `least_factor`, serves them
/// from the choice on (but for iterations after a move of the count, the
/// box's), after the same iterations as the box's run (alike up to
/// there), and ends at least `fewer` iterations before the box at the
/// same contact.
fn takes_the_blocks(n: usize, least_factor: f64, fewer: usize) {
    let (chosen, blocks, report) = peers_problem(n, None);
    assert_eq!(blocks, Some(AUTOMATIC_BLOCK_SIDE));
    assert_eq!(report.blocks, Some(AUTOMATIC_BLOCK_SIDE));
    assert!(report.box_factor.unwrap() >= least_factor);
    let after = chosen.iterations - report.decided_after.unwrap();
    assert!((1..=after).contains(&report.two_level_iterations));
    let (boxed, none, box_report) = peers_problem(n, Some(None));
    assert_eq!(none, None);
    assert_eq!(
        (box_report.decided_after, box_report.box_factor),
        (report.decided_after, report.box_factor)
    );
    assert_eq!(
        (box_report.blocks, box_report.two_level_iterations),
        (None, 0)
    );
    assert!(
        chosen.iterations + fewer <= boxed.iterations,
        "{} against the box's {}",
        chosen.iterations,
        boxed.iterations
    );
    common::assert_same_contact(&chosen, &boxed);
}

/// At 1024^2 the rough film of `examples/rough_benchmark.rs` (the same
/// surface over 1 mm, isolated, on a 0.1 mm rubber film, E = 1 MPa, nu =
/// 0.49, on a rigid base, at 5 kPa) keeps the box: its box decides on a
/// factor between [`AUTOMATIC_BLOCKS_BOX_RATE`] and
/// [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`] (measured 0.411), where the
/// blocks would have taken 19 fine iterations against its 20 and 0.83 to
/// 1.34 times its time over four seeds (BENCHMARKS.md, "The blocks on
/// smaller grids"). No blocks built, none served.
#[test]
fn rough_film_on_a_1024_grid_keeps_the_box() {
    let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.49).unwrap(), 1e-4).unwrap();
    let (_, blocks, report) = rough_problem(&film, 1024, 1e-3, Boundary::Isolated, 5e3, None);
    let factor = report.box_factor.unwrap();
    assert!(
        (AUTOMATIC_BLOCKS_BOX_RATE..AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE).contains(&factor),
        "{factor}"
    );
    assert_eq!(blocks, None);
    assert_eq!((report.blocks, report.two_level_iterations), (None, 0));
}

/// Below 1024^2 the solver keeps the box: the rough problem at 512^2 takes
/// the box's iterations exactly (measured 27) and builds no blocks,
/// although the box's factor at the choice (measured 0.555) lies above
/// [`AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE`]: the grid is too small.
#[test]
fn rough_contact_on_a_smaller_grid_keeps_the_box() {
    let (chosen, blocks, report) = peers_problem(512, None);
    assert_eq!(blocks, None);
    assert!(report.box_factor.unwrap() >= AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE);
    assert_eq!((report.blocks, report.two_level_iterations), (None, 0));
    let (boxed, _, _) = peers_problem(512, Some(None));
    assert_eq!(chosen.iterations, boxed.iterations);
    assert_eq!(chosen.depth.to_bits(), boxed.depth.to_bits());
}

/// A contact of one patch keeps the box on a large grid: a sphere (R = 10
/// mm) pressed 2 um into a rubber half-space on 2048 x 2048 cells of 1 um,
/// isolated (a contact about 280 cells across), builds no blocks and
/// takes the box's iterations exactly. (Its box converges faster than
/// `AUTOMATIC_BLOCKS_BOX_RATE`; the patch count's own test is in
/// `src/solver/coarse_choice.rs`.)
#[test]
fn one_patch_on_a_large_grid_keeps_the_box() {
    let body = Substrate::half_space(Material::new(1e6, 0.5).unwrap());
    let grid = Grid::new(2048, 2048, 1e-6).unwrap();
    let sphere = Sphere::new(1e-2).unwrap();
    let [chosen, boxed] = chosen_and_boxed(
        || ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default()),
        |solver| solver.solve_depth(&sphere, 2e-6, None, &mut ()),
    );
    assert_eq!(
        (chosen.iterations, chosen.force.to_bits()),
        (boxed.iterations, boxed.force.to_bits())
    );
}

/// Many patches of one scale keep the box: a periodic two-way sinusoid
/// (`h = (cos kx + cos ky) / 2 * 1e-2 / 32`, 32 waves a side) on 2048 x
/// 2048 cells of a unit square pressed into a periodic half-space of `E*
/// = 1` at a mean pressure of `2e-3` (1024 equal patches, 13.8 % in
/// contact). The box's residual falls by about a factor of 0.12 an
/// iteration while the count settles, below
/// [`AUTOMATIC_BLOCKS_BOX_RATE`]: the solver keeps the box and its
/// iterations (measured 10) to the bit. Without the rate's test it took
/// the blocks, 11 fine iterations and 1.3 times the time.
#[test]
fn many_equal_patches_keep_the_box() {
    assert_eq!(AUTOMATIC_BLOCKS_BOX_RATE, 0.3);
    let n = 2048;
    let grid = Grid::square_of_side(n, 1.0).unwrap();
    let k = 2.0 * std::f64::consts::PI * 32.0;
    let centre = |i: usize| (i as f64 + 0.5) * grid.spacing();
    let heights: Vec<f64> = (0..n * n)
        .map(|c| 0.5 * 1e-2 / 32.0 * ((k * centre(c / n)).cos() + (k * centre(c % n)).cos()))
        .collect();
    let surface = HeightMap::new(grid, heights).unwrap();
    let body = Substrate::half_space(Material::new(1.0, 0.0).unwrap());
    let params = SolverParams {
        tolerance: 1e-8,
        ..SolverParams::default()
    };
    let [chosen, boxed] = chosen_and_boxed(
        || ContactSolver::new(&body, &grid, Boundary::Periodic, params),
        |solver| solver.solve_force(&surface, 2e-3, None, &mut ()),
    );
    assert_eq!(
        (chosen.iterations, chosen.depth.to_bits()),
        (boxed.iterations, boxed.depth.to_bits())
    );
}
