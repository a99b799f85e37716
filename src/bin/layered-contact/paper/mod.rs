//! Reproduces the simulations and analytics of Lyashenko, Popov & Borysiuk
//! (2023, Lubricants 11, 84): a rubber layer (`E = 0.324 MPa`, `nu = 0.48`) on
//! glass, `h = 5 .. 25 mm`, probed by flat punches and spheres.
//!
//! ```text
//! layered-contact paper [--out DIR] [--fine]
//! cargo run --release --example paper -- [--out DIR] [--fine]
//! ```
//!
//! Writes to `DIR` (default `target/paper`):
//! * `stiffness.csv` (`h_mm,D_mm,eps,series,exact,bem`) and `stiffness.svg`;
//! * `flat_punch_curves.csv` (`h_mm,D_mm,phase,depth_m,force_N,contact_area_m2`)
//!   and `flat_punch_curves.svg`;
//! * `sphere_curves.csv` (`R_mm,h_mm,dgamma1,phase,depth_m,force_N,contact_radius_m`)
//!   and `sphere_curves.svg`;
//!
//! and prints a summary. `--fine` doubles the resolution.

mod experiment;
mod figures;

use std::error::Error as StdError;
use std::path::Path;

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

use experiment::{Config, StiffnessRow};
use layered_contact::analytic::PunchStiffnessSeries;
use layered_contact::scene::Curve;

pub type Result<T> = std::result::Result<T, Box<dyn StdError + Send + Sync>>;

/// Runs the reproduction into `out` (`fine`: twice the resolution), with a
/// progress bar on standard error and the summary on standard output.
pub fn run(out: &Path, fine: bool) -> Result<()> {
    let config = if fine {
        Config::fine()
    } else {
        Config::standard()
    };
    let out = out.to_path_buf();
    std::fs::create_dir_all(&out)?;
    let started = std::time::Instant::now();

    let punch_jobs: Vec<(f64, f64)> = config
        .thicknesses_mm
        .iter()
        .flat_map(|&h| config.punch_diameters_mm.iter().map(move |&d| (h, d)))
        .collect();
    let sphere_jobs = config.sphere_runs();
    let total = config.thicknesses_mm.len() * config.stiffness_diameters_mm.len()
        + punch_jobs.len()
        + sphere_jobs.len();
    let bar = ProgressBar::new(total as u64);
    bar.set_style(ProgressStyle::with_template(
        "{elapsed_precise} [{bar:40}] {pos}/{len} {msg}",
    )?);

    bar.set_message("stiffness");
    let tick = || bar.inc(1);
    let stiffness = experiment::stiffness_rows(&config, &tick)?;

    bar.set_message("flat punches");
    let punch_curves: Vec<PunchRun> = punch_jobs
        .par_iter()
        .map(|&(h, d)| -> Result<PunchRun> {
            let curve =
                experiment::punch_scene(h, d, config.punch_depth, config.steps).run(&mut |_| {})?;
            let exact = experiment::exact_punch_pull_off_point(h, d, experiment::DGAMMA_PUNCH)?;
            let loading_error = experiment::punch_loading_error(h, d, &curve)?;
            bar.inc(1);
            Ok(PunchRun {
                h,
                d,
                curve,
                exact,
                loading_error,
            })
        })
        .collect::<Result<_>>()?;

    bar.set_message("spheres");
    let sphere_curves: Vec<SphereRun> = sphere_jobs
        .par_iter()
        .map(|&(r, h, dgamma)| -> Result<SphereRun> {
            let scene = experiment::sphere_scene(
                r,
                h,
                dgamma,
                config.sphere_depth,
                config.steps,
                config.cells_across_sphere,
            );
            let curve = scene.run(&mut |_| {})?;
            let exact = experiment::exact_sphere_pull_off_point(r, h, dgamma)?;
            let loading_error =
                experiment::sphere_loading_error(r, h, dgamma, config.sphere_depth, &curve)?;
            bar.inc(1);
            Ok(SphereRun {
                r,
                h,
                dgamma,
                curve,
                exact,
                loading_error,
            })
        })
        .collect::<Result<_>>()?;
    bar.finish_with_message("done");

    write_stiffness(&out, &stiffness)?;
    write_punch_curves(&out, &punch_curves)?;
    write_sphere_curves(&out, &sphere_curves)?;
    figures::stiffness(&out.join("stiffness.svg"), &stiffness, &config)?;
    let index = |values: &[f64], v: f64| values.iter().position(|x| *x == v).unwrap_or(0);
    let punch_runs: Vec<figures::Run> = punch_curves
        .iter()
        .map(|p| figures::Run {
            label: format!("h = {} mm", p.h),
            panel: p.d,
            color: figures::run_color(index(&config.thicknesses_mm, p.h), experiment::DGAMMA_PUNCH),
            loading: true,
            curve: &p.curve,
            exact: p.exact,
        })
        .collect();
    figures::punch_curves(&out.join("flat_punch_curves.svg"), &punch_runs, &config)?;
    let sphere_runs: Vec<figures::Run> = sphere_curves
        .iter()
        .map(|s| {
            let standard = (s.dgamma - experiment::DGAMMA_PUNCH).abs() < 1e-12;
            figures::Run {
                label: format!("h = {} mm, dgamma1 = {} J/m^2", s.h, s.dgamma),
                panel: s.r,
                color: figures::run_color(index(&config.thicknesses_mm, s.h), s.dgamma),
                loading: standard,
                curve: &s.curve,
                exact: s.exact,
            }
        })
        .collect();
    figures::sphere_curves(&out.join("sphere_curves.svg"), &sphere_runs, &config)?;

    summary(&stiffness, &punch_curves, &sphere_curves)?;
    say!(
        "\nwrote {} in {:.1} s (wall time of the whole run)",
        out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// A flat-punch curve with its exact pull-off `(depth, force)` and the
/// largest deviation of its loading branch from the exact one.
struct PunchRun {
    h: f64,
    d: f64,
    curve: Curve,
    exact: (f64, f64),
    loading_error: f64,
}

/// A sphere curve, likewise.
struct SphereRun {
    r: f64,
    h: f64,
    dgamma: f64,
    curve: Curve,
    exact: (f64, f64),
    loading_error: f64,
}

fn write_stiffness(out: &std::path::Path, rows: &[StiffnessRow]) -> Result<()> {
    let mut w = csv::Writer::from_path(out.join("stiffness.csv"))?;
    w.write_record(["h_mm", "D_mm", "eps", "series", "exact", "bem"])?;
    for r in rows {
        let bem = r.bem.map_or(String::new(), |b| format!("{b:.8}"));
        w.write_record([
            format!("{}", r.h_mm),
            format!("{}", r.d_mm),
            format!("{:.6}", r.eps),
            format!("{:.8}", r.series),
            format!("{:.8}", r.exact),
            bem,
        ])?;
    }
    w.flush()?;
    Ok(())
}

fn write_punch_curves(out: &std::path::Path, curves: &[PunchRun]) -> Result<()> {
    let mut w = csv::Writer::from_path(out.join("flat_punch_curves.csv"))?;
    w.write_record([
        "h_mm",
        "D_mm",
        "phase",
        "depth_m",
        "force_N",
        "contact_area_m2",
    ])?;
    for PunchRun { h, d, curve, .. } in curves {
        for s in &curve.steps {
            w.write_record([
                format!("{h}"),
                format!("{d}"),
                s.phase.name().to_string(),
                format!("{:e}", s.depth),
                format!("{:e}", s.force),
                format!("{:e}", s.contact_area),
            ])?;
        }
    }
    w.flush()?;
    Ok(())
}

fn write_sphere_curves(out: &std::path::Path, curves: &[SphereRun]) -> Result<()> {
    let mut w = csv::Writer::from_path(out.join("sphere_curves.csv"))?;
    w.write_record([
        "R_mm",
        "h_mm",
        "dgamma1",
        "phase",
        "depth_m",
        "force_N",
        "contact_radius_m",
    ])?;
    for SphereRun {
        r,
        h,
        dgamma,
        curve,
        ..
    } in curves
    {
        for s in &curve.steps {
            w.write_record([
                format!("{r}"),
                format!("{h}"),
                format!("{dgamma}"),
                s.phase.name().to_string(),
                format!("{:e}", s.depth),
                format!("{:e}", s.force),
                format!("{:e}", s.contact_radius),
            ])?;
        }
    }
    w.flush()?;
    Ok(())
}

fn summary(stiffness: &[StiffnessRow], punches: &[PunchRun], spheres: &[SphereRun]) -> Result<()> {
    let series = PunchStiffnessSeries::new(experiment::rubber(), 5e-3)?;
    let (mut lo, mut hi) = (1e-6, 5e-3);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if series.evaluate(0.5 * mid)?.ratio < 1.2 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    say!("\n# Summary");
    let exact = stiffness
        .iter()
        .find(|r| r.h_mm == 5.0 && r.d_mm == 5.0)
        .map_or("-".to_string(), |r| format!("{:.4}", r.exact));
    say!(
        "series K/(2aE*) at h = D = 5 mm: {:.4} (exact {exact}; paper: 1.9)",
        series.evaluate(2.5e-3)?.ratio
    );
    say!(
        "h = 5 mm series reaches 1.2 at D = {:.4} mm (paper: 1.55 mm)",
        0.5 * (lo + hi) * 1e3
    );
    let worst = stiffness
        .iter()
        .filter_map(|r| r.bem.map(|b| (b / r.exact - 1.0, r)))
        .max_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
    if let Some((error, row)) = worst {
        say!(
            "largest BEM deviation from the exact stiffness: {:+.2} % (h = {} mm, D = {} mm)",
            100.0 * error,
            row.h_mm,
            row.d_mm
        );
    }
    say!(
        "\nflat punch pull-off [mN], BEM / exact (dgamma1 = {}), error; loading branch error:",
        experiment::DGAMMA_PUNCH
    );
    let (mut worst_pull, mut worst_loading) = (0.0f64, 0.0f64);
    for p in punches {
        let bem = experiment::pull_off(&p.curve);
        let error = bem / p.exact.1 - 1.0;
        worst_pull = worst_pull.max(error.abs());
        worst_loading = worst_loading.max(p.loading_error);
        say!(
            "  h = {:>4} mm, D = {:>4} mm: {:9.2} / {:9.2}  {:+.2} %; loading {:.2} %",
            p.h,
            p.d,
            bem * 1e3,
            p.exact.1 * 1e3,
            100.0 * error,
            100.0 * p.loading_error
        );
    }
    say!("\nsphere pull-off [mN], BEM / exact JKR on the layer (load control), error; loading branch error:");
    for s in spheres {
        let bem = experiment::pull_off(&s.curve);
        let error = bem / s.exact.1 - 1.0;
        worst_pull = worst_pull.max(error.abs());
        worst_loading = worst_loading.max(s.loading_error);
        say!(
            "  R = {:>5} mm, h = {:>4} mm, dgamma1 = {:5.3}: {:9.2} / {:9.2}  {:+.2} %; loading {:.2} %",
            s.r,
            s.h,
            s.dgamma,
            bem * 1e3,
            s.exact.1 * 1e3,
            100.0 * error,
            100.0 * s.loading_error
        );
    }
    say!(
        "\nworst pull-off error {:.2} %, worst loading-branch error {:.2} % (of the peak force)",
        100.0 * worst_pull,
        100.0 * worst_loading
    );
    Ok(())
}
