//! # Grids beyond one machine: the solver split across MPI ranks
//!
//! A rough contact of 8192 x 8192 cells needs about 8.7 GB on one
//! process; 32768 x 32768 (the contact-mechanics challenge's scale) needs
//! over 100 GB on an isolated grid. With the `mpi` cargo feature the same
//! solver runs with the grid split across the processes ("ranks") of an MPI
//! run, on one machine or many (tamaas does this with FFTW-MPI,
//! ContactMechanics with muFFT and NuMPI).
//!
//! ## What is split, and how
//!
//! Each rank holds a band of the grid's rows (a slab) of every per-cell
//! vector of the constrained conjugate gradients (Polonsky & Keer 1999,
//! Wear 231, 206). Bands start at multiples of `2^L` rows, `L` the number
//! of coarser grids of the multi-resolution start, so that each rank's
//! band on a coarser grid covers exactly the coarse cells of its fine
//! rows: restriction and prolongation stay on the rank.
//!
//! The compliance is an FFT convolution (zero-padded on an isolated grid).
//! Split, it is the slab-decomposed 2D FFT of distributed FFT libraries:
//!
//! 1. each rank transforms its own rows (real-to-complex);
//! 2. one `MPI_Alltoallv` sends every rank its share of the half-spectrum
//!    columns of all rows (a transpose);
//! 3. each rank transforms its columns, multiplies by its columns of the
//!    kernel's spectrum, and transforms back;
//! 4. a second `MPI_Alltoallv` returns the rows;
//! 5. each rank transforms its rows back (complex-to-real).
//!
//! Every row and column goes through the same 1D transforms as on one
//! process, so the operator itself agrees with the serial one to the last
//! bit. The box preconditioner (Vollebregt 2014, J. Comput. Phys. 257,
//! 333) is the same convolution on a box around the contact (in single
//! precision; the exchanges carry its values as `f64`, exactly), whose rows
//! each rank takes from its band. It carries the residual one cell past
//! the contact's edges first and gathers the result back after (the
//! four-neighbour mean, `kernel::inverse`'s extension): before and after
//! the transform each rank sends its band's first row to the rank before
//! and its last to the rank after (one `MPI_Alltoallv` of two rows each),
//! so that the cells next to a band's edge see their neighbours on the
//! other rank as on one process. Every sum over the grid (the
//! conjugate-gradient products, the force, the contact's bounds) is added
//! over the ranks with `MPI_Allreduce`, so every rank takes the same
//! decisions and the same steps.
//!
//! Only the order in which sums are added differs from one process: the
//! results agree to rounding. `tests/mpi.rs` solves a rough periodic film,
//! a rough isolated half-space on a grid whose coarse grid has an odd
//! number of rows, and a sphere on a film under depth and under force
//! control (the outer ranks' rows then hold no contact), each
//! warm-started through two loads, on 2 and 4 ranks: forces within 2e-15
//! and pressures within 8e-15 of the largest (asserted below 1e-12). The
//! iteration counts differ by at most one (2026-12-02): a serial solver's
//! coarse levels on a grid even each way take Galerkin's operator from
//! the finer level's spectrum
//! ([`ComplianceOperator`](crate::kernel::ComplianceOperator)), of which
//! each rank holds only its columns, so split solvers build theirs from
//! the substrate on each coarse grid; both converge to the same contact.
//!
//! Split solvers take the two-level preconditioner
//! ([`ContactSolver::set_coarse_blocks`](crate::solver::ContactSolver::set_coarse_blocks),
//! and by themselves for a rough contact on a grid of at least
//! [`AUTOMATIC_BLOCKS_CELLS`](crate::solver::AUTOMATIC_BLOCKS_CELLS) cells,
//! 1024^2: [`ContactSolver::set_automatic_coarse_blocks`](crate::solver::ContactSolver::set_automatic_coarse_blocks))
//! as serial ones do, if every rank holds whole rows of blocks (its first
//! row a multiple of the block side: an even split of a grid whose side is
//! a power of two, on a power of two of ranks). Each rank counts its own
//! blocks' cells and pairs, the counts and each application's block sums
//! are added over the ranks (two values a block an iteration, and one a
//! block for each of an application's two coarse solves), and every rank
//! solves the small coarse system itself. Where the rows do not fit, the
//! automatic choice keeps the box and `set_coarse_blocks` refuses
//! ([`Error::InvalidParameter`](crate::Error::InvalidParameter)).
//! `tests/mpi.rs` runs a rough film, periodic and isolated, with blocks
//! of 16 at 2 and 4 ranks (the same iterations as the serial solver with
//! them, the results within 7e-15) and one on 2048^2 cells where serial
//! and split solvers choose for themselves: both take the blocks, in the
//! same iterations, the results within 5e-14.
//!
//! Split solvers run the active-set loops of a solve that finds its set
//! slowly ([`solver`](crate::solver), `src/solver/active_set.rs`) as
//! serial ones do. The test's fifth case is such a contact: a sphere on a
//! stiff layer over a far softer base, whose contact is a ring, solved
//! from a cold start at two depths (2026-12-03): 495 to 1270 iterations
//! split with the loops against 2100 to 2621 without; forces within 3e-14
//! of the serial run's and pressures within 9e-11 of the largest, as
//! without the loops. That ring is ill-conditioned: the paths part on the
//! sums' rounding before the loops start, and a relative change of 1e-14
//! fixes its pressures only to about 1e-10, so the test asserts 1e-9 for
//! its pressures and 1e-12 for everything else.
//! It also runs the tool on a scene file under `mpirun -np 2` and compares
//! the curve with the one-process run.
//!
//! What stays whole on every rank: the kernel's spectrum while it is built
//! (each rank keeps its columns), the influence coefficients it is built
//! from on an isolated grid, and a height map read from a text file. A
//! scene's `.npy` height map (little-endian `float64` in C order, what
//! NumPy writes by default; other layouts are read whole and cut) is read
//! in bands: each rank reads its own rows from the file, and the grid from
//! the header alone. A scene's rough surface is synthesised in shares:
//! every rank draws the whole sequence of random numbers but keeps its
//! band of the spectrum's columns, transforms them, exchanges the blocks
//! once and transforms its rows, so that it holds its own rows only, equal
//! bit for bit to the serial surface's (a unit test checks this on 1 to 5
//! ranks; `tests/mpi.rs` runs the tool on both kinds split and serial). A
//! rank that fails to read its rows stops every rank.
//! [`distributed_memory_estimate`](crate::kernel::distributed_memory_estimate)
//! counts these; `layered-contact check scene.toml --ranks N` prints it.
//!
//! Only the non-adhesive solves run split. The adhesive methods (energy
//! balance, mesh criterion, edge release rates) return
//! [`Error::Unsupported`](crate::Error::Unsupported) on a split solver,
//! and so does a scene that asks for fields or stresses when split (each
//! rank holds only its rows of them).
//!
//! ## Building and running
//!
//! The `mpi` crate (rsmpi) binds the system's MPI library: install Open
//! MPI or MPICH with its headers, and libclang (Debian: `apt-get install
//! libopenmpi-dev openmpi-bin libclang-dev`).
//!
//! ```text
//! cargo build --release --features mpi
//! mpirun -np 4 target/release/layered-contact run examples/scenes/rough_film_split.toml -o out
//! ```
//!
//! Under `mpirun` (Open MPI) or a PMI launcher (MPICH's Hydra, Slurm's
//! `srun`) the tool splits the scene across the ranks; rank 0 prints and
//! writes the curve. Started without a launcher it runs on one process as
//! usual. Set `RAYON_NUM_THREADS` to the cores each rank should use.
//!
//! From Rust, every rank builds the solver and calls every solve with the
//! same arguments:
//!
//! ```text
//! let (universe, _) = mpi::initialize_with_threading(mpi::Threading::Serialized).unwrap();
//! let ranks = layered_contact::distributed::Ranks::new(universe.world())?;
//! let mut solver = ContactSolver::distributed(&body, &grid, Boundary::Periodic, params, &ranks)?;
//! let (solution, warm) = solver.solve_force(&surface, force, None, &mut ())?;
//! // solution.force, .contact_area, .depth: the whole grid's, on every rank;
//! // solution.pressure, warm: this rank's rows, solver.local_rows().
//! ```
//!
//! ## A 32768 x 32768 rough contact on a Slurm cluster
//!
//! `examples/slurm/rough_32768.sbatch` runs
//! `examples/scenes/rough_32768.toml` (the rough film of
//! `rough_film_split.toml` at 32768 cells a side, periodic) on 16 ranks.
//! The memory per rank it asks for is what `check --ranks 16` predicts for
//! that scene; the script's comments give the numbers. Timings measured on
//! this machine (two ranks) are in `BENCHMARKS.md`, "Split across MPI
//! ranks".
