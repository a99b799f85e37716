//! Rigid indenters: the shapes pressed into the body.
//!
//! An indenter is a rigid surface given by its height `f(x, y)` above its
//! lowest point (on its axis, at `x = y = 0`), measured towards the body's
//! outside. At depth `d` the gap between the indenter and the deformed
//! surface is `g = f - d + u_z` (see [`doc::conventions`](crate::doc::conventions)). A point the
//! indenter can never reach (outside a punch's face, beyond a sphere's
//! equator) has height `+inf`.
//!
//! Implement [`Indenter`] for your own shape and every solver accepts it.
//!
//! ```
//! use layered_contact::indenter::{FlatPunch, Indenter, Sphere, Tilted};
//!
//! let punch = FlatPunch::new(1e-3)?;
//! assert_eq!(punch.height(0.5e-3, 0.0), 0.0);
//! assert_eq!(punch.height(2e-3, 0.0), f64::INFINITY);
//! let ball = Sphere::new(0.05)?;
//! assert!((ball.height(1e-3, 0.0) - (0.05 - (0.05f64.powi(2) - 1e-6).sqrt())).abs() < 1e-18);
//! // A punch tilted by 1 mrad about the y axis touches first at x = -a.
//! let tilted = Tilted::new(punch, 1e-3, 0.0)?;
//! assert!(tilted.height(-1e-3, 0.0) < tilted.height(1e-3, 0.0));
//! Ok::<(), layered_contact::Error>(())
//! ```

mod height_map;
mod shapes;
pub(crate) mod tilt;

pub use height_map::HeightMap;
pub use shapes::{Cone, FlatPunch, Paraboloid, Sphere};
pub use tilt::Tilted;

/// A rigid indenter, described by its height profile.
pub trait Indenter {
    /// The height `f(x, y)` (m) of the indenter's surface at `(x, y)` (m,
    /// from its axis), above its lowest point; `+inf` where it cannot touch.
    /// Must not be NaN.
    fn height(&self, x: f64, y: f64) -> f64;

    /// The radius (m) of a disc about the axis outside which the indenter
    /// cannot touch at the depths of interest: used to size grids. For
    /// unbounded shapes (paraboloid, cone) it is the radius the caller gave.
    fn bounding_radius(&self) -> f64;
}

impl<T: Indenter + ?Sized> Indenter for Box<T> {
    fn height(&self, x: f64, y: f64) -> f64 {
        (**self).height(x, y)
    }

    fn bounding_radius(&self) -> f64 {
        (**self).bounding_radius()
    }
}

impl<T: Indenter + ?Sized> Indenter for &T {
    fn height(&self, x: f64, y: f64) -> f64 {
        (**self).height(x, y)
    }

    fn bounding_radius(&self) -> f64 {
        (**self).bounding_radius()
    }
}
