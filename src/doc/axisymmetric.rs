//! # Exact axisymmetric contact on a coated half-space
//!
//! Implemented by [`Axisymmetric`](crate::analytic::Axisymmetric).
//!
//! ## Setting
//!
//! A rigid axisymmetric indenter of profile `f(r)` is pressed to depth `d`
//! into a coated half-space with surface compliance
//! `u_z(q) = 2 (1 - Lambda_g(q h)) / (E1* q)` (see [`theory`](super::theory)).
//! The contact is a disc of radius `a`. With the Hankel transform
//! `P(q) = Integral_0^a p(r) J0(q r) r dr`, the surface displacement is
//!
//! ```text
//! u(r) = Integral_0^inf u_z(q) P(q) J0(q r) q dq = (2/E1*) Integral_0^inf (1 - Lambda_g(q h)) P(q) J0(q r) dq.
//! ```
//!
//! ## Reduction to a Fredholm equation
//!
//! Represent the pressure by an auxiliary function `phi` on `[0, a]`
//! (Sneddon 1966, *Mixed boundary value problems in potential theory*;
//! the same device as in Vorovich et al. 1974 for layers):
//!
//! ```text
//! P(q) = (E1*/pi) Integral_0^a phi(t) cos(q t) dt,
//! p(r) = (E1*/pi) [ phi(a)/sqrt(a^2 - r^2) - Integral_r^a phi'(t)/sqrt(t^2 - r^2) dt ].
//! ```
//!
//! Using `Integral_0^inf cos(q t) J0(q r) dq = H(r - t) / sqrt(r^2 - t^2)`,
//!
//! ```text
//! u(r) = (2/pi) Integral_0^r phi(t)/sqrt(r^2 - t^2) dt
//!      - (2/pi) Integral_0^a phi(s) Integral_0^inf Lambda_g(q h) cos(q s) J0(q r) dq ds.
//! ```
//!
//! The first term is an Abel operator. Its inverse,
//! `phi(x) = d/dx Integral_0^x r w(r)/sqrt(x^2 - r^2) dr` for
//! `(2/pi) Integral_0^r phi/sqrt(r^2 - t^2) dt = w(r)`, together with
//! `Integral_0^x r J0(q r)/sqrt(x^2 - r^2) dr = sin(q x)/q`, turns the contact
//! condition `u(r) = d - f(r)` (`r <= a`) into
//!
//! ```text
//! phi(x) - (2/pi) Integral_0^a K(x, s) phi(s) ds = d - g(x),
//! K(x, s) = Integral_0^inf Lambda_g(q h) cos(q x) cos(q s) dq = [k(x - s) + k(x + s)] / (2h),
//! k(y) = Integral_0^inf Lambda_g(u) cos(u y / h) du,
//! g(x) = d/dx Integral_0^x r f(r)/sqrt(x^2 - r^2) dr = x Integral_0^x f'(r)/sqrt(x^2 - r^2) dr,
//! ```
//!
//! `g` being the equivalent profile of the method of dimensionality
//! reduction (Popov & Hess 2015): `g = 0` for a flat punch, `x^2 / R` for a
//! paraboloid. In `xi = x/a` and `eps = a/h` the kernel is
//! `(eps/pi) [k(eps (xi - s)) + k(eps (xi + s))]`: a Fredholm equation of the
//! second kind with a smooth kernel.
//!
//! ## Results
//!
//! ```text
//! F   = 2 pi P(0) = 2 E1* Integral_0^a phi(t) dt,
//! K_I = lim sqrt(2 pi (a - r)) (-p) = -E1* phi(a) / sqrt(pi a),
//! G   = K_I^2 / (2 E1*) = E1* phi(a)^2 / (2 pi a).
//! ```
//!
//! By linearity `phi = d psi_1 - (a^2/R) psi_2` with `psi_1`, `psi_2` the
//! solutions for right-hand sides 1 and `xi^2`. Then:
//!
//! * flat punch: `K / (2 a E1*) = Integral_0^1 psi_1`; detachment at
//!   `G = dgamma`, `d_c = -sqrt(2 pi a dgamma / E1*) / psi_1(1)`;
//! * paraboloid, non-adhesive: `phi(a) = 0` gives
//!   `d = (a^2/R) psi_2(1) / psi_1(1)`;
//! * paraboloid, JKR: `phi(a) = -sqrt(2 pi a dgamma / E1*)`.
//!
//! On a half-space `Lambda_g = 0`: `psi_1 = 1`, `psi_2 = xi^2`, and the
//! formulas are Boussinesq's, Hertz's and JKR's.
//!
//! Any other tip ([`Tip`](crate::analytic::Tip): the sphere, `g = x
//! atanh(x/R)`; the cone, `g = (pi/2) x cot(theta)`; the cone with a
//! spherical apex, whose `g` has a kink where the two meet) enters through
//! `phi = d psi_1 - psi_g`, `psi_g` the solution for the right-hand side
//! `g(a xi)`. Split as `psi_g = g + chi`, only the smooth
//! `chi = (I - K)^-1 K g` is discretised (with `K g` integrated piecewise
//! between kinks), so the Nystrom rule keeps its exponential convergence;
//! the order is doubled until `Integral psi_g` and `psi_g(1)` change by
//! less than `1e-10`. The JKR edge condition and the force are as for the
//! paraboloid, and an AFM cantilever of stiffness `k` jumps off at the
//! least position of its base, `Z = d + F/k` (where `dF/dd = -k`), and
//! jumps in at the first radius going out where `F + k d = 0`
//! ([`LayeredTip::spring_pull_off`](crate::analytic::LayeredTip::spring_pull_off),
//! [`spring_jump_in`](crate::analytic::LayeredTip::spring_jump_in)). Where
//! the branch folds (a soft film over a stiffer layer over a far softer
//! base) `Z` has several local minima; the pull-off is the least of them,
//! as the load- and displacement-controlled pull-offs are the least force
//! and depth over the radii.
//!
//! ## The disc of contact
//!
//! All of this assumes that the contact is the disc `r < a`. The pressure
//! `p(r) = (E1*/pi) [phi(a) / sqrt(a^2 - r^2) - Integral_r^a phi'(t) /
//! sqrt(t^2 - r^2) dt]` (Sneddon 1965 on a half-space;
//! [`LayeredTip::pressure`](crate::analytic::LayeredTip::pressure), over
//! `t = r cosh u`, which makes the tail smooth) says whether it is: with
//! adhesion the bonded disc may pull anywhere inside, without it only where
//! it presses everywhere
//! ([`LayeredTip::holds_without_adhesion`](crate::analytic::LayeredTip::holds_without_adhesion),
//! [`LayeredFlatPunch::holds_without_adhesion`](crate::analytic::LayeredFlatPunch::holds_without_adhesion)).
//! A stiff layer on a far softer base bends like a plate on a foundation:
//! pressed to a few layer thicknesses its middle lifts off the tip and the
//! contact is a ring, which the BEM finds and the disc's solution does not
//! (a sphere on a layer 3000 to 8000 times stiffer than its base, from
//! about `a = 3 h`; `examples/disc_or_ring.rs`). Its force still comes within
//! about `1e-4` of the ring's there, its contact radius does not;
//! [`Scene::reference`](crate::scene::Scene::reference) gives no exact values
//! for such a scene.
//!
//! ## The loading's state
//!
//! On such bodies the branch may fold: the depth (or force) of the
//! equilibrium of contact radius `a` rises, falls and rises again with `a`,
//! so one depth has several equilibria. A quasi-static loading from first
//! contact follows the first rising part and jumps outward at each fold,
//! so at a depth it stops at the first radius where the depth rises
//! through it
//! ([`LayeredTip::loading_at_depth`](crate::analytic::LayeredTip::loading_at_depth)),
//! which may lie far inside the largest-radius equilibrium
//! ([`LayeredTip::at_depth`](crate::analytic::LayeredTip::at_depth)): an
//! adhesive cone on a 1 kPa film over an 8.7 kPa layer over a 4 Pa base
//! stops at 3.0 mm at a depth of 5 mm, where another equilibrium has 25.5
//! mm (`tests/promise.rs`, finding 15). Scenes take the loading's state as
//! their peak, and size their grids by it.
//!
//! ## The unloading's state
//!
//! Unloaded from its peak, a contact's edge stays pinned until the energy
//! release rate reaches the receding work of adhesion, then recedes: as
//! the depth falls the edge reaches exactly the radii inside the peak's
//! whose receding depth lies below that of every radius between them and
//! the peak, and jumps inward at each fold
//! ([`LayeredJkrCycle::unloading`](crate::analytic::LayeredJkrCycle::unloading):
//! the first radius, going inward from the peak, at which the receding
//! depth reaches the target). The branch's largest-radius equilibrium at
//! that depth may lie beyond the peak, where an unloading never goes: a
//! paraboloid of 0.23 m with works of 6.3e-5 and 4.5e-3 J/m^2 on a stack
//! as above, pressed 10 um, recedes to 2.78 mm at 1 um below its release,
//! where the widest equilibrium has 21.6 mm (`tests/unloading_state.rs`).
//! The least force of the unloading is sought over the radii up to the
//! peak's (a second, deeper least beyond it is never reached) and, under
//! displacement control, refused with [`Error::Unsupported`](crate::Error::Unsupported)
//! where it lies on radii that a fold makes the edge jump over.
//!
//! ## Numerics
//!
//! `k(y)` is tabulated once per substrate by Chebyshev interpolation on
//! `[0, 1]` and octaves `[2^k, 2^(k+1)]` up to `y = 2 eps_max`, each node a
//! Gauss-Legendre quadrature of the cosine transform (panels of one period,
//! geometric refinement towards `u = 0` for soft bases); its derivative is
//! the derivative of the Chebyshev series. The Fredholm equation is solved by
//! Nystrom's method with Gauss-Legendre nodes on `[0, 1]`, starting at
//! `max(16, 4 eps)` nodes and doubling until `Integral psi` and `psi(1)`
//! change by less than `1e-11`. The solution is evaluated off the nodes by
//! Nystrom interpolation.
//!
//! Measured (nu = 0.48, rigid base): 32 nodes suffice up to `eps = 2`
//! (70-90 microseconds per stiffness), 160 at `eps = 10`, 800 at `eps = 50`;
//! the difference to the series falls like `eps^5` (4.1e-6 at `eps = 0.1`),
//! and is -4.0 % at `eps = 1`.
