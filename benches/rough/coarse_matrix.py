"""Does the balancing preconditioner of `two_level.py` keep its effect when
its coarse matrix `E = Z^T A Z` (the compliance between the contact cells
of `b x b` blocks) is not computed exactly (one convolution per block) but
from the coarse grid (issue 27)? Asked of the same numpy model:

- exact: `E` by one convolution per aggregate (as `two_level.py`);
- coarse: `E_ab = f_a f_b Kc(a - b)` for `a != b`, `Kc` the compliance
  between whole blocks (one convolution for all: the kernel is
  translation invariant), `f` the blocks' contact fractions, and the
  diagonal `E_aa` exact (each block's own pairs, local);
- coarse, near: as coarse, and the pairs of the 8 neighbouring blocks exact
  too;
- coarse, scaled: `f_a f_b Kc(a - b)` everywhere (the diagonal too).

Iterations of PCG to 1e-8 on the converged contact set's linear system.

Usage: python coarse_matrix.py N B [--full | --inner]   (numpy, scipy, layered_contact)
"""

import sys

import numpy as np

from projected_cg import operator, pressure_space, spectra, surface
from two_level import Restricted, blocks, pcg


# The exact coarse matrix (one convolution per aggregate) up to this N.
EXACT_UP_TO = 512


def block_pairs(member, kernel, b, near):
    """Sum of kernel over the pairs of member cells in blocks a and a + d,
    for each block a and each offset d in `near`: {(a, d): sum}."""
    n = member.shape[0]
    nb = n // b
    cells = {}
    for i, j in zip(*np.nonzero(member)):
        cells.setdefault((i // b, j // b), []).append((i, j))
    sums = {}
    for (bi, bj), mine in cells.items():
        mine = np.array(mine)
        for di, dj in near:
            other = cells.get(((bi + di) % nb, (bj + dj) % nb))
            if other is None:
                continue
            other = np.array(other)
            dx = (mine[:, None, 0] - other[None, :, 0]) % n
            dy = (mine[:, None, 1] - other[None, :, 1]) % n
            sums[(bi, bj, di, dj)] = kernel[dx, dy].sum()
    return sums


def coarse_grid(member, b):
    """The coarse grid of `member`'s b x b blocks: the blocks with member
    cells (in the order `blocks(member, b)` labels them), their shares of
    member cells `f`, and `Kc`, the compliance between whole blocks by
    block offset (one convolution for all)."""
    n = member.shape[0]
    nb = n // b
    _, compliance = spectra(n)
    whole = np.zeros((n, n))
    whole[:b, :b] = 1.0
    Kc = operator(compliance)(whole).reshape(nb, b, nb, b).sum(axis=(1, 3))
    i, j = np.nonzero(member)
    ids = np.unique((i // b) * nb + j // b)
    count = np.bincount((i // b) * nb + j // b, minlength=nb * nb)[ids]
    return ids, count / b**2, Kc


def coarse_matrices(member, b):
    """The approximate coarse matrices over the blocks' aggregates, ordered
    as `blocks(member, b)` labels them."""
    n = member.shape[0]
    nb = n // b
    _, compliance = spectra(n)
    delta = np.zeros((n, n))
    delta[0, 0] = 1.0
    kernel = operator(compliance)(delta)
    ids, f, Kc = coarse_grid(member, b)
    bi, bj = ids // nb, ids % nb
    scaled = np.outer(f, f) * Kc[(bi[:, None] - bi[None, :]) % nb, (bj[:, None] - bj[None, :]) % nb]
    index = {(a, c): k for k, (a, c) in enumerate(zip(bi, bj))}
    own = scaled.copy()
    for (a, c, _, _), s in block_pairs(member, kernel, b, [(0, 0)]).items():
        k = index[(a, c)]
        own[k, k] = s
    ring = [(di, dj) for di in (-1, 0, 1) for dj in (-1, 0, 1)]
    near = scaled.copy()
    for (a, c, di, dj), s in block_pairs(member, kernel, b, ring).items():
        near[index[(a, c)], index[((a + di) % nb, (c + dj) % nb)]] = s
    return {"coarse": own, "coarse, near": near, "coarse, scaled": scaled}


def projected(ops, r):
    """`Q r + (I - Pi) B (I - Pi) r`, `Pi` the mean over each aggregate:
    balancing with `A Z` replaced by `Z N^-1 E` (no fine convolutions)."""
    count = np.bincount(ops.labels, minlength=ops.m)
    mean = lambda v: (ops.restrict(v) / count)[ops.labels]  # noqa: E731
    y = ops.B(r - mean(r))
    return ops.Q(r) + y - mean(y)


def main(n, b):
    h = surface(n)
    p, _ = pressure_space(h, 1e-10)
    member = p > 0
    exact = n < EXACT_UP_TO * 2
    ops = Restricted(member, blocks(member, b), exact)
    rhs = -h[member]
    rhs -= rhs.mean()
    both = lambda: (f"{pcg(ops.A, ops.balancing, rhs)} / "  # noqa: E731
                    f"{pcg(ops.A, lambda r: projected(ops, r), rhs)}")
    row = [f"{n}", f"{int(member.sum())}", f"{b} ({ops.m})", f"{pcg(ops.A, ops.B, rhs)}"]
    if exact:
        row += [f"{pcg(ops.A, ops.balancing, rhs)}",
                f"{pcg(ops.A, lambda r: projected(ops, r), rhs)}"]
        for E in coarse_matrices(member, b).values():
            ops.E_inv = np.linalg.inv(E)
            row.append(both())
    else:
        ops.E_inv = np.linalg.inv(coarse_matrices(member, b)["coarse"])
        row += ["", "", both(), "", ""]
    print("| " + " | ".join(row) + " |")


def full(n, b):
    """The constrained conjugate gradients from a cold start (tolerance
    1e-8) with `B` and with the projected two-level preconditioner over
    the working set's b x b blocks (its coarse matrix rebuilt each
    iteration)."""
    h = surface(n)
    plain, it_plain = pressure_space(h, 1e-8)

    def two_level(W, r):
        ops = Restricted(W, blocks(W, b), exact=False)
        ops.E_inv = np.linalg.inv(coarse_matrices(W, b)["coarse"])
        return ops.embed(projected(ops, r[W]))

    coarse, it_coarse = pressure_space(h, 1e-8, precondition=two_level)
    difference = np.abs(coarse - plain).sum() / plain.sum()
    print(f"constrained CG at N = {n}: {it_plain} iterations with B, {it_coarse} with the "
          f"projected two-level preconditioner over blocks of {b} (pressures differ by "
          f"{difference:.1e})")


def inner(n, b):
    """PCG iterations (to 1e-10) of the coarse solve `E c = s` applied on the
    coarse grid, as a solver would (one coarse convolution per iteration):
    `E v = f (Kc * (f v)) + (D - f^2 Kc(0)) v` on the blocks with contact,
    preconditioned by Jacobi or by `F^-1 P Kc^-1 P F^-1` (the coarse grid's
    masked inverse)."""
    h = surface(n)
    p, _ = pressure_space(h, 1e-10)
    member = p > 0
    nb = n // b
    E = coarse_matrices(member, b)["coarse"]
    ids, f, Kc = coarse_grid(member, b)
    kc_hat = np.fft.rfft2(Kc)
    inverse = np.zeros_like(kc_hat)
    inverse[np.abs(kc_hat) > 1e-12 * np.abs(kc_hat).max()] = 1.0 / kc_hat[
        np.abs(kc_hat) > 1e-12 * np.abs(kc_hat).max()]

    def grid(v):
        g = np.zeros(nb * nb)
        g[ids] = v
        return g.reshape(nb, nb)

    def conv(hat, v):
        return np.fft.irfft2(np.fft.rfft2(grid(v)) * hat, s=(nb, nb)).ravel()[ids]

    diagonal = np.diag(E) - f * f * Kc[0, 0]
    apply = lambda v: f * conv(kc_hat, f * v) + diagonal * v  # noqa: E731
    rng = np.random.default_rng(1)
    rhs = rng.standard_normal(len(ids))
    check = np.linalg.norm(apply(rhs) - E @ rhs) / np.linalg.norm(E @ rhs)
    jacobi = pcg(apply, lambda r: r / np.diag(E), rhs, tol=1e-10)
    masked = pcg(apply, lambda r: conv(inverse, r / f) / f, rhs, tol=1e-10)
    print(f"| {n} | {b} | {len(ids)} | {check:.1e} | {jacobi} | {masked} |")


if __name__ == "__main__":
    if "--inner" in sys.argv[3:]:
        print("| N | B | active blocks | coarse apply against E | Jacobi | masked Kc^-1 |")
        print("|---|---|---|---|---|---|")
        inner(int(sys.argv[1]), int(sys.argv[2]))
        sys.exit()
    if "--full" in sys.argv[3:]:
        full(int(sys.argv[1]), int(sys.argv[2]))
        sys.exit()
    print("| N | contact cells | blocks (aggregates) | B | exact E: balancing | projected "
          "| coarse: balancing / projected | coarse, near | coarse, scaled |")
    print("|---|---|---|---|---|---|---|---|---|")
    main(int(sys.argv[1]), int(sys.argv[2]))

