//! What accuracy costs in time: each case solved on grids of 8, 16, 32, ...
//! cells across the contact (up to 512, while the next run would take under
//! a minute), against
//! a trusted reference (closed forms and the exact axisymmetric solutions),
//! with the Richardson extrapolation of consecutive resolutions and the exact
//! solver as rows of their own. (The cost of one CG iteration against an
//! FFT round trip of the padded grid is timed by `benches/solver.rs`.)
//!
//! ```text
//! cargo run --release --example accuracy -- [--out DIR] [--max-cells N] [--budget SECONDS]
//!                                            [--only CASE_PREFIX]
//! ```
//!
//! A case stops refining where the next run would take longer than the
//! budget (default 60 s; a doubling costs about eight times as much).
//!
//! Writes `accuracy.csv` (`case,cells_across,n_grid,rel_error,seconds,iterations,grid_bytes`),
//! `accuracy.svg` (error against time, log-log) and `BENCHMARKS.md` to `DIR`
//! (default `target/accuracy`), and prints the markdown table.

use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use layered_contact::analytic::{Axisymmetric, Hertz, JkrSphere};
use layered_contact::scene::{
    richardson, Adhesion, AdhesionMethod, IndenterSpec, Protocol, Quantity, Resolution, Scene,
    SolverSettings, SubstrateSpec,
};
use layered_contact::{Grid, Material, Substrate};
use plotters::prelude::*;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

struct Case {
    name: &'static str,
    scene: Scene,
    quantity: Quantity,
    reference: f64,
    /// Seconds for the exact (analytic / axisymmetric) value and its error.
    exact: (f64, f64),
    /// Resolutions: the first, and the largest.
    cells: (usize, usize),
    /// The order of the error in `1/N` that Richardson extrapolation
    /// removes: 1, but 2 for the cohesive zone's pull-off.
    order: f64,
}

struct Row {
    case: String,
    cells_across: usize,
    n_grid: usize,
    rel_error: f64,
    seconds: f64,
    iterations: usize,
    grid_bytes: usize,
}

fn rubber() -> Material {
    Material::new(0.324e6, 0.48).expect("valid")
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let value = f();
    (value, start.elapsed().as_secs_f64())
}

fn cases() -> Result<Vec<Case>> {
    let soft = Material::new(1e6, 0.5)?;
    let half_space = SubstrateSpec::HalfSpace {
        youngs_modulus: 1e6,
        poisson_ratio: 0.5,
    };
    let layer = |h: f64| SubstrateSpec::LayerOnRigidBase {
        youngs_modulus: 0.324e6,
        poisson_ratio: 0.48,
        thickness: h,
    };
    let base = |substrate, indenter, adhesion, protocol| Scene {
        substrate,
        indenter,
        adhesion,
        protocol,
        resolution: Resolution {
            cells_across: 8,
            margin: 0.25,
        },
        ..Scene::default()
    };
    let mut cases = Vec::new();

    let (a, d) = (1e-3, 1e-5);
    cases.push(Case {
        name: "punch_half_space",
        scene: base(
            half_space.clone(),
            IndenterSpec::FlatPunch { radius: a },
            Adhesion::None,
            Protocol::Depth { depth: d },
        ),
        quantity: Quantity::PeakForce,
        reference: 2.0 * a * soft.contact_modulus() * d,
        exact: (0.0, 0.0),
        cells: (8, 512),
        order: 1.0,
    });
    for eps in [0.5, 2.0] {
        let (a, h) = (2.5e-3, 2.5e-3 / eps);
        let ((punch, exact_error), seconds) = timed(|| {
            let exact = Axisymmetric::new(
                &Substrate::layer_on_rigid_base(rubber(), h).expect("valid"),
                eps,
            )
            .expect("valid");
            let punch = exact.flat_punch(a).expect("converges");
            (punch.stiffness(), punch.convergence())
        });
        cases.push(Case {
            name: if eps < 1.0 {
                "punch_layer_a_over_h=0.5"
            } else {
                "punch_layer_a_over_h=2"
            },
            scene: base(
                layer(h),
                IndenterSpec::FlatPunch { radius: a },
                Adhesion::None,
                Protocol::Depth { depth: 1e-5 },
            ),
            quantity: Quantity::PeakForce,
            reference: punch * 1e-5,
            exact: (seconds, exact_error),
            cells: (8, 512),
            order: 1.0,
        });
    }
    let (r, d) = (0.01, 1e-4);
    cases.push(Case {
        name: "hertz_sphere",
        scene: base(
            half_space,
            IndenterSpec::Paraboloid { radius: r },
            Adhesion::None,
            Protocol::Depth { depth: d },
        ),
        quantity: Quantity::PeakForce,
        reference: Hertz::new(&soft, r)?.force(d),
        exact: (0.0, 0.0),
        cells: (8, 512),
        order: 1.0,
    });
    let (a, h) = (2.5e-3, 5e-3);
    let ((pull_off, exact_error), seconds) = timed(|| {
        let exact = Axisymmetric::new(
            &Substrate::layer_on_rigid_base(rubber(), h).expect("valid"),
            0.5,
        )
        .expect("valid");
        let punch = exact.flat_punch(a).expect("converges");
        (punch.pull_off_force(0.326), punch.convergence())
    });
    let kendall_on_layer = base(
        layer(h),
        IndenterSpec::FlatPunch { radius: a },
        Adhesion::Constant {
            work_of_adhesion: 0.326,
        },
        Protocol::Cycle {
            max_depth: 2e-4,
            steps: 20,
        },
    );
    cases.push(Case {
        name: "punch_jkr_layer_pull_off",
        scene: kendall_on_layer.clone(),
        quantity: Quantity::PullOffForce,
        reference: pull_off,
        exact: (seconds, exact_error),
        cells: (8, 512),
        order: 1.0,
    });
    // The same punch by the local criterion: loaded through the cohesive
    // zone, unloaded along its peeling path (the automatic method of a
    // tilted punch; named here, the untilted one taking the energy
    // balance).
    let mut peeled = kendall_on_layer;
    peeled.solver.adhesion_method = AdhesionMethod::CohesiveZone;
    cases.push(Case {
        name: "punch_jkr_layer_pull_off/peeling_path",
        scene: peeled,
        quantity: Quantity::PullOffForce,
        reference: pull_off,
        exact: (seconds, exact_error),
        cells: (16, 256),
        order: 1.0,
    });
    cases.extend(sphere_pull_off_cases()?);
    Ok(cases)
}

/// The JKR pull-off of a sphere (R = 10 mm, dgamma = 0.05 J/m^2) on a rubber
/// (E = 1 MPa, nu = 0.48) half-space and on layers of it whose pull-off
/// contact is about 1 and 3 thicknesses wide, on a rigid base and on an
/// elastic one ten times stiffer: both adhesion methods, from 16 cells
/// across the pull-off contact, pressed until the contact is 1.5 pull-off
/// radii wide. The reference is the exact (layered) JKR pull-off force.
fn sphere_pull_off_cases() -> Result<Vec<Case>> {
    let (e, nu, r, dgamma) = (1e6, 0.48, 0.01, 0.05);
    let a = JkrSphere::new(&Material::new(e, nu)?, r, dgamma)?.pull_off_contact_radius();
    let mut cases = Vec::new();
    let substrates = [
        (
            "half_space",
            SubstrateSpec::HalfSpace {
                youngs_modulus: e,
                poisson_ratio: nu,
            },
        ),
        (
            "rigid_base_a/h=1",
            SubstrateSpec::LayerOnRigidBase {
                youngs_modulus: e,
                poisson_ratio: nu,
                thickness: a,
            },
        ),
        (
            "rigid_base_a/h=3",
            SubstrateSpec::LayerOnRigidBase {
                youngs_modulus: e,
                poisson_ratio: nu,
                thickness: a / 4.0,
            },
        ),
        (
            "E2/E1=10_a/h=1",
            SubstrateSpec::LayerOnElasticBase {
                youngs_modulus: e,
                poisson_ratio: nu,
                thickness: a,
                base_youngs_modulus: 10.0 * e,
                base_poisson_ratio: nu,
            },
        ),
        (
            "E2/E1=10_a/h=3",
            SubstrateSpec::LayerOnElasticBase {
                youngs_modulus: e,
                poisson_ratio: nu,
                thickness: a / 4.0,
                base_youngs_modulus: 10.0 * e,
                base_poisson_ratio: nu,
            },
        ),
    ];
    for (label, substrate) in substrates {
        let (exact, seconds) = timed(|| -> Result<_> {
            let exact = Axisymmetric::new(&substrate.build()?, 20.0)?;
            let ball = exact.paraboloid(r, dgamma)?;
            let pull_off = ball.pull_off()?.load_control;
            let depth = ball.at_contact_radius(1.5 * pull_off.contact_radius)?.depth;
            let error = exact
                .flat_punch(pull_off.contact_radius)
                .map_or(0.0, |p| p.convergence());
            Ok((pull_off.force, pull_off.contact_radius, depth, error))
        });
        let (pull_off, radius, depth, error) = exact?;
        for method in [
            AdhesionMethod::EnergyBalance,
            AdhesionMethod::CohesiveZone,
            AdhesionMethod::MeshCriterion,
        ] {
            let name = match method {
                AdhesionMethod::EnergyBalance => "energy",
                AdhesionMethod::CohesiveZone => "cohesive",
                _ => "mesh",
            };
            let scene = Scene {
                substrate: substrate.clone(),
                indenter: IndenterSpec::Paraboloid { radius: r },
                adhesion: Adhesion::Constant {
                    work_of_adhesion: dgamma,
                },
                protocol: Protocol::Cycle {
                    max_depth: depth,
                    steps: 10,
                },
                resolution: Resolution {
                    cells_across: 16,
                    margin: 0.05,
                },
                solver: SolverSettings {
                    adhesion_method: method,
                    ..SolverSettings::default()
                },
                ..Scene::default()
            };
            if method == AdhesionMethod::CohesiveZone && label == "half_space" {
                // The zone's contact radius at the peak (1.5 pull-off
                // radii), read as its equivalent crack's: first order.
                cases.push(Case {
                    name: "jkr_sphere_peak_radius/half_space/cohesive",
                    scene: scene.clone(),
                    quantity: Quantity::PeakContactRadius,
                    reference: 1.5 * radius,
                    exact: (seconds, error),
                    cells: (16, 256),
                    order: 1.0,
                });
            }
            cases.push(Case {
                name: Box::leak(format!("jkr_sphere_pull_off/{label}/{name}").into_boxed_str()),
                scene,
                quantity: Quantity::PullOffForce,
                reference: pull_off,
                exact: (seconds, error),
                cells: (16, 256),
                order: if method == AdhesionMethod::CohesiveZone {
                    2.0
                } else {
                    1.0
                },
            });
        }
    }
    Ok(cases)
}

/// Bytes of the grids of one solve: the padded real array, two complex
/// buffers and the spectrum of the operator, and six per-cell solver vectors.
fn grid_bytes(grid: &Grid) -> usize {
    let (n0, n1) = (2 * grid.rows(), 2 * grid.columns());
    let half = n1 / 2 + 1;
    8 * n0 * n1 + 2 * 16 * n0 * half + 8 * n0 * half + 6 * 8 * grid.len()
}

fn main() -> Result<()> {
    let mut out = PathBuf::from("target/accuracy");
    let mut max_cells = 512;
    let mut budget = 60.0;
    let mut only: Option<String> = None;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            "--max-cells" => {
                max_cells = args.next().ok_or("--max-cells needs a number")?.parse()?
            }
            "--budget" => budget = args.next().ok_or("--budget needs seconds")?.parse()?,
            "--only" => only = Some(args.next().ok_or("--only needs a case prefix")?),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    std::fs::create_dir_all(&out)?;
    let mut rows = Vec::new();
    let all = cases()?;
    let names: Vec<&'static str> = all.iter().map(|c| c.name).collect();
    let chosen: Vec<_> = all
        .into_iter()
        .filter(|c| only.as_ref().is_none_or(|o| c.name.starts_with(o.as_str())))
        .collect();
    if chosen.is_empty() {
        // An empty table has no axes to plot (and the plot's log axes
        // over an empty range ran out of memory).
        return Err(format!(
            "no case starts with {:?}; the cases are: {}",
            only.unwrap_or_default(),
            names.join(", ")
        )
        .into());
    }
    for case in chosen {
        let mut previous: Option<(usize, f64, f64)> = None;
        rows.push(Row {
            case: format!("{}/exact", case.name),
            cells_across: 0,
            n_grid: 0,
            rel_error: case.exact.1,
            seconds: case.exact.0,
            iterations: 0,
            grid_bytes: 0,
        });
        let mut cells = case.cells.0;
        while cells <= max_cells.min(case.cells.1) {
            let scene = Scene {
                resolution: Resolution {
                    cells_across: cells,
                    ..case.scene.resolution
                },
                ..case.scene.clone()
            };
            let (curve, seconds) = timed(|| scene.run(&mut |_| {}));
            let curve = match curve {
                // A typed refusal (a grid too coarse for the method) is a
                // result of the case: the next resolution is tried.
                Err(e @ layered_contact::Error::Unsupported { .. }) => {
                    eprintln!("{:28} {cells:4} cells: refused: {e}", case.name);
                    cells *= 2;
                    continue;
                }
                other => other?,
            };
            let value = case.quantity.of(&curve).ok_or("quantity missing")?;
            let error = (value / case.reference - 1.0).abs();
            rows.push(Row {
                case: case.name.to_string(),
                cells_across: cells,
                n_grid: curve.grid.rows(),
                rel_error: error,
                seconds,
                iterations: curve.steps.iter().map(|s| s.iterations).sum(),
                grid_bytes: grid_bytes(&curve.grid),
            });
            if let Some((coarse, coarse_value, coarse_seconds)) = previous {
                let extrapolated = richardson((coarse, coarse_value), (cells, value), case.order);
                rows.push(Row {
                    case: format!("{}/richardson", case.name),
                    cells_across: cells,
                    n_grid: curve.grid.rows(),
                    rel_error: (extrapolated / case.reference - 1.0).abs(),
                    seconds: seconds + coarse_seconds,
                    iterations: 0,
                    grid_bytes: grid_bytes(&curve.grid),
                });
            }
            eprintln!(
                "{:28} {cells:4} cells: error {error:.2e}, {seconds:.3} s",
                case.name
            );
            previous = Some((cells, value, seconds));
            // A doubling costs 4 to 20 times as much (more cells, more
            // iterations): stop where the next run would pass the budget.
            if seconds * 8.0 > budget {
                break;
            }
            cells *= 2;
        }
    }

    let mut csv = csv::Writer::from_path(out.join("accuracy.csv"))?;
    csv.write_record([
        "case",
        "cells_across",
        "n_grid",
        "rel_error",
        "seconds",
        "iterations",
        "grid_bytes",
    ])?;
    for r in &rows {
        csv.write_record([
            r.case.clone(),
            r.cells_across.to_string(),
            r.n_grid.to_string(),
            format!("{:.3e}", r.rel_error),
            format!("{:.4e}", r.seconds),
            r.iterations.to_string(),
            r.grid_bytes.to_string(),
        ])?;
    }
    csv.flush()?;

    let mut table = String::from("| case | cells across | grid | rel. error | seconds | CG iterations | grid memory |\n|---|---|---|---|---|---|---|\n");
    for r in &rows {
        writeln!(
            table,
            "| {} | {} | {} | {:.2e} | {:.4} | {} | {:.1} MB |",
            r.case,
            r.cells_across,
            r.n_grid,
            r.rel_error,
            r.seconds,
            r.iterations,
            r.grid_bytes as f64 / 1e6
        )?;
    }
    println!("{table}");
    let benchmarks = format!(
        "# Benchmarks\n\nRegenerated by `cargo run --release --example accuracy` (this machine: 2 cores).\n\n\
         ## Accuracy against cost\n\nErrors against closed forms (Boussinesq, Hertz, JKR) and the exact \
         axisymmetric solutions (rows `/exact`: their own cost and convergence); rows `/richardson` \
         extrapolate the two resolutions up to the given one (`1/N`; `1/N^2` for the cohesive zone).\n\n{table}"
    );
    std::fs::write(out.join("BENCHMARKS.md"), benchmarks)?;
    plot(&out.join("accuracy.svg"), &rows)?;
    eprintln!("wrote {}", out.display());
    Ok(())
}

fn plot(path: &std::path::Path, rows: &[Row]) -> Result<()> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "invalid font")?;
    let root = SVGBackend::new(path, (1000, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let positive: Vec<&Row> = rows
        .iter()
        .filter(|r| r.rel_error > 0.0 && r.seconds > 0.0)
        .collect();
    if positive.is_empty() {
        // Nothing to place on log axes (every error or time zero).
        return Ok(());
    }
    let t0 = positive
        .iter()
        .map(|r| r.seconds)
        .fold(f64::INFINITY, f64::min)
        / 2.0;
    let t1 = positive.iter().map(|r| r.seconds).fold(0.0, f64::max) * 2.0;
    let e0 = positive
        .iter()
        .map(|r| r.rel_error)
        .fold(f64::INFINITY, f64::min)
        / 2.0;
    let e1 = positive.iter().map(|r| r.rel_error).fold(0.0, f64::max) * 2.0;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "What accuracy costs: BEM (lines), Richardson (squares), exact solver (stars)",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(55)
        .y_label_area_size(75)
        .build_cartesian_2d((t0..t1).log_scale(), (e0..e1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("wall time [s]")
        .y_desc("relative error")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .draw()?;
    let mut names: Vec<&str> = rows
        .iter()
        .filter(|r| !r.case.contains('/'))
        .map(|r| r.case.as_str())
        .collect();
    names.dedup();
    for (i, name) in names.iter().enumerate() {
        let color = Palette99::pick(i).to_rgba();
        let bem: Vec<(f64, f64)> = positive
            .iter()
            .filter(|r| r.case == *name)
            .map(|r| (r.seconds, r.rel_error))
            .collect();
        chart
            .draw_series(LineSeries::new(bem.clone(), color.stroke_width(2)))?
            .label(*name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
            });
        chart.draw_series(bem.iter().map(|p| Circle::new(*p, 3, color.filled())))?;
        let extrapolated = format!("{name}/richardson");
        chart.draw_series(positive.iter().filter(|r| r.case == extrapolated).map(|r| {
            Rectangle::new(
                [
                    (r.seconds * 0.93, r.rel_error * 0.85),
                    (r.seconds * 1.07, r.rel_error * 1.15),
                ],
                color.filled(),
            )
        }))?;
        let exact = format!("{name}/exact");
        chart.draw_series(
            positive
                .iter()
                .filter(|r| r.case == exact)
                .map(|r| Cross::new((r.seconds, r.rel_error), 7, color.stroke_width(3))),
        )?;
    }
    chart
        .configure_series_labels()
        .label_font(("sans-serif", 14))
        .position(SeriesLabelPosition::LowerLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
