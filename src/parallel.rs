//! Row-wise passes over row-major grids, on all threads with the `parallel`
//! feature. Each row is handled by the same code whatever the number of
//! threads, and per-row results come back in row order, so sums folded from
//! them do not depend on it.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// `f(row index, row)` on every row of `width` values of `data`.
pub(crate) fn for_each_row<T: Send>(
    data: &mut [T],
    width: usize,
    f: impl Fn(usize, &mut [T]) + Sync + Send,
) {
    let width = width.max(1);
    #[cfg(feature = "parallel")]
    data.par_chunks_mut(width)
        .enumerate()
        .for_each(|(i, row)| f(i, row));
    #[cfg(not(feature = "parallel"))]
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
    {
        data.par_chunks_mut(width)
            .enumerate()
            .map(|(i, row)| f(i, row))
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        data.chunks_mut(width)
            .enumerate()
            .map(|(i, row)| f(i, row))
            .collect()
    }
}
