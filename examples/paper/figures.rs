//! SVG figures of the `paper` example (plotters, with the DejaVu Sans font
//! embedded so that no system font is needed).

use std::error::Error;
use std::path::Path;

use plotters::prelude::*;
use plotters::style::register_font;

use crate::experiment::{Config, StiffnessRow};
use layered_contact::scene::{Curve, Phase};

type Result<T> = std::result::Result<T, Box<dyn Error + Send + Sync>>;

const FONT: &str = "sans-serif";

fn palette(i: usize) -> RGBColor {
    const COLORS: [RGBColor; 6] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
    ];
    COLORS[i % COLORS.len()]
}

fn register() -> Result<()> {
    register_font(FONT, FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "invalid embedded font")?;
    Ok(())
}

/// Tick labels without a "-0".
fn tick(v: &f64) -> String {
    let rounded = (v * 1e3).round() / 1e3 + 0.0;
    format!("{rounded}")
}

/// The legend box of a chart.
fn legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    size: u32,
    position: SeriesLabelPosition,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    chart
        .configure_series_labels()
        .label_font((FONT, size))
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| e.to_string())?;
    Ok(())
}

/// A panel of force against depth with labelled axes.
fn force_depth_chart<'a, DB: DrawingBackend + 'a>(
    panel: &'a DrawingArea<DB, plotters::coord::Shift>,
    caption: String,
    x: (f64, f64),
    y: (f64, f64),
) -> Result<
    ChartContext<
        'a,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(panel)
        .caption(caption, (FONT, 20))
        .margin(10)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("depth d [mm]")
        .y_desc("force F [N]")
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(|e| e.to_string())?;
    Ok(chart)
}

fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    let pad = 0.05 * (hi - lo).max(1e-12);
    (lo - pad, hi + pad)
}

/// `K/(2aE*)` against `D`: series (solid), exact (dashed), BEM (circles), the
/// point `a = h` of each layer marked by a cross.
pub fn stiffness(path: &Path, rows: &[StiffnessRow], config: &Config) -> Result<()> {
    register()?;
    let root = SVGBackend::new(path, (1000, 720)).into_drawing_area();
    root.fill(&WHITE)?;
    let max_d = rows.iter().map(|r| r.d_mm).fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Flat punch on a rubber layer on glass (E = 0.324 MPa, nu = 0.48)",
            (FONT, 22),
        )
        .margin(15)
        .x_label_area_size(55)
        .y_label_area_size(70)
        .build_cartesian_2d(0f64..max_d, 0.9f64..6.0f64)?;
    chart
        .configure_mesh()
        .x_desc("punch diameter D [mm]")
        .y_desc("stiffness K / (2 a E*)")
        .label_style((FONT, 16))
        .axis_desc_style((FONT, 18))
        .draw()?;
    let mut marked = false;
    for (i, &h) in config.thicknesses_mm.iter().enumerate() {
        let color = palette(i);
        let line: Vec<&StiffnessRow> = rows
            .iter()
            .filter(|r| r.h_mm == h && r.bem.is_none())
            .collect();
        let clip = |v: f64| v.min(6.0);
        chart
            .draw_series(LineSeries::new(
                line.iter().map(|r| (r.d_mm, clip(r.series))),
                color.stroke_width(2),
            ))?
            .label(format!("h = {h} mm: series"))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
            });
        chart
            .draw_series(DashedLineSeries::new(
                line.iter().map(|r| (r.d_mm, clip(r.exact))),
                6,
                4,
                color.stroke_width(2),
            ))?
            .label(format!("h = {h} mm: exact (dashed), BEM (o)"))
            .legend(move |(x, y)| Circle::new((x + 12, y), 4, color.filled()));
        chart.draw_series(rows.iter().filter(|r| r.h_mm == h).filter_map(|r| {
            r.bem
                .map(|b| Circle::new((r.d_mm, clip(b)), 5, color.filled()))
        }))?;
        // The point a = h (D = 2h) on the exact curve, where the series stops being trustworthy.
        if let Some(at_h) = line.iter().find(|r| (r.d_mm - 2.0 * h).abs() < 1e-9) {
            if at_h.exact <= 6.0 {
                let cross = chart.draw_series(std::iter::once(Cross::new(
                    (at_h.d_mm, at_h.exact),
                    7,
                    BLACK.stroke_width(2),
                )))?;
                if !marked {
                    cross
                        .label("a = h (series trustworthy for smaller D)")
                        .legend(|(x, y)| Cross::new((x + 12, y), 6, BLACK.stroke_width(2)));
                    marked = true;
                }
            }
        }
    }
    legend(&mut chart, 14, SeriesLabelPosition::UpperLeft)?;
    root.present()?;
    Ok(())
}

/// Force against depth, one panel per punch diameter, one line per layer.
pub fn punch_curves(path: &Path, curves: &[(f64, f64, Curve)], config: &Config) -> Result<()> {
    register()?;
    let root = SVGBackend::new(path, (1200, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, config.punch_diameters_mm.len().div_ceil(2)));
    for (panel, &d) in panels.iter().zip(&config.punch_diameters_mm) {
        let mine: Vec<&(f64, f64, Curve)> = curves.iter().filter(|c| c.1 == d).collect();
        let (x0, x1) = range(
            mine.iter()
                .flat_map(|c| c.2.steps.iter().map(|s| s.depth * 1e3)),
        );
        let (y0, y1) = range(mine.iter().flat_map(|c| c.2.steps.iter().map(|s| s.force)));
        let mut chart =
            force_depth_chart(panel, format!("flat punch D = {d} mm"), (x0, x1), (y0, y1))?;
        for (i, (h, _, curve)) in mine.iter().enumerate() {
            let color = palette(i);
            for phase in [Phase::Loading, Phase::Unloading] {
                let mut points: Vec<(f64, f64)> = curve
                    .phase(phase)
                    .map(|s| (s.depth * 1e3, s.force))
                    .collect();
                points.sort_by(|a, b| a.0.total_cmp(&b.0));
                let series = chart.draw_series(LineSeries::new(points, color.stroke_width(2)))?;
                if phase == Phase::Loading {
                    series.label(format!("h = {h} mm")).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
                    });
                }
            }
        }
        legend(&mut chart, 13, SeriesLabelPosition::UpperLeft)?;
    }
    root.present()?;
    Ok(())
}

/// Force against depth loops, one column per sphere radius: the whole
/// loop above, the adhesive part (pull-off) enlarged below. Loading solid,
/// unloading dashed; the extra works of adhesion of the thinnest layer in
/// grey (their loading branch is the same as the standard one's).
pub fn sphere_curves(
    path: &Path,
    curves: &[(f64, f64, f64, Curve)],
    config: &Config,
) -> Result<()> {
    register()?;
    let root = SVGBackend::new(path, (1500, 1000)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, config.sphere_radii_mm.len()));
    let columns = config.sphere_radii_mm.len();
    for (column, &r) in config.sphere_radii_mm.iter().enumerate() {
        let mine: Vec<&(f64, f64, f64, Curve)> = curves.iter().filter(|c| c.0 == r).collect();
        let lowest = mine
            .iter()
            .flat_map(|c| c.3.steps.iter().map(|s| s.force))
            .fold(0.0, f64::min);
        let (x0, x1) = range(
            mine.iter()
                .flat_map(|c| c.3.steps.iter().map(|s| s.depth * 1e3)),
        );
        let (y0, y1) = range(mine.iter().flat_map(|c| c.3.steps.iter().map(|s| s.force)));
        let zoom_depth = mine
            .iter()
            .flat_map(|c| {
                c.3.steps
                    .iter()
                    .filter(|s| s.force < -lowest)
                    .map(|s| s.depth * 1e3)
            })
            .fold(x0, f64::max);
        for (row, (x_range, y_range, caption)) in [
            ((x0, x1), (y0, y1), format!("sphere R = {r} mm")),
            (
                (x0, zoom_depth),
                (1.15 * lowest, -lowest),
                format!("sphere R = {r} mm: pull-off"),
            ),
        ]
        .into_iter()
        .enumerate()
        {
            let panel = &panels[row * columns + column];
            let mut chart = force_depth_chart(panel, caption, x_range, y_range)?;
            let mut index = 0;
            for (_, h, dgamma, curve) in &mine {
                let standard = (*dgamma - crate::experiment::DGAMMA_PUNCH).abs() < 1e-12;
                let color = if standard {
                    index += 1;
                    palette(index - 1)
                } else if *dgamma < crate::experiment::DGAMMA_PUNCH {
                    RGBColor(160, 160, 160)
                } else {
                    RGBColor(40, 40, 40)
                };
                let inside = |(x, y): &(f64, f64)| {
                    *x >= x_range.0 && *x <= x_range.1 && *y >= y_range.0 && *y <= y_range.1
                };
                let loading: Vec<(f64, f64)> = curve
                    .phase(Phase::Loading)
                    .map(|s| (s.depth * 1e3, s.force))
                    .filter(inside)
                    .collect();
                let mut unloading: Vec<(f64, f64)> = curve
                    .phase(Phase::Unloading)
                    .map(|s| (s.depth * 1e3, s.force))
                    .filter(inside)
                    .collect();
                unloading.sort_by(|a, b| b.0.total_cmp(&a.0));
                let label = format!("h = {h} mm, dgamma1 = {dgamma} J/m^2");
                if standard {
                    chart.draw_series(LineSeries::new(loading, color.stroke_width(2)))?;
                }
                chart
                    .draw_series(DashedLineSeries::new(
                        unloading,
                        5,
                        3,
                        color.stroke_width(2),
                    ))?
                    .label(label)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
                    });
            }
            legend(
                &mut chart,
                12,
                if row == 0 {
                    SeriesLabelPosition::UpperLeft
                } else {
                    SeriesLabelPosition::LowerRight
                },
            )?;
        }
    }
    root.present()?;
    Ok(())
}
