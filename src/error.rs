//! The one error type of the crate.
//!
//! Every fallible constructor and solver returns [`Error`]. Each variant names
//! the offending quantity and carries its value, so that a message such as
//! `Poisson ratio must lie in [0, 0.5], got 0.7` tells the caller what to fix.

/// A number as a person reads it: plain between `1e-4` and `1e7`, in
/// scientific notation beyond (`1e-300`, not three hundred zeros).
struct Readable(f64);

impl std::fmt::Display for Readable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = self.0;
        if v == 0.0 || !v.is_finite() || (1e-4..1e7).contains(&v.abs()) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

fn readable(value: &f64) -> Readable {
    Readable(*value)
}

/// Everything that can go wrong in `layered-contact`.
///
/// The enum is `#[non_exhaustive]`: later versions may add variants, so match
/// with a wildcard arm.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// Young's modulus is NaN or outside `[1e-150, 1e150]` Pa.
    #[error("Young's modulus must lie in [1e-150, 1e150] Pa, got {} Pa", readable(.value))]
    InvalidYoungsModulus {
        /// The rejected value, in Pa.
        value: f64,
    },
    /// Poisson's ratio is outside `[0, 0.5]` or NaN.
    #[error("Poisson ratio must lie in [0, 0.5], got {}", readable(.value))]
    InvalidPoissonRatio {
        /// The rejected value.
        value: f64,
    },
    /// A layer thickness is negative or NaN, or zero on a rigid base (which
    /// would leave no elastic body at all).
    #[error("layer thickness must be {expected}, got {} m", readable(.value))]
    InvalidThickness {
        /// The rejected value, in m.
        value: f64,
        /// What was expected instead.
        expected: &'static str,
    },
    /// Any other scalar input outside its domain (a radius, an angle, a work
    /// of adhesion, an index, ...).
    #[error("{name} must be {expected}, got {}", readable(.value))]
    InvalidParameter {
        /// The name of the parameter, as in the documentation.
        name: &'static str,
        /// The rejected value (converted to `f64` for integer parameters).
        value: f64,
        /// What was expected instead.
        expected: &'static str,
    },
    /// A grid has no cells, or so many that its padded FFT arrays would not
    /// fit in memory.
    #[error("grid of {rows} x {columns} cells is invalid: expected {expected}")]
    InvalidGrid {
        /// Cells along the first axis.
        rows: usize,
        /// Cells along the second axis.
        columns: usize,
        /// What was expected instead.
        expected: &'static str,
    },
    /// A field passed to an operator does not have the length of its grid.
    #[error("{field} has {found} values, but the grid has {expected} cells")]
    ShapeMismatch {
        /// Which argument was wrong.
        field: &'static str,
        /// The number of cells of the grid.
        expected: usize,
        /// The length that was passed.
        found: usize,
    },
    /// The indenter cannot touch the surface anywhere on the grid (its height
    /// is `+inf` at every cell centre): the grid does not reach it.
    #[error("the indenter (bounding radius {} m) does not reach any cell of a grid {} m wide", readable(.bounding_radius), readable(.grid_extent))]
    IndenterOutsideGrid {
        /// The indenter's bounding radius, m.
        bounding_radius: f64,
        /// The smaller side of the grid, m.
        grid_extent: f64,
    },
    /// A combination of options the library does not offer.
    #[error("{feature} is not available: {reason}")]
    Unsupported {
        /// What was asked for.
        feature: &'static str,
        /// Why not, and what to use instead.
        reason: &'static str,
    },
    /// The caller's interrupt check ([`ContactSolver::set_interrupt`](crate::solver::ContactSolver::set_interrupt))
    /// asked to stop (Ctrl-C in Python).
    #[error("{what} was interrupted")]
    Interrupted {
        /// What was running.
        what: &'static str,
    },
    /// A failure inside the library that valid input should never cause;
    /// please report it.
    #[error("internal error in {what}: {detail}")]
    Internal {
        /// The component that failed.
        what: &'static str,
        /// Its message.
        detail: String,
    },
    /// The contact reaches the edge of an isolated grid (or the grid leaves
    /// too little room around it), so the result would be truncated: use a
    /// wider grid.
    #[error("the contact reaches the grid's edge ({cells} cells in contact): {detail}")]
    ContactReachesEdge {
        /// Cells in the contact (or in the largest usable set).
        cells: usize,
        /// What reached the edge.
        detail: &'static str,
    },
    /// A computed quantity is not finite (overflow or underflow in the
    /// input's scales); no result is returned rather than a NaN or an
    /// infinity.
    #[error("{what} produced a non-finite value ({})", readable(.value))]
    NonFinite {
        /// The computation.
        what: &'static str,
        /// The value it produced.
        value: f64,
    },
    /// Under force control, no equilibrium exists at the requested force:
    /// an adhesive contact pulled beyond its pull-off force, or a pull on an
    /// indenter that is not in contact.
    #[error(
        "no equilibrium at force {} N: the least force the contact can hold is {} N",
        readable(.force),
        readable(.least)
    )]
    NoEquilibrium {
        /// The requested force, N.
        force: f64,
        /// The least (most tensile) force with an equilibrium, N.
        least: f64,
    },
    /// The memory a computation needs could not be had.
    #[error("{what} need about {bytes} bytes, which could not be allocated")]
    OutOfMemory {
        /// The estimate, in bytes.
        bytes: usize,
        /// What needed it.
        what: &'static str,
    },
    /// A height-map file could not be read or parsed.
    #[error("height map {path}: {detail}")]
    HeightMapFile {
        /// The file.
        path: String,
        /// What went wrong (with the line for text files).
        detail: String,
    },
    /// A scene file (or text) could not be read or parsed.
    #[error("{source_name}: {detail}")]
    SceneFile {
        /// The file, or `TOML text` / `JSON text`.
        source_name: String,
        /// What went wrong, with the line, column and key where known.
        detail: String,
    },
    /// An iterative method stopped before reaching its tolerance.
    #[error("{method} did not converge after {iterations} iterations (residual {residual:e})")]
    NoConvergence {
        /// The method that gave up.
        method: &'static str,
        /// Iterations (or panels, or refinements) performed.
        iterations: usize,
        /// The last residual or error estimate reached.
        residual: f64,
    },
    // New variants go last: the semver check treats a variant's position as
    // its discriminant.
    /// Another rank of a run split across MPI ranks (feature `mpi`) failed,
    /// and its own error says why; this rank stopped too, so that no rank
    /// waits in a collective for one that has returned.
    #[error("{failed} other MPI rank(s) failed (see their errors); this rank stopped with them")]
    OtherRankFailed {
        /// How many other ranks failed.
        failed: usize,
    },
}

/// `Result` with the crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// A zeroed vector of `len` values, or [`Error::OutOfMemory`] naming
/// `what` instead of an abort.
pub(crate) fn zeroed<T: Clone + Default>(len: usize, what: &'static str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| Error::OutOfMemory {
        bytes: len.saturating_mul(std::mem::size_of::<T>()),
        what,
    })?;
    v.resize(len, T::default());
    Ok(v)
}

/// `value` if it is finite, else [`Error::InvalidParameter`] naming it
/// (for front-ends and bindings that take values the library's infallible
/// methods would turn into NaN).
///
/// ```
/// let error = layered_contact::error::finite("depth", f64::NAN).unwrap_err();
/// assert_eq!(error.to_string(), "depth must be finite, got NaN");
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for NaN and infinities.
pub fn finite(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            value,
            expected: "finite",
        })
    }
}

/// `value` if it is positive and finite, else [`Error::InvalidParameter`]
/// naming it.
///
/// # Errors
/// [`Error::InvalidParameter`] otherwise.
pub fn positive_finite(name: &'static str, value: f64) -> Result<f64> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            value,
            expected: "positive and finite",
        })
    }
}

/// `value` if it lies in `[lo, hi]` (so not NaN), else
/// [`Error::InvalidParameter`] naming it, with `expected` stating the
/// range as a person reads it. Counts pass as `f64` (exact up to 2^53).
pub(crate) fn within(
    name: &'static str,
    value: f64,
    (lo, hi): (f64, f64),
    expected: &'static str,
) -> Result<f64> {
    if (lo..=hi).contains(&value) {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            value,
            expected,
        })
    }
}

/// `value` if it is non-negative and finite, else
/// [`Error::InvalidParameter`] naming it.
///
/// # Errors
/// [`Error::InvalidParameter`] otherwise.
pub fn non_negative_finite(name: &'static str, value: f64) -> Result<f64> {
    if value >= 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            value,
            expected: "non-negative and finite",
        })
    }
}

/// `Ok` for a positive work of adhesion (J/m^2), which a pull-off needs.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `work_of_adhesion` for zero.
pub(crate) fn work_for_pull_off(work: f64) -> Result<()> {
    if work == 0.0 {
        return Err(Error::InvalidParameter {
            name: "work_of_adhesion",
            value: 0.0,
            expected: "positive for a pull-off",
        });
    }
    Ok(())
}

/// Checks an advancing (loading, `dgamma0`) and a receding (unloading,
/// `dgamma1`) work of adhesion: each non-negative and finite, and
/// `dgamma0 <= dgamma1` (an edge that advanced more easily than it recedes
/// would cycle). Returns them.
pub(crate) fn works_of_adhesion(advancing: f64, receding: f64) -> Result<(f64, f64)> {
    let advancing = non_negative_finite("work_of_adhesion (advancing)", advancing)?;
    let receding = non_negative_finite("work_of_adhesion (receding)", receding)?;
    if advancing > receding {
        return Err(Error::InvalidParameter {
            name: "work_of_adhesion (advancing)",
            value: advancing,
            expected: "at most the receding work of adhesion (dgamma0 <= dgamma1)",
        });
    }
    Ok((advancing, receding))
}

/// Checks that `nu` is a Poisson ratio in `[0, 0.5]`.
pub(crate) fn poisson_ratio(nu: f64) -> Result<f64> {
    if (0.0..=0.5).contains(&nu) {
        Ok(nu)
    } else {
        Err(Error::InvalidPoissonRatio { value: nu })
    }
}
