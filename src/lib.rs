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
//! See [`doc::conventions`] for the long form.
//!
//! # Example
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
pub mod doc;
pub mod error;
pub mod grid;
pub mod indenter;
pub mod kernel;
pub mod material;
mod numerics;
pub mod scene;
pub mod solver;
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
