//! Stresses below the surface at a scene's most loaded step, when its
//! outputs ask for them ([`StressOutputs`]).

use crate::error::{Error, Result};
use crate::solver::Solution;
use crate::stress::{
    check_depth, default_padding, rigid_floor, InterfaceTractions, Side, StressPlane,
    SubsurfaceStress, VolumeMaximum, DEFAULT_PADDING,
};
use crate::substrate::Substrate;
use crate::{Boundary, Grid};

/// The most planes a scene may ask for.
pub const MAX_STRESS_PLANES: usize = 1000;

/// Which stresses a scene computes at its most loaded step (none by
/// default). Depths in metres below the surface.
///
/// ```toml
/// [outputs.stresses]
/// depths = [0.5e-6, 2e-6]              # planes at these depths
/// depth_grid = { to = 6e-6, planes = 25 } # and evenly from the surface
/// interfaces = true                      # the tractions on every interface
/// padding = 8                            # an isolated grid padded 8 times
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct StressOutputs {
    /// Planes at these depths, m.
    pub depths: Vec<f64>,
    /// Evenly spaced planes from the surface.
    pub depth_grid: Option<DepthGrid>,
    /// The tractions on every interface of a layered body.
    pub interfaces: bool,
    /// How many times an isolated grid is padded (default
    /// [`DEFAULT_PADDING`]; see [`SubsurfaceStress::with_padding`]).
    pub padding: Option<usize>,
}

/// `planes` evenly spaced planes from the surface to `to` (both included).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct DepthGrid {
    /// The deepest plane, m.
    pub to: f64,
    /// How many planes (at least 2).
    pub planes: usize,
}

impl StressOutputs {
    /// Whether anything is asked for.
    pub fn any(&self) -> bool {
        !self.depths.is_empty() || self.depth_grid.is_some() || self.interfaces
    }

    /// The depths of every plane asked for, sorted, without repeats.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a negative or non-finite depth, a
    /// depth grid of fewer than 2 planes, more than [`MAX_STRESS_PLANES`]
    /// planes, or a plane in or below a rigid base.
    pub fn plane_depths(&self, substrate: &Substrate) -> Result<Vec<f64>> {
        let mut depths = self.depths.clone();
        if let Some(grid) = self.depth_grid {
            crate::error::within(
                "outputs.stresses.depth_grid.planes",
                grid.planes as f64,
                (2.0, MAX_STRESS_PLANES as f64),
                "between 2 and 1000",
            )?;
            let step = grid.to / (grid.planes - 1) as f64;
            depths.extend((0..grid.planes).map(|k| k as f64 * step));
        }
        let floor = rigid_floor(substrate);
        for &depth in &depths {
            check_depth(depth, Side::Below, floor)?;
        }
        depths.sort_by(f64::total_cmp);
        depths.dedup();
        if depths.len() > MAX_STRESS_PLANES {
            return Err(Error::InvalidParameter {
                name: "number of stress planes",
                value: depths.len() as f64,
                expected: "at most 1000",
            });
        }
        Ok(depths)
    }
}

/// The stresses of a scene's most loaded step.
#[derive(Debug, Clone, PartialEq)]
pub struct SubsurfaceResult {
    /// The planes asked for, shallowest first (at an interface's depth, the
    /// layer below).
    pub planes: Vec<StressPlane>,
    /// The tractions on each interface, top down (empty unless asked for).
    pub interfaces: Vec<InterfaceTractions>,
    /// The largest von Mises stress over the planes.
    pub von_mises: Option<VolumeMaximum>,
    /// The largest shear stress (Tresca) over the planes.
    pub max_shear: Option<VolumeMaximum>,
    /// The largest principal stress (the most tensile) over the planes.
    pub tension: Option<VolumeMaximum>,
    /// The depths of the layers' bottoms (the interfaces and the base's
    /// top), m, top down; empty for a half-space.
    pub boundaries: Vec<f64>,
}

impl SubsurfaceResult {
    /// The result of `planes` and `interfaces` in a body whose layers end
    /// at `boundaries`, with the maxima over the planes.
    pub fn new(
        planes: Vec<StressPlane>,
        interfaces: Vec<InterfaceTractions>,
        boundaries: Vec<f64>,
    ) -> Self {
        SubsurfaceResult {
            von_mises: VolumeMaximum::over(&planes, |s| s.von_mises()),
            max_shear: VolumeMaximum::over(&planes, |s| s.max_shear()),
            tension: VolumeMaximum::over(&planes, |s| s.principal()[0]),
            planes,
            interfaces,
            boundaries,
        }
    }
}

/// Computes the stresses `outputs` asks for under the pressure of `peak`.
pub(super) fn compute(
    outputs: &StressOutputs,
    substrate: &Substrate,
    grid: &Grid,
    boundary: Boundary,
    peak: &Solution,
) -> Result<SubsurfaceResult> {
    let depths = outputs.plane_depths(substrate)?;
    let pressure = peak.pressure.as_ref().ok_or(Error::Internal {
        what: "scene stresses",
        detail: "the peak kept no pressure".into(),
    })?;
    let pressure: Vec<f64> = pressure.iter().copied().collect();
    let padding = match boundary {
        Boundary::Isolated => outputs.padding.unwrap_or(DEFAULT_PADDING),
        // A periodic grid is never padded (a padding asked for is ignored).
        Boundary::Periodic => default_padding(boundary),
    };
    let mut stress = SubsurfaceStress::with_padding(substrate, grid, boundary, padding)?;
    let planes = stress.planes(&pressure, &depths, Side::Below)?;
    let interfaces = if outputs.interfaces {
        stress.interfaces(&pressure)?
    } else {
        Vec::new()
    };
    Ok(SubsurfaceResult::new(
        planes,
        interfaces,
        stress.interface_depths(),
    ))
}
