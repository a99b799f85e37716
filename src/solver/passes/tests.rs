//! The passes against direct computations.

use super::*;

/// A seeded pseudo-random value in `[-1, 1)` (a linear congruential
/// generator).
fn next(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// The gap pass's working set against a cell-by-cell count: members, the
/// gaps' sum (in the same order: equal to the last bit), their largest
/// absolute value, new overlap and the bounding rows and columns, on a
/// grid of short rows and on one whose rows are longer than a chunk (rows
/// cut across chunks), with patchy contact and unreachable cells.
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
        let set = gaps_and_working_set(
            &profile,
            &displacement,
            &pressure,
            &reachable,
            reference,
            columns,
            &mut gap,
            &mut working,
        );
        let mut expected = WorkingSet::default();
        let mut bounds: Option<Bounds> = None;
        // Chunk by chunk, as the pass adds its sums.
        let mut chunk_sum = 0.0;
        for c in 0..n {
            let g = if reachable[c] {
                profile[c] - reference + displacement[c]
            } else {
                0.0
            };
            assert_eq!(gap[c], g);
            let member = reachable[c] && (pressure[c] > 0.0 || g < 0.0);
            assert_eq!(working[c], member);
            if c % CHUNK == 0 {
                expected.gap_sum += chunk_sum;
                chunk_sum = 0.0;
            }
            if member {
                expected.members += 1;
                chunk_sum += g;
                expected.gap_max = expected.gap_max.max(g.abs());
                expected.overlap |= pressure[c] == 0.0;
                let (i, j) = (c / columns, c % columns);
                bounds = union(bounds, Some(((i, i), (j, j))));
            }
        }
        expected.gap_sum += chunk_sum;
        assert!(expected.members > 0 && expected.members < n / 2);
        assert_eq!(set.members, expected.members);
        assert_eq!(set.gap_sum, expected.gap_sum);
        assert_eq!(set.gap_max, expected.gap_max);
        assert_eq!(set.overlap, expected.overlap);
        assert_eq!(set.bounds, bounds);
    }
}
