"""Cost of the fitting models: for each tip on a film on glass and on a
stack, the exact tables (built once per fit on a rigid support), one
evaluation of a 300-point curve from them, and one whole fit of a seeded
synthetic curve (2000 points, 1 % noise) with its model evaluations.
Prints the rows of BENCHMARKS.md's table. With ``--family``, the modulus
families instead (``CurveModel(..., modulus_range=...)``: 12 exact tables
once, then every curve from them) on supports that do not scale, approach
and retract.

    python fit_benchmark.py [--family]
"""

import os
import sys
import time

import numpy as np
import scipy.optimize  # noqa: F401  (imported here, not inside the first timed fit)

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


FAMILY_SAMPLES = [
    ("film on a gel (2.5 kPa)", Sample(thickness=H, poisson_ratio=0.5, base_youngs_modulus=2.5e3,
                                       base_poisson_ratio=0.5)),
    ("film on a coating on glass", Sample(thickness=H, poisson_ratio=0.5,
                                          below=((1e6, 0.4, 1e-6),))),
]


def family():
    """A paraboloid (R = 5 um) on each sample, moduli 3 to 30 kPa: the
    family's build, one 300-point curve (approach and retract, 1 mJ/m^2),
    and fits of seeded synthetic curves (1 % noise) from 8 kPa."""
    radius, w, z0 = 5e-6, 1e-3, 1e-7
    print(f"load average {os.getloadavg()[0]:.2f}")
    print("| sample | family (s) | approach curve (ms) | retract curve (ms) | approach fit (ms, calls) "
          "| retract fit (ms, calls) | E error | w error |")
    print("|---|---|---|---|---|---|---|---|")
    for label, sample in FAMILY_SAMPLES:
        start = time.perf_counter()
        model = CurveModel("paraboloid", radius, sample, max_depth=0.9 * H,
                           modulus_range=(3e3, 30e3))
        model.force(np.array([0.1 * H]), E)
        build = time.perf_counter() - start
        depth = np.linspace(-0.5e-6, 0.5 * H, 300)
        times = []
        for work in (0.0, w):
            start = time.perf_counter()
            for k in range(200):
                model.force(depth, E * (1.0 + 1e-3 * k), work)
            times.append((time.perf_counter() - start) / 200)
        rng = np.random.default_rng(5)
        z = np.linspace(0.0, 0.5 * H, 300)
        f = model.force(z - z0, E)
        f = f + 0.01 * np.max(f) * rng.standard_normal(z.size)
        calls = model.calls
        start = time.perf_counter()
        fit = fit_curve(z, f, tip="paraboloid", radius=radius, sample=sample,
                        youngs_modulus=8e3, model=model)
        approach = (time.perf_counter() - start, model.calls - calls)
        z = np.linspace(0.5 * H + z0, -0.8e-6 + z0, 2000)
        f = model.force(z - z0, E, w)
        f = f + 0.01 * np.max(np.abs(f)) * rng.standard_normal(z.size)
        calls = model.calls
        start = time.perf_counter()
        retract = fit_curve(z, f, tip="paraboloid", radius=radius, sample=sample,
                            segment="retract", youngs_modulus=8e3, work_of_adhesion=0.5e-3,
                            model=model)
        seconds = (time.perf_counter() - start, model.calls - calls)
        assert not model._tables, "the family served every call"
        e_error = retract.params["youngs_modulus"] / E - 1
        w_error = retract.params["work_of_adhesion"] / w - 1
        print(f"| {label} | {build:.2f} | {1e3 * times[0]:.2f} | {1e3 * times[1]:.2f} | "
              f"{1e3 * approach[0]:.0f} ({approach[1]}) | {1e3 * seconds[0]:.0f} ({seconds[1]}) | "
              f"{100 * e_error:+.2f} % | {100 * w_error:+.2f} % |")
        del fit


if __name__ == "__main__":
    if "--family" in sys.argv[1:]:
        family()
    else:
        main()
