//! The propagation of one plane-strain Fourier mode through one layer of a
//! [`Stack`](super::Stack): the bounded, scaled propagator's scalars (exact
//! and as power series), each layer's constant matrices, and the step of
//! the compliance through a layer in its Moebius or congruence form (see
//! the [parent module](super) and [`doc::multilayer`](crate::doc::multilayer)).

use super::super::series::{Scalar, Series};
use super::Layer;
use crate::material::Material;

/// A 2 x 2 matrix.
pub(super) type M2<S> = [[S; 2]; 2];

pub(super) fn mul<S: Scalar>(a: &M2<S>, b: &M2<S>) -> M2<S> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| a[i][0].times(b[0][j]).plus(a[i][1].times(b[1][j])))
    })
}

pub(super) fn add<S: Scalar>(a: &M2<S>, b: &M2<S>) -> M2<S> {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j].plus(b[i][j])))
}

pub(super) fn sub<S: Scalar>(a: &M2<S>, b: &M2<S>) -> M2<S> {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j].minus(b[i][j])))
}

pub(super) fn transpose<S: Scalar>(a: &M2<S>) -> M2<S> {
    [[a[0][0], a[1][0]], [a[0][1], a[1][1]]]
}

pub(super) fn inverse<S: Scalar>(a: &M2<S>) -> M2<S> {
    let det = a[0][0].times(a[1][1]).minus(a[0][1].times(a[1][0]));
    let zero = S::constant(0.0);
    [
        [a[1][1].over(det), zero.minus(a[0][1]).over(det)],
        [zero.minus(a[1][0]).over(det), a[0][0].over(det)],
    ]
}

pub(super) fn constant<S: Scalar>(a: &M2<f64>) -> M2<S> {
    a.map(|row| row.map(S::constant))
}

/// `scale * e^(-2x) * L^T D R`.
pub(super) fn congruence<S: Scalar>(
    factor: S,
    left: &M2<S>,
    difference: &M2<S>,
    right: &M2<S>,
) -> M2<S> {
    mul(&mul(&transpose(left), difference), right).map(|row| row.map(|v| v.times(factor)))
}

/// The scalars of one layer's scaled propagator at `x = q h`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Terms<S> {
    /// `e^(-2x)`.
    pub(super) e2: S,
    pub(super) c: S,
    pub(super) s: S,
    /// `x s / 2`.
    pub(super) xs_half: S,
    pub(super) g: S,
    /// Whether `x > 1`: then [`step`] takes the congruence form.
    pub(super) thick: bool,
}

/// Beyond this `x = q h` a layer hides everything below it to the last bit
/// (`e^(-2x)` underflows): it acts as a half-space of its own material.
pub(super) const X_HALF_SPACE: f64 = 400.0;

/// The terms at `x >= 0`, each to full relative precision; `None` beyond
/// [`X_HALF_SPACE`].
pub(super) fn terms_at(x: f64) -> Option<Terms<f64>> {
    if x > X_HALF_SPACE {
        return None;
    }
    let e2 = (-2.0 * x).exp();
    let s = -0.5 * (-2.0 * x).exp_m1();
    let g = if x < 1.0 {
        // e^(-x) (x cosh x - sinh x) / 2 = e^(-x) sum_k k x^(2k+1) / (2k+1)!
        let x2 = x * x;
        let mut term = x * x2 / 6.0; // x^3 / 3!
        let mut sum = term;
        let mut k = 1.0;
        while term > 1e-17 * sum {
            term *= x2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
            k += 1.0;
            sum += k * term;
        }
        (-x).exp() * sum
    } else {
        0.25 * (x * (1.0 + e2) - 2.0 * s)
    };
    Some(Terms {
        e2,
        c: 0.5 * (1.0 + e2),
        s,
        xs_half: 0.5 * x * s,
        g,
        thick: x > 1.0,
    })
}

/// The terms as power series in `t` for `x = ratio * t`.
pub(super) fn terms_series(ratio: f64) -> Terms<Series> {
    let e2 = Series::exp(-2.0 * ratio);
    let one = Series::constant(1.0);
    let x = Series::monomial(1).scale(ratio);
    let s = one.sub(&e2).scale(0.5);
    Terms {
        e2,
        c: one.add(&e2).scale(0.5),
        s,
        xs_half: x.mul(&s).scale(0.5),
        g: x.mul(&one.add(&e2)).sub(&s.scale(2.0)).scale(0.25),
        thick: false,
    }
}

/// One layer in units of the top layer: thickness `tau = h / h1`, the
/// constant matrices of its state equation, and its half-space compliance.
#[derive(Debug, Clone)]
pub(super) struct LayerShape {
    pub(super) tau: f64,
    pub(super) a: [[f64; 4]; 4],
    pub(super) n: [[f64; 4]; 4],
    pub(super) an: [[f64; 4]; 4],
    pub(super) half_space: M2<f64>,
}

/// The half-space compliance of a material with Poisson ratio `nu` and
/// `r = mu1 / mu` (stresses in units of `mu1`).
pub(super) fn half_space_compliance(nu: f64, r: f64) -> M2<f64> {
    let off = r * (0.5 - nu);
    [[-r * (1.0 - nu), off], [off, -r * (1.0 - nu)]]
}

impl LayerShape {
    pub(super) fn new(layer: &Layer, top: &Material, h1: f64) -> Self {
        let nu = layer.material.poisson_ratio();
        let r = top.shear_modulus() / layer.material.shear_modulus();
        let w = 1.0 / (1.0 - nu);
        let c = nu * w;
        let k = (0.5 - nu) * w;
        LayerShape {
            tau: layer.thickness / h1,
            a: [
                [0.0, 1.0, r, 0.0],
                [-c, 0.0, 0.0, k * r],
                [2.0 * w / r, 0.0, 0.0, c],
                [0.0, 0.0, -1.0, 0.0],
            ],
            n: [
                [w, 0.0, 0.0, 0.5 * r * w],
                [0.0, -w, -0.5 * r * w, 0.0],
                [0.0, 2.0 * w / r, w, 0.0],
                [-2.0 * w / r, 0.0, 0.0, -w],
            ],
            an: [
                [0.0, w, 0.5 * r * w, 0.0],
                [-w, 0.0, 0.0, -0.5 * r * w],
                [2.0 * w / r, 0.0, 0.0, w],
                [0.0, -2.0 * w / r, -w, 0.0],
            ],
            half_space: half_space_compliance(nu, r),
        }
    }

    /// The blocks `[P11, P12, P21, P22]` of the scaled upward propagator.
    pub(super) fn propagator<S: Scalar>(&self, terms: &Terms<S>) -> [M2<S>; 4] {
        let entry = |i: usize, j: usize| {
            let identity = if i == j { terms.c } else { S::constant(0.0) };
            identity
                .plus(terms.xs_half.scaled(self.n[i][j]))
                .minus(terms.s.scaled(self.a[i][j]))
                .minus(terms.g.scaled(self.an[i][j]))
        };
        let block = |r: usize, c: usize| -> M2<S> {
            std::array::from_fn(|i| std::array::from_fn(|j| entry(r + i, c + j)))
        };
        [block(0, 0), block(0, 2), block(2, 0), block(2, 2)]
    }
}

/// `(P21 C + P22)^(-1)` for the compliance `C` below the layer.
pub(super) fn right<S: Scalar>(p: &[M2<S>; 4], below: &M2<S>) -> M2<S> {
    inverse(&add(&mul(&p[2], below), &p[3]))
}

/// The compliance at the top of a layer over `below`. For `x <= 1` the
/// Moebius ratio `(P11 C + P12) R`, `R` the [`right`] factor, which stays
/// close to `C`; for thicker layers the layer's half-space compliance (the
/// map's fixed point) plus the congruence of the difference,
/// `C_hs + e^(-2x) L^T (C - C_hs) R`, since the ratio's terms grow like `x`
/// and cancel (3 digits lost at `x = 30`) while the congruence is damped by
/// `e^(-2x)`. `p` is the layer's [`LayerShape::propagator`] and
/// `right_below` its [`right`] factor of `below`, which the callers need
/// too.
pub(super) fn step<S: Scalar>(
    layer: &LayerShape,
    terms: &Terms<S>,
    p: &[M2<S>; 4],
    below: &M2<S>,
    right_below: &M2<S>,
) -> Split<S> {
    if !terms.thick {
        return Split {
            half: [[0.0; 2]; 2],
            deviation: mul(&add(&mul(&p[0], below), &p[1]), right_below),
        };
    }
    let half: M2<S> = constant(&layer.half_space);
    let left = right(p, &half);
    Split {
        half: layer.half_space,
        deviation: congruence(terms.e2, &left, &sub(below, &half), right_below),
    }
}

/// A compliance kept as a half-space's plus the deviation from it, so that
/// an exponentially small deviation is not absorbed (two layers of one
/// material: the difference of their half-spaces is exactly zero). After a
/// thin layer (`x <= 1`) `half` is zero and `deviation` the whole compliance.
#[derive(Debug, Clone, Copy)]
pub(super) struct Split<S> {
    pub(super) half: M2<f64>,
    pub(super) deviation: M2<S>,
}

impl<S: Scalar> Split<S> {
    pub(super) fn whole(&self) -> M2<S> {
        add(&constant(&self.half), &self.deviation)
    }

    /// The compliance minus `half`: `(H - half) + deviation`.
    pub(super) fn offset(&self, half: &M2<f64>) -> M2<S> {
        let difference: M2<f64> =
            std::array::from_fn(|i| std::array::from_fn(|j| self.half[i][j] - half[i][j]));
        add(&constant(&difference), &self.deviation)
    }
}
