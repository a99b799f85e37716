//! Where the solver's automatic choice of preconditioner decides, read back
//! from a fine solve's trace (shared by the benchmark examples).

/// The iteration at whose start the automatic choice
/// (`ContactSolver::set_automatic_coarse_blocks`) decides and the box's
/// mean residual factor it judges by, from a fine solve's `(residual,
/// contact cells)` after each iteration: the first iteration after three
/// in a row that each changed the contact count by at most a thousandth
/// of it, the factor taken over those three (`coarse_choice.rs`, the
/// constants `AUTOMATIC_BLOCKS_BOX_RATE` and `QUIET_ITERATIONS`). `None`
/// if the solve ended before.
pub fn decision(trace: &[(f64, usize)]) -> Option<(usize, f64)> {
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
