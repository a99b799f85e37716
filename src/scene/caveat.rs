//! What a curve carries besides its steps: the known limits of the method
//! that computed it ([`Caveat`]) and the thresholds that decide them.

use super::{Curve, IndenterSpec, Phase, Scene};
use crate::error::Result;
use crate::kernel::FourierCompliance;
use crate::solver::CohesiveZone;
use crate::Substrate;

/// A known limit of the method that computed a [`Curve`], reported with it
/// instead of being left for the reader to discover.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Caveat {
    /// The energy-balance adhesion method balanced the energy release rate
    /// averaged over the contact edge, along contact sets that are level
    /// sets of the profile but neither discs (about the axis or a
    /// paraboloid's apex) on an isolated grid nor strips across a periodic one: the JKR-limit solution only
    /// where the release is even along the edge. For a tilted, elliptic or
    /// rectangular indenter or a height map the forces may be off by several
    /// per cent ([`doc::adhesion`](crate::doc::adhesion));
    /// [`ContactSolver::edge_release`](crate::solver::ContactSolver::edge_release)
    /// shows how uneven the release is on a contact, and the mesh-dependent
    /// criterion is the cell-by-cell alternative. For a flat punch (tilted,
    /// or with a face that is not round) the balance is too strong (a
    /// square by 7 to 9 %):
    /// [`ContactSolver::peel_punch`](crate::solver::ContactSolver::peel_punch)
    /// gives its pull-off by the local criterion, and a scene of a flat
    /// punch through the cohesive zone (the automatic method for a tilted
    /// one) unloads along that path. See
    /// [`AdhesiveBranches::edge_averaged`](crate::solver::AdhesiveBranches::edge_averaged).
    EdgeAveragedAdhesion,
    /// The mesh-dependent adhesion criterion (Pohrt & Popov 2015, the
    /// method of the reference experiment's simulations) computed the
    /// adhesive steps cell by cell: its pull-off depends on the cell size
    /// (too strong by about `3/N` on a curved edge `N` cells across) and on
    /// how the contact edge lies on the grid (a straight edge along the grid
    /// acts as if the work of adhesion were about 1.66 times larger): a
    /// reference method, not a converged JKR-limit answer
    /// ([`doc::adhesion`](crate::doc::adhesion)).
    MeshDependentAdhesion,
    /// The cohesive zone ([`CohesiveZone`])
    /// spans two cells, its fewest, and is still longer than a quarter of
    /// the top layer's thickness (the layer is thinner than eight cells):
    /// it then acts as a softer law than the JKR limit and the forces are
    /// biased by per cents: a sphere's pull-off on a film on a rigid base
    /// -0.8 % with the zone half the thickness, -4.6 % with the whole (see
    /// [`ZONE_LAYER_FRACTION`](crate::solver::ZONE_LAYER_FRACTION)); on a
    /// layer over a far softer one, where the zone's modulus is the
    /// body's at its length, a paraboloid's peak force and pull-off -2.4
    /// and +2.9 % at 64 cells across, -7.3 and +5.1 % at 32
    /// (`tests/scene_cohesive_soft_below.rs`), a sphere's peak force +5.0 %
    /// at 64 and +1.9 % at 128
    /// (`BENCHMARKS.md`, "The cohesive contact's area"); a nearly
    /// incompressible layer (`nu` 0.49) on a base 290 times stiffer, a
    /// sphere's pull-off -9.9, -6.9, -2.0 % at 16, 32, 64 cells (the
    /// cohesive reference sweep's seed 71; `BENCHMARKS.md`, "The loading
    /// branch under hysteresis"). Where the body is also far stiffer at the
    /// zone's length than at the contact's (a stiff layer on a far softer
    /// body under a wide contact) the bias grows to tens of per cents:
    /// [`Caveat::CohesiveZoneStifferThanContact`] is reported with this one.
    /// Of the reference sweep's cases with this caveat alone at 16 cells
    /// across, the largest error was 11.3 % (seed 51, a sphere on a nearly
    /// incompressible layer over a base 31 times softer, the ratio of
    /// [`ZoneScales::modulus_ratio`] 13.7; +5.2 and +0.73 % at 32 and 64),
    /// the median pull-off error 0.9 % (`BENCHMARKS.md`, "The zone stiffer
    /// than the contact"). A finer grid resolves it.
    CohesiveZoneLongAgainstLayer,
    /// With [`Caveat::CohesiveZoneLongAgainstLayer`], under an indenter
    /// whose contact edge moves and is one contact (not a flat punch or a
    /// rough surface), the body is far stiffer
    /// at the zone's length than at the contact's size: its contact
    /// modulus `E*(q) = 2 / (q u_z(q))` (Perriot & Barthel 2004) at the
    /// zone's wavelength `q = 2 pi / l` is at least
    /// [`ZONE_CONTACT_MODULUS_RATIO`] times its modulus at the peak
    /// contact's, `q = pi / a` ([`ZoneScales`]): a stiff layer on a body far
    /// softer below, under a contact much wider than the layer is thick.
    /// The zone's law, set by the body's modulus at its length, is then far
    /// from that of the contact's scale, and pull-offs came out too strong
    /// by up to tens of per cents. Measured at 16 cells across on the
    /// cohesive reference sweep's scenes with a zone long against the layer
    /// (`BENCHMARKS.md`, "The zone stiffer than the contact"): the six
    /// spheres and paraboloids with the ratio from 33 to 366 and an exact
    /// pull-off, -0.24, +4.3, +6.2, +12.7, +18.6 and +32 %; seed 74's
    /// paraboloid (a 57 GPa
    /// layer 24 um thick over a base 3850 times softer, the ratio 448)
    /// +40 %, and +22, +14, +5.1, +0.20 % at 20, 24, 32, 64 cells across,
    /// where the zone is 2.4 to 0.73 times the layer's thickness. The
    /// energy balance, where it applies, has no such bias (seed 74's peak
    /// force +0.04 % at 16 cells). A finer grid resolves it: the zone
    /// shorter than the layer.
    CohesiveZoneStifferThanContact,
    /// A synthesised rough surface went through the cohesive zone: its
    /// forces depend on the zone's length, and their JKR limit is not
    /// established. Measured on the same surface refined from 64^2 to
    /// 512^2 cells (`BENCHMARKS.md`, "Adhesion through a resolved cohesive
    /// zone"): at a fixed zone the cycle converges in the grid (0.036 %
    /// between the two finest), but the converged pull-off moved by +8,
    /// +25 and -16 % as the zone halved from the surface's shortest
    /// wavelength to an eighth of it. Read the forces as those of a cohesive
    /// (Maugis-Dugdale) law of the zone's length
    /// ([`CohesiveZone::with_zone_cells`](crate::solver::CohesiveZone::with_zone_cells));
    /// `doc::adhesion`.
    CohesiveZoneOnRoughSurface,
    /// The cohesive zone was wider than the contact at the pull-off (the
    /// contact's widest patch fewer cells across than the zone): the zones
    /// of its two sides meet, and the force is a cohesive law's, not the
    /// JKR limit's. Johnson's sinusoid so resolved came out 0.9 to 25 %
    /// weak (`BENCHMARKS.md`, "The cohesive zone on contacts it spans");
    /// see [`CohesivePullOff::zone_spans_contact`](crate::solver::CohesivePullOff::zone_spans_contact).
    /// A finer grid resolves it.
    CohesiveZoneSpansContact,
    /// With adhesion hysteresis through the cohesive zone, the contact of
    /// an indenter that is neither a flat punch nor a rough surface came
    /// off near where the loading left it (at the pull-off it still covered
    /// [`PINNED_AREA_FRACTION`] of the peak's contact area or more: the edge
    /// was pinned), or the body is far softer below its surface (its
    /// softest contact modulus at least [`SOFT_BELOW_CONTRAST`] times below
    /// the surface's), where the contact jumps off as soon as a pinned edge
    /// moves. Such a pull-off
    /// comes where the pinned edge begins to recede, and through the zone
    /// it converges slowly in the grid, mostly too weak: -8.4, -3.7, -1.4 %
    /// at 16, 32, 64 cells across on a half-space (works 0.146 and 1.122
    /// J/m^2), -19, -9.6, -6.3 % on a layer over a base 2000 times softer.
    /// Of the cohesive reference sweep's scenes with hysteresis (seeds 11,
    /// 37 and 50 to 69), the 33 flagged at 32 cells came out -17.5 to
    /// +3.3 % (the last under the long-zone caveat too), the 48 not flagged
    /// within 1.5 % (`BENCHMARKS.md`, "The loading branch under
    /// hysteresis"). A finer grid narrows it; for an axisymmetric contact
    /// the energy balance is exact.
    CohesivePinnedPullOff,
    /// A cycle's unloading through the cohesive zone ended before the
    /// contact was lost: past the least force (searched between its steps),
    /// the zone's fixed point reached no equilibrium at a later step from
    /// the one before, even in 16 substeps. The curve ends at the last
    /// equilibrium reached. Its pull-off is the least force of the steps it
    /// has (a second, lower minimum further out would be missed); the depth
    /// at which the contact is lost is not known. Seen where the contact had
    /// shrunk to a few cells, narrower than the zone, near where
    /// displacement control lets go (the reference sweep's seed 156 at 16
    /// cells across: two cells, its pull-off -1.03 % off the exact one;
    /// `BENCHMARKS.md`, "Seeds 156, 159 and 162 settled"). A finer grid
    /// resolves the tail.
    CohesiveUnloadingCutShort,
    /// The energy balance on a flat punch whose stiffness barely changes
    /// with its contact: `(A / k) dk/dA` at the face below 0.4 (0.5 on a
    /// half-space; a stiff layer over a far softer body, whose stiffness
    /// the body below sets). The balance's release rate is the area
    /// derivative of that stiffness, from fits of neighbouring contact
    /// sets, and its pull-off came out 0.5 to 6 % off (not converging with
    /// the grid) where the ratio was 0.25 or less: a punch on a stiff plate
    /// over bases of 0.19 Pa to 1.9 kPa, at 16 to 64 cells across
    /// (`BENCHMARKS.md`, "Seeds 156, 159 and 162 settled";
    /// `examples/punch_peeling.rs`). The peeling path by the local
    /// criterion converges there (0.8 / 0.4 / 0.2 % at 16 / 32 / 64 cells):
    /// `adhesion_method = "cohesive_zone"`, which `auto` takes where it
    /// reads the exact ratio below 0.4 (punches up to 50 top-layer
    /// thicknesses wide, [`Scene::resolved_adhesion_method`](super::Scene::resolved_adhesion_method)),
    /// so that the caveat shows where the energy balance was asked for or
    /// the punch is wider.
    EnergyBalanceFlatStiffness,
}

/// The least part of the peak's contact area that a contact still covers
/// at its pull-off for [`Caveat::CohesivePinnedPullOff`]. Measured ratios
/// (through the cohesive zone, 32 and 64 cells across): edges pinned to the
/// pull-off 0.73 to 0.93 (a sphere on a half-space 0.83; over bases 2000 to
/// 10000 times softer 0.73, 0.93, 0.83; a cone 0.81), edges that recede
/// before it, whose pull-offs are within 0.6 %, 0.52 and 0.58 (a sphere on
/// a rubber film on glass, works 0.05 and 0.1 J/m^2; on a stack over a
/// base 32 times softer).
pub const PINNED_AREA_FRACTION: f64 = 0.7;

/// The ratio of the surface's contact modulus to the body's softest from
/// which [`Caveat::CohesivePinnedPullOff`] applies with hysteresis whatever
/// the pull-off's contact: over bases 2600 and 9700 times softer than the
/// layer the cohesive zone's edge receded early and came off with 0.61 to
/// 0.69 of the peak's area in six of the sweep's runs (-6.6 to -20.2 % at
/// 16 or 32 cells), where unflagged bodies 10 and 18 times softer below
/// came within 0.9 % at 32 cells.
pub const SOFT_BELOW_CONTRAST: f64 = 100.0;

/// The ratio of the body's contact modulus at the cohesive zone's length
/// to its modulus at the peak contact's size ([`ZoneScales::modulus_ratio`])
/// from which [`Caveat::CohesiveZoneStifferThanContact`] applies to a zone
/// long against the layer. Of the cohesive reference sweep's 154 long-zone
/// cases at 16 cells across (seeds 53, 56, 60, 75, 77 and 80 to 92), the
/// 143 below it came within 8.3 % (that at a ratio of 24; the median pull-off
/// error 0.9 %); of the 11 above it, the five flat punches within 1.4 %,
/// the curved indenters off by up to 32 % (`BENCHMARKS.md`, "The zone
/// stiffer than the contact").
pub const ZONE_CONTACT_MODULUS_RATIO: f64 = 30.0;

/// The cohesive zone's scales against the body's, on a run's grid: the
/// measures of [`Caveat::CohesiveZoneLongAgainstLayer`] and
/// [`Caveat::CohesiveZoneStifferThanContact`].
///
/// ```
/// use layered_contact::scene::ZoneScales;
/// use layered_contact::solver::CohesiveZone;
/// use layered_contact::{Material, Substrate};
///
/// // A 57 GPa layer 24 um thick resting on a half-space 3850 times softer,
/// // cells of 35.4 um and a peak contact of 0.40 mm (the sweep's seed 74).
/// let body = Substrate::layer_resting_on_elastic_base(
///     Material::new(5.7e10, 0.3)?,
///     2.41e-5,
///     Material::new(1.48e7, 0.5)?,
/// )?;
/// let zone = CohesiveZone::new(68.6, 68.6)?;
/// let scales = ZoneScales::new(&zone, &body, 3.54e-5, 4.0e-4).unwrap();
/// assert_eq!(scales.cells, 2.0);
/// assert!((scales.length / scales.layer_thickness - 2.94).abs() < 0.01);
/// assert!(scales.stiffer_than_contact());
/// assert!((400.0..500.0).contains(&scales.modulus_ratio));
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct ZoneScales {
    /// The zone's cells ([`CohesiveZone::cells_on`]).
    pub cells: f64,
    /// The zone's length, m.
    pub length: f64,
    /// The top layer's thickness, m.
    pub layer_thickness: f64,
    /// The peak contact's radius (of equal area), m.
    pub contact_radius: f64,
    /// `E*(2 pi / length) / E*(pi / contact_radius)`, with `E*(q) = 2 / (q
    /// u_z(q))` the body's contact modulus at wavenumber `q` (Perriot &
    /// Barthel 2004, [`FourierCompliance`]): above 1 where the body is
    /// stiffer at the zone's length than at the contact's size.
    pub modulus_ratio: f64,
}

impl ZoneScales {
    /// The scales of `zone` on cells of `spacing` (m) of `substrate`, under
    /// a peak contact of radius `contact_radius` (m); `None` on a body
    /// without a layer, or where the radius or spacing is not positive and
    /// finite.
    pub fn new(
        zone: &CohesiveZone,
        substrate: &Substrate,
        spacing: f64,
        contact_radius: f64,
    ) -> Option<ZoneScales> {
        let layer_thickness = substrate.top_thickness()?;
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if !positive(spacing) || !positive(contact_radius) {
            return None;
        }
        let cells = zone.cells_on(spacing, Some(layer_thickness));
        let length = cells * spacing;
        let compliance = FourierCompliance::new(substrate);
        let pi = std::f64::consts::PI;
        let modulus_ratio = compliance.contact_modulus_at(2.0 * pi / length)
            / compliance.contact_modulus_at(pi / contact_radius);
        Some(ZoneScales {
            cells,
            length,
            layer_thickness,
            contact_radius,
            modulus_ratio,
        })
    }

    /// Whether [`Caveat::CohesiveZoneStifferThanContact`] applies (with the
    /// zone long against the layer): the ratio at least
    /// [`ZONE_CONTACT_MODULUS_RATIO`], or not a number.
    pub fn stiffer_than_contact(&self) -> bool {
        self.modulus_ratio >= ZONE_CONTACT_MODULUS_RATIO || self.modulus_ratio.is_nan()
    }
}

impl Scene {
    /// The scales of the cohesive zone that computed `curve`
    /// ([`Scene::cohesive_zone`] on `curve`'s grid) under its peak contact
    /// (the largest contact of its loading branch); `None` where the scene
    /// has no cohesive zone, the body no layer, or the loading no contact.
    ///
    /// # Errors
    /// As [`Scene::cohesive_zone`] and building the substrate.
    pub fn zone_scales(&self, curve: &Curve) -> Result<Option<ZoneScales>> {
        let Some(zone) = self.cohesive_zone()? else {
            return Ok(None);
        };
        let substrate = self.substrate.build()?;
        Ok(ZoneScales::new(
            &zone,
            &substrate,
            curve.grid.spacing(),
            peak_radius(&curve.steps),
        ))
    }
}

/// The caveats of a run through the cohesive `zone` on cells of `spacing`
/// (m) of `substrate`, under a peak contact of radius `peak_radius` (m),
/// of `indenter` (`untilted` or not), whose least force's contact was
/// `least_across` cells across (`None` if it never pulled).
pub(super) fn cohesive(
    zone: &CohesiveZone,
    substrate: &Substrate,
    (spacing, peak_radius): (f64, f64),
    (indenter, untilted): (&IndenterSpec, bool),
    least_across: Option<f64>,
) -> Vec<Caveat> {
    let top = substrate.top_thickness();
    // An untilted punch's contact is its face from the first step and its
    // unloading peels by the edge's release rates: no zone forms. Measured
    // with the zone under two cells (a punch on a plate over bases of 0.19
    // Pa to 190 kPa, `examples/punch_peeling.rs`): within 0.9 / 0.42 /
    // 0.24 % at 16 / 32 / 64 cells across, converging like `1 / N`.
    let face = untilted && matches!(indenter, IndenterSpec::FlatPunch { .. });
    let thin = !zone.resolves_layer(spacing, top) && !face;
    let rough = matches!(indenter, IndenterSpec::RoughSurface { .. });
    // A flat punch's face holds its edge: the sweep's five punches with the
    // ratio at 59 to 123 came within 1.4 %. A rough surface's patches are
    // far smaller than the circle of the whole contact's area, and its
    // own caveat says more.
    let stiffer = thin
        && !rough
        && !matches!(indenter, IndenterSpec::FlatPunch { .. })
        && ZoneScales::new(zone, substrate, spacing, peak_radius)
            .is_some_and(|scales| scales.stiffer_than_contact());
    let spans = least_across.is_some_and(|across| across < zone.cells_on(spacing, top));
    [
        (thin, Caveat::CohesiveZoneLongAgainstLayer),
        (stiffer, Caveat::CohesiveZoneStifferThanContact),
        (rough, Caveat::CohesiveZoneOnRoughSurface),
        (spans, Caveat::CohesiveZoneSpansContact),
    ]
    .into_iter()
    .filter_map(|(applies, caveat)| applies.then_some(caveat))
    .collect()
}

/// The largest contact radius of the loading steps among `steps` (0
/// without any).
pub(super) fn peak_radius(steps: &[super::Step]) -> f64 {
    steps
        .iter()
        .filter(|s| s.phase == Phase::Loading)
        .map(|s| s.contact_radius)
        .fold(0.0, f64::max)
}

impl std::fmt::Display for Caveat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Caveat::EdgeAveragedAdhesion => f.write_str(
                "edge-averaged adhesion: the contact sets are neither discs (about the grid's \
                 axis or a paraboloid's apex) nor strips across a periodic grid, so the energy balance averages the \
                 energy release rate over the edge and its forces may be off by several per \
                 cent (the JKR-limit solution only where the release is even along the edge; \
                 a flat punch's pull-off by the local criterion: ContactSolver::peel_punch, \
                 Python layered_contact.peel_punch)",
            ),
            Caveat::MeshDependentAdhesion => f.write_str(
                "mesh-dependent adhesion: the criterion of Pohrt & Popov (2015) decides each \
                 cell, so the pull-off depends on the cell size (about 3/N too strong on a \
                 curved edge N cells across) and on how the contact edge lies on the grid (up \
                 to about 40 % too strong along a straight edge on the grid): a reference \
                 method, not a converged answer",
            ),
            Caveat::CohesiveZoneLongAgainstLayer => f.write_str(
                "cohesive zone long against the layer: the top layer is thinner than eight \
                 cells, so the two-cell zone is longer than a quarter of its thickness and \
                 the forces may be off by per cents (on a rigid base -0.8 % with the zone \
                 half the thickness, -4.6 % with the whole; over a far softer layer up to \
                 8 % measured; a nearly incompressible layer on a far stiffer base -6.9 % at \
                 32 cells across): refine the grid",
            ),
            Caveat::CohesiveZoneStifferThanContact => f.write_str(
                "cohesive zone on a skin far stiffer than the contact's body: at the zone's \
                 length the body is at least 30 times stiffer than at the contact's size (a \
                 stiff layer on a far softer body), and such pull-offs came out -0.2 to +13 % \
                 off with the ratio below 100 and +19 to +40 % above it at 16 cells across \
                 (the last +5 % at 32 and +0.2 % at 64): refine the grid until the zone \
                 is shorter than the layer's thickness, or for an axisymmetric contact use the \
                 energy balance",
            ),
            Caveat::CohesiveZoneOnRoughSurface => f.write_str(
                "cohesive zone on a rough surface: the forces depend on the zone's length and \
                 their JKR limit is not established (measured on a rough film, converged in \
                 the grid at a fixed zone, the pull-off moved by +8, +25 and -16 % as the zone \
                 halved from the shortest wavelength to an eighth of it): read them as a \
                 cohesive law's of the zone's length",
            ),
            Caveat::CohesiveZoneSpansContact => f.write_str(
                "cohesive zone wider than the contact at the pull-off: the zones of the \
                 contact's two sides meet, so the force is a cohesive law's, not the JKR \
                 limit's (Johnson's sinusoid so resolved came out 0.9 to 25 % weak): refine \
                 the grid",
            ),
            Caveat::CohesivePinnedPullOff => f.write_str(
                "pinned pull-off through the cohesive zone: with adhesion hysteresis the \
                 contact came off near where the loading left it, or the body is far softer \
                 below its surface, and such a pull-off converges slowly in the grid, \
                 mostly too weak (-8.4, -3.7, -1.4 % at 16, 32, 64 cells across on a \
                 half-space; -19, -9.6, -6.3 % over a base 2000 times softer): refine the \
                 grid, or for an axisymmetric contact use the energy balance (exact)",
            ),
            Caveat::EnergyBalanceFlatStiffness => f.write_str(
                "energy balance on a punch whose stiffness barely changes with its contact (a \
                 stiff layer over a far softer body): the pull-off is the area derivative of \
                 that stiffness and came out up to 6 % off on such bodies, not converging with \
                 the grid: use adhesion_method = \"cohesive_zone\" (its peeling path converges)",
            ),
            Caveat::CohesiveUnloadingCutShort => f.write_str(
                "unloading cut short through the cohesive zone: past the least force the \
                 zone's fixed point reached no equilibrium at a later step, so the curve ends \
                 before the contact is lost (its pull-off is the least force of the steps it \
                 has; where the contact is lost is not known): refine the grid",
            ),
        }
    }
}

impl Curve {
    /// Whether the contact at the pull-off still covers
    /// [`PINNED_AREA_FRACTION`] of the peak's (the last loading step's)
    /// contact area or more.
    pub(super) fn came_off_pinned(&self) -> bool {
        let peak = self.phase(Phase::Loading).last().map(|s| s.contact_area);
        match (peak, self.pull_off()) {
            (Some(peak), Some(pull_off)) if peak > 0.0 => {
                pull_off.contact_area >= PINNED_AREA_FRACTION * peak
            }
            _ => false,
        }
    }
}
