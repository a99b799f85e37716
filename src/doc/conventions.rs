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
//! ## Grids and fields
//!
//! A [`Grid`](crate::Grid) of `rows x columns` square cells of side `Delta`
//! is centred on the indenter's axis: cell `(i, j)` has its centre at
//! `x = (i + 1/2 - rows/2) Delta`, `y = (j + 1/2 - columns/2) Delta`. Every
//! field ([`Solution::pressure`](crate::solver::Solution::pressure),
//! `displacement`, `gap`, a [`HeightMap`](crate::indenter::HeightMap)'s
//! heights) is an array of `rows x columns` values, `[i, j]` at that centre,
//! stored row-major; the command-line tool writes them as `.npy` beside
//! `x.npy` and `y.npy`, and the Python package returns them with `x` and `y`.
//!
//! An indenter's height `f(x, y)` is measured from its lowest point,
//! positive away from the body; the gap at depth `d` is
//! `g = f - d + u_z >= 0`.
//!
//! ## Names
//!
//! Indenter shapes live in [`indenter`](crate::indenter)
//! ([`FlatPunch`](crate::indenter::FlatPunch),
//! [`Cone`](crate::indenter::Cone), ...); the closed-form solutions for them
//! on a half-space carry their authors' names in
//! [`analytic`](crate::analytic)
//! ([`BoussinesqPunch`](crate::analytic::BoussinesqPunch),
//! [`SneddonCone`](crate::analytic::SneddonCone),
//! [`Hertz`](crate::analytic::Hertz), [`JkrSphere`](crate::analytic::JkrSphere)).
//!
//! ## Errors
//!
//! Constructors validate their input and return a typed
//! [`Error`](crate::Error) whose variant and fields name the offending value.
//! Once built, evaluation methods are infallible: they take the free variable
//! (a depth, a contact radius, `q h`) as `f64` and return `f64`. A NaN free
//! variable gives a NaN result, as for the `f64` methods of `std`; every finite
//! (or infinite, where meaningful) argument gives a finite result.
