//! The split of a grid's rows across the processes of a distributed run
//! (the `mpi` feature), and the few collective operations the solver needs.
//!
//! Each process ("rank") holds a contiguous band of rows, a slab, of every
//! per-cell vector; the FFT convolution exchanges its half-spectra once
//! each way (a transpose, [`Exchange::all_to_all`]) and every sum over the
//! grid is added over the ranks ([`Exchange::sum`]). A serial solver has no
//! [`Slab`] and never calls these.

use std::ops::Range;
use std::sync::Arc;

use num_complex::Complex;

use crate::error::{Error, Result};

/// The collective operations of a distributed run, over all its ranks.
/// Every rank must call them in the same order with matching sizes.
pub(crate) trait Exchange: Send + Sync {
    /// This process's rank, `0..ranks()`.
    fn rank(&self) -> usize;
    /// The number of ranks.
    fn ranks(&self) -> usize;
    /// Replaces each value by its sum over the ranks.
    fn sum(&self, values: &mut [f64]);
    /// Replaces each value by its smallest value over the ranks.
    fn min(&self, values: &mut [f64]);
    /// Sends `send_counts[k]` consecutive values of `send` (in rank order)
    /// to rank `k` and receives `receive_counts[k]` from rank `k` into
    /// consecutive places of `receive` (in rank order).
    fn all_to_all(
        &self,
        send: &[Complex<f64>],
        send_counts: &[usize],
        receive: &mut [Complex<f64>],
        receive_counts: &[usize],
    );
}

/// A grid's rows split across the ranks of an [`Exchange`].
#[derive(Clone)]
pub(crate) struct Slab {
    pub(crate) exchange: Arc<dyn Exchange>,
    /// Rank `k` holds rows `starts[k]..starts[k + 1]`.
    pub(crate) starts: Vec<usize>,
}

impl std::fmt::Debug for Slab {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Slab")
            .field("rank", &self.exchange.rank())
            .field("starts", &self.starts)
            .finish()
    }
}

impl Slab {
    /// `rows` split into bands whose first rows are multiples of `align`
    /// (so that the grids of half, a quarter, ... the rows split along the
    /// same lines), as even as that allows.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if a rank would hold no row.
    pub(crate) fn new(exchange: Arc<dyn Exchange>, rows: usize, align: usize) -> Result<Self> {
        let ranks = exchange.ranks().max(1);
        let align = align.max(1);
        let units = rows.div_ceil(align);
        if units < ranks {
            return Err(Error::InvalidParameter {
                name: "ranks of the distributed run",
                value: ranks as f64,
                expected: "at most one per band of rows the multi-resolution grids share \
                           (rows / 2^levels): use fewer ranks or a larger grid",
            });
        }
        let starts = (0..=ranks)
            .map(|k| ((k * units / ranks) * align).min(rows))
            .collect();
        Ok(Slab { exchange, starts })
    }

    /// The split of `grid`'s rows for a solver: each rank's first row a
    /// multiple of `2^L`, `L` the number of multi-resolution levels below
    /// it, so that the bands line up on every coarser grid.
    pub(crate) fn for_grid(exchange: Arc<dyn Exchange>, grid: &crate::grid::Grid) -> Result<Self> {
        let mut levels = 0u32;
        let (mut rows, mut columns) = (grid.rows(), grid.columns());
        while rows.min(columns) >= crate::solver::MULTIRESOLUTION_CELLS {
            (rows, columns) = (rows.div_ceil(2), columns.div_ceil(2));
            levels += 1;
        }
        Self::new(exchange, grid.rows(), 1 << levels)
    }

    /// The same split on the grid of half the rows (rounded up).
    pub(crate) fn halved(&self, rows: usize) -> Self {
        let half = rows.div_ceil(2);
        Slab {
            exchange: Arc::clone(&self.exchange),
            starts: self
                .starts
                .iter()
                .map(|s| s.div_ceil(2).min(half))
                .collect(),
        }
    }

    /// This rank's rows.
    pub(crate) fn rows(&self) -> Range<usize> {
        let k = self.exchange.rank();
        self.starts[k]..self.starts[k + 1]
    }

    /// The rows of every rank, in rank order.
    pub(crate) fn counts(&self) -> Vec<usize> {
        lengths(&self.starts)
    }

    /// Sums `values` over the ranks.
    pub(crate) fn sum(&self, values: &mut [f64]) {
        self.exchange.sum(values);
    }

    /// `Ok` on every rank if every rank's `result` is `Ok`; else an error on
    /// every rank (its own, or one naming another rank's failure), so that
    /// no rank goes on to wait for one that has stopped.
    pub(crate) fn agree<T>(&self, result: Result<T>) -> Result<T> {
        let mut failed = [f64::from(u8::from(result.is_err()))];
        self.exchange.sum(&mut failed);
        match result {
            Err(e) => Err(e),
            Ok(_) if failed[0] > 0.0 => Err(Error::OtherRankFailed {
                failed: failed[0] as usize,
            }),
            ok => ok,
        }
    }
}

/// Splits `n` items into `parts` consecutive ranges as evenly as possible
/// (the first ones one longer): the starts and the end.
pub(crate) fn even_starts(n: usize, parts: usize) -> Vec<usize> {
    let parts = parts.max(1);
    (0..=parts).map(|k| k * n / parts).collect()
}

/// The lengths of the consecutive ranges that `starts` (the starts and the
/// end) delimit.
pub(crate) fn lengths(starts: &[usize]) -> Vec<usize> {
    starts.windows(2).map(|w| w[1] - w[0]).collect()
}

/// `result` when serial (`slab` is `None`); split, [`Slab::agree`].
pub(crate) fn agree<T>(slab: Option<&Slab>, result: Result<T>) -> Result<T> {
    match slab {
        Some(slab) => slab.agree(result),
        None => result,
    }
}

/// An [`Exchange`] between threads of one process, to test split code
/// without MPI: [`threads::run`] runs a closure on every rank.
#[cfg(test)]
pub(crate) mod threads {
    use std::sync::{Arc, Barrier, Mutex, PoisonError};

    use num_complex::Complex;

    use super::Exchange;

    /// A rank's send buffer of an all-to-all, and its counts per rank.
    type Posted = (Vec<Complex<f64>>, Vec<usize>);

    /// What each rank has posted for the collective under way.
    struct Board {
        barrier: Barrier,
        reals: Mutex<Vec<Vec<f64>>>,
        blocks: Mutex<Vec<Posted>>,
    }

    /// One rank.
    pub(crate) struct Threads {
        rank: usize,
        ranks: usize,
        board: Arc<Board>,
    }

    impl Threads {
        /// Every rank's values of one reduction, in rank order.
        fn gather(&self, values: &[f64]) -> Vec<Vec<f64>> {
            let lock = || {
                self.board
                    .reals
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
            };
            lock()[self.rank] = values.to_vec();
            self.board.barrier.wait();
            let all = lock().clone();
            self.board.barrier.wait();
            all
        }

        /// Each value folded over the ranks, in rank order, from `start`.
        fn reduce(&self, values: &mut [f64], start: f64, op: fn(f64, f64) -> f64) {
            let all = self.gather(values);
            for (k, v) in values.iter_mut().enumerate() {
                *v = all.iter().map(|r| r[k]).fold(start, op);
            }
        }
    }

    impl Exchange for Threads {
        fn rank(&self) -> usize {
            self.rank
        }
        fn ranks(&self) -> usize {
            self.ranks
        }
        fn sum(&self, values: &mut [f64]) {
            self.reduce(values, 0.0, |a, b| a + b);
        }
        fn min(&self, values: &mut [f64]) {
            self.reduce(values, f64::INFINITY, f64::min);
        }
        fn all_to_all(
            &self,
            send: &[Complex<f64>],
            send_counts: &[usize],
            receive: &mut [Complex<f64>],
            receive_counts: &[usize],
        ) {
            let lock = || {
                self.board
                    .blocks
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
            };
            lock()[self.rank] = (send.to_vec(), send_counts.to_vec());
            self.board.barrier.wait();
            {
                let blocks = lock();
                let mut at = 0;
                for (source, (values, counts)) in blocks.iter().enumerate() {
                    let from: usize = counts[..self.rank].iter().sum();
                    let n = receive_counts[source];
                    receive[at..at + n].copy_from_slice(&values[from..from + n]);
                    at += n;
                }
            }
            self.board.barrier.wait();
        }
    }

    /// `work(exchange)` on each of `ranks` threads, the results in rank
    /// order.
    pub(crate) fn run<T: Send>(
        ranks: usize,
        work: impl Fn(Arc<dyn Exchange>) -> T + Sync,
    ) -> Vec<T> {
        let board = Arc::new(Board {
            barrier: Barrier::new(ranks),
            reals: Mutex::new(vec![Vec::new(); ranks]),
            blocks: Mutex::new(vec![(Vec::new(), Vec::new()); ranks]),
        });
        std::thread::scope(|scope| {
            let handles: Vec<_> = (0..ranks)
                .map(|rank| {
                    let exchange: Arc<dyn Exchange> = Arc::new(Threads {
                        rank,
                        ranks,
                        board: Arc::clone(&board),
                    });
                    let work = &work;
                    scope.spawn(move || work(exchange))
                })
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("a rank's thread panicked"))
                .collect()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rank `rank` of `ranks`, summing nothing (the split alone is tested).
    struct Alone {
        rank: usize,
        ranks: usize,
    }

    impl Exchange for Alone {
        fn rank(&self) -> usize {
            self.rank
        }
        fn ranks(&self) -> usize {
            self.ranks
        }
        fn sum(&self, _: &mut [f64]) {}
        fn min(&self, _: &mut [f64]) {}
        fn all_to_all(&self, _: &[Complex<f64>], _: &[usize], _: &mut [Complex<f64>], _: &[usize]) {
        }
    }

    /// Rank 0 of 4, whose sums add the failures of the other ranks.
    struct Others {
        failed: f64,
    }

    impl Exchange for Others {
        fn rank(&self) -> usize {
            0
        }
        fn ranks(&self) -> usize {
            4
        }
        fn sum(&self, values: &mut [f64]) {
            values[0] += self.failed;
        }
        fn min(&self, _: &mut [f64]) {}
        fn all_to_all(&self, _: &[Complex<f64>], _: &[usize], _: &mut [Complex<f64>], _: &[usize]) {
        }
    }

    #[test]
    fn a_failure_on_any_rank_stops_every_rank() {
        let slab = |failed: f64| Slab::new(Arc::new(Others { failed }), 64, 1).unwrap();
        let own = || Error::Interrupted { what: "a test" };
        // Two other ranks failed: this one stops too, and says how many.
        match slab(2.0).agree(Ok(1)) {
            Err(Error::OtherRankFailed { failed }) => assert_eq!(failed, 2),
            other => panic!("expected OtherRankFailed, got {other:?}"),
        }
        // Its own error wins over the others'.
        assert!(matches!(
            slab(2.0).agree::<()>(Err(own())),
            Err(Error::Interrupted { .. })
        ));
        // Nobody failed.
        assert_eq!(slab(0.0).agree(Ok(1)).unwrap(), 1);
    }

    #[test]
    fn bands_line_up_on_every_coarser_grid() {
        let exchange = Arc::new(Alone { rank: 2, ranks: 4 });
        // 130 rows, one coarser level (align 2): 65 pairs of rows in four
        // bands of 16, 16, 16 and 17 pairs.
        let slab = Slab::new(exchange.clone(), 130, 2).unwrap();
        assert_eq!(slab.starts, vec![0, 32, 64, 96, 130]);
        assert_eq!(slab.rows(), 64..96);
        assert_eq!(slab.counts(), vec![32, 32, 32, 34]);
        let coarse = slab.halved(130);
        assert_eq!(coarse.starts, vec![0, 16, 32, 48, 65]);
        // 1024 rows, four levels (align 16): 64 bands of 16 rows at most.
        let slab = Slab::new(exchange.clone(), 1024, 16).unwrap();
        assert!(slab.starts.iter().all(|s| s % 16 == 0));
        assert!(Slab::new(Arc::new(Alone { rank: 0, ranks: 65 }), 1024, 16).is_err());
        assert_eq!(even_starts(10, 4), vec![0, 2, 5, 7, 10]);
    }
}
