//! Which cells of a cohesive zone with hysteresis hold with the receding
//! work: the cells in contact at an equilibrium, and, when the indenter is
//! withdrawn from one, the advancing zone's open cells around its contact.

use super::cohesive_area::open_zone;
use super::polonsky_keer::Control;
use super::WarmStart;

/// The relative margin by which a depth or force must fall below the warm
/// start's to count as a withdrawal (the warm start's own depth, read back
/// from its gaps, carries rounding of about `1e-16` of the profile).
const WITHDRAWAL_MARGIN: f64 = 1e-9;

/// The open cells of the advancing zone that a reversal bonds: those whose
/// gap is at most this fraction of the advancing law's range.
///
/// Measured, not derived ([`bonded_from`] has the reasons): the sphere of
/// 0.1 m on a 1 kPa half-space with works 0.146 and 1.122 J/m^2 (its edge
/// pinned from the peak to the pull-off; the cohesive reference sweep's
/// seed 29), pull-off error and the largest error of the unloading branch
/// (its first eight steps against the energy balance's curve at the same
/// depths on 64 cells, within 0.05 % of the exact pull-off, over the
/// pull-off force) at 16 / 32 / 64 cells across (`BENCHMARKS.md`, "A
/// pinned edge under hysteresis"):
///
/// | fraction | pull-off | branch |
/// |---|---|---|
/// | 0 (the closed cells alone, before) | -23.6 / -11.6 / -4.3 % | 28.7 / 19.5 / 11.4 % |
/// | 0.5 | -11.4 / -4.5 / -1.6 % | 13.2 / 6.8 / 3.6 % |
/// | 0.6 | -8.4 / -3.7 / -1.4 % | 9.8 / 5.0 / 3.3 % |
/// | 0.7 | -6.9 / -3.0 / -1.1 % | 9.2 / 6.5 / 4.1 % |
/// | 0.85 | -5.9 / -2.3 / -0.6 % | 11.7 / 8.0 / 5.5 % |
/// | 1 (the whole zone) | -5.4 / -1.3 / -0.4 % | 13.1 / 11.1 / 7.2 % |
///
/// At 128 cells (a zone of 5.7 cells) 0.6 gives -0.78 % and 2.5 %, the
/// closed cells alone -2.85 % and 9.6 %.
pub(super) const BOND_GAP_FRACTION: f64 = 0.6;

/// The cells bonded before a solve from `warm` under `control`, and
/// whether the solve's own equilibrium counts as withdrawn
/// (`WarmStart::withdrawn`): `warm`'s bonded cells and, at a reversal (a
/// withdrawal, a smaller depth or force, from an equilibrium that was not
/// itself withdrawn), the open cells of its zone joined to its contact
/// ([`open_zone`]) whose gap is at most [`BOND_GAP_FRACTION`] of the
/// advancing law's `range` (m). `profile` and `displacement` are the warm
/// start's (the displacement `K p` of its pressures); `area` is a cell's
/// (m^2).
///
/// Why: in the JKR limit a contact edge whose receding work exceeds the
/// advancing one is pinned where loading left it (the edge held until the
/// energy release rate reaches the receding work: Johnson, Kendall &
/// Roberts 1971, Proc. R. Soc. A 324, 301, with hysteresis as in Maugis
/// 2000, *Contact, Adhesion and Rupture of Elastic Solids*, ch. 5;
/// [`LayeredJkrCycle`](crate::analytic::LayeredJkrCycle)), and the
/// cohesive zone's equivalent crack lies
/// [`EQUIVALENT_TIP`](super::EQUIVALENT_TIP) of a zone beyond its closed
/// cells. Bonding only the closed cells pinned the unloading's zone inside
/// them: its equivalent crack receded most of a zone from the peak's as
/// soon as the unloading began, the branch too weak and the pull-off short
/// by about the zone's length. Bonding the whole advancing zone puts the
/// receding zone's outer end where the advancing zone's was (the pull-off
/// right to first order), but its cells, a fraction of the receding law's
/// range open, pull with nearly its peak and close: the contact grows as
/// the unloading begins and the branch is too strong. The cells up to
/// [`BOND_GAP_FRACTION`] of the advancing range balance the two. Only at a
/// reversal: bonding the zone at every loading step let the receding work
/// pull the advancing edge on (the peak force 84 % short on that sphere
/// with the whole zone), and at every unloading step the cells the last
/// one closed could bond the next ring out.
pub(super) fn bonded_from(
    warm: &WarmStart,
    control: Control,
    depth: f64,
    (profile, displacement): (&[f64], &[f64]),
    area: f64,
    (cells, periodic): ((usize, usize), bool),
    range: f64,
) -> (Vec<bool>, bool) {
    let mut bonded = warm.attached.clone();
    let contact = warm.contact.as_deref().unwrap_or(&warm.attached);
    let Some(before) = warm_depth(contact, (profile, displacement), control, depth) else {
        return (bonded, false);
    };
    let direction = direction(warm, control, depth, before, area);
    if direction != Direction::Withdraws || warm.withdrawn {
        let withdrawn = warm.withdrawn && direction != Direction::Advances;
        return (bonded, withdrawn);
    }
    let tension: Vec<f64> = warm.pressure.iter().map(|&p| p.min(0.0)).collect();
    let open = open_zone(contact, &tension, cells, periodic);
    for (c, b) in bonded.iter_mut().enumerate() {
        let gap = profile[c] - before + displacement[c];
        if open[c] && gap <= BOND_GAP_FRACTION * range {
            *b = true;
        }
    }
    (bonded, true)
}

/// The depth of `warm`'s equilibrium: under depth control read from its
/// closed cells (`profile + K p` there), under force control `depth` (the
/// fixed point's first depth is the warm start's). `None` without a closed
/// cell.
fn warm_depth(
    contact: &[bool],
    (profile, displacement): (&[f64], &[f64]),
    control: Control,
    depth: f64,
) -> Option<f64> {
    match control {
        Control::Depth(_) => {
            let (sum, count) = contact
                .iter()
                .zip(profile.iter().zip(displacement))
                .filter(|(&closed, _)| closed)
                .fold((0.0, 0usize), |(s, k), (_, (h, u))| (s + h + u, k + 1));
            (count > 0).then(|| sum / count as f64)
        }
        Control::Force(_) => contact.iter().any(|&c| c).then_some(depth),
    }
}

/// Whether a cell follows the receding law in a round: `bonded` in it, and
/// either bonded `before` the solve (at the warm start's equilibrium, or by
/// a reversal) or the solve `withdrawn` (`bonded_from`'s flag). A cell
/// that closes during a solve that is not withdrawn (loading, holding)
/// carries at most the advancing law's peak until an equilibrium bonds it:
/// its tension is the advancing edge's, which the advancing work governs
/// (Johnson, Kendall & Roberts 1971; the loading branch of
/// [`LayeredJkrCycle`](crate::analytic::LayeredJkrCycle)). The receding
/// peak on the cells a loading closed pulled the contact on past the
/// advancing work's: a sphere of 0.1 m on a 1 kPa layer 0.14 m thick over
/// a base 2000 times softer, works 0.177 and 1.122 J/m^2 (the cohesive
/// reference sweep's seed 56), came to its peak with a contact radius
/// +8.8 / +8.5 / +10.2 % too wide at 16 / 32 / 64 cells across, not
/// converging; now +2.3 / +1.6 / +0.6 % (`BENCHMARKS.md`, "The loading
/// branch under hysteresis"). A cell bonded before keeps the receding law
/// closed and open alike: capping it at the advancing peak while closed and
/// pulling it with the receding law once open made the rounds of a rough
/// film's force step cycle (a cell closing and opening in turn) to the
/// round limit.
pub(super) fn recedes(bonded: bool, before: bool, withdrawn: bool) -> bool {
    bonded && (withdrawn || before)
}

/// Which way a solve moves the indenter from its warm start.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Direction {
    Withdraws,
    Holds,
    Advances,
}

/// Which way `control` moves the indenter from `warm`'s equilibrium at
/// depth `before` (m): under depth control by its depth, under force
/// control by its force against `warm`'s total (`area` a cell's, m^2),
/// either beyond [`WITHDRAWAL_MARGIN`] of the warm start's.
fn direction(warm: &WarmStart, control: Control, depth: f64, before: f64, area: f64) -> Direction {
    let (now, then) = match control {
        Control::Depth(_) => (depth, before),
        Control::Force(force) => (force, warm.pressure.iter().sum::<f64>() * area),
    };
    let margin = WITHDRAWAL_MARGIN * then.abs();
    if now < then - margin {
        Direction::Withdraws
    } else if now > then + margin {
        Direction::Advances
    } else {
        Direction::Holds
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A warm start on a row of five cells: the middle one closed at the
    /// depth `1e-6` (its `profile + K p`), the others open at gaps 0.5,
    /// 0.2 (left of it), 0.7 and 0.1 (right) of a range of `1e-7` m, all
    /// in tension but the last, which carries none.
    fn row() -> (WarmStart, Vec<f64>, Vec<f64>) {
        let depth = 1e-6;
        let gaps = [0.5e-7, 0.2e-7, 0.0, 0.7e-7, 0.1e-7];
        let warm = WarmStart {
            pressure: vec![-1.0, -2.0, 10.0, -0.5, 0.0],
            attached: vec![false, false, true, false, false],
            contact: Some(vec![false, false, true, false, false]),
            withdrawn: false,
        };
        let displacement = vec![1e-7; 5];
        let profile = gaps.iter().map(|g| g + depth - 1e-7).collect();
        (warm, profile, displacement)
    }

    fn bonded(warm: &WarmStart, control: Control, depth: f64) -> (Vec<bool>, bool) {
        let (_, profile, displacement) = row();
        let dims = ((1, 5), false);
        bonded_from(
            warm,
            control,
            depth,
            (&profile, &displacement),
            1.0,
            dims,
            1e-7,
        )
    }

    #[test]
    fn a_reversal_bonds_the_zone_within_the_fraction_of_the_range() {
        let (warm, _, _) = row();
        // Withdrawn by 1 nm: the cells at 0.2 and 0.5 of the range join
        // (0.6 bounds them), the one at 0.7 does not, nor the cell with no
        // tension.
        let (cells, withdrawn) = bonded(&warm, Control::Depth(0.999e-6), 0.999e-6);
        assert_eq!(cells, [true, true, true, false, false]);
        assert!(withdrawn);
        // Under force control: a force below the warm start's 6.5 N.
        let (cells, withdrawn) = bonded(&warm, Control::Force(6.0), 1e-6);
        assert_eq!(cells, [true, true, true, false, false]);
        assert!(withdrawn);
    }

    #[test]
    fn a_newly_closed_cell_recedes_only_once_withdrawn() {
        // (bonded now, bonded before, withdrawn) -> receding law.
        assert!(!recedes(true, false, false));
        assert!(recedes(true, false, true));
        assert!(recedes(true, true, false));
        assert!(recedes(true, true, true));
        assert!(!recedes(false, false, true));
        assert!(!recedes(false, true, true));
    }

    #[test]
    fn advancing_holding_and_a_second_withdrawal_bond_nothing_new() {
        let (mut warm, _, _) = row();
        let closed = vec![false, false, true, false, false];
        // Deeper, or at the warm start's own depth or force (to within its
        // margin): nothing new, and not withdrawn.
        for (control, depth) in [
            (Control::Depth(1.001e-6), 1.001e-6),
            (Control::Depth(1e-6 * (1.0 - 1e-12)), 1e-6 * (1.0 - 1e-12)),
            (Control::Force(7.0), 1e-6),
            (Control::Force(6.5), 1e-6),
        ] {
            assert_eq!(bonded(&warm, control, depth), (closed.clone(), false));
        }
        // From a withdrawn equilibrium a withdrawal bonds nothing new and
        // stays withdrawn; holding stays withdrawn; advancing does not.
        warm.withdrawn = true;
        assert_eq!(
            bonded(&warm, Control::Depth(0.9e-6), 0.9e-6),
            (closed.clone(), true)
        );
        assert_eq!(
            bonded(&warm, Control::Force(6.5), 1e-6),
            (closed.clone(), true)
        );
        assert_eq!(bonded(&warm, Control::Force(7.0), 1e-6), (closed, false));
    }
}
