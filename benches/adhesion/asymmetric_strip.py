"""Stress-intensity factors of an off-centre contact strip on Johnson's sinusoid.

The check behind `JkrSinusoid::strip_stress_intensity` (src/analytic/sinusoid.rs):
a rigid surface g (1 - cos(2 pi x / lambda)) on an elastic half-space (plane
strain, E*), one contact strip lower < x < upper per period held bonded at the
mean pressure pbar. The periodic singular integral equation

    u'(x) = -(2 / (pi E*)) int p(t) (pi / lambda) cot(pi (x - t) / lambda) dt,
    u'(x) = -f'(x) on the strip,

becomes, with T = tan(pi (x - c) / lambda) (c the strip's centre), a Cauchy
kernel on (-A, A) plus a term in T alone. It is solved here numerically by
Gauss-Chebyshev quadrature (Erdogan & Gupta 1972, Q. Appl. Math. 29, 525:
p = phi(T) / sqrt(A^2 - T^2), n nodes, n - 1 collocation points and the mean
pressure), phi extrapolated to the ends by its Chebyshev series; that is
independent of the closed form, which this script prints beside it. The
values in the unit test `gauss_chebyshev_values` are this script's numeric
column (n = 64).

    python benches/adhesion/asymmetric_strip.py
"""
import numpy as np
from numpy.polynomial import chebyshev as C


def numeric(lam, g, estar, lower, upper, pbar, n=64):
    """(K_lower, K_upper), positive where the edge pulls, by Gauss-Chebyshev."""
    c = 0.5 * (lower + upper)
    a = 0.5 * (upper - lower)
    big_a = np.tan(np.pi * a / lam)
    i = np.arange(1, n + 1)
    t = big_a * np.cos((2 * i - 1) * np.pi / (2 * n))
    k = np.arange(1, n)
    x = big_a * np.cos(k * np.pi / n)
    h = np.pi ** 2 * estar * g / lam
    m = np.zeros((n, n))
    rhs = np.zeros(n)
    for r, xr in enumerate(x):
        m[r] = (np.pi / n) * (1 / (xr - t) + t / (1 + t ** 2))
        rhs[r] = h * np.sin(2 * np.pi * (c + lam / np.pi * np.arctan(xr)) / lam)
    m[n - 1] = (lam / np.pi) * (np.pi / n) / (1 + t ** 2)
    rhs[n - 1] = pbar * lam
    phi = np.linalg.solve(m, rhs)
    coef = C.chebfit(t / big_a, phi, n - 1)
    scale = np.sqrt(lam / (big_a * (1 + big_a ** 2)))
    return -C.chebval(-1, coef) * scale, -C.chebval(1, coef) * scale


def closed(lam, g, estar, lower, upper, pbar):
    """The closed form of `strip_stress_intensity`."""
    c = 0.5 * (lower + upper)
    psi = 0.5 * np.pi * (upper - lower) / lam
    flank = np.pi * estar * g / lam * np.sin(psi)
    scale = np.sqrt(lam / np.tan(psi))
    k_upper = scale * (flank * np.sin(np.pi * (upper + c) / lam) - pbar)
    k_lower = scale * (-flank * np.sin(np.pi * (lower + c) / lam) - pbar)
    return k_lower, k_upper


if __name__ == "__main__":
    worst = 0.0
    print("lower upper pbar | numeric K_lower K_upper | closed form | relative difference")
    for lower, upper, pbar in [
        (-0.1, 0.1, -300.0),
        (-0.05, 0.15, -300.0),
        (-0.2, 0.05, 500.0),
        (0.1, 0.3, 0.0),
        (-0.4, 0.3, 100.0),
    ]:
        num = numeric(1.0, 1e-3, 1e6, lower, upper, pbar)
        exact = closed(1.0, 1e-3, 1e6, lower, upper, pbar)
        diff = max(abs(a / b - 1) for a, b in zip(num, exact))
        worst = max(worst, diff)
        print(f"{lower} {upper} {pbar} | {float(num[0])!r} {float(num[1])!r} | {exact[0]:.12g} {exact[1]:.12g} | {diff:.1e}")
    print(f"largest relative difference {worst:.1e}")
