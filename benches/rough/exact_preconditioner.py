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

Beside them, two extensions `E` of `edge_extension.py`'s `E^T K^-1 E`
(the exact inverse is that with the elastic, energy-minimising `E`): 16
sweeps of the four-neighbour mean outside the set, and the discrete
Laplace (H^1-harmonic) extension, solved exactly (scipy's sparse LU).

Usage: python exact_preconditioner.py N [N ...]   (numpy, scipy, layered_contact)
"""

import sys

import numpy as np
import scipy.sparse as sparse
import scipy.sparse.linalg as sparse_linalg

from edge_extension import laplace as mean_sweeps
from projected_cg import operator, pressure_space, spectra, surface
from two_level import pcg_solve


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

        x, iterations = pcg_solve(lambda v: restricted(K, v), lambda v: restricted(M, v), r[W],
                                  tol=tol, most=1000)
        count[0] += iterations
        out = np.zeros((n, n))
        out[W] = x
        return out

    return precondition, count


def harmonic(n):
    """`E^T K^-1 E` with `E` the discrete Laplace extension of the working
    set's values (periodic five-point Laplacian `L`): `E = [I; -L_FF^-1
    L_FW]`, `E^T y = y_W - L_WF L_FF^-1 y_F`."""
    stiffness, _ = spectra(n)
    K_inv = operator(stiffness)
    ring = sparse.diags([-np.ones(n - 1), 2 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1],
                        format="lil")
    ring[0, n - 1] = ring[n - 1, 0] = -1
    eye = sparse.identity(n, format="csr")
    L = (sparse.kron(ring.tocsr(), eye) + sparse.kron(eye, ring.tocsr())).tocsr()

    def precondition(W, r):
        inside = W.ravel()
        free = ~inside
        L_FF = sparse_linalg.splu(L[free][:, free].tocsc())
        L_FW = L[free][:, inside]
        x = np.zeros(n * n)
        x[inside] = r.ravel()[inside]
        x[free] = -L_FF.solve(L_FW @ x[inside])
        y = K_inv(x.reshape(n, n)).ravel()
        out = np.zeros(n * n)
        out[inside] = y[inside] - L_FW.T @ L_FF.solve(y[free])
        return out.reshape(n, n)

    return precondition


def main(sizes):
    print("| N | box: iterations | exact, inner to 1e-2: outer (inner) | exact, inner to 1e-10: "
          "outer (inner) | 16 sweeps | Laplace extension | pressures apart |")
    print("|---|---|---|---|---|---|---|")
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
        _, swept = pressure_space(h, 1e-8, precondition=mean_sweeps(16, 1.0,
                                                                    operator(spectra(n)[0])))
        cells.append(str(swept))
        cells.append(str(pressure_space(h, 1e-8, precondition=harmonic(n))[1]) if n <= 512
                     else "-")
        print(f"| {n} | {' | '.join(cells)} | {apart:.1e} |", flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [128, 256])
