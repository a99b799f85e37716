//! The passes against direct computations.

use super::*;

/// A seeded pseudo-random value in `[-1, 1)` (a linear congruential
/// generator; the solver's tests share it).
pub(in crate::solver) fn next(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// The gap pass's working set against a cell-by-cell count: members, the
/// gaps' sum (in the same order: equal to the last bit), their largest
/// absolute value, new overlap, the overlapping cells' count, sum and
/// least gap, those apart from the contact, and the bounding rows and
/// columns, on a grid of short rows and on one whose rows are longer than
/// a chunk (rows cut across chunks), with patchy contact and unreachable
/// cells. Then the overlap apart from the contact shallower than the mean
/// left out (as a fine solve does: some overlapping cells stay out, some
/// shallower ones beside the contact join), and the same with those beside
/// it (as while the contact shrinks): the members cell by cell, the
/// sum as the chunks' sums less the cells left out in order (to the last
/// bit; within `n eps sum |g|` of a direct sum), the bounds and largest
/// gap kept.
#[test]
fn the_working_set_is_counted_cell_by_cell() {
    for (rows, columns, seed) in [(61, 37, 1), (3, CHUNK + 4321, 2), (5, 8, 3)] {
        let n = rows * columns;
        let mut state = seed;
        let profile: Vec<f64> = (0..n).map(|_| next(&mut state)).collect();
        let displacement: Vec<f64> = (0..n).map(|_| 0.1 * next(&mut state)).collect();
        let pressure: Vec<f64> = (0..n)
            .map(|_| next(&mut state).max(0.0) * f64::from(next(&mut state) > 0.5))
            .collect();
        let reachable: Vec<bool> = (0..n).map(|_| next(&mut state) > -0.9).collect();
        // Few members: the bounds are inside the grid.
        let reference = -0.8;
        let (mut gap, mut working) = (vec![f64::NAN; n], vec![false; n]);
        let run = |gap: &mut [f64], working: &mut [bool]| {
            gaps_and_working_set(
                &profile,
                &displacement,
                &pressure,
                &reachable,
                reference,
                columns,
                gap,
                working,
            )
        };
        let set = run(&mut gap, &mut working).set();
        let mut expected = WorkingSet::default();
        let mut bounds: Option<Bounds> = None;
        // Chunk by chunk, as the pass adds its sums.
        let (mut chunk_sum, mut chunk_overlap) = (0.0, 0.0);
        let g = |c: usize| {
            if reachable[c] {
                profile[c] - reference + displacement[c]
            } else {
                0.0
            }
        };
        let overlaps = |c: usize| reachable[c] && pressure[c] == 0.0 && g(c) < 0.0;
        let beside = |c: usize| {
            let j = c % columns;
            (j > 0 && pressure[c - 1] > 0.0) || (j + 1 < columns && pressure[c + 1] > 0.0)
        };
        // A member of the pass's set: in contact or overlapping.
        let joins = |c: usize| reachable[c] && (pressure[c] > 0.0 || g(c) < 0.0);
        for c in 0..n {
            assert_eq!(gap[c], g(c));
            let member = joins(c);
            assert_eq!(working[c], member);
            if c % CHUNK == 0 {
                expected.gap_sum += chunk_sum;
                expected.overlap_sum += chunk_overlap;
                (chunk_sum, chunk_overlap) = (0.0, 0.0);
            }
            if overlaps(c) {
                expected.overlap_cells += 1;
                expected.apart_cells += usize::from(!beside(c));
                chunk_overlap += g(c);
                expected.deepest = expected.deepest.min(g(c));
            }
            if member {
                expected.members += 1;
                chunk_sum += g(c);
                expected.gap_max = expected.gap_max.max(g(c).abs());
                expected.overlap |= pressure[c] == 0.0;
                let (i, j) = (c / columns, c % columns);
                bounds = union(bounds, Some(((i, i), (j, j))));
            }
        }
        expected.gap_sum += chunk_sum;
        expected.overlap_sum += chunk_overlap;
        assert!(expected.members > 0 && expected.members < n / 2);
        assert!(expected.apart_cells > 0 && expected.apart_cells < expected.overlap_cells);
        assert_eq!(set.overlap_cells, expected.overlap_cells);
        assert_eq!(set.apart_cells, expected.apart_cells);
        assert_eq!(set.overlap_sum, expected.overlap_sum);
        assert_eq!(set.deepest, expected.deepest);
        assert_eq!(set.members, expected.members);
        assert_eq!(set.gap_sum, expected.gap_sum);
        assert_eq!(set.gap_max, expected.gap_max);
        assert_eq!(set.overlap, expected.overlap);
        assert_eq!(set.bounds, bounds);

        // The overlap shallower than the mean left out: apart from the
        // contact, and then beside it too (as while the contact shrinks).
        let join_at = set.overlap_sum / set.overlap_cells as f64;
        for beside_too in [false, true] {
            let pass = run(&mut gap, &mut working);
            let stays_out = |c: usize, beside: bool| (beside_too || !beside) && g(c) > join_at;
            let left = pass.leave_out(&gap, &mut working, stays_out);
            let leaves = |c: usize| overlaps(c) && (beside_too || !beside(c)) && g(c) > join_at;
            let (mut members, mut direct, mut magnitude) = (0, 0.0, 0.0);
            let (mut left_out, mut shallow_beside) = (0, 0);
            for c in 0..n {
                let member = joins(c) && !leaves(c);
                assert_eq!(working[c], member, "cell {c}");
                left_out += usize::from(leaves(c));
                shallow_beside += usize::from(member && overlaps(c) && g(c) > join_at);
                members += usize::from(member);
                direct += if member { g(c) } else { 0.0 };
                magnitude += g(c).abs();
            }
            // The order of the subtraction: a chunk's sum, then the cells
            // left out one by one.
            let mut in_order = 0.0;
            for k in 0..n.div_ceil(CHUNK) {
                let cells = k * CHUNK..((k + 1) * CHUNK).min(n);
                let mut part: f64 = 0.0;
                for c in cells.clone().filter(|&c| joins(c)) {
                    part += g(c);
                }
                for c in cells.filter(|&c| leaves(c)) {
                    part -= g(c);
                }
                in_order += part;
            }
            // Shallow overlap beside the contact stays on the larger grids
            // unless it leaves too (the 5 x 8 grid has one cell left out
            // and none beside the contact shallower than the mean).
            assert!(left_out > 0, "{left_out}");
            assert_eq!(
                shallow_beside > 0,
                n > 100 && !beside_too,
                "{shallow_beside}"
            );
            assert_eq!(left.members, members);
            assert_eq!(left.members + left_out, set.members);
            assert_eq!(left.gap_sum, in_order);
            assert!((left.gap_sum - direct).abs() <= n as f64 * f64::EPSILON * magnitude);
            assert_eq!(left.gap_max, set.gap_max);
            assert_eq!(left.bounds, set.bounds);
        }
    }
}
