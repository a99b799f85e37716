//! # Accuracy and its cost
//!
//! What to expect from each part, measured by the `accuracy` example
//! (`cargo run --release --example accuracy`, which regenerates
//! `BENCHMARKS.md`) and asserted by the tests.
//!
//! ## Analytic and exact solutions
//!
//! * `R(t)`, `Lambda_g(t)`: relative error below `1e-15` against 80-digit
//!   references, for every `t`, base and Poisson ratio.
//! * `a_m`: relative error about `2e-16` for `m <= 2`.
//! * [`Axisymmetric`](crate::analytic::Axisymmetric): converged to `1e-11`
//!   (the Nystrom order doubles until results change by less); about 70
//!   microseconds per flat-punch stiffness up to `a/h = 2`, 3 ms at
//!   `a/h = 10`, 0.1 s at `a/h = 50`.
//!
//! ## Influence coefficients
//!
//! Against an independent quadrature, below `1e-14` of the self-coefficient
//! for `h/Delta` from 0.5 to `1e6` on rigid, stiff and soft bases; thin
//! layers (`h/Delta = 1e-3`) settle by the uniaxial-strain compliance to
//! `1e-12`. The FFT operator equals the dense sum to `1e-12`.
//!
//! ## The BEM
//!
//! The discretisation error falls like `1/N` with `N` cells across the
//! contact:
//!
//! | quantity | error at `N = 64` | order |
//! |---|---|---|
//! | flat-punch stiffness, half-space or layer (equal-area grid) | 0.35-0.8 % (from below) | `1/N` |
//! | Hertz force | `7e-5` | about `1/N^2` |
//! | Hertz contact radius | 0.5 % | staircase, `1/N` |
//! | Kendall pull-off (flat punch) | 0.3 % | about `1/N` |
//! | JKR sphere pull-off | 3 % (6-11 % at 10-20 cells per pull-off radius) | slow, edge criterion |
//!
//! For the `1/N` quantities Richardson extrapolation of two resolutions
//! ([`richardson`](crate::scene::richardson)) gains one to two orders of
//! magnitude at the cost of the coarser run; [`Scene::converge`] doubles the
//! resolution until a requested accuracy is reached. It does not help the
//! Hertz force (already second order) nor the adhesive pull-off forces, whose
//! convergence is irregular.
//!
//! [`Scene::converge`]: crate::scene::Scene::converge
//!
//! ## Cost
//!
//! One constrained-CG iteration costs 1.2 to 1.6 times one real-to-complex
//! plus complex-to-real FFT of the padded `2N x 2N` grid (one operator
//! application per iteration); at `N = 1024` that is about 35-40 ms on this
//! 2-core machine. A non-adhesive solve takes 40 to 140 iterations; an
//! adhesive step, a few rounds of a preconditioned CG on the attached cells.
