//! The operator's part of a step of the constrained conjugate gradients:
//! the search direction's energy `t . K t` (the step length's
//! denominator) and the displacement's move by the step's change of the
//! pressure. After a step whose clamping needed a convolution (most
//! iterations of a rough contact) the next likely clamps too: its length
//! then comes from the energy summed over the spectrum of the forward
//! transform alone (Parseval's theorem, half a round trip) and its
//! displacement from one convolution of the whole change of the pressure,
//! instead of `K t` and the clamping correction's response apart (two
//! round trips). Measured in `BENCHMARKS.md` ("Rough contacts beside
//! tamaas").

use std::ops::Range;

use crate::error::Result;

use super::{passes, ContactSolver};

impl ContactSolver {
    /// `t . K t` of the workspace's direction `t` (zero off the working
    /// set, whose rows are `cells`), this rank's share. `deferred`: from
    /// the spectrum alone; else through `K t`, left in `response` for
    /// [`ContactSolver::respond_to_step`].
    pub(super) fn direction_energy(&mut self, deferred: bool, cells: Range<usize>) -> Result<f64> {
        let ws = &mut self.workspace;
        if deferred {
            return self.operator.energy(&ws.direction);
        }
        self.operator.apply(&ws.direction, &mut ws.response)?;
        Ok(passes::dot(
            &ws.response[cells.clone()],
            &ws.direction[cells],
        ))
    }

    /// Moves the displacement by the response to the step just taken
    /// (`step` along the direction, `corrected` cells clamped, on the
    /// working set's rows `cells`; `direct`: their displacements cost less
    /// summed directly than convolved): `gap` holds the whole change of the
    /// pressure if `deferred` (see [`passes::step`]), else the clamping's
    /// correction, `K t` being in `response` and already subtracted. Under
    /// force control with a rescale to come (`rescaled`) a convolved
    /// response is left in `response` for it instead: returns whether it
    /// is pending there.
    pub(super) fn respond_to_step(
        &mut self,
        deferred: bool,
        corrected: usize,
        direct: bool,
        step: f64,
        cells: Range<usize>,
        rescaled: bool,
    ) -> Result<bool> {
        let ws = &mut self.workspace;
        if deferred && corrected == 0 {
            // No clamping after all: the direction's response.
            self.operator
                .apply_add(&ws.direction, &mut ws.displacement, -step)?;
            return Ok(false);
        }
        if corrected == 0 {
            return Ok(false);
        }
        if !deferred && direct {
            // A few clamped cells: their displacements by direct
            // summation, cheaper than a convolution.
            if let Some(k) = self.operator.influence() {
                let loads = passes::nonzeros(&ws.gap[cells.clone()], cells.start);
                k.add_loads(&loads, &mut ws.displacement);
                return Ok(false);
            }
        }
        if rescaled {
            self.operator.apply(&ws.gap, &mut ws.response)?;
            return Ok(true);
        }
        self.operator
            .apply_add(&ws.gap, &mut ws.displacement, 1.0)?;
        Ok(false)
    }
}
