//! The exact model a fit evaluates: the sample, one table at the starting
//! modulus rescaled where the force scales with it, a family of tables
//! over a range of moduli where it does not (`--modulus-range`), or a table
//! per modulus, thickness or support modulus tried.

use layered_contact::analytic::{ForceCurve, ModulusFamily, Tip};
use layered_contact::{Base, Material, Substrate};

use crate::Result;

/// The model's inputs at one set of parameters.
#[derive(Clone, Copy, Debug)]
pub(super) struct Values {
    pub(super) modulus: f64,
    pub(super) contact: f64,
    pub(super) work: f64,
    pub(super) thickness: Option<f64>,
    /// Young's modulus of the elastic support.
    pub(super) base_modulus: Option<f64>,
}

/// The exact model: one table at the starting modulus, rescaled on glass
/// or a half-space (and used as it is at that modulus elsewhere); rebuilt
/// for each other modulus on an elastic support or a stack, and for each
/// thickness or support modulus when they are fitted.
pub(super) struct Model {
    pub(super) sample: Sample,
    pub(super) tip: Option<Tip>,
    pub(super) radius: f64,
    pub(super) max_depth: f64,
    pub(super) table: ForceCurve,
    pub(super) table_modulus: f64,
    /// The approach curves over a range of moduli, when asked for.
    pub(super) family: Option<ModulusFamily>,
}

pub(super) struct Sample {
    pub(super) thickness: Option<f64>,
    pub(super) poisson: f64,
    pub(super) base: Option<Material>,
    pub(super) below: Vec<(f64, f64, f64)>,
    pub(super) unbonded: bool,
}

impl Sample {
    /// Whether the force scales with the film's modulus (one layer on
    /// glass, or a half-space).
    pub(super) fn scales(&self) -> bool {
        self.base.is_none() && self.below.is_empty()
    }

    /// The `--below` layers, top first.
    fn below_layers(&self) -> Result<Vec<(Material, f64)>> {
        self.below
            .iter()
            .map(|&(e, nu, t)| Ok((Material::new(e, nu)?, t)))
            .collect()
    }

    /// What the layers rest on: glass, or the elastic support.
    fn support_base(&self) -> Base {
        self.base.map_or(Base::Rigid, Base::Elastic)
    }

    pub(super) fn substrate(&self, modulus: f64) -> Result<Substrate> {
        let film = Material::new(modulus, self.poisson)?;
        if self.unbonded {
            let h = self
                .thickness
                .ok_or("--unbonded: the resting film needs its --thickness")?;
            if !self.below.is_empty() {
                let support = Substrate::stack(&self.below_layers()?, self.support_base())?;
                return Ok(Substrate::layer_resting_on(film, h, &support)?);
            }
            return Ok(match self.base {
                None => Substrate::layer_resting_on_rigid_base(film, h)?,
                Some(base) => Substrate::layer_resting_on_elastic_base(film, h, base)?,
            });
        }
        if !self.below.is_empty() {
            let h = self
                .thickness
                .ok_or("--below needs the film's --thickness")?;
            let mut layers = vec![(film, h)];
            layers.extend(self.below_layers()?);
            return Ok(Substrate::stack(&layers, self.support_base())?);
        }
        Ok(match (self.thickness, self.base) {
            (None, _) => Substrate::half_space(film),
            (Some(h), None) => Substrate::layer_on_rigid_base(film, h)?,
            (Some(h), Some(base)) => Substrate::layer_on_elastic_base(film, h, base)?,
        })
    }
}

/// The table of `tip` (a flat punch of `radius` if `None`) on `sample`
/// with a film of `modulus`, to `max_depth`.
pub(super) fn build_table(
    sample: &Sample,
    tip: Option<Tip>,
    radius: f64,
    max_depth: f64,
    modulus: f64,
) -> Result<ForceCurve> {
    let substrate = sample.substrate(modulus)?;
    Ok(match tip {
        Some(tip) => ForceCurve::on(&substrate, tip, max_depth)?,
        None => ForceCurve::flat_punch_on(&substrate, radius)?,
    })
}

/// How many times a table is rebuilt twice as deep when an adhesive curve
/// does not reach the model's depth (`ForceCurve::reach`).
const DEEPER_TABLES: usize = 6;

impl Model {
    /// The model's forces at `depths` (m) for the parameters `v`: NaN only
    /// where no exact table reaches (a depth beyond the model's, or
    /// adhesion so strong that tables [`DEEPER_TABLES`] times twice as deep
    /// still end above it).
    pub(super) fn forces(&self, depths: &[f64], v: &Values) -> Vec<f64> {
        let out = self.forces_from_tables(depths, v);
        let short = |forces: &[f64]| {
            forces
                .iter()
                .zip(depths)
                .any(|(f, d)| f.is_nan() && *d <= self.max_depth)
        };
        if !short(&out) {
            return out;
        }
        // Adhesion lifts the indenter at a given contact radius: the
        // tables end above the deepest points. Deeper ones, built here.
        let mut depth = self.max_depth;
        for _ in 0..DEEPER_TABLES {
            depth *= 2.0;
            let Ok(table) = self.table_for(v, depth) else {
                break;
            };
            let forces = table.forces(depths, 1.0, v.work);
            if !short(&forces) {
                return forces;
            }
        }
        out
    }

    fn forces_from_tables(&self, depths: &[f64], v: &Values) -> Vec<f64> {
        let base = self.sample.base;
        let fixed = v.thickness == self.sample.thickness
            && v.base_modulus == base.map(|b| b.youngs_modulus());
        if fixed && (self.sample.scales() || v.modulus == self.table_modulus) {
            return self
                .table
                .forces(depths, v.modulus / self.table_modulus, v.work);
        }
        if let Some(family) = &self.family {
            let (lo, hi) = family.youngs_range();
            if fixed && (lo..=hi).contains(&v.modulus) {
                return family.adhesive_forces(depths, v.modulus, v.work);
            }
        }
        match self.table_for(v, self.max_depth) {
            Ok(table) => table.forces(depths, 1.0, v.work),
            Err(_) => vec![f64::NAN; depths.len()],
        }
    }

    /// The exact table at the parameters `v` to `max_depth`.
    fn table_for(&self, v: &Values, max_depth: f64) -> Result<ForceCurve> {
        let base = self.sample.base;
        // The support's Poisson ratio stays as given.
        let base = match (base, v.base_modulus) {
            (Some(b), Some(e)) => Some(Material::new(e, b.poisson_ratio())?),
            _ => base,
        };
        let sample = Sample {
            thickness: v.thickness,
            base,
            below: self.sample.below.clone(),
            ..self.sample
        };
        build_table(&sample, self.tip, self.radius, max_depth, v.modulus)
    }
}
