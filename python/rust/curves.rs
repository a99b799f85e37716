//! Bindings for fitting measured curves: the tabulated exact force curve
//! of a tip (`analytic::ForceCurve`), and pull-offs and jump-ins under a
//! cantilever.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use layered_contact as lc;

use super::{checked_len, OrPy, Substrate};

/// The tip named `kind` (`"paraboloid"`, `"sphere"`, `"cone"`,
/// `"rounded_cone"`) of radius `radius` (m; tip radius, sphere radius or
/// apex radius) and half-angle `half_angle` (rad; cones).
pub(crate) fn tip(kind: &str, radius: f64, half_angle: f64) -> PyResult<lc::analytic::Tip> {
    use lc::analytic::Tip;
    Ok(match kind {
        "paraboloid" => Tip::Paraboloid { radius },
        "sphere" => Tip::Sphere { radius },
        "cone" => Tip::Cone { half_angle },
        "rounded_cone" => Tip::RoundedCone {
            half_angle,
            tip_radius: radius,
        },
        other => {
            return Err(super::InvalidInputError::new_err(format!(
                "tip {other:?}: expected 'paraboloid', 'sphere', 'cone' or 'rounded_cone'"
            )))
        }
    })
}

/// [`tip`], or `None` for `"flat_punch"` (its radius passed apart).
fn tip_or_punch(kind: &str, radius: f64, half_angle: f64) -> PyResult<Option<lc::analytic::Tip>> {
    Ok(match kind {
        "flat_punch" => None,
        other => Some(tip(other, radius, half_angle)?),
    })
}

/// The exact force curve of a tip on `substrate`, tabulated to
/// `max_depth` (m) once and then evaluated for any modulus (on glass or a
/// half-space) and work of adhesion (`analytic::ForceCurve`). `kind` as
/// for [`tip`], or `"flat_punch"` (`radius`: the punch's).
#[pyclass(module = "layered_contact._native", frozen)]
pub(crate) struct ForceCurve {
    inner: lc::analytic::ForceCurve,
}

#[pymethods]
impl ForceCurve {
    #[new]
    #[pyo3(signature = (substrate, kind, radius, max_depth, half_angle=f64::NAN))]
    fn new(
        py: Python<'_>,
        substrate: &Substrate,
        kind: &str,
        radius: f64,
        max_depth: f64,
        half_angle: f64,
    ) -> PyResult<Self> {
        let tip = tip_or_punch(kind, radius, half_angle)?;
        let substrate = substrate.inner.clone();
        let inner = py
            .detach(|| match tip {
                Some(tip) => lc::analytic::ForceCurve::on(&substrate, tip, max_depth),
                None => lc::analytic::ForceCurve::flat_punch_on(&substrate, radius),
            })
            .py_err()?;
        Ok(ForceCurve { inner })
    }

    /// The forces (N) at `depth` (m, any shape) for a top layer whose
    /// contact modulus is `modulus_ratio` times the table's, with work of
    /// adhesion `work_of_adhesion` (J/m^2): the fixed-grips branch, 0 before
    /// contact and after detachment, NaN beyond `reach(...)`.
    #[pyo3(signature = (depth, modulus_ratio=1.0, work_of_adhesion=0.0))]
    fn forces<'py>(
        &self,
        py: Python<'py>,
        depth: PyReadonlyArrayDyn<'py, f64>,
        modulus_ratio: f64,
        work_of_adhesion: f64,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        checked_len("depth", depth.shape())?;
        let shape = depth.shape().to_vec();
        let depths: Vec<f64> = depth.as_array().iter().copied().collect();
        let inner = &self.inner;
        let forces = py.detach(|| inner.forces(&depths, modulus_ratio, work_of_adhesion));
        PyArray1::from_vec(py, forces).reshape(shape)
    }

    /// The deepest indentation (m) whose force the table gives for
    /// `modulus_ratio` and `work_of_adhesion` (J/m^2): `max_depth` without
    /// adhesion, less with it when adhesion lifts the indenter at the
    /// table's largest contact radius by more.
    #[pyo3(signature = (modulus_ratio=1.0, work_of_adhesion=0.0))]
    fn reach(&self, modulus_ratio: f64, work_of_adhesion: f64) -> f64 {
        self.inner.reach(modulus_ratio, work_of_adhesion)
    }

    /// The contact modulus `E1*` of the table's body, Pa.
    #[getter]
    fn contact_modulus(&self) -> f64 {
        self.inner.contact_modulus()
    }

    /// The deepest indentation the table reaches, m.
    #[getter]
    fn max_depth(&self) -> f64 {
        self.inner.max_depth()
    }
}

/// The force curves of a tip (as [`ForceCurve`]) on `substrate` with
/// its top layer's Young's modulus anywhere in `youngs_range` (Pa), from
/// `nodes` exact tables at Chebyshev nodes in `ln E`
/// (`analytic::ModulusFamily`): for fits and force maps on supports where
/// the force does not scale with the modulus (an elastic base, a stack).
#[pyclass(module = "layered_contact._native", frozen)]
pub(crate) struct ModulusFamily {
    inner: lc::analytic::ModulusFamily,
}

#[pymethods]
impl ModulusFamily {
    #[new]
    #[pyo3(signature = (substrate, kind, radius, max_depth, youngs_range, nodes=12, half_angle=f64::NAN))]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    fn new(
        py: Python<'_>,
        substrate: &Substrate,
        kind: &str,
        radius: f64,
        max_depth: f64,
        youngs_range: (f64, f64),
        nodes: usize,
        half_angle: f64,
    ) -> PyResult<Self> {
        let tip = tip_or_punch(kind, radius, half_angle)?;
        let substrate = substrate.inner.clone();
        let inner = py
            .detach(|| {
                lc::analytic::ModulusFamily::new(
                    &substrate,
                    tip,
                    radius,
                    max_depth,
                    youngs_range,
                    nodes,
                )
            })
            .py_err()?;
        Ok(ModulusFamily { inner })
    }

    /// The forces (N) at `depth` (m, any shape) for a top layer of Young's
    /// modulus `youngs_modulus` (Pa) and work of adhesion
    /// `work_of_adhesion` (J/m^2, 0 for the approach), along the
    /// fixed-grips branch; NaN outside the range.
    #[pyo3(signature = (depth, youngs_modulus, work_of_adhesion=0.0))]
    fn forces<'py>(
        &self,
        py: Python<'py>,
        depth: PyReadonlyArrayDyn<'py, f64>,
        youngs_modulus: f64,
        work_of_adhesion: f64,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        checked_len("depth", depth.shape())?;
        let shape = depth.shape().to_vec();
        let depths: Vec<f64> = depth.as_array().iter().copied().collect();
        let inner = &self.inner;
        let forces = py.detach(|| inner.adhesive_forces(&depths, youngs_modulus, work_of_adhesion));
        PyArray1::from_vec(py, forces).reshape(shape)
    }

    /// The deepest indentation (m) whose force the family gives at
    /// `youngs_modulus` (Pa) with `work_of_adhesion` (J/m^2); NaN outside
    /// the range.
    #[pyo3(signature = (youngs_modulus, work_of_adhesion=0.0))]
    fn reach(&self, youngs_modulus: f64, work_of_adhesion: f64) -> f64 {
        self.inner.reach(youngs_modulus, work_of_adhesion)
    }

    /// The range of Young's moduli covered, Pa.
    #[getter]
    fn youngs_range(&self) -> (f64, f64) {
        self.inner.youngs_range()
    }
}

/// The pull-offs of a tip (as [`tip`]) with work of adhesion
/// `work_of_adhesion` (J/m^2) on `substrate`: a dict of dicts (`force` N,
/// `depth` m, `contact_radius` m) under `load_control`,
/// `displacement_control` and, for a cantilever of stiffness `spring`
/// (N/m), `spring_pull_off` and `spring_jump_in`.
#[pyfunction]
#[pyo3(signature = (substrate, kind, radius, work_of_adhesion, half_angle=f64::NAN, spring=None))]
pub(crate) fn tip_pull_off<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    kind: &str,
    radius: f64,
    work_of_adhesion: f64,
    half_angle: f64,
    spring: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let tip = tip(kind, radius, half_angle)?;
    let substrate = substrate.inner.clone();
    let states = py
        .detach(
            || -> lc::Result<Vec<(&'static str, lc::analytic::ContactState)>> {
                let modulus = substrate.surface_material().contact_modulus();
                let (_, reach) = tip.pull_off_radii(work_of_adhesion, modulus);
                let exact =
                    lc::analytic::Axisymmetric::up_to_contact_radius_in_range(&substrate, reach)?;
                let states = exact.tip(tip, work_of_adhesion)?;
                let pull = states.pull_off()?;
                let mut out = vec![
                    ("load_control", pull.load_control),
                    ("displacement_control", pull.displacement_control),
                ];
                if let Some(k) = spring {
                    out.push(("spring_pull_off", states.spring_pull_off(k)?));
                    out.push(("spring_jump_in", states.spring_jump_in(k)?));
                }
                Ok(out)
            },
        )
        .py_err()?;
    let d = PyDict::new(py);
    for (name, s) in states {
        let entry = PyDict::new(py);
        entry.set_item("force", s.force)?;
        entry.set_item("depth", s.depth)?;
        entry.set_item("contact_radius", s.contact_radius)?;
        d.set_item(name, entry)?;
    }
    Ok(d)
}

/// Which points of a retract segment (`position`, `force`: 1-D arrays of
/// one length) are still on the sample (`analytic::before_jump_off`).
#[pyfunction]
pub(crate) fn before_jump_off<'py>(
    py: Python<'py>,
    position: PyReadonlyArrayDyn<'py, f64>,
    force: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<bool>>> {
    let n = checked_len("position", position.shape())?;
    if checked_len("force", force.shape())? != n {
        return Err(super::InvalidInputError::new_err(
            "position and force: expected arrays of one length",
        ));
    }
    let position: Vec<f64> = position.as_array().iter().copied().collect();
    let force: Vec<f64> = force.as_array().iter().copied().collect();
    Ok(PyArray1::from_vec(
        py,
        lc::analytic::before_jump_off(&position, &force),
    ))
}

/// The pressure (Pa) at radii `r` (m, any shape) of a tip (as [`tip`]) on
/// `substrate` with work of adhesion `work_of_adhesion` (J/m^2) at the
/// equilibrium of contact radius `contact_radius` (m)
/// (`analytic::LayeredTip::pressure`), and that disc's least pressure over
/// its mean (`LayeredTip::minimum_pressure_ratio`: negative where it pulls
/// on the tip, which without adhesion makes the contact a ring, not the
/// disc).
#[pyfunction]
#[pyo3(signature = (substrate, kind, radius, work_of_adhesion, contact_radius, r, half_angle=f64::NAN))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn tip_pressure<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    kind: &str,
    radius: f64,
    work_of_adhesion: f64,
    contact_radius: f64,
    r: PyReadonlyArrayDyn<'py, f64>,
    half_angle: f64,
) -> PyResult<(Bound<'py, PyArrayDyn<f64>>, f64)> {
    let tip = tip(kind, radius, half_angle)?;
    checked_len("r", r.shape())?;
    let shape = r.shape().to_vec();
    let radii: Vec<f64> = r.as_array().iter().copied().collect();
    let substrate = substrate.inner.clone();
    let (pressures, least) = py
        .detach(|| -> lc::Result<(Vec<f64>, f64)> {
            let exact =
                lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, contact_radius)?;
            let layered = exact.tip(tip, work_of_adhesion)?;
            let pressures = radii
                .iter()
                .map(|&x| layered.pressure(contact_radius, x))
                .collect::<lc::Result<Vec<f64>>>()?;
            Ok((pressures, layered.minimum_pressure_ratio(contact_radius)?))
        })
        .py_err()?;
    Ok((PyArray1::from_vec(py, pressures).reshape(shape)?, least))
}
