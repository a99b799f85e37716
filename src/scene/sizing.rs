//! Grid sizing: how fine and how wide a scene's grid is, from the contacts
//! it must hold and resolve.

use crate::error::{Error, Result};
use crate::grid::fft_friendly;
use crate::grid::Grid;

use crate::analytic::{ContactState, LayeredTip};
use crate::solver::CohesiveZone;

use super::reference::least_of_unloading;

use super::{Adhesion, AdhesionMethod, IndenterSpec, Protocol, Scene};

/// Grid sizing consults the exact solution only up to this `a/h`: a table
/// to 20 takes milliseconds, one to 50 up to a few seconds (`check` took
/// 3.4 s for the adhesive scene of `tests/scene_reference.rs` whose contact
/// spreads to 38 thicknesses, 2026-11-29). It was 20 until then, beyond
/// which the estimate sizing falls back to was about ten times too small for
/// that scene.
const SIZING_MAX_EPS: f64 = 50.0;

/// The fewest cells across a displacement-controlled cycle's jump-off
/// contact is given, whatever `cells_across` asks of the pull-off's: 7.2
/// cells across is a disc of 41 cells, above the 36 the energy balance
/// needs to place a least force or depth there (`RESOLVED_CELLS`). A
/// paraboloid's jump-off contact on a half-space is 0.48 of its pull-off's
/// (JKR 1971), so from 16 cells across its grid is sized by the pull-off as
/// before; a cone's is a ninth (Maugis & Barquins 1981), which 16 cells
/// across the pull-off left at 1.8 cells, refused. (A share of
/// `cells_across` instead, 0.45, refined the grid of a sphere on a film
/// over a stiffer base at 64 cells, whose jump-off had 26 cells already.)
const JUMP_OFF_CELLS: f64 = 7.2;

/// The widest grid a scene builds, in cells.
const MAX_GRID_CELLS: usize = 8192;

impl Scene {
    /// The radius (m) of the largest contact the protocol should reach, for
    /// sizing the grid.
    fn contact_radius_estimate(&self) -> Result<f64> {
        let substrate = self.substrate.build()?;
        let softest = substrate.softest_contact_modulus();
        Ok(match (&self.indenter, self.protocol) {
            (IndenterSpec::FlatPunch { radius }, _) => *radius,
            (IndenterSpec::Custom(custom), _) => crate::indenter::Indenter::bounding_radius(custom),
            // Solved on the map's own grid; never sized.
            (IndenterSpec::HeightMap { .. } | IndenterSpec::RoughSurface { .. }, _) => {
                return Err(Error::Internal {
                    what: "grid sizing",
                    detail: "a height map is not sized from its contact".into(),
                })
            }
            (IndenterSpec::Sphere { radius } | IndenterSpec::Paraboloid { radius }, protocol) => {
                let radius = *radius;
                let (target, by_force) = match protocol {
                    Protocol::Depth { depth } => (depth.abs(), false),
                    Protocol::Cycle { max_depth, .. } => (max_depth, false),
                    Protocol::Force { force } => (force, true),
                    Protocol::ForceCycle { max_force, .. } => (max_force, true),
                };
                let hertz = if by_force {
                    (0.75 * target * radius / softest).cbrt()
                } else {
                    (radius * target).sqrt()
                };
                let estimate = match substrate.top_thickness() {
                    Some(thickness) => {
                        exact_contact_radius(&substrate, thickness, radius, target, by_force, hertz)
                            .unwrap_or(1.5 * hertz)
                    }
                    None => hertz,
                };
                estimate.min(radius)
            }
            (
                IndenterSpec::Cone {
                    half_angle,
                    base_radius,
                },
                protocol,
            ) => {
                let (half_angle, base_radius) = (*half_angle, *base_radius);
                let depth = match protocol {
                    Protocol::Depth { depth } => depth.abs(),
                    Protocol::Cycle { max_depth, .. } => max_depth,
                    Protocol::Force { force }
                    | Protocol::ForceCycle {
                        max_force: force, ..
                    } => (0.5 * std::f64::consts::PI * force / (softest * half_angle.tan())).sqrt(),
                };
                (2.0 * depth * half_angle.tan() / std::f64::consts::PI).min(base_radius)
            }
        })
    }

    /// For an adhesive scene with a paraboloid, sphere or cone: the radii
    /// (m) of the loading peak's contact and of the smallest contact to
    /// resolve, the pull-off contact (and where
    /// [`Scene::resolves_jump_off`] the radius that gives the jump-off
    /// contact [`JUMP_OFF_CELLS`] across, [`Scene::jump_off_resolved`]),
    /// from the exact (layered) JKR solution, given the non-adhesive
    /// `estimate` of the peak's. `None` where there is none, or it fails.
    /// (A tilted tip is sized as its untilted one: the tilts are small.)
    fn adhesive_radii(&self, estimate: f64) -> Option<(f64, f64)> {
        let (_, receding) = self.adhesion.works()?;
        // A sphere by its own solution: its paraboloid's contact is wider
        // (at 0.8 of the radius the paraboloid's pull-off contact came to
        // 1.6 radii, and the grid resolved half the cells asked for).
        let curved = super::reference::curved_tip(&self.indenter)?;
        if receding == 0.0 {
            return None;
        }
        let substrate = self.substrate.build().ok()?;
        let Some((peak, unloading)) = self.exact_unloading(&substrate, curved, estimate)? else {
            return self.base_jkr_radii(&substrate, curved, estimate);
        };
        let least = |depth| {
            let state = least_of_unloading(&unloading, Some(peak.contact_radius), depth, false);
            Some(state.ok()?.contact_radius)
        };
        let mut smallest = least(false)?;
        if self.resolves_jump_off() {
            smallest = smallest.min(self.jump_off_resolved(least(true)?));
        }
        Some((peak.contact_radius, smallest))
    }

    /// The exact (layered) solution at the peak of the protocol (at the
    /// advancing work of adhesion) and the unloading from it (at the
    /// receding work), for the `curved` tip on `substrate`, given the
    /// non-adhesive `estimate` (m) of the peak's contact radius. `Some(None)`
    /// where the table stops short of the peak (beyond [`SIZING_MAX_EPS`]
    /// layer thicknesses or the tip's cap); `None` without adhesion, where
    /// the peak makes no contact, or where the solution fails.
    fn exact_unloading(
        &self,
        substrate: &crate::substrate::Substrate,
        curved: super::reference::CurvedTip,
        estimate: f64,
    ) -> Option<Option<(ContactState, LayeredTip)>> {
        let (advancing, receding) = self.adhesion.works()?;
        let scale = curved
            .on_half_space(substrate.surface_material(), receding)
            .ok()?
            .pull_off_contact_radius();
        // The exact solution is tabulated over the contact radii it may need:
        // the pull-off's (a few JKR scales) and the peak's (about twice the
        // non-adhesive estimate); its cost grows with the range.
        let reach = (3.0 * scale).max(2.0 * estimate);
        // Widened until the peak is within the table: adhesion (or a stiff
        // layer on a far softer base) may spread the contact far beyond
        // twice the non-adhesive estimate (1.0 mm against 0.18 mm for an
        // adhesive paraboloid on a thin layer over a base a thousand times
        // softer), past what growing the grid reaches.
        let Some((exact, peak)) = super::reference::tip_peak(
            substrate,
            (curved, advancing),
            self.protocol,
            reach,
            SIZING_MAX_EPS,
        )
        .ok()?
        else {
            return Some(None);
        };
        let unloading = exact.tip(curved.tip, receding).ok()?;
        Some(Some((peak?, unloading)))
    }

    /// The exact pull-off force (N, negative) of an adhesive cone's
    /// unloading from its peak (the untilted cone's, on the scene's body),
    /// `None` where the exact solution has none or does not reach the
    /// peak. A cone's pull-off depends on the body's modulus (`-54
    /// dgamma^2 / (pi E* s^3)` on a half-space), so no closed form bounds
    /// it on a layered body; the exact solution does.
    pub(super) fn exact_cone_pull_off(&self) -> Option<f64> {
        let curved = super::reference::curved_tip(&self.indenter)
            .filter(|c| matches!(c.tip, crate::analytic::Tip::Cone { .. }))?;
        let substrate = self.substrate.build().ok()?;
        let estimate = self.contact_radius_estimate().ok()?;
        let (peak, unloading) = self.exact_unloading(&substrate, curved, estimate)??;
        let least = least_of_unloading(&unloading, Some(peak.contact_radius), false, false);
        Some(least.ok()?.force)
    }

    /// The contact radius (m) whose diameter `cells_across` must span for
    /// a jump-off contact of radius `jump_off` (m) to have
    /// [`JUMP_OFF_CELLS`] across.
    fn jump_off_resolved(&self, jump_off: f64) -> f64 {
        jump_off * self.resolution.cells_across as f64 / JUMP_OFF_CELLS
    }

    /// Whether the grid must resolve the jump-off contact of a
    /// displacement-controlled unloading as well as the pull-off's: a
    /// depth cycle through the energy balance, which places its jump-off
    /// only on contact sets it resolves (the cohesive zone follows the
    /// contact down to whatever it covers, and says where its zone spans
    /// it).
    fn resolves_jump_off(&self) -> bool {
        matches!(self.protocol, Protocol::Cycle { .. })
            && self.resolved_adhesion_method() == AdhesionMethod::EnergyBalance
    }

    /// Where the exact table stops short of the contact (beyond
    /// [`SIZING_MAX_EPS`] layer thicknesses: layers on an elastic base
    /// thousands of times softer, whose contact is so wide that the base
    /// sets it; or a cone's contact beyond its base): JKR on a half-space
    /// of the base (the long-wave limit of the body; the layers only
    /// stiffen it), or the non-adhesive `estimate` where that is wider.
    /// `None` on a rigid base. Three random scenes of this kind, whose
    /// grids the non-adhesive estimate had made 10 to 30 times too narrow,
    /// now run (`tests/scene_reference.rs`).
    fn base_jkr_radii(
        &self,
        substrate: &crate::substrate::Substrate,
        curved: super::reference::CurvedTip,
        estimate: f64,
    ) -> Option<(f64, f64)> {
        let (advancing, receding) = self.adhesion.works()?;
        let base = crate::material::Material::new(substrate.deep_contact_modulus(), 0.0).ok()?;
        let peak = curved
            .on_half_space(&base, advancing)
            .ok()?
            .contact_radius_at(self.protocol.peak())?;
        let unloading = curved.on_half_space(&base, receding).ok()?;
        let pull_off = if self.resolves_jump_off() {
            unloading
                .pull_off_contact_radius()
                .min(self.jump_off_resolved(unloading.jump_off_contact_radius()))
        } else {
            unloading.pull_off_contact_radius()
        };
        let peak = peak.max(estimate).min(curved.cap);
        let pull_off = pull_off.min(curved.cap);
        (peak.is_normal() && pull_off.is_normal()).then_some((peak, pull_off))
    }

    /// The cohesive zone this scene's adhesion is solved with, `None`
    /// where the scene takes another method (or has no adhesion). Its zone
    /// grows with the resolution like the contact it resolves:
    /// [`CohesiveZone::with_resolution`] of
    /// [`cells_across`](super::Resolution::cells_across) (four cells up to
    /// 64 across, eight at 256), so that a scene's pull-off converges as
    /// `cells_across` grows instead of settling on the lattice's bias of a
    /// fixed zone (`BENCHMARKS.md`, "The cohesive zone grown with the
    /// resolution"). A height map or rough surface, solved on its own grid
    /// and not sized from a contact, keeps
    /// [`COHESIVE_ZONE_CELLS`](crate::solver::COHESIVE_ZONE_CELLS).
    ///
    /// ```
    /// use layered_contact::scene::{Adhesion, AdhesionMethod, IndenterSpec, Scene};
    ///
    /// let mut scene = Scene {
    ///     indenter: IndenterSpec::Sphere { radius: 1e-2 },
    ///     adhesion: Adhesion::Constant { work_of_adhesion: 0.05 },
    ///     ..Scene::default()
    /// };
    /// scene.solver.adhesion_method = AdhesionMethod::CohesiveZone;
    /// scene.resolution.cells_across = 256;
    /// assert_eq!(scene.cohesive_zone()?.unwrap().zone_cells(), 8.0);
    /// scene.solver.adhesion_method = AdhesionMethod::EnergyBalance;
    /// assert!(scene.cohesive_zone()?.is_none());
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a work of adhesion the law refuses
    /// ([`CohesiveZone::new`]).
    pub fn cohesive_zone(&self) -> Result<Option<CohesiveZone>> {
        let (Some((loading, unloading)), AdhesionMethod::CohesiveZone) =
            (self.adhesion.works(), self.resolved_adhesion_method())
        else {
            return Ok(None);
        };
        let zone = CohesiveZone::new(loading, unloading)?;
        if self.indenter.is_map() {
            return Ok(Some(zone));
        }
        zone.with_resolution(self.resolution.cells_across as f64)
            .map(Some)
    }

    /// The grid the scene is solved on (before any growth).
    ///
    /// # Errors
    /// As [`Scene::validate`].
    ///
    /// `cells_across` spans the diameter of the smallest contact the
    /// protocol must resolve: the punch, or for curved indenters the peak
    /// contact and, in an adhesive scene with a sphere, paraboloid or cone,
    /// the pull-off contact (from the exact layered JKR solution) if that is
    /// smaller. The grid holds the peak contact with `margin` on each side.
    /// Grid sizes are rounded up to products of 2, 3, 5 and 7 (fast FFTs).
    /// A [custom](IndenterSpec::Custom) indenter is treated like a curved
    /// one whose peak contact is its bounding disc. The height-map kinds are
    /// solved on their own grid.
    /// A flat punch's grid holds its face and a ring of cells; on a periodic
    /// grid it is the period of an array of punches, the diameter times `1 +
    /// 2 margin` (at least two cells more).
    /// For a flat punch (untilted or not) the spacing is adjusted within 2 %
    /// of `2a / cells_across` so that the cells whose centres lie on the
    /// punch have the punch's area (with the energy-balance or the
    /// cohesive-zone adhesion, the area of a disc
    /// [`EDGE_SHIFT`](crate::solver::EDGE_SHIFT) cells wider, since the
    /// balance's sets are shifted discs and the peeling path's release
    /// rates see the same edge): the staircase punch then
    /// has the right radius on average, and the stiffness converges smoothly
    /// like `1/N`, so that [`richardson`](crate::scene::richardson)
    /// extrapolation removes its error (see
    /// [`doc::accuracy`](crate::doc::accuracy)).
    pub fn grid(&self) -> Result<Grid> {
        self.validate_settings()?;
        if let Some(grid) = self.indenter.map_grid()? {
            return Ok(grid);
        }
        self.indenter.build(self.tilt)?;
        let n = self.resolution.cells_across;
        if let IndenterSpec::FlatPunch { radius } = self.indenter {
            // On a periodic grid the period: the diameter and the margin
            // on each side (an isolated grid holds the face and a ring).
            let across = match self.boundary {
                crate::grid::Boundary::Periodic => {
                    let period = n as f64 * (1.0 + 2.0 * self.resolution.margin);
                    (period.ceil() as usize).max(n + 2)
                }
                crate::grid::Boundary::Isolated => n + 2,
            };
            if across > MAX_GRID_CELLS {
                return Err(Error::InvalidParameter {
                    name: "resolution.margin",
                    value: self.resolution.margin,
                    expected: "a period of at most 8192 cells (the punch's cells across \
                               times 1 + 2 margin)",
                });
            }
            let mut cells = fft_friendly(across);
            // The energy balance's sets are shifted discs (EDGE_SHIFT), so
            // its punch is too, and so is the peeling path's that unloads
            // the cohesive zone's punch (Kendall -0.07, -0.26, -0.60 % at
            // 32, 64, 128 cells across against -1.10, -1.66, -1.05 % on the
            // equal-area staircase); the non-adhesive punch and the
            // mesh-dependent criterion (as published) take the equal-area
            // staircase, whose error is a clean `c / N` that Richardson
            // extrapolation removes (the shifted staircase's is smaller but
            // changes sign near 32 cells across and is not a power of `N`).
            let shift = match (self.adhesion, self.resolved_adhesion_method()) {
                (Adhesion::None, _) => 0.0,
                (_, AdhesionMethod::EnergyBalance | AdhesionMethod::CohesiveZone) => {
                    crate::solver::EDGE_SHIFT
                }
                _ => 0.0,
            };
            let spacing = equal_area_spacing(radius, n, cells, shift);
            // A ring of cells off the face all round (the peeling path
            // needs its rim inside the grid): the spacing is within 2 % of
            // `2a / n`, so the face may reach `n + 2` cells' outer ring
            // (at 68, 78, 88, 106 cells across, among others). The next
            // size of the same parity keeps the staircase (the punch
            // centred on a cell or a corner as before).
            for _ in 0..MAX_WIDENINGS {
                if !face_reaches_outer_ring(radius / spacing, cells) {
                    break;
                }
                cells = next_fft_friendly_of_parity(cells);
            }
            return Grid::new(cells, cells, spacing);
        }
        let peak = self.contact_radius_estimate()?;
        let (peak, resolved) = match self.adhesive_radii(peak) {
            Some((peak, pull_off)) => (peak, peak.min(pull_off)),
            None => {
                if !(peak.is_normal() && peak > 0.0) {
                    let (name, value) = self.protocol.reach();
                    return Err(Error::InvalidParameter {
                        name,
                        value,
                        expected: "a load that makes contact (the grid of a curved \
                                   indenter is sized from its contact)",
                    });
                }
                (peak, peak)
            }
        };
        let spacing = 2.0 * resolved / n as f64;
        let across = 2.0 * peak * (1.0 + 2.0 * self.resolution.margin) / spacing;
        // Room for the energy balance's sets beyond the peak contact.
        let headroom = if self.adhesion.works().is_some() {
            8.0
        } else {
            0.0
        };
        let cells = (across + headroom).ceil();
        if cells.is_nan() || cells > MAX_GRID_CELLS as f64 {
            return Err(Error::InvalidParameter {
                name: "resolution.cells_across",
                value: n as f64,
                expected: "a grid of at most 8192 cells across the peak contact \
                           (the pull-off contact is much smaller than the peak's)",
            });
        }
        let cells = fft_friendly(cells as usize);
        Grid::new(cells, cells, spacing)
    }
}

/// Widenings of a punch's grid tried before it is used as it is.
const MAX_WIDENINGS: usize = 16;

/// Whether a disc of `radius` cells about the centre of a `cells`-wide
/// square grid holds the centre of a cell of its outer ring.
fn face_reaches_outer_ring(radius: f64, cells: usize) -> bool {
    let edge = 0.5 * cells as f64 - 0.5;
    let off = if cells.is_multiple_of(2) { 0.5 } else { 0.0 };
    radius >= edge.hypot(off)
}

/// The next FFT-friendly size above `cells` of the same parity (bounded:
/// even sizes are every power of two apart at most; odd ones are products
/// of 3, 5 and 7).
fn next_fft_friendly_of_parity(cells: usize) -> usize {
    let mut candidate = cells + 1;
    for _ in 0..64 {
        let size = fft_friendly(candidate);
        if size % 2 == cells % 2 {
            return size;
        }
        candidate = size + 1;
    }
    cells + 2
}

/// A spacing within 2 % of `2 radius / n` for which the cells of a
/// `cells`-square grid whose centres lie within `radius` of its centre form
/// a staircase disc whose effective radius, `sqrt(A / pi) - shift` cells
/// (see [`EDGE_SHIFT`](crate::solver::EDGE_SHIFT)), is the punch's.
fn equal_area_spacing(radius: f64, n: usize, cells: usize, shift: f64) -> f64 {
    let half = 0.5 * cells as f64;
    // Cells of each row whose centres lie on the disc, counted in O(1) per
    // row: `|j + 0.5 - half| <= sqrt(r^2 - x^2) / spacing`.
    let area_error = |spacing: f64| {
        let r = radius / spacing;
        let inside: f64 = (0..cells)
            .map(|i| {
                let x = i as f64 + 0.5 - half;
                let reach = r * r - x * x;
                if reach < 0.0 {
                    return 0.0;
                }
                let w = reach.sqrt();
                // j + 0.5 - half in [-w, w]  <=>  j in [half - 0.5 - w, half - 0.5 + w]
                let lo = (half - 0.5 - w).ceil().max(0.0);
                let hi = (half - 0.5 + w).floor().min(cells as f64 - 1.0);
                (hi - lo + 1.0).max(0.0)
            })
            .sum();
        let effective = radius + shift * spacing;
        (inside * spacing * spacing / (std::f64::consts::PI * effective * effective) - 1.0).abs()
    };
    let nominal = 2.0 * radius / n as f64;
    (0..=80)
        .map(|k| nominal * (0.98 + 0.0005 * k as f64))
        .min_by(|a, b| area_error(*a).total_cmp(&area_error(*b)))
        .unwrap_or(nominal)
}

/// The contact radius of a paraboloid of tip radius `radius` at depth (or
/// force) `target` on a coated substrate, from the exact axisymmetric
/// solution (bisection on the contact radius); `None` if it cannot be found
/// (then the caller falls back to Hertz).
fn exact_contact_radius(
    substrate: &crate::substrate::Substrate,
    thickness: f64,
    radius: f64,
    target: f64,
    by_force: bool,
    hertz: f64,
) -> Option<f64> {
    let upper = (2.0 * hertz).min(radius);
    let eps = upper / thickness;
    if eps > SIZING_MAX_EPS {
        return None;
    }
    let exact = crate::analytic::Axisymmetric::new(substrate, eps).ok()?;
    let ball = exact.paraboloid(radius, 0.0).ok()?;
    let value = |a: f64| {
        ball.at_contact_radius(a)
            .ok()
            .map(|s| if by_force { s.force } else { s.depth })
    };
    if value(upper)? < target {
        return Some(upper);
    }
    let (mut lo, mut hi) = (0.0, upper);
    // 2^-30 of the bracket: far finer than a cell.
    for _ in 0..30 {
        let mid = 0.5 * (lo + hi);
        if value(mid)? < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(hi)
}
