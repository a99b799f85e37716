//! Anderson acceleration of a fixed-point iteration `x = G(x)` (Anderson
//! 1965, J. ACM 12, 547; in the form of Walker & Ni 2011, SIAM J. Numer.
//! Anal. 49, 1715): the next iterate mixes the last few `G(x)` with the
//! weights that minimise the combined residual `G(x) - x` in least squares.

use std::collections::VecDeque;

/// The mixing history: the last `depth` differences of residuals and of
/// `G(x)`.
pub(super) struct Anderson {
    depth: usize,
    /// `(Delta f, Delta g)` pairs, oldest first.
    differences: VecDeque<(Vec<f64>, Vec<f64>)>,
    /// The previous residual and `G(x)`.
    last: Option<(Vec<f64>, Vec<f64>)>,
}

impl Anderson {
    pub(super) fn new(depth: usize) -> Self {
        Anderson {
            depth,
            differences: VecDeque::with_capacity(depth),
            last: None,
        }
    }

    /// Forgets the history (after a step that made the residual grow).
    pub(super) fn reset(&mut self) {
        self.differences.clear();
        self.last = None;
    }

    /// The next iterate into `x`, from `g = G(x)` (and `x` itself).
    pub(super) fn next(&mut self, x: &mut [f64], g: &[f64]) {
        let f: Vec<f64> = g.iter().zip(x.iter()).map(|(g, x)| g - x).collect();
        if let Some((f_old, g_old)) = self.last.take() {
            let df = f.iter().zip(&f_old).map(|(a, b)| a - b).collect();
            let dg = g.iter().zip(&g_old).map(|(a, b)| a - b).collect();
            if self.differences.len() == self.depth {
                self.differences.pop_front();
            }
            self.differences.push_back((df, dg));
        }
        let gamma = self.weights(&f);
        x.copy_from_slice(g);
        for ((_, dg), w) in self.differences.iter().zip(&gamma) {
            for (x, d) in x.iter_mut().zip(dg) {
                *x -= w * d;
            }
        }
        self.last = Some((f, g.to_vec()));
    }

    /// The least-squares weights `gamma` minimising `|f - sum gamma_j
    /// Delta f_j|`, by the normal equations with a small Tikhonov term
    /// (the differences are few and may be nearly dependent); zero weights
    /// where the system is singular.
    fn weights(&self, f: &[f64]) -> Vec<f64> {
        let m = self.differences.len();
        if m == 0 {
            return Vec::new();
        }
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(a, b)| a * b).sum::<f64>();
        let mut a = vec![vec![0.0; m + 1]; m];
        for i in 0..m {
            for j in 0..=i {
                let v = dot(&self.differences[i].0, &self.differences[j].0);
                a[i][j] = v;
                a[j][i] = v;
            }
            a[i][m] = dot(&self.differences[i].0, f);
        }
        let trace: f64 = (0..m).map(|i| a[i][i]).sum();
        for (i, row) in a.iter_mut().enumerate() {
            row[i] += 1e-10 * trace / m as f64;
        }
        // Gaussian elimination with partial pivoting on the m x m system.
        for col in 0..m {
            let pivot = (col..m)
                .max_by(|&r, &s| a[r][col].abs().total_cmp(&a[s][col].abs()))
                .unwrap_or(col);
            a.swap(col, pivot);
            let p = a[col][col];
            if p == 0.0 || !p.is_finite() {
                return vec![0.0; m];
            }
            for r in col + 1..m {
                let factor = a[r][col] / p;
                for c in col..=m {
                    a[r][c] -= factor * a[col][c];
                }
            }
        }
        let mut gamma = vec![0.0; m];
        for r in (0..m).rev() {
            let tail: f64 = (r + 1..m).map(|c| a[r][c] * gamma[c]).sum();
            gamma[r] = (a[r][m] - tail) / a[r][r];
        }
        if gamma.iter().all(|g| g.is_finite()) {
            gamma
        } else {
            vec![0.0; m]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Anderson;

    #[test]
    fn accelerates_a_linear_contraction_to_its_fixed_point() {
        // x = A x + b with A = diag(0.9, 0.5, -0.7): plain iteration needs
        // about 200 steps to 1e-10; Anderson with three differences solves
        // a three-dimensional linear map exactly after four.
        let a = [0.9, 0.5, -0.7];
        let b = [1.0, 2.0, 3.0];
        let exact: Vec<f64> = (0..3).map(|i| b[i] / (1.0 - a[i])).collect();
        let mut x = vec![0.0; 3];
        let mut mixer = Anderson::new(3);
        for _ in 0..6 {
            let g: Vec<f64> = (0..3).map(|i| a[i] * x[i] + b[i]).collect();
            mixer.next(&mut x, &g);
        }
        for i in 0..3 {
            assert!((x[i] - exact[i]).abs() < 1e-8 * exact[i].abs(), "{x:?}");
        }
    }
}
