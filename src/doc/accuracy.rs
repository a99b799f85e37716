//! # Accuracy and its cost
//!
//! What to expect from each part, measured by the `accuracy` example
//! (`cargo run --release --example accuracy`, which regenerates
//! `BENCHMARKS.md`) and asserted by the tests.
//!
//! ## Analytic and exact solutions
//!
//! * `R(t)`, `Lambda_g(t)`: relative error below `1e-15` against 80-digit
//!   references, for every `t`, base and Poisson ratio.
//! * `a_m`: relative error about `2e-16` for `m <= 2`.
//! * [`Axisymmetric`](crate::analytic::Axisymmetric): converged to `1e-11`
//!   (the Nystrom order doubles until results change by less); about 70
//!   microseconds per flat-punch stiffness up to `a/h = 2`, 3 ms at
//!   `a/h = 10`, 0.1 s at `a/h = 50`.
//!
//! ## Influence coefficients
//!
//! Against an independent quadrature, below `1e-14` of the self-coefficient
//! for `h/Delta` from 0.5 to `1e6` on rigid, stiff and soft bases; thin
//! layers (`h/Delta = 1e-3`) settle by the uniaxial-strain compliance to
//! `1e-12`. The FFT operator equals the dense sum to `1e-12`.
//!
//! ## The BEM
//!
//! With `N` cells across the contact, measured by the `accuracy` example
//! (`BENCHMARKS.md`):
//!
//! | quantity | error at `N = 64` | convergence |
//! |---|---|---|
//! | flat-punch stiffness, half-space or layer (equal-area grid) | 0.35-0.83 % | `c / N` (`c` = 0.23 to 0.53); Richardson of 256 and 512 cells: `7e-8` to `2e-6` |
//! | flat punch on a nearly incompressible layer much thinner than the contact (`nu = 0.4985`, `a/h = 18.6`, rigid base) | 0.48 % | 0.34 % at 128, 0.16 % at 256: the edge's boundary layer, `h` wide, needs several cells per thickness |
//! | Hertz force | `7e-5` | about `1/N^2` |
//! | Hertz contact radius | 0.5 % | staircase, `1/N` |
//! | JKR sphere pull-off, energy balance (default) | 0.0005-0.07 % (0.3 % or less at 16 cells) | staircase noise, up to 0.25 % below 64 cells |
//! | JKR sphere pull-off, mesh-dependent criterion | 0.02-4.2 % | about `3/N` on a half-space, irregular on layers |
//! | Kendall pull-off (flat punch, energy balance) | 0.02 % | staircase noise below 0.15 % |
//! | a punch's pull-off under hysteresis (`dgamma` 0.0175 / 0.326 J/m^2) on a half-space and on films on a rigid base, `a/h` 0.35 to 8 (`examples/punch_peeling.rs -- films`; `BENCHMARKS.md`, "`auto` peels a punch whose stiffness barely changes") | energy balance -0.35 to +0.08 %, the peeling path +0.02 to +0.09 % | the balance stalls (-0.08 to -0.39 % at 128 cells) and refused 3 of its 44 runs at 16 and 32 cells; the peeling path +0.66 to +0.89, +0.41 to +0.45 % at 16, 32 cells, -0.06 to -0.13 % at 128: crossing zero, not a power of `1/N` |
//! | Kendall pull-off on a layer, the cohesive zone and the peeling path (`punch_jkr_layer_pull_off/peeling_path`) | 0.081 % | 0.67, 0.43 % at 16, 32 cells, 0.070 / 0.036 % at 128 / 256 (the disc's edge by its angular modes); Richardson of 128 and 256: `1.7e-5` |
//!
//! The row of the incompressible layer is `layered-contact run
//! examples/scenes/punch_on_incompressible_film.toml` at 64, 128 and 256
//! cells (`BENCHMARKS.md`, single runs).
//!
//! Flat-punch grids choose their spacing (within 2 % of nominal) so that the
//! staircase disc has the punch's area. The error left is the edge's: the
//! piecewise-constant pressures miss part of the square-root singularity, a
//! clean `c / N` from below (`N c` = 0.525, 0.547, 0.512, 0.530, 0.531,
//! 0.530, 0.532 at 8 to 512 cells on the layer at `a/h = 2`), which
//! Richardson extrapolation ([`richardson`](crate::scene::richardson))
//! removes: from 64 and 128 cells `2.7e-4`, `4.6e-4` and `5.7e-4` of the
//! exact stiffness on the half-space and the layers at `a/h` = 0.5 and 2,
//! from 128 and 256 `3.4e-6` to `9.5e-6`, from 256 and 512 `6.7e-8`,
//! `3.2e-7` and `2.1e-6` (`tests/scene.rs` checks 64 and 128 on the layer).
//! Until 2026-11-24 the grid made the disc's *effective* radius (its
//! equal-area radius less [`EDGE_SHIFT`](crate::solver::EDGE_SHIFT) cells)
//! the punch's: smaller raw errors (0.07-0.17 % at 64 cells) but not a power
//! of `1/N` (they changed sign near 32 cells), so extrapolation gained
//! nothing (`1.4e-3` to `3.9e-3` from 32 and 64 cells). The energy
//! balance's punch keeps that grid, since its contact sets are shifted
//! discs.
//!
//! ### Adhesion
//!
//! The JKR sphere pull-off (`R = 10 mm`, `dgamma = 0.05 J/m^2`, rubber
//! `E = 1 MPa`, `nu = 0.48`) against the exact (layered) JKR value, `N` cells
//! across the pull-off contact, pressed until the contact is 1.5 pull-off
//! radii wide, on a half-space and on layers whose pull-off contact is about
//! one and three thicknesses wide, on a rigid base and on a base ten times
//! stiffer:
//!
//! | body | method | 16 | 32 | 64 | 128 |
//! |---|---|---|---|---|---|
//! | half-space | energy balance | 0.17 % | 0.19 % | 0.004 % | 0.007 % |
//! | half-space | mesh criterion | 16 % | 5.9 % | 3.2 % | 1.3 % (97 s) |
//! | rigid base, `a/h = 1` | energy balance | 0.22 % | 0.06 % | 0.003 % | 0.02 % |
//! | rigid base, `a/h = 1` | mesh criterion | 13 % | 4.7 % | 4.2 % | 0.8 % |
//! | rigid base, `a/h = 3` | energy balance | refused (film 2.7 cells) | 0.21 % | 0.03 % | 0.01 % |
//! | rigid base, `a/h = 3` | mesh criterion | 0.9 % | 1.6 % | 0.8 % | 0.6 % |
//! | base `E2/E1 = 10`, `a/h = 1` | energy balance | 0.03 % | 0.02 % | 0.003 % | 0.01 % |
//! | base `E2/E1 = 10`, `a/h = 1` | mesh criterion | 15 % | 7.9 % | 2.5 % | 1.6 % |
//! | base `E2/E1 = 10`, `a/h = 3` | energy balance | 0.07 % | 0.15 % | 0.03 % | 0.01 % |
//! | base `E2/E1 = 10`, `a/h = 3` | mesh criterion | 3.5 % | 2.9 % | 0.02 % | 1.0 % |
//!
//! (all cases, times and iterations in `BENCHMARKS.md`). The energy balance's
//! residual error is staircase noise, not a power of `1/N`, so Richardson
//! extrapolation does not improve it (it is already below 0.3 % at 16 cells
//! and below 0.1 % from 64 cells up, where a whole cycle takes 0.35-0.8 s); the mesh criterion converges like
//! `3/N` but irregularly, and extrapolation helps it only sometimes.
//!
//! On layers the energy balance used to stop improving near `1e-3` (rigid
//! base, `a/h = 1`: 0.067, 0.086, 0.091 % at 64, 128, 256 cells) while on
//! the half-space it reaches `7e-6` at 256: the stall was the bias of its
//! local quadratic fits in `(ln r, ln y)` over 35 % of the radius, exact
//! for the half-space's power laws and not for a layer's terms. On a
//! layered body under a curved indenter (any layer thickness since
//! 2026-11-29: a sphere pressed to 0.85 of its radius into a stack of
//! layers about a cell thick came out 12 % under its exact peak force with
//! the wide family, 1.0 % with this one) the family's sets are
//! now 2.5 % of the radius apart and the fits span 10 % (at least one and
//! four cells): 0.0026, 0.017, 0.0014 % on that case, and every layered
//! body of the table below `1e-4` at 256 cells (`BENCHMARKS.md`), for
//! about 2.5 times the solves from 64 cells up. Local cubics over the wide
//! window gave 0.0024 % at 256 cells but doubled the half-space's error at
//! 64 and 128 and lost the thin layer's pull-off at the family's smallest
//! sets; a flat punch keeps the wide family (the fine one moved its
//! pull-off on a layer by -0.5 %). The staircase noise (about `1e-4` at
//! 128 cells, not monotone in `N`) is the next floor. A whole
//! adhesive loading-unloading cycle by the energy balance costs 300-500 CG
//! iterations at 32-64 cells across the pull-off contact, the iterations of
//! five to eight non-adhesive solves on the same grid, each about twice as
//! expensive (it applies the operator and its preconditioner): ten to fifteen
//! non-adhesive solves in time. The mesh criterion takes 3000-6000. See [`adhesion`](super::adhesion) for the methods.
//!
//! Beyond axisymmetry (tables in `BENCHMARKS.md`, tests in
//! `tests/adhesion_shapes.rs` and `tests/edge_release.rs`):
//!
//! | case | reference | 64 | 128 | 256 | order |
//! |---|---|---|---|---|---|
//! | wavy surface, crests along the grid, energy balance | Johnson (1995) pull-off | -1.16 % | -0.46 % | -0.19 % | 1.3 |
//! | wavy surface, crests at 45 degrees, energy balance | Johnson (1995) pull-off | -1.09 % | -0.46 % | -0.19 % | 1.2 |
//! | wavy surface, crests along two cells by one, energy balance | Johnson (1995) pull-off | | -0.46 % | -0.20 % | 1.2 |
//! | wavy surface, crests along the grid, cohesive zone of 8 cells | Johnson (1995) pull-off | -4.27 % | -1.64 % | -0.43 % | 1.9 |
//! | wavy surface, crests at 45 degrees, cohesive zone of 8 cells | Johnson (1995) pull-off | -4.15 % | -1.57 % | -0.51 % | 1.6 |
//! | wavy surface, crests along the grid, cohesive zone of 4 cells (default) | Johnson (1995) pull-off | -1.78 % | +0.34 % | -0.02 % | lattice-trapped |
//! | wavy surface, crests at 45 degrees, cohesive zone of 4 cells (default) | Johnson (1995) pull-off | -1.77 % | -0.61 % | +0.12 % | lattice-trapped |
//!
//! (`N` = lines of cells per wavelength, `alpha = 0.3`: 30 cells across the
//! pull-off contact at 256 along the grid; -0.087 % at 512 along two cells
//! by one.) The local release rates of
//! [`ContactSolver::edge_release`](crate::solver::ContactSolver::edge_release),
//! `N` = cells across the contact:
//!
//! | case | reference | 16 | 32 | 64 |
//! |---|---|---|---|---|
//! | elliptical punch, `b/a = 1/2`, at 0, 30, 45 degrees, centre at five sub-cell offsets, worst of 15 (0.22 % at 128, 0.084 % at 256; the fit in Galin's functions) | onset force | 3.06 % | 1.06 % | 0.39 % |
//! | the same with the window along the edge (before 2026-11-28), 0 and 30 degrees | onset force | | | -0.39 to +0.76 % |
//! | circular punch under moment, mean over the edge (worst cell), angular modes 0 to 2 | `K(theta)` | -1.78 % (1.97 %) | -0.49 % (0.69 %) | -0.19 % (0.34 %) |
//! | JKR sphere's pull-off contact off the cell centres (four positions), mean over the edge (worst cell), nine modes (-0.095 to -0.116 % (0.17 to 0.40 %) at 256) | JKR `G` | -1.4 to -2.3 % (6.8 to 24 %) | -0.80 to -1.18 % (1.4 to 8.1 %) | -0.39 to -0.57 % (0.42 to 3.8 %) |
//! | the same on a film, `a/h = 1.75`, rigid base, two positions (-0.22 % (0.38 to 0.99 %) at 128) | exact layered JKR, `G = dgamma` | -1.5 to -2.3 % (5.6 to 21 %) | -0.84 to -0.95 % (1.3 to 7.2 %) | -0.38 to -0.40 % (0.40 to 2.2 %) |
//! | strip off the trough of a sinusoid, worst edge of either orientation (20, 40, 80 cells across) | exact asymmetric strip `G` | -7.0 % | -0.83 % | -0.40 % |
//!
//! The cohesive zone on compact contacts (default curvature correction;
//! `N` cells across the pull-off contact; `BENCHMARKS.md`, "Adhesion
//! through a resolved cohesive zone" and "The cohesive zone's width"):
//!
//! | case | reference | 16 | 32 | 64 | 128 | order |
//! |---|---|---|---|---|---|---|
//! | JKR sphere, half-space (+0.045 % at 256: the narrow zone's lattice noise) | JKR pull-off | -1.95 % | -0.61 % | -0.13 % | -0.0037 % | 2 to 128 |
//! | JKR sphere, half-space, zone of 8 cells (the default until 2026-11-27) | JKR pull-off | -6.39 % | -2.42 % | -0.66 % | -0.17 % | 2 |
//! | JKR sphere, film `h = a` on glass (zone within a quarter of the film: 2, 4, 4, 4 cells) | exact layered JKR | -1.08 % | -1.09 % | -0.24 % | +0.0027 % | 2 |
//! | JKR sphere, that film on a layer ten times stiffer, `2a` thick, on glass (+0.036 % at 256) | exact stacked JKR | -1.20 % | -1.01 % | -0.24 % | -0.0025 % | 2 to 128 |
//! | JKR sphere, film `a/h = 2.93` on a rigid base (scene cycle, `examples/accuracy.rs`; magnitudes; zone of two cells to 64 cells across, 4 at 128) | exact layered JKR | 2.4 % | 0.25 % | 0.035 % | 0.015 % | none yet |
//! | Kendall's flat punch (the zone alone) | Kendall (1971) | refused: pinned at the rim (-23 % at 64); a scene unloads along the peeling path below | | | | |
//!
//! The pull-off of bonded flat punches along their peeling paths
//! ([`ContactSolver::peel_punch`](crate::solver::ContactSolver::peel_punch);
//! `N` cells across; `tests/peel_punch.rs`, `BENCHMARKS.md`, "Local release
//! rates along an edge"):
//!
//! | case | reference | 16 | 32 | 64 | 128 |
//! |---|---|---|---|---|---|
//! | Kendall's disc | Kendall (1971), radius of the staircase's area less the edge shift | +0.66 % | +0.37 % | | |
//! | Kendall's disc on five grids within 1 % of each other's spacing (`examples/punch_peel` with `STRETCH`; the disc's edge by its angular modes) | Kendall (1971), the face's radius | | | -0.48 to -0.08 % | -0.24 to -0.04 % |
//! | a disc tilted by a tenth or a quarter of Kendall's depth towards 0 or 30 degrees, five sub-cell positions, onset | exact force-and-moment onset of the staircase's disc | | +0.37 to +1.20 % | +0.21 to +0.51 % | +0.11 to +0.24 % |
//! | scene: a disc tilted by a tenth of Kendall's depth, pull-off (`tests/scene_tilted_punch.rs`) | over the exact onset (the path comes off within 1 % beyond) | 1.0094 | 1.0050 | 1.0015 | 1.0047 |
//! | scene: the untilted punch through the zone and its path, half-space / film `a/h = 2` | Kendall / exact layered Kendall | | -0.07 / +0.50 % | -0.26 / -0.14 % | -0.60 / -0.45 % |
//! | Kendall's disc on a film, `a/h` = 1 / 2, rigid base | exact layered Kendall (`Axisymmetric`) | | +0.38 / +0.39 % | / +0.23 % | |
//! | square, along the grid / 30 / 45 degrees (uN over `N^1.5`) | none: about 472 | | 477.1 (along; 476.3 / 480.9 / 476.5 before 2026-11-28) | 472.2 / 471.4 / 476.0 | 472.4 / 472.3 / 471.8 |
//! | disc tilted by a tenth / a quarter of Kendall's depth, onset | punch under force and moment (exact) | | +1.0 / +1.6 % | +0.31 / +1.1 % | |
//!
//! For the `1/N` quantities Richardson extrapolation of two resolutions
//! ([`richardson`](crate::scene::richardson)) gains one to two orders of
//! magnitude at the cost of the coarser run; [`Scene::converge`] doubles the
//! resolution until a requested accuracy is reached. It does not help the
//! Hertz force (already second order) nor the quantities whose error is
//! staircase noise (both pull-offs with the energy balance).
//!
//! [`Scene::converge`]: crate::scene::Scene::converge
//!
//! ## Cost
//!
//! A non-adhesive solve is a constrained conjugate-gradient iteration
//! (Polonsky & Keer 1999) preconditioned with the compliance's inverse on a
//! box around the contact (Vollebregt 2014) and started, when cold, from
//! the solution on the grid of half the cells each way (recursively down to
//! 64 cells). On the peers' Hertz benchmark (paraboloid on a half-space,
//! contact radius a quarter of the grid, tolerance 1e-8) it takes 11 to 15
//! iterations from N = 256 to N = 4096. Each applies the operator once to
//! the search direction (0.6 to 0.7 of a plain FFT round trip of the padded
//! `2N x 2N` grid, or the next fast FFT length above `2N - 1` when `N` is
//! not a power of two: only the data rows are transformed), once more when
//! clamping at zero moved pressures off that direction (by direct summation
//! over the influence coefficients when few cells clamped, see
//! [`InfluenceCoefficients::add_loads`](crate::kernel::InfluenceCoefficients::add_loads)),
//! plus a periodic FFT round trip on the contact's box (in single precision:
//! the preconditioner only shapes the search direction) and a few passes
//! over the working set's rows. After a step whose clamping needed a
//! convolution (most iterations of a rough contact) the next takes its
//! length from the direction's energy `t . K t`, summed over the spectrum
//! of a forward transform in single precision (a step length, whose
//! rounding of about `1e-7` the displacement's update in double precision
//! does not carry), and moves the displacement by one convolution of the
//! whole change of the pressure. One thread, an iteration costs 1.11 (N = 512) and
//! 1.04 (N = 1024) plain padded round trips from the multi-resolution
//! start, 1.12 and 1.02 warm-started, and 1.50 and 1.52 without the
//! multi-resolution start, when the contact set changes in most iterations
//! (criterion, `benches/solver.rs`). A warm start goes through the coarse
//! grids as well (see
//! [`ContactSolver::solve_depth`](crate::solver::ContactSolver::solve_depth)).
//! Whole solves on this 2-core machine (one thread / two threads, force
//! control, coarse solvers built; 2026-11-25, `BENCHMARKS.md` "Speed: the
//! peers' Hertz benchmark" gives the load and the earlier runs):
//!
//! | N | iterations | time, 1 thread | time, 2 threads | peak memory |
//! |---|---|---|---|---|
//! | 256 | 13 | 0.03 s | 0.02 s | 12 MB |
//! | 512 | 12 | 0.19 s | 0.07 s | 33 MB |
//! | 1024 | 12 | 0.62 s | 0.34 s | 115 MB |
//! | 2048 | 12 | 2.9 s | 1.6 s | 444 MB |
//! | 4096 | 11 | 12.6 s | 7.4 s | 1613 MB |
//!
//! A solver needs about 100 to 115 bytes per cell of the unpadded grid on
//! an isolated grid from N = 2048 up, under 100 from 4096 on
//! (`BENCHMARKS.md`, "Speed: rough contacts on large grids"): the
//! operator's half-spectra of the grid's rows (16 bytes, one buffer, which
//! the preconditioner's FFT borrows) and its kernel spectrum (8: it is
//! even, and only its non-negative row wavenumbers are kept), the influence
//! coefficients (8, kept for direct sums up to
//! [`KEEP_INFLUENCE_CELLS`](crate::kernel::KEEP_INFLUENCE_CELLS) cells and
//! dropped beyond), the solver's per-cell vectors (about 70, one of which
//! holds the preconditioner's box while it is idle), and the box's
//! multiplier; the coarser solvers of the multi-resolution start keep only
//! their kernels and plans between starts (no influence coefficients under
//! a fine grid that keeps none) and work in the finer solver's vectors. [`kernel::memory_estimate`](crate::kernel::memory_estimate)
//! gives the estimate a solver reserves before allocating.
//!
//! Rough contacts (a self-affine surface of Hurst exponent 0.8 down to four
//! cells) take more iterations, growing with the grid (about 1.3 times per
//! doubling) as the surface gains roughness; the constrained conjugate
//! gradients keep their conjugation when the working set grows (a
//! projected Fletcher-Reeves step), where Polonsky and Keer restart (121
//! iterations before, 46 after, on the periodic half-space of the tamaas
//! comparison at 1024 x 1024). On an isolated grid a contact spread over
//! the whole grid keeps its preconditioner box's margin (the grid
//! zero-padded): the rough film of those tables took 27 / 36 / 48
//! iterations at 1024^2 / 2048^2 / 4096^2, 31 / 41 / 58 with a box cut to
//! the grid, whose periodic images coupled opposite edges; 62 at 8192^2
//! (2026-11-29). A cold solve's early iterations in single precision (until
//! the pressure changes by less than `1e-5` an iteration, then the
//! displacement recomputed in double) and two restarts of its conjugation
//! brought that to 26 / 34 / 43 (2026-12-02; the 4096^2 film then solved
//! in 18 to 25 s on two threads as this machine's speed drifts). The
//! preconditioner extends the residual by zero off the working set, which
//! leaves a jump at every edge of every patch; carrying it one cell past
//! the edges (the four-neighbour mean) and gathering the result back by
//! the transpose (`P E^T M^-1 E P`, still symmetric and positive) brought
//! the count to 17 / 20 / 25 / 34 / 41 from 512^2 to 8192^2 (the periodic
//! film's 17 / 20 / 26 / 34 / 42), at the same cost an iteration on an
//! isolated grid: the 4096^2 film in 15.3 to 19.0 s, against 17.7 to 25.9
//! s without, in runs alternating through the machine's drift. On
//! periodic grids, whose transforms are cheaper, the extension's two
//! passes cost up to a fifth of an iteration and take back part of the
//! gain (`BENCHMARKS.md`, "The box inverse past the contact's edges").
//! With the roughness's cut-off fixed as the grid is refined the count
//! stays nearly flat: from 512^2 to 8192^2 the isolated film 16 / 16 / 16
//! / 17 / 20, the periodic film 13 / 14 / 15 / 16 / 19, a periodic
//! half-space 20 / 21 / 21 / 22 / 24, a periodic coated stack 39 to 52;
//! an isolated coated stack over a soft base 45 / 46 / 54 / 55 / 67
//! (2026-12-05, `BENCHMARKS.md`, "The choice on fixed roughness and on one
//! patch"). The growth on the surfaces above is the surface's, which gains
//! a scale with every doubling. On a grid even each
//! way the coarse levels take Galerkin's coarse operator `R K P` of the
//! level above from its spectrum (nothing evaluated on the coarse grids:
//! 1.5 s less of the isolated 4096^2 film's start). The coarse levels of
//! the multi-resolution start stop at their tolerance with overlap left,
//! which the fine solve takes in, and a level started from its own coarser
//! level stops at 3 % of how far that start was (its first iteration's
//! change) when that is looser: a rough surface's levels start far apart,
//! so they stop sooner (a fifth to a third fewer coarse iterations), a
//! smooth contact's start near and keep their tolerance. The level right
//! under the solve keeps its tolerance whatever its start: the solve
//! starts from its solution, and a loosened one set the tamaas problem at
//! 8192^2 off on a zig-zag of its contact (up to 64 fine iterations over
//! seven seeds, 44 to 49 since, 39 to 43 with the rule for new overlap
//! below; `BENCHMARKS.md`, "The start level under the solve").
//! Tables
//! (iterations, times and memory from 256 x 256 to 8192 x 8192, and beside
//! tamaas) in `BENCHMARKS.md`, "Speed: rough contacts on large grids" and
//! "Rough contacts beside tamaas".
//!
//! The box serves a contact of one scale of patches well and one of many
//! scales worse: once the set has settled, the residual's rate slows with
//! every doubling of a rough surface's grid. A coarse correction over the
//! working set's cells of `16 x 16` blocks, inside which the box acts
//! (two-level balancing, Mandel 1993, Commun. Numer. Meth. Eng. 9, 233;
//! the coarse matrix from the grid of blocks:
//! [`ContactSolver::set_coarse_blocks`](crate::solver::ContactSolver::set_coarse_blocks)),
//! holds that rate and makes the count grow like `log N`, for two more
//! applications of the compliance and two solves on the grid of blocks an
//! iteration (on an isolated grid the applications go through the
//! multi-resolution start's coarse level, `P A_c P^T / 4`, at a quarter of
//! their cost: the 4096^2 film in 17.2 to 19.1 s against 19.3 to 22.7 s;
//! `BENCHMARKS.md`, "The two-level preconditioner through the coarse
//! level"). It joins once the contact count has settled (built over a
//! working set that still has cells to shed, it spreads pressure over
//! them). The solver takes it by itself where it pays
//! ([`ContactSolver::set_automatic_coarse_blocks`](crate::solver::ContactSolver::set_automatic_coarse_blocks),
//! the default): for a contact of more than 256 patches whose box
//! converges slowly (a mean factor of at least 0.3 an iteration while the
//! count settles) on a grid of at least 2048^2 cells, where on the rough
//! films, a periodic half-space and
//! a coating over a soft base it took 0.73 to 0.94 times the box's time
//! (the isolated film at 2048^2 1.13, 0.99 since its applications go
//! through the coarse level); from 1024^2 if the factor is at
//! least 0.5, where the periodic half-space and the coated stacks took
//! 0.67 to 0.90 times the box's time and the films, whose boxes decide on
//! 0.40 to 0.46, keep the box (the blocks would take 0.83 to 1.34 times
//! it; `BENCHMARKS.md`, "The blocks on smaller grids"); on smaller grids
//! and for contacts of few patches, the box: a sphere, a
//! flat punch or a cone on 2048^2 cells took 1.4 to 1.8 times the box's
//! time with the blocks, even a punch on a coated stack whose box
//! converged slowly (a factor of 0.8); rough contacts of fixed roughness,
//! which keep the box by the same test, forgo up to a quarter on a coated
//! stack and save up to a third on the films (`BENCHMARKS.md`, "A
//! two-level preconditioner for rough contacts", "The coarse correction
//! once the contact settles", "The solver's own choice of preconditioner"
//! and "The choice on fixed roughness and on one patch", have the counts,
//! times and memory from 512^2 to 8192^2). What a solve chose, after how
//! many iterations and on which factor:
//! [`ContactSolver::last_preconditioning`](crate::solver::ContactSolver::last_preconditioning).
//!
//! After the multi-resolution start a rough contact's fine asperities
//! overlap all over the prolonged contact; let in at once (Polonsky and
//! Keer's rule) they take load from their neighbours and the contact
//! overshoots its final size before it is shed again, a few per cent an
//! iteration. A fine solve from no warm start of the caller's lets new
//! overlap away from the contact's edge join only if it is at least as
//! deep as the overlap's mean (the most violated constraints first, as
//! active-set methods add them; cells beside the contact in their row
//! always join, so a Hertzian contact, whose overlap is a ring at its
//! edge, keeps its 12 to 13 iterations). On a solve from the
//! multi-resolution start, once the contact shrinks (its count fell in
//! the iteration before), the overlap beside it is held to the same
//! threshold: a retreating edge does not take back shallow overlap the
//! next steps shed again. Together, on a coated stack at 4096^2 / 8192^2
//! 51 / 67 fine iterations against 63 / 81 without either, the periodic
//! half-space at 8192^2 a mean of 40.6 against 46.9 over seven seeds
//! (0.96 of the time against the mean alone on one seed), the films the
//! same counts at up to 2 % more time (`BENCHMARKS.md`, "Only the deeper
//! overlap joins, at no extra pass" and "The edge held while the contact
//! shrinks").
//!
//! Most of the overlap that still joined was wrong, and ever more of it as
//! the grid refines: in the early fine iterations the gap's error is
//! smooth, so a shallow overlapping cell is as likely the error of the
//! pressures around it as a new asperity. The gaps of the cells in contact,
//! zero at the solution, measure that error: smoothed along the row by a
//! normalised Gaussian of 8 cells (Knutsson and Westin's normalised
//! convolution, 1993), they estimate it near each overlapping cell, and a
//! fine solve from the multi-resolution start keeps out a cell whose gap
//! less the estimate is at least zero (the deepest always joins; rows only,
//! so a split solve needs no exchange). The periodic half-space then takes
//! 20.0 / 21.5 / 26.5 / 31.1 fine iterations from 1024^2 to 8192^2 (over
//! four seeds, seven at 8192^2; 21.5 / 26.75 / 31.25 / 40.6 before), about
//! five more a doubling at the top, like log N; the coated stack at
//! 4096^2 / 8192^2 43 / 49, at 0.87 of the time at 4096^2, the half-space
//! at 8192^2 0.91; the films from one more to three fewer, the
//! Hertzian contacts as before (`BENCHMARKS.md`, "New overlap the gap
//! error explains stays out").
//!
//! ### Rough contacts: the contact area and the kernel
//!
//! The same seeded self-affine surface (Hurst 0.8, rms slope 0.1, roll-off
//! at a quarter of the period, cut-off at four cells) pressed into a
//! periodic half-space at a mean pressure of `0.01 E*` comes out with 20.9 %
//! of its area in contact here and 22.4 % in tamaas (2.9) on 128 x 128
//! cells. The difference is the discretisation: this crate's influence
//! coefficients are those of a uniform pressure over each cell, tamaas'
//! the point spectral kernel `2/(E* q)` at each wavenumber, which is
//! stiffer near the grid's Nyquist wavenumber, where the surface's shortest
//! waves are. Fourier-interpolating the same surface onto grids 2, 4 and 8
//! times finer (`benches/peers/rough.py --refine 128`, `BENCHMARKS.md`),
//! both fractions fall at first order in the cell size to the same limit,
//! 20.19 % (Richardson extrapolation of the two finest, either code):
//!
//! | cells per shortest wavelength | 4 | 8 | 16 | 32 |
//! |---|---|---|---|---|
//! | this crate | 20.886 % | 20.554 % | 20.377 % | 20.285 % |
//! | tamaas | 22.351 % | 21.216 % | 20.686 % | 20.440 % |
//!
//! The cell-integrated coefficients carry about a third of the point
//! kernel's error at every resolution (0.69 against 2.16 points of area at
//! four cells per wavelength); a surface cut off at four cells is resolved
//! to about 3 % of its contact area here, 11 % with the point kernel.
//!
//! The mean gap `u_bar` ([`Solution::mean_gap`](crate::solver::Solution::mean_gap))
//! and the interfacial stiffness `-dp_bar/du_bar` between loads of a force
//! protocol, against Westergaard's wavy surface (`u_bar / D = 1 - s + s ln
//! s`, `s = p_bar/p*`; `tests/interface.rs`): the mean gap within 8.1e-4,
//! 2.0e-4 and 9.2e-6 at 128, 256 and 512 cells per wavelength (`s` = 0.1
//! to 0.7), the stiffness within 0.07 % at 512.
//!
//! An adhesive cycle by the energy balance takes two warm-started clamped
//! solves of about eight preconditioned iterations per set of the family,
//! with one set per cell of radius (or per 10 % of it).
