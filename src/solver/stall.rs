//! When the constrained conjugate gradients of
//! [`polonsky_keer`](super::polonsky_keer) give up keeping their
//! conjugation across new overlap.
//!
//! The solver keeps the conjugation where a new cell overlaps (a projected
//! Fletcher-Reeves step) instead of restarting it as Polonsky and Keer do
//! (1999, Wear 231, 206-219): on rough contacts, whose working set grows
//! in most early iterations, restarting keeps the iteration near steepest
//! descent. But the kept conjugation can cycle: a cell at the contact's
//! edge leaves the set and overlaps again, the directions carry the old
//! set, and the change per iteration wanders about a level instead of
//! falling. A flat punch on a layer 2800 times stiffer than its base
//! (`E` = 42 MPa, 0.13 mm thick, under a punch of 1.9 mm radius, 16
//! cells across, the cohesive zone's first solve at zero depth) wandered
//! between `1e-4` and `2e-3` for 10000 iterations, one cell at the rim
//! flickering in and out of the set. Once the change has gone
//! [`STALL_ITERATIONS`] iterations without a new least value, the solve
//! restarts its conjugation at every new overlap for the rest of the way
//! (Polonsky and Keer's own rule, which converges there in about 80 more
//! iterations).

/// Iterations without a new least change of the pressure after which a
/// solve restarts its conjugation wherever a new cell overlaps. Far above
/// what a converging solve spends without a new least change (its change
/// falls at a steady rate: 0.35 to 0.77 an iteration on rough contacts up
/// to 4096^2, BENCHMARKS.md "Speed: rough contacts on large grids"), so
/// that only a cycling solve is touched.
pub(super) const STALL_ITERATIONS: usize = 50;

/// The least change so far and the iterations since it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Stall {
    least: f64,
    since: usize,
    stalled: bool,
}

impl Stall {
    /// A solve not yet begun.
    pub(super) fn new() -> Self {
        Stall {
            least: f64::INFINITY,
            since: 0,
            stalled: false,
        }
    }

    /// Records an iteration's relative change of the pressure.
    pub(super) fn record(&mut self, change: f64) {
        if change < self.least {
            self.least = change;
            self.since = 0;
        } else {
            self.since += 1;
            self.stalled |= self.since >= STALL_ITERATIONS;
        }
    }

    /// Whether the solve restarts its conjugation at new overlap: once it
    /// has stalled, for the rest of the solve.
    pub(super) fn restarts_on_overlap(&self) -> bool {
        self.stalled
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_falling_change_never_stalls_and_a_wandering_one_does_for_good() {
        let mut stall = Stall::new();
        // A steady rate of 0.9 for 300 iterations: a new least each time.
        for i in 0..300 {
            stall.record(0.9f64.powi(i));
        }
        assert!(!stall.restarts_on_overlap());
        // Then a wander above the least: stalled at exactly the 50th.
        for i in 0..STALL_ITERATIONS {
            assert!(!stall.restarts_on_overlap(), "stalled after {i}");
            stall.record(1.0);
        }
        assert!(stall.restarts_on_overlap());
        // A new least does not undo it.
        stall.record(0.0);
        assert!(stall.restarts_on_overlap());
    }
}
