//! # Theory: from the coated half-space to BEM influence coefficients
//!
//! ## Fourier compliance
//!
//! A unit normal point force on the surface of a layer (`E1`, `nu1`,
//! thickness `h`) bonded to a base (`E2`, `nu2`, or rigid) displaces the
//! surface by `u_z(q) = 2 R(q h) / (E1* q)` in Fourier space (Perriot & Barthel
//! 2004, J. Mater. Res. 19, 600; Lyashenko, Popov & Borysiuk 2023),
//! with the coating factor `R(t)` evaluated by
//! [`CoatingFunctions`](crate::substrate::CoatingFunctions) in a
//! cancellation-free form. Checked facts: `R = 1` for equal materials,
//! `R -> 1` as `t -> inf`, `R(0) = E1*/E2*`, and on a rigid base
//! `R(t) = 1 - Lambda(t)` with `u_z(0) = h (1 + nu1)(1 - 2 nu1) / (E1 (1 - nu1))`.
//!
//! ## Real-space Green's function
//!
//! With `Lambda_g = 1 - R` and `Lambda0 = Lambda_g(0) = 1 - E1*/E2*` (1 on a
//! rigid base), the inverse Hankel transform of `u_z` is
//!
//! ```text
//! w(r) = (1/2pi) Integral_0^inf u_z(q) J0(q r) q dq
//!      = 1/(pi E1*) [ 1/r - Lambda0 / sqrt(r^2 + h^2) - g(r/h) / h ],
//! g(rho) = Integral_0^inf f(u) J0(u rho) du,      f(u) = Lambda_g(u) - Lambda0 e^(-u),
//! ```
//!
//! using `Integral_0^inf J0(q r) dq = 1/r` and
//! `Integral_0^inf e^(-q h) J0(q r) dq = 1/sqrt(r^2 + h^2)` (Gradshteyn &
//! Ryzhik 6.611.1). The first term is the layer's half-space (Boussinesq);
//! the second carries the change of modulus from the layer to the base at
//! distances beyond `h`; the third is smooth (`f(0) = 0`) and decays like
//! `-f_2 / rho^3` (`f_k` the Taylor coefficients of `f`), because
//! `Integral_0^inf u^(2n) J0(u rho) du = (-1)^n ((2n-1)!!)^2 / rho^(2n+1)`
//! and odd powers contribute nothing. On a rigid base `g` is `1/rho -
//! 1/sqrt(1 + rho^2)` plus a part that decays exponentially (about `1e-8` at
//! `rho = 20`): the coated body's Green's function itself decays
//! exponentially, turning negative (uplift) beyond `r ~ 0.9 h`.
//!
//! ## Cell integrals by corner functions
//!
//! The influence coefficient `K(di, dj)` is the integral of `w` over a
//! square cell seen from the centre of another. Any axis-aligned rectangle
//! integral is an inclusion-exclusion of four *corner functions*
//! `F(X, Y) = Integral_0^X Integral_0^Y w dA`, odd in `X` and `Y`:
//!
//! * `1/r`: `F = X asinh(Y/X) + Y asinh(X/Y)` (Love 1929);
//! * `1/sqrt(r^2 + c^2)`: `F = X asinh(Y/sqrt(X^2+c^2)) + Y asinh(X/sqrt(Y^2+c^2))
//!   - c atan(X Y / (c sqrt(X^2 + Y^2 + c^2)))`;
//! * `g`: in polar coordinates about the corner,
//!   `F = Integral_0^atan(Y/X) Gc(X/cos t) dt + Integral_0^atan(X/Y) Gc(Y/cos t) dt`
//!   with the disc integral `Gc(R) = Integral_0^R g rho d rho
//!   = R Integral_0^inf (f(u)/u) J1(u R) du`.
//!
//! `Gc` is tabulated once per (substrate, grid) by Chebyshev interpolation on
//! octaves of `R`, each node a Gauss-Legendre quadrature of the oscillatory
//! `J1` integral on panels of one period; beyond the table it follows
//! `Gc(R) ~ f_1 + f_2/R - 3 f_4/R^3 + 45 f_6/R^5`, and the table ends where
//! the two agree to `1e-14` (at `R = 64` on a rigid base). The angular
//! integrals use Gauss-Legendre on pieces over which `X/cos t` doubles, or
//! the closed form of the asymptotic expansion.
//!
//! Because the corner functions are evaluated at the cell corners and
//! differenced, the same code serves very thin layers (`h / Delta = 1e-3`,
//! where a cell's centre settles by the uniaxial-strain compliance and its
//! neighbours not at all) and very thick ones (`h / Delta = 1e6`, where the
//! remainder is a small smooth correction). The differencing costs absolute
//! accuracy of order `1e-16 r / Delta` times the self-coefficient for far
//! cells, as in Love's formula itself.
//!
//! ## Accuracy measured
//!
//! Against an independent computation (direct `J0` Hankel quadrature of
//! `Integral Lambda_g J0`, integrated over the cell by tensor Gauss-Legendre),
//! for `h / Delta` from 0.5 to `1e6` on rigid, stiff and soft bases: the
//! largest difference is below `1e-14` of the self-coefficient. For
//! `h / Delta = 1e-3` and `1e-2` on a rigid base the self-coefficient equals
//! the uniaxial-strain settlement to `1e-12` (tests `tests/kernel.rs`).
//!
//! ## Convolution without wrap-around
//!
//! For an isolated contact the pressure on an `N x M` grid is zero-padded to
//! `2N x 2M` and the coefficients are laid out in wrap-around order (offset
//! `-d` at index `2N - d`), so the circular convolution computed by FFT is the
//! linear one. For a periodic grid the multiplier is
//! `u_z(q) sinc(q_x Delta/2) sinc(q_y Delta/2)` at `q = 2 pi k / L`.
