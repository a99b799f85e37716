//! Adhesive contact in the JKR limit with the mesh-dependent detachment
//! criterion (Pohrt & Popov 2015).

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::{check_finite, ContactSolver, IterationInfo, Observer, Solution, WarmStart};

/// How far beyond `sigma_c K(0,0)` a gap may be for a cell next to the
/// contact to be tried: the near-tip gap of a crack at the critical stress
/// intensity is about `sigma_c K(0,0)` one cell from the tip and grows like
/// the square root of the distance, so the filter is loose and the solve
/// that follows decides.
const REACH_FACTOR: f64 = 4.0;

/// The least ratio of the body's `E*` at wavelengths up to
/// [`MESH_SCALE_CELLS`] cells to its surface's that the mesh-dependent
/// criterion accepts: its critical stress takes the surface's `E*` at the
/// cell's scale (Pohrt & Popov 2015, a half-space).
const MESH_SOFTENING: f64 = 0.95;

/// The wavelengths, in cells, over which [`MESH_SOFTENING`] is asked.
const MESH_SCALE_CELLS: f64 = 4.0;

impl ContactSolver {
    /// Refuses the mesh-dependent criterion on a body softer at the cells'
    /// scale than its surface (a stiff layer over a far softer one, under
    /// a few cells thick). On a 4.85 GPa plate 37.6 um thick over a 13.2
    /// MPa layer, 131 um cells (the cohesive reference sweep's seed 13) the
    /// criterion gave a pull-off 13.3 times the exact one, on a 1 kPa layer
    /// over a 2.7 Pa one 7.3 times; with the modulus of the wavelengths of
    /// one, two or four cells in the critical stress instead, +582, +62 and
    /// -42 % (`BENCHMARKS.md`, "The zone's modulus"): no modulus at the
    /// cell's scale stands in for the layers there.
    fn check_mesh_body(&self) -> Result<()> {
        let surface = self.surface_contact_modulus;
        let seen = super::cohesive_law::zone_modulus(
            &self.compliance,
            surface,
            MESH_SCALE_CELLS * self.grid().spacing(),
            self.substrate.top_thickness(),
        )?;
        if seen >= MESH_SOFTENING * surface {
            return Ok(());
        }
        Err(Error::InvalidParameter {
            name: "the body's E* at wavelengths of four cells over its surface's \
                   (mesh-dependent criterion)",
            value: seen / surface,
            expected: "at least 0.95: the criterion of Pohrt & Popov (2015) takes the surface's \
                       E* at the cell's scale, and on a body this much softer there its forces \
                       are off by up to orders of magnitude; refine the grid (cells thinner \
                       than the top layer) or use the energy balance or the cohesive zone",
        })
    }

    /// Adhesive contact at `depth` (m) with one work of adhesion
    /// `work_of_adhesion` (J/m^2) for advancing and receding contact: the
    /// JKR limit (Johnson, Kendall & Roberts 1971; the cell criterion of Pohrt
    /// & Popov 2015). See
    /// [`solve_depth_hysteretic`](Self::solve_depth_hysteretic).
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth_hysteretic`].
    pub fn solve_depth_adhesive<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        work_of_adhesion: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        self.serial_only("solve depth adhesive")?;
        let work = crate::error::non_negative_finite("work_of_adhesion", work_of_adhesion)?;
        self.solve_depth_hysteretic(indenter, depth, work, work, warm, observer)
    }

    /// Adhesive contact at `depth` (m) in the JKR limit with adhesion
    /// hysteresis: the contact edge advances while the energy release rate is
    /// below `advancing` (`dgamma0`, J/m^2) and recedes where it exceeds
    /// `receding` (`dgamma1 >= dgamma0`), through the mesh-dependent critical
    /// stress `sqrt(E1* dgamma / (0.473201 Delta))` of each
    /// ([`critical_stress`](Self::critical_stress); Pohrt & Popov 2015).
    ///
    /// The set of attached cells evolves from the warm start's (the history).
    /// On each attached set the displacement is prescribed (`u = d - f`) and
    /// the pressures follow from a preconditioned conjugate-gradient solve;
    /// then
    ///
    /// * cells over the receding critical tension that are connected to the
    ///   contact edge through such cells detach (tension inside the contact
    ///   never nucleates a crack in the JKR limit), and stay detached for the
    ///   rest of this call;
    /// * cells the indenter penetrates attach, and, while nothing has
    ///   detached in this call (an edge that recedes does not also advance),
    ///   so, tentatively, do cells next to the contact whose gap is below
    ///   `sigma_c(advancing) K(0,0)` (a cell with a larger gap would carry
    ///   more than the advancing critical tension once attached); after the
    ///   next solve, tentative cells over the advancing critical tension are
    ///   let go again, so the edge moves out only as far as it holds;
    ///
    /// until nothing changes. With zero work of adhesion this is the
    /// non-adhesive contact. When every cell has detached the contact is
    /// lost: the solution has no contact and force 0.
    ///
    /// # Errors
    /// As [`ContactSolver::solve_depth`], and [`Error::InvalidParameter`]
    /// for a negative or non-finite work of adhesion or `advancing >
    /// receding`, or for a body softer at wavelengths of four cells than
    /// its surface by more than 5 % (a stiff layer over a far softer one,
    /// a few cells thick), where the criterion's critical stress does not
    /// hold.
    pub fn solve_depth_hysteretic<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        advancing: f64,
        receding: f64,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        self.serial_only("solve depth hysteretic")?;
        check_finite("depth", depth)?;
        let (advancing, receding) = crate::error::works_of_adhesion(advancing, receding)?;
        self.check_warm_start(warm)?;
        self.check_mesh_body()?;
        self.sample_profile(indenter)?;
        let sigma_c = self.critical_stress(receding);
        let sigma_advancing = self.critical_stress(advancing);
        // A gap below this, next to the contact, may close and still hold.
        let reach = REACH_FACTOR * sigma_advancing * self.self_compliance()?;
        let n = self.grid().len();
        let columns = self.grid().columns();
        let reachable = self.reachable();
        // The history's attached cells, and the cells within half the depth
        // of the indenter's lowest point (Hertz: the contact reaches f = d/2),
        // from which the contact grows by penetration and advance (starting
        // with every geometrically overlapping cell would make it recede).
        let lowest = self
            .workspace
            .profile
            .iter()
            .cloned()
            .fold(f64::INFINITY, f64::min);
        let mut attached: Vec<bool> = (0..n)
            .map(|c| {
                let f = self.workspace.profile[c];
                reachable[c]
                    && (warm.is_some_and(|w| w.attached[c]) || f - lowest < 0.5 * (depth - lowest))
            })
            .collect();
        let mut pressure: Vec<f64> = match warm {
            Some(w) => (0..n)
                .map(|c| if attached[c] { w.pressure[c] } else { 0.0 })
                .collect(),
            None => vec![0.0; n],
        };
        let mut released = vec![false; n];
        let mut tentative = vec![false; n];
        let mut total_iterations = 0;
        let mut residual = 0.0;
        // Each round removes or adds at least one cell of a finite set, so
        // `4 n` rounds bound any sequence that does not cycle.
        for round in 1..=(4 * n + 4) {
            self.check_interrupt("the mesh-dependent criterion's rounds")?;
            if !attached.contains(&true) {
                return Ok(self.no_contact(depth));
            }
            let (iterations, r) = self.clamped_solve(depth, &attached, &mut pressure)?;
            total_iterations += iterations;
            residual = r;
            // Displacement of the converged pressure is in the workspace.
            // Cells the edge advanced onto in the last round stay only if
            // they hold against the advancing criterion; if any is let go,
            // solve again before judging the rest.
            let mut reverted = 0usize;
            for c in 0..n {
                if std::mem::take(&mut tentative[c]) && pressure[c] < -sigma_advancing {
                    attached[c] = false;
                    pressure[c] = 0.0;
                    released[c] = true;
                    reverted += 1;
                }
            }
            if reverted > 0 {
                observer.observe(&IterationInfo {
                    iteration: round,
                    residual,
                    contact_cells: attached.iter().filter(|a| **a).count(),
                });
                continue;
            }
            // Only cells connected to the boundary of the contact through
            // cells over the critical stress detach: the criterion stands for a
            // crack at the contact edge (Pohrt & Popov 2015); tension inside the
            // contact never nucleates one in the JKR limit.
            let detach = edge_connected(&attached, columns, |c| pressure[c] < -sigma_c);
            let ws = &self.workspace;
            let mut changed = detach.len();
            for c in detach {
                attached[c] = false;
                pressure[c] = 0.0;
                released[c] = true;
            }
            let before = attached.clone();
            for c in 0..n {
                // A cell released in this step stays released: the collocated
                // surface of a small ring of cells in tension can overshoot the
                // indenter, which would re-attach it and cycle.
                if attached[c] || released[c] || !reachable[c] {
                    continue;
                }
                let gap = ws.profile[c] - depth + ws.displacement[c];
                if gap < 0.0 {
                    attached[c] = true;
                    changed += 1;
                } else if gap <= reach && next_to(&before, columns, c) {
                    attached[c] = true;
                    tentative[c] = true;
                    changed += 1;
                }
            }
            observer.observe(&IterationInfo {
                iteration: round,
                residual,
                contact_cells: attached.iter().filter(|a| **a).count(),
            });
            if changed == 0 {
                let solution = self.solution(
                    &pressure,
                    depth,
                    total_iterations,
                    residual,
                    Some(&attached),
                );
                super::check_solution(&solution)?;
                return Ok((
                    solution,
                    WarmStart {
                        pressure,
                        attached,
                        contact: None,
                        withdrawn: false,
                    },
                ));
            }
        }
        Err(Error::NoConvergence {
            method: "adhesive active-set iteration",
            iterations: 4 * n + 4,
            residual,
        })
    }

    /// Preconditioned conjugate gradients for the pressures on the attached
    /// cells that give `u = depth - f` there (pressure 0 elsewhere), with the
    /// body's compliance inverted on a box around the attached set
    /// (Vollebregt 2014, as the contact solves' preconditioner) restricted
    /// to it as preconditioner. Until 2026-11-30 this was the half-space
    /// stiffness `E* |q| / 2` of the surface material on the whole padded
    /// grid: a round trip of the grid's size for every set, however small,
    /// and on a soft layer over a far stiffer base (where the body is far
    /// stiffer at long waves than its surface) more iterations
    /// (`BENCHMARKS.md`, "The family on windows of the grid"). Leaves the
    /// displacement of the result in the workspace. Returns iterations and
    /// the final relative residual.
    pub(super) fn clamped_solve(
        &mut self,
        depth: f64,
        attached: &[bool],
        pressure: &mut [f64],
    ) -> Result<(usize, f64)> {
        let mut target = std::mem::take(&mut self.workspace.target);
        if target.len() != self.workspace.profile.len() {
            // Allocated on first use: non-adhesive solves never need it.
            target = super::cell_vector(self.workspace.profile.len())?;
        }
        for (t, f) in target.iter_mut().zip(&self.workspace.profile) {
            *t = depth - f;
        }
        let result = self.clamped_cg(attached, &target, pressure);
        self.workspace.target = target;
        result
    }

    /// Preconditioned conjugate gradients for the pressures on the attached
    /// cells whose displacement there is `target` (pressure 0 elsewhere),
    /// starting from `pressure`. See [`clamped_solve`](Self::clamped_solve).
    pub(super) fn clamped_cg(
        &mut self,
        attached: &[bool],
        target: &[f64],
        pressure: &mut [f64],
    ) -> Result<(usize, f64)> {
        self.clamped_cg_with(attached, target, pressure, false)
    }

    /// [`clamped_cg`](Self::clamped_cg), preconditioned as the constrained
    /// conjugate gradients are if `two_level` (the two-level preconditioner
    /// if it is on: [`ContactSolver::set_coarse_blocks`]), else by the box.
    pub(super) fn clamped_cg_with(
        &mut self,
        attached: &[bool],
        target: &[f64],
        pressure: &mut [f64],
        two_level: bool,
    ) -> Result<(usize, f64)> {
        let n = pressure.len();
        let tolerance = self.params.tolerance;
        let ws = &mut self.workspace;
        // `gap` holds the residual r = b - K p on the attached set,
        // `response` the preconditioned residual z (the box inverse on the
        // attached set, the working set) and then K t, `direction` the
        // search direction t.
        self.operator.apply(pressure, &mut ws.displacement)?;
        let mut b_norm = 0.0;
        let mut r_norm = 0.0;
        // The residual's largest magnitude, for the single-precision box.
        let mut gap_max = 0.0f64;
        for c in 0..n {
            if attached[c] {
                let b = target[c];
                b_norm += b * b;
                ws.gap[c] = b - ws.displacement[c];
                r_norm += ws.gap[c] * ws.gap[c];
                gap_max = gap_max.max(ws.gap[c].abs());
            } else {
                ws.gap[c] = 0.0;
            }
        }
        // On a split solver (the active-set loops of a split
        // non-adhesive solve) sums and bounds are taken over every rank.
        let mut norms = [b_norm, r_norm];
        self.sum_over_ranks(&mut norms);
        let [b_norm, mut r_norm] = norms;
        super::all_finite(
            "clamped solve (prescribed displacements or their norm overflow)",
            &[b_norm, r_norm],
        )?;
        let b_norm = b_norm.sqrt().max(f64::MIN_POSITIVE);
        self.workspace.working.copy_from_slice(attached);
        let columns = self.grid().columns();
        let set = attached.iter().enumerate().filter(|(_, on)| **on);
        let bounds = super::passes::bounds_of(set.map(|(c, _)| c), columns);
        let (bounds, gap_max) = self.whole_bounds(bounds, gap_max);
        let mut rz = self.precondition_step(bounds, 0.0, gap_max, two_level)?.1;
        rz = self.summed(rz);
        let ws = &mut self.workspace;
        // Only the attached cells of the box's `response` are read.
        for ((d, &z), &on) in ws.direction.iter_mut().zip(&ws.response).zip(attached) {
            *d = if on { z } else { 0.0 };
        }
        let mut iterations = 0;
        while r_norm.sqrt() > tolerance * b_norm {
            self.check_interrupt("the conjugate gradients on the attached cells")?;
            if iterations == self.params.max_iterations {
                return Err(Error::NoConvergence {
                    method: "conjugate gradients on the attached cells",
                    iterations,
                    residual: r_norm.sqrt() / b_norm,
                });
            }
            iterations += 1;
            let ws = &mut self.workspace;
            self.operator.apply(&ws.direction, &mut ws.response)?;
            let mut curvature = 0.0;
            for c in 0..n {
                if attached[c] {
                    curvature += ws.direction[c] * ws.response[c];
                }
            }
            let curvature = self.summed(curvature);
            if curvature.is_nan() || rz.is_nan() || curvature <= 0.0 || rz <= 0.0 {
                break;
            }
            let step = rz / curvature;
            r_norm = 0.0;
            let mut gap_max = 0.0f64;
            let ws = &mut self.workspace;
            for c in 0..n {
                if attached[c] {
                    pressure[c] += step * ws.direction[c];
                    ws.gap[c] -= step * ws.response[c];
                    r_norm += ws.gap[c] * ws.gap[c];
                    gap_max = gap_max.max(ws.gap[c].abs());
                }
            }
            r_norm = self.summed(r_norm);
            let gap_max = self.max_over_ranks(gap_max);
            let rz_new = self.precondition_step(bounds, 0.0, gap_max, two_level)?.1;
            let rz_new = self.summed(rz_new);
            let beta = rz_new / rz;
            rz = rz_new;
            let ws = &mut self.workspace;
            for c in 0..n {
                ws.direction[c] = if attached[c] {
                    ws.response[c] + beta * ws.direction[c]
                } else {
                    0.0
                };
            }
        }
        let ws = &mut self.workspace;
        self.operator.apply(pressure, &mut ws.displacement)?;
        Ok((iterations, r_norm.sqrt() / b_norm))
    }
}

/// Whether cell `c` has an attached 4-neighbour.
fn next_to(attached: &[bool], columns: usize, c: usize) -> bool {
    let rows = attached.len() / columns;
    let (i, j) = (c / columns, c % columns);
    (i > 0 && attached[c - columns])
        || (i + 1 < rows && attached[c + columns])
        || (j > 0 && attached[c - 1])
        || (j + 1 < columns && attached[c + 1])
}

/// Whether attached cell `c` has a detached (or missing) 4-neighbour.
fn on_boundary(attached: &[bool], columns: usize, c: usize) -> bool {
    super::on_outer_ring(c, attached.len() / columns, columns)
        || !attached[c - columns]
        || !attached[c + columns]
        || !attached[c - 1]
        || !attached[c + 1]
}

/// The attached cells satisfying `violates` that are 4-connected, through
/// such cells, to a boundary cell of the attached set.
fn edge_connected(
    attached: &[bool],
    columns: usize,
    violates: impl Fn(usize) -> bool,
) -> Vec<usize> {
    let n = attached.len();
    let mut marked = vec![false; n];
    let mut stack: Vec<usize> = (0..n)
        .filter(|&c| attached[c] && violates(c) && on_boundary(attached, columns, c))
        .collect();
    for &c in &stack {
        marked[c] = true;
    }
    let mut found = Vec::new();
    while let Some(c) = stack.pop() {
        found.push(c);
        for m in super::neighbours(c, n / columns, columns)
            .into_iter()
            .flatten()
        {
            if attached[m] && !marked[m] && violates(m) {
                marked[m] = true;
                stack.push(m);
            }
        }
    }
    found
}
