"""Why does a sphere on a stiff layer over a far softer base take hundreds
to thousands of iterations (`examples/disc_or_ring.rs`)? Asked of the numpy
model of `projected_cg.py`: is it the preconditioner or the working set?

The body: a layer of `E1* = 1`, thickness `h = 1`, on a half-space `E1* /
ratio`, as the compliance `2 / (E1* q) + 1 / (D q^4 + E2* q / 2)`, `D =
E1* h^3 / 12` (the layer's own half-space plus a Kirchhoff plate on the
base: a model of the shape of the layered compliance, not the crate's
kernel); a paraboloid `R = 20 h` on a periodic grid `64 h` wide, `N` x `N`
cells, load control at the mean pressure `pbar` (in `E1*`), tolerance
1e-8, cold starts from the lowest 5 % of the cells. Columns:

- `PK`: the constrained conjugate gradients as the crate runs them
  (Polonsky & Keer 1999, Wear 231, 206; the conjugation kept across new
  overlap where it descends), preconditioned by the box inverse `P K P`
  (Vollebregt 2014, J. Comput. Phys. 257, 333);
- `restart`: the same, the conjugation restarted at every new overlap
  (Polonsky and Keer's own rule, which the crate takes up once a solve
  stalls, `src/solver/stall.rs`);
- `k=2`, `k=8`: the box with the residual extended by `k` sweeps of the
  four-neighbour mean past the set (`edge_extension.py`);
- `linear`: preconditioned conjugate gradients on the converged contact
  set held fixed (no constraint), with the box and with none: what the
  linear system costs once the set is known;
- `active set`: a primal-dual active-set loop (Hintermueller, Ito &
  Kunisch 2002, SIAM J. Optim. 13, 865): solve the linear system on the
  current set to 1e-10, drop the cells whose pressure came out tensile,
  add those the indenter overlaps; its outer loops and the inner
  iterations of all of them.

Usage: python plate_active_set.py [N]   (numpy, layered_contact)
"""

import sys

import numpy as np

import edge_extension as ee
import projected_cg as pc

WIDTH, THICKNESS, RADIUS = 64.0, 1.0, 20.0


def body(ratio, n):
    """Heights of the paraboloid and the compliance and stiffness spectra."""
    dx = WIDTH / n
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=dx)
    qx, qy = np.meshgrid(q1, q1, indexing="ij")
    q = np.hypot(qx, qy)[:, : n // 2 + 1]
    plate = THICKNESS**3 / 12.0
    compliance = np.zeros_like(q)
    m = q > 0
    compliance[m] = 2.0 / q[m] + 1.0 / (plate * q[m] ** 4 + q[m] / (2.0 * ratio))
    stiffness = np.zeros_like(q)
    stiffness[m] = 1.0 / compliance[m]
    x = (np.arange(n) - n / 2 + 0.5) * dx
    xx, yy = np.meshgrid(x, x, indexing="ij")
    return (xx**2 + yy**2) / (2 * RADIUS), compliance, stiffness


def constrained(height, compliance, pbar, precondition, restart=False):
    """The crate's constrained conjugate gradients (with `restart`, Polonsky
    and Keer's restarts at new overlap); (pressures, iterations)."""
    apply = pc.operator(compliance)
    p = np.where(height < np.percentile(height, 5), 1.0, 0.0)
    p *= pbar / p.mean()
    u, t, rz_old = apply(p), np.zeros_like(height), 0.0
    for it in range(1, 5001):
        g = height + u
        g = g - np.mean(g[p > 0])
        joining = (p == 0) & (g < 0)
        member = (p > 0) | joining
        r = np.where(member, g - g[member].mean(), 0.0)
        z = np.where(member, precondition(member, r), 0.0)
        z = np.where(member, z - z[member].mean(), 0.0)
        rz = np.sum(r * z)
        beta = rz / rz_old if rz_old > 0 else 0.0
        descends = rz + beta * np.sum(np.where(member, t, 0) * r) > 0
        if joining.any() and (restart or (beta > 0 and not descends)):
            beta = 0.0
        t = np.where(member, z + beta * t, 0.0)
        step = np.sum(r * t) / np.sum(t * apply(t))
        new = np.maximum(p - step * t, 0.0)
        new *= pbar / new.mean()
        change = np.abs(new - p).sum() / new.sum()
        p, u, rz_old = new, apply(new), rz
        if change <= 1e-8 and not joining.any():
            return p, it
    return p, 5000


def linear(height, compliance, pbar, member, precondition):
    """Conjugate gradients on `member` held fixed; (iterations, pressures)."""
    apply = pc.operator(compliance)
    p = np.where(member, pbar / member.mean(), 0.0)
    u, t, rz_old = apply(p), np.zeros_like(p), 0.0
    size = np.sqrt(np.sum(np.where(member, height, 0.0) ** 2))
    for it in range(1, 20001):
        g = height + u
        r = np.where(member, g - g[member].mean(), 0.0)
        if np.sqrt(np.sum(r * r)) < 1e-10 * size:
            return it, p
        z = np.where(member, precondition(member, r), 0.0)
        z = np.where(member, z - z[member].mean(), 0.0)
        rz = np.sum(r * z)
        t = np.where(member, z + (rz / rz_old if rz_old > 0 else 0.0) * t, 0.0)
        response = apply(t)
        step = np.sum(r * t) / np.sum(t * response)
        p, u, rz_old = p - step * t, u - step * response, rz
    return 20000, p


def active_set(height, compliance, pbar, precondition, loops=100):
    """The primal-dual active-set loop; (outer loops, inner iterations)."""
    apply = pc.operator(compliance)
    member = height < np.percentile(height, 5)
    total = 0
    for outer in range(1, loops + 1):
        iterations, p = linear(height, compliance, pbar, member, precondition)
        total += iterations
        g = height + apply(p)
        g = g - g[member].mean()
        tensile = member & (p < 0)
        overlap = ~member & (g < -1e-12 * np.abs(height).max())
        if not tensile.any() and not overlap.any():
            return outer, total
        member = (member & ~tensile) | overlap
    return loops, total


def main(n):
    print(f"{n} x {n} cells, iterations to 1e-8 from a cold start")
    print("| E1/E2 | pbar | contact cells | PK | restart | k=2 | k=8 | linear, box / none "
          "| active set: loops, inner |")
    print("|---|---|---|---|---|---|---|---|---|")
    for ratio in (1.0, 30.0, 300.0, 3000.0):
        for pbar in (3e-5, 1e-4):
            height, compliance, stiffness = body(ratio, n)
            box = pc.operator(stiffness)
            counts = []
            for sweeps in (0, 2, 8):
                p, it = constrained(height, compliance, pbar, ee.laplace(sweeps, 1.0, box))
                counts.append(it if sweeps else (it, p))
            (pk, p), k2, k8 = counts
            _, restarted = constrained(height, compliance, pbar, ee.laplace(0, 1.0, box), True)
            member = p > 0
            boxed, _ = linear(height, compliance, pbar, member, ee.laplace(0, 1.0, box))
            plain, _ = linear(height, compliance, pbar, member, lambda m, r: np.where(m, r, 0.0))
            loops, inner = active_set(height, compliance, pbar, ee.laplace(0, 1.0, box))
            print(f"| {ratio:g} | {pbar:g} | {member.sum()} | {pk} | {restarted} | {k2} | {k8} "
                  f"| {boxed} / {plain} "
                  f"| {loops}, {inner} |", flush=True)


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 128)
