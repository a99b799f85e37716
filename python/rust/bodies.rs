//! Materials and substrates: the elastic bodies.

use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use layered_contact as lc;

use super::*;

/// An isotropic linear-elastic material: `Material(youngs_modulus, poisson_ratio)`,
/// Young's modulus `E` in Pa (positive) and Poisson's ratio `nu` in `[0, 0.5]`.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
pub(crate) struct Material {
    pub(crate) inner: lc::Material,
}

#[pymethods]
impl Material {
    #[new]
    fn new(youngs_modulus: f64, poisson_ratio: f64) -> PyResult<Self> {
        Ok(Material {
            inner: lc::Material::new(youngs_modulus, poisson_ratio).py_err()?,
        })
    }

    /// Young's modulus E, Pa.
    #[getter]
    fn youngs_modulus(&self) -> f64 {
        self.inner.youngs_modulus()
    }

    /// Poisson ratio nu.
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.inner.poisson_ratio()
    }

    /// Plane-strain modulus E* = E / (1 - nu^2), Pa.
    #[getter]
    fn contact_modulus(&self) -> f64 {
        self.inner.contact_modulus()
    }

    fn __repr__(&self) -> String {
        format!(
            "Material(youngs_modulus={:e}, poisson_ratio={})",
            self.inner.youngs_modulus(),
            self.inner.poisson_ratio()
        )
    }

    /// Pickling (multiprocessing, Dask): the constructor and its arguments.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (f64, f64))> {
        let m = slf.get().inner;
        Ok((
            slf.get_type().into_any(),
            (m.youngs_modulus(), m.poisson_ratio()),
        ))
    }
}

/// The elastic body: a half-space, a layer, or a stack of bonded layers, on a
/// rigid or elastic base.
#[pyclass(module = "layered_contact._native", frozen)]
#[derive(Clone)]
pub(crate) struct Substrate {
    pub(crate) inner: lc::Substrate,
}

#[pymethods]
impl Substrate {
    /// A homogeneous half-space.
    #[staticmethod]
    fn half_space(material: &Material) -> Self {
        Substrate {
            inner: lc::Substrate::half_space(material.inner),
        }
    }

    /// A layer of thickness `thickness` (m) resting on a rigid base without
    /// friction (Dimitriadis et al. 2002's unbonded layer).
    #[staticmethod]
    fn layer_resting_on_rigid_base(layer: &Material, thickness: f64) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_resting_on_rigid_base(layer.inner, thickness).py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) resting without friction on an
    /// elastic half-space of `base`.
    #[staticmethod]
    fn layer_resting_on_elastic_base(
        layer: &Material,
        thickness: f64,
        base: &Material,
    ) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_resting_on_elastic_base(layer.inner, thickness, base.inner)
                .py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) resting without friction on
    /// `support`, a body of bonded layers (a half-space, a layer, a stack):
    /// the interface under the layer carries no shear, those below stay
    /// bonded.
    #[staticmethod]
    fn layer_resting_on(layer: &Material, thickness: f64, support: &Substrate) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_resting_on(layer.inner, thickness, &support.inner)
                .py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) bonded to a rigid base.
    #[staticmethod]
    fn layer_on_rigid_base(layer: &Material, thickness: f64) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_on_rigid_base(layer.inner, thickness).py_err()?,
        })
    }

    /// A layer of thickness `thickness` (m) bonded to an elastic half-space.
    #[staticmethod]
    fn layer_on_elastic_base(layer: &Material, thickness: f64, base: &Material) -> PyResult<Self> {
        Ok(Substrate {
            inner: lc::Substrate::layer_on_elastic_base(layer.inner, thickness, base.inner)
                .py_err()?,
        })
    }

    /// Bonded `layers`, each `(material, thickness)` (m), top first, on an
    /// elastic half-space of `base`, or on a rigid base when `base` is None.
    /// Adjacent layers of one material merge; one layer left is a coating.
    #[staticmethod]
    #[pyo3(signature = (layers, base=None))]
    fn stack(
        layers: Vec<(PyRef<'_, Material>, f64)>,
        base: Option<PyRef<'_, Material>>,
    ) -> PyResult<Self> {
        let layers: Vec<(lc::Material, f64)> = layers.iter().map(|(m, h)| (m.inner, *h)).collect();
        let base = base.map_or(lc::Base::Rigid, |m| lc::Base::Elastic(m.inner));
        Ok(Substrate {
            inner: lc::Substrate::stack(&layers, base).py_err()?,
        })
    }

    /// The number of layers (0 for a half-space).
    #[getter]
    fn layer_count(&self) -> usize {
        match &self.inner {
            lc::Substrate::HalfSpace(_) => 0,
            lc::Substrate::Stack(stack) => stack.layers().len(),
            _ => 1,
        }
    }

    /// The total thickness of the layers (m); None for a half-space.
    #[getter]
    fn total_thickness(&self) -> Option<f64> {
        self.inner.total_thickness()
    }

    /// `Substrate.half_space(Material(...))` and the like: the constructor
    /// that rebuilds it.
    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let (name, arguments) = slf.get().parts(slf.py())?;
        let arguments = arguments
            .iter()
            .map(|a| Ok(a.bind(slf.py()).repr()?.to_string()))
            .collect::<PyResult<Vec<String>>>()?;
        Ok(format!("Substrate.{name}({})", arguments.join(", ")))
    }

    /// Pickling (multiprocessing, Dask): the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let (name, arguments) = slf.get().parts(py)?;
        Ok((slf.get_type().getattr(name)?, PyTuple::new(py, arguments)?))
    }
}

impl Substrate {
    /// The constructor's name and arguments that rebuild this substrate.
    fn parts(&self, py: Python<'_>) -> PyResult<(&'static str, Vec<Py<PyAny>>)> {
        let material = |m: &lc::Material| -> PyResult<Py<PyAny>> {
            Ok(Py::new(py, Material { inner: *m })?.into_any())
        };
        let number =
            |v: f64| -> PyResult<Py<PyAny>> { Ok(v.into_pyobject(py)?.into_any().unbind()) };
        Ok(match &self.inner {
            lc::Substrate::HalfSpace(m) => ("half_space", vec![material(m)?]),
            lc::Substrate::Coated(c) => {
                let (layer, h) = (material(c.layer())?, number(c.thickness())?);
                match (c.base(), c.is_frictionless()) {
                    (lc::Base::Rigid, false) => ("layer_on_rigid_base", vec![layer, h]),
                    (lc::Base::Rigid, true) => ("layer_resting_on_rigid_base", vec![layer, h]),
                    (lc::Base::Elastic(b), false) => {
                        ("layer_on_elastic_base", vec![layer, h, material(b)?])
                    }
                    (lc::Base::Elastic(b), true) => (
                        "layer_resting_on_elastic_base",
                        vec![layer, h, material(b)?],
                    ),
                }
            }
            lc::Substrate::Stack(stack) if stack.top_rests() => {
                let rest: Vec<(lc::Material, f64)> = stack.layers()[1..]
                    .iter()
                    .map(|l| (*l.material(), l.thickness()))
                    .collect();
                let support = Substrate {
                    inner: lc::Substrate::stack(&rest, *stack.base()).py_err()?,
                };
                (
                    "layer_resting_on",
                    vec![
                        material(stack.top().material())?,
                        number(stack.top().thickness())?,
                        Py::new(py, support)?.into_any(),
                    ],
                )
            }
            lc::Substrate::Stack(stack) => {
                let layers = stack
                    .layers()
                    .iter()
                    .map(|l| {
                        Ok(
                            PyTuple::new(py, [material(l.material())?, number(l.thickness())?])?
                                .into_any()
                                .unbind(),
                        )
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                let base = match stack.base() {
                    lc::Base::Rigid => py.None(),
                    lc::Base::Elastic(b) => material(b)?,
                };
                (
                    "stack",
                    vec![PyList::new(py, layers)?.into_any().unbind(), base],
                )
            }
        })
    }
}
