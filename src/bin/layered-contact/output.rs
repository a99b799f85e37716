//! What `run` writes: the curve as CSV, the fields as `.npy` with their
//! cell-centre coordinates, and an SVG plot of the curve.

use std::path::{Path, PathBuf};

use ndarray::Array1;
use plotters::prelude::*;

use layered_contact::scene::{Curve, Phase, Quantity, Scene};
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
    plot(scene, curve, &svg)?;
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

/// Force against depth, loading solid and unloading dashed, under a title
/// naming the scene; where the scene has exact values
/// ([`Scene::reference`]) they are drawn beside the BEM curve: the exact
/// stiffness as a dotted line through the origin, the exact peak force as a
/// cross at the peak depth and the exact pull-off force as a dotted
/// horizontal line. Axes in SI-prefixed units (`um`, `mN`, ...).
fn plot(scene: &Scene, curve: &Curve, path: &Path) -> Result<()> {
    register_font()?;
    let references = scene.reference().unwrap_or_default();
    let exact = |quantity: Quantity| {
        references
            .iter()
            .find(|r| r.quantity == quantity)
            .map(|r| r.value)
    };
    let peak_depth = curve.phase(Phase::Loading).last().map(|s| s.depth);
    let mut depths: Vec<f64> = curve.steps.iter().map(|s| s.depth).collect();
    let mut forces: Vec<f64> = curve.steps.iter().map(|s| s.force).collect();
    forces.extend(exact(Quantity::PeakForce));
    forces.extend(exact(Quantity::PullOffForce));
    depths.extend(peak_depth);
    let (depth_scale, depth_unit) = si_unit(&depths, "m");
    let (force_scale, force_unit) = si_unit(&forces, "N");
    let depths = range(depths.iter().map(|d| d / depth_scale));
    let forces = range(forces.iter().map(|f| f / force_scale));
    let point = |s: &layered_contact::scene::Step| (s.depth / depth_scale, s.force / force_scale);
    let points = |phase: Phase| -> Vec<(f64, f64)> { curve.phase(phase).map(point).collect() };
    let root = SVGBackend::new(path, (800, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title(scene, curve), (FONT, 16))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(depths.0..depths.1, forces.0..forces.1)
        .map_err(|e| e.to_string())?;
    let (x_span, y_span) = (depths.1 - depths.0, forces.1 - forces.0);
    chart
        .configure_mesh()
        .x_desc(format!("depth d [{depth_unit}]"))
        .y_desc(format!("force F [{force_unit}]"))
        .x_label_formatter(&|v| tick(*v, x_span))
        .y_label_formatter(&|v| tick(*v, y_span))
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
        .label("loading (BEM)")
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
        .label("unloading (BEM)")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], orange.stroke_width(2)));
    chart
        .draw_series(
            curve
                .steps
                .iter()
                .map(|s| Circle::new(point(s), 3, BLACK.filled())),
        )
        .map_err(|e| e.to_string())?;
    let grey = RGBColor(90, 90, 90);
    if let (Some(k), Some(deepest)) = (exact(Quantity::Stiffness), peak_depth) {
        let line = [
            (0.0, 0.0),
            (deepest / depth_scale, k * deepest / force_scale),
        ];
        chart
            .draw_series(DashedLineSeries::new(line, 2, 4, grey.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label("exact stiffness")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], grey.stroke_width(2)));
    }
    if let (Some(force), Some(deepest)) = (exact(Quantity::PeakForce), peak_depth) {
        let at = (deepest / depth_scale, force / force_scale);
        chart
            .draw_series([Cross::new(at, 7, BLACK.stroke_width(2))])
            .map_err(|e| e.to_string())?
            .label("exact peak force")
            .legend(|(x, y)| Cross::new((x + 10, y), 5, BLACK.stroke_width(2)));
    }
    if let Some(force) = exact(Quantity::PullOffForce) {
        let line = [
            (depths.0, force / force_scale),
            (depths.1, force / force_scale),
        ];
        let red = RGBColor(214, 39, 40);
        chart
            .draw_series(DashedLineSeries::new(line, 2, 4, red.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label("exact pull-off force")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], red.stroke_width(2)));
    }
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

/// "flat punch on half space: 7 steps on a 18 x 18 grid" (the scene
/// file's kinds; "custom" for an indenter given in code).
fn title(scene: &Scene, curve: &Curve) -> String {
    let kind = |value: Option<toml::Value>| {
        value
            .as_ref()
            .and_then(|v| v.get("kind"))
            .and_then(|k| k.as_str())
            .map_or("custom".to_string(), |k| k.replace('_', " "))
    };
    format!(
        "{} on {}: {} steps on a {} x {} grid",
        kind(toml::Value::try_from(&scene.indenter).ok()),
        kind(toml::Value::try_from(&scene.substrate).ok()),
        curve.steps.len(),
        curve.grid.rows(),
        curve.grid.columns()
    )
}

/// The power of 1000 that brings the largest of `values` into `[1, 1000)`,
/// and the unit with its SI prefix.
fn si_unit(values: &[f64], unit: &str) -> (f64, String) {
    const PREFIXES: [(i32, &str); 7] = [
        (-5, "f"),
        (-4, "p"),
        (-3, "n"),
        (-2, "u"),
        (-1, "m"),
        (0, ""),
        (1, "k"),
    ];
    let largest = values
        .iter()
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let power = if largest > 0.0 {
        (largest.log10() / 3.0).floor() as i32
    } else {
        0
    };
    let (power, prefix) = PREFIXES
        .iter()
        .copied()
        .find(|&(p, _)| p == power.clamp(-5, 1))
        .unwrap_or((0, ""));
    (1000f64.powi(power), format!("{prefix}{unit}"))
}

/// A tick label with the decimals that tell the ticks apart, the same on
/// every tick of an axis `span` long; zero for
/// values that are zero but for rounding (a millionth of the axis).
fn tick(value: f64, span: f64) -> String {
    if value.abs() <= 1e-6 * span {
        return "0".to_string();
    }
    // Ticks are 1, 2 or 5 times a power of ten, at least a twentieth of the
    // axis apart.
    let digits = (-(span / 20.0).log10().floor()).clamp(0.0, 6.0) as usize;
    format!("{value:.digits$}")
}

/// The range of `values` with 5 % padding (and zero included).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let pad = 0.05 * (hi - lo).max(f64::MIN_POSITIVE);
    (lo - pad, hi + pad)
}
