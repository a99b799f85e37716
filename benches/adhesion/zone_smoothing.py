"""What a smoothing of the residual along the zone does to the cohesive
zone's fixed point (issue 23), asked of the model of ``zone_schur.py``: a
disc of contact (radius ``R`` cells, held at zero gap), a ring of zone
cells ``W`` wide round it, the law of four cells, cell-integrated
Boussinesq coefficients; ``A = I - J`` the fixed point's linear map
(``J = sigma' S_Z``, ``S_Z`` the zone's Schur complement).

The crate's preconditioner (``src/solver/cohesive_smoothing.rs``) takes the
round's residual ``r`` as ``(I + alpha W) r``, ``W = D^-1/2 G D^-1/2``,
``G`` the Gaussian ``exp(-d^2 / rho^2)`` between zone cells and ``D`` its
row sums. Printed: the condition number of ``A`` and of ``(I + alpha W)
A`` (real positive eigenvalues: ``I + alpha W`` is symmetric positive
definite), for gains ``alpha`` and radii ``rho`` (cells). Anderson mixing,
a Krylov method, contracts by about ``(sqrt(kappa) - 1) / (sqrt(kappa) +
1)`` a round.

Usage: python zone_smoothing.py   (numpy; about a minute)
"""

import numpy as np

from zone_schur import ring_map


def main():
    gains, radii = (1, 2, 4), (2, 4, 8)
    header = " | ".join(f"alpha {a}, rho {r}" for a in gains for r in radii)
    print(f"| R | W | kappa of A | {header} |")
    print("|---|---|---|" + "---|" * (len(gains) * len(radii)))
    for radius, width in ((16, 4), (32, 4), (16, 5), (32, 5)):
        a, xz, yz, _ = ring_map(radius, width)
        w = np.linalg.eigvalsh(a)
        row = [f"{w[-1] / w[0]:.2f}"]
        d2 = (xz[:, None] - xz[None, :]) ** 2 + (yz[:, None] - yz[None, :]) ** 2
        for gain in gains:
            for rho in radii:
                g = np.exp(-d2 / rho**2)
                s = g.sum(axis=1)
                smoothing = g / np.sqrt(s[:, None] * s[None, :])
                w = np.linalg.eigvals((np.eye(len(xz)) + gain * smoothing) @ a).real
                row.append(f"{w.max() / w.min():.2f}")
        print(f"| {radius} | {width} | " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
