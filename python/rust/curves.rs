//! Bindings for fitting measured curves: the non-adhesive states of the
//! exact paraboloid and the flat punch's stiffness and edge factor at the
//! same contact radii, from which the JKR curve follows for any work of
//! adhesion (and, on a rigid support, any modulus) without solving again.

use numpy::{PyArray1, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

use layered_contact as lc;

use super::{checked_len, OrPy, Substrate};

/// For a paraboloid of tip radius `radius` (m) on `substrate`, at each
/// contact radius of `contact_radius` (m): the non-adhesive depth `d0` (m)
/// and force `f0` (N), the flat punch's stiffness `k` (N/m) and edge factor
/// `psi1` (the rim's stress intensity relative to the half-space punch's).
/// With a work of adhesion `w` the JKR state at that radius is
/// `d = d0 - sqrt(2 pi a w / E1*) / psi1`, `F = f0 + k (d - d0)`.
#[pyfunction]
pub(crate) fn paraboloid_terms<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    radius: f64,
    contact_radius: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<[Bound<'py, PyArray1<f64>>; 4]> {
    checked_len("contact_radius", contact_radius.shape())?;
    let radii: Vec<f64> = contact_radius.as_array().iter().copied().collect();
    let largest = radii.iter().copied().fold(0.0f64, f64::max);
    let substrate = substrate.inner.clone();
    let rows = py
        .detach(|| -> lc::Result<Vec<[f64; 4]>> {
            let exact = lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, largest)?;
            let ball = exact.paraboloid(radius, 0.0)?;
            radii
                .iter()
                .map(|&a| {
                    let state = ball.at_contact_radius(a)?;
                    let punch = exact.flat_punch(a)?;
                    Ok([
                        state.depth,
                        state.force,
                        punch.stiffness(),
                        punch.edge_factor(),
                    ])
                })
                .collect()
        })
        .py_err()?;
    Ok(std::array::from_fn(|k| {
        PyArray1::from_vec(py, rows.iter().map(|r| r[k]).collect())
    }))
}
