//! Solver parameters, progress reports and results.

use ndarray::Array2;

/// Which fields a solve keeps in its [`Solution`]. None by default: a curve of
/// a thousand steps stores a thousand sets of scalars, not a thousand
/// pressure maps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct Fields {
    /// Keep the cell pressures (Pa).
    pub pressure: bool,
    /// Keep the surface displacements at the cell centres (m, positive into
    /// the body).
    pub displacement: bool,
    /// Keep the gap between indenter and deformed surface (m; `+inf` where
    /// the indenter cannot reach).
    pub gap: bool,
}

impl Fields {
    /// Every field.
    pub fn all() -> Self {
        Fields {
            pressure: true,
            displacement: true,
            gap: true,
        }
    }
}

/// Parameters of the contact solvers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverParams {
    /// Relative tolerance: on the change of the pressure per iteration for the
    /// constrained conjugate gradients (Polonsky and Keer's criterion), on the
    /// residual of the linear system for the adhesive inner solves. It
    /// bounds the change, not the pressures' error: on an ill-conditioned
    /// contact the error is far larger (a ring of contact on a stiff layer
    /// over a base 8000 times softer: two solves that each met `1e-10`
    /// differed by `2.8e-7` of the largest pressure, at `1e-14` by `1e-10`;
    /// `BENCHMARKS.md`, "A folding branch; the loops split across ranks").
    /// Their forces agreed far closer (`1.1e-11` and `3e-14`).
    pub tolerance: f64,
    /// Iteration limit (per inner solve for the adhesive solver).
    pub max_iterations: usize,
    /// Which fields to keep.
    pub fields: Fields,
    /// Precondition the constrained conjugate gradients with the
    /// compliance's inverse on a box around the contact (Vollebregt 2014);
    /// `false` iterates without a preconditioner, as Polonsky and Keer did
    /// (about ten times the iterations on large grids; for comparison).
    pub precondition: bool,
    /// Start cold non-adhesive solves on grids of at least
    /// [`MULTIRESOLUTION_CELLS`](super::MULTIRESOLUTION_CELLS) cells each
    /// way from the solution on the grid of half the cells (rounded up),
    /// recursively, and correct warm starts there; `false` starts from zero pressure (or uniform, under
    /// force control).
    pub multiresolution: bool,
}

impl Default for SolverParams {
    fn default() -> Self {
        SolverParams {
            tolerance: 1e-10,
            max_iterations: 10_000,
            fields: Fields::default(),
            precondition: true,
            multiresolution: true,
        }
    }
}

/// What an observer sees after each iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IterationInfo {
    /// Iterations so far in this solve.
    pub iteration: usize,
    /// The current residual (see [`SolverParams::tolerance`]).
    pub residual: f64,
    /// Cells currently in contact.
    pub contact_cells: usize,
}

/// Receives progress from a solver; a library never prints, so pass one to
/// log or plot convergence. `()` ignores everything; any
/// `FnMut(&IterationInfo)` closure is an observer.
pub trait Observer {
    /// Called after each iteration.
    fn observe(&mut self, info: &IterationInfo);
}

impl Observer for () {
    fn observe(&mut self, _info: &IterationInfo) {}
}

impl<F: FnMut(&IterationInfo)> Observer for F {
    fn observe(&mut self, info: &IterationInfo) {
        self(info)
    }
}

/// The result of one solve.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Depth `d` of the indenter's axis point below the undeformed surface, m.
    pub depth: f64,
    /// Total force `F = sum p Delta^2`, N (negative when adhesion pulls).
    pub force: f64,
    /// First moments of the pressure about the indenter axis,
    /// `(sum p x Delta^2, sum p y Delta^2)`, N m.
    pub moment: (f64, f64),
    /// Contact area: cells in contact times the cell area, m^2. Through a
    /// cohesive zone ([`ContactSolver::solve_depth_cohesive`](super::ContactSolver::solve_depth_cohesive)),
    /// the area of the equivalent crack: the closed cells and
    /// [`EQUIVALENT_TIP`](super::EQUIVALENT_TIP) of the zone's open cells
    /// around them.
    pub contact_area: f64,
    /// Radius of the circle of equal area, `sqrt(A / pi)`, m.
    pub contact_radius: f64,
    /// Number of cells in contact (through a cohesive zone, the closed
    /// ones).
    pub contact_cells: usize,
    /// Whether the contact touches the outer ring of cells of an isolated
    /// grid: unless the indenter itself ends there (a punch as wide as the
    /// grid), the contact was truncated by the grid and the result is wrong;
    /// solve again on a wider grid. Always `false` on a periodic grid.
    pub edge_contact: bool,
    /// Iterations used on this grid (about one operator application each).
    pub iterations: usize,
    /// Iterations of the multi-resolution start on the coarser grids (of
    /// half, a quarter, ... the cells each way), 0 without one; each costs
    /// a quarter, a sixteenth, ... of an iteration on this grid.
    pub coarse_iterations: usize,
    /// Final residual.
    pub residual: f64,
    /// Cell pressures (Pa), if asked for in [`Fields`]: `rows x columns`,
    /// `[i, j]` at the cell centre `x = (i + 1/2 - rows/2) Delta`,
    /// `y = (j + 1/2 - columns/2) Delta` from the indenter's axis.
    pub pressure: Option<Array2<f64>>,
    /// Surface displacements (m, into the body) at the same cell centres,
    /// if asked for.
    pub displacement: Option<Array2<f64>>,
    /// Gaps (m) at the same cell centres, if asked for.
    pub gap: Option<Array2<f64>>,
}

impl Solution {
    /// The mean gap over the grid, m: the mean separation `u_bar` between
    /// the indenter and the deformed surface of a rough contact, whose
    /// derivative along a force protocol gives the interfacial stiffness
    /// `-dp_bar/du_bar` (Persson 2007, Phys. Rev. Lett. 99, 125502). On a
    /// periodic half-space the mean displacement is zero (the uniform mode
    /// is fixed by the approach), so `u_bar = <h> - d` with `h` the
    /// indenter's heights; for Westergaard's wavy surface of amplitude
    /// `D` (`h = D (1 - cos)`), `u_bar / D = 1 - s + s ln s` with `s = p_bar/p*`
    /// (`tests/interface.rs` checks the BEM against it).
    ///
    /// `None` without the gap field ([`Fields::gap`]) or where the indenter
    /// does not cover every cell (an isolated sphere: the gap is infinite
    /// beyond it).
    pub fn mean_gap(&self) -> Option<f64> {
        let gap = self.gap.as_ref()?;
        if gap.is_empty() || gap.iter().any(|g| !g.is_finite()) {
            return None;
        }
        gap.mean()
    }
}

/// The state a solve ends in, to start the next load step from: the cell
/// pressures and, for adhesive contact, which cells are attached (the
/// history that makes loading and unloading differ).
#[derive(Debug, Clone, PartialEq)]
pub struct WarmStart {
    pub(crate) pressure: Vec<f64>,
    pub(crate) attached: Vec<bool>,
    /// The cells whose gap is closed, where they differ from `attached`:
    /// the cohesive zone's bonded cells include its open zone.
    pub(crate) contact: Option<Vec<bool>>,
    /// Whether the cohesive solve that made it withdrew the indenter (or
    /// held it) from a withdrawn equilibrium: its advancing zone was bonded
    /// at the reversal and is not bonded again
    /// (`src/solver/cohesive_bonding.rs`).
    pub(crate) withdrawn: bool,
}

impl WarmStart {
    /// Number of cells attached (in contact).
    pub fn attached_cells(&self) -> usize {
        self.attached.iter().filter(|a| **a).count()
    }

    /// Whether cell `c` (row-major index) is attached.
    pub fn is_attached(&self, c: usize) -> bool {
        self.attached.get(c).copied().unwrap_or(false)
    }
}
