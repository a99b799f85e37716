"""The stiffness figure of Lyashenko, Popov & Borysiuk (2023): a flat punch
of diameter D on a rubber layer (E = 0.324 MPa, nu = 0.48) of thickness h on
glass, K / (2 a E*) against D, exact (lines) and boundary-element scenes
(points).

    pip install ./python matplotlib
    python python/examples/stiffness_figure.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import layered_contact as lc  # noqa: E402

rubber = lc.Material(0.324e6, 0.48)
diameters = np.linspace(0.5e-3, 30e-3, 60)
fig, ax = plt.subplots(figsize=(6, 4.5))
for h in (5e-3, 10e-3, 15e-3, 20e-3, 25e-3):
    film = lc.Substrate.layer_on_rigid_base(rubber, h)
    exact = lc.analytic.flat_punch_stiffness(film, diameters / 2)
    line = ax.plot(diameters * 1e3, exact / (diameters * rubber.contact_modulus), label=f"h = {h * 1e3:g} mm")[0]
    for d in (5e-3, 15e-3, 25e-3):
        scene = {
            "substrate": {"kind": "layer_on_rigid_base", "youngs_modulus": 0.324e6, "poisson_ratio": 0.48, "thickness": h},
            "indenter": {"kind": "flat_punch", "radius": d / 2},
            "protocol": {"kind": "cycle", "max_depth": 1e-4, "steps": 2},
            "resolution": {"cells_across": 32},
        }
        k = lc.run_scene(scene).stiffness
        ax.plot(d * 1e3, k / (d * rubber.contact_modulus), "o", color=line.get_color())
ax.set_xlabel("punch diameter D [mm]")
ax.set_ylabel("K / (2 a E*)")
ax.legend()
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "stiffness.png"
fig.savefig(out, dpi=120)
print(f"wrote {out}")
