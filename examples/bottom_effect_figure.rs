//! The figure of `doc::bottom_effect`: the exact force of a paraboloid on
//! an incompressible layer bonded to glass, relative to Hertz's, against
//! `chi = sqrt(R d)/h`, with the exact fourth-order series and the series
//! of Dimitriadis et al. (2002) and Garcia & Garcia (2018). Writes `src/doc/bottom_effect.svg`, which
//! the guide page includes.
//!
//! ```sh
//! cargo run --release --example bottom_effect_figure
//! ```

use plotters::prelude::*;
use plotters::style::FontStyle;

use layered_contact::analytic::{
    truncated_series, Axisymmetric, ParaboloidForceSeries, DIMITRIADIS_BONDED, GARCIA_PARABOLOID,
};
use layered_contact::{Material, Substrate};

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

fn main() -> Result<()> {
    let h = 1e-5;
    let substrate = Substrate::layer_on_rigid_base(Material::new(1e6, 0.5)?, h)?;
    let estar = substrate.surface_material().contact_modulus();
    let exact = Axisymmetric::new(&substrate, 3.0)?;
    let ball = exact.paraboloid(h, 0.0)?;
    // (chi, exact ratio) along the contact radius, R = h.
    let mut points = Vec::new();
    for k in 1..=240 {
        let a = 1.5 * h * k as f64 / 240.0;
        let s = ball.at_contact_radius(a)?;
        let hertz = 4.0 / 3.0 * estar * h.sqrt() * s.depth.powf(1.5);
        points.push(((h * s.depth).sqrt() / h, s.force / hertz));
    }
    let series = ParaboloidForceSeries::new(0.5)?.coefficients();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/doc/bottom_effect.svg");
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "invalid font")?;
    let root = SVGBackend::new(&path, (720, 460)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Paraboloid on an incompressible layer on glass: force over Hertz's",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..1.0, 0.8..5.0)?;
    chart
        .configure_mesh()
        .x_desc("chi = sqrt(R d) / h")
        .y_desc("F / F_Hertz")
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .draw()?;
    let within = |p: &&(f64, f64)| p.0 <= 1.0;
    chart
        .draw_series(LineSeries::new(
            points.iter().filter(within).copied(),
            BLACK.stroke_width(2),
        ))?
        .label("exact (layered-contact)")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    let curves: [(&str, Option<&[f64; 4]>, RGBColor); 4] = [
        ("exact series, 4th order", Some(&series), BLUE),
        ("Dimitriadis et al. (2002)", Some(&DIMITRIADIS_BONDED), RED),
        (
            "Garcia & Garcia (2018)",
            Some(&GARCIA_PARABOLOID),
            RGBColor(0, 150, 70),
        ),
        ("Hertz", None, RGBColor(120, 120, 120)),
    ];
    for (name, c, color) in curves {
        chart
            .draw_series(LineSeries::new(
                points
                    .iter()
                    .filter(within)
                    .map(|&(chi, _)| (chi, c.map_or(1.0, |c| truncated_series(c, chi))))
                    .take_while(|&(_, ratio)| ratio <= 5.0),
                color.stroke_width(2),
            ))?
            .label(name)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    eprintln!("wrote {}", path.display());
    Ok(())
}
