//! The boundary-element contact solver.
//!
//! [`ContactSolver`] owns a [`ComplianceOperator`] (kernel and FFT plans,
//! built once) and solves, for any [`Indenter`]:
//!
//! * [`ContactSolver::solve_depth`]: non-adhesive contact at a given depth,
//!   by the constrained conjugate gradients of Polonsky & Keer (1999, Wear
//!   231, 206), displacement-controlled variant;
//! * [`ContactSolver::solve_force`]: non-adhesive contact at a given total
//!   force, Polonsky & Keer's force-controlled algorithm (the search
//!   directions carry no net force; the depth is the Lagrange multiplier);
//! * [`ContactSolver::adhesive_branches`]: adhesive contact in the JKR limit
//!   by the energy balance over the contact edge, along a family of contact
//!   sets; the [`AdhesiveBranches`] it returns answer any depth or force,
//!   loading or unloading, with adhesion hysteresis, and locate the pull-off
//!   (the default method of scenes; its accuracy against exact JKR is
//!   tabulated in [`doc::accuracy`](crate::doc::accuracy));
//! * [`ContactSolver::solve_depth_adhesive`] and
//!   [`ContactSolver::solve_depth_hysteretic`]: adhesive contact in the JKR
//!   limit with the mesh-dependent criterion of Pohrt & Popov (2015, Facta
//!   Univ. Mech. Eng. 13, 3), cell by cell: a cell in contact may carry
//!   tension down to `-sigma_c = -sqrt(E1* dgamma / (0.473201 Delta))`; an
//!   edge cell whose tension exceeds it detaches (receding work of
//!   adhesion), and the edge advances onto the cells next to it that can
//!   hold (advancing work of adhesion) and onto every cell the indenter
//!   penetrates. The reference method, for any contact shape, converging
//!   slowly.
//!
//! [`doc::adhesion`](crate::doc::adhesion) compares the two.
//!
//! The non-adhesive iteration runs over the working set of bound-constrained
//! minimisation (cells in contact and cells the indenter overlaps) and is
//! preconditioned with the compliance's inverse on a periodic box around
//! that set, after Vollebregt (2014, J. Comput. Phys. 257, 333): its
//! iteration count hardly grows with the grid (11 to 15 for a Hertzian
//! contact from 256 to 4096 cells across). A solve on a grid of at least
//! [`MULTIRESOLUTION_CELLS`] cells each way starts from the same problem
//! solved on the grid of half the cells (twice their size), recursively; a
//! warm start is corrected there first (Brandt's full approximation
//! scheme). [`SolverParams::precondition`] and
//! [`SolverParams::multiresolution`] turn either off. On rough contacts,
//! whose box-preconditioned count grows with every doubling of the grid,
//! a coarse correction over blocks of cells (two-level balancing, Mandel
//! 1993) joins once the contact set has settled, whose count grows like
//! `log N`, at 1.5 to 2 times the cost an iteration: by itself on grids of
//! at least [`AUTOMATIC_BLOCKS_CELLS`] cells for contacts of many patches
//! whose box converges slowly
//! ([`ContactSolver::set_automatic_coarse_blocks`], the default), or as
//! [`ContactSolver::set_coarse_blocks`] sets it.
//!
//! Each solve may start from the [`WarmStart`] of the previous one. For
//! non-adhesive contact that only saves work (on the Hertz benchmark at
//! 1024 x 1024 a step of 4 % in depth takes 13 fine iterations, as a cold
//! solve does, and 42 instead of 47 on the coarse grids; a step of 0.04 %,
//! 12 and 39); for adhesive contact the warm start carries the history
//! (which cells are attached). Solves allocate only their output; scratch buffers live in the
//! solver.
//!
//! The indenter's axis stands at the centre of the grid.

// The iterations walk several per-cell arrays in step; an index reads clearer
// than a five-way zip.
#![allow(clippy::needless_range_loop)]

mod active_set;
mod adhesive;
mod anderson;
mod balancing;
mod cg_ends;
mod coarse_choice;
mod coarse_space;
mod cohesive;
mod cohesive_area;
mod cohesive_bonding;
mod cohesive_closest;
mod cohesive_force;
mod cohesive_law;
mod cohesive_pull_off;
mod cohesive_smoothing;
mod cohesive_steps;
mod curvature;
mod griffith;
pub(crate) mod least_force;
mod multiresolution;
mod overlap_joining;
mod params;
mod passes;
mod patch_width;
mod polonsky_keer;
mod preconditioning;
mod split;
mod stall;
mod step_response;
mod workspace;

use ndarray::Array2;

use crate::error::{Error, Result};
use crate::grid::{Boundary, Grid};
use crate::indenter::Indenter;
use crate::kernel::{ComplianceOperator, FourierCompliance};
use crate::substrate::Substrate;
use preconditioning::Preconditioner;

use workspace::Workspace;

pub use coarse_choice::{
    Preconditioning, AUTOMATIC_BLOCKS_BOX_RATE, AUTOMATIC_BLOCKS_CELLS,
    AUTOMATIC_BLOCKS_LARGE_CELLS, AUTOMATIC_BLOCKS_SMALL_GRID_BOX_RATE, AUTOMATIC_BLOCK_SIDE,
};
pub use cohesive_area::EQUIVALENT_TIP;
pub use cohesive_law::{
    CohesiveZone, COHESIVE_ZONE_CELLS, CURVATURE_CORRECTION, ZONE_LAYER_FRACTION,
};
pub(crate) use cohesive_pull_off::pinned_at_rim;
pub(crate) use cohesive_pull_off::substeps;
pub use cohesive_pull_off::CohesivePullOff;
pub use griffith::{
    AdhesiveBranches, BranchPoint, EdgeFit, EdgePoint, EdgeRelease, PeelPoint, PeelingPath, Reach,
    EDGE_SHIFT, EDGE_WINDOW, PEEL_FRACTION,
};
pub use multiresolution::MULTIRESOLUTION_CELLS;
pub use params::{Fields, IterationInfo, Observer, Solution, SolverParams, WarmStart};

/// The constant of the mesh-dependent critical stress (Pohrt & Popov 2015).
pub const MESH_CRITERION_CONSTANT: f64 = 0.473201;

/// A contact solver for one substrate on one grid. See the [module
/// docs](self).
///
/// ```
/// use layered_contact::indenter::FlatPunch;
/// use layered_contact::solver::{ContactSolver, SolverParams};
/// use layered_contact::{Boundary, Grid, Material, Substrate};
///
/// let rubber = Material::new(1e6, 0.5)?;
/// let a = 1e-3;
/// let grid = Grid::square_of_side(34, 2.125 * a)?; // 32 cells across the punch
/// let mut solver = ContactSolver::new(
///     &Substrate::half_space(rubber), &grid, Boundary::Isolated, SolverParams::default())?;
/// let punch = FlatPunch::new(a)?;
/// let (solution, _) = solver.solve_depth(&punch, 1e-5, None, &mut ())?;
/// // Boussinesq: F = 2 a E* d at the radius of equal area, within ~1/N.
/// let exact = 2.0 * solution.contact_radius * rubber.contact_modulus() * 1e-5;
/// assert!((solution.force / exact - 1.0).abs() < 0.03);
/// Ok::<(), layered_contact::Error>(())
/// ```
pub struct ContactSolver {
    operator: ComplianceOperator,
    params: SolverParams,
    /// The substrate's Fourier compliance, for the preconditioner.
    compliance: FourierCompliance,
    /// The constrained conjugate gradients' preconditioner, built on first
    /// use for a box around the contact and rebuilt only when the contact
    /// outgrows it (or shrinks far inside it).
    preconditioner: Option<Preconditioner>,
    /// Whether the preconditioner runs in double precision (the cohesive
    /// zone's rounds) rather than single ([`Preconditioner`]).
    double_preconditioner: bool,
    /// Whether the constrained conjugate gradients' early iterations apply
    /// the operator in single precision (`polonsky_keer.rs`; on by
    /// default, off in the tests that compare against double throughout).
    single_precision: bool,
    /// The factor by which the last solve scaled its warm start, its own
    /// (`ContactSolver::scale_warm_start`; 1 when it had none) times its
    /// coarser levels': a coarse start level's, read by the finer level to
    /// scale its own warm start's detail alike.
    warm_scale: f64,
    /// The substrate, for the coarser solvers.
    substrate: Substrate,
    /// The solver on the grid of half the cells each way and twice their
    /// size, for the multi-resolution start (built on first use; `None`
    /// also when the grid cannot be halved).
    coarse: Option<Option<Box<ContactSolver>>>,
    /// `E*` of the surface material, for the critical stress.
    surface_contact_modulus: f64,
    workspace: Workspace,
    /// Asked after every iteration and every step: stop when it says so.
    interrupt: Option<Interrupt>,
    /// Whether this solver is a coarse level of a finer one's
    /// multi-resolution start: its solves stop at their tolerance even
    /// while cells still overlap the indenter (the finer solve takes them
    /// in).
    start_level: bool,
    /// Whether this start level may stop at its loosened tolerance
    /// ([`multiresolution::loosened`]): every start level but the one
    /// right under the solve asked for, whose solution that solve starts
    /// from (why: `loosened`'s documentation).
    loosens: bool,
    /// The two-level preconditioner, if it is on
    /// ([`ContactSolver::set_coarse_blocks`]) or the automatic choice built
    /// it.
    balancing: Option<Box<balancing::Balancing>>,
    /// Whether each fine solve chooses between the box and the two-level
    /// preconditioner itself (the default;
    /// [`ContactSolver::set_automatic_coarse_blocks`]) rather than as
    /// [`ContactSolver::set_coarse_blocks`] set it.
    coarse_automatic: bool,
    /// How the last constrained conjugate gradients were preconditioned
    /// ([`ContactSolver::last_preconditioning`]).
    preconditioning: Option<Preconditioning>,
}

/// A check that a long computation should stop (Ctrl-C), asked after every
/// solver iteration and every scene step: `true` stops it with
/// [`Error::Interrupted`]. It must be cheap (it runs thousands of times a
/// second) and may be called from the solving thread only.
pub type Interrupt = std::sync::Arc<dyn Fn() -> bool + Send + Sync>;

/// [`Error::Interrupted`] naming `what` if `check` asks to stop.
pub(crate) fn interrupted(check: &Option<Interrupt>, what: &'static str) -> Result<()> {
    match check {
        Some(check) if check() => Err(Error::Interrupted { what }),
        _ => Ok(()),
    }
}

impl std::fmt::Debug for ContactSolver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ContactSolver")
            .field("operator", &self.operator)
            .field("params", &self.params)
            .finish_non_exhaustive()
    }
}

impl ContactSolver {
    /// A solver for `substrate` on `grid` (kernel and FFT plans built here).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a tolerance that is not positive and
    /// finite or a zero iteration limit; the errors of
    /// [`ComplianceOperator::new`] (a film the grid cannot resolve, a cell
    /// compliance out of range, [`Error::OutOfMemory`]).
    pub fn new(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        params: SolverParams,
    ) -> Result<Self> {
        let operator = ComplianceOperator::new(substrate, grid, boundary)?;
        Self::with_operator(operator, substrate, params)
    }

    /// A solver reusing an existing operator of `substrate` (for example one
    /// shared between scenes).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a tolerance that is not positive and
    /// finite or a zero iteration limit; [`Error::OutOfMemory`] if the
    /// per-cell vectors cannot be allocated.
    pub fn with_operator(
        operator: ComplianceOperator,
        substrate: &Substrate,
        params: SolverParams,
    ) -> Result<Self> {
        crate::error::positive_finite("tolerance", params.tolerance)?;
        if params.max_iterations == 0 {
            return Err(Error::InvalidParameter {
                name: "max_iterations",
                value: 0.0,
                expected: "at least 1",
            });
        }
        let n = operator.local_cells();
        Ok(ContactSolver {
            operator,
            params,
            compliance: FourierCompliance::new(substrate),
            preconditioner: None,
            double_preconditioner: false,
            single_precision: true,
            warm_scale: 1.0,
            substrate: substrate.clone(),
            coarse: None,
            surface_contact_modulus: substrate.surface_material().contact_modulus(),
            workspace: Workspace::new(n)?,
            interrupt: None,
            start_level: false,
            loosens: false,
            balancing: None,
            coarse_automatic: true,
            preconditioning: None,
        })
    }

    /// Sets (or with `None` removes) the check asked after every iteration
    /// of every solve, and by scenes after every step: when it returns
    /// `true` the solve stops with [`Error::Interrupted`].
    ///
    /// ```
    /// use layered_contact::indenter::Sphere;
    /// use layered_contact::solver::{ContactSolver, SolverParams};
    /// use layered_contact::{Boundary, Error, Grid, Material, Substrate};
    ///
    /// let body = Substrate::half_space(Material::new(1e6, 0.5)?);
    /// let grid = Grid::new(32, 32, 1e-5)?;
    /// let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default())?;
    /// solver.set_interrupt(Some(std::sync::Arc::new(|| true)));
    /// let stopped = solver.solve_depth(&Sphere::new(1e-2)?, 1e-6, None, &mut ());
    /// assert!(matches!(stopped, Err(Error::Interrupted { .. })));
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn set_interrupt(&mut self, check: Option<Interrupt>) {
        self.interrupt = check;
    }

    /// The check set by [`ContactSolver::set_interrupt`].
    pub fn interrupt(&self) -> Option<&Interrupt> {
        self.interrupt.as_ref()
    }

    /// [`Error::Interrupted`] if the interrupt check asks to stop.
    pub(crate) fn check_interrupt(&self, what: &'static str) -> Result<()> {
        // Every rank stops together.
        self.agreed(interrupted(&self.interrupt, what))
    }

    /// Frees the per-cell scratch vectors, the preconditioner and the
    /// operator's FFT buffer (a coarse solver between multi-resolution
    /// starts); the next solve allocates them again.
    fn release_scratch(&mut self) {
        self.workspace = Workspace::default();
        self.preconditioner = None;
        self.operator.release_buffer();
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        self.operator.grid()
    }

    /// The body this solver presses into.
    pub fn substrate(&self) -> &Substrate {
        &self.substrate
    }

    /// The grid rows this solver holds: all of them, or on a solver split
    /// across MPI ranks (the `mpi` feature) this rank's band, which its
    /// warm starts and solution fields cover.
    pub fn local_rows(&self) -> std::ops::Range<usize> {
        self.operator.local_rows()
    }

    /// The compliance operator (kernel and FFT plans).
    pub fn operator(&self) -> &ComplianceOperator {
        &self.operator
    }

    /// The parameters.
    pub fn params(&self) -> &SolverParams {
        &self.params
    }

    /// Replaces the parameters (the kernel is kept).
    pub fn set_params(&mut self, params: SolverParams) {
        self.params = params;
        if let Some(Some(coarse)) = self.coarse.as_mut() {
            coarse.set_params(multiresolution::coarse_params(&params));
        }
    }

    /// The critical tensile stress `sqrt(E1* dgamma / (0.473201 Delta))` for a
    /// work of adhesion `dgamma` on this grid, Pa.
    pub fn critical_stress(&self, work_of_adhesion: f64) -> f64 {
        (self.surface_contact_modulus * work_of_adhesion
            / (MESH_CRITERION_CONSTANT * self.grid().spacing()))
        .sqrt()
    }

    /// Samples the indenter at the cell centres (axis at the grid centre).
    /// Returns the smallest height.
    fn sample_profile<I: Indenter + ?Sized>(&mut self, indenter: &I) -> Result<f64> {
        let grid = *self.operator.grid();
        let local = self.operator.local_rows();
        let n = self.local_cells();
        let fitted = self.workspace.fit(n);
        self.agreed(fitted)?;
        let columns = grid.columns();
        let mut lowest = f64::INFINITY;
        let mut bad = None;
        for (c, f) in self.workspace.profile.iter_mut().enumerate() {
            let (x, y) = grid.cell_centre(local.start + c / columns, c % columns);
            let h = indenter.height(x, y);
            if h.is_nan() || h == f64::NEG_INFINITY {
                bad = Some(h);
                break;
            }
            *f = h;
            lowest = lowest.min(h);
        }
        let checked = match bad {
            Some(h) => Err(Error::InvalidParameter {
                name: "indenter height",
                value: h,
                expected: "finite or +inf at every cell centre",
            }),
            None => Ok(()),
        };
        self.agreed(checked)?;
        if let Some(slab) = self.operator.slab() {
            let mut values = [lowest];
            slab.exchange.min(&mut values);
            lowest = values[0];
        }
        if lowest == f64::INFINITY {
            let (lx, ly) = grid.extent();
            return Err(Error::IndenterOutsideGrid {
                bounding_radius: indenter.bounding_radius(),
                grid_extent: lx.min(ly),
            });
        }
        Ok(lowest)
    }

    /// Which cells the sampled indenter can reach (finite height).
    fn reachable(&self) -> Vec<bool> {
        self.workspace
            .profile
            .iter()
            .map(|f| f.is_finite())
            .collect()
    }

    /// Assembles the solution from `pressure` (with the workspace holding
    /// the displacement of that pressure and the profile).
    fn solution(
        &mut self,
        pressure: &[f64],
        depth: f64,
        iterations: usize,
        residual: f64,
        attached: Option<&[bool]>,
    ) -> Solution {
        let grid = *self.operator.grid();
        let area = grid.cell_area();
        let columns = grid.columns();
        let (mut force, mut mx, mut my, mut cells) = (0.0, 0.0, 0.0, 0usize);
        let mut edge_contact = false;
        let isolated = self.operator.boundary() == Boundary::Isolated;
        let rows = grid.rows();
        let local = self.operator.local_rows();
        // The cell index on the whole grid of this rank's cell `c`.
        let first = local.start * columns;
        for (c, &p) in pressure.iter().enumerate() {
            let in_contact = match attached {
                Some(a) => a[c],
                None => p > 0.0,
            };
            if in_contact {
                cells += 1;
                edge_contact |= isolated && on_outer_ring(first + c, rows, columns);
            }
            let (x, y) = grid.cell_centre((first + c) / columns, c % columns);
            force += p * area;
            mx += p * x * area;
            my += p * y * area;
        }
        if self.operator.slab().is_some() {
            let mut totals = [
                force,
                mx,
                my,
                cells as f64,
                f64::from(u8::from(edge_contact)),
            ];
            self.sum_over_ranks(&mut totals);
            (force, mx, my) = (totals[0], totals[1], totals[2]);
            cells = totals[3] as usize;
            edge_contact = totals[4] > 0.0;
        }
        // Distributed, the fields are this rank's rows.
        let shape = (local.len(), grid.columns());
        let field = |keep: bool, values: &dyn Fn() -> Vec<f64>| {
            keep.then(|| {
                Array2::from_shape_vec(shape, values()).expect("field has the grid's shape")
            })
        };
        let ws = &self.workspace;
        let fields = self.params.fields;
        let contact_area = cells as f64 * area;
        Solution {
            depth,
            force,
            moment: (mx, my),
            contact_area,
            contact_radius: (contact_area / std::f64::consts::PI).sqrt(),
            contact_cells: cells,
            edge_contact,
            iterations,
            coarse_iterations: 0,
            residual,
            pressure: field(fields.pressure, &|| pressure.to_vec()),
            displacement: field(fields.displacement, &|| ws.displacement.clone()),
            gap: field(fields.gap, &|| {
                ws.profile
                    .iter()
                    .zip(&ws.displacement)
                    .map(|(f, u)| f - depth + u)
                    .collect()
            }),
        }
    }

    /// The solution with no contact at `depth` (the indenter does not reach
    /// the surface, or it has been pulled off).
    fn no_contact(&mut self, depth: f64) -> (Solution, WarmStart) {
        let n = self.local_cells();
        self.workspace.displacement.fill(0.0);
        let pressure = vec![0.0; n];
        let solution = self.solution(&pressure, depth, 0, 0.0, None);
        (
            solution,
            WarmStart {
                pressure,
                attached: vec![false; n],
                contact: None,
                withdrawn: false,
            },
        )
    }

    fn check_warm_start(&self, warm: Option<&WarmStart>) -> Result<()> {
        match warm {
            Some(w) if w.pressure.len() != self.local_cells() => Err(Error::ShapeMismatch {
                field: "warm start",
                expected: self.local_cells(),
                found: w.pressure.len(),
            }),
            _ => Ok(()),
        }
    }
}

/// A solution whose scalars are all finite, else [`Error::NonFinite`]: no
/// NaN or infinity leaves a solver inside an `Ok`.
pub(crate) fn check_solution(solution: &Solution) -> Result<()> {
    all_finite(
        "contact solution",
        &[
            solution.depth,
            solution.force,
            solution.moment.0,
            solution.moment.1,
            solution.contact_area,
            solution.residual,
        ],
    )
}

/// `Ok` if every one of `values` is finite, else [`Error::NonFinite`] naming
/// `what` and the first offending value.
pub(crate) fn all_finite(what: &'static str, values: &[f64]) -> Result<()> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(&value) => Err(Error::NonFinite { what, value }),
        None => Ok(()),
    }
}

/// A zeroed per-cell vector, or [`Error::OutOfMemory`] instead of an abort.
fn cell_vector(n: usize) -> Result<Vec<f64>> {
    crate::error::zeroed(n, "a solver's per-cell vectors")
}

/// Whether cell `c` of a row-major `rows x columns` grid lies on its outer
/// ring of cells.
pub(super) fn on_outer_ring(c: usize, rows: usize, columns: usize) -> bool {
    let (i, j) = (c / columns, c % columns);
    i == 0 || j == 0 || i + 1 == rows || j + 1 == columns
}

/// The 4-neighbours of cell `c` on a row-major grid of `rows x columns`.
pub(super) fn neighbours(c: usize, rows: usize, columns: usize) -> [Option<usize>; 4] {
    let (i, j) = (c / columns, c % columns);
    [
        (i > 0).then(|| c - columns),
        (i + 1 < rows).then(|| c + columns),
        (j > 0).then(|| c - 1),
        (j + 1 < columns).then(|| c + 1),
    ]
}

/// The 4-neighbours of cell `c` (up, down, left, right), wrapping round a
/// periodic grid.
pub(super) fn wrapped_neighbours(
    c: usize,
    rows: usize,
    columns: usize,
    periodic: bool,
) -> [Option<usize>; 4] {
    if !periodic {
        return neighbours(c, rows, columns);
    }
    let (i, j) = (c / columns, c % columns);
    [
        Some(((i + rows - 1) % rows) * columns + j),
        Some(((i + 1) % rows) * columns + j),
        Some(i * columns + (j + columns - 1) % columns),
        Some(i * columns + (j + 1) % columns),
    ]
}

pub(crate) use crate::error::finite as check_finite;
