//! Real-space influence coefficients of the isolated (non-periodic) problem.

use std::f64::consts::PI;

use crate::grid::Grid;
use crate::substrate::Substrate;

use super::cell::{lifted_love, love};
use super::radial::{RadialDensity, RadialRemainder, TailTolerance};

/// A tail error estimate (relative to the self-coefficient) this small ends
/// the remainder's table: against coefficients tabulated all the way out,
/// the estimate was 8 to 5e5 times the real error (contrasts 10 to 1e4).
const ENOUGH_TAIL_ERROR: f64 = 1e-10;
/// The largest tail error estimate of usable coefficients (see
/// [`InfluenceCoefficients::tail_error_estimate`]).
pub const MAX_TAIL_ERROR: f64 = 1e-6;
/// A remainder term whose length is at least this many cells is integrated
/// over each cell by a product Gauss rule instead of by corner functions:
/// `g` is analytic near the real axis (its singularities lie about two
/// lengths off it), so on cells this small the rule is exact to rounding
/// (see [`cell_rule_order`]), and it costs 4 to 25 evaluations of `g` per
/// cell instead of two angular quadratures per corner (at 2048 x 2048 cells
/// on a film 200 cells thick, 1.5 s instead of 11 s).
const CELL_RULE_MIN_CELLS: f64 = 8.0;

/// The displacement at the centre of a cell due to a unit uniform pressure on
/// another cell, for every offset between two cells of a grid: the isolated
/// (non-periodic) influence coefficients of the substrate, m/Pa.
///
/// The coefficient for an offset `(di, dj)` (in cells) is the integral of the
/// point-force Green's function `w(r)` over the loaded cell,
/// `K(di, dj) = Integral_cell w(|x_ij - p|) dp`, with `w` split as in
/// [`doc::theory`](crate::doc::theory):
///
/// * the layer half-space `1/(pi E1* r)`, by Love's exact closed form;
/// * `-Lambda0 / (pi E1* sqrt(r^2 + h^2))`, by its exact closed form;
/// * the smooth remainder `-g(r/h)/(pi E1* h)`, by a tabulated radial
///   integral and Gauss-Legendre quadrature in angle.
///
/// Each is a corner function evaluated at the `(rows + 1) x (columns + 1)`
/// cell corners and combined by inclusion-exclusion, so every `h / Delta`
/// from `1e-3` to `1e6` is handled by the same code. A homogeneous
/// half-space uses only the first term. Coefficients depend only on `|di|`
/// and `|dj|` (the matrix is symmetric: reciprocity).
///
/// ```
/// use layered_contact::kernel::InfluenceCoefficients;
/// use layered_contact::{Grid, Material, Substrate};
///
/// let rubber = Material::new(1e6, 0.5)?;
/// let grid = Grid::new(8, 8, 1e-4)?;
/// let half = InfluenceCoefficients::isolated(&Substrate::half_space(rubber), &grid);
/// // Love (1929): a uniform square of side D deflects its centre by
/// // 4 asinh(1) D / (pi E*).
/// let love = 4.0 * 1f64.asinh() * 1e-4 / (std::f64::consts::PI * rubber.contact_modulus());
/// assert!((half.get(0, 0) / love - 1.0).abs() < 1e-14);
/// // A film on glass is stiffer:
/// let film = Substrate::layer_on_rigid_base(rubber, 2e-4)?;
/// let coated = InfluenceCoefficients::isolated(&film, &grid);
/// assert!(coated.get(0, 0) < half.get(0, 0));
/// Ok::<(), layered_contact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct InfluenceCoefficients {
    grid: Grid,
    /// `K(|di|, |dj|)`, row-major over `rows x columns` offsets.
    values: Vec<f64>,
    /// Estimated absolute error of the remainder's tail, relative to the
    /// self-coefficient (0 for a half-space).
    tail_error: f64,
}

/// Gauss points per side of the cell rule for cells `spacing` lengths
/// wide. The rule's error falls like `spacing^(2m)` for `m` points; these
/// orders keep it below the corner functions' own rounding (measured
/// against them over every coefficient of 64 x 64 grids, on a rigid base
/// and on bases 10 and 1000 times softer, at 8 to 1024 cells per length:
/// at most `7.5e-15`, `6.1e-14` and `3.5e-12` of the self-coefficient, the
/// same as the two routes' disagreement with higher orders).
fn cell_rule_order(spacing: f64) -> usize {
    match spacing {
        s if s <= 1.0 / 256.0 => 2,
        s if s <= 1.0 / 32.0 => 3,
        s if s <= 1.0 / 16.0 => 4,
        _ => 5,
    }
}

/// The cell rule of one remainder term: `Integral_cell g(|p|/h)/h dp` over
/// the cell at an offset of `(di, dj)` cells, by a product Gauss rule.
struct CellRule<'a> {
    length: f64,
    /// The cell size over `length`.
    spacing: f64,
    density: &'a RadialDensity,
    /// Nodes (about the cell's centre) and weights, in units of `length`.
    points: Vec<(f64, f64)>,
}

impl<'a> CellRule<'a> {
    /// `None` where the term is integrated by corner functions.
    fn new(term: &'a CornerTerm, delta: f64) -> Option<Self> {
        let density = term.density.as_ref()?;
        let spacing = delta / term.length;
        let rule = crate::numerics::gauss(cell_rule_order(spacing));
        let points = rule
            .as_node_weight_pairs()
            .iter()
            .map(|&(x, w)| (0.5 * spacing * x, 0.5 * spacing * w))
            .collect();
        Some(CellRule {
            length: term.length,
            spacing,
            density,
            points,
        })
    }

    fn integral(&self, di: usize, dj: usize) -> f64 {
        let (x0, y0) = (di as f64 * self.spacing, dj as f64 * self.spacing);
        let sum: f64 = self
            .points
            .iter()
            .map(|&(x, wx)| {
                let x = x0 + x;
                wx * self
                    .points
                    .iter()
                    .map(|&(y, wy)| wy * self.density.at(x.hypot(y0 + y)))
                    .sum::<f64>()
            })
            .sum();
        self.length * sum
    }
}

/// `f(k, l)` for every `(k, l)` of a `rows x columns` table, row-major,
/// with `f` symmetric where both lie below `min(rows, columns)`: those
/// entries are computed once (rows in parallel) and mirrored.
fn symmetric_table(
    rows: usize,
    columns: usize,
    f: impl Fn(usize, usize) -> f64 + Sync + Send,
) -> Vec<f64> {
    let mut table = vec![0.0; rows * columns];
    crate::parallel::for_each_row(&mut table, columns, |k, row| {
        let from = if k < columns { k } else { 0 };
        for (l, value) in row.iter_mut().enumerate().skip(from) {
            *value = f(k, l);
        }
    });
    for k in 1..rows.min(columns) {
        for l in 0..k {
            table[k * columns + l] = table[l * columns + k];
        }
    }
    table
}

/// The corner function `F(X, Y)` of the Green's function, without the
/// factor `1/(pi E1*)` (see [`doc::theory`](crate::doc::theory)): Love's
/// closed form, minus for a layered body one lifted Love term and one
/// tabulated remainder per length scale (the layer's thickness, or each
/// interface depth of a stack, see [`doc::multilayer`](crate::doc::multilayer)).
struct CornerFunction {
    terms: Vec<CornerTerm>,
}

struct CornerTerm {
    length: f64,
    lambda0: f64,
    remainder: RadialRemainder,
    /// `g` itself where the remainder is integrated by the cell rule (then
    /// the corner function leaves it out).
    density: Option<RadialDensity>,
}

impl CornerFunction {
    fn eval(&self, x: f64, y: f64) -> f64 {
        self.terms.iter().fold(love(x, y), |total, term| {
            let h = term.length;
            let remainder = match term.density {
                Some(_) => 0.0,
                None => h * term.remainder.corner(x / h, y / h),
            };
            total - term.lambda0 * lifted_love(x, y, h) - remainder
        })
    }
}

impl InfluenceCoefficients {
    /// The isolated influence coefficients of `substrate` on `grid`.
    pub fn isolated(substrate: &Substrate, grid: &Grid) -> Self {
        let (rows, columns) = (grid.rows(), grid.columns());
        let delta = grid.spacing();
        let corner_at = |k: usize| (k as f64 + 0.5) * delta;
        let modulus = substrate.surface_material().contact_modulus();
        let reach = corner_at(rows).hypot(corner_at(columns));
        // The tail error enters each corner at most as h (pi/2) |mismatch|,
        // a coefficient as four corners; relative to the self-coefficient:
        let self_love = 4.0 * love(0.5 * delta, 0.5 * delta);
        let relative_tail = |h: f64, mismatch: f64| {
            // No mismatch, no error, whatever the thickness (at h = f64::MAX
            // the product would be inf * 0 = NaN).
            if mismatch == 0.0 {
                0.0
            } else {
                2.0 * PI * h * mismatch / self_love
            }
        };
        let corner_function = CornerFunction {
            terms: substrate
                .terms()
                .into_iter()
                .map(|term| {
                    let h = term.length;
                    let mismatch_for = |relative: f64| relative * self_love / (2.0 * PI * h);
                    let remainder = RadialRemainder::new(
                        &term.functions,
                        0.5 * delta / h,
                        reach / h,
                        TailTolerance {
                            enough: mismatch_for(ENOUGH_TAIL_ERROR),
                            unusable: mismatch_for(MAX_TAIL_ERROR),
                        },
                    );
                    let density = (h >= CELL_RULE_MIN_CELLS * delta)
                        .then(|| RadialDensity::new(&term.functions, &remainder, reach / h));
                    CornerTerm {
                        length: h,
                        lambda0: term.functions.lambda(0.0),
                        remainder,
                        density,
                    }
                })
                .collect(),
        };
        let tail = corner_function
            .terms
            .iter()
            .map(|term| match &term.density {
                // A cell's error is its area times g's.
                Some(density) => {
                    term.length * (delta / term.length).powi(2) * density.tail_mismatch()
                        / self_love
                }
                None => relative_tail(term.length, term.remainder.tail_mismatch()),
            })
            .sum();
        // Corner values F((k + 1/2) Delta, (l + 1/2) Delta).
        let corners = symmetric_table(rows, columns, |k, l| {
            corner_function.eval(corner_at(k), corner_at(l))
        });
        // F is odd in each argument: the corner at -Delta/2 is minus the one at +Delta/2.
        let corner = |k: isize, l: isize| -> f64 {
            let sign = if (k < 0) != (l < 0) { -1.0 } else { 1.0 };
            sign * corners[k.max(-k - 1) as usize * columns + l.max(-l - 1) as usize]
        };
        // Remainders by the cell rule.
        let cell_rules: Vec<CellRule> = corner_function
            .terms
            .iter()
            .filter_map(|term| CellRule::new(term, delta))
            .collect();
        let cell_remainder = |di: usize, dj: usize| -> f64 {
            cell_rules.iter().map(|rule| rule.integral(di, dj)).sum()
        };
        let scale = 1.0 / (PI * modulus);
        let values = symmetric_table(rows, columns, |di, dj| {
            let (i, j) = (di as isize, dj as isize);
            let integral =
                corner(i, j) - corner(i - 1, j) - corner(i, j - 1) + corner(i - 1, j - 1);
            scale * (integral - cell_remainder(di, dj))
        });
        InfluenceCoefficients {
            grid: *grid,
            values,
            tail_error: tail,
        }
    }

    /// The grid the coefficients belong to.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The coefficient for an offset of `(di, dj)` cells (any signs, `|di| <
    /// rows`, `|dj| < columns`; 0 beyond), m/Pa.
    pub fn get(&self, di: isize, dj: isize) -> f64 {
        let (i, j) = (di.unsigned_abs(), dj.unsigned_abs());
        if i < self.grid.rows() && j < self.grid.columns() {
            self.values[i * self.grid.columns() + j]
        } else {
            0.0
        }
    }

    /// Adds the displacements of a few loaded cells to `displacement`
    /// (row-major over the grid) by direct summation, `u(x) += sum_j f_j
    /// K(x - x_j)`, each of `loads` a cell index and its uniform pressure
    /// (Pa). Exact and cheaper than an FFT convolution for a handful of
    /// cells: it costs `loads.len()` passes over the grid. Rows are summed
    /// in parallel, each in the order of `loads`, so the result does not
    /// depend on the number of threads.
    ///
    /// ```
    /// use layered_contact::kernel::InfluenceCoefficients;
    /// use layered_contact::{Grid, Material, Substrate};
    ///
    /// let grid = Grid::new(3, 4, 1e-4)?;
    /// let k = InfluenceCoefficients::isolated(
    ///     &Substrate::half_space(Material::new(1e6, 0.3)?), &grid);
    /// let mut u = vec![0.0; 12];
    /// k.add_loads(&[(5, 2.0), (11, -1.0)], &mut u); // cells (1, 1) and (2, 3)
    /// let expected = 2.0 * k.get(0 - 1, 3 - 1) - k.get(0 - 2, 3 - 3);
    /// assert_eq!(u[3], expected); // cell (0, 3)
    /// Ok::<(), layered_contact::Error>(())
    /// ```
    ///
    /// # Panics
    /// If `displacement` does not hold one value per cell or a load's cell
    /// is off the grid (a caller's bug).
    pub fn add_loads(&self, loads: &[(usize, f64)], displacement: &mut [f64]) {
        let (rows, columns) = (self.grid.rows(), self.grid.columns());
        assert_eq!(displacement.len(), rows * columns, "one value per cell");
        assert!(
            loads.iter().all(|&(c, _)| c < rows * columns),
            "loaded cells on the grid"
        );
        crate::parallel::for_each_row(displacement, columns, |i, row| {
            for &(c, load) in loads {
                let (li, lj) = (c / columns, c % columns);
                let k = &self.values[i.abs_diff(li) * columns..][..columns];
                // Columns left of the load see K(lj - j), right of it K(j - lj).
                for (u, k) in row[..lj].iter_mut().zip(k[1..=lj].iter().rev()) {
                    *u += load * k;
                }
                for (u, k) in row[lj..].iter_mut().zip(k) {
                    *u += load * k;
                }
            }
        });
    }

    /// The coefficients of the grid of half the cells each way (`coarse`:
    /// `rows / 2 x columns / 2` cells of twice the size, both sides even),
    /// Galerkin's `R K P`: a uniform pressure on a coarse cell is one on its
    /// four fine cells (`P`), and a coarse cell's displacement is the mean of
    /// its four fine cells' (`R`). So `K_c(I, J) = 1/4 sum w(a) w(b) K(2I + a,
    /// 2J + b)` over `a, b` in `-1, 0, 1`, `w = (1, 2, 1)` (the pairs of a
    /// source and a target cell per offset). Every fine offset it reads lies
    /// on the table (at most `2 (rows / 2 - 1) + 1 = rows - 1`).
    pub(crate) fn halved(&self, coarse: &Grid) -> Self {
        let (rows, columns) = (coarse.rows(), coarse.columns());
        let weight = |a: isize| if a == 0 { 2.0 } else { 1.0 };
        let mut values = vec![0.0; rows * columns];
        crate::parallel::for_each_row(&mut values, columns, |i, row| {
            for (j, value) in row.iter_mut().enumerate() {
                let (fi, fj) = (2 * i as isize, 2 * j as isize);
                let mut sum = 0.0;
                for a in -1..=1 {
                    for b in -1..=1 {
                        sum += weight(a) * weight(b) * self.get(fi + a, fj + b);
                    }
                }
                *value = 0.25 * sum;
            }
        });
        InfluenceCoefficients {
            grid: *coarse,
            values,
            tail_error: self.tail_error,
        }
    }

    /// The self-coefficient `K(0, 0)`, m/Pa.
    pub fn self_coefficient(&self) -> f64 {
        self.values[0]
    }

    /// An estimate of the largest absolute error of a coefficient, relative to
    /// the layer half-space's self-coefficient, from where the tabulated
    /// remainder hands over to its asymptotic expansion. Below `1e-10` for a
    /// rigid base and moderate contrasts; it grows for coatings much stiffer
    /// than their base (contrasts of `1e3` and more) on grids that span many
    /// thousand coating thicknesses: their Green's functions vary on the
    /// coating's membrane and bending lengths, far beyond `h`, and the
    /// coefficients are then wrong by orders of magnitude.
    /// [`ComplianceOperator::new`](crate::kernel::ComplianceOperator::new)
    /// refuses coefficients whose estimate exceeds [`MAX_TAIL_ERROR`]
    /// (`1e-6`; against coefficients tabulated all the way out, the estimate
    /// was 8 to 5e5 times the real error for contrasts from 10 to `1e4`).
    pub fn tail_error_estimate(&self) -> f64 {
        self.tail_error
    }
}
