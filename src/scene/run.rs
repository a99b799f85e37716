//! Running a scene: its solver, the step-by-step and energy-balance runs,
//! the grid grown when a contact reaches its edge, and the stresses below
//! the surface at the most loaded step.

use super::*;

impl Scene {
    /// A solver for this scene's substrate on `grid`.
    fn solver_on(&self, grid: &Grid) -> Result<ContactSolver> {
        ContactSolver::new(
            &self.substrate.build()?,
            grid,
            self.boundary,
            self.solver_params(),
        )
    }

    /// The solver parameters of this scene.
    fn solver_params(&self) -> SolverParams {
        SolverParams {
            tolerance: self.solver.tolerance,
            max_iterations: self.solver.max_iterations,
            fields: Fields::default(),
            ..SolverParams::default()
        }
    }

    /// Builds the kernel and FFT plans for this scene (the expensive part),
    /// to pass to [`Scene::run_on`] once or many times.
    ///
    /// # Errors
    /// As [`Scene::validate`].
    pub fn solver(&self) -> Result<ContactSolver> {
        self.solver_on(&self.grid()?)
    }

    /// Builds this scene's solver split across the ranks of an MPI run
    /// (the `mpi` feature; see [`crate::distributed`]), to pass to
    /// [`Scene::run_on`] on every rank. Scenes without adhesion run split;
    /// their steps are the whole grid's on every rank. Fields and stresses
    /// are refused there ([`Error::Unsupported`]): each rank holds only its
    /// own rows of them.
    ///
    /// # Errors
    /// As [`Scene::solver`] and [`ContactSolver::distributed`].
    #[cfg(feature = "mpi")]
    pub fn distributed_solver(&self, ranks: &crate::distributed::Ranks) -> Result<ContactSolver> {
        ContactSolver::distributed(
            &self.substrate.build()?,
            &self.grid()?,
            self.boundary,
            self.solver_params(),
            ranks,
        )
    }

    /// Runs the scene, reporting each step to `progress`.
    ///
    /// # Errors
    /// Invalid scenes, and solver failures (typed, with residuals).
    pub fn run(&self, progress: &mut dyn FnMut(&Step)) -> Result<Curve> {
        let mut solver = self.solver()?;
        self.run_on(&mut solver, progress)
    }

    /// Runs the scene on a solver built by [`Scene::solver`] (or shared with
    /// another scene on the same substrate and grid, as [`Scene::grid`]
    /// gives it: a flat punch's grid depends on the adhesion method, a
    /// curved indenter's on the protocol too). A curved or custom
    /// indenter whose contact reaches the edge of the grid restarts on a
    /// grid 1.5 times as wide with the same spacing (at most four times).
    ///
    /// # Errors
    /// As [`Scene::run`].
    pub fn run_on(
        &self,
        solver: &mut ContactSolver,
        progress: &mut dyn FnMut(&Step),
    ) -> Result<Curve> {
        self.run_observed(solver, progress, &mut ())
    }

    /// As [`Scene::run_on`], with `observer` seeing the inner solves as they
    /// go: every iteration of the step-by-step solves, and for the energy
    /// balance, whose steps all come at once after it has built its family
    /// of contact sets, one report per set of that family
    /// ([`IterationInfo::iteration`](crate::solver::IterationInfo::iteration)
    /// counts the sets from the largest down, again from 1 when a family is
    /// widened to reach the load; `contact_cells` is the set's size), so
    /// that a front-end can show progress before the first step. The
    /// step-by-step solves report every conjugate-gradient iteration, those
    /// of the coarser grids of a cold start included.
    ///
    /// ```
    /// use std::cell::Cell;
    ///
    /// use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Scene};
    /// use layered_contact::solver::IterationInfo;
    ///
    /// let scene = Scene {
    ///     indenter: IndenterSpec::Paraboloid { radius: 0.01 },
    ///     adhesion: Adhesion::Constant { work_of_adhesion: 0.05 },
    ///     protocol: Protocol::Cycle { max_depth: 2e-6, steps: 3 },
    ///     ..Scene::default()
    /// };
    /// let (sets, steps) = (Cell::new(0), Cell::new(0));
    /// let mut solver = scene.solver()?;
    /// let curve = scene.run_observed(
    ///     &mut solver,
    ///     &mut |_| steps.set(steps.get() + 1),
    ///     // Every set is reported before the first step.
    ///     &mut |_: &IterationInfo| {
    ///         assert_eq!(steps.get(), 0);
    ///         sets.set(sets.get() + 1);
    ///     },
    /// )?;
    /// assert!(sets.get() >= 10 && steps.get() == curve.steps.len());
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Scene::run`].
    pub fn run_observed(
        &self,
        solver: &mut ContactSolver,
        progress: &mut dyn FnMut(&Step),
        observer: &mut dyn Observer,
    ) -> Result<Curve> {
        self.validate_settings()?;
        if solver.is_split()
            && (self.outputs.fields != Fields::default() || self.outputs.stresses.any())
        {
            return Err(Error::Unsupported {
                feature: "fields and stresses of a scene split across MPI ranks",
                reason: "each rank holds only its own rows of them: run the scene on one \
                         process for its fields and stresses",
            });
        }
        let mut grown: Option<ContactSolver> = None;
        for _ in 0..=MAX_GRID_GROWTH {
            let active = grown.as_mut().unwrap_or(&mut *solver);
            // Built for each grid (a grid grows only for the shapes that
            // are cheap to build): a rank of a split run synthesises or
            // reads only its own rows of a rough surface or `.npy` map.
            let slab = active.operator().slab();
            let built = self
                .indenter
                .build_on(self.tilt, slab.map(|slab| (slab, active.grid())));
            // A rank that cannot read its rows stops every rank.
            let indenter = crate::slab::agree(slab, built)?;
            let outcome = match (self.adhesion.works(), self.resolved_adhesion_method()) {
                (Some(works), AdhesionMethod::EnergyBalance) => {
                    energy::run(self, active, &*indenter, works, progress, observer)?
                }
                (_, method) => {
                    match Runner::new(self, active, &indenter, observer)?.run(progress) {
                        // A cohesive zone that did not settle on the grid's
                        // outer ring: a wider grid, as for a contact there.
                        Err(Error::ContactReachesEdge { .. })
                            if method == AdhesionMethod::CohesiveZone =>
                        {
                            Outcome::ReachedEdge
                        }
                        other => other?,
                    }
                }
            };
            match outcome {
                Outcome::Done(mut curve) => {
                    if self.outputs.stresses.any() {
                        let peak = curve.peak.as_ref().ok_or(Error::Internal {
                            what: "scene stresses",
                            detail: "no most loaded step was kept".into(),
                        })?;
                        curve.stresses = Some(stresses::compute(
                            &self.outputs.stresses,
                            &self.substrate.build()?,
                            &curve.grid,
                            self.boundary,
                            peak,
                        )?);
                        // Keep only what was asked for (the pressure was
                        // kept for the stresses).
                        if self.outputs.fields == Fields::default() {
                            curve.peak = None;
                        } else if !self.outputs.fields.pressure {
                            if let Some(peak) = curve.peak.as_mut() {
                                peak.pressure = None;
                            }
                        }
                    }
                    return Ok(*curve);
                }
                Outcome::ReachedEdge if self.indenter.is_map() => {
                    return Err(Error::Unsupported {
                        feature: "an adhesive contact reaching the edge of a height map",
                        reason: "pad the map with heights the contact does not reach, \
                                 or solve it on a periodic grid",
                    })
                }
                Outcome::ReachedEdge => {
                    let grid = *active.grid();
                    let cells = fft_friendly((grid.rows() * 3).div_ceil(2));
                    grown = Some(self.solver_like(active, cells)?);
                }
                Outcome::MissesTip => {
                    let grid = *active.grid();
                    if grid.rows() % 2 == 1 && grid.columns() % 2 == 1 {
                        // A cell centre already sits on the axis: the
                        // lowest point is elsewhere (a tilted indenter).
                        let (name, value) = self.protocol.reach();
                        return Err(Error::InvalidParameter {
                            name,
                            value,
                            expected: "deeper than the indenter's lowest cell centre \
                                       (the indenter touches between cell centres: use \
                                       a deeper load or more cells)",
                        });
                    }
                    // One more cell puts a cell centre on the axis, where
                    // the indenter touches first.
                    let cells = grid.rows().max(grid.columns()) | 1;
                    grown = Some(self.solver_like(active, cells)?);
                }
            }
        }
        Err(Error::InvalidParameter {
            name: "resolution.margin",
            value: self.resolution.margin,
            expected: "a grid that holds the contact (it still reached the edge after growing)",
        })
    }

    /// A solver on a `cells`-square grid of `solver`'s spacing, with its
    /// interrupt check (a grid grown or re-centred during a run).
    fn solver_like(&self, solver: &ContactSolver, cells: usize) -> Result<ContactSolver> {
        let grid = Grid::new(cells, cells, solver.grid().spacing())?;
        let mut next = solver.like_on(
            &self.substrate.build()?,
            &grid,
            self.boundary,
            self.solver_params(),
        )?;
        next.set_interrupt(solver.interrupt().cloned());
        Ok(next)
    }
}
