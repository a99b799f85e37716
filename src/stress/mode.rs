//! The stresses of one Fourier mode of surface pressure inside a layered
//! body, exact and free of growing exponentials.
//!
//! A pressure `p cos(q xi)` (`xi` along the wavevector) deforms the body in
//! plane strain in the `(xi, z)` plane. In each layer the Airy stress
//! function is `phi = F(s) cos(q xi)`, `s = q z` measured from the layer's
//! top, with `(D^2 - 1)^2 F = 0` (Timoshenko & Goodier 1970, sec. 24;
//! Burmister 1945 for layered systems). Written in the four solutions that
//! decay away from one face of the layer,
//!
//! ```text
//! F(s) = (a1 + a2 s) e^(-s) + (b1 + b2 r) e^(-r),   r = x - s,  x = q h,
//! ```
//!
//! every basis function is at most `max(1, x) e^(-min(s, r))` inside the
//! layer, so nothing overflows however thick the layer (the elastic base
//! keeps only the decaying pair). With `mu` the layer's shear modulus (in
//! units of the top layer's) and amplitudes `sigma_zz = S cos`, `sigma_xi_z =
//! T sin`, `sigma_xi_xi = Sigma cos`, `u_xi = U sin / q`, `u_z = W cos / q`:
//!
//! ```text
//! S = -F,  T = F',  Sigma = F'',  sigma_eta_eta = nu (Sigma + S),
//! U = ((1 - nu) F'' + nu F) / (2 mu),   W = U' - F' / mu.
//! ```
//!
//! The coefficients of all layers follow from one banded linear system: at
//! the top `T = 0`, `S = -1` (unit pressure); at a bonded interface the four
//! of `(U, W, T, S)` continuous; on a rigid base `U = W = 0`, or `T = W = 0`
//! for a layer resting on it without friction; on an elastic base
//! continuity with its decaying pair (without friction: `T = 0` on both
//! sides, `W` and `S` continuous). For a half-space `F = (1 + s) e^(-s)`,
//! the closed form the tests check.

use crate::error::{Error, Result};

/// One layer in units of the top layer's shear modulus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Ply {
    /// Shear modulus over the top layer's.
    pub(super) mu: f64,
    pub(super) nu: f64,
    /// Thickness, m.
    pub(super) thickness: f64,
}

/// The body, top down, as the mode solution sees it.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Column {
    pub(super) plies: Vec<Ply>,
    /// The elastic base (`None`: rigid).
    pub(super) base: Option<Ply>,
    /// The bottom layer rests on its base without friction.
    pub(super) frictionless: bool,
}

/// `F, F', F'', F'''` of the four basis functions of a layer at `s`
/// (`x` its thickness in `1/q`): `e^(-s)`, `s e^(-s)`, `e^(-r)`, `r e^(-r)`.
fn basis(s: f64, x: f64) -> [[f64; 4]; 4] {
    let e = (-s).exp();
    let r = x - s;
    let f = (-r).exp();
    [
        [e, -e, e, -e],
        [s * e, (1.0 - s) * e, (s - 2.0) * e, (3.0 - s) * e],
        [f, f, f, f],
        [r * f, -(1.0 - r) * f, (r - 2.0) * f, -(3.0 - r) * f],
    ]
}

/// `F, F', F'', F'''` of the elastic base's two decaying functions.
fn base_basis(s: f64) -> [[f64; 4]; 2] {
    let e = (-s).exp();
    [
        [e, -e, e, -e],
        [s * e, (1.0 - s) * e, (s - 2.0) * e, (3.0 - s) * e],
    ]
}

/// `(U, W, T, S)` of `F, F', F'', F'''` in a material of `mu`, `nu`.
fn state(d: &[f64; 4], mu: f64, nu: f64) -> [f64; 4] {
    let u = ((1.0 - nu) * d[2] + nu * d[0]) / (2.0 * mu);
    let u_slope = ((1.0 - nu) * d[3] + nu * d[1]) / (2.0 * mu);
    [u, u_slope - d[1] / mu, d[1], -d[0]]
}

/// The stresses of one mode per unit pressure at a point:
/// `(sigma_zz, sigma_xi_xi, sigma_eta_eta, sigma_xi_z)`, the shear the
/// amplitude of `sin(q xi)`, the others of `cos(q xi)`.
pub(super) type ModeStress = [f64; 4];

fn stresses(d: &[f64; 4], nu: f64) -> ModeStress {
    [-d[0], d[2], nu * (d[2] - d[0]), d[1]]
}

/// Upper and lower bandwidth the elimination may touch (the system's own
/// bandwidths are at most 5; partial pivoting adds the lower to the upper).
const BAND: usize = 12;

impl Column {
    /// Unknowns: four per layer, two for an elastic base.
    pub(super) fn unknowns(&self) -> usize {
        4 * self.plies.len() + if self.base.is_some() { 2 } else { 0 }
    }

    /// The basis coefficients of every layer (and the base) for a unit
    /// pressure of wavenumber `q > 0`, into `out` (length
    /// [`Column::unknowns`]); `matrix` is scratch.
    pub(super) fn solve(&self, q: f64, matrix: &mut Vec<f64>, out: &mut [f64]) -> Result<()> {
        let n = self.unknowns();
        matrix.clear();
        matrix.resize(n * n, 0.0);
        out.iter_mut().for_each(|v| *v = 0.0);
        let mut row = 0;
        let set = |m: &mut Vec<f64>, r: usize, c: usize, v: f64| m[r * n + c] = v;
        // Top: T = 0, S = -1.
        match self.plies.first() {
            Some(top) => {
                let b = basis(0.0, q * top.thickness);
                for (k, d) in b.iter().enumerate() {
                    let y = state(d, top.mu, top.nu);
                    set(matrix, 0, k, y[2]);
                    set(matrix, 1, k, y[3]);
                }
            }
            None => {
                let base = self.base.as_ref().ok_or_else(|| Error::Internal {
                    what: "subsurface stress",
                    detail: "a body with neither layers nor base".into(),
                })?;
                for (k, d) in base_basis(0.0).iter().enumerate() {
                    let y = state(d, base.mu, base.nu);
                    set(matrix, 0, k, y[2]);
                    set(matrix, 1, k, y[3]);
                }
            }
        }
        out[1] = -1.0;
        row += 2;
        // Bonded interfaces between layers.
        for (i, pair) in self.plies.windows(2).enumerate() {
            let (upper, lower) = (&pair[0], &pair[1]);
            let x = q * upper.thickness;
            let above = basis(x, x);
            let below = basis(0.0, q * lower.thickness);
            for k in 0..4 {
                let ya = state(&above[k], upper.mu, upper.nu);
                let yb = state(&below[k], lower.mu, lower.nu);
                for c in 0..4 {
                    set(matrix, row + c, 4 * i + k, ya[c]);
                    set(matrix, row + c, 4 * (i + 1) + k, -yb[c]);
                }
            }
            row += 4;
        }
        // The bottom.
        if let Some(last) = self.plies.last() {
            let l = self.plies.len() - 1;
            let x = q * last.thickness;
            let above: Vec<[f64; 4]> = basis(x, x)
                .iter()
                .map(|d| state(d, last.mu, last.nu))
                .collect();
            match (&self.base, self.frictionless) {
                (None, false) => {
                    for (k, y) in above.iter().enumerate() {
                        set(matrix, row, 4 * l + k, y[0]);
                        set(matrix, row + 1, 4 * l + k, y[1]);
                    }
                }
                (None, true) => {
                    for (k, y) in above.iter().enumerate() {
                        set(matrix, row, 4 * l + k, y[2]);
                        set(matrix, row + 1, 4 * l + k, y[1]);
                    }
                }
                (Some(base), frictionless) => {
                    let below: Vec<[f64; 4]> = base_basis(0.0)
                        .iter()
                        .map(|d| state(d, base.mu, base.nu))
                        .collect();
                    let b0 = 4 * self.plies.len();
                    // Rows: U (or the layer's T), W, T (the base's), S.
                    for (k, y) in above.iter().enumerate() {
                        let first = if frictionless { y[2] } else { y[0] };
                        set(matrix, row, 4 * l + k, first);
                        set(matrix, row + 1, 4 * l + k, y[1]);
                        if !frictionless {
                            set(matrix, row + 2, 4 * l + k, y[2]);
                        }
                        set(matrix, row + 3, 4 * l + k, y[3]);
                    }
                    for (k, y) in below.iter().enumerate() {
                        if !frictionless {
                            set(matrix, row, b0 + k, -y[0]);
                        }
                        set(matrix, row + 1, b0 + k, -y[1]);
                        set(matrix, row + 2, b0 + k, -y[2]);
                        set(matrix, row + 3, b0 + k, -y[3]);
                    }
                }
            }
        }
        banded_solve(matrix, n, out)
    }

    /// The layer holding depth `z` (m) and the depth of its top: the lower
    /// one at an interface unless `above`; `plies.len()` for the base.
    pub(super) fn locate(&self, z: f64, above: bool) -> (usize, f64) {
        let mut top = 0.0;
        for (i, ply) in self.plies.iter().enumerate() {
            let bottom = top + ply.thickness;
            if z < bottom || (above && z == bottom) {
                return (i, top);
            }
            top = bottom;
        }
        (self.plies.len(), top)
    }

    /// The stresses per unit pressure at `s = q (z - top)` in layer `index`
    /// from its coefficients in `coefficients` (as [`Column::solve`]
    /// returns them).
    pub(super) fn stress_at(
        &self,
        index: usize,
        s: f64,
        q: f64,
        coefficients: &[f64],
    ) -> ModeStress {
        let mut f = [0.0; 4];
        let mut add = |functions: &[[f64; 4]], first: usize| {
            for (k, d) in functions.iter().enumerate() {
                let c = coefficients[first + k];
                for (v, dv) in f.iter_mut().zip(d) {
                    *v += c * dv;
                }
            }
        };
        match self.plies.get(index) {
            Some(ply) => add(&basis(s, q * ply.thickness), 4 * index),
            None if self.base.is_some() => add(&base_basis(s), 4 * self.plies.len()),
            // A rigid base carries no field (the callers refuse its depths).
            None => {}
        }
        stresses(&f, self.ply(index).map_or(0.0, |p| p.nu))
    }

    /// Layer `index`, or the elastic base for `plies.len()`.
    pub(super) fn ply(&self, index: usize) -> Option<&Ply> {
        self.plies.get(index).or(self.base.as_ref())
    }
}

impl Column {
    /// The stresses per unit pressure in layer `index` (the base for
    /// `plies.len()`) as the wavenumber tends to zero at fixed depth:
    /// `(sigma_zz, sigma_xi_xi, sigma_eta_eta)` (the shear vanishes). Long
    /// waves see the layers as thin: on an elastic base the base's surface
    /// strain `eps = -(1 - 2 nu_b) / (2 mu_b)` along the wave (none across
    /// it) is imposed on every bonded layer, on a rigid base none; a layer
    /// sliding on its base carries no membrane stress along the wave. In
    /// the base (or a half-space) `sigma_xi_xi = -1`, `sigma_eta_eta = -2
    /// nu` (the limit of the closed form). This is the limit an isolated
    /// contact's mean needs: its direction average is the integral of the
    /// stress over an unbounded plane.
    pub(super) fn long_wave(&self, index: usize) -> [f64; 3] {
        let Some(ply) = self.plies.get(index) else {
            let nu = self.ply(index).map_or(0.0, |b| b.nu);
            return [-1.0, -1.0, -2.0 * nu];
        };
        let xi = if self.frictionless {
            0.0
        } else {
            let strain = self
                .base
                .map_or(0.0, |b| -(1.0 - 2.0 * b.nu) / (2.0 * b.mu));
            (2.0 * ply.mu * strain - ply.nu) / (1.0 - ply.nu)
        };
        [-1.0, xi, ply.nu * (xi - 1.0)]
    }
}

/// Solves the `n x n` row-major `matrix` (destroyed) for `rhs` in place by
/// Gaussian elimination with partial pivoting, touching only the band.
fn banded_solve(matrix: &mut [f64], n: usize, rhs: &mut [f64]) -> Result<()> {
    for j in 0..n {
        let last_row = (j + BAND + 1).min(n);
        let last_col = (j + 2 * BAND + 1).min(n);
        let mut pivot = j;
        for r in j + 1..last_row {
            if matrix[r * n + j].abs() > matrix[pivot * n + j].abs() {
                pivot = r;
            }
        }
        let value = matrix[pivot * n + j];
        if value == 0.0 || !value.is_finite() {
            return Err(Error::Internal {
                what: "subsurface stress",
                detail: format!("singular mode system at unknown {j} of {n}"),
            });
        }
        if pivot != j {
            for c in j..last_col {
                matrix.swap(pivot * n + c, j * n + c);
            }
            rhs.swap(pivot, j);
        }
        for r in j + 1..last_row {
            let factor = matrix[r * n + j] / value;
            if factor != 0.0 {
                for c in j..last_col {
                    matrix[r * n + c] -= factor * matrix[j * n + c];
                }
                rhs[r] -= factor * rhs[j];
            }
        }
    }
    for j in (0..n).rev() {
        let last_col = (j + 2 * BAND + 1).min(n);
        let mut sum = rhs[j];
        for c in j + 1..last_col {
            sum -= matrix[j * n + c] * rhs[c];
        }
        rhs[j] = sum / matrix[j * n + j];
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ply(mu: f64, nu: f64, thickness: f64) -> Ply {
        Ply { mu, nu, thickness }
    }

    /// The long-wave limits against the modes themselves at `q h = 1e-6`:
    /// the approach is linear in `q` (a slope of 10 for a layer sliding on
    /// a base ten times softer) and the basis loses `1/(q h)^2` to
    /// conditioning, so within 1e-4.
    #[test]
    fn long_waves_tend_to_the_limit() {
        let columns = [
            Column {
                plies: vec![ply(1.0, 0.3, 1.0), ply(0.2, 0.45, 0.5)],
                base: Some(ply(3.0, 0.25, 0.0)),
                frictionless: false,
            },
            Column {
                plies: vec![ply(1.0, 0.3, 1.0), ply(0.2, 0.45, 0.5)],
                base: None,
                frictionless: false,
            },
            Column {
                plies: vec![ply(1.0, 0.45, 1.0)],
                base: Some(ply(0.1, 0.3, 0.0)),
                frictionless: true,
            },
            Column {
                plies: vec![ply(1.0, 0.45, 1.0)],
                base: None,
                frictionless: true,
            },
        ];
        let q = 1e-6;
        for column in columns {
            let mut m = Vec::new();
            let mut c = vec![0.0; column.unknowns()];
            column.solve(q, &mut m, &mut c).unwrap();
            let total: f64 = column.plies.iter().map(|p| p.thickness).sum();
            for z in [0.3, 0.9, 1.2, 1.6] {
                if column.base.is_none() && z >= total {
                    continue;
                }
                let (i, top) = column.locate(z, false);
                let s = column.stress_at(i, q * (z - top), q, &c);
                let limit = column.long_wave(i);
                for k in 0..3 {
                    assert!(
                        (s[k] - limit[k]).abs() < 1e-4,
                        "{column:?} z {z} k {k}: {s:?} {limit:?}"
                    );
                }
            }
        }
    }

    /// The half-space mode: `sigma_zz = -(1 + s) e^(-s)`, `sigma_xx = -(1 -
    /// s) e^(-s)`, `sigma_xz = -s e^(-s)`, to rounding, alone and as a stack
    /// of identical layers on a base of the same material.
    #[test]
    fn half_space_mode_is_the_closed_form() {
        let alone = Column {
            plies: vec![],
            base: Some(ply(1.0, 0.3, 0.0)),
            frictionless: false,
        };
        let stacked = Column {
            plies: vec![ply(1.0, 0.3, 0.7), ply(1.0, 0.3, 2.0), ply(1.0, 0.3, 30.0)],
            base: Some(ply(1.0, 0.3, 0.0)),
            frictionless: false,
        };
        let q = 1.3;
        for column in [alone, stacked] {
            let mut m = Vec::new();
            let mut c = vec![0.0; column.unknowns()];
            column.solve(q, &mut m, &mut c).unwrap();
            for z in [0.0, 0.1, 0.7, 1.5, 2.7, 20.0, 40.0] {
                let (i, top) = column.locate(z, false);
                let s = column.stress_at(i, q * (z - top), q, &c);
                let t = q * z;
                let e = (-t).exp();
                let expected = [-(1.0 + t) * e, -(1.0 - t) * e, -0.3 * 2.0 * e, -t * e];
                for k in 0..4 {
                    assert!(
                        (s[k] - expected[k]).abs() < 1e-15,
                        "{z} {k}: {s:?} {expected:?}"
                    );
                }
            }
        }
    }
}
