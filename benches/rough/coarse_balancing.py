"""Does the two-level balancing preconditioner keep its iterations when its
coarse matrix comes from a coarse grid instead of one convolution per
aggregate? Asked of the numpy model of `projected_cg.py` (issue 27), with
the coarse space of `two_level.py`: the working set's cells in each `b x b`
block. The exact coarse matrix `E_IJ = sum_{i in I, j in J} K_ij` (over the
set's cells) costs one convolution per block; the cheap one, buildable in
the solver at about one coarse convolution an iteration, is

    E~_IJ = n_I n_J Kb(I - J) / b^4      (far blocks)

with `n_I` the set's cells in block `I` and `Kb` the compliance between
two whole blocks (one convolution of one block, once per grid), the blocks
within `near` of each other (Chebyshev distance in blocks, the block itself
at 0) summed exactly over their cells' pairs from the cells' kernel (a
correlation of the two blocks' occupancies: about `(2b)^2` products a cell
for each near offset).

Balancing (Mandel 1993, Commun. Numer. Meth. Eng. 9, 233): `Q + (I - Q A)
B (I - A Q)`, `Q = Z E~^-1 Z^T`, symmetric positive definite for any
symmetric positive definite `E~`; two more applications of `A` an
iteration than the box `B` alone.

As the crate starts (`--crate`): the box with one sweep of the edge
extension (`edge_extension.laplace(1, ...)`) in both, and a start from the
problem on the grid twice coarser (the heights averaged over 2 x 2 cells,
solved to `1e-3`, its pressures repeated on the fine cells).

With `--from K` (as the crate, 2026-12-06): the box alone for the first
K - 1 iterations, balancing from the K-th, the conjugation restarted there.

Usage: python coarse_balancing.py B N [N ...] [--crate [--from K]]
(numpy, scipy, layered_contact)
"""

import sys

import numpy as np

from edge_extension import laplace
from projected_cg import operator, pressure_space, spectra, surface
from two_level import Restricted, blocks, pcg


def cell_kernel(n):
    """The compliance's response at every cell to a unit pressure on cell
    (0, 0) (periodic)."""
    _, compliance = spectra(n)
    delta = np.zeros((n, n))
    delta[0, 0] = 1.0
    return operator(compliance)(delta)


def block_kernel(n, b):
    """`Kb(I - J)`: the compliance summed over the pairs of two whole
    blocks, on the (n/b)^2 grid of block offsets."""
    _, compliance = spectra(n)
    one = np.zeros((n, n))
    one[:b, :b] = 1.0
    u = operator(compliance)(one)
    nb = n // b
    return u.reshape(nb, b, nb, b).sum(axis=(1, 3))


def near_sums(member, kernel, b, offset):
    """For every block `I`, `sum_{i in I, j in I + offset} K_ij` over the
    member cells, by correlating the two blocks' occupancies on a `2b`
    (or `4b` for an offset block) window of the cells' kernel."""
    n = member.shape[0]
    nb = n // b
    oi, oj = offset
    occ = member.reshape(nb, b, nb, b).transpose(0, 2, 1, 3).astype(float)
    other = np.roll(occ, (-oi, -oj), axis=(0, 1))
    size = 4 * b
    fa = np.fft.rfft2(occ, s=(size, size))
    fb = np.fft.rfft2(other, s=(size, size))
    # corr[d] = sum_x a(x) b(x + d): the pairs at cell offset d + offset * b.
    corr = np.fft.irfft2(np.conj(fa) * fb, s=(size, size))
    d = np.fft.fftfreq(size, 1.0 / size).astype(int)
    di, dj = np.meshgrid(d + oi * b, d + oj * b, indexing="ij")
    window = kernel[di % n, dj % n]
    return np.einsum("ijxy,xy->ij", np.rint(corr), window)


def cheap_coarse(member, b, near, kernel, kb):
    """The cheap coarse matrix over the blocks that hold member cells, and
    their labels (as `two_level.blocks`)."""
    n = member.shape[0]
    nb = n // b
    counts = member.reshape(nb, b, nb, b).sum(axis=(1, 3)).astype(float)
    used = np.flatnonzero(counts.ravel() > 0)
    bi, bj = np.unravel_index(used, (nb, nb))
    di = (bi[:, None] - bi[None, :]) % nb
    dj = (bj[:, None] - bj[None, :]) % nb
    c = counts.ravel()[used]
    E = np.outer(c, c) * kb[di, dj] / b**4
    position = {int(k): m for m, k in enumerate(used)}
    for oi in range(-near, near + 1):
        for oj in range(-near, near + 1):
            sums = near_sums(member, kernel, b, (oi, oj))
            for m, k in enumerate(used):
                i, j = divmod(int(k), nb)
                other = position.get(((i + oi) % nb) * nb + (j + oj) % nb)
                if other is not None:
                    E[m, other] = sums[i, j]
    return 0.5 * (E + E.T)


def cheap_ops(member, b, near, kernel, kb):
    """`two_level.Restricted` with the cheap coarse matrix."""
    ops = Restricted(member, blocks(member, b), exact=False)
    ops.E_inv = np.linalg.inv(cheap_coarse(member, b, near, kernel, kb))
    return ops


def linear(n, b, kernel, kb):
    """PCG iterations on the converged contact set's linear system."""
    h = surface(n)
    p, _ = pressure_space(h, 1e-10)
    member = p > 0
    rhs = -h[member]
    rhs -= rhs.mean()
    exact = Restricted(member, blocks(member, b)) if n <= 256 else None
    diagonal = cheap_ops(member, b, 0, kernel, kb)
    row = [pcg(diagonal.A, diagonal.B, rhs)]
    row.append(pcg(exact.A, exact.balancing, rhs) if exact else "-")
    for ops in (diagonal, cheap_ops(member, b, 1, kernel, kb)):
        row.append(pcg(ops.A, ops.balancing, rhs))
    return int(member.sum()), row


def coarse_start(h):
    """Pressures from the problem on the grid twice coarser (heights
    averaged over 2 x 2 cells, solved to 1e-3), repeated on the fine cells."""
    n = h.shape[0]
    coarse = h.reshape(n // 2, 2, n // 2, 2).mean(axis=(1, 3))
    p, _ = pressure_space(coarse, 1e-3)
    return np.repeat(np.repeat(p, 2, axis=0), 2, axis=1)


def crate_problem(n):
    """The surface on n x n cells, its start from the grid twice coarser
    and the box with one sweep of the edge extension, as the crate starts
    and preconditions (also `active_set_outer.py`, `longer_steps.py`)."""
    stiffness, _ = spectra(n)
    h = surface(n)
    return h, coarse_start(h), laplace(1, 1.0, operator(stiffness))


def crate_like(b, sizes, first=1):
    """The box with the edge extension from a coarse start, alone and
    inside balancing (from the `first` iteration on, the box before)."""
    print(f"blocks of {b}; the edge extension (one sweep) and a start from the grid twice "
          "coarser, as the crate")
    print("| N | constrained: box + extension | balancing, cheap E~ (neighbours exact) |")
    print("|---|---|---|")
    for n in sizes:
        kernel, kb = cell_kernel(n), block_kernel(n, b)
        h, start, extended = crate_problem(n)
        _, plain = pressure_space(h, 1e-8, precondition=extended, start=start)

        calls = [0]

        def balanced(W, r):
            calls[0] += 1
            if calls[0] < first:
                return extended(W, r)
            ops = cheap_ops(W, b, 1, kernel, kb)
            ops.B = lambda v: extended(W, ops.embed(v))[W]
            return ops.embed(ops.balancing(r[W]))

        _, two = pressure_space(h, 1e-8, precondition=balanced, start=start, restart_at=first)
        print(f"| {n} | {plain} | {two} |", flush=True)


def main(b, sizes):
    print(f"blocks of {b}: linear PCG on the converged set (1e-8); constrained CG, cold (1e-8)")
    print("| N | contact cells | B | balancing, exact E | E~ diagonal exact | E~ near exact "
          "| constrained: B | balancing, E~ near exact |")
    print("|---|---|---|---|---|---|---|---|")
    for n in sizes:
        kernel, kb = cell_kernel(n), block_kernel(n, b)
        cells, row = linear(n, b, kernel, kb)
        h = surface(n)
        _, plain = pressure_space(h, 1e-8)
        _, two = pressure_space(
            h, 1e-8,
            precondition=lambda W, r: (lambda o: o.embed(o.balancing(r[W])))(
                cheap_ops(W, b, 1, kernel, kb)))
        print(f"| {n} | {cells} | {' | '.join(map(str, row))} | {plain} | {two} |", flush=True)


if __name__ == "__main__":
    args = sys.argv[1:]
    first = 1
    if "--from" in args:
        k = args.index("--from")
        first = int(args[k + 1])
        del args[k:k + 2]
        if "--crate" not in args:
            raise SystemExit("--from K needs --crate")
    sizes = [int(a) for a in args[1:] if not a.startswith("--")] or [128, 256]
    if "--crate" in args:
        crate_like(int(args[0]), sizes, first)
    else:
        main(int(args[0]), sizes)
