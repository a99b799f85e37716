//! Stacks of bonded layers: the coating factor by a compliance (Riccati)
//! recursion that carries only decaying exponentials.
//!
//! The derivation is in [`doc::multilayer`](crate::doc::multilayer). Per
//! wavenumber `q`, the state `y = (U, W, T/mu1, S/mu1)` of a plane-strain
//! Fourier mode (displacements and the shear and normal stresses on planes
//! `z = const`, `z` measured into the body in units of `1/q`) obeys
//! `y' = A y` in each layer, with `A^2 = I + N`, `N^2 = 0`, so that the
//! propagator over a layer of `x = q h`, scaled by `e^(-x)`, is
//!
//! ```text
//! P(x) = e^(-x) exp(-A x) = c I + (x s / 2) N - s A - g A N,
//! c = (1 + e^(-2x))/2,  s = (1 - e^(-2x))/2,  g = (x (1 + e^(-2x)) - (1 - e^(-2x)))/4,
//! ```
//!
//! bounded for every `x`. The compliance `C` (2 x 2, displacements over
//! stresses) at the top of a layer follows from the one below by the Moebius
//! map `C_top = (P11 C + P12)(P21 C + P22)^(-1)`, starting from zero on a
//! rigid base or from the half-space compliance of an elastic base. Two
//! compliances propagated through the same layer differ by the congruence
//!
//! ```text
//! F(X) - F(Y) = e^(-2x) (P21 Y + P22)^(-T) (X - Y) (P21 X + P22)^(-1),
//! ```
//!
//! which carries the exponential decay of deep interfaces explicitly: the
//! deviation of the surface compliance from the top material's half-space
//! (`Lambda_g`) and its split into one term per interface keep their
//! relative precision however small they are.

use std::sync::Arc;

use crate::material::Material;

use super::series::{Scalar, Series, TAYLOR_TERMS};
use super::Base;

/// One layer of a [`Stack`]: a material and a finite positive thickness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layer {
    material: Material,
    thickness: f64,
}

impl Layer {
    pub(crate) fn new(material: Material, thickness: f64) -> Self {
        Layer {
            material,
            thickness,
        }
    }

    /// The layer's material.
    pub fn material(&self) -> &Material {
        &self.material
    }

    /// The layer's thickness, m.
    pub fn thickness(&self) -> f64 {
        self.thickness
    }
}

/// Two or more layers, top first, on a base; built by
/// [`Substrate::stack`](super::Substrate::stack), which merges what can be
/// merged (so adjacent bonded layers differ in material and every thickness
/// is positive and finite), or by
/// [`Substrate::layer_resting_on`](super::Substrate::layer_resting_on), whose
/// top layer rests on the bonded layers below without friction.
#[derive(Debug, Clone, PartialEq)]
pub struct Stack {
    layers: Arc<[Layer]>,
    base: Base,
    /// The top layer rests on the layers below without friction.
    resting: bool,
}

impl Stack {
    pub(crate) fn new(layers: Vec<Layer>, base: Base) -> Self {
        Stack {
            layers: layers.into(),
            base,
            resting: false,
        }
    }

    /// A stack whose top layer rests without friction on the bonded
    /// `layers[1..]` on `base`.
    pub(crate) fn resting(layers: Vec<Layer>, base: Base) -> Self {
        Stack {
            resting: true,
            ..Stack::new(layers, base)
        }
    }

    /// Whether the top layer rests on the layers below without friction
    /// (the interface under it carries no shear); every other interface is
    /// bonded.
    pub fn top_rests(&self) -> bool {
        self.resting
    }

    /// The layers, top first.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// The top layer, in contact with the indenter.
    pub fn top(&self) -> &Layer {
        &self.layers[0]
    }

    /// What the bottom layer is bonded to.
    pub fn base(&self) -> &Base {
        &self.base
    }

    /// The sum of the layer thicknesses, m.
    pub fn total_thickness(&self) -> f64 {
        self.layers.iter().map(Layer::thickness).sum()
    }

    /// The coating factor of the stack as a function of `t = q h1`, `h1` the
    /// top layer's thickness.
    pub fn functions(&self) -> StackFunctions {
        StackFunctions {
            shape: Arc::new(Shape::new(self)),
            resting: self
                .resting
                .then(|| Arc::new(super::resting::Resting::new(self))),
        }
    }
}

/// A 2 x 2 matrix.
type M2<S> = [[S; 2]; 2];

fn mul<S: Scalar>(a: &M2<S>, b: &M2<S>) -> M2<S> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| a[i][0].times(b[0][j]).plus(a[i][1].times(b[1][j])))
    })
}

fn add<S: Scalar>(a: &M2<S>, b: &M2<S>) -> M2<S> {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j].plus(b[i][j])))
}

fn sub<S: Scalar>(a: &M2<S>, b: &M2<S>) -> M2<S> {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j].minus(b[i][j])))
}

fn transpose<S: Scalar>(a: &M2<S>) -> M2<S> {
    [[a[0][0], a[1][0]], [a[0][1], a[1][1]]]
}

fn inverse<S: Scalar>(a: &M2<S>) -> M2<S> {
    let det = a[0][0].times(a[1][1]).minus(a[0][1].times(a[1][0]));
    let zero = S::constant(0.0);
    [
        [a[1][1].over(det), zero.minus(a[0][1]).over(det)],
        [zero.minus(a[1][0]).over(det), a[0][0].over(det)],
    ]
}

fn constant<S: Scalar>(a: &M2<f64>) -> M2<S> {
    a.map(|row| row.map(S::constant))
}

/// `scale * e^(-2x) * L^T D R`.
fn congruence<S: Scalar>(factor: S, left: &M2<S>, difference: &M2<S>, right: &M2<S>) -> M2<S> {
    mul(&mul(&transpose(left), difference), right).map(|row| row.map(|v| v.times(factor)))
}

/// The scalars of one layer's scaled propagator at `x = q h`.
#[derive(Debug, Clone, Copy)]
struct Terms<S> {
    /// `e^(-2x)`.
    e2: S,
    c: S,
    s: S,
    /// `x s / 2`.
    xs_half: S,
    g: S,
    /// Whether `x > 1`: then [`step`] takes the congruence form.
    thick: bool,
}

/// Beyond this `x = q h` a layer hides everything below it to the last bit
/// (`e^(-2x)` underflows): it acts as a half-space of its own material.
const X_HALF_SPACE: f64 = 400.0;

/// The terms at `x >= 0`, each to full relative precision; `None` beyond
/// [`X_HALF_SPACE`].
fn terms_at(x: f64) -> Option<Terms<f64>> {
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
fn terms_series(ratio: f64) -> Terms<Series> {
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
struct LayerShape {
    tau: f64,
    a: [[f64; 4]; 4],
    n: [[f64; 4]; 4],
    an: [[f64; 4]; 4],
    half_space: M2<f64>,
}

/// The half-space compliance of a material with Poisson ratio `nu` and
/// `r = mu1 / mu` (stresses in units of `mu1`).
fn half_space_compliance(nu: f64, r: f64) -> M2<f64> {
    let off = r * (0.5 - nu);
    [[-r * (1.0 - nu), off], [off, -r * (1.0 - nu)]]
}

impl LayerShape {
    fn new(layer: &Layer, top: &Material, h1: f64) -> Self {
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
    fn propagator<S: Scalar>(&self, terms: &Terms<S>) -> [M2<S>; 4] {
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
fn right<S: Scalar>(p: &[M2<S>; 4], below: &M2<S>) -> M2<S> {
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
fn step<S: Scalar>(
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
struct Split<S> {
    half: M2<f64>,
    deviation: M2<S>,
}

impl<S: Scalar> Split<S> {
    fn whole(&self) -> M2<S> {
        add(&constant(&self.half), &self.deviation)
    }

    /// The compliance minus `half`: `(H - half) + deviation`.
    fn offset(&self, half: &M2<f64>) -> M2<S> {
        let difference: M2<f64> =
            std::array::from_fn(|i| std::array::from_fn(|j| self.half[i][j] - half[i][j]));
        add(&constant(&difference), &self.deviation)
    }
}

/// A stack in units of its top layer (thickness 1, shear modulus 1).
#[derive(Debug, Clone)]
struct Shape {
    layers: Vec<LayerShape>,
    /// The base's half-space compliance; zero for a rigid base.
    base: M2<f64>,
    rigid_base: bool,
    /// `1 - nu1`.
    top_factor: f64,
    /// `E1* / E_k*` of each layer and the base (0 for a rigid base).
    modulus_ratios: Vec<f64>,
    /// `(E1*/2) sum tau_i / M_i`, the uniaxial-strain limit of `R(t)/t` on a
    /// rigid base.
    uniaxial: f64,
}

impl Shape {
    fn new(stack: &Stack) -> Self {
        let top = stack.top().material;
        let h1 = stack.top().thickness;
        let layers = stack
            .layers
            .iter()
            .map(|layer| LayerShape::new(layer, &top, h1))
            .collect();
        let e1 = top.contact_modulus();
        let mut modulus_ratios: Vec<f64> = stack
            .layers
            .iter()
            .map(|l| e1 / l.material.contact_modulus())
            .collect();
        let (base, rigid_base) = match &stack.base {
            Base::Rigid => {
                modulus_ratios.push(0.0);
                ([[0.0; 2]; 2], true)
            }
            Base::Elastic(material) => {
                modulus_ratios.push(e1 / material.contact_modulus());
                (
                    half_space_compliance(
                        material.poisson_ratio(),
                        top.shear_modulus() / material.shear_modulus(),
                    ),
                    false,
                )
            }
        };
        let uniaxial = 0.5
            * e1
            * stack
                .layers
                .iter()
                .map(|l| l.thickness / h1 / l.material.uniaxial_strain_modulus())
                .sum::<f64>();
        Shape {
            layers,
            base,
            rigid_base,
            top_factor: 1.0 - top.poisson_ratio(),
            modulus_ratios,
            uniaxial,
        }
    }

    /// The compliance below layer `index`: the next layer's half-space
    /// material, or the base under the last layer.
    fn below(&self, index: usize) -> &M2<f64> {
        self.layers
            .get(index + 1)
            .map_or(&self.base, |layer| &layer.half_space)
    }

    /// The compliance at the top of layer `from` of the stack's layers
    /// `from..` on its base.
    fn compliance<S: Scalar>(
        &self,
        from: usize,
        terms: &impl Fn(f64) -> Option<Terms<S>>,
    ) -> Split<S> {
        let mut c = Split {
            half: self.base,
            deviation: constant(&[[0.0; 2]; 2]),
        };
        for layer in self.layers[from..].iter().rev() {
            c = match terms(layer.tau) {
                Some(t) => {
                    let p = layer.propagator(&t);
                    let below = c.whole();
                    step(layer, &t, &p, &below, &right(&p, &below))
                }
                None => Split {
                    half: layer.half_space,
                    deviation: constant(&[[0.0; 2]; 2]),
                },
            };
        }
        c
    }

    /// `R = -C_zz / (1 - nu1)` at the surface.
    fn r<S: Scalar>(&self, terms: &impl Fn(f64) -> Option<Terms<S>>) -> S {
        S::constant(0.0)
            .minus(self.compliance(0, terms).whole()[1][1])
            .scaled(1.0 / self.top_factor)
    }

    /// `Lambda_g = (C - C_half-space)_zz / (1 - nu1)`, the deviation at the
    /// top layer kept separate from the half-space's compliance.
    fn lambda<S: Scalar>(&self, terms: &impl Fn(f64) -> Option<Terms<S>>) -> S {
        let top = &self.layers[0];
        let Some(t) = terms(top.tau) else {
            return S::constant(0.0);
        };
        let below = self.compliance(1, terms);
        let p = top.propagator(&t);
        let half: M2<S> = constant(&top.half_space);
        let difference = below.offset(&top.half_space);
        let d = congruence(
            t.e2,
            &right(&p, &half),
            &difference,
            &right(&p, &below.whole()),
        );
        d[1][1].scaled(1.0 / self.top_factor)
    }

    /// The change of `Lambda_g` that interface `k` (under layer `k`) brings:
    /// layers `0..=k` on the half-space below layer `k`, minus layers
    /// `0..k` on the half-space of layer `k`.
    fn bracket<S: Scalar>(&self, k: usize, terms: &impl Fn(f64) -> Option<Terms<S>>) -> S {
        let layer = &self.layers[k];
        let Some(t) = terms(layer.tau) else {
            return S::constant(0.0);
        };
        let below: M2<S> = constant(self.below(k));
        // The two bodies agree above interface k: X has the layer on what
        // lies below it, Y the layer's own half-space.
        let mut y: M2<S> = constant(&layer.half_space);
        let p = layer.propagator(&t);
        let right_below = right(&p, &below);
        let mut d = congruence(t.e2, &right(&p, &y), &sub(&below, &y), &right_below);
        let mut x = step(layer, &t, &p, &below, &right_below).whole();
        for layer in self.layers[..k].iter().rev() {
            let Some(t) = terms(layer.tau) else {
                return S::constant(0.0);
            };
            let p = layer.propagator(&t);
            let (right_y, right_x) = (right(&p, &y), right(&p, &x));
            d = congruence(t.e2, &right_y, &d, &right_x);
            y = step(layer, &t, &p, &y, &right_y).whole();
            x = step(layer, &t, &p, &x, &right_x).whole();
        }
        d[1][1].scaled(1.0 / self.top_factor)
    }

    /// Depth of the bottom of layer `k`, in units of `h1`.
    fn depth(&self, k: usize) -> f64 {
        self.layers[..=k].iter().map(|l| l.tau).sum()
    }
}

/// The coating factor `R(t)` and `Lambda_g(t) = 1 - R(t)` of a [`Stack`], as
/// functions of `t = q h1` (`h1` the top layer's thickness), from the
/// recursion of the [module docs](self): `u_z(q) = 2 R(q h1) / (E1* q)`.
///
/// ```
/// use layered_contact::substrate::{Base, CoatingFunctions};
/// use layered_contact::{Error, Material, Substrate};
///
/// let hard = Material::new(200e9, 0.3)?;
/// let soft = Material::new(2e9, 0.4)?;
/// let stack = Substrate::stack(&[(hard, 1e-6), (soft, 5e-6)], Base::Elastic(hard))?;
/// let Substrate::Stack(stack) = stack else { unreachable!() };
/// let f = stack.functions();
/// // Long waves see the base, short waves the top layer:
/// assert!((f.r(1e-12) - 1.0).abs() < 1e-9);
/// assert!((f.r(50.0) - 1.0).abs() < 1e-30);
/// // In between, the soft interlayer makes the body more compliant:
/// assert!(f.r(0.5) > 1.5);
/// assert!((f.r(0.5) + f.lambda(0.5) - 1.0).abs() < 1e-14);
/// Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct StackFunctions {
    shape: Arc<Shape>,
    /// The top layer resting on the rest without friction.
    resting: Option<Arc<super::resting::Resting>>,
}

impl StackFunctions {
    /// The coating factor `R(t)`, `t = q h1`.
    pub fn r(&self, t: f64) -> f64 {
        let t = t.abs();
        if let Some(resting) = &self.resting {
            return super::closed_form::frictionless_r(resting.rho(t), t);
        }
        self.shape.r(&|tau: f64| terms_at(tau * t))
    }

    /// `Lambda_g(t) = 1 - R(t)`, with its exponentially small tail to full
    /// relative precision.
    pub fn lambda(&self, t: f64) -> f64 {
        let t = t.abs();
        if let Some(resting) = &self.resting {
            return super::closed_form::frictionless_lambda(resting.rho(t), t);
        }
        self.shape.lambda(&|tau: f64| terms_at(tau * t))
    }

    /// `R(0)`: `E1*/E_base*`, 0 on a rigid base.
    pub fn r_at_zero(&self) -> f64 {
        *self.shape.modulus_ratios.last().expect("a base")
    }

    /// The Taylor coefficients of the whole `Lambda_g(t)` at `t = 0` (the
    /// kernel takes a bonded stack's per interface, [`Self::brackets`]).
    pub(crate) fn lambda_taylor(&self) -> Series {
        match &self.resting {
            Some(resting) => super::closed_form::frictionless_lambda_taylor(&resting.rho_taylor()),
            None => Series::constant(1.0).sub(&self.shape.r(&|tau: f64| Some(terms_series(tau)))),
        }
    }

    /// `R(t) / t`; at `t = 0` on a rigid base the uniaxial-strain limit
    /// `(E1*/2) sum (h_i/h1) / M_i`, `M_i` the layers' uniaxial-strain moduli
    /// (`+inf` on an elastic base).
    pub fn r_over_t(&self, t: f64) -> f64 {
        let t = t.abs();
        if let Some(resting) = &self.resting {
            let (rho, rho_over_t) = resting.rho_and_over_t(t);
            return super::closed_form::frictionless_r_over_t(rho, rho_over_t, t);
        }
        if t == 0.0 {
            return if self.shape.rigid_base {
                self.shape.uniaxial
            } else {
                f64::INFINITY
            };
        }
        self.r(t) / t
    }

    /// The functions of `layers` on `base` exactly as given, without the
    /// merging of [`Substrate::stack`](super::Substrate::stack): for checking
    /// the recursion against the closed form of one layer and against
    /// merged stacks.
    ///
    /// # Errors
    /// [`Error::InvalidThickness`](crate::Error::InvalidThickness) unless
    /// there is a layer and every thickness is positive and finite; the
    /// modulus and depth limits of [`Substrate::stack`](super::Substrate::stack).
    #[doc(hidden)]
    pub fn unmerged(layers: &[(Material, f64)], base: Base) -> crate::Result<Self> {
        if layers.is_empty() {
            return Err(crate::Error::InvalidThickness {
                value: 0.0,
                expected: "at least one layer",
            });
        }
        for &(_, thickness) in layers {
            crate::error::positive_finite("thickness", thickness).map_err(|_| {
                crate::Error::InvalidThickness {
                    value: thickness,
                    expected: "positive and finite",
                }
            })?;
        }
        let layers: Vec<Layer> = layers.iter().map(|&(m, h)| Layer::new(m, h)).collect();
        super::check_stack(&layers, &base)?;
        Ok(Stack::new(layers, base).functions())
    }

    /// The terms of `Lambda_g` one per interface, in units of each
    /// interface's depth.
    pub(crate) fn brackets(&self) -> Vec<Bracket> {
        (0..self.shape.layers.len())
            .map(|k| Bracket {
                shape: Arc::clone(&self.shape),
                index: k,
                depth: self.shape.depth(k),
            })
            .collect()
    }

    /// The Taylor coefficients of `R(t)` at `t = 0`, for tests.
    #[doc(hidden)]
    pub fn r_taylor(&self) -> [f64; TAYLOR_TERMS] {
        match self.resting {
            Some(_) => Series::constant(1.0).sub(&self.lambda_taylor()).0,
            None => self.shape.r(&|tau: f64| Some(terms_series(tau))).0,
        }
    }
}

/// The part of a stack's `Lambda_g` due to one interface (see
/// [`Shape::bracket`]), as a function of `u = q z` with `z` the interface's
/// depth: it starts at `E1*/E_k* - E1*/E_(k+1)*` and decays like `e^(-2u)`.
#[derive(Debug, Clone)]
pub(crate) struct Bracket {
    shape: Arc<Shape>,
    index: usize,
    /// Depth of the interface over `h1`.
    depth: f64,
}

impl Bracket {
    /// Depth of the interface, in units of the top layer's thickness.
    pub(crate) fn depth(&self) -> f64 {
        self.depth
    }

    /// The value at `u = q z`.
    pub(crate) fn lambda(&self, u: f64) -> f64 {
        let t = u.abs() / self.depth;
        self.shape
            .bracket(self.index, &|tau: f64| terms_at(tau * t))
    }

    /// Taylor coefficients in `u` at 0.
    pub(crate) fn lambda_taylor(&self) -> Series {
        let depth = self.depth;
        self.shape
            .bracket(self.index, &|tau: f64| Some(terms_series(tau / depth)))
    }
}
