//! The pull-off of a bonded flat punch of any face, tilted or not, by the
//! local Griffith criterion: its contact peeled along the edge cells that
//! reach the work of adhesion first, each contact's critical depth and
//! force from the release rates of [`ContactSolver::edge_release`].

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::super::ContactSolver;
use super::material::{ClampedPair, EdgeForces};
use super::{EdgeFit, EDGE_WINDOW};

/// Edge cells whose release rate is at least this fraction of the largest
/// peel together in one step of [`ContactSolver::peel_punch`]. The path
/// tends to the quasi-static one as the fraction tends to one; measured
/// (`examples/punch_peel.rs`, `BENCHMARKS.md`), the square punch's pull-off
/// over `N^1.5` at 64 cells across: 455.4, 465.7, 473.3, 471.1, 473.3 uN
/// with 0.8, 0.9, 0.95, 0.98, 0.99 (94 steps at 0.98 against 68 at 0.95).
pub const PEEL_FRACTION: f64 = 0.95;

/// Fewest face cells a punch's face may have; below as many cells a path
/// may end where no edge cell is left to reach the work of adhesion.
const MIN_FACE_CELLS: usize = 16;

/// A contact of at most this fraction's inverse of the bonded cells at
/// the start (or of fewer cells than the square of [`EDGE_WINDOW`]) whose
/// edge releases nowhere ends the path (it holds at most about
/// `16^(-3/4)`, an eighth, of the start's force, by Kendall's scaling with
/// the area, and a pull-off there is refused as unresolved): the window,
/// wider than the remnant, cancels its facets. Kendall's disc at 64 cells
/// across came to 32 such cells.
const REMNANT_FRACTION: usize = 16;

/// The width (cells) of the window along the edge for a contact of
/// `cells` cells: [`EDGE_WINDOW`], or the square root of the cells across
/// it where that is wider. A digital circle of `R` cells' radius repeats
/// steps of one pattern over runs of about `sqrt(2 R)` cells, so a fixed
/// window averages ever less of them and its largest rate rises with the
/// grid. Measured on Kendall's disc (`examples/punch_peel`, five grid
/// spacings within 1 % of each other, `BENCHMARKS.md`, "Local release
/// rates along an edge"): with 8 cells at 64, 128 and 256 cells across
/// -1.0 to -0.7, -1.7 to -0.35, -2.0 to -1.05 %; with this width the
/// same at 64 and -1.0 to -0.1, -0.7 to -0.2 % at 128 and 256.
fn peel_window(cells: usize) -> f64 {
    let across = 2.0 * (cells as f64 / std::f64::consts::PI).sqrt();
    EDGE_WINDOW.max(across.sqrt())
}

/// The refusal of a contact whose edge never releases the work of
/// adhesion.
fn never_releases() -> Error {
    Error::Unsupported {
        feature: "peeling a contact whose edge never releases the work of adhesion",
        reason: "a pulled punch's edge releases energy without bound; this contact's rates do \
                 not grow as it is pulled (or it is under the window's size)",
    }
}

/// One bonded contact along a punch's peeling path, at the depth and force
/// where its first edge cell, pulled, releases the work of adhesion.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PeelPoint {
    /// Depth, m, as in [`ContactSolver::solve_depth`]: below the face's
    /// lowest height when it pulls.
    pub depth: f64,
    /// Force, N (negative: pulled).
    pub force: f64,
    /// The bonded contact's stiffness `dF/dd`, N/m: at any depth `d` it
    /// carries `force + stiffness (d - depth)`.
    pub stiffness: f64,
    /// Cells in contact.
    pub contact_cells: usize,
    /// Contact area, m^2 (the cells').
    pub contact_area: f64,
    /// The edge cell that reaches the work of adhesion first (m from the
    /// indenter's axis): where the contact peels next.
    pub peels_at: (f64, f64),
    /// How this contact's release rates were estimated: fitted by modes
    /// (the whole face of a disc or an ellipse) or smoothed by the window
    /// (contacts peeled from those, other shapes).
    pub fit: EdgeFit,
}

/// The peeling path of a bonded flat punch ([`ContactSolver::peel_punch`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PeelingPath {
    points: Vec<PeelPoint>,
    iterations: usize,
    /// Per cell, the step of the path at which it peeled (the number of
    /// points for the face's last cells, `usize::MAX` off the face).
    peeled_at: Vec<usize>,
}

impl PeelingPath {
    /// The contacts from the whole face on, each at its critical force (at
    /// least the whole face's).
    pub fn points(&self) -> &[PeelPoint] {
        &self.points
    }

    /// Conjugate-gradient iterations of the path's clamped solves.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The pull-off under force control: the most tensile critical force
    /// along the path (the punch comes off there: every contact after it
    /// peels at a smaller pull).
    pub fn pull_off(&self) -> &PeelPoint {
        &self.points[self.pull_off_index()]
    }

    /// The jump-off under displacement control: the most tensile critical
    /// depth along the path.
    pub fn jump_off(&self) -> &PeelPoint {
        &self.points[self.most(|p| p.depth)]
    }

    /// Whether the punch comes off where it starts to detach (the whole
    /// face's critical force the most tensile): Kendall's instability, as
    /// for a disc; false where peeled contacts hold more (a punch with
    /// corners).
    pub fn detaches_at_onset(&self) -> bool {
        self.pull_off_index() == 0
    }

    /// The cells in contact at point `k` of the path (row-major).
    pub(crate) fn contact(&self, k: usize) -> Vec<bool> {
        self.peeled_at
            .iter()
            .map(|&step| step != usize::MAX && step >= k)
            .collect()
    }

    /// The points a depth-controlled pull visits (each holds until its
    /// critical depth, and the next holds only if its own is deeper): the
    /// path's records of the most tensile critical depth.
    pub(crate) fn visited(&self) -> Vec<usize> {
        let mut visited: Vec<usize> = Vec::new();
        for (k, p) in self.points.iter().enumerate() {
            if visited
                .last()
                .is_none_or(|&j| p.depth < self.points[j].depth)
            {
                visited.push(k);
            }
        }
        visited
    }

    /// Refuses a path whose pull-off or least force under depth control
    /// is held by a remnant of less than `1 / REMNANT_FRACTION` of the
    /// cells bonded at the start, or of fewer cells than the square of
    /// [`EDGE_WINDOW`] (its rates then average its whole edge): a steeply
    /// tilted face pressed in part comes off at a sliver by its rim, whose
    /// force is the grid's, not the punch's. A disc of 1 mm tilted by 0.05
    /// rad, pressed to 0.4 of its rise, on rubber (the equal-area
    /// staircase): -19, -4.9, -8.8 mN at 16, 32, 64 cells across from
    /// remnants of 32 cells and 1 to 4 % of the start, -5.0 mN at 128 from
    /// 12 %.
    fn resolved(&self) -> Result<()> {
        let Some(first) = self.points.first() else {
            return Err(never_releases());
        };
        let start = first.contact_cells;
        let least_visited = self
            .visited()
            .into_iter()
            .min_by(|&a, &b| self.points[a].force.total_cmp(&self.points[b].force))
            .unwrap_or(0);
        let extremes = [self.pull_off_index(), least_visited];
        if extremes.iter().any(|&k| {
            let cells = self.points[k].contact_cells;
            cells * REMNANT_FRACTION < start || (cells as f64) < EDGE_WINDOW * EDGE_WINDOW
        }) {
            return Err(Error::Unsupported {
                feature: "a punch's pull-off at a contact the grid hardly resolves",
                reason: "the peeling path's most tensile force is held by a remnant of \
                         less than a sixteenth of the cells bonded at the start or of fewer than \
                         64 cells (a face pressed in part, coming off at a sliver by its rim): \
                         refine the grid",
            });
        }
        Ok(())
    }

    /// The index of the point [`pull_off`](Self::pull_off) returns.
    pub(crate) fn pull_off_index(&self) -> usize {
        self.most(|p| p.force)
    }

    /// The index of the first point of least `key` (`peel_punch` returns
    /// at least the whole face's point).
    fn most(&self, key: impl Fn(&PeelPoint) -> f64) -> usize {
        let mut best = 0;
        for (k, p) in self.points.iter().enumerate().skip(1) {
            if key(p) < key(&self.points[best]) {
                best = k;
            }
        }
        best
    }
}

impl ContactSolver {
    /// The peeling path of a flat punch bonded over its whole face (the
    /// cells the indenter reaches, inside the grid: its face ends at a rim,
    /// so that the contact is pinned there; the face may be tilted). For
    /// each contact the two clamped solves of the energy balance (a unit
    /// depth and the face's heights) give every edge cell's release rate as
    /// a quadratic in the depth ([`edge_release`](Self::edge_release)'s
    /// rates); the contact holds until the first edge cell, pulled, releases
    /// the (receding) `work_of_adhesion`, J/m^2: that depth and its force
    /// are the contact's critical ones. The edge cells then releasing at
    /// least [`PEEL_FRACTION`] of it peel, until fewer than four cells are
    /// left. Under force control the punch comes off at the most tensile of
    /// those forces ([`PeelingPath::pull_off`]): at once for a disc
    /// (Kendall 1971, J. Phys. D 4, 1186), later for a face with corners,
    /// where it starts to detach at a force that falls with the cell
    /// (`doc::adhesion`, "The local criterion"). The path assumes the face
    /// bonded whole when the pull starts (a punch pressed into full
    /// contact). Two clamped solves a step.
    ///
    /// ```
    /// use layered_contact::indenter::FlatPunch;
    /// use layered_contact::solver::{ContactSolver, SolverParams};
    /// use layered_contact::{Boundary, Grid, Material, Substrate};
    ///
    /// let rubber = Material::new(1e6, 0.48)?;
    /// let grid = Grid::square_of_side(32, 3.2e-3)?;
    /// let body = Substrate::half_space(rubber);
    /// let mut solver =
    ///     ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default())?;
    /// let punch = FlatPunch::new(1e-3)?;
    /// let path = solver.peel_punch(&punch, 0.05)?;
    /// // A disc comes off where it starts to detach, near Kendall's force.
    /// assert!(path.detaches_at_onset());
    /// let kendall = (8.0 * std::f64::consts::PI * rubber.contact_modulus() * 0.05 * 1e-9).sqrt();
    /// assert!((path.pull_off().force / -kendall - 1.0).abs() < 0.05);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a work of adhesion that is not
    /// positive and finite, or a face of fewer than 16 cells;
    /// [`Error::Unsupported`] for an indenter that reaches the grid's outer
    /// ring or every cell of a periodic grid (no rim: a sphere, a cone, a
    /// face with a sloping shoulder) or a contact whose edge never releases
    /// the work of adhesion; [`Error::NoConvergence`] from the clamped
    /// solves.
    pub fn peel_punch<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        work_of_adhesion: f64,
    ) -> Result<PeelingPath> {
        self.peel(indenter, work_of_adhesion, None)
    }

    /// The peeling path of a flat punch from `bonded` (row-major cells, a
    /// part of its face): [`peel_punch`](Self::peel_punch) from a punch
    /// bonded only in part, such as a tilted face pressed in to where its
    /// contact reaches the rim on one side and ends at a front on the face
    /// elsewhere (a scene's cohesive-zone loading, whose peak is the
    /// start). Edge cells on the face peel by the same local criterion as
    /// those at the rim (the release rates of
    /// [`edge_release`](Self::edge_release) hold at any edge); none
    /// advances, as none does while a punch is pulled.
    ///
    /// ```
    /// use layered_contact::indenter::FlatPunch;
    /// use layered_contact::solver::{ContactSolver, SolverParams};
    /// use layered_contact::{Boundary, Grid, Material, Substrate};
    ///
    /// let rubber = Material::new(1e6, 0.48)?;
    /// let grid = Grid::square_of_side(32, 3.2e-3)?;
    /// let body = Substrate::half_space(rubber);
    /// let mut solver =
    ///     ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default())?;
    /// let punch = FlatPunch::new(1e-3)?;
    /// let whole = solver.peel_punch(&punch, 0.05)?;
    /// // From the face bonded whole, the same path.
    /// let face: Vec<bool> = (0..grid.len())
    ///     .map(|c| {
    ///         let (x, y) = grid.cell_centre(c / 32, c % 32);
    ///         x.hypot(y) < 1e-3
    ///     })
    ///     .collect();
    /// let from = solver.peel_punch_from(&punch, 0.05, &face)?;
    /// assert_eq!(from.pull_off().force, whole.pull_off().force);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`peel_punch`](Self::peel_punch), the 16 cells counted in
    /// `bonded`; [`Error::ShapeMismatch`] for `bonded` not of the grid's
    /// length; [`Error::InvalidParameter`] for a bonded cell off the face.
    pub fn peel_punch_from<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        work_of_adhesion: f64,
        bonded: &[bool],
    ) -> Result<PeelingPath> {
        self.peel(indenter, work_of_adhesion, Some(bonded))
    }

    /// [`peel_punch`](Self::peel_punch) from `bonded`, or from the whole
    /// face.
    fn peel<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        work_of_adhesion: f64,
        bonded: Option<&[bool]>,
    ) -> Result<PeelingPath> {
        self.serial_only("peel punch")?;
        let work = crate::error::positive_finite("work_of_adhesion", work_of_adhesion)?;
        let lowest = self.sample_profile(indenter)?;
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let (spacing, area) = (grid.spacing(), grid.cell_area());
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        let n = grid.len();
        let on_face: Vec<bool> = self
            .workspace
            .profile
            .iter()
            .map(|h| h.is_finite())
            .collect();
        let mut attached = match bonded {
            None => on_face.clone(),
            Some(b) if b.len() != n => {
                return Err(Error::ShapeMismatch {
                    field: "bonded cells",
                    expected: n,
                    found: b.len(),
                })
            }
            Some(b) => {
                if let Some(off) = (0..n).find(|&c| b[c] && !on_face[c]) {
                    return Err(Error::InvalidParameter {
                        name: "bonded cell off the punch's face",
                        value: off as f64,
                        expected: "bonded cells on the face (cells the indenter reaches)",
                    });
                }
                b.to_vec()
            }
        };
        let face = attached.iter().filter(|a| **a).count();
        if face < MIN_FACE_CELLS {
            return Err(Error::InvalidParameter {
                name: "punch face cells",
                value: face as f64,
                expected: "at least 16 cells that the indenter reaches (its face) bonded",
            });
        }
        let rimless = if periodic {
            on_face.iter().all(|f| *f)
        } else {
            (0..n).any(|c| on_face[c] && super::super::on_outer_ring(c, rows, columns))
        };
        if rimless {
            return Err(Error::Unsupported {
                feature: "peeling an indenter without a rim inside the grid",
                reason: "the path starts from a punch's face bonded whole, pinned at a rim; \
                         this indenter reaches the grid's outer ring (a sphere, a cone, a face \
                         with a sloping shoulder, or a face wider than the grid)",
            });
        }
        let mut punch = vec![0.0; n];
        let mut shape = vec![0.0; n];
        let mut target = vec![0.0; n];
        let mut punch_displacement = super::super::cell_vector(n)?;
        let mut shape_displacement = super::super::cell_vector(n)?;
        let mut points = Vec::new();
        let mut iterations = 0usize;
        let mut peeled_at = vec![usize::MAX; n];
        // Each step peels at least the cell that reaches the work first.
        for _ in 0..face {
            self.check_interrupt("peeling a punch")?;
            let cells = attached.iter().filter(|a| **a).count();
            if cells < 4 {
                break;
            }
            for c in 0..n {
                if !attached[c] {
                    punch[c] = 0.0;
                    shape[c] = 0.0;
                }
            }
            let (solved, _) =
                self.solve_clamped_pair(&attached, lowest, &mut target, &mut punch, &mut shape)?;
            iterations += solved;
            self.operator.apply(&punch, &mut punch_displacement)?;
            self.operator.apply(&shape, &mut shape_displacement)?;
            let pair = ClampedPair {
                attached: &attached,
                profile: &self.workspace.profile,
                lowest,
                punch: &punch,
                punch_displacement: &punch_displacement,
                shape: &shape,
                shape_displacement: &shape_displacement,
            };
            let forces = EdgeForces::new(
                &pair,
                rows,
                columns,
                spacing,
                periodic,
                matches!(self.substrate, crate::Substrate::HalfSpace(_)),
            );
            let (rates, fit) = forces.smoothed(spacing, peel_window(cells));
            // The first edge cell to release the work as the depth falls.
            let first = rates
                .iter()
                .enumerate()
                .filter_map(|(k, r)| r.critical_depth(work).map(|d| (k, d)))
                .max_by(|a, b| a.1.total_cmp(&b.1));
            let Some((top, depth)) = first else {
                let remnant =
                    cells * REMNANT_FRACTION <= face || (cells as f64) < EDGE_WINDOW * EDGE_WINDOW;
                if cells < MIN_FACE_CELLS || remnant {
                    // The last few cells, whose facets cancel (a block of
                    // two by two has no edge direction), or a remnant
                    // narrower than the window, too small to hold a
                    // resolved pull-off (`PeelingPath::resolved`): they
                    // come off with the path's end.
                    break;
                }
                return Err(never_releases());
            };
            let (stiffness, shape_force) = (0..n)
                .filter(|&c| attached[c])
                .fold((0.0, 0.0), |(k, f), c| {
                    (k + punch[c] * area, f + shape[c] * area)
                });
            let (i, j) = (forces.cells[top] / columns, forces.cells[top] % columns);
            points.push(PeelPoint {
                depth: lowest + depth,
                force: stiffness * depth - shape_force,
                stiffness,
                contact_cells: cells,
                contact_area: cells as f64 * area,
                peels_at: grid.cell_centre(i, j),
                fit,
            });
            let threshold = PEEL_FRACTION * work;
            let step = points.len() - 1;
            for (&c, rate) in forces.cells.iter().zip(&rates) {
                if rate.at(depth) >= threshold && rate.edge_pressure(depth) < 0.0 {
                    attached[c] = false;
                    peeled_at[c] = step;
                }
            }
            attached[forces.cells[top]] = false;
            peeled_at[forces.cells[top]] = step;
        }
        for (at, &stays) in peeled_at.iter_mut().zip(&attached) {
            if stays {
                *at = points.len();
            }
        }
        let values: Vec<f64> = points
            .iter()
            .flat_map(|p| [p.force, p.depth, p.stiffness])
            .collect();
        crate::solver::all_finite("peeling path", &values)?;
        if points.is_empty() {
            // A bonded set under the window's size whose facets cancel at
            // the start: no edge cell ever released.
            return Err(never_releases());
        }
        let path = PeelingPath {
            points,
            iterations,
            peeled_at,
        };
        path.resolved()?;
        Ok(path)
    }

    /// The pressures, contact and fields of `attached` (row-major cells)
    /// held bonded to `indenter` at `depth`: one clamped solve (none
    /// without a cell).
    pub(crate) fn clamped_solution<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        attached: &[bool],
    ) -> Result<super::super::Solution> {
        crate::solver::check_finite("depth", depth)?;
        self.sample_profile(indenter)?;
        let n = self.grid().len();
        let mut pressure = vec![0.0; n];
        let (iterations, residual) = if attached.iter().any(|a| *a) {
            self.clamped_solve(depth, attached, &mut pressure)?
        } else {
            self.workspace.displacement.fill(0.0);
            (0, 0.0)
        };
        let solution = self.solution(&pressure, depth, iterations, residual, Some(attached));
        crate::solver::check_solution(&solution)?;
        Ok(solution)
    }
}
