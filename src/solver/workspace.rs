//! The solver's scratch vectors, one value per cell, and how a coarser
//! solve of a multi-resolution start borrows them.

use crate::error::Result;

/// Scratch vectors, one value per cell (empty when released).
#[derive(Default)]
pub(super) struct Workspace {
    pub(super) profile: Vec<f64>,
    pub(super) displacement: Vec<f64>,
    pub(super) gap: Vec<f64>,
    pub(super) direction: Vec<f64>,
    pub(super) response: Vec<f64>,
    pub(super) previous: Vec<f64>,
    /// Prescribed displacements of a clamped solve (allocated on first
    /// use).
    pub(super) target: Vec<f64>,
    /// Cells of the working set (in contact or overlapping).
    pub(super) working: Vec<bool>,
}

/// `vector` holding `n` values: shortened, or lengthened with zeros within
/// its capacity, or else allocated anew.
pub(super) fn fit<T: Clone + Default>(vector: &mut Vec<T>, n: usize) -> Result<()> {
    if vector.len() > n || vector.capacity() >= n {
        vector.resize(n, T::default());
    } else {
        *vector = Vec::new();
        *vector = crate::error::zeroed(n, "a solver's per-cell vectors")?;
    }
    Ok(())
}

impl Workspace {
    pub(super) fn new(n: usize) -> Result<Self> {
        let mut workspace = Workspace::default();
        workspace.fit(n)?;
        Ok(workspace)
    }

    /// Sizes every vector (but the clamped solve's target) for `n` cells,
    /// reusing what each holds: a workspace lent to a coarser solve and
    /// given back allocates nothing.
    pub(super) fn fit(&mut self, n: usize) -> Result<()> {
        for vector in [
            &mut self.profile,
            &mut self.displacement,
            &mut self.gap,
            &mut self.direction,
            &mut self.response,
            &mut self.previous,
        ] {
            fit(vector, n)?;
        }
        fit(&mut self.working, n)
    }

    /// The vectors a coarser solve may use while this one waits for its
    /// start: all but the profile (already sampled) and the target. They
    /// come back with [`Workspace::restore`]; their values are scratch.
    pub(super) fn lend(&mut self) -> Workspace {
        Workspace {
            profile: Vec::new(),
            displacement: std::mem::take(&mut self.displacement),
            gap: std::mem::take(&mut self.gap),
            direction: std::mem::take(&mut self.direction),
            response: std::mem::take(&mut self.response),
            previous: std::mem::take(&mut self.previous),
            target: Vec::new(),
            working: std::mem::take(&mut self.working),
        }
    }

    /// Takes the lent vectors of `lent` (but its profile and target) in
    /// place of this workspace's own.
    pub(super) fn restore(&mut self, lent: &mut Workspace) {
        let taken = lent.lend();
        self.displacement = taken.displacement;
        self.gap = taken.gap;
        self.direction = taken.direction;
        self.response = taken.response;
        self.previous = taken.previous;
        self.working = taken.working;
    }
}
