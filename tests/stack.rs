//! Stacks of bonded layers: the recursion against an independent 50-digit
//! solution, the closed form of one layer, and the exact limits.

use layered_contact::kernel::FourierCompliance;
use layered_contact::substrate::{Base, CoatingFunctions, StackFunctions};
use layered_contact::{Material, Substrate};

fn material(value: &serde_json::Value) -> Material {
    Material::new(
        value["youngs_modulus"].as_f64().unwrap(),
        value["poisson_ratio"].as_f64().unwrap(),
    )
    .unwrap()
}

/// Every point of `tests/data/stack_reference.json` (36 three-layer stacks:
/// hard/soft/hard and soft/hard/soft at contrasts 10 and 1000, nu from 0 to
/// 0.5, rigid and elastic bases, t from 1e-3 to 30), computed by
/// `tests/data/stack_reference.py` from the direct boundary-value system in
/// 50-digit arithmetic: R and Lambda_g = 1 - R, each relative to itself.
/// Measured: R within 5.1e-15, Lambda within 7.7e-14 for t <= 10 and 3.5e-13
/// at t = 30 (Lambda ~ 1e-25); asserted 1e-14 and 1e-12.
#[test]
fn three_layer_stacks_match_the_direct_solution() {
    let data: serde_json::Value =
        serde_json::from_str(include_str!("data/stack_reference.json")).unwrap();
    let mut worst = (0.0f64, 0.0f64);
    let mut count = 0;
    for case in data["cases"].as_array().unwrap() {
        let layers: Vec<(Material, f64)> = case["layers"]
            .as_array()
            .unwrap()
            .iter()
            .map(|l| (material(l), l["thickness"].as_f64().unwrap()))
            .collect();
        let base = if case["base"].is_null() {
            Base::Rigid
        } else {
            Base::Elastic(material(&case["base"]))
        };
        let f = StackFunctions::unmerged(&layers, base).unwrap();
        for point in case["points"].as_array().unwrap() {
            let t = point["t"].as_f64().unwrap();
            let r: f64 = point["r"].as_str().unwrap().parse().unwrap();
            let lambda: f64 = point["lambda"].as_str().unwrap().parse().unwrap();
            let r_error = (f.r(t) / r - 1.0).abs();
            let lambda_error = (f.lambda(t) / lambda - 1.0).abs();
            println!(
                "{} t={t}: R {r_error:.1e} Lambda {lambda_error:.1e}",
                case["name"]
            );
            worst = (worst.0.max(r_error), worst.1.max(lambda_error));
            count += 1;
        }
    }
    println!(
        "{count} points, worst R {:.1e}, worst Lambda {:.1e}",
        worst.0, worst.1
    );
    assert_eq!(count, 576);
    assert!(worst.0 < 1e-14 && worst.1 < 1e-12, "{worst:?}");
}

fn logspace(from: f64, to: f64, count: usize) -> impl Iterator<Item = f64> {
    let ratio = (to / from).powf(1.0 / (count - 1) as f64);
    (0..count).map(move |k| from * ratio.powi(k as i32))
}

/// One layer through the recursion against the closed form of Perriot &
/// Barthel (2004), to its rounding: 3 bases x 4 Poisson ratios x 41 values
/// of `t` from 1e-4 to 1e2. Measured: R within 3.6e-15; Lambda within
/// 2.8e-13 of itself down to 1e-20 (t ~ 20), and within 3.6e-12 of itself
/// in the tail beyond (t = 100, Lambda ~ 1e-85), where the layer factors of
/// the congruence lose digits like (q h)^2. Asserted: 1e-14 for R, 1e-12 for
/// Lambda above 1e-20 and 1e-11 below.
#[test]
fn one_layer_recursion_matches_the_closed_form() {
    let bases = [
        Base::Rigid,
        Base::Elastic(Material::new(1e3, 0.3).unwrap()),
        Base::Elastic(Material::new(1e9, 0.2).unwrap()),
    ];
    let (mut worst_r, mut worst_lambda, mut worst_tail) = (0.0f64, 0.0f64, 0.0f64);
    for base in bases {
        for nu in [0.0, 0.3, 0.49, 0.5] {
            let layer = Material::new(1e6, nu).unwrap();
            let closed = CoatingFunctions::new(&layer, &base);
            let stack = StackFunctions::unmerged(&[(layer, 2e-3)], base).unwrap();
            for t in logspace(1e-4, 1e2, 41) {
                worst_r = worst_r.max((stack.r(t) / closed.r(t) - 1.0).abs());
                let error = (stack.lambda(t) / closed.lambda(t) - 1.0).abs();
                if closed.lambda(t).abs() > 1e-20 {
                    worst_lambda = worst_lambda.max(error);
                } else {
                    worst_tail = worst_tail.max(error);
                }
            }
        }
    }
    println!("worst R {worst_r:.1e}, Lambda {worst_lambda:.1e}, tail {worst_tail:.1e}");
    assert!(worst_r < 1e-14 && worst_lambda < 1e-12 && worst_tail < 1e-11);
}

/// Layers of one material split anywhere equal the one layer of the summed
/// thickness (the propagators compose), compared at the same wavenumber
/// `q` from 1e-3 to 20 (Lambda down to 5e-15). Measured: 2.4e-14; asserted
/// 1e-13. (Beyond, in Lambda's tail below 1e-30, the relative error grows
/// to 8e-11 at 1e-31 and 5e-7 at 1e-48.)
#[test]
fn identical_layers_equal_one_layer() {
    let m = Material::new(5e6, 0.45).unwrap();
    let base = Base::Elastic(Material::new(1e8, 0.3).unwrap());
    let closed = CoatingFunctions::new(&m, &base);
    let split = StackFunctions::unmerged(&[(m, 0.3), (m, 0.5), (m, 0.2)], base).unwrap();
    let mut worst = 0.0f64;
    for q in logspace(1e-3, 20.0, 30) {
        // t = q h: h = 1 for the merged layer, 0.3 for the split stack's top.
        worst = worst.max((split.r(0.3 * q) / closed.r(q) - 1.0).abs());
        worst = worst.max((split.lambda(0.3 * q) / closed.lambda(q) - 1.0).abs());
    }
    println!("worst {worst:.1e}");
    assert!(worst < 1e-13, "{worst:e}");
}

/// `Substrate::stack` reduces exactly: merged layers, dropped zero
/// thicknesses, an infinite layer as the base, bottom layers of the base's
/// material, one layer left as `Coated`, none as the base's half-space.
#[test]
fn stacks_reduce_exactly() {
    let a = Material::new(1e9, 0.3).unwrap();
    let b = Material::new(2e6, 0.45).unwrap();
    let c = Material::new(7e7, 0.2).unwrap();
    let rigid = Base::Rigid;
    assert_eq!(
        Substrate::stack(&[(a, 1.0), (a, 2.0)], rigid).unwrap(),
        Substrate::layer_on_rigid_base(a, 3.0).unwrap()
    );
    assert_eq!(
        Substrate::stack(&[(a, 1.0), (b, 0.0), (a, 2.0), (c, 1.0)], Base::Elastic(c)).unwrap(),
        Substrate::layer_on_elastic_base(a, 3.0, c).unwrap()
    );
    assert_eq!(
        Substrate::stack(&[(a, 1.0), (b, f64::INFINITY), (c, 1.0)], rigid).unwrap(),
        Substrate::layer_on_elastic_base(a, 1.0, b).unwrap()
    );
    assert_eq!(
        Substrate::stack(&[(a, f64::INFINITY), (b, 1.0)], rigid).unwrap(),
        Substrate::half_space(a)
    );
    assert_eq!(
        Substrate::stack(&[], Base::Elastic(b)).unwrap(),
        Substrate::half_space(b)
    );
    assert!(Substrate::stack(&[(a, 0.0)], rigid).is_err());
    let Substrate::Stack(stack) =
        Substrate::stack(&[(a, 1.0), (b, 2.0), (b, 1.0), (c, 0.5)], rigid).unwrap()
    else {
        panic!("a stack")
    };
    assert_eq!(stack.layers().len(), 3);
    assert_eq!(stack.layers()[1].thickness(), 3.0);
    assert_eq!(stack.total_thickness(), 4.5);
    for bad in [f64::NAN, -1.0] {
        assert!(matches!(
            Substrate::stack(&[(a, 1.0), (b, bad)], rigid),
            Err(layered_contact::Error::InvalidThickness { .. })
        ));
    }
    // Moduli and depths out of range are typed errors.
    let soft = Material::new(1.0, 0.3).unwrap();
    assert!(matches!(
        Substrate::stack(&[(a, 1.0), (soft, 1.0)], rigid),
        Err(layered_contact::Error::InvalidParameter { .. })
    ));
    assert!(matches!(
        Substrate::stack(&[(a, 1e-13), (b, 1.0)], rigid),
        Err(layered_contact::Error::InvalidParameter { .. })
    ));
}

/// The limits of the issue: a thick top layer is its material's half-space
/// (to rounding once `e^(-2 q h1)` underflows the precision), and a
/// vanishing top layer leaves the stack below it, to first order in its
/// thickness.
#[test]
fn thick_and_vanishing_top_layers() {
    let a = Material::new(3e8, 0.25).unwrap();
    let b = Material::new(2e6, 0.48).unwrap();
    let c = Material::new(9e7, 0.1).unwrap();
    let base = Base::Elastic(Material::new(2e11, 0.3).unwrap());
    let half = FourierCompliance::new(&Substrate::half_space(a));
    let thick =
        FourierCompliance::new(&Substrate::stack(&[(a, 40.0), (b, 1.0), (c, 2.0)], base).unwrap());
    for q in [1.0, 3.0, 10.0] {
        assert!(
            (thick.eval(q) / half.eval(q) - 1.0).abs() < 1e-15,
            "q = {q}"
        );
    }
    let below = FourierCompliance::new(&Substrate::stack(&[(b, 1.0), (c, 2.0)], base).unwrap());
    let deviation = |eps: f64| {
        let thin = FourierCompliance::new(
            &Substrate::stack(&[(a, eps), (b, 1.0), (c, 2.0)], base).unwrap(),
        );
        logspace(1e-2, 10.0, 9)
            .map(|q| (thin.eval(q) / below.eval(q) - 1.0).abs())
            .fold(0.0, f64::max)
    };
    let (coarse, fine) = (deviation(1e-6), deviation(1e-9));
    println!("deviation {coarse:.2e} at 1e-6, {fine:.2e} at 1e-9");
    assert!(fine < 1e-7, "{fine:e}");
    // First order: a thousand times thinner, a thousand times closer.
    assert!(
        (coarse / fine / 1e3 - 1.0).abs() < 0.01,
        "{coarse:e} {fine:e}"
    );
}

/// The Taylor coefficients of R (power-series arithmetic through the same
/// recursion) against the values: R(0) = 0 and R'(0) the uniaxial-strain
/// compliance on a rigid base, and the truncated series (through t^8) equal
/// to R at t = 1e-3, where the omitted terms are below 1e-20 of it.
#[test]
fn taylor_coefficients_match_the_values() {
    let a = Material::new(3e8, 0.25).unwrap();
    let b = Material::new(2e6, 0.4).unwrap();
    let f = StackFunctions::unmerged(&[(a, 1.0), (b, 2.0), (a, 0.5)], Base::Rigid).unwrap();
    let taylor = f.r_taylor();
    assert_eq!(taylor[0], 0.0);
    assert!(
        (taylor[1] / f.r_over_t(0.0) - 1.0).abs() < 1e-14,
        "{} {}",
        taylor[1],
        f.r_over_t(0.0)
    );
    let t = 1e-3f64;
    let sum: f64 = taylor
        .iter()
        .enumerate()
        .map(|(k, c)| c * t.powi(k as i32))
        .sum();
    assert!((sum / f.r(t) - 1.0).abs() < 1e-13, "{sum} {}", f.r(t));
}
