//! Which adhesion method a scene runs: [`AdhesionMethod::Auto`] resolved
//! to the method that converges to the JKR limit for the scene.

use std::cell::RefCell;

use super::{AdhesionMethod, IndenterSpec, Scene};
use crate::analytic::Axisymmetric;
use crate::grid::Boundary;

/// The least `(A / k) dk/dA` at a punch's face (the bonded contact's
/// stiffness `k` against its area `A`; 0.5 on a half-space, 2 for a thin
/// incompressible film on a rigid base) at which the energy balance takes
/// the punch: below it `auto` takes the cohesive zone's peeling path, and
/// an energy-balance curve carries
/// [`Caveat::EnergyBalanceFlatStiffness`](super::Caveat::EnergyBalanceFlatStiffness).
/// Measured (`examples/punch_peeling.rs`, `BENCHMARKS.md`, "Seeds 156, 159
/// and 162 settled"): a punch on a stiff plate over bases of 0.19 Pa to
/// 190 kPa, the ratio 0.0039 to 0.92; the energy balance's pull-off 0.5 to
/// 6 % off at 16 to 64 cells across where it is 0.25 or less, not
/// converging, within 1.1 % where it is 0.57 or more; the peeling path
/// within 0.9 / 0.42 / 0.24 % at 16 / 32 / 64 cells on all seven.
pub(super) const PUNCH_STIFFNESS_SLOPE: f64 = 0.4;

/// The widest punch, in top-layer thicknesses, whose stiffness slope `auto`
/// reads from the exact solution, as [`Scene::reference`] does (its
/// Nystrom order grows like `8 a/h`: 0.05 s at 10 thicknesses on the plate
/// of `examples/punch_peeling.rs`, which prints it; `BENCHMARKS.md`,
/// "`auto` peels a punch whose stiffness barely changes"); a wider one
/// keeps the energy balance, its curve flagged by the branches' own slope.
const SLOPE_MAX_EPS: f64 = 50.0;

thread_local! {
    /// The last punch whose stiffness slope was read: its substrate (as
    /// printed), its radius's bits and the slope (`None` where the exact
    /// solution gave none), so that a scene's several calls read it once.
    static LAST_SLOPE: RefCell<Option<(String, u64, Option<f64>)>> = const { RefCell::new(None) };
}

impl Scene {
    /// The adhesion method this scene runs: its
    /// [`SolverSettings::adhesion_method`](super::SolverSettings::adhesion_method),
    /// with [`Auto`](AdhesionMethod::Auto) resolved to the energy balance
    /// for an untilted sphere or cone, any paraboloid (a tilted one is a
    /// paraboloid moved off the axis) and an untilted flat punch whose
    /// stiffness grows with its contact (below), all on an isolated grid,
    /// and to the cohesive zone for every other scene (never `Auto`).
    ///
    /// A flat punch on a layered body goes to the cohesive zone (its
    /// unloading along the peeling path by the local criterion) where the
    /// exact bonded punch's `(A / k) dk/dA` at its face is below 0.4 (a
    /// stiff plate over a far softer base; 0.5 on a half-space): there the
    /// energy balance's release rate, the area derivative of a stiffness
    /// that barely changes, came out 0.5 to 6 % off on such bodies, not
    /// converging with the grid, where the peeling path converges like
    /// `1 / N` (`BENCHMARKS.md`, "Seeds 156, 159 and 162 settled";
    /// [`Caveat::EnergyBalanceFlatStiffness`](super::Caveat::EnergyBalanceFlatStiffness)).
    /// The slope is read from the exact
    /// axisymmetric solution ([`LayeredFlatPunch`](crate::analytic::LayeredFlatPunch))
    /// for punches up to 50 top-layer thicknesses wide.
    ///
    /// ```
    /// use layered_contact::scene::{AdhesionMethod, IndenterSpec, Scene, Tilt};
    ///
    /// let sphere = Scene {
    ///     indenter: IndenterSpec::Paraboloid { radius: 0.01 },
    ///     ..Scene::default()
    /// };
    /// assert_eq!(sphere.resolved_adhesion_method(), AdhesionMethod::EnergyBalance);
    /// let tilted = Scene {
    ///     indenter: IndenterSpec::Cone { half_angle: 1.2, base_radius: 1e-3 },
    ///     tilt: Some(Tilt { angle_x: 0.0, angle_y: 0.01 }),
    ///     ..Scene::default()
    /// };
    /// assert_eq!(tilted.resolved_adhesion_method(), AdhesionMethod::CohesiveZone);
    /// ```
    pub fn resolved_adhesion_method(&self) -> AdhesionMethod {
        if self.solver.adhesion_method != AdhesionMethod::Auto {
            return self.solver.adhesion_method;
        }
        if self.contact_sets_are_discs() && !self.punch_stiffness_is_flat() {
            AdhesionMethod::EnergyBalance
        } else {
            AdhesionMethod::CohesiveZone
        }
    }

    /// The adhesion method this scene's adhesive steps run
    /// ([`resolved_adhesion_method`](Self::resolved_adhesion_method)), or
    /// `None` for a scene without adhesion: what the tool prints and
    /// Python's `Curve.adhesion_method` gives.
    ///
    /// ```
    /// use layered_contact::scene::{Adhesion, AdhesionMethod, Scene};
    ///
    /// assert_eq!(Scene::default().adhesion_method_run(), None);
    /// let sticky = Scene {
    ///     adhesion: Adhesion::Constant { work_of_adhesion: 0.05 },
    ///     ..Scene::default()
    /// };
    /// assert_eq!(sticky.adhesion_method_run(), Some(AdhesionMethod::EnergyBalance));
    /// ```
    pub fn adhesion_method_run(&self) -> Option<AdhesionMethod> {
        self.adhesion
            .works()
            .map(|_| self.resolved_adhesion_method())
    }

    /// Whether the indenter's level sets are discs on an isolated grid, where
    /// the energy balance releases evenly along the edge and is exact: an
    /// untilted sphere, paraboloid, cone or flat punch, and a tilted
    /// paraboloid (`r^2 / 2R + x tan(t)` is the paraboloid about `x = -R
    /// tan(t)`, lowered by `R tan(t)^2 / 2`).
    pub(crate) fn contact_sets_are_discs(&self) -> bool {
        let untilted = self.untilted();
        self.boundary == Boundary::Isolated
            && match self.indenter {
                IndenterSpec::Paraboloid { .. } => true,
                IndenterSpec::Sphere { .. }
                | IndenterSpec::Cone { .. }
                | IndenterSpec::FlatPunch { .. } => untilted,
                _ => false,
            }
    }

    /// Whether the scene has no tilt, or a tilt of zero angles.
    pub(crate) fn untilted(&self) -> bool {
        self.tilt
            .is_none_or(|t| t.angle_x == 0.0 && t.angle_y == 0.0)
    }

    /// Whether the scene is an adhesive flat punch on a layered body whose
    /// exact bonded stiffness barely changes with its contact: `(A / k)
    /// dk/dA` at the face below [`PUNCH_STIFFNESS_SLOPE`]. False where the
    /// slope is not read (a half-space, a punch wider than
    /// [`SLOPE_MAX_EPS`] top-layer thicknesses, a substrate that does not
    /// build).
    fn punch_stiffness_is_flat(&self) -> bool {
        let IndenterSpec::FlatPunch { radius } = self.indenter else {
            return false;
        };
        if self.adhesion.works().is_none() {
            return false;
        }
        let Ok(substrate) = self.substrate.build() else {
            return false;
        };
        let Some(thickness) = substrate.top_thickness() else {
            return false;
        };
        if !(radius > 0.0 && radius.is_finite() && radius / thickness <= SLOPE_MAX_EPS) {
            return false;
        }
        let key = (format!("{:?}", self.substrate), radius.to_bits());
        let cached = LAST_SLOPE.with_borrow(|last| {
            last.as_ref()
                .filter(|(s, r, _)| (s, r) == (&key.0, &key.1))
                .map(|(_, _, slope)| *slope)
        });
        let slope = cached.unwrap_or_else(|| {
            let slope = punch_stiffness_slope(&substrate, radius);
            LAST_SLOPE.set(Some((key.0, key.1, slope)));
            slope
        });
        slope.is_some_and(|s| s < PUNCH_STIFFNESS_SLOPE)
    }
}

/// `(A / k) dk/dA` of the bonded flat punch of `radius` on `substrate` at
/// its face, exactly ([`LayeredFlatPunch::area_slope`](crate::analytic::LayeredFlatPunch::area_slope)).
/// `None` where the exact solution fails or gives a value that is not
/// finite and positive.
fn punch_stiffness_slope(substrate: &crate::Substrate, radius: f64) -> Option<f64> {
    let exact = Axisymmetric::up_to_contact_radius(substrate, radius).ok()?;
    let slope = exact.flat_punch(radius).ok()?.area_slope();
    (slope.is_finite() && slope > 0.0).then_some(slope)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::substrate::Base;
    use crate::{Material, Substrate};

    /// The slope from the rim's release rate against a central difference
    /// of the exact stiffness over +-0.1 % of the radius (its truncation
    /// about 1e-6 of the slope, the Nystrom solutions' own error below
    /// that): on a half-space 0.5 (`k = 2 a E*`), on a stiff plate over a
    /// far softer base 0.0039 and over a stiffer one 0.57 (the punches of
    /// `examples/punch_peeling.rs`), within 1e-5 of the difference
    /// (measured 5.3e-7 on the soft base).
    #[test]
    fn the_slope_is_the_stiffness_derivative() {
        let top = Material::new(1e3, 0.45).unwrap();
        let plate = Material::new(7.238902357342152e5, 0.0).unwrap();
        let on = |base: f64| {
            Substrate::stack(
                &[(top, 9.624654318820577e-3), (plate, 2.8840133077183354e-2)],
                Base::Elastic(Material::new(base, 0.0).unwrap()),
            )
            .unwrap()
        };
        let radius = 0.1;
        for (body, expected) in [
            (Substrate::half_space(top), 0.5),
            (on(0.19), 0.0039),
            (on(1.9e4), 0.569),
        ] {
            let slope = punch_stiffness_slope(&body, radius).unwrap();
            let exact = Axisymmetric::up_to_contact_radius(&body, 1.01 * radius).unwrap();
            let k = |a: f64| exact.flat_punch(a).unwrap().stiffness();
            let dk = (k(1.001 * radius) - k(0.999 * radius)) / (0.002 * radius);
            let difference = dk * radius / (2.0 * k(radius));
            assert!(
                (slope / difference - 1.0).abs() < 1e-5,
                "{slope} {difference}"
            );
            assert!((slope / expected - 1.0).abs() < 0.01, "{slope} {expected}");
        }
    }
}
