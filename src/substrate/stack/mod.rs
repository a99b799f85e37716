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

mod propagator;

use propagator::{
    congruence, constant, half_space_compliance, right, step, sub, terms_at, terms_series,
    LayerShape, Split, Terms, M2,
};

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
            return super::frictionless::frictionless_r(resting.rho(t), t);
        }
        self.shape.r(&|tau: f64| terms_at(tau * t))
    }

    /// `Lambda_g(t) = 1 - R(t)`, with its exponentially small tail to full
    /// relative precision.
    pub fn lambda(&self, t: f64) -> f64 {
        let t = t.abs();
        if let Some(resting) = &self.resting {
            return super::frictionless::frictionless_lambda(resting.rho(t), t);
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
            Some(resting) => super::frictionless::frictionless_lambda_taylor(&resting.rho_taylor()),
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
            return super::frictionless::frictionless_r_over_t(rho, rho_over_t, t);
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
