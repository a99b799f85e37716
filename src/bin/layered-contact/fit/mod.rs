//! `layered-contact fit`: the modulus, the work of adhesion and the contact
//! point of a film from a measured force curve, with the exact model
//! (`analytic::ForceCurve`) and MINPACK's Levenberg-Marquardt
//! (`levenberg-marquardt`); standard errors from the Jacobian at the
//! solution. The same model and rules as Python's `layered_contact.fit`.

use std::path::{Path, PathBuf};

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra_lm::{DMatrix, DVector, Dyn, Owned};

use layered_contact::analytic::{before_jump_off, ModulusFamily, Tip};
use layered_contact::Material;

use super::Result;

mod model;

use model::{build_table, Model, Sample, Values};

/// Chebyshev nodes of a `--modulus-range` family: within 1e-9 of the exact
/// curves over a decade, with or without adhesion (`tests/force_curve.rs`).
const FAMILY_NODES: usize = 12;

/// The residual, in units of the curve's largest force, of a point the
/// model cannot reach at a trial step (see `Problem::residuals`).
const UNREACHABLE: f64 = 1e6;

/// Step of the central differences of the Jacobian, in scaled parameters.
const JACOBIAN_STEP: f64 = 1e-6;

/// The measured curve and what is known of the sample and the tip.
#[derive(clap::Args, Debug)]
pub(crate) struct FitArgs {
    /// CSV of two columns: position (m, increasing into the sample; the
    /// piezo's with --spring-constant) and force (N). Lines that are not
    /// two numbers (a header, comments) are skipped.
    curve: PathBuf,
    /// paraboloid, sphere, cone, rounded-cone or flat-punch.
    #[arg(long)]
    tip: String,
    /// Tip, sphere, apex or punch radius, m.
    #[arg(long)]
    radius: Option<f64>,
    /// Half-angle of a cone, degrees (axis to face).
    #[arg(long)]
    half_angle: Option<f64>,
    /// Film thickness, m (omit for a half-space).
    #[arg(long)]
    thickness: Option<f64>,
    /// Poisson ratio of the film.
    #[arg(long, default_value_t = 0.5)]
    poisson: f64,
    /// Young's modulus of an elastic support, Pa (omit for glass: rigid).
    #[arg(long)]
    base_modulus: Option<f64>,
    /// Poisson ratio of the elastic support.
    #[arg(long, default_value_t = 0.3)]
    base_poisson: f64,
    /// The film rests on its support (glass, --base-modulus, or the --below
    /// layers, themselves bonded) without friction instead of being bonded.
    #[arg(long)]
    unbonded: bool,
    /// A bonded layer under the film, `E,nu,thickness` (Pa, -, m); repeat
    /// from the top down for a stack.
    #[arg(long, value_parser = layer)]
    below: Vec<(f64, f64, f64)>,
    /// approach (no adhesion) or retract (fits the work of adhesion too).
    #[arg(long, default_value = "approach")]
    segment: String,
    /// Starting Young's modulus, Pa.
    #[arg(long)]
    modulus: f64,
    /// Starting work of adhesion (retract), J/m^2.
    #[arg(long, default_value_t = 1e-3)]
    work: f64,
    /// Starting contact point, m.
    #[arg(long, default_value_t = 0.0)]
    contact_point: f64,
    /// Cantilever stiffness, N/m: the positions are the piezo's and the
    /// tip's is `z - F/k`.
    #[arg(long)]
    spring_constant: Option<f64>,
    /// On an elastic support or layers below: build exact tables once at
    /// Chebyshev nodes in ln E over this range of the film's modulus,
    /// `LO,HI` (Pa), and interpolate the curves (approach and retract)
    /// between them (analytic::ModulusFamily) instead of a table per
    /// modulus tried.
    #[arg(long, value_parser = range)]
    modulus_range: Option<(f64, f64)>,
    /// Fit the film's thickness too (starting from --thickness).
    #[arg(long)]
    fit_thickness: bool,
    /// Fit the elastic support's modulus too (starting from --base-modulus).
    #[arg(long)]
    fit_base_modulus: bool,
    /// Output folder for fit.csv (data, model, residuals).
    #[arg(short, long, default_value = "out")]
    out: PathBuf,
}

/// A fitted parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Param {
    Modulus,
    ContactPoint,
    Work,
    Thickness,
    BaseModulus,
}

impl Param {
    fn name(self) -> &'static str {
        match self {
            Param::Modulus => "youngs_modulus (Pa)",
            Param::ContactPoint => "contact_point (m)",
            Param::Work => "work_of_adhesion (J/m^2)",
            Param::Thickness => "thickness (m)",
            Param::BaseModulus => "base_youngs_modulus (Pa)",
        }
    }

    /// The value at the scaled parameter `p`: `unit e^p` for the positive
    /// quantities (so that no step of the optimiser leaves their range),
    /// `unit p` for the contact point.
    fn value(self, p: f64, unit: f64) -> f64 {
        match self {
            Param::ContactPoint => unit * p,
            _ => unit * p.exp(),
        }
    }

    /// The scaled parameter of `value`.
    fn scaled(self, value: f64, unit: f64) -> f64 {
        match self {
            Param::ContactPoint => value / unit,
            _ => (value / unit).ln(),
        }
    }

    /// `d value / d p` at the scaled parameter `p`: the unit, or the value
    /// itself for a logarithm.
    fn slope(self, p: f64, unit: f64) -> f64 {
        match self {
            Param::ContactPoint => unit,
            _ => self.value(p, unit),
        }
    }
}

/// The least-squares problem in scaled parameters: the logarithm of each
/// positive quantity over its start, the contact point over the curve's
/// span (see [`Param::value`]); residuals in units of the largest measured
/// force.
#[derive(Clone)]
struct Problem<'a> {
    model: &'a Model,
    z: &'a [f64],
    force: &'a [f64],
    fitted: &'a [Param],
    unit: Vec<f64>,
    params: DVector<f64>,
    force_unit: f64,
}

impl Problem<'_> {
    fn values(&self) -> Values {
        let sample = &self.model.sample;
        let mut v = Values {
            modulus: f64::NAN,
            contact: f64::NAN,
            work: 0.0,
            thickness: sample.thickness,
            base_modulus: sample.base.map(|b| b.youngs_modulus()),
        };
        for (k, param) in self.fitted.iter().enumerate() {
            let value = self.value_of(k);
            match param {
                Param::Modulus => v.modulus = value,
                Param::ContactPoint => v.contact = value,
                Param::Work => v.work = value,
                Param::Thickness => v.thickness = Some(value),
                Param::BaseModulus => v.base_modulus = Some(value),
            }
        }
        v
    }

    fn value_of(&self, k: usize) -> f64 {
        self.fitted[k].value(self.params[k], self.unit[k])
    }

    fn model(&self) -> Vec<f64> {
        let v = self.values();
        let depths: Vec<f64> = self.z.iter().map(|z| z - v.contact).collect();
        self.model.forces(&depths, &v)
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.params.copy_from(x);
    }

    fn params(&self) -> DVector<f64> {
        self.params.clone()
    }

    /// The scaled residuals; a trial point where the model has no force
    /// (parameters whose exact tables do not reach the curve's depths, such
    /// as a work of adhesion thousands of times too large) gets residuals
    /// of [`UNREACHABLE`] largest forces there, so that Levenberg-Marquardt
    /// rejects the step and shrinks its trust region instead of stopping.
    fn residuals(&self) -> Option<DVector<f64>> {
        let model = self.model();
        let r = DVector::from_iterator(
            model.len(),
            model.iter().zip(self.force).map(|(m, f)| {
                if m.is_finite() {
                    (f - m) / self.force_unit
                } else {
                    UNREACHABLE
                }
            }),
        );
        r.iter().all(|v| v.is_finite()).then_some(r)
    }

    /// Central differences, one pair of model evaluations per parameter
    /// (steps of 1e-6 of the scaled parameters, about 1e-12 of truncation).
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        let n = self.params.len();
        let mut jacobian = DMatrix::zeros(self.z.len(), n);
        for j in 0..n {
            let h = JACOBIAN_STEP * self.params[j].abs().max(1.0);
            let mut shifted = self.clone();
            shifted.params[j] += h;
            let plus = shifted.residuals()?;
            shifted.params[j] -= 2.0 * h;
            let minus = shifted.residuals()?;
            jacobian.set_column(j, &((plus - minus) / (2.0 * h)));
        }
        Some(jacobian)
    }
}

/// Reads two numeric columns, skipping lines that are not two numbers.
fn read_curve(path: &Path) -> Result<(Vec<f64>, Vec<f64>)> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let (mut z, mut f) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let fields: Vec<&str> = line
            .split([',', ';', '\t', ' '])
            .filter(|s| !s.is_empty())
            .collect();
        if let [a, b] = fields[..] {
            if let (Ok(a), Ok(b)) = (a.parse::<f64>(), b.parse::<f64>()) {
                if !(a.is_finite() && b.is_finite()) {
                    return Err(format!("{}: a value is not finite: {line}", path.display()).into());
                }
                z.push(a);
                f.push(b);
            }
        }
    }
    if z.len() < 4 {
        return Err(format!(
            "{}: {} rows of two numbers; at least 4 are needed",
            path.display(),
            z.len()
        )
        .into());
    }
    Ok((z, f))
}

/// The comma-separated numbers of `text`; a number that does not parse is
/// reported with what was `expected`.
fn numbers(text: &str, expected: &str) -> std::result::Result<Vec<f64>, String> {
    text.split(',')
        .map(|v| v.trim().parse::<f64>())
        .collect::<std::result::Result<_, _>>()
        .map_err(|e| format!("{text}: {e}; expected {expected}"))
}

/// `LO,HI` of a range of moduli.
fn range(text: &str) -> std::result::Result<(f64, f64), String> {
    let values = numbers(text, "LO,HI (Pa)")?;
    match values[..] {
        [lo, hi] if lo > 0.0 && lo < hi && hi.is_finite() => Ok((lo, hi)),
        _ => Err(format!("{text}: expected LO,HI with 0 < LO < HI (Pa)")),
    }
}

/// `E,nu,thickness` of a layer under the film.
fn layer(text: &str) -> std::result::Result<(f64, f64, f64), String> {
    let values = numbers(text, "E,nu,thickness")?;
    match values[..] {
        [e, nu, t] => Ok((e, nu, t)),
        _ => Err(format!("{text}: expected three numbers E,nu,thickness")),
    }
}

fn positive(name: &str, value: Option<f64>) -> Result<f64> {
    match value {
        Some(v) if v > 0.0 && v.is_finite() => Ok(v),
        Some(v) => Err(format!("--{name} {v}: expected a positive number").into()),
        None => Err(format!("--{name} is needed for this tip").into()),
    }
}

pub(crate) fn fit(args: &FitArgs) -> Result<()> {
    let (mut z, mut force) = read_curve(&args.curve)?;
    if let Some(k) = args.spring_constant {
        let k = positive("spring-constant", Some(k))?;
        for (z, f) in z.iter_mut().zip(&force) {
            *z -= f / k;
        }
    }
    let adhesive = match args.segment.as_str() {
        "approach" => false,
        "retract" => true,
        other => return Err(format!("--segment {other}: expected approach or retract").into()),
    };
    if adhesive {
        let keep = before_jump_off(&z, &force);
        z = z.iter().zip(&keep).filter(|k| *k.1).map(|k| *k.0).collect();
        force = force
            .iter()
            .zip(&keep)
            .filter(|k| *k.1)
            .map(|k| *k.0)
            .collect();
        if z.len() < 4 {
            return Err("retract segment: fewer than 4 points before the pull-off".into());
        }
    }
    let tip = match args.tip.as_str() {
        "paraboloid" => Some(Tip::Paraboloid {
            radius: positive("radius", args.radius)?,
        }),
        "sphere" => Some(Tip::Sphere {
            radius: positive("radius", args.radius)?,
        }),
        "cone" => Some(Tip::Cone {
            half_angle: positive("half-angle", args.half_angle)?.to_radians(),
        }),
        "rounded-cone" => Some(Tip::RoundedCone {
            half_angle: positive("half-angle", args.half_angle)?.to_radians(),
            tip_radius: positive("radius", args.radius)?,
        }),
        "flat-punch" => None,
        other => {
            return Err(format!(
                "--tip {other}: expected paraboloid, sphere, cone, rounded-cone or flat-punch"
            )
            .into())
        }
    };
    let radius = match tip {
        Some(Tip::Cone { .. }) => f64::NAN,
        _ => positive("radius", args.radius)?,
    };
    let modulus = positive("modulus", Some(args.modulus))?;
    let span = z.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - z.iter().copied().fold(f64::INFINITY, f64::min);
    let deepest = z.iter().copied().fold(f64::NEG_INFINITY, f64::max) - args.contact_point;
    let base = args
        .base_modulus
        .map(|e| Material::new(e, args.base_poisson))
        .transpose()?;
    let sample = Sample {
        thickness: args.thickness,
        poisson: args.poisson,
        base,
        below: args.below.clone(),
        unbonded: args.unbonded,
    };
    let max_depth = (deepest + 0.5 * span).max(f64::MIN_POSITIVE);
    let table = build_table(&sample, tip, radius, max_depth, modulus)?;
    let family = match args.modulus_range {
        Some(range) if !sample.scales() => Some(ModulusFamily::new(
            &sample.substrate(modulus)?,
            tip,
            radius,
            max_depth,
            range,
            FAMILY_NODES,
        )?),
        _ => None,
    };
    let model = Model {
        sample,
        tip,
        radius,
        max_depth,
        table,
        table_modulus: modulus,
        family,
    };
    let force_unit = force
        .iter()
        .map(|f| f.abs())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let work = positive("work", Some(args.work))?;
    // (parameter, unit, start): the positive quantities in units of their
    // starts, the contact point in units of the curve's span.
    let mut fitted = vec![
        (Param::Modulus, modulus, modulus),
        (Param::ContactPoint, span, args.contact_point),
    ];
    if adhesive {
        fitted.push((Param::Work, work, work));
    }
    if args.fit_thickness {
        let h = args
            .thickness
            .ok_or("--fit-thickness starts from --thickness")?;
        fitted.push((Param::Thickness, h, h));
    }
    if args.fit_base_modulus {
        let e = base
            .map(|b| b.youngs_modulus())
            .ok_or("--fit-base-modulus starts from --base-modulus")?;
        fitted.push((Param::BaseModulus, e, e));
    }
    let start = fitted
        .iter()
        .map(|&(param, unit, start)| param.scaled(start, unit))
        .collect();
    let params: Vec<Param> = fitted.iter().map(|f| f.0).collect();
    let problem = Problem {
        model: &model,
        z: &z,
        force: &force,
        fitted: &params,
        unit: fitted.iter().map(|f| f.1).collect(),
        params: DVector::from_vec(start),
        force_unit,
    };
    let (problem, report) = LevenbergMarquardt::new().minimize(problem);
    if !report.termination.was_successful() {
        return Err(format!("the fit did not converge: {:?}", report.termination).into());
    }
    let residuals = problem
        .residuals()
        .ok_or("the model is not finite at the fit")?;
    let jacobian = problem.jacobian().ok_or("no Jacobian at the fit")?;
    let dof = (z.len() - problem.params.len()).max(1) as f64;
    let variance = residuals.norm_squared() / dof;
    let covariance = (jacobian.transpose() * &jacobian)
        .try_inverse()
        .ok_or("the parameters are not determined by the curve (singular normal matrix)")?;
    for (k, param) in params.iter().enumerate() {
        let slope = param.slope(problem.params[k], problem.unit[k]);
        let stderr = (covariance[(k, k)] * variance).sqrt() * slope;
        say!(
            "{:>26} = {:.6e} +- {:.2e}",
            param.name(),
            problem.value_of(k),
            stderr
        );
    }
    say!(
        "{} points, {} model evaluations, rms residual {:.3e} N",
        z.len(),
        report.number_of_evaluations,
        (residuals.norm_squared() / z.len() as f64).sqrt() * force_unit
    );
    std::fs::create_dir_all(&args.out)
        .map_err(|e| format!("cannot create {}: {e}", args.out.display()))?;
    let fitted = problem.model();
    let mut csv = String::from("position_m,force_N,model_N,residual_N\n");
    for ((z, f), m) in z.iter().zip(&force).zip(&fitted) {
        csv.push_str(&format!("{z:.9e},{f:.9e},{m:.9e},{:.9e}\n", f - m));
    }
    let path = args.out.join("fit.csv");
    std::fs::write(&path, csv).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    say!("wrote {}", path.display());
    Ok(())
}
