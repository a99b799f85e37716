//! The smooth remainder of the coated half-space's Green's function, in
//! radial form.
//!
//! With `Lambda_g(t) = 1 - R(t)` and `Lambda0 = Lambda_g(0) = 1 - E1*/E2*`
//! (1 on a rigid base), the surface displacement due to a unit point force at
//! distance `r` is the Hankel transform of `u_z(q)` (Perriot & Barthel 2004):
//!
//! ```text
//! w(r) = 1/(pi E1*) [ 1/r - Lambda0 / sqrt(r^2 + h^2) - g(r/h) / h ],
//! g(rho) = Integral_0^inf f(u) J0(u rho) du,      f(u) = Lambda_g(u) - Lambda0 e^(-u),
//! ```
//!
//! using `Integral_0^inf e^(-qh) J0(qr) dq = 1/sqrt(r^2 + h^2)`. The first two
//! terms have closed-form cell integrals ([`super::cell`]); `f(0) = 0` makes
//! `g` smooth and decaying (`g ~ -f_2 / rho^3`, `f_k` the Taylor coefficients
//! of `f`). Its integral over a disc of radius `R`,
//!
//! ```text
//! Gc(R) = Integral_0^R g(rho) rho d rho = R Integral_0^inf (f(u)/u) J1(u R) du,
//! ```
//!
//! is all the cell integrals need: over a rectangle `[0, X] x [0, Y]` with a
//! corner at the field point, in polar coordinates,
//!
//! ```text
//! Integral g dA = Integral_0^atan(Y/X) Gc(X / cos t) dt + Integral_0^atan(X/Y) Gc(Y / cos t) dt.
//! ```
//!
//! `Gc` is tabulated by piecewise Chebyshev interpolation on octaves
//! `[2^k, 2^(k+1)]` (in units of `h`), each node computed by Gauss-Legendre
//! quadrature of the oscillatory integral on panels of one period of `J1`.
//! For large `R` it follows the asymptotic expansion
//! `Gc(R) = f_1 + f_2/R - 3 f_4/R^3 + 45 f_6/R^5 + ...` (from
//! `Integral_0^inf u^(2n) J0(u rho) du = (-1)^n ((2n-1)!!)^2 / rho^(2n+1)`);
//! the table stops where the two agree to within the caller's tolerance, or
//! at `R = 8192`, recording the mismatch there. A coating much stiffer than
//! its base has Taylor coefficients that grow like powers of the contrast
//! (its membrane and bending lengths are many thicknesses), so its
//! asymptotics hold only far out: where they still disagree at `R = 8192`
//! by more than the caller can accept, the table is not built at all and the
//! mismatch is reported (the caller refuses such coefficients).

use gauss_quad::legendre::GaussLegendre;

use crate::numerics::{gauss, oscillatory_integral, OctaveTable};
use crate::substrate::Spectral;

/// Gauss points per panel of the Hankel quadrature.
const HANKEL_ORDER: usize = 20;
/// Gauss points per angular piece of the corner integral.
const ANGLE_ORDER: usize = 16;
/// Smallest octave exponent tabulated.
const MIN_OCTAVE: i32 = -40;
/// The table never extends beyond this radius (units of `h`): building it
/// out to here costs a few seconds.
const MAX_TABLE_RADIUS: f64 = 8192.0;
/// Beyond this radius the table ends as soon as its tail error is below the
/// caller's `enough`, not only at full agreement.
const USUAL_TABLE_RADIUS: f64 = 512.0;
/// Agreement of table and asymptotics, relative to `1 + |Gc(inf)|`, that
/// ends the table whatever the caller accepts.
const TAIL_AGREEMENT: f64 = 1e-14;

/// How closely the asymptotic expansion must continue the table (absolute
/// mismatches of `Gc`, units of `h`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TailTolerance {
    /// A mismatch this small ends the table beyond `512 h`.
    pub(crate) enough: f64,
    /// A mismatch larger than this at the largest table radius makes the
    /// table pointless: the remainder is returned without it.
    pub(crate) unusable: f64,
}

/// `Gc(R)` of the module docs for one coated substrate, over a range of `R`.
#[derive(Debug, Clone)]
pub(crate) struct RadialRemainder {
    /// `Gc` on `[table.start(), table.end()]`; `None` if every radius needed
    /// lies in the asymptotic range.
    table: Option<OctaveTable>,
    /// `Gc(R) ~ a[0] + a[1]/R + a[2]/R^3 + a[3]/R^5` beyond the table.
    asymptotic: [f64; 4],
    /// `|table - asymptotics|` where the asymptotics take over, in units of
    /// `h` (0 if they are never used).
    tail_mismatch: f64,
}

impl RadialRemainder {
    /// The remainder of `functions`, tabulated for `R` in `[r_min, r_max]`
    /// (units of `h`; `r_min > 0`) until the asymptotics continue it within
    /// `tolerance`.
    pub(crate) fn new(
        functions: &Spectral,
        r_min: f64,
        r_max: f64,
        tolerance: TailTolerance,
    ) -> Self {
        let lambda0 = functions.lambda(0.0);
        let taylor = functions
            .lambda_taylor()
            .sub(&crate::substrate::Series::exp(-1.0).scale(lambda0));
        let f = taylor.0;
        let mut remainder = RadialRemainder {
            table: None,
            asymptotic: [f[1], f[2], -3.0 * f[4], 45.0 * f[6]],
            tail_mismatch: 0.0,
        };
        let top = r_max.min(MAX_TABLE_RADIUS);
        let rule = gauss(HANKEL_ORDER);
        if r_min >= top {
            remainder.tail_mismatch = remainder.mismatch_at(functions, lambda0, top);
            return remainder;
        }
        if r_max > top {
            // The table would end at `top` at the latest: if the asymptotics
            // do not hold there, no table makes the coefficients usable.
            let last = remainder.mismatch_at(functions, lambda0, top);
            if last.is_nan() || last > tolerance.unusable {
                remainder.tail_mismatch = last;
                return remainder;
            }
        }
        let first = (r_min.log2().floor() as i32).max(MIN_OCTAVE);
        let agreement = TAIL_AGREEMENT * (1.0 + remainder.asymptotic[0].abs());
        let mut mismatch = 0.0;
        let table = OctaveTable::build(
            first,
            false,
            |r| disc_integral(functions, lambda0, r, &rule),
            |end| {
                if end >= r_max {
                    return true; // the table covers every radius needed
                }
                if end >= top || end >= 32.0 {
                    mismatch = remainder.mismatch_at(functions, lambda0, end);
                    // Out to 512 h the table ends only at full agreement
                    // (a few panels per node); beyond, once the tail is
                    // as small as the caller needs.
                    return end >= top
                        || mismatch <= agreement
                        || (end >= USUAL_TABLE_RADIUS && mismatch <= tolerance.enough);
                }
                false
            },
        );
        if table.end() < r_max {
            remainder.tail_mismatch = mismatch;
        }
        remainder.table = Some(table);
        remainder
    }

    fn mismatch_at(&self, functions: &Spectral, lambda0: f64, r: f64) -> f64 {
        let numeric = disc_integral(functions, lambda0, r, &gauss(HANKEL_ORDER));
        (numeric - self.asymptotic_at(r)).abs()
    }

    /// `|table - asymptotics|` where the table ends (units of `h`): an
    /// estimate of the error of `Gc` beyond the table.
    pub(crate) fn tail_mismatch(&self) -> f64 {
        self.tail_mismatch
    }

    fn asymptotic_at(&self, r: f64) -> f64 {
        let [a0, a1, a3, a5] = self.asymptotic;
        let inv = 1.0 / r;
        let inv2 = inv * inv;
        a0 + inv * (a1 + inv2 * (a3 + inv2 * a5))
    }

    fn table_end(&self) -> f64 {
        self.table.as_ref().map_or(0.0, OctaveTable::end)
    }

    /// `Gc(R)`, `R >= 0` in units of `h`.
    pub(crate) fn disc(&self, r: f64) -> f64 {
        match &self.table {
            Some(table) if r < table.end() => {
                if r < table.start() {
                    // Gc(R) ~ g(0) R^2 / 2 below the first octave.
                    let scale = r / table.start();
                    table.eval(table.start()) * scale * scale
                } else {
                    table.eval(r)
                }
            }
            _ => self.asymptotic_at(r),
        }
    }

    /// `Integral_0^atan(Y/X) Gc(X / cos t) dt` for `X > 0`, `Y >= 0`.
    fn wedge(&self, x: f64, y: f64, rule: &GaussLegendre) -> f64 {
        let end = y.atan2(x);
        if x >= self.table_end() {
            // Closed form of the asymptotic expansion.
            let [a0, a1, a3, a5] = self.asymptotic;
            let s = end.sin();
            let s3 = s * s * s;
            let s5 = s3 * s * s;
            return a0 * end
                + a1 * s / x
                + a3 * (s - s3 / 3.0) / x.powi(3)
                + a5 * (s - 2.0 * s3 / 3.0 + s5 / 5.0) / x.powi(5);
        }
        // Pieces over which the radius X / cos t doubles.
        let diagonal = x.hypot(y);
        let mut total = 0.0;
        let mut lower = 0.0;
        let mut radius = x;
        while lower < end {
            radius *= 2.0;
            let upper = if radius >= diagonal {
                end
            } else {
                ((radius * radius - x * x).sqrt() / x).atan().min(end)
            };
            total += rule.integrate(lower, upper, |t| self.disc(x / t.cos()));
            lower = upper;
        }
        total
    }

    /// `Integral_0^X Integral_0^Y g(|p|) dp` for `X, Y >= 0` (units of `h`).
    pub(crate) fn corner(&self, x: f64, y: f64) -> f64 {
        if x == 0.0 || y == 0.0 {
            return 0.0;
        }
        let rule = gauss(ANGLE_ORDER);
        self.wedge(x, y, &rule) + self.wedge(y, x, &rule)
    }
}

/// `g(rho)` itself, for integrating the remainder over cells by a product
/// Gauss rule where it is smooth on the cell's scale: a Chebyshev head on
/// `[0, 1/4]` and octave pieces out to where [`RadialRemainder`]'s table
/// ends (or the largest radius needed), then the derivative of the same
/// asymptotic expansion, `g = Gc'(R)/R = -(a1/R^3 + 3 a3/R^5 + 5 a5/R^7)`.
#[derive(Debug, Clone)]
pub(crate) struct RadialDensity {
    table: OctaveTable,
    asymptotic: [f64; 4],
    /// `|table - asymptotics|` where the asymptotics take over (0 if they
    /// are never used).
    tail_mismatch: f64,
}

impl RadialDensity {
    /// `g` of `functions` (whose disc integral is `remainder`) for radii up
    /// to `r_max` (units of `h`).
    pub(crate) fn new(functions: &Spectral, remainder: &RadialRemainder, r_max: f64) -> Self {
        let lambda0 = functions.lambda(0.0);
        let rule = gauss(HANKEL_ORDER);
        let end = match &remainder.table {
            Some(table) => table.end().min(r_max),
            None => r_max.min(MAX_TABLE_RADIUS),
        };
        let table = OctaveTable::build(
            -2,
            true,
            |r| density(functions, lambda0, r, &rule),
            |top| top >= end,
        );
        let mut density_table = RadialDensity {
            table,
            asymptotic: remainder.asymptotic,
            tail_mismatch: 0.0,
        };
        if density_table.table.end() < r_max {
            let top = density_table.table.end();
            density_table.tail_mismatch =
                (density(functions, lambda0, top, &rule) - density_table.asymptotic_at(top)).abs();
        }
        density_table
    }

    fn asymptotic_at(&self, r: f64) -> f64 {
        let [_, a1, a3, a5] = self.asymptotic;
        let inv2 = 1.0 / (r * r);
        -inv2 / r * (a1 + inv2 * (3.0 * a3 + inv2 * 5.0 * a5))
    }

    /// `g(rho)`, `rho >= 0` in units of `h`.
    pub(crate) fn at(&self, rho: f64) -> f64 {
        if rho < self.table.end() {
            self.table.eval(rho)
        } else {
            self.asymptotic_at(rho)
        }
    }

    /// `|table - asymptotics|` of `g` where the asymptotics take over.
    pub(crate) fn tail_mismatch(&self) -> f64 {
        self.tail_mismatch
    }
}

/// `f(u) = Lambda_g(u) - Lambda0 e^(-u)`, and the `u` beyond which it is
/// negligible.
fn remainder_spectrum(functions: &Spectral, lambda0: f64) -> (impl Fn(f64) -> f64 + '_, f64) {
    let f = move |u: f64| functions.lambda(u) - lambda0 * (-u).exp();
    (f, 50.0 + (1.0 + lambda0.abs()).ln())
}

/// `g(rho) = Integral_0^inf f(u) J0(u rho) du`.
fn density(functions: &Spectral, lambda0: f64, rho: f64, rule: &GaussLegendre) -> f64 {
    let (f, u_max) = remainder_spectrum(functions, lambda0);
    let integrand = |u: f64| f(u) * libm::j0(u * rho);
    oscillatory_integral(integrand, rho.max(1e-300), u_max, rule)
}

/// `Gc(R) = R Integral_0^inf (f(u)/u) J1(u R) du`.
fn disc_integral(functions: &Spectral, lambda0: f64, r: f64, rule: &GaussLegendre) -> f64 {
    let (f, u_max) = remainder_spectrum(functions, lambda0);
    let integrand = |u: f64| f(u) / u * libm::j1(u * r);
    r * oscillatory_integral(integrand, r, u_max, rule)
}
