//! Truncated power series in `t`, for the Taylor coefficients of the
//! coating functions at `t = 0`.

/// Number of Taylor coefficients kept by [`Series`].
pub(crate) const TAYLOR_TERMS: usize = 9;

/// A power series in `t` truncated after `t^(TAYLOR_TERMS - 1)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Series(pub(crate) [f64; TAYLOR_TERMS]);

impl Series {
    pub(crate) fn constant(c: f64) -> Self {
        let mut s = [0.0; TAYLOR_TERMS];
        s[0] = c;
        Series(s)
    }

    pub(crate) fn monomial(power: usize) -> Self {
        let mut s = [0.0; TAYLOR_TERMS];
        s[power] = 1.0;
        Series(s)
    }

    /// `e^(c t)`.
    pub(crate) fn exp(c: f64) -> Self {
        let mut s = [0.0; TAYLOR_TERMS];
        s[0] = 1.0;
        for k in 1..TAYLOR_TERMS {
            s[k] = s[k - 1] * c / k as f64;
        }
        Series(s)
    }

    /// `sinh t - t`.
    pub(crate) fn sinh_minus_identity() -> Self {
        let mut s = [0.0; TAYLOR_TERMS];
        let mut factorial = 1.0;
        for (k, value) in s.iter_mut().enumerate().skip(1) {
            factorial *= k as f64;
            if k % 2 == 1 && k >= 3 {
                *value = 1.0 / factorial;
            }
        }
        Series(s)
    }

    fn zip(&self, other: &Self, op: impl Fn(f64, f64) -> f64) -> Self {
        let mut s = [0.0; TAYLOR_TERMS];
        for (k, value) in s.iter_mut().enumerate() {
            *value = op(self.0[k], other.0[k]);
        }
        Series(s)
    }

    pub(crate) fn add(&self, other: &Self) -> Self {
        self.zip(other, |x, y| x + y)
    }

    pub(crate) fn sub(&self, other: &Self) -> Self {
        self.zip(other, |x, y| x - y)
    }

    pub(crate) fn scale(&self, c: f64) -> Self {
        Series(self.0.map(|x| x * c))
    }

    pub(crate) fn mul(&self, other: &Self) -> Self {
        let mut s = [0.0; TAYLOR_TERMS];
        for i in 0..TAYLOR_TERMS {
            for j in 0..TAYLOR_TERMS - i {
                s[i + j] += self.0[i] * other.0[j];
            }
        }
        Series(s)
    }

    /// `self / other`, requiring `other.0[0] != 0`.
    pub(crate) fn div(&self, other: &Self) -> Self {
        let mut q = [0.0; TAYLOR_TERMS];
        for k in 0..TAYLOR_TERMS {
            let known: f64 = (0..k).map(|j| q[j] * other.0[k - j]).sum();
            q[k] = (self.0[k] - known) / other.0[0];
        }
        Series(q)
    }
}

/// The arithmetic the stack recursion needs, shared by plain numbers (values
/// of the coating functions) and truncated power series (their Taylor
/// coefficients at `t = 0`).
pub(crate) trait Scalar: Copy {
    fn constant(c: f64) -> Self;
    fn plus(self, other: Self) -> Self;
    fn minus(self, other: Self) -> Self;
    fn times(self, other: Self) -> Self;
    /// `self / other`; for a series `other` must not vanish at `t = 0`.
    fn over(self, other: Self) -> Self;
    fn scaled(self, c: f64) -> Self;
}

impl Scalar for f64 {
    fn constant(c: f64) -> Self {
        c
    }
    fn plus(self, other: Self) -> Self {
        self + other
    }
    fn minus(self, other: Self) -> Self {
        self - other
    }
    fn times(self, other: Self) -> Self {
        self * other
    }
    fn over(self, other: Self) -> Self {
        self / other
    }
    fn scaled(self, c: f64) -> Self {
        self * c
    }
}

impl Scalar for Series {
    fn constant(c: f64) -> Self {
        Series::constant(c)
    }
    fn plus(self, other: Self) -> Self {
        self.add(&other)
    }
    fn minus(self, other: Self) -> Self {
        self.sub(&other)
    }
    fn times(self, other: Self) -> Self {
        self.mul(&other)
    }
    fn over(self, other: Self) -> Self {
        self.div(&other)
    }
    fn scaled(self, c: f64) -> Self {
        self.scale(c)
    }
}
