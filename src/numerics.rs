//! Numerical building blocks shared by the kernel and the analytic module:
//! Gauss-Legendre rules, piecewise Chebyshev tables on octaves, and
//! quadrature of oscillatory integrals over `[0, inf)`.

use std::f64::consts::PI;
use std::num::NonZeroUsize;

use gauss_quad::legendre::GaussLegendre;

/// A Gauss-Legendre rule of `order` points (`order >= 1`).
pub(crate) fn gauss(order: usize) -> GaussLegendre {
    GaussLegendre::new(NonZeroUsize::new(order.max(1)).expect("order is at least 1"))
}

/// Chebyshev nodes per table piece.
const NODES: usize = 24;

/// A Chebyshev interpolant of degree `NODES - 1` on an interval `[lo, hi]`.
#[derive(Debug, Clone)]
pub(crate) struct Chebyshev {
    lo: f64,
    hi: f64,
    coefficients: [f64; NODES],
}

impl Chebyshev {
    /// Interpolates `f` at the Chebyshev points of the first kind on `[lo, hi]`.
    pub(crate) fn new(lo: f64, hi: f64, mut f: impl FnMut(f64) -> f64) -> Self {
        let n = NODES as f64;
        let values: [f64; NODES] = std::array::from_fn(|j| {
            let x = (PI * (j as f64 + 0.5) / n).cos();
            f(0.5 * (lo + hi) + 0.5 * (hi - lo) * x)
        });
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
        Chebyshev {
            lo,
            hi,
            coefficients,
        }
    }

    /// The value at `x` (clamped to the interval), by Clenshaw's recurrence.
    pub(crate) fn eval(&self, x: f64) -> f64 {
        let t = ((2.0 * x - self.lo - self.hi) / (self.hi - self.lo)).clamp(-1.0, 1.0);
        let (mut b1, mut b2) = (0.0, 0.0);
        for &c in self.coefficients.iter().skip(1).rev() {
            let b0 = 2.0 * t * b1 - b2 + c;
            b2 = b1;
            b1 = b0;
        }
        t * b1 - b2 + self.coefficients[0]
    }

    /// The interpolant's derivative, itself a Chebyshev series
    /// (`c'_(k-1) = c'_(k+1) + 2 k c_k`).
    pub(crate) fn derivative(&self) -> Self {
        let mut d = [0.0; NODES];
        for k in (1..NODES).rev() {
            let next = if k + 1 < NODES { d[k + 1] } else { 0.0 };
            d[k - 1] = next + 2.0 * k as f64 * self.coefficients[k];
        }
        d[0] *= 0.5;
        let scale = 2.0 / (self.hi - self.lo);
        Chebyshev {
            lo: self.lo,
            hi: self.hi,
            coefficients: d.map(|c| c * scale),
        }
    }
}

/// A function tabulated by Chebyshev pieces on the octaves
/// `[2^k, 2^(k+1)]`, `k = first, first + 1, ...`, optionally with a head
/// piece on `[0, 2^first]`.
#[derive(Debug, Clone)]
pub(crate) struct OctaveTable {
    first: i32,
    head: Option<Box<Chebyshev>>,
    pieces: Vec<Chebyshev>,
}

impl OctaveTable {
    /// Tabulates `f` from `2^first` (or from 0 with `with_head`) octave by
    /// octave until `stop(end)` returns true after an octave ending at `end`.
    pub(crate) fn build(
        first: i32,
        with_head: bool,
        mut f: impl FnMut(f64) -> f64,
        mut stop: impl FnMut(f64) -> bool,
    ) -> Self {
        let start = 2f64.powi(first);
        let head = with_head.then(|| Box::new(Chebyshev::new(0.0, start, &mut f)));
        let mut pieces = Vec::new();
        let mut octave = first;
        loop {
            let lo = 2f64.powi(octave);
            pieces.push(Chebyshev::new(lo, 2.0 * lo, &mut f));
            octave += 1;
            if stop(2.0 * lo) {
                break;
            }
        }
        OctaveTable {
            first,
            head,
            pieces,
        }
    }

    /// Where the table starts (0 with a head piece).
    pub(crate) fn start(&self) -> f64 {
        if self.head.is_some() {
            0.0
        } else {
            2f64.powi(self.first)
        }
    }

    /// Where the table ends.
    pub(crate) fn end(&self) -> f64 {
        2f64.powi(self.first + self.pieces.len() as i32)
    }

    /// The piece holding `x` (the nearest one outside the range).
    fn piece(&self, x: f64) -> &Chebyshev {
        let start = 2f64.powi(self.first);
        if x < start {
            if let Some(head) = &self.head {
                return head;
            }
            return &self.pieces[0];
        }
        let index = (x.log2().floor() as i32 - self.first).max(0) as usize;
        &self.pieces[index.min(self.pieces.len() - 1)]
    }

    /// The tabulated value at `x` (clamped to the range).
    pub(crate) fn eval(&self, x: f64) -> f64 {
        self.piece(x).eval(x)
    }

    /// The derivative table.
    pub(crate) fn derivative(&self) -> Self {
        OctaveTable {
            first: self.first,
            head: self.head.as_ref().map(|h| Box::new(h.derivative())),
            pieces: self.pieces.iter().map(Chebyshev::derivative).collect(),
        }
    }
}

/// `Integral_0^inf f(u) w(u) du` for a smooth `f` negligible beyond `u_max`
/// and an oscillating weight folded into `f` with angular frequency
/// `frequency`: Gauss-Legendre on panels of one period (at most 1 wide),
/// refined geometrically towards `u = 0`, where `f` may vary on short scales.
pub(crate) fn oscillatory_integral(
    f: impl Fn(f64) -> f64,
    frequency: f64,
    u_max: f64,
    rule: &GaussLegendre,
) -> f64 {
    let width = (2.0 * PI / frequency).min(1.0);
    let mut total = 0.0;
    let mut upper = width;
    for _ in 0..60 {
        let lower = 0.5 * upper;
        total += rule.integrate(lower, upper, &f);
        upper = lower;
    }
    let panels = (u_max / width).ceil() as usize;
    for i in 1..panels {
        let lower = i as f64 * width;
        total += rule.integrate(lower, lower + width, &f);
    }
    total
}
