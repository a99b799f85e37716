"""Issue 23, a measurement for the choice of method: the JKR limit as a
cohesive zone resolved on the grid.

Johnson's wavy surface (K. L. Johnson 1995, Int. J. Solids Struct. 32, 423;
alpha = 0.3) pressed into a periodic half-space whose surface carries a
short-range adhesive law instead of a Griffith criterion: the interaction
energy per area phi(g) = -dgamma (1 - g/rho)^2 for gaps g < rho (a linear
softening traction 2 dgamma/rho (1 - g/rho), whose integral is dgamma).
The range rho is tied to the cell size so that the cohesive zone,
E* rho^2 / (4 dgamma), spans `k` cells: as the grid is refined the zone
shrinks with the cell and the solution tends to the JKR limit (Maugis 1992,
J. Colloid Interface Sci. 150, 243, for the sphere; Mueser 2014, Beilstein
J. Nanotechnol. 5, 419, on resolving the interaction range). The
equilibrium of each machine displacement is a bound-constrained minimum of
the total energy (elastic energy from the spectral half-space stiffness
E*|q|/2, the interaction, and a stiff spring on the mean displacement,
through which the displacement is prescribed), found by L-BFGS-B from the
previous step's solution. The pull-off is the most tensile mean pressure
along the unloading path, to the step of the scan.

"along": the crests run along the grid's rows (a single row suffices).
"diagonal": the crests run at 45 degrees on an n x n grid; n cells across
the square are n / sqrt(2) cells per wavelength across the crests.

    python3 benches/adhesion/cohesive_zone.py along 8 181 362 724
    python3 benches/adhesion/cohesive_zone.py diagonal 8 256 512

prints the pull-off's relative error against Johnson's value. Needs numpy
and scipy. A prototype for measuring, not part of the crate.
"""

import sys

import numpy as np
from scipy.optimize import brentq, minimize

ALPHA = 0.3
# Units: E* = 1, wavelength = 1, amplitude g = 1, so that p* = pi E* g /
# wavelength = pi and dgamma = alpha^2 pi^2 / 2.
DGAMMA = ALPHA**2 * np.pi**2 / 2
SPRING = 50.0  # on the mean displacement, in units of p* per wavelength


def johnson_pull_off(alpha):
    """The most tensile mean pressure of pbar/p* = sin^2 psi - alpha sqrt(tan psi)."""
    slope = lambda psi: 2 * np.sin(psi) * np.cos(psi) - alpha / (
        2 * np.cos(psi) ** 2 * np.sqrt(np.tan(psi))
    )
    psis = np.linspace(1e-6, np.pi / 2 - 1e-6, 20001)
    d = slope(psis)
    i = np.where((d[:-1] < 0) & (d[1:] >= 0))[0][0]
    psi = brentq(slope, psis[i], psis[i + 1], xtol=1e-15)
    return np.pi * (np.sin(psi) ** 2 - alpha * np.sqrt(np.tan(psi)))


class Wavy:
    def __init__(self, n, direction, zone_cells):
        if direction == "along":
            rows, side = 1, 1.0
            spacing = side / n
            x = (np.arange(n) + 0.5) * spacing
            self.h = np.broadcast_to(1 - np.cos(2 * np.pi * x), (rows, n)).copy()
        else:
            rows, side = n, np.sqrt(2.0)
            spacing = side / n
            x = (np.arange(n) + 0.5) * spacing
            xx, yy = np.meshgrid(x, x)
            self.h = 1 - np.cos(2 * np.pi * (xx + yy) / side)
        qx = 2 * np.pi * np.fft.fftfreq(n, d=spacing)
        qy = 2 * np.pi * np.fft.fftfreq(rows, d=spacing)
        qx, qy = np.meshgrid(qx, qy)
        self.stiffness = np.hypot(qx, qy) / 2
        self.rho = 2 * np.sqrt(DGAMMA * zone_cells * spacing)

    def energy(self, v, depth):
        v = v.reshape(self.h.shape)
        elastic = np.fft.ifft2(self.stiffness * np.fft.fft2(v)).real
        t = np.clip(1 - (self.h + v) / self.rho, 0, None)
        mean = v.mean() + depth
        e = 0.5 * np.sum(v * elastic) - DGAMMA * np.sum(t * t) + 0.5 * SPRING * v.size * mean**2
        grad = elastic + 2 * DGAMMA / self.rho * t + SPRING * mean
        return e, grad.ravel()

    def solve(self, depth, start):
        bounds = [(-h, None) for h in self.h.ravel()]
        result = minimize(
            self.energy, start, args=(depth,), jac=True, method="L-BFGS-B", bounds=bounds,
            options=dict(maxiter=20000, maxcor=30, ftol=1e-15, gtol=1e-11 * DGAMMA),
        )
        v = result.x
        touching = np.mean(self.h.ravel() + v <= 1e-12)
        return v, SPRING * (v.mean() + depth), touching, result.nit


def pull_off(n, direction, zone_cells):
    body = Wavy(n, direction, zone_cells)
    depth = 0.5
    v, p, _, iterations = body.solve(depth, -0.5 * body.h.ravel())
    while depth > 0.0:  # unload in coarse steps to zero displacement
        depth -= 0.1
        v, p, _, it = body.solve(depth, v)
        iterations += it
    best = p
    while True:  # then in fine steps until the contact jumps off
        depth -= 0.004
        w, p, touching, it = body.solve(depth, v)
        iterations += it
        if touching == 0:
            return best, iterations
        v, best = w, min(best, p)


if __name__ == "__main__":
    direction, zone_cells = sys.argv[1], float(sys.argv[2])
    reference = johnson_pull_off(ALPHA)
    for n in map(int, sys.argv[3:]):
        value, iterations = pull_off(n, direction, zone_cells)
        print(
            f"{direction}, zone of {zone_cells:g} cells, n = {n}: pull-off error "
            f"{value / reference - 1:+.4%} ({iterations} L-BFGS-B iterations)",
            flush=True,
        )
