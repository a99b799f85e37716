//! Force control through the cohesive zone of [`cohesive`](super::cohesive):
//! the same fixed point, each inner solve under force control (the
//! compressive part carries the force less the tensions' pull), so that one
//! fixed point reaches a prescribed force where a depth search takes
//! several. Scenes' force protocols take each step this way first
//! (`scene::runner::cohesive_force`).

use crate::error::{Error, Result};
use crate::indenter::Indenter;

use super::cohesive::MAX_ROUNDS;
use super::polonsky_keer::Control;
use super::{check_finite, CohesiveZone, ContactSolver, Observer, Solution, WarmStart};

impl ContactSolver {
    /// Adhesive contact carrying `force` (N, negative pulls) through the
    /// cohesive zone ([`CohesiveZone`]), from `from`: an equilibrium's
    /// state and its depth (m; the [`Solution::depth`] of the solve that
    /// returned the state). The fixed point of
    /// [`ContactSolver::solve_depth_cohesive`] with each inner solve under
    /// force control (the compressive part carries `force` less the
    /// tensions' pull), the depth found with the contact; the state's
    /// bonded cells carry the history, as for the depth-controlled solve.
    /// Beyond the least force the contact can hold (the load-controlled
    /// pull-off) there is no equilibrium: the rounds walk the contact off
    /// and the solve returns an error, never a number.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a non-finite force or depth;
    /// [`Error::NoConvergence`] where the fixed point does not converge
    /// (beyond the least force, or a force inside a snap of the path where
    /// a cell joins or leaves the zone) or the tensions alone pull more than
    /// `force` with no contact left to carry the rest; as
    /// [`ContactSolver::solve_depth_cohesive`] otherwise.
    ///
    /// # Example
    /// ```
    /// use layered_contact::analytic::JkrSphere;
    /// use layered_contact::indenter::Sphere;
    /// use layered_contact::solver::{CohesiveZone, ContactSolver, SolverParams};
    /// use layered_contact::{Boundary, Grid, Material, Substrate};
    ///
    /// let rubber = Material::new(1e6, 0.48)?;
    /// let jkr = JkrSphere::new(&rubber, 1e-2, 0.05)?;
    /// let a = jkr.pull_off_contact_radius();
    /// let grid = Grid::square_of_side(48, 4.0 * a)?;
    /// let body = Substrate::half_space(rubber);
    /// let mut solver =
    ///     ContactSolver::new(&body, &grid, Boundary::Isolated, SolverParams::default())?;
    /// let (sphere, zone) = (Sphere::new(1e-2)?, CohesiveZone::new(0.05, 0.05)?);
    /// let depth = jkr.depth(1.5 * a);
    /// let (_, state) = solver.solve_depth_cohesive(&sphere, depth, &zone, None, &mut ())?;
    /// // Pulled with JKR's force at 1.2 pull-off radii.
    /// let force = jkr.force(1.2 * a);
    /// let (pulled, _) =
    ///     solver.solve_force_cohesive(&sphere, force, &zone, (&state, depth), &mut ())?;
    /// assert!((pulled.force / force - 1.0).abs() < 1e-12);
    /// assert!((pulled.depth - jkr.depth(1.2 * a)).abs() < 0.05 * jkr.critical_depth().abs());
    /// # Ok::<(), layered_contact::Error>(())
    /// ```
    pub fn solve_force_cohesive<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        force: f64,
        zone: &CohesiveZone,
        from: (&WarmStart, f64),
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        let limits = (MAX_ROUNDS, &mut 0);
        self.solve_force_cohesive_within(indenter, force, zone, from, limits, observer)
    }

    /// [`ContactSolver::solve_force_cohesive`] in at most `rounds`
    /// fixed-point rounds (scenes' force steps, which search the depth
    /// where these do not suffice), adding the CG iterations spent to
    /// `spent` whether it converges or not.
    pub(crate) fn solve_force_cohesive_within<I: Indenter + ?Sized>(
        &mut self,
        indenter: &I,
        force: f64,
        zone: &CohesiveZone,
        (warm, from_depth): (&WarmStart, f64),
        (rounds, spent): (usize, &mut usize),
        observer: &mut dyn Observer,
    ) -> Result<(Solution, WarmStart)> {
        check_finite("force", force)?;
        check_finite("depth", from_depth)?;
        let control = Control::Force(force);
        let limits = (rounds.min(MAX_ROUNDS), spent);
        let (depth, warm) = (from_depth, Some(warm));
        self.cohesive_fixed_point(indenter, control, depth, zone, warm, limits, observer)
    }
}

/// Under force control, scales the compressive pressures so that they
/// carry `force` less the pull of the tensions (both times the cell's
/// `area`) after `rounds` rounds, and returns the inner solves' control
/// (that load); an error where the tensions pull more than the force asks
/// (no contact can carry the rest: beyond the least force, the contact
/// walks off). Under depth control, `control` itself.
pub(super) fn carry(
    control: Control,
    area: f64,
    tension: &[f64],
    (compressive, rounds): (&mut [f64], usize),
) -> Result<Control> {
    let Control::Force(force) = control else {
        return Ok(control);
    };
    let target = force - area * tension.iter().sum::<f64>();
    let carried = area * compressive.iter().sum::<f64>();
    if target.is_nan() || target <= 0.0 {
        return Err(Error::NoConvergence {
            method: "cohesive zone under force control (the tensions alone pulled more than \
                     the force asked, leaving no contact: beyond the least force?)",
            iterations: rounds,
            residual: target / force.abs().max(f64::MIN_POSITIVE),
        });
    }
    if carried > 0.0 {
        let factor = target / carried;
        compressive.iter_mut().for_each(|p| *p *= factor);
    }
    Ok(Control::Force(target))
}

#[cfg(test)]
mod tests {
    use crate::solver::cohesive::tests::jkr_sphere_at_one_and_a_half_radii;
    use crate::Error;

    /// The JKR sphere (12 cells across the pull-off contact radius): from
    /// the equilibrium at 1.5 pull-off radii, the force of JKR's contact of
    /// 1.2 radii is reached by one fixed point under force control. It
    /// carries the force asked to rounding, at JKR's depth to the zone's
    /// error, and is a fixed point of the depth-controlled map at the depth
    /// it found. A pull beyond the least force the contact holds (JKR's
    /// load-controlled pull-off, here 1.2 times it) has no equilibrium: an
    /// error, not a number.
    #[test]
    fn one_fixed_point_under_force_control_reaches_the_depth_controlled_equilibrium() {
        let (jkr, mut solver, sphere, zone, warm) = jkr_sphere_at_one_and_a_half_radii();
        let a = jkr.pull_off_contact_radius();
        let start = jkr.depth(1.5 * a);
        let force = jkr.force(1.2 * a);
        let mut spent = 0;
        let (at, end) = solver
            .solve_force_cohesive_within(
                &sphere,
                force,
                &zone,
                (&warm, start),
                (200, &mut spent),
                &mut (),
            )
            .unwrap();
        assert_eq!(spent, at.iterations);
        assert!(
            (at.force / force - 1.0).abs() < 1e-12,
            "{} {force}",
            at.force
        );
        // Shallower than the start, within the zone's error of JKR's depth.
        let error = (at.depth - jkr.depth(1.2 * a)) / jkr.critical_depth().abs();
        assert!(at.depth < start && error.abs() < 0.05, "{error}");
        // From its own state the depth-controlled fixed point stays (1e-9:
        // measured 2.0e-11); from the path's start it lands on the same
        // contact, an equilibrium of the lattice 7.2e-6 of the force away
        // (a zone cell held a little differently: the snaps of up to 4e-4
        // in `scene::runner::cohesive_force`).
        let (same, _) = solver
            .solve_depth_cohesive(&sphere, at.depth, &zone, Some(&end), &mut ())
            .unwrap();
        let off = (same.force - at.force).abs() / force.abs();
        assert!(off < 1e-9, "{off:e}");
        let (again, _) = solver
            .solve_depth_cohesive(&sphere, at.depth, &zone, Some(&warm), &mut ())
            .unwrap();
        let off = (again.force - at.force).abs() / force.abs();
        assert!(off < 1e-4, "{off:e}");
        assert_eq!(again.contact_cells, at.contact_cells);
        // Beyond the least force: the contact walks off (in 9 rounds).
        let beyond = 1.2 * jkr.pull_off_force();
        let pulled = solver.solve_force_cohesive(&sphere, beyond, &zone, (&warm, start), &mut ());
        assert!(
            matches!(pulled, Err(Error::NoConvergence { .. })),
            "{pulled:?}"
        );
    }
}
