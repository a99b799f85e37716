"""The peers' Hertz benchmark in tamaas and ContactMechanics, beside this
crate's `hertz_benchmark` example; prints a Markdown table with the ratios.

Rigid paraboloid R = 1 on a non-periodic half-space E* = 1, domain 2 x 2 on
N x N cells, depth 0.25 (contact radius a = L/4), tolerance 1e-8.

* ContactMechanics: `FreeFFTElasticHalfSpace` (zero-padded, non-periodic),
  Polonsky-Keer constrained conjugate gradients under force (load) and under
  depth (offset) control.
* tamaas is periodic only: it solves the same problem on a periodic domain
  of twice the size and cells (4 x 4 on 2N x 2N, the cost of zero padding;
  the nearest periodic image is 4 away) under load control.

Usage: python peers.py rust.csv N [N ...]   (rust.csv from hertz_benchmark)
"""

import csv
import os
import sys
import tempfile
import time

import numpy as np

R, DEPTH, L, TOL = 1.0, 0.25, 2.0, 1e-8
FORCE = 4.0 / 3.0 * np.sqrt(R) * DEPTH**1.5


def timed_tamaas(solve):
    """Seconds and iterations of `solve()`, a tamaas solve: tamaas logs its
    iterations on stderr, read there."""
    with tempfile.TemporaryFile(mode="w+") as log:
        sys.stderr.flush()
        saved = os.dup(2)
        os.dup2(log.fileno(), 2)
        try:
            start = time.perf_counter()
            solve()
            seconds = time.perf_counter() - start
        finally:
            os.dup2(saved, 2)
            os.close(saved)
        log.seek(0)
        rows = [line.split() for line in log if line.strip()[:1].isdigit()]
    return seconds, int(rows[-1][0]) + 1 if rows else -1


def tamaas_load(n):
    import tamaas as tm

    n2, l2 = 2 * n, 2 * L
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [l2, l2], [n2, n2])
    model.E, model.nu = 1.0, 0.0
    x = (np.arange(n2) + 0.5) * l2 / n2 - l2 / 2
    xx, yy = np.meshgrid(x, x, indexing="ij")
    solver = tm.PolonskyKeerRey(model, -(xx**2 + yy**2) / (2 * R), TOL)
    return timed_tamaas(lambda: solver.solve(FORCE / l2**2))


def contactmechanics(n, control):
    from ContactMechanics import FreeFFTElasticHalfSpace
    from ContactMechanics.Optimization.ConstrainedConjugateGradients import (
        constrained_conjugate_gradients,
    )
    from SurfaceTopography import make_sphere

    substrate = FreeFFTElasticHalfSpace((n, n), 1.0, (L, L))
    surface = make_sphere(R, (n, n), (L, L), kind="paraboloid")
    kwargs = {"external_force": FORCE} if control == "force" else {"offset": DEPTH}
    start = time.perf_counter()
    result = constrained_conjugate_gradients(
        substrate, surface, pentol=TOL * DEPTH, thermotol=TOL, **kwargs
    )
    return time.perf_counter() - start, result.nit


def main():
    rust = {}
    with open(sys.argv[1]) as f:
        for row in csv.DictReader(f):
            rust[(int(row["N"]), row["control"])] = (float(row["solve_s"]), int(row["iterations"]))
    print("| N | this crate, force | this crate, depth | tamaas (load) | "
          "ContactMechanics (load / depth) | faster peer / this crate |")
    print("|---|---|---|---|---|---|")
    for n in map(int, sys.argv[2:]):
        peers = {}
        for name, run in [
            ("tamaas", lambda: tamaas_load(n)),
            ("cm_force", lambda: contactmechanics(n, "force")),
            ("cm_depth", lambda: contactmechanics(n, "depth")),
        ]:
            try:
                peers[name] = run()
            except ImportError as e:
                print(f"<!-- {name}: not installed ({e}) -->")
        fmt = lambda r: f"{r[0]:.2f} s, {r[1]} it" if r else "-"
        force, depth = rust.get((n, "force")), rust.get((n, "depth"))
        fastest = min((v[0] for v in peers.values()), default=None)
        ratio = f"{fastest / force[0]:.0f}x" if fastest and force else "-"
        print(f"| {n} | {fmt(force)} | {fmt(depth)} | {fmt(peers.get('tamaas'))} | "
              f"{fmt(peers.get('cm_force'))} / {fmt(peers.get('cm_depth'))} | {ratio} |")


if __name__ == "__main__":
    main()
