//! The coating factor of a layer resting without friction on a support
//! known by its normal surface compliance alone, `rho` times the layer's
//! half-space compliance at each wavenumber: an elastic base (constant
//! `rho`, [`CoatingFunctions::frictionless`](super::CoatingFunctions::frictionless))
//! or a layered support (`rho(t)`, [`Substrate::layer_resting_on`](super::Substrate::layer_resting_on)).

use super::closed_form::{one_minus_exp_terms, T_NEGLIGIBLE};
use super::series::{Series, TAYLOR_TERMS};

/// `D(t) / t`, `g = (1 - e^(-2t)) / t` and `P(t) / t` of a layer resting
/// without friction on a support of normal compliance `rho` times the
/// layer's half-space compliance at `t = q h` (see
/// [`CoatingFunctions::frictionless`](super::CoatingFunctions::frictionless)), all finite and positive at `t = 0`
/// (8, 2 and 8).
fn frictionless_parts(rho: f64, t: f64) -> (f64, f64, f64) {
    if t == 0.0 {
        return (8.0, 2.0, 8.0);
    }
    let e1 = (-t).exp();
    let e2 = e1 * e1;
    // (1 - e^(-2t)) / t
    let g = -(-2.0 * t).exp_m1() / t;
    let p = -(-4.0 * t).exp_m1() / t + 4.0 * e2;
    let d = if rho > 0.0 {
        p + rho * one_minus_exp_terms(t) * (g + 2.0 * e1)
    } else {
        p
    };
    (d, g, p)
}

/// `R(t)` of a layer resting without friction on a support whose normal
/// compliance at `t = q h` is `rho` times the layer's half-space compliance
/// `2/(E1* q)`: `(rho P/t + t g^2) / (D/t)`. The layer couples to its
/// support through the normal traction and displacement of one wavenumber
/// only, so `rho` may be any support's (an elastic base's `E1*/E2*`, a
/// layered support's `E1*/E2* R_2(q h_2)`).
pub(crate) fn frictionless_r(rho: f64, t: f64) -> f64 {
    let t = t.abs();
    if t > T_NEGLIGIBLE {
        return 1.0;
    }
    let (d, g, p) = frictionless_parts(rho, t);
    (rho * p + t * g * g) / d
}

/// `e^(2t) Lambda_g(t)` of [`frictionless_r`]'s layer:
/// `2 (n - rho (n + 2t)) / (D/t)`, `n = (1 + 2t - e^(-2t)) / t = 2 + g`.
pub(crate) fn frictionless_lambda_scaled(rho: f64, t: f64) -> f64 {
    let t = t.abs();
    let (d, g, _) = frictionless_parts(rho, t);
    let n = 2.0 + g;
    2.0 * (n - rho * (n + 2.0 * t)) / d
}

/// `Lambda_g(t)` of [`frictionless_r`]'s layer, its exponential tail to
/// full relative precision.
pub(crate) fn frictionless_lambda(rho: f64, t: f64) -> f64 {
    let t = t.abs();
    if t > T_NEGLIGIBLE {
        return 0.0;
    }
    (-2.0 * t).exp() * frictionless_lambda_scaled(rho, t)
}

/// `R(t)/t` of [`frictionless_r`]'s layer, from `rho` and `rho / t` (finite
/// at `t = 0` on a rigid-based support; `+inf` there on an elastic one):
/// `(rho/t P/t + g^2) / (D/t)`.
pub(crate) fn frictionless_r_over_t(rho: f64, rho_over_t: f64, t: f64) -> f64 {
    let t = t.abs();
    if t > T_NEGLIGIBLE {
        return 1.0 / t;
    }
    let (d, g, p) = frictionless_parts(rho, t);
    let support = if rho > 0.0 { rho_over_t * p } else { 0.0 };
    (support + g * g) / d
}

/// The Taylor coefficients of [`frictionless_lambda`] at `t = 0` for a
/// support ratio given by its own series `rho(t)`: `2 e^(-2t) [n - rho (n
/// + 2t)] / [D(t) / t]`, each bracket summed term by term (the division
/// by `t` exact).
pub(crate) fn frictionless_lambda_taylor(rho: &Series) -> Series {
    let mut g = [0.0; TAYLOR_TERMS];
    let mut p = [0.0; TAYLOR_TERMS];
    let mut factorial = 1.0;
    for j in 0..TAYLOR_TERMS {
        let next = factorial * (j + 1) as f64;
        g[j] = -(-2.0f64).powi(j as i32 + 1) / next;
        p[j] = -(-4.0f64).powi(j as i32 + 1) / next + 4.0 * (-2.0f64).powi(j as i32) / factorial;
        factorial = next;
    }
    let g = Series(g);
    let n = g.add(&Series::constant(2.0));
    // D/t = P/t + rho f(t) (g + 2 e^(-t)), f = 2 e^(-t) (sinh t - t).
    let e1 = Series::exp(-1.0);
    let f = e1.scale(2.0).mul(&Series::sinh_minus_identity());
    let d = Series(p).add(&f.mul(&g.add(&e1.scale(2.0))).mul(rho));
    let numerator = n.sub(&n.add(&Series::monomial(1).scale(2.0)).mul(rho));
    Series::exp(-2.0).mul(&numerator).scale(2.0).div(&d)
}
