//! The operator's part of a step of the constrained conjugate gradients:
//! the search direction's energy `t . K t` (the step length's
//! denominator) and the displacement's move by the step's change of the
//! pressure. After a step whose clamping needed a convolution (most
//! iterations of a rough contact) the next likely clamps too: its length
//! then comes from the energy summed over the spectrum of the forward
//! transform alone (Parseval's theorem, half a round trip) and its
//! displacement from one convolution of the whole change of the pressure,
//! instead of `K t` and the clamping correction's response apart (two
//! round trips). That energy's transform runs in single precision (half
//! the bytes; a relative rounding of about `1e-7` in the step length,
//! while the displacement moves by the double-precision response to the
//! step actually taken, so that `u = K p` holds to `f64`'s rounding).
//! In a cold solve's early iterations every application runs in single
//! precision ([`Arithmetic`]): there the pressure still changes by more
//! than `1e-5` an iteration, far above the `1e-7` by which `f32`'s rounding
//! moves the displacement, and the solve recomputes the displacement in
//! double before it ends. Measured in `BENCHMARKS.md` ("Rough contacts
//! beside tamaas", "Speed: rough contacts on large grids").

use std::ops::Range;

use crate::error::Result;

use super::passes::{self, Before, Rescaled};
use super::ContactSolver;

impl ContactSolver {
    /// `t . K t` of the workspace's direction `t` (zero off the working
    /// set, whose rows are `cells`; `t_max` its largest absolute value on
    /// this rank), this rank's share, and whether it was summed in single
    /// precision (the caller checks that the total is finite and
    /// positive). `deferred`: from the spectrum alone, in single precision
    /// (a step length; the displacement's move stays in double) except in
    /// the cohesive zone's rounds (whose fixed point follows the inner
    /// solves' last digits); else through `K t`, left in `response` for
    /// [`ContactSolver::respond_to_step`], in single precision where
    /// `arithmetic` gives the direction's scale (a cold solve's early
    /// iterations).
    pub(super) fn direction_energy(
        &mut self,
        deferred: bool,
        cells: Range<usize>,
        t_max: f64,
        arithmetic: Arithmetic,
    ) -> Result<(f64, bool)> {
        let magnitude = match arithmetic.direction {
            Some(magnitude) => Some(magnitude),
            None if deferred && !self.double_preconditioner => {
                // A scale the same on every rank: the sum of the ranks' largest.
                Some(self.summed(t_max))
            }
            None => None,
        };
        let ws = &mut self.workspace;
        if deferred {
            return match magnitude {
                Some(m) => Ok((self.operator.energy_single(&ws.direction, m)?, true)),
                None => Ok((self.operator.energy(&ws.direction)?, false)),
            };
        }
        let (direction, response) = (&ws.direction, &mut ws.response);
        match magnitude {
            Some(m) => self
                .operator
                .apply_single(direction, response, m, |_, k| k)?,
            None => self.operator.apply(direction, response)?,
        }
        let energy = passes::dot(&ws.response[cells.clone()], &ws.direction[cells]);
        Ok((energy, magnitude.is_some()))
    }

    /// Moves the displacement by the response to the step just taken
    /// (`step` along the direction, `corrected` cells clamped, on the
    /// working set's rows `cells`; `direct`: their displacements cost less
    /// summed directly than convolved): `gap` holds the whole change of the
    /// pressure if `deferred` (see [`passes::step`]), else the clamping's
    /// correction, `K t` being in `response` and already subtracted. Under
    /// force control with a rescale by `rescale` to come, a convolution
    /// does it in its last pass ([`passes::rescale_row`]) and its sums are
    /// returned; `None`: the caller still rescales.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn respond_to_step(
        &mut self,
        deferred: bool,
        corrected: usize,
        direct: bool,
        step: f64,
        cells: Range<usize>,
        pressure: &mut [f64],
        rescale: Option<f64>,
        arithmetic: Arithmetic,
    ) -> Result<Option<Rescaled>> {
        if deferred && corrected == 0 {
            // No clamping after all: the direction's response.
            let magnitude = arithmetic.direction;
            return self.respond(true, true, -step, cells, pressure, rescale, magnitude);
        }
        if corrected == 0 {
            return Ok(None);
        }
        if !deferred && direct {
            // A few clamped cells: their displacements by direct
            // summation, cheaper than a convolution.
            if let Some(k) = self.operator.influence() {
                let ws = &mut self.workspace;
                let loads = passes::nonzeros(&ws.gap[cells.clone()], cells.start);
                k.add_loads(&loads, &mut ws.displacement);
                return Ok(None);
            }
        }
        let magnitude = arithmetic.change;
        self.respond(false, deferred, 1.0, cells, pressure, rescale, magnitude)
    }

    /// `u += factor K x`, `x` the direction or else `gap`, rescaled by
    /// `rescale` inside the convolution if given (its sums returned); in
    /// single precision if `x`'s `magnitude` is given (a scale the same on
    /// every rank, [`Arithmetic`]).
    #[allow(clippy::too_many_arguments)]
    fn respond(
        &mut self,
        x_is_direction: bool,
        deferred: bool,
        factor: f64,
        cells: Range<usize>,
        pressure: &mut [f64],
        rescale: Option<f64>,
        magnitude: Option<f64>,
    ) -> Result<Option<Rescaled>> {
        let columns = self.grid().columns();
        let ws = &mut self.workspace;
        let x = if x_is_direction {
            &ws.direction
        } else {
            &ws.gap
        };
        let Some(scale) = rescale else {
            let output = &mut ws.displacement;
            match magnitude {
                Some(m) => self
                    .operator
                    .apply_single(x, output, m, |u, k| u + factor * k)?,
                None => self.operator.apply_add(x, output, factor)?,
            }
            return Ok(None);
        };
        // A deferred step left the change of the pressure in `gap`.
        let before = if deferred {
            Before::Changes(&ws.gap)
        } else {
            Before::Pressures(&ws.previous)
        };
        let profile = &ws.profile;
        let targets = passes::rescale_targets(cells, columns, pressure, &mut ws.displacement);
        // Row `i`'s old pressures (or changes) and profile.
        let of_row = |i: usize| {
            let cells = i * columns..(i + 1) * columns;
            (before.cells(cells.clone()), &profile[cells])
        };
        let rows = match magnitude {
            // `K x` of a row is `unscale` times its single-precision values.
            Some(m) => {
                self.operator
                    .apply_into_single(x, m, targets, |i, row, response, unscale| {
                        let (before, profile) = of_row(i);
                        passes::rescale_row(row, response, unscale * factor, before, profile, scale)
                    })?
            }
            None => self.operator.apply_into(x, targets, |i, row, response| {
                let (before, profile) = of_row(i);
                passes::rescale_row(row, response, factor, before, profile, scale)
            })?,
        };
        Ok(Some(passes::add_rescaled(rows)))
    }
}

/// The arithmetic of a constrained conjugate-gradient step's applications
/// of the operator: in double precision, or in single with the scales of
/// what it is applied to (the same on every rank, about their largest
/// absolute values; [`ComplianceOperator::apply_single`]).
///
/// [`ComplianceOperator::apply_single`]: crate::kernel::ComplianceOperator
#[derive(Clone, Copy, Default)]
pub(super) struct Arithmetic {
    /// The search direction's scale, single precision only.
    pub(super) direction: Option<f64>,
    /// The scale of the step's change of the pressure (or its clamping
    /// correction), single precision only.
    pub(super) change: Option<f64>,
}
