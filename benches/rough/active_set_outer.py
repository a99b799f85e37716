"""Does the rough contact's set settle in fewer iterations if the set is
changed only every few iterations, all at once (an inexact primal-dual
active set method, Hintermueller, Ito & Kunisch 2002, SIAM J. Optim. 13,
865), instead of at every step of the constrained conjugate gradients
(Polonsky & Keer 1999)? Asked of the numpy model of `projected_cg.py`
(issue 27: the tamaas problem's fine count at 8192^2 is the settling of
its contact, BENCHMARKS.md "The blocks on smaller grids").

Both start from the problem on the grid twice coarser and take the box
with one sweep of the edge extension, as the crate
(`coarse_balancing.crate_problem`).

- Constrained CG (`projected_cg.pressure_space`): the pressure clamped at
  zero and the overlap joined at every step.
- Outer loop: on a frozen set `S` (the cells with pressure and those the
  indenter overlaps), `K` conjugate-gradient steps of the linear problem
  (gaps zero on `S`, the load fixed; pressures may go negative), then the
  set changes at once: cells of negative pressure leave (their pressure
  set to zero), overlapping cells join, and the load is rescaled. Stops
  when a pass leaves the set as it was and the change of the pressures
  falls below the tolerance.

Prints the iterations (each one application of the compliance and one of
the box) to 1e-8 and the contact cells of each; both must end at the same
contact.

Usage: python active_set_outer.py N [N ...] [--inner K ...]
(numpy, layered_contact)
"""

import sys

import numpy as np

from coarse_balancing import crate_problem
from projected_cg import PBAR, operator, pressure_space, spectra


def outer_loop(h, start, precondition, inner, tol=1e-8, most=2000):
    """Pressures, iterations and passes of the outer active-set loop with
    `inner` linear steps a pass."""
    _, compliance = spectra(h.shape[0])
    K = operator(compliance)
    p = start * (PBAR / start.mean())
    total, passes = 0, 0
    while total < most:
        passes += 1
        u = K(p)
        depth = np.mean((h + u)[p > 0])
        g = h + u - depth
        S = (p > 0) | (g < 0)
        before = p.copy()
        t, rz_old = np.zeros_like(h), 0.0
        for _ in range(inner):
            total += 1
            depth = np.mean((h + u)[S])
            r = np.where(S, h + u - depth, 0.0)
            z = np.where(S, precondition(S, r), 0.0)
            z = np.where(S, z - z[S].mean(), 0.0)
            rz = np.sum(r * z)
            beta = rz / rz_old if rz_old > 0 else 0.0
            t = z + beta * t
            Kt = K(t)
            step = rz / np.sum(t * Kt)
            p = p - step * t
            u = u - step * Kt
            rz_old = rz
        new = np.maximum(p, 0.0)
        new *= PBAR / new.mean()
        u = K(new)
        depth = np.mean((h + u)[new > 0])
        joining = (new == 0) & (h + u - depth < 0)
        change = np.abs(new - before).sum() / new.sum()
        same = np.array_equal(new > 0, before > 0) and not joining.any()
        p = new
        if same and change <= tol:
            return p, total, passes
    return p, total, passes


def main(sizes, inners):
    print("| N | constrained CG: iterations, contact | " +
          " | ".join(f"outer, {k} a pass: iterations (passes), contact" for k in inners) + " |")
    print("|---|---|" + "---|" * len(inners))
    for n in sizes:
        h, start, box = crate_problem(n)
        p, it = pressure_space(h, 1e-8, precondition=box, start=start)
        cells = [f"{it}, {int((p > 0).sum())}"]
        for k in inners:
            q, total, passes = outer_loop(h, start, box, k)
            cells.append(f"{total} ({passes}), {int((q > 0).sum())}")
        print(f"| {n} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    args = sys.argv[1:]
    inners = [5, 10]
    if "--inner" in args:
        k = args.index("--inner")
        inners = [int(a) for a in args[k + 1:]]
        args = args[:k]
    main([int(a) for a in args] or [256, 512], inners)
