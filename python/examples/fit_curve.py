"""From a CSV force curve to the modulus and the work of adhesion of a film.

    python fit_curve.py [curve.csv] [--plot fit.png]

The CSV has two columns, piezo position (m, increasing into the sample) and
force (N), one retract segment from the deepest point on. Without a file,
a synthetic curve is made with the exact model (seeded noise of 1 % of the
largest force) and written to ``synthetic_curve.csv`` first. The tip, the
film's thickness and Poisson ratio and the support are set below.
"""

import argparse
import time

import numpy as np

from layered_contact.fit import CurveModel, Sample, fit_curve

TIP, RADIUS = "paraboloid", 5e-6  # colloidal probe, m
SAMPLE = Sample(thickness=4e-6, poisson_ratio=0.5)  # gel film on glass


def synthetic(path: str) -> None:
    model = CurveModel(TIP, RADIUS, SAMPLE, max_depth=2.5e-6)
    z = np.linspace(2.1e-6, -0.7e-6, 2000)
    force = model.force(z - 1e-7, 10e3, 1e-3)
    rng = np.random.default_rng(2026)
    force += 0.01 * np.max(np.abs(force)) * rng.standard_normal(z.size)
    np.savetxt(path, np.column_stack([z, force]), delimiter=",", header="z_m,force_N")


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="?")
    parser.add_argument("--plot")
    args = parser.parse_args(argv)
    path = args.csv
    if path is None:
        path = "synthetic_curve.csv"
        synthetic(path)
    z, force = np.loadtxt(path, delimiter=",", unpack=True)
    start = time.perf_counter()
    result = fit_curve(z, force, tip=TIP, radius=RADIUS, sample=SAMPLE, segment="retract",
                       youngs_modulus=5e3, work_of_adhesion=0.5e-3)
    seconds = time.perf_counter() - start
    for name, value in result.params.items():
        print(f"{name:>17} = {value:.5g} +- {result.stderr[name]:.2g}")
    print(f"{result.calls} model evaluations, {seconds:.2f} s, rms residual {result.rms:.3g} N")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        result.plot().figure.savefig(args.plot, dpi=150)
    return result.params


if __name__ == "__main__":
    main()
