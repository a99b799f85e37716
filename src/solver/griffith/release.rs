//! The local Griffith criterion on a given contact: the energy release rate
//! and stress-intensity factor at every point of its edge, from the
//! material forces of `material.rs`.

use ndarray::Array2;

use crate::error::{Error, Result};
use crate::indenter::Indenter;
use crate::solver::{check_finite, ContactSolver};

use super::material::{ClampedPair, EdgeForces};

/// Default width of the Gaussian that smooths the release rate along the
/// edge, in cells: wide enough that the staircase's pattern averages out,
/// narrow next to the contacts it resolves. Measured with the local
/// quadratic fit (`tests/edge_release.rs`, `BENCHMARKS.md`): the elliptical
/// punch's onset at 64 cells across is 0.2 to 0.8 % off at 8 cells, 0.5 to
/// 0.9 % at 12 and 0.9 to 1.3 % at 16 (a wider window blurs the peak at the
/// tips); the worst edge cell of the JKR sphere's disc on the cell centres
/// is 2.5 % off at 8 cells. (Both measured before those edges were fitted
/// by their modes, [`EdgeFit::Modes`], where the window sets only the
/// normals.)
pub const EDGE_WINDOW: f64 = 8.0;
/// The widest smoothing window accepted, cells.
const MAX_WINDOW: f64 = 64.0;

/// The release rate at one cell on the edge of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct EdgePoint {
    /// The cell: row `i` and column `j` of the grid.
    pub cell: (usize, usize),
    /// The cell centre relative to the indenter's axis, m.
    pub position: (f64, f64),
    /// Outward unit normal of the (smoothed) edge.
    pub normal: (f64, f64),
    /// Energy release rate `G` (J/m^2): the elastic energy the contact
    /// would gain per unit of area if its edge advanced here at fixed
    /// depth; in the JKR limit the edge recedes where `G` exceeds the
    /// (receding) work of adhesion and advances where it falls below the
    /// advancing one.
    pub release_rate: f64,
    /// Mode-I stress-intensity factor `K = +-sqrt(2 E1* G)` (Pa m^1/2),
    /// positive where the edge pulls (tension), negative where it pushes;
    /// `E1*` is the top layer's contact modulus, since the edge singularity
    /// sees only the material around it.
    pub stress_intensity: f64,
}

/// How the release rates along an edge were estimated from the material
/// forces of its cells ([`doc::adhesion`](crate::doc::adhesion)).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum EdgeFit {
    /// Fitted over the whole edge in the `functions` smooth functions where
    /// the rate lies exactly: a digital ellipse on a half-space (or disc on
    /// any body) under a planar face (5: Galin's pressure, on a disc the
    /// angular modes 0 to 2) or a quadratic one (9). Converges at first
    /// order whatever the edge's direction, at every cell.
    Modes {
        /// 5 (planar face) or 9 (quadratic face).
        functions: usize,
    },
    /// Smoothed along the edge by a local quadratic fit over a Gaussian
    /// window of `cells`: the mean converges, but single cells on the
    /// digital edge's flat facets stray by up to about 10 % at 64 cells
    /// across, and the largest rate by about a per cent.
    Window {
        /// The window's width, cells.
        cells: f64,
    },
}

/// The edge of a contact held at a depth, with its release rates.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct EdgeRelease {
    /// Depth, m.
    pub depth: f64,
    /// Total force on the contact, N (negative when it pulls).
    pub force: f64,
    /// The edge cells (attached cells with a detached 4-neighbour).
    pub points: Vec<EdgePoint>,
    /// Conjugate-gradient iterations of the clamped solve.
    pub iterations: usize,
    /// How the rates were estimated: fitted by modes or smoothed by the
    /// window.
    pub fit: EdgeFit,
}

impl EdgeRelease {
    /// The edge point of largest release rate: where the contact starts to
    /// detach. `None` for an edge without points.
    pub fn max_release(&self) -> Option<&EdgePoint> {
        self.points
            .iter()
            .max_by(|a, b| a.release_rate.total_cmp(&b.release_rate))
    }
}

impl ContactSolver {
    /// The energy release rate along the edge of `contact` (cells held
    /// bonded to `indenter` at `depth`, `rows x columns` like
    /// [`Solution::pressure`](super::super::Solution::pressure)), smoothed
    /// along the edge over `window` cells ([`EDGE_WINDOW`] is a good
    /// default). The edge of one digital ellipse on a half-space, or disc
    /// on any body, under a planar face (a flat punch, tilted or not) or a
    /// quadratic one (a paraboloid) on an isolated grid is fitted instead
    /// in the five (nine) functions where the release rate lies exactly
    /// (Galin's pressure; on a circle the angular modes 0 to 2 (4); the
    /// window then sets only the normals; see
    /// [`doc::adhesion`](crate::doc::adhesion)).
    ///
    /// One clamped solve gives the pressures and displacements; the release
    /// rate follows from the configurational (material) forces of the edge
    /// cells (Eshelby 1951; Rice 1968, J. Appl. Mech. 35, 379), whose sum
    /// over any smooth virtual motion `V` of the edge converges to
    /// `int G V.n ds` at first order in the cell size whatever the edge's
    /// direction on the grid (see [`doc::adhesion`](crate::doc::adhesion)).
    /// On the JKR sphere's pull-off contact (fitted by its modes) the mean
    /// over the edge is off by -0.39 to -0.57 % at 64 cells across and
    /// -0.095 to -0.116 % at 256, the worst cell by 0.42 to 3.8 % and 0.17
    /// to 0.40 % (four sub-cell positions); on other contacts, smoothed by
    /// the window, single cells on the digital edge's flat facets stray by
    /// up to 10 % at 64 cells, more on larger contacts with the window
    /// fixed: see [`doc::adhesion`](crate::doc::adhesion).
    ///
    /// The JKR sphere's pull-off contact, 32 cells across, held bonded at the
    /// JKR depth of its effective radius: its edge is a digital disc under a
    /// quadratic face, fitted by nine modes, and the rate at every edge cell
    /// is within 1.5 % of `dgamma` (1.36 % measured at the worst cell;
    /// `tests/edge_release.rs`).
    ///
    /// ```
    /// use layered_contact::analytic::JkrSphere;
    /// use layered_contact::indenter::Paraboloid;
    /// use layered_contact::solver::{ContactSolver, EdgeFit, SolverParams, EDGE_SHIFT, EDGE_WINDOW};
    /// use layered_contact::{Boundary, Grid, Material, Substrate};
    ///
    /// let (rubber, radius, work) = (Material::new(1e6, 0.48)?, 0.01, 0.05);
    /// let a = JkrSphere::new(&rubber, radius, work)?.pull_off_contact_radius();
    /// let delta = 2.0 * a / 32.0;
    /// let grid = Grid::square_of_side(48, 48.0 * delta)?;
    /// let mut solver = ContactSolver::new(
    ///     &Substrate::half_space(rubber), &grid, Boundary::Isolated, SolverParams::default())?;
    /// let contact = ndarray::Array2::from_shape_fn((48, 48), |(i, j)| {
    ///     let (x, y) = grid.cell_centre(i, j);
    ///     x.hypot(y) < a
    /// });
    /// // The staircase's effective radius and the JKR depth there.
    /// let cells = contact.iter().filter(|&&c| c).count() as f64;
    /// let r = ((cells / std::f64::consts::PI).sqrt() - EDGE_SHIFT) * delta;
    /// let estar = rubber.contact_modulus();
    /// let depth = r * r / radius - (2.0 * std::f64::consts::PI * r * work / estar).sqrt();
    /// let edge = solver.edge_release(&Paraboloid::new(radius)?, depth, &contact, EDGE_WINDOW)?;
    /// assert_eq!(edge.fit, EdgeFit::Modes { functions: 9 });
    /// assert!(edge.points.iter().all(|p| (p.release_rate / work - 1.0).abs() < 0.015));
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth, a window outside
    /// `[1, 64]` cells, a mask of the wrong shape, an empty contact or one
    /// holding a cell the indenter does not reach;
    /// [`Error::ContactReachesEdge`] for a contact on the outer ring of an
    /// isolated grid; [`Error::NoConvergence`] from the clamped solve.
    pub fn edge_release<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        contact: &Array2<bool>,
        window: f64,
    ) -> Result<EdgeRelease> {
        self.serial_only("edge release")?;
        check_finite("depth", depth)?;
        crate::error::within(
            "window",
            window,
            (1.0, MAX_WINDOW),
            "between 1 and 64 cells",
        )?;
        let grid = *self.grid();
        let (rows, columns) = (grid.rows(), grid.columns());
        if contact.dim() != (rows, columns) {
            return Err(Error::InvalidParameter {
                name: "contact mask rows",
                value: contact.nrows() as f64,
                expected: "the grid's rows x columns",
            });
        }
        self.sample_profile(indenter)?;
        let attached: Vec<bool> = contact.iter().copied().collect();
        let periodic = self.operator.boundary() == crate::grid::Boundary::Periodic;
        let mut cells = 0usize;
        for (c, &bonded) in attached.iter().enumerate() {
            if !bonded {
                continue;
            }
            cells += 1;
            let height = self.workspace.profile[c];
            if !height.is_finite() {
                return Err(Error::InvalidParameter {
                    name: "contact mask cell the indenter does not reach",
                    value: c as f64,
                    expected: "only cells where the indenter's height is finite",
                });
            }
            if !periodic && super::super::on_outer_ring(c, rows, columns) {
                return Err(Error::ContactReachesEdge {
                    cells,
                    detail: "the contact mask reaches the grid's outer ring",
                });
            }
        }
        if cells == 0 || cells == attached.len() {
            return Err(Error::InvalidParameter {
                name: "contact cells",
                value: cells as f64,
                expected: "at least one cell in contact and one out of it",
            });
        }
        let mut pressure = vec![0.0; attached.len()];
        let (iterations, residual) = self.clamped_solve(depth, &attached, &mut pressure)?;
        let solution = self.solution(&pressure, depth, iterations, residual, Some(&attached));
        super::super::check_solution(&solution)?;
        let zero = vec![0.0; attached.len()];
        // One state: its pressures and displacements as the "punch" pair at
        // unit depth, the profile carrying the indenter's slope.
        let pair = ClampedPair {
            attached: &attached,
            profile: &self.workspace.profile,
            lowest: 0.0,
            punch: &pressure,
            punch_displacement: &self.workspace.displacement,
            shape: &zero,
            shape_displacement: &zero,
        };
        let forces = EdgeForces::new(
            &pair,
            rows,
            columns,
            grid.spacing(),
            periodic,
            matches!(self.substrate, crate::Substrate::HalfSpace(_)),
        );
        let (rates, fit) = forces.smoothed(grid.spacing(), window);
        let modulus = self.surface_contact_modulus;
        let mut points = Vec::with_capacity(rates.len());
        for (&c, rate) in forces.cells.iter().zip(&rates) {
            let (i, j) = (c / columns, c % columns);
            // The rate of a single state: F(1) = a - b.
            let release_rate = rate.at(1.0);
            let tensile = rate.edge_pressure(1.0) < 0.0;
            let magnitude = (2.0 * modulus * release_rate.max(0.0)).sqrt();
            points.push(EdgePoint {
                cell: (i, j),
                position: grid.cell_centre(i, j),
                normal: (rate.normal[0], rate.normal[1]),
                release_rate,
                stress_intensity: if tensile { magnitude } else { -magnitude },
            });
        }
        crate::solver::all_finite(
            "edge release rates",
            &points.iter().map(|p| p.release_rate).collect::<Vec<_>>(),
        )?;
        Ok(EdgeRelease {
            depth,
            force: solution.force,
            points,
            iterations,
            fit,
        })
    }
}
