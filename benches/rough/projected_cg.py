"""Questions about the rough periodic contact's iterations, asked of a numpy
model of the solver (issue 27): does the gap-space (dual) formulation
converge in fewer iterations than the pressure space, does the
Polak-Ribiere conjugation beat Fletcher-Reeves, and does a preconditioner
applied in single precision change the iterations or the answer?

The problem is `benches/peers/rough.py`'s (this crate's seeded self-affine
surface, Hurst 0.8, rms slope 0.1, roll-off at L/4, cut-off at 4 cells, a
periodic half-space with E* = 1 pressed to the mean pressure 0.01), with
the point spectral kernel `2 / (E* q)` instead of the crate's
cell-integrated one and a cold start (no multi-resolution start), so the
counts compare the formulations, not the crate.

- Pressure space: the crate's constrained conjugate gradients (Polonsky &
  Keer 1999, Wear 231, 206), preconditioned by the stiffness `E* q / 2`
  on the whole grid (Vollebregt 2014, J. Comput. Phys. 257, 333), the
  conjugation kept where new overlap joins unless the direction would not
  descend, the pressure rescaled to the load after each step.
- Gap space: the dual bound-constrained problem, minimise
  `1/2 (g - h) A (g - h) + pbar sum g` over gaps `g >= 0` (`A` the
  stiffness; its gradient is the pressure), the same projected
  conjugate gradients preconditioned by the compliance.

Usage: python projected_cg.py N [N ...]   (numpy and layered_contact)
"""

import sys

import numpy as np

import layered_contact as lc

L, PBAR = 1.0, 0.01


def surface(n):
    """Indenter heights (above its lowest point) on n x n cells."""
    spacing = L / n
    h = lc.rough_surface_heights(hurst=0.8, long_cutoff=L / 4, short_cutoff=4 * spacing, seed=1,
                                 cells=n, spacing=spacing, rms_slope=0.1)
    return h.max() - h


def spectra(n):
    """The stiffness E* q / 2 and the compliance (zero at q = 0)."""
    q = 2 * np.pi * np.fft.fftfreq(n, d=L / n)
    qx, qy = np.meshgrid(q, q, indexing="ij")
    stiffness = np.hypot(qx, qy)[:, : n // 2 + 1] / 2.0
    compliance = np.zeros_like(stiffness)
    compliance[stiffness > 0] = 1.0 / stiffness[stiffness > 0]
    return stiffness, compliance


def operator(multiplier, single=False):
    """x -> the periodic convolution with `multiplier`, in float32 if `single`."""
    if single:
        m = multiplier.astype(np.float32)
        return lambda x: np.fft.irfft2(np.fft.rfft2(x.astype(np.float32)) * m,
                                       s=x.shape).astype(np.float64)
    return lambda x: np.fft.irfft2(np.fft.rfft2(x) * multiplier, s=x.shape)


def pressure_space(h, tol, rule="fr", single=False, precondition=None, start=None,
                   restart_at=None, project=None):
    """Pressures and iterations of the constrained conjugate gradients;
    `precondition(W, r)`, if given, replaces the stiffness on the working
    set `W` (`two_level.py`); `start`, if given, the first pressures
    (`coarse_balancing.py`); `restart_at`, if given, the iteration whose
    conjugation restarts (where `precondition` changes metric);
    `project(p, step, t)`, if given, replaces the step `p - step t`
    clamped and rescaled to the load: it returns the new pressures, their
    displacement and whether the conjugation restarts after them
    (`longer_steps.py`)."""
    stiffness, compliance = spectra(h.shape[0])
    K, M = operator(compliance), operator(stiffness, single)
    p = np.full(h.shape, PBAR) if start is None else start * (PBAR / start.mean())
    u, t, rz_old, z_old = K(p), np.zeros_like(h), 0.0, np.zeros_like(h)
    for it in range(1, 5001):
        depth = np.mean((h + u)[p > 0])
        g = h + u - depth
        joining = (p == 0) & (g < 0)
        W = (p > 0) | joining
        r = np.where(W, g - g[W].mean(), 0.0)
        z = np.where(W, M(r) if precondition is None else precondition(W, r), 0.0)
        z = np.where(W, z - z[W].mean(), 0.0)
        rz = np.sum(r * z)
        if rz_old <= 0 or it == restart_at:
            beta = 0.0
        elif rule == "fr":
            beta = rz / rz_old
        else:  # Polak-Ribiere, restarted where negative
            beta = max(0.0, (rz - np.sum(r * z_old)) / rz_old)
        if joining.any() and beta > 0 and rz + beta * np.sum(np.where(W, t, 0) * r) <= 0:
            beta = 0.0
        t = np.where(W, z + beta * t, 0.0)
        step = np.sum(r * t) / np.sum(t * K(t))
        if project is None:
            new, restart = np.maximum(p - step * t, 0.0), False
            new *= PBAR / new.mean()
            u_new = K(new)
        else:
            new, u_new, restart = project(p, step, t)
        change = np.abs(new - p).sum() / new.sum()
        p, u, rz_old, z_old = new, u_new, (0.0 if restart else rz), z
        if change <= tol and not joining.any():
            return p, it
    return p, 5000


def gap_space(h, tol):
    """Pressures and iterations of the dual problem in the gaps."""
    stiffness, compliance = spectra(h.shape[0])
    A, M = operator(stiffness), operator(compliance)
    g = np.maximum(h - np.percentile(h, 20), 0.0)  # the lowest fifth closed
    Ag, t, rz_old = A(g - h), np.zeros_like(h), 0.0
    for it in range(1, 5001):
        r = Ag + PBAR  # the pressure
        joining = (g == 0) & (r < 0)  # closed cells in tension open
        W = (g > 0) | joining
        r = np.where(W, r, 0.0)
        z = np.where(W, M(r), 0.0)
        rz = np.sum(r * z)
        beta = rz / rz_old if rz_old > 0 else 0.0
        if joining.any() and beta > 0 and rz + beta * np.sum(np.where(W, t, 0) * r) <= 0:
            beta = 0.0
        t = np.where(W, z + beta * t, 0.0)
        At = A(t)
        step = np.sum(r * t) / np.sum(t * At) if np.sum(t * At) > 0 else 0.0
        new = np.maximum(g - step * t, 0.0)
        change = np.abs(new - g).sum() / max(new.sum(), 1e-300)
        g, Ag, rz_old = new, A(new - h), rz
        if change <= tol and not joining.any():
            return np.maximum(Ag + PBAR, 0.0) * (g == 0), it
    return np.maximum(Ag + PBAR, 0.0) * (g == 0), 5000


def main(sizes):
    print("| N | pressure space (FR) | Polak-Ribiere | float32 preconditioner | gap space "
          "| contact |")
    print("|---|---|---|---|---|---|")
    for n in sizes:
        h = surface(n)
        exact, _ = pressure_space(h, 1e-13)
        error = lambda p: np.abs(p - exact).sum() / exact.sum()  # noqa: E731
        rows = [pressure_space(h, 1e-8), pressure_space(h, 1e-8, rule="pr"),
                pressure_space(h, 1e-8, single=True), gap_space(h, 1e-8)]
        cells = " | ".join(f"{it} it ({error(p):.1e})" for p, it in rows)
        print(f"| {n} | {cells} | {100 * np.mean(exact > 0):.2f} % |")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [128, 256])
