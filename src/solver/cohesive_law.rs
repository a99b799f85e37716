//! The cohesive zone's law: a short-range adhesive law whose range shrinks
//! with the cell, so that its zone spans a fixed number of cells
//! ([`CohesiveZone`]), and the defaults measured for it. The fixed point
//! that solves with it is in [`cohesive`](super::cohesive).

use crate::error::{Error, Result};
use crate::kernel::FourierCompliance;

#[cfg(doc)]
use super::ContactSolver;

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
/// cells on the sphere at 64 cells across. Beyond about 128 cells across
/// the contact a zone of four cells stops converging (its lattice
/// trapping): [`CohesiveZone::with_resolution`] grows it with the grid.
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
    pub(super) advancing: f64,
    pub(super) receding: f64,
    pub(super) zone_cells: f64,
    pub(super) curvature_correction: f64,
}

impl CohesiveZone {
    /// The law for the advancing (loading, `dgamma0`) and receding
    /// (unloading, `dgamma1 >= dgamma0`) works of adhesion, J/m^2, with a
    /// zone of [`COHESIVE_ZONE_CELLS`] cells and the curvature correction
    /// [`CURVATURE_CORRECTION`]. A cell bonds when it is in contact at an
    /// equilibrium and then holds with `dgamma1` until its gap exceeds the
    /// receding range; a cell that has not touched pulls with `dgamma0`.
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
        crate::error::within(
            "cohesive zone width (cells)",
            cells,
            (2.0, 256.0),
            "in [2, 256]",
        )?;
        Ok(CohesiveZone {
            zone_cells: cells,
            ..self
        })
    }

    /// The same law with its zone grown with the resolution: `max(4,
    /// sqrt(N) / 2)` cells for `N` = `cells_across` cells across the
    /// pull-off contact (its narrow side; 4 up to 64 cells, 8 at 256, 16
    /// at 1024). A zone of a fixed number of cells stops converging to the
    /// JKR limit once its own discretisation is the largest error: a
    /// straight contact edge along the grid is trapped by the lattice and
    /// the least force of the unloading, which ripples as the edge steps
    /// from cell to cell, is too strong by +0.26 to +0.49 % with 4 cells,
    /// +0.02 to +0.11 % with 8 and under +0.01 % with 16 at 512 to 4096
    /// cells per wavelength (Johnson's sinusoid, `BENCHMARKS.md`, "The
    /// cohesive zone grown with the resolution"); on curved edges the
    /// ripple averages out to less (the sphere's +0.045 % at 256 cells
    /// across with 4 cells). The zone's length
    /// against the contact costs `-c (k / N)^2` (`c` about 44 % on the
    /// sphere), so a zone growing like `sqrt(N)` lets both fall: about
    /// first order in `1/N` (the JKR sphere: -0.131, -0.064, -0.0135,
    /// -0.0012 % at 64 to 512 cells across, orders 1.0, 2.3, 3.5, so not a
    /// power to extrapolate with: take the finest run).
    /// A zone far narrower than this on a fine grid can be pinned by the
    /// lattice well beyond the ripple: 8 cells on the sinusoid at about
    /// 1000 cells across its contact (this gives 15.5) reached a pinned
    /// state 4.6 % beyond the pull-off.
    /// `examples/cohesive_convergence.rs` sizes the zone so with `auto`,
    /// and scenes with their `cells_across`
    /// ([`Scene::cohesive_zone`](crate::scene::Scene::cohesive_zone)).
    ///
    /// ```
    /// use layered_contact::solver::CohesiveZone;
    ///
    /// let zone = CohesiveZone::new(0.05, 0.05)?;
    /// assert_eq!(zone.with_resolution(32.0)?.zone_cells(), 4.0);
    /// assert_eq!(zone.with_resolution(256.0)?.zone_cells(), 8.0);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for `cells_across` not in `[1, 2^18]`
    /// (the zone would pass 256 cells).
    pub fn with_resolution(self, cells_across: f64) -> Result<Self> {
        crate::error::within(
            "cells across the pull-off contact",
            cells_across,
            (1.0, 262_144.0),
            "in [1, 262144]",
        )?;
        self.with_zone_cells(COHESIVE_ZONE_CELLS.max(0.5 * cells_across.sqrt()))
    }

    /// The same law with the zone's first-order bias on curved edges taken
    /// out: each cell pulls with `dgamma / (1 + c kappa l)`, `kappa` the
    /// curvature of the contact's edge near it and `l` the zone's length
    /// (`c` = 0 leaves the law as it is; default [`CURVATURE_CORRECTION`]).
    /// The curvature is that of the contact's cells smoothed over the zone,
    /// taken at the first round of each solve (for a load step, the
    /// contact of the last one, moved by the step) and held while the
    /// fixed point converges; read again once the tensions have settled
    /// (their change below 1e-3 of the law's peak) and from the converged
    /// contact, the fixed point resumed whenever the factors (as their
    /// square roots, weighted by the tensions they scale) moved by more
    /// than 2e-3 (at most eight times a solve, and no more once a read
    /// changes them by no less than the read before it): a long step that
    /// moves the edge by many cells gets the curvature of the contact it
    /// reaches.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside `[0, 1]`.
    pub fn with_curvature_correction(self, c: f64) -> Result<Self> {
        crate::error::within(
            "cohesive zone curvature correction",
            c,
            (0.0, 1.0),
            "in [0, 1]",
        )?;
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

/// `E*` of the body as the cohesive zone sees it: the least of `2 / (q
/// u_z(q))` over the wavelengths `2 pi / q` no longer than the zone's
/// length `l` (m), with the surface material's `E*` (`q -> inf`). On a
/// half-space, and on layers over stiffer ones, that is the surface's
/// `E*`; under a zone long against a stiff top layer over a softer one it
/// is the softer modulus the zone's own wavelengths see. The law's range
/// `rho = 2 sqrt(dgamma l / E*)` balances its stiffness `2 dgamma / rho^2`
/// against the body's `E* q / 2` at `q = 1 / l`, so its zone spans its
/// cells where the body is no softer than `E*` at the zone's scales; a
/// body softer there shortens the zone in proportion, to a fraction of a
/// cell, where the lattice traps the edge.
///
/// Before 2026-12-02 the law took the surface material's `E*` on every
/// body. A stiff top layer over a far softer one (4.85 GPa, 37.6 um over
/// 13.2 MPa, 14 um, on a 7.9 GPa base; the cohesive reference sweep's
/// seed 13) is 8.6 times softer at wavelengths of the zone's 263 um (two
/// cells of a 16-cell grid) than its surface: the zone spanned about a
/// quarter of a cell and the cycle's peak force came out 69 % weak and its
/// pull-off 114 % strong, with a caveat that promised per cents. With the
/// least modulus: +0.4 % and +1.6 % (`BENCHMARKS.md`, "The zone's
/// modulus"). The sampled wavenumbers run from `2 pi / l` to the larger of
/// a thousand times that and `100 / h` (`h` the top layer's thickness,
/// beyond which the body is its surface material to `e^-200`), 16 a
/// decade; a modulus softer than the surface's by less than `1e-9` of it
/// (rounding) is the surface's.
///
/// The mesh-dependent criterion asks the same of wavelengths up to four
/// cells before it solves (`src/solver/adhesive.rs`).
///
/// # Errors
/// [`Error::Internal`] where the compliance there is not finite and
/// positive (a body the kernel builds always has one).
pub(super) fn zone_modulus(
    compliance: &FourierCompliance,
    surface: f64,
    length: f64,
    top_thickness: Option<f64>,
) -> Result<f64> {
    const PER_DECADE: f64 = 16.0;
    let first = 2.0 * std::f64::consts::PI / length;
    let Some(h) = top_thickness else {
        return Ok(surface);
    };
    let last = (1e3 * first).max(100.0 / h);
    // At most 16 decades (257 samples), which reach a top layer 1e-14 of
    // the zone's length thin.
    let decades = (last / first).log10().clamp(0.0, 16.0);
    let samples = (decades * PER_DECADE).ceil() as usize;
    let mut modulus = surface;
    for k in 0..=samples {
        let q = first * 10f64.powf(k as f64 / PER_DECADE);
        let seen = compliance.contact_modulus_at(q);
        if seen.is_nan() {
            modulus = seen;
            break;
        }
        // Softer than the surface by rounding only (a layer over stiffer
        // ones at short wavelengths) leaves the surface's modulus as it is.
        if seen < surface * (1.0 - 1e-9) {
            modulus = modulus.min(seen);
        }
    }
    if modulus.is_finite() && modulus > 0.0 {
        Ok(modulus)
    } else {
        Err(Error::Internal {
            what: "the body's modulus at the grid's scale",
            detail: format!(
                "the body's compliance at wavelengths under {length:e} m \
                 gives a modulus of {modulus:e} Pa"
            ),
        })
    }
}

/// One work of adhesion's law on this grid: the peak tension and the range.
#[derive(Clone, Copy)]
pub(super) struct Law {
    pub(super) peak: f64,
    pub(super) range: f64,
}

impl Law {
    /// The law of `work` (J/m^2) on cells of `spacing` (m) of a surface of
    /// contact modulus `modulus` (Pa), on a grid of `area` (m^2).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming the work of adhesion where its
    /// range or peak tension is not finite, or the peak over the whole grid
    /// would not be a finite force (a work of adhesion of `1e308` J/m^2:
    /// the range overflows and the peak is NaN).
    pub(super) fn new(
        zone: &CohesiveZone,
        work: f64,
        spacing: f64,
        modulus: f64,
        area: f64,
    ) -> Result<Self> {
        let range = zone.range(work, spacing, modulus);
        let peak = if range > 0.0 { work / range * 2.0 } else { 0.0 };
        if range.is_finite() && peak.is_finite() && (peak * area).is_finite() {
            Ok(Law { peak, range })
        } else {
            Err(Error::InvalidParameter {
                name: "work of adhesion",
                value: work,
                expected: "small enough that the cohesive law's range and peak tension over \
                           the grid are finite",
            })
        }
    }

    /// The law of `root^2` times the work of adhesion over the same zone
    /// (its peak and range scale with `root`).
    pub(super) fn scaled(&self, root: f64) -> Law {
        Law {
            peak: self.peak * root,
            range: self.range * root,
        }
    }

    /// The tension (Pa, `<= 0`) at a gap `g >= 0`.
    pub(super) fn tension(&self, g: f64) -> f64 {
        if g < self.range {
            -self.peak * (1.0 - g / self.range)
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Material, Substrate};

    fn modulus_of(substrate: &Substrate, length: f64) -> f64 {
        let surface = substrate.surface_material().contact_modulus();
        let compliance = FourierCompliance::new(substrate);
        zone_modulus(&compliance, surface, length, substrate.top_thickness()).unwrap()
    }

    /// A half-space and a film on a rigid base (stiffer below) keep their
    /// surface's `E*` to the last bit, whatever the zone's length.
    #[test]
    fn bodies_no_softer_below_keep_the_surface_modulus() {
        let rubber = Material::new(1e6, 0.48).unwrap();
        let surface = rubber.contact_modulus();
        for length in [1e-9, 1e-4, 1e3] {
            assert_eq!(modulus_of(&Substrate::half_space(rubber), length), surface);
            let film = Substrate::layer_on_rigid_base(rubber, 1e-4).unwrap();
            assert_eq!(modulus_of(&film, length), surface);
        }
    }

    /// A film a million times thinner than the zone over a base ten times
    /// softer: at the zone's wavelengths the body is its base, whose own
    /// `E*` is the closed form (the film's share `q h E1 / E2` about 6e-5).
    #[test]
    fn a_film_far_thinner_than_the_zone_is_its_base() {
        let (film, base) = (
            Material::new(1e7, 0.3).unwrap(),
            Material::new(1e6, 0.45).unwrap(),
        );
        let body = Substrate::layer_on_elastic_base(film, 1e-9, base).unwrap();
        let seen = modulus_of(&body, 1e-3);
        assert!(
            (seen / base.contact_modulus() - 1.0).abs() < 1e-3,
            "{seen:e}"
        );
    }

    /// A stiff plate over a far softer layer on a stiff base (the reference
    /// sweep's seed 13): softest at wavelengths near the zone's, 8.6 times
    /// softer than its surface; the sampled least within 0.5 % of the least
    /// over 2000 wavenumbers a decade.
    #[test]
    fn a_stiff_plate_over_a_soft_layer_takes_its_softest_modulus() {
        let layers = [
            (
                Material::new(4.851901410873788e9, 0.45).unwrap(),
                3.759473894676288e-5,
            ),
            (
                Material::new(1.3204302992092755e7, 0.0).unwrap(),
                1.4047347491749039e-5,
            ),
        ];
        let base =
            crate::substrate::Base::Elastic(Material::new(7.872956920080994e9, 0.0).unwrap());
        let body = Substrate::stack(&layers, base).unwrap();
        let length = 2.0 * 1.3157e-4;
        let seen = modulus_of(&body, length);
        let compliance = FourierCompliance::new(&body);
        let first = 2.0 * std::f64::consts::PI / length;
        let dense = (0..=8000)
            .map(|k| first * 10f64.powf(k as f64 / 2000.0))
            .map(|q| 2.0 / (q * compliance.eval(q)))
            .fold(f64::INFINITY, f64::min);
        assert!(
            (seen / dense - 1.0).abs() < 5e-3,
            "{seen:e} against {dense:e}"
        );
        let surface = body.surface_material().contact_modulus();
        assert!(seen < surface / 8.0, "{seen:e} against {surface:e}");
    }
}
