//! The exact values a scene can be checked against, where they exist: the
//! axisymmetric solutions of [`analytic::Axisymmetric`](crate::analytic::Axisymmetric) for an untilted flat
//! punch, paraboloid, sphere or cone on an isolated half-space or coated body.

use crate::analytic::{
    Axisymmetric, ContactState, JkrCone, JkrFlatPunch, JkrSphere, LayeredTip, Tip,
};
use crate::error::{Error, Result};
use crate::grid::Boundary;
use crate::material::Material;
use crate::solver::Reach;
use crate::substrate::Substrate;

use super::{IndenterSpec, Protocol, Quantity, Scene};
#[cfg(doc)]
use crate::analytic::LayeredFlatPunch;

/// An exact value of one of a scene's [`Quantity`]s.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Reference {
    /// Which quantity of the scene's curve it is for.
    pub quantity: Quantity,
    /// Its exact value (SI units).
    pub value: f64,
    /// Where it comes from.
    pub source: &'static str,
}

/// Solutions are not tabulated beyond this `a/h` for a reference (the
/// Nystrom order grows like `8 a/h`).
const REFERENCE_MAX_EPS: f64 = 50.0;

/// How many times [`tip_peak`] widens its table fourfold for a peak
/// the table does not reach (on a layered body `exact_to` refuses tables
/// past their largest `a/h` first).
const MAX_WIDENINGS: usize = 8;

impl Scene {
    /// The exact values this scene's curve can be compared with: for an
    /// untilted flat punch, paraboloid, sphere or cone on an isolated grid,
    /// from the exact axisymmetric solution on the scene's substrate (the
    /// sphere's own, not its paraboloid's: [`Tip::Sphere`]; the cone's,
    /// [`Tip::Cone`], JKR's cone of Maugis & Barquins 1981 on a half-space).
    ///
    /// * Flat punch: the stiffness; the force at the deepest step of a
    ///   depth-driven protocol; with adhesion the pull-off force at the
    ///   unloading work of adhesion (Kendall's on a half-space), its edge
    ///   followed as it peels inward where that is stable
    ///   ([`Axisymmetric::punch_pull_off`]: a stiff plate over a far softer
    ///   base). Without
    ///   adhesion none where the bonded solution pulls somewhere on the
    ///   face ([`LayeredFlatPunch::holds_without_adhesion`]): the face then
    ///   lifts off there and the contact is not the face.
    /// * Paraboloid, sphere and cone: the force and contact radius at the deepest
    ///   step of a depth-driven protocol, or the contact radius at the peak
    ///   force of a force-driven one (at the advancing work of adhesion);
    ///   with adhesion the load-controlled pull-off force at the receding work
    ///   (JKR's `-3/2 pi R dgamma` on a half-space), which is also the least
    ///   force of a displacement-controlled unloading; where the peak's
    ///   contact is narrower than that pull-off's (a receding work well
    ///   above the advancing one), the force at which the pinned contact
    ///   lets go, the receding state at the peak's radius. Without
    ///   adhesion none where that disc's solution pulls somewhere inside
    ///   ([`LayeredTip::holds_without_adhesion`]): a stiff layer on a far
    ///   softer base lifts off the tip's middle, and the contact is a ring.
    ///
    /// Empty for other scenes, for contacts wider than 50 layer
    /// thicknesses, and for a sphere pressed to a contact beyond 0.95 of its
    /// radius.
    ///
    /// ```
    /// use layered_contact::scene::{IndenterSpec, Protocol, Quantity, Scene, SubstrateSpec};
    ///
    /// let scene = Scene {
    ///     substrate: SubstrateSpec::HalfSpace { youngs_modulus: 1e6, poisson_ratio: 0.5 },
    ///     indenter: IndenterSpec::FlatPunch { radius: 1e-3 },
    ///     protocol: Protocol::Depth { depth: 1e-5 },
    ///     ..Scene::default()
    /// };
    /// let stiffness = scene.reference()?[0];
    /// assert_eq!(stiffness.quantity, Quantity::Stiffness);
    /// // 2 E* a with E* = E / (1 - nu^2).
    /// assert!((stiffness.value / (2.0 * 1e6 / 0.75 * 1e-3) - 1.0).abs() < 1e-12);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Scene::validate`], and failures of the exact solution.
    pub fn reference(&self) -> Result<Vec<Reference>> {
        self.validate()?;
        if self.boundary != Boundary::Isolated || !self.untilted() {
            return Ok(Vec::new());
        }
        let substrate = self.substrate.build()?;
        let (advancing, receding) = self.adhesion.works().unwrap_or((0.0, 0.0));
        let adhesive = self.adhesion.works().is_some();
        let mut out = Vec::new();
        match (&self.indenter, curved_tip(&self.indenter)) {
            (&IndenterSpec::FlatPunch { radius }, _) => {
                let Some(exact) = exact_to(&substrate, radius, REFERENCE_MAX_EPS)? else {
                    return Ok(out);
                };
                let punch = exact.flat_punch(radius)?;
                // Without adhesion the face is the contact only where the
                // bonded solution presses everywhere on it: a stiff layer
                // on a soft base pulls at the face's centre (its least
                // pressure is negative), the face then lifts off there,
                // and the bonded stiffness is not the scene's (9 % above
                // the converged solve at `a/h` = 5.6 and `E2/E1` = 2.6e-4).
                if !adhesive && !punch.holds_without_adhesion() {
                    return Ok(out);
                }
                let source = "exact axisymmetric flat punch";
                out.push(Reference {
                    quantity: Quantity::Stiffness,
                    value: punch.stiffness(),
                    source,
                });
                // At depth <= 0 the punch makes no contact (force 0, no
                // relative error to speak of); the bonded solution's
                // tension would not be the problem solved.
                if let Some(depth) = self.peak_depth().filter(|&d| d > 0.0) {
                    out.push(Reference {
                        quantity: Quantity::PeakForce,
                        value: punch.stiffness() * depth,
                        source,
                    });
                }
                if adhesive && receding > 0.0 {
                    // Its edge peeling inward: the least force a
                    // force-driven unloading reaches, or a depth-driven
                    // one before its depth turns.
                    let pull_off = exact.punch_pull_off(radius, receding)?;
                    let (load, depth) = (pull_off.load_control, pull_off.displacement_control);
                    let by_force = matches!(self.protocol.peak(), Reach::Force(_));
                    let value = if by_force || load.contact_radius >= depth.contact_radius {
                        load.force
                    } else {
                        depth.force
                    };
                    out.push(Reference {
                        quantity: Quantity::PullOffForce,
                        value,
                        source,
                    });
                }
            }
            (_, Some(curved)) => {
                let tip = curved.tip;
                let source = match tip {
                    Tip::Sphere { .. } => "exact axisymmetric sphere",
                    Tip::Cone { .. } => "exact axisymmetric cone",
                    _ => "exact axisymmetric paraboloid",
                };
                // The widest contact wanted: twice the non-adhesive radius
                // at the peak (a force-driven peak by the surface
                // material's modulus), or a few JKR radii at pull-off.
                let surface = substrate.surface_material();
                let dry = curved
                    .on_half_space(surface, 0.0)?
                    .contact_radius_at(self.protocol.peak())
                    .unwrap_or(0.0);
                let jkr = curved
                    .on_half_space(surface, receding)?
                    .pull_off_contact_radius();
                let widest = (2.0 * dry).max(3.0 * jkr);
                let Some((exact, peak)) = tip_peak(
                    &substrate,
                    (curved, advancing),
                    self.protocol,
                    widest,
                    REFERENCE_MAX_EPS,
                )?
                else {
                    return Ok(out);
                };
                if let Some(state) = peak.filter(|s| s.contact_radius > 0.0) {
                    // Without adhesion the disc is the contact only where
                    // its solution presses everywhere: a stiff layer on a
                    // far softer base, pressed far, lifts off the tip's
                    // middle (the contact a ring; a sphere's disc pulled
                    // there at 18 % of its mean pressure, and its radius
                    // was 45 % off the BEM's ring's area).
                    if !adhesive
                        && !exact
                            .tip(tip, 0.0)?
                            .holds_without_adhesion(state.contact_radius)?
                    {
                        return Ok(out);
                    }
                    if self.peak_depth().is_some() {
                        out.push(Reference {
                            quantity: Quantity::PeakForce,
                            value: state.force,
                            source,
                        });
                    }
                    out.push(Reference {
                        quantity: Quantity::PeakContactRadius,
                        value: state.contact_radius,
                        source,
                    });
                }
                if adhesive && receding > 0.0 {
                    let unloading = exact.tip(tip, receding)?;
                    // The least force of the unloading from the peak: a
                    // contact pinned at a peak narrower than the free
                    // pull-off's (a receding work well above the advancing
                    // one) comes off as its edge lets go, at the receding
                    // state of the peak's radius (`LayeredJkrCycle::
                    // unloading_pull_off`: a sphere with works 0.0088 and
                    // 0.074 J/m^2 let go at a force 17 % under the free
                    // pull-off's); a film on a far softer base has a
                    // second, deeper least force far beyond the peak,
                    // which the unloading never reaches (a cone on a film
                    // over a base 300 times softer came off at -1.5 mN,
                    // its reference the peak's +2.5 mN before).
                    let least = least_of_unloading(
                        &unloading,
                        peak.map(|p| p.contact_radius),
                        false,
                        matches!(self.protocol, Protocol::Cycle { .. }),
                    );
                    // Beyond the table, or jumped over inside a fold of
                    // the receding branch: no pull-off reference.
                    let pull_off = match least {
                        Err(
                            Error::InvalidParameter {
                                name: "contact_radius",
                                ..
                            }
                            | Error::Unsupported { .. },
                        ) => return Ok(out),
                        other => other?,
                    };
                    // A cone pulled off beyond its base: not a cone's.
                    if pull_off.contact_radius > curved.cap {
                        return Ok(out);
                    }
                    let force = pull_off.force;
                    out.push(Reference {
                        quantity: Quantity::PullOffForce,
                        value: force,
                        source,
                    });
                }
            }
            _ => {}
        }
        Ok(out)
    }

    /// The deepest depth of a depth-driven protocol.
    fn peak_depth(&self) -> Option<f64> {
        match self.protocol.peak() {
            Reach::Depth(depth) => Some(depth),
            Reach::Force(_) => None,
        }
    }
}

/// The closed form's pull-off over this factor bounds a force cycle's
/// pull-off from below ([`Scene::pull_off_bound`]).
const PULL_OFF_MARGIN: f64 = 10.0;

impl Scene {
    /// A lower bound (N, positive) on the magnitude of the pull-off force of
    /// this scene's adhesive unloading, where a closed form (or for a cone
    /// the exact solution) gives one; `None` elsewhere (periodic grids,
    /// height maps, custom and tilted flat indenters) and without
    /// adhesion. A tenth ([`PULL_OFF_MARGIN`]) of:
    ///
    /// * a paraboloid: JKR's `3/2 pi R dgamma` (Johnson, Kendall & Roberts
    ///   1971, Proc. R. Soc. A 324, 301), which does not depend on the
    ///   body's modulus (a layered body's pull-off lies near it: between
    ///   its two half-space limits);
    /// * a sphere: the smaller of that and Kendall's punch of the sphere's
    ///   radius, `sqrt(8 pi R^3 E* dgamma)` (Kendall 1971, J. Phys. D 4,
    ///   1186), since its contact cannot pass the equator;
    /// * an untilted flat punch: Kendall's of its radius;
    /// * a cone, tilted or not: the exact pull-off of the untilted cone on
    ///   the scene's body ([`Scene::exact_cone_pull_off`]; on a half-space
    ///   Maugis & Barquins' `54 dgamma^2 tan^3(theta) / (pi E*)`), since a
    ///   cone's depends on the modulus;
    ///
    /// `E*` the softest contact modulus of the body (a softer body lets go
    /// at a smaller force), `dgamma` the receding work of adhesion.
    pub(super) fn pull_off_bound(&self, substrate: &Substrate) -> Option<f64> {
        let (_, receding) = self.adhesion.works()?;
        if self.boundary != Boundary::Isolated {
            return None;
        }
        // A half-space of the softest modulus (`nu = 0`: `E* = E`).
        let softest = Material::new(substrate.softest_contact_modulus(), 0.0).ok()?;
        let jkr = |radius| {
            Some(
                -JkrSphere::new(&softest, radius, receding)
                    .ok()?
                    .pull_off_force(),
            )
        };
        let kendall = |radius| {
            Some(
                -JkrFlatPunch::new(&softest, radius, receding)
                    .ok()?
                    .pull_off_force(),
            )
        };
        let closed = match self.indenter {
            IndenterSpec::Paraboloid { radius } => jkr(radius)?,
            IndenterSpec::Sphere { radius } => jkr(radius)?.min(kendall(radius)?),
            IndenterSpec::FlatPunch { radius } if self.untilted() => kendall(radius)?,
            IndenterSpec::Cone { .. } => -self.exact_cone_pull_off()?,
            _ => return None,
        };
        Some(closed / PULL_OFF_MARGIN).filter(|b| b.is_finite())
    }
}

/// A curved indenter of the exact solution: its [`Tip`] and the widest
/// contact radius (m) it has (a sphere's 0.95 of its radius, where its
/// exact solution ends; a cone's base radius, beyond which it cannot
/// touch; unbounded for a paraboloid).
#[derive(Debug, Clone, Copy)]
pub(super) struct CurvedTip {
    pub(super) tip: Tip,
    pub(super) cap: f64,
}

/// The exact solution's tip for a sphere, paraboloid or cone indenter;
/// `None` for other indenters.
pub(super) fn curved_tip(indenter: &IndenterSpec) -> Option<CurvedTip> {
    let (tip, cap) = match *indenter {
        IndenterSpec::Sphere { radius } => (Tip::Sphere { radius }, 0.95 * radius),
        IndenterSpec::Paraboloid { radius } => (Tip::Paraboloid { radius }, f64::INFINITY),
        IndenterSpec::Cone {
            half_angle,
            base_radius,
        } => (Tip::Cone { half_angle }, base_radius),
        _ => return None,
    };
    Some(CurvedTip { tip, cap })
}

/// A curved tip's JKR contact on a half-space, in closed form: the sphere's
/// paraboloid (Johnson, Kendall & Roberts 1971) or the cone (Maugis &
/// Barquins 1981). Sizes grids and tables; never a reference itself.
pub(super) enum HalfSpaceJkr {
    Paraboloid(JkrSphere),
    Cone(JkrCone),
}

impl CurvedTip {
    /// The tip's JKR contact on a half-space of `material` with `work`
    /// (J/m^2; 0 for the non-adhesive contact).
    pub(super) fn on_half_space(&self, material: &Material, work: f64) -> Result<HalfSpaceJkr> {
        Ok(match self.tip {
            Tip::Cone { half_angle } => {
                HalfSpaceJkr::Cone(JkrCone::new(material, half_angle, work)?)
            }
            Tip::Sphere { radius } | Tip::Paraboloid { radius } => {
                HalfSpaceJkr::Paraboloid(JkrSphere::new(material, radius, work)?)
            }
            _ => {
                return Err(Error::Internal {
                    what: "curved tip",
                    detail: "a scene's curved tip is a sphere, paraboloid or cone".into(),
                })
            }
        })
    }
}

impl HalfSpaceJkr {
    /// The contact radius at load-controlled pull-off, m.
    pub(super) fn pull_off_contact_radius(&self) -> f64 {
        match self {
            HalfSpaceJkr::Paraboloid(jkr) => jkr.pull_off_contact_radius(),
            HalfSpaceJkr::Cone(jkr) => jkr.pull_off_contact_radius(),
        }
    }

    /// The contact radius at which a displacement-controlled unloading
    /// jumps off, m.
    pub(super) fn jump_off_contact_radius(&self) -> f64 {
        match self {
            HalfSpaceJkr::Paraboloid(jkr) => jkr.critical_contact_radius(),
            HalfSpaceJkr::Cone(jkr) => jkr.critical_contact_radius(),
        }
    }

    /// The contact radius (m) at a protocol's peak, `None` where the
    /// contact has come off (or none is made).
    pub(super) fn contact_radius_at(&self, peak: Reach) -> Option<f64> {
        match (self, peak) {
            (HalfSpaceJkr::Paraboloid(jkr), Reach::Depth(depth)) => {
                jkr.contact_radius_at_depth(depth)
            }
            (HalfSpaceJkr::Paraboloid(jkr), Reach::Force(force)) => {
                jkr.contact_radius_at_force(force)
            }
            (HalfSpaceJkr::Cone(jkr), Reach::Depth(depth)) => jkr.contact_radius_at_depth(depth),
            (HalfSpaceJkr::Cone(jkr), Reach::Force(force)) => jkr.contact_radius_at_force(force),
        }
    }
}

/// The state of least force (`depth` false) or depth of the exact
/// `unloading` from a peak contact of `peak_radius` (m): below it, not a
/// deeper one beyond it (a film on a much softer base,
/// [`LayeredTip::least_below`], which refuses a least force that a
/// depth-controlled unloading (`displacement_control`) jumps over); where
/// the peak makes no contact (`None` or 0), over every radius.
///
/// # Errors
/// As [`LayeredTip::pull_off`].
pub(super) fn least_of_unloading(
    unloading: &LayeredTip,
    peak_radius: Option<f64>,
    depth: bool,
    displacement_control: bool,
) -> Result<ContactState> {
    match peak_radius.filter(|&a| a > 0.0) {
        Some(a) => unloading.least_below(a, depth, displacement_control),
        None if depth => unloading.pull_off().map(|p| p.displacement_control),
        None => unloading.load_controlled_pull_off(),
    }
}

/// The exact solutions on `substrate` tabulated from contact radius
/// `reach` (m) on, and the peak of `protocol` for `(tip, work)` (a
/// paraboloid, sphere or cone, the work of adhesion J/m^2): where the peak
/// lies beyond the table (a stiff layer on a far softer base, or adhesion,
/// spreads the contact beyond twice Hertz's radius) the table widens
/// fourfold, at most [`MAX_WIDENINGS`] times. `None` where it would reach
/// past `max_eps` layer thicknesses, or past the tip's cap (0.95 of a
/// sphere's radius, where its exact solution ends; a cone's base).
///
/// # Errors
/// Failures of the exact solution other than a peak beyond the table.
pub(super) fn tip_peak(
    substrate: &Substrate,
    (curved, work): (CurvedTip, f64),
    protocol: Protocol,
    reach: f64,
    max_eps: f64,
) -> Result<Option<(Axisymmetric, Option<ContactState>)>> {
    let CurvedTip { tip, cap } = curved;
    let mut reach = reach;
    for widening in 0..=MAX_WIDENINGS {
        let Some(exact) = exact_to(substrate, reach, max_eps)? else {
            return Ok(None);
        };
        let tip_solution = exact.tip(tip, work)?;
        let peak = match protocol.peak() {
            // The state the loading reaches, not a wider one beyond a fold.
            Reach::Depth(depth) => tip_solution.loading_at_depth(depth),
            Reach::Force(force) => tip_solution.loading_at_force(force),
        };
        match peak {
            // Beyond a sphere's cap a wider table does not help.
            Err(Error::InvalidParameter {
                name: "depth" | "force",
                ..
            }) if reach >= cap => return Ok(None),
            Err(Error::InvalidParameter {
                name: "depth" | "force",
                ..
            }) if widening < MAX_WIDENINGS => reach *= 4.0,
            // A cone's contact beyond its base is not a cone's.
            Ok(Some(state)) if state.contact_radius > cap => return Ok(None),
            other => return Ok(Some((exact, other?))),
        }
    }
    Ok(None)
}

/// The exact solutions on `substrate` for contacts up to `radius`, `None`
/// beyond `max_eps` layer thicknesses.
fn exact_to(substrate: &Substrate, radius: f64, max_eps: f64) -> Result<Option<Axisymmetric>> {
    let within = substrate
        .top_thickness()
        .is_none_or(|thickness| radius / thickness <= max_eps);
    if !(within && radius > 0.0 && radius.is_finite()) {
        return Ok(None);
    }
    Axisymmetric::up_to_contact_radius(substrate, radius).map(Some)
}
