//! Bindings for fitting measured curves: the non-adhesive states of an
//! exact axisymmetric tip and the flat punch's stiffness and edge factor at
//! the same contact radii, from which the JKR curve follows for any work of
//! adhesion (and, on a rigid support, any modulus) without solving again;
//! pull-offs and jump-ins under a cantilever.

use numpy::{PyArray1, PyReadonlyArrayDyn, PyUntypedArrayMethods};
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

/// For a tip on `substrate`, at each contact radius of `contact_radius`
/// (m): the non-adhesive depth `d0` (m) and force `f0` (N), the flat
/// punch's stiffness `k` (N/m) and edge factor `psi1` (the rim's stress
/// intensity relative to the half-space punch's). With a work of adhesion
/// `w` the JKR state at that radius is `d = d0 - sqrt(2 pi a w / E1*) /
/// psi1`, `F = f0 + k (d - d0)`.
#[pyfunction]
#[pyo3(signature = (substrate, kind, radius, contact_radius, half_angle=f64::NAN))]
pub(crate) fn tip_terms<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    kind: &str,
    radius: f64,
    contact_radius: PyReadonlyArrayDyn<'py, f64>,
    half_angle: f64,
) -> PyResult<[Bound<'py, PyArray1<f64>>; 4]> {
    checked_len("contact_radius", contact_radius.shape())?;
    let tip = tip(kind, radius, half_angle)?;
    let radii: Vec<f64> = contact_radius.as_array().iter().copied().collect();
    let largest = radii.iter().copied().fold(0.0f64, f64::max);
    let substrate = substrate.inner.clone();
    let rows = py
        .detach(|| -> lc::Result<Vec<[f64; 4]>> {
            let exact = lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, largest)?;
            let states = exact.tip(tip, 0.0)?;
            // The paraboloid has its own, faster, solution.
            let ball = match tip {
                lc::analytic::Tip::Paraboloid { radius } => Some(exact.paraboloid(radius, 0.0)?),
                _ => None,
            };
            radii
                .iter()
                .map(|&a| {
                    let state = match &ball {
                        Some(ball) => ball.at_contact_radius(a)?,
                        None => states.at_contact_radius(a)?,
                    };
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

/// The pull-offs of a tip (as [`tip_terms`]) with work of adhesion
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
                // At most the exact solution's range; the search stays inside it.
                let most = substrate.top_thickness().map_or(f64::INFINITY, |h| {
                    h * lc::analytic::Axisymmetric::MAX_RADIUS_OVER_THICKNESS
                });
                let exact =
                    lc::analytic::Axisymmetric::up_to_contact_radius(&substrate, reach.min(most))?;
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
