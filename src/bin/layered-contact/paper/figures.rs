//! SVG figures of the `paper` example (plotters, with the DejaVu Sans font
//! embedded so that no system font is needed).

use std::error::Error;
use std::path::Path;

use plotters::prelude::*;
use plotters::style::register_font;

use super::experiment::{Config, StiffnessRow};
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

/// One force-depth curve with its exact pull-off `(depth m, force N)`.
pub struct Run<'a> {
    /// Line label.
    pub label: String,
    /// Which panel (punch diameter or sphere radius, mm).
    pub panel: f64,
    /// Colour.
    pub color: RGBColor,
    /// Whether to draw the loading branch (the extra works of adhesion of
    /// the spheres share the standard one's).
    pub loading: bool,
    pub curve: &'a Curve,
    pub exact: (f64, f64),
}

/// The colour of layer `index`, or grey / black for the extra works of
/// adhesion below / above the standard one.
pub fn run_color(index: usize, dgamma: f64) -> RGBColor {
    let standard = (dgamma - super::experiment::DGAMMA_PUNCH).abs() < 1e-12;
    if standard {
        palette(index)
    } else if dgamma < super::experiment::DGAMMA_PUNCH {
        RGBColor(150, 150, 150)
    } else {
        RGBColor(40, 40, 40)
    }
}

/// The last state in contact on the unloading branch: where the contact
/// comes off.
fn detachment(curve: &Curve) -> Option<(f64, f64)> {
    curve
        .phase(Phase::Unloading)
        .filter(|s| s.contact_area > 0.0)
        .last()
        .map(|s| (s.depth * 1e3, s.force))
}

/// Draws one run: loading solid, unloading dashed in the order computed
/// (starting at the peak, so the loop closes), a triangle where unloading
/// starts, the jump off the surface as a dotted vertical line down to zero
/// force, the BEM pull-off (least force) as a dot and the exact one as a
/// ring around it.
fn draw_run<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<
        'a,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    run: &Run,
    window: ((f64, f64), (f64, f64)),
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let ((x0, x1), (y0, y1)) = window;
    let inside = |&(x, y): &(f64, f64)| x >= x0 && x <= x1 && y >= y0 && y <= y1;
    let color = run.color;
    let points = |phase: Phase| -> Vec<(f64, f64)> {
        run.curve
            .phase(phase)
            .filter(|s| phase == Phase::Loading || s.contact_area > 0.0)
            .map(|s| (s.depth * 1e3, s.force))
            .filter(inside)
            .collect()
    };
    if run.loading {
        chart.draw_series(LineSeries::new(
            points(Phase::Loading),
            color.stroke_width(2),
        ))?;
    }
    chart.draw_series(DashedLineSeries::new(
        points(Phase::Unloading),
        6,
        4,
        color.stroke_width(2),
    ))?;
    if run.loading {
        if let Some(peak) = run.curve.phase(Phase::Unloading).next() {
            let p = (peak.depth * 1e3, peak.force);
            if inside(&p) {
                chart.draw_series(std::iter::once(TriangleMarker::new(p, 7, color.filled())))?;
            }
        }
    }
    if let Some((d, f)) = detachment(run.curve) {
        let jump = [(d, f.max(y0)), (d, 0.0f64.min(y1))];
        chart.draw_series(DashedLineSeries::new(jump, 2, 3, color.stroke_width(1)))?;
    }
    // The exact pull-off as a ring in the run's colour, the BEM's as a dot
    // drawn over it: within a few tenths of a per cent the dot sits inside
    // the ring, and both stay visible (a black cross hid the dots and did
    // not tell the runs apart).
    let exact = (run.exact.0 * 1e3, run.exact.1);
    if inside(&exact) {
        chart.draw_series(std::iter::once(Circle::new(
            exact,
            9,
            color.stroke_width(2),
        )))?;
    }
    if let Some(p) = run.curve.pull_off() {
        let p = (p.depth * 1e3, p.force);
        if inside(&p) {
            chart.draw_series(std::iter::once(Circle::new(p, 4, color.filled())))?;
        }
    }
    Ok(())
}

/// A legend strip: coloured lines for the runs, then the symbols.
fn legend_strip<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    entries: &[(String, RGBColor)],
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let font = (FONT, 15).into_font();
    let (width, _) = area.dim_in_pixel();
    let per_row = 4usize;
    let column = (width as i32 - 40) / per_row as i32;
    for (k, (text, color)) in entries.iter().enumerate() {
        let x = 20 + (k % per_row) as i32 * column;
        let y = 14 + (k / per_row) as i32 * 22;
        area.draw(&PathElement::new(
            vec![(x, y), (x + 26, y)],
            color.stroke_width(3),
        ))
        .map_err(|e| e.to_string())?;
        area.draw(&Text::new(text.clone(), (x + 34, y - 8), font.clone()))
            .map_err(|e| e.to_string())?;
    }
    let y = 14 + entries.len().div_ceil(per_row) as i32 * 22;
    let symbols = "solid: loading (dgamma0 = 0.0175 J/m^2)  |  dashed: unloading (dgamma1)  |  \
                   triangle: unloading starts  |  dotted vertical: jump off the surface  |  \
                   dot: BEM pull-off (least force)  |  ring: exact pull-off";
    area.draw(&Text::new(symbols, (20, y - 6), font))
        .map_err(|e| e.to_string())?;
    Ok(())
}

/// Force against depth, one panel per punch diameter, one line per layer.
pub fn punch_curves(path: &Path, runs: &[Run], config: &Config) -> Result<()> {
    register()?;
    let root = SVGBackend::new(path, (1300, 1000)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(900);
    let panels = top.split_evenly((2, config.punch_diameters_mm.len().div_ceil(2)));
    for (panel, &d) in panels.iter().zip(&config.punch_diameters_mm) {
        let mine: Vec<&Run> = runs.iter().filter(|r| r.panel == d).collect();
        let x = range(mine.iter().flat_map(|r| {
            r.curve
                .steps
                .iter()
                .map(|s| s.depth * 1e3)
                .chain([r.exact.0 * 1e3])
        }));
        let y = range(
            mine.iter()
                .flat_map(|r| r.curve.steps.iter().map(|s| s.force).chain([r.exact.1])),
        );
        let mut chart = force_depth_chart(panel, format!("flat punch D = {d} mm"), x, y)?;
        for run in &mine {
            draw_run(&mut chart, run, (x, y))?;
        }
    }
    let mut entries: Vec<(String, RGBColor)> = Vec::new();
    for run in runs {
        if !entries.iter().any(|(l, _)| *l == run.label) {
            entries.push((run.label.clone(), run.color));
        }
    }
    legend_strip(&bottom, &entries)?;
    root.present()?;
    Ok(())
}

/// Force against depth loops, one column per sphere radius: the whole
/// loop above, the adhesive part (pull-off) enlarged below; the extra works
/// of adhesion of the thinnest layer in grey and black (their loading branch
/// is the standard one's). The legend sits below the panels, clear of the
/// curves.
pub fn sphere_curves(path: &Path, runs: &[Run], config: &Config) -> Result<()> {
    register()?;
    let root = SVGBackend::new(path, (1500, 1100)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(980);
    let panels = top.split_evenly((2, config.sphere_radii_mm.len()));
    let columns = config.sphere_radii_mm.len();
    for (column, &r) in config.sphere_radii_mm.iter().enumerate() {
        let mine: Vec<&Run> = runs.iter().filter(|run| run.panel == r).collect();
        let forces = || {
            mine.iter()
                .flat_map(|run| run.curve.steps.iter().map(|s| s.force).chain([run.exact.1]))
        };
        let lowest = forces().fold(0.0, f64::min);
        let x = range(
            mine.iter()
                .flat_map(|run| run.curve.steps.iter().map(|s| s.depth * 1e3)),
        );
        let y = range(forces());
        let zoom_depth = mine
            .iter()
            .flat_map(|run| {
                run.curve
                    .steps
                    .iter()
                    .filter(|s| s.force < -0.3 * lowest)
                    .map(|s| s.depth * 1e3)
            })
            .fold(x.0, f64::max);
        for (row, (window, caption)) in [
            ((x, y), format!("sphere R = {r} mm")),
            (
                ((x.0, zoom_depth), (1.1 * lowest, -0.3 * lowest)),
                format!("sphere R = {r} mm: pull-off"),
            ),
        ]
        .into_iter()
        .enumerate()
        {
            let panel = &panels[row * columns + column];
            let mut chart = force_depth_chart(panel, caption, window.0, window.1)?;
            for run in &mine {
                draw_run(&mut chart, run, window)?;
            }
        }
    }
    let mut entries: Vec<(String, RGBColor)> = Vec::new();
    for run in runs {
        if !entries.iter().any(|(l, _)| *l == run.label) {
            entries.push((run.label.clone(), run.color));
        }
    }
    legend_strip(&bottom, &entries)?;
    root.present()?;
    Ok(())
}
