//! Shared test helpers.

use std::sync::mpsc;
use std::time::Duration;

/// Seconds any one property-test or fuzz case may take before it counts as
/// a hang (`LAYERED_CONTACT_CASE_SECONDS`, default 60: the slowest case of
/// the heavy runs takes a few seconds on 2 cores).
pub fn case_seconds() -> u64 {
    env_number("LAYERED_CONTACT_CASE_SECONDS", 60)
}

/// The number in the environment variable `name`, or `default` where it is
/// unset or does not parse (the switches of the heavy test runs).
pub fn env_number<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Whether `e` is one of the typed refusals a solve may end in on an
/// input it cannot represent: an invalid parameter, an unsupported case,
/// or no convergence (never a panic or NaN).
#[allow(dead_code)]
pub fn refused(e: &layered_contact::Error) -> bool {
    matches!(
        e,
        layered_contact::Error::InvalidParameter { .. }
            | layered_contact::Error::Unsupported { .. }
            | layered_contact::Error::NoConvergence { .. }
    )
}

/// Runs `f` on its own thread and returns its value, or panics with "hang"
/// if it takes longer than [`case_seconds`] (the thread is left behind; the
/// test has failed). A panic inside `f` is passed on.
#[allow(dead_code)]
pub fn bounded<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    bounded_case("", f)
}

/// [`bounded`], naming the case (`label`) if it hangs.
#[allow(dead_code)]
pub fn bounded_case<T: Send + 'static>(label: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    let handle = std::thread::spawn(move || {
        let value = f();
        let _ = tx.send(());
        value
    });
    match rx.recv_timeout(Duration::from_secs(case_seconds())) {
        Ok(()) => handle
            .join()
            .unwrap_or_else(|e| std::panic::resume_unwind(e)),
        Err(mpsc::RecvTimeoutError::Disconnected) => match handle.join() {
            Ok(value) => value,
            Err(e) => std::panic::resume_unwind(e),
        },
        Err(mpsc::RecvTimeoutError::Timeout) => {
            panic!(
                "hang: a case ran for more than {} s: {label}",
                case_seconds()
            )
        }
    }
}

/// `g(rho) = Integral_0^inf lambda(u) J0(u rho) du` by direct Gauss-Legendre
/// quadrature on panels of at most `max_width` up to `u = 60` (where every
/// tested `Lambda_g` is negligible): the independent route the kernel tests
/// compare the influence coefficients' remainder with.
#[allow(dead_code)]
pub fn hankel_j0(lambda: impl Fn(f64) -> f64, rho: f64, max_width: f64) -> f64 {
    let rule = gauss_quad::legendre::GaussLegendre::new(30.try_into().unwrap());
    let width = (2.0 * std::f64::consts::PI / rho.max(1e-300)).min(max_width);
    let panels = (60.0 / width).ceil() as usize;
    (0..panels)
        .map(|i| {
            let a = i as f64 * width;
            rule.integrate(a, a + width, |u| lambda(u) * libm::j0(u * rho))
        })
        .sum()
}

/// `Integral over the cell of side delta centred on the origin of
/// g(|(x, y) - p| / h) dp`, by `order x order` Gauss points on each quarter
/// (the integrand's kink at the field point falls on the quarters' corners
/// when the field point is the cell's centre).
#[allow(dead_code)]
pub fn cell_integral(
    g: impl Fn(f64) -> f64,
    x: f64,
    y: f64,
    delta: f64,
    h: f64,
    order: usize,
) -> f64 {
    let rule = gauss_quad::legendre::GaussLegendre::new(order.try_into().unwrap());
    let mut total = 0.0;
    for x0 in [-0.5 * delta, 0.0] {
        for y0 in [-0.5 * delta, 0.0] {
            total += rule.integrate(x0, x0 + 0.5 * delta, |xi| {
                rule.integrate(y0, y0 + 0.5 * delta, |eta| g((x - xi).hypot(y - eta) / h))
            });
        }
    }
    total
}

/// A version-1 `.npy` file: magic, the header dictionary padded with spaces
/// to a multiple of 64 bytes (NumPy's layout), then `data`.
#[allow(dead_code)]
pub fn npy_file(descr: &str, fortran: bool, shape: &str, data: &[u8]) -> Vec<u8> {
    let mut dict = format!(
        "{{'descr': '{descr}', 'fortran_order': {}, 'shape': {shape}, }}",
        if fortran { "True" } else { "False" }
    );
    while (10 + dict.len() + 1) % 64 != 0 {
        dict.push(' ');
    }
    dict.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out.extend_from_slice(data);
    out
}

/// The rubber and sphere of the adhesion tests: `E = 1 MPa`, `nu = 0.48`,
/// a 10 mm radius, `dgamma = 0.05 J/m^2`.
#[allow(dead_code)]
pub mod rubber_sphere {
    use layered_contact::Material;

    pub const E: f64 = 1e6;
    pub const NU: f64 = 0.48;
    pub const RADIUS: f64 = 0.01;
    pub const WORK: f64 = 0.05;

    pub fn rubber() -> Material {
        Material::new(E, NU).unwrap()
    }

    /// A cycle of the rubber half-space under a paraboloid of [`RADIUS`]
    /// with [`WORK`], tilted by `tilt`, to `max_depth` (m) in `steps`, on
    /// `resolution`.
    pub fn paraboloid_cycle(
        tilt: Option<layered_contact::scene::Tilt>,
        max_depth: f64,
        steps: usize,
        resolution: layered_contact::scene::Resolution,
    ) -> layered_contact::scene::Scene {
        use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Scene, SubstrateSpec};
        Scene {
            substrate: SubstrateSpec::HalfSpace {
                youngs_modulus: E,
                poisson_ratio: NU,
            },
            indenter: IndenterSpec::Paraboloid { radius: RADIUS },
            tilt,
            adhesion: Adhesion::Constant {
                work_of_adhesion: WORK,
            },
            protocol: Protocol::Cycle { max_depth, steps },
            resolution,
            ..Scene::default()
        }
    }

    /// A solver for the rubber half-space on `grid`.
    pub fn rubber_solver(
        grid: &layered_contact::Grid,
        boundary: layered_contact::Boundary,
    ) -> layered_contact::solver::ContactSolver {
        layered_contact::solver::ContactSolver::new(
            &layered_contact::Substrate::half_space(rubber()),
            grid,
            boundary,
            layered_contact::solver::SolverParams::default(),
        )
        .unwrap()
    }
}

/// The largest difference of two solutions' cell pressures (both need
/// their pressure field).
#[allow(dead_code)]
pub fn largest_difference(
    a: &layered_contact::solver::Solution,
    b: &layered_contact::solver::Solution,
) -> f64 {
    let (p, q) = (a.pressure.as_ref().unwrap(), b.pressure.as_ref().unwrap());
    p.iter()
        .zip(q)
        .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()))
}

/// The operator applied afresh to a solution's pressure, and how far the
/// displacement the solution reports is from it: `(fresh, largest
/// difference, largest fresh value)`. The solution needs its fields.
#[allow(dead_code)]
pub fn fresh_displacement(
    operator: &mut layered_contact::kernel::ComplianceOperator,
    solution: &layered_contact::solver::Solution,
) -> (Vec<f64>, f64, f64) {
    let pressure: Vec<f64> = solution
        .pressure
        .as_ref()
        .unwrap()
        .iter()
        .copied()
        .collect();
    let reported = solution.displacement.as_ref().unwrap();
    let mut fresh = vec![0.0; pressure.len()];
    operator.apply(&pressure, &mut fresh).unwrap();
    let largest = fresh.iter().fold(0.0f64, |m, u| m.max(u.abs()));
    let worst = reported
        .iter()
        .zip(&fresh)
        .fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
    (fresh, worst, largest)
}

/// The scene's exact pull-off force (N), from [`Scene::reference`](layered_contact::scene::Scene::reference).
#[allow(dead_code)]
pub fn exact_pull_off(scene: &layered_contact::scene::Scene) -> f64 {
    let exact = scene.reference().unwrap().into_iter();
    exact
        .filter(|r| r.quantity == layered_contact::scene::Quantity::PullOffForce)
        .map(|r| r.value)
        .next()
        .unwrap()
}

/// The relative error of `curve`'s pull-off against `scene`'s exact one.
#[allow(dead_code)]
pub fn pull_off_error(
    scene: &layered_contact::scene::Scene,
    curve: &layered_contact::scene::Curve,
) -> f64 {
    curve.pull_off().unwrap().force / exact_pull_off(scene) - 1.0
}

/// The seeded self-affine surface of the rough-contact tests (and of
/// `examples/rough_benchmark.rs`) on `n` cells across a square of `side`:
/// Hurst 0.8, rms slope 0.1, roll-off at a quarter of the side, cut-off at
/// four cells.
#[allow(dead_code)]
pub fn rough_surface(side: f64, n: usize, seed: u64) -> layered_contact::topography::SelfAffine {
    layered_contact::topography::SelfAffine {
        hurst: 0.8,
        amplitude: layered_contact::topography::Amplitude::RmsSlope(0.1),
        long_cutoff: 0.25 * side,
        short_cutoff: 4.0 * side / n as f64,
        seed,
    }
}

/// Two solves of one rough contact by different preconditioners reach the
/// same contact: the same contact cells and depths within 1e-8 (each
/// solve's tolerance, 1e-8, bounds its pressures' last change, not their
/// error).
#[allow(dead_code)]
pub fn assert_same_contact(
    a: &layered_contact::solver::Solution,
    b: &layered_contact::solver::Solution,
) {
    assert_eq!(a.contact_cells, b.contact_cells);
    assert!(
        (a.depth / b.depth - 1.0).abs() < 1e-8,
        "{} {}",
        a.depth,
        b.depth
    );
}
