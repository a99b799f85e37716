"""Would longer projected steps move the rough contact's set faster? Asked
of the numpy model of `projected_cg.py` (issue 27), from the coarse start
and with the box of `coarse_balancing.py --crate`: after each constrained
conjugate-gradient step `p - a t` (`a` the step that minimises the energy
along `t` before the clamp), the steps `k a` for each `k` of a list are
clamped and rescaled to the load as well, and the one of least energy
`sum p (u / 2 + h)` is taken (a search along the projection arc,
Bertsekas 1976, IEEE Trans. Autom. Control 21, 174; each further `k`
costs one application of the compliance). The conjugation restarts after
a longer step. Prints the iterations to 1e-8, how many steps were longer,
and the contact cells (which must be the plain run's).

Usage: python longer_steps.py N [N ...]   (numpy, layered_contact)
"""

import sys

import numpy as np

from coarse_balancing import coarse_start
from edge_extension import laplace
from projected_cg import PBAR, operator, spectra, surface


def energy(p, u, h):
    """The load's potential energy, its gradient the gap (up to the mean)."""
    return np.sum(p * (0.5 * u + h))


def searched(h, start, precondition, factors, tol=1e-8, most=3000):
    """Pressures, iterations and longer steps taken, each step the best of
    `factors` times the conjugate-gradient step."""
    _, compliance = spectra(h.shape[0])
    K = operator(compliance)
    p = start * (PBAR / start.mean())
    u, t, rz_old, longer = K(p), np.zeros_like(h), 0.0, 0
    for it in range(1, most + 1):
        depth = np.mean((h + u)[p > 0])
        g = h + u - depth
        joining = (p == 0) & (g < 0)
        W = (p > 0) | joining
        r = np.where(W, g - g[W].mean(), 0.0)
        z = np.where(W, precondition(W, r), 0.0)
        z = np.where(W, z - z[W].mean(), 0.0)
        rz = np.sum(r * z)
        beta = rz / rz_old if rz_old > 0 else 0.0
        if joining.any() and beta > 0 and rz + beta * np.sum(np.where(W, t, 0) * r) <= 0:
            beta = 0.0
        t = np.where(W, z + beta * t, 0.0)
        step = np.sum(r * t) / np.sum(t * K(t))
        best = None
        for k in factors:
            new = np.maximum(p - k * step * t, 0.0)
            new *= PBAR / new.mean()
            un = K(new)
            e = energy(new, un, h)
            if best is None or e < best[0]:
                best = (e, new, un, k)
        _, new, un, k = best
        change = np.abs(new - p).sum() / new.sum()
        p, u, rz_old = new, un, (rz if k == 1.0 else 0.0)
        longer += k != 1.0
        if change <= tol and not joining.any():
            return p, it, longer
    return p, most, longer


def main(sizes):
    lists = ([1.0], [1.0, 2.0], [1.0, 1.5, 3.0])
    print("| N | " + " | ".join(f"steps {k}: iterations (longer), contact" for k in lists) + " |")
    print("|---|" + "---|" * len(lists))
    for n in sizes:
        stiffness, _ = spectra(n)
        box = laplace(1, 1.0, operator(stiffness))
        h = surface(n)
        start = coarse_start(h)
        cells = []
        for factors in lists:
            p, it, longer = searched(h, start, box, factors)
            cells.append(f"{it} ({longer}), {int((p > 0).sum())}")
        print(f"| {n} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [256, 512])
