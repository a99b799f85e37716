//! A stack whose top layer rests on the layers below without friction
//! ([`Substrate::layer_resting_on`](super::Substrate::layer_resting_on)):
//! the support seen through its normal surface compliance alone.

use super::series::{Series, TAYLOR_TERMS};
use super::{check_stack, Base, CoatingFunctions, Layer, Stack, StackFunctions, Substrate};
use crate::error::{Error, Result};
use crate::material::Material;

impl Substrate {
    /// A `layer` of `thickness` (m) resting without friction on `support`,
    /// a body of bonded layers: the interface under the layer carries no
    /// shear (Dimitriadis et al. 2002's unbonded case), every interface
    /// below stays bonded. The layer couples to its support through the
    /// normal surface compliance alone, so its coating factor is that of
    /// [`CoatingFunctions::frictionless`] with the support's ratio `rho =
    /// E1*/E2*` replaced by `(E1*/E2*) R_2(q h_2)`, `R_2` the support's own
    /// coating factor (`tests/unbonded.rs` checks it against the
    /// plane-strain equations integrated through every layer).
    ///
    /// On a half-space this is [`Substrate::layer_resting_on_elastic_base`];
    /// `thickness = +inf` gives the layer's half-space.
    ///
    /// ```
    /// use layered_contact::{Base, Error, Material, Substrate};
    ///
    /// let cell = Material::new(10e3, 0.5)?;
    /// let coating = Substrate::layer_on_rigid_base(Material::new(1e6, 0.4)?, 1e-6)?;
    /// let resting = Substrate::layer_resting_on(cell, 4e-6, &coating)?;
    /// let Substrate::Stack(stack) = &resting else { unreachable!() };
    /// assert!(stack.top_rests() && stack.layers().len() == 2);
    /// // Bonded, the same layers are stiffer (a smaller coating factor):
    /// let bonded = Substrate::stack(&[(cell, 4e-6), (Material::new(1e6, 0.4)?, 1e-6)], Base::Rigid)?;
    /// let Substrate::Stack(bonded) = &bonded else { unreachable!() };
    /// assert!(stack.functions().r(0.5) > bonded.functions().r(0.5));
    /// Ok::<(), Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidThickness`] for a thickness that is NaN or not
    /// positive; [`Error::Unsupported`] for a support with a frictionless
    /// interface of its own; the limits of [`Substrate::stack`] on the
    /// layers together.
    pub fn layer_resting_on(layer: Material, thickness: f64, support: &Substrate) -> Result<Self> {
        if thickness.is_nan() || thickness <= 0.0 {
            return Err(Error::InvalidThickness {
                value: thickness,
                expected: "positive (m), or +inf for the layer's half-space",
            });
        }
        if thickness == f64::INFINITY {
            return Ok(Substrate::HalfSpace(layer));
        }
        let (below, base): (Vec<Layer>, Base) = match support {
            Substrate::HalfSpace(material) => {
                return Self::layer_resting_on_elastic_base(layer, thickness, *material)
            }
            Substrate::Coated(c) if !c.frictionless => {
                (vec![Layer::new(c.layer, c.thickness)], c.base)
            }
            Substrate::Stack(s) if !s.top_rests() => (s.layers().to_vec(), *s.base()),
            _ => {
                return Err(Error::Unsupported {
                    feature: "a layer resting on a support with a frictionless interface",
                    reason: "one frictionless interface per body, under its top layer",
                })
            }
        };
        let layers: Vec<Layer> = std::iter::once(Layer::new(layer, thickness))
            .chain(below)
            .collect();
        check_stack(&layers, &base)?;
        Ok(Substrate::Stack(Stack::resting(layers, base)))
    }
}

/// What the top layer of a [`Stack::top_rests`] stack rests on: the bonded
/// rest, seen through its normal surface compliance only (a shear-free
/// interface couples one wavenumber's normal traction and displacement),
/// `rho(t) = (E1*/E2*) R_2(t h2/h1)` times the top layer's half-space
/// compliance, with `R_2` the rest's own coating factor.
#[derive(Debug, Clone)]
pub(super) struct Resting {
    /// `E1*/E2*`, the top layer's contact modulus over the next layer's.
    ratio: f64,
    /// `h2/h1`.
    scale: f64,
    support: Support,
}

/// The coating functions of the bonded rest under a resting top layer.
#[derive(Debug, Clone)]
enum Support {
    Layer(CoatingFunctions),
    Stack(StackFunctions),
}

impl Resting {
    pub(super) fn new(stack: &Stack) -> Self {
        let layers = stack.layers();
        let (top, next) = (&layers[0], &layers[1]);
        let rest = &layers[1..];
        let support = if rest.len() == 1 {
            Support::Layer(CoatingFunctions::new(next.material(), stack.base()))
        } else {
            Support::Stack(Stack::new(rest.to_vec(), *stack.base()).functions())
        };
        Resting {
            ratio: top.material().contact_modulus() / next.material().contact_modulus(),
            scale: next.thickness() / top.thickness(),
            support,
        }
    }

    /// `rho(t)`.
    pub(super) fn rho(&self, t: f64) -> f64 {
        let u = self.scale * t;
        self.ratio
            * match &self.support {
                Support::Layer(f) => f.r(u),
                Support::Stack(f) => f.r(u),
            }
    }

    /// `rho(t)` and `rho(t) / t` (finite at 0 on a rigid base).
    pub(super) fn rho_and_over_t(&self, t: f64) -> (f64, f64) {
        let u = self.scale * t;
        let over_u = match &self.support {
            Support::Layer(f) => f.r_over_t(u),
            Support::Stack(f) => f.r_over_t(u),
        };
        (self.rho(t), self.ratio * self.scale * over_u)
    }

    /// The Taylor series of `rho(t)` at 0.
    pub(super) fn rho_taylor(&self) -> Series {
        let r = match &self.support {
            Support::Layer(f) => Series::constant(1.0).sub(&f.lambda_taylor()).0,
            Support::Stack(f) => f.r_taylor(),
        };
        let mut power = 1.0;
        let mut out = [0.0; TAYLOR_TERMS];
        for (o, c) in out.iter_mut().zip(r) {
            *o = self.ratio * c * power;
            power *= self.scale;
        }
        Series(out)
    }
}
