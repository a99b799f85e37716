//! Axisymmetric indenters.

use crate::error::{positive_finite, Error, Result};

use super::Indenter;

/// A flat cylindrical punch of radius `a`: height 0 on its face (`r <= a`),
/// unreachable outside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatPunch {
    radius: f64,
}

impl FlatPunch {
    /// A punch of `radius` (m).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `radius` is not positive and finite.
    pub fn new(radius: f64) -> Result<Self> {
        Ok(FlatPunch {
            radius: positive_finite("radius", radius)?,
        })
    }

    /// The punch radius `a`, m.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

impl Indenter for FlatPunch {
    fn height(&self, x: f64, y: f64) -> f64 {
        if x.hypot(y) <= self.radius {
            0.0
        } else {
            f64::INFINITY
        }
    }

    fn bounding_radius(&self) -> f64 {
        self.radius
    }
}

/// A rigid sphere of radius `R`, the exact spherical cap
/// `f = R - sqrt(R^2 - r^2)` (unreachable beyond its equator).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    radius: f64,
}

impl Sphere {
    /// A sphere of `radius` (m).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `radius` is not positive and finite.
    pub fn new(radius: f64) -> Result<Self> {
        Ok(Sphere {
            radius: positive_finite("radius", radius)?,
        })
    }
}

impl Indenter for Sphere {
    fn height(&self, x: f64, y: f64) -> f64 {
        let r = x.hypot(y);
        let big = self.radius;
        if r <= big {
            // R - sqrt(R^2 - r^2) = r^2 / (R + sqrt(R^2 - r^2)), without cancellation.
            r * r / (big + ((big - r) * (big + r)).sqrt())
        } else {
            f64::INFINITY
        }
    }

    fn bounding_radius(&self) -> f64 {
        self.radius
    }
}

/// A paraboloid `f = r^2 / (2R)`, Hertz's approximation of a sphere of
/// radius `R`. Unbounded; its bounding radius is `R`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Paraboloid {
    radius: f64,
}

impl Paraboloid {
    /// A paraboloid of tip radius `radius` (m).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `radius` is not positive and finite.
    pub fn new(radius: f64) -> Result<Self> {
        Ok(Paraboloid {
            radius: positive_finite("radius", radius)?,
        })
    }
}

impl Indenter for Paraboloid {
    fn height(&self, x: f64, y: f64) -> f64 {
        (x * x + y * y) / (2.0 * self.radius)
    }

    fn bounding_radius(&self) -> f64 {
        self.radius
    }
}

/// A cone of half-angle `theta` (axis to face), `f = r cot(theta)`, cut off
/// at a base radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cone {
    slope: f64,
    base_radius: f64,
}

impl Cone {
    /// A cone of `half_angle` (radians, in `(0, pi/2)`) with a base of
    /// `base_radius` (m), beyond which it cannot touch.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an angle outside `(0, pi/2)` or a
    /// base radius that is not positive and finite.
    pub fn new(half_angle: f64, base_radius: f64) -> Result<Self> {
        if !(half_angle > 0.0 && half_angle < std::f64::consts::FRAC_PI_2) {
            return Err(Error::InvalidParameter {
                name: "half_angle",
                value: half_angle,
                expected: "in (0, pi/2) radians",
            });
        }
        let slope = 1.0 / half_angle.tan();
        if !slope.is_finite() {
            return Err(Error::InvalidParameter {
                name: "half_angle",
                value: half_angle,
                expected: "large enough that the face's slope 1/tan(angle) is finite",
            });
        }
        Ok(Cone {
            slope,
            base_radius: positive_finite("base_radius", base_radius)?,
        })
    }
}

impl Indenter for Cone {
    fn height(&self, x: f64, y: f64) -> f64 {
        let r = x.hypot(y);
        if r == 0.0 {
            0.0
        } else if r <= self.base_radius {
            r * self.slope
        } else {
            f64::INFINITY
        }
    }

    fn bounding_radius(&self) -> f64 {
        self.base_radius
    }
}
