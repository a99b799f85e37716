//! One contact on a grid split across the processes of an MPI run (the
//! `mpi` feature, which needs a system MPI library such as Open MPI or
//! MPICH, and `libclang` to build its bindings).
//!
//! [`ContactSolver::distributed`] builds the same solver as
//! [`ContactSolver::new`] with each rank holding a band of the grid's rows
//! (a slab) of every per-cell vector and its share of the kernel's
//! spectrum. The FFT convolution transforms each rank's rows, exchanges
//! the half-spectra once each way with `MPI_Alltoallv` (a slab-decomposed
//! 2D FFT, as in FFTW-MPI), and filters each rank's columns; every sum of
//! the constrained conjugate gradients is added over the ranks with
//! `MPI_Allreduce`. The multi-resolution start and the box preconditioner
//! run split the same way (the bands line up on every coarser grid). So a
//! run on any number of ranks takes the same steps as the serial solver,
//! and its results agree with it to the rounding of the sums' order.
//!
//! Only the non-adhesive solves ([`ContactSolver::solve_depth`],
//! [`ContactSolver::solve_force`]) run split; the adhesive methods return
//! [`Error::Unsupported`]. A [`Solution`](crate::solver::Solution)'s
//! scalars (force, area, moments, contact cells) are the whole grid's on
//! every rank; its fields and warm starts are the rank's own rows,
//! [`ContactSolver::local_rows`].
//!
//! ```no_run
//! use layered_contact::distributed::Ranks;
//! use layered_contact::indenter::Sphere;
//! use layered_contact::solver::{ContactSolver, SolverParams};
//! use layered_contact::{Boundary, Grid, Material, Substrate};
//!
//! let (universe, _) = mpi::initialize_with_threading(mpi::Threading::Serialized).unwrap();
//! let ranks = Ranks::new(universe.world())?;
//! let body = Substrate::half_space(Material::new(1e6, 0.5)?);
//! let grid = Grid::new(1024, 1024, 1e-6)?;
//! let mut solver =
//!     ContactSolver::distributed(&body, &grid, Boundary::Isolated, SolverParams::default(), &ranks)?;
//! let (solution, _) = solver.solve_depth(&Sphere::new(1e-2)?, 1e-5, None, &mut ())?;
//! if ranks.rank() == 0 {
//!     println!("F = {} N", solution.force);
//! }
//! Ok::<(), layered_contact::Error>(())
//! ```

use std::sync::{Arc, Mutex};

use mpi::collective::SystemOperation;
use mpi::datatype::{Partition, PartitionMut};
use mpi::topology::SimpleCommunicator;
use mpi::traits::{Communicator, CommunicatorCollectives};
use num_complex::Complex;

use crate::error::{Error, Result};
use crate::grid::{Boundary, Grid};
use crate::slab::{Exchange, Slab};
use crate::solver::{ContactSolver, SolverParams};
use crate::substrate::Substrate;

/// The processes of an MPI communicator that share one grid.
#[derive(Clone)]
pub struct Ranks {
    exchange: Arc<MpiExchange>,
}

impl std::fmt::Debug for Ranks {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Ranks")
            .field("rank", &self.rank())
            .field("count", &self.count())
            .finish()
    }
}

impl Ranks {
    /// The ranks of `communicator` (usually `universe.world()`).
    ///
    /// # Errors
    /// [`Error::Unsupported`] if MPI was initialised with less than
    /// `MPI_THREAD_SERIALIZED` support: the solver calls MPI from the thread
    /// that solves, which need not be the one that initialised MPI
    /// (initialise with `mpi::initialize_with_threading(mpi::Threading::Serialized)`).
    pub fn new(communicator: SimpleCommunicator) -> Result<Self> {
        use mpi::Threading;
        if matches!(
            mpi::environment::threading_support(),
            Threading::Single | Threading::Funneled
        ) {
            return Err(Error::Unsupported {
                feature: "MPI initialised without MPI_THREAD_SERIALIZED",
                reason: "the solver may call MPI from any one thread at a time: initialise \
                         with mpi::initialize_with_threading(mpi::Threading::Serialized)",
            });
        }
        let rank = usize::try_from(communicator.rank()).unwrap_or(0);
        let ranks = usize::try_from(communicator.size()).unwrap_or(1).max(1);
        Ok(Ranks {
            exchange: Arc::new(MpiExchange {
                communicator: Mutex::new(Handle(communicator)),
                rank,
                ranks,
            }),
        })
    }

    /// This process's rank, `0..count()`.
    pub fn rank(&self) -> usize {
        self.exchange.rank
    }

    /// The number of ranks.
    pub fn count(&self) -> usize {
        self.exchange.ranks
    }

    /// The sum over the ranks of each of `values` (every rank must call it
    /// with as many values): for totals of quantities a caller adds up from
    /// each rank's rows.
    pub fn sum(&self, values: &mut [f64]) {
        self.exchange.sum(values);
    }
}

impl ContactSolver {
    /// A solver for `substrate` on `grid` split across `ranks`: every rank
    /// calls this and then every solve, with the same arguments. See the
    /// [module](self).
    ///
    /// # Errors
    /// As [`ContactSolver::new`] (on every rank if on any), and
    /// [`Error::InvalidParameter`] if there are more ranks than bands of
    /// `2^L` rows (`L` the multi-resolution levels: 16 rows on a 1024-row
    /// grid).
    pub fn distributed(
        substrate: &Substrate,
        grid: &Grid,
        boundary: Boundary,
        params: SolverParams,
        ranks: &Ranks,
    ) -> Result<Self> {
        let exchange: Arc<dyn Exchange> = ranks.exchange.clone();
        let slab = Slab::for_grid(exchange, grid)?;
        ContactSolver::on_slab(substrate, grid, boundary, params, &slab)
    }
}

/// A communicator's handle. `SimpleCommunicator` is not `Send` because
/// its handle is a C pointer; MPI initialised with
/// `MPI_THREAD_SERIALIZED` (checked by [`Ranks::new`]) lets any thread use
/// it while calls do not overlap, which the mutex around it ensures.
struct Handle(SimpleCommunicator);

// SAFETY: see `Handle`: every use goes through `MpiExchange`'s mutex, and
// `Ranks::new` refuses an MPI initialised without serialized threading.
unsafe impl Send for Handle {}

/// The collectives of an MPI communicator.
struct MpiExchange {
    communicator: Mutex<Handle>,
    rank: usize,
    ranks: usize,
}

impl MpiExchange {
    fn with<R>(&self, f: impl FnOnce(&SimpleCommunicator) -> R) -> R {
        // A poisoned lock only means another thread panicked while it held
        // the handle; the handle itself is unchanged.
        let handle = self
            .communicator
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        f(&handle.0)
    }

    fn reduce(&self, values: &mut [f64], operation: SystemOperation) {
        let send = values.to_vec();
        self.with(|c| c.all_reduce_into(&send[..], values, operation));
    }
}

/// MPI counts and offsets of `counts` values (each below `2^31`: the
/// largest exchange, a rank's half-spectra of 32768 x 32768 cells on two
/// ranks, is 5.4e8 values).
fn mpi_counts(counts: &[usize]) -> (Vec<mpi::Count>, Vec<mpi::Count>) {
    let count = |n: usize| mpi::Count::try_from(n).unwrap_or(mpi::Count::MAX);
    let mut offset = 0;
    let offsets = counts
        .iter()
        .map(|n| {
            let at = count(offset);
            offset += n;
            at
        })
        .collect();
    (counts.iter().map(|&n| count(n)).collect(), offsets)
}

impl Exchange for MpiExchange {
    fn rank(&self) -> usize {
        self.rank
    }

    fn ranks(&self) -> usize {
        self.ranks
    }

    fn sum(&self, values: &mut [f64]) {
        self.reduce(values, SystemOperation::sum());
    }

    fn min(&self, values: &mut [f64]) {
        self.reduce(values, SystemOperation::min());
    }

    fn all_to_all(
        &self,
        send: &[Complex<f64>],
        send_counts: &[usize],
        receive: &mut [Complex<f64>],
        receive_counts: &[usize],
    ) {
        let (counts, offsets) = mpi_counts(send_counts);
        let (receive_counts, receive_offsets) = mpi_counts(receive_counts);
        let send = Partition::new(send, counts, offsets);
        let mut receive = PartitionMut::new(receive, receive_counts, receive_offsets);
        self.with(|c| c.all_to_all_varcount_into(&send, &mut receive));
    }
}
