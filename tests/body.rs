//! Materials, substrates and the coating functions: validation, exact limits,
//! and properties over the whole parameter box (seeded proptest).

use layered_contact::analytic::{a_m, lambda};
use layered_contact::substrate::{Base, CoatingFunctions};
use layered_contact::{Error, Material, Substrate};
use proptest::prelude::*;

/// Lyashenko, Popov & Borysiuk (2023), written exactly as printed. For a rigid base every term of
/// numerator and denominator has the sign of `L < 0`, so this naive form has
/// no cancellation and is an independent reference at full precision.
fn lambda_spec(u: f64, nu: f64) -> f64 {
    let l = 4.0 * nu - 3.0;
    let e2 = (-2.0 * u).exp();
    let e4 = e2 * e2;
    (2.0 * l * e4 - (l * l + 1.0 + 4.0 * u + 4.0 * u * u) * e2)
        / (l * e4 - (l * l + 1.0 + 4.0 * u * u) * e2 + l)
}

#[test]
fn material_values_and_errors() {
    let m = Material::new(2.0e11, 0.3).unwrap();
    assert!((m.contact_modulus() - 2.0e11 / 0.91).abs() < 1e-3);
    assert!((m.shear_modulus() - 2.0e11 / 2.6).abs() < 1e-3);
    assert_eq!(m.kolosov_constant(), 3.0 - 1.2);
    let incompressible = Material::new(1e6, 0.5).unwrap();
    assert_eq!(incompressible.contact_modulus(), 1e6 / 0.75);
    assert_eq!(incompressible.uniaxial_strain_modulus(), f64::INFINITY);

    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let err = Material::new(bad, 0.3).unwrap_err();
        assert!(
            matches!(err, Error::InvalidYoungsModulus { value } if value.to_bits() == bad.to_bits())
        );
        assert!(err.to_string().contains(&format!("{bad}")));
    }
    // E finite but E* = E/(1 - nu^2) overflows.
    assert!(matches!(
        Material::new(f64::MAX, 0.5),
        Err(Error::InvalidYoungsModulus { .. })
    ));
    for bad in [-0.01, 0.5000001, f64::NAN, 1.0] {
        let err = Material::new(1e6, bad).unwrap_err();
        assert!(matches!(err, Error::InvalidPoissonRatio { .. }));
        assert!(err.to_string().contains(&format!("{bad}")));
    }
    // The accepted range is [1e-150, 1e150] Pa: 1.2e308 made every influence
    // coefficient underflow to 0 and a subnormal E made them infinite (issue
    // 12, finding 5); both ends are accepted, just beyond them refused.
    for bad in [1e-300, 5e-324, 0.9999e-150, 1.0001e150, 1.2e308] {
        assert!(matches!(
            Material::new(bad, 0.0),
            Err(Error::InvalidYoungsModulus { value }) if value == bad
        ));
    }
    assert!(Material::new(1e-150, 0.0).is_ok() && Material::new(1e150, 0.5).is_ok());
}

#[test]
fn substrate_limits_reduce_exactly() {
    let layer = Material::new(1e6, 0.48).unwrap();
    let base = Material::new(1e9, 0.3).unwrap();
    assert_eq!(
        Substrate::layer_on_elastic_base(layer, 0.0, base).unwrap(),
        Substrate::HalfSpace(base)
    );
    assert_eq!(
        Substrate::layer_on_elastic_base(layer, f64::INFINITY, base).unwrap(),
        Substrate::HalfSpace(layer)
    );
    assert_eq!(
        Substrate::layer_on_elastic_base(layer, 1e-3, layer).unwrap(),
        Substrate::HalfSpace(layer)
    );
    assert_eq!(
        Substrate::layer_on_rigid_base(layer, f64::INFINITY).unwrap(),
        Substrate::HalfSpace(layer)
    );
    let Substrate::Coated(coating) = Substrate::layer_on_elastic_base(layer, 2e-3, base).unwrap()
    else {
        panic!("a real coating must stay coated")
    };
    assert_eq!(coating.thickness(), 2e-3);
    assert_eq!(coating.layer(), &layer);
    assert_eq!(coating.base(), &Base::Elastic(base));

    for bad in [-1e-3, f64::NAN, f64::NEG_INFINITY] {
        let err = Substrate::layer_on_elastic_base(layer, bad, base).unwrap_err();
        assert!(
            matches!(err, Error::InvalidThickness { value, .. } if value.to_bits() == bad.to_bits())
        );
    }
    for bad in [0.0, -1e-3, f64::NAN] {
        let err = Substrate::layer_on_rigid_base(layer, bad).unwrap_err();
        assert!(matches!(err, Error::InvalidThickness { .. }));
        assert!(err.to_string().contains(&format!("{bad}")));
    }
}

/// `Lambda` against the printed formula of Lyashenko et al. (2023) (see `lambda_spec`), relative
/// error below 4 ulp wherever the reference has not underflowed; exact
/// `Lambda(0) = 1`; no NaN or overflow out to `u = 1e300`.
#[test]
fn lambda_matches_spec_formula() {
    for nu in [0.0, 0.1, 0.25, 0.3, 0.45, 0.48, 0.4999, 0.5] {
        assert!((lambda(0.0, nu).unwrap() - 1.0).abs() < 1e-15);
        for i in 1..=3000 {
            let u = i as f64 * 0.1;
            let reference = lambda_spec(u, nu);
            let value = lambda(u, nu).unwrap();
            if reference > 1e-290 {
                let err = (value / reference - 1.0).abs();
                assert!(err < 1e-15, "nu {nu}, u {u}: {value:e} vs {reference:e}");
            } else {
                assert!(value.abs() < 1e-280);
            }
        }
        for u in [1e3, 1e10, 1e300, f64::INFINITY] {
            assert_eq!(lambda(u, nu).unwrap(), 0.0);
        }
    }
    assert!(matches!(
        lambda(1.0, 0.6),
        Err(Error::InvalidPoissonRatio { .. })
    ));
}

/// Huge orders return at once: `|a_m| ~ m^2 4^-m` underflows beyond m ~ 530.
#[test]
fn huge_moment_orders_underflow_quickly() {
    assert!(a_m(500, 0.3).unwrap().abs() < 1e-290);
    assert_eq!(a_m(u32::MAX, 0.3).unwrap(), 0.0);
}

/// Higher moments against an independent quadrature of `lambda_spec` times
/// `(u/2)^(2m) / (m!)^2` with a different rule (40 points on panels of 0.5),
/// to 1e-12.
#[test]
fn higher_moments_match_independent_quadrature() {
    let rule = gauss_quad::legendre::GaussLegendre::new(40.try_into().unwrap());
    for nu in [0.0, 0.35, 0.5] {
        for m in [3u32, 5, 10, 20] {
            let factorial: f64 = (1..=m).map(f64::from).product();
            let weight = |u: f64| (0.5 * u).powi(2 * m as i32) / (factorial * factorial);
            let integral: f64 = (0..400)
                .map(|k| {
                    let start = 0.5 * k as f64;
                    rule.integrate(start, start + 0.5, |u| lambda_spec(u, nu) * weight(u))
                })
                .sum();
            let expected = if m % 2 == 0 { integral } else { -integral };
            let value = a_m(m, nu).unwrap();
            assert!(
                (value / expected - 1.0).abs() < 1e-12,
                "a_{m}({nu}) = {value:e}, independent {expected:e}"
            );
        }
    }
}

/// A base material from `log10(E2/E1)` in `[-6, 100]`, or the rigid base.
fn base_strategy() -> impl Strategy<Value = Base> {
    prop_oneof![
        Just(Base::Rigid),
        (-6.0f64..100.0, 0.0f64..=0.5).prop_map(|(log_ratio, nu2)| Base::Elastic(
            Material::new(10f64.powf(log_ratio), nu2).unwrap()
        )),
    ]
}

fn nu_strategy() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.5), Just(0.4999), Just(0.0), 0.0f64..=0.5]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, rng_seed: proptest::test_runner::RngSeed::Fixed(20261121), ..ProptestConfig::default() })]

    /// `R` is finite and positive (zero only at `t = 0` on a rigid base), and
    /// `R + Lambda_g = 1` to rounding, for `t` from 0 to 1e6.
    #[test]
    fn coating_functions_are_finite_and_consistent(
        nu1 in nu_strategy(), base in base_strategy(), log_t in -12.0f64..6.0,
    ) {
        let layer = Material::new(1.0, nu1).unwrap();
        let f = CoatingFunctions::new(&layer, &base);
        for t in [0.0, 10f64.powf(log_t)] {
            let r = f.r(t);
            let l = f.lambda(t);
            prop_assert!(r.is_finite() && l.is_finite());
            prop_assert!(r > 0.0 || (t == 0.0 && base == Base::Rigid) || r == 0.0 && t < 1e-100);
            prop_assert!((r + l - 1.0).abs() <= 2e-15 * (1.0 + r), "t {}: R {} Lambda {}", t, r, l);
        }
    }

    /// `R(0) = E1*/E2*` exactly (to rounding of `G`), and `R` tends to it
    /// continuously: `R(t)/R(0) - 1 = t (n1/n0 - d1/d0) + O(t^2)` with
    /// `n1/n0 ~ 1/G` and `d1/d0 ~ G`, so `|R(t)/R(0) - 1| < 10 (G + 1/G) t`.
    #[test]
    fn thin_layer_limit_is_the_base(nu1 in nu_strategy(), nu2 in 0.0f64..=0.5, log_ratio in -6.0f64..6.0) {
        let layer = Material::new(1.0, nu1).unwrap();
        let base = Material::new(10f64.powf(log_ratio), nu2).unwrap();
        let f = CoatingFunctions::new(&layer, &Base::Elastic(base));
        let expected = layer.contact_modulus() / base.contact_modulus();
        prop_assert!((f.r(0.0) / expected - 1.0).abs() < 4e-15);
        let t = 1e-14;
        let g = f.shear_ratio();
        prop_assert!((f.r(t) / f.r(0.0) - 1.0).abs() < 10.0 * (g + 1.0 / g) * t);
    }

    /// Thick-layer limit: `|1 - R(t)| = |Lambda_g(t)| <= 2e4 t^2 e^(-2t)` (the
    /// bound of the direct form's numerator for `|lam|, |m| <= 3`), up to the
    /// two roundings of `R = N/D`.
    #[test]
    fn thick_layer_limit_is_the_layer(nu1 in nu_strategy(), base in base_strategy(), t in 20.0f64..400.0) {
        let layer = Material::new(1.0, nu1).unwrap();
        let f = CoatingFunctions::new(&layer, &base);
        let bound = 2e4 * t * t * (-2.0 * t).exp();
        prop_assert!((f.r(t) - 1.0).abs() <= bound.max(2.0 * f64::EPSILON));
        prop_assert!(f.lambda(t).abs() <= bound);
    }

    /// A base with `E2 = 1e100 E1` is the rigid base to 1e-9 (the rigid-base limit).
    #[test]
    fn stiff_base_is_rigid_base(nu1 in nu_strategy(), nu2 in 0.0f64..=0.5, log_t in -8.0f64..3.0) {
        let layer = Material::new(1.0, nu1).unwrap();
        let stiff = CoatingFunctions::new(&layer, &Base::Elastic(Material::new(1e100, nu2).unwrap()));
        let rigid = CoatingFunctions::new(&layer, &Base::Rigid);
        let t = 10f64.powf(log_t);
        prop_assert!((stiff.r(t) - rigid.r(t)).abs() <= 1e-9 * rigid.r(t) + 1e-90);
        prop_assert!((stiff.lambda(t) - rigid.lambda(t)).abs() <= 1e-9 * rigid.lambda(t).abs() + 1e-90);
    }

    /// On a rigid base the layer is stiffer than its half-space at every
    /// wavelength: `0 <= Lambda <= 1`.
    #[test]
    fn rigid_base_lambda_is_a_fraction(nu in nu_strategy(), u in 0.0f64..50.0) {
        let l = lambda(u, nu).unwrap();
        prop_assert!((0.0..=1.0 + 4e-16).contains(&l), "Lambda({}) = {}", u, l);
    }
}
