//! Force curves over a range of top-layer moduli, for fits on supports
//! where the force does not scale with the modulus (an elastic base, a
//! stack): a few exact tables at Chebyshev nodes in `ln E`, interpolated.

use crate::error::{Error, Result};
use crate::substrate::Substrate;

use super::curve::Branch;
use super::{ForceCurve, Tip};

/// The fewest and most Chebyshev nodes a [`ModulusFamily`] may have.
pub const MODULUS_NODES: (usize, usize) = (4, 64);

/// The force curves (approach and retract) of one tip on a body whose top
/// layer's Young's modulus ranges over `[lo, hi]`, the rest fixed
/// ([`Substrate::with_surface_youngs_modulus`]): exact tables
/// ([`ForceCurve`]) at `n` Chebyshev nodes of the second kind in `ln E`, on
/// one set of contact radii, and at any modulus in the range the table
/// whose columns (depth, force and punch stiffness per unit `E*`, edge
/// factor) are the barycentric interpolants (Berrut & Trefethen 2004, SIAM
/// Rev. 46, 501) of the nodes' at each contact radius
/// ([`curve`](Self::curve)). They are analytic in `ln E` (the contact
/// moves from the support-dominated to the layer-dominated limit over a
/// decade or two), so the error falls geometrically with `n`;
/// `tests/force_curve.rs` measures it, with and without adhesion. On glass
/// or a half-space a single [`ForceCurve`] scales exactly and needs no
/// family.
///
/// A fit on an elastic support otherwise builds a table per modulus it
/// tries (0.3 to 3 s each); a force map of many curves on one sample
/// builds the family once and then evaluates a curve at the cost of one
/// table's (`cargo bench --bench axisymmetric`, `BENCHMARKS.md`).
///
/// ```
/// use layered_contact::analytic::{Axisymmetric, ForceCurve, ModulusFamily, Tip};
/// use layered_contact::{Material, Substrate};
///
/// let gel = Material::new(2.5e3, 0.5)?;
/// let film = Substrate::layer_on_elastic_base(Material::new(1e4, 0.5)?, 4e-6, gel)?;
/// let tip = Tip::Paraboloid { radius: 5e-6 };
/// let family = ModulusFamily::new(&film, Some(tip), 5e-6, 2e-6, (5e3, 20e3), 12)?;
/// let direct = ForceCurve::on(&film.with_surface_youngs_modulus(8e3)?, tip, 2e-6)?;
/// let (f, g) = (family.forces(&[1e-6], 8e3)[0], direct.force(1e-6, 1.0, 0.0));
/// assert!((f / g - 1.0).abs() < 1e-6);
/// // Retract curves too (work of adhesion 1 mJ/m^2):
/// let retract = family.curve(8e3)?.force(-0.1e-6, 1.0, 1e-3);
/// assert!((retract / direct.force(-0.1e-6, 1.0, 1e-3) - 1.0).abs() < 1e-6);
/// # Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct ModulusFamily {
    /// `ln E` of the nodes, and the range's ends.
    nodes: Vec<f64>,
    range: (f64, f64),
    /// The barycentric weights of the nodes.
    weights: Vec<f64>,
    curves: Vec<ForceCurve>,
}

impl ModulusFamily {
    /// The family of `tip` (a flat punch of `radius`, m, if `None`; the
    /// radius is unused otherwise) on `body` with its top layer's Young's
    /// modulus anywhere in `youngs_range` (Pa), to `max_depth` (m), from
    /// `nodes` exact tables. Twelve nodes per decade of modulus reach the
    /// tables' own precision on a film over a softer gel and on a stack
    /// (`tests/force_curve.rs`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a range that is not `0 < lo < hi <
    /// inf` or a node count outside [`MODULUS_NODES`]; the errors of
    /// [`Substrate::with_surface_youngs_modulus`] and of
    /// [`ForceCurve::on`] at any node.
    pub fn new(
        body: &Substrate,
        tip: Option<Tip>,
        radius: f64,
        max_depth: f64,
        youngs_range: (f64, f64),
        nodes: usize,
    ) -> Result<Self> {
        let (lo, hi) = youngs_range;
        if !(lo > 0.0 && lo < hi && hi.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "youngs_range (lower end)",
                value: lo,
                expected: "0 < lower < upper < inf (Pa)",
            });
        }
        crate::error::within(
            "nodes of a modulus family",
            nodes as f64,
            (MODULUS_NODES.0 as f64, MODULUS_NODES.1 as f64),
            "between 4 and 64",
        )?;
        let (a, b) = (lo.ln(), hi.ln());
        let last = nodes - 1;
        let x: Vec<f64> = (0..nodes)
            .map(|k| {
                let c = (std::f64::consts::PI * k as f64 / last as f64).cos();
                0.5 * (a + b) + 0.5 * (b - a) * c
            })
            .collect();
        // Chebyshev points of the second kind: weights (-1)^k, halved at the ends.
        let weights = (0..nodes)
            .map(|k| {
                let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                if k == 0 || k == last {
                    0.5 * sign
                } else {
                    sign
                }
            })
            .collect();
        let substrates = x
            .iter()
            .map(|&ln_e| body.with_surface_youngs_modulus(ln_e.exp()))
            .collect::<Result<Vec<_>>>()?;
        let curves = match tip {
            None => substrates
                .iter()
                .map(|substrate| ForceCurve::flat_punch_on(substrate, radius))
                .collect::<Result<Vec<_>>>()?,
            Some(tip) => {
                // One set of radii for every node, wide enough for the
                // node that needs the widest, so that the tables combine
                // at each contact radius.
                let exact = substrates
                    .iter()
                    .map(|substrate| {
                        let exact = ForceCurve::exact_on(substrate, tip, max_depth)?;
                        let branch = Branch::new(&exact, tip)?;
                        Ok((exact, branch))
                    })
                    .collect::<Result<Vec<_>>>()?;
                let mut largest: f64 = 0.0;
                for (e, branch) in &exact {
                    largest = largest.max(ForceCurve::largest_radius(e, branch, tip, max_depth)?);
                }
                exact
                    .iter()
                    .map(|(e, branch)| ForceCurve::tabulate(e, branch, tip, largest, max_depth))
                    .collect::<Result<Vec<_>>>()?
            }
        };
        Ok(ModulusFamily {
            nodes: x,
            range: (lo, hi),
            weights,
            curves,
        })
    }

    /// The range of Young's moduli covered, Pa.
    pub fn youngs_range(&self) -> (f64, f64) {
        self.range
    }

    /// The table at Young's modulus `youngs_modulus` (Pa) of the top layer:
    /// at each contact radius of the tables, the barycentric interpolant in
    /// `ln E` of the non-adhesive depth, the force and the punch stiffness
    /// per unit `E*`, and the punch's edge factor. Its curves, with or
    /// without adhesion ([`ForceCurve::forces`] with ratio 1), cost what a
    /// single table's do.
    ///
    /// Interpolating at fixed contact radius rather than at fixed depth
    /// serves retract curves too: the JKR state at a radius follows from
    /// these columns alone, while the nodes' branches end at different
    /// depths.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a modulus outside
    /// [`youngs_range`](Self::youngs_range) or an interpolated table that
    /// is not positive and finite where it must be.
    pub fn curve(&self, youngs_modulus: f64) -> Result<ForceCurve> {
        let (lo, hi) = self.range;
        if !(youngs_modulus >= lo && youngs_modulus <= hi) {
            return Err(Error::InvalidParameter {
                name: "youngs_modulus",
                value: youngs_modulus,
                expected: "within the family's youngs_range (Pa)",
            });
        }
        let x = youngs_modulus.ln();
        // The node itself, or the barycentric coefficients.
        let exact = self.nodes.iter().position(|&node| node == x);
        let coefficients: Vec<f64> = match exact {
            Some(k) => (0..self.nodes.len())
                .map(|j| if j == k { 1.0 } else { 0.0 })
                .collect(),
            None => {
                let raw: Vec<f64> = self
                    .nodes
                    .iter()
                    .zip(&self.weights)
                    .map(|(node, w)| w / (x - node))
                    .collect();
                let sum: f64 = raw.iter().sum();
                raw.iter().map(|r| r / sum).collect()
            }
        };
        // E* of the modulus wanted: E*/E*_node = E / E_node (one Poisson
        // ratio).
        let modulus = self.curves[0].contact_modulus() * (x - self.nodes[0]).exp();
        ForceCurve::combine(&self.curves, &coefficients, modulus).ok_or(Error::InvalidParameter {
            name: "youngs_modulus",
            value: youngs_modulus,
            expected: "a modulus whose interpolated table is positive and finite",
        })
    }

    /// The deepest indentation (m) whose force the family gives at
    /// `youngs_modulus` (Pa) with `work_of_adhesion` (J/m^2): see
    /// [`ForceCurve::reach`]. NaN outside the range.
    pub fn reach(&self, youngs_modulus: f64, work_of_adhesion: f64) -> f64 {
        self.curve(youngs_modulus)
            .map_or(f64::NAN, |curve| curve.reach(1.0, work_of_adhesion))
    }

    /// The approach force (N) at each of `depths` (m) for a top layer of
    /// Young's modulus `youngs_modulus` (Pa): NaN outside the range, and
    /// where a table gives NaN (beyond its depth). See
    /// [`curve`](Self::curve).
    pub fn forces(&self, depths: &[f64], youngs_modulus: f64) -> Vec<f64> {
        self.adhesive_forces(depths, youngs_modulus, 0.0)
    }

    /// The force (N) at each of `depths` (m) for a top layer of Young's
    /// modulus `youngs_modulus` (Pa) and work of adhesion
    /// `work_of_adhesion` (J/m^2), along the fixed-grips branch (as
    /// [`ForceCurve::forces`]): NaN outside the range, for a negative work
    /// and beyond the tables' depth.
    pub fn adhesive_forces(
        &self,
        depths: &[f64],
        youngs_modulus: f64,
        work_of_adhesion: f64,
    ) -> Vec<f64> {
        match self.curve(youngs_modulus) {
            Ok(curve) => curve.forces(depths, 1.0, work_of_adhesion),
            Err(_) => vec![f64::NAN; depths.len()],
        }
    }
}

impl ForceCurve {
    /// The table whose columns are `sum_k c_k` of the `curves`' (tables on
    /// the same radii, or flat punches of one radius), the forces and
    /// stiffnesses per unit of each table's contact modulus and then times
    /// `contact_modulus` (Pa): the interpolant of a family of tables at one
    /// modulus. `None` unless the tables share their radii and the result
    /// is positive and finite where the tables' logarithms are needed.
    pub(super) fn combine(
        curves: &[ForceCurve],
        coefficients: &[f64],
        contact_modulus: f64,
    ) -> Option<ForceCurve> {
        let first = curves.first()?;
        let n = first.radius.len();
        let mut out = ForceCurve {
            contact_modulus,
            tip: first.tip,
            log_radius: first.log_radius.clone(),
            radius: first.radius.clone(),
            depth: vec![0.0; n],
            force: vec![0.0; n],
            log_depth: Vec::new(),
            log_force: Vec::new(),
            stiffness: vec![0.0; n],
            edge: vec![0.0; n],
            max_depth: first.max_depth,
        };
        for (curve, &c) in curves.iter().zip(coefficients) {
            if curve.radius != first.radius || curve.tip != first.tip {
                return None;
            }
            if c == 0.0 {
                continue;
            }
            let per_modulus = c * contact_modulus / curve.contact_modulus;
            for k in 0..n {
                out.depth[k] += c * curve.depth[k];
                out.force[k] += per_modulus * curve.force[k];
                out.stiffness[k] += per_modulus * curve.stiffness[k];
                out.edge[k] += c * curve.edge[k];
            }
            out.max_depth = out.max_depth.min(curve.max_depth);
        }
        if out.tip.is_some() {
            out.log_depth = out.depth.iter().map(|d| d.ln()).collect();
            out.log_force = out.force.iter().map(|f| f.ln()).collect();
        }
        let finite = [&out.log_depth, &out.log_force, &out.stiffness, &out.edge]
            .iter()
            .all(|column| column.iter().all(|v| v.is_finite()));
        finite.then_some(out)
    }
}
