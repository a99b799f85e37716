"""The rough periodic contact of issue 27 in this crate and in tamaas, side
by side on one thread, and why their contact areas differ.

A seeded self-affine surface (Hurst 0.8, rms slope 0.1, roll-off at L/4,
cut-off at 4 cells; this crate's `rough_surface_heights`, seed 1) on an
N x N periodic grid of side L = 1, pressed into a periodic half-space
(E* = 1) at the mean pressure 0.01 E* (about 20 % of the area in contact),
tolerance 1e-8, both under load control. Prints a Markdown table: time,
iterations and contact fraction of each code, and their ratio.

With ``--refine N0``, the convergence study instead: the N0 surface,
Fourier-interpolated onto grids 2, 4 and 8 times finer (the same
continuous surface, its cut-off now 8, 16, 32 cells), solved by both codes
at the same mean pressure. The contact fractions of the two
discretisations (this crate's influence coefficients of uniform pressure
over a cell, tamaas' point spectral kernel 2/(E* q)) meet as the cells
shrink under the surface's shortest wavelength.

With ``--repeat R`` each code solves each problem R times, alternately
(this crate, tamaas, this crate, ...), and the table gives the median
times: this machine's speed wanders by 10 to 20 % over minutes, so a
single pair of runs can move the ratio by as much.

Usage:
    python rough.py [--repeat R] N [N ...]
    python rough.py --refine N0
Needs numpy, tamaas and layered_contact in the running Python.
"""

import os
import statistics
import sys
import time

import numpy as np

import layered_contact as lc
from peers import timed_tamaas

L, PRESSURE, TOL = 1.0, 0.01, 1e-8
HURST, SLOPE, SEED = 0.8, 0.1, 1


def surface(n):
    """Heights (m) of the seeded surface on n x n cells."""
    spacing = L / n
    return lc.rough_surface_heights(
        hurst=HURST, long_cutoff=L / 4, short_cutoff=4 * spacing, seed=SEED, cells=n,
        spacing=spacing, rms_slope=SLOPE,
    )


def refined(heights, factor):
    """The same band-limited surface on a grid `factor` times finer: its
    spectrum zero-padded (exact Fourier interpolation)."""
    n = heights.shape[0]
    m = n * factor
    spectrum = np.fft.fftshift(np.fft.fft2(heights))
    padded = np.zeros((m, m), dtype=complex)
    start = (m - n) // 2
    padded[start:start + n, start:start + n] = spectrum
    return np.real(np.fft.ifft2(np.fft.ifftshift(padded))) * factor**2


def this_crate(heights):
    """Seconds, iterations on the finest grid, contact fraction."""
    n = heights.shape[0]
    material = lc.Material(1.0, 0.0)  # E* = E / (1 - nu^2) = 1
    body = lc.Substrate.half_space(material)
    solver = lc.ContactSolver(body, n, n, L / n, periodic=True, tolerance=TOL)
    indenter = lc.Indenter.height_map(np.max(heights) - heights, L / n)
    start = time.perf_counter()
    solution = solver.solve_force(indenter, PRESSURE * L * L)
    seconds = time.perf_counter() - start
    fraction = solution.contact_area / (L * L)
    return seconds, solution.iterations, fraction


def tamaas(heights):
    """Seconds, iterations, contact fraction."""
    import tamaas as tm

    n = heights.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
    model.E, model.nu = 1.0, 0.0
    solver = tm.PolonskyKeerRey(model, np.ascontiguousarray(heights), TOL)
    seconds, iterations = timed_tamaas(lambda: solver.solve(PRESSURE))
    fraction = float(np.mean(model.traction > 0.0))
    return seconds, iterations, fraction


def median_run(runs):
    """The median time of `runs` (seconds, iterations, fraction), with the
    iterations and fraction of the first run (every run gives the same)."""
    return statistics.median(r[0] for r in runs), runs[0][1], runs[0][2]


def side_by_side(sizes, repeat=1):
    print(f"load average {os.getloadavg()[0]:.2f}, median of {repeat} run(s) each")
    print("| N | this crate (s) | iterations | contact | tamaas (s) | iterations | contact "
          "| time ratio |")
    print("|---|---|---|---|---|---|---|---|")
    for n in sizes:
        heights = surface(n)
        ours, theirs = [], []
        for _ in range(repeat):
            ours.append(this_crate(heights))
            theirs.append(tamaas(heights))
        ours, theirs = median_run(ours), median_run(theirs)
        print(f"| {n} | {ours[0]:.2f} | {ours[1]} | {100 * ours[2]:.2f} % | "
              f"{theirs[0]:.2f} | {theirs[1]} | {100 * theirs[2]:.2f} % | {theirs[0] / ours[0]:.1f} |")


def refinement(n0):
    print(f"load average {os.getloadavg()[0]:.2f}")
    print("| cells per shortest wavelength | N | this crate | tamaas | difference |")
    print("|---|---|---|---|---|")
    base = surface(n0)
    for factor in (1, 2, 4, 8):
        heights = base if factor == 1 else refined(base, factor)
        ours = this_crate(heights)[2]
        theirs = tamaas(heights)[2]
        print(f"| {4 * factor} | {n0 * factor} | {100 * ours:.3f} % | {100 * theirs:.3f} % | "
              f"{100 * (theirs / ours - 1):+.2f} % |")


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[:1] == ["--refine"]:
        refinement(int(args[1]))
    else:
        repeat = 1
        if args[:1] == ["--repeat"]:
            repeat, args = int(args[1]), args[2:]
        side_by_side([int(a) for a in args] or [256, 512], repeat)
