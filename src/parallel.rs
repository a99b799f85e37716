//! Row-wise passes over row-major grids, on all threads with the `parallel`
//! feature. Each row is handled by the same code whatever the number of
//! threads, and per-row results come back in row order, so sums folded from
//! them do not depend on it.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Below this many values a pass runs on the calling thread: forking to the
/// pool costs more than it saves, and on small grids solved thousands of
/// times (a 100 000-step cycle on 16 cells) the idle workers' spinning cost
/// twice the solves in system time.
#[cfg(feature = "parallel")]
const MIN_PARALLEL_VALUES: usize = 1 << 14;

/// `f(row index, row)` on every row of `width` values of `data`.
pub(crate) fn for_each_row<T: Send>(
    data: &mut [T],
    width: usize,
    f: impl Fn(usize, &mut [T]) + Sync + Send,
) {
    let width = width.max(1);
    #[cfg(feature = "parallel")]
    if data.len() >= MIN_PARALLEL_VALUES {
        data.par_chunks_mut(width)
            .enumerate()
            .for_each(|(i, row)| f(i, row));
        return;
    }
    data.chunks_mut(width)
        .enumerate()
        .for_each(|(i, row)| f(i, row));
}

/// `f(row index, row)` on every row of `width` values of `data`; the
/// results in row order.
pub(crate) fn map_rows<T: Send, R: Send>(
    data: &mut [T],
    width: usize,
    f: impl Fn(usize, &mut [T]) -> R + Sync + Send,
) -> Vec<R> {
    let width = width.max(1);
    #[cfg(feature = "parallel")]
    if data.len() >= MIN_PARALLEL_VALUES {
        return data
            .par_chunks_mut(width)
            .enumerate()
            .map(|(i, row)| f(i, row))
            .collect();
    }
    data.chunks_mut(width)
        .enumerate()
        .map(|(i, row)| f(i, row))
        .collect()
}

/// As [`for_each_row`], with scratch made by `init` once per piece of work
/// a thread takes (not once per row) and passed to `f`.
pub(crate) fn for_each_row_with<T: Send, S>(
    data: &mut [T],
    width: usize,
    init: impl Fn() -> S + Sync + Send,
    f: impl Fn(&mut S, usize, &mut [T]) + Sync + Send,
) {
    let width = width.max(1);
    #[cfg(feature = "parallel")]
    if data.len() >= MIN_PARALLEL_VALUES {
        data.par_chunks_mut(width)
            .enumerate()
            .for_each_init(&init, |scratch, (i, row)| f(scratch, i, row));
        return;
    }
    let mut scratch = init();
    data.chunks_mut(width)
        .enumerate()
        .for_each(|(i, row)| f(&mut scratch, i, row));
}

/// `f(row index)` for `rows` rows of `width` values each (read-only work:
/// the closure reads what it needs); the results in row order.
pub(crate) fn map_row_indices<R: Send>(
    rows: usize,
    width: usize,
    f: impl Fn(usize) -> R + Sync + Send,
) -> Vec<R> {
    #[cfg(feature = "parallel")]
    if rows.saturating_mul(width) >= MIN_PARALLEL_VALUES {
        return (0..rows).into_par_iter().map(f).collect();
    }
    let _ = width;
    (0..rows).map(f).collect()
}
