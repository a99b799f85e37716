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
//! | cell compliance `Delta / E*` | `[1e-280, 1e280]` m/Pa | [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new) | `InvalidParameter` |
//! | grid | at most `2^15` cells per axis, `2^26` in all, and memory that can be had | [`Grid::new`](crate::Grid::new), [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new) ([`memory_estimate`](crate::kernel::memory_estimate)) | `InvalidGrid`, `OutOfMemory` |
//! | scene `cells_across`, `margin`, `steps`, `pull_off_bisections` | `8..=8192`, `[0, 10]`, `1..=100000`, `0..=60` | [`Scene::validate`](crate::scene::Scene::validate) | `InvalidParameter` |
//! | works of adhesion | finite, `>= 0`, advancing `<=` receding | solvers and scenes | `InvalidParameter` |
//!
//! ## Mechanisms
//!
//! * **Bounded loops.** Every loop whose count comes from input has a bound
//!   checked up front: protocol steps, bisections, grid growth, unloading
//!   past the surface (the increment doubles beyond `-max_depth`, and the
//!   run stops at `-20 max_depth` with `NoConvergence`), solver iterations,
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
//!
//! ## How it is tested
//!
//! * `tests/promise.rs`: one regression test per finding of a hostile
//!   review (514 extreme API cases, 351 mutated scene files), each of which
//!   hung, returned NaN or a wrong number before its fix.
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
//!   (default 60 s).
