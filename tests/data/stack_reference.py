"""Reference values of the coating factor R(t) of three-layer stacks.

Independent of the crate's recursion: the plane-strain Navier equations are
solved symbolically (sympy) for the general Fourier-mode solution of one
layer, and the boundary-value problem of the whole stack (4 amplitudes per
layer, 2 for an elastic base) is assembled as one dense 4n x 4n (+2) linear
system and solved in 50-digit arithmetic (mpmath). Each layer's solution is
written with exponentials decaying away from its own faces, so nothing
overflows.

Per Fourier mode u_x = U(z) sin(qx), u_z = W(z) cos(qx) (z into the body),
a unit pressure cos(qx) on a frictionless surface gives
R(q h1) = E1* q W(0) / 2, with h1 the top layer's thickness.

Run: python3 tests/data/stack_reference.py > tests/data/stack_reference.json
(needs sympy and mpmath; the values do not depend on the machine).
"""
import json

import mpmath as mp
import sympy as sp

mp.mp.dps = 50

z, lam, mu = sp.symbols("z lam mu")
a1, a2, b1, b2, c1, c2, d1, d2 = sp.symbols("a1 a2 b1 b2 c1 c2 d1 d2")
# Ansatz for q = 1: U = (a1 + a2 z) e^-z + (b1 + b2 z) e^z, W likewise.
U = (a1 + a2 * z) * sp.exp(-z) + (b1 + b2 * z) * sp.exp(z)
W = (c1 + c2 * z) * sp.exp(-z) + (d1 + d2 * z) * sp.exp(z)
# Navier: mu (U'' - U) - (lam + mu)(U + W') = 0,
#         mu (W'' - W) + (lam + mu)(U' + W'') = 0.
eq1 = sp.expand(mu * (sp.diff(U, z, 2) - U) - (lam + mu) * (U + sp.diff(W, z)))
eq2 = sp.expand(mu * (sp.diff(W, z, 2) - W) + (lam + mu) * (sp.diff(U, z) + sp.diff(W, z, 2)))
conditions = []
for eq in (eq1, eq2):
    for e in (sp.exp(-z), sp.exp(z)):
        part = sp.expand(eq).coeff(e)
        conditions += [part.coeff(z, 0), part.coeff(z, 1)]
relations = sp.solve(conditions, [c1, c2, d1, d2], dict=True)[0]
U_s, W_s = U, W.subs(relations)
T_s = mu * (sp.diff(U_s, z) - W_s)  # sigma_xz / sin(qx)
S_s = lam * (U_s + sp.diff(W_s, z)) + 2 * mu * sp.diff(W_s, z)  # sigma_zz / cos(qx)
state = [sp.simplify(f) for f in (U_s, W_s, T_s, S_s)]
amplitudes = (a1, a2, b1, b2)
# Rows: d(state)/d(amplitude) as functions of (z, lam, mu).
basis = [[sp.lambdify((z, lam, mu), sp.diff(f, a), "mpmath") for a in amplitudes] for f in state]


def lame(E, nu):
    E, nu = mp.mpf(E), mp.mpf(nu)
    return E * nu / ((1 + nu) * (1 - 2 * nu)) if nu != mp.mpf("0.5") else None, E / (2 * (1 + nu))


def layer_rows(E, nu, x, zeta):
    """State at local depth zeta in a layer of thickness x: 4 x 4 matrix over
    (a1, a2, b1', b2'), the growing modes referred to the layer's bottom so
    that every entry is bounded."""
    lm, m = lame(E, nu)
    if lm is None:
        raise ValueError("nu = 0.5 is handled as a limit")
    rows = []
    for f in basis:
        decaying = [f[0](zeta, lm, m), f[1](zeta, lm, m)]
        # e^z (b1 + b2 z) with z = zeta: substitute zeta -> zeta - x and
        # divide by e^x: e^(zeta - x)(b1 + b2 (zeta - x)) is a solution too.
        growing = [f[2](zeta - x, lm, m), f[3](zeta - x, lm, m)]
        rows.append(decaying + growing)
    return rows


def coating_factor(layers, base, t):
    """R(t), t = q h1, for layers [(E, nu, h)] top first on base None (rigid)
    or (E, nu)."""
    h1 = mp.mpf(layers[0][2])
    n = len(layers)
    unknowns = 4 * n + (2 if base else 0)
    A = mp.zeros(unknowns, unknowns)
    rhs = mp.zeros(unknowns, 1)
    row = 0
    blocks = []
    for i, (E, nu, h) in enumerate(layers):
        x = t * mp.mpf(h) / h1
        blocks.append((layer_rows(E, nu, x, mp.mpf(0)), layer_rows(E, nu, x, x)))
    top = blocks[0][0]
    # Surface: sigma_xz = 0, sigma_zz = -1.
    for k in range(4):
        A[row, k] = top[2][k]
        A[row + 1, k] = top[3][k]
    rhs[row + 1] = -1
    row += 2
    for i in range(n - 1):
        bottom, next_top = blocks[i][1], blocks[i + 1][0]
        for comp in range(4):
            for k in range(4):
                A[row, 4 * i + k] = bottom[comp][k]
                A[row, 4 * (i + 1) + k] = -next_top[comp][k]
            row += 1
    bottom = blocks[-1][1]
    if base is None:
        for comp in range(2):
            for k in range(4):
                A[row, 4 * (n - 1) + k] = bottom[comp][k]
            row += 1
    else:
        half = layer_rows(base[0], base[1], mp.mpf(1), mp.mpf(0))
        for comp in range(4):
            for k in range(4):
                A[row, 4 * (n - 1) + k] = bottom[comp][k]
            for k in range(2):
                A[row, 4 * n + k] = -half[comp][k]
            row += 1
    assert row == unknowns
    amplitudes = mp.lu_solve(A, rhs)
    w0 = sum(top[1][k] * amplitudes[k] for k in range(4))
    E1, nu1 = mp.mpf(layers[0][0]), mp.mpf(layers[0][1])
    return E1 / (1 - nu1**2) * w0 / 2


def main():
    # nu = 0.5 is reached as 0.5 - 1e-30 (50-digit arithmetic keeps the limit
    # to ~1e-28).
    half = "0.499999999999999999999999999999"
    stacks = []
    for name, moduli in (("hard/soft/hard", (1e3, 1.0, 1e3)), ("soft/hard/soft", (1.0, 1e3, 1.0)),
                         ("hard/soft/hard x10", (10.0, 1.0, 10.0)), ("soft/hard/soft x10", (1.0, 10.0, 1.0))):
        for nus in (("0", "0.25", half), (half, "0", "0.3"), ("0.3", half, "0")):
            for thick in ((1.0, 2.0, 0.5), (1.0, 0.1, 5.0)):
                for base in (None, (1.0, "0.3"), (1e3, "0.2")):
                    stacks.append((name, [(moduli[k], nus[k], thick[k]) for k in range(3)], base))
    cases = []
    ts = ["1e-3", "1e-2", "0.1", "0.3", "1", "3", "10", "30"]
    for name, layers, base in stacks:
        points = []
        for t in ts:
            r = coating_factor(layers, base, mp.mpf(t))
            points.append({"t": float(mp.mpf(t)), "r": mp.nstr(r, 30), "lambda": mp.nstr(1 - r, 30)})
        cases.append({
            "name": name,
            "layers": [{"youngs_modulus": E, "poisson_ratio": float(mp.mpf(nu)), "thickness": h}
                       for E, nu, h in layers],
            "base": None if base is None else {"youngs_modulus": base[0], "poisson_ratio": float(mp.mpf(base[1]))},
            "points": points,
        })
    print(json.dumps({"source": "tests/data/stack_reference.py (50-digit direct boundary-value system)",
                      "cases": cases}, indent=1))


if __name__ == "__main__":
    main()
