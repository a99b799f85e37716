"""Would a coarse space flatten the rough contact's iterations? Asked of the
numpy model of `projected_cg.py` (issue 27): the preconditioner `B = P K^-1
P` (Vollebregt 2014) against two-level ones with a coarse space `Z` of
aggregates (the contact cells of each `b x b` block, or of each connected
patch) and the exact coarse matrix `E = Z^T A Z`, `A` the compliance
restricted to the contact:

- additive: `B + w Z E^-1 Z^T`;
- balancing (Mandel 1993, Commun. Numer. Meth. Eng. 9, 233): `Q + (I - Q A)
  B (I - A Q)`, `Q = Z E^-1 Z^T`, symmetric positive definite for any
  symmetric positive definite `B`, two more applications of `A` per
  iteration;
- A-DEF2 (Tang, Nabben, Vuik & Erlangga 2009, J. Sci. Comput. 39, 340):
  `(I - Q A) B + Q`, one more application, not symmetric.

First on the linear system of the converged contact set (PCG to 1e-8), then
in the constrained conjugate gradients of `projected_cg.py` from a cold
start (tolerance 1e-8). The exact `E` takes one convolution per
aggregate, so this only measures what a coarse space could give.

Usage: python two_level.py N B [--full]   (numpy, scipy, layered_contact)
"""

import sys

import numpy as np
import scipy.ndimage as ndi

from projected_cg import operator, pressure_space, spectra, surface


def pcg(apply, precondition, rhs, tol=1e-8, x0=None, most=2000):
    """Iterations of preconditioned conjugate gradients to a relative
    residual of `tol`."""
    return pcg_solve(apply, precondition, rhs, tol, x0, most)[1]


def pcg_solve(apply, precondition, rhs, tol=1e-8, x0=None, most=2000):
    """The solution and the iterations of preconditioned conjugate
    gradients to a relative residual of `tol` (at most `most`)."""
    x = np.zeros_like(rhs) if x0 is None else x0.copy()
    r = rhs - apply(x)
    z = precondition(r)
    d, rz, norm = z.copy(), r @ z, np.linalg.norm(rhs)
    for it in range(1, most + 1):
        ad = apply(d)
        alpha = rz / (d @ ad)
        x += alpha * d
        r -= alpha * ad
        if np.linalg.norm(r) <= tol * norm:
            return x, it
        z = precondition(r)
        rz, rz_old = r @ z, rz
        d = z + rz / rz_old * d
    return x, most


class Restricted:
    """The compliance `A` and `B = P K^-1 P` on the cells `member` of an
    n x n grid, and the coarse space of the aggregates `labels` (one per
    member cell, 0..m) with its exact coarse matrix (one convolution per
    aggregate) unless `exact` is false (`E_inv` then set by the caller)."""

    def __init__(self, member, labels, exact=True):
        n = member.shape[0]
        stiffness, compliance = spectra(n)
        self.K, self.M = operator(compliance), operator(stiffness)
        self.n, self.index = n, np.flatnonzero(member.ravel())
        self.labels, self.m = labels, labels.max() + 1
        if not exact:
            return
        self.E = np.zeros((self.m, self.m))
        for k in range(self.m):
            self.E[:, k] = self.restrict(self.A((labels == k).astype(float)))
        self.E_inv = np.linalg.inv(self.E)

    def embed(self, v):
        f = np.zeros(self.n * self.n)
        f[self.index] = v
        return f.reshape(self.n, self.n)

    def A(self, v):
        return self.K(self.embed(v)).ravel()[self.index]

    def B(self, v):
        return self.M(self.embed(v)).ravel()[self.index]

    def restrict(self, v):
        return np.bincount(self.labels, weights=v, minlength=self.m)

    def Q(self, v):
        return (self.E_inv @ self.restrict(v))[self.labels]

    def balancing(self, r):
        qr = self.Q(r)
        y = self.B(r - self.A(qr))
        return qr + y - self.Q(self.A(y))

    def adef2(self, r):
        y = self.B(r)
        return y - self.Q(self.A(y)) + self.Q(r)


def blocks(member, b):
    """Aggregate labels: the member cells of each b x b block."""
    i, j = np.nonzero(member)
    _, labels = np.unique((i // b) * (member.shape[0] // b) + j // b, return_inverse=True)
    return labels


def patches(member):
    """Aggregate labels: the connected patches (4-neighbours)."""
    labelled, _ = ndi.label(member)
    return labelled[member] - 1


def linear(n, b):
    """Iterations on the converged contact set's linear system."""
    h = surface(n)
    p, _ = pressure_space(h, 1e-10)
    member = p > 0
    for name, labels in [(f"blocks of {b}", blocks(member, b)), ("patches", patches(member))]:
        ops = Restricted(member, labels)
        rhs = -h[member]
        rhs -= rhs.mean()
        plain = pcg(ops.A, ops.B, rhs)
        additive = [pcg(ops.A, lambda r, w=w: ops.B(r) + w * ops.Q(r), rhs) for w in (0.1, 1, 10)]
        balancing = pcg(ops.A, ops.balancing, rhs)
        adef2 = pcg(ops.A, ops.adef2, rhs, x0=ops.Q(rhs))
        print(f"| {n} | {int(member.sum())} | {name} ({ops.m}) | {plain} | "
              f"{' / '.join(map(str, additive))} | {balancing} | {adef2} |")


def balanced(W, r, b):
    """The balancing preconditioner over the working set `W`'s b x b
    blocks, applied to the residual `r` (for `pressure_space`)."""
    ops = Restricted(W, blocks(W, b))
    return ops.embed(ops.balancing(r[W]))


def main(n, b, full):
    print("| N | contact cells | coarse space (aggregates) | B | additive w = 0.1 / 1 / 10 "
          "| balancing | A-DEF2 |")
    print("|---|---|---|---|---|---|---|")
    linear(n, b)
    if full:
        h = surface(n)
        plain, it_plain = pressure_space(h, 1e-8)
        coarse, it_coarse = pressure_space(h, 1e-8, precondition=lambda W, r: balanced(W, r, b))
        difference = np.abs(coarse - plain).sum() / plain.sum()
        print(f"constrained CG at N = {n}: {it_plain} iterations with B, {it_coarse} with "
              f"balancing over blocks of {b} (pressures differ by {difference:.1e})")


if __name__ == "__main__":
    main(int(sys.argv[1]), int(sys.argv[2]), "--full" in sys.argv[3:])
