"""Cost of the fitting models: for each tip on a film on glass and on a
stack, the exact tables (built once per fit on a rigid support), one
evaluation of a 300-point curve from them, and one whole fit of a seeded
synthetic curve (2000 points, 1 % noise) with its model evaluations.
Prints the rows of BENCHMARKS.md's table.

    python fit_benchmark.py
"""

import os
import time

import numpy as np

from layered_contact.fit import CurveModel, Sample, fit_curve

H, E = 4e-6, 10e3
TIPS = [
    ("paraboloid", dict(radius=5e-6)),
    ("sphere", dict(radius=5e-6)),
    ("cone", dict(half_angle=np.radians(70.0))),
    ("rounded_cone", dict(radius=0.3e-6, half_angle=np.radians(70.0))),
    ("flat_punch", dict(radius=1e-6)),
]
SAMPLES = [
    ("film on glass", Sample(thickness=H, poisson_ratio=0.5)),
    ("film on a coating on glass", Sample(thickness=H, poisson_ratio=0.5,
                                          below=((1e6, 0.4, 1e-6),))),
]


def main():
    print(f"load average {os.getloadavg()[0]:.2f}")
    print("| tip | sample | tables (s) | one 300-point curve (ms) | fit (s) | model calls | E error |")
    print("|---|---|---|---|---|---|---|")
    for tip, size in TIPS:
        for label, sample in SAMPLES:
            start = time.perf_counter()
            model = CurveModel(tip, size.get("radius"), sample, max_depth=0.6 * H,
                               half_angle=size.get("half_angle"))
            model.force(np.array([0.1 * H]), E)
            tables = time.perf_counter() - start
            depth = np.linspace(0.0, 0.5 * H, 300)
            runs = 20 if sample.scales_with_modulus else 2
            start = time.perf_counter()
            for k in range(runs):
                model.force(depth, E * (1.0 + 1e-3 * k))
            curve = (time.perf_counter() - start) / runs
            z = np.linspace(-0.5e-6, 0.5 * H, 2000)
            f = model.force(z - 1e-7, E)
            f = f + 0.01 * np.max(f) * np.random.default_rng(5).standard_normal(z.size)
            start = time.perf_counter()
            fit = fit_curve(z, f, tip=tip, sample=sample, youngs_modulus=2e4, **size)
            seconds = time.perf_counter() - start
            error = fit.params["youngs_modulus"] / E - 1
            print(f"| {tip} | {label} | {tables:.2f} | {1e3 * curve:.2f} | {seconds:.2f} | "
                  f"{fit.calls} | {100 * error:+.2f} % |")


if __name__ == "__main__":
    main()
