//! # layered-contact
//!
//! Normal contact of rigid indenters (flat punches, spheres, cones, any shape)
//! with an elastic half-space covered by an elastic layer, with and without
//! adhesion. The layer is bonded to a rigid base or to an elastic half-space.
//!
//! The crate has three parts behind one API:
//!
//! 1. the fundamental solution of the coated half-space turned into BEM
//!    kernels ([`substrate`] for the body and its functions `R(t)` and
//!    `Lambda_g(t)`, [`kernel`] for `u_z(q)`, the influence coefficients and
//!    the FFT compliance operator),
//! 2. [`solver`]: an FFT boundary-element contact solver generic over
//!    [`indenter`] shapes, non-adhesive and adhesive (JKR limit),
//! 3. [`analytic`]: closed forms, series and exact solutions the solver is
//!    checked against.
//!
//! [`scene`] ties them into experiments (substrate, indenter, adhesion,
//! loading protocol, outputs) that serialize to TOML or JSON, and runs them
//! to a requested accuracy. Guide pages: [`doc`].
//!
//! # Conventions
//!
//! * SI units throughout, `f64`.
//! * Depth `d > 0` presses the indenter into the body; pressure `p > 0` is
//!   compressive; force `F > 0` pushes, an adhesive (tensile) force is
//!   negative.
//! * A material is built from Young's modulus `E` and Poisson's ratio `nu`
//!   ([`Material::new`]); the contact modulus `E* = E / (1 - nu^2)` is derived
//!   and called [`Material::contact_modulus`]. `nu` ranges over `[0, 0.5]`,
//!   and `nu = 0.5` is an ordinary case.
//! * Layer quantities carry the index 1 (`E1`, `nu1`, thickness `h`), the base
//!   the index 2; `G = mu1 / mu2` (0 for a rigid base).
//! * Bad input is a typed [`Error`] at construction; no function panics or
//!   returns NaN on valid input.
//!
//! See [`doc::conventions`] for the long form (grids, field arrays and their
//! coordinates, names).
//!
//! # Using it
//!
//! ```toml
//! [dependencies]
//! layered-contact = { git = "<this repository>" }
//! # or, without the command-line tool's dependencies:
//! # layered-contact = { git = "<this repository>", default-features = false, features = ["serde", "parallel"] }
//! ```
//!
//! A sphere pressed into a rubber film on glass, by the boundary-element
//! solver, checked against the exact axisymmetric solution:
//!
//! ```
//! use layered_contact::analytic::Axisymmetric;
//! use layered_contact::indenter::Paraboloid;
//! use layered_contact::solver::{ContactSolver, SolverParams};
//! use layered_contact::{Boundary, Grid, Material, Substrate};
//!
//! let film = Substrate::layer_on_rigid_base(Material::new(0.324e6, 0.48)?, 5e-3)?;
//! // 128 x 128 cells of 50 um around the axis.
//! let grid = Grid::new(128, 128, 50e-6)?;
//! let mut solver = ContactSolver::new(&film, &grid, Boundary::Isolated, SolverParams::default())?;
//! let ball = Paraboloid::new(0.05)?;
//! let (solution, _) = solver.solve_depth(&ball, 0.1e-3, None, &mut ())?;
//!
//! let exact = Axisymmetric::new(&film, 1.0)?.paraboloid(0.05, 0.0)?.at_depth(0.1e-3)?.unwrap();
//! assert!((solution.force / exact.force - 1.0).abs() < 0.01);
//! Ok::<(), layered_contact::Error>(())
//! ```
//!
//! Whole experiments (a loading cycle with adhesion, grid sized from the
//! contact) are [`scene::Scene`]s; they also run from TOML files with the
//! `layered-contact` command-line tool and from Python (`python/`).
//!
//! # Example: a closed form
//!
//! The stiffness of a 5 mm flat punch on a 5 mm rubber film on glass, from the
//! series of Lyashenko, Popov & Borysiuk (2023):
//!
//! ```
//! use layered_contact::{analytic::PunchStiffnessSeries, Material};
//!
//! let rubber = Material::new(0.324e6, 0.48)?;
//! let series = PunchStiffnessSeries::new(rubber, 5e-3)?;
//! let k = series.evaluate(2.5e-3)?;
//! assert!((k.ratio - 1.8857).abs() < 1e-4); // 89 % stiffer than on a half-space
//! Ok::<(), layered_contact::Error>(())
//! ```

#![warn(missing_docs)]

pub mod analytic;
#[cfg(feature = "mpi")]
pub mod distributed;
pub mod doc;
pub mod error;
mod files;
pub mod grid;
pub mod indenter;
pub mod kernel;
pub mod material;
mod numerics;
mod parallel;
pub mod scene;
mod slab;
pub mod solver;
pub mod stress;
pub mod substrate;
pub mod topography;

pub use error::{Error, Result};
pub use grid::{Boundary, Grid};
pub use material::Material;
pub use substrate::{Base, Coating, Substrate};

/// The README's code example, compiled and run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
