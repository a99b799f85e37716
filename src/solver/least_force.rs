//! The least force of an unloading within a bracket of three equilibria:
//! golden-section search (Kiefer 1953, Proc. Am. Math. Soc. 4, 502), which
//! holds for a force that turns smoothly and for one that jumps where the
//! contact is lost, then the vertex of the parabola through the least force
//! and its neighbours (exact to third order in the bracket where the force
//! is smooth). Each new equilibrium is reached from the nearest solved one
//! above it, as the quasi-static unloading reaches it, so that the history
//! (which cells are bonded) is the unloading's.

/// One equilibrium of the search: its depth (m), force (N) and whatever
/// the caller keeps of it (its state, its solution).
pub(crate) struct Probe<S> {
    pub(crate) depth: f64,
    pub(crate) force: f64,
    pub(crate) kept: S,
}

/// The bracket a search narrows to, as a fraction of an unloading step
/// (scenes and [`ContactSolver::cohesive_pull_off`](super::ContactSolver::cohesive_pull_off)).
pub(crate) const STEP_FRACTION: f64 = 1.0 / 16.0;

/// Equilibria solved by one search at most.
pub(crate) const MAX_PROBES: usize = 24;

/// The golden section's smaller part, `(3 - sqrt 5) / 2`.
const GOLDEN: f64 = 0.381_966_011_250_105_1;

/// Searches the least force of `bracket` (three probes at falling depths,
/// the middle one of least force) until the bracket around the least force
/// is at most `width` (m) wide, then solves the parabola's vertex through
/// the least force and its neighbours if it lies inside. `solve(depth,
/// from)` gives the equilibrium at `depth` reached from the probe `from`
/// above it. Returns every probe, the three given first, by falling depth;
/// at most [`MAX_PROBES`] solves.
pub(crate) fn least_force<S, E>(
    bracket: [Probe<S>; 3],
    width: f64,
    mut solve: impl FnMut(f64, &Probe<S>) -> Result<Probe<S>, E>,
) -> Result<Vec<Probe<S>>, E> {
    let mut probes: Vec<Probe<S>> = bracket.into_iter().collect();
    for k in 0..MAX_PROBES {
        // The least force and its neighbours (the ends never hold it: the
        // middle of the bracket was below both, and forces only fall).
        let m = (1..probes.len() - 1)
            .min_by(|&a, &b| probes[a].force.total_cmp(&probes[b].force))
            .unwrap_or(1);
        let (d0, d1, d2) = (probes[m - 1].depth, probes[m].depth, probes[m + 1].depth);
        let depth = if d0 - d2 > width {
            // A golden section of the larger side.
            if d0 - d1 > d1 - d2 {
                d1 + GOLDEN * (d0 - d1)
            } else {
                d1 - GOLDEN * (d1 - d2)
            }
        } else {
            let (f0, f1, f2) = (probes[m - 1].force, probes[m].force, probes[m + 1].force);
            let p = (d1 - d0) * (d1 - d0) * (f1 - f2) - (d1 - d2) * (d1 - d2) * (f1 - f0);
            let q = (d1 - d0) * (f1 - f2) - (d1 - d2) * (f1 - f0);
            let vertex = d1 - 0.5 * p / q;
            let apart = 1e-3 * (d0 - d2);
            let inside = vertex < d0 - apart && vertex > d2 + apart;
            if !(inside && (vertex - d1).abs() > apart) || k + 1 == MAX_PROBES {
                break;
            }
            vertex
        };
        // From the nearest probe above.
        let place = probes.partition_point(|p| p.depth > depth);
        let probe = solve(depth, &probes[place - 1])?;
        probes.insert(place, probe);
        if d0 - d2 <= width {
            break;
        }
    }
    Ok(probes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quartic with its minimum at 0.3, and a cusp (a contact lost at the
    /// least force): the search finds each minimum to the width, the
    /// smooth one in a few solves, and keeps the probes in order.
    #[test]
    fn finds_the_least_value_of_a_smooth_and_of_a_cusped_curve() {
        let smooth = |x: f64| (x - 0.3).powi(2) + 0.5 * (x - 0.3).powi(4) - 1.0;
        let cusp = |x: f64| if x > 0.7 { x - 1.0 } else { 0.0 };
        for (f, at, width, most) in [
            (smooth as fn(f64) -> f64, 0.3, 1e-3, 16),
            (cusp as fn(f64) -> f64, 0.7, 1e-2, 12),
        ] {
            let probe = |x: f64| Probe {
                depth: x,
                force: f(x),
                kept: (),
            };
            let mut solves = 0;
            let probes = least_force([probe(1.0), probe(0.75), probe(0.0)], width, |x, from| {
                assert!(from.depth > x);
                solves += 1;
                Ok::<_, ()>(probe(x))
            })
            .unwrap();
            let best = probes
                .iter()
                .min_by(|a, b| a.force.total_cmp(&b.force))
                .unwrap();
            assert!((best.depth - at).abs() < width, "{} {at}", best.depth);
            assert!(probes.windows(2).all(|w| w[0].depth > w[1].depth));
            assert!(solves <= most, "{solves}");
        }
    }
}
