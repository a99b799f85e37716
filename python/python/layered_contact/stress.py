"""A figure of the stresses below the surface: one field on the x-z section
through the grid's middle column, with the layer boundaries."""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

__all__ = ["plot_section"]


def plot_section(stresses: dict, field: str = "von_mises", column: Optional[int] = None,
                 ax: Any = None) -> Any:
    """Draws ``stresses[field]`` (a dict from ``subsurface_stress`` or
    ``Curve.stresses``, at least two planes) on the x-z section through
    ``column`` (the middle column by default), depth downwards, with the
    layer boundaries as white lines (matplotlib, an optional dependency).
    Returns the axes."""
    import matplotlib.pyplot as plt

    values = np.asarray(stresses[field])
    depth = np.asarray(stresses["depth"])
    x = np.asarray(stresses["x"])
    if values.ndim != 3 or values.shape[0] < 2:
        raise ValueError(f"{field}: a section needs at least two planes, got shape {values.shape}")
    j = values.shape[2] // 2 if column is None else column
    if not 0 <= j < values.shape[2]:
        raise ValueError(f"column {j}: expected 0 to {values.shape[2] - 1}")
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4))
    mesh = ax.pcolormesh(x, depth, values[:, :, j], shading="nearest")
    for boundary in stresses.get("boundaries", []):
        if boundary <= depth[-1]:
            ax.axhline(boundary, color="white", lw=1.5)
    ax.set_ylim(depth[-1], depth[0])
    ax.set_xlabel("x [m]")
    ax.set_ylabel("depth z [m]")
    ax.set_title(f"{field} on the x-z section (column {j})")
    ax.figure.colorbar(mesh, ax=ax, label=f"{field} [Pa]")
    return ax
