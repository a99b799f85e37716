//! # Stresses below the surface
//!
//! [`SubsurfaceStress`](crate::stress::SubsurfaceStress) turns any surface
//! pressure on the grid of a solve into the full stress tensor on planes
//! at any depth, in a half-space, a layer or a stack, bonded or sliding on
//! a rigid or an elastic base; a scene computes them at its most loaded
//! step when `[outputs.stresses]` asks ([`StressOutputs`](crate::scene::StressOutputs)).
//!
//! ## Formulation
//!
//! A Fourier mode `p cos(q xi)` of the pressure deforms the body in plane
//! strain in the plane of its wavevector. In each layer the Airy stress
//! function (Timoshenko & Goodier 1970, sec. 24; Burmister 1945 for layered
//! systems) is `F(s) cos(q xi)`, `s = q z` from the layer's top, with
//!
//! ```text
//! F(s) = (a1 + a2 s) e^(-s) + (b1 + b2 r) e^(-r),   r = q h - s,
//! sigma_zz = -F,  sigma_xi_z = F',  sigma_xi_xi = F'',  sigma_eta_eta = nu (F'' - F),
//! u_xi = ((1 - nu) F'' + nu F) / (2 mu q),   u_z = (u_xi' - F' / mu) / q.
//! ```
//!
//! Each basis function decays away from one face of its layer, so none
//! exceeds `max(1, q h)` inside it and nothing grows however thick the
//! layer or short the wave (the care the stack recursion of
//! [`multilayer`](super::multilayer) takes for the surface compliance). The
//! four coefficients per layer (two for an elastic base) follow from one
//! banded system: unit pressure and no shear at the top, the four of
//! displacement and traction continuous at a bonded interface, and at the
//! base no displacement (rigid), no shear and no normal displacement (a
//! layer sliding on glass), or continuity with the base's decaying pair
//! (sliding: the normal components only, no shear on either side). The
//! modes of every distinct `|q|` are solved once per grid; a plane then
//! costs six inverse FFTs, rotated from `(xi, eta)` to `(x, y)`:
//! `sigma_xx = c^2 sigma_xi_xi + s^2 sigma_eta_eta`, `sigma_xy = c s
//! (sigma_xi_xi - sigma_eta_eta)`, `sigma_xz = c sigma_xi_z`, with `(c, s)`
//! the wavevector's direction.
//!
//! The pressure is the trigonometric interpolant of the cell values (on
//! the surface plane `sigma_zz` is minus the pressure cell by cell). A
//! pressure uniform in each cell differs from it by modes beyond the
//! grid's Nyquist wavenumber, whose stresses decay like `e^(-pi z /
//! Delta)`: on planes within a cell or two of the surface the two
//! readings of the same cell values differ; below they agree.
//!
//! The mean pressure is where periodic and isolated contacts part. A
//! periodic body cannot strain on average in its plane, so the mean puts
//! every layer in uniaxial strain (`sigma_xx = sigma_yy = nu/(1 - nu)
//! sigma_zz`). An isolated contact is computed on a grid zero-padded
//! (twice along each axis by default) with the mean mode set to the
//! direction average of the long-wave limit of the modes (long waves see
//! the layers as thin plies strained with the base's surface), which is
//! the integral of the stress of an unbounded body over a plane. What the
//! padding leaves is the field of the periodic images less their mean: on
//! the axis of a Hertz contact on a grid 4 radii wide, 1.4e-2 `p0` padded
//! twice, and it falls only like the cube of the period.
//!
//! That field is then taken out. Seen from the grid the images lie at
//! least a grid's width away, so their field is smooth there and depends
//! on the pressure only through its low moments; a coarse grid (about 16
//! cells across the grid's shorter side) resolves it. The pressure is
//! deposited on the coarse cells by cloud-in-cell weights, which keep its
//! force and first moments, and the coarse planes are computed twice: with
//! the padded grid's period `L` and with `8 L`. In their difference the
//! near field, the same in both, cancels, and what is left is the images'
//! field at `L` less theirs at `8 L`; interpolated back with the same
//! weights (bilinear) and subtracted, it leaves the images of the long
//! period, about `8^-3` of the short one's. The coarse modes carry a
//! filter `exp(-(q/q_c)^4)`, `q_c` 0.45 times their Nyquist wavenumber,
//! so that the coarse field is smooth between its cells and a local field
//! (`sigma_zz = -p` on the surface) stays local: the filter's kernel,
//! wrapped round the short period, reaches the grid at 1e-11 `p0`. This is
//! the particle-mesh idea (Hockney & Eastwood 1988, ch. 5) applied to the
//! images alone. It costs two coarse planes, the larger of `(16 x 2 x 8)^2
//! = 256^2` cells, beside the padded plane.
//!
//! A wavevector on the Nyquist row (or column) of the FFT stands for both
//! signs of its component: what is odd in it (`sigma_xy`, the shears along
//! it) is set to zero there and what is even keeps its value, the
//! trapezoidal rule at the band's edge. (Setting the direction cosine
//! itself to zero, as an earlier version did, took a row of the band's
//! edge out of `sigma_xx`: a first-order error in the padding, 3.3e-3
//! `p0` on the surface under a Hertz contact padded twice.)
//!
//! ## Tangential tractions (not yet)
//!
//! The mode's state is already `(U, W, T, S)`, the shear traction included,
//! so a tangential surface traction along the wavevector is a second
//! right-hand side of the same banded system (`T = t` at the top instead
//! of 0). A traction across the wavevector drives the antiplane (SH) mode:
//! `u_eta` and `sigma_eta_z` with `phi'' = phi` in each layer, two
//! decaying functions per layer and two conditions per interface, a
//! smaller system of the same kind. Friction and partial slip would add
//! both; nothing else in the planes or the FFTs changes.
//!
//! ## Accuracy (`tests/stress.rs`)
//!
//! | case | reference | error |
//! |---|---|---|
//! | cosine on a periodic half-space, oblique | closed form (Johnson 1985, sec. 2.6) | 1.6e-15 `p0` |
//! | cosine through a three-layer stack on glass | plane-strain equations integrated by matrix exponentials | 4.9e-11 `p0` (the reference's own loss) |
//! | three bonded interfaces, random pressure | tractions and in-plane strains continuous, Hooke's law below | 1.1e-16, 6.2e-16 |
//! | Hertz, periodic cell 32 radii, 16 cells per radius | axis, Johnson eq. 3.64 | 2.5e-4 `p0` (`sigma_z`), 8.7e-4 (`sigma_r`) |
//! | Hertz, isolated, grid 4 radii wide, padded twice | axis, Johnson eq. 3.64 | 2.5e-4 `p0` (the cells' share; 1.4e-2 without the images' correction) |
//! | the same, whole planes | the same padded 8 times | 2.3e-5 `p0` at `z` of 4 cells and below; 1.7e-4 within a cell or two of the surface, at the grid's edge |
//! | the same, surface | `sigma_zz = -p` | 8e-12 `p0` |
//! | a strip of the grid, 24 x 96, images 8 cells from the contact's edge | the square grid | 4.3e-4 `p0` (1.5e-2 without) |
//! | Hertz from a BEM solve, isolated | axis; largest shear 0.310 `p0` at 0.48 `a` | 1.0e-3 `p0`; 0.3096 `p0` at 0.48 `a` |
//! | uniform circle (Love 1929), periodic cell 32 radii | axis | 3.7e-3 `p` (the cells' staircase edge) |
//! | one loaded cell, isolated | Boussinesq, 6 to 20 cells away | 2.3e-4 (the cell's size) to 1.4e-5 of the largest component |
//! | three-layer pavement, isolated, grid 8 radii wide | KENPAVE (Huang 2004) | `sigma_z` 0.10 psi of 100; `sigma_r` 0.56 % |
//!
//! A stiff layer on a soft base bends over many contact radii, so its
//! images reach far: under the pavement (asphalt 50 times stiffer than its
//! subgrade) a grid 8 radii wide padded 4 times left 1.2 % of the load in
//! the asphalt's radial stress before the correction; with it the default
//! meets KENPAVE on that grid. Check a result by doubling the padding
//! ([`SubsurfaceStress::with_padding`](crate::stress::SubsurfaceStress::with_padding),
//! or `outputs.stresses.padding` in a scene).
//!
//! ## Cost (`benches/stress.rs`)
//!
//! A plane is six inverse FFTs of the padded grid, where an application of
//! the surface compliance operator is one forward and one inverse: three
//! applications' worth. A block of 16 spectrum columns finds the six
//! fields' multipliers once (one read of the modes per bin), then filters,
//! transforms and transposes one field at a time within the second-level
//! cache. Measured on a 512 x 512 grid (`BENCHMARKS.md` has the machine,
//! the load and the date): a plane costs 5 to 7 operator applications,
//! periodic or isolated, on a half-space or a three-layer coating, into
//! reused fields ([`planes_into`](crate::stress::SubsurfaceStress::planes_into));
//! writing six fresh fields can add as much again. Planning (every distinct
//! wavenumber's banded solve) takes 9 to 25 ms periodic and 38 to 106 ms
//! isolated.
//!
//! ## Example: where a hard coating first yields
//!
//! `examples/coating_yield.rs`: 2 um of TiN (E = 400 GPa, yield 8 GPa) on
//! 1 um of chromium (279 GPa, 1.2 GPa) on steel (210 GPa, 1.6 GPa) under a
//! rigid ball of radius 100 um, on a grid of 128 x 128 cells over 8 um,
//! planes every 0.1 um down to 6 um. Bisection on the depth for the load
//! at which the largest ratio of the von Mises stress to the local yield
//! stress reaches one (`cargo run --release --example coating_yield`, 7 s):
//!
//! ```text
//! first yield: depth 2.3786e-8 m, force 1.5525e-2 N (von Mises / yield 1.0000)
//!   at z = 2.000e-6 m (chromium), r = 4.419e-8 m
//!   contact radius 1.431e-6 m, peak pressure 3.6754e9 Pa
//!   interface at 2.0e-6 m: largest shear traction 3.4438e8 Pa at r = 1.423e-6 m; ...
//!   interface at 3.0e-6 m: largest shear traction 1.6006e8 Pa at r = 1.833e-6 m; ...
//! ```
//!
//! The soft interlayer yields first, on the axis right under the TiN,
//! while the TiN itself is far from its own yield stress; the shear on the
//! TiN/chromium interface peaks near the contact's edge (`r = a`), where
//! delamination would start, and on the chromium/steel interface further
//! out. On a grid twice as wide at the same spacing the first yield is
//! the same to the digits shown, and twice as coarse 0.05 % higher in
//! force; padded 4 times without the images' correction it came out 0.29
//! % higher.
//!
//! ```
//! // The same computation on one plane, from Rust:
//! use layered_contact::stress::{Side, SubsurfaceStress};
//! use layered_contact::{Base, Boundary, Grid, Material, Substrate};
//!
//! let body = Substrate::stack(
//!     &[(Material::new(400e9, 0.25)?, 2e-6), (Material::new(279e9, 0.21)?, 1e-6)],
//!     Base::Elastic(Material::new(210e9, 0.3)?),
//! )?;
//! let grid = Grid::new(32, 32, 0.25e-6)?;
//! let pressure = vec![0.0; grid.len()]; // from a solve's Solution::pressure
//! let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Isolated)?;
//! let plane = stress.plane(&pressure, 2e-6, Side::Below)?; // the chromium's top
//! let (largest, _cell) = plane.max_of(|s| s.von_mises());
//! assert_eq!(largest, 0.0);
//! # Ok::<(), layered_contact::Error>(())
//! ```
