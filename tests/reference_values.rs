//! The analytic module and the coating factor against the independently
//! computed high-precision values of `tests/data/analytic.json` (a copy of
//! the project's `shared/reference/analytic.json`, 80-digit arithmetic).

use layered_contact::analytic::{a_m, PunchStiffnessSeries};
use layered_contact::substrate::{Base, CoatingFunctions};
use layered_contact::Material;
use serde_json::Value;

fn reference() -> Value {
    let text = include_str!("data/analytic.json");
    serde_json::from_str(text).expect("reference file is valid JSON")
}

fn rel_err(value: f64, reference: f64) -> f64 {
    ((value - reference) / reference).abs()
}

/// `a0`, `a1`, `a2` for eight Poisson ratios. Tolerance 1e-12 relative (the
/// issue's bar); the quadrature reaches ~2e-15, so 1e-12 leaves room for
/// compiler and libm differences only.
#[test]
fn moments_a_m_match_reference_to_1e_12() {
    let data = reference();
    let by_nu = data["a_m"]["by_nu"].as_object().unwrap();
    assert_eq!(by_nu.len(), 8);
    let mut worst = 0.0f64;
    for (nu, moments) in by_nu {
        let nu: f64 = nu.parse().unwrap();
        for m in 0..3u32 {
            let expected = moments[format!("a{m}")].as_f64().unwrap();
            let err = rel_err(a_m(m, nu).unwrap(), expected);
            worst = worst.max(err);
            assert!(err < 1e-12, "a{m}(nu = {nu}): relative error {err:e}");
        }
    }
    // The accuracy actually reached, so a regression shows up here first.
    assert!(worst < 1e-14, "worst a_m error {worst:e}");
}

/// The Eq. 5 table for nu = 0.48, all h and D, to 1e-12 relative.
#[test]
fn series_table_matches_reference_to_1e_12() {
    let data = reference();
    let table = data["eq5_ratio_nu_0.48"]["table"].as_object().unwrap();
    let rubber = Material::new(0.324e6, 0.48).unwrap();
    let mut count = 0;
    for (h_mm, row) in table {
        let h = h_mm.parse::<f64>().unwrap() * 1e-3;
        let series = PunchStiffnessSeries::new(rubber, h).unwrap();
        for (d_mm, expected) in row.as_object().unwrap() {
            let radius = 0.5 * d_mm.parse::<f64>().unwrap() * 1e-3;
            let k = series.evaluate(radius).unwrap();
            let err = rel_err(k.ratio, expected.as_f64().unwrap());
            assert!(err < 1e-12, "h = {h_mm} mm, D = {d_mm} mm: error {err:e}");
            assert_eq!(k.eps, radius / h);
            assert_eq!(k.is_within_validity(), radius <= h);
            count += 1;
        }
    }
    assert_eq!(count, 30);
}

/// The diameter at which the h = 5 mm curve reaches 1.2, by bisection in the
/// test (the series increases monotonically with D on (0, 2h]), to 1e-6 mm.
#[test]
fn crossing_of_1_2_at_h_5mm() {
    let data = reference();
    let expected_mm = data["eq5_D_where_ratio_is_1.2_for_h_5mm"]["value_mm"]
        .as_f64()
        .unwrap();
    let series = PunchStiffnessSeries::new(Material::new(0.324e6, 0.48).unwrap(), 5e-3).unwrap();
    let ratio = |d_mm: f64| series.evaluate(0.5e-3 * d_mm).unwrap().ratio - 1.2;
    let (mut lo, mut hi) = (0.1, 5.0);
    assert!(ratio(lo) < 0.0 && ratio(hi) > 0.0);
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if ratio(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let found = 0.5 * (lo + hi);
    assert!(
        (found - expected_mm).abs() < 1e-6,
        "crossing at {found} mm, reference {expected_mm} mm"
    );
    // The paper: h/D = 3.2 there.
    assert!((5.0 / found - 3.2).abs() < 0.01);
}

/// Every coating-factor point (rigid base, E2/E1 from 1e-3 to 1e100, nu1 up to
/// 0.5, q h from 0 to 100) to 5e-15 relative (absolute where R = 0).
#[test]
fn coating_factor_matches_reference_to_5e_15() {
    let data = reference();
    let points = data["coating_factor"]["points"].as_array().unwrap();
    assert_eq!(points.len(), 100);
    let e1 = 1.0e6;
    for point in points {
        let t = point["qh"].as_f64().unwrap();
        let nu1 = point["nu1"].as_f64().unwrap();
        let nu2 = point["nu2"].as_f64().unwrap();
        let expected: f64 = point["R"].as_str().unwrap().parse().unwrap();
        let layer = Material::new(e1, nu1).unwrap();
        let base = match &point["E2_over_E1"] {
            Value::String(s) if s == "inf" => Base::Rigid,
            ratio => Base::Elastic(Material::new(ratio.as_f64().unwrap() * e1, nu2).unwrap()),
        };
        let r = CoatingFunctions::new(&layer, &base).r(t);
        let err = if expected == 0.0 {
            r.abs()
        } else {
            rel_err(r, expected)
        };
        assert!(
            err < 5e-15,
            "R({t}) for {point}: got {r:e}, expected {expected:e}, error {err:e}"
        );
    }
}
