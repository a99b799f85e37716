"""Does the box preconditioner lose its grip on rough contacts at the
contact's edges? Asked of the numpy model of `projected_cg.py` (issue 27).

The constrained conjugate gradients are preconditioned by `P K^-1 P`
(Vollebregt 2014, J. Comput. Phys. 257, 333): the residual on the working
set, extended by zero, through the stiffness `K^-1` (here `E* q / 2` on the
periodic grid), restricted to the set. The exact preconditioner, the
inverse of the compliance restricted to the set `C`, is the Schur
complement of `K^-1`: `A_CC^-1 = E^T K^-1 E` with `E` the extension of a
displacement on `C` that minimises the elastic energy (the half-space's
surface displacement where the pressure outside `C` vanishes). Extension
by zero leaves a jump at every edge of every patch, which the stiffness
charges for; any extension `E` (identity on `C`) gives a symmetric positive
definite `E^T K^-1 E`, closer to `A_CC^-1` the closer `E` is to the
energy-minimising one. Measured here:

- `k` sweeps of the four-neighbour mean outside the set (the set's cells
  held), from zero: a discrete Laplace (H^1, not the elastic H^1/2)
  extension reaching `k` cells out, and its transpose on the way back;
- the extension of the one sweep scaled by `theta`;
- the sweeps along the rows only (`rows k`), which a split run could do
  without its neighbours' rows;
- a normalised convolution (the binomial blur of the set's residual over
  that of its indicator) out to `r` cells: full weight next to the set;
- the stiffness's multiplier itself reshaped (`q^0.8`, `q^0.6`,
  `1 / (1 + q)`), which costs nothing.

Counts are the constrained conjugate gradients' iterations from a cold
start to `1e-8` (`projected_cg.pressure_space`), so they compare the
preconditioners, not the crate's multi-resolution solves.

Usage: python edge_extension.py PBAR N [N ...]   (numpy, layered_contact)
       PBAR 0.003 gives about 7 % contact, 0.01 about 21 %.
"""

import sys

import numpy as np

import projected_cg as pc


def mean4(x):
    """The four-neighbour mean on the periodic grid (symmetric)."""
    return 0.25 * (np.roll(x, 1, 0) + np.roll(x, -1, 0) + np.roll(x, 1, 1) + np.roll(x, -1, 1))


def laplace(sweeps, theta, stiffness):
    """`E^T K^-1 E`, `E` the sweeps of the mean outside the set."""
    def precondition(member, r):
        outside = ~member
        x = np.where(member, r, 0.0)
        for _ in range(sweeps):
            x = np.where(member, x, theta * mean4(x))
        y = stiffness(x)
        # E^T = the sweeps' transposes in reverse: S^T y = D_C y + theta M (D_O y).
        for _ in range(sweeps):
            y = np.where(member, y, 0.0) + theta * mean4(np.where(outside, y, 0.0))
        return y
    return precondition


def mean2(x):
    """The two-neighbour mean along the rows (symmetric)."""
    return 0.5 * (np.roll(x, 1, 1) + np.roll(x, -1, 1))


def along_rows(sweeps, stiffness):
    """`E^T K^-1 E`, `E` the sweeps of the mean along the rows only."""
    def precondition(member, r):
        outside = ~member
        x = np.where(member, r, 0.0)
        for _ in range(sweeps):
            x = np.where(member, x, mean2(x))
        y = stiffness(x)
        for _ in range(sweeps):
            y = np.where(member, y, 0.0) + mean2(np.where(outside, y, 0.0))
        return y
    return precondition


def binomial(x, radius):
    """The separable binomial blur of `2 radius + 1` taps (symmetric)."""
    weights = np.array([1.0])
    for _ in range(2 * radius):
        weights = np.convolve(weights, [0.5, 0.5])
    for axis in (0, 1):
        x = sum(w * np.roll(x, j - radius, axis) for j, w in enumerate(weights))
    return x


def normalised(radius, stiffness):
    """`E^T K^-1 E`, `E` the normalised convolution outside the set."""
    def precondition(member, r):
        reach = binomial(member.astype(float), radius)
        scale = np.where(~member & (reach > 1e-3), 1.0 / np.maximum(reach, 1e-300), 0.0)
        x = np.where(member, r, 0.0)
        y = stiffness(x + scale * binomial(x, radius))
        return np.where(member, y + binomial(scale * y, radius), 0.0)
    return precondition


def main(pbar, sizes):
    pc.PBAR = pbar
    print(f"mean pressure {pbar} E*: iterations from a cold start to 1e-8")
    header = None
    for n in sizes:
        h = pc.surface(n)
        multiplier, _ = pc.spectra(n)
        stiffness = pc.operator(multiplier)
        q = 2 * multiplier
        cases = [("box", laplace(0, 1.0, stiffness))]
        cases += [(f"k={k}", laplace(k, 1.0, stiffness)) for k in (1, 2, 4, 16)]
        cases += [(f"k=1, theta={t}", laplace(1, t, stiffness)) for t in (1.5, 2.0)]
        cases += [(f"rows {k}", along_rows(k, stiffness)) for k in (1, 2)]
        cases += [(f"normalised r={r}", normalised(r, stiffness)) for r in (1, 2)]
        for name, reshaped in [("q^0.8", multiplier ** 0.8), ("q^0.6", multiplier ** 0.6),
                               ("1/(1+q)", multiplier / (1 + q / n))]:
            apply = pc.operator(reshaped)
            cases.append((name, lambda member, r, apply=apply: apply(np.where(member, r, 0.0))))
        counts = []
        for _, precondition in cases:
            p, iterations = pc.pressure_space(h, 1e-8, precondition=precondition)
            counts.append(iterations)
        if header is None:
            header = ["N", "contact"] + [name for name, _ in cases]
            print("| " + " | ".join(header) + " |")
            print("|" + "---|" * len(header))
        cells = [str(n), f"{100 * np.mean(p > 0):.1f} %"] + [str(c) for c in counts]
        print("| " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main(float(sys.argv[1]), [int(a) for a in sys.argv[2:]] or [128, 256])
