//! The computations of the `paper` example, shared with the test that runs a
//! reduced version of them (`tests/paper.rs`). No I/O here.

#![allow(dead_code)]

use layered_contact::analytic::{Axisymmetric, LayeredJkrCycle, PunchStiffnessSeries};
use layered_contact::scene::{
    richardson, Adhesion, Curve, IndenterSpec, Phase, Protocol, Resolution, Scene, SolverSettings,
    SubstrateSpec,
};
use layered_contact::{Error, Material, Substrate};

/// Material of the reference experiment (Lyashenko, Popov & Borysiuk 2023).
pub const YOUNGS_MODULUS: f64 = 0.324e6;
/// Poisson ratio of the rubber.
pub const POISSON_RATIO: f64 = 0.48;
/// Work of adhesion while the contact grows, J/m^2.
pub const DGAMMA_LOADING: f64 = 0.0175;
/// Work of adhesion while a flat punch is pulled off, J/m^2.
pub const DGAMMA_PUNCH: f64 = 0.326;

/// How much to compute.
#[derive(Debug, Clone)]
pub struct Config {
    /// Layer thicknesses, mm.
    pub thicknesses_mm: Vec<f64>,
    /// Punch diameters of the stiffness table, mm.
    pub stiffness_diameters_mm: Vec<f64>,
    /// Punch diameters of the force-depth curves, mm.
    pub punch_diameters_mm: Vec<f64>,
    /// Sphere radii, mm.
    pub sphere_radii_mm: Vec<f64>,
    /// Maximum depth of the punches, m.
    pub punch_depth: f64,
    /// Maximum depth of the spheres, m.
    pub sphere_depth: f64,
    /// Cells across a punch for the stiffness.
    pub cells_across_punch: usize,
    /// Cells across the smallest sphere contact to resolve (the pull-off
    /// contact, or the peak's if smaller).
    pub cells_across_sphere: usize,
    /// Loading increments of each curve.
    pub steps: usize,
}

impl Config {
    /// The default run (the README's main command).
    pub fn standard() -> Self {
        Config {
            thicknesses_mm: vec![5.0, 10.0, 15.0, 20.0, 25.0],
            stiffness_diameters_mm: vec![1.0, 2.0, 4.0, 7.0, 10.0, 15.0],
            punch_diameters_mm: vec![4.0, 7.0, 10.0, 15.0],
            sphere_radii_mm: vec![30.0, 50.0, 100.0],
            punch_depth: 0.2e-3,
            sphere_depth: 0.5e-3,
            cells_across_punch: 80,
            cells_across_sphere: 32,
            steps: 20,
        }
    }

    /// Publication resolution (`--fine`).
    pub fn fine() -> Self {
        Config {
            cells_across_punch: 160,
            cells_across_sphere: 64,
            steps: 50,
            ..Self::standard()
        }
    }

    /// The sphere runs: `(R mm, h mm, dgamma1)`; the extra unloading works
    /// of adhesion only for the thinnest layer.
    pub fn sphere_runs(&self) -> Vec<(f64, f64, f64)> {
        let thinnest = self
            .thicknesses_mm
            .iter()
            .cloned()
            .fold(f64::INFINITY, f64::min);
        let mut runs = Vec::new();
        for &r in &self.sphere_radii_mm {
            for &h in &self.thicknesses_mm {
                runs.push((r, h, DGAMMA_PUNCH));
                if h == thinnest {
                    runs.push((r, h, 0.27));
                    runs.push((r, h, 0.722));
                }
            }
        }
        runs
    }
}

pub fn rubber() -> Material {
    Material::new(YOUNGS_MODULUS, POISSON_RATIO).expect("valid material")
}

pub fn film(h_mm: f64) -> Result<Substrate, Error> {
    Substrate::layer_on_rigid_base(rubber(), h_mm * 1e-3)
}

/// One row of `stiffness.csv`.
#[derive(Debug, Clone, Copy)]
pub struct StiffnessRow {
    pub h_mm: f64,
    pub d_mm: f64,
    pub eps: f64,
    pub series: f64,
    pub exact: f64,
    pub bem: Option<f64>,
}

/// `K / (2 a E*)` of a flat punch of diameter `d_mm` on layer `h_mm` by the
/// BEM (non-adhesive, 1 um deep, on the scene's equal-area grid): the
/// Richardson extrapolation of `cells_across` and twice as many, whose
/// errors are a clean `c / N` (see `doc::accuracy`): at 80 and 160 cells
/// within 0.02 % of the exact solution, where 80 cells alone are 0.3 to
/// 0.7 % below it.
pub fn bem_ratio(h_mm: f64, d_mm: f64, cells_across: usize) -> Result<f64, Error> {
    let radius = 0.5e-3 * d_mm;
    let depth = 1e-6;
    let force = |cells_across: usize| -> Result<f64, Error> {
        let scene = Scene {
            protocol: Protocol::Depth { depth },
            resolution: Resolution {
                cells_across,
                margin: 0.0,
            },
            solver: SolverSettings {
                tolerance: 1e-10,
                ..SolverSettings::default()
            },
            adhesion: Adhesion::None,
            ..punch_scene(h_mm, d_mm, depth, 1)
        };
        let curve = scene.run(&mut |_| {})?;
        Ok(curve.steps.last().map_or(0.0, |s| s.force))
    };
    let fine = 2 * cells_across;
    let force = richardson(
        (cells_across, force(cells_across)?),
        (fine, force(fine)?),
        1.0,
    );
    Ok(force / depth / (2.0 * radius * rubber().contact_modulus()))
}

/// The stiffness table: every `h` and `D` with series, exact and BEM, plus a
/// fine `D` grid (0.25 mm to 16 mm) with series and exact only.
pub fn stiffness_rows(
    config: &Config,
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<StiffnessRow>, Error> {
    let mut rows = Vec::new();
    let fine_d: Vec<f64> = (1..=64).map(|k| 0.25 * k as f64).collect();
    for &h in &config.thicknesses_mm {
        let series = PunchStiffnessSeries::new(rubber(), h * 1e-3)?;
        let max_d = config
            .stiffness_diameters_mm
            .iter()
            .chain(&fine_d)
            .cloned()
            .fold(0.0, f64::max);
        let exact = Axisymmetric::new(&film(h)?, 0.5 * max_d / h * 1.01)?;
        let row = |d: f64, bem: Option<f64>| -> Result<StiffnessRow, Error> {
            let radius = 0.5e-3 * d;
            Ok(StiffnessRow {
                h_mm: h,
                d_mm: d,
                eps: 0.5 * d / h,
                series: series.evaluate(radius)?.ratio,
                exact: exact.flat_punch(radius)?.ratio(),
                bem,
            })
        };
        for &d in &fine_d {
            rows.push(row(d, None)?);
        }
        for &d in &config.stiffness_diameters_mm {
            rows.push(row(d, Some(bem_ratio(h, d, config.cells_across_punch)?))?);
            progress();
        }
    }
    Ok(rows)
}

/// The scene of a flat punch of diameter `d_mm` on layer `h_mm`: loaded to
/// `depth` with `dgamma0`, pulled off with `dgamma1`.
pub fn punch_scene(h_mm: f64, d_mm: f64, depth: f64, steps: usize) -> Scene {
    Scene {
        substrate: SubstrateSpec::LayerOnRigidBase {
            youngs_modulus: YOUNGS_MODULUS,
            poisson_ratio: POISSON_RATIO,
            thickness: h_mm * 1e-3,
        },
        indenter: IndenterSpec::FlatPunch {
            radius: 0.5e-3 * d_mm,
        },
        adhesion: Adhesion::Hysteresis {
            loading: DGAMMA_LOADING,
            unloading: DGAMMA_PUNCH,
        },
        protocol: Protocol::Cycle {
            max_depth: depth,
            steps,
        },
        resolution: Resolution {
            cells_across: 64,
            margin: 0.0,
        },
        solver: SolverSettings {
            pull_off_bisections: 12,
            ..SolverSettings::default()
        },
        ..Scene::default()
    }
}

/// The scene of a sphere of radius `r_mm` on layer `h_mm`, modelled as the
/// paraboloid `f = r^2 / (2R)` of JKR theory and of the exact layered
/// solution it is compared with (at the deepest point, `a/R` up to 0.17, a
/// spherical cap would carry up to 0.7 % more force).
pub fn sphere_scene(
    r_mm: f64,
    h_mm: f64,
    dgamma1: f64,
    depth: f64,
    steps: usize,
    cells: usize,
) -> Scene {
    Scene {
        substrate: SubstrateSpec::LayerOnRigidBase {
            youngs_modulus: YOUNGS_MODULUS,
            poisson_ratio: POISSON_RATIO,
            thickness: h_mm * 1e-3,
        },
        indenter: IndenterSpec::Paraboloid {
            radius: r_mm * 1e-3,
        },
        adhesion: Adhesion::Hysteresis {
            loading: DGAMMA_LOADING,
            unloading: dgamma1,
        },
        protocol: Protocol::Cycle {
            max_depth: depth,
            steps,
        },
        resolution: Resolution {
            cells_across: cells,
            margin: 0.15,
        },
        ..Scene::default()
    }
}

/// Exact pull-off force of a flat punch (diameter `d_mm`, layer `h_mm`).
pub fn exact_punch_pull_off(h_mm: f64, d_mm: f64, dgamma: f64) -> Result<f64, Error> {
    Ok(exact_punch_pull_off_point(h_mm, d_mm, dgamma)?.1)
}

/// Exact pull-off `(depth m, force N)` of a flat punch: it detaches at once
/// when the edge's energy release rate reaches `dgamma`.
pub fn exact_punch_pull_off_point(h_mm: f64, d_mm: f64, dgamma: f64) -> Result<(f64, f64), Error> {
    let radius = 0.5e-3 * d_mm;
    let exact = Axisymmetric::new(&film(h_mm)?, radius / (h_mm * 1e-3) * 1.01)?;
    let punch = exact.flat_punch(radius)?;
    Ok((punch.critical_depth(dgamma), punch.pull_off_force(dgamma)))
}

/// The largest deviation of a punch curve's loading branch from the exact
/// `F = K d`, relative to the exact force at the deepest point.
pub fn punch_loading_error(h_mm: f64, d_mm: f64, curve: &Curve) -> Result<f64, Error> {
    let radius = 0.5e-3 * d_mm;
    let exact = Axisymmetric::new(&film(h_mm)?, radius / (h_mm * 1e-3) * 1.01)?;
    let stiffness = exact.flat_punch(radius)?.stiffness();
    let peak = curve.steps.iter().map(|s| s.depth).fold(0.0, f64::max) * stiffness;
    Ok(curve
        .phase(Phase::Loading)
        .filter(|s| s.depth > 0.0)
        .map(|s| ((s.force - stiffness * s.depth) / peak).abs())
        .fold(0.0, f64::max))
}

/// The largest deviation of a sphere curve's loading branch from the exact
/// layered JKR loading curve (advancing work of adhesion), relative to the
/// exact force at the deepest point.
pub fn sphere_loading_error(
    r_mm: f64,
    h_mm: f64,
    dgamma1: f64,
    max_depth: f64,
    curve: &Curve,
) -> Result<f64, Error> {
    let exact = Axisymmetric::new(&film(h_mm)?, 4.0)?;
    let cycle = LayeredJkrCycle::new(&exact, r_mm * 1e-3, DGAMMA_LOADING, dgamma1, max_depth)?;
    let peak = cycle.peak().force;
    let mut worst: f64 = 0.0;
    for step in curve.phase(Phase::Loading).filter(|s| s.depth > 0.0) {
        if let Some(state) = cycle.loading(step.depth)? {
            worst = worst.max(((step.force - state.force) / peak).abs());
        }
    }
    Ok(worst)
}

/// Exact pull-off force (load control) of a paraboloid of radius `r_mm` on
/// layer `h_mm`.
pub fn exact_sphere_pull_off(r_mm: f64, h_mm: f64, dgamma: f64) -> Result<f64, Error> {
    Ok(exact_sphere_pull_off_point(r_mm, h_mm, dgamma)?.1)
}

/// Exact pull-off `(depth m, force N)` (load control, the least force) of a
/// paraboloid of radius `r_mm` on layer `h_mm`.
pub fn exact_sphere_pull_off_point(r_mm: f64, h_mm: f64, dgamma: f64) -> Result<(f64, f64), Error> {
    let exact = Axisymmetric::new(&film(h_mm)?, 4.0)?;
    let state = exact
        .paraboloid(r_mm * 1e-3, dgamma)?
        .pull_off()?
        .load_control;
    Ok((state.depth, state.force))
}

/// The minimum force of a curve (its pull-off force), or 0.
pub fn pull_off(curve: &Curve) -> f64 {
    curve.pull_off().map_or(0.0, |s| s.force)
}
