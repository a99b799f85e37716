//! What `run` writes of the stresses below the surface: each component on
//! every plane as `.npy` (`planes x rows x columns`, `[k, i, j]` at depth
//! `stress_depths.npy[k]` and `x.npy[i]`, `y.npy[j]`), the interface
//! tractions, and an x-z section of the von Mises stress (`section.svg`)
//! with the layer boundaries.

use std::path::{Path, PathBuf};

use ndarray::{Array1, Array3};
use plotters::prelude::*;
use plotters::style::colors::colormaps::ViridisRGB;

use layered_contact::scene::{Curve, SubsurfaceResult};
use layered_contact::stress::{StressPlane, VolumeMaximum};
use layered_contact::Grid;

use crate::output::{register_font, save, FONT};
use crate::Result;

/// `planes x rows x columns` of one field of each plane.
fn stack<'a>(grid: &Grid, fields: impl Iterator<Item = &'a Vec<f64>>) -> Result<Array3<f64>> {
    let flat: Vec<f64> = fields.flatten().copied().collect();
    let planes = flat.len() / grid.len().max(1);
    Ok(Array3::from_shape_vec(
        (planes, grid.rows(), grid.columns()),
        flat,
    )?)
}

/// Writes the stresses of `curve` into `out`; the paths written.
pub fn write(curve: &Curve, out: &Path) -> Result<Vec<PathBuf>> {
    let Some(result) = &curve.stresses else {
        return Ok(Vec::new());
    };
    let grid = &curve.grid;
    let mut written = Vec::new();
    let planes = &result.planes;
    if !planes.is_empty() {
        type Field = fn(&StressPlane) -> &Vec<f64>;
        let components: [(&str, Field); 6] = [
            ("stress_xx.npy", |p| &p.xx),
            ("stress_yy.npy", |p| &p.yy),
            ("stress_zz.npy", |p| &p.zz),
            ("stress_xy.npy", |p| &p.xy),
            ("stress_xz.npy", |p| &p.xz),
            ("stress_yz.npy", |p| &p.yz),
        ];
        for (name, field) in components {
            written.push(save(out, name, &stack(grid, planes.iter().map(field))?)?);
        }
        let von_mises: Vec<Vec<f64>> = planes.iter().map(|p| p.map(|s| s.von_mises())).collect();
        written.push(save(out, "von_mises.npy", &stack(grid, von_mises.iter())?)?);
        let depths = Array1::from_iter(planes.iter().map(|p| p.depth));
        written.push(save(out, "stress_depths.npy", &depths)?);
        if planes.len() >= 2 {
            let path = out.join("section.svg");
            section(grid, planes, &von_mises, &result.boundaries, &path)?;
            written.push(path);
        }
    }
    if !result.interfaces.is_empty() {
        let list = &result.interfaces;
        written.push(save(
            out,
            "interface_normal.npy",
            &stack(grid, list.iter().map(|t| &t.normal))?,
        )?);
        written.push(save(
            out,
            "interface_shear_x.npy",
            &stack(grid, list.iter().map(|t| &t.shear_x))?,
        )?);
        written.push(save(
            out,
            "interface_shear_y.npy",
            &stack(grid, list.iter().map(|t| &t.shear_y))?,
        )?);
        let depths = Array1::from_iter(list.iter().map(|t| t.depth));
        written.push(save(out, "interface_depths.npy", &depths)?);
    }
    Ok(written)
}

/// One line per maximum: value, depth and position.
pub fn summary(grid: &Grid, result: &SubsurfaceResult) -> Vec<String> {
    let line = |name: &str, max: &Option<VolumeMaximum>| {
        max.map(|m| {
            let (x, y) = grid.cell_centre(m.cell / grid.columns(), m.cell % grid.columns());
            format!(
                "{name}: {:.6e} Pa at depth {:.4e} m, x {:.4e} m, y {:.4e} m",
                m.value, m.depth, x, y
            )
        })
    };
    let mut lines: Vec<String> = [
        line("largest von Mises stress", &result.von_mises),
        line("largest shear stress (Tresca)", &result.max_shear),
        line("largest principal stress", &result.tension),
    ]
    .into_iter()
    .flatten()
    .collect();
    for t in &result.interfaces {
        let (shear, k) = t.largest_shear();
        let (x, y) = grid.cell_centre(k / grid.columns(), k % grid.columns());
        lines.push(format!(
            "interface at {:.4e} m: largest shear traction {shear:.6e} Pa at x {x:.4e} m, y {y:.4e} m",
            t.depth
        ));
    }
    lines
}

/// The von Mises stress on the x-z section through the grid's middle
/// column, with the interfaces as white lines.
fn section(
    grid: &Grid,
    planes: &[StressPlane],
    von_mises: &[Vec<f64>],
    interfaces: &[f64],
    path: &Path,
) -> Result<()> {
    register_font()?;
    let j = grid.columns() / 2;
    let xs: Vec<f64> = (0..grid.rows()).map(|i| grid.cell_centre(i, j).0).collect();
    let depths: Vec<f64> = planes.iter().map(|p| p.depth).collect();
    let value = |k: usize, i: usize| von_mises[k][i * grid.columns() + j];
    let top = von_mises
        .iter()
        .flat_map(|v| v.iter().copied())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let deepest = depths.last().copied().unwrap_or(0.0);
    let half = 0.5 * grid.spacing();
    let root = SVGBackend::new(path, (860, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("von Mises stress on the x-z section (0 to {top:.3e} Pa)"),
            (FONT, 17),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d((xs[0] - half)..(xs[xs.len() - 1] + half), deepest..0.0)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("x [m]")
        .y_desc("depth z [m]")
        .x_label_formatter(&|v| format!("{v:.2e}"))
        .y_label_formatter(&|v| format!("{v:.2e}"))
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .draw()
        .map_err(|e| e.to_string())?;
    // Each sample fills the band halfway to its neighbours.
    let bands: Vec<(f64, f64)> = (0..depths.len())
        .map(|k| {
            let above = if k == 0 {
                depths[0]
            } else {
                0.5 * (depths[k - 1] + depths[k])
            };
            let below = if k + 1 == depths.len() {
                depths[k]
            } else {
                0.5 * (depths[k] + depths[k + 1])
            };
            (above, below)
        })
        .collect();
    chart
        .draw_series((0..depths.len()).flat_map(|k| {
            let (above, below) = bands[k];
            let xs = &xs;
            (0..xs.len()).map(move |i| {
                let colour = ViridisRGB::get_color_normalized(value(k, i), 0.0, top);
                Rectangle::new(
                    [(xs[i] - half, above), (xs[i] + half, below)],
                    colour.filled(),
                )
            })
        }))
        .map_err(|e| e.to_string())?;
    for &depth in interfaces.iter().filter(|d| **d <= deepest) {
        chart
            .draw_series(LineSeries::new(
                [(xs[0] - half, depth), (xs[xs.len() - 1] + half, depth)],
                WHITE.stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
    }
    root.present().map_err(|e| e.to_string())?;
    Ok(())
}
