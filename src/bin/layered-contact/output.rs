//! What `run` writes: the curve as CSV, the fields as `.npy` with their
//! cell-centre coordinates, and an SVG plot of the curve.

use std::path::{Path, PathBuf};

use ndarray::Array1;
use plotters::prelude::*;

use layered_contact::scene::{Curve, Phase, Scene};
use layered_contact::Grid;

use crate::Result;

/// Writes every output of `curve` into `out`; the paths written.
pub fn write_all(scene: &Scene, curve: &Curve, out: &Path) -> Result<Vec<PathBuf>> {
    let mut written = vec![write_csv(curve, &out.join("curve.csv"))?];
    let fields = write_fields(scene, curve, out)?;
    let stresses = crate::stress_output::write(curve, out)?;
    if fields.is_empty() && !stresses.is_empty() {
        written.extend(write_coordinates(&curve.grid, out)?);
    }
    written.extend(fields);
    written.extend(stresses);
    let svg = out.join("curve.svg");
    plot(curve, &svg)?;
    written.push(svg);
    Ok(written)
}

/// `phase,depth_m,force_N,contact_area_m2,contact_radius_m,iterations`.
fn write_csv(curve: &Curve, path: &Path) -> Result<PathBuf> {
    let mut writer = csv::Writer::from_path(path)?;
    writer.write_record([
        "phase",
        "depth_m",
        "force_N",
        "contact_area_m2",
        "contact_radius_m",
        "iterations",
    ])?;
    for s in &curve.steps {
        writer.write_record([
            s.phase.name().to_string(),
            format!("{:e}", s.depth),
            format!("{:e}", s.force),
            format!("{:e}", s.contact_area),
            format!("{:e}", s.contact_radius),
            s.iterations.to_string(),
        ])?;
    }
    writer.flush()?;
    Ok(path.to_path_buf())
}

/// Writes `array` to `out/name` as `.npy`; its path.
pub fn save<D: ndarray::Dimension>(
    out: &Path,
    name: &str,
    array: &ndarray::Array<f64, D>,
) -> Result<PathBuf> {
    let path = out.join(name);
    ndarray_npy::write_npy(&path, array)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(path)
}

/// The fields the scene asked for, at its most loaded step: `pressure.npy`
/// (Pa), `displacement.npy` and `gap.npy` (m), each `rows x columns` with
/// `[i, j]` at `x.npy[i]`, `y.npy[j]` (the cell centres, m from the
/// indenter's axis; [`Grid::cell_centre`]).
fn write_fields(scene: &Scene, curve: &Curve, out: &Path) -> Result<Vec<PathBuf>> {
    let fields = scene.outputs.fields;
    if !(fields.pressure || fields.displacement || fields.gap) {
        return Ok(Vec::new());
    }
    let Some(peak) = &curve.peak else {
        return Err("the scene asked for fields but none were kept".into());
    };
    let mut written = Vec::new();
    for (name, field) in [
        ("pressure.npy", &peak.pressure),
        ("displacement.npy", &peak.displacement),
        ("gap.npy", &peak.gap),
    ] {
        if let Some(array) = field {
            written.push(save(out, name, array)?);
        }
    }
    written.extend(write_coordinates(&curve.grid, out)?);
    Ok(written)
}

/// `x.npy` and `y.npy`: the cell centres along the rows and the columns,
/// m from the indenter's axis.
pub fn write_coordinates(grid: &Grid, out: &Path) -> Result<Vec<PathBuf>> {
    let x = Array1::from_iter((0..grid.rows()).map(|i| grid.cell_centre(i, 0).0));
    let y = Array1::from_iter((0..grid.columns()).map(|j| grid.cell_centre(0, j).1));
    Ok(vec![save(out, "x.npy", &x)?, save(out, "y.npy", &y)?])
}

/// The family name of the embedded font the figures use.
pub const FONT: &str = "sans-serif";

/// Registers the embedded font under [`FONT`] (the SVGs carry their text
/// in it, whatever the machine has installed).
pub fn register_font() -> Result<()> {
    plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "invalid embedded font")?;
    Ok(())
}

/// Force against depth, loading solid and unloading dashed.
fn plot(curve: &Curve, path: &Path) -> Result<()> {
    register_font()?;
    let points = |phase: Phase| -> Vec<(f64, f64)> {
        curve.phase(phase).map(|s| (s.depth, s.force)).collect()
    };
    let depths = range(curve.steps.iter().map(|s| s.depth));
    let forces = range(curve.steps.iter().map(|s| s.force));
    let root = SVGBackend::new(path, (800, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let mut chart = ChartBuilder::on(&root)
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(depths.0..depths.1, forces.0..forces.1)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("depth d [m]")
        .y_desc("force F [N]")
        .x_label_formatter(&|v| format!("{v:.2e}"))
        .y_label_formatter(&|v| format!("{v:.2e}"))
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .draw()
        .map_err(|e| e.to_string())?;
    let blue = RGBColor(31, 119, 180);
    chart
        .draw_series(LineSeries::new(
            points(Phase::Loading),
            blue.stroke_width(2),
        ))
        .map_err(|e| e.to_string())?
        .label("loading")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], blue.stroke_width(2)));
    let orange = RGBColor(255, 127, 14);
    chart
        .draw_series(DashedLineSeries::new(
            points(Phase::Unloading),
            6,
            4,
            orange.stroke_width(2),
        ))
        .map_err(|e| e.to_string())?
        .label("unloading")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], orange.stroke_width(2)));
    chart
        .draw_series(
            curve
                .steps
                .iter()
                .map(|s| Circle::new((s.depth, s.force), 3, BLACK.filled())),
        )
        .map_err(|e| e.to_string())?;
    chart
        .configure_series_labels()
        .label_font((FONT, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| e.to_string())?;
    root.present().map_err(|e| e.to_string())?;
    Ok(())
}

/// The range of `values` with 5 % padding (and zero included).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let pad = 0.05 * (hi - lo).max(f64::MIN_POSITIVE);
    (lo - pad, hi + pad)
}
