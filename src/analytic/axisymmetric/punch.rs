//! The flat cylindrical punch on a coated half-space, bonded: stiffness,
//! edge stress intensity and Kendall's pull-off.

use std::f64::consts::PI;

use super::{pressure_profile, Nystrom};

/// A flat punch on the coated half-space: stiffness, edge stress intensity,
/// JKR (Kendall) pull-off.
///
/// It solves the *bonded* problem: the whole face is held at the punch's
/// displacement, so the pressure may be tensile inside the face (a stiff
/// layer on a much softer base bends, and its middle pulls on the punch).
/// Such a solution holds without adhesion only if the pressure is
/// compressive everywhere: [`minimum_pressure_ratio`](Self::minimum_pressure_ratio)
/// and [`holds_without_adhesion`](Self::holds_without_adhesion) say whether
/// it does; where it does not, a non-adhesive punch lifts off inside and
/// the BEM (which solves that unilateral problem) is rightly softer.
#[derive(Debug, Clone)]
pub struct LayeredFlatPunch {
    pub(super) contact_modulus: f64,
    pub(super) radius: f64,
    pub(super) solution: Nystrom,
}

impl LayeredFlatPunch {
    /// `eps = a/h` (0 on a half-space).
    pub fn eps(&self) -> f64 {
        self.solution.eps
    }

    /// The least pressure over the face divided by the mean pressure
    /// `F / (pi a^2)` (independent of the depth): negative where the bonded
    /// solution pulls on the punch. Sampled at 400 radii over `[0, 0.999 a]`
    /// (near the edge the pressure grows like `1/sqrt(a - r)`, so the
    /// minimum lies inside).
    pub fn minimum_pressure_ratio(&self) -> f64 {
        let depth = 1.0;
        let mean = self.stiffness() * depth / (PI * self.radius * self.radius);
        (0..400)
            .map(|k| self.pressure(depth, 0.999 * self.radius * k as f64 / 399.0))
            .fold(f64::INFINITY, f64::min)
            / mean
    }

    /// Whether the bonded solution is compressive over the whole face, so
    /// that it is also the solution without adhesion.
    pub fn holds_without_adhesion(&self) -> bool {
        self.minimum_pressure_ratio() >= 0.0
    }

    /// The stiffness `K = 2 a E1* Integral_0^1 psi`, N/m.
    pub fn stiffness(&self) -> f64 {
        2.0 * self.radius * self.contact_modulus * self.ratio()
    }

    /// `K / (2 a E1*)`.
    pub fn ratio(&self) -> f64 {
        self.solution.integral(false)
    }

    /// The edge factor `psi(1)`: the stress intensity relative to the
    /// half-space punch at the same depth.
    pub fn edge_factor(&self) -> f64 {
        self.solution.edge(false)
    }

    /// The Nystrom order used.
    pub fn order(&self) -> usize {
        self.solution.nodes.len()
    }

    /// The relative change of the results at the last doubling of the order.
    pub fn convergence(&self) -> f64 {
        self.solution.change
    }

    /// The stress intensity factor at the rim, `K_I = -E1* d psi(1) / sqrt(pi a)`
    /// (Pa m^(1/2), positive in tension).
    pub fn stress_intensity_factor(&self, depth: f64) -> f64 {
        -self.contact_modulus * depth * self.edge_factor() / (PI * self.radius).sqrt()
    }

    /// The energy release rate `G = K_I^2 / (2 E1*) = E1* d^2 psi(1)^2 / (2 pi a)`, J/m^2.
    pub fn energy_release_rate(&self, depth: f64) -> f64 {
        self.stress_intensity_factor(depth).powi(2) / (2.0 * self.contact_modulus)
    }

    /// The depth at which a punch stuck with `work_of_adhesion` detaches,
    /// `-sqrt(2 pi a dgamma / E1*) / psi(1)`, m.
    pub fn critical_depth(&self, work_of_adhesion: f64) -> f64 {
        -(2.0 * PI * self.radius * work_of_adhesion.max(0.0) / self.contact_modulus).sqrt()
            / self.edge_factor()
    }

    /// The pull-off force `K d_c`, N (negative). The contact radius is fixed,
    /// so load and displacement control agree.
    pub fn pull_off_force(&self, work_of_adhesion: f64) -> f64 {
        self.stiffness() * self.critical_depth(work_of_adhesion)
    }

    /// The pressure at radius `r` under the punch at `depth`, Pa.
    pub fn pressure(&self, depth: f64, r: f64) -> f64 {
        pressure_profile(
            self.contact_modulus,
            &self.solution,
            self.radius,
            depth,
            0.0,
            r,
        )
    }
}
