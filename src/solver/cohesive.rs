//! Adhesive contact in the JKR limit through a cohesive zone resolved on the
//! grid: a short-range adhesive law whose range shrinks with the cell, so
//! that its zone spans a fixed number of cells and the solution tends to
//! the JKR limit as the grid is refined, for any contact shape.
//!
//! The law (energy per unit area of a gap `g`, `w(g) = -dgamma (1 -
//! g/rho)^2` for `g < rho`, zero beyond) pulls with the tension `sigma(g) =
//! -(2 dgamma / rho)(1 - g/rho)`; its zone, where the gap is open but below
//! `rho`, is `E* rho^2 / (4 dgamma)` long (Maugis 1992, J. Colloid
//! Interface Sci. 150, 243, for Dugdale's law; the same scale for this
//! one). With the range `rho = 2 sqrt(dgamma k Delta / E*)` it spans `k`
//! cells. The JKR limit is the zone's vanishing width: `G = dgamma` holds
//! at every point of every edge without the edge being located.
//!
//! Each equilibrium is a fixed point: for given tensions `t` (one per cell,
//! from the gaps) the contact is the non-adhesive one of the profile
//! shifted by their displacement, `f + K t`, solved by the constrained
//! conjugate gradients for the compressive part `p' = p - t >= 0`; the
//! gaps of that solution give new tensions. The map contracts at a rate of
//! about `1 / (2 pi)` set by the law's negative stiffness `2 dgamma /
//! rho^2` against the compliance over a zone; near a pull-off (a fold of
//! the equilibrium branch) it slows down, and beyond it the iteration
//! walks the contact off, as the quasi-static jump does.

use std::borrow::Cow;

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::cohesive_steps::Stepper;
use super::polonsky_keer::Control;
use super::{check_finite, ContactSolver, Observer, Solution, WarmStart};

/// The default width of the cohesive zone, in cells.
///
/// Chosen by measurement (`examples/cohesive_convergence`, default
/// curvature correction; `BENCHMARKS.md`, "The cohesive zone's width"): the
/// pull-off error is a function of the zone's length against the contact,
/// so a narrower zone is a finer grid, until the lattice traps the few
/// cells that carry it. JKR sphere on a half-space at 16, 32, 64 cells
/// across the pull-off contact: -6.39, -2.42, -0.66 % with 8 cells, -4.17,
/// -1.43, -0.39 % with 6, -3.37, -1.12, -0.27 % with 5, -1.95, -0.61,
/// -0.13 % with 4. Johnson's sinusoid at 128, 181, 256 cells per
/// wavelength, along the grid / at 45 degrees, worst of the two: 1.75,
/// 0.91, 0.57 % with 8, 0.61, 0.34, 0.12 % with 4 (the two orientations
/// then differ by up to 0.95 % at 128, against 0.09 % with 8: lattice
/// trapping, but each nearer the limit). An elliptic paraboloid against
/// the energy balance at 16, 32, 64 cells: -4.58, -1.41, -0.37 % with 8,
/// -1.55, -0.25, -0.049 % with 4. About 1.5 times the iterations of 8
/// cells on the sphere at 64 cells across.
pub const COHESIVE_ZONE_CELLS: f64 = 4.0;

/// The default first-order correction of the zone's bias on curved edges
/// ([`CohesiveZone::with_curvature_correction`]): measured on the JKR
/// sphere, whose pull-off error without it is `0.20 l / a` as the zone
/// `l` shrinks against the contact radius `a` (+2.26, +4.06 % at `l / a`
/// = 1/8, 1/4; Maugis-Dugdale theory gives `0.17 (c - a) / a`), the same
/// on a layer (+4.06 % at 1/4), and zero on straight edges (Johnson's
/// sinusoid: second order without it).
pub const CURVATURE_CORRECTION: f64 = 0.2;

/// The longest cohesive zone on a layer, as a fraction of the top layer's
/// thickness ([`CohesiveZone::cells_on`]): the JKR limit needs the zone
/// short against every length of the body, and a zone of [`COHESIVE_ZONE_CELLS`]
/// cells as long as the thickness of the film under it behaves as a softer
/// (Maugis-Dugdale) law. Measured on the sphere on a film on a rigid base a
/// quarter of the half-space's pull-off radius thick, `N` = 64 and 128
/// cells across that radius's contact (the film 8 and 16 cells thick),
/// pull-off errors against the zone's length `l`: -2.28 % at `l = h`,
/// +0.22 % and +0.95 % at `h/2`, +0.060 % and +0.014 % at `h/4`, and
/// +0.054 % at `h/8` (a zone of two cells, coarse in its own right).
pub const ZONE_LAYER_FRACTION: f64 = 0.25;

/// The fewest cells a cohesive zone may span.
const MIN_ZONE_CELLS: f64 = 2.0;

/// The largest change of the cells' curvature factors (as their square
/// roots, weighted by the tensions they scale) between the contact a solve
/// started from and the one it converged to that is left unread
/// ([`ContactSolver::solve_depth_cohesive`]).
const ROOT_TOLERANCE: f64 = 2e-3;

/// Times one solve reads its curvature again from a converged contact.
const MAX_REREADS: usize = 8;

/// Fixed-point rounds of one cohesive solve before it gives up.
const MAX_ROUNDS: usize = 2000;

/// A short-range adhesive law whose range shrinks with the cell: the JKR
/// limit for any contact shape ([`ContactSolver::solve_depth_cohesive`]).
///
/// ```
/// use layered_contact::solver::CohesiveZone;
///
/// let law = CohesiveZone::new(0.05, 0.05)?.with_zone_cells(8.0)?;
/// // On 1 um cells of a rubber of E* = 1 MPa: rho = 2 sqrt(dgamma k Delta / E*).
/// let rho = law.range(0.05, 1e-6, 1e6);
/// assert!((rho - 2.0 * (0.05 * 8.0 * 1e-6 / 1e6f64).sqrt()).abs() < 1e-18);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CohesiveZone {
    advancing: f64,
    receding: f64,
    zone_cells: f64,
    curvature_correction: f64,
}

impl CohesiveZone {
    /// The law for the advancing (loading, `dgamma0`) and receding
    /// (unloading, `dgamma1 >= dgamma0`) works of adhesion, J/m^2, with a
    /// zone of [`COHESIVE_ZONE_CELLS`] cells and the curvature correction
    /// [`CURVATURE_CORRECTION`]. A cell bonds when it touches
    /// and then holds with `dgamma1` until its gap exceeds the receding
    /// range; a cell that has not touched pulls with `dgamma0`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a negative or non-finite work of
    /// adhesion or `advancing > receding`.
    pub fn new(advancing: f64, receding: f64) -> Result<Self> {
        let (advancing, receding) = crate::error::works_of_adhesion(advancing, receding)?;
        Ok(CohesiveZone {
            advancing,
            receding,
            zone_cells: COHESIVE_ZONE_CELLS,
            curvature_correction: CURVATURE_CORRECTION,
        })
    }

    /// The same law with a zone of `cells` cells (2 to 256): wider zones
    /// leave less lattice trapping and converge later.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside `[2, 256]`.
    pub fn with_zone_cells(self, cells: f64) -> Result<Self> {
        if !(2.0..=256.0).contains(&cells) {
            return Err(Error::InvalidParameter {
                name: "cohesive zone width (cells)",
                value: cells,
                expected: "in [2, 256]",
            });
        }
        Ok(CohesiveZone {
            zone_cells: cells,
            ..self
        })
    }

    /// The same law with the zone's first-order bias on curved edges taken
    /// out: each cell pulls with `dgamma / (1 + c kappa l)`, `kappa` the
    /// curvature of the contact's edge near it and `l` the zone's length
    /// (`c` = 0 leaves the law as it is; default [`CURVATURE_CORRECTION`]).
    /// The curvature is that of the contact's cells smoothed over the zone,
    /// taken at the first round of each solve (for a load step, the
    /// contact of the last one, moved by the step) and held while the
    /// fixed point converges; then read again from the converged contact,
    /// and the fixed point resumed, while the factors (as their square
    /// roots, weighted by the tensions they scale) move by more than 2e-3
    /// (at most eight times): a long step that moves the edge by many
    /// cells gets the curvature of the contact it reaches.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside `[0, 1]`.
    pub fn with_curvature_correction(self, c: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&c) {
            return Err(Error::InvalidParameter {
                name: "cohesive zone curvature correction",
                value: c,
                expected: "in [0, 1]",
            });
        }
        Ok(CohesiveZone {
            curvature_correction: c,
            ..self
        })
    }

    /// The advancing work of adhesion, J/m^2.
    pub fn advancing(&self) -> f64 {
        self.advancing
    }

    /// The receding work of adhesion, J/m^2.
    pub fn receding(&self) -> f64 {
        self.receding
    }

    /// The zone's width in cells.
    pub fn zone_cells(&self) -> f64 {
        self.zone_cells
    }

    /// The zone's width in cells on a grid of `spacing` (m) over a body
    /// whose top layer is `top_thickness` (m) thick (`None`: a half-space):
    /// [`zone_cells`](Self::zone_cells), but no longer than
    /// [`ZONE_LAYER_FRACTION`] of the layer and no shorter than two cells.
    /// [`ContactSolver::solve_depth_cohesive`] solves with this width.
    ///
    /// ```
    /// use layered_contact::solver::CohesiveZone;
    ///
    /// let zone = CohesiveZone::new(0.05, 0.05)?;
    /// assert_eq!(zone.cells_on(1e-6, None), 4.0);
    /// assert_eq!(zone.cells_on(1e-6, Some(1e-4)), 4.0);
    /// assert!((zone.cells_on(1e-6, Some(1.2e-5)) - 3.0).abs() < 1e-12);
    /// assert_eq!(zone.cells_on(1e-6, Some(2e-6)), 2.0);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn cells_on(&self, spacing: f64, top_thickness: Option<f64>) -> f64 {
        match top_thickness {
            Some(h) => self
                .zone_cells
                .min((ZONE_LAYER_FRACTION * h / spacing).max(MIN_ZONE_CELLS)),
            None => self.zone_cells,
        }
    }

    /// Whether a zone of [`cells_on`](Self::cells_on) cells is within
    /// [`ZONE_LAYER_FRACTION`] of the top layer's thickness: false when
    /// the layer is thinner than eight cells (the zone of two cells is then
    /// longer than a quarter of it and the pull-off biased, by -0.8 % at
    /// half the thickness and -4.6 % at the whole, measured as in
    /// [`ZONE_LAYER_FRACTION`]).
    ///
    /// ```
    /// use layered_contact::solver::CohesiveZone;
    ///
    /// let zone = CohesiveZone::new(0.05, 0.05)?;
    /// assert!(zone.resolves_layer(1.9182e-5, None));
    /// // A zone of exactly a quarter of the film (2.6 cells) resolves it.
    /// assert!(zone.resolves_layer(1.9182e-5, Some(2e-4)));
    /// assert!(!zone.resolves_layer(1.9182e-5, Some(1.5e-4)));
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn resolves_layer(&self, spacing: f64, top_thickness: Option<f64>) -> bool {
        // In cells, as `cells_on` compares: a zone of `cells_on` cells is
        // within the quarter unless that quarter is under the fewest cells.
        top_thickness.is_none_or(|h| ZONE_LAYER_FRACTION * h / spacing >= MIN_ZONE_CELLS)
    }

    /// The law's range `rho = 2 sqrt(dgamma k Delta / E*)` (m) for a work
    /// of adhesion `work` on cells of `spacing` (m) of a surface of contact
    /// modulus `contact_modulus` (Pa).
    pub fn range(&self, work: f64, spacing: f64, contact_modulus: f64) -> f64 {
        2.0 * (work * self.zone_cells * spacing / contact_modulus).sqrt()
    }
}

/// One work of adhesion's law on this grid: the peak tension and the range.
#[derive(Clone, Copy)]
struct Law {
    peak: f64,
    range: f64,
}

impl Law {
    fn new(zone: &CohesiveZone, work: f64, spacing: f64, modulus: f64) -> Self {
        let range = zone.range(work, spacing, modulus);
        let peak = if range > 0.0 { 2.0 * work / range } else { 0.0 };
        Law { peak, range }
    }

    /// The law of `root^2` times the work of adhesion over the same zone
    /// (its peak and range scale with `root`).
    fn scaled(&self, root: f64) -> Law {
        Law {
            peak: self.peak * root,
            range: self.range * root,
        }
    }

    /// The tension (Pa, `<= 0`) at a gap `g >= 0`.
    fn tension(&self, g: f64) -> f64 {
        if g < self.range {
            -self.peak * (1.0 - g / self.range)
        } else {
            0.0
        }
    }
}

impl ContactSolver {
    /// Each cell's curvature factor of `zone`'s law, as its square root,
    /// from the cells in `contact`.
    fn curvature_roots(&self, contact: &[bool], zone: &CohesiveZone) -> Vec<f64> {
        let grid = self.grid();
        let bend = super::curvature::edge_curvature(
            contact,
            grid.rows(),
            grid.columns(),
            self.operator.boundary() == crate::grid::Boundary::Periodic,
            zone.zone_cells,
        );
        bend.iter()
            .map(|kappa| {
                let bias = zone.curvature_correction * kappa * zone.zone_cells;
                (1.0 / (1.0 + bias.clamp(-0.5, 0.5))).sqrt()
            })
            .collect()
    }

    /// Adhesive contact at `depth` (m) in the JKR limit by a cohesive zone
    /// resolved on the grid ([`CohesiveZone`]; the method is described in
    /// [`doc::adhesion`](crate::doc::adhesion)). Any contact shape, on
    /// isolated and periodic grids: edges advance and recede where their
    /// local energy release rate asks, contacts split and merge. `warm`
    /// carries the history (the last pressures and which cells are bonded).
    ///
    /// The solution's pressure includes the tension of the open zone
    /// (cells out of contact within the law's range); its contact cells
    /// are those whose gap is closed. On a layered body the zone is at
    /// most [`ZONE_LAYER_FRACTION`] of the top layer's thickness
    /// ([`CohesiveZone::cells_on`]); where that is under two cells
    /// ([`CohesiveZone::resolves_layer`] false) the pull-off is biased by
    /// per cents and scenes report it.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite depth;
    /// [`Error::ShapeMismatch`] for a warm start from another grid;
    /// [`Error::NoConvergence`] if the fixed point or an inner solve does
    /// not converge; as [`ContactSolver::solve_depth`] otherwise.
    pub fn solve_depth_cohesive<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        depth: f64,
        zone: &CohesiveZone,
        warm: Option<&WarmStart>,
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        self.serial_only("solve depth cohesive")?;
        check_finite("depth", depth)?;
        self.check_warm_start(warm)?;
        self.sample_profile(indenter)?;
        let spacing = self.grid().spacing();
        let modulus = self.surface_contact_modulus;
        // The zone within a quarter of the top layer.
        let zone = &CohesiveZone {
            zone_cells: zone.cells_on(spacing, self.substrate.top_thickness()),
            ..*zone
        };
        let advancing = Law::new(zone, zone.advancing, spacing, modulus);
        let receding = Law::new(zone, zone.receding, spacing, modulus);
        let n = self.local_cells();
        let base = self.workspace.profile.clone();
        let mut bonded = match warm {
            Some(w) => w.attached.clone(),
            None => vec![false; n],
        };
        // The tensions from the gaps of the last pressures at this depth.
        let mut total = match warm {
            Some(w) => w.pressure.clone(),
            None => vec![0.0; n],
        };
        let mut kt = super::cell_vector(n)?;
        self.operator.apply(&total, &mut kt)?;
        let mut tension = vec![0.0; n];
        for c in 0..n {
            let g = (base[c] - depth + kt[c]).max(0.0);
            let law = if bonded[c] { &receding } else { &advancing };
            tension[c] = law.tension(g);
        }
        let mut compressive: Vec<f64> = (0..n).map(|c| (total[c] - tension[c]).max(0.0)).collect();
        let scale = receding.peak.max(f64::MIN_POSITIVE);
        let outer = self.params.tolerance;
        let tolerance = outer.max(1e-13);
        let mut iterations = 0usize;
        let mut change = f64::INFINITY;
        let mut stepper = Stepper::new();
        let mut mapped = vec![0.0; n];
        // Each cell's law as the square root of its curvature factor (the
        // peak and the range scale with it), set at the first round and
        // read again from converged contacts.
        let mut roots: Vec<f64> = Vec::new();
        // Each cell's largest tension, Pa (its law's peak).
        let mut caps = vec![0.0; n];
        // Curvatures read again from a converged contact.
        let mut rereads = 0usize;
        // The round's contact: the cells carrying compressive pressure.
        let mut contact = vec![false; n];
        for _ in 0..MAX_ROUNDS {
            self.check_interrupt("the cohesive zone's fixed point")?;
            self.operator.apply(&tension, &mut kt)?;
            for c in 0..n {
                self.workspace.profile[c] = base[c] + kt[c];
            }
            let start = WarmStart {
                pressure: std::mem::take(&mut compressive),
                attached: Vec::new(),
            };
            // Inner solves only as tight as the fixed point has come: a
            // hundredth of the last change of the tensions.
            let inner = tolerance.max(1e-2 * change.min(scale) / scale);
            self.params.tolerance = inner;
            let solved =
                self.constrained_cg(Control::Depth(depth), Some(Cow::Owned(start)), observer);
            self.params.tolerance = outer;
            let (solution, end) = match solved {
                Ok(pair) => pair,
                Err(e) => {
                    self.workspace.profile.copy_from_slice(&base);
                    return Err(e);
                }
            };
            iterations += solution.iterations;
            compressive = end.pressure;
            // The tensions the law gives at the gaps of this solution.
            let previous = change;
            change = 0.0;
            for (k, p) in contact.iter_mut().zip(&compressive) {
                *k = *p > 0.0;
            }
            // The edge's curvature from the first round's contact, then
            // held while the fixed point converges (the law does not change
            // with the contact within those rounds); read again from the
            // converged contact below.
            if zone.curvature_correction > 0.0 && roots.is_empty() {
                roots = self.curvature_roots(&contact, zone);
            }
            let ws = &self.workspace;
            let mut contact_cells = 0usize;
            for c in 0..n {
                let touching = contact[c];
                contact_cells += usize::from(touching);
                let g = if touching {
                    0.0
                } else {
                    (ws.profile[c] - depth + ws.displacement[c]).max(0.0)
                };
                let root = roots.get(c).copied().unwrap_or(1.0);
                if touching {
                    bonded[c] = true;
                } else if g >= receding.range * root {
                    bonded[c] = false;
                }
                let law = if bonded[c] { &receding } else { &advancing };
                let law = law.scaled(root);
                mapped[c] = law.tension(g);
                caps[c] = law.peak;
                change = f64::max(change, (mapped[c] - tension[c]).abs());
            }
            let converged = change <= tolerance * scale && inner <= tolerance;
            if converged && zone.curvature_correction > 0.0 && rereads < MAX_REREADS {
                // A step that moved the contact far (a coarse protocol
                // step) read its curvature from a contact unlike the
                // converged one: read it again, and go on while it moves.
                let fresh = self.curvature_roots(&contact, zone);
                // The change weighted by the tensions it scales.
                let (mut moved, mut pull) = (0.0, 0.0);
                for ((a, b), t) in fresh.iter().zip(&roots).zip(&mapped) {
                    moved += (a - b).abs() * t.abs();
                    pull += t.abs();
                }
                if moved > ROOT_TOLERANCE * pull {
                    roots = fresh;
                    rereads += 1;
                    stepper.law_changed();
                    continue;
                }
            }
            if converged {
                // The solution of the tensions just solved for (the law's
                // tensions at its gaps differ by at most `change`).
                for c in 0..n {
                    total[c] = compressive[c] + tension[c];
                }
                let ws = &mut self.workspace;
                ws.profile.copy_from_slice(&base);
                for (u, k) in ws.displacement.iter_mut().zip(&kt) {
                    *u += k;
                }
                let residual = change / scale;
                let solution = self.solution(&total, depth, iterations, residual, Some(&contact));
                super::check_solution(&solution)?;
                return Ok((
                    solution,
                    WarmStart {
                        pressure: total,
                        attached: bonded,
                    },
                ));
            }
            stepper.next(
                change,
                previous,
                contact_cells,
                &mut tension,
                &mapped,
                &caps,
            );
            // The compressive part keeps the total pressure of the cells.
            for c in 0..n {
                if compressive[c] > 0.0 {
                    compressive[c] = (compressive[c] + mapped[c] - tension[c]).max(0.0);
                }
            }
        }
        self.workspace.profile.copy_from_slice(&base);
        Err(Error::NoConvergence {
            method: "cohesive zone fixed point",
            iterations: MAX_ROUNDS,
            residual: change / scale,
        })
    }
}
