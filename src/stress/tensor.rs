//! The stress tensor at a point and the scalar measures derived from it.

/// A symmetric stress tensor, Pa (tension positive: a pressed body has
/// `zz < 0` under the contact). `z` points into the body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stress {
    /// `sigma_xx`.
    pub xx: f64,
    /// `sigma_yy`.
    pub yy: f64,
    /// `sigma_zz`.
    pub zz: f64,
    /// `sigma_xy`.
    pub xy: f64,
    /// `sigma_xz`.
    pub xz: f64,
    /// `sigma_yz`.
    pub yz: f64,
}

impl Stress {
    /// The mean normal stress `(xx + yy + zz) / 3` (negative in
    /// compression).
    pub fn hydrostatic(&self) -> f64 {
        (self.xx + self.yy + self.zz) / 3.0
    }

    /// The von Mises equivalent stress `sqrt(3 J2)`, from the components
    /// (no eigenvalues needed).
    pub fn von_mises(&self) -> f64 {
        let d =
            (self.xx - self.yy).powi(2) + (self.yy - self.zz).powi(2) + (self.zz - self.xx).powi(2);
        let s = self.xy * self.xy + self.xz * self.xz + self.yz * self.yz;
        (0.5 * d + 3.0 * s).sqrt()
    }

    /// The principal stresses, largest (most tensile) first, by the
    /// trigonometric solution of the characteristic cubic (Smith 1961,
    /// Comm. ACM 4, 168), exact for a diagonal tensor.
    pub fn principal(&self) -> [f64; 3] {
        let off = self.xy * self.xy + self.xz * self.xz + self.yz * self.yz;
        let mut values = if off == 0.0 {
            [self.xx, self.yy, self.zz]
        } else {
            let mean = self.hydrostatic();
            let (a, b, c) = (self.xx - mean, self.yy - mean, self.zz - mean);
            // p = sqrt(J2 / 1.5 ...): the deviator's scale.
            let p2 = (a * a + b * b + c * c + 2.0 * off) / 6.0;
            let p = p2.sqrt();
            // det of the deviator over p^3, halved: cos(3 theta).
            let det = a * (b * c - self.yz * self.yz) - self.xy * (self.xy * c - self.yz * self.xz)
                + self.xz * (self.xy * self.yz - b * self.xz);
            let r = (det / (2.0 * p2 * p)).clamp(-1.0, 1.0);
            let phi = r.acos() / 3.0;
            let third = 2.0 * std::f64::consts::PI / 3.0;
            let largest = mean + 2.0 * p * phi.cos();
            let smallest = mean + 2.0 * p * (phi + third).cos();
            [largest, 3.0 * mean - largest - smallest, smallest]
        };
        values.sort_by(|x, y| y.total_cmp(x));
        values
    }

    /// The largest shear stress (Tresca), half the spread of the principal
    /// stresses.
    pub fn max_shear(&self) -> f64 {
        let [first, _, last] = self.principal();
        0.5 * (first - last)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rotated diagonal tensor: the principal values come back, von
    /// Mises and Tresca agree with their principal forms.
    #[test]
    fn invariants_of_a_rotated_tensor() {
        let (s1, s2, s3) = (3.0, -1.0, -7.0);
        // Rotation by 0.4 rad about z, then 0.9 rad about x.
        let (c, s) = (0.4f64.cos(), 0.4f64.sin());
        let (cx, sx) = (0.9f64.cos(), 0.9f64.sin());
        let rz = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
        let rx = [[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]];
        let r: [[f64; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| (0..3).map(|k| rx[i][k] * rz[k][j]).sum())
        });
        let d = [s1, s2, s3];
        let t = |i: usize, j: usize| (0..3).map(|k| r[i][k] * d[k] * r[j][k]).sum::<f64>();
        let stress = Stress {
            xx: t(0, 0),
            yy: t(1, 1),
            zz: t(2, 2),
            xy: t(0, 1),
            xz: t(0, 2),
            yz: t(1, 2),
        };
        let p = stress.principal();
        for (got, want) in p.iter().zip([s1, s2, s3]) {
            assert!((got - want).abs() < 1e-14, "{p:?}");
        }
        let vm = (0.5 * ((s1 - s2).powi(2) + (s2 - s3).powi(2) + (s3 - s1).powi(2))).sqrt();
        assert!((stress.von_mises() - vm).abs() < 1e-14);
        assert!((stress.max_shear() - 5.0).abs() < 1e-14);
        assert!((stress.hydrostatic() + 5.0 / 3.0).abs() < 1e-15);
    }
}
