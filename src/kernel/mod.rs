//! The coated half-space's fundamental solution turned into BEM kernels.
//!
//! * [`FourierCompliance`]: `u_z(q)`, the surface displacement of a unit
//!   point force in Fourier space.
//! * [`InfluenceCoefficients`]: its cell-integrated real-space form for the
//!   isolated problem.
//! * [`ComplianceOperator`]: pressure -> displacement by FFT, isolated or
//!   periodic, built once and applied many times.
//!
//! The derivation of the influence coefficients is in
//! [`doc::theory`](crate::doc::theory).

mod cell;
mod convolution;
mod even_convolution;
mod fourier;
mod influence;
mod inverse;
mod operator;
mod radial;

pub(crate) use convolution::wavenumber;
pub(crate) use even_convolution::EvenConvolution;
pub use fourier::FourierCompliance;
pub use influence::{InfluenceCoefficients, MAX_TAIL_ERROR};
pub(crate) use inverse::{BoxInverse, Residual};
pub(crate) use operator::ShareBuffer;
pub use operator::{
    check_film, distributed_memory_estimate, memory_estimate, ComplianceOperator,
    DIRECT_LOADS_PER_LOG2, KEEP_INFLUENCE_CELLS, MIN_THICKNESS_OVER_SPACING,
};
