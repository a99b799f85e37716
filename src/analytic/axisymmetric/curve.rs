//! The force-indentation curve of a tip on a coated body, tabulated once
//! and then evaluated at any depth, modulus and work of adhesion in
//! microseconds: the model a fit calls a hundred times per measured curve.
//!
//! The table holds, at contact radii spaced evenly in `ln a`, the
//! non-adhesive state `d0(a)`, `F0(a)` of the tip and the stiffness `K(a)`
//! and edge factor `psi1(a)` of the flat punch of the same radius. With a
//! work of adhesion `w` the JKR state at that radius follows without
//! solving again (the adhesive part is the punch's, linear elasticity):
//! `d = d0 - sqrt(2 pi a w / E*) / psi1`, `F = F0 + K (d - d0)`. On a
//! single layer over a rigid base (or a half-space) the solution depends on
//! the modulus only through `E*`, so `F0` and `K` scale with it.
//!
//! A depth's force is found along the fixed-grips branch (from the least
//! depth on) by cubic Hermite interpolation in `ln a` of `d` and `F` (of
//! `ln d` and `ln F` without adhesion, where they are nearly linear), with
//! slopes from fifth-order differences of the evenly spaced table, and a
//! safeguarded Newton inversion of `d(ln a)` within its interval.

use super::{Axisymmetric, ContactState, LayeredParaboloid, LayeredTip, Tip};
use crate::error::{positive_finite, Error, Result};
use crate::substrate::Substrate;

/// Radii in the table, spaced evenly in `ln a` from `SMALLEST` times the
/// largest: 500 over five decades, a step of 2.3 %. Interpolation error,
/// relative to the curve's largest force: 1e-10 to 4e-10 without adhesion,
/// up to 6e-8 with it next to the fixed-grips branch's start
/// (`tests/force_curve.rs`).
const POINTS: usize = 500;
const SMALLEST: f64 = 1e-5;
/// Attempts to widen the table until it reaches the deepest indentation.
const WIDENINGS: usize = 24;
/// The table's largest contact radius over the least that reaches its
/// `max_depth` without adhesion: adhesion lifts the indenter at a given
/// contact radius, so an adhesive curve needs larger radii to reach the
/// same depth. Twice the radius holds, for a paraboloid on a half-space,
/// works of adhesion up to `9 E* max_depth^2 / (4 pi a)` (`a` the contact
/// radius at `max_depth` without adhesion: the lift at `2 a` is then `3
/// max_depth`); beyond, [`ForceCurve::reach`] says how deep the table goes.
const HEADROOM: f64 = 2.0;
/// Safeguarded Newton steps of the inversion (1e-14 of an interval after 5).
const NEWTON_STEPS: usize = 8;

/// The tabulated force curve of one tip on one coated body.
///
/// ```
/// use layered_contact::analytic::{Axisymmetric, ForceCurve, Tip};
/// use layered_contact::{Material, Substrate};
///
/// let film = Substrate::layer_on_rigid_base(Material::new(10e3, 0.5)?, 4e-6)?;
/// let exact = Axisymmetric::up_to_contact_radius(&film, 10e-6)?;
/// let curve = ForceCurve::new(&exact, Tip::Paraboloid { radius: 5e-6 }, 2e-6)?;
/// let state = exact.paraboloid(5e-6, 0.0)?.at_contact_radius(2e-6)?;
/// // At the modulus of the table (ratio 1), without adhesion:
/// let f = curve.force(state.depth, 1.0, 0.0);
/// assert!((f / state.force - 1.0).abs() < 1e-7);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct ForceCurve {
    pub(super) contact_modulus: f64,
    pub(super) tip: Option<Tip>,
    /// `ln a`, evenly spaced (one entry for a flat punch).
    pub(super) log_radius: Vec<f64>,
    pub(super) radius: Vec<f64>,
    pub(super) depth: Vec<f64>,
    pub(super) force: Vec<f64>,
    /// `ln d0`, `ln F0` (empty for a flat punch).
    pub(super) log_depth: Vec<f64>,
    pub(super) log_force: Vec<f64>,
    pub(super) stiffness: Vec<f64>,
    pub(super) edge: Vec<f64>,
    pub(super) max_depth: f64,
}

impl ForceCurve {
    /// The curve of `tip` on the body of `exact`, tabulated to `max_depth`
    /// (m) of indentation.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a `max_depth` that is not positive
    /// and finite, or one the exact solution does not reach within its
    /// range of contact radii (a spherical cap's below 0.95 of its radius);
    /// others as [`LayeredTip::at_contact_radius`](super::LayeredTip::at_contact_radius).
    pub fn new(exact: &Axisymmetric, tip: Tip, max_depth: f64) -> Result<Self> {
        let branch = Branch::new(exact, tip)?;
        let largest = Self::largest_radius(exact, &branch, tip, max_depth)?;
        Self::tabulate(exact, &branch, tip, largest, max_depth)
    }

    /// The largest contact radius of a table that reaches `max_depth`:
    /// Hertz's or Sneddon's at that depth, widened by half at a time (at
    /// most [`WIDENINGS`] times, within the tip's and the solution's range)
    /// until the exact depth there reaches `max_depth`, then [`HEADROOM`]
    /// times that (within the range) for adhesive curves.
    pub(super) fn largest_radius(
        exact: &Axisymmetric,
        branch: &Branch,
        tip: Tip,
        max_depth: f64,
    ) -> Result<f64> {
        let max_depth = positive_finite("max_depth", max_depth)?;
        let limit = tip.max_contact_radius().min(exact.max_contact_radius());
        let mut largest = first_radius(tip, max_depth).min(limit);
        for _ in 0..WIDENINGS {
            if branch.at(largest)?.depth >= max_depth {
                return Ok((HEADROOM * largest).min(limit));
            }
            if largest >= limit {
                break;
            }
            largest = (1.5 * largest).min(limit);
        }
        Err(Error::InvalidParameter {
            name: "max_depth",
            value: max_depth,
            expected: "a depth the exact solution reaches within its range of contact radii",
        })
    }

    /// The table of `tip` on the body of `exact` at [`POINTS`] radii evenly
    /// spaced in `ln a` up to `largest` (m), for indentations up to
    /// `max_depth` (m), which the depth at `largest` must reach.
    pub(super) fn tabulate(
        exact: &Axisymmetric,
        branch: &Branch,
        tip: Tip,
        largest: f64,
        max_depth: f64,
    ) -> Result<Self> {
        let max_depth = positive_finite("max_depth", max_depth)?;
        let largest = positive_finite("largest contact radius of a table", largest)?;
        let step = -SMALLEST.ln() / (POINTS - 1) as f64;
        let log_radius: Vec<f64> = (0..POINTS)
            .map(|k| largest.ln() - step * (POINTS - 1 - k) as f64)
            .collect();
        let radius: Vec<f64> = log_radius.iter().map(|l| l.exp()).collect();
        let mut columns = [(); 4].map(|_| Vec::with_capacity(POINTS));
        for &a in &radius {
            let state = branch.at(a)?;
            let punch = exact.flat_punch(a)?;
            for (column, value) in columns.iter_mut().zip([
                state.depth,
                state.force,
                punch.stiffness(),
                punch.edge_factor(),
            ]) {
                column.push(value);
            }
        }
        let [depth, force, stiffness, edge] = columns;
        crate::solver::all_finite("force curve table", &depth)?;
        crate::solver::all_finite("force curve table", &force)?;
        if depth[POINTS - 1] < max_depth {
            return Err(Error::InvalidParameter {
                name: "max_depth",
                value: max_depth,
                expected: "a depth the table's largest contact radius reaches",
            });
        }
        Ok(ForceCurve {
            contact_modulus: exact.contact_modulus,
            tip: Some(tip),
            log_radius,
            radius,
            log_depth: depth.iter().map(|d| d.ln()).collect(),
            log_force: force.iter().map(|f| f.ln()).collect(),
            depth,
            force,
            stiffness,
            edge,
            max_depth,
        })
    }

    /// The exact solution a table of `tip` on `substrate` to `max_depth`
    /// needs: eight times Hertz's or Sneddon's contact radius at that depth,
    /// within [`Axisymmetric::MAX_RADIUS_OVER_THICKNESS`] layer thicknesses.
    pub(super) fn exact_on(
        substrate: &Substrate,
        tip: Tip,
        max_depth: f64,
    ) -> Result<Axisymmetric> {
        let max_depth = positive_finite("max_depth", max_depth)?;
        let reach = 8.0 * first_radius(tip.validated()?, max_depth);
        Axisymmetric::up_to_contact_radius_in_range(substrate, reach)
    }

    /// The curve of `tip` on `substrate` to `max_depth` (m), with the exact
    /// solutions built as far as the table needs: eight times Hertz's or
    /// Sneddon's contact radius at that depth, within
    /// [`Axisymmetric::MAX_RADIUS_OVER_THICKNESS`] layer thicknesses (the
    /// table widens itself within that range if the layer stiffens the
    /// contact less).
    ///
    /// # Errors
    /// As [`ForceCurve::new`] and [`Axisymmetric::new`].
    pub fn on(substrate: &Substrate, tip: Tip, max_depth: f64) -> Result<Self> {
        let exact = Self::exact_on(substrate, tip, max_depth)?;
        Self::new(&exact, tip, max_depth)
    }

    /// The bonded flat punch of `radius` (m) on `substrate`.
    ///
    /// # Errors
    /// As [`ForceCurve::flat_punch`].
    pub fn flat_punch_on(substrate: &Substrate, radius: f64) -> Result<Self> {
        let radius = positive_finite("radius", radius)?;
        let exact = Axisymmetric::up_to_contact_radius(substrate, radius)?;
        Self::flat_punch(&exact, radius)
    }

    /// The bonded flat punch of `radius` (m) on the body of `exact`: the
    /// force is `K d` until it detaches at `d = -sqrt(2 pi a w / E*) / psi1`.
    ///
    /// # Errors
    /// As [`Axisymmetric::flat_punch`].
    pub fn flat_punch(exact: &Axisymmetric, radius: f64) -> Result<Self> {
        let punch = exact.flat_punch(radius)?;
        Ok(ForceCurve {
            contact_modulus: exact.contact_modulus,
            tip: None,
            log_radius: vec![radius.ln()],
            radius: vec![radius],
            depth: vec![0.0],
            force: vec![0.0],
            log_depth: Vec::new(),
            log_force: Vec::new(),
            stiffness: vec![punch.stiffness()],
            edge: vec![punch.edge_factor()],
            max_depth: f64::INFINITY,
        })
    }

    /// The contact modulus `E1*` of the table's body, Pa.
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// The deepest indentation the table reaches, m.
    pub fn max_depth(&self) -> f64 {
        self.max_depth
    }

    /// The force (N) at indentation `depth` (m) for a top layer whose
    /// contact modulus is `modulus_ratio` times the table's, with work of
    /// adhesion `work_of_adhesion` (J/m^2), along the fixed-grips branch:
    /// 0 before contact and after detachment. Scaling by the modulus is
    /// exact only on a single layer over a rigid base or a half-space;
    /// elsewhere build the table at the modulus wanted and pass 1. A NaN,
    /// a depth beyond [`reach`](Self::reach) (the table's
    /// [`max_depth`](Self::max_depth) without adhesion, less with it), a
    /// ratio that is not positive or a negative work gives NaN. For many
    /// depths, [`forces`](Self::forces) builds the branch once.
    pub fn force(&self, depth: f64, modulus_ratio: f64, work_of_adhesion: f64) -> f64 {
        self.forces(&[depth], modulus_ratio, work_of_adhesion)[0]
    }

    /// The deepest indentation (m) whose force the table gives for
    /// `modulus_ratio` and `work_of_adhesion` (J/m^2): its
    /// [`max_depth`](Self::max_depth) without adhesion; with adhesion the
    /// JKR depth at the table's largest contact radius, if that is less
    /// (adhesion lifts the indenter at a given contact radius, by more the
    /// larger the work and the softer the layer). NaN where
    /// [`forces`](Self::forces) gives NaN for every depth. A table that
    /// must reach deeper with adhesion is built to a larger `max_depth`.
    pub fn reach(&self, modulus_ratio: f64, work_of_adhesion: f64) -> f64 {
        let last = self.radius.len() - 1;
        match (usable(modulus_ratio, work_of_adhesion), self.tip) {
            (false, _) => f64::NAN,
            (true, None) => self.max_depth,
            (true, Some(_)) => {
                let modulus = modulus_ratio * self.contact_modulus;
                let lift = self.lift(last, modulus, work_of_adhesion);
                self.max_depth.min(self.depth[last] + lift)
            }
        }
    }

    /// `d - d0 = -sqrt(2 pi a w / E*) / psi1` at entry `k` of the table: the
    /// JKR state's depth less the non-adhesive one at the same radius.
    fn lift(&self, k: usize, modulus: f64, work_of_adhesion: f64) -> f64 {
        -(2.0 * std::f64::consts::PI * self.radius[k] * work_of_adhesion / modulus).sqrt()
            / self.edge[k]
    }

    /// [`force`](Self::force) at each of `depths`.
    pub fn forces(&self, depths: &[f64], modulus_ratio: f64, work_of_adhesion: f64) -> Vec<f64> {
        if !usable(modulus_ratio, work_of_adhesion) {
            return vec![f64::NAN; depths.len()];
        }
        let modulus = modulus_ratio * self.contact_modulus;
        let n = self.radius.len();
        let lift: Vec<f64> = (0..n)
            .map(|k| self.lift(k, modulus, work_of_adhesion))
            .collect();
        let outside = |depth: f64| depth.is_nan() || depth > self.max_depth;
        if self.tip.is_none() {
            return depths
                .iter()
                .map(|&depth| match depth {
                    d if outside(d) => f64::NAN,
                    d if d >= lift[0] => modulus_ratio * self.stiffness[0] * d,
                    _ => 0.0,
                })
                .collect();
        }
        if work_of_adhesion == 0.0 {
            let power = if matches!(self.tip, Some(Tip::Cone { .. })) {
                2.0
            } else {
                1.5
            };
            return depths
                .iter()
                .map(|&depth| match depth {
                    d if outside(d) => f64::NAN,
                    d if d <= 0.0 => 0.0,
                    // Below the smallest contact: the half-space's power law.
                    d if d < self.depth[0] => {
                        modulus_ratio * self.force[0] * (d / self.depth[0]).powf(power)
                    }
                    d => {
                        let x = invert(&self.log_radius, &self.log_depth, d.ln(), 0);
                        modulus_ratio * hermite(&self.log_radius, &self.log_force, x).exp()
                    }
                })
                .collect();
        }
        let d: Vec<f64> = (0..n).map(|k| self.depth[k] + lift[k]).collect();
        let f: Vec<f64> = (0..n)
            .map(|k| modulus_ratio * (self.force[k] + self.stiffness[k] * lift[k]))
            .collect();
        let start = (0..n).min_by(|&i, &j| d[i].total_cmp(&d[j])).unwrap_or(0);
        depths
            .iter()
            .map(|&depth| match depth {
                // Beyond the adhesive branch's deepest state: the table
                // does not reach (see `reach`).
                x if outside(x) || x > d[n - 1] => f64::NAN,
                x if x < d[start] || start + 1 >= n => 0.0,
                x => hermite(&self.log_radius, &f, invert(&self.log_radius, &d, x, start)),
            })
            .collect()
    }
}

/// Whether a modulus ratio and a work of adhesion give a curve: a positive
/// finite ratio, a non-negative finite work.
fn usable(modulus_ratio: f64, work_of_adhesion: f64) -> bool {
    modulus_ratio > 0.0
        && modulus_ratio.is_finite()
        && work_of_adhesion >= 0.0
        && work_of_adhesion.is_finite()
}

/// The non-adhesive states of a tip on one body along the contact radius:
/// a paraboloid's from its own solution, any other tip's from
/// [`Axisymmetric::tip`] (which also validates the tip).
pub(super) enum Branch {
    Paraboloid(LayeredParaboloid),
    Tip(LayeredTip),
}

impl Branch {
    pub(super) fn new(exact: &Axisymmetric, tip: Tip) -> Result<Self> {
        let states = exact.tip(tip, 0.0)?;
        Ok(match tip {
            Tip::Paraboloid { radius } => Branch::Paraboloid(exact.paraboloid(radius, 0.0)?),
            _ => Branch::Tip(states),
        })
    }

    /// The state at contact radius `a` (m).
    fn at(&self, a: f64) -> Result<ContactState> {
        match self {
            Branch::Paraboloid(ball) => ball.at_contact_radius(a),
            Branch::Tip(states) => states.at_contact_radius(a),
        }
    }
}

/// A contact radius (m) near the deepest indentation's: Hertz's for a
/// round tip, Sneddon's for a cone (the larger for a rounded cone).
fn first_radius(tip: Tip, depth: f64) -> f64 {
    match tip {
        Tip::Paraboloid { radius } | Tip::Sphere { radius } => (radius * depth).sqrt(),
        Tip::Cone { half_angle } => 2.0 / std::f64::consts::PI * depth * half_angle.tan(),
        Tip::RoundedCone {
            half_angle,
            tip_radius,
        } => (tip_radius * depth)
            .sqrt()
            .max(2.0 / std::f64::consts::PI * depth * half_angle.tan()),
    }
}

/// The slope of `y` against the evenly spaced `x` at entry `k`: fifth-order
/// central differences inside, one-sided ones at the ends.
fn slope(x: &[f64], y: &[f64], k: usize) -> f64 {
    let n = y.len();
    let h = if n > 1 { x[1] - x[0] } else { 1.0 };
    match (k, n) {
        (_, 0 | 1) => 0.0,
        (_, 2..=4) => {
            let (i, j) = if k + 1 < n { (k, k + 1) } else { (k - 1, k) };
            (y[j] - y[i]) / (x[j] - x[i])
        }
        (0, _) => {
            (-25.0 * y[0] + 48.0 * y[1] - 36.0 * y[2] + 16.0 * y[3] - 3.0 * y[4]) / (12.0 * h)
        }
        (1, _) => (-3.0 * y[0] - 10.0 * y[1] + 18.0 * y[2] - 6.0 * y[3] + y[4]) / (12.0 * h),
        (k, n) if k == n - 1 => {
            (25.0 * y[k] - 48.0 * y[k - 1] + 36.0 * y[k - 2] - 16.0 * y[k - 3] + 3.0 * y[k - 4])
                / (12.0 * h)
        }
        (k, n) if k == n - 2 => {
            (3.0 * y[k + 1] + 10.0 * y[k] - 18.0 * y[k - 1] + 6.0 * y[k - 2] - y[k - 3])
                / (12.0 * h)
        }
        (k, _) => (y[k - 2] - 8.0 * y[k - 1] + 8.0 * y[k + 1] - y[k + 2]) / (12.0 * h),
    }
}

/// The cubic Hermite interpolant of `y` (slopes from [`slope`]) at `t`
/// within the table, and its derivative.
fn hermite_with_slope(x: &[f64], y: &[f64], t: f64) -> (f64, f64) {
    let n = x.len();
    let k = interval(x, t);
    let h = x[k + 1] - x[k];
    let s = ((t - x[k]) / h).clamp(0.0, 1.0);
    let (m0, m1) = (slope(x, y, k) * h, slope(x, y, k + 1) * h);
    let (y0, y1) = (y[k], y[k + 1]);
    let s2 = s * s;
    let s3 = s2 * s;
    let value = (2.0 * s3 - 3.0 * s2 + 1.0) * y0
        + (s3 - 2.0 * s2 + s) * m0
        + (-2.0 * s3 + 3.0 * s2) * y1
        + (s3 - s2) * m1;
    let derivative = ((6.0 * s2 - 6.0 * s) * y0
        + (3.0 * s2 - 4.0 * s + 1.0) * m0
        + (-6.0 * s2 + 6.0 * s) * y1
        + (3.0 * s2 - 2.0 * s) * m1)
        / h;
    debug_assert!(n >= 2);
    (value, derivative)
}

fn hermite(x: &[f64], y: &[f64], t: f64) -> f64 {
    hermite_with_slope(x, y, t).0
}

/// The index `k` with `x[k] <= t <= x[k + 1]` (clamped to the table).
fn interval(x: &[f64], t: f64) -> usize {
    let n = x.len();
    x.partition_point(|&v| v <= t).clamp(1, n - 1) - 1
}

/// The `x` at which the Hermite interpolant of `y` (increasing from entry
/// `start` on) equals `target`: the table interval, then safeguarded
/// Newton steps within it.
fn invert(x: &[f64], y: &[f64], target: f64, start: usize) -> f64 {
    let n = x.len();
    let k = (start + y[start..].partition_point(|&v| v < target)).clamp(start + 1, n - 1) - 1;
    let (mut lo, mut hi) = (x[k], x[k + 1]);
    let span = y[k + 1] - y[k];
    let mut t = if span > 0.0 {
        lo + (hi - lo) * ((target - y[k]) / span).clamp(0.0, 1.0)
    } else {
        0.5 * (lo + hi)
    };
    for _ in 0..NEWTON_STEPS {
        let (value, derivative) = hermite_with_slope(x, y, t);
        let miss = value - target;
        if miss < 0.0 {
            lo = t;
        } else if miss > 0.0 {
            hi = t;
        } else {
            break;
        }
        let newton = t - miss / derivative;
        t = if derivative > 0.0 && newton >= lo && newton <= hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    t
}

/// Which points of a measured retract segment (`position` into the sample,
/// `force`) are still on the sample: those deeper than the jump off it,
/// taken as the first point past the most tensile one, in order of
/// decreasing position, whose force is back above half of it (the jump of
/// an AFM cantilever, or the end of a fixed-grips curve's steep tail).
/// Beyond it the cantilever is free and the points say nothing of the
/// sample, while a model's detachment is a jump that least squares cannot
/// straddle. Where no point comes back (the curve ends on the jump), or
/// the most tensile point comes first, every point is kept.
///
/// ```
/// use layered_contact::analytic::before_jump_off;
///
/// let z = [3.0, 2.0, 1.0, 0.0, -1.0];
/// let f = [5.0, 1.0, -2.0, -0.5, 0.0];
/// assert_eq!(before_jump_off(&z, &f), [true, true, true, false, false]);
/// ```
pub fn before_jump_off(position: &[f64], force: &[f64]) -> Vec<bool> {
    let n = position.len().min(force.len());
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| position[b].total_cmp(&position[a]));
    let Some(lowest) = (0..n).min_by(|&a, &b| force[order[a]].total_cmp(&force[order[b]])) else {
        return Vec::new();
    };
    let least = force[order[lowest]];
    let last = match (lowest..n).find(|&k| force[order[k]] > 0.5 * least) {
        Some(k) if k > 0 => k - 1,
        _ => n - 1,
    };
    let cut = position[order[last]];
    position[..n].iter().map(|&z| z >= cut).collect()
}
