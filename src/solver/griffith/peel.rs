//! The pull-off of a bonded flat punch of any face by the local Griffith
//! criterion: its contact peeled along the edge cells of largest release
//! rate, each contact's critical force from
//! [`ContactSolver::edge_release`].

use ndarray::Array2;

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::super::ContactSolver;
use super::EDGE_WINDOW;

/// Edge cells whose release rate is at least this fraction of the largest
/// peel together in one step of [`ContactSolver::peel_punch`]. The path
/// tends to the quasi-static one as the fraction tends to one; measured
/// (`examples/punch_peel.rs`, `BENCHMARKS.md`), the square punch's pull-off
/// over `N^1.5` at 64 cells across: 455.4, 465.7, 473.3, 471.1, 473.3 uN
/// with 0.8, 0.9, 0.95, 0.98, 0.99 (94 steps at 0.98 against 45 at 0.95).
pub const PEEL_FRACTION: f64 = 0.95;

/// Fewest face cells a punch's face may have.
const MIN_FACE_CELLS: usize = 16;

/// Heights within this many cell sizes of the lowest belong to the face.
const FACE_FLATNESS: f64 = 1e-9;

/// One bonded contact along a punch's peeling path, at the force where its
/// largest release rate equals the work of adhesion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeelPoint {
    /// Depth, m (negative: pulled).
    pub depth: f64,
    /// Force, N (negative: pulled).
    pub force: f64,
    /// Cells in contact.
    pub contact_cells: usize,
    /// Contact area, m^2 (the cells').
    pub contact_area: f64,
    /// Where the release rate is largest (m from the indenter's axis):
    /// where the contact peels next.
    pub peels_at: (f64, f64),
}

/// The peeling path of a bonded flat punch ([`ContactSolver::peel_punch`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PeelingPath {
    points: Vec<PeelPoint>,
    iterations: usize,
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
        self.most(|p| p.force)
    }

    /// The jump-off under displacement control: the most tensile critical
    /// depth along the path.
    pub fn jump_off(&self) -> &PeelPoint {
        self.most(|p| p.depth)
    }

    /// Whether the punch comes off where it starts to detach (the whole
    /// face's critical force the most tensile): Kendall's instability, as
    /// for a disc; false where peeled contacts hold more (a punch with
    /// corners).
    pub fn detaches_at_onset(&self) -> bool {
        std::ptr::eq(self.pull_off(), &self.points[0])
    }

    fn most(&self, key: impl Fn(&PeelPoint) -> f64) -> &PeelPoint {
        // `peel_punch` returns at least the whole face's point.
        let mut best = &self.points[0];
        for p in &self.points[1..] {
            if key(p) < key(best) {
                best = p;
            }
        }
        best
    }
}

impl ContactSolver {
    /// The peeling path of a flat punch bonded over its whole face (the
    /// cells at the indenter's lowest height, within `1e-9` of a cell;
    /// every cell beside it out of the indenter's reach, so that the contact
    /// is pinned at the rim): the largest release rate of each contact
    /// ([`edge_release`](Self::edge_release)) gives the force and depth at
    /// which it reaches the (receding) `work_of_adhesion`, J/m^2; the edge
    /// cells within [`PEEL_FRACTION`] of it then peel, until fewer than four
    /// cells are left. Under force control the punch comes off at the most
    /// tensile of those forces ([`PeelingPath::pull_off`]): at once for a
    /// disc (Kendall 1971, J. Phys. D 4, 1186), later for a face with
    /// corners, where it starts to detach at a force that falls with the
    /// cell (`doc::adhesion`, "The local criterion"). One clamped solve a
    /// step.
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
    /// [`Error::Unsupported`] for a face with cells beside it that the
    /// indenter reaches (not a punch's rim) or a contact whose edge
    /// releases no energy; [`Error::ContactReachesEdge`] for a face on the
    /// grid's outer ring; as [`edge_release`](Self::edge_release)
    /// otherwise.
    pub fn peel_punch<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        work_of_adhesion: f64,
    ) -> Result<PeelingPath> {
        let work = crate::error::positive_finite("work_of_adhesion", work_of_adhesion)?;
        let lowest = self.sample_profile(indenter)?;
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        let spacing = grid.spacing();
        let profile = &self.workspace.profile;
        let level = lowest + FACE_FLATNESS * spacing;
        let mut contact =
            Array2::from_shape_fn((rows, columns), |(i, j)| profile[i * columns + j] <= level);
        let face = contact.iter().filter(|c| **c).count();
        if face < MIN_FACE_CELLS {
            return Err(Error::InvalidParameter {
                name: "punch face cells",
                value: face as f64,
                expected: "at least 16 cells at the indenter's lowest height (a flat face)",
            });
        }
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        for ((i, j), &on_face) in contact.indexed_iter() {
            if on_face {
                continue;
            }
            let beside = neighbours(i, j, rows, columns, periodic).any(|(k, l)| contact[[k, l]]);
            if beside && profile[i * columns + j].is_finite() {
                return Err(Error::Unsupported {
                    feature: "peeling a punch whose face has cells beside it that the indenter \
                              reaches",
                    reason: "the path assumes a contact pinned at a rim; a face that meets a \
                             rounded or sloping shoulder can grow beyond it (use the cohesive \
                             zone)",
                });
            }
        }
        // Any pull: the rates scale with its square, the forces with it.
        let depth = lowest - spacing * 1e-3;
        let mut points = Vec::new();
        let mut iterations = 0usize;
        // Each step peels at least the cell of the largest rate.
        for _ in 0..face {
            self.check_interrupt("peeling a punch")?;
            let cells = contact.iter().filter(|c| **c).count();
            if cells < 4 {
                break;
            }
            let edge = self.edge_release(indenter, depth, &contact, EDGE_WINDOW)?;
            iterations += edge.iterations;
            let top =
                edge.max_release()
                    .filter(|p| p.release_rate > 0.0)
                    .ok_or(Error::Unsupported {
                        feature: "peeling a contact whose edge releases no energy",
                        reason:
                            "a pulled punch's edge always releases energy; this contact is not \
                             pulled",
                    })?;
            let scale = (work / top.release_rate).sqrt();
            points.push(PeelPoint {
                depth: lowest + (depth - lowest) * scale,
                force: edge.force * scale,
                contact_cells: cells,
                contact_area: cells as f64 * spacing * spacing,
                peels_at: top.position,
            });
            let threshold = PEEL_FRACTION * top.release_rate;
            for p in &edge.points {
                if p.release_rate >= threshold {
                    contact[[p.cell.0, p.cell.1]] = false;
                }
            }
        }
        crate::solver::all_finite(
            "peeling path forces",
            &points.iter().map(|p| p.force).collect::<Vec<_>>(),
        )?;
        Ok(PeelingPath { points, iterations })
    }
}

/// The four neighbours of cell `(i, j)` (wrapped on a periodic grid).
fn neighbours(
    i: usize,
    j: usize,
    rows: usize,
    columns: usize,
    periodic: bool,
) -> impl Iterator<Item = (usize, usize)> {
    let steps = [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)];
    steps.into_iter().filter_map(move |(di, dj)| {
        let (k, l) = (i as i64 + di, j as i64 + dj);
        if periodic {
            Some((
                k.rem_euclid(rows as i64) as usize,
                l.rem_euclid(columns as i64) as usize,
            ))
        } else if k < 0 || l < 0 || k >= rows as i64 || l >= columns as i64 {
            None
        } else {
            Some((k as usize, l as usize))
        }
    })
}
