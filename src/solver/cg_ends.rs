//! How the constrained conjugate gradients of
//! [`polonsky_keer`](super::polonsky_keer) start (the initial pressure) and
//! finish (the converged solution and warm start, the singular uniform
//! mode).

use std::borrow::Cow;

use crate::error::{Error, Result};

use super::polonsky_keer::Control;
use super::{passes, ContactSolver, Solution, WarmStart};

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
        Ok((solution, WarmStart { pressure, attached }))
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
}
