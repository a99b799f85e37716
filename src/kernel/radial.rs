//! The smooth remainder of the coated half-space's Green's function, in
//! radial form.
//!
//! With `Lambda_g(t) = 1 - R(t)` and `Lambda0 = Lambda_g(0) = 1 - E1*/E2*`
//! (1 on a rigid base), the surface displacement due to a unit point force at
//! distance `r` is the Hankel transform of `u_z(q)` (SPEC section 2):
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
//! the table stops where the two agree to `1e-14`, or at `R = 512`, recording
//! the mismatch there.

use std::f64::consts::PI;
use std::num::NonZeroUsize;

use gauss_quad::legendre::GaussLegendre;

use crate::substrate::CoatingFunctions;

/// Chebyshev nodes per octave.
const NODES: usize = 24;
/// Gauss points per panel of the Hankel quadrature.
const HANKEL_ORDER: usize = 20;
/// Gauss points per angular piece of the corner integral.
const ANGLE_ORDER: usize = 16;
/// Smallest octave exponent tabulated.
const MIN_OCTAVE: i32 = -40;
/// The table never extends beyond this radius (units of `h`).
const MAX_TABLE_RADIUS: f64 = 512.0;
/// Agreement of table and asymptotics that ends the table.
const TAIL_AGREEMENT: f64 = 1e-14;

fn gauss(order: usize) -> GaussLegendre {
    GaussLegendre::new(NonZeroUsize::new(order).expect("order is positive"))
}

/// Chebyshev interpolant on one octave.
#[derive(Debug, Clone)]
struct Piece {
    coefficients: [f64; NODES],
}

impl Piece {
    /// Chebyshev nodes on `[-1, 1]`.
    fn nodes() -> [f64; NODES] {
        std::array::from_fn(|j| (PI * (j as f64 + 0.5) / NODES as f64).cos())
    }

    fn from_values(values: &[f64; NODES]) -> Self {
        let n = NODES as f64;
        let coefficients = std::array::from_fn(|k| {
            let sum: f64 = values
                .iter()
                .enumerate()
                .map(|(j, v)| v * (PI * k as f64 * (j as f64 + 0.5) / n).cos())
                .sum();
            if k == 0 {
                sum / n
            } else {
                2.0 * sum / n
            }
        });
        Piece { coefficients }
    }

    /// Clenshaw's recurrence at `x` in `[-1, 1]`.
    fn eval(&self, x: f64) -> f64 {
        let (mut b1, mut b2) = (0.0, 0.0);
        for &c in self.coefficients.iter().skip(1).rev() {
            let b0 = 2.0 * x * b1 - b2 + c;
            b2 = b1;
            b1 = b0;
        }
        x * b1 - b2 + self.coefficients[0]
    }
}

/// `Gc(R)` of the module docs for one coated substrate, over a range of `R`.
#[derive(Debug, Clone)]
pub(crate) struct RadialRemainder {
    pieces: Vec<Piece>,
    first_octave: i32,
    table_start: f64,
    table_end: f64,
    /// `Gc(R) ~ a[0] + a[1]/R + a[2]/R^3 + a[3]/R^5` beyond the table.
    asymptotic: [f64; 4],
    /// `|table - asymptotics|` at `table_end`, in units of `h`.
    tail_mismatch: f64,
}

impl RadialRemainder {
    /// The remainder of `functions`, tabulated for `R` in `[r_min, r_max]`
    /// (units of `h`; `r_min > 0`).
    pub(crate) fn new(functions: &CoatingFunctions, r_min: f64, r_max: f64) -> Self {
        let lambda0 = functions.lambda(0.0);
        let taylor = functions
            .lambda_taylor()
            .sub(&crate::substrate::Series::exp(-1.0).scale(lambda0));
        let f = taylor.0;
        let asymptotic = [f[1], f[2], -3.0 * f[4], 45.0 * f[6]];
        let mut remainder = RadialRemainder {
            pieces: Vec::new(),
            first_octave: 0,
            table_start: f64::INFINITY,
            table_end: 0.0,
            asymptotic,
            tail_mismatch: 0.0,
        };
        let top = r_max.min(MAX_TABLE_RADIUS);
        if r_min >= top {
            // Everything needed lies in the asymptotic range.
            remainder.table_end = 0.0;
            remainder.tail_mismatch = remainder.mismatch_at(functions, lambda0, top);
            return remainder;
        }
        let first = (r_min.log2().floor() as i32).max(MIN_OCTAVE);
        remainder.first_octave = first;
        remainder.table_start = 2f64.powi(first);
        let rule = gauss(HANKEL_ORDER);
        let nodes = Piece::nodes();
        let mut octave = first;
        loop {
            let start = 2f64.powi(octave);
            let values =
                nodes.map(|x| disc_integral(functions, lambda0, start * (1.5 + 0.5 * x), &rule));
            remainder.pieces.push(Piece::from_values(&values));
            octave += 1;
            let end = 2f64.powi(octave);
            remainder.table_end = end;
            if end >= r_max {
                // The table covers every radius needed.
                break;
            }
            if end >= top {
                remainder.tail_mismatch = remainder.mismatch_at(functions, lambda0, end);
                break;
            }
            if end >= 32.0 {
                let mismatch = remainder.mismatch_at(functions, lambda0, end);
                if mismatch <= TAIL_AGREEMENT * (1.0 + asymptotic[0].abs()) {
                    remainder.tail_mismatch = mismatch;
                    break;
                }
            }
        }
        remainder
    }

    fn mismatch_at(&self, functions: &CoatingFunctions, lambda0: f64, r: f64) -> f64 {
        (disc_integral(functions, lambda0, r, &gauss(HANKEL_ORDER)) - self.asymptotic_at(r)).abs()
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

    /// `Gc(R)`, `R >= 0` in units of `h`.
    pub(crate) fn disc(&self, r: f64) -> f64 {
        if r >= self.table_end {
            return self.asymptotic_at(r);
        }
        if r < self.table_start {
            // Gc(R) ~ g(0) R^2 / 2 below the first octave.
            let scale = r / self.table_start;
            return self.pieces[0].eval(-1.0) * scale * scale;
        }
        let octave = (r.log2().floor() as i32).max(self.first_octave);
        let index = ((octave - self.first_octave) as usize).min(self.pieces.len() - 1);
        let start = 2f64.powi(self.first_octave + index as i32);
        let x = (2.0 * r / start - 3.0).clamp(-1.0, 1.0);
        self.pieces[index].eval(x)
    }

    /// `Integral_0^atan(Y/X) Gc(X / cos t) dt` for `X > 0`, `Y >= 0`.
    fn wedge(&self, x: f64, y: f64, rule: &GaussLegendre) -> f64 {
        let end = y.atan2(x);
        if x >= self.table_end {
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

/// `Gc(R) = R Integral_0^inf (f(u)/u) J1(u R) du` by Gauss-Legendre on panels
/// of one period of `J1` (at most 1 wide), refined geometrically towards
/// `u = 0` where `f` may vary on short scales (soft bases).
fn disc_integral(functions: &CoatingFunctions, lambda0: f64, r: f64, rule: &GaussLegendre) -> f64 {
    let integrand = |u: f64| {
        let f = functions.lambda(u) - lambda0 * (-u).exp();
        f / u * libm::j1(u * r)
    };
    let width = (2.0 * PI / r).min(1.0);
    let u_max = 50.0 + (1.0 + lambda0.abs()).ln();
    let mut total = 0.0;
    let mut upper = width;
    for _ in 0..60 {
        let lower = 0.5 * upper;
        total += rule.integrate(lower, upper, integrand);
        upper = lower;
    }
    let panels = (u_max / width).ceil() as usize;
    for i in 1..panels {
        let lower = i as f64 * width;
        total += rule.integrate(lower, lower + width, integrand);
    }
    r * total
}
