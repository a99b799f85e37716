"""How few iterations could a better preconditioner give the rough
contact? Asked of the numpy model of `projected_cg.py` (issue 27): the
constrained conjugate gradients in pressure space preconditioned by the
box `B = P K^-1 P` (Vollebregt 2014, J. Comput. Phys. 257, 333), against
the same iteration preconditioned by the exact inverse of the compliance
restricted to the working set, `(K_WW)^-1`, applied by inner conjugate
gradients (preconditioned by `B`) to a relative residual of `tol`. The
outer iterations of the second are the floor that any preconditioner
leaves: the cost of settling the contact set; the inner ones what the
exact inverse costs when it is had by iterating.

Usage: python exact_preconditioner.py N [N ...]   (numpy, layered_contact)
"""

import sys

import numpy as np

from projected_cg import operator, pressure_space, spectra, surface


def exact_inverse(n, tol):
    """A `precondition(W, r)` for `pressure_space` solving `K_WW z = r` by
    conjugate gradients preconditioned by the box, and the running count
    of its inner iterations."""
    stiffness, compliance = spectra(n)
    K, M = operator(compliance), operator(stiffness)
    count = [0]

    def precondition(W, r):
        def restricted(op, x):
            full = np.zeros((n, n))
            full[W] = x
            return op(full)[W]

        rhs = r[W]
        x, res = np.zeros_like(rhs), rhs.copy()
        z = restricted(M, res)
        d, rz, norm = z.copy(), res @ z, np.linalg.norm(rhs)
        for _ in range(1000):
            kd = restricted(K, d)
            alpha = rz / (d @ kd)
            x += alpha * d
            res -= alpha * kd
            count[0] += 1
            if np.linalg.norm(res) <= tol * norm:
                break
            z = restricted(M, res)
            rz, rz_old = res @ z, rz
            d = z + rz / rz_old * d
        out = np.zeros((n, n))
        out[W] = x
        return out

    return precondition, count


def main(sizes):
    print("| N | box: iterations | exact, inner to 1e-2: outer (inner) | exact, inner to 1e-10: "
          "outer (inner) | pressures apart |")
    print("|---|---|---|---|---|")
    for n in sizes:
        h = surface(n)
        box, box_iterations = pressure_space(h, 1e-8)
        cells = [str(box_iterations)]
        apart = 0.0
        for tol in (1e-2, 1e-10):
            if tol < 1e-2 and n > 512:
                cells.append("-")
                continue
            precondition, count = exact_inverse(n, tol)
            p, iterations = pressure_space(h, 1e-8, precondition=precondition)
            cells.append(f"{iterations} ({count[0]})")
            apart = max(apart, np.abs(p - box).sum() / box.sum())
        print(f"| {n} | {' | '.join(cells)} | {apart:.1e} |", flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [128, 256])
