//! # Stacks of bonded layers
//!
//! A [`Stack`](crate::substrate::Stack) is `n` bonded elastic layers (top
//! first: shear moduli `mu_i`, Poisson ratios `nu_i`, thicknesses `h_i`) on
//! a rigid base or an elastic half-space, built with
//! [`Substrate::stack`](crate::Substrate::stack). Everything the crate does
//! for one layer it does for a stack: the coating factor `R(t)`
//! ([`StackFunctions`](crate::substrate::StackFunctions)), influence
//! coefficients and FFT operators, the exact axisymmetric solutions, scenes
//! (`kind = "stack"`), the command-line tool and the Python package
//! (`Substrate.stack`).
//!
//! ## The state equation of one layer
//!
//! For one Fourier mode of wavenumber `q` in plane strain (the surface
//! compliance of an axisymmetric load follows from the same `u_z(q)` by a
//! Hankel transform), write `u_x = U(z) sin(q x)`, `u_z = W(z) cos(q x)`,
//! `sigma_xz = T(z) sin(q x)`, `sigma_zz = S(z) cos(q x)`, `z` into the
//! body. Hooke's law and the two equilibrium equations give, with lengths in
//! units of `1/q`, stresses in units of the top layer's `mu1`, `r = mu1/mu`,
//! `w = 1/(1 - nu)`, `c = nu w` and `k = (1/2 - nu) w`, the first-order
//! system `y' = A y` for `y = (U, W, T/mu1, S/mu1)`:
//!
//! ```text
//!     |  0     1    r    0  |
//! A = | -c     0    0   k r |
//!     | 2w/r   0    0    c  |
//!     |  0     0   -1    0  |
//! ```
//!
//! regular for every `nu` in `[0, 1/2]` (at `nu = 1/2`, `k = 0`). Its
//! eigenvalues are `+1` and `-1`, each a Jordan block of two: `A^2 = I + N`
//! with `N^2 = 0`. Summing the exponential series with this gives the
//! propagator in closed form,
//!
//! ```text
//! exp(A x) = cosh x I + (x sinh x / 2) N + sinh x A + ((x cosh x - sinh x) / 2) A N.
//! ```
//!
//! ## Only decaying exponentials
//!
//! The state at the top of a layer of `x = q h` follows from the state at its
//! bottom by `exp(-A x)`, whose entries grow like `x e^x`. Scaled by `e^(-x)`,
//!
//! ```text
//! P(x) = e^(-x) exp(-A x) = c I + (x s/2) N - s A - g A N,
//! c = (1 + e^(-2x))/2,   s = (1 - e^(-2x))/2,   g = (x (1 + e^(-2x)) - (1 - e^(-2x)))/4,
//! ```
//!
//! every entry is bounded by a multiple of `1 + x`, and only `e^(-2x)`
//! appears (`g` is summed as a series below `x = 1`, where its two terms
//! cancel). The scale drops out of everything below.
//!
//! ## The compliance recursion
//!
//! Let `C` be the 2 x 2 compliance at an interface: the displacements
//! `(U, W)` of the body below it per unit stresses `(T, S)`. A rigid base
//! has `C = 0`; an elastic half-space (the decaying solution of its own
//! `A`) has
//!
//! ```text
//! C_hs = r [ -(1 - nu)   1/2 - nu ]
//!          [  1/2 - nu  -(1 - nu) ].
//! ```
//!
//! Through a layer, with `P` split into 2 x 2 blocks, the compliance at its
//! top is the Moebius (Riccati) map
//!
//! ```text
//! C_top = F(C) = (P11 C + P12) (P21 C + P22)^(-1),
//! ```
//!
//! applied from the base up, layer by layer. The surface compliance gives
//! the coating factor of the crate's convention, `u_z(q) = 2 R(q h1) / (E1* q)`:
//!
//! ```text
//! R = -C_zz / (1 - nu1),      Lambda_g = 1 - R = (C - C_hs,1)_zz / (1 - nu1).
//! ```
//!
//! For one layer this reproduces the closed form of Perriot & Barthel (2004,
//! J. Mater. Res. 19, 600), see [`substrate::closed_form`](crate::substrate::closed_form).
//!
//! ## Differences are congruences
//!
//! The scaled propagator is symplectic up to its scale,
//! `P^T J P = e^(-2x) J` with `J = [[0, I], [-I, 0]]` (the reciprocity
//! theorem of the layer). For such maps, two compliances that pass through
//! the same layer differ by a congruence:
//!
//! ```text
//! F(X) - F(Y) = e^(-2x) (P21 Y + P22)^(-T) (X - Y) (P21 X + P22)^(-1).
//! ```
//!
//! Three things follow, each used by [`StackFunctions`](crate::substrate::StackFunctions):
//!
//! * A layer's half-space compliance is the fixed point of its own map, so
//!   `F(C) = C_hs + e^(-2x) L^T (C - C_hs) R`. The plain ratio's terms grow
//!   like `x` and cancel (three digits lost at `x = 30`); this form is damped
//!   by `e^(-2x)` and is used for every layer with `x > 1`. Thinner layers
//!   use the ratio, which stays close to `C`.
//! * `Lambda_g`, the deviation of the surface compliance from the top
//!   material's half-space, is the congruence of `C_2 - C_hs,1` through the
//!   top layer: its factor `e^(-2 q h1)` is explicit, so the exponentially
//!   small tail keeps its relative precision (to `1e-13` where
//!   `Lambda_g > 1e-20`; in the tail beyond the layer factors lose digits
//!   like `(q h1)^2`). Compliances are carried as a half-space's plus the
//!   deviation from it, so that two adjacent layers of one material
//!   subtract their half-spaces exactly.
//! * The split of `Lambda_g` by interface below.
//!
//! At `t -> 0` the recursion is regular (`P(0) = I`): with power series in
//! place of numbers (same code, generic over the arithmetic) it yields the
//! Taylor coefficients of `R` and of each interface term at `t = 0`, which
//! the kernels' far-field expansions need; `R'(0)` on a rigid base is the
//! uniaxial-strain compliance `(E1*/2) sum (h_i/h1)/M_i`.
//!
//! ## One term per interface
//!
//! The single-layer kernels ([`doc::theory`](crate::doc::theory),
//! [`doc::axisymmetric`](crate::doc::axisymmetric)) tabulate integrals of
//! `Lambda_g` in units of the layer thickness, relying on `Lambda_g`
//! decaying like `e^(-2 q h)` and varying on the scale `1/h`. A stack has
//! as many scales as interfaces: its `Lambda_g` decays on the top layer's
//! thickness but varies on the depth `z_n` of the deepest interface. The
//! crate therefore writes it as a telescoping sum,
//!
//! ```text
//! Lambda_g = sum_k B_k,     B_k = Lambda^(k) - Lambda^(k-1),
//! ```
//!
//! with `Lambda^(k)` the body made of layers `1..k` on the half-space of the
//! material below layer `k` (the base for `k = n`) and `Lambda^(0) = 0`.
//! The two bodies of `B_k` agree above interface `k`, so `B_k` is one
//! congruence of `(C_below - C_hs,k)` through layer `k`, carried up through
//! the layers above it by further congruences: it starts at
//! `E1*/E_k* - E1*/E_(k+1)*`, decays like `e^(-2 q z_k)` and varies on the
//! scale `1/z_k`: a single-layer-like function in units of `z_k`. Each
//! `B_k` gets its own lifted-Love term, radial remainder table and
//! asymptotic tail in the influence coefficients, and its own cosine
//! transform in the axisymmetric kernel, each in units of its own depth;
//! for one layer the sum is the single-layer kernel itself. This keeps
//! every table as small as a single layer's whatever the thickness ratios.
//!
//! ## A top layer resting without friction
//!
//! [`Substrate::layer_resting_on`](crate::Substrate::layer_resting_on)
//! puts a layer on a body of bonded layers with a shear-free interface
//! between them (a cell or a gel film lying on a coated support). Across
//! it only the normal traction and displacement of each Fourier mode are
//! continuous, so the layer sees its support through the support's normal
//! surface compliance alone, `2 R_2(q h_2) / (E2* q)`. The layer's own
//! frictionless closed form
//! ([`CoatingFunctions::frictionless`](crate::substrate::CoatingFunctions::frictionless))
//! holds with its constant `rho = E1*/E2*` replaced by `rho(t) = (E1*/E2*)
//! R_2(t h_2/h_1)`, and its Taylor series with `rho`'s. The compliance
//! recursion above could not carry this interface directly: above a
//! sliding interface the tangential compliance has a pole at `q = 0` (the
//! layer slides as a membrane). `tests/unbonded.rs` checks `R(t)` against
//! the plane-strain equations integrated through every layer (within
//! 1.3e-15), and the boundary elements against the exact solution on such
//! a body (-0.6 % for a punch 64 cells across). The kernel takes its
//! `Lambda_g` whole (one term, not one per interface); stresses below such
//! a body are refused with a typed error.
//!
//! ## Limits, costs and checks
//!
//! * [`Substrate::stack`](crate::Substrate::stack) reduces exactly first:
//!   zero thicknesses are dropped, adjacent layers of one material merge, an
//!   infinite layer becomes the base, bottom layers of the base's material
//!   merge into it, one layer left is [`Substrate::Coated`](crate::Substrate::Coated)
//!   (closed form). Stacks are limited to 64 layers after merging, the top
//!   layer at most `1e7` times stiffer and at most `1e60` times softer in
//!   shear than anything below, and a total thickness of at most `1e12` top
//!   layers.
//! * Building the kernels costs one single-layer table per interface, each
//!   evaluation of `B_k` `k` layer steps: measured on this crate's 2-core
//!   test machine for a 128 x 128 grid, alternating hard and soft layers on
//!   steel: influence coefficients 0.083 s for one layer, 0.77 s for three,
//!   2.2 s for six (criterion bench `stack_kernel`); 11 s for twelve and
//!   39 s for 24 in single runs before the per-layer factors were shared
//!   between the two bodies of a term; the axisymmetric kernel (`a/h1` up to 5)
//!   0.011 s, 0.25 s and 0.68 s for one, three and six; one value of `R(t)`
//!   of a three-layer stack 0.33 microseconds. The isolated operator's cost
//!   grows like the square of the layer count `L` (`L` tables, each
//!   evaluation `O(L)` steps): about `0.033 L^2` s on a 16 x 16 grid
//!   (`BENCHMARKS.md`, single runs), so a 64-layer stack takes about two
//!   minutes to build; `layered-contact check` prints this estimate for a
//!   stack.
//! * Tests (`tests/stack.rs`, `tests/stack_contact.rs`): `R` and `Lambda_g`
//!   of 36 three-layer stacks (hard/soft/hard, soft/hard/soft, contrasts 10
//!   and 1000, `nu` from 0 to 1/2, rigid and elastic bases; 576 points)
//!   against a direct 4n x 4n boundary-value solution in 50-digit arithmetic
//!   (`tests/data/stack_reference.py`): `R` within `5.1e-15`, `Lambda_g`
//!   within `3.5e-13` of itself; one layer through the recursion against the
//!   closed form (`R` within `3.6e-15`); layers of one material split three
//!   ways against one layer (`2.4e-14`); a thick top layer equals its
//!   half-space, a vanishing one the stack below to first order; influence
//!   coefficients against a direct quadrature of the whole stack's Green's
//!   function (`6.9e-15` of the self-coefficient); the boundary-element
//!   solver at 128 cells across against the exact stack solutions: flat
//!   punch stiffness `-0.31 %` and `-0.14 %`, paraboloid force within
//!   `4e-5` and contact radius `+0.12 %`.
