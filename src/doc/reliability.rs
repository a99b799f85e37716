//! # Reliability: the promise and how it is kept
//!
//! **No input makes the crate panic, hang, or return a NaN or infinity
//! inside an `Ok`, and it never returns a silently wrong answer.** Bad or
//! unresolvable input is a typed [`Error`](crate::Error) that names the
//! value and the range it should lie in.
//!
//! ## Ranges that are guaranteed
//!
//! Checked where each quantity is built:
//!
//! | quantity | accepted | where | otherwise |
//! |---|---|---|---|
//! | Young's modulus `E` | `[1e-150, 1e150]` Pa | [`Material::new`](crate::Material::new) | `InvalidYoungsModulus` |
//! | Poisson's ratio `nu` | `[0, 0.5]` | [`Material::new`](crate::Material::new) | `InvalidPoissonRatio` |
//! | layer over base shear moduli `mu1/mu2` | at most `1e7` | [`Substrate::layer_on_elastic_base`](crate::Substrate::layer_on_elastic_base) | `InvalidParameter` |
//! | layer on a rigid base, `h / Delta` | at least `1e-3`; below `0.5` only where uniaxial strain describes the film (see [`check_film`](crate::kernel::check_film)) | [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new) | `InvalidParameter` |
//! | top layer on any support (elastic base, rest of a stack), `h1 / Delta` | at least `0.5`, or a film and support whose compliance at the cell's wavenumber is resolvable (`>= 1e-4` of the layer's) with squeeze flow below 1 % of it: a nearly incompressible film on a support that acts as rigid is refused | [`check_film`](crate::kernel::check_film) | `InvalidParameter` |
//! | isolated influence coefficients | tail error estimate at most `1e-6` (a coating `1e3` or more times stiffer than its base: grid diagonal at most 8192 coating thicknesses) | [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new) | `InvalidParameter` |
//! | load | penetration `0` or at least `1e-100 Delta`; force `0` or at least `1e-100 E* Delta^2` | [`solve_depth`](crate::solver::ContactSolver::solve_depth), [`solve_force`](crate::solver::ContactSolver::solve_force) | `InvalidParameter` |
//! | files read (scene, `.npy` and text height maps) | regular files of at most 16 MiB, 513 MiB and 2 GiB; a `.npy` header's shape within the bytes that follow it | [`Scene::read`](crate::scene::Scene::read), [`HeightMap::from_npy`](crate::indenter::HeightMap::from_npy), [`HeightMap::from_text`](crate::indenter::HeightMap::from_text) | `SceneFile`, `HeightMapFile` |
//! | rough surfaces | 2 to 32768 cells a side | [`Scene::validate`](crate::scene::Scene::validate) | `InvalidParameter` |
//! | Python arrays | at most `2^27` values per call, shapes checked before any copy | the bindings | `InvalidInputError` |
//! | cell compliance `Delta / E*` | `[1e-280, 1e280]` m/Pa | [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new) | `InvalidParameter` |
//! | grid | at most `2^15` cells per axis, `2^30` in all, and memory that can be had | [`Grid::new`](crate::Grid::new), [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new) ([`memory_estimate`](crate::kernel::memory_estimate)) | `InvalidGrid`, `OutOfMemory` |
//! | scene `cells_across`, `margin`, `steps`, `pull_off_bisections` | `8..=8192`, `[0, 10]`, `1..=100000`, `0..=60` | [`Scene::validate`](crate::scene::Scene::validate) | `InvalidParameter` |
//! | works of adhesion | finite, `>= 0`, advancing `<=` receding | solvers and scenes | `InvalidParameter` |
//! | a solver split across MPI ranks (feature `mpi`) | non-adhesive solves only; scenes without fields or stresses; at most one rank per band of `2^L` rows (`L` multi-resolution levels); at most `2^31` values exchanged per rank; the two-level preconditioner only where every rank holds whole rows of its blocks (else the box, and `set_coarse_blocks` refuses); every rank stops with an error when one does (no rank waits in a collective for one that has returned) | [`ContactSolver::distributed`](crate::solver::ContactSolver), the adhesive methods, [`Scene::run_on`](crate::scene::Scene::run_on) | `Unsupported`, `InvalidParameter`, `OtherRankFailed` (on the ranks that did not fail themselves) |
//!
//! ## Mechanisms
//!
//! * **Bounded loops.** Every loop whose count comes from input has a bound
//!   checked up front: protocol steps, bisections, grid growth, unloading
//!   past the surface (the increment doubles beyond `-max_depth`; with the
//!   energy balance the run goes on past the exact jump-off, which a
//!   cycle a few nanometres deep finds thousands of loading depths above
//!   the surface; with the cohesive zone and the mesh criterion it stops
//!   with `NoConvergence` past the larger of `-4096 max_depth` and four
//!   times Kendall's pull-off depth of a punch as wide as the grid on the
//!   body's softest material, which no contact the grid holds passes in
//!   the JKR limit), solver iterations,
//!   the adhesive active-set rounds, the energy balance's family widenings,
//!   the exact solver's Nystrom order and bracket searches, the FFT-size
//!   search (a power of two lies within `[n, 2n]`).
//! * **Finite before `Ok`.** Every solve checks its scalars (force, depth,
//!   moments, contact area, residual) before returning; an overflow in the
//!   inner iterations (depths or heights near `1e300`, forces near `1e299`)
//!   is `Error::NonFinite`, not a `NoConvergence` with an infinite residual.
//! * **Singular problems refused.** Full contact under depth control on a
//!   periodic grid without a rigid base (the mean pressure is undetermined)
//!   is `Error::Unsupported`; a pull beyond the pull-off force is
//!   `Error::NoEquilibrium`; an adhesive family that splits into patches
//!   is `Error::Unsupported` for the energy balance.
//! * **Flags where the answer may be truncated.** A contact that touches the
//!   outer ring of an isolated grid sets
//!   [`Solution::edge_contact`](crate::solver::Solution::edge_contact);
//!   scenes regrow the grid, and the energy balance reports
//!   `Error::ContactReachesEdge`.
//! * **Bonded versus unilateral.** [`LayeredFlatPunch`](crate::analytic::LayeredFlatPunch)
//!   is the bonded solution; it reports its least pressure and whether it
//!   holds without adhesion.
//! * **NaN in, NaN out** for the closed forms of [`analytic`](crate::analytic),
//!   never a silent 0.
//! * **Derived quantities checked where they are built.** The kernel's
//!   tail error estimate, the top layer against its support, a `.npy`
//!   header's shape against the file's length, an array's shape against
//!   the limits before a copy.
//! * **Interruptible.** [`ContactSolver::set_interrupt`](crate::solver::ContactSolver::set_interrupt)
//!   sets a check asked after every iteration and every scene step
//!   (`Error::Interrupted`): Ctrl-C stops a Python run within about a
//!   step.
//! * **First touch.** A JKR contact jumps in when the indenter touches, not
//!   when a cell centre does: a depth-driven adhesive scene whose depth
//!   reaches no cell centre moves to a grid with a cell centre on the axis.
//! * **A tool that cannot write says so.** A closed or full standard output
//!   ends the tool with status 1 and a sentence, not a panic.
//!
//! ## How it is tested
//!
//! * `tests/promise.rs` and `tests/promise_round3.rs`: one regression test
//!   per finding of two hostile reviews (issues 12 and 24), each of which
//!   hung, aborted, returned NaN or a wrong number before its fix; the
//!   physical ones against bounds (a stiffer coating carries more, a film
//!   on a support carries the support's force) or exact solutions (JKR,
//!   the lubrication limit of an incompressible film).
//! * `tests/hard_cases.rs`: incompressible and thin layers, contrasts from
//!   `1e-6` to `1e100`, extreme wavenumbers and depths, and seeded property
//!   tests over the parameter box, every case under a time bound (a hang
//!   fails, it does not stall). `LAYERED_CONTACT_PROPTEST_CASES=3000 cargo
//!   test --release --test hard_cases` is the heavy run.
//! * `tests/fuzz_scenes.rs`: scene files (TOML and JSON) mutated at random
//!   (extreme numbers, swapped kinds, deleted, duplicated or swapped lines,
//!   inserted bytes), parsed, validated and run at reduced resolution, each
//!   under a time bound: a curve with finite numbers or a typed error.
//!   `cargo test` runs 96 cases; `LAYERED_CONTACT_FUZZ_CASES=100000 cargo
//!   test --release --test fuzz_scenes` is the large run.
//!   `LAYERED_CONTACT_CASE_SECONDS` sets the time bound of one case
//!   (default 60 s), `LAYERED_CONTACT_FUZZ_SEED` the seed (default 12) so
//!   that a large run can draw other cases.
//! * `tests/fuzz_npy.rs`: `.npy` height maps built by hand (C and Fortran
//!   order, other dtypes and byte orders, other ranks) and mutated (header
//!   shapes replaced by extreme or lying values, bytes flipped, inserted or
//!   cut off): a height map of finite heights or a typed error, each case
//!   time-bounded. 96 cases in `cargo test`; the same
//!   `LAYERED_CONTACT_FUZZ_CASES` sets a large run.
//! * `tests/reference_sweep.rs`: random axisymmetric scenes (an untilted
//!   punch, paraboloid, sphere or cone, with or without adhesion, on every kind
//!   of body, moduli and thicknesses over decades, Poisson's ratios up to
//!   0.5) driven through a depth cycle at 16 cells across and compared with
//!   their exact values ([`Scene::reference`](crate::scene::Scene::reference)):
//!   within a tolerance of the discretisation, or a typed error that names
//!   a limit of the method (a failed iteration fails the test). 12 cases in
//!   `cargo test`; `LAYERED_CONTACT_REFERENCE_CASES=2000` a large run,
//!   `LAYERED_CONTACT_REFERENCE_SEED` its seed (default 7).
