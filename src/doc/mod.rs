//! Guide pages: long-form documentation that does not belong to one item.
//!
//! * [`conventions`]: units, signs, names.
//! * [`theory`]: the coating factor, the Green's function and the influence coefficients.
//! * [`axisymmetric`]: the exact axisymmetric solutions and their Fredholm equation.
//! * [`bottom_effect`]: the small-indentation series AFM users fit against the exact solution.
//! * [`multilayer`]: stacks of bonded layers: the recursion for the coating factor, and how the kernels split it by interface.
//! * [`subsurface`]: stresses inside the layers and at their interfaces, and where a coating first yields.
//! * [`adhesion`]: the two JKR adhesion methods, energy balance and mesh criterion, and the local release rates along an edge.
//! * [`accuracy`]: what each part achieves, and what it costs.
//! * [`distributed`]: one grid split across the ranks of an MPI run (the `mpi` feature).
//! * [`scene_files`]: every key of a scene file, its type, default and unit; the JSON Schema.
//! * [`reliability`]: the promise (no panic, hang, NaN or silent wrong answer), the guaranteed ranges, and how they are tested.

pub mod accuracy;
pub mod adhesion;
pub mod axisymmetric;
pub mod bottom_effect;
pub mod conventions;
pub mod distributed;
pub mod multilayer;
pub mod reliability;
#[cfg(feature = "serde")]
pub mod scene_files;
pub mod subsurface;
pub mod theory;
