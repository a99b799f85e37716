//! The preconditioner of the constrained conjugate gradients: the
//! compliance's inverse on a periodic box around the working set
//! (Vollebregt 2014, J. Comput. Phys. 257, 333-351).

use crate::error::Result;
use crate::grid::{fft_fast_even, Boundary};
use crate::kernel::{BoxInverse, Residual, ShareBuffer};

use super::passes::{self, Bounds};
use super::ContactSolver;

/// The box inverse in single precision (contact solves: half the bytes a
/// round trip, the same iterations and solutions; `BENCHMARKS.md`, "Speed:
/// rough contacts on large grids") or double (the cohesive zone's rounds,
/// whose fixed point follows the inner solves' last digits: in single
/// precision Johnson's sinusoid at 45 degrees took another path through
/// its pull-off and stalled in a cycle of rounds).
pub(super) enum Preconditioner {
    Single(BoxInverse<f32>),
    Double(BoxInverse<f64>),
}

impl Preconditioner {
    fn size(&self) -> (usize, usize) {
        match self {
            Preconditioner::Single(p) => p.size(),
            Preconditioner::Double(p) => p.size(),
        }
    }

    fn data(&self) -> (usize, usize) {
        match self {
            Preconditioner::Single(p) => p.data(),
            Preconditioner::Double(p) => p.data(),
        }
    }

    fn is_double(&self) -> bool {
        matches!(self, Preconditioner::Double(_))
    }

    fn apply_in(
        &mut self,
        buffer: &mut ShareBuffer,
        residual: &Residual<'_>,
        result: &mut [f64],
    ) -> Result<(f64, f64)> {
        match self {
            Preconditioner::Single(p) => p.apply_in(buffer, residual, result),
            Preconditioner::Double(p) => p.apply_in(buffer, residual, result),
        }
    }
}

impl ContactSolver {
    /// `response = P M^-1 P (gap - shift)` on the working set (`gap -
    /// shift` itself without preconditioning), `M^-1` the compliance's inverse on a periodic box
    /// around the working set ([`BoxInverse`]; the whole grid when
    /// periodic), of even sides of fast FFT lengths ([`fft_fast_even`]).
    /// The box is rebuilt only when the set outgrows it or needs less than
    /// 2/3 of its area (a rebuild costs about three applications; a box
    /// left 2.25 times too large, as before, doubled the preconditioner's
    /// share of an iteration). Returns `(sum z, sum z (gap - shift))` over
    /// the working set; `bounds` is the working set's bounding box and
    /// `gap_max` its largest absolute gap (from the gap pass).
    pub(super) fn precondition_working_set(
        &mut self,
        bounds: Option<Bounds>,
        shift: f64,
        gap_max: f64,
    ) -> Result<(f64, f64)> {
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let periodic = self.operator.boundary() == Boundary::Periodic;
        let ws = &mut self.workspace;
        if !self.params.precondition {
            for (z, g) in ws.response.iter_mut().zip(&ws.gap) {
                *z = g - shift;
            }
            return Ok(passes::sum_and_dot(&ws.working, &ws.response, &ws.response));
        }
        let Some(bounds) = bounds else {
            ws.response.fill(0.0);
            return Ok((0.0, 0.0));
        };
        // A margin of a sixteenth of the extent (at least 4 cells) keeps
        // the box's periodic images apart; the stiffness decays like 1/r^3.
        // A box that would reach past an isolated grid holds the whole grid
        // (its data) zero-padded to that size ([`BoxInverse`]).
        let side = |(lo, hi): (usize, usize), cells: usize| {
            let extent = hi - lo + 1;
            if periodic {
                cells
            } else {
                fft_fast_even(extent + 2 * (extent / 16).max(4))
            }
        };
        let needed = (side(bounds.0, rows), side(bounds.1, columns));
        let data = (needed.0.min(rows), needed.1.min(columns));
        let double = self.double_preconditioner;
        let reuse = self.preconditioner.as_ref().is_some_and(|p| {
            let (m0, m1) = p.size();
            p.is_double() == double
                && m0 >= needed.0
                && m1 >= needed.1
                && 2 * m0 * m1 <= 3 * needed.0 * needed.1
        });
        if !reuse {
            // Free the old box before building the new one.
            self.preconditioner = None;
            let (compliance, modulus) = (&self.compliance, self.surface_contact_modulus);
            let slab = self.operator.slab();
            let built = if double {
                BoxInverse::new(compliance, modulus, grid.spacing(), needed, data, slab)
                    .map(Preconditioner::Double)
            } else {
                BoxInverse::new(compliance, modulus, grid.spacing(), needed, data, slab)
                    .map(Preconditioner::Single)
            };
            self.preconditioner = Some(self.agreed(built)?);
        }
        let ws = &mut self.workspace;
        let Some(inverse) = self.preconditioner.as_mut() else {
            return Ok((0.0, 0.0));
        };
        // The box's data centred on the working set (at the grid's origin
        // when it spans the grid: periodic, or a box wider than the grid;
        // the data never exceeds the grid).
        let (m0, m1) = inverse.data();
        let start = |(lo, hi): (usize, usize), m: usize, cells: usize| {
            if m == cells {
                0
            } else {
                lo as isize - (m.saturating_sub(hi - lo + 1) / 2) as isize
            }
        };
        let origin = (start(bounds.0, m0, rows), start(bounds.1, m1, columns));
        // The box's FFT works in the compliance operator's buffer.
        self.operator.lend_buffer(|buffer| {
            let residual = Residual {
                columns,
                origin,
                member: &ws.working,
                values: &ws.gap,
                shift,
                magnitude: gap_max + shift.abs(),
                extend: !double,
            };
            inverse.apply_in(buffer, &residual, &mut ws.response)
        })
    }
}
