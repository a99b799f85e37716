//! Subsurface stresses (`layered_contact::stress`) against closed forms
//! and an independent integration: a cosine pressure on a periodic
//! half-space (exact to rounding), the plane-strain equations of one mode
//! integrated through a stack by matrix exponentials, the tractions and
//! strains that bonded interfaces carry across, the Hertz field on the
//! axis (Johnson 1985, eq. 3.64) and a uniform pressure on a circle (Love
//! 1929) in a periodic cell many times the contact.

use layered_contact::stress::{Side, Stress, SubsurfaceStress};
use layered_contact::{Base, Boundary, Error, Grid, Material, Substrate};
use nalgebra::Matrix4;
use std::f64::consts::PI;

/// `p0 cos(kx x + ky y)` at the cell centres of `grid`.
fn cosine(grid: &Grid, kx: f64, ky: f64, p0: f64) -> Vec<f64> {
    let dx = grid.spacing();
    (0..grid.len())
        .map(|k| {
            // x along the row index, as Grid::cell_centre.
            let (i, j) = (k / grid.columns(), k % grid.columns());
            let (x, y) = ((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
            p0 * (kx * x + ky * y).cos()
        })
        .collect()
}

#[test]
fn a_cosine_on_a_half_space_is_exact() {
    // An oblique wave (3 periods along x, 2 along y), so that the rotation
    // from the wave's plane to the grid's axes is exercised:
    // sigma_zz = -p0 (1 + qz) e^(-qz) cos, sigma_xi_xi = -p0 (1 - qz) e^(-qz) cos,
    // sigma_eta_eta = -2 nu p0 e^(-qz) cos, sigma_xi_z = -p0 qz e^(-qz) sin.
    // Measured within 3e-15 p0; asserted 1e-13 p0.
    let nu = 0.3;
    let body = Substrate::half_space(Material::new(1e9, nu).unwrap());
    let grid = Grid::new(32, 48, 1e-6).unwrap();
    let (kx, ky) = (2.0 * PI * 3.0 / 32e-6, 2.0 * PI * 2.0 / 48e-6);
    let q = kx.hypot(ky);
    let (c, s) = (kx / q, ky / q);
    let p0 = 2e6;
    let pressure = cosine(&grid, kx, ky, p0);
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic).unwrap();
    let mut worst: f64 = 0.0;
    for z in [0.0, 0.3e-6, 2e-6, 7e-6, 30e-6] {
        let plane = stress.plane(&pressure, z, Side::Below).unwrap();
        let t = q * z;
        let e = (-t).exp();
        for k in [0, 17, 400, 1535] {
            let (i, j) = (k / 48, k % 48);
            let phase = kx * (i as f64 + 0.5) * 1e-6 + ky * (j as f64 + 0.5) * 1e-6;
            let (cos, sin) = (phase.cos(), phase.sin());
            let xi = -p0 * (1.0 - t) * e * cos;
            let eta = -2.0 * nu * p0 * e * cos;
            let shear = -p0 * t * e * sin;
            let expected = Stress {
                xx: c * c * xi + s * s * eta,
                yy: s * s * xi + c * c * eta,
                zz: -p0 * (1.0 + t) * e * cos,
                xy: c * s * (xi - eta),
                xz: c * shear,
                yz: s * shear,
            };
            let got = plane.at(k);
            for (g, w) in [
                (got.xx, expected.xx),
                (got.yy, expected.yy),
                (got.zz, expected.zz),
                (got.xy, expected.xy),
                (got.xz, expected.xz),
                (got.yz, expected.yz),
            ] {
                worst = worst.max((g - w).abs() / p0);
            }
        }
    }
    println!("cosine on a half-space: worst error {worst:e} p0");
    assert!(worst < 1e-13);
}

/// The stresses `(sigma_zz, sigma_xi_xi, sigma_xi_z)` of the mode `cos(q
/// xi)` with unit pressure at depth `z` in a stack of `(mu, nu, h)` on a
/// rigid base, from `y' = A y` integrated by matrix exponentials (the
/// equations of `tests/unbonded.rs`, in units of `1/q`): the surface
/// displacements from the two conditions at the base, then the state
/// carried down to `z`.
fn mode_by_integration(layers: &[(f64, f64, f64)], q: f64, z: f64) -> [f64; 3] {
    let matrix = |mu: f64, nu: f64| {
        let lam = 2.0 * mu * nu / (1.0 - 2.0 * nu);
        let m = lam + 2.0 * mu;
        #[rustfmt::skip]
        let a = Matrix4::new(
            0.0, 1.0, 1.0 / mu, 0.0,
            -lam / m, 0.0, 0.0, 1.0 / m,
            m - lam * lam / m, 0.0, 0.0, lam / m,
            0.0, 0.0, -1.0, 0.0,
        );
        (a, lam, m)
    };
    let through = |depth: f64| {
        let mut phi = Matrix4::identity();
        let mut top = 0.0;
        for &(mu, nu, h) in layers {
            let step = (depth - top).clamp(0.0, h);
            phi = (matrix(mu, nu).0 * (q * step)).exp() * phi;
            top += h;
        }
        phi
    };
    let total: f64 = layers.iter().map(|l| l.2).sum();
    let phi = through(total);
    // U = W = 0 at the base, with y(0) = (U0, W0, 0, -1).
    let det = phi[(0, 0)] * phi[(1, 1)] - phi[(0, 1)] * phi[(1, 0)];
    let u0 = (phi[(0, 3)] * phi[(1, 1)] - phi[(0, 1)] * phi[(1, 3)]) / det;
    let w0 = (phi[(0, 0)] * phi[(1, 3)] - phi[(1, 0)] * phi[(0, 3)]) / det;
    let y = through(z) * nalgebra::Vector4::new(u0, w0, 0.0, -1.0);
    let mut top = 0.0;
    let (mut mu, mut nu) = (layers[0].0, layers[0].1);
    for &(m, n, h) in layers {
        if z >= top {
            (mu, nu) = (m, n);
        }
        top += h;
    }
    let (_, lam, m) = matrix(mu, nu);
    let w_slope = (y[3] - lam * y[0]) / m;
    [y[3], m * y[0] + lam * w_slope, y[2]]
}

#[test]
fn a_stack_matches_the_integrated_equations() {
    // A stiff coating on a softer interlayer on a third material, on a
    // rigid base; a cosine along x of wavelength 2.5 times the top layer.
    // The reference's matrix exponentials over q h = 8.8 lose up to
    // e^(2 q h) eps (4e-9 relative); measured at most 4.9e-11 p0, asserted
    // 2e-10 p0.
    let top = Material::new(200e9, 0.25).unwrap();
    let middle = Material::new(20e9, 0.35).unwrap();
    let bottom = Material::new(70e9, 0.3).unwrap();
    let (h1, h2, h3) = (1e-6, 0.5e-6, 2e-6);
    let body = Substrate::stack(&[(top, h1), (middle, h2), (bottom, h3)], Base::Rigid).unwrap();
    let grid = Grid::new(50, 4, 0.05e-6).unwrap();
    let q = 2.0 * PI / 2.5e-6;
    let pressure = cosine(&grid, q, 0.0, 1.0);
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic).unwrap();
    let mu1 = top.shear_modulus();
    let layers: Vec<(f64, f64, f64)> = [(top, h1), (middle, h2), (bottom, h3)]
        .iter()
        .map(|(m, h)| (m.shear_modulus() / mu1, m.poisson_ratio(), *h))
        .collect();
    let mut worst: f64 = 0.0;
    for z in [0.2e-6, 0.99e-6, 1.2e-6, 1.7e-6, 3.0e-6] {
        let plane = stress.plane(&pressure, z, Side::Below).unwrap();
        let [zz, xx, xz] = mode_by_integration(&layers, q, z);
        for i in [0, 7, 31] {
            let phase = q * (i as f64 + 0.5) * 0.05e-6;
            let k = 4 * i + 1;
            for (got, want) in [
                (plane.zz[k], zz * phase.cos()),
                (plane.xx[k], xx * phase.cos()),
                (plane.xz[k], xz * phase.sin()),
            ] {
                worst = worst.max((got - want).abs());
            }
        }
    }
    println!("stack against integration: worst {worst:e} p0");
    assert!(worst < 2e-10);
}

#[test]
fn bonded_interfaces_carry_tractions_and_strains_across() {
    // A random-phase pressure (seeded sum of 40 modes) on a three-layer
    // stack on an elastic base: at each interface the tractions and the
    // in-plane strains agree on both sides to rounding, and the in-plane
    // stresses below follow from those above by Hooke's law in the lower
    // material; they jump by tens of per cent. A layer resting on its base
    // without friction carries no shear across.
    let top = Material::new(300e9, 0.2).unwrap();
    let middle = Material::new(140e9, 0.21).unwrap();
    let lower = Material::new(30e9, 0.4).unwrap();
    let steel = Material::new(210e9, 0.3).unwrap();
    let body = Substrate::stack(
        &[(top, 1e-6), (middle, 0.3e-6), (lower, 0.8e-6)],
        Base::Elastic(steel),
    )
    .unwrap();
    let grid = Grid::new(32, 32, 0.1e-6).unwrap();
    let mut seed: u64 = 12345;
    let mut next = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut pressure = vec![1e8; grid.len()];
    for _ in 0..40 {
        let (m, n) = ((next() * 6.0) as i32 - 3, (next() * 6.0) as i32 - 3);
        let (kx, ky) = (2.0 * PI * m as f64 / 3.2e-6, 2.0 * PI * n as f64 / 3.2e-6);
        let (amplitude, phase) = (2e7 * next(), 2.0 * PI * next());
        for (k, p) in pressure.iter_mut().enumerate() {
            let (i, j) = (k / 32, k % 32);
            let (x, y) = ((i as f64 + 0.5) * 0.1e-6, (j as f64 + 0.5) * 0.1e-6);
            *p += amplitude * (kx * x + ky * y + phase).cos();
        }
    }
    let scale = pressure.iter().map(|p| p.abs()).fold(0.0, f64::max);
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic).unwrap();
    let materials = [top, middle, lower, steel];
    let (mut continuity, mut hooke, mut jump): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for (k, depth) in stress.interface_depths().into_iter().enumerate() {
        let above = stress.plane(&pressure, depth, Side::Above).unwrap();
        let below = stress.plane(&pressure, depth, Side::Below).unwrap();
        let (upper, lower) = (materials[k], materials[k + 1]);
        for c in 0..grid.len() {
            let (a, b) = (above.at(c), below.at(c));
            for (x, y) in [(a.zz, b.zz), (a.xz, b.xz), (a.yz, b.yz)] {
                continuity = continuity.max((x - y).abs() / scale);
            }
            // In-plane strains from each side.
            let strain = |s: &Stress, m: &Material| {
                let (e, nu) = (m.youngs_modulus(), m.poisson_ratio());
                [
                    (s.xx - nu * (s.yy + s.zz)) / e,
                    (s.yy - nu * (s.xx + s.zz)) / e,
                    (1.0 + nu) * s.xy / e,
                ]
            };
            let (ea, eb) = (strain(&a, &upper), strain(&b, &lower));
            let unit = scale / upper.youngs_modulus().min(lower.youngs_modulus());
            for (x, y) in ea.iter().zip(&eb) {
                continuity = continuity.max((x - y).abs() / unit);
            }
            // Hooke's law in the lower material from the strains above.
            let (e, nu) = (lower.youngs_modulus(), lower.poisson_ratio());
            let plane = e / (1.0 - nu * nu);
            let xx = plane * (ea[0] + nu * ea[1]) + nu / (1.0 - nu) * a.zz;
            let xy = e / (1.0 + nu) * ea[2];
            hooke = hooke
                .max((xx - b.xx).abs() / scale)
                .max((xy - b.xy).abs() / scale);
            jump = jump.max((a.xx - b.xx).abs() / scale);
        }
    }
    println!("interfaces: continuity {continuity:e}, Hooke {hooke:e}, largest jump {jump:.3}");
    assert!(
        continuity < 1e-12 && hooke < 1e-12,
        "{continuity:e} {hooke:e}"
    );
    assert!(jump > 0.1);
    // Without friction: no shear on the interface, from either side.
    let gel = Material::new(10e3, 0.45).unwrap();
    let resting = Substrate::layer_resting_on_elastic_base(gel, 1e-6, steel).unwrap();
    let mut stress = SubsurfaceStress::new(&resting, &grid, Boundary::Periodic).unwrap();
    let pressure: Vec<f64> = pressure.iter().map(|p| p * 1e-4).collect();
    for side in [Side::Above, Side::Below] {
        let plane = stress.plane(&pressure, 1e-6, side).unwrap();
        let shear = plane
            .xz
            .iter()
            .chain(&plane.yz)
            .map(|v| v.abs())
            .fold(0.0, f64::max);
        assert!(shear < 1e-12 * scale * 1e-4, "{shear:e}");
    }
}

/// The Hertz pressure `p0 sqrt(1 - r^2/a^2)` (or a uniform `p0` with
/// `uniform`) centred on a cell of an `n x n` periodic grid with `a` equal
/// to `cells` cells.
fn circle(n: usize, cells: usize, uniform: bool) -> (Grid, Vec<f64>) {
    let a = 1e-3;
    let dx = a / cells as f64;
    let grid = Grid::new(n, n, dx).unwrap();
    let c = (n as f64 / 2.0 + 0.5) * dx;
    let pressure = (0..n * n)
        .map(|k| {
            let x = ((k / n) as f64 + 0.5) * dx - c;
            let y = ((k % n) as f64 + 0.5) * dx - c;
            let r2 = (x * x + y * y) / (a * a);
            match (r2 < 1.0, uniform) {
                (false, _) => 0.0,
                (true, true) => 1.0,
                (true, false) => (1.0 - r2).sqrt(),
            }
        })
        .collect();
    (grid, pressure)
}

#[test]
fn hertz_and_love_on_the_axis() {
    // On the axis of a Hertz pressure (Johnson 1985, eq. 3.64):
    // sigma_z = -p0 / (1 + z^2/a^2),
    // sigma_r = -p0 [(1 + nu)(1 - (z/a) atan(a/z)) - 1 / (2 (1 + z^2/a^2))];
    // under a uniform p on a circle (Love 1929; Johnson eq. 3.37 ff.):
    // sigma_z = -p [1 - z^3 / (a^2 + z^2)^(3/2)],
    // sigma_r = -(p/2) [(1 + 2 nu) - 2 (1 + nu) z / sqrt(a^2 + z^2) + z^3 / (a^2 + z^2)^(3/2)].
    // The periodic cell adds the images' mean lateral stress,
    // -nu/(1 - nu) times the mean pressure, ~(a/L)^2: measured sigma_r off by
    // 2.9e-3 p0 at L = 16 a and 8.7e-4 p0 at L = 32 a (order 1.7), sigma_z
    // within 2.5e-4 p0 (16 cells per radius). Asserted: 1.5e-3 and 5e-4
    // at L = 32 a and the fall with L. The uniform circle's edge is a
    // staircase of cells (its load off by a first-order share, and the
    // jump rings): measured 3.7e-3 and 3.6e-3 p, asserted 5e-3.
    let nu = 0.3;
    let body = Substrate::half_space(Material::new(1e9, nu).unwrap());
    let a = 1e-3;
    let hertz_z = |z: f64| -1.0 / (1.0 + z * z);
    let hertz_r = |z: f64| -(1.0 + nu) * (1.0 - z * (1.0 / z).atan()) + 0.5 / (1.0 + z * z);
    let love_z = |z: f64| -(1.0 - z.powi(3) / (1.0 + z * z).powf(1.5));
    let love_r = |z: f64| {
        -0.5 * ((1.0 + 2.0 * nu) - 2.0 * (1.0 + nu) * z / (1.0 + z * z).sqrt()
            + z.powi(3) / (1.0 + z * z).powf(1.5))
    };
    let mut lateral = Vec::new();
    for (per_radius, uniform) in [(16usize, false), (32, false), (32, true)] {
        let n = 16 * per_radius;
        let (grid, pressure) = circle(n, 16, uniform);
        let axis = (n / 2) * n + n / 2;
        let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic).unwrap();
        let (mut dz, mut dr): (f64, f64) = (0.0, 0.0);
        for zr in [0.25, 0.48, 1.0, 2.0] {
            let plane = stress.plane(&pressure, zr * a, Side::Below).unwrap();
            let s = plane.at(axis);
            let (z_exact, r_exact) = if uniform {
                (love_z(zr), love_r(zr))
            } else {
                (hertz_z(zr), hertz_r(zr))
            };
            dz = dz.max((s.zz - z_exact).abs());
            dr = dr.max((s.xx - r_exact).abs()).max((s.yy - r_exact).abs());
        }
        println!("L = {per_radius} a, uniform {uniform}: sigma_z {dz:.2e}, sigma_r {dr:.2e}");
        lateral.push(dr);
        if uniform {
            assert!(dz < 5e-3 && dr < 5e-3, "{dz:e} {dr:e}");
        } else if per_radius == 32 {
            assert!(dz < 5e-4 && dr < 1.5e-3, "{dz:e} {dr:e}");
        }
    }
    assert!(lateral[0] / lateral[1] > 2.5, "{lateral:?}");
}

#[test]
fn hertz_maximum_shear_is_under_the_surface() {
    // nu = 0.3: the largest shear 0.310 p0 at z = 0.48 a (Johnson 1985,
    // sec. 3.4); here against the closed form on the axis, maximised on a
    // fine scan (0.3101 p0 at 0.4807 a). Measured on the planes z/a = 0.40
    // to 0.56: the largest at 0.48, 0.3104 p0; asserted within 1e-3 p0
    // and at 0.48.
    let nu = 0.3;
    let body = Substrate::half_space(Material::new(1e9, nu).unwrap());
    let (grid, pressure) = circle(512, 16, false);
    let axis = 256 * 512 + 256;
    let tau = |z: f64| {
        let r = -(1.0 + nu) * (1.0 - z * (1.0 / z).atan()) + 0.5 / (1.0 + z * z);
        0.5 * (r + 1.0 / (1.0 + z * z)).abs()
    };
    let (exact, at) = (1..2000)
        .map(|k| (tau(k as f64 * 5e-4), k as f64 * 5e-4))
        .fold((0.0, 0.0), |b, v| if v.0 > b.0 { v } else { b });
    assert!((exact - 0.310).abs() < 5e-4 && (at - 0.48).abs() < 5e-3);
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic).unwrap();
    let (best, depth) = [0.40, 0.44, 0.48, 0.52, 0.56]
        .iter()
        .map(|zr| {
            let plane = stress.plane(&pressure, zr * 1e-3, Side::Below).unwrap();
            (plane.at(axis).max_shear(), *zr)
        })
        .fold((0.0, 0.0), |b, v| if v.0 > b.0 { v } else { b });
    println!("max shear {best:.4} p0 at {depth} a (closed form {exact:.4} at {at})");
    assert!((best - exact).abs() < 1e-3 && depth == 0.48);
}

#[test]
fn bad_requests_are_refused() {
    let body = Substrate::layer_on_rigid_base(Material::new(1e9, 0.3).unwrap(), 1e-6).unwrap();
    let grid = Grid::new(8, 8, 1e-7).unwrap();
    for (boundary, padding) in [(Boundary::Isolated, 1), (Boundary::Periodic, 2)] {
        assert!(matches!(
            SubsurfaceStress::with_padding(&body, &grid, boundary, padding),
            Err(Error::InvalidParameter { .. })
        ));
    }
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Periodic).unwrap();
    let p = vec![1.0; 64];
    assert!(matches!(
        stress.plane(&p[..10], 0.0, Side::Below),
        Err(Error::ShapeMismatch { .. })
    ));
    for depth in [-1e-9, f64::NAN, 2e-6, f64::INFINITY] {
        assert!(matches!(
            stress.plane(&p, depth, Side::Below),
            Err(Error::InvalidParameter { .. })
        ));
    }
    // The rigid base's face belongs to the layer above only.
    assert!(stress.plane(&p, 1e-6, Side::Below).is_err());
    let plane = stress.plane(&p, 1e-6, Side::Above).unwrap();
    // A uniform pressure: uniaxial strain, sigma_xx = nu / (1 - nu) sigma_zz.
    assert!((plane.zz[5] + 1.0).abs() < 1e-15);
    assert!((plane.xx[5] + 0.3 / 0.7).abs() < 1e-15);
    let mut bad = p.clone();
    bad[3] = f64::NAN;
    assert!(matches!(
        stress.plane(&bad, 0.0, Side::Below),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn an_isolated_contact_has_no_images() {
    // The Hertz pressure on an isolated grid 4 radii wide (16 cells per
    // radius), padded twice (the default): on the axis against Johnson's
    // eq. 3.64 at z/a = 0.25, 0.48, 1, 2; over whole planes against the
    // same grid padded 8 times; on the surface sigma_zz = -p.
    // Before the images' correction the axis was off by 1.40e-2, 1.86e-3
    // and 2.50e-4 p0 padded 2, 4 and 8 times, and the planes padded twice
    // and 8 times differed by 1.6e-2 p0. Measured now: the axis 2.51e-4 p0
    // (the cell size's share, the periodic test's floor); the planes at
    // z >= 4 cells within 2.3e-5 p0 (the images at 8 times the period,
    // which the correction leaves, and the coarse grid's resolution of the
    // rest); the planes within a cell or two of the surface 1.7e-4 p0 at
    // the grid's edge (the band-limited pressure's ripple, which the
    // coarse grid cannot see, falling like e^(-pi z / Delta)); the surface
    // sigma_zz 6e-12 p0.
    let nu = 0.3;
    let body = Substrate::half_space(Material::new(1e9, nu).unwrap());
    let (grid, pressure) = circle(64, 16, false);
    let axis = 32 * 64 + 32;
    let hertz_z = |z: f64| -1.0 / (1.0 + z * z);
    let hertz_r = |z: f64| -(1.0 + nu) * (1.0 - z * (1.0 / z).atan()) + 0.5 / (1.0 + z * z);
    let depths: Vec<f64> = [0.0, 0.01, 0.05, 0.1, 0.25, 0.48, 1.0, 2.0]
        .iter()
        .map(|z| z * 1e-3)
        .collect();
    let mut default = SubsurfaceStress::new(&body, &grid, Boundary::Isolated).unwrap();
    let mut long = SubsurfaceStress::with_padding(&body, &grid, Boundary::Isolated, 8).unwrap();
    let planes = default.planes(&pressure, &depths, Side::Below).unwrap();
    let reference = long.planes(&pressure, &depths, Side::Below).unwrap();
    // Buffers of other sizes and values are refilled, not added to.
    let mut reused = reference[..3].to_vec();
    reused[1].xy = vec![7.0; 5];
    default
        .planes_into(&pressure, &depths, Side::Below, &mut reused)
        .unwrap();
    assert_eq!(reused, planes);
    let (mut axis_error, mut deep, mut shallow): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for (plane, r) in planes.iter().zip(&reference) {
        let zr = plane.depth / 1e-3;
        let difference = plane
            .components()
            .iter()
            .zip(r.components())
            .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
            .fold(0.0, f64::max);
        if zr >= 0.25 {
            let t = plane.at(axis);
            axis_error = axis_error
                .max((t.zz - hertz_z(zr)).abs())
                .max((t.xx - hertz_r(zr)).abs())
                .max((t.yy - hertz_r(zr)).abs());
            deep = deep.max(difference);
        } else {
            shallow = shallow.max(difference);
        }
    }
    let surface = pressure
        .iter()
        .zip(&planes[0].zz)
        .map(|(p, zz)| (p + zz).abs())
        .fold(0.0, f64::max);
    println!(
        "padded twice: axis {axis_error:.2e} p0; against 8 times {deep:.2e} p0 deep, \
         {shallow:.2e} p0 shallow; surface {surface:.1e} p0"
    );
    assert!(axis_error < 3e-4, "{axis_error:e}");
    assert!(deep < 5e-5 && shallow < 5e-4, "{deep:e} {shallow:e}");
    assert!(surface < 1e-10, "{surface:e}");
}

#[test]
fn a_strip_of_a_grid_sees_what_the_square_grid_sees() {
    // The same pressure (Hertz, 8 cells per radius) on an isolated grid
    // 24 x 96 and on one 96 x 96 (zero beyond the strip): the field is the
    // same. Across the strip the images lie only 24 cells away, 8 from the
    // contact's edge; the coarse grid is then sized by the strip's width.
    // Measured at z = 0.8, 4 and 16 cells: 4.3e-4, 1.6e-4 and 1.3e-4 p0,
    // where without the correction the grids differed by 1.1e-2, 9.3e-3
    // and 1.5e-2 p0. Asserted: 1e-3.
    let body = Substrate::half_space(Material::new(1e9, 0.3).unwrap());
    let (square, pressure) = circle(96, 8, false);
    let strip = Grid::new(24, 96, square.spacing()).unwrap();
    let rows = 36..60;
    let strip_pressure: Vec<f64> = pressure[rows.start * 96..rows.end * 96].to_vec();
    let mut a = SubsurfaceStress::new(&body, &square, Boundary::Isolated).unwrap();
    let mut b = SubsurfaceStress::new(&body, &strip, Boundary::Isolated).unwrap();
    let mut worst: f64 = 0.0;
    for z in [0.1e-3, 0.5e-3, 2e-3] {
        let full = a.plane(&pressure, z, Side::Below).unwrap();
        let part = b.plane(&strip_pressure, z, Side::Below).unwrap();
        for (x, y) in full.components().iter().zip(part.components()) {
            for (u, v) in x[rows.start * 96..rows.end * 96].iter().zip(y) {
                worst = worst.max((u - v).abs());
            }
        }
    }
    println!("strip against square: {worst:.2e} p0");
    assert!(worst < 1e-3, "{worst:e}");
}

#[test]
fn a_boundary_element_hertz_solve_gives_the_hertz_field() {
    // A paraboloid pressed into a half-space by the BEM (grid 4 contact
    // radii wide, contact about 16 cells in radius), its pressure into the
    // stresses: on the axis against Johnson's eq. 3.64 with the solve's own
    // contact radius and p0 = 3F / (2 pi a^2). Measured worst 1.0e-3 p0 on
    // the planes z/a = 0.25 to 2 (1.9e-3 before the images' correction),
    // and the largest shear 0.3096 p0 at 0.48 a. Asserted 5e-3 p0, and the
    // largest shear at z/a = 0.48 within 2e-3 p0 of 0.310.
    use layered_contact::indenter::Paraboloid;
    use layered_contact::solver::{ContactSolver, Fields, SolverParams};
    let nu = 0.3;
    let material = Material::new(1e9, nu).unwrap();
    let body = Substrate::half_space(material);
    let (radius, a) = (50e-3, 1e-3);
    let dx = a / 16.0;
    let grid = Grid::new(64, 64, dx).unwrap();
    let params = SolverParams {
        fields: Fields {
            pressure: true,
            ..Fields::default()
        },
        ..SolverParams::default()
    };
    let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params).unwrap();
    // The indenter is centred on the grid's centre, a cell corner: the axis
    // lies between four cells, so the axis values are their average.
    let (s, _) = solver
        .solve_depth(
            &Paraboloid::new(radius).unwrap(),
            a * a / radius,
            None,
            &mut (),
        )
        .unwrap();
    let pressure: Vec<f64> = s.pressure.unwrap().iter().copied().collect();
    let a_bem = (3.0 * s.force * radius / (4.0 * material.contact_modulus())).cbrt();
    let p0 = 3.0 * s.force / (2.0 * PI * a_bem * a_bem);
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Isolated).unwrap();
    let around = [31 * 64 + 31, 31 * 64 + 32, 32 * 64 + 31, 32 * 64 + 32];
    let mut worst: f64 = 0.0;
    let mut shear = (0.0, 0.0);
    for zr in [0.25, 0.4, 0.48, 0.56, 1.0, 2.0] {
        let plane = stress.plane(&pressure, zr * a_bem, Side::Below).unwrap();
        let mean = |f: &[f64]| around.iter().map(|&k| f[k]).sum::<f64>() / 4.0;
        // Offsets of half a cell from the axis change the axis values by
        // (dx / a)^2 / 8 of p0: below 1e-3.
        let (zz, xx) = (mean(&plane.zz) / p0, mean(&plane.xx) / p0);
        let exact_z = -1.0 / (1.0 + zr * zr);
        let exact_r = -(1.0 + nu) * (1.0 - zr * (1.0 / zr).atan()) + 0.5 / (1.0 + zr * zr);
        worst = worst.max((zz - exact_z).abs()).max((xx - exact_r).abs());
        let tau = 0.5 * (xx - zz).abs();
        if tau > shear.0 {
            shear = (tau, zr);
        }
    }
    println!(
        "BEM Hertz: worst {worst:.2e} p0, largest shear {:.4} p0 at {} a",
        shear.0, shear.1
    );
    assert!(worst < 5e-3, "{worst:e}");
    assert!(
        (shear.0 - 0.310).abs() < 2e-3 && shear.1 == 0.48,
        "{shear:?}"
    );
}

#[test]
fn scenes_compute_the_stresses_they_ask_for() {
    // A hard coating on steel under a ball (examples/scenes/coating_stresses.toml,
    // coarser): on the surface plane sigma_zz is minus the pressure cell by
    // cell (the interpolant meets the cells' values; measured 7e-11 of the
    // peak, the tail of the images' coarse filter wrapped round the period,
    // asserted 1e-9), the interfaces come top down with the
    // tractions continuous with the planes at their depths, and the
    // maxima lie on the planes. Depths below a rigid base are refused
    // before anything is solved.
    use layered_contact::scene::{
        DepthGrid, IndenterSpec, LayerSpec, MaterialSpec, Outputs, Protocol, Scene, StressOutputs,
        SubstrateSpec,
    };
    use layered_contact::solver::Fields;
    let layer = |e: f64, nu: f64, t: f64| LayerSpec {
        youngs_modulus: e,
        poisson_ratio: nu,
        thickness: t,
    };
    let mut scene = Scene {
        substrate: SubstrateSpec::Stack {
            layers: vec![layer(400e9, 0.25, 2e-6), layer(279e9, 0.21, 1e-6)],
            base: Some(MaterialSpec {
                youngs_modulus: 210e9,
                poisson_ratio: 0.3,
            }),
        },
        indenter: IndenterSpec::Sphere { radius: 100e-6 },
        protocol: Protocol::Depth { depth: 0.25e-6 },
        outputs: Outputs {
            fields: Fields {
                pressure: true,
                ..Fields::default()
            },
            stresses: StressOutputs {
                depths: vec![2e-6, 0.0],
                depth_grid: Some(DepthGrid {
                    to: 4e-6,
                    planes: 5,
                }),
                interfaces: true,
                padding: None,
            },
        },
        ..Scene::default()
    };
    scene.resolution.cells_across = 32;
    let curve = scene.run(&mut |_| {}).unwrap();
    let result = curve.stresses.as_ref().unwrap();
    let depths: Vec<f64> = result.planes.iter().map(|p| p.depth).collect();
    assert_eq!(depths, [0.0, 1e-6, 2e-6, 3e-6, 4e-6]);
    let pressure = curve.peak.as_ref().unwrap().pressure.as_ref().unwrap();
    let peak = pressure.iter().copied().fold(0.0, f64::max);
    let surface = &result.planes[0];
    let worst = pressure
        .iter()
        .zip(&surface.zz)
        .map(|(p, zz)| (p + zz).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-9 * peak, "{worst:e} of {peak:e}");
    assert_eq!(result.boundaries, [2e-6, 3e-6]);
    let tractions: Vec<f64> = result.interfaces.iter().map(|t| t.depth).collect();
    assert_eq!(tractions, [2e-6, 3e-6]);
    let at_interface = &result.planes[2];
    for (a, b) in at_interface.zz.iter().zip(&result.interfaces[0].normal) {
        assert!((a - b).abs() < 1e-12 * peak);
    }
    let vm = result.von_mises.unwrap();
    let on_plane = result
        .planes
        .iter()
        .find(|p| p.depth == vm.depth)
        .unwrap()
        .at(vm.cell)
        .von_mises();
    assert_eq!(on_plane, vm.value);
    // Without fields asked for, the pressure the stresses needed is not kept.
    scene.outputs.fields = Fields::default();
    let curve = scene.run(&mut |_| {}).unwrap();
    assert!(curve.peak.is_none() && curve.stresses.is_some());
    // A plane in a rigid base is refused up front.
    let mut rigid = scene.clone();
    rigid.substrate = SubstrateSpec::LayerOnRigidBase {
        youngs_modulus: 400e9,
        poisson_ratio: 0.25,
        thickness: 2e-6,
    };
    assert!(matches!(
        rigid.run(&mut |_| {}),
        Err(Error::InvalidParameter { .. })
    ));
}

/// KENPAVE's stresses on the axis of a three-layer pavement (Huang 2004,
/// Pavement Analysis and Design, 2nd ed.; the values as PyMastic's
/// validation lists them, `Validation/Kenpave.csv`): 100 psi on a circle
/// of radius 5.99 in over 6 in of asphalt (E = 500 ksi, nu = 0.35) and
/// 10 in of base (40 ksi, 0.4) on a subgrade (10 ksi, 0.45), bonded.
/// `(z in, sigma_z, sigma_r)`, compression positive, psi; at an interface
/// the layer above.
const KENPAVE: [(f64, f64, f64); 11] = [
    (1.0, 95.838, 156.984),
    (2.0, 84.247, 88.377),
    (3.0, 67.411, 25.997),
    (4.0, 48.805, -33.924),
    (5.0, 32.784, -96.245),
    (6.0, 24.051, -166.448),
    (7.0, 20.789, -0.699),
    (10.0, 13.195, -3.682),
    (16.0, 5.722, -11.87),
    (17.0, 5.354, 0.372),
    (29.0, 2.844, 0.156),
];

#[test]
fn a_three_layer_pavement_matches_kenpave() {
    // Units as published (in, psi, ksi): the stresses scale with the load
    // and not with the unit of length. The circle is resolved by 8 cells
    // per radius with each cell's pressure its covered fraction (16 x 16
    // samples), on a grid 8 radii wide at the default padding. The stiff
    // asphalt bends over tens of radii, so its images reach far: before
    // the images' correction, sigma_r at z = 3 in was 1.22 psi off padded
    // 4 times, and the grid had to be 16 radii wide padded 8 times.
    // Measured: sigma_z within 0.10 psi, sigma_r within 0.56 % where it
    // exceeds 10 psi and 0.016 psi elsewhere.
    // Asserted: 0.2 psi, 1 % and 0.1 psi. The surface (z = 0) is left out:
    // there KENPAVE gives sigma_r = 259.2 psi and PyMastic 240.4 (with
    // sigma_z = 107 where the load is 100), the Hankel integrals' own
    // error; here 235.1, continuous with 231.0 at z = 0.05 and 195.3 at
    // z = 0.5 (PyMastic 194.5).
    let body = Substrate::stack(
        &[
            (Material::new(500e3, 0.35).unwrap(), 6.0),
            (Material::new(40e3, 0.4).unwrap(), 10.0),
        ],
        Base::Elastic(Material::new(10e3, 0.45).unwrap()),
    )
    .unwrap();
    let (a, per_radius) = (5.99, 8usize);
    let n = 8 * per_radius;
    let dx = a / per_radius as f64;
    let grid = Grid::new(n, n, dx).unwrap();
    let c = n as f64 / 2.0 * dx;
    let sub = 16;
    let pressure: Vec<f64> = (0..n * n)
        .map(|k| {
            let (i, j) = (k / n, k % n);
            let inside = (0..sub * sub)
                .filter(|s| {
                    let x = (i as f64 + ((s / sub) as f64 + 0.5) / sub as f64) * dx - c;
                    let y = (j as f64 + ((s % sub) as f64 + 0.5) / sub as f64) * dx - c;
                    x * x + y * y < a * a
                })
                .count();
            100.0 * inside as f64 / (sub * sub) as f64
        })
        .collect();
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Isolated).unwrap();
    // The axis is the corner of four cells.
    let h = n / 2;
    let around = [
        (h - 1) * n + h - 1,
        (h - 1) * n + h,
        h * n + h - 1,
        h * n + h,
    ];
    let (mut dz, mut relative, mut small): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for (z, sz, sr) in KENPAVE {
        let side = if z == 6.0 || z == 16.0 {
            Side::Above
        } else {
            Side::Below
        };
        let plane = stress.plane(&pressure, z, side).unwrap();
        let mean = |f: &[f64]| -around.iter().map(|&k| f[k]).sum::<f64>() / 4.0;
        let (zz, rr) = (mean(&plane.zz), mean(&plane.xx));
        dz = dz.max((zz - sz).abs());
        if sr.abs() > 10.0 {
            relative = relative.max(((rr - sr) / sr).abs());
        } else {
            small = small.max((rr - sr).abs());
        }
    }
    println!("KENPAVE: sigma_z {dz:.3} psi, sigma_r {relative:.2e} relative, {small:.3} psi");
    assert!(
        dz < 0.2 && relative < 0.01 && small < 0.1,
        "{dz} {relative} {small}"
    );
}

#[test]
fn one_loaded_cell_gives_boussinesq_far_from_it() {
    // One cell of pressure p (a force P = p Delta^2) in the middle of an
    // isolated 65 x 65 grid at the default padding: at distances of 6 to 20 cells
    // and depths of 4 to 12 the field is Boussinesq's point load (Johnson
    // 1985, eqs. 3.18-3.19), with rho = sqrt(r^2 + z^2):
    // sigma_z = -3 P z^3 / (2 pi rho^5),  tau_rz = -3 P r z^2 / (2 pi rho^5),
    // sigma_r = P/(2 pi) [(1 - 2 nu)/r^2 (1 - z/rho) - 3 z r^2/rho^5],
    // sigma_theta = -(1 - 2 nu) P/(2 pi) [1/r^2 (1 - z/rho) - z/rho^3].
    // The cell's size changes the field by about (Delta/rho)^2 / 24 of
    // itself (1.6e-3 at the nearest point). Measured, relative to the
    // largest component at each point: 2.3e-4, 1.4e-5 and 7.2e-5 (padded 8
    // times without the images' correction: 2.3e-4, 1.2e-4 and 6.2e-4).
    // Asserted 1e-3.
    let nu = 0.3;
    let body = Substrate::half_space(Material::new(1e9, nu).unwrap());
    let (n, dx) = (65usize, 1e-6);
    let grid = Grid::new(n, n, dx).unwrap();
    let mut pressure = vec![0.0; n * n];
    let centre = (n / 2) * n + n / 2;
    pressure[centre] = 1.0;
    let force = dx * dx;
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Isolated).unwrap();
    let mut errors = Vec::new();
    for (cells_out, cells_down) in [(6usize, 4usize), (10, 8), (20, 12)] {
        let (r, z) = (cells_out as f64 * dx, cells_down as f64 * dx);
        let plane = stress.plane(&pressure, z, Side::Below).unwrap();
        // x along the rows: the cell `cells_out` rows below the centre.
        let s = plane.at(centre + cells_out * n);
        let rho = r.hypot(z);
        let k = force / (2.0 * PI);
        let exact = [
            -3.0 * k * z.powi(3) / rho.powi(5),
            k * ((1.0 - 2.0 * nu) / (r * r) * (1.0 - z / rho) - 3.0 * z * r * r / rho.powi(5)),
            -(1.0 - 2.0 * nu) * k * ((1.0 - z / rho) / (r * r) - z / rho.powi(3)),
            -3.0 * k * r * z * z / rho.powi(5),
        ];
        let got = [s.zz, s.xx, s.yy, s.xz];
        let scale = exact.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let error = got
            .iter()
            .zip(&exact)
            .map(|(g, e)| (g - e).abs() / scale)
            .fold(0.0, f64::max);
        println!("r = {cells_out}, z = {cells_down} cells: {got:?} against {exact:?}, {error:.2e}");
        errors.push(error);
    }
    assert!(errors.iter().all(|e| *e < 1e-3), "{errors:?}");
}

#[test]
fn hertz_surface_tension_peaks_at_the_edge() {
    // The surface of a Hertz contact (Johnson 1985, eq. 3.61): inside,
    // sigma_r/p0 = (1 - 2 nu)/3 (a/r)^2 (1 - (1 - r^2/a^2)^(3/2))
    // - (1 - r^2/a^2)^(1/2); outside, (1 - 2 nu)/3 (a/r)^2, a tension
    // largest at r = a ((1 - 2 nu)/3 = 0.1333 p0 for nu = 0.3). Along a
    // row through the centre of an isolated grid 4 radii wide, 16, 32 and
    // 64 cells per radius. Measured within a quarter radius of the edge:
    // 5.81e-3, 2.92e-3, 1.50e-3 p0, at r = a (first order: the pressure's
    // square-root edge, which the cells sample); beyond it 7.2e-4, 2.2e-4,
    // 5.8e-5; the largest sigma_xx on the surface 0.1275, 0.1304, 0.1318
    // p0 (8 cells: 1.09e-2 and 0.1224). Asserted: the order above 0.9, 2e-3 at the edge
    // and 1e-4 away from it at 64 cells, the largest within 2e-3.
    let nu = 0.3;
    let body = Substrate::half_space(Material::new(1e9, nu).unwrap());
    let tension = (1.0 - 2.0 * nu) / 3.0;
    let exact = |r: f64| {
        if r >= 1.0 {
            tension / (r * r)
        } else if r == 0.0 {
            -(1.0 + 2.0 * nu) / 2.0
        } else {
            let s = (1.0 - r * r).sqrt();
            tension / (r * r) * (1.0 - s.powi(3)) - s
        }
    };
    let mut at_edge = Vec::new();
    for cells in [16usize, 32, 64] {
        let n = 4 * cells;
        let (grid, pressure) = circle(n, cells, false);
        let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Isolated).unwrap();
        let surface = stress.plane(&pressure, 0.0, Side::Below).unwrap();
        let (mut edge, mut away): (f64, f64) = (0.0, 0.0);
        // x along the rows: cell (i, n/2) lies at r = (i - n/2) cells.
        for i in n / 2..n {
            let r = (i - n / 2) as f64 / cells as f64;
            let error = (surface.xx[i * n + n / 2] - exact(r)).abs();
            if (r - 1.0).abs() > 0.25 {
                away = away.max(error);
            } else {
                edge = edge.max(error);
            }
        }
        let largest = surface.max_of(|s| s.xx).0;
        println!(
            "{cells} cells per radius: edge {edge:.2e}, away {away:.2e}, largest {largest:.4}"
        );
        at_edge.push(edge);
        if cells == 64 {
            assert!(edge < 2e-3 && away < 1e-4, "{edge:e} {away:e}");
            assert!((largest - tension).abs() < 2e-3, "{largest}");
        }
    }
    let order = (at_edge[0] / at_edge[2]).log2() / 2.0;
    assert!(order > 0.9, "{at_edge:?}");
}
