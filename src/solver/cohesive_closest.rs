//! How a cohesive zone's fixed point hands back its equilibrium: the
//! solution of a converged round, or, where the rounds came within
//! [`CLOSE_ENOUGH`] of the equilibrium and then left it, the closest round.
//! Used by [`solve_depth_cohesive`](super::ContactSolver::solve_depth_cohesive).

use crate::error::Result;

use super::cohesive_area::EQUIVALENT_TIP;
use super::{ContactSolver, Solution, WarmStart};

/// The largest change of the tensions (over the law's peak) of a round
/// that a fixed point ending without convergence hands back (its residual
/// says how close it came), where the tolerance asks for less.
///
/// On a stiff plate over a far softer layer (`tests/scene_cohesive_soft_below.rs`,
/// 32 cells across) the rounds of an unloading step came to 4.0e-8 of the
/// law's peak with the contact and the law fixed, then a mode of the
/// rounds grew back by about 1.5 % a round (a mode of the plain steps
/// whose factor exceeds one, which damping does not turn) to 5e-4, and the
/// solve ended in `NoConvergence` after its 2000 rounds. A change of 1e-6
/// of the peak moves a cell's tension by a millionth of the peak, the
/// force by at most a millionth of the zone's pull, far below the zone's
/// discretisation (per cents to tenths of one). Depth control only: under
/// force control a fixed point that does not converge is how a force past
/// the least one shows.
pub(super) const CLOSE_ENOUGH: f64 = 1e-6;

/// A round of the fixed point: the total pressure (Pa, tensions included),
/// its displacement (m), the closed cells, the bonded ones, the open zone's
/// cells joined to the closed ones ([`open_zone_cells`](super::cohesive_area::open_zone_cells)),
/// the depth (m) and the round's change of the tensions (over the law's
/// peak).
pub(super) struct Round {
    pub(super) total: Vec<f64>,
    pub(super) displacement: Vec<f64>,
    pub(super) contact: Vec<bool>,
    pub(super) bonded: Vec<bool>,
    pub(super) open: usize,
    pub(super) depth: f64,
    pub(super) residual: f64,
    /// Whether the solve withdraws (`WarmStart::withdrawn`).
    pub(super) withdrawn: bool,
}

impl ContactSolver {
    /// The solution and warm start of `round` after `iterations` CG
    /// iterations, with the workspace's profile the indenter's alone: the
    /// round's displacement goes to the workspace, and the contact area is
    /// the equivalent crack's ([`EQUIVALENT_TIP`]).
    pub(super) fn cohesive_round_solution(
        &mut self,
        round: Round,
        iterations: usize,
    ) -> Result<(Solution, WarmStart)> {
        self.workspace
            .displacement
            .copy_from_slice(&round.displacement);
        let area = self.grid().cell_area();
        let mut solution = self.solution(
            &round.total,
            round.depth,
            iterations,
            round.residual,
            Some(&round.contact),
        );
        solution.contact_area += EQUIVALENT_TIP * round.open as f64 * area;
        solution.contact_radius = (solution.contact_area / std::f64::consts::PI).sqrt();
        super::check_solution(&solution)?;
        Ok((
            solution,
            WarmStart {
                pressure: round.total,
                attached: round.bonded,
                contact: Some(round.contact),
                withdrawn: round.withdrawn,
            },
        ))
    }
}
