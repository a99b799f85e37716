//! The half-space closed forms against independent routes to the same number:
//! quadrature of their own pressure fields, numerical extrema and derivatives,
//! and energy balances. Quadrature is Gauss-Legendre from `gauss-quad`.

use std::f64::consts::PI;
use std::num::NonZeroUsize;

use gauss_quad::legendre::GaussLegendre;
use layered_contact::analytic::{BoussinesqPunch, Hertz, JkrFlatPunch, JkrSphere, SneddonCone};
use layered_contact::{Error, Material};

fn rubber() -> Material {
    Material::new(0.324e6, 0.48).unwrap()
}

fn rule(order: usize) -> GaussLegendre {
    GaussLegendre::new(NonZeroUsize::new(order).unwrap())
}

/// Minimum of a unimodal `f` on `[lo, hi]` by golden-section search.
fn argmin(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let x1 = hi - g * (hi - lo);
        let x2 = lo + g * (hi - lo);
        if f(x1) < f(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    0.5 * (lo + hi)
}

/// Hertz: the force is the integral of the pressure (substitution
/// `r = a sin(theta)` removes the square-root edge, so 40 Gauss points give
/// ~1e-15), `dF/dd = 2aE*` by central differences (error ~h^2, 1e-9), and
/// `p0 = 3F/(2 pi a^2)`.
#[test]
fn hertz_force_is_integral_of_pressure() {
    let hertz = Hertz::new(&rubber(), 0.05).unwrap();
    for depth in [1e-6, 1e-4, 5e-4] {
        let a = hertz.contact_radius(depth);
        let integral = rule(40).integrate(0.0, PI / 2.0, |theta| {
            let r = a * theta.sin();
            2.0 * PI * r * hertz.pressure(depth, r) * a * theta.cos()
        });
        let force = hertz.force(depth);
        assert!((integral / force - 1.0).abs() < 1e-13, "depth {depth}");
        let p0 = 3.0 * force / (2.0 * PI * a * a);
        assert!((hertz.central_pressure(depth) / p0 - 1.0).abs() < 1e-14);
        let h = depth * 1e-4;
        let slope = (hertz.force(depth + h) - hertz.force(depth - h)) / (2.0 * h);
        assert!((slope / hertz.stiffness(depth) - 1.0).abs() < 1e-7);
    }
    assert_eq!(hertz.force(-1e-3), 0.0);
    assert_eq!(hertz.depth_at_force(-1.0), 0.0);
}

/// Flat punch: the Boussinesq pressure integrates to the force
/// (`r = a sin(theta)` again).
#[test]
fn flat_punch_pressure_integrates_to_force() {
    let punch = BoussinesqPunch::new(&rubber(), 2e-3).unwrap();
    let force = punch.force(1e-4);
    assert!((force - 2.0 * 2e-3 * rubber().contact_modulus() * 1e-4).abs() < 1e-15);
    let a = 2e-3;
    let integral = rule(20).integrate(0.0, PI / 2.0, |theta| {
        let r = a * theta.sin();
        2.0 * PI * r * punch.pressure(force, r) * a * theta.cos()
    });
    assert!((integral / force - 1.0).abs() < 1e-14);
    assert_eq!(punch.pressure(force, a), 0.0);
}

/// Kendall: pull-off where the energy release rate from the compliance
/// derivative, `G = (F^2/2) dC/dA` with `C(a) = 1/(2aE*)` differentiated
/// numerically, equals `dgamma`.
#[test]
fn kendall_pull_off_from_compliance_derivative() {
    let material = rubber();
    let (a, dgamma) = (2.5e-3, 0.326);
    let punch = JkrFlatPunch::new(&material, a, dgamma).unwrap();
    let compliance = |radius: f64| 1.0 / (2.0 * radius * material.contact_modulus());
    let h = a * 1e-5;
    let dc_da = (compliance(a + h) - compliance(a - h)) / (2.0 * h);
    let dc_darea = dc_da / (2.0 * PI * a);
    // G = F^2/2 |dC/dA| = dgamma  =>  |F| = sqrt(2 dgamma / |dC/dA|)
    let pull_off = -(2.0 * dgamma / dc_darea.abs()).sqrt();
    assert!((punch.pull_off_force() / pull_off - 1.0).abs() < 1e-9);
    assert!((punch.force(punch.critical_depth()) - punch.pull_off_force()).abs() < 1e-12);
    assert_eq!(punch.force(1.01 * punch.critical_depth()), 0.0);
    // The rim stress intensity factor gives back dgamma at the critical depth.
    let k1 = punch.stress_intensity_factor(punch.critical_depth());
    assert!((k1 * k1 / (2.0 * material.contact_modulus()) / dgamma - 1.0).abs() < 1e-12);
}

/// JKR sphere: the load-controlled pull-off is the numerical minimum of
/// `F(a)`, the displacement-controlled one the minimum of `d(a)`; each point
/// of the curve satisfies the energy balance
/// `(F_Hertz(a) - F)^2 / (8 pi a^3 E*) = dgamma`; `dgamma = 0` is Hertz.
#[test]
fn jkr_sphere_extrema_and_energy_balance() {
    let material = rubber();
    let (radius, dgamma) = (0.05, 0.326);
    let jkr = JkrSphere::new(&material, radius, dgamma).unwrap();
    let scale = jkr.pull_off_contact_radius();

    let a_force = argmin(|a| jkr.force(a), 1e-3 * scale, 10.0 * scale);
    assert!((a_force / scale - 1.0).abs() < 1e-6);
    assert!((jkr.force(a_force) / jkr.pull_off_force() - 1.0).abs() < 1e-12);
    assert!((jkr.pull_off_force() + 1.5 * PI * dgamma * radius).abs() < 1e-15);

    let a_depth = argmin(|a| jkr.depth(a), 1e-3 * scale, 10.0 * scale);
    assert!((a_depth / jkr.critical_contact_radius() - 1.0).abs() < 1e-6);
    assert!((jkr.depth(a_depth) / jkr.critical_depth() - 1.0).abs() < 1e-12);

    let e_star = material.contact_modulus();
    for a in [0.5 * scale, scale, 3.0 * scale] {
        let f_hertz = 4.0 * e_star * a.powi(3) / (3.0 * radius);
        let g = (f_hertz - jkr.force(a)).powi(2) / (8.0 * PI * a.powi(3) * e_star);
        assert!((g / dgamma - 1.0).abs() < 1e-12);
        // Round trips on the stable branches.
        let back = jkr.contact_radius_at_force(jkr.force(a)).unwrap();
        if a >= scale {
            assert!((back / a - 1.0).abs() < 1e-10);
        }
        let back = jkr.contact_radius_at_depth(jkr.depth(a)).unwrap();
        if a >= jkr.critical_contact_radius() {
            assert!((back / a - 1.0).abs() < 1e-12);
        }
    }
    assert_eq!(
        jkr.contact_radius_at_force(1.01 * jkr.pull_off_force()),
        None
    );
    assert_eq!(
        jkr.contact_radius_at_depth(1.01 * jkr.critical_depth()),
        None
    );

    let hertz = Hertz::new(&material, radius).unwrap();
    let sticky_free = JkrSphere::new(&material, radius, 0.0).unwrap();
    let d = 1e-4;
    let a = hertz.contact_radius(d);
    assert!((sticky_free.force(a) / hertz.force(d) - 1.0).abs() < 1e-14);
    assert!((sticky_free.depth(a) / d - 1.0).abs() < 1e-14);
}

/// Cone: the force is the integral of Sneddon's pressure
/// `p(r) = (E* cot(theta)/2) arccosh(a/r)`; the `r ln r` singularity at the
/// apex limits 400 Gauss points to ~1e-9.
#[test]
fn cone_force_is_integral_of_sneddon_pressure() {
    let material = Material::new(70e9, 0.17).unwrap();
    let half_angle = 70.3f64.to_radians();
    let cone = SneddonCone::new(&material, half_angle).unwrap();
    let depth = 1e-7;
    let a = cone.contact_radius(depth);
    let amplitude = 0.5 * material.contact_modulus() / half_angle.tan();
    let integral = rule(400).integrate(0.0, a, |r| 2.0 * PI * r * amplitude * (a / r).acosh());
    assert!((integral / cone.force(depth) - 1.0).abs() < 1e-8);
    // d = (pi/2) a cot(theta)
    assert!((depth / (0.5 * PI * a / half_angle.tan()) - 1.0).abs() < 1e-14);
}

/// Bad input to the closed forms is a typed error naming the value.
#[test]
fn closed_forms_reject_bad_input() {
    let m = rubber();
    let err = Hertz::new(&m, -1.0).unwrap_err();
    assert!(matches!(err, Error::InvalidParameter { name: "radius", value, .. } if value == -1.0));
    assert!(err.to_string().contains("-1"));
    assert!(matches!(
        JkrSphere::new(&m, 0.01, f64::NAN),
        Err(Error::InvalidParameter {
            name: "work_of_adhesion",
            ..
        })
    ));
    assert!(matches!(
        JkrFlatPunch::new(&m, 0.01, -0.1),
        Err(Error::InvalidParameter {
            name: "work_of_adhesion",
            ..
        })
    ));
    assert!(matches!(
        SneddonCone::new(&m, 0.0),
        Err(Error::InvalidParameter {
            name: "half_angle",
            ..
        })
    ));
    assert!(BoussinesqPunch::new(&m, f64::INFINITY).is_err());
}
