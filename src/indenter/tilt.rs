//! Small tilts of any indenter.

use crate::error::{Error, Result};

use super::Indenter;

/// An indenter rotated by small angles: `angle_y` about the `y` axis (the
/// face rises with `x`) and `angle_x` about the `x` axis (it rises with
/// `y`): `f'(x, y) = f(x, y) + x tan(angle_y) + y tan(angle_x)`.
///
/// The depth stays the approach of the axis point, so a tilted flat punch of
/// radius `a` first touches at its low edge when `d = -a tan(angle)`. The
/// rotation is linearised in the profile (exact heights, no change of the
/// horizontal footprint), valid for the small misalignments of experiments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tilted<I> {
    inner: I,
    slope_x: f64,
    slope_y: f64,
}

/// The tilt angles [`Tilted::new`] takes: finite and below 0.1 rad.
pub(crate) fn check_angles(angle_y: f64, angle_x: f64) -> Result<()> {
    for (name, angle) in [("angle_y", angle_y), ("angle_x", angle_x)] {
        if angle.is_nan() || angle.abs() >= 0.1 {
            return Err(Error::InvalidParameter {
                name,
                value: angle,
                expected: "a small angle, |angle| < 0.1 rad",
            });
        }
    }
    Ok(())
}

impl<I: Indenter> Tilted<I> {
    /// `inner` tilted by `angle_y` about the `y` axis and `angle_x` about the
    /// `x` axis (radians, `|angle| < 0.1`, i.e. below about 6 degrees).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an angle that is not finite or not small.
    pub fn new(inner: I, angle_y: f64, angle_x: f64) -> Result<Self> {
        check_angles(angle_y, angle_x)?;
        Ok(Tilted {
            inner,
            slope_x: angle_y.tan(),
            slope_y: angle_x.tan(),
        })
    }

    /// The untilted indenter.
    pub fn inner(&self) -> &I {
        &self.inner
    }
}

impl<I: Indenter> Indenter for Tilted<I> {
    fn height(&self, x: f64, y: f64) -> f64 {
        self.inner.height(x, y) + x * self.slope_x + y * self.slope_y
    }

    fn bounding_radius(&self) -> f64 {
        self.inner.bounding_radius()
    }
}
