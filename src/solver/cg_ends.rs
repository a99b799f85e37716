//! How the constrained conjugate gradients of
//! [`polonsky_keer`](super::polonsky_keer) start (the initial pressure) and
//! finish (the converged solution and warm start, the singular uniform
//! mode).

use std::borrow::Cow;

use crate::error::{Error, Result};

use super::polonsky_keer::Control;
use super::{passes, ContactSolver, Solution, WarmStart};

/// A warm start within this factor of its least-energy scale
/// ([`ContactSolver::scale_warm_start`]) is left as it is: scaling every
/// warm start cost a non-adhesive cycle of a tilted paraboloid (29 steps)
/// 13.2 / 13.0 / 13.0 solves' iterations at 16 / 32 / 64 cells against
/// 12.5 / 12.2 / 13.2 unscaled (`PLAIN=1 cargo run --release --example
/// adhesive_cycle_cost -- cohesive 16 32 64`, 2026-11-29), and its
/// adhesive cycle 2327 iterations against 2231 at 64 cells.
const WARM_SCALE_KEPT: f64 = 4.0;

impl ContactSolver {
    /// The solution and warm start of a converged pressure.
    pub(super) fn converged(
        &mut self,
        control: Control,
        pressure: Vec<f64>,
        mut depth: f64,
        iteration: usize,
        residual: f64,
    ) -> Result<(Solution, WarmStart)> {
        let n = self.grid().len();
        // The displacement is K p, kept up to date step by step (and
        // recomputed every REFRESH iterations): the depth under force
        // control follows from it.
        if let Control::Force(_) = control {
            let ws = &self.workspace;
            let (sum, count) = passes::contact_sum(&ws.profile, &ws.displacement, &pressure);
            let mut totals = [sum, count as f64];
            self.sum_over_ranks(&mut totals);
            depth = totals[0] / totals[1].max(1.0);
        }
        let solution = self.solution(&pressure, depth, iteration, residual, None);
        super::check_solution(&solution)?;
        if matches!(control, Control::Depth(_))
            && solution.contact_cells == n
            && !self.operator.uniform_mode_bounded()
        {
            return Err(self.singular_uniform_mode());
        }
        let attached = pressure.iter().map(|p| *p > 0.0).collect();
        Ok((
            solution,
            WarmStart {
                pressure,
                attached,
                contact: None,
                withdrawn: false,
            },
        ))
    }

    /// The error of a periodic grid in full contact on a body without a
    /// rigid base under depth control: the mean pressure is undetermined
    /// by the depth (the uniform mode's compliance is infinite). Anything
    /// else that stalls the step is a bug.
    pub(super) fn singular_uniform_mode(&self) -> Error {
        if self.operator.uniform_mode_bounded() {
            return Error::Internal {
                what: "constrained conjugate gradients",
                detail: "the operator is not positive definite on the working set".into(),
            };
        }
        Error::Unsupported {
            feature: "full contact under depth control on a periodic grid \
                      without a rigid base",
            reason: "the mean pressure is undetermined (the uniform mode's \
                     compliance is infinite); prescribe the force (solve_force)",
        }
    }

    /// The operator's response at a cell to unit pressure on it.
    pub(super) fn self_compliance(&mut self) -> Result<f64> {
        if let Some(influence) = self.operator.influence() {
            return Ok(influence.self_coefficient());
        }
        let ws = &mut self.workspace;
        ws.direction.fill(0.0);
        ws.direction[0] = 1.0;
        self.operator.apply(&ws.direction, &mut ws.response)?;
        Ok(ws.response[0].max(f64::MIN_POSITIVE))
    }

    /// A starting pressure: the warm start (which the caller keeps only if
    /// it has contact on a reachable cell), else zero (or uniform on the
    /// reachable cells, for force control).
    pub(super) fn initial_pressure(
        &self,
        control: Control,
        warm: Option<Cow<'_, WarmStart>>,
        reachable: &[bool],
    ) -> Vec<f64> {
        let clamp = |p: f64, r: bool| if r { p.max(0.0) } else { 0.0 };
        match warm {
            Some(Cow::Owned(w)) => {
                let mut pressure = w.pressure;
                for (p, r) in pressure.iter_mut().zip(reachable) {
                    *p = clamp(*p, *r);
                }
                return pressure;
            }
            Some(Cow::Borrowed(w)) => {
                return w
                    .pressure
                    .iter()
                    .zip(reachable)
                    .map(|(p, r)| clamp(*p, *r))
                    .collect();
            }
            None => {}
        }
        match control {
            // The first iteration steps from zero along the preconditioned
            // overlap.
            Control::Depth(_) => vec![0.0; reachable.len()],
            Control::Force(_) => reachable
                .iter()
                .map(|r| if *r { 1.0 } else { 0.0 })
                .collect(),
        }
    }

    /// Scales a warm start under depth control to the least energy along
    /// its own direction: `p <- a p`, `u <- a u` with `a = sum p (depth -
    /// h) / sum p u` (the minimum of `p . K p / 2 + p . (h - depth)` on the
    /// ray through `p`; `u = K p` is the start's displacement, already
    /// computed, so this costs two sums), unless `a` is within a factor
    /// [`WARM_SCALE_KEPT`] of one. A warm start far from the new
    /// depth's scale (a flat punch unloaded from `5e-6` m to `1e-15` m) left
    /// the iteration to cancel a pressure a billion times too large, whose
    /// rounding it never converged out of (10000 iterations at a residual of
    /// `3e-8`); a close one is scaled by about one. `a <= 0` (the start
    /// pulls where the new depth does not reach) starts from zero
    /// pressure, as a cold start does. Returns the factor.
    pub(super) fn scale_warm_start(&mut self, depth: f64, pressure: &mut [f64]) -> f64 {
        let ws = &mut self.workspace;
        let mut sums = [0.0, 0.0];
        for ((p, h), u) in pressure.iter().zip(&ws.profile).zip(&ws.displacement) {
            if *p > 0.0 {
                sums[0] += p * (depth - h);
                sums[1] += p * u;
            }
        }
        self.sum_over_ranks(&mut sums);
        let factor = sums[0] / sums[1];
        if !factor.is_finite() || sums[1] <= 0.0 {
            return 1.0;
        }
        if (1.0 / WARM_SCALE_KEPT..=WARM_SCALE_KEPT).contains(&factor) {
            return 1.0;
        }
        let factor = factor.max(0.0);
        passes::scale(pressure, factor);
        passes::scale(&mut self.workspace.displacement, factor);
        factor
    }
}
