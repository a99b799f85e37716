"""Why the cohesive zone's fixed point needs more rounds on finer grids, and
what a coarse space round the edge would take away.

A disc of contact (radius ``R`` cells, held at zero gap) with a cohesive
zone four cells wide round it (``R <= r < R + 4``), cell-integrated
Boussinesq coefficients (``zone_sweep_radius.py``). The fixed point's
linear rate is the spectrum of ``J = sigma' S_Z``: ``sigma' = sigma_max /
rho = E* / (2 k Delta)`` the law's negative stiffness (``k`` = 4 cells) and
``S_Z = K_ZZ - K_ZC K_CC^-1 K_CZ`` the zone's compliance with the contact
held (its Schur complement). Prints the largest eigenvalue ``mu`` (the
plain rounds' rate), the condition number of ``I - J`` (Anderson mixing,
a Krylov method, contracts by about ``(sqrt(kappa) - 1) / (sqrt(kappa) +
1)`` a round), and the same condition number with a coarse space of the
ring's angular harmonics ``cos(m theta)``, ``sin(m theta)``, ``m <= M``,
deflated (its part solved exactly, as a two-level method would), and
with a coarse space of aggregates instead (the ring cut into ``A``
sectors, each one vector, constant on its cells: what a coarse space
round an edge of any shape would be).

``--width W`` makes the ring ``W`` cells wide with the law of four (the
cells whose gap is below the range: the solved zone spans a little more
or less than the law's ``k`` cells).

Usage: python zone_schur.py [--width W] [R ...]   (numpy; R = 8 16 32 by
default; R = 32 takes about 15 s)
"""

import sys

import numpy as np

from zone_sweep_radius import love

ZONE = 4
SLOPE = 1.0 / (2 * ZONE)  # sigma' in E* / Delta


def ring_map(radius, width=ZONE):
    """The fixed point's linear map ``I - J`` on a ring of zone cells
    ``width`` wide round a disc of contact of ``radius`` cells, and the zone
    cells' centres."""
    n = radius + width + 2
    x, y = np.meshgrid(np.arange(-n, n + 1) + 0.0, np.arange(-n, n + 1) + 0.0)
    # Cell centres at half-integers so that the disc is symmetric.
    x, y = x.ravel() + 0.5, y.ravel() + 0.5
    r = np.hypot(x, y)
    contact, zone = r < radius, (r >= radius) & (r < radius + width)
    xc, yc, xz, yz = x[contact], y[contact], x[zone], y[zone]
    k_cc = love(xc[:, None] - xc[None, :], yc[:, None] - yc[None, :])
    k_cz = love(xc[:, None] - xz[None, :], yc[:, None] - yz[None, :])
    k_zz = love(xz[:, None] - xz[None, :], yz[:, None] - yz[None, :])
    s_z = k_zz - k_cz.T @ np.linalg.solve(k_cc, k_cz)
    s_z = 0.5 * (s_z + s_z.T)
    return np.eye(len(xz)) - SLOPE * s_z, xz, yz, len(xc)


def rates(radius, width=ZONE):
    a, xz, yz, contact_cells = ring_map(radius, width)
    mu = 1.0 - np.linalg.eigvalsh(a)
    out = [radius, contact_cells, len(xz), mu.max(), 1.0 / (1.0 - mu.max())]
    theta = np.arctan2(yz, xz)
    for harmonics in (0, 2, 4, 8, 16):
        columns = [np.ones_like(theta)]
        for m in range(1, harmonics + 1):
            columns += [np.cos(m * theta), np.sin(m * theta)]
        v = np.linalg.qr(np.array(columns).T)[0]
        # Deflation: A restricted to the A-orthogonal complement of V.
        p = np.eye(len(xz)) - v @ np.linalg.solve(v.T @ a @ v, v.T @ a)
        w = np.linalg.eigvals(a @ p)
        w = np.sort(w.real[np.abs(w) > 1e-10])
        out.append(w[-1] / w[0])
    for sectors in (8, 16, 32):
        cut = np.floor((theta + np.pi) / (2 * np.pi) * sectors).astype(int) % sectors
        v = np.array([(cut == s).astype(float) for s in range(sectors)]).T
        v /= np.linalg.norm(v, axis=0)
        p = np.eye(len(xz)) - v @ np.linalg.solve(v.T @ a @ v, v.T @ a)
        w = np.linalg.eigvals(a @ p)
        w = np.sort(w.real[np.abs(w) > 1e-10])
        out.append(w[-1] / w[0])
    return out


def main():
    args = sys.argv[1:]
    width = ZONE
    if args[:1] == ["--width"]:
        width, args = int(args[1]), args[2:]
    radii = [int(r) for r in args] or [8, 16, 32]
    print(f"ring {width} cells wide, the law of {ZONE}")
    print("| R (cells) | contact cells | zone cells | largest mu | kappa of I - J "
          "| deflating M = 0 | 2 | 4 | 8 | 16 | A = 8 | 16 | 32 sectors |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for radius in radii:
        row = rates(radius, width)
        print("| " + " | ".join(f"{v:.3g}" if isinstance(v, float) else str(v) for v in row) + " |")


if __name__ == "__main__":
    main()
