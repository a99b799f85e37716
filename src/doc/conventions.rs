//! # Conventions
//!
//! ## Units and signs
//!
//! Everything is SI and `f64`: lengths in m, moduli and pressures in Pa,
//! forces in N, stiffnesses in N/m, works of adhesion in J/m^2.
//!
//! | quantity | positive means |
//! |---|---|
//! | depth `d` | the indenter is pressed into the body (below the undeformed surface) |
//! | pressure `p` | compression; a tensile (adhesive) traction is negative |
//! | force `F` | the indenter pushes on the body; an adhesive pull is negative |
//! | surface displacement `u_z` | into the body (the surface moves down under a push) |
//!
//! ## Materials
//!
//! A [`Material`](crate::Material) is built from Young's modulus `E` and
//! Poisson's ratio `nu`, both explicit. The plane-strain contact modulus
//! `E* = E / (1 - nu^2)` is always called *contact modulus* and is never an
//! input; no parameter anywhere means "either `E` or `E*`".
//!
//! ## Bodies
//!
//! | symbol | meaning |
//! |---|---|
//! | `E1`, `nu1`, `h` | the layer: modulus, Poisson ratio, thickness |
//! | `E2`, `nu2` | the elastic base (half-space) under the layer |
//! | `G = mu1 / mu2` | shear-modulus ratio; `G = 0` for a rigid base |
//! | `kappa_i = 3 - 4 nu_i` | Kolosov's constant (plane strain) |
//! | `t = q h` | wavenumber times thickness, the argument of `R` and `Lambda_g` |
//! | `eps = a / h` | punch (or contact) radius over thickness |
//!
//! A layer of infinite thickness, or of the same material as its elastic
//! base, *is* a half-space of the layer material, and a zero-thickness layer
//! on an elastic base is the base's half-space: the
//! [`Substrate`](crate::Substrate) constructors return
//! [`Substrate::HalfSpace`](crate::Substrate::HalfSpace) for these limits.
//!
//! ## Errors
//!
//! Constructors validate their input and return a typed
//! [`Error`](crate::Error) whose variant and fields name the offending value.
//! Once built, evaluation methods are infallible: they take the free variable
//! (a depth, a contact radius, `q h`) as `f64` and return `f64`. A NaN free
//! variable gives a NaN result, as for the `f64` methods of `std`; every finite
//! (or infinite, where meaningful) argument gives a finite result.
