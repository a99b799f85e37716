//! JKR adhesion of a wavy (sinusoidal) surface in plane strain.

use std::f64::consts::PI;

use crate::error::{finite, non_negative_finite, positive_finite, Error, Result};
use crate::material::Material;

/// Bisection steps for the pull-off's contact width (the bracket shrinks by
/// `2^-60`).
const BISECTIONS: usize = 60;
/// Points of the scan that brackets the pull-off.
const SCAN: usize = 4096;

/// A rigid surface `z = g (1 - cos(2 pi x / lambda))` (or a body with that
/// profile against a rigid flat) pressed on a half-space with work of
/// adhesion `dgamma`, in the JKR limit and plane strain (K. L. Johnson 1995,
/// Int. J. Solids Struct. 32, 423). With the contact half-width `a` per
/// period and `psi = pi a / lambda`, the mean pressure is
///
/// ```text
/// pbar / p* = sin^2 psi - alpha sqrt(tan psi),
/// p* = pi E* g / lambda,     alpha = sqrt(2 lambda dgamma / (pi^2 g^2 E*)),
/// ```
///
/// Westergaard's non-adhesive solution (1939) plus the periodic flat punch
/// whose edge stress-intensity factor `K = pbar_F sqrt(lambda / tan psi)`
/// meets Griffith's `K = sqrt(2 E* dgamma)`. Under load control the contact
/// breaks at the minimum of `pbar`, which exists while `alpha` is below
/// about 1.065; above, `pbar` falls all the way to full contact, which the
/// JKR limit never breaks (Johnson's contact also snaps to full contact at
/// zero load from `alpha` of about 0.57 up).
///
/// ```
/// use layered_contact::{analytic::JkrSinusoid, Material};
///
/// let rubber = Material::new(1e6, 0.48)?;
/// // No adhesion: Westergaard, pbar = p* sin^2(pi a / lambda).
/// let dry = JkrSinusoid::new(&rubber, 1e-3, 1e-5, 0.0)?;
/// let p = dry.mean_pressure(0.25e-3);
/// assert!((p - 0.5 * dry.full_contact_pressure()).abs() < 1e-12 * p);
/// let sticky = JkrSinusoid::new(&rubber, 1e-3, 1e-5, 0.01)?;
/// let (pull_off, half_width) = sticky.pull_off()?;
/// assert!(pull_off < 0.0 && half_width < 0.25e-3);
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrSinusoid {
    contact_modulus: f64,
    wavelength: f64,
    amplitude: f64,
    work_of_adhesion: f64,
}

impl JkrSinusoid {
    /// A surface of `wavelength` and `amplitude` `g` (m; peak to trough
    /// `2 g`) on a half-space of `material`, work of adhesion
    /// `work_of_adhesion` (J/m^2).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a wavelength or amplitude that is not
    /// positive and finite, or a negative or non-finite work of adhesion.
    pub fn new(
        material: &Material,
        wavelength: f64,
        amplitude: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        Ok(JkrSinusoid {
            contact_modulus: material.contact_modulus(),
            wavelength: positive_finite("wavelength", wavelength)?,
            amplitude: positive_finite("amplitude", amplitude)?,
            work_of_adhesion: non_negative_finite("work_of_adhesion", work_of_adhesion)?,
        })
    }

    /// The mean pressure of full contact without adhesion, `p* = pi E* g /
    /// lambda`, Pa.
    pub fn full_contact_pressure(&self) -> f64 {
        PI * self.contact_modulus * self.amplitude / self.wavelength
    }

    /// Johnson's adhesion parameter `alpha = sqrt(2 lambda dgamma / (pi^2
    /// g^2 E*))`.
    pub fn adhesion_parameter(&self) -> f64 {
        (2.0 * self.wavelength * self.work_of_adhesion
            / (PI * PI * self.amplitude * self.amplitude * self.contact_modulus))
            .sqrt()
    }

    /// The mean pressure (Pa, negative when the surfaces pull) with contact
    /// strips of half-width `half_width` per period: NaN outside `[0,
    /// lambda / 2)`, where no strip of that width exists.
    pub fn mean_pressure(&self, half_width: f64) -> f64 {
        if (0.0..0.5 * self.wavelength).contains(&half_width) {
            self.pressure_at(PI * half_width / self.wavelength)
        } else {
            f64::NAN
        }
    }

    /// The pull-off under load control: the most tensile mean pressure of
    /// the adhesive branch (Pa) and the contact half-width there (m).
    ///
    /// # Errors
    /// [`Error::Unsupported`] if `alpha` is so large that the mean
    /// pressure falls all the way to full contact (no pull-off in the JKR
    /// limit).
    pub fn pull_off(&self) -> Result<(f64, f64)> {
        let alpha = self.adhesion_parameter();
        if alpha == 0.0 {
            return Ok((0.0, 0.0));
        }
        // d pbar / d psi / p* = 2 sin cos - alpha / (2 cos^2 sqrt(tan)):
        // negative near 0 and near pi/2; the pull-off is where it first
        // turns positive.
        let slope = |psi: f64| {
            let (s, c) = psi.sin_cos();
            2.0 * s * c - alpha / (2.0 * c * c * psi.tan().sqrt())
        };
        let top = 0.5 * PI;
        let first = (1..SCAN)
            .map(|k| top * k as f64 / SCAN as f64)
            .find(|&psi| slope(psi) > 0.0)
            .ok_or(Error::Unsupported {
                feature: "a pull-off of this JKR sinusoid",
                reason: "its adhesion parameter is large enough for the surfaces to \
                         snap into full contact, which the JKR limit never breaks",
            })?;
        let (mut low, mut high) = (first - top / SCAN as f64, first);
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (low + high);
            if slope(mid) > 0.0 {
                high = mid;
            } else {
                low = mid;
            }
        }
        let psi = 0.5 * (low + high);
        Ok((self.pressure_at(psi), psi * self.wavelength / PI))
    }

    /// The stress-intensity factors at the two edges of a contact strip
    /// `lower < x < upper` (one strip per period, `x` measured from a
    /// trough of the surface, where it is lowest, m) held bonded at the
    /// mean pressure `mean_pressure` (Pa, negative when the surfaces pull):
    /// `(K_lower, K_upper)` in Pa m^1/2, positive where the edge pulls (as
    /// [`EdgePoint::stress_intensity`](crate::solver::EdgePoint::stress_intensity)),
    /// whatever the work of adhesion; the energy release rate at each edge
    /// is `K^2 / (2 E*)`. With `psi = pi (upper - lower) / (2 lambda)` and
    /// `c = (lower + upper) / 2`,
    ///
    /// ```text
    /// K_upper = sqrt(lambda / tan psi) (p* sin psi sin(pi (upper + c) / lambda) - pbar),
    /// K_lower = sqrt(lambda / tan psi) (-p* sin psi sin(pi (lower + c) / lambda) - pbar).
    /// ```
    ///
    /// A strip off the trough has unequal edges: the one up the flank pulls
    /// harder (the asymmetric fronts of a sliding or hysteretic wavy
    /// contact, Carbone & Mangialardi 2004, J. Mech. Phys. Solids 52, 1267).
    /// Derivation: the map `T = tan(pi (x - c) / lambda)` turns the
    /// periodic kernel `(pi / lambda) cot(pi (x - t) / lambda)` into the
    /// Cauchy kernel plus a term in `t` alone, and the surface's slope into
    /// a rational function with poles at `T = +-i`; the finite Hilbert
    /// transform inverts in closed form (Muskhelishvili 1953, Singular
    /// Integral Equations, ch. 11), and the mean pressure fixes the
    /// remaining constant. The symmetric strip (`c = 0`) is Johnson's
    /// (1995) `K = (p* sin^2 psi - pbar) sqrt(lambda / tan psi)`;
    /// `benches/adhesion/asymmetric_strip.py` checks the formula against a
    /// Gauss-Chebyshev solution of the singular integral equation (Erdogan
    /// & Gupta 1972, Q. Appl. Math. 29, 525) to `1e-12`.
    ///
    /// ```
    /// use layered_contact::{analytic::JkrSinusoid, Material};
    ///
    /// let rubber = Material::new(1e6, 0.48)?;
    /// let wave = JkrSinusoid::new(&rubber, 1e-3, 1e-5, 0.05)?;
    /// // A strip 0.25 mm wide moved 0.05 mm up one flank, pulled at -100 Pa.
    /// let (lower, upper) = wave.strip_stress_intensity(-0.075e-3, 0.175e-3, -100.0)?;
    /// assert!(upper > lower && lower > 0.0);
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for non-finite bounds or mean pressure,
    /// a strip whose width is not between zero and the wavelength, or
    /// factors that overflow (a strip narrower than about `1e-300` of the
    /// wavelength, a mean pressure near `f64::MAX`).
    pub fn strip_stress_intensity(
        &self,
        lower: f64,
        upper: f64,
        mean_pressure: f64,
    ) -> Result<(f64, f64)> {
        finite("lower", lower)?;
        finite("upper", upper)?;
        finite("mean_pressure", mean_pressure)?;
        let width = upper - lower;
        if !(width > 0.0 && width < self.wavelength) {
            return Err(Error::InvalidParameter {
                name: "upper - lower",
                value: width,
                expected: "a strip width between zero and the wavelength (m)",
            });
        }
        let lambda = self.wavelength;
        let psi = 0.5 * PI * width / lambda;
        let centre = 0.5 * (lower + upper);
        let scale = (lambda / psi.tan()).sqrt();
        let flank = self.full_contact_pressure() * psi.sin();
        let k_upper = scale * (flank * (PI * (upper + centre) / lambda).sin() - mean_pressure);
        let k_lower = scale * (-flank * (PI * (lower + centre) / lambda).sin() - mean_pressure);
        if !(k_lower.is_finite() && k_upper.is_finite()) {
            // A strip so narrow that `tan psi` underflows, or a pressure so
            // large that `K` overflows.
            return Err(Error::InvalidParameter {
                name: "upper - lower",
                value: width,
                expected: "a strip whose stress-intensity factors are finite \
                           (not narrower than about 1e-300 of the wavelength)",
            });
        }
        Ok((k_lower, k_upper))
    }

    fn pressure_at(&self, psi: f64) -> f64 {
        self.full_contact_pressure()
            * (psi.sin().powi(2) - self.adhesion_parameter() * psi.tan().sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wave(work: f64) -> JkrSinusoid {
        JkrSinusoid::new(&Material::new(1e6, 0.48).unwrap(), 1.0, 1e-3, work).unwrap()
    }

    #[test]
    fn a_symmetric_strip_at_johnsons_pressure_releases_the_work_of_adhesion() {
        let w = wave(0.05);
        let estar = w.contact_modulus;
        for half_width in [0.02, 0.1, 0.3, 0.45] {
            let pbar = w.mean_pressure(half_width);
            let (lower, upper) = w
                .strip_stress_intensity(-half_width, half_width, pbar)
                .unwrap();
            for k in [lower, upper] {
                assert!(k > 0.0);
                let g = k * k / (2.0 * estar);
                assert!((g / 0.05 - 1.0).abs() < 1e-12, "{half_width}: {g}");
            }
        }
    }

    #[test]
    fn gauss_chebyshev_values() {
        // benches/adhesion/asymmetric_strip.py: lambda = 1 m, g = 1 mm,
        // E* = 1 MPa (here E = (1 - 0.48^2) MPa), 64 Chebyshev nodes;
        // (lower, upper, pbar) -> (K_lower, K_upper), Pa m^1/2.
        let w = JkrSinusoid::new(
            &Material::new(1e6 * (1.0 - 0.48 * 0.48), 0.48).unwrap(),
            1.0,
            1e-3,
            0.0,
        )
        .unwrap();
        let table = [
            (
                (-0.05, 0.15, -300.0),
                (526.2998369235028, 1527.3662782655576),
            ),
            ((-0.2, 0.05, 500.0), (643.5530053199259, -923.4487479374776)),
            ((0.1, 0.3, 0.0), (-1377.8497510536251, 1703.1159550834548)),
            ((-0.4, 0.3, 100.0), (1902.103014573391, 1341.4775480854494)),
        ];
        for ((lower, upper, pbar), (k_lower, k_upper)) in table {
            let (a, b) = w.strip_stress_intensity(lower, upper, pbar).unwrap();
            assert!((a - k_lower).abs() < 1e-9 * k_lower.abs(), "{a} {k_lower}");
            assert!((b - k_upper).abs() < 1e-9 * k_upper.abs(), "{b} {k_upper}");
            // One period on, or mirrored about the trough: the same edges.
            let (c, d) = w
                .strip_stress_intensity(lower + 1.0, upper + 1.0, pbar)
                .unwrap();
            assert!((c - a).abs() < 1e-9 * a.abs() && (d - b).abs() < 1e-9 * b.abs());
            let (e, f) = w.strip_stress_intensity(-upper, -lower, pbar).unwrap();
            assert!((e - b).abs() < 1e-9 * b.abs() && (f - a).abs() < 1e-9 * a.abs());
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: 2000,
            rng_seed: proptest::test_runner::RngSeed::Fixed(20261127),
            ..proptest::prelude::ProptestConfig::default()
        })]
        /// Any bounds and pressure: finite factors or a typed error.
        #[test]
        fn never_a_nan(lower in proptest::num::f64::ANY, width in proptest::num::f64::ANY,
                       pbar in proptest::num::f64::ANY, lambda in 1e-9f64..1e3) {
            let w = JkrSinusoid::new(&Material::new(1e6, 0.48).unwrap(), lambda, 1e-6, 0.05)
                .unwrap();
            match w.strip_stress_intensity(lower, lower + width, pbar) {
                Ok((a, b)) => proptest::prop_assert!(a.is_finite() && b.is_finite()),
                Err(e) => {
                    let typed = matches!(e, Error::InvalidParameter { .. });
                    proptest::prop_assert!(typed, "{e}");
                }
            }
        }
    }

    #[test]
    fn bad_strips_are_refused() {
        let w = wave(0.05);
        for (lower, upper, pbar) in [
            (0.1, 0.1, 0.0),
            (0.2, 0.1, 0.0),
            (0.0, 1.0, 0.0),
            (f64::NAN, 0.1, 0.0),
            (0.0, 0.1, f64::INFINITY),
            (0.0, 1e-320, 0.0),
            (0.0, 0.1, 1e308),
        ] {
            assert!(matches!(
                w.strip_stress_intensity(lower, upper, pbar),
                Err(Error::InvalidParameter { .. })
            ));
        }
    }
}
