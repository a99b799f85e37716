//! Guide pages: long-form documentation that does not belong to one item.
//!
//! * [`conventions`]: units, signs, names.
//! * [`theory`]: the coating factor, the Green's function and the influence coefficients.
//! * [`axisymmetric`]: the exact axisymmetric solutions and their Fredholm equation.

pub mod axisymmetric;
pub mod conventions;
pub mod theory;
