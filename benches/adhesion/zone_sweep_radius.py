"""Why the cohesive zone cannot be swept once per conjugate-gradient step.

The zone's law (``solver/cohesive.rs``) has the negative stiffness
``sigma_max / rho``; a sweep that sets each zone cell's tension from its gap
contracts only if the zone's compliance stays below ``rho / sigma_max =
2 k Delta / E*`` (``k`` the zone's width in cells: 8 Delta / E* for the
default of 4). With the contact re-solved between sweeps (the fixed point)
the compliance is the zone's Schur complement with the contact held; swept
after a single step of the contact's iteration it is the free compliance
``K_ZZ`` of the zone's cells. This prints the largest eigenvalue of
``K_ZZ`` (units ``Delta / E*``) for bands four cells wide and for rings
four cells wide round discs, from the cell-integrated Boussinesq
coefficients of a uniform pressure on a square cell (Love 1929, Phil.
Trans. R. Soc. A 228, 377; Johnson 1985, Contact Mechanics, eq. 3.25).

Usage: python zone_sweep_radius.py   (numpy; a few seconds)
"""

import numpy as np


def love(x, y, a=0.5, b=0.5):
    """Displacement at (x, y) under unit pressure on |x'| < a, |y'| < b, in
    units of Delta / E* (cell side Delta = 1)."""

    def f(X, Y):
        r = np.hypot(X, Y)
        return X * np.log(Y + r) + Y * np.log(X + r)

    return (f(x + a, y + b) - f(x + a, y - b) - f(x - a, y + b) + f(x - a, y - b)) / np.pi


def largest(xs, ys):
    k = love(xs[:, None] - xs[None, :], ys[:, None] - ys[None, :])
    return np.linalg.eigvalsh(k)[-1]


def main():
    print("self-compliance of a cell:", love(0.0, 0.0))
    print("threshold rho / sigma_max for a zone of 4 cells: 8")
    for length in (64, 128, 256, 512):
        x, y = np.meshgrid(np.arange(length), np.arange(4), indexing="ij")
        print(f"band 4 x {length}: {largest(x.ravel(), y.ravel()):.2f}")
    for radius in (16, 32, 64):
        x, y = np.meshgrid(np.arange(-radius - 6, radius + 7), np.arange(-radius - 6, radius + 7))
        r = np.hypot(x, y)
        ring = (r >= radius) & (r < radius + 4)
        print(f"ring 4 cells wide round a disc of radius {radius}: {largest(x[ring], y[ring]):.2f}")


if __name__ == "__main__":
    main()
