//! The elastic body: a homogeneous half-space, one elastic layer bonded to a
//! rigid base or to an elastic half-space, or a stack of bonded layers on
//! either, and the functions of `t = q h` that describe a coated body.
//!
//! * [`CoatingFunctions`]: the coating factor `R(t)` of one layer, in closed
//!   form (Perriot & Barthel 2004), see [`closed_form`].
//! * [`StackFunctions`]: the coating factor of a [`Stack`], by a recursion
//!   with only decaying exponentials, see [`stack`] and
//!   [`doc::multilayer`](crate::doc::multilayer).

pub mod closed_form;
mod frictionless;
mod resting;
mod series;
pub mod stack;

pub use closed_form::CoatingFunctions;
pub(crate) use series::Series;
pub use stack::{Layer, Stack, StackFunctions};

use crate::error::{Error, Result};
use crate::material::Material;

/// What the layer is bonded to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Base {
    /// A rigid base (glass under a rubber film, say): zero displacement at the
    /// interface. A first-class case, not a large modulus.
    Rigid,
    /// An elastic half-space of the given material.
    Elastic(Material),
}

/// An elastic layer of finite thickness bonded to a base. Built only through
/// the validating constructors of [`Substrate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coating {
    layer: Material,
    thickness: f64,
    base: Base,
    /// Resting on its base without friction instead of bonded.
    frictionless: bool,
}

impl Coating {
    /// The layer material (`E1`, `nu1`).
    pub fn layer(&self) -> &Material {
        &self.layer
    }

    /// The layer thickness `h`, m (positive and finite).
    pub fn thickness(&self) -> f64 {
        self.thickness
    }

    /// What the layer is bonded to.
    pub fn base(&self) -> &Base {
        &self.base
    }

    /// Whether the layer rests on its base without friction
    /// ([`Substrate::layer_resting_on_rigid_base`],
    /// [`Substrate::layer_resting_on_elastic_base`]) instead of being bonded.
    pub fn is_frictionless(&self) -> bool {
        self.frictionless
    }

    /// The functions `R(t)` and `Lambda_g(t)` of this coating.
    pub fn functions(&self) -> CoatingFunctions {
        if self.frictionless {
            CoatingFunctions::frictionless(&self.layer, &self.base)
        } else {
            CoatingFunctions::new(&self.layer, &self.base)
        }
    }
}

/// The elastic body the indenter presses into.
///
/// The constructors reduce the exact limits, so that no layered machinery is
/// built where none is needed: a layer of infinite thickness, or of the same
/// material as its elastic base, is the layer's half-space; a layer of zero
/// thickness on an elastic base is the base's half-space; a stack merges
/// adjacent layers of one material and drops layers of zero thickness, and a
/// stack left with one layer is [`Substrate::Coated`].
///
/// ```
/// use layered_contact::{Base, Error, Material, Substrate};
///
/// let rubber = Material::new(0.324e6, 0.48)?;
/// let film = Substrate::layer_on_rigid_base(rubber, 5e-3)?;
/// assert!(matches!(film, Substrate::Coated(_)));
/// // Limits that reduce exactly:
/// let thick = Substrate::layer_on_rigid_base(rubber, f64::INFINITY)?;
/// assert_eq!(thick, Substrate::HalfSpace(rubber));
/// let same = Substrate::layer_on_elastic_base(rubber, 1e-3, rubber)?;
/// assert_eq!(same, Substrate::HalfSpace(rubber));
/// // Bad input is a typed error:
/// assert!(matches!(
///     Substrate::layer_on_rigid_base(rubber, -1e-3),
///     Err(Error::InvalidThickness { .. })
/// ));
/// Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Substrate {
    /// A homogeneous elastic half-space.
    HalfSpace(Material),
    /// A layer of finite positive thickness bonded to a base.
    Coated(Coating),
    /// Two or more bonded layers on a base.
    Stack(Stack),
}

/// The largest layer-to-base shear modulus ratio `mu1/mu2` accepted (for a
/// stack: the top layer over any layer or the base).
pub const MAX_SHEAR_RATIO: f64 = 1e7;

/// The smallest shear modulus ratio `mu1/mu_k` of a stack's top layer over a
/// layer or elastic base below it: stiffer than that is a rigid base.
pub const MIN_STACK_SHEAR_RATIO: f64 = 1e-60;

/// The most layers a stack may have after merging: building its kernel
/// costs about the square of the count (see
/// [`doc::multilayer`](crate::doc::multilayer)).
pub const MAX_STACK_LAYERS: usize = 64;

/// The largest total thickness of a stack over its top layer's thickness:
/// beyond, make the thick layer the (elastic) base.
pub const MAX_STACK_DEPTH_RATIO: f64 = 1e12;

impl Substrate {
    /// A homogeneous half-space of `material`.
    pub fn half_space(material: Material) -> Self {
        Substrate::HalfSpace(material)
    }

    /// A layer of `thickness` (m) bonded to a rigid base.
    ///
    /// `thickness = +inf` gives the layer's half-space.
    ///
    /// # Errors
    /// [`Error::InvalidThickness`] if `thickness` is NaN, negative or zero (a
    /// zero-thickness layer on a rigid base leaves no elastic body).
    pub fn layer_on_rigid_base(layer: Material, thickness: f64) -> Result<Self> {
        if thickness.is_nan() || thickness <= 0.0 {
            return Err(Error::InvalidThickness {
                value: thickness,
                expected: "positive on a rigid base (or +inf for a half-space)",
            });
        }
        Ok(Self::coated(layer, thickness, Base::Rigid))
    }

    /// A layer of `thickness` (m) resting on a rigid base without friction:
    /// in contact everywhere, free to slide (the unbonded layer of
    /// Dimitriadis et al. 2002, Biophys. J. 82, 2798; a gel or a cell on
    /// glass it does not stick to). See
    /// [`CoatingFunctions::frictionless_rigid_base`] for its coating
    /// factor. `thickness = +inf` gives the layer's half-space.
    ///
    /// ```
    /// use layered_contact::{Material, Substrate};
    /// use layered_contact::analytic::Axisymmetric;
    ///
    /// let gel = Material::new(10e3, 0.5)?;
    /// let bonded = Substrate::layer_on_rigid_base(gel, 4e-6)?;
    /// let resting = Substrate::layer_resting_on_rigid_base(gel, 4e-6)?;
    /// let k = |s: &Substrate| Axisymmetric::new(s, 1.0)?.flat_punch(2e-6).map(|p| p.stiffness());
    /// // Free to slide, the film is softer than bonded, stiffer than a half-space.
    /// let half = 2.0 * 2e-6 * gel.contact_modulus();
    /// assert!(half < k(&resting)? && k(&resting)? < k(&bonded)?);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Substrate::layer_on_rigid_base`].
    pub fn layer_resting_on_rigid_base(layer: Material, thickness: f64) -> Result<Self> {
        Ok(match Self::layer_on_rigid_base(layer, thickness)? {
            Substrate::Coated(coating) => Substrate::Coated(Coating {
                frictionless: true,
                ..coating
            }),
            other => other,
        })
    }

    /// A layer of `thickness` (m) resting without friction on an elastic
    /// half-space of `base` (a gel on a softer or stiffer gel, a cell on a
    /// soft substrate): shear-free interface, continuous normal displacement
    /// and traction. See [`CoatingFunctions::frictionless`] for its coating
    /// factor. `thickness = 0` gives the base's half-space and `thickness =
    /// +inf` the layer's; a layer of the base's own material stays a layer
    /// (the interface still slides).
    ///
    /// ```
    /// use layered_contact::{Material, Substrate};
    /// use layered_contact::analytic::Axisymmetric;
    ///
    /// let gel = Material::new(10e3, 0.5)?;
    /// let bonded = Substrate::layer_on_elastic_base(gel, 4e-6, gel)?; // the half-space
    /// let resting = Substrate::layer_resting_on_elastic_base(gel, 4e-6, gel)?;
    /// let k = |s: &Substrate| Axisymmetric::new(s, 1.0)?.flat_punch(2e-6).map(|p| p.stiffness());
    /// // Free to slide on its own material, the layer is softer than the half-space.
    /// assert!(k(&resting)? < k(&bonded)?);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Substrate::layer_on_elastic_base`].
    pub fn layer_resting_on_elastic_base(
        layer: Material,
        thickness: f64,
        base: Material,
    ) -> Result<Self> {
        // Validates as bonded (same limits), then keeps the layer even when
        // it is of the base's material.
        Self::layer_on_elastic_base(layer, thickness, base)?;
        Ok(match thickness {
            0.0 => Substrate::HalfSpace(base),
            f64::INFINITY => Substrate::HalfSpace(layer),
            _ => Substrate::Coated(Coating {
                layer,
                thickness,
                base: Base::Elastic(base),
                frictionless: true,
            }),
        })
    }

    /// A layer of `thickness` (m) bonded to an elastic half-space of `base`.
    ///
    /// `thickness = 0` gives the base's half-space, `thickness = +inf` or
    /// `layer == base` the layer's half-space.
    ///
    /// # Errors
    /// [`Error::InvalidThickness`] if `thickness` is NaN or negative;
    /// [`Error::InvalidParameter`] if the base is more than `1e7` times
    /// softer in shear than the layer (`mu1/mu2 > 1e7`): the base then
    /// carries nothing the kernel can resolve (and at `mu1/mu2` beyond the
    /// `f64` range the kernel's integrals would not end).
    pub fn layer_on_elastic_base(layer: Material, thickness: f64, base: Material) -> Result<Self> {
        if thickness.is_nan() || thickness < 0.0 {
            return Err(Error::InvalidThickness {
                value: thickness,
                expected: "non-negative (or +inf for a half-space)",
            });
        }
        let shear_ratio = layer.shear_modulus() / base.shear_modulus();
        if thickness > 0.0
            && thickness < f64::INFINITY
            && (shear_ratio.is_nan() || shear_ratio > MAX_SHEAR_RATIO)
        {
            return Err(Error::InvalidParameter {
                name: "shear modulus ratio mu1/mu2 (layer over base)",
                value: shear_ratio,
                expected: "at most 1e7 (a base 1e7 times softer than its layer carries nothing)",
            });
        }
        if thickness == 0.0 {
            return Ok(Substrate::HalfSpace(base));
        }
        if layer == base {
            return Ok(Substrate::HalfSpace(layer));
        }
        Ok(Self::coated(layer, thickness, Base::Elastic(base)))
    }

    fn coated(layer: Material, thickness: f64, base: Base) -> Self {
        if thickness == f64::INFINITY {
            Substrate::HalfSpace(layer)
        } else {
            Substrate::Coated(Coating {
                layer,
                thickness,
                base,
                frictionless: false,
            })
        }
    }

    /// A stack of bonded `layers`, each `(material, thickness)` (m), top
    /// first, on `base`.
    ///
    /// The stack is reduced exactly before anything is built: a layer of
    /// infinite thickness becomes the base (the layers below it are never
    /// reached), layers of zero thickness are dropped, adjacent layers of one
    /// material merge (their thicknesses add), bottom layers of the base's
    /// material merge into an elastic base. One layer left gives
    /// [`Substrate::Coated`] (as [`Substrate::layer_on_rigid_base`] or
    /// [`Substrate::layer_on_elastic_base`]), none the base's half-space.
    ///
    /// ```
    /// use layered_contact::{Base, Error, Material, Substrate};
    ///
    /// let dlc = Material::new(300e9, 0.2)?;
    /// let chromium = Material::new(140e9, 0.21)?;
    /// let steel = Material::new(210e9, 0.3)?;
    /// let coat = Substrate::stack(&[(dlc, 2e-6), (chromium, 0.3e-6)], Base::Elastic(steel))?;
    /// let Substrate::Stack(stack) = &coat else { unreachable!() };
    /// assert_eq!(stack.layers().len(), 2);
    /// assert_eq!(stack.total_thickness(), 2.3e-6);
    /// // Two layers of one material are one layer:
    /// let merged = Substrate::stack(&[(dlc, 1e-6), (dlc, 1e-6)], Base::Elastic(steel))?;
    /// assert_eq!(merged, Substrate::layer_on_elastic_base(dlc, 2e-6, steel)?);
    /// Ok::<(), Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidThickness`] for a NaN or negative thickness, or for a
    /// stack on a rigid base that reduces to no layer;
    /// [`Error::InvalidParameter`] if the top layer is more than `1e7` times
    /// stiffer in shear than a layer or elastic base below it, or more than
    /// `1e60` times softer (use a rigid base), if the stack is more than
    /// `1e12` times thicker than its top layer, or if more than
    /// [`MAX_STACK_LAYERS`] layers remain after merging.
    pub fn stack(layers: &[(Material, f64)], base: Base) -> Result<Self> {
        for &(_, thickness) in layers {
            if thickness.is_nan() || thickness < 0.0 {
                return Err(Error::InvalidThickness {
                    value: thickness,
                    expected: "non-negative for every layer of a stack (or +inf for a half-space)",
                });
            }
        }
        let (layers, base) = merge(layers, base);
        match layers.as_slice() {
            [] => match base {
                Base::Elastic(material) => Ok(Substrate::HalfSpace(material)),
                Base::Rigid => Err(Error::InvalidThickness {
                    value: 0.0,
                    expected:
                        "a stack on a rigid base with at least one layer of positive thickness",
                }),
            },
            [single] => match base {
                Base::Rigid => Self::layer_on_rigid_base(*single.material(), single.thickness()),
                Base::Elastic(material) => {
                    Self::layer_on_elastic_base(*single.material(), single.thickness(), material)
                }
            },
            _ => {
                check_stack(&layers, &base)?;
                Ok(Substrate::Stack(Stack::new(layers, base)))
            }
        }
    }

    /// The material at the surface: the (top) layer of a coated body, or the
    /// half-space material.
    pub fn surface_material(&self) -> &Material {
        match self {
            Substrate::HalfSpace(material) => material,
            Substrate::Coated(coating) => &coating.layer,
            Substrate::Stack(stack) => stack.top().material(),
        }
    }

    /// The same body with the top layer's (or the half-space's) Young's
    /// modulus `youngs_modulus` (Pa), its Poisson ratio, thickness, support
    /// and interface kept: what a fit of the top layer's modulus varies.
    ///
    /// ```
    /// use layered_contact::{Material, Substrate};
    ///
    /// let gel = Material::new(2.5e3, 0.5)?;
    /// let film = Substrate::layer_resting_on_elastic_base(Material::new(1e4, 0.5)?, 4e-6, gel)?;
    /// let stiffer = film.with_surface_youngs_modulus(2e4)?;
    /// assert_eq!(stiffer.surface_material().youngs_modulus(), 2e4);
    /// assert_eq!(stiffer, Substrate::layer_resting_on_elastic_base(Material::new(2e4, 0.5)?, 4e-6, gel)?);
    /// # Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidYoungsModulus`] for a modulus out of range, and the
    /// constructors' errors for the new contrast with the layers below.
    pub fn with_surface_youngs_modulus(&self, youngs_modulus: f64) -> Result<Self> {
        let top = Material::new(youngs_modulus, self.surface_material().poisson_ratio())?;
        match self {
            Substrate::HalfSpace(_) => Ok(Substrate::HalfSpace(top)),
            Substrate::Coated(c) => match (c.base, c.frictionless) {
                (Base::Rigid, false) => Self::layer_on_rigid_base(top, c.thickness),
                (Base::Rigid, true) => Self::layer_resting_on_rigid_base(top, c.thickness),
                (Base::Elastic(base), false) => Self::layer_on_elastic_base(top, c.thickness, base),
                (Base::Elastic(base), true) => {
                    Self::layer_resting_on_elastic_base(top, c.thickness, base)
                }
            },
            Substrate::Stack(stack) if stack.top_rests() => {
                let support = self.support().flatten().ok_or(Error::Unsupported {
                    feature: "a resting layer without its support",
                    reason: "the layers below a resting top layer form a valid body",
                })?;
                Self::layer_resting_on(top, stack.top().thickness(), &support)
            }
            Substrate::Stack(stack) => {
                let layers: Vec<(Material, f64)> = std::iter::once((top, stack.top().thickness()))
                    .chain(
                        stack.layers()[1..]
                            .iter()
                            .map(|l| (*l.material(), l.thickness())),
                    )
                    .collect();
                Self::stack(&layers, *stack.base())
            }
        }
    }

    /// The thickness of the top layer (m), the length that scales the
    /// coating functions (`t = q h`); `None` for a half-space.
    pub fn top_thickness(&self) -> Option<f64> {
        match self {
            Substrate::HalfSpace(_) => None,
            Substrate::Coated(coating) => Some(coating.thickness),
            Substrate::Stack(stack) => Some(stack.top().thickness()),
        }
    }

    /// What supports the top layer: `None` for a half-space (no layer),
    /// `Some(None)` for a rigid base right under it, `Some(Some(body))`
    /// otherwise (the elastic base, or the rest of a stack on its base).
    pub(crate) fn support(&self) -> Option<Option<Substrate>> {
        let base = self.base()?;
        let rest: Vec<(Material, f64)> = match self {
            Substrate::Stack(stack) => stack.layers()[1..]
                .iter()
                .map(|layer| (*layer.material(), layer.thickness()))
                .collect(),
            _ => Vec::new(),
        };
        Some(match (rest.is_empty(), base) {
            (true, Base::Rigid) => None,
            (true, Base::Elastic(material)) => Some(Substrate::HalfSpace(*material)),
            // The rest of a valid stack is a valid stack.
            (false, base) => Substrate::stack(&rest, *base).ok(),
        })
    }

    /// The total thickness of the layers (m); `None` for a half-space.
    pub fn total_thickness(&self) -> Option<f64> {
        match self {
            Substrate::HalfSpace(_) => None,
            Substrate::Coated(coating) => Some(coating.thickness),
            Substrate::Stack(stack) => Some(stack.total_thickness()),
        }
    }

    /// What the layers are bonded to; `None` for a half-space.
    pub fn base(&self) -> Option<&Base> {
        match self {
            Substrate::HalfSpace(_) => None,
            Substrate::Coated(coating) => Some(&coating.base),
            Substrate::Stack(stack) => Some(stack.base()),
        }
    }

    /// `E*` of the material deepest in the body: the half-space's, the
    /// elastic base's, or `+inf` for a rigid base. Long waves see it alone.
    pub fn deep_contact_modulus(&self) -> f64 {
        match self.base() {
            None => self.surface_material().contact_modulus(),
            Some(Base::Rigid) => f64::INFINITY,
            Some(Base::Elastic(material)) => material.contact_modulus(),
        }
    }

    /// The smallest `E*` of the body's materials (layers and elastic base).
    pub fn softest_contact_modulus(&self) -> f64 {
        let surface = self.surface_material().contact_modulus();
        let layers = match self {
            Substrate::Stack(stack) => stack
                .layers()
                .iter()
                .map(|layer| layer.material().contact_modulus())
                .fold(surface, f64::min),
            _ => surface,
        };
        layers.min(self.deep_contact_modulus())
    }

    /// The pieces of `Lambda_g` with their length scales (empty for a
    /// half-space): one for a layer, one per interface for a stack.
    pub(crate) fn terms(&self) -> Vec<Term> {
        match self {
            Substrate::HalfSpace(_) => Vec::new(),
            Substrate::Coated(coating) => vec![Term {
                length: coating.thickness,
                functions: Spectral::Closed(coating.functions()),
            }],
            Substrate::Stack(stack) if stack.top_rests() => vec![Term {
                length: stack.top().thickness(),
                functions: Spectral::Resting(stack.functions()),
            }],
            Substrate::Stack(stack) => {
                let h1 = stack.top().thickness();
                stack
                    .functions()
                    .brackets()
                    .into_iter()
                    .map(|bracket| Term {
                        length: bracket.depth() * h1,
                        functions: Spectral::Bracket(bracket),
                    })
                    .collect()
            }
        }
    }
}

/// The reduced form of a stack (see [`Substrate::stack`]); thicknesses are
/// valid.
fn merge(layers: &[(Material, f64)], base: Base) -> (Vec<Layer>, Base) {
    let mut merged: Vec<Layer> = Vec::new();
    let mut base = base;
    for &(material, thickness) in layers {
        if thickness == f64::INFINITY {
            base = Base::Elastic(material);
            break;
        }
        if thickness == 0.0 {
            continue;
        }
        match merged.last_mut() {
            Some(last) if *last.material() == material => {
                *last = Layer::new(material, last.thickness() + thickness);
            }
            _ => merged.push(Layer::new(material, thickness)),
        }
    }
    if let Base::Elastic(material) = base {
        while merged
            .last()
            .is_some_and(|last| *last.material() == material)
        {
            merged.pop();
        }
    }
    (merged, base)
}

/// The limits of [`Substrate::stack`] on moduli and thicknesses.
pub(crate) fn check_stack(layers: &[Layer], base: &Base) -> Result<()> {
    if layers.len() > MAX_STACK_LAYERS {
        return Err(Error::InvalidParameter {
            name: "number of layers (after merging)",
            value: layers.len() as f64,
            expected: "at most 64",
        });
    }
    let Some(top) = layers.first() else {
        return Ok(());
    };
    let below = layers[1..]
        .iter()
        .map(|layer| *layer.material())
        .chain(match base {
            Base::Rigid => None,
            Base::Elastic(material) => Some(*material),
        });
    for material in below {
        let ratio = top.material().shear_modulus() / material.shear_modulus();
        crate::error::within(
            "shear modulus ratio mu1/mu_k (top layer over a layer or base below)",
            ratio,
            (MIN_STACK_SHEAR_RATIO, MAX_SHEAR_RATIO),
            "within [1e-60, 1e7] (stiffer than 1e60 times the top: a rigid base)",
        )?;
    }
    let depth = layers.iter().map(Layer::thickness).sum::<f64>() / top.thickness();
    if depth.is_nan() || depth > MAX_STACK_DEPTH_RATIO {
        return Err(Error::InvalidParameter {
            name: "total thickness / top layer thickness",
            value: depth,
            expected: "at most 1e12 (make a layer that thick the elastic base)",
        });
    }
    Ok(())
}

/// The functions of one piece of a layered body's `Lambda_g`.
#[derive(Debug, Clone)]
pub(crate) enum Spectral {
    /// One layer on a base, in closed form.
    Closed(CoatingFunctions),
    /// One interface of a stack.
    Bracket(stack::Bracket),
    /// A stack whose top layer rests on the rest without friction, whole.
    Resting(StackFunctions),
}

impl Spectral {
    /// The value at `u = q * length`.
    pub(crate) fn lambda(&self, u: f64) -> f64 {
        match self {
            Spectral::Closed(functions) => functions.lambda(u),
            Spectral::Bracket(bracket) => bracket.lambda(u),
            Spectral::Resting(functions) => functions.lambda(u),
        }
    }

    /// Taylor coefficients in `u` at 0.
    pub(crate) fn lambda_taylor(&self) -> Series {
        match self {
            Spectral::Closed(functions) => functions.lambda_taylor(),
            Spectral::Bracket(bracket) => bracket.lambda_taylor(),
            Spectral::Resting(functions) => functions.lambda_taylor(),
        }
    }
}

/// One piece of `Lambda_g` and the length `u = q * length` is measured in.
#[derive(Debug, Clone)]
pub(crate) struct Term {
    pub(crate) length: f64,
    pub(crate) functions: Spectral,
}
