"""Would longer projected steps move the rough contact's set faster? Asked
of the numpy model of `projected_cg.py` (issue 27), from the coarse start
and with the box of `coarse_balancing.py --crate`: after each constrained
conjugate-gradient step `p - a t` (`a` the step that minimises the energy
along `t` before the clamp), the steps `k a` for each `k` of a list are
clamped and rescaled to the load as well, and the one of least energy
`sum p (u / 2 + h)` is taken (a search along the projection arc,
Bertsekas 1976, IEEE Trans. Autom. Control 21, 174; each further `k`
costs one application of the compliance). The conjugation restarts after
a longer step; the rest is `projected_cg.pressure_space`. Prints the
iterations to 1e-8, how many steps were longer, and the contact cells
(which must be the plain run's).

Usage: python longer_steps.py N [N ...]   (numpy, layered_contact)
"""

import sys

import numpy as np

from coarse_balancing import crate_problem
from projected_cg import PBAR, operator, pressure_space, spectra


def energy(p, u, h):
    """The load's potential energy, its gradient the gap (up to the mean)."""
    return np.sum(p * (0.5 * u + h))


def searched(h, start, precondition, factors, tol=1e-8):
    """Pressures, iterations and longer steps taken, each step the best of
    `factors` times the conjugate-gradient step
    (`projected_cg.pressure_space` with the arc search as its `project`)."""
    _, compliance = spectra(h.shape[0])
    K = operator(compliance)
    longer = [0]

    def project(p, step, t):
        best = None
        for k in factors:
            new = np.maximum(p - k * step * t, 0.0)
            new *= PBAR / new.mean()
            u = K(new)
            e = energy(new, u, h)
            if best is None or e < best[0]:
                best = (e, new, u, k)
        _, new, u, k = best
        longer[0] += k != 1.0
        return new, u, k != 1.0

    p, it = pressure_space(h, tol, precondition=precondition, start=start, project=project)
    return p, it, longer[0]


def main(sizes):
    lists = ([1.0], [1.0, 2.0], [1.0, 1.5, 3.0])
    print("| N | " + " | ".join(f"steps {k}: iterations (longer), contact" for k in lists) + " |")
    print("|---|" + "---|" * len(lists))
    for n in sizes:
        h, start, box = crate_problem(n)
        cells = []
        for factors in lists:
            p, it, longer = searched(h, start, box, factors)
            cells.append(f"{it} ({longer}), {int((p > 0).sum())}")
        print(f"| {n} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [256, 512])
