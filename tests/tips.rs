//! Exact axisymmetric tips beyond the paraboloid (`analytic::Tip`): the
//! sphere, the cone and the rounded cone, against closed forms on a
//! half-space (Sneddon 1965; JKR cone of Maugis 2000), the paraboloid's own
//! solution, and on coated bodies the identity `dF/dd = K(a)` (the
//! non-adhesive force grows at the stiffness of the flat punch of the
//! current contact radius, for any profile), which involves a different
//! solution (the punch's) from the one tested.

use std::f64::consts::PI;

use layered_contact::analytic::{Axisymmetric, SneddonCone, Tip};
use layered_contact::{Error, Material, Substrate};

fn rubber() -> Material {
    Material::new(1e6, 0.48).unwrap()
}

fn bodies() -> Vec<(&'static str, Substrate)> {
    vec![
        (
            "layer on glass",
            Substrate::layer_on_rigid_base(rubber(), 2e-6).unwrap(),
        ),
        (
            "layer on a softer base",
            Substrate::layer_on_elastic_base(rubber(), 2e-6, Material::new(2e5, 0.3).unwrap())
                .unwrap(),
        ),
        (
            "stack",
            Substrate::stack(
                &[(rubber(), 1e-6), (Material::new(5e6, 0.3).unwrap(), 1e-6)],
                layered_contact::substrate::Base::Rigid,
            )
            .unwrap(),
        ),
    ]
}

const TIPS: [Tip; 4] = [
    Tip::Paraboloid { radius: 3e-6 },
    Tip::Sphere { radius: 3e-6 },
    Tip::Cone { half_angle: 1.2 },
    Tip::RoundedCone {
        half_angle: 1.2,
        tip_radius: 1e-6,
    },
];

#[test]
fn half_space_closed_forms() {
    let half = Axisymmetric::new(&Substrate::half_space(rubber()), 1.0).unwrap();
    let e = rubber().contact_modulus();
    let (r, theta, w) = (3e-6f64, 1.2f64, 0.02);
    for a in [0.1e-6f64, 1e-6, 2.5e-6] {
        // Sneddon's sphere: d = (a/2) ln((R+a)/(R-a)),
        // F = (E*/2) [(a^2 + R^2) ln((R+a)/(R-a)) - 2 a R].
        let log = ((r + a) / (r - a)).ln();
        let s = half
            .tip(Tip::Sphere { radius: r }, 0.0)
            .unwrap()
            .at_contact_radius(a)
            .unwrap();
        assert!((s.depth / (0.5 * a * log) - 1.0).abs() < 1e-13);
        let force = 0.5 * e * ((a * a + r * r) * log - 2.0 * a * r);
        assert!(
            (s.force / force - 1.0).abs() < 1e-9,
            "{} {}",
            s.force,
            force
        );
        // JKR cone (Maugis 2000): d = (pi/2) a cot - sqrt(2 pi a w / E*),
        // F = (pi/2) E* a^2 cot - sqrt(8 pi E* w a^3).
        let c = half
            .tip(Tip::Cone { half_angle: theta }, w)
            .unwrap()
            .at_contact_radius(a)
            .unwrap();
        let cot = 1.0 / theta.tan();
        let depth = 0.5 * PI * a * cot - (2.0 * PI * a * w / e).sqrt();
        let force = 0.5 * PI * e * a * a * cot - (8.0 * PI * e * w * a.powi(3)).sqrt();
        assert!((c.depth / depth - 1.0).abs() < 1e-12);
        assert!((c.force / force - 1.0).abs() < 1e-12);
        let sneddon = SneddonCone::new(&rubber(), theta).unwrap();
        let dry = half
            .tip(Tip::Cone { half_angle: theta }, 0.0)
            .unwrap()
            .at_contact_radius(a)
            .unwrap();
        assert!((dry.force / sneddon.force(dry.depth) - 1.0).abs() < 1e-12);
    }
}

/// The profile's general path (`chi = (I - K)^-1 K g`, a right-hand side
/// of its own) against the paraboloid's quadratic solution, through a
/// sphere a thousand times wider than its contact: its profile `x
/// atanh(x/R) = x^2/R (1 + x^2/(3 R^2) + ...)` differs from its
/// paraboloid's by at most `(a/R)^2 / 3` (6e-7 here) of the profile terms,
/// so depth and force differ by less than `(a/R)^2` of the non-adhesive
/// ones, where a wrong kernel, node or weight would show at once.
#[test]
fn a_wide_sphere_is_its_paraboloid() {
    let radius = 3e-3;
    for (name, body) in bodies() {
        let exact = Axisymmetric::new(&body, 5.0).unwrap();
        let dry = exact.paraboloid(radius, 0.0).unwrap();
        for w in [0.0, 0.02] {
            let sphere = exact.tip(Tip::Sphere { radius }, w).unwrap();
            let ball = exact.paraboloid(radius, w).unwrap();
            for a in [0.2e-6, 1e-6, 4e-6] {
                let (t, b, scale) = (
                    sphere.at_contact_radius(a).unwrap(),
                    ball.at_contact_radius(a).unwrap(),
                    dry.at_contact_radius(a).unwrap(),
                );
                let bound = (a / radius).powi(2);
                assert!(
                    (t.force - b.force).abs() < bound * scale.force.abs(),
                    "{name}: {} against {}",
                    t.force,
                    b.force
                );
                assert!(
                    (t.depth - b.depth).abs() < bound * scale.depth.abs(),
                    "{name}: {} against {}",
                    t.depth,
                    b.depth
                );
            }
        }
    }
}

#[test]
fn force_grows_at_the_punch_stiffness_for_every_tip_and_body() {
    // Central differences in the contact radius (step 1e-4 a): truncation
    // about 1e-8 relative; bound 1e-6.
    for (name, body) in bodies() {
        let exact = Axisymmetric::new(&body, 5.0).unwrap();
        for tip in TIPS {
            let states = exact.tip(tip, 0.0).unwrap();
            // Inside and beyond the rounded cone's kink (b = 0.36 um).
            for a in [0.3e-6, 0.8e-6, 2.5e-6] {
                let h = 1e-4 * a;
                let (lo, hi) = (
                    states.at_contact_radius(a - h).unwrap(),
                    states.at_contact_radius(a + h).unwrap(),
                );
                let slope = (hi.force - lo.force) / (hi.depth - lo.depth);
                let punch = exact.flat_punch(a).unwrap().stiffness();
                assert!(
                    (slope / punch - 1.0).abs() < 1e-6,
                    "{name} {tip:?} a {a}: {slope} {punch}"
                );
            }
        }
    }
}

#[test]
fn adhesive_tips_pull_off_where_the_force_is_least() {
    // The JKR cone on a half-space (Maugis 2000): from the closed forms
    // above, F(a) is least at a = 18 w tan^2 / (pi E*) and d(a) at
    // 2 w tan^2 / (pi E*); the search (a logarithmic scan refined by golden
    // section) finds both.
    let half = Axisymmetric::new(&Substrate::half_space(rubber()), 1.0).unwrap();
    let e = rubber().contact_modulus();
    let (theta, w) = (1.2f64, 0.02);
    let pull = half
        .tip(Tip::Cone { half_angle: theta }, w)
        .unwrap()
        .pull_off()
        .unwrap();
    // dF/da = 0: pi E* a cot = (3/2) sqrt(8 pi E* w a) -> a = 18 w tan^2 / (pi E*).
    let a = 18.0 * w * theta.tan().powi(2) / (PI * e);
    assert!((pull.load_control.contact_radius / a - 1.0).abs() < 1e-6);
    let cot = 1.0 / theta.tan();
    let force = 0.5 * PI * e * a * a * cot - (8.0 * PI * e * w * a.powi(3)).sqrt();
    assert!((pull.load_control.force / force - 1.0).abs() < 1e-12);
    // dd/da = 0: (pi/2) cot = (1/2) sqrt(2 pi w / (E* a)) -> a = 2 w tan^2 / (pi E*).
    let a = 2.0 * w * theta.tan().powi(2) / (PI * e);
    assert!((pull.displacement_control.contact_radius / a - 1.0).abs() < 1e-6);
}

#[test]
fn bad_tips_are_refused() {
    let exact = Axisymmetric::new(&Substrate::half_space(rubber()), 1.0).unwrap();
    for tip in [
        Tip::Cone { half_angle: 0.0 },
        Tip::Cone {
            half_angle: PI / 2.0,
        },
        Tip::Cone {
            half_angle: f64::NAN,
        },
        Tip::Sphere { radius: -1.0 },
        Tip::RoundedCone {
            half_angle: 1.0,
            tip_radius: 0.0,
        },
        Tip::Paraboloid {
            radius: f64::INFINITY,
        },
    ] {
        assert!(
            matches!(exact.tip(tip, 0.0), Err(Error::InvalidParameter { .. })),
            "{tip:?}"
        );
    }
    assert!(exact.tip(Tip::Cone { half_angle: 1.0 }, -1.0).is_err());
    let sphere = exact.tip(Tip::Sphere { radius: 1e-6 }, 0.0).unwrap();
    assert!(matches!(
        sphere.at_contact_radius(0.96e-6),
        Err(Error::InvalidParameter { .. })
    ));
    assert!(sphere.at_contact_radius(0.94e-6).unwrap().force.is_finite());
    assert!(exact
        .tip(Tip::Cone { half_angle: 1.0 }, 0.0)
        .unwrap()
        .pull_off()
        .is_err());
}

#[test]
fn cantilever_pull_off_and_jump_in_on_the_jkr_sphere() {
    // JKR on a half-space: F(a) = 4 E* a^3/(3R) - sqrt(8 pi E* w a^3),
    // d(a) = a^2/R - sqrt(2 pi a w / E*), and their derivatives in closed
    // form. The spring's pull-off has F'/d' = -k, its jump-in F + k d = 0;
    // soft and stiff springs tend to load and displacement control.
    let half = Axisymmetric::new(&Substrate::half_space(rubber()), 1.0).unwrap();
    let e = rubber().contact_modulus();
    let (r, w) = (3e-6f64, 0.02);
    let ball = half.tip(Tip::Paraboloid { radius: r }, w).unwrap();
    let pull = ball.pull_off().unwrap();
    let slope = |a: f64| {
        let force = 4.0 * e * a * a / r - 1.5 * (8.0 * PI * e * w * a).sqrt();
        let depth = 2.0 * a / r - 0.5 * (2.0 * PI * w / (e * a)).sqrt();
        force / depth
    };
    for k in [0.01, 0.1, 1.0, 10.0] {
        let s = ball.spring_pull_off(k).unwrap();
        assert!((slope(s.contact_radius) / -k - 1.0).abs() < 1e-5, "k {k}");
        let j = ball.spring_jump_in(k).unwrap();
        assert!(
            (j.force + k * j.depth).abs() < 1e-9 * j.force.abs(),
            "k {k}"
        );
        assert!(j.force < 0.0 && j.depth > 0.0);
    }
    let soft = ball.spring_pull_off(1e-9).unwrap();
    assert!((soft.force / pull.load_control.force - 1.0).abs() < 1e-8);
    let stiff = ball.spring_pull_off(1e9).unwrap();
    assert!((stiff.depth / pull.displacement_control.depth - 1.0).abs() < 1e-8);
    assert!(ball.spring_pull_off(0.0).is_err() && ball.spring_jump_in(f64::NAN).is_err());
}

#[test]
fn tips_at_a_depth_or_force_invert_the_closed_forms() {
    // The JKR sphere beyond the paraboloid (Maugis 1995): with Sneddon's
    // d_s(a) = (a/2) L and F_s(a) = (E*/2) [(a^2 + R^2) L - 2 a R],
    // L = ln((R+a)/(R-a)), the adhesive contact has d = d_s - sqrt(2 pi a
    // w / E*) and F = F_s - sqrt(8 pi E* w a^3); the JKR cone as in
    // `half_space_closed_forms`. The searches by depth and by force must
    // land on the radius the closed forms were evaluated at (bisection to
    // 2^-50 of a bracket of about 10 % of `a`: 1e-13 relative, and the
    // force along with it).
    let half = Axisymmetric::new(&Substrate::half_space(rubber()), 1.0).unwrap();
    let e = rubber().contact_modulus();
    let (r, theta, w) = (3e-6f64, 1.2f64, 0.02);
    let sphere = half.tip(Tip::Sphere { radius: r }, w).unwrap();
    let cone = half.tip(Tip::Cone { half_angle: theta }, w).unwrap();
    let cot = 1.0 / theta.tan();
    let exact_sphere = |a: f64| {
        let log = ((r + a) / (r - a)).ln();
        (
            0.5 * a * log - (2.0 * PI * a * w / e).sqrt(),
            0.5 * e * ((a * a + r * r) * log - 2.0 * a * r) - (8.0 * PI * e * w * a.powi(3)).sqrt(),
        )
    };
    let exact_cone = |a: f64| {
        (
            0.5 * PI * a * cot - (2.0 * PI * a * w / e).sqrt(),
            0.5 * PI * e * a * a * cot - (8.0 * PI * e * w * a.powi(3)).sqrt(),
        )
    };
    // Radii on the stable branches of both controls (beyond the
    // load-controlled pull-off radius: about 0.79 um for the sphere, as its
    // paraboloid's `0.63 a_0`, and 0.58 um for the cone).
    for (tip, exact) in [
        (&sphere, &exact_sphere as &dyn Fn(f64) -> (f64, f64)),
        (&cone, &exact_cone),
    ] {
        for a in [1.0e-6, 1.5e-6, 2.6e-6] {
            let (depth, force) = exact(a);
            let by_depth = tip.at_depth(depth).unwrap().unwrap();
            assert!((by_depth.contact_radius / a - 1.0).abs() < 1e-12, "{a}");
            assert!((by_depth.force - force).abs() < 1e-11 * force.abs().max(1e-9));
            let by_force = tip.at_force(force).unwrap().unwrap();
            assert!((by_force.contact_radius / a - 1.0).abs() < 1e-12, "{a}");
            assert!((by_force.depth - depth).abs() < 1e-11 * depth.abs().max(1e-12));
        }
        // Below the pull-offs there is no adhesive equilibrium.
        let pull = tip.pull_off().unwrap();
        assert!(tip
            .at_force(1.01 * pull.load_control.force)
            .unwrap()
            .is_none());
        assert!(tip
            .at_depth(pull.displacement_control.depth - 1e-9)
            .unwrap()
            .is_none());
    }
    // A depth the cap cannot reach (its contact beyond 0.95 R) is refused,
    // naming the depth; without adhesion nothing touches at depth 0.
    let too_deep = exact_sphere(0.96 * r).0;
    assert!(matches!(
        sphere.at_depth(too_deep),
        Err(Error::InvalidParameter { name: "depth", .. })
    ));
    let dry = half.tip(Tip::Sphere { radius: r }, 0.0).unwrap();
    assert!(dry.at_depth(0.0).unwrap().is_none());
    assert!(dry.at_depth(-1e-9).unwrap().is_none());
}

#[test]
fn tips_at_a_depth_on_coated_bodies_invert_their_contact_radius() {
    // On coated bodies no closed form: the state the search finds at the
    // depth of a known contact radius is that radius's.
    for (name, body) in bodies() {
        let exact = Axisymmetric::up_to_contact_radius(&body, 2.9e-6).unwrap();
        for tip in TIPS {
            let tip = exact.tip(tip, 0.02).unwrap();
            for a in [1.2e-6, 2.5e-6] {
                let state = tip.at_contact_radius(a).unwrap();
                let found = tip.at_depth(state.depth).unwrap().unwrap();
                assert!(
                    (found.contact_radius / a - 1.0).abs() < 1e-12,
                    "{name} {tip:?} {a}"
                );
                let found = tip.at_force(state.force).unwrap().unwrap();
                assert!(
                    (found.contact_radius / a - 1.0).abs() < 1e-12,
                    "{name} {tip:?} {a}"
                );
            }
        }
    }
}

/// The closed-form JKR cone (`analytic::JkrCone`, Maugis & Barquins 1981)
/// against the exact cone on a half-space, whose pull-offs come from a
/// numerical minimisation of the Fredholm solution's force and depth (an
/// independent path: no closed form of the pull-off is used there). The
/// minimisation locates the least force to about `1e-8` of the radius
/// (its force to the square of that), so radii are compared to `1e-6` and
/// forces and depths to `1e-10`; the inversions by force and depth are
/// bisections to full precision (`1e-12`).
#[test]
fn jkr_cone_closed_form_matches_the_exact_cone() {
    use layered_contact::analytic::JkrCone;
    let half = Axisymmetric::new(&Substrate::half_space(rubber()), 1.0).unwrap();
    for (theta, w) in [(1.2f64, 0.02), (1.3, 0.05), (0.6, 0.1)] {
        let closed = JkrCone::new(&rubber(), theta, w).unwrap();
        let exact = half.tip(Tip::Cone { half_angle: theta }, w).unwrap();
        let pull = exact.pull_off().unwrap();
        let load = pull.load_control;
        assert!((load.force / closed.pull_off_force() - 1.0).abs() < 1e-10);
        assert!((load.contact_radius / closed.pull_off_contact_radius() - 1.0).abs() < 1e-6);
        let fixed = pull.displacement_control;
        assert!((fixed.depth / closed.critical_depth() - 1.0).abs() < 1e-10);
        assert!((fixed.contact_radius / closed.critical_contact_radius() - 1.0).abs() < 1e-6);
        // The stable branches, by force and by depth, against the exact
        // solution's own searches.
        for scale in [0.5, 1.0, 10.0] {
            let force = scale * closed.pull_off_force().abs();
            let a = closed.contact_radius_at_force(force).unwrap();
            let at = exact.at_force(force).unwrap().unwrap();
            assert!(
                (a / at.contact_radius - 1.0).abs() < 1e-12,
                "{theta} {scale}"
            );
            let depth = closed.depth(a);
            let b = closed.contact_radius_at_depth(depth).unwrap();
            assert!((b / a - 1.0).abs() < 1e-12, "{theta} {scale}");
        }
        // No adhesive equilibrium below the pull-offs; none for NaN.
        assert!(closed
            .contact_radius_at_force(1.001 * closed.pull_off_force())
            .is_none());
        assert!(closed
            .contact_radius_at_depth(1.001 * closed.critical_depth())
            .is_none());
        assert!(closed.contact_radius_at_force(f64::NAN).is_none());
    }
    // Without adhesion, Sneddon's cone.
    let dry = JkrCone::new(&rubber(), 1.2, 0.0).unwrap();
    let sneddon = SneddonCone::new(&rubber(), 1.2).unwrap();
    let a = dry.contact_radius_at_depth(1e-6).unwrap();
    assert!((a / sneddon.contact_radius(1e-6) - 1.0).abs() < 1e-13);
    assert!(JkrCone::new(&rubber(), 1.6, 0.05).is_err());
    assert!(JkrCone::new(&rubber(), 1.2, -0.05).is_err());
}

/// A cone on a stiff layer resting on a far softer base, with a large work
/// of adhesion (the cohesive reference sweep's seed 75: a 52 GPa layer 0.5
/// mm thick over a base 970 times softer, 1.7e5 J/m^2): the depth of its
/// adhesive branch rises with the contact radius to a local maximum
/// (1.16e-3 m near 0.51 mm) and then falls (the base's own JKR branch,
/// -4.5e-3 m at 8.8 mm). The loading equilibrium at a depth below that
/// maximum is the root on the rising part, about 0.26 mm, where the
/// cohesive zone's grid solution lands (0.27 mm at 16 cells across, +3.7 %
/// in its contact radius, +0.19 % in its peak force): the walk from Sneddon's radius (0.71 mm, on the falling
/// part) read its first rising sample as the branch's minimum and ended in
/// `InvalidParameter` from a least depth at the table's end. Checked
/// against direct evaluations: the depth equal to the target, rising
/// through it.
#[test]
fn a_root_beyond_a_local_maximum_of_the_branch_is_found() {
    let body = Substrate::layer_resting_on_elastic_base(
        Material::new(5.233563611308424e10, 0.2).unwrap(),
        4.978801340756114e-4,
        Material::new(5.3796043836172484e7, 0.49).unwrap(),
    )
    .unwrap();
    let exact = Axisymmetric::up_to_contact_radius(&body, 1.1e-2).unwrap();
    let cone = exact
        .tip(
            Tip::Cone {
                half_angle: 1.1913977797509538,
            },
            1.742310475350797e5,
        )
        .unwrap();
    // The branch: up to a local maximum of the depth, then down.
    let depth = |a: f64| cone.at_contact_radius(a).unwrap().depth;
    assert!(depth(5.1e-4) > 1e-3 && depth(8.8e-3) < -4e-3);
    let target = 4.475263158937329e-4;
    let state = cone.at_depth(target).unwrap().unwrap();
    let a = state.contact_radius;
    assert!((state.depth / target - 1.0).abs() < 1e-9, "{state:?}");
    assert!((2.5e-4..2.8e-4).contains(&a), "{a}");
    assert!(depth(0.99 * a) < target && target < depth(1.01 * a));
}
