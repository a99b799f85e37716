//! Bindings of the stresses below the surface (`layered_contact::stress`
//! and a scene's `Curve::stresses`): dicts of NumPy arrays.

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use layered_contact as lc;
use lc::scene::SubsurfaceResult;
use lc::stress::{StressPlane, VolumeMaximum};

use super::{centres, OrPy, Substrate};

/// `planes x rows x columns` of one field of each plane.
fn stack<'py>(
    py: Python<'py>,
    grid: &lc::Grid,
    fields: impl Iterator<Item = Vec<f64>>,
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<f64> = fields.flatten().collect();
    let planes = flat.len() / grid.len().max(1);
    Ok(PyArray1::from_vec(py, flat)
        .reshape([planes, grid.rows(), grid.columns()])?
        .into_any())
}

fn maximum<'py>(
    py: Python<'py>,
    grid: &lc::Grid,
    max: Option<VolumeMaximum>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    max.map(|m| {
        let d = PyDict::new(py);
        let (i, j) = (m.cell / grid.columns(), m.cell % grid.columns());
        let (x, y) = grid.cell_centre(i, j);
        d.set_item("value", m.value)?;
        d.set_item("depth", m.depth)?;
        d.set_item("x", x)?;
        d.set_item("y", y)?;
        d.set_item("row", i)?;
        d.set_item("column", j)?;
        Ok(d)
    })
    .transpose()
}

/// The dict of `planes` (and `interfaces`) on `grid`: `depth` (m),
/// `xx` ... `yz`, `von_mises`, `max_shear`, `hydrostatic`, the principal
/// stresses `principal_max`, `principal_mid`, `principal_min` (Pa, `planes
/// x rows x columns`), `x`, `y` (m), `boundaries` (the layers' bottoms, m),
/// `interfaces` (a dict of `depth`, `normal`, `shear_x`, `shear_y`) and the
/// maxima over the planes (`max_von_mises`, `max_shear_stress`,
/// `max_principal`: dicts of `value`, `depth`, `x`, `y`, `row`, `column`).
pub(crate) fn stresses_dict<'py>(
    py: Python<'py>,
    grid: &lc::Grid,
    result: &SubsurfaceResult,
) -> PyResult<Bound<'py, PyDict>> {
    let (planes, interfaces) = (&result.planes, &result.interfaces);
    let d = PyDict::new(py);
    d.set_item(
        "depth",
        PyArray1::from_vec(py, planes.iter().map(|p| p.depth).collect()),
    )?;
    type Field = fn(&StressPlane) -> Vec<f64>;
    let fields: [(&str, Field); 12] = [
        ("xx", |p| p.xx.clone()),
        ("yy", |p| p.yy.clone()),
        ("zz", |p| p.zz.clone()),
        ("xy", |p| p.xy.clone()),
        ("xz", |p| p.xz.clone()),
        ("yz", |p| p.yz.clone()),
        ("von_mises", |p| p.map(|s| s.von_mises())),
        ("max_shear", |p| p.map(|s| s.max_shear())),
        ("hydrostatic", |p| p.map(|s| s.hydrostatic())),
        ("principal_max", |p| p.map(|s| s.principal()[0])),
        ("principal_mid", |p| p.map(|s| s.principal()[1])),
        ("principal_min", |p| p.map(|s| s.principal()[2])),
    ];
    for (name, field) in fields {
        d.set_item(name, stack(py, grid, planes.iter().map(field))?)?;
    }
    let (x, y) = centres(py, grid);
    d.set_item("x", x)?;
    d.set_item("y", y)?;
    d.set_item("boundaries", result.boundaries.clone())?;
    let t = PyDict::new(py);
    t.set_item(
        "depth",
        PyArray1::from_vec(py, interfaces.iter().map(|i| i.depth).collect()),
    )?;
    t.set_item(
        "normal",
        stack(py, grid, interfaces.iter().map(|i| i.normal.clone()))?,
    )?;
    t.set_item(
        "shear_x",
        stack(py, grid, interfaces.iter().map(|i| i.shear_x.clone()))?,
    )?;
    t.set_item(
        "shear_y",
        stack(py, grid, interfaces.iter().map(|i| i.shear_y.clone()))?,
    )?;
    d.set_item("interfaces", t)?;
    d.set_item("max_von_mises", maximum(py, grid, result.von_mises)?)?;
    d.set_item("max_shear_stress", maximum(py, grid, result.max_shear)?)?;
    d.set_item("max_principal", maximum(py, grid, result.tension)?)?;
    Ok(d)
}

/// The stresses below the surface of `substrate` under `pressure` (Pa, a
/// `rows x columns` array on square cells of side `spacing`, m, centred on
/// the axis) on planes at `depths` (m): a dict as `Curve.stresses` (see
/// `stresses_dict`). `periodic` for one period of a periodic surface;
/// otherwise the grid is isolated and zero-padded `padding` times (2 by
/// default; the periodic images' field is taken out). `side` picks the
/// layer above (`"above"`) or below (`"below"`) at an interface's depth;
/// `interfaces` adds the tractions on every interface.
#[pyfunction]
#[pyo3(signature = (substrate, pressure, spacing, depths, periodic=false, padding=None, side="below", interfaces=false))]
#[allow(clippy::too_many_arguments)] // Python keyword arguments
pub(crate) fn subsurface_stress<'py>(
    py: Python<'py>,
    substrate: &Substrate,
    pressure: PyReadonlyArray2<'py, f64>,
    spacing: f64,
    depths: Vec<f64>,
    periodic: bool,
    padding: Option<usize>,
    side: &str,
    interfaces: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let shape = pressure.shape();
    let grid = lc::Grid::new(shape[0], shape[1], spacing).py_err()?;
    let values: Vec<f64> = pressure.as_array().iter().copied().collect();
    let side = match side {
        "above" => lc::stress::Side::Above,
        "below" => lc::stress::Side::Below,
        other => {
            return Err(super::InvalidInputError::new_err(format!(
                "side {other:?}: expected \"above\" or \"below\""
            )))
        }
    };
    let boundary = if periodic {
        lc::Boundary::Periodic
    } else {
        lc::Boundary::Isolated
    };
    let padding = padding.unwrap_or(lc::stress::default_padding(boundary));
    let body = substrate.inner.clone();
    let result = py
        .detach(|| -> lc::Result<_> {
            let mut stress =
                lc::stress::SubsurfaceStress::with_padding(&body, &grid, boundary, padding)?;
            let planes = stress.planes(&values, &depths, side)?;
            let tractions = if interfaces {
                stress.interfaces(&values)?
            } else {
                Vec::new()
            };
            Ok(SubsurfaceResult::new(
                planes,
                tractions,
                stress.interface_depths(),
            ))
        })
        .py_err()?;
    stresses_dict(py, &grid, &result)
}
