//! The Fourier-space surface compliance `u_z(q)` of a substrate.

use crate::substrate::{CoatingFunctions, StackFunctions, Substrate};

/// The surface normal displacement, in Fourier space, due to a unit normal
/// point force: `u_z(q) = 2 / (E* q)` on a half-space and
/// `u_z(q) = 2 R(q h) / (E1* q)` on a coated half-space (Perriot & Barthel 2004,
/// J. Mater. Res. 19, 600; `R` from [`CoatingFunctions`], or from
/// [`StackFunctions`] for a stack, `h` its top layer's thickness). Units m/N
/// times m^2, i.e. m^3/N.
///
/// At `q = 0` it is `+inf` on a half-space and on a layer over an elastic
/// base, and the finite uniaxial-strain compliance
/// `h (1 + nu1)(1 - 2 nu1) / (E1 (1 - nu1))` on a rigid base (0 for an
/// incompressible layer; for a stack the sum over its layers): see
/// [`FourierCompliance::at_zero`].
///
/// ```
/// use layered_contact::kernel::FourierCompliance;
/// use layered_contact::{Material, Substrate};
///
/// let layer = Material::new(1e6, 0.3)?;
/// let h = 2e-3;
/// let film = FourierCompliance::new(&Substrate::layer_on_rigid_base(layer, h)?);
/// let uniaxial = h * 1.3 * 0.4 / (1e6 * 0.7);
/// assert!((film.at_zero() / uniaxial - 1.0).abs() < 1e-15);
/// assert!((film.eval(1e-6) / uniaxial - 1.0).abs() < 1e-6);
/// // At short wavelengths the film looks like its own half-space.
/// let q = 1e6;
/// assert!((film.eval(q) * layer.contact_modulus() * q / 2.0 - 1.0).abs() < 1e-15);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct FourierCompliance {
    /// `E*` of the surface material (layer or half-space).
    contact_modulus: f64,
    body: Body,
}

/// What lies under the surface material.
#[derive(Debug, Clone)]
enum Body {
    HalfSpace,
    /// A layer of this thickness and its functions.
    Layer(f64, CoatingFunctions),
    /// A stack, its top layer's thickness and its functions.
    Stack(f64, StackFunctions),
}

impl FourierCompliance {
    /// The compliance of `substrate`.
    pub fn new(substrate: &Substrate) -> Self {
        let body = match substrate {
            Substrate::HalfSpace(_) => Body::HalfSpace,
            Substrate::Coated(coating) => Body::Layer(coating.thickness(), coating.functions()),
            Substrate::Stack(stack) => Body::Stack(stack.top().thickness(), stack.functions()),
        };
        FourierCompliance {
            contact_modulus: substrate.surface_material().contact_modulus(),
            body,
        }
    }

    /// `u_z(q)` for wavenumber `|q|` (rad/m), m^3/N.
    pub fn eval(&self, q: f64) -> f64 {
        let q = q.abs();
        let (h, r_over_t) = match &self.body {
            Body::HalfSpace => return 2.0 / (self.contact_modulus * q),
            Body::Layer(h, functions) => (h, functions.r_over_t(q * h)),
            Body::Stack(h, functions) => (h, functions.r_over_t(q * h)),
        };
        2.0 * h * r_over_t / self.contact_modulus
    }

    /// The body's contact modulus at wavenumber `|q|` (rad/m), `E*(q) = 2 /
    /// (q u_z(q))` (Pa): the surface's `E*` at short wavelengths, the
    /// deepest material's at long ones over an elastic base (the apparent
    /// modulus of Perriot & Barthel 2004, J. Mater. Res. 19, 600).
    ///
    /// ```
    /// use layered_contact::kernel::FourierCompliance;
    /// use layered_contact::{Material, Substrate};
    ///
    /// let (film, glass) = (Material::new(1e6, 0.3)?, Material::new(7e10, 0.2)?);
    /// let body = FourierCompliance::new(&Substrate::layer_on_elastic_base(film, 1e-4, glass)?);
    /// assert!((body.contact_modulus_at(1e9) / film.contact_modulus() - 1.0).abs() < 1e-6);
    /// assert!((body.contact_modulus_at(1e-8) / glass.contact_modulus() - 1.0).abs() < 1e-6);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn contact_modulus_at(&self, q: f64) -> f64 {
        2.0 / (q.abs() * self.eval(q))
    }

    /// `u_z(0)`: finite only for a layer on a rigid base.
    pub fn at_zero(&self) -> f64 {
        self.eval(0.0)
    }
}
