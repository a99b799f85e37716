//! Non-adhesive contact by constrained conjugate gradients (Polonsky & Keer
//! 1999, Wear 231, 206-219).

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::{check_finite, ContactSolver, IterationInfo, Observer, Solution, WarmStart};

/// Iterations between full recomputations of `u = K p`.
const REFRESH: usize = 50;

/// Which quantity a non-adhesive solve prescribes.
#[derive(Clone, Copy)]
enum Control {
    Depth(f64),
    Force(f64),
}

impl ContactSolver {
    /// Non-adhesive contact at `depth` (m): pressures `p >= 0`, zero gap
    /// where `p > 0`, non-negative gap elsewhere.
    ///
    /// A depth at which the indenter does not yet touch gives a solution
    /// without contact (force 0). `warm` starts the iteration from a previous
    /// solution (any depth) on the same grid.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth or an indenter
    /// height that is NaN; [`Error::IndenterOutsideGrid`] if the indenter
    /// reaches no cell; [`Error::ShapeMismatch`] for a warm start from another
    /// grid; [`Error::NoConvergence`] if the tolerance is not reached within
    /// the iteration limit.
    pub fn solve_depth<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        check_finite("depth", depth)?;
        self.check_warm_start(warm)?;
        let lowest = self.sample_profile(indenter)?;
        if depth <= lowest {
            return Ok(self.no_contact(depth));
        }
        self.constrained_cg(Control::Depth(depth), warm, observer)
    }

    /// Non-adhesive contact under total force `force` (N, `>= 0`); the depth
    /// is part of the solution. Zero force gives the first-contact depth and
    /// no contact.
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth`], and [`Error::InvalidParameter`] for
    /// a negative force (a non-adhesive contact cannot pull).
    pub fn solve_force<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        force: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        let force = crate::error::non_negative_finite("force", force)?;
        self.check_warm_start(warm)?;
        let lowest = self.sample_profile(indenter)?;
        if force == 0.0 {
            return Ok(self.no_contact(lowest));
        }
        self.constrained_cg(Control::Force(force), warm, observer)
    }

    fn constrained_cg(
        &mut self,
        control: Control,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        let n = self.grid().len();
        let area = self.grid().cell_area();
        let reachable = self.reachable();
        let self_coefficient = self.self_compliance()?;
        let mut pressure = self.initial_pressure(control, warm, &reachable, self_coefficient);
        if let Control::Force(w) = control {
            let total = area * pressure.iter().sum::<f64>();
            rescale(&mut pressure, w / total);
        }
        let tolerance = self.params.tolerance;
        let (mut delta, mut g_old) = (0.0, 1.0);
        self.workspace.direction.fill(0.0);
        let mut depth = match control {
            Control::Depth(d) => d,
            Control::Force(_) => 0.0,
        };
        let mut residual = f64::INFINITY;
        // u = K p is kept up to date incrementally: one operator application
        // per iteration (K t), plus one only when clamping or new overlap
        // changed the pressure off the search direction, and a full refresh
        // every REFRESH iterations against drift.
        self.operator
            .apply(&pressure, &mut self.workspace.displacement)?;
        for iteration in 1..=self.params.max_iterations {
            let ws = &mut self.workspace;
            if iteration % REFRESH == 0 {
                self.operator.apply(&pressure, &mut ws.displacement)?;
            }
            // Gap (up to the unknown depth under force control).
            let reference = match control {
                Control::Depth(d) => d,
                Control::Force(_) => 0.0,
            };
            let mut contact = 0usize;
            let (mut gap_sum, mut g_norm) = (0.0, 0.0);
            for c in 0..n {
                ws.gap[c] = if reachable[c] {
                    ws.profile[c] - reference + ws.displacement[c]
                } else {
                    0.0
                };
                if pressure[c] > 0.0 {
                    contact += 1;
                    gap_sum += ws.gap[c];
                    g_norm += ws.gap[c] * ws.gap[c];
                }
            }
            if contact == 0 {
                // Every pressure was clamped: restart from the overlap.
                for c in 0..n {
                    if reachable[c] && ws.gap[c] < 0.0 {
                        pressure[c] = -ws.gap[c] / self_coefficient;
                    }
                }
                delta = 0.0;
                self.operator.apply(&pressure, &mut ws.displacement)?;
                continue;
            }
            super::all_finite(
                "constrained conjugate gradients (the depth, heights or force \
                 overflow f64 at these moduli and cell sizes)",
                &[g_norm, gap_sum],
            )?;
            if let Control::Force(_) = control {
                // Gaps relative to the mean over the contact (the depth);
                // the norm is recomputed, not corrected, to avoid cancellation.
                depth = gap_sum / contact as f64;
                g_norm = 0.0;
                for c in 0..n {
                    if reachable[c] {
                        ws.gap[c] -= depth;
                    }
                    if pressure[c] > 0.0 {
                        g_norm += ws.gap[c] * ws.gap[c];
                    }
                }
            }
            // Conjugation; a zero previous norm (every gap closed exactly)
            // restarts from steepest descent instead of making 0/0 = NaN.
            let beta = if g_old > 0.0 {
                delta * (g_norm / g_old)
            } else {
                0.0
            };
            for c in 0..n {
                ws.direction[c] = if pressure[c] > 0.0 {
                    ws.gap[c] + beta * ws.direction[c]
                } else {
                    0.0
                };
            }
            g_old = g_norm;
            self.operator.apply(&ws.direction, &mut ws.response)?;
            let mut mean = 0.0;
            if let Control::Force(_) = control {
                mean = (0..n)
                    .filter(|&c| pressure[c] > 0.0)
                    .map(|c| ws.response[c])
                    .sum::<f64>()
                    / contact as f64;
                for r in ws.response.iter_mut() {
                    *r -= mean;
                }
            }
            let (mut numerator, mut denominator) = (0.0, 0.0);
            for c in 0..n {
                if pressure[c] > 0.0 {
                    numerator += ws.gap[c] * ws.direction[c];
                    denominator += ws.response[c] * ws.direction[c];
                }
            }
            let step = if denominator > 0.0 {
                numerator / denominator
            } else {
                0.0
            };
            // One pass: step along the direction, clamp at zero, add new
            // overlap (Polonsky & Keer's steps 7-9), and keep u = K p up to
            // date: u += -step K t now, + K (correction) below, the
            // correction being what clamping and overlap added to
            // p - step t (`gap` holds it once read).
            let mut overlap = false;
            let mut corrected = false;
            let (mut change, mut size, mut contact_cells) = (0.0, 0.0, 0usize);
            let force_control = matches!(control, Control::Force(_));
            if force_control {
                ws.previous.copy_from_slice(&pressure);
            }
            for c in 0..n {
                let old = pressure[c];
                let stepped = old - step * ws.direction[c];
                let mut new = if old > 0.0 { stepped.max(0.0) } else { 0.0 };
                if reachable[c] && new == 0.0 && ws.gap[c] < 0.0 {
                    new = -step.max(0.0) * ws.gap[c];
                    if new <= 0.0 {
                        new = -ws.gap[c] / self_coefficient;
                    }
                    overlap = true;
                }
                pressure[c] = new;
                ws.displacement[c] -= step * (ws.response[c] + mean);
                ws.gap[c] = new - stepped;
                corrected |= ws.gap[c] != 0.0;
                change += (new - old).abs();
                size += new;
                contact_cells += usize::from(new > 0.0);
            }
            delta = if overlap { 0.0 } else { 1.0 };
            if corrected {
                self.operator.apply(&ws.gap, &mut ws.response)?;
                for (u, k) in ws.displacement.iter_mut().zip(&ws.response) {
                    *u += k;
                }
            }
            if let Control::Force(w) = control {
                let total = area * size;
                if total > 0.0 {
                    rescale(&mut pressure, w / total);
                    rescale(&mut ws.displacement, w / total);
                }
                change = pressure
                    .iter()
                    .zip(&ws.previous)
                    .map(|(a, b)| (a - b).abs())
                    .sum();
                size = pressure.iter().sum();
            }
            residual = if size > 0.0 {
                change / size
            } else {
                f64::INFINITY
            };
            observer.observe(&IterationInfo {
                iteration,
                residual,
                contact_cells,
            });
            if residual <= tolerance && !overlap {
                // Final displacement and depth for the converged pressure.
                self.operator
                    .apply(&pressure, &mut self.workspace.displacement)?;
                if let Control::Force(_) = control {
                    let ws = &self.workspace;
                    let (sum, count) = (0..n)
                        .filter(|&c| pressure[c] > 0.0)
                        .fold((0.0, 0usize), |(s, k), c| {
                            (s + ws.profile[c] + ws.displacement[c], k + 1)
                        });
                    depth = sum / count.max(1) as f64;
                }
                let solution = self.solution(&pressure, depth, iteration, residual, None);
                super::check_solution(&solution)?;
                if matches!(control, Control::Depth(_))
                    && solution.contact_cells == n
                    && !self.operator.uniform_mode_bounded()
                {
                    // Periodic grid in full contact: the mean pressure is
                    // undetermined by the depth (infinite compliance of the
                    // uniform mode).
                    return Err(Error::Unsupported {
                        feature: "full contact under depth control on a periodic grid \
                                  without a rigid base",
                        reason: "the mean pressure is undetermined (the uniform mode's \
                                 compliance is infinite); prescribe the force (solve_force)",
                    });
                }
                let attached = pressure.iter().map(|p| *p > 0.0).collect();
                return Ok((solution, WarmStart { pressure, attached }));
            }
        }
        Err(Error::NoConvergence {
            method: "constrained conjugate gradients (Polonsky-Keer)",
            iterations: self.params.max_iterations,
            residual,
        })
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

    /// A starting pressure: the warm start where it has contact, else the
    /// overlap divided by the self-compliance (or uniform, for force control).
    fn initial_pressure(
        &self,
        control: Control,
        warm: Option<&WarmStart>,
        reachable: &[bool],
        self_coefficient: f64,
    ) -> Vec<f64> {
        if let Some(w) = warm {
            let p: Vec<f64> = w
                .pressure
                .iter()
                .zip(reachable)
                .map(|(p, r)| if *r { p.max(0.0) } else { 0.0 })
                .collect();
            if p.iter().any(|v| *v > 0.0) {
                return p;
            }
        }
        let profile = &self.workspace.profile;
        match control {
            Control::Depth(d) => profile
                .iter()
                .map(|f| {
                    if f.is_finite() {
                        (d - f).max(0.0) / self_coefficient
                    } else {
                        0.0
                    }
                })
                .collect(),
            Control::Force(_) => reachable
                .iter()
                .map(|r| if *r { 1.0 } else { 0.0 })
                .collect(),
        }
    }
}

fn rescale(values: &mut [f64], factor: f64) {
    for v in values {
        *v *= factor;
    }
}
